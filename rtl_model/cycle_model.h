/*
 * The cycle-level model (docs/cycle_model.md).
 *
 * The functional pipeline computes every value; while fs_context.cycle is
 * set it reports the work it does through the fs_cycle_* calls below (one
 * call per draw, triangle, quad, textured quad, clear, read-back, render
 * mode change and query), and this model computes when each piece of work
 * passes each clocked unit.  Units are stages with a service time per work
 * item, a latency and a bounded FIFO in front; an item's departure is
 *     depart = max(start + service, memory done, the downstream FIFO has room)
 *     start  = max(arrival, the stage's previous departure)
 * evaluated item by item in program order, which gives back-pressure,
 * busy/stalled/idle cycles and FIFO high-water marks exactly without
 * ticking empty cycles.  A unit no work has reached is not in the chain.
 */
#ifndef FS_CYCLE_MODEL_H
#define FS_CYCLE_MODEL_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <GL/gl.h>
#include "../pipeline/config.h"
#include "../pipeline/rasterizer.h"

typedef struct fs_context fs_context;
typedef struct fs_cycle fs_cycle;
struct fs_tex_object;

typedef enum fs_cycle_mode {
    FS_CYCLE_FULL,     /* every draw simulated */
    FS_CYCLE_SAMPLED   /* some draws simulated, the others estimated and skipped */
} fs_cycle_mode;

/* Counters of one frame, draw or query (cycle_stats.def). */
typedef struct fs_cycle_stats {
#define FS_CSTAT(name, unit, meaning) uint64_t name;
#define FS_CUNIT(name, meaning) uint64_t name##_busy, name##_stalled, name##_idle, name##_fifo_hwm;
#include "cycle_stats.def"
#undef FS_CSTAT
#undef FS_CUNIT
} fs_cycle_stats;

typedef struct fs_cycle_stat_info {
    const char *name, *unit, *meaning;
    size_t offset;
} fs_cycle_stat_info;
extern const fs_cycle_stat_info fs_cycle_stat_table[];
extern const int fs_cycle_stat_count;
void fs_cycle_stats_list(FILE *f);

/* Creates the model for a configuration (already checked).  NULL with a
 * message in err on a configuration the model cannot build. */
fs_cycle *fs_cycle_create(const fs_config *cfg, fs_cycle_mode mode, char *err, size_t errlen);
void fs_cycle_destroy(fs_cycle *cy);
/* Attaches the model to a context (sets c->cycle). */
void fs_cycle_attach(fs_cycle *cy, fs_context *c);
/* From now on the model reports its signals (cycle_signals.h) to w, which
 * must outlive it.  Full mode only: -1 in sampled mode (its estimated work
 * has no cycles to show) or out of memory. */
struct fs_signals;
int fs_cycle_signals_attach(fs_cycle *cy, struct fs_signals *w);

/* ---- calls from the functional pipeline (only when c->cycle != NULL) ---- */
/* A draw of n vertices in mode; false in sampled mode when the draw is
 * estimated: the caller then skips it (no vertices, no fragments).  True
 * with the tile sample's `fill` set: estimated too, but the caller runs it
 * in the sampled tiles (the model's hooks ignore it). */
bool fs_cycle_draw(fs_cycle *cy, fs_context *c, GLenum mode, size_t n);
/* A triangle assembled (before culling and clipping). */
void fs_cycle_triangle(fs_cycle *cy);
/* Sampled mode's screen-tile sample.  It is the first member of struct
 * fs_cycle so that the rasterizer's per-quad test below inlines to a load
 * and a branch (every = 1 outside tile sampling). */
typedef struct fs_cycle_tiles {
    uint32_t every;   /* one tile in `every` is rasterized */
    uint32_t step;    /* width in tiles of a block of `every` tiles (one sampled per block) */
    int shift;        /* log2 of the tile side */
    /* The screen's tiles, 1 where sampled: the rasterizer asks per
     * triangle, and the hash below costs five divisions.  Three zero bytes
     * follow it, so that a tile's entry can be read as 4 bytes (the vertex
     * stage's 8-wide triangle pass gathers 32-bit words). */
    uint32_t map_w, map_h;
    const uint8_t *map;
    /* The current draw is estimated, but it writes depth or stencil that
     * later simulated draws test against: the pipeline still runs it in the
     * sampled tiles (only triangles whose box meets one), untimed, so that
     * those tiles stay exact (sampling.every; docs/cycle_model.md). */
    bool fill;
} fs_cycle_tiles;
static inline const fs_cycle_tiles *fs_cycle_tile_sample(const fs_cycle *cy)
{
    return (const fs_cycle_tiles *)(const void *)cy;
}
/* True when quad (x, y) lies in a tile sampled mode does not rasterize: the
 * caller drops it before interpolation, texturing and the per-fragment
 * operations, and the model charges its work from the sampled tiles. */
/* Whether tile (tx, ty) is in the sample: the screen's tiles are cut into
 * blocks of step x (every / step) tiles, and each block has one sampled
 * tile at a position hashed from the block (jittered, i.e. stratified
 * random, sampling: even coverage of the screen like a lattice, but
 * unbiased whatever regular structure the scene has, which a fixed
 * lattice is not). */
static inline bool fs_cycle_tile_hashed(const fs_cycle_tiles *t, uint32_t tx, uint32_t ty)
{
    uint32_t bw = t->step, bh = t->every / t->step;
    uint32_t bx = tx / bw, by = ty / bh;
    uint32_t h = bx * 0x9E3779B1u ^ (by + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h %= t->every;
    return tx - bx * bw == h % bw && ty - by * bh == h / bw;
}
static inline bool fs_cycle_tile_sampled(const fs_cycle_tiles *t, uint32_t tx, uint32_t ty)
{
    if (tx < t->map_w && ty < t->map_h)
        return t->map[(size_t)ty * t->map_w + tx];
    return fs_cycle_tile_hashed(t, tx, ty);
}
/* Whether a sampled tile meets the window-space pixel box [x0, x1] x
 * [y0, y1] (inclusive): the one walk of the tile map over a box, for the
 * vertex stage's batch and triangle boxes and the rasterizer's triangles. */
static inline bool fs_cycle_tiles_meet_box(const fs_cycle_tiles *t, int x0, int y0, int x1, int y1)
{
    const int sh = t->shift;
    for (int ty = y0 >> sh; ty <= y1 >> sh; ty++)
        for (int tx = x0 >> sh; tx <= x1 >> sh; tx++)
            if (fs_cycle_tile_sampled(t, (uint32_t)tx, (uint32_t)ty))
                return true;
    return false;
}
/* The tile sample when tile sampling is on, else NULL (cy may be NULL). */
static inline const fs_cycle_tiles *fs_cycle_tiles_active(const fs_cycle *cy)
{
    const fs_cycle_tiles *t = cy ? fs_cycle_tile_sample(cy) : NULL;
    return t && t->every > 1 ? t : NULL;
}
static inline bool fs_cycle_quad_skipped(const fs_cycle *cy, int x, int y)
{
    const fs_cycle_tiles *t = fs_cycle_tile_sample(cy);
    if (t->every <= 1)
        return false;
    return !fs_cycle_tile_sampled(t, (uint32_t)x >> t->shift, (uint32_t)y >> t->shift);
}
/* Tile sampling: a triangle of `area` pixels whose bounding box is centred
 * at window (x, y) is about to be rasterized in the sampled tiles only. */
void fs_cycle_triangle_area(fs_cycle *cy, double area, int x, int y);
/* A quad after the per-fragment operations ran on it, with their record of
 * what they did (pipeline/fragment_ops.h). */
struct fs_quad_work;
void fs_cycle_quad(fs_cycle *cy, fs_context *c, const fs_quad *q, const struct fs_quad_work *w);
/* The texture unit sampled quad q of texture t and read the texels r
 * lists (units/texture_reads.h). */
struct fs_tex_reads;
void fs_cycle_texture(fs_cycle *cy, const struct fs_tex_object *t, const fs_quad *q, const struct fs_tex_reads *r);
/* The texture unit filtered quad q's covered pixels with the fast-footprint
 * filter; out[i] (4 entries) is pixel i's result (the texel rectangles it read and its
 * weighting-ROM lookups, units/texture_filter.h). */
struct fs_filter_out;
void fs_cycle_texture_footprint(fs_cycle *cy, const struct fs_tex_object *t, const fs_quad *q,
                                const struct fs_filter_out *out);
/* MP-Grid: the CTR was reloaded n times while the quad was sampled. */
void fs_cycle_ctr_reloads(fs_cycle *cy, uint64_t n);
/* glClear of w x h pixels with mask. */
void fs_cycle_clear(fs_cycle *cy, fs_context *c, GLbitfield mask, int w, int h);
/* glReadPixels of `bytes` bytes: a drain, then the read. */
void fs_cycle_read_pixels(fs_cycle *cy, fs_context *c, uint64_t bytes);
/* glRenderMode(mode): a drain (the unit's counters are read or reset). */
void fs_cycle_render_mode(fs_cycle *cy, fs_context *c, GLenum mode);
void fs_cycle_query_begin(fs_cycle *cy, fs_context *c, GLuint id);
void fs_cycle_query_end(fs_cycle *cy, fs_context *c);
/* Reading a query's result: the front end waits until it is available. */
void fs_cycle_query_wait(fs_cycle *cy, fs_context *c, GLuint id);

/* ---- calls from the driver ---- */
/* Sampled mode: the trace's frame count (decides frame or draw sampling). */
void fs_cycle_set_frames(fs_cycle *cy, uint64_t frames);
/* Sampled mode: should the driver skip this call (a draw, clear or
 * read-back in a frame that is interpolated, not simulated)? */
bool fs_cycle_skip_call(const fs_cycle *cy, const fs_context *c, int cmd);
/* Sampled mode: after the last frame, fills in the skipped frames' cycles
 * (linear between the simulated frames around them).  Idempotent. */
void fs_cycle_finish(fs_cycle *cy);
/* Cycles of frame f after fs_cycle_finish, and whether it was skipped. */
uint64_t fs_cycle_frame_cycles(const fs_cycle *cy, uint64_t f, bool *skipped);
/* Ends a frame: drains the pipeline and returns the frame's counters. */
void fs_cycle_frame_end(fs_cycle *cy, fs_cycle_stats *out);
/* Sampled mode's estimate of the relative standard error of the total
 * cycles so far (0 in full mode). */
double fs_cycle_error_estimate(const fs_cycle *cy);
/* A closed draw or query, handed to the record callback as it closes (so
 * long traces need no memory per draw). */
typedef enum fs_cycle_kind { FS_CYCLE_DRAW, FS_CYCLE_QUERY } fs_cycle_kind;
typedef struct fs_cycle_record {
    fs_cycle_kind kind;
    uint64_t index, frame;
    GLuint id;          /* query name (queries) or GL mode (draws) */
    uint64_t vertices;
    bool estimated;
    fs_cycle_stats s;
} fs_cycle_record;
typedef void (*fs_cycle_record_fn)(void *user, const fs_cycle_record *r);
/* Queries are always handed to fn; draws only when `draws` (a paper-scale
 * frame has tens of thousands of draws). */
void fs_cycle_set_record_fn(fs_cycle *cy, fs_cycle_record_fn fn, void *user, bool draws);
/* Counters since creation (cycles included). */
void fs_cycle_totals(const fs_cycle *cy, fs_cycle_stats *out);
/* Writes one JSON object body / CSV line of a stats record. */
void fs_cycle_stats_write_json(FILE *f, const fs_cycle_stats *s);
void fs_cycle_stats_write_csv_header(FILE *f);
void fs_cycle_stats_write_csv(FILE *f, const fs_cycle_stats *s);
#endif
