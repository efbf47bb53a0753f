/*
 * Alpha test (GL 1.5 spec 4.1.4) and glAlphaFunc.
 *
 * llvmpipe does not compare floats: for an RGBA8 colour buffer it converts
 * both the fragment alpha and the reference to 8 bits first and compares the
 * integers.  That conversion is not the one used for the colour write
 * (fs_unorm8): it scales by 255/256 in float and adds 2^15, so the 8 bits
 * appear in the low mantissa bits after a round-to-nearest-even addition.
 * The two roundings differ near ties, so the exact recipe matters;
 * tests/test_fragment_ops.c checks it against OSMesa a few ulps around
 * several references.
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
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

static inline unsigned alpha_unorm8(float x)
{
    x = x > 0.0f ? x : 0.0f;
    x = x < 1.0f ? x : 1.0f;
    /* volatile-free: C11 without FP_CONTRACT keeps the multiply and add
     * separately rounded, as the LLVM IR llvmpipe emits does. */
    float y = x * (255.0f / 256.0f);
    y = y + 32768.0f;
    uint32_t bits;
    memcpy(&bits, &y, sizeof bits);
    return bits & 0xffu;
}

static inline bool alpha_pass(GLenum func, unsigned a, unsigned ref)
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
    unsigned ref = alpha_unorm8(c->frag.alpha_ref);
    for (int i = 0; i < 4; i++)
        if ((mask >> i & 1u) && alpha_pass(c->frag.alpha_func, alpha_unorm8(q->color[i][3]), ref))
            out |= 1u << i;
    return out;
}
