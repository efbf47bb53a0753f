/*
 * Triangle rasterization (GL 1.5 spec 3.5), modelled pixel-exactly on
 * llvmpipe as OSMesa uses it (Mesa 22.3: lp_setup_tri.c, lp_rast_tri.c,
 * lp_state_setup.c, lp_bld_interp.c; read for the rules, not copied).
 *
 * Coverage: vertices are snapped to fixed point with subpixel_bits fraction
 * bits after subtracting the half-pixel centre offset, edge functions are
 * exact 64-bit integers, and a +1 bias on the constant term includes pixels
 * exactly on left edges and on horizontal edges at the triangle's lowest GL y
 * (llvmpipe's bottom_edge_rule in its y-down frame).  Facing and zero-area
 * culling use the fixed-point signed area (llvmpipe's calc_fixed_position).
 *
 * Attributes: planes are set up in float from the unsnapped positions in
 * llvmpipe's order of operations, evaluated at integer pixel positions with
 * a fused multiply-add (LLVM fuses llvm.fmuladd on this FMA-capable CPU), and
 * colours/texture coordinates are interpolated perspective-correctly
 * (llvmpipe sets LP_INTERP_PERSPECTIVE for smooth colours).
 */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "rasterizer_priv.h"
#include "../units/texture_unit.h"
#include "raster_threads.h"

/* x86 builds carry an FMA variant of the attribute evaluation, chosen at run
 * time (no -march flags in reference builds). */
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define FS_RASTER_HAVE_FMA 1
#else
#define FS_RASTER_HAVE_FMA 0
#endif


#ifndef FS_RASTER_PREFETCH
#define FS_RASTER_PREFETCH 1
#endif

#ifdef __clang__
/* Every float operation below must round separately, as llvmpipe's do. */
#pragma STDC FP_CONTRACT OFF
#endif

void fs_raster_state_init(fs_raster_state *r, int subpixel_bits)
{
    /* Initial values: GL 1.5 spec table 6.13. */
    memset(r, 0, sizeof *r);
    r->cull_enabled = false;
    r->cull_mode = GL_BACK;
    r->front_face = GL_CCW;
    r->offset_fill = false;
    r->offset_factor = 0.0f;
    r->offset_units = 0.0f;
    r->polygon_mode[0] = r->polygon_mode[1] = GL_FILL;
    for (int i = 0; i < 32; i++)
        r->stipple[i] = 0xffffffffu;
    r->point_size = 1.0f;
    r->line_width = 1.0f;
    r->subpixel_bits = subpixel_bits < 1 ? 8 : subpixel_bits > 12 ? 12 : subpixel_bits;
    r->interpolate_tex = false;
    r->tex_mask = 0;
    r->tex_units = 1;
    r->reference_path = false;
    r->use_y_raster = false;
#if FS_RASTER_HAVE_FMA
    r->has_fma = __builtin_cpu_supports("fma");
    r->has_avx2 = r->has_fma && __builtin_cpu_supports("avx2");
#else
    r->has_fma = false;
    r->has_avx2 = false;
#endif
}

/* Round to nearest even like cvtss2si/cvtps2dq under the default MXCSR.
 * lrintf is a libm call here (errno semantics keep GCC from inlining it),
 * and this runs per vertex and per fragment. */
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
static inline int32_t round_even(float v) { return _mm_cvtss_si32(_mm_set_ss(v)); }
#else
static inline int32_t round_even(float v) { return (int32_t)lrintf(v); }
#endif

/* ---- attribute planes and quad emission (shared with lines and points) ---- */

/* llvmpipe evaluates a0 + dadx*x + dady*y as two llvm.fmuladd calls, which
 * LLVM turns into FMA instructions on this machine.  The product of a float
 * and a small integer is exact in double, so one double addition rounded to
 * float reproduces the FMA except when the double sum itself had to round
 * onto a float rounding boundary (probability about 2^-29). */
static inline float fmadd(float a, float b, float c)
{
    return (float)((double)a * (double)b + (double)c);
}

static inline float plane_at(const fs_plane *p, float x, float y)
{
    if (p->constant)
        return p->a0;
    return fmadd(p->dady, y, fmadd(p->dadx, x, p->a0));
}

void fs_plane_constant(fs_plane *p, float v)
{
    p->a0 = v;
    p->dadx = p->dady = 0.0f;
    p->constant = true;
}

static inline uint32_t quantize_depth(float z, int depth_bits)
{
    /* llvmpipe clamps the fragment depth to [0,1] (unorm buffer, depth clamp
     * off) and converts it with lp_build_clamped_float_to_unsigned_norm. */
    if (!(z > 0.0f))
        return 0;
    if (z >= 1.0f)
        return depth_bits >= 32 ? 0xffffffffu : (uint32_t)((1ull << depth_bits) - 1);
    /* Measured against OSMesaGetDepthBuffer (tests/test_rasterizer.c,
     * random_*: every written depth equal): the depth is scaled by
     * 2^bits - 1 in float and rounded to nearest even. */
    float scale = (float)((1u << depth_bits) - 1);
    return (uint32_t)round_even(z * scale);
}

uint32_t fs_raster_quantize_depth(float z, int depth_bits)
{
    return quantize_depth(z, depth_bits);
}

/* The per-pixel attribute evaluation, instantiated once with the portable
 * plane_at and once with hardware FMA (same results; the FMA one is faster
 * and needs no emulation). */
/* Texture coordinates (s, t, r, q) at window position (px, py) into
 * out[4], perspective-correct like the colours (GL 1.5 spec 3.5.1 eq.
 * 3.7): for the quad's own pixels and for the rows and the neighbouring quad
 * llvmpipe's lambda also reads. */
#define FS_PLANES4_AT(PLANE_AT, planes, px, py, out)                             \
    do {                                                                          \
        float *out_ = (out);                                                      \
        if (s->perspective) {                                                     \
            float oow_ = 1.0f / PLANE_AT(&s->w, px, py);                          \
            for (int k_ = 0; k_ < 4; k_++)                                        \
                out_[k_] = PLANE_AT(&(planes)[k_], px, py) * oow_;                \
        } else {                                                                  \
            for (int k_ = 0; k_ < 4; k_++)                                        \
                out_[k_] = PLANE_AT(&(planes)[k_], px, py);                       \
        }                                                                         \
    } while (0)
/* A unit's coordinates that are constants for the primitive (tex_constant)
 * are used as they are, without the division. */
#define FS_TEX_AT(PLANE_AT, px, py, out)                                          \
    do {                                                                          \
        if (s->tex_constant & (1u << u)) {                                        \
            for (int kc_ = 0; kc_ < 4; kc_++)                                     \
                (out)[kc_] = s->tex[u][kc_].a0;                                   \
        } else {                                                                  \
            FS_PLANES4_AT(PLANE_AT, s->tex[u], px, py, out);                      \
        }                                                                         \
    } while (0)

#define FS_EMIT_PIXELS(PLANE_AT)                                                  \
    for (int i = 0; i < 4; i++) {                                                 \
        if (!(m & (1u << i)))                                                     \
            continue;                                                             \
        float px = (float)(q->x + (i & 1));                                       \
        float py = (float)fs_raster_row_to_gl(s->height, q->y + (i >> 1));        \
        /* llvmpipe adds the polygon offset after interpolation (it travels in \
         * a0.x of the position), even when it is zero. */                       \
        float z = PLANE_AT(&s->z, px, py) + s->zoffset;                           \
        q->z[i] = quantize_depth(z, depth_bits);                                  \
        if (s->perspective && !(s->color_constant && (s->color2_constant || !s->use_color2))) { \
            /* Perspective-correct (GL 1.5 spec 3.5.1 eq. 3.7): a/w and 1/w are \
             * linear in window space; llvmpipe divides per pixel (not a    \
             * constant colour: fs_raster_state.const_attribs). */           \
            float oow = 1.0f / PLANE_AT(&s->w, px, py);                           \
            for (int k = 0; k < 4; k++)                                           \
                q->color[i][k] = s->color_constant ? PLANE_AT(&s->color[k], px, py) \
                                                   : PLANE_AT(&s->color[k], px, py) * oow; \
            for (int k = 0; k < 3 && s->use_color2; k++)                          \
                q->color2[i][k] = s->color2_constant ? PLANE_AT(&s->color2[k], px, py) \
                                                     : PLANE_AT(&s->color2[k], px, py) * oow; \
        } else {                                                                  \
            for (int k = 0; k < 4; k++)                                           \
                q->color[i][k] = PLANE_AT(&s->color[k], px, py);                  \
            for (int k = 0; k < 3 && s->use_color2; k++)                          \
                q->color2[i][k] = PLANE_AT(&s->color2[k], px, py);                \
        }                                                                         \
        /* The fog coordinate: perspective-correct whatever the shading. */   \
        if (s->use_fog)                                                           \
            q->fog[i] = s->perspective ? PLANE_AT(&s->fog, px, py) * (1.0f / PLANE_AT(&s->w, px, py)) \
                                       : PLANE_AT(&s->fog, px, py);               \
    }                                                                             \
    /* Texture coordinates of all four pixels, covered or not: lambda comes \
     * from the quad's differences (GL 1.5 spec 3.8.8; llvmpipe shades   \
     * whole quads), for each enabled unit. */                                   \
    if (s->use_tex)                                                               \
        FS_FOR_EACH_UNIT(u, s->tex_mask) {                                        \
            fs_quad_tex *qt = &q->unit[u];                                        \
            for (int i = 0; i < 4; i++) {                                         \
                float px = (float)(q->x + (i & 1));                               \
                float py = (float)fs_raster_row_to_gl(s->height, q->y + (i >> 1)); \
                FS_TEX_AT(PLANE_AT, px, py, qt->tex[i]);                          \
            }                                                                     \
            /* Odd heights: the rows that complete llvmpipe's quads (fs_quad). */ \
            if (s->height & 1)                                                    \
                for (int i = 0; i < 4; i++) {                                     \
                    float px = (float)(q->x + (i & 1));                           \
                    int gy = i < 2 ? q->y - 1 : q->y + 2;                         \
                    float py = (float)fs_raster_row_to_gl(s->height, gy);         \
                    FS_TEX_AT(PLANE_AT, px, py, i < 2 ? qt->tex_below[i & 1] : qt->tex_above[i & 1]); \
                }                                                                 \
            /* The quad sharing llvmpipe's vector, when texturing asks (fs_quad). */ \
            if (tex_pair)                                                         \
                for (int r = (s->height & 1) ? 0 : 1; r < ((s->height & 1) ? 4 : 3); r++) \
                    for (int j = 0; j < 2; j++) {                                 \
                        float px = (float)((q->x ^ 2) + j);                       \
                        float py = (float)fs_raster_row_to_gl(s->height, q->y - 1 + r); \
                        FS_TEX_AT(PLANE_AT, px, py, qt->tex_pair[r][j]);          \
                    }                                                             \
        }                                                                         \
    /* A smooth line's or point's coverage attribute: a generic varying,     \
     * perspective-correct like the texture coordinates (fs_prim_setup.aa). */ \
    if (s->aa_shade)                                                              \
        for (int i = 0; i < 4; i++) {                                             \
            if (!(m & (1u << i)))                                                 \
                continue;                                                         \
            float px = (float)(q->x + (i & 1));                                   \
            float py = (float)fs_raster_row_to_gl(s->height, q->y + (i >> 1));    \
            FS_PLANES4_AT(PLANE_AT, s->aa, px, py, q->aa[i]);                     \
        }

static void emit_pixels(const fs_prim_setup *s, fs_quad *q, unsigned m, int depth_bits, bool tex_pair)
{
    FS_EMIT_PIXELS(plane_at)
}

#if FS_RASTER_HAVE_FMA
__attribute__((target("fma"))) static inline float plane_at_fma(const fs_plane *p, float x, float y)
{
    if (p->constant)
        return p->a0;
    return __builtin_fmaf(p->dady, y, __builtin_fmaf(p->dadx, x, p->a0));
}

__attribute__((target("fma"))) static void emit_pixels_fma(const fs_prim_setup *s, fs_quad *q, unsigned m,
                                                            int depth_bits, bool tex_pair)
{
    FS_EMIT_PIXELS(plane_at_fma)
}
#endif

void fs_raster_emit_quad(fs_context *c, const fs_prim_setup *s, fs_quad *q)
{
    /* The observer's tile mask (observer.h): one branch in functional mode. */
    if (c->observer && fs_tile_mask_drops_quad(&c->observer->mask, q->x, q->y))
        return;
    unsigned m = q->mask;
    if (s->stipple) {
        /* Polygon stipple (3.5.6): window-aligned, so the quad's two rows
         * and two columns (q->x and q->y are even) pick two adjacent bits
         * of two pattern rows. */
        unsigned k = (unsigned)q->x & 31u;
        unsigned lo = (s->stipple[(unsigned)q->y & 31u] >> k) & 3u;
        unsigned hi = (s->stipple[((unsigned)q->y + 1u) & 31u] >> k) & 3u;
        m &= lo | hi << 2;
        if (!m)
            return;
        q->mask = m;
    }
    q->front_facing = s->front;
    c->stats.quads_generated++;
    c->stats.fragments_generated += (unsigned)((0x4332322132212110ull >> (4 * (m & 0xfu))) & 0xfu);
#if FS_RASTER_HAVE_FMA
    if (c->raster.has_fma) {
        emit_pixels_fma(s, q, m, c->fb.depth_bits, c->raster.tex_pair_lod);
        if (s->use_tex)
            fs_texture_quad(c, q); /* texturing (GL 1.5 spec 3.8) precedes 4.1 */
        if (s->aa_shade)
            s->aa_shade(q); /* the end of llvmpipe's fragment shader */
        fs_quad_work w = fs_fragment_quad(c, q);
        FS_OBSERVE(c, quad, c, q, &w);
        return;
    }
#endif
    emit_pixels(s, q, m, c->fb.depth_bits, c->raster.tex_pair_lod);
    if (s->use_tex)
        fs_texture_quad(c, q);
    if (s->aa_shade)
        s->aa_shade(q);
    fs_quad_work w = fs_fragment_quad(c, q);
    FS_OBSERVE(c, quad, c, q, &w);
}

/* ---- generic plane regions (lines, points) ---- */

void fs_edge_plane(fs_edge_planes *e, int i, int64_t xa, int64_t ya, int64_t xb, int64_t yb, int order)
{
    int64_t dcdx = ya - yb, dcdy = xa - xb;
    int64_t cc = dcdx * xa - dcdy * ya;
    /* Same fill convention as triangles: left edges and GL-bottom edges. */
    if (dcdx < 0 || (dcdx == 0 && dcdy < 0))
        cc++;
    e->c[i] = cc;
    e->dcdx[i] = dcdx * ((int64_t)1 << order);
    e->dcdy[i] = dcdy * ((int64_t)1 << order);
}

void fs_raster_planes(fs_context *c, const fs_prim_setup *s, const fs_edge_planes *e)
{
    const int H = s->height;
    int gy0 = fs_raster_row_to_gl(H, e->y1), gy1 = fs_raster_row_to_gl(H, e->y0);
    for (int qy = gy0 & ~1; qy <= gy1; qy += 2) {
        for (int qx = e->x0 & ~1; qx <= e->x1; qx += 2) {
            unsigned mask = 0;
            for (int i = 0; i < 4; i++) {
                int px = qx + (i & 1), gy = qy + (i >> 1);
                int ry = fs_raster_row_to_gl(H, gy);
                if (px < e->x0 || px > e->x1 || ry < e->y0 || ry > e->y1)
                    continue;
                bool in = true;
                for (int k = 0; k < e->n; k++)
                    in = in && e->c[k] - e->dcdx[k] * px + e->dcdy[k] * ry > 0;
                if (in)
                    mask |= 1u << i;
            }
            if (mask) {
                fs_quad q;
                q.x = qx;
                q.y = qy;
                q.mask = mask;
                fs_raster_emit_quad(c, s, &q);
            }
        }
    }
}

/* ---- triangle setup ---- */

typedef struct tri_edges {
    /* E(x, y) = c - dcdx*x + dcdy*y at integer pixel (x, y) of the raster
     * frame, fill-rule bias included; the pixel is inside when E > 0 for all
     * three edges (llvmpipe tests E - 1 >= 0). */
    int64_t c[3], dcdx[3], dcdy[3];
    int x0, x1, y0, y1; /* bounding box in raster pixels, inclusive, on screen */
} tri_edges;

/* Fixed-point limit: coordinates of |v| < 2^29 subpixels keep every edge
 * product below 2^61.  llvmpipe itself only ever sees clipped vertices (draw
 * clips with no guard band), so anything beyond is not a case to match. */
#define FIXED_LIMIT 536870912.0f

typedef struct vpos { float x, y; } vpos;

/* Builds the plane of one attribute (lp_state_setup.c calc_coef4). */
typedef struct coef_args {
    float x0c, y0c, dx01o, dy01o, dx20o, dy20o;
} coef_args;

static void calc_coef(fs_plane *p, const coef_args *g, float a0, float a1, float a2)
{
    float da01 = a0 - a1;
    float da20 = a2 - a0;
    float t1 = da01 * g->dy20o;
    float t2 = da20 * g->dy01o;
    float dadx = t1 - t2;
    float t3 = da20 * g->dx01o;
    float t4 = da01 * g->dx20o;
    float dady = t3 - t4;
    float ax = dadx * g->x0c;
    float ay = dady * g->y0c;
    float sum = ax + ay;
    p->a0 = a0 - sum;
    p->dadx = dadx;
    p->dady = dady;
    p->constant = dadx == 0.0f && dady == 0.0f && p->a0 == a0;
}

/* The n planes of a colour (the primary, or the secondary's r, g, b),
 * the float[4] at byte offset `field` of each vertex: constants of the
 * provoking vertex (the first) when flat, else divided by w when the
 * primitive has perspective.  With every 1/w equal to 1, llvmpipe's
 * multiply by 1/w and divide by the interpolated 1/w (exactly 1) change
 * nothing. */
static void color_planes(fs_plane *p, int n, const coef_args *g, const fs_rvertex *const v[3], size_t field,
                         const fs_prim_setup *s, bool constant)
{
    const float *col[3];
    for (int i = 0; i < 3; i++)
        col[i] = (const float *)(const void *)((const char *)v[i] + field);
    for (int k = 0; k < n; k++) {
        if (constant)
            fs_plane_constant(&p[k], col[0][k]);
        else if (s->perspective)
            calc_coef(&p[k], g, col[0][k] * v[0]->inv_w, col[1][k] * v[1]->inv_w, col[2][k] * v[2]->inv_w);
        else
            calc_coef(&p[k], g, col[0][k], col[1][k], col[2][k]);
    }
}

static void raster_tri_fast(fs_context *c, const fs_prim_setup *s, const tri_edges *e, const fs_tile_mask *t);
static void report_area(fs_context *c, const tri_edges *e, int64_t area2);
static bool box_meets_band(const fs_raster_state *r, int H, const tri_edges *e);
static bool box_meets_mask(const fs_context *c, const fs_tile_mask *t, const tri_edges *e);
static void raster_tri_reference(fs_context *c, const fs_prim_setup *s, const tri_edges *e);

/* What every triangle needs before its edges: snapped positions in
 * llvmpipe's counter-clockwise order, facing and the on-screen box. */
typedef struct tri_snap {
    int idx[3];      /* the vertices in counter-clockwise order */
    int64_t x[3], y[3]; /* snapped, in that order */
    int64_t area;    /* twice the signed area in subpixels squared */
    bool front;
    tri_edges e;     /* the box only */
} tri_snap;

/* false when the triangle makes no fragment (culled, degenerate or off
 * screen; counted). */
static bool tri_snap_box(fs_context *c, const float px[3], const float py[3], tri_snap *t)
{
    const fs_raster_state *r = &c->raster;
    const int W = c->fb.width, H = c->fb.height;
    const int order = r->subpixel_bits;
    const float fixed_one = (float)(1 << order);
    int64_t X[3], Y[3];

    /* Snap (lp_setup_tri.c calc_fixed_position): subtract the pixel-centre
     * offset, scale, round to nearest even (cvtps2dq).  Non-finite or
     * out-of-range positions cannot be snapped: the triangle is dropped
     * and counted with the culled ones. */
    for (int i = 0; i < 3; i++) {
        float fx = (px[i] - 0.5f) * fixed_one;
        float fy = (py[i] - 0.5f) * fixed_one;
        if (!(fabsf(fx) < FIXED_LIMIT) || !(fabsf(fy) < FIXED_LIMIT)) {
            c->stats.triangles_culled++;
            return false;
        }
        X[i] = round_even(fx);
        Y[i] = round_even(fy);
    }

    /* Signed area in fixed point; positive is counter-clockwise in GL's
     * y-up window coordinates (the two y flips of llvmpipe's frame and its
     * area formula cancel). */
    int64_t area = (X[0] - X[1]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[0] - Y[1]);
    if (area == 0) {
        c->stats.triangles_culled++;
        return false;
    }
    t->area = area;
    /* GL 1.5 spec 3.5.1: facing from the sign of the area and glFrontFace. */
    bool ccw = area > 0;
    bool front = (r->front_face == GL_CCW) ? ccw : !ccw;
    if (fs_raster_culled(r, front)) {
        c->stats.triangles_culled++;
        return false;
    }
    t->front = front;

    /* llvmpipe rasterizes every triangle counter-clockwise; a clockwise one
     * has v0 and v1 swapped (last-vertex provoking convention), which also
     * changes which vertex the attribute planes are built from. */
    int *idx = t->idx;
    idx[0] = 0;
    idx[1] = 1;
    idx[2] = 2;
    if (!ccw) {
        idx[0] = 1;
        idx[1] = 0;
    }
    int64_t *x = t->x, *y = t->y;
    for (int i = 0; i < 3; i++) {
        x[i] = X[idx[i]];
        y[i] = Y[idx[i]];
    }

    /* Bounding box (do_triangle_ccw): inclusive x0, exclusive max x; the y
     * rounding is adjusted by one subpixel for the bottom-edge rule. */
    const int adj = 1;
    int64_t minx, maxx, miny, maxy;
    fs_corner_box(x, y, 3, &minx, &maxx, &miny, &maxy);
    int64_t bx0 = fs_floor_shift(minx, order);
    int64_t bx1 = fs_floor_shift(maxx - 1, order);
    int64_t by0 = fs_floor_shift(miny + adj, order);
    int64_t by1 = fs_floor_shift(maxy - 1 + adj, order);
    if (!fs_window_box(bx0, by0, bx1, by1, W, H, &t->e.x0, &t->e.x1, &t->e.y0, &t->e.y1)) {
        /* Entirely off screen: llvmpipe counts it culled too. */
        c->stats.triangles_rasterized++;
        return false;
    }
    return true;
}

void fs_raster_triangle_dropped(fs_context *c, const float x[3], const float y_raster[3])
{
    if (c->par_recording) /* earlier triangles first (raster_threads.h) */
        fs_par_draw_end(c);
    tri_snap t;
    if (!tri_snap_box(c, x, y_raster, &t))
        return;
    report_area(c, &t.e, t.area);
    c->stats.triangles_rasterized++;
}

/* aa: NULL, or the coverage attribute of each vertex (fs_raster_triangle_aa). */
static void raster_triangle(fs_context *c, const fs_rvertex *const v[3], const float (*aa)[4],
                            void (*aa_shade)(fs_quad *q))
{
    const fs_raster_state *r = &c->raster;
    const int W = c->fb.width, H = c->fb.height;
    const int order = r->subpixel_bits;
    float px[3], py[3];
    for (int i = 0; i < 3; i++) {
        px[i] = v[i]->x;
        py[i] = r->use_y_raster ? v[i]->y_raster : fs_raster_y(H, v[i]->y);
    }
    tri_snap t;
    if (!tri_snap_box(c, px, py, &t))
        return;
    if (r->band_n > 1 && !box_meets_band(r, H, &t.e)) {
        /* Another thread's rows only: counted as handed on, as below. */
        c->stats.triangles_rasterized++;
        return;
    }
    const bool front = t.front;
    const int *idx = t.idx;
    const int64_t *x = t.x, *y = t.y;
    tri_edges e = t.e;

    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        int64_t dcdx = y[i] - y[j];
        int64_t dcdy = x[i] - x[j];
        int64_t cc = dcdx * x[i] - dcdy * y[i];
        /* Fill convention: pixels exactly on an edge belong to left edges
         * (dcdx < 0) and, for horizontal edges, to the bottom edge of GL's
         * y-up window (dcdy < 0 in llvmpipe's y-down frame). */
        if (dcdx < 0 || (dcdx == 0 && dcdy < 0))
            cc++;
        e.c[i] = cc;
        e.dcdx[i] = dcdx * (1 << order);
        e.dcdy[i] = dcdy * (1 << order);
    }

    /* The observer's tile mask: a triangle none of whose box's tiles is
     * masked only reports its area and needs no attribute planes. */
    const fs_tile_mask *ts = r->reference_path ? NULL : fs_tile_mask_active(c);
    if (ts) {
        report_area(c, &e, t.area);
        if (!box_meets_mask(c, ts, &e)) {
            c->stats.triangles_rasterized++;
            return;
        }
    }
    /* Small triangles land on cold framebuffer lines: start fetching the
     * depth and colour rows now so the misses overlap the plane setup
     * below instead of stalling the per-fragment operations. */
    if (FS_RASTER_PREFETCH && e.y1 - e.y0 < 8 && e.x1 - e.x0 < 16) {
        for (int ry = e.y0; ry <= e.y1; ry++) {
            size_t o = (size_t)fs_raster_row_to_gl(H, ry) * (size_t)W + (size_t)e.x0;
            __builtin_prefetch(&c->fb.depth[o], 1);
            __builtin_prefetch(&c->fb.color[o * 4], 1);
            if (((o + (size_t)(e.x1 - e.x0)) ^ o) >= 16) {
                __builtin_prefetch(&c->fb.depth[o + (size_t)(e.x1 - e.x0)], 1);
                __builtin_prefetch(&c->fb.color[(o + (size_t)(e.x1 - e.x0)) * 4], 1);
            }
        }
    }
    /* Attribute planes (lp_state_setup.c init_args/calc_coef4) from the
     * unsnapped float positions, in llvmpipe's vertex order. */
    const fs_rvertex *a = v[idx[0]], *b = v[idx[1]], *d = v[idx[2]];
    vpos pa = {px[idx[0]], py[idx[0]]}, pb = {px[idx[1]], py[idx[1]]}, pd = {px[idx[2]], py[idx[2]]};
    coef_args g;
    float dx01 = pa.x - pb.x, dy01 = pa.y - pb.y;
    float dx20 = pd.x - pa.x, dy20 = pd.y - pa.y;
    float ef_e = dx01 * dy20;
    float ef_f = dy01 * dx20;
    float ooa = 1.0f / (ef_e - ef_f);
    g.x0c = pa.x - 0.5f;
    g.y0c = pa.y - 0.5f;
    g.dx20o = dx20 * ooa;
    g.dy20o = dy20 * ooa;
    g.dx01o = dx01 * ooa;
    g.dy01o = dy01 * ooa;

    fs_prim_setup s;
    s.front = front;
    s.height = H;
    s.use_tex = r->interpolate_tex;
    s.use_fog = r->interpolate_fog;
    s.tex_mask = r->tex_mask;
    s.zoffset = 0.0f;
    /* llvmpipe's triangle setup offsets by the factor and units whenever
     * any of the three offset enables is on (Mesa's state tracker passes
     * them on only then; lp_state_setup.c reads the values, not which
     * enable: measured on OSMesa, GL_POLYGON_OFFSET_POINT alone moves
     * filled triangles).  On the draw-module route the offset is already
     * in the vertices' depth (polygon_mode.c) and the setup applies none. */
    if ((r->offset_fill || r->offset_line || r->offset_point) && !fs_raster_draw_pipeline(r) &&
        (r->offset_factor != 0.0f || r->offset_units != 0.0f)) {
        /* GL 1.5 spec 3.5.5: o = m*factor + r*units with m the max depth
         * slope; llvmpipe (lp_do_offset_tri) takes m = max(|dz/dx|, |dz/dy|)
         * from the plane and r = 2 / (2^bits - 1) (util_get_depth_format_mrd
         * times two, in double, then rounded to float). */
        float dz01 = a->z - b->z, dz20 = d->z - a->z;
        float r1a = dz20 * dy01, r1b = dy20 * dz01;
        float r2a = dx20 * dz01, r2b = dz20 * dx01;
        float res1 = r1a - r1b, res2 = r2a - r2b;
        float dzdx = fabsf(res1 * ooa), dzdy = fabsf(res2 * ooa);
        /* Unordered-greater select: a NaN dz/dy picks dz/dx. */
        float mx = !(dzdx <= dzdy) ? dzdx : dzdy;
        float mult = mx * r->offset_factor;
        double mrd = 1.0 / (double)((1ull << c->fb.depth_bits) - 1);
        float units = (float)((double)r->offset_units * mrd * 2.0);
        s.zoffset = units + mult;
    }
    calc_coef(&s.z, &g, a->z, b->z, d->z);
    s.perspective = !(a->inv_w == 1.0f && b->inv_w == 1.0f && d->inv_w == 1.0f);
    /* Flat shading: the provoking colour (every vertex carries it) as a
     * constant (fs_raster_state.flat_color). */
    s.color_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR);
    s.color2_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR2);
    s.tex_constant = r->const_attribs / FS_ATTR_TEX(0);
    if (s.perspective)
        calc_coef(&s.w, &g, a->inv_w, b->inv_w, d->inv_w);
    const fs_rvertex *const abd[3] = {a, b, d};
    color_planes(s.color, 4, &g, abd, offsetof(fs_rvertex, color), &s, s.color_constant);
    s.use_color2 = r->interpolate_color2;
    if (s.use_color2)
        color_planes(s.color2, 3, &g, abd, offsetof(fs_rvertex, color2), &s, s.color2_constant);
    if (s.use_tex)
        FS_FOR_EACH_UNIT(u, s.tex_mask)
            if (s.tex_constant & (1u << u))
                for (int k = 0; k < 4; k++)
                    fs_plane_constant(&s.tex[u][k], a->tex[u][k]);
    if (s.perspective) {
        if (s.use_tex)
            FS_FOR_EACH_UNIT(u, s.tex_mask & ~s.tex_constant)
                for (int k = 0; k < 4; k++) {
                    float ta = a->tex[u][k] * a->inv_w, tb = b->tex[u][k] * b->inv_w;
                    float td = d->tex[u][k] * d->inv_w;
                    calc_coef(&s.tex[u][k], &g, ta, tb, td);
                }
        if (s.use_fog)
            calc_coef(&s.fog, &g, a->fog * a->inv_w, b->fog * b->inv_w, d->fog * d->inv_w);
    } else {
        if (s.use_tex)
            FS_FOR_EACH_UNIT(u, s.tex_mask & ~s.tex_constant)
                for (int k = 0; k < 4; k++)
                    calc_coef(&s.tex[u][k], &g, a->tex[u][k], b->tex[u][k], d->tex[u][k]);
        if (s.use_fog)
            calc_coef(&s.fog, &g, a->fog, b->fog, d->fog);
    }

    s.aa_shade = aa_shade;
    /* Stipple applies to filled polygons only; the triangles of smooth
     * lines and points come with it off (draw_get_rasterizer_no_cull). */
    s.stipple = r->polygon_stipple && !aa_shade ? r->stipple : NULL;
    if (aa_shade)
        for (int k = 0; k < 4; k++) {
            const float *aa0 = aa[idx[0]], *aa1 = aa[idx[1]], *aa2 = aa[idx[2]];
            if (s.perspective)
                calc_coef(&s.aa[k], &g, aa0[k] * a->inv_w, aa1[k] * b->inv_w, aa2[k] * d->inv_w);
            else
                calc_coef(&s.aa[k], &g, aa0[k], aa1[k], aa2[k]);
        }

    c->stats.triangles_rasterized++;
    if (r->reference_path)
        raster_tri_reference(c, &s, &e);
    else
        raster_tri_fast(c, &s, &e, ts);
}

void fs_raster_triangle(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2)
{
    if (c->par_recording) {
        fs_par_record(c, v0, v1, v2);
        return;
    }
    const fs_rvertex *const v[3] = {v0, v1, v2};
    raster_triangle(c, v, NULL, NULL);
}

void fs_raster_triangle_now(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2)
{
    const fs_rvertex *const v[3] = {v0, v1, v2};
    raster_triangle(c, v, NULL, NULL);
}

void fs_raster_triangle_aa(fs_context *c, const fs_rvertex *const v[3], const float aa[3][4],
                           void (*aa_shade)(fs_quad *q))
{
    /* The draw module's rasterizer state for these triangles keeps only
     * scissor, flat shading and the pixel-centre rules: no culling, no
     * polygon offset (draw_get_rasterizer_no_cull).  The vertices' y is in
     * llvmpipe's frame (y_raster). */
    if (c->par_recording) /* earlier triangles first (raster_threads.h) */
        fs_par_draw_end(c);
    fs_raster_state *r = &c->raster;
    const fs_raster_state saved = *r;
    r->cull_enabled = false;
    r->offset_fill = r->offset_line = r->offset_point = false;
    r->use_y_raster = true;
    raster_triangle(c, v, aa, aa_shade);
    r->cull_enabled = saved.cull_enabled;
    r->offset_fill = saved.offset_fill;
    r->offset_line = saved.offset_line;
    r->offset_point = saved.offset_point;
    r->use_y_raster = saved.use_y_raster;
}

void fs_raster_quad_aa(fs_context *c, const fs_rvertex v[4], const float aa[4][4], const int tris[2][3],
                       void (*aa_shade)(fs_quad *q))
{
    for (int t = 0; t < 2; t++) {
        const fs_rvertex *tv[3];
        float ta[3][4];
        for (int i = 0; i < 3; i++) {
            tv[i] = &v[tris[t][i]];
            memcpy(ta[i], aa[tris[t][i]], sizeof ta[i]);
        }
        fs_raster_triangle_aa(c, tv, (const float(*)[4])ta, aa_shade);
    }
}

/* ---- coverage: the plain reference and the incremental fast path ---- */

/* Quads are aligned to even GL coordinates; the raster frame is flipped in
 * y, so GL row gy is raster row H-1-gy. */
static void raster_tri_reference(fs_context *c, const fs_prim_setup *s, const tri_edges *e)
{
    /* The plain per-pixel evaluation lines and points use, on three edges. */
    fs_edge_planes p;
    p.n = 3;
    for (int k = 0; k < 3; k++) {
        p.c[k] = e->c[k];
        p.dcdx[k] = e->dcdx[k];
        p.dcdy[k] = e->dcdy[k];
    }
    p.x0 = e->x0;
    p.x1 = e->x1;
    p.y0 = e->y0;
    p.y1 = e->y1;
    fs_raster_planes(c, s, &p);
}

/* The same coverage with the edge functions stepped incrementally: per quad
 * the three edges' values at the four pixels are formed by additions and the
 * mask is read from sign bits (E - 1 >= 0 for all edges). */
/* The quads of the triangle's bounding box that start in [bx0, bx1] x
 * [by0, by1] (even GL coordinates inside the box); the border masks refer
 * to the whole box. */
static inline void raster_tri_box(fs_context *c, const fs_prim_setup *s, const tri_edges *e, int bx0, int bx1,
                                  int by0, int by1)
{
    const int H = s->height;
    const int gy0 = fs_raster_row_to_gl(H, e->y1), gy1 = fs_raster_row_to_gl(H, e->y0);
    const int qx0 = e->x0 & ~1, qy0 = gy0 & ~1;
    /* Masks that keep pixels inside the bounding box at its borders. */
    const unsigned left = (e->x0 & 1) ? 0xAu : 0xFu;   /* drop column 0 */
    const unsigned right = (e->x1 & 1) ? 0xFu : 0x5u;  /* drop column 1 */
    const unsigned bottom = (gy0 & 1) ? 0xCu : 0xFu;   /* drop row 0 */
    const unsigned top = (gy1 & 1) ? 0xFu : 0x3u;      /* drop row 1 */
    const int qxl = e->x1 & ~1, qyl = gy1 & ~1;

    /* In GL rows, moving up one row moves down one raster row. */
    int64_t row[3], ddx[3], ddy[3];
    for (int k = 0; k < 3; k++) {
        ddx[k] = -e->dcdx[k];
        ddy[k] = -e->dcdy[k];
        int64_t ry = fs_raster_row_to_gl(H, by0);
        row[k] = e->c[k] - 1 - e->dcdx[k] * bx0 + e->dcdy[k] * ry;
    }
    for (int qy = by0; qy <= by1; qy += 2) {
        unsigned ymask = (qy == qy0 ? bottom : 0xFu) & (qy == qyl ? top : 0xFu);
        int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        for (int qx = bx0; qx <= bx1; qx += 2) {
            /* Pixel 0 at (qx, qy); 1 = +x; 2 = +y; 3 = +x+y. */
            int64_t a0 = e0 | e1 | e2;
            int64_t a1 = (e0 + ddx[0]) | (e1 + ddx[1]) | (e2 + ddx[2]);
            int64_t a2 = (e0 + ddy[0]) | (e1 + ddy[1]) | (e2 + ddy[2]);
            int64_t a3 = (e0 + ddx[0] + ddy[0]) | (e1 + ddx[1] + ddy[1]) | (e2 + ddx[2] + ddy[2]);
            unsigned mask = (unsigned)(~((uint64_t)a0 >> 63) & 1u) |
                            (unsigned)((~((uint64_t)a1 >> 63) & 1u) << 1) |
                            (unsigned)((~((uint64_t)a2 >> 63) & 1u) << 2) |
                            (unsigned)((~((uint64_t)a3 >> 63) & 1u) << 3);
            mask &= ymask;
            if (qx == qx0)
                mask &= left;
            if (qx == qxl)
                mask &= right;
            if (mask) {
                fs_quad q;
                q.x = qx;
                q.y = qy;
                q.mask = mask;
                fs_raster_emit_quad(c, s, &q);
            }
            e0 += 2 * ddx[0];
            e1 += 2 * ddx[1];
            e2 += 2 * ddx[2];
        }
        for (int k = 0; k < 3; k++)
            row[k] += 2 * ddy[k];
    }
}

/* While the tile mask is on: the triangle's area in pixels (area2 is twice
 * it, in units of 2^(2 * subpixel bits)), at most its box, and the box's
 * centre go to the observer (observer.h), which sees the triangle's quads
 * in the masked tiles only. */
static void report_area(fs_context *c, const tri_edges *e, int64_t area2)
{
    const int H = c->fb.height;
    const int gy0 = fs_raster_row_to_gl(H, e->y1), gy1 = fs_raster_row_to_gl(H, e->y0);
    /* Scaling by a power of two is exact: the same as dividing by 2 and
     * then by 2^(2 * subpixel bits), without a libm call per triangle. */
    double area = fabs((double)area2) * (0.5 / (double)((int64_t)1 << (2 * c->raster.subpixel_bits)));
    double box = (double)(e->x1 - e->x0 + 1) * (double)(e->y1 - e->y0 + 1);
    FS_OBSERVE(c, triangle_area, area < box ? area : box, (e->x0 + e->x1) / 2, (gy0 + gy1) / 2);
}

/* Whether one of this thread's bands of rows meets the box (threaded
 * rasterization, raster_threads.h). */
static bool box_meets_band(const fs_raster_state *r, int H, const tri_edges *e)
{
    const int gy0 = fs_raster_row_to_gl(H, e->y1) & ~1, gy1 = fs_raster_row_to_gl(H, e->y0);
    const int b0 = gy0 >> FS_PAR_BAND_SHIFT, b1 = gy1 >> FS_PAR_BAND_SHIFT;
    if (b1 - b0 + 1 >= r->band_n)
        return true;
    for (int b = b0; b <= b1; b++)
        if (b % r->band_n == r->band_i)
            return true;
    return false;
}

/* Whether a masked tile meets the box (tiles are at least 2 pixels wide
 * and aligned to even coordinates, so they hold whole quads). */
static bool box_meets_mask(const fs_context *c, const fs_tile_mask *t, const tri_edges *e)
{
    const int H = c->fb.height;
    const int gy0 = fs_raster_row_to_gl(H, e->y1), gy1 = fs_raster_row_to_gl(H, e->y0);
    return fs_tile_mask_meets_box(t, e->x0 & ~1, gy0 & ~1, e->x1, gy1);
}

/* t: the observer's tile mask, else NULL; then only its tiles of the box
 * are walked. */
static void raster_tri_fast(fs_context *c, const fs_prim_setup *s, const tri_edges *e, const fs_tile_mask *t)
{
    const int H = s->height;
    const int gy0 = fs_raster_row_to_gl(H, e->y1), gy1 = fs_raster_row_to_gl(H, e->y0);
    const int qx0 = e->x0 & ~1, qy0 = gy0 & ~1;
    if (!t && c->raster.band_n > 1) {
        /* Threaded: this thread's bands of rows only (raster_threads.h);
         * bands are 2^FS_PAR_BAND_SHIFT rows from row 0, so each starts
         * even and holds whole quads. */
        const int n = c->raster.band_n, me = c->raster.band_i, sh = FS_PAR_BAND_SHIFT;
        for (int b = qy0 >> sh; b <= gy1 >> sh; b++) {
            if (b % n != me)
                continue;
            int by0 = b << sh, by1 = by0 + (1 << sh) - 1;
            raster_tri_box(c, s, e, qx0, e->x1, by0 > qy0 ? by0 : qy0, by1 < gy1 ? by1 : gy1);
        }
        return;
    }
    if (!t) {
        raster_tri_box(c, s, e, qx0, e->x1, qy0, gy1);
        return;
    }
    const int sh = t->shift;
    for (int ty = qy0 >> sh; ty <= gy1 >> sh; ty++)
        for (int tx = qx0 >> sh; tx <= e->x1 >> sh; tx++) {
            if (!fs_tile_mask_has(t, (uint32_t)tx, (uint32_t)ty))
                continue;
            int bx0 = tx << sh, by0 = ty << sh;
            int bx1 = bx0 + (1 << sh) - 1, by1 = by0 + (1 << sh) - 1;
            raster_tri_box(c, s, e, bx0 > qx0 ? bx0 : qx0, bx1 < e->x1 ? bx1 : e->x1, by0 > qy0 ? by0 : qy0,
                           by1 < gy1 ? by1 : gy1);
        }
}
