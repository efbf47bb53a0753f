/*
 * Primitive assembly (GL 1.5 spec 2.6.1) and flat shading (2.14.7): the
 * ten primitive types become points, lines and triangles in the vertex
 * order and with the splits Mesa's llvmpipe uses, because the split
 * decides which triangle owns a quad's diagonal and how colours
 * interpolate across it.
 *
 * llvmpipe takes one of two routes per draw (per Mesa's draw module and
 * measured against OSMesa):
 *  - no vertex outside the view volume: the vertices go to the setup code
 *    as the primitive type.  Non-indexed smooth-shaded quads split along
 *    v0-v2 as (0,1,2),(0,2,3); indexed draws (glDrawElements, display
 *    lists) and flat-shaded quads split along v1-v3 as (0,1,3),(1,2,3);
 *    quad strips (0,1,3),(2,0,3); polygons fan as (i-1,i,0).
 *  - some vertex outside: the whole draw goes through the draw pipeline's
 *    decomposition, quads (0,1,3),(1,2,3), quad strips (2,0,3),(0,1,3),
 *    polygons (i+1,i+2,0), and triangles needing it are clipped (clip.c).
 * Provoking vertex (2.14.7): the last vertex of each primitive, the first
 * of a polygon; in every split above it lands last in the triangle.
 */
#include <math.h>
#include "vertex_internal.h"

bool fs_prim_mode_valid(GLenum mode)
{
    return mode <= GL_POLYGON; /* GL_POINTS (0) .. GL_POLYGON (9) */
}

typedef struct prim_ctx {
    fs_context *c;
    const fs_vs_setup *s;
    fs_pvert *pv;
    fs_ivert *iv;        /* lazy attributes: the inputs, else NULL */
    const uint32_t *idx;
    int prov;            /* provoking position in each triangle, -1 smooth */
    bool tiles;          /* sampled mode's tile sample is on for this draw */
    bool charge;         /* ... and a triangle outside it may be only charged */
    bool fill;           /* an estimated draw run in the sampled tiles only:
                            the others are not timed, so nothing else needs them
                            (a batch that misses the sample, iv NULL, is only
                            charged: the same as fs_prim_sampled_list) */
} prim_ctx;

static inline size_t I(const prim_ctx *p, size_t i)
{
    return p->idx ? p->idx[i] : i;
}

static inline fs_pvert *V(const prim_ctx *p, size_t i)
{
    return &p->pv[I(p, i)];
}

static inline float lo3(float a, float b, float c)
{
    float m = b < a ? b : a;
    return c < m ? c : m;
}

static inline float hi3(float a, float b, float c)
{
    float m = b > a ? b : a;
    return c > m ? c : m;
}

/* Whether an unclipped triangle's window box meets a sampled tile.
 * Compares, not fminf/fmaxf (library calls).  A NaN in the first vertex
 * makes the box NaN, which counts as sampled; one in another is dropped,
 * which is harmless: the rasterizer culls a triangle with a NaN position
 * before it reads a colour. */
static bool box_sampled_xy(const prim_ctx *p, const float x[3], const float y[3])
{
    return fs_vs_box_sampled(fs_cycle_tile_sample(p->c->cycle), lo3(x[0], x[1], x[2]), lo3(y[0], y[1], y[2]),
                             hi3(x[0], x[1], x[2]), hi3(y[0], y[1], y[2]));
}

static bool box_sampled(const prim_ctx *p, const fs_pvert *v0, const fs_pvert *v1, const fs_pvert *v2)
{
    const float x[3] = {v0->win[0], v1->win[0], v2->win[0]}, y[3] = {v0->win[1], v1->win[1], v2->win[1]};
    return box_sampled_xy(p, x, y);
}

/* Sampled mode's tile sample: lights the lazy vertices of a triangle that
 * may make fragments in a sampled tile; the others are charged by area and
 * never read their colours. */
static void tri_attributes(const prim_ctx *p, size_t a, size_t b, size_t cc)
{
    const size_t k[3] = {I(p, a), I(p, b), I(p, cc)};
    for (int i = 0; i < 3; i++)
        if (p->pv[k[i]].lazy)
            fs_vs_attributes(p->c, p->s, p->iv, p->pv, k[i]);
}

/* A filled draw's triangle that misses the sample still counts its area
 * (unsnapped, which is close enough for a measure of the draw's work; the
 * others give theirs from the rasterizer). */
/* ... from its doubled signed area a2 (window space), unless it is
 * degenerate or culled. */
static void fill_charge(fs_context *c, float a2)
{
    bool front = (c->raster.front_face == GL_CCW) == (a2 > 0.0f);
    if (!(a2 != 0.0f) || fs_raster_culled(&c->raster, front))
        return;
    fs_cycle_triangle_area(c->cycle, 0.5 * fabs((double)a2), 0, 0);
}

static void fill_area(fs_context *c, const fs_pvert *v0, const fs_pvert *v1, const fs_pvert *v2)
{
    if (v0->mask | v1->mask | v2->mask)
        return; /* wholly outside a plane: no fragments */
    fill_charge(c, (v1->win[0] - v0->win[0]) * (v2->win[1] - v0->win[1]) -
                       (v2->win[0] - v0->win[0]) * (v1->win[1] - v0->win[1]));
}

static void tri_draw(const prim_ctx *p, size_t a, size_t b, size_t cc, bool reach);

static void tri(const prim_ctx *p, size_t a, size_t b, size_t cc)
{
    fs_context *c = p->c;
    const fs_pvert *v0 = V(p, a), *v1 = V(p, b), *v2 = V(p, cc);
    c->stats.triangles_in++;
    unsigned any = v0->mask | v1->mask | v2->mask, all = v0->mask & v1->mask & v2->mask;
    /* Whether the triangle may make fragments in a sampled tile: a clipped
     * one is left to the clipper; a batch without lazy vertices reaches
     * none (fs_vs_process). */
    bool reach = !p->tiles || (p->iv && !all && (any || box_sampled(p, v0, v1, v2)));
    if (p->fill && !reach) {
        fill_area(c, v0, v1, v2);
        return;
    }
    tri_draw(p, a, b, cc, reach);
}

/* A triangle past tri's sampling decisions (counted in triangles_in). */
static void tri_draw(const prim_ctx *p, size_t a, size_t b, size_t cc, bool reach)
{
    fs_context *c = p->c;
    const fs_pvert *v0 = V(p, a), *v1 = V(p, b), *v2 = V(p, cc);
    unsigned any = v0->mask | v1->mask | v2->mask, all = v0->mask & v1->mask & v2->mask;
    if (c->cycle)
        fs_cycle_triangle(c->cycle);
    if (p->iv && (reach || !p->charge))
        tri_attributes(p, a, b, cc); /* the rasterizer reads what it is given */
    if (any == 0) {
        if (!reach && p->charge) {
            /* Only its area counts: no rasterizer vertices to build. */
            const float x[3] = {v0->win[0], v1->win[0], v2->win[0]};
            const float y[3] = {v0->win[4], v1->win[4], v2->win[4]};
            fs_raster_triangle_charge(c, x, y);
            return;
        }
        fs_emit_triangle(c, p->s, v0, v1, v2, p->prov);
    } else if (all) {
        c->stats.triangles_rejected++;
    } else {
        c->stats.triangles_clipped++;
        fs_clip_triangle(c, p->s, v0, v1, v2, p->prov);
    }
}

#if FS_VS_HAVE_FMA
/* lo3 / hi3 lane by lane: the same compares, so the same NaN outcome. */
__attribute__((target("avx2,fma"))) static inline __m256 lo3_8(__m256 a, __m256 b, __m256 c)
{
    __m256 m = _mm256_blendv_ps(a, b, _mm256_cmp_ps(b, a, _CMP_LT_OQ));
    return _mm256_blendv_ps(m, c, _mm256_cmp_ps(c, m, _CMP_LT_OQ));
}

__attribute__((target("avx2,fma"))) static inline __m256 hi3_8(__m256 a, __m256 b, __m256 c)
{
    __m256 m = _mm256_blendv_ps(a, b, _mm256_cmp_ps(b, a, _CMP_GT_OQ));
    return _mm256_blendv_ps(m, c, _mm256_cmp_ps(c, m, _CMP_GT_OQ));
}

/* box_pixel of vertex_array.c lane by lane. */
__attribute__((target("avx2,fma"))) static inline __m256i box_pixel8(__m256 v)
{
    __m256i t = _mm256_cvttps_epi32(v);
    t = _mm256_blendv_epi8(_mm256_set1_epi32(65536), t, _mm256_castps_si256(_mm256_cmp_ps(v, _mm256_set1_ps(65536.0f), _CMP_LT_OQ)));
    return _mm256_and_si256(t, _mm256_castps_si256(_mm256_cmp_ps(v, _mm256_setzero_ps(), _CMP_GT_OQ)));
}

enum { FILL_NOTHING, FILL_AREA, FILL_REACH };

/* What tri() decides for 8 triangles of a tile-sampled triangle list, from
 * their corners' window x, y and clip masks (lane j, corner k): the
 * rasterizer's (reach), an area to charge (a filled draw: fill_charge of a2;
 * a timed one: group8) or nothing.  Lane by lane
 * the same compares and float operations as tri, box_sampled,
 * fs_vs_box_sampled and fill_area; boxes over more than 2 x 2 tiles, or off
 * the tile map, ask box_sampled_xy.  Sampled mode meets every triangle
 * of a one-frame trace here. */
__attribute__((target("avx2,fma"))) static void fill_classify8(const prim_ctx *p, const __m256 x[3], const __m256 y[3],
                                                               const __m256i m[3], uint8_t code[8], float a2[8])
{
    const fs_cycle_tiles *t = fs_cycle_tile_sample(p->c->cycle);
    const __m256i any = _mm256_or_si256(_mm256_or_si256(m[0], m[1]), m[2]);
    const __m256i all = _mm256_and_si256(_mm256_and_si256(m[0], m[1]), m[2]);
    /* fs_vs_box_sampled */
    const __m256 x0 = lo3_8(x[0], x[1], x[2]), x1 = hi3_8(x[0], x[1], x[2]);
    const __m256 y0 = lo3_8(y[0], y[1], y[2]), y1 = hi3_8(y[0], y[1], y[2]);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256i ordered = _mm256_castps_si256(_mm256_and_ps(_mm256_cmp_ps(x0, x1, _CMP_LE_OQ), _mm256_cmp_ps(y0, y1, _CMP_LE_OQ)));
    const __m128i sh = _mm_cvtsi32_si128(t->shift);
    const __m256i tx0 = _mm256_srl_epi32(box_pixel8(_mm256_sub_ps(x0, one)), sh);
    const __m256i ty0 = _mm256_srl_epi32(box_pixel8(_mm256_sub_ps(y0, one)), sh);
    const __m256i tx1 = _mm256_srl_epi32(box_pixel8(_mm256_add_ps(x1, one)), sh);
    const __m256i ty1 = _mm256_srl_epi32(box_pixel8(_mm256_add_ps(y1, one)), sh);
    /* Lanes the 2 x 2 lookup below answers: on the map, at most 2 x 2 tiles. */
    const __m256i two = _mm256_set1_epi32(2);
    __m256i easy = _mm256_and_si256(_mm256_cmpgt_epi32(two, _mm256_sub_epi32(tx1, tx0)),
                                    _mm256_cmpgt_epi32(two, _mm256_sub_epi32(ty1, ty0)));
    easy = _mm256_and_si256(easy, _mm256_and_si256(_mm256_cmpgt_epi32(_mm256_set1_epi32((int)t->map_w), tx1),
                                                   _mm256_cmpgt_epi32(_mm256_set1_epi32((int)t->map_h), ty1)));
    easy = _mm256_and_si256(easy, ordered);
    const __m256i w = _mm256_set1_epi32((int)t->map_w);
    const __m256i r0 = _mm256_mullo_epi32(ty0, w), r1 = _mm256_mullo_epi32(ty1, w);
    const int *map = (const int *)(const void *)t->map;
    __m256i hit = _mm256_setzero_si256();
    if (map) {
        const __m256i cells[4] = {_mm256_add_epi32(r0, tx0), _mm256_add_epi32(r0, tx1), _mm256_add_epi32(r1, tx0),
                                  _mm256_add_epi32(r1, tx1)};
        for (int k = 0; k < 4; k++) /* scale 1: byte offsets; the map's padding makes the 4-byte reads safe */
            hit = _mm256_or_si256(hit, _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), map, cells[k], easy, 1));
        hit = _mm256_and_si256(hit, _mm256_set1_epi32(0xff));
    } else {
        easy = _mm256_setzero_si256();
    }
    /* fill_area's a2 */
    const __m256 a = _mm256_sub_ps(_mm256_mul_ps(_mm256_sub_ps(x[1], x[0]), _mm256_sub_ps(y[2], y[0])),
                                   _mm256_mul_ps(_mm256_sub_ps(x[2], x[0]), _mm256_sub_ps(y[1], y[0])));
    _mm256_storeu_ps(a2, a);
    uint32_t an[8], al[8], e[8], h[8];
    _mm256_storeu_si256((__m256i *)(void *)an, any);
    _mm256_storeu_si256((__m256i *)(void *)al, all);
    _mm256_storeu_si256((__m256i *)(void *)e, easy);
    _mm256_storeu_si256((__m256i *)(void *)h, hit);
    for (int j = 0; j < 8; j++) {
        if (al[j]) {
            code[j] = FILL_NOTHING; /* wholly outside a plane */
        } else if (an[j]) {
            code[j] = FILL_REACH; /* clipped */
        } else {
            bool sampled;
            if (e[j]) {
                sampled = h[j] != 0;
            } else {
                const float bx[3] = {x[0][j], x[1][j], x[2][j]}, by[3] = {y[0][j], y[1][j], y[2][j]};
                sampled = box_sampled_xy(p, bx, by);
            }
            code[j] = sampled ? FILL_REACH : FILL_AREA;
        }
    }
}

/* One group of 8 triangles (batch vertices i .. i + 23) as classified:
 * one that reaches a sampled tile gets its vertices made
 * (fs_vs_lazy_vertex) and goes to tri_draw; of a filled draw, one that
 * does not is charged its area a2; of a timed draw, it is timed and
 * charged from its corners' window x and y_raster, as tri_draw does. */
static void group8(const prim_ctx *p, size_t i, const uint8_t code[8], const float a2[8], const float x[3][8],
                   const float yr[3][8])
{
    fs_context *c = p->c;
    for (size_t j = 0; j < 8; j++) {
        c->stats.triangles_in++;
        size_t k = i + 3 * j;
        if (code[j] == FILL_REACH) {
            for (size_t v = k; v < k + 3; v++)
                fs_vs_lazy_vertex(c, p->s, p->iv, p->pv, v);
            tri_draw(p, k, k + 1, k + 2, true);
        } else if (p->fill) {
            if (code[j] == FILL_AREA)
                fill_charge(c, a2[j]);
        } else { /* tri_draw without reach */
            fs_cycle_triangle(c->cycle);
            if (code[j] == FILL_AREA) {
                const float tx[3] = {x[0][j], x[1][j], x[2][j]}, ty[3] = {yr[0][j], yr[1][j], yr[2][j]};
                fs_raster_triangle_charge(c, tx, ty);
            } else {
                c->stats.triangles_rejected++;
            }
        }
    }
}

/* A tile-sampled glDrawArrays(GL_TRIANGLES) read straight from a float
 * vertex array (fs_vs_corners8), without fs_vs_process: no batch of
 * transformed vertices to gather from, and only the vertices of triangles
 * that reach a sampled tile made.  Filled and timed draws as tri: the same
 * decisions, charges and bits (each lane does vs_position's operations).  Returns how many of the n vertices it did
 * (groups of 24). */
__attribute__((target("avx2,fma"))) static size_t sampled_list(const prim_ctx *pp, size_t first, size_t n)
{
    const prim_ctx p = *pp;
    fs_context *c = p.c;
    const fs_vs_setup *s = p.s;
    size_t i = 0;
    for (; i + 24 <= n; i += 24) {
        uint8_t code[8];
        float a2[8], xs[3][8], ys[3][8];
        __m256 x[3], y[3], yr[3];
        __m256i m[3];
        fs_vs_corners8(c, s, first + i, x, y, yr, m);
        fill_classify8(&p, x, y, m, code, a2);
        if (!p.fill) /* group8 charges from them */
            for (int k = 0; k < 3; k++) {
                _mm256_storeu_ps(xs[k], x[k]);
                _mm256_storeu_ps(ys[k], yr[k]);
            }
        group8(&p, i, code, a2, xs, ys);
    }
    return i;
}

size_t fs_prim_sampled_list(fs_context *c, const fs_vs_setup *s, size_t first, size_t n, fs_pvert *pv, fs_ivert *iv)
{
    prim_ctx p = {c, s, pv, iv, NULL, s->flat ? 2 : -1, true, !c->raster.reference_path && !fs_vs(c)->tri_hook,
                  fs_cycle_tile_sample(c->cycle)->fill};
    if (!p.fill && !p.charge)
        return 0; /* every triangle goes to the rasterizer, with its vertices */
    return sampled_list(&p, first, n);
}
#else
size_t fs_prim_sampled_list(fs_context *c, const fs_vs_setup *s, size_t first, size_t n, fs_pvert *pv, fs_ivert *iv)
{
    (void)c, (void)s, (void)first, (void)n, (void)pv, (void)iv;
    return 0;
}
#endif

static void line(const prim_ctx *p, size_t a, size_t b)
{
    fs_clip_line(p->c, p->s, V(p, a), V(p, b));
}

void fs_prim_draw(fs_context *c, const fs_vs_setup *s, GLenum mode, fs_pvert *pv, fs_ivert *iv,
                  const uint32_t *idx, size_t count, bool elements)
{
    const bool tiles = fs_vs_tile_sample(c, mode) != NULL;
    prim_ctx p = {c, s, pv, iv, idx, s->flat ? 2 : -1, tiles,
                  tiles && !c->raster.reference_path && !fs_vs(c)->tri_hook,
                  tiles && fs_cycle_tile_sample(c->cycle)->fill};
    /* Only quads and quad strips split by the route (see the top). */
    bool pipeline = false;
    for (size_t i = 0; i < count && !pipeline && (mode == GL_QUADS || mode == GL_QUAD_STRIP); i++)
        pipeline = V(&p, i)->mask != 0;
    size_t i;
    switch (mode) {
    case GL_POINTS:
        for (i = 0; i < count; i++) {
            const fs_pvert *v = V(&p, i);
            /* GL 1.5 spec 2.12 / 3.3: a point whose vertex lies outside the
             * clip volume is discarded, however wide (measured on OSMesa:
             * a size-9 point centred 0.01 pixel outside any window or
             * viewport edge draws nothing, one on the edge or inside draws
             * its whole square, also outside the viewport). */
            if (v->mask || !(v->clip[3] > 0.0f) || !isfinite(v->win[0]) || !isfinite(v->win[1]))
                continue;
            fs_emit_point(c, s, v);
        }
        break;
    case GL_LINES:
        for (i = 0; i + 1 < count; i += 2)
            line(&p, i, i + 1);
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        if (count < 2)
            break;
        for (i = 1; i < count; i++)
            line(&p, i - 1, i);
        if (mode == GL_LINE_LOOP)
            line(&p, count - 1, 0);
        break;
    case GL_TRIANGLES:
        for (i = 0; i + 2 < count; i += 3)
            tri(&p, i, i + 1, i + 2);
        break;
    case GL_TRIANGLE_STRIP:
        for (i = 2; i < count; i++) {
            if (i & 1)
                tri(&p, i - 1, i - 2, i);
            else
                tri(&p, i - 2, i - 1, i);
        }
        break;
    case GL_TRIANGLE_FAN:
        for (i = 2; i < count; i++)
            tri(&p, 0, i - 1, i);
        break;
    case GL_QUADS:
        for (i = 3; i < count; i += 4) {
            if (!pipeline && !elements && !s->flat) {
                tri(&p, i - 3, i - 2, i - 1);
                tri(&p, i - 3, i - 1, i);
            } else {
                tri(&p, i - 3, i - 2, i);
                tri(&p, i - 2, i - 1, i);
            }
        }
        break;
    case GL_QUAD_STRIP:
        for (i = 3; i < count; i += 2) {
            if (!pipeline) {
                tri(&p, i - 3, i - 2, i);
                tri(&p, i - 1, i - 3, i);
            } else {
                tri(&p, i - 1, i - 3, i);
                tri(&p, i - 3, i - 2, i);
            }
        }
        break;
    case GL_POLYGON:
        for (i = 2; i < count; i++)
            tri(&p, i - 1, i, 0);
        break;
    default:
        break;
    }
}
