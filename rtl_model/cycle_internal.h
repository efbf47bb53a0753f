/*
 * Internals of the cycle-level model shared by its files: the FIFO engine
 * (cycle_fifo.h, cycle_fifo.c; memories in memory.c), the observer of the
 * functional pipeline's work (cycle_observer.c), the sampling estimator of
 * sampled mode (cycle_sampling.c) and the per-unit service times
 * (front_end.c, triangle_setup.c, rasterizer_stage.c, texture_stage.c,
 * fragment_stage.c, occlusion_stage.c).
 */
#ifndef FS_CYCLE_INTERNAL_H
#define FS_CYCLE_INTERNAL_H
#include "cycle_model.h"
#include "../pipeline/observer.h"
#include "../pipeline/rasterizer.h"
#include "../pipeline/fragment_ops.h"
#include "texture_cache.h"
#include "cycle_fifo.h"

/* Unit indices follow FS_CUNIT order in cycle_stats.def. */
enum {
#define FS_CUNIT(name, meaning) FS_U_##name,
#include "cycle_stats.def"
#undef FS_CUNIT
    FS_U_COUNT
};

typedef struct fs_cyc_unit {
    int n;                  /* instances */
    fs_cyc_stage *st;
    bool active;            /* work has reached it: it is in the chain */
} fs_cyc_unit;

/* Sampled mode: draws of one kind (mode, vertex count, state). */
typedef struct fs_cyc_kind {
    uint64_t key, seen, nsamp;
    double sum, sumsq;
} fs_cyc_kind;
#define FS_CYC_KINDS 8192

/* Tile sampling: what the sampled quads of one kind of draw (its fragment
 * state) cost, as exponentially weighted sums over a window of about
 * FS_CYC_POOL_WINDOW quads of the screen (FS_CYC_POOL_WINDOW / tiles
 * sampled quads), so the cost per quad follows a frame's changing depth
 * complexity.  A window of 64 sampled quads at 1 tile in 16 followed the
 * scene's swings of quads per fragment too closely (textured came out 3%
 * low); a window counted in sampled quads lags the frame by more screen
 * quads the sparser the sample, and the lag is a bias where the cost per
 * quad drifts as the depth buffer fills (bench32 +0.4%, +1.0%, +2.0% at
 * tiles = 16, 32, 64 with 1024 sampled quads; +0.3% and +0.6% at 32 and
 * 64 with this window), and never below FS_CYC_POOL_MIN sampled quads.
 * Each triangle is then timed with its own estimated quads at these costs
 * (spread), not only the sampled quads (lumped). */
typedef struct fs_cyc_pool {
    uint64_t key;
    /* Per quad (a sample) or weighted sums of them (a pool): quads;
     * fragments; raster cycles; whether textured, texture cycles, bytes,
     * whether it missed the cache, and the texture unit's occupancy (the
     * longer of cycles and memory time); the same for the fragment stage
     * (reads: it read the framebuffer); whether the Occlusion Unit saw it,
     * its cycles, whether it wrote a hit. */
    double quads, frags, raster;
    double tex_quads, tex, tex_bytes, tex_miss, tex_occ;
    double frag, frag_bytes, frag_reads, frag_occ;
    double occ_quads, occ, occ_writes;
} fs_cyc_pool;
#define FS_CYC_POOLS 64
#define FS_CYC_POOL_WINDOW 16384.0
/* the normal quantile of a two-sided 95% interval (the error estimate) */
#define FS_CYC_Z95 1.96
#define FS_CYC_POOL_MIN 64.0
#define FS_CYC_NO_SEQ UINT32_MAX

/* What spread timing rounds to whole cycles, bytes and counts. */
enum {
    FS_CARRY_raster, FS_CARRY_tex, FS_CARRY_tex_occ, FS_CARRY_tex_bytes, FS_CARRY_frag, FS_CARRY_frag_occ,
    FS_CARRY_frag_bytes, FS_CARRY_occ, FS_CARRY_quads, FS_CARRY_frags, FS_CARRY_COUNT
};

/* Sampled mode's screen-tile sample: one tile in `every` is rasterized,
 * one in each block of `step` x (every / step) tiles. */
typedef struct fs_cycle_tiles {
    uint32_t every;
    uint32_t step;
} fs_cycle_tiles;

/* Whether tile (tx, ty) is in the sample: the screen's tiles are cut into
 * blocks of step x (every / step) tiles, and each block has one sampled
 * tile at a position hashed from the block (jittered, i.e. stratified
 * random, sampling: even coverage of the screen like a lattice, but
 * unbiased whatever regular structure the scene has, which a fixed
 * lattice is not).  The map of the pipeline's tile mask caches it for the
 * screen's tiles (fs_cyc_tile_tables_alloc). */
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

struct fs_cycle {
    /* What the pipeline sees of the model (c->observer): the reports it
     * takes and, in tile sampling, the tile mask of the sampled tiles
     * (mask.on while every > 1; mask.quiet: the current draw is
     * estimated but filled in the sampled tiles, sampling.every). */
    fs_observer watch;
    fs_cycle_tiles tiles;
    fs_cycle_config cfg;
    fs_cycle_mode mode;
    fs_cyc_unit u[FS_U_COUNT];
    fs_cyc_stage rtri;        /* setup -> fragment generator FIFO (triangles) */
    int nmem;
    fs_cyc_mem *fbmem;        /* one per image engine, or the unified one */
    fs_cyc_mem *texmem;       /* one per board, or the unified one */
    fs_tex_cache **cache;     /* one per texture unit, NULL entries: no cache */
    int engines_total;

    uint64_t cmd;             /* the host's command time: nothing starts before it */
    uint64_t done;            /* latest completion of any item */
    uint64_t est;             /* estimated cycles (sampled mode) */
    fs_cycle_stats acc;       /* cumulative counters (unit fields unused) */

    /* current draw's front end share per triangle (1/256 cycles) */
    uint64_t fe_per_tri, fe_frac;
    uint64_t tri_arrival;
    bool tri_started, tri_open;

    /* texture work of the quad being processed */
    bool tex_pending;
    uint64_t tex_service, tex_bytes, tex_misses;
    /* occlusion work of the quad being processed */
    bool occ_pending;
    uint64_t occ_cycles, occ_cur, occ_writes, occ_arb;
    int occ_last_engine, occ_last_x, occ_last_y, occ_last_writer;
    bool occu_hooked;

    /* draws and frames */
    uint64_t frame, draw_index, query_index;
    bool draw_open, draw_sampled, draw_estimated;
    fs_cyc_kind *draw_kind;
    GLenum draw_mode;
    uint64_t draw_vertices;
    fs_cycle_stats draw_snap, frame_snap;
    uint64_t draw_t0;
    fs_cycle_record_fn record_fn;
    bool record_draws;        /* per-draw records too (a snapshot per draw) */
    void *record_user;

    /* queries */
    GLuint query_id;
    uint64_t query_issue;
    fs_cycle_stats query_snap;
    struct { GLuint id; uint64_t ready; } qready[64];
    int nqready;

    fs_cyc_kind *kinds;
    /* Draw sampling: this frame's draws in order, their kind, cycles
     * (negative: estimated, filled in at the frame end) and work, their
     * triangles' areas at the cost per fragment (work_add_area; negative:
     * none measured, the draw was skipped). */
    struct fs_cyc_seq { fs_cyc_kind *k; double c, w; } *seq;
    size_t nseq, seq_cap, seq_open;   /* seq_open: entry of the simulated draw + 1, 0 if none */
    size_t seq_work;                  /* entry whose work is arriving + 1, 0 if none */
    double draw_work;                 /* their work so far */
    double draw_var;                  /* variance of the draw estimates so far */

    /* sampled mode, frame sampling */
    uint64_t nframes_trace;
    uint64_t frame_step;        /* the largest step of the frame sequences (fs_cycle_set_frames) */
    /* Frame clustering (fs_cycle_set_frame_signatures): per frame of the
     * trace its signatures (kind: the calls without floating-point
     * arguments or array contents; exact: everything), and the plan made
     * from them: the sequence a frame is interpolated in (frame 0, the
     * warm-up, in none: FS_CYC_NO_SEQ) and whether it is simulated. */
    uint64_t *sig_kind, *sig_exact, nsig;
    uint32_t *plan_seq;
    bool *plan_sim;
    uint64_t nplan;
    uint32_t nseqs;
    bool frame_sampling, frame_skipped, finished;
    bool too_short;             /* 3+ frames, too few to sample: simulated in full */
    uint64_t *frame_cycles;     /* per frame; skipped frames filled by fs_cycle_finish */
    bool *frame_was_skipped;
    uint64_t frame_cap, frames_done;
    double frame_error;         /* absolute error estimate of the interpolated cycles */
    double *frame_tile_err;     /* per frame: tile sampling's standard error of its cycles */
    /* fs_cycle_finish: the frames' 95% half-width (curvature or scatter of
     * the simulated frames), summed over the sequences */
    double frame_half;

    /* sampled mode, tile sampling: work (unscaled service cycles) and
     * fragments per tile of the screen in this frame (pairs), for the
     * error estimate */
    double *tile_work;
    int tiles_x, tiles_y, fb_width, fb_height;
    uint8_t *tile_map;    /* what watch.mask.map points to */
    double tile_var;            /* variance of the tile-sampled frames' cycles so far */
    /* ratio estimator: areas and sampled fragments of the triangles done,
     * and the current triangle's */
    double area_done, frags_done, area_cur, frags_cur, kq;
    /* work_add_area's work per fragment of pool wpf_pool (NULL: due again) */
    const struct fs_cyc_pool *wpf_pool;
    double wpf;
    double pool_keep; /* pool_add's weight of the sums so far (set_tiles: the window) */
    bool kq_stale; /* kq is due from area_done / frags_done (fs_cycle_quad asks) */
    /* spread timing of tile-sampled triangles: the current draw's pool,
     * all pools, the one of every kind together (fallback), the current
     * triangle's centre and whether it awaits its estimate (its area is
     * area_cur), and the fractions of cycles, bytes and counts carried
     * between items so that rounding does not bias the sums */
    fs_cyc_pool *pool_cur, pools[FS_CYC_POOLS], pool_any;
    int tri_cx, tri_cy;
    bool tri_est;
    double carry[FS_CARRY_COUNT];

    /* signals (cycle_signal_taps.c), sig NULL when none are written: the
     * taps of every stage, FIFO and memory; CTR reloads of the quad being
     * processed; the last Occlusion Unit quad's engine and bus cycles */
    fs_signals *sig;
    fs_sig_tap *taps;
    uint64_t sig_ctr, occ_last_tests, occ_last_writes;
};

/* Latest completion time so far (the pipeline drained). */
static inline uint64_t fs_cyc_time(const fs_cycle *cy) { return cy->done > cy->cmd ? cy->done : cy->cmd; }
/* ... and with the estimated cycles of sampled mode. */
static inline uint64_t fs_cyc_now_total(const fs_cycle *cy) { return fs_cyc_time(cy) + cy->est; }

/* ---- the observer (cycle_observer.c) ---- */
/* The reports of pipeline/observer.h (user: the fs_cycle), in
 * cycle_observer.c, cycle_sampling.c (triangle_area) and texture_stage.c. */
bool fs_cycle_draw(void *user, fs_context *c, GLenum mode, size_t n);
void fs_cycle_triangle(void *user);
void fs_cycle_triangle_area(void *user, double area, int x, int y);
void fs_cycle_quad(void *user, fs_context *c, const fs_quad *q, const fs_quad_work *w);
void fs_cycle_texture(void *user, const struct fs_tex_object *t, const fs_quad *q, const struct fs_tex_reads *r);
void fs_cycle_texture_footprint(void *user, const struct fs_tex_object *t, const fs_quad *q,
                                const struct fs_filter_out *out);
void fs_cycle_ctr_reloads(void *user, uint64_t n);
void fs_cycle_clear(void *user, fs_context *c, GLbitfield mask, int w, int h);
void fs_cycle_read_pixels(void *user, fs_context *c, uint64_t bytes);
void fs_cycle_render_mode(void *user, fs_context *c, GLenum mode);
void fs_cycle_query_begin(void *user, fs_context *c, GLuint id);
void fs_cycle_query_end(void *user, fs_context *c);
void fs_cycle_query_wait(void *user, fs_context *c, GLuint id);
/* The current draw's record (fs_cycle_set_record_fn); an estimated draw's
 * is its estimate alone. */
void fs_cyc_emit_draw(fs_cycle *cy, bool estimated, uint64_t cycles);

/* ---- signals (cycle_signal_taps.c), each only when cy->sig is set ---- */
static inline void fs_cyc_signal(fs_cycle *cy, uint64_t t, int sig, int64_t v)
{
    if (cy->sig)
        fs_signals_put(cy->sig, t, sig, 0, v);
}
/* The quad's texture unit starts at t: its CTR reloads. */
void fs_cyc_signal_texture(fs_cycle *cy, uint64_t t);
/* Occlusion Unit e starts the quad at t: its engines' and OccU Control's cycles. */
void fs_cyc_signal_occlusion(fs_cycle *cy, int e, uint64_t t);
/* A draw, a render mode change, a query's begin, end and result. */
void fs_cyc_signal_draw(fs_cycle *cy, const fs_context *c, uint64_t t);
void fs_cyc_signal_render_mode(fs_cycle *cy, GLenum mode, uint64_t t);
void fs_cyc_signal_query_end(fs_cycle *cy, const fs_context *c, uint64_t issue, uint64_t ready);
void fs_cyc_signal_free(fs_cycle *cy);

/* ---- the sampling estimator (cycle_sampling.c) ---- */
/* The tile sample's per-screen tables, once it and the screen are known. */
void fs_cyc_tile_tables_alloc(fs_cycle *cy);
/* A draw begins: -1 when it is simulated, else it is estimated and the
 * answer is fs_cycle_draw's (1: filled in the sampled tiles, 0: skipped). */
int fs_cyc_sample_draw(fs_cycle *cy, const fs_context *c, GLenum mode, size_t n);
/* Times the current tile-sampled triangle (tri_est) as its estimated quads. */
void fs_cyc_spread_triangle(fs_cycle *cy);
/* A sampled quad of a spread (or, fill, a filled draw's) triangle into the
 * cost pools; n fragments, of which `reaching` reached the tests. */
void fs_cyc_sample_quad(fs_cycle *cy, fs_context *c, const fs_quad *q, unsigned n, unsigned reaching,
                        unsigned passed, unsigned written, bool fill);
/* How many quads a lumped quad of tile sampling stands for (the ratio
 * estimator), and its unscaled work w at its tile (the error estimate). */
double fs_cyc_lump_factor(fs_cycle *cy);
void fs_cyc_tile_work_add(fs_cycle *cy, const fs_quad *q, double w, unsigned frags);
/* The frame's estimated draws, charged at its end; then the frame's error
 * and, with frame sampling, its cycles kept for fs_cycle_finish. */
void fs_cyc_charge_estimated_draws(fs_cycle *cy);
void fs_cyc_sample_frame_end(fs_cycle *cy, uint64_t frame_cycles);
/* Whether frame f is simulated under frame sampling. */
bool fs_cyc_frame_simulated(const fs_cycle *cy, uint64_t f);

/* ---- per-unit service times ---- */
uint64_t fs_cyc_front_end_per_triangle(const fs_cycle_config *cfg, GLenum mode, size_t n); /* 1/256 cycles */
uint64_t fs_cyc_front_end_cycles(const fs_cycle_config *cfg, size_t vertices);
uint64_t fs_cyc_setup_cycles(const fs_cycle_config *cfg);
uint64_t fs_cyc_readback_cycles(const fs_cycle_config *cfg, uint64_t bytes);
uint64_t fs_cyc_raster_cycles(const fs_cycle_config *cfg, unsigned fragments);
int fs_cyc_route(const fs_cycle *cy, int x, int y);     /* image engine of a pixel */
int fs_cyc_texture_init(fs_cycle *cy, char *err, size_t errlen);
/* The distinct texel addresses (sorted) the texture unit reads for one
 * footprint-filtered pixel: o's rectangles wrapped by t's wrap modes, at
 * most cap of them before deduplication.  Returns the count. */
#define FS_CYC_FP_MAX_TEXELS 256u
struct fs_filter_out;
unsigned fs_cyc_footprint_addresses(const struct fs_tex_object *t, const struct fs_filter_out *o, uint64_t *a,
                                    unsigned cap);
void fs_cyc_texture_free(fs_cycle *cy);
void fs_cyc_fragment_work(const fs_context *c, const fs_cycle *cy, unsigned reaching, unsigned passed,
                          unsigned written, uint64_t *service, uint64_t *bytes, bool *reads);
void fs_cyc_occlusion_hook(fs_cycle *cy, fs_context *c);
void fs_cyc_occlusion_quad_end(fs_cycle *cy, uint64_t *service, bool *writes);
#endif
