/*
 * The pipeline's one interface to whoever watches its work.
 *
 * The functional pipeline computes every value and knows nothing of time.
 * A watcher (the clocked model is the one there is; docs/architecture.md)
 * attaches an fs_observer to the context and hears
 * of the work as it is done: each draw, assembled triangle, quad and its
 * record of what the per-fragment operations did, textured quad, clear,
 * read-back, render-mode change and query.  With no observer attached
 * (c->observer NULL) each report point is one branch and nothing else runs.
 *
 * The watcher may also ask for less work, at three granularities:
 *  - draw: the draw hook answers false, and the draw is skipped before any
 *    vertex is fetched;
 *  - batch and triangle: while the observer's tile mask is on, only the
 *    masked screen tiles are rendered.  A batch or triangle whose window box
 *    meets no masked tile makes no fragment there, so it is not lit or
 *    rasterized; the triangle hooks still hear of it, with its area (for a
 *    watcher that accounts the work it stands for);
 *  - quad: quads outside the masked tiles are dropped before interpolation.
 * A quiet draw (mask.quiet) is rendered inside the mask only for what it
 * leaves in the buffers: its triangles are not reported one by one, only
 * the areas of those the mask drops.
 */
#ifndef FS_OBSERVER_H
#define FS_OBSERVER_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;
struct fs_quad;
struct fs_quad_work;
struct fs_tex_object;
struct fs_tex_reads;
struct fs_filter_out;

/* Screen tiles of 2^shift pixels (at least 2, aligned to even
 * coordinates, so they hold whole quads).  A tile of the map is rendered
 * when its byte is 1; three zero bytes follow the map so that an entry can
 * be read as a 32-bit word.  Tiles off the map ask off_map. */
typedef struct fs_tile_mask {
    bool on;          /* render only the masked tiles */
    bool quiet;       /* the current draw is rendered for its buffers only */
    int shift;
    uint32_t map_w, map_h;
    const uint8_t *map;
    bool (*off_map)(const void *user, uint32_t tx, uint32_t ty);
    const void *off_map_user;
} fs_tile_mask;

static inline bool fs_tile_mask_has(const fs_tile_mask *m, uint32_t tx, uint32_t ty)
{
    if (tx < m->map_w && ty < m->map_h)
        return m->map[(size_t)ty * m->map_w + tx];
    return m->off_map(m->off_map_user, tx, ty);
}

/* Whether the mask, when on, drops the quad at window (x, y) (its tile is
 * not masked): the rasterizer's per-quad test. */
static inline bool fs_tile_mask_drops_quad(const fs_tile_mask *m, int x, int y)
{
    return m->on && !fs_tile_mask_has(m, (uint32_t)x >> m->shift, (uint32_t)y >> m->shift);
}

/* Whether a masked tile meets the window-space pixel box [x0, x1] x
 * [y0, y1] (inclusive, non-negative): the one walk of the mask over a box,
 * for the vertex stage's batch and triangle boxes and the rasterizer's
 * triangles. */
static inline bool fs_tile_mask_meets_box(const fs_tile_mask *m, int x0, int y0, int x1, int y1)
{
    const int sh = m->shift;
    for (int ty = y0 >> sh; ty <= y1 >> sh; ty++)
        for (int tx = x0 >> sh; tx <= x1 >> sh; tx++)
            if (fs_tile_mask_has(m, (uint32_t)tx, (uint32_t)ty))
                return true;
    return false;
}

/* The reports.  user is fs_observer.user. */
typedef struct fs_observer_ops {
    /* A draw of n vertices in mode, before any vertex is fetched; false:
     * skip it (no vertices, no fragments). */
    bool (*draw)(void *user, fs_context *c, GLenum mode, size_t n);
    /* A triangle assembled (before culling and clipping). */
    void (*triangle)(void *user);
    /* While the mask is on: a triangle of `area` pixels (at most its box)
     * whose box is centred at window (x, y) is rasterized in the masked
     * tiles only, or (a quiet draw's triangle the mask drops, x = y = 0)
     * not at all. */
    void (*triangle_area)(void *user, double area, int x, int y);
    /* A quad after the per-fragment operations ran on it, with their record
     * of what they did (fragment_ops.h). */
    void (*quad)(void *user, fs_context *c, const struct fs_quad *q, const struct fs_quad_work *w);
    /* The texture unit looked up quad q's texels in texture t: those r
     * lists (units/texture_reads.h). */
    void (*texture)(void *user, const struct fs_tex_object *t, const struct fs_quad *q, const struct fs_tex_reads *r);
    /* ... or filtered its pixels with the fast-footprint filter; out[i] (4
     * entries) is pixel i's result (units/texture_filter.h). */
    void (*texture_footprint)(void *user, const struct fs_tex_object *t, const struct fs_quad *q,
                              const struct fs_filter_out *out);
    /* MP-Grid: the CTR was reloaded n times during the quad's lookups. */
    void (*ctr_reloads)(void *user, uint64_t n);
    /* glClear of w x h pixels with mask. */
    void (*clear)(void *user, fs_context *c, GLbitfield mask, int w, int h);
    /* glReadPixels of `bytes` bytes. */
    void (*read_pixels)(void *user, fs_context *c, uint64_t bytes);
    /* glRenderMode(mode) (the Occlusion Unit's counters are read or reset). */
    void (*render_mode)(void *user, fs_context *c, GLenum mode);
    void (*query_begin)(void *user, fs_context *c, GLuint id);
    void (*query_end)(void *user, fs_context *c);
    /* A query's result is read. */
    void (*query_wait)(void *user, fs_context *c, GLuint id);
} fs_observer_ops;

typedef struct fs_observer {
    const fs_observer_ops *ops;
    void *user;
    fs_tile_mask mask;
} fs_observer;
#endif
