/*
 * The validation step (issue 18 item 2): state derived from the GL state
 * is built once when the state changed (fs_context.dirty, glPushAttrib's
 * bits, pipeline/state.h), not per quad.  Today it derives the fragment
 * half: the fragment key, a compact word of the state that decides which
 * per-fragment path a quad takes (GL 1.5 spec 4.1, 4.2), and the fragment
 * function chosen by it from the table of variants (pipeline/fragment_ops.c).
 */
#ifndef FS_VALIDATE_H
#define FS_VALIDATE_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>
#include "state.h"

/* The fields of the fragment key.  A flag is the raw enable: a variant
 * that is only right with a feature off tests the flag, so an enable that
 * has no effect (stencil without stencil bits) just takes the general path. */
#define FS_FKEY_NO_COLOR (1u << 0)     /* glDrawBuffer(GL_NONE), 4.2.1 */
#define FS_FKEY_SUPPRESS (1u << 1)     /* an occlusion mode writes nothing */
#define FS_FKEY_SCISSOR (1u << 2)      /* 4.1.2 */
#define FS_FKEY_ALPHA (1u << 3)        /* 4.1.4 */
#define FS_FKEY_STENCIL (1u << 4)      /* 4.1.5 */
#define FS_FKEY_DEPTH (1u << 5)        /* 4.1.6 */
#define FS_FKEY_DEPTH_WRITE (1u << 6)  /* glDepthMask, 4.2.2 */
#define FS_FKEY_DEPTH_FUNC_SHIFT 7     /* 3 bits: func - GL_NEVER */
#define FS_FKEY_BLEND (1u << 10)       /* 4.1.8 */
#define FS_FKEY_BLEND_SRC_SHIFT 11     /* 4 bits: fs_fkey_blend_factor */
#define FS_FKEY_BLEND_DST_SHIFT 15     /* 4 bits */
#define FS_FKEY_LOGIC (1u << 19)       /* GL_COLOR_LOGIC_OP, 4.1.10 */
#define FS_FKEY_LOGIC_OP_SHIFT 20      /* 4 bits: op - GL_CLEAR */
#define FS_FKEY_COLOR_MASK_SHIFT 24    /* 4 bits: bit k is channel k, 4.2.2 */
/* Blending other than one factor pair under FUNC_ADD: separate alpha
 * factors or another equation (GL 1.4, 4.1.8).  The constant colour is not
 * in the key: only the general path reads it. */
#define FS_FKEY_BLEND_EXT (1u << 28)
#define FS_FKEY_FOG (1u << 29)         /* GL_FOG, 3.10: only the general path fogs */
#define FS_FKEY_COLOR_SUM (1u << 30)   /* 3.9, fs_raster_state.interpolate_color2: likewise */

#define FS_FKEY_DEPTH_FUNC_MASK (7u << FS_FKEY_DEPTH_FUNC_SHIFT)
#define FS_FKEY_BLEND_SRC_MASK (15u << FS_FKEY_BLEND_SRC_SHIFT)
#define FS_FKEY_BLEND_DST_MASK (15u << FS_FKEY_BLEND_DST_SHIFT)
#define FS_FKEY_LOGIC_OP_MASK (15u << FS_FKEY_LOGIC_OP_SHIFT)
#define FS_FKEY_COLOR_MASK_MASK (15u << FS_FKEY_COLOR_MASK_SHIFT)
#define FS_FKEY_DEPTH_FUNC(func) ((uint32_t)((func) - GL_NEVER) << FS_FKEY_DEPTH_FUNC_SHIFT)
/* The 15 blend factors of GL 1.5 spec table 4.2 as 0..14, for constants
 * (FS_FKEY_BLEND_FUNC) and for any value (fs_fkey_blend_factor: 15 for an
 * enum that is none of them). */
#define FS_FKEY_BLEND_FACTOR(f)                                                   \
    ((f) == GL_ZERO || (f) == GL_ONE ? (uint32_t)(f)                              \
     : (f) < GL_CONSTANT_COLOR      ? 2u + (uint32_t)((f) - GL_SRC_COLOR)         \
                                    : 11u + (uint32_t)((f) - GL_CONSTANT_COLOR))
#define FS_FKEY_BLEND_FUNC(src, dst) \
    (FS_FKEY_BLEND_FACTOR(src) << FS_FKEY_BLEND_SRC_SHIFT | FS_FKEY_BLEND_FACTOR(dst) << FS_FKEY_BLEND_DST_SHIFT)
static inline uint32_t fs_fkey_blend_factor(GLenum f)
{
    bool known = f == GL_ZERO || f == GL_ONE || (f >= GL_SRC_COLOR && f <= GL_SRC_ALPHA_SATURATE) ||
                 (f >= GL_CONSTANT_COLOR && f <= GL_ONE_MINUS_CONSTANT_ALPHA);
    return known ? FS_FKEY_BLEND_FACTOR(f) : 15u;
}

/* The groups whose state the fragment key reads. */
#define FS_FRAGMENT_KEY_GROUPS                                                              \
    (GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | \
     GL_SCISSOR_BIT | GL_FOG_BIT | FS_DIRTY_OCCLUSION_MODE)

/* The fragment key of the context's current state, computed from scratch. */
uint32_t fs_fragment_key(const fs_context *c);

/* The validation step: rebuilds what the dirty groups affect and clears
 * c->dirty.  Called before a quad whenever c->dirty is not 0
 * (fs_fragment_quad), so the derived state is never stale. */
void fs_validate(fs_context *c);
#endif
