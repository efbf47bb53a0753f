/*
 * Stencil test (GL 1.5 spec 4.1.5): glStencilFunc, glStencilOp and
 * glStencilMask on an 8-bit stencil buffer.  The update runs from
 * fs_stencil_depth_quad (depth_test.c) because it depends on the depth result.
 */
#include "fragment_stages.h"

static bool op_valid(GLenum op)
{
    switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR:
    case GL_INVERT: case GL_INCR_WRAP: case GL_DECR_WRAP:
        return true;
    default:
        return false;
    }
}

void fs_exec_StencilFunc(fs_context *c, GLenum func, GLint ref, GLuint mask)
{
    if (func < GL_NEVER || func > GL_ALWAYS) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.stencil_func = func;
    /* Clamped to [0, 2^s - 1] (4.1.5) when given: glGet returns it so on
     * OSMesa (measured: 369 gives 255, -5 gives 0 with 8 bits). */
    GLint max = (1 << c->fb.stencil_bits) - 1;
    c->frag.stencil_ref = ref < 0 ? 0 : ref > max ? max : ref;
    c->frag.stencil_value_mask = mask;
    fs_state_mark(c, GL_STENCIL_BUFFER_BIT);
}

void fs_exec_StencilOp(fs_context *c, GLenum fail, GLenum zfail, GLenum zpass)
{
    if (!op_valid(fail) || !op_valid(zfail) || !op_valid(zpass)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.stencil_fail = fail;
    c->frag.stencil_zfail = zfail;
    c->frag.stencil_zpass = zpass;
    fs_state_mark(c, GL_STENCIL_BUFFER_BIT);
}

void fs_exec_StencilMask(fs_context *c, GLuint mask)
{
    c->frag.stencil_write_mask = mask;
    fs_state_mark(c, GL_STENCIL_BUFFER_BIT);
}

/* The reference is clamped to [0, 2^s - 1] (4.1.5). */
static inline unsigned clamped_ref(const fs_context *c)
{
    GLint max = (1 << c->fb.stencil_bits) - 1;
    GLint r = c->frag.stencil_ref;
    return (unsigned)(r < 0 ? 0 : (r > max ? max : r));
}

bool fs_stencil_test(const fs_context *c, uint8_t stored)
{
    unsigned m = c->frag.stencil_value_mask;
    unsigned r = clamped_ref(c) & m, s = stored & m;
    switch (c->frag.stencil_func) {
    case GL_NEVER: return false;
    case GL_LESS: return r < s;
    case GL_EQUAL: return r == s;
    case GL_LEQUAL: return r <= s;
    case GL_GREATER: return r > s;
    case GL_NOTEQUAL: return r != s;
    case GL_GEQUAL: return r >= s;
    default: return true;
    }
}

uint8_t fs_stencil_apply(const fs_context *c, GLenum op, uint8_t stored)
{
    unsigned max = (1u << c->fb.stencil_bits) - 1u;
    unsigned v;
    switch (op) {
    case GL_ZERO: v = 0; break;
    case GL_REPLACE: v = clamped_ref(c); break;
    case GL_INCR: v = stored < max ? stored + 1u : max; break;      /* saturates */
    case GL_DECR: v = stored > 0 ? stored - 1u : 0; break;          /* saturates */
    case GL_INVERT: v = ~(unsigned)stored & max; break;
    case GL_INCR_WRAP: v = (stored + 1u) & max; break;
    case GL_DECR_WRAP: v = (stored - 1u) & max; break;
    default: return stored; /* GL_KEEP */
    }
    unsigned wm = c->frag.stencil_write_mask & max;
    return (uint8_t)((stored & ~wm) | (v & wm));
}
