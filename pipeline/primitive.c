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
 * A draw is what llvmpipe receives: Mesa concatenates consecutive
 * immediate glBegin(GL_QUADS)/glEnd with nothing flushing between into
 * one (fs_prim_state.quads_run), so a quad inside the volume takes the
 * pipeline route after a merged one with a vertex outside.  The other
 * direction (the outside vertex in a later glBegin/glEnd) is not
 * modelled: the earlier quads are drawn at their glEnd
 * (tests/test_quad_merge.c, KNOWN_REVERSE).
 * Provoking vertex (2.14.7): the last vertex of each primitive, the first
 * of a polygon; in every split above it lands last in the triangle.  With
 * glProvokingVertex(GL_FIRST_VERTEX_CONVENTION) (ARB_provoking_vertex's
 * table) lines, triangles, strips and fans take their first vertex's
 * colour instead (a fan's vertex i + 1), which llvmpipe emits first;
 * quads and quad strips keep the last (GL_QUADS_FOLLOW_PROVOKING_VERTEX_
 * CONVENTION is false on llvmpipe), polygons the first.
 */
#include <math.h>
#include "vertex_internal.h"
#include "raster_threads.h"

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
    bool first;          /* GL_FIRST_VERTEX_CONVENTION (flat only) */
    bool masked;         /* the observer's tile mask is on for this draw */
    bool drop;           /* ... and a triangle outside it may skip the rasterizer */
    bool quiet;          /* a quiet draw (observer.h): a triangle outside the
                            mask only reports its area (a batch outside it,
                            iv NULL, likewise) */
    bool unfilled;       /* the draw module's route (fs_raster_draw_pipeline):
                            triangles carry their edges */
} prim_ctx;

static inline size_t I(const prim_ctx *p, size_t i)
{
    return p->idx ? p->idx[i] : i;
}

static inline fs_pvert *V(const prim_ctx *p, size_t i)
{
    return &p->pv[I(p, i)];
}

/* Whether an unclipped triangle's window box meets a masked tile.
 * Compares, not fminf/fmaxf (library calls).  A NaN in the first vertex
 * makes the box NaN, which counts as meeting; one in another is dropped,
 * which is harmless: the rasterizer culls a triangle with a NaN position
 * before it reads a colour. */
static bool box_masked(const prim_ctx *p, const fs_pvert *v0, const fs_pvert *v1, const fs_pvert *v2)
{
    const float x[3] = {v0->win[0], v1->win[0], v2->win[0]}, y[3] = {v0->win[1], v1->win[1], v2->win[1]};
    return fs_vs_box_masked(fs_tile_mask_active(p->c), fs_lo3(x[0], x[1], x[2]), fs_lo3(y[0], y[1], y[2]),
                            fs_hi3(x[0], x[1], x[2]), fs_hi3(y[0], y[1], y[2]));
}

/* Lights the lazy vertices of a triangle that may make fragments in a
 * masked tile; the others never have their colours read. */
static void tri_attributes(const prim_ctx *p, size_t a, size_t b, size_t cc)
{
    const size_t k[3] = {I(p, a), I(p, b), I(p, cc)};
    for (int i = 0; i < 3; i++)
        if (p->pv[k[i]].lazy)
            fs_vs_attributes(p->c, p->s, p->iv, p->pv, k[i]);
}

/* A quiet draw's triangle outside the mask reports its area (unsnapped,
 * which is close enough for a measure of the draw's work; the others give
 * theirs from the rasterizer), unless it makes no fragment anywhere:
 * wholly outside a clip plane, degenerate or culled. */
static void quiet_area(fs_context *c, const fs_pvert *v0, const fs_pvert *v1, const fs_pvert *v2)
{
    if (v0->mask | v1->mask | v2->mask)
        return;
    float a2 = (v1->win[0] - v0->win[0]) * (v2->win[1] - v0->win[1]) -
               (v2->win[0] - v0->win[0]) * (v1->win[1] - v0->win[1]);
    bool front = (c->raster.front_face == GL_CCW) == (a2 > 0.0f);
    if (!(a2 != 0.0f) || fs_raster_culled(&c->raster, front))
        return;
    FS_OBSERVE(c, triangle_area, 0.5 * fabs((double)a2), 0, 0);
}

/* The vertices' edge flags as bits 3-5 of a triangle's edges (clip.c). */
static unsigned vertex_edges(const prim_ctx *p, size_t a, size_t b, size_t cc)
{
    const uint8_t *e = p->s->edge;
    if (!e)
        return p->c->st.edge_flag ? FS_EDGES_ALL << 3 : 0;
    return (e[I(p, a)] ? 8u : 0u) | (e[I(p, b)] ? 16u : 0u) | (e[I(p, cc)] ? 32u : 0u);
}

/* What clip.c takes as a triangle's edges: 0 off the draw module's route. */
static inline unsigned route_edges(const prim_ctx *p, size_t a, size_t b, size_t cc, unsigned bound)
{
    return p->unfilled ? FS_EDGES_ROUTE | bound | vertex_edges(p, a, b, cc) : 0;
}

/* A triangle with its boundary edges `bound` (bit i: edge from its vertex
 * i to i+1 mod 3), as Mesa's draw module decomposes each primitive type:
 * every edge of independent triangles, strips and fans, the outer edges
 * of quads, quad strips and polygons (GL 1.5 spec 2.6.2, 3.5.4). */
static void tri_e(const prim_ctx *p, size_t a, size_t b, size_t cc, unsigned bound)
{
    fs_context *c = p->c;
    /* The line stipple counter restarts at a triangle the draw module
     * marks (FS_EDGES_RESET; polygon_mode.c). */
    c->raster.stipple_reset = (bound & FS_EDGES_RESET) != 0;
    bound &= FS_EDGES_ALL;
    const fs_pvert *v0 = V(p, a), *v1 = V(p, b), *v2 = V(p, cc);
    c->stats.triangles_in++;
    unsigned any = v0->mask | v1->mask | v2->mask, all = v0->mask & v1->mask & v2->mask;
    /* Whether the triangle may make fragments in a masked tile: a clipped
     * one is left to the clipper; a batch without lazy vertices reaches
     * none (fs_vs_process). */
    bool reach = !p->masked || (p->iv && !all && (any || box_masked(p, v0, v1, v2)));
    if (p->quiet && !reach) {
        quiet_area(c, v0, v1, v2);
        return;
    }
    if (c->observer)
        c->observer->ops->triangle(c->observer->user);
    /* The rasterizer and the clipper read what they are given; a triangle
     * rejected below (all) reads nothing (fs_vs_defer_shading). */
    if (p->iv && !all && (reach || !p->drop))
        tri_attributes(p, a, b, cc);
    if (any == 0) {
        if (!reach && p->drop) {
            /* Only its area counts: no rasterizer vertices to build. */
            const float x[3] = {v0->win[0], v1->win[0], v2->win[0]};
            const float y[3] = {v0->win[4], v1->win[4], v2->win[4]};
            fs_raster_triangle_dropped(c, x, y);
            return;
        }
        fs_emit_triangle(c, p->s, v0, v1, v2, p->prov, route_edges(p, a, b, cc, bound));
    } else if (all) {
        c->stats.triangles_rejected++;
    } else {
        c->stats.triangles_clipped++;
        fs_clip_triangle(c, p->s, v0, v1, v2, p->prov, route_edges(p, a, b, cc, bound));
    }
}

static inline void tri(const prim_ctx *p, size_t a, size_t b, size_t cc)
{
    tri_e(p, a, b, cc, FS_EDGES_ALL | FS_EDGES_RESET);
}

/* reset: the segment starts a primitive, which sets the line stipple
 * counter to 0 if the segment reaches the stipple (rasterize_line.c). */
static void line(const prim_ctx *p, size_t a, size_t b, bool reset)
{
    p->c->raster.stipple_reset = reset;
    fs_clip_line(p->c, p->s, V(p, a), V(p, b));
}

/* Whether the draw's triangles take the draw module's pipeline stages
 * (fs_raster_draw_pipeline), or, measured on OSMesa, at least its
 * decomposition: a polygon mode other than GL_FILL whose face is culled
 * does not, unless the vertices carry edge flags of their own. */
static bool draw_module_route(const fs_context *c, const fs_vs_setup *s)
{
    const fs_raster_state *r = &c->raster;
    return fs_raster_draw_pipeline(r) ||
           (s->edge && (r->polygon_mode[0] != GL_FILL || r->polygon_mode[1] != GL_FILL));
}

void fs_prim_draw(fs_context *c, const fs_vs_setup *s, GLenum mode, fs_pvert *pv, fs_ivert *iv,
                  const uint32_t *idx, size_t count, bool elements)
{
    const fs_tile_mask *m = fs_vs_tile_mask(c, mode);
    prim_ctx p = {c, s, pv, iv, idx, s->flat ? 2 : -1, s->flat_first, m != NULL, m && !c->raster.reference_path && !fs_vs(c)->tri_hook,
                  m && m->quiet, draw_module_route(c, s)};
    /* Only quads and quad strips split by the route (see the top); the
     * draw module's stages take every triangle through its pipeline.
     * Measured on OSMesa: a filled draw whose vertices carry edge flags of
     * their own keeps the unclipped route's split even when clipped.
     * Selection and feedback always take the draw pipeline's route (Mesa
     * feeds them from its draw module; measured: a quad comes out as
     * (0,1,3),(1,2,3)). */
    bool pipeline = p.unfilled || fs_render_mode_diverts(&c->rmode);
    c->raster.offset_latch = -1;
    /* Threaded rasterization records the filled triangles and rasterizes
     * them at the end (raster_threads.h). */
    fs_par_draw_begin(c, mode, p.unfilled, fs_vs(c)->tri_hook != NULL);
    for (size_t i = 0; i < count && !pipeline && !s->edge && (mode == GL_QUADS || mode == GL_QUAD_STRIP); i++)
        pipeline = V(&p, i)->mask != 0;
    /* A draw Mesa concatenates onto an earlier one that took the pipeline
     * route is part of that draw (fs_prim_state.quads_run). */
    pipeline |= c->prim.quads_force_pipeline && mode == GL_QUADS && !s->edge;
    c->prim.quads_route = pipeline;
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
            line(&p, i, i + 1, true);
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        if (count < 2)
            break;
        for (i = 1; i < count; i++)
            line(&p, i - 1, i, i == 1);
        if (mode == GL_LINE_LOOP)
            line(&p, count - 1, 0, false);
        break;
    case GL_TRIANGLES:
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
        if (p.first) {
            /* GL_FIRST_VERTEX_CONVENTION (ARB_provoking_vertex's table):
             * the triangle's first vertex, strip vertex i, fan vertex
             * i + 1; llvmpipe then emits that vertex first (its setup's
             * and draw module's flatshade_first orders). */
            p.prov = 0;
            for (i = 2; i < count; i++) {
                if (mode == GL_TRIANGLES && i % 3 != 2)
                    continue;
                if (mode == GL_TRIANGLE_FAN)
                    tri(&p, i - 1, i, 0);
                else if (mode == GL_TRIANGLE_STRIP && (i & 1))
                    tri(&p, i - 2, i, i - 1);
                else
                    tri(&p, i - 2, i - 1, i);
            }
            break;
        }
        if (mode == GL_TRIANGLES) {
            for (i = 0; i + 2 < count; i += 3)
                tri(&p, i, i + 1, i + 2);
        } else if (mode == GL_TRIANGLE_STRIP) {
            for (i = 2; i < count; i++) {
                if (i & 1)
                    tri(&p, i - 1, i - 2, i);
                else
                    tri(&p, i - 2, i - 1, i);
            }
        } else {
            for (i = 2; i < count; i++)
                tri(&p, 0, i - 1, i);
        }
        break;
    case GL_QUADS:
        for (i = 3; i < count; i += 4) {
            if (!pipeline && !elements && !s->flat) {
                tri(&p, i - 3, i - 2, i - 1);
                tri(&p, i - 3, i - 1, i);
            } else {
                tri_e(&p, i - 3, i - 2, i, 5u | FS_EDGES_RESET);
                tri_e(&p, i - 2, i - 1, i, 3u);
            }
        }
        break;
    case GL_QUAD_STRIP:
        for (i = 3; i < count; i += 2) {
            if (!pipeline) {
                tri(&p, i - 3, i - 2, i);
                tri(&p, i - 1, i - 3, i);
            } else {
                tri_e(&p, i - 1, i - 3, i, 5u | FS_EDGES_RESET);
                tri_e(&p, i - 3, i - 2, i, 3u);
            }
        }
        break;
    case GL_POLYGON:
        /* Fan (i-1, i, 0): edge 0 is always outer, edge 1 (i -> 0) only
         * in the last triangle, edge 2 (0 -> 1) only in the first. */
        for (i = 2; i < count; i++)
            tri_e(&p, i - 1, i, 0, 1u | (i + 1 == count ? 2u : 0u) | (i == 2 ? 4u | FS_EDGES_RESET : 0u));
        break;
    default:
        break;
    }
    fs_par_draw_end(c);
}
