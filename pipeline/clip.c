/*
 * Clipping (GL 1.5 spec 2.12) and the hand-over to the rasterizer.
 *
 * llvmpipe clips in homogeneous clip space against all six view-volume
 * planes when a depth buffer is attached (its x/y guard band is only used
 * without one), so fragsim does the same.  The plane order, the
 * Sutherland-Hodgman walk that keeps the first vertex first, the
 * choice of interpolation direction (always from the vertex inside) and the
 * float arithmetic of new vertices (x_w = x_c * (1/w_c) * scale + translate,
 * unfused, while unclipped vertices keep the transform's fused result)
 * follow Mesa's draw module so that clipped edges land on the same
 * sub-pixel positions.  The enabled user clip planes (2.11, clip_plane.c)
 * come after the six, in clip space, in the order of their numbers.
 * Lines are clipped by all six planes and the user planes (no guard band
 * for them, fs_clip_line), in rendering as in selection and feedback
 * (pipeline/render_mode.c).  Points are
 * dropped when their vertex is outside any plane (primitive.c).
 * Non-finite distances drop the primitive.
 */
#include <math.h>
#include <string.h>
#include "vertex_internal.h"

/* Planes as (a,b,c,d) with inside a*x + b*y + c*z + d*w >= 0:
 * x <= w, x >= -w, y <= w, y >= -w, z >= -w, z <= w. */
static const float planes[6][4] = {
    {-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0, 0, -1, 1},
};

unsigned fs_clip_mask(const float v[4])
{
    const float x = v[0], y = v[1], z = v[2], w = v[3];
    unsigned m = 0;
    if (x > w) m |= 1;
    if (0.0f > x + w) m |= 2;
    if (y > w) m |= 4;
    if (0.0f > y + w) m |= 8;
    if (0.0f > z + w) m |= 16;
    if (z > w) m |= 32;
    /* NaN compares false everywhere: mark it outside so it is dropped, and
     * a zero w (possible only at the origin) cannot be divided by. */
    if (m == 0 && !(w > 0.0f))
        m = 0x3f;
    return m;
}

static inline float dot4(const float *a, const float *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* A clipped vertex with its attributes; window position and colours are
 * filled when it is created. */
typedef struct cvert {
    float clip[4];
    float win[5];
    float col[2][4];
    float tc[FS_MAX_TEXTURE_UNITS][4]; /* the first fs_vs_setup.ntex units */
    float fog;        /* fog coordinate (fs_pvert.fog) */
    float col2[2][4]; /* secondary colour (fs_pvert.col2) */
    float psize;      /* derived point size (fs_pvert.psize) */
    bool edge; /* the vertex's edge flag (GL 1.5 spec 2.6.2) */
} cvert;

static void from_pvert(const fs_vs_setup *s, cvert *d, const fs_pvert *v)
{
    d->edge = true;
    memcpy(d->clip, v->clip, sizeof d->clip);
    memcpy(d->win, v->win, sizeof d->win);
    memcpy(d->col, v->col, sizeof d->col);
    memcpy(d->tc, v->tc, (size_t)s->ntex * sizeof d->tc[0]);
    d->fog = v->fog;
    memcpy(d->col2, v->col2, sizeof d->col2);
    d->psize = v->psize;
}

#define LERP(t, out, in) ((out) + (t) * ((in) - (out)))

/* New vertex between out and in at parameter t from out (Mesa's interp()). */
static void interp(const fs_vs_setup *s, cvert *d, float t, const cvert *out, const cvert *in, bool two)
{
    for (int k = 0; k < 4; k++)
        d->clip[k] = LERP(t, out->clip[k], in->clip[k]);
    const float oow = 1.0f / d->clip[3];
    d->win[0] = d->clip[0] * oow * s->vp_scale[0] + s->vp_trans[0];
    d->win[1] = d->clip[1] * oow * s->vp_scale[1] + s->vp_trans[1];
    d->win[2] = d->clip[2] * oow * s->vp_scale[2] + s->vp_trans[2];
    d->win[3] = oow;
    d->win[4] = d->clip[1] * oow * s->yr_scale + s->yr_trans;
    for (int k = 0; k < 4; k++) {
        d->col[0][k] = LERP(t, out->col[0][k], in->col[0][k]);
        d->col2[0][k] = LERP(t, out->col2[0][k], in->col2[0][k]);
    }
    for (int u = 0; u < s->ntex; u++)
        for (int k = 0; k < 4; k++)
            d->tc[u][k] = LERP(t, out->tc[u][k], in->tc[u][k]);
    if (two)
        for (int k = 0; k < 4; k++) {
            d->col[1][k] = LERP(t, out->col[1][k], in->col[1][k]);
            d->col2[1][k] = LERP(t, out->col2[1][k], in->col2[1][k]);
        }
    d->fog = LERP(t, out->fog, in->fog);
    /* The draw module's clipper interpolates every vertex output, the
     * point size too (a GL_POINT polygon's new vertices). */
    d->psize = LERP(t, out->psize, in->psize);
}

static void to_rvertex(fs_rvertex *r, const float *win, const float *col, const float *col2, const float (*tc)[4],
                       int ntex, float fog)
{
    r->fog = fog;
    memcpy(r->color2, col2, sizeof r->color2);
    r->x = win[0];
    r->y = win[1];
    r->z = win[2];
    r->inv_w = win[3];
    r->y_raster = win[4];
    memcpy(r->color, col, sizeof r->color);
    memcpy(r->tex, tc, (size_t)ntex * sizeof r->tex[0]);
}

/* Facing decides which colour two-sided lighting uses (2.14.1); the
 * rasterizer repeats the test on snapped positions for culling. */
static int back_side(const fs_context *c, const float *a, const float *b, const float *d)
{
    float det = (a[0] - d[0]) * (b[1] - d[1]) - (b[0] - d[0]) * (a[1] - d[1]);
    bool ccw = det > 0.0f;
    bool front = c->raster.front_face == GL_CCW ? ccw : !ccw;
    return front ? 0 : 1;
}

/* What a triangle hands the rasterizer of each vertex: window position,
 * colours and secondary colours (front then back, 8 floats each), texture
 * coordinates (per unit) and fog coordinate; and when flat, the provoking
 * vertex's colours and secondary colours instead. */
typedef struct tri_src {
    const float *win[3], *col[3], *col2[3];
    const float (*tc[3])[4];
    float fog[3];
    const float *flat_col, *flat_col2;
    float psize[3]; /* derived point sizes, for GL_POINT polygons */
} tri_src;

static void emit3(fs_context *c, const fs_vs_setup *s, const tri_src *t, unsigned edges)
{
    int side = s->two_side ? back_side(c, t->win[0], t->win[1], t->win[2]) : 0;
    /* Feedback reports each vertex's own colour also under flat shading
     * (measured on OSMesa: Mesa's feedback stage comes before flat
     * shading would apply). */
    const bool flat = t->flat_col && !fs_render_mode_diverts(&c->rmode);
    fs_rvertex r[3];
    for (int i = 0; i < 3; i++)
        to_rvertex(&r[i], t->win[i], (flat ? t->flat_col : t->col[i]) + 4 * side,
                   (flat ? t->flat_col2 : t->col2[i]) + 4 * side, t->tc[i], s->ntex, t->fog[i]);
    for (int i = 0; i < 3; i++)
        r[i].point_size = s->points_attenuated ? t->psize[i] : 0.0f;
    if (fs_render_mode_diverts(&c->rmode)) {
        fs_render_mode_triangle(c, &r[0], &r[1], &r[2]);
        return;
    }
    fs_vs_impl *vi = fs_vs(c);
    if (vi->tri_hook)
        vi->tri_hook(vi->hook_user, &r[0], &r[1], &r[2]);
    if (edges & FS_EDGES_ROUTE)
        fs_raster_polygon(c, &r[0], &r[1], &r[2], edges & FS_EDGES_ALL);
    else
        fs_raster_triangle(c, &r[0], &r[1], &r[2]);
}

static void emit_cverts(fs_context *c, const fs_vs_setup *s, const cvert *a, const cvert *b, const cvert *d,
                        const float *flat_col, const float *flat_col2, unsigned edges)
{
    const tri_src t = {{a->win, b->win, d->win}, {a->col[0], b->col[0], d->col[0]},
                       {a->col2[0], b->col2[0], d->col2[0]}, {a->tc, b->tc, d->tc},
                       {a->fog, b->fog, d->fog}, flat_col, flat_col2, {a->psize, b->psize, d->psize}};
    emit3(c, s, &t, edges);
}

/* The drawn edges of a triangle from its boundary-edge bits (0-2) and its
 * vertices' edge flags (3-5): edge i starts at vertex i. */
static inline unsigned drawn_edges(unsigned edges)
{
    return (edges & (edges >> 3) & FS_EDGES_ALL) | (edges & FS_EDGES_ROUTE);
}

/* An unclipped triangle goes straight from its fs_pverts, without cvert
 * copies: under a tile mask most triangles are only snapped and their
 * areas reported. */
void fs_emit_triangle(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0,
                      const fs_pvert *v1, const fs_pvert *v2, int provoking, unsigned edges)
{
    const fs_pvert *pv[3] = {v0, v1, v2};
    const fs_pvert *f = provoking >= 0 ? pv[provoking] : NULL;
    const tri_src t = {{v0->win, v1->win, v2->win}, {v0->col[0], v1->col[0], v2->col[0]},
                       {v0->col2[0], v1->col2[0], v2->col2[0]}, {v0->tc, v1->tc, v2->tc},
                       {v0->fog, v1->fog, v2->fog}, f ? f->col[0] : NULL, f ? f->col2[0] : NULL,
                       {v0->psize, v1->psize, v2->psize}};
    emit3(c, s, &t, drawn_edges(edges));
}

/* A triangle clipped by the six view-volume planes and the eight user
 * planes has at most 3 + 14 vertices. */
#define MAX_CLIPPED 32

/* Emits the clipped polygon in[0..n-1] as a fan with the first vertex
 * last, as Mesa's clipper does for the last-vertex convention.  Edge k
 * (in[k] -> in[k+1]) is a boundary edge when bound[k]; each fan triangle
 * (in[i-1], in[i], in[0]) carries edge i-1 as its edge 0, the closing edge
 * n-1 as its edge 1 (last triangle) and edge 0 as its edge 2 (first). */
static void emit_clipped(fs_context *c, const fs_vs_setup *s, cvert *const *in, const bool *bound, unsigned n,
                         const float *flat, const float *flat2, unsigned route)
{
    for (unsigned i = 2; i < n; i++) {
        unsigned e = (bound[i - 1] ? 1u : 0u) | (i == n - 1 && bound[n - 1] ? 2u : 0u) | (i == 2 && bound[0] ? 4u : 0u);
        unsigned v = (in[i - 1]->edge ? 1u : 0u) | (in[i]->edge ? 2u : 0u) | (in[0]->edge ? 4u : 0u);
        /* Mesa's clipper marks the first triangle of the fan as starting
         * a primitive for the line stipple, whatever the original was. */
        c->raster.stipple_reset = i == 2;
        emit_cverts(c, s, in[i - 1], in[i], in[0], flat, flat2, (e & v) | route);
    }
}

void fs_clip_triangle(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0,
                      const fs_pvert *v1, const fs_pvert *v2, int provoking, unsigned edges)
{
    cvert store[3 + MAX_CLIPPED];
    cvert *la[MAX_CLIPPED + 1], *lb[MAX_CLIPPED + 1];
    bool ea[MAX_CLIPPED + 1], eb[MAX_CLIPPED + 1];
    cvert **in = la, **out = lb;
    bool *ein = ea, *eout = eb;
    int nstore = 3;
    from_pvert(s, &store[0], v0);
    from_pvert(s, &store[1], v1);
    from_pvert(s, &store[2], v2);
    for (int k = 0; k < 3; k++) {
        in[k] = &store[k];
        store[k].edge = (edges >> (3 + k)) & 1u;
        ein[k] = (edges >> k) & 1u;
    }
    unsigned n = 3;
    unsigned mask = v0->mask | v1->mask | v2->mask;
    const bool two = s->two_side;
    float flat[2][4], flat2[2][4] = {{0}};
    if (provoking >= 0) {
        const fs_pvert *pv[3] = {v0, v1, v2};
        memcpy(flat, pv[provoking]->col, sizeof flat);
        memcpy(flat2, pv[provoking]->col2, sizeof flat2);
    }
    while (mask && n >= 3) {
        int plane = __builtin_ctz(mask);
        mask &= mask - 1;
        const bool user = plane >= FS_CLIP_USER_BIT;
        const float *pl = user ? s->ucp[plane - FS_CLIP_USER_BIT] : planes[plane];
        cvert *prev = in[0];
        float dp_prev = dot4(prev->clip, pl);
        if (!isfinite(dp_prev)) {
            c->stats.triangles_rejected++;
            return;
        }
        unsigned outn = 0;
        in[n] = in[0];
        ein[n] = ein[0];
        for (unsigned i = 1; i <= n; i++) {
            cvert *cur = in[i];
            float dp = dot4(cur->clip, pl);
            if (!isfinite(dp)) {
                c->stats.triangles_rejected++;
                return;
            }
            bool different;
            if (dp_prev >= 0.0f) {
                if (outn >= MAX_CLIPPED) return;
                eout[outn] = ein[i - 1];
                out[outn++] = prev;
                different = dp < 0.0f;
            } else {
                different = !(dp < 0.0f);
            }
            if (different) {
                if (outn >= MAX_CLIPPED || nstore >= 3 + MAX_CLIPPED) return;
                cvert *nv = &store[nstore++];
                /* The edge along the view volume's plane is no polygon
                 * edge (GL 1.5 spec 2.12 keeps edge flags on the original
                 * edges only): the vertex going out starts it with its
                 * flag clear; one coming back in continues the clipped
                 * edge with the outside vertex's flag (Mesa's clipper).
                 * Along a user plane llvmpipe draws the edge (its draw
                 * module does as NVIDIA's drivers do): the vertex going
                 * out starts a boundary edge with its flag set. */
                eout[outn] = ein[i - 1];
                out[outn++] = nv;
                float denom = dp - dp_prev;
                if (dp < 0.0f) {
                    /* Going out: interpolate from the inside vertex. */
                    if (-dp < dp_prev)
                        interp(s, nv, dp / denom, cur, prev, two);
                    else
                        interp(s, nv, -dp_prev / denom, prev, cur, two);
                    nv->edge = user;
                    if (user)
                        eout[outn - 1] = true;
                } else {
                    if (-dp_prev < dp)
                        interp(s, nv, -dp_prev / denom, prev, cur, two);
                    else
                        interp(s, nv, dp / denom, cur, prev, two);
                    nv->edge = prev->edge;
                }
            }
            prev = cur;
            dp_prev = dp;
        }
        cvert **t = in;
        in = out;
        out = t;
        bool *et = ein;
        ein = eout;
        eout = et;
        n = outn;
    }
    if (n < 3) {
        c->stats.triangles_rejected++;
        return;
    }
    emit_clipped(c, s, in, ein, n, provoking >= 0 ? &flat[0][0] : NULL, &flat2[0][0], edges & FS_EDGES_ROUTE);
}

/* flat: the provoking vertex when flat shading, else NULL. */
static void emit_line2(fs_context *c, const fs_vs_setup *s, const cvert *a, const cvert *b, const fs_pvert *flat)
{
    if (fs_render_mode_diverts(&c->rmode))
        flat = NULL; /* as emit3 */
    fs_rvertex r[2];
    to_rvertex(&r[0], a->win, flat ? flat->col[0] : a->col[0], flat ? flat->col2[0] : a->col2[0], a->tc, s->ntex,
               a->fog);
    to_rvertex(&r[1], b->win, flat ? flat->col[0] : b->col[0], flat ? flat->col2[0] : b->col2[0], b->tc, s->ntex,
               b->fog);
    if (fs_render_mode_diverts(&c->rmode))
        fs_render_mode_line(c, &r[0], &r[1]);
    else
        fs_raster_line(c, &r[0], &r[1]);
}

void fs_emit_line(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0, const fs_pvert *v1)
{
    cvert a, b;
    from_pvert(s, &a, v0);
    from_pvert(s, &b, v1);
    emit_line2(c, s, &a, &b, s->flat ? (s->flat_first ? v0 : v1) : NULL);
}

void fs_clip_line(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0, const fs_pvert *v1)
{
    unsigned m = v0->mask | v1->mask;
    if (m == 0) {
        fs_emit_line(c, s, v0, v1);
        return;
    }
    if (v0->mask & v1->mask)
        return;
    /* Every plane of the view volume, x and y too: llvmpipe's draw module
     * has no guard band for lines (measured against OSMesa on random
     * lines with ends beyond the window, of widths 1 to 7: clipped at the
     * viewport's edges they are exact, passed whole 40% of the wide ones
     * differ), and selection and feedback see them clipped the same way
     * (measured: a line leaving the window ends on its edge). */
    unsigned pm = m; /* then the user planes (bits 4 up) */
    float t0 = 0.0f, t1 = 0.0f;
    while (pm) {
        int plane = __builtin_ctz(pm);
        pm &= pm - 1;
        const float *pl = plane >= FS_CLIP_USER_BIT ? s->ucp[plane - FS_CLIP_USER_BIT] : planes[plane];
        float dp0 = dot4(v0->clip, pl), dp1 = dot4(v1->clip, pl);
        if (!isfinite(dp0) || !isfinite(dp1))
            return;
        if (dp1 < 0.0f) {
            float t = dp1 / (dp1 - dp0);
            t1 = t > t1 ? t : t1;
        }
        if (dp0 < 0.0f) {
            float t = dp0 / (dp0 - dp1);
            t0 = t > t0 ? t : t0;
        }
        if (t0 + t1 >= 1.0f)
            return;
    }
    cvert a, b, ca, cb;
    from_pvert(s, &a, v0);
    from_pvert(s, &b, v1);
    cvert *pa = &a, *pb = &b;
    if (v0->mask) {
        interp(s, &ca, t0, &a, &b, false);
        pa = &ca;
    }
    if (v1->mask) {
        interp(s, &cb, t1, &b, &a, false);
        pb = &cb;
    }
    if (!(pa->clip[3] > 0.0f) || !(pb->clip[3] > 0.0f))
        return;
    emit_line2(c, s, pa, pb, s->flat ? (s->flat_first ? v0 : v1) : NULL);
}

void fs_emit_point(fs_context *c, const fs_vs_setup *s, const fs_pvert *v)
{
    fs_rvertex r;
    r.x = v->win[0];
    r.y = v->win[1];
    r.z = v->win[2];
    r.inv_w = v->win[3];
    r.y_raster = v->win[4];
    memcpy(r.color, v->col[0], sizeof r.color);
    memcpy(r.tex, v->tc, (size_t)s->ntex * sizeof r.tex[0]);
    r.fog = v->fog;
    memcpy(r.color2, v->col2[0], sizeof r.color2);
    r.point_size = s->points_attenuated ? v->psize : s->point_size;
    if (fs_render_mode_diverts(&c->rmode))
        fs_render_mode_point(c, &r);
    else
        fs_raster_point_sized(c, &r, r.point_size);
}
