/*
 * The common ground of the texture filters: a MIPmap pyramid seen read-only,
 * a pixel's footprint in texture space, and one signature every filter
 * implements, so that the GL sampler, the fast-footprint filter
 * (footprint_filter.c), the reference filters (texture_reference.c) and the
 * filter study all call the same code for the same arithmetic.
 *
 * Units: texture positions are in level-0 texels, (0,0) the corner of the
 * first texel, texel centres at +0.5 (GL 1.5 spec 3.8.8 with u = s*width).
 * Colours are RGBA in [0,1].
 */
#ifndef FS_TEXTURE_FILTER_H
#define FS_TEXTURE_FILTER_H
#include <stdint.h>
#include <GL/gl.h>
#include "texture_unit.h"

/* A read-only MIPmap: level l is width[l] x height[l] RGBA8 texels, row 0 at
 * v near 0.  levels counts the defined levels (1..FS_TEX_MAX_LEVELS).
 * wrap_s / wrap_t: GL_REPEAT or GL_CLAMP_TO_EDGE (GL_CLAMP is treated as
 * CLAMP_TO_EDGE here: there is no border colour in the study). */
typedef struct fs_mip_view {
    int levels;
    int width[FS_TEX_MAX_LEVELS], height[FS_TEX_MAX_LEVELS];
    const uint8_t *texels[FS_TEX_MAX_LEVELS];
    GLenum wrap_s, wrap_t;
} fs_mip_view;

/* A pixel's footprint.  (u, v): where the pixel centre maps.  The Jacobian
 * (du/dx, dv/dx, du/dy, dv/dy) at the centre.  corner_u/v: where the pixel
 * square's corners map, in the order (x-.5,y-.5), (x+.5,y-.5), (x+.5,y+.5),
 * (x-.5,y+.5); for an affine approximation they are centre +- J/2, under
 * exact perspective they form a general quadrilateral. */
typedef struct fs_footprint {
    double u, v;
    double dudx, dvdx, dudy, dvdy;
    double corner_u[4], corner_v[4];
} fs_footprint;

/* What a filter returns besides the colour, for the study's statistics. */
typedef struct fs_filter_out {
    float rgba[4];
    int texels;        /* texels fetched from memory (distinct addresses) */
    float level;       /* MIPmap level used (fractional when blended) */
    int cls;           /* filter-specific class, e.g. the hybrid's choice */
    /* What the filter read, for the cycle model's texture unit
     * (rtl_model/texture_stage.c): up to two texel rectangles in their
     * level's texels, before wrapping (nrects 0: not reported), and the
     * weighting-ROM lookups made.  Filled by the footprint filter. */
    int nrects;
    struct fs_filter_rect { int level, x0, y0, w, h; } rect[2];
    int rom_lookups;
} fs_filter_out;

/* Every filter: params points to that filter's own parameter struct (may be
 * NULL for filters without parameters).  Must give a finite colour for any
 * footprint, including NaN/Inf and zero-area ones. */
typedef void fs_filter_fn(const fs_mip_view *m, const fs_footprint *fp, const void *params,
                          fs_filter_out *out);

/* A pyramid built by 2x2 box averaging (the study's textures; GL's
 * glTexImage2D levels come from the application instead).  w and h must be
 * powers of two.  Returns 0, or -1 on bad sizes or no memory. */
typedef struct fs_mip_owned {
    fs_mip_view view;
    uint8_t *store;
} fs_mip_owned;
int fs_mip_build_box(fs_mip_owned *out, const uint8_t *rgba, int w, int h, GLenum wrap);
void fs_mip_free(fs_mip_owned *m);

/* Fetches texel (x, y) of a level, wrapped by the view's wrap modes; the
 * level is clamped to [0, levels-1]. */
void fs_mip_fetch(const fs_mip_view *m, int level, int x, int y, float out[4]);
/* Bilinear at level `level` (GL 1.5 spec eq. 3.22-3.23), (u, v) in level-0
 * texels.  Returns the number of texels read (4). */
int fs_mip_bilinear(const fs_mip_view *m, int level, double u, double v, float out[4]);
/* The 2x2 block fs_mip_bilinear reads: its first texel (x0, y0), before
 * wrapping, at the returned (clamped) level. */
int fs_mip_bilinear_block(const fs_mip_view *m, int level, double u, double v, int *x0, int *y0);
/* The levels fs_mip_trilinear reads at lambda: returns 1 (magnified, or at
 * or beyond the last level) or 2, filling levels[]. */
int fs_mip_trilinear_levels(const fs_mip_view *m, double lambda, int levels[2]);
/* Trilinear (GL's LINEAR_MIPMAP_LINEAR, 3.8.8) at level of detail lambda;
 * lambda <= 0 gives bilinear on level 0.  Returns texels read (4 or 8). */
int fs_mip_trilinear(const fs_mip_view *m, double lambda, double u, double v, float out[4]);
/* GL's isotropic level of detail from the Jacobian, eq. 3.19 with the
 * larger of the two axis lengths (Heckbert's q, Huettner eq. 4.10). */
double fs_footprint_lambda_iso(const fs_footprint *fp);
/* Fills the corners from the centre and Jacobian (affine footprint). */
void fs_footprint_affine_corners(fs_footprint *fp);
#endif
