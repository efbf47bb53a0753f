/*
 * Scissor test (GL 1.5 spec 4.1.2) and glScissor.
 */
#include "fragment_stages.h"

void fs_exec_Scissor(fs_context *c, GLint x, GLint y, GLsizei width, GLsizei height)
{
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->frag.scissor[0] = x;
    c->frag.scissor[1] = y;
    c->frag.scissor[2] = width;
    c->frag.scissor[3] = height;
    fs_state_mark(c, GL_SCISSOR_BIT);
}

bool fs_scissor_rect(const fs_context *c, int *x0, int *y0, int *x1, int *y1)
{
    /* 64-bit sums: x + width may overflow int for extreme (legal) arguments. */
    int64_t ax = 0, ay = 0, bx = c->fb.width, by = c->fb.height;
    if (c->frag.scissor_enabled) {
        const GLint *s = c->frag.scissor;
        int64_t sx1 = (int64_t)s[0] + s[2], sy1 = (int64_t)s[1] + s[3];
        if (s[0] > ax) ax = s[0];
        if (s[1] > ay) ay = s[1];
        if (sx1 < bx) bx = sx1;
        if (sy1 < by) by = sy1;
    }
    if (ax >= bx || ay >= by) {
        *x0 = *y0 = *x1 = *y1 = 0;
        return false;
    }
    *x0 = (int)ax;
    *y0 = (int)ay;
    *x1 = (int)bx;
    *y1 = (int)by;
    return true;
}

unsigned fs_scissor_quad(const fs_context *c, int qx, int qy, unsigned mask)
{
    const GLint *s = c->frag.scissor;
    int64_t x1 = (int64_t)s[0] + s[2], y1 = (int64_t)s[1] + s[3];
    unsigned in = 0;
    for (int i = 0; i < 4; i++) {
        int64_t x = qx + (i & 1), y = qy + (i >> 1);
        if (x >= s[0] && x < x1 && y >= s[1] && y < y1)
            in |= 1u << i;
    }
    return mask & in;
}
