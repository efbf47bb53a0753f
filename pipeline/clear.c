/*
 * Clearing the buffers (GL 1.5 spec 4.2.3): glClear, glClearColor,
 * glClearDepth, glClearStencil.  Clear honours pixel ownership, the scissor
 * box and the colour, depth and stencil write masks, and nothing else
 * (no alpha/stencil/depth test, blending or logic op).
 */
#include <math.h>
#include "fragment_stages.h"


void fs_exec_ClearColor(fs_context *c, GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
{
    fs_clamp_color4(c->frag.clear_color, red, green, blue, alpha);
}

void fs_exec_ClearDepth(fs_context *c, GLclampd depth)
{
    c->frag.clear_depth = depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0;
}

void fs_exec_ClearStencil(fs_context *c, GLint s)
{
    c->frag.clear_stencil = s;
}

/* 4.2.3: the accumulation buffer's clear colour, clamped to [-1, 1]
 * (pipeline/accum.c clears with it), and the colour index clear value,
 * which only answers glGet (no colour index mode). */
void fs_exec_ClearAccum(fs_context *c, GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha)
{
    const float v[4] = {red, green, blue, alpha};
    for (int k = 0; k < 4; k++)
        c->st.accum_clear[k] = v[k] > -1.0f ? (v[k] < 1.0f ? v[k] : 1.0f) : -1.0f;
    fs_state_mark(c, GL_ACCUM_BUFFER_BIT);
}

/* OSMesa keeps the index as an integer (measured: 3.7 reads back as 3,
 * -5 as -5, 4e9 as -294967296): toward zero, to 64 bits, of which the low
 * 32 are the value; a float beyond 64 bits or NaN gives 0. */
void fs_exec_ClearIndex(fs_context *c, GLfloat index)
{
    int64_t i = index > -9.2e18f && index < 9.2e18f ? (int64_t)index : INT64_MIN;
    c->st.index_clear = (GLint)(uint32_t)i;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
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
    fs_modelview_analyse(c);
    const GLbitfield all = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                           GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if (mask & ~all) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->stats.clears++;
    /* Outside GL_RENDER mode Mesa clears nothing (its glClear acts only in
     * GL_RENDER); occlusion modes follow GL_SELECT (see suppress_writes). */
    if (c->frag.suppress_writes || fs_render_mode_diverts(&c->rmode))
        return;
    int x0, y0, x1, y1;
    if (!fs_scissor_rect(c, &x0, &y0, &x1, &y1))
        return;
    fs_framebuffer *fb = &c->fb;
    const fs_fragment_state *f = &c->frag;
    size_t w = (size_t)fb->width;
    FS_OBSERVE(c, clear, c, mask, x1 - x0, y1 - y0);
    if (mask & GL_ACCUM_BUFFER_BIT)
        fs_accum_clear(c, x0, y0, x1, y1);

    bool color = (mask & GL_COLOR_BUFFER_BIT) && c->draw_buffer != GL_NONE && /* 4.2.1 */
                 (f->color_mask[0] || f->color_mask[1] || f->color_mask[2] || f->color_mask[3]);
    bool all_channels = f->color_mask[0] && f->color_mask[1] && f->color_mask[2] && f->color_mask[3];
    uint8_t rgba[4];
    for (int k = 0; k < 4; k++)
        rgba[k] = fs_unorm8(f->clear_color[k]);
    bool depth = (mask & GL_DEPTH_BUFFER_BIT) && f->depth_write;
    uint32_t z = fs_clear_depth_value(c);
    unsigned smax = fb->stencil_bits > 0 ? (1u << fb->stencil_bits) - 1u : 0u;
    unsigned wm = f->stencil_write_mask & smax;
    /* Only the low s bits of the clear value are used (4.2.3). */
    unsigned sv = (unsigned)f->clear_stencil & smax;
    bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && wm;
    /* The observer's tile mask (observer.h): nothing outside the masked
     * tiles is rendered, so only they are cleared (a 1024 x 1024 window's
     * clear cost a twentieth of such a one-frame run). */
    const fs_tile_mask *ts = fs_tile_mask_active(c);
    const int sh = ts ? ts->shift : 0;
    for (int y = y0; y < y1; y++) {
        for (int tx = ts ? x0 >> sh : 0; tx <= (ts ? (x1 - 1) >> sh : 0); tx++) {
            int a = x0, b = x1;
            if (ts) {
                if (!fs_tile_mask_has(ts, (uint32_t)tx, (uint32_t)y >> sh))
                    continue;
                a = tx << sh > x0 ? tx << sh : x0;
                b = (tx + 1) << sh < x1 ? (tx + 1) << sh : x1;
            }
            size_t o = (size_t)y * w;
            if (color) {
                uint8_t *p = fb->color + (o + (size_t)a) * 4;
                for (int x = a; x < b; x++, p += 4) {
                    if (all_channels)
                        memcpy(p, rgba, 4);
                    else
                        fs_masked_color_write(c, p, rgba);
                }
            }
            if (depth)
                for (int x = a; x < b; x++)
                    fb->depth[o + (size_t)x] = z;
            if (stencil)
                for (int x = a; x < b; x++)
                    fb->stencil[o + (size_t)x] = (uint8_t)((fb->stencil[o + (size_t)x] & ~wm) | (sv & wm));
        }
    }
}
