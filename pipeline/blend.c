/*
 * Blending (GL 1.5 spec 4.1.8): glBlendFunc, glBlendFuncSeparate,
 * glBlendEquation and glBlendColor (GL 1.4, imaging subset before).
 *
 * llvmpipe blends an RGBA8 target in 8-bit fixed point: factors are 8-bit
 * (ONE_MINUS_x is 255 - x, SRC_ALPHA_SATURATE is min(As, 255 - Ad) for RGB
 * and 255 for alpha), each product is the 16-bit approximation
 * (ab + (ab >> 8) + 128) >> 8 of ab/255, and the two terms are added or
 * subtracted with unsigned saturation (FUNC_SUBTRACT and
 * FUNC_REVERSE_SUBTRACT stop at 0); MIN and MAX take the per-channel
 * minimum or maximum of source and destination without factors, as table
 * 4.1 says.  The source colour and the constant colour are converted with
 * fs_unorm8.  tests/test_fragment_ops.c checks every factor pair, every
 * equation and separate factors against OSMesa.
 */
#include "fragment_stages.h"

bool fs_blend_factor_valid(GLenum f, bool is_src)
{
    (void)is_src;
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
        /* Only a source factor in GL 1.5's table 4.2, but Mesa's
         * compatibility context accepts it as a destination factor too
         * (GL 3.3 and later allow it; measured on OSMesa: no error), and
         * its value is the same formula there. */
        return true;
    default:
        return false;
    }
}

static void set_blend_factors(fs_context *c, GLenum src_rgb, GLenum dst_rgb, GLenum src_a, GLenum dst_a)
{
    if (!fs_blend_factor_valid(src_rgb, true) || !fs_blend_factor_valid(dst_rgb, false) ||
        !fs_blend_factor_valid(src_a, true) || !fs_blend_factor_valid(dst_a, false)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.blend_src = src_rgb;
    c->frag.blend_dst = dst_rgb;
    c->frag.blend_src_alpha = src_a;
    c->frag.blend_dst_alpha = dst_a;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

void fs_exec_BlendFunc(fs_context *c, GLenum sfactor, GLenum dfactor)
{
    set_blend_factors(c, sfactor, dfactor, sfactor, dfactor);
}

void fs_exec_BlendFuncSeparate(fs_context *c, GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha,
                               GLenum dfactorAlpha)
{
    set_blend_factors(c, sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha);
}

void fs_exec_BlendEquation(fs_context *c, GLenum mode)
{
    switch (mode) {
    case GL_FUNC_ADD: case GL_FUNC_SUBTRACT: case GL_FUNC_REVERSE_SUBTRACT: case GL_MIN: case GL_MAX:
        c->frag.blend_equation = mode;
        fs_state_mark(c, GL_COLOR_BUFFER_BIT);
        return;
    default:
        fs_error(c, GL_INVALID_ENUM);
    }
}


void fs_exec_BlendColor(fs_context *c, GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
{
    /* clamped when specified (4.1.8; OSMesa's glGet answers the clamped values) */
    fs_clamp_color4(c->frag.blend_color, red, green, blue, alpha);
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

static inline unsigned mul_norm8(unsigned a, unsigned b)
{
    unsigned ab = a * b;
    return (ab + (ab >> 8) + 128u) >> 8;
}

/* Factor f (table 4.2) for channel k, from source s, destination d and
 * constant colour cc, all unorm8. */
static inline unsigned factor(GLenum f, int k, const uint8_t s[4], const uint8_t d[4], const uint8_t cc[4])
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
    case GL_CONSTANT_COLOR: return cc[k];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 255u - cc[k];
    case GL_CONSTANT_ALPHA: return cc[3];
    default: return 255u - cc[3]; /* GL_ONE_MINUS_CONSTANT_ALPHA */
    }
}

/* Equation (table 4.1) on the weighted terms, saturated to [0,255]. */
static inline unsigned equation(GLenum eq, unsigned s, unsigned d, unsigned ws, unsigned wd)
{
    switch (eq) {
    case GL_FUNC_SUBTRACT: return ws > wd ? ws - wd : 0u;
    case GL_FUNC_REVERSE_SUBTRACT: return wd > ws ? wd - ws : 0u;
    case GL_MIN: return s < d ? s : d;
    case GL_MAX: return s > d ? s : d;
    default: return ws + wd > 255u ? 255u : ws + wd; /* GL_FUNC_ADD */
    }
}

void fs_blend_rgba8(const fs_context *c, const uint8_t src[4], uint8_t dst[4])
{
    const fs_fragment_state *f = &c->frag;
    uint8_t d[4], cc[4];
    memcpy(d, dst, 4);
    for (int k = 0; k < 4; k++)
        cc[k] = fs_unorm8(f->blend_color[k]);
    for (int k = 0; k < 4; k++) {
        GLenum sf = k < 3 ? f->blend_src : f->blend_src_alpha;
        GLenum df = k < 3 ? f->blend_dst : f->blend_dst_alpha;
        unsigned ws = mul_norm8(src[k], factor(sf, k, src, d, cc));
        unsigned wd = mul_norm8(d[k], factor(df, k, src, d, cc));
        dst[k] = (uint8_t)equation(f->blend_equation, src[k], d[k], ws, wd);
    }
}
