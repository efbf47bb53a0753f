/*
 * Blending (GL 1.5 spec 4.1.8) and glBlendFunc, with blend equation
 * FUNC_ADD and a constant colour of (0,0,0,0) (fragsim has no glBlendColor).
 *
 * llvmpipe blends an RGBA8 target in 8-bit fixed point: factors are 8-bit
 * (ONE_MINUS_x is 255 - x, SRC_ALPHA_SATURATE is min(As, 255 - Ad) for RGB
 * and 255 for alpha), each product is the 16-bit approximation
 * (ab + (ab >> 8) + 128) >> 8 of ab/255, and the two terms are added with
 * unsigned saturation.  The source colour is first converted with
 * fs_unorm8.  tests/test_fragment_ops.c checks every factor pair against
 * OSMesa.
 */
#include "fragment_stages.h"

bool fs_blend_factor_valid(GLenum f, bool is_src)
{
    switch (f) {
    case GL_ZERO: case GL_ONE:
    case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR:
    case GL_DST_COLOR: case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA:
    case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA:
    case GL_CONSTANT_COLOR: case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
        return true;
    case GL_SRC_ALPHA_SATURATE:
        /* Only a source factor before GL 1.4 and still in GL 1.5 (table 4.2). */
        return is_src;
    default:
        return false;
    }
}

void fs_exec_BlendFunc(fs_context *c, GLenum sfactor, GLenum dfactor)
{
    if (!fs_blend_factor_valid(sfactor, true) || !fs_blend_factor_valid(dfactor, false)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.blend_src = sfactor;
    c->frag.blend_dst = dfactor;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

static inline unsigned mul_norm8(unsigned a, unsigned b)
{
    unsigned ab = a * b;
    return (ab + (ab >> 8) + 128u) >> 8;
}

static inline unsigned factor(GLenum f, int k, const uint8_t s[4], const uint8_t d[4])
{
    switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[k];
    case GL_ONE_MINUS_SRC_COLOR: return 255u - s[k];
    case GL_DST_COLOR: return d[k];
    case GL_ONE_MINUS_DST_COLOR: return 255u - d[k];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255u - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255u - d[3];
    case GL_SRC_ALPHA_SATURATE:
        if (k == 3)
            return 255;
        return s[3] < 255u - d[3] ? s[3] : 255u - d[3];
    case GL_CONSTANT_COLOR: case GL_CONSTANT_ALPHA: return 0;
    default: return 255; /* ONE_MINUS_CONSTANT_* with a zero constant */
    }
}

void fs_blend_rgba8(const fs_context *c, const uint8_t src[4], uint8_t dst[4])
{
    GLenum sf = c->frag.blend_src, df = c->frag.blend_dst;
    uint8_t d[4];
    memcpy(d, dst, 4);
    for (int k = 0; k < 4; k++) {
        unsigned v = mul_norm8(src[k], factor(sf, k, src, d)) + mul_norm8(d[k], factor(df, k, src, d));
        dst[k] = (uint8_t)(v > 255u ? 255u : v);
    }
}
