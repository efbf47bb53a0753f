/*
 * Per-fragment operations chain (GL 1.5 spec 4.1, figure 4.1): pixel
 * ownership (4.1.1), scissor (4.1.2), alpha (4.1.4), stencil (4.1.5), depth
 * (4.1.6), the Occlusion Unit attachment point, blending (4.1.8), dithering
 * (4.1.9), logic op (4.1.10) and the masked write (4.2.2).
 *
 * The path is chosen per quad from the state because glEnable/glDisable
 * (owned by the driver) change c->frag directly, so there is no hook to
 * recompute a cached choice; the check is a handful of loads per quad.
 * fs_fragment_quad_general is the reference; the fast paths must give the
 * same bytes and statistics (tests/test_fragment_ops.c holds them equal).
 */
#include "fragment_stages.h"

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

/* Depth test LESS/LEQUAL with depth writes, everything else off: the state
 * of most opaque 3D drawing. */
static fs_quad_work quad_depth_write(fs_context *c, const fs_quad *q, unsigned m, bool lequal)
{
    fs_framebuffer *fb = &c->fb;
    size_t w = (size_t)fb->width;
    size_t base = (size_t)q->y * w + (size_t)q->x;
    unsigned passed = 0;
    for (int i = 0; i < 4; i++) {
        if (!(m >> i & 1u))
            continue;
        size_t k = base + (size_t)(i >> 1) * w + (size_t)(i & 1);
        uint32_t z = q->z[i];
        bool pass = lequal ? z <= fb->depth[k] : z < fb->depth[k];
        if (!pass)
            continue;
        fb->depth[k] = z;
        store_rgba8(fb->color + k * 4, q->color[i]);
        passed |= 1u << i;
    }
    unsigned np = fs_popcount4(passed);
    c->stats.killed_depth += fs_popcount4(m) - np;
    occlusion_point(c, q, m, passed);
    c->stats.fragments_written += np;
    return (fs_quad_work){0, np, np};
}

/* No tests at all: plain overwrite (2D, clears drawn as quads). */
static fs_quad_work quad_plain(fs_context *c, const fs_quad *q, unsigned m)
{
    fs_framebuffer *fb = &c->fb;
    size_t w = (size_t)fb->width;
    size_t base = (size_t)q->y * w + (size_t)q->x;
    for (int i = 0; i < 4; i++) {
        if (m >> i & 1u)
            store_rgba8(fb->color + (base + (size_t)(i >> 1) * w + (size_t)(i & 1)) * 4, q->color[i]);
    }
    occlusion_point(c, q, m, m);
    unsigned n = fs_popcount4(m);
    c->stats.fragments_written += n;
    return (fs_quad_work){0, n, n};
}

fs_quad_work fs_fragment_quad(fs_context *c, fs_quad *q)
{
    const fs_fragment_state *f = &c->frag;
    unsigned m = q->mask & 0xfu;
    if (!m)
        return (fs_quad_work){0, 0, 0};
    bool simple = !f->suppress_writes && c->draw_buffer != GL_NONE && !f->scissor_enabled && !f->alpha_enabled && !f->stencil_enabled &&
                  !f->blend_enabled && !f->logic_op_enabled &&
                  f->color_mask[0] && f->color_mask[1] && f->color_mask[2] && f->color_mask[3];
    int qx = q->x, qy = q->y;
    if (simple && qx >= 0 && qy >= 0 && qx + 1 < c->fb.width && qy + 1 < c->fb.height) {
        if (!f->depth_enabled)
            return quad_plain(c, q, m);
        if (f->depth_write && (f->depth_func == GL_LESS || f->depth_func == GL_LEQUAL))
            return quad_depth_write(c, q, m, f->depth_func == GL_LEQUAL);
    }
    return fs_fragment_quad_general(c, q);
}
