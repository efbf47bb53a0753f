/*
 * Per-fragment operations (GL 1.5 spec 4.1), in GL's order: pixel ownership,
 * scissor, alpha, stencil, depth, [Occlusion Unit attachment point],
 * blending, logic op, masked writes.  Each test lives in its own file
 * (scissor.c, alpha_test.c, stencil_test.c, depth_test.c, blend.c,
 * logic_op.c); fragment_ops.c chains them.
 */
#ifndef FS_FRAGMENT_OPS_H
#define FS_FRAGMENT_OPS_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>
#include "rasterizer.h"

/* What the per-fragment operations did to one quad, for the observer
 * (observer.h) to take instead of diffing the statistics: fragments
 * discarded before the stencil and depth tests (pixel ownership, scissor,
 * alpha test), fragments that passed every test (what GL_SAMPLES_PASSED
 * counts), fragments written. */
typedef struct fs_quad_work {
    unsigned killed_early, passed, written;
} fs_quad_work;

/* A per-fragment path: runs the operations on a quad and writes the
 * survivors; returns what they did. */
typedef fs_quad_work (*fs_fragment_fn)(fs_context *c, fs_quad *q);

typedef struct fs_fragment_state {
    /* scissor (4.1.2) */
    bool scissor_enabled;
    GLint scissor[4];           /* x, y, width, height */
    /* alpha test (4.1.4) */
    bool alpha_enabled;
    GLenum alpha_func;
    float alpha_ref;
    /* stencil (4.1.5) */
    bool stencil_enabled;
    GLenum stencil_func;
    GLint stencil_ref;
    GLuint stencil_value_mask, stencil_write_mask;
    GLenum stencil_fail, stencil_zfail, stencil_zpass;
    /* depth (4.1.6) */
    bool depth_enabled;
    GLenum depth_func;
    bool depth_write;
    /* blending (4.1.8) */
    bool blend_enabled;
    GLenum blend_src, blend_dst;             /* the RGB factors (GL_BLEND_SRC_RGB, _DST_RGB) */
    GLenum blend_src_alpha, blend_dst_alpha; /* glBlendFuncSeparate's alpha factors (1.4) */
    GLenum blend_equation;                   /* glBlendEquation (1.4, table 4.1) */
    float blend_color[4];                    /* glBlendColor, clamped to [0,1] */
    /* dithering (4.1.9) has no effect on an RGBA8 buffer in llvmpipe */
    bool dither_enabled;
    /* logic op (4.1.10) */
    bool logic_op_enabled;      /* GL_COLOR_LOGIC_OP */
    GLenum logic_op;
    /* masks and clear values (4.2) */
    bool color_mask[4];
    float clear_color[4];
    double clear_depth;
    GLint clear_stencil;
    /* Set while an occlusion render mode is active (units/occlusion_gl.c):
     * every test still runs, but nothing is written to the colour, depth or
     * stencil buffer and glClear does nothing, as in GL_SELECT (GL 1.5 spec
     * 5.2; Huettner 1999, 3.2.1: occlusion modes do not change the
     * framebuffer). */
    bool suppress_writes;
    /* Derived state, never set by a command: the fragment key of the state
     * above and the path the table of variants gives for it, built by the
     * validation step (pipeline/validate.c) when c->dirty says the state
     * changed.  glPushAttrib saves neither (they are in no state row). */
    uint32_t key;
    fs_fragment_fn quad_fn;
} fs_fragment_state;

void fs_fragment_state_init(fs_fragment_state *f);

/* Runs the per-fragment operations on a quad and writes the survivors;
 * returns what they did.  Validates first if the state changed. */
fs_quad_work fs_fragment_quad(fs_context *c, fs_quad *q);

/*
 * The table of variants: specialised paths for common states, each the
 * general path (fs_fragment_quad_general, the reference) with the stages
 * its state makes no-ops left out, and so giving the same bytes,
 * statistics, work record and Occlusion Unit hook calls
 * (tests/test_fragment_variants.c holds them equal).  An entry serves the
 * fragment keys k (pipeline/validate.h) with (k & mask) == value; the first
 * that matches is chosen; the last entry, the general path, matches all.
 * A variant is only given quads wholly inside the window with a non-empty
 * mask, so it needs no pixel ownership test (4.1.1).
 */
typedef struct fs_fragment_variant {
    const char *name;
    uint32_t mask, value;
    fs_fragment_fn fn;
} fs_fragment_variant;
const fs_fragment_variant *fs_fragment_variants(int *count);

/* fs_fragment_quad with the path fn instead of the validated one: fn for
 * quads wholly inside the window, the general path for the others. */
fs_quad_work fs_fragment_quad_with(fs_context *c, fs_quad *q, fs_fragment_fn fn);

/*
 * Occlusion Unit attachment point (issue 3): called right after the depth
 * test with the quad and the mask of pixels whose depth (and stencil) test
 * passed.  `tested` is the mask that reached the depth test.  A NULL hook
 * costs one branch.
 */
typedef void (*fs_occlusion_hook_fn)(fs_context *c, void *user, const fs_quad *q,
                                     unsigned tested, unsigned passed);
#endif
