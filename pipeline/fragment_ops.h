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
    GLenum blend_src, blend_dst;
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
} fs_fragment_state;

void fs_fragment_state_init(fs_fragment_state *f);

/* What the per-fragment operations did to one quad, for the observer
 * (observer.h) to take instead of diffing the statistics: fragments
 * discarded before the stencil and depth tests (pixel ownership, scissor,
 * alpha test), fragments that passed every test (what GL_SAMPLES_PASSED
 * counts), fragments written. */
typedef struct fs_quad_work {
    unsigned killed_early, passed, written;
} fs_quad_work;

/* Runs the per-fragment operations on a quad and writes the survivors;
 * returns what they did. */
fs_quad_work fs_fragment_quad(fs_context *c, fs_quad *q);

/*
 * Occlusion Unit attachment point (issue 3): called right after the depth
 * test with the quad and the mask of pixels whose depth (and stencil) test
 * passed.  `tested` is the mask that reached the depth test.  A NULL hook
 * costs one branch.
 */
typedef void (*fs_occlusion_hook_fn)(fs_context *c, void *user, const fs_quad *q,
                                     unsigned tested, unsigned passed);
#endif
