/*
 * Fast footprint filtering (Huettner 1999, 4.3.3-4.3.6): level selection,
 * corner snapping, triangle split, the three-stage ROM lookup, the
 * evaluator and the hybrid selector.
 *
 * Where the dissertation leaves choices open, fragsim decides as follows
 * (each is also stated in docs/extensions/footprint_filter.txt):
 *
 * - Array shape and level.  Eq. 4.17 gives the finest level lambda0 at
 *   which the bounding box holds at most M texels for real-valued a', b'.
 *   The ROMs exist for power-of-two arrays a x b = M (and their
 *   transposes), so the level used is the first lambda >= lambda0 at which
 *   the snapped corners fit into one of them.
 * - Border corners.  The ROM only holds triangles with two corners on the
 *   border of T (4.3.4).  T can always be placed so that one corner of the
 *   quadrilateral with extreme x and one with extreme y lie on its border,
 *   but for both triangles to be in the ROM these two corners must be the
 *   ends of the splitting diagonal.  When no placement and diagonal do
 *   that (e.g. a diamond-shaped footprint whose x- and y-extreme corners
 *   are adjacent), each triangle gets its own array: two steps and up to
 *   2M texels, the dissertation's "T between M and 2M" (4.3.6).  Every
 *   triangle alone has a placement with two corners on the border.
 * - Two arrays for distorted footprints (4.3.6, Fig. 4.32, "up to 2M
 *   texels in two steps").  The bounding box of a rotated, elongated
 *   footprint is far larger than the footprint, so eq. 4.17 picks a level
 *   at which the footprint is thinner than a texel and its snapped corners
 *   collapse or bloat.  fragsim therefore also cuts the footprint in two
 *   across its longer screen axis (through the mid-points of the two
 *   crossing edges); each half gets its own bounding box, eq. 4.17 level
 *   and one array of M texels (its own ROM lookups).  The halves are used
 *   when neither filters at a coarser and at least one at a finer level
 *   than the whole footprint does, or when the whole fits no level; the result is their mean (each half is
 *   the image of half the pixel square in the affine approximation; a
 *   shift in hardware).  Only the choice between one and two steps is
 *   made per pixel; no coverage is computed at run time.
 * - Snapping.  Integer positions round to the nearest lattice point.
 *   The study (docs/texture_filtering.md) uses integer positions for every
 *   M: an a x b array offers (a+1)(b+1) positions against a*b mid-points,
 *   so a snapped footprint fits at a finer level, and the error per corner
 *   is at most half a texel in each axis either way.  The study's rows
 *   "mid-point snapping" measure the alternative for M = 16 and 32.
 * - Normalisation.  Eq. 4.19 sums T[i] * (w1[i] + w2[i]); with absolute
 *   coverages in the ROM that sum is the footprint's area times the
 *   colour, so fragsim divides by the sum of the weights (a constant
 *   texture then filters to itself exactly).
 * - Diagonal.  A concave snapped quadrilateral is split along its inner
 *   diagonal (both triangles with the same orientation); either diagonal of
 *   a convex one gives the same coverage.
 * - Collapse.  A footprint thinner than a texel of level lambda may snap to
 *   zero area; then finer levels are tried while it fits, else its short
 *   edges are stretched to 1.5 texels before snapping (widen(): one or two
 *   texels thick, along its own direction; an earlier per-axis "outward"
 *   rounding left thin diagonal footprints collapsed and sent them to
 *   trilinear) at the first level from lambda on where that fits; failing
 *   that the pixel is filtered with the two halves above, if they fit,
 *   else trilinearly (class TRILINEAR).
 * - Bad input (NaN/Inf corners, huge coordinates) is filtered trilinearly
 *   at GL's isotropic level, which fs_mip_trilinear defines for any input.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "footprint.h"

#define MAX_SHAPES 8

struct fs_footprint_filter {
    int M;
    bool midpoint, hybrid;
    double iso_limit;
    int nroms;
    fs_fp_rom rom[MAX_SHAPES];
};

fs_footprint_filter *fs_footprint_filter_create(int M, bool midpoint, bool hybrid)
{
    if (M != 8 && M != 16 && M != 32 && M != 64)
        return NULL;
    fs_footprint_filter *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->M = M;
    f->midpoint = midpoint;
    f->hybrid = hybrid;
    f->iso_limit = FS_FP_ISO_LIMIT;
    int a[8], b[8];
    int n = fs_fp_shapes(M, midpoint, a, b);
    for (int i = 0; i < n; i++) {
        if (fs_fp_rom_build(&f->rom[i], a[i], b[i], midpoint) != 0) {
            fs_footprint_filter_destroy(f);
            return NULL;
        }
        f->nroms++;
    }
    return f;
}

void fs_footprint_filter_destroy(fs_footprint_filter *f)
{
    if (!f)
        return;
    for (int i = 0; i < f->nroms; i++)
        fs_fp_rom_free(&f->rom[i]);
    free(f);
}

void fs_footprint_filter_set_iso_limit(fs_footprint_filter *f, double ratio)
{
    if (ratio >= 1.0)
        f->iso_limit = ratio;
}

int fs_footprint_filter_budget(const fs_footprint_filter *f) { return f->M; }

int fs_footprint_lambda(double u, double v, int M, double *mo, double *no)
{
    if (mo)
        *mo = 0.0;
    if (no)
        *no = 0.0;
    if (!(u > 0.0) || !(v > 0.0) || !isfinite(u) || !isfinite(v) || M <= 0)
        return 0;
    /* Eq. 4.14: a = sqrt(M f), f = u / v; eq. 4.15: a' = a, b' = M / a;
     * eq. 4.16: m = log2(u / a'), n = log2(v / b'); eq. 4.17. */
    double f = u / v;
    double a = sqrt((double)M * f);
    double b = (double)M / a;
    double m = log2(u / a), n = log2(v / b);
    if (mo)
        *mo = m;
    if (no)
        *no = n;
    double l = ceil(fmax(m, n));
    if (!(l > -1e6) || !(l < 1e6))
        return l > 0 ? 1000000 : 0;
    return (int)l;
}

/* ---- one level ---- */

/* An a x b array of the ROM `rom`, possibly transposed, placed with its
 * position (0, 0) at level grid position (ox, oy). */
typedef struct placement {
    int rom;
    bool transposed;
    int ox, oy;
} placement;

typedef struct fp_step {
    placement pl;
    const uint8_t *w[2];
    int nw;
} fp_step;

static void array_positions(const fs_fp_rom *r, bool tr, int *px, int *py)
{
    *px = tr ? r->py : r->px;
    *py = tr ? r->px : r->py;
}

static long long orient(const int *X, const int *Y, int i, int j, int k)
{
    return (long long)(X[j] - X[i]) * (Y[k] - Y[i]) - (long long)(Y[j] - Y[i]) * (X[k] - X[i]);
}

/* Looks triangle (X[t[k]], Y[t[k]]) up under placement pl, ordering its
 * corners so that two on the border come first.  NULL when fewer than two
 * lie on the border. */
static const uint8_t *lookup_tri(const fs_footprint_filter *f, const placement *pl, const int *X, const int *Y,
                                 const int t[3])
{
    const fs_fp_rom *r = &f->rom[pl->rom];
    int ax[3], ay[3], on[3], nb = 0;
    for (int k = 0; k < 3; k++) {
        int x = X[t[k]] - pl->ox, y = Y[t[k]] - pl->oy;
        ax[k] = pl->transposed ? y : x;
        ay[k] = pl->transposed ? x : y;
        on[k] = fs_fp_rom_on_border(r, ax[k], ay[k]);
        nb += on[k];
    }
    if (nb < 2)
        return NULL;
    int o[3], n = 0;
    for (int k = 0; k < 3; k++)
        if (on[k] && n < 2)
            o[n++] = k;
    for (int k = 0; k < 3; k++)
        if (k != o[0] && k != o[1]) {
            o[2] = k;
            break;
        }
    int qx[3] = {ax[o[0]], ax[o[1]], ax[o[2]]}, qy[3] = {ay[o[0]], ay[o[1]], ay[o[2]]};
    return fs_fp_rom_lookup(r, qx, qy);
}

/* Candidate placements of the bounding box [x0,x1] x [y0,y1]: every array
 * orientation that holds it, with the box touching the left or right and
 * the bottom or top border (the only ways to put an extreme corner on the
 * border).  Returns the count. */
static int placements(const fs_footprint_filter *f, int x0, int x1, int y0, int y1, placement *out)
{
    int n = 0;
    for (int i = 0; i < f->nroms; i++)
        for (int t = 0; t < 2; t++) {
            const fs_fp_rom *r = &f->rom[i];
            if (t && r->a == r->b)
                continue;
            int px, py;
            array_positions(r, t, &px, &py);
            if (x1 - x0 > px - 1 || y1 - y0 > py - 1)
                continue;
            int oxs[2] = {x0, x1 - (px - 1)}, oys[2] = {y0, y1 - (py - 1)};
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++)
                    out[n++] = (placement){i, t != 0, oxs[a], oys[b]};
        }
    return n;
}

enum { LEVEL_NOFIT, LEVEL_COLLAPSED, LEVEL_OK };

typedef struct level_result {
    fp_step step[2];
    int nsteps;
} level_result;

static bool tri_degenerate(const int *X, const int *Y, const int t[3])
{
    return orient(X, Y, t[0], t[1], t[2]) == 0;
}

/* Snaps one coordinate (4.3.4): integer positions by rounding to the
 * nearest; mid-points of the texel a corner lies in, a corner on a grid
 * line going up and right (floor does both). */
static int snap(double x, bool midpoint)
{
    return (int)(midpoint ? floor(x) : floor(x + 0.5));
}

/* The collapse fallback: a footprint thinner than a texel of the level has
 * its two short opposite edges stretched about their mid-points to at
 * least FP_MIN_EDGE texels before snapping, so that their ends snap to
 * different positions (two points closer than sqrt(2) texels may share
 * one) and the snapped footprint keeps its direction with a thickness of
 * one or two texels.  Corner set-up arithmetic like the bounding box, no
 * coverage computation. */
#define FP_MIN_EDGE 1.5
static void widen(double x[4], double y[4])
{
    double l01 = hypot(x[1] - x[0], y[1] - y[0]) + hypot(x[3] - x[2], y[3] - y[2]);
    double l12 = hypot(x[2] - x[1], y[2] - y[1]) + hypot(x[0] - x[3], y[0] - y[3]);
    int e0 = l01 <= l12 ? 0 : 1; /* edges (e0, e0+1) and (e0+2, e0+3) */
    for (int e = e0; e < 4; e += 2) {
        int i = e, j = (e + 1) & 3;
        double dx = x[j] - x[i], dy = y[j] - y[i], len = hypot(dx, dy);
        if (len >= FP_MIN_EDGE)
            continue;
        if (!(len > 1e-9)) {
            /* A point-like edge: stretch it across the long axis. */
            int k = (i + 3) & 3;
            double ax = x[k] - x[i], ay = y[k] - y[i], al = hypot(ax, ay);
            dx = al > 1e-9 ? -ay / al : 1.0;
            dy = al > 1e-9 ? ax / al : 0.0;
            len = 1.0;
        }
        double mx = 0.5 * (x[i] + x[j]), my = 0.5 * (y[i] + y[j]), h = 0.5 * FP_MIN_EDGE / len;
        x[i] = mx - dx * h;
        y[i] = my - dy * h;
        x[j] = mx + dx * h;
        y[j] = my + dy * h;
    }
}

/* A quadrilateral in level-0 texels, corners in the pixel's order. */
typedef struct quad {
    double u[4], v[4];
} quad;

static int try_level(const fs_footprint_filter *f, const fs_mip_view *m, const quad *q, int lam, bool widened,
                     bool one_step, level_result *res)
{
    double sx = (double)m->width[lam] / m->width[0], sy = (double)m->height[lam] / m->height[0];
    int X[4], Y[4];
    double x[4], y[4];
    for (int k = 0; k < 4; k++) {
        x[k] = q->u[k] * sx;
        y[k] = q->v[k] * sy;
        if (!(fabs(x[k]) < 1e8) || !(fabs(y[k]) < 1e8))
            return LEVEL_NOFIT;
    }
    if (widened)
        widen(x, y);
    for (int k = 0; k < 4; k++) {
        X[k] = snap(x[k], f->midpoint);
        Y[k] = snap(y[k], f->midpoint);
    }
    int x0 = X[0], x1 = X[0], y0 = Y[0], y1 = Y[0];
    for (int k = 1; k < 4; k++) {
        x0 = X[k] < x0 ? X[k] : x0;
        x1 = X[k] > x1 ? X[k] : x1;
        y0 = Y[k] < y0 ? Y[k] : y0;
        y1 = Y[k] > y1 ? Y[k] : y1;
    }
    placement pl[4 * 2 * MAX_SHAPES];
    int npl = placements(f, x0, x1, y0, y1, pl);
    if (npl == 0)
        return LEVEL_NOFIT;
    static const int tris[2][2][3] = {{{0, 1, 2}, {0, 2, 3}}, {{1, 2, 3}, {1, 3, 0}}};
    bool valid[2];
    for (int d = 0; d < 2; d++) {
        long long o1 = orient(X, Y, tris[d][0][0], tris[d][0][1], tris[d][0][2]);
        long long o2 = orient(X, Y, tris[d][1][0], tris[d][1][1], tris[d][1][2]);
        valid[d] = (o1 >= 0 && o2 >= 0) || (o1 <= 0 && o2 <= 0);
    }
    if (!valid[0] && !valid[1])
        valid[0] = valid[1] = true; /* self-intersecting: either split */
    bool any_area = false;
    for (int d = 0; d < 2; d++)
        for (int t = 0; t < 2; t++)
            any_area |= valid[d] && !tri_degenerate(X, Y, tris[d][t]);
    if (!any_area)
        return LEVEL_COLLAPSED;
    /* One step: one array holding both triangles. */
    for (int i = 0; i < npl; i++)
        for (int d = 0; d < 2; d++) {
            if (!valid[d])
                continue;
            fp_step s = {pl[i], {NULL, NULL}, 0};
            bool ok = true;
            for (int t = 0; t < 2 && ok; t++) {
                if (tri_degenerate(X, Y, tris[d][t]))
                    continue;
                const uint8_t *w = lookup_tri(f, &pl[i], X, Y, tris[d][t]);
                if (w)
                    s.w[s.nw++] = w;
                else
                    ok = false;
            }
            if (ok) {
                res->step[0] = s;
                res->nsteps = 1;
                return LEVEL_OK;
            }
        }
    if (one_step)
        return LEVEL_NOFIT;
    /* Two steps: each triangle of the first valid diagonal in its own
     * array. */
    int d = valid[0] ? 0 : 1;
    res->nsteps = 0;
    for (int t = 0; t < 2; t++) {
        const int *tri = tris[d][t];
        if (tri_degenerate(X, Y, tri))
            continue;
        int tx0 = X[tri[0]], tx1 = tx0, ty0 = Y[tri[0]], ty1 = ty0;
        for (int k = 1; k < 3; k++) {
            tx0 = X[tri[k]] < tx0 ? X[tri[k]] : tx0;
            tx1 = X[tri[k]] > tx1 ? X[tri[k]] : tx1;
            ty0 = Y[tri[k]] < ty0 ? Y[tri[k]] : ty0;
            ty1 = Y[tri[k]] > ty1 ? Y[tri[k]] : ty1;
        }
        placement tp[4 * 2 * MAX_SHAPES];
        int ntp = placements(f, tx0, tx1, ty0, ty1, tp);
        const uint8_t *w = NULL;
        int i;
        for (i = 0; i < ntp && !w; i++)
            w = lookup_tri(f, &tp[i], X, Y, tri);
        if (!w)
            return LEVEL_NOFIT; /* cannot happen: see the file comment */
        res->step[res->nsteps++] = (fp_step){tp[i - 1], {w, NULL}, 1};
    }
    return LEVEL_OK;
}

/* Texels of a step's array at level lam in array orientation. */
static void step_extent(const fs_footprint_filter *f, const fp_step *s, int *a, int *b)
{
    const fs_fp_rom *r = &f->rom[s->pl.rom];
    *a = s->pl.transposed ? r->b : r->a;
    *b = s->pl.transposed ? r->a : r->b;
}

/* Eq. 4.19 over the steps, normalised by the weight sum.  Returns false
 * when every weight is 0. */
static bool evaluate(const fs_footprint_filter *f, const fs_mip_view *m, int lam, const level_result *res,
                     float rgba[4], int *texels)
{
    double acc[4] = {0, 0, 0, 0};
    long total = 0;
    int n = 0;
    int ext[2][4];
    for (int s = 0; s < res->nsteps; s++) {
        const fp_step *st = &res->step[s];
        const fs_fp_rom *r = &f->rom[st->pl.rom];
        int a, b;
        step_extent(f, st, &a, &b);
        for (int j = 0; j < b; j++)
            for (int i = 0; i < a; i++) {
                int ti = st->pl.transposed ? j : i, tj = st->pl.transposed ? i : j;
                int w = 0;
                for (int k = 0; k < st->nw; k++)
                    w += st->w[k][ti + tj * r->a];
                if (w == 0)
                    continue;
                float t[4];
                fs_mip_fetch(m, lam, st->pl.ox + i, st->pl.oy + j, t);
                for (int ch = 0; ch < 4; ch++)
                    acc[ch] += (double)w * t[ch];
                total += w;
            }
        ext[s][0] = st->pl.ox;
        ext[s][1] = st->pl.ox + a;
        ext[s][2] = st->pl.oy;
        ext[s][3] = st->pl.oy + b;
        n += a * b;
    }
    if (total == 0)
        return false;
    for (int ch = 0; ch < 4; ch++)
        rgba[ch] = (float)(acc[ch] / (double)total);
    /* The hardware loads each array T whole; two overlapping arrays share
     * the overlap; an array wider than the level reads a texel again. */
    if (res->nsteps == 2) {
        int ox = (ext[0][1] < ext[1][1] ? ext[0][1] : ext[1][1]) - (ext[0][0] > ext[1][0] ? ext[0][0] : ext[1][0]);
        int oy = (ext[0][3] < ext[1][3] ? ext[0][3] : ext[1][3]) - (ext[0][2] > ext[1][2] ? ext[0][2] : ext[1][2]);
        if (ox > 0 && oy > 0)
            n -= ox * oy;
    }
    long cap = (long)m->width[lam] * m->height[lam];
    *texels = n > cap ? (int)cap : n;
    return true;
}

/* The larger over the smaller singular value of the Jacobian. */
static double axis_ratio(const fs_footprint *fp)
{
    double a = fp->dudx, b = fp->dudy, c = fp->dvdx, d = fp->dvdy;
    double s = 0.5 * (a * a + b * b + c * c + d * d), det = a * d - b * c;
    double disc = sqrt(fmax(0.0, s * s - det * det));
    double big = s + disc;
    if (!(big > 0.0))
        return 1.0;
    double small = det * det / big;
    if (!(small > 0.0))
        return INFINITY;
    return sqrt(big / small);
}

/* Reports the 2x2 block fs_mip_bilinear reads at `level` as the next
 * rectangle of out (texture_filter.h), for the cycle model. */
static void report_block(const fs_mip_view *m, int level, double u, double v, fs_filter_out *out)
{
    int x0, y0;
    level = fs_mip_bilinear_block(m, level, u, v, &x0, &y0);
    out->rect[out->nrects++] = (struct fs_filter_rect){level, x0, y0, 2, 2};
}

static void trilinear(const fs_mip_view *m, const fs_footprint *fp, fs_filter_out *out)
{
    double lam = fs_footprint_lambda_iso(fp);
    out->texels = fs_mip_trilinear(m, lam, fp->u, fp->v, out->rgba);
    int lv[2];
    int n = fs_mip_trilinear_levels(m, lam, lv);
    out->nrects = 0;
    for (int i = 0; i < n; i++)
        report_block(m, lv[i], fp->u, fp->v, out);
    double top = m->levels - 1;
    out->level = (float)(lam > 0.0 ? (lam < top ? lam : top) : 0.0);
    out->cls = FS_FP_CLASS_TRILINEAR;
}

/* The footprint filter on one quadrilateral q: the level of eq. 4.17 from
 * its bounding box, then the first level from there on where the snapped
 * corners fit an array (one step, or two for a diamond unless one_step).
 * False when no level of the pyramid works. */
typedef struct quad_out {
    float rgba[4];
    int texels, level, nsteps, lookups;
    int ext[2][4]; /* the steps' arrays: x0, x1, y0, y1 in level texels */
} quad_out;

static bool filter_quad(const fs_footprint_filter *f, const fs_mip_view *m, const quad *q, bool one_step,
                        quad_out *qo)
{
    double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
    for (int k = 0; k < 4; k++) {
        u0 = fmin(u0, q->u[k]);
        u1 = fmax(u1, q->u[k]);
        v0 = fmin(v0, q->v[k]);
        v1 = fmax(v1, q->v[k]);
    }
    int top = m->levels - 1;
    int lam0 = fs_footprint_lambda(u1 - u0, v1 - v0, f->M, NULL, NULL);
    lam0 = lam0 < 0 ? 0 : lam0 > top ? top : lam0;
    level_result res;
    int used = -1;
    for (int lam = lam0; lam <= top && used < 0; lam++) {
        int r = try_level(f, m, q, lam, false, one_step, &res);
        if (r == LEVEL_OK && evaluate(f, m, lam, &res, qo->rgba, &qo->texels)) {
            used = lam;
        } else if (r != LEVEL_NOFIT) {
            /* Collapsed: thicker at finer levels, while it still fits;
             * else widened (one or two texels thick) at this or the next
             * levels where that fits. */
            for (int l = lam - 1; l >= 0 && used < 0; l--) {
                int r2 = try_level(f, m, q, l, false, one_step, &res);
                if (r2 == LEVEL_NOFIT)
                    break;
                if (r2 == LEVEL_OK && evaluate(f, m, l, &res, qo->rgba, &qo->texels))
                    used = l;
            }
            for (int l = lam; l <= top && used < 0; l++)
                if (try_level(f, m, q, l, true, one_step, &res) == LEVEL_OK &&
                    evaluate(f, m, l, &res, qo->rgba, &qo->texels))
                    used = l;
            break;
        }
    }
    if (used < 0)
        return false;
    qo->level = used;
    qo->nsteps = res.nsteps;
    qo->lookups = 0;
    for (int s = 0; s < res.nsteps; s++) {
        int a, b;
        step_extent(f, &res.step[s], &a, &b);
        qo->ext[s][0] = res.step[s].pl.ox;
        qo->ext[s][1] = res.step[s].pl.ox + a;
        qo->ext[s][2] = res.step[s].pl.oy;
        qo->ext[s][3] = res.step[s].pl.oy + b;
        qo->lookups += res.step[s].nw;
    }
    return true;
}

/* The two halves of a footprint, cut through the mid-points of the two
 * edges that cross its longer screen-space axis (Fig. 4.32: two arrays for
 * a distorted footprint).  In the affine approximation each half is the
 * image of one half of the pixel square, so a box filter over the pixel
 * weights them equally. */
static void split_halves(const quad *q, quad h[2])
{
    /* Corners in pixel order: 0 (x-,y-), 1 (x+,y-), 2 (x+,y+), 3 (x-,y+).
     * The x axis runs from edge 3-0 to edge 1-2, the y axis from edge 0-1
     * to edge 2-3. */
    double xu = 0.5 * (q->u[1] + q->u[2] - q->u[0] - q->u[3]), xv = 0.5 * (q->v[1] + q->v[2] - q->v[0] - q->v[3]);
    double yu = 0.5 * (q->u[2] + q->u[3] - q->u[0] - q->u[1]), yv = 0.5 * (q->v[2] + q->v[3] - q->v[0] - q->v[1]);
    bool along_x = xu * xu + xv * xv >= yu * yu + yv * yv;
    /* Rotate the corner order so that the cut runs through edges 0-1 and
     * 2-3 (the long axis from edge 3-0 to edge 1-2). */
    int o[4];
    for (int k = 0; k < 4; k++)
        o[k] = along_x ? k : (k + 1) & 3;
    double mu01 = 0.5 * (q->u[o[0]] + q->u[o[1]]), mv01 = 0.5 * (q->v[o[0]] + q->v[o[1]]);
    double mu23 = 0.5 * (q->u[o[2]] + q->u[o[3]]), mv23 = 0.5 * (q->v[o[2]] + q->v[o[3]]);
    h[0] = (quad){{q->u[o[0]], mu01, mu23, q->u[o[3]]}, {q->v[o[0]], mv01, mv23, q->v[o[3]]}};
    h[1] = (quad){{mu01, q->u[o[1]], q->u[o[2]], mu23}, {mv01, q->v[o[1]], q->v[o[2]], mv23}};
}

/* Reports array `step` of q (the texels the hardware loads whole) as the
 * next rectangle of out. */
static void report_array(const quad_out *q, int step, fs_filter_out *out)
{
    const int *e = q->ext[step];
    out->rect[out->nrects++] = (struct fs_filter_rect){q->level, e[0], e[2], e[1] - e[0], e[3] - e[2]};
}

static int overlap(const int a[4], const int b[4])
{
    int ox = (a[1] < b[1] ? a[1] : b[1]) - (a[0] > b[0] ? a[0] : b[0]);
    int oy = (a[3] < b[3] ? a[3] : b[3]) - (a[2] > b[2] ? a[2] : b[2]);
    return ox > 0 && oy > 0 ? ox * oy : 0;
}

void fs_footprint_filter_run(const fs_footprint_filter *f, const fs_mip_view *m, const fs_footprint *fp,
                             fs_filter_out *out, int *rom_lookups)
{
    memset(out, 0, sizeof *out);
    if (rom_lookups)
        *rom_lookups = 0;
    bool finite = isfinite(fp->u) && isfinite(fp->v);
    quad q;
    for (int k = 0; k < 4; k++) {
        finite = finite && isfinite(fp->corner_u[k]) && isfinite(fp->corner_v[k]);
        q.u[k] = fp->corner_u[k];
        q.v[k] = fp->corner_v[k];
    }
    if (!finite) {
        trilinear(m, fp, out);
        return;
    }
    if (f->hybrid) {
        /* 4.3.6: bilinear on level 0 when the footprint is smaller than a
         * texel (GL's magnification, lambda <= 0), MIPmapping for nearly
         * isotropic footprints, the footprint filter for the rest. */
        if (!(fs_footprint_lambda_iso(fp) > 0.0)) {
            out->texels = fs_mip_bilinear(m, 0, fp->u, fp->v, out->rgba);
            out->cls = FS_FP_CLASS_BILINEAR0;
            report_block(m, 0, fp->u, fp->v, out);
            return;
        }
        if (!(axis_ratio(fp) > f->iso_limit)) {
            trilinear(m, fp, out);
            return;
        }
    }
    quad_out whole, half[2];
    bool ok = filter_quad(f, m, &q, false, &whole);
    /* Two steps for a distorted footprint (4.3.6: "up to 2M texels in two
     * steps"; Fig. 4.32: two arrays): each half of the footprint gets its
     * own bounding box, level (eq. 4.17) and array of M texels.  Used when
     * the second step buys detail: no half filters at a coarser level and
     * at least one at a finer level than the whole footprint does in one
     * array (the bounding box of the whole wastes the budget: a rotated,
     * elongated footprint), and also when the whole fits no level.  The halves are averaged (equal weights, a shift in
     * hardware). */
    quad h[2];
    split_halves(&q, h);
    bool two = false;
    if (filter_quad(f, m, &h[0], true, &half[0]) && filter_quad(f, m, &h[1], true, &half[1]))
        two = !ok || (half[0].level <= whole.level && half[1].level <= whole.level &&
                      (half[0].level < whole.level || half[1].level < whole.level));
    if (two) {
        for (int ch = 0; ch < 4; ch++)
            out->rgba[ch] = 0.5f * (half[0].rgba[ch] + half[1].rgba[ch]);
        out->texels = half[0].texels + half[1].texels;
        if (half[0].level == half[1].level) {
            /* One level: the two arrays share their overlap, and neither
             * reads more than the whole level (as in evaluate). */
            const int *e0 = half[0].ext[0], *e1 = half[1].ext[0];
            long n = (long)(e0[1] - e0[0]) * (e0[3] - e0[2]) + (long)(e1[1] - e1[0]) * (e1[3] - e1[2]) -
                     overlap(e0, e1);
            long cap = (long)m->width[half[0].level] * m->height[half[0].level];
            out->texels = (int)(n < cap ? n : cap);
        }
        out->level = 0.5f * (float)(half[0].level + half[1].level);
        out->cls = FS_FP_CLASS_FOOTPRINT_2M;
        for (int k = 0; k < 2; k++)
            report_array(&half[k], 0, out);
        out->rom_lookups = half[0].lookups + half[1].lookups;
        if (rom_lookups)
            *rom_lookups = out->rom_lookups;
        return;
    }
    if (!ok) {
        trilinear(m, fp, out);
        return;
    }
    memcpy(out->rgba, whole.rgba, sizeof out->rgba);
    out->texels = whole.texels;
    out->level = (float)whole.level;
    out->cls = whole.nsteps == 2 ? FS_FP_CLASS_FOOTPRINT_2M : FS_FP_CLASS_FOOTPRINT;
    for (int k = 0; k < whole.nsteps; k++)
        report_array(&whole, k, out);
    out->rom_lookups = whole.lookups;
    if (rom_lookups)
        *rom_lookups = whole.lookups;
}

void fs_filter_footprint(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out)
{
    const fs_footprint_filter *f = params;
    if (!f) {
        memset(out, 0, sizeof *out);
        trilinear(m, fp, out);
        return;
    }
    fs_footprint_filter_run(f, m, fp, out, NULL);
}
