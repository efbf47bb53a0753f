/*
 * The MP-Grid residency manager (Huettner 1999, 4.1.1, Fig. 4.2 and 4.5):
 * per pyramid, the finest level needed follows from the screen size of the
 * projected bounding box of the polygons it textures, rounded up to a power
 * of two; levels are loaded and freed as the viewer moves; an occluded box
 * needs no level (4.1.2).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "mpgrid.h"

static bool finite3(const double v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

int fs_mpgrid_camera_lookat(fs_mpgrid_camera *cam, const double eye[3], const double center[3], const double up[3],
                            double fovy_deg, double znear, double zfar, int vp_w, int vp_h)
{
    if (!finite3(eye) || !finite3(center) || !finite3(up) || !isfinite(fovy_deg) || !isfinite(znear) ||
        !isfinite(zfar) || !(fovy_deg > 0.0 && fovy_deg < 180.0) || !(znear > 0.0) || !(zfar > znear) ||
        vp_w <= 0 || vp_h <= 0)
        return -1;
    /* gluLookAt (GLU 1.3, 4.2): f = centre - eye, s = f x up, u = s x f. */
    double f[3] = {center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]};
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (!(fl > 0.0))
        return -1;
    for (int k = 0; k < 3; k++)
        f[k] /= fl;
    double s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(sl > 1e-12))
        return -1;
    for (int k = 0; k < 3; k++)
        s[k] /= sl;
    double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    /* V: rows s, u, -f, translated by -eye (row-major here). */
    double V[4][4] = {{s[0], s[1], s[2], 0}, {u[0], u[1], u[2], 0}, {-f[0], -f[1], -f[2], 0}, {0, 0, 0, 1}};
    for (int r = 0; r < 3; r++)
        V[r][3] = -(V[r][0] * eye[0] + V[r][1] * eye[1] + V[r][2] * eye[2]);
    /* gluPerspective (GLU 1.3, 6.2). */
    double aspect = (double)vp_w / vp_h, ct = 1.0 / tan(fovy_deg * (3.14159265358979323846 / 360.0));
    double P[4][4] = {{ct / aspect, 0, 0, 0},
                      {0, ct, 0, 0},
                      {0, 0, (zfar + znear) / (znear - zfar), 2.0 * zfar * znear / (znear - zfar)},
                      {0, 0, -1, 0}};
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            double a = 0;
            for (int k = 0; k < 4; k++)
                a += P[r][k] * V[k][c];
            cam->m[c * 4 + r] = a;
        }
    cam->vp_w = vp_w;
    cam->vp_h = vp_h;
    return 0;
}

typedef struct v4 { double x[4]; } v4;

/* Sutherland-Hodgman against one clip-space plane dot(p, x) >= 0 (GL 1.5
 * spec 2.12's view volume -w <= x, y, z <= w). */
static int clip_plane(const v4 *in, int n, v4 *out, int axis, double sign)
{
    int k = 0;
    for (int a = 0; a < n; a++) {
        const v4 *p = &in[a], *q = &in[(a + 1) % n];
        double dp = p->x[3] + sign * p->x[axis], dq = q->x[3] + sign * q->x[axis];
        if (dp >= 0)
            out[k++] = *p;
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            for (int c = 0; c < 4; c++)
                out[k].x[c] = p->x[c] + t * (q->x[c] - p->x[c]);
            k++;
        }
    }
    return k;
}

double fs_mpgrid_projected_extent(const fs_mpgrid_camera *cam, const double lo[3], const double hi[3])
{
    if (!finite3(lo) || !finite3(hi) || cam->vp_w <= 0 || cam->vp_h <= 0)
        return -1;
    for (int k = 0; k < 16; k++)
        if (!isfinite(cam->m[k]))
            return -1;
    static const int face[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    v4 corner[8];
    for (int c = 0; c < 8; c++) {
        double p[3] = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]};
        for (int r = 0; r < 4; r++)
            corner[c].x[r] = cam->m[r] * p[0] + cam->m[4 + r] * p[1] + cam->m[8 + r] * p[2] + cam->m[12 + r];
    }
    for (int f = 0; f < 6; f++) {
        /* Each clip plane adds at most one vertex: 4 + 6. */
        v4 a[10], b[10];
        int n = 4;
        for (int k = 0; k < 4; k++)
            a[k] = corner[face[f][k]];
        for (int axis = 0; axis < 3 && n > 0; axis++) {
            n = clip_plane(a, n, b, axis, 1.0);
            n = clip_plane(b, n, a, axis, -1.0);
        }
        for (int k = 0; k < n; k++) {
            if (!(a[k].x[3] > 0))
                continue;
            /* Window coordinates (2.11.1), in pixels. */
            double x = (a[k].x[0] / a[k].x[3] + 1.0) * 0.5 * cam->vp_w;
            double y = (a[k].x[1] / a[k].x[3] + 1.0) * 0.5 * cam->vp_h;
            xmin = x < xmin ? x : xmin;
            xmax = x > xmax ? x : xmax;
            ymin = y < ymin ? y : ymin;
            ymax = y > ymax ? y : ymax;
        }
    }
    if (!(xmax >= xmin))
        return 0;
    double e = xmax - xmin > ymax - ymin ? xmax - xmin : ymax - ymin;
    /* A box seen exactly edge-on still needs its coarsest level. */
    return e > 0 ? e : 1e-300;
}

int fs_mpgrid_needed_level(const fs_mpgrid_layout *L, double extent)
{
    if (!(extent > 0) || !isfinite(extent))
        return isinf(extent) && extent > 0 ? 0 : L->levels;
    /* Round the extent up to a power of two r (4.1.1).  An extent that is
     * a power of two up to rounding noise (1e-9 relative) counts as that
     * power: the paper's example has boxes whose projection is exactly 512
     * pixels, and noise must not double their memory. */
    int level = L->levels - 1;
    for (int r = 1; level > 0 && (double)r < extent * (1.0 - 1e-9); r *= 2)
        level--;
    return level;
}

static int keep_level(const fs_mpgrid_layout *L, int keep_side)
{
    /* The first level whose larger side is <= keep_side. */
    for (int l = 0; l < L->levels; l++) {
        int w = fs_mpgrid_level_w(L, l), h = fs_mpgrid_level_h(L, l);
        if ((w > h ? w : h) <= keep_side)
            return l;
    }
    return L->levels;
}

static int needed_all(const fs_mpgrid_layout *L, const fs_mpgrid_camera *cam, const fs_mpgrid_box *boxes,
                      int keep_side, int *needed, int *visible)
{
    int keep = keep_level(L, keep_side);
    int vis = 0;
    for (int p = 0; p < L->n * L->m; p++) {
        const fs_mpgrid_box *b = &boxes[p];
        double e = b->unbounded ? INFINITY : fs_mpgrid_projected_extent(cam, b->lo, b->hi);
        if (e < 0)
            return -1;
        int lv = b->occluded ? L->levels : fs_mpgrid_needed_level(L, e);
        vis += lv < L->levels;
        needed[p] = lv < keep ? lv : keep;
    }
    if (visible)
        *visible = vis;
    return 0;
}

int fs_mpgrid_adapted_bytes(const fs_mpgrid_layout *L, const fs_mpgrid_camera *cam, const fs_mpgrid_box *boxes,
                            int bytes_per_texel, int keep_side, uint64_t *bytes, int *needed_out)
{
    fs_mpgrid_layout chk;
    if (!L || !cam || !boxes || !bytes || bytes_per_texel <= 0 ||
        fs_mpgrid_make_layout(L->n, L->m, L->tile_w, L->tile_h, &chk) < 0)
        return -1;
    int np = chk.n * chk.m;
    int *needed = needed_out ? needed_out : malloc((size_t)np * sizeof *needed);
    if (!needed)
        return -1;
    int rc = needed_all(&chk, cam, boxes, keep_side, needed, NULL);
    uint64_t sum = 0;
    for (int p = 0; rc == 0 && p < np; p++)
        sum += fs_mpgrid_pyramid_bytes(&chk, needed[p], bytes_per_texel);
    if (!needed_out)
        free(needed);
    if (rc == 0)
        *bytes = sum;
    return rc;
}

int fs_mpgrid_adapt(fs_mpgrid *g, const fs_mpgrid_camera *cam, const fs_mpgrid_box *boxes, int keep_side,
                    fs_mpgrid_frame *fr)
{
    if (!g || !g->table || !cam || !boxes)
        return -1;
    int np = g->L.n * g->L.m;
    uint64_t loaded0 = g->levels_loaded, freed0 = g->levels_freed;
    /* Decide everything first, so bad input changes nothing. */
    int vis = 0;
    for (int p = 0; p < np; p++) {
        const fs_mpgrid_box *b = &boxes[p];
        if (!b->unbounded && fs_mpgrid_projected_extent(cam, b->lo, b->hi) < 0)
            return -1;
    }
    int keep = keep_level(&g->L, keep_side);
    for (int p = 0; p < np; p++) {
        const fs_mpgrid_box *b = &boxes[p];
        double e = b->unbounded ? INFINITY : fs_mpgrid_projected_extent(cam, b->lo, b->hi);
        int lv = b->occluded ? g->L.levels : fs_mpgrid_needed_level(&g->L, e);
        vis += lv < g->L.levels;
        if (fs_mpgrid_set_finest(g, p % g->L.n, p / g->L.n, lv < keep ? lv : keep) < 0)
            return -1;
    }
    if (fr) {
        fr->bytes_resident = g->bytes_resident;
        fr->levels_loaded = g->levels_loaded - loaded0;
        fr->levels_freed = g->levels_freed - freed0;
        fr->pyramids_visible = vis;
    }
    return 0;
}
