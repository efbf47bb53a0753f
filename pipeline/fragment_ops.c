/*
 * Per-fragment operations chain (GL 1.5 spec 4.1): ownership, scissor,
 * alpha, stencil, depth, blending, dithering, logic op, masked writes.
 */
#include <math.h>
#include "context.h"

void fs_fragment_state_init(fs_fragment_state *f)
{
    /* Initial values from GL 1.5 spec tables 6.19-6.21. */
    f->scissor_enabled = false;
    f->scissor[0] = f->scissor[1] = 0;
    f->scissor[2] = f->scissor[3] = 0; /* set from the window size on first use */
    f->alpha_enabled = false;
    f->alpha_func = GL_ALWAYS;
    f->alpha_ref = 0.0f;
    f->stencil_enabled = false;
    f->stencil_func = GL_ALWAYS;
    f->stencil_ref = 0;
    f->stencil_value_mask = ~0u;
    f->stencil_write_mask = ~0u;
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
}

static inline uint8_t to_unorm8(float x)
{
    if (!(x > 0.0f)) return 0;
    if (x >= 1.0f) return 255;
    return (uint8_t)lrintf(x * 255.0f);
}

void fs_fragment_quad(fs_context *c, fs_quad *q)
{
    fs_framebuffer *fb = &c->fb;
    fs_fragment_state *f = &c->frag;
    for (int i = 0; i < 4; i++) {
        if (!(q->mask & (1u << i))) continue;
        int x = q->x + (i & 1), y = q->y + (i >> 1);
        if (x < 0 || y < 0 || x >= fb->width || y >= fb->height) {
            c->stats.killed_ownership++;
            continue;
        }
        size_t idx = (size_t)y * (size_t)fb->width + (size_t)x;
        if (f->depth_enabled) {
            if (!(q->z[i] < fb->depth[idx])) { c->stats.killed_depth++; continue; }
            if (f->depth_write) fb->depth[idx] = q->z[i];
        }
        c->stats.fragments_passed_depth++;
        uint8_t *p = fb->color + idx * 4;
        for (int k = 0; k < 4; k++) p[k] = to_unorm8(q->color[i][k]);
        c->stats.fragments_written++;
    }
}
