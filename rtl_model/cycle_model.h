/*
 * The cycle-level model (docs/cycle_model.md).
 *
 * The functional pipeline computes every value; attached as the context's
 * observer (pipeline/observer.h) this model hears of the work it does (one
 * report per draw, triangle, quad, textured quad, clear, read-back, render
 * mode change and query) and computes when each piece of work
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
#include "cycle_config.h"

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
fs_cycle *fs_cycle_create(const fs_cycle_config *cfg, fs_cycle_mode mode, char *err, size_t errlen);
void fs_cycle_destroy(fs_cycle *cy);
/* Attaches the model to a context: it becomes the context's observer
 * (c->observer, pipeline/observer.h) and hears of all the work from then on. */
void fs_cycle_attach(fs_cycle *cy, fs_context *c);
/* From now on the model reports its signals (cycle_signals.h) to w, which
 * must outlive it.  Full mode only: -1 in sampled mode (its estimated work
 * has no cycles to show) or out of memory. */
struct fs_signals;
int fs_cycle_signals_attach(fs_cycle *cy, struct fs_signals *w);

/* Sampled mode's tile sample: whether quad (x, y) lies in a tile that is
 * not rasterized (false outside tile sampling). */
bool fs_cycle_quad_skipped(const fs_cycle *cy, int x, int y);

/* ---- calls from the driver ---- */
/* Sampled mode, before fs_cycle_set_frames: each frame's signatures of
 * work, from its calls (the driver hashes them without executing any):
 * `kind` without floating-point arguments and array contents, `exact` of
 * everything.  Frames with the same signature are interpolated among
 * themselves (docs/cycle_model.md, frame clustering); the arrays are
 * copied.  Without signatures all frames after frame 0 are one sequence. */
void fs_cycle_set_frame_signatures(fs_cycle *cy, const uint64_t *kind, const uint64_t *exact, uint64_t n);
/* Sampled mode: the trace's frame count (decides frame or draw sampling,
 * and which frames are simulated). */
void fs_cycle_set_frames(fs_cycle *cy, uint64_t frames);
/* Sampled mode: is the current frame interpolated, not simulated?  The
 * driver then skips its draws, clears and read-backs (fs_cmd_skippable). */
bool fs_cycle_frame_skipped(const fs_cycle *cy);
/* Sampled mode on a trace of 3 to 5 frames: too short to sample frames
 * with an error estimate (docs/cycle_model.md), so simulated in full. */
bool fs_cycle_too_short(const fs_cycle *cy);
/* Sampled mode: after the last frame, fills in the skipped frames' cycles
 * (linear between the simulated frames around them).  Idempotent. */
void fs_cycle_finish(fs_cycle *cy);
/* Cycles of frame f after fs_cycle_finish, and whether it was skipped. */
uint64_t fs_cycle_frame_cycles(const fs_cycle *cy, uint64_t f, bool *skipped);
/* Ends a frame: drains the pipeline and returns the frame's counters. */
void fs_cycle_frame_end(fs_cycle *cy, fs_cycle_stats *out);
/* Sampled mode's error estimate: the half-width of a 95% confidence
 * interval of the total cycles so far, relative to them (0 in full mode);
 * after fs_cycle_finish it covers the interpolated frames too. */
double fs_cycle_error_estimate(const fs_cycle *cy);
/* Its parts (independent; the estimate is their root sum of squares). */
enum { FS_CYCLE_ERR_FRAMES, FS_CYCLE_ERR_TILES, FS_CYCLE_ERR_DRAWS, FS_CYCLE_ERR_PARTS };
void fs_cycle_error_parts(const fs_cycle *cy, double part[FS_CYCLE_ERR_PARTS]);
/* sampling.max_error: cfg, the configuration of the finished run cy,
 * changed to sample more where cy's estimate is largest (the next pass);
 * false when cfg already simulates everything. */
bool fs_cycle_config_denser(const fs_cycle *cy, fs_cycle_config *cfg);
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
