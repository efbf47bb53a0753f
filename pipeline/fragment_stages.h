/*
 * Private interface between fragment_ops.c and the per-fragment stages
 * (GL 1.5 spec 4.1.2-4.1.10).  Masks are quad masks: bit i is pixel i of an
 * fs_quad (0 = (x,y), 1 = (x+1,y), 2 = (x,y+1), 3 = (x+1,y+1)).
 */
#ifndef FS_FRAGMENT_STAGES_H
#define FS_FRAGMENT_STAGES_H
#include <stdint.h>
#include <string.h>
#include "context.h"

/* Float colour to an 8-bit unsigned normalized value the way llvmpipe does it
 * for an RGBA8 target: clamp (NaN to 0), scale by 255 in float, round to
 * nearest even (cvtps2dq).  Adding 1.5*2^23 rounds to an integer in the
 * current (nearest-even) mode without a libm call; the low bits are that
 * integer because its ulp is exactly 1. */
static inline uint8_t fs_unorm8(float x)
{
    x = x > 0.0f ? x : 0.0f;
    x = x < 1.0f ? x : 1.0f;
    float r = x * 255.0f + 12582912.0f;
    uint32_t bits;
    memcpy(&bits, &r, sizeof bits);
    return (uint8_t)bits;
}

/* Bits of a quad mask set; used for the kill counters. */
static inline unsigned fs_popcount4(unsigned m)
{
    return (m & 1u) + ((m >> 1) & 1u) + ((m >> 2) & 1u) + ((m >> 3) & 1u);
}

/* fragment_ops.c: the stage-by-stage path every fast path must match. */
fs_quad_work fs_fragment_quad_general(fs_context *c, fs_quad *q);

/* fog.c (GL 1.5 spec 3.10): fog applied to the colours of the quad pixels
 * in mask, before the per-fragment operations; and its constants, derived
 * by the validation step from the GL_FOG_BIT state. */
void fs_fog_quad(fs_context *c, fs_quad *q, unsigned mask);
void fs_fog_validate(fs_context *c);
/* color_sum.c (3.9): the secondary colours added to the primary ones. */
void fs_color_sum_quad(fs_quad *q, unsigned mask);

/* scissor.c: the mask of quad pixels inside the scissor box. */
unsigned fs_scissor_quad(const fs_context *c, int qx, int qy, unsigned mask);
/* The scissor box clipped to the window as [x0,x1) x [y0,y1); used by
 * glClear too.  Returns false when it is empty. */
bool fs_scissor_rect(const fs_context *c, int *x0, int *y0, int *x1, int *y1);

/* alpha_test.c: the mask of quad pixels that pass the alpha test. */
unsigned fs_alpha_test_quad(const fs_context *c, const fs_quad *q, unsigned mask);

/* stencil_test.c */
bool fs_stencil_test(const fs_context *c, uint8_t stored);
uint8_t fs_stencil_apply(const fs_context *c, GLenum op, uint8_t stored);

/* depth_test.c: does fragment depth z pass against the stored value? */
bool fs_depth_test(GLenum func, uint32_t z, uint32_t stored);

/* Stencil and depth together (4.1.5, 4.1.6), because the stencil update
 * depends on the depth result.  idx[i] is the framebuffer index of pixel i.
 * Returns the mask that passed both; *tested receives the mask that reached
 * the depth test. */
unsigned fs_stencil_depth_quad(fs_context *c, const fs_quad *q, unsigned mask,
                               const size_t idx[4], unsigned *tested);

/* blend.c: blends src into dst (both RGBA8) in place in dst, 4.1.8. */
void fs_blend_rgba8(const fs_context *c, const uint8_t src[4], uint8_t dst[4]);
bool fs_blend_factor_valid(GLenum f, bool is_src);

/* logic_op.c: applies the logic op to each byte of src and dst, 4.1.10. */
void fs_logic_op_rgba8(GLenum op, const uint8_t src[4], uint8_t dst[4]);

/* clear.c: the clear depth in depth-buffer units. */
uint32_t fs_clear_depth_value(const fs_context *c);

/* write_masks.c: writes rgba into dst honouring the colour mask (4.2.2). */
void fs_masked_color_write(const fs_context *c, uint8_t *dst, const uint8_t rgba[4]);
/* A colour given as GLclampf (glClearColor, glBlendColor) clamped to
 * [0,1] when specified (GL 1.5 spec 2.1.1, 4.1.8, 4.2.3; NaN to 0). */
static inline void fs_clamp_color4(float dst[4], float r, float g, float b, float a)
{
    const float v[4] = {r, g, b, a};
    for (int k = 0; k < 4; k++)
        dst[k] = v[k] > 0.0f ? (v[k] < 1.0f ? v[k] : 1.0f) : 0.0f;
}
#endif
