/*
 * Per-fragment operations chain (GL 1.5 spec 4.1, figure 4.1): pixel
 * ownership (4.1.1), scissor (4.1.2), alpha (4.1.4), stencil (4.1.5), depth
 * (4.1.6), the Occlusion Unit attachment point, blending (4.1.8), dithering
 * (4.1.9), logic op (4.1.10) and the masked write (4.2.2).
 *
 * fs_fragment_quad_general is the reference.  The path a quad takes is
 * chosen once per state change, not per quad: the validation step
 * (validate.c) computes the fragment key and picks the first entry of the
 * table of variants below that serves it; the variants must give the same
 * bytes, statistics, work records and hook calls as the general path
 * (tests/test_fragment_variants.c, tests/test_fragment_ops.c).
 */
#include "fragment_stages.h"
#include "validate.h"

void fs_fragment_state_init(fs_fragment_state *f)
{
    /* Initial values from GL 1.5 spec tables 6.19-6.21. */
    f->scissor_enabled = false;
    f->scissor[0] = f->scissor[1] = 0;
    /* GL's initial box is the window size, which is not known here; a box as
     * large as the largest framebuffer behaves identically (the window clips
     * it).  A context that knows its size may overwrite these two values. */
    f->scissor[2] = f->scissor[3] = 16384;
    f->alpha_enabled = false;
    f->alpha_func = GL_ALWAYS;
    f->alpha_ref = 0.0f;
    f->stencil_enabled = false;
    f->stencil_func = GL_ALWAYS;
    f->stencil_ref = 0;
    /* 0xff as on OSMesa (pipeline/state.def); the same tests and writes
     * as all ones on the 8-bit stencil buffer. */
    f->stencil_value_mask = 0xffu;
    f->stencil_write_mask = 0xffu;
    f->stencil_fail = f->stencil_zfail = f->stencil_zpass = GL_KEEP;
    f->depth_enabled = false;
    f->depth_func = GL_LESS;
    f->depth_write = true;
    f->blend_enabled = false;
    f->blend_src = GL_ONE;
    f->blend_dst = GL_ZERO;
    f->blend_src_alpha = GL_ONE;
    f->blend_dst_alpha = GL_ZERO;
    f->blend_equation = GL_FUNC_ADD;
    for (int i = 0; i < 4; i++)
        f->blend_color[i] = 0.0f;
    f->dither_enabled = true;
    f->logic_op_enabled = false;
    f->logic_op = GL_COPY;
    for (int i = 0; i < 4; i++) {
        f->color_mask[i] = true;
        f->clear_color[i] = 0.0f;
    }
    f->clear_depth = 1.0;
    f->clear_stencil = 0;
    f->suppress_writes = false;
    /* Derived by the first validation (the context starts all dirty). */
    f->key = 0;
    f->quad_fn = fs_fragment_quad_general;
}

static inline void store_rgba8(uint8_t *p, const float col[4])
{
    p[0] = fs_unorm8(col[0]);
    p[1] = fs_unorm8(col[1]);
    p[2] = fs_unorm8(col[2]);
    p[3] = fs_unorm8(col[3]);
}

/* Pixel ownership (4.1.1): fragments outside the window are discarded. */
static inline unsigned ownership_mask(const fs_context *c, int qx, int qy, unsigned mask)
{
    int w = c->fb.width, h = c->fb.height;
    if (qx >= 0 && qy >= 0 && qx + 1 < w && qy + 1 < h)
        return mask;
    unsigned in = 0;
    for (int i = 0; i < 4; i++) {
        int x = qx + (i & 1), y = qy + (i >> 1);
        if (x >= 0 && y >= 0 && x < w && y < h)
            in |= 1u << i;
    }
    return mask & in;
}

static inline void occlusion_point(fs_context *c, const fs_quad *q, unsigned tested, unsigned passed)
{
    /* === Occlusion Unit attachment point (issue 3 attaches the Occlusion
     * Unit here): after the stencil and depth tests, before blending.  passed
     * is what GL_SAMPLES_PASSED counts (alpha, stencil and depth passed). */
    if (c->occlusion_hook)
        c->occlusion_hook(c, c->occlusion_user, q, tested, passed);
    c->stats.fragments_passed_depth += fs_popcount4(passed);
}

fs_quad_work fs_fragment_quad_general(fs_context *c, fs_quad *q)
{
    const fs_fragment_state *f = &c->frag;
    fs_framebuffer *fb = &c->fb;
    unsigned m = q->mask & 0xfu, n;
    fs_quad_work w = {0, 0, 0};

    /* The colour sum (GL 1.5 spec 3.9) and fog (3.10) end the
     * rasterization stage, before 4.1. */
    if ((f->key & FS_FKEY_COLOR_SUM) && c->raster.interpolate_color2)
        fs_color_sum_quad(q, m);
    if (f->key & FS_FKEY_FOG)
        fs_fog_quad(c, q, m);
    n = ownership_mask(c, q->x, q->y, m);
    c->stats.killed_ownership += fs_popcount4(m & ~n);
    m = n;
    if (f->scissor_enabled) {
        n = fs_scissor_quad(c, q->x, q->y, m);
        c->stats.killed_scissor += fs_popcount4(m & ~n);
        m = n;
    }
    if (f->alpha_enabled) {
        n = fs_alpha_test_quad(c, q, m);
        c->stats.killed_alpha += fs_popcount4(m & ~n);
        m = n;
    }
    w.killed_early = fs_popcount4((q->mask & 0xfu) & ~m);
    if (!m)
        return w;

    size_t idx[4];
    for (int i = 0; i < 4; i++)
        idx[i] = (size_t)(q->y + (i >> 1)) * (size_t)fb->width + (size_t)(q->x + (i & 1));

    unsigned tested;
    unsigned passed = fs_stencil_depth_quad(c, q, m, idx, &tested);
    occlusion_point(c, q, tested, passed);
    w.passed = fs_popcount4(passed);
    if (f->suppress_writes)
        return w;
    w.written = w.passed;
    if (c->draw_buffer == GL_NONE) {
        /* glDrawBuffer(GL_NONE): no colour buffer is written (4.2.1). */
        c->stats.fragments_written += w.written;
        return w;
    }

    /* Dithering (4.1.9) is enabled by default but llvmpipe does not dither
     * an RGBA8 buffer, so it has no stage here. */
    bool all_channels = f->color_mask[0] && f->color_mask[1] && f->color_mask[2] && f->color_mask[3];
    for (int i = 0; i < 4; i++) {
        if (!(passed >> i & 1u))
            continue;
        uint8_t *p = fb->color + idx[i] * 4;
        uint8_t src[4], out[4];
        store_rgba8(src, q->color[i]);
        if (f->logic_op_enabled) {
            memcpy(out, p, 4);
            fs_logic_op_rgba8(f->logic_op, src, out);
        } else if (f->blend_enabled) {
            memcpy(out, p, 4);
            fs_blend_rgba8(c, src, out);
        } else {
            memcpy(out, src, 4);
        }
        if (all_channels)
            memcpy(p, out, 4);
        else
            fs_masked_color_write(c, p, out);
    }
    c->stats.fragments_written += w.written;
    return w;
}

/* ---- the variants ---- */

/* The product of blending, as blend.c computes it for llvmpipe: the 16-bit
 * approximation of ab/255. */
static inline unsigned mul_norm8(unsigned a, unsigned b)
{
    unsigned ab = a * b;
    return (ab + (ab >> 8) + 128u) >> 8;
}

/* The blending variants, 4.1.8: source factor GL_SRC_ALPHA and the
 * destination factor GL_ONE_MINUS_SRC_ALPHA (transparency) or GL_ONE
 * (additive), with the products and the saturation of fs_blend_rgba8 but
 * without its choice of factor per channel.  The mode is the destination
 * factor (0: blending off). */
enum blend_mode { B_OFF = 0, B_SRC_ALPHA = GL_ONE_MINUS_SRC_ALPHA, B_SRC_ALPHA_ONE = GL_ONE };

static inline __attribute__((always_inline)) void blend_src_alpha(uint8_t *p, const float col[4], enum blend_mode b)
{
    uint8_t s[4];
    store_rgba8(s, col);
    unsigned a = s[3], da = b == B_SRC_ALPHA ? 255u - a : 255u;
    for (int k = 0; k < 4; k++) {
        unsigned v = mul_norm8(s[k], a) + mul_norm8(p[k], da);
        p[k] = (uint8_t)(v > 255u ? 255u : v);
    }
}

/* The depth test's variants, 4.1.6: the depth function (0: test off). */
enum depth_mode { Z_OFF = 0, Z_LESS = GL_LESS, Z_LEQUAL = GL_LEQUAL, Z_GREATER = GL_GREATER, Z_ALWAYS = GL_ALWAYS };

static inline __attribute__((always_inline)) bool depth_pass(enum depth_mode zmode, uint32_t z, uint32_t stored)
{
    return zmode == Z_LESS ? z < stored : zmode == Z_LEQUAL ? z <= stored : zmode == Z_GREATER ? z > stored : true;
}

/* The general path for a quad wholly inside the window with scissor,
 * alpha, stencil and logic op off, all colour channels written, a colour
 * buffer to draw to and no occlusion mode: only the depth test (one of
 * enum depth_mode, with or without depth writes) and blending (one of
 * enum blend_mode) remain.  The variants give the arguments as constants,
 * so each is compiled without the branches the others need.  The
 * attachment point is called after the writes here: the hook sees the
 * quad and the masks, never the colour buffer. */
static inline __attribute__((always_inline)) fs_quad_work
quad_fast(fs_context *c, const fs_quad *q, enum depth_mode zmode, bool zwrite, enum blend_mode blend)
{
    fs_framebuffer *fb = &c->fb;
    unsigned m = q->mask & 0xfu;
    size_t w = (size_t)fb->width;
    size_t base = (size_t)q->y * w + (size_t)q->x;
    unsigned passed = 0;
    for (int i = 0; i < 4; i++) {
        if (!(m >> i & 1u))
            continue;
        size_t k = base + (size_t)(i >> 1) * w + (size_t)(i & 1);
        if (zmode != Z_OFF) {
            uint32_t z = q->z[i];
            if (!depth_pass(zmode, z, fb->depth[k]))
                continue;
            if (zwrite)
                fb->depth[k] = z;
        }
        if (blend != B_OFF)
            blend_src_alpha(fb->color + k * 4, q->color[i], blend);
        else
            store_rgba8(fb->color + k * 4, q->color[i]);
        passed |= 1u << i;
    }
    unsigned np = fs_popcount4(passed);
    c->stats.killed_depth += fs_popcount4(m) - np;
    occlusion_point(c, q, m, passed);
    c->stats.fragments_written += np;
    return (fs_quad_work){0, np, np};
}

/* The fields every fast variant tests: all of them off but the colour
 * mask, which has all four channels on; and those of the depth test and
 * blending when the variant has them. */
#define FAST_MASK                                                                             \
    (FS_FKEY_NO_COLOR | FS_FKEY_SUPPRESS | FS_FKEY_SCISSOR | FS_FKEY_ALPHA | FS_FKEY_STENCIL | \
     FS_FKEY_LOGIC | FS_FKEY_COLOR_MASK_MASK | FS_FKEY_DEPTH | FS_FKEY_BLEND | FS_FKEY_FOG | \
     FS_FKEY_COLOR_SUM)
#define FAST_VALUE (15u << FS_FKEY_COLOR_MASK_SHIFT)
#define DEPTH_MASK(z) ((z) ? FS_FKEY_DEPTH_WRITE | FS_FKEY_DEPTH_FUNC_MASK : 0u)
#define DEPTH_VALUE(z, zwrite) \
    ((z) ? FS_FKEY_DEPTH | FS_FKEY_DEPTH_FUNC(z) | ((zwrite) ? FS_FKEY_DEPTH_WRITE : 0u) : 0u)
#define BLEND_MASK(b) ((b) ? FS_FKEY_BLEND_SRC_MASK | FS_FKEY_BLEND_DST_MASK | FS_FKEY_BLEND_EXT : 0u)
#define BLEND_VALUE(b) ((b) ? FS_FKEY_BLEND | FS_FKEY_BLEND_FUNC(GL_SRC_ALPHA, b) : 0u)

/* One function per row of fragment_variants.def. */
#define FS_FRAGMENT_VARIANT(fn, name, zmode, zwrite, blend) \
    static fs_quad_work fn(fs_context *c, fs_quad *q) { return quad_fast(c, q, zmode, zwrite, blend); }
#include "fragment_variants.def"

static const fs_fragment_variant variants[] = {
#define FS_FRAGMENT_VARIANT(fn, name, zmode, zwrite, blend) \
    {name, FAST_MASK | DEPTH_MASK(zmode) | BLEND_MASK(blend), FAST_VALUE | DEPTH_VALUE(zmode, zwrite) | BLEND_VALUE(blend), fn},
#include "fragment_variants.def"
    {"general", 0, 0, fs_fragment_quad_general},
};

const fs_fragment_variant *fs_fragment_variants(int *count)
{
    *count = (int)(sizeof variants / sizeof variants[0]);
    return variants;
}

fs_quad_work fs_fragment_quad_with(fs_context *c, fs_quad *q, fs_fragment_fn fn)
{
    if (!(q->mask & 0xfu))
        return (fs_quad_work){0, 0, 0};
    int qx = q->x, qy = q->y;
    if (qx >= 0 && qy >= 0 && qx + 1 < c->fb.width && qy + 1 < c->fb.height)
        return fn(c, q);
    return fs_fragment_quad_general(c, q);
}

fs_quad_work fs_fragment_quad(fs_context *c, fs_quad *q)
{
    if (c->dirty)
        fs_validate(c);
    return fs_fragment_quad_with(c, q, c->frag.quad_fn);
}
