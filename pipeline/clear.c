/*
 * Clearing the buffers (GL 1.5 spec 4.2.3): glClear, glClearColor,
 * glClearDepth, glClearStencil.  Clear honours pixel ownership, the scissor
 * box and the colour, depth and stencil write masks, and nothing else
 * (no alpha/stencil/depth test, blending or logic op).
 */
#include <math.h>
#include "fragment_stages.h"

static inline float clampf01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

void fs_exec_ClearColor(fs_context *c, GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
{
    c->frag.clear_color[0] = clampf01(red);
    c->frag.clear_color[1] = clampf01(green);
    c->frag.clear_color[2] = clampf01(blue);
    c->frag.clear_color[3] = clampf01(alpha);
}

void fs_exec_ClearDepth(fs_context *c, GLclampd depth)
{
    c->frag.clear_depth = depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0;
}

void fs_exec_ClearStencil(fs_context *c, GLint s)
{
    c->frag.clear_stencil = s;
}

/* The clear depth in buffer units: scaled in double and rounded to nearest
 * even, which matches OSMesa's full-window clears exactly.  llvmpipe's
 * scissored clears take another route and differ by one unit for about a
 * quarter of values (measured by tests/test_fragment_ops.c). */
uint32_t fs_clear_depth_value(const fs_context *c)
{
    return (uint32_t)lrint(c->frag.clear_depth * (double)c->fb.depth_max);
}

void fs_exec_Clear(fs_context *c, GLbitfield mask)
{
    const GLbitfield all = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                           GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if (mask & ~all) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->stats.clears++;
    /* Outside GL_RENDER mode Mesa clears nothing (its glClear acts only in
     * GL_RENDER); occlusion modes follow GL_SELECT (see suppress_writes). */
    if (c->frag.suppress_writes)
        return;
    int x0, y0, x1, y1;
    if (!fs_scissor_rect(c, &x0, &y0, &x1, &y1))
        return;
    fs_framebuffer *fb = &c->fb;
    const fs_fragment_state *f = &c->frag;
    size_t w = (size_t)fb->width;
    if (c->cycle)
        fs_cycle_clear(c->cycle, c, mask, x1 - x0, y1 - y0);

    if ((mask & GL_COLOR_BUFFER_BIT) &&
        (f->color_mask[0] || f->color_mask[1] || f->color_mask[2] || f->color_mask[3])) {
        uint8_t rgba[4];
        for (int k = 0; k < 4; k++)
            rgba[k] = fs_unorm8(f->clear_color[k]);
        bool all_channels = f->color_mask[0] && f->color_mask[1] && f->color_mask[2] && f->color_mask[3];
        for (int y = y0; y < y1; y++) {
            uint8_t *p = fb->color + ((size_t)y * w + (size_t)x0) * 4;
            if (all_channels) {
                for (int x = x0; x < x1; x++, p += 4)
                    memcpy(p, rgba, 4);
            } else {
                for (int x = x0; x < x1; x++, p += 4)
                    fs_masked_color_write(c, p, rgba);
            }
        }
    }
    if ((mask & GL_DEPTH_BUFFER_BIT) && f->depth_write) {
        uint32_t z = fs_clear_depth_value(c);
        for (int y = y0; y < y1; y++) {
            uint32_t *p = fb->depth + (size_t)y * w;
            for (int x = x0; x < x1; x++)
                p[x] = z;
        }
    }
    if ((mask & GL_STENCIL_BUFFER_BIT) && fb->stencil_bits > 0) {
        unsigned max = (1u << fb->stencil_bits) - 1u;
        unsigned wm = f->stencil_write_mask & max;
        /* Only the low s bits of the clear value are used (4.2.3). */
        unsigned v = (unsigned)f->clear_stencil & max;
        if (wm) {
            for (int y = y0; y < y1; y++) {
                uint8_t *p = fb->stencil + (size_t)y * w;
                for (int x = x0; x < x1; x++)
                    p[x] = (uint8_t)((p[x] & ~wm) | (v & wm));
            }
        }
    }
}
