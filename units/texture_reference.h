/*
 * Reference texture filters for the filter study (issue 4, item 4), each an
 * fs_filter_fn (texture_filter.h):
 *
 *  - footprint assembly (Schilling, Knittel, Strasser, "Texram", IEEE CG&A
 *    16(3), 1996; restated in Huettner's dissertation 4.3.1, eq. 4.12-4.13);
 *  - N-probe anisotropic filtering in the style of the recommended
 *    implementation of EXT_texture_filter_anisotropic;
 *  - EWA with a Gaussian (Heckbert, "Fundamentals of texture mapping and
 *    image warping", 1989, 3.5.8);
 *  - a ground truth: the box average over the pixel's exact preimage of the
 *    bilinearly reconstructed level 0, by stratified supersampling.
 *
 * And the study's scene: a textured ground plane seen by a pinhole camera,
 * with the exact screen -> texture mapping and exact pixel footprints.
 *
 * Screen coordinates are GL window coordinates: x right, y up, pixel (i, j)
 * covers [i, i+1] x [j, j+1]; texture positions are level-0 texels.
 */
#ifndef FS_TEXTURE_REFERENCE_H
#define FS_TEXTURE_REFERENCE_H
#include <stdbool.h>
#include <stddef.h>
#include "texture_filter.h"

/* ---- footprint assembly ------------------------------------------------ */
typedef struct fs_fa_params {
    int max_n;          /* most probes per pixel (power of two, >= 1) */
} fs_fa_params;
/* The plan: N probes at level lambda, stepping (du, dv) between probes,
 * centred on the footprint centre.  Returns N. */
int fs_fa_plan(const fs_footprint *fp, const fs_fa_params *p, double *lambda, double *du, double *dv);
void fs_filter_footprint_assembly(const fs_mip_view *m, const fs_footprint *fp, const void *params,
                                  fs_filter_out *out);

/* ---- EXT_texture_filter_anisotropic-style N-probe ------------------------ */
typedef struct fs_aniso_params {
    double max_aniso;   /* TEXTURE_MAX_ANISOTROPY_EXT, >= 1 */
} fs_aniso_params;
int fs_aniso_plan(const fs_footprint *fp, const fs_aniso_params *p, double *lambda, double *du, double *dv);
void fs_filter_aniso(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out);

/* ---- EWA with a Gaussian ------------------------------------------------- */
typedef struct fs_ewa_params {
    double sigma_px;      /* standard deviation of the screen-space Gaussian, pixels */
    double radius;        /* truncation radius, in standard deviations */
    double min_sigma;     /* added to every axis, in texels of the chosen level: the
                             minimum-radius enlargement (reconstruction filter) */
    double minor_texels;  /* level chosen so the minor axis's deviation spans >= this */
    double max_aniso;     /* major/minor ratio beyond which the level is raised */
    int max_texels;       /* support larger than this moves up a level */
} fs_ewa_params;
/* The kernel on its level: weight exp(-Q/2) with
 * Q = A du^2 + B du dv + C dv^2 (du, dv from the centre, in level texels),
 * truncated at Q <= radius^2; texels x0..x1, y0..y1 bound the support. */
typedef struct fs_ewa_kernel {
    int level;
    double cu, cv;          /* centre in level texels */
    double A, B, C, q_max;
    double det_sigma;       /* determinant of the covariance (level texels^2) */
    int x0, x1, y0, y1;
} fs_ewa_kernel;
/* Returns 0, or -1 when the footprint is not finite (then the filter falls
 * back to the top level). */
int fs_ewa_setup(const fs_mip_view *m, const fs_footprint *fp, const fs_ewa_params *p, fs_ewa_kernel *k);
void fs_filter_ewa(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out);

/* ---- ground truth ---------------------------------------------------------- */
typedef struct fs_truth_params {
    int min_n;            /* at least min_n x min_n strata per pixel (>= 16 in the study) */
    int max_n;            /* at most max_n along each axis */
    double spacing;       /* wanted sample spacing in level-0 texels along each edge */
    unsigned seed;        /* jitter seed (deterministic) */
} fs_truth_params;
/* The box average over the preimage of the pixel square: the homography that
 * maps the unit square onto the footprint's four corners (Heckbert 1989,
 * 2.2.3, square-to-quad) is the exact perspective mapping of a planar
 * surface; n x n strata, one jittered sample each, bilinear on level 0.
 * Falls back to the affine corners when the corners are not usable. */
void fs_filter_truth(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out);
/* The square-to-quad mapping itself: (s, t) in [0,1]^2 -> (u, v). Returns
 * false when the corners do not define a proper (non-folding) mapping. */
typedef struct fs_homography { double a, b, c, d, e, f, g, h; } fs_homography;
bool fs_homography_from_corners(const fs_footprint *fp, fs_homography *H);
void fs_homography_map(const fs_homography *H, double s, double t, double *u, double *v);

/* ---- the ground-plane scene -------------------------------------------- */
/* A pinhole camera at height eye_height above the plane z = 0, looking along
 * +y and pitched down by pitch_deg; the texture lies on the plane scaled by
 * texels_per_unit and rotated by tex_rotate_deg, offset by (u0, v0).  Pixels
 * whose centre ray meets the plane farther than far_dist (ground distance)
 * or not at all show the sky. */
typedef struct fs_ground_scene {
    int width, height;
    double eye_height, pitch_deg, fov_y_deg;
    double texels_per_unit, tex_rotate_deg, u0, v0;
    double far_dist;
} fs_ground_scene;
/* Checks the description; 0, or -1 with a message. */
int fs_ground_scene_check(const fs_ground_scene *s, char *err, size_t errlen);
/* Exact mapping of screen position (x, y) to texture (u, v); false when the
 * ray does not meet the plane in front of the camera. */
bool fs_ground_map(const fs_ground_scene *s, double x, double y, double *u, double *v);
/* Whether pixel (px, py) shows the plane (centre within far_dist and all four
 * corners on the plane). */
bool fs_ground_pixel_visible(const fs_ground_scene *s, int px, int py);
/* The exact footprint of a pixel: centre, analytic Jacobian at the centre,
 * the four exactly projected corners.  False when the pixel is not visible. */
bool fs_ground_footprint(const fs_ground_scene *s, int px, int py, fs_footprint *fp);

/* ---- comparison ------------------------------------------------------------ */
/* PSNR over RGB of two float RGBA images (values in [0,1], peak 1), over the
 * pixels where mask is non-zero (all when mask is NULL).  INFINITY when
 * identical, NAN when no pixel is compared. */
double fs_psnr_rgb(const float *a, const float *b, const uint8_t *mask, size_t pixels);

/* A 32-bit integer hash (xor-shift-multiply finaliser) for the ground
 * truth's jitter and the study's procedural textures: deterministic on
 * every platform and compiler. */
uint32_t fs_hash32(uint32_t x);
#endif
