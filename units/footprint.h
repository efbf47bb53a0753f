/*
 * Fast footprint filtering (Huettner, dissertation 1999, section 4.3.2-4.3.6;
 * Huettner & Strasser, "Fast footprint MIPmapping", Graphics Hardware 1999).
 *
 * A texel budget M per pixel.  The level lambda follows from the footprint's
 * bounding box (eq. 4.14-4.17); the footprint's corners are snapped to the
 * level's texel grid (integer positions "I", or texel mid-points "MS" with
 * the tie rule "up and right"); the quadrilateral is split into two
 * triangles, and each triangle's weight vector of M 8-bit coverages is read
 * from a weighting ROM through a three-stage pointer structure indexed by
 * the triangle's corners (Fig. 4.31); C = sum T[i] * (w1[i] + w2[i])
 * (eq. 4.19), divided by the sum of the weights.
 *
 * Files: footprint_rom.c (ROM generation, the pointer structure, the Table
 * 4.3 counts), footprint_filter.c (level selection, snapping, lookup,
 * evaluation, the hybrid selector).  The GL interface is the extension
 * GL_FRAGSIM_footprint_filter (docs/extensions/footprint_filter.txt).
 */
#ifndef FS_FOOTPRINT_H
#define FS_FOOTPRINT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "texture_filter.h"

/* The ROMs and lookup structures for one M. */
typedef struct fs_footprint_filter fs_footprint_filter;

/* M in {8,16,32,64}; midpoint: mid-point snapping (else integer positions);
 * hybrid: the hybrid selector (trilinear for near-isotropic footprints,
 * bilinear on level 0 when the footprint is smaller than a texel, the
 * footprint filter otherwise, up to 2M texels in two steps).  NULL on a bad
 * M or no memory.  The ROMs are generated here (no global state). */
fs_footprint_filter *fs_footprint_filter_create(int M, bool midpoint, bool hybrid);
void fs_footprint_filter_destroy(fs_footprint_filter *f);

/* fs_filter_fn; params is the fs_footprint_filter*.  out->texels: texels
 * fetched (the whole a x b array of every step, distinct addresses);
 * out->level: lambda used (the mean of the two halves' levels when the
 * footprint was cut in two); out->cls: one of the classes below
 * (FOOTPRINT_2M: two steps, each with its own array). */
void fs_filter_footprint(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out);
enum { FS_FP_CLASS_BILINEAR0, FS_FP_CLASS_TRILINEAR, FS_FP_CLASS_FOOTPRINT, FS_FP_CLASS_FOOTPRINT_2M };

/* fs_filter_footprint that also reports the ROM lookups made (0..2). */
void fs_footprint_filter_run(const fs_footprint_filter *f, const fs_mip_view *m, const fs_footprint *fp,
                             fs_filter_out *out, int *rom_lookups);

/* The hybrid selector's isotropy limit: footprints whose axis ratio
 * (larger over smaller singular value of the Jacobian) is at most this are
 * MIPmapped.  Default FS_FP_ISO_LIMIT; values < 1 or NaN are ignored.
 * The dissertation (4.3.6) gives no value.  2 is chosen a priori: trilinear
 * MIPmapping at the isotropic level (the larger axis) blurs the minor axis
 * by the axis ratio, and a factor 2 is what MIPmapping already accepts
 * between two levels; beyond it the footprint counts as distorted. */
#define FS_FP_ISO_LIMIT 2.0
void fs_footprint_filter_set_iso_limit(fs_footprint_filter *f, double ratio);
int fs_footprint_filter_budget(const fs_footprint_filter *f);

/* Eq. 4.14-4.17: the level for a bounding box of u x v level-0 texels and
 * budget M (m and n returned when not NULL).  Not clamped to the pyramid;
 * 0 for degenerate or non-finite input. */
int fs_footprint_lambda(double u, double v, int M, double *m, double *n);

/* ---- the weighting ROM of one a x b texel array (footprint_rom.c) ---- */

/* Corner positions are (x, y) with 0 <= x < px, 0 <= y < py: lattice points
 * (I: px = a+1, py = b+1) or texel mid-points (MS: px = a, py = b).  A
 * position lies on the border when x or y is extreme.  The ROM holds the
 * triangles (c1, c2, c3) with c1 != c2 on the border and c3 any other
 * position, in that order (the paper's counting), each a vector of a*b
 * coverages quantised to 0..255, texel (i, j) at index i + j*a. */
typedef struct fs_fp_rom {
    int a, b;
    bool midpoint;
    int px, py;
    int p, pb;               /* positions, border positions */
    int16_t *border_rank;    /* p entries: rank among border positions, or -1 */
    uint32_t *stage1;        /* pb: c1 -> block of stage2 */
    uint32_t *stage2;        /* pb*(pb-1): (c1, c2) -> block of stage3 */
    uint32_t *stage3;        /* pb*(pb-1)*(p-2): (c1, c2, c3) -> vector */
    uint8_t *w;              /* vectors * a*b weights */
    size_t vectors;
} fs_fp_rom;

/* Generates the ROM (exact coverage by polygon clipping, 8-bit).  Returns 0,
 * or -1 on bad sizes or no memory (r is then empty). */
int fs_fp_rom_build(fs_fp_rom *r, int a, int b, bool midpoint);
void fs_fp_rom_free(fs_fp_rom *r);
/* The three-stage lookup (Fig. 4.31): the weight vector of the triangle
 * with corner positions (x[k], y[k]); corners 0 and 1 must lie on the
 * border and all three must differ.  NULL otherwise. */
const uint8_t *fs_fp_rom_lookup(const fs_fp_rom *r, const int x[3], const int y[3]);
bool fs_fp_rom_on_border(const fs_fp_rom *r, int x, int y);

/* Exact area of texel square [i, i+1] x [j, j+1] covered by the triangle
 * (tx, ty) (Sutherland-Hodgman clipping, shoelace area). */
double fs_fp_triangle_texel_coverage(const double tx[3], const double ty[3], int i, int j);

/* ---- Table 4.3 counts ---- */

typedef struct fs_fp_count {
    int a, b;                 /* texels */
    bool midpoint;
    long long p, pb;          /* positions, border positions */
    long long vectors;        /* pb * (pb-1) * (p-2) */
    long long weights;        /* vectors * a*b: the size of W */
    long long pointers_full;  /* p + p(p-1) + p(p-1)(p-2): no border reduction */
    long long pointers;       /* pb + pb(pb-1) + pb(pb-1)(p-2): what our ROM stores */
} fs_fp_count;
void fs_fp_count_shape(int a, int b, bool midpoint, fs_fp_count *out);

/* One row of the dissertation's Table 4.3 as printed. */
typedef struct fs_fp_paper_row {
    int M;
    bool midpoint;
    int gx, gy;               /* the "I 5x5" / "MS 4x4" label: positions (I) or texels (MS) */
    long long f1, f2, f3;     /* the printed factors f1 * f2 * f3 * M */
    long long weights;        /* the printed product */
    long long pointers;       /* the printed pointer count */
} fs_fp_paper_row;
extern const fs_fp_paper_row fs_fp_paper_table[];
extern const int fs_fp_paper_table_rows;
/* The texel array a x b of a paper row. */
void fs_fp_paper_shape(const fs_fp_paper_row *r, int *a, int *b);

/* The array shapes (a <= b, a*b = M) the filter uses for M and a snapping
 * mode: those whose ROM has at most FS_FP_ROM_MAX_WEIGHTS weights; returns
 * how many were written (at most 8). */
#define FS_FP_ROM_MAX_WEIGHTS (32LL << 20)
int fs_fp_shapes(int M, bool midpoint, int a[8], int b[8]);
#endif
