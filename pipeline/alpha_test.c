/*
 * Alpha test (GL 1.5 spec 4.1.4) and glAlphaFunc.  llvmpipe compares the
 * fragment's float alpha with the float reference (no conversion to the
 * buffer's precision first); tests/test_fragment_ops.c checks this against
 * OSMesa around reference values.
 */
#include "fragment_stages.h"

static bool func_valid(GLenum f)
{
    return f >= GL_NEVER && f <= GL_ALWAYS;
}

void fs_exec_AlphaFunc(fs_context *c, GLenum func, GLclampf ref)
{
    if (!func_valid(func)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.alpha_func = func;
    /* clampf arguments are clamped when specified (GL 1.5 spec 2.3). */
    c->frag.alpha_ref = ref > 0.0f ? (ref < 1.0f ? ref : 1.0f) : 0.0f;
}

static inline bool alpha_pass(GLenum func, float a, float ref)
{
    switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return a < ref;
    case GL_EQUAL: return a == ref;
    case GL_LEQUAL: return a <= ref;
    case GL_GREATER: return a > ref;
    case GL_NOTEQUAL: return a != ref;
    case GL_GEQUAL: return a >= ref;
    default: return true;
    }
}

unsigned fs_alpha_test_quad(const fs_context *c, const fs_quad *q, unsigned mask)
{
    unsigned out = 0;
    for (int i = 0; i < 4; i++)
        if ((mask >> i & 1u) && alpha_pass(c->frag.alpha_func, q->color[i][3], c->frag.alpha_ref))
            out |= 1u << i;
    return out;
}
