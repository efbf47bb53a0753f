/*
 * The observer of the cycle-level model: it takes the functional
 * pipeline's work (draws, triangles, quads, clears, read-backs, queries,
 * frames: the fs_cycle_* calls of cycle_model.h) and times it on the FIFO
 * engine (cycle_fifo.h), unit by unit; it owns the model's creation, the
 * statistics table and the records.  Sampled mode's estimates are asked of
 * the sampling estimator (cycle_sampling.c).
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "cycle_internal.h"
#include "../pipeline/context.h"
#include "../units/occlusion_unit.h"

/* ---- statistics table ---- */

const fs_cycle_stat_info fs_cycle_stat_table[] = {
#define FS_CSTAT(name, unit, meaning) {#name, unit, meaning, offsetof(fs_cycle_stats, name)},
#define FS_CUNIT(name, meaning)                                                                          \
    {#name "_busy", "cycles", "cycles the " meaning " worked, summed over its instances",                \
     offsetof(fs_cycle_stats, name##_busy)},                                                             \
    {#name "_stalled", "cycles", "cycles the " meaning " held finished work because the next FIFO was "  \
     "full or memory was busy", offsetof(fs_cycle_stats, name##_stalled)},                               \
    {#name "_idle", "cycles", "cycles the " meaning " had no work (instances x cycles - busy - stalled)", \
     offsetof(fs_cycle_stats, name##_idle)},                                                             \
    {#name "_fifo_hwm", "entries", "most entries waiting in the FIFO feeding the " meaning               \
     " (in the frame so far)", offsetof(fs_cycle_stats, name##_fifo_hwm)},
#include "cycle_stats.def"
#undef FS_CSTAT
#undef FS_CUNIT
};
const int fs_cycle_stat_count = (int)(sizeof fs_cycle_stat_table / sizeof fs_cycle_stat_table[0]);

static inline uint64_t *field(fs_cycle_stats *s, int i)
{
    return (uint64_t *)((char *)s + fs_cycle_stat_table[i].offset);
}

void fs_cycle_stats_list(FILE *f)
{
    for (int i = 0; i < fs_cycle_stat_count; i++)
        fprintf(f, "%-24s %-10s %s\n", fs_cycle_stat_table[i].name, fs_cycle_stat_table[i].unit,
                fs_cycle_stat_table[i].meaning);
}

void fs_cycle_stats_write_json(FILE *f, const fs_cycle_stats *s)
{
    for (int i = 0; i < fs_cycle_stat_count; i++)
        fprintf(f, "%s\"%s\": %llu", i ? ", " : "", fs_cycle_stat_table[i].name,
                (unsigned long long)*field((fs_cycle_stats *)s, i));
}

void fs_cycle_stats_write_csv_header(FILE *f)
{
    for (int i = 0; i < fs_cycle_stat_count; i++)
        fprintf(f, ",%s", fs_cycle_stat_table[i].name);
}

void fs_cycle_stats_write_csv(FILE *f, const fs_cycle_stats *s)
{
    for (int i = 0; i < fs_cycle_stat_count; i++)
        fprintf(f, ",%llu", (unsigned long long)*field((fs_cycle_stats *)s, i));
}

/* ---- creation ---- */

static const long *unit_fifo(const fs_cycle_config *g, int u)
{
    switch (u) {
    case FS_U_front_end: return &g->frontend_fifo_depth;
    case FS_U_setup: return &g->frontend_fifo_depth;  /* the FIFO feeding setup */
    case FS_U_raster: return &g->setup_fifo_depth;
    case FS_U_texture: return &g->raster_fifo_depth;
    case FS_U_fragment: return &g->texture_fifo_depth;
    default: return &g->fragment_fifo_depth;
    }
}

static long unit_latency(const fs_cycle_config *g, int u)
{
    switch (u) {
    case FS_U_front_end: return g->frontend_latency;
    case FS_U_setup: return g->setup_latency;
    case FS_U_raster: return g->raster_latency;
    case FS_U_texture: return g->texture_latency;
    case FS_U_fragment: return g->fragment_latency;
    default: return g->occlusion_latency;
    }
}

static const fs_observer_ops cycle_observer_ops = {
    fs_cycle_draw, fs_cycle_triangle, fs_cycle_triangle_area, fs_cycle_quad, fs_cycle_texture,
    fs_cycle_texture_footprint, fs_cycle_ctr_reloads, fs_cycle_clear, fs_cycle_read_pixels,
    fs_cycle_render_mode, fs_cycle_query_begin, fs_cycle_query_end, fs_cycle_query_wait,
};

/* Tiles off the mask's map (off the screen, or all of them when the map
 * could not be allocated) are in the sample as the hash says. */
static bool tile_off_map(const void *tiles, uint32_t tx, uint32_t ty)
{
    return fs_cycle_tile_hashed(tiles, tx, ty);
}

fs_cycle *fs_cycle_create(const fs_cycle_config *cfg, fs_cycle_mode mode, char *err, size_t errlen)
{
    fs_cycle *cy = calloc(1, sizeof *cy);
    if (!cy) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    cy->cfg = *cfg;
    cy->mode = mode;
    cy->tiles.every = 1;
    cy->watch.ops = &cycle_observer_ops;
    cy->watch.user = cy;
    cy->watch.mask.off_map = tile_off_map;
    cy->watch.mask.off_map_user = &cy->tiles;
    const fs_cycle_config *g = &cy->cfg;
    int boards = (int)g->raster_boards, engines = boards * (int)g->fragment_image_engines;
    cy->engines_total = engines;
    int count[FS_U_COUNT] = {1, 1, boards, boards, engines, engines};
    bool ok = true;
    for (int u = 0; u < FS_U_COUNT; u++) {
        cy->u[u].n = count[u];
        cy->u[u].st = calloc((size_t)count[u], sizeof *cy->u[u].st);
        ok &= cy->u[u].st != NULL;
        for (int i = 0; ok && i < count[u]; i++)
            ok &= fs_cyc_stage_init(&cy->u[u].st[i], (uint32_t)unit_latency(g, u), (uint32_t)*unit_fifo(g, u)) == 0;
    }
    ok &= fs_cyc_stage_init(&cy->rtri, 0, (uint32_t)g->setup_fifo_depth) == 0;
    /* Memories: O2 has one for everything; otherwise a framebuffer memory
     * per image engine and a texture memory per board. */
    cy->nmem = g->memory_unified ? 1 : engines + boards;
    fs_cyc_mem *mem = calloc((size_t)cy->nmem, sizeof *mem);
    cy->kinds = mode == FS_CYCLE_SAMPLED ? calloc(FS_CYC_KINDS, sizeof *cy->kinds) : NULL;
    if (!ok || !mem || (mode == FS_CYCLE_SAMPLED && !cy->kinds)) {
        free(mem);
        fs_cycle_destroy(cy);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (g->memory_unified) {
        fs_cyc_mem_init(&mem[0], (uint64_t)g->memory_bytes_per_cycle, (uint32_t)g->memory_latency);
        cy->fbmem = cy->texmem = mem;
    } else {
        for (int i = 0; i < engines; i++)
            fs_cyc_mem_init(&mem[i], (uint64_t)g->memory_bytes_per_cycle, (uint32_t)g->memory_latency);
        for (int i = 0; i < boards; i++)
            fs_cyc_mem_init(&mem[engines + i], (uint64_t)g->memory_texture_bytes_per_cycle,
                            (uint32_t)g->memory_texture_latency);
        cy->fbmem = mem;
        cy->texmem = mem + engines;
    }
    for (int i = 0; i < engines; i++)
        cy->u[FS_U_fragment].st[i].mem = g->memory_unified ? mem : &mem[i];
    for (int i = 0; i < boards; i++)
        cy->u[FS_U_texture].st[i].mem = g->memory_unified ? mem : &mem[engines + i];
    if (fs_cyc_texture_init(cy, err, errlen) != 0) {
        fs_cycle_destroy(cy);
        return NULL;
    }
    cy->occ_last_engine = cy->occ_last_writer = -1;
    return cy;
}

void fs_cycle_destroy(fs_cycle *cy)
{
    if (!cy)
        return;
    fs_cyc_texture_free(cy);
    fs_cyc_signal_free(cy);
    for (int u = 0; u < FS_U_COUNT; u++) {
        for (int i = 0; cy->u[u].st && i < cy->u[u].n; i++)
            fs_cyc_stage_free(&cy->u[u].st[i]);
        free(cy->u[u].st);
    }
    fs_cyc_stage_free(&cy->rtri);
    free(cy->frame_cycles);
    free(cy->tile_work);
    free(cy->tile_map);
    free(cy->seq);
    free(cy->frame_was_skipped);
    free(cy->frame_tile_err);
    free(cy->sig_kind);
    free(cy->sig_exact);
    free(cy->plan_seq);
    free(cy->plan_sim);
    free(cy->fbmem);
    free(cy->kinds);
    free(cy);
}

void fs_cycle_attach(fs_cycle *cy, fs_context *c)
{
    c->observer = &cy->watch;
    cy->fb_width = c->fb.width;
    cy->fb_height = c->fb.height;
    fs_cyc_tile_tables_alloc(cy);
}

bool fs_cycle_quad_skipped(const fs_cycle *cy, int x, int y)
{
    return fs_tile_mask_drops_quad(&cy->watch.mask, x, y);
}

void fs_cycle_set_record_fn(fs_cycle *cy, fs_cycle_record_fn fn, void *user, bool draws)
{
    cy->record_draws = fn && draws;
    cy->record_fn = fn;
    cy->record_user = user;
}

/* ---- snapshots ---- */

static void snapshot(const fs_cycle *cy, fs_cycle_stats *s)
{
    *s = cy->acc;
    s->cycles = fs_cyc_time(cy) + cy->est;
#define FS_CUNIT(name, meaning)                                                     \
    {                                                                               \
        const fs_cyc_unit *un = &cy->u[FS_U_##name];                                \
        s->name##_busy = s->name##_stalled = s->name##_fifo_hwm = 0;                \
        for (int i = 0; i < un->n; i++) {                                           \
            s->name##_busy += un->st[i].busy;                                       \
            s->name##_stalled += un->st[i].stalled;                                 \
            const fs_cyc_fifo *ff = FS_U_##name == FS_U_raster ? &cy->rtri.in : &un->st[i].in; \
            if (ff->hwm > s->name##_fifo_hwm)                                       \
                s->name##_fifo_hwm = ff->hwm;                                       \
        }                                                                           \
        s->name##_idle = 0;                                                         \
    }
#include "cycle_stats.def"
#undef FS_CUNIT
}

/* now - then; the fields that are not sums are fixed up. */
static void diff(const fs_cycle *cy, const fs_cycle_stats *now, const fs_cycle_stats *then, fs_cycle_stats *out)
{
    for (int i = 0; i < fs_cycle_stat_count; i++)
        *field(out, i) = *field((fs_cycle_stats *)now, i) - *field((fs_cycle_stats *)then, i);
    out->query_latency_max = now->query_latency_max;
#define FS_CUNIT(name, meaning)                                                                   \
    {                                                                                             \
        uint64_t all = (uint64_t)cy->u[FS_U_##name].n * out->cycles;                              \
        uint64_t used = out->name##_busy + out->name##_stalled;                                   \
        out->name##_idle = all > used ? all - used : 0;                                           \
        out->name##_fifo_hwm = now->name##_fifo_hwm;                                              \
    }
#include "cycle_stats.def"
#undef FS_CUNIT
    out->tex_cache_hit_permille = out->tex_cache_accesses ? out->tex_cache_hits * 1000 / out->tex_cache_accesses : 0;
}

void fs_cycle_totals(const fs_cycle *cy, fs_cycle_stats *out)
{
    fs_cycle_stats now, zero;
    snapshot(cy, &now);
    memset(&zero, 0, sizeof zero);
    diff(cy, &now, &zero, out);
}

/* The rasterizer "starts" a triangle without quads when it reaches it. */
static inline void close_triangle(fs_cycle *cy)
{
    if (cy->tri_est)
        fs_cyc_spread_triangle(cy);
    if (cy->tri_open && !cy->tri_started) {
        uint64_t t = cy->tri_arrival;
        for (int b = 0; b < cy->u[FS_U_raster].n; b++)
            if (cy->u[FS_U_raster].st[b].free > t)
                t = cy->u[FS_U_raster].st[b].free;
        fs_cyc_fifo_push(&cy->rtri.in, t);
    }
    cy->tri_open = false;
}


void fs_cyc_emit_draw(fs_cycle *cy, bool estimated, uint64_t cycles)
{
    fs_cycle_record r;
    memset(&r, 0, sizeof r);
    r.kind = FS_CYCLE_DRAW;
    r.index = cy->draw_index;
    r.frame = cy->frame;
    r.id = cy->draw_mode;
    r.vertices = cy->draw_vertices;
    r.estimated = estimated;
    if (estimated) {
        r.s.cycles = r.s.estimated_cycles = cycles;
        r.s.draws = r.s.draws_estimated = 1;
    } else {
        fs_cycle_stats now;
        snapshot(cy, &now);
        diff(cy, &now, &cy->draw_snap, &r.s);
        r.s.draws = 1;
    }
    cy->record_fn(cy->record_user, &r);
}

static uint64_t issue_time(const fs_cycle *cy);

static void close_draw(fs_cycle *cy)
{
    if (!cy->draw_open)
        return;
    close_triangle(cy);
    cy->draw_open = false;
    if (cy->draw_kind && cy->draw_sampled) {
        double t = (double)(fs_cyc_now_total(cy) - cy->draw_t0);
        if (cy->seq_open)
            cy->seq[cy->seq_open - 1].c = t;
        cy->seq_open = 0;
        cy->draw_kind->nsamp++;
        cy->draw_kind->sum += t;
        cy->draw_kind->sumsq += t * t;
    }
    if (cy->record_draws)
        fs_cyc_emit_draw(cy, false, 0);
    cy->draw_index++;
}

bool fs_cycle_draw(void *user, fs_context *c, GLenum mode, size_t n)
{
    fs_cycle *cy = user;
    close_draw(cy);
    if (!cy->occu_hooked && c->occlusion)
        fs_cyc_occlusion_hook(cy, c);
    cy->draw_mode = mode;
    cy->draw_vertices = n;
    cy->acc.draws++;
    cy->draw_kind = NULL;
    cy->draw_sampled = false;
    int estimated = fs_cyc_sample_draw(cy, c, mode, n);
    if (estimated >= 0)
        return estimated;
    cy->draw_open = true;
    cy->draw_t0 = fs_cyc_now_total(cy);
    if (cy->sig)
        fs_cyc_signal_draw(cy, c, issue_time(cy));
    if (cy->record_draws)
        snapshot(cy, &cy->draw_snap);
    cy->fe_per_tri = fs_cyc_front_end_per_triangle(&cy->cfg, mode, n);
    cy->fe_frac = 0;
    if (cy->fe_per_tri == 0) {
        /* Points and lines: the front end and setup see the whole draw as
         * one item; its fragments follow it. */
        fs_cyc_unit *fe = &cy->u[FS_U_front_end], *su = &cy->u[FS_U_setup];
        uint64_t a = fs_cyc_step(fe->st, cy->cmd, fs_cyc_front_end_cycles(&cy->cfg, n), 0, false, su->st);
        a = fs_cyc_step(su->st, a, fs_cyc_setup_cycles(&cy->cfg) * n, 0, false, &cy->rtri);
        cy->tri_arrival = a;
        cy->tri_open = true;
        cy->tri_started = false;
        if (a > cy->done)
            cy->done = a;
    }
    return true;
}

void fs_cycle_triangle(void *user)
{
    fs_cycle *cy = user;
    if (cy->watch.mask.quiet)
        return;
    close_triangle(cy);
    cy->fe_frac += cy->fe_per_tri;
    uint64_t fe = cy->fe_frac >> 8;
    cy->fe_frac &= 255u;
    fs_cyc_stage *fst = cy->u[FS_U_front_end].st, *sst = cy->u[FS_U_setup].st;
    uint64_t setup = fs_cyc_setup_cycles(&cy->cfg);
    uint64_t a = fs_cyc_step_n(fst, cy->cmd, fe, fe, 0, false, sst, 1);
    a = fs_cyc_step_n(sst, a, setup, setup, 0, false, &cy->rtri, 1);
    cy->tri_arrival = a;
    cy->tri_open = true;
    cy->tri_started = false;
    cy->acc.triangles++;
    if (a > cy->done)
        cy->done = a;
}

/* ---- quads ---- */

void fs_cycle_quad(void *user, fs_context *c, const fs_quad *q, const fs_quad_work *w)
{
    fs_cycle *cy = user;
    unsigned m = q->mask & 0xfu;
    unsigned n = (unsigned)((0x4332322132212110ull >> (4 * m)) & 0xfu);
    unsigned written = w->written, passed = w->passed;
    unsigned reaching = n > w->killed_early ? n - w->killed_early : 0;
    if (cy->watch.mask.quiet) {
        /* A filled estimated draw: its sampled quads keep the cost pools
         * (and the texture cache) current for the simulated draws after
         * it, which otherwise priced their first quads at the costs of
         * the last simulated draw (bench32 +8% after 7 filled draws). */
        fs_cyc_sample_quad(cy, c, q, n, reaching, passed, written, true);
        return;
    }

    int e = fs_cyc_route(cy, q->x, q->y);
    int b = e / (int)cy->cfg.fragment_image_engines;
    fs_cyc_stage *rs = &cy->u[FS_U_raster].st[b];
    fs_cyc_stage *ts = cy->tex_pending ? &cy->u[FS_U_texture].st[b] : NULL;
    fs_cyc_stage *fs = &cy->u[FS_U_fragment].st[e];
    fs_cyc_stage *os = cy->occ_pending ? &cy->u[FS_U_occlusion].st[e] : NULL;
    uint64_t arr = cy->tri_arrival;
    if (!cy->tri_started) {
        fs_cyc_fifo_push(&cy->rtri.in, arr > rs->free ? arr : rs->free);
        cy->tri_started = true;
    }
    /* Tile sampling: a quad of a triangle whose area is known is timed with
     * its triangle (sample_quad, spread_triangle).  Other quads (lines,
     * points, triangles reaching past the left or bottom edge) are lumped:
     * the quad stands for about `every` quads at its place in the other
     * tiles of its block, so its service and memory traffic count that
     * many times, the factor being the ratio of the triangles' areas to
     * their sampled fragments so far (Cochran, Sampling Techniques, 3rd
     * ed., ch. 6, the ratio estimator). */
    uint64_t k = cy->tiles.every;
    double kq = 1.0;
    if (k > 1 && cy->tri_est) {
        fs_cyc_sample_quad(cy, c, q, n, reaching, passed, written, false);
        return;
    }
    if (k > 1)
        kq = fs_cyc_lump_factor(cy);
#define FS_SCALE(v) (k > 1 ? (uint64_t)llround((double)(v) * kq) : (uint64_t)(v))
    uint64_t quad_work = FS_SCALE(fs_cyc_raster_cycles(&cy->cfg, n)) + FS_SCALE(cy->tex_service);
    uint64_t a = fs_cyc_step(rs, arr, FS_SCALE(fs_cyc_raster_cycles(&cy->cfg, n)), 0, false, ts ? ts : fs);
    if (ts) {
        cy->u[FS_U_texture].active = true;
        if (cy->sig)
            fs_cyc_signal_texture(cy, a > ts->free ? a : ts->free);
        a = fs_cyc_step(ts, a, FS_SCALE(cy->tex_service), FS_SCALE(cy->tex_bytes), cy->tex_misses && !cy->cfg.memory_prefetch, fs);
        cy->tex_pending = false;
        cy->tex_service = cy->tex_bytes = cy->tex_misses = 0;
    }
    uint64_t service, bytes;
    bool reads;
    fs_cyc_fragment_work(c, cy, reaching, passed, written, &service, &bytes, &reads);
    service = FS_SCALE(service);
    bytes = FS_SCALE(bytes);
    quad_work += service + bytes / (uint64_t)cy->cfg.memory_bytes_per_cycle;
    a = fs_cyc_step(fs, a, service, bytes, reads, os);
    cy->acc.fb_bytes += bytes;
    if (os) {
        bool writes;
        cy->u[FS_U_occlusion].active = true;
        fs_cyc_occlusion_quad_end(cy, &service, &writes);
        if (cy->sig)
            fs_cyc_signal_occlusion(cy, e, a > os->free ? a : os->free);
        a = fs_cyc_step(os, a, FS_SCALE(service), 0, false, NULL);
        if (writes)
            a += (uint64_t)cy->cfg.occlusion_write_latency;
    }
    if (a > cy->done)
        cy->done = a;
    if (k > 1)
        fs_cyc_tile_work_add(cy, q, (double)quad_work / kq, n);
    cy->acc.quads += FS_SCALE(1);
    cy->acc.fragments += FS_SCALE(n);
#undef FS_SCALE
}

/* ---- clears, synchronisation, queries ---- */

void fs_cycle_clear(void *user, fs_context *c, GLbitfield mask, int w, int h)
{
    fs_cycle *cy = user;
    (void)c;
    close_triangle(cy);
    uint64_t bpp = ((mask & GL_COLOR_BUFFER_BIT) ? 4u : 0u) +
                   ((mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) ? 4u : 0u);
    uint64_t pixels = (uint64_t)(w > 0 ? w : 0) * (uint64_t)(h > 0 ? h : 0);
    int n = cy->engines_total;
    uint64_t share = (pixels + (uint64_t)n - 1) / (uint64_t)n;
    uint64_t rate = (uint64_t)cy->cfg.fragment_clear_pixels_per_cycle;
    for (int e = 0; e < n; e++) {
        fs_cyc_stage *fs = &cy->u[FS_U_fragment].st[e];
        uint64_t a = fs_cyc_step(fs, cy->cmd, (share + rate - 1) / rate, share * bpp, false, NULL);
        if (a > cy->done)
            cy->done = a;
    }
    cy->acc.fb_bytes += pixels * bpp;
}

/* The time the host issues a command that waits: after the front end took
 * everything before it. */
static uint64_t issue_time(const fs_cycle *cy)
{
    uint64_t t = cy->u[FS_U_front_end].st[0].free;
    return t > cy->cmd ? t : cy->cmd;
}

/* The front end waits until `ready`; returns the cycles it waited. */
static uint64_t wait_until(fs_cycle *cy, uint64_t ready)
{
    uint64_t issue = issue_time(cy);
    uint64_t w = ready > issue ? ready - issue : 0;
    if (ready > cy->cmd)
        cy->cmd = ready;
    if (cy->cmd > cy->done)
        cy->done = cy->cmd;
    cy->acc.syncs++;
    cy->acc.sync_cycles += w;
    if (cy->sig)
        fs_signals_drained(cy->sig, cy->cmd);
    return w;
}

static uint64_t merge_latency(const fs_cycle *cy)
{
    return (uint64_t)cy->cfg.occlusion_merge_board_latency + (uint64_t)cy->cfg.occlusion_merge_global_latency;
}

void fs_cycle_read_pixels(void *user, fs_context *c, uint64_t bytes)
{
    fs_cycle *cy = user;
    (void)c;
    close_triangle(cy);
    uint64_t t = fs_cyc_time(cy);
    fs_cyc_mem *m = cy->fbmem;
    uint64_t ready = fs_cyc_mem_reserve(m, t, bytes) + m->latency;
    cy->acc.fb_bytes += bytes;
    if (cy->cfg.readback_ps_per_byte > 0)
        ready = t + fs_cyc_readback_cycles(&cy->cfg, bytes);
    cy->acc.readback_cycles += ready - t;
    wait_until(cy, ready);
}

/* The calibrated read-back: the read path's setup and a time per byte,
 * faster for the first readback.fast_bytes (Huettner 1999, footnote 5 of
 * 3.1.10 gives two read sizes per machine: configs/o2.ini and
 * infinite_reality.ini say how their keys follow from them).  Exact in
 * 128-bit integers, rounded up to whole cycles. */
uint64_t fs_cyc_readback_cycles(const fs_cycle_config *cfg, uint64_t bytes)
{
    uint64_t fast = bytes < (uint64_t)cfg->readback_fast_bytes ? bytes : (uint64_t)cfg->readback_fast_bytes;
    unsigned __int128 ps = (unsigned __int128)cfg->readback_setup_ns * 1000u +
                           (unsigned __int128)fast * (uint64_t)cfg->readback_fast_ps_per_byte +
                           (unsigned __int128)(bytes - fast) * (uint64_t)cfg->readback_ps_per_byte;
    /* cycles = ps * kHz / 10^9, rounded up */
    unsigned __int128 c = (ps * (uint64_t)cfg->clock_khz + 999999999u) / 1000000000u;
    return c > UINT64_MAX / 2 ? UINT64_MAX / 2 : (uint64_t)c;
}

void fs_cycle_render_mode(void *user, fs_context *c, GLenum mode)
{
    fs_cycle *cy = user;
    close_triangle(cy);
    fs_cyc_occlusion_hook(cy, c);
    if (cy->sig)
        fs_cyc_signal_render_mode(cy, mode, issue_time(cy));
    /* glRenderMode returns the pass's results: every fragment before it
     * must have left the engines and the reports must be merged. */
    cy->acc.rendermode_sync_cycles += wait_until(cy, fs_cyc_time(cy) + merge_latency(cy));
}

void fs_cycle_query_begin(void *user, fs_context *c, GLuint id)
{
    fs_cycle *cy = user;
    fs_cyc_occlusion_hook(cy, c);
    cy->query_id = id;
    cy->query_issue = fs_cyc_now_total(cy);
    fs_cyc_signal(cy, issue_time(cy), FS_SIG_query_begin, 1);
    snapshot(cy, &cy->query_snap);
}

void fs_cycle_query_end(void *user, fs_context *c)
{
    fs_cycle *cy = user;
    close_triangle(cy);
    uint64_t issue = issue_time(cy);
    uint64_t ready = fs_cyc_time(cy) + merge_latency(cy);
    if (cy->sig)
        fs_cyc_signal_query_end(cy, c, issue, ready);
    uint64_t lat = ready > issue ? ready - issue : 0;
    cy->acc.queries++;
    cy->acc.query_latency += lat;
    if (lat > cy->acc.query_latency_max)
        cy->acc.query_latency_max = lat;
    int slot = -1;
    for (int i = 0; i < cy->nqready; i++)
        if (cy->qready[i].id == cy->query_id)
            slot = i;
    if (slot < 0)
        slot = cy->nqready < 64 ? cy->nqready++ : (int)(cy->query_index % 64);
    cy->qready[slot].id = cy->query_id;
    cy->qready[slot].ready = ready;
    if (cy->record_fn) {
        fs_cycle_record r;
        memset(&r, 0, sizeof r);
        r.kind = FS_CYCLE_QUERY;
        r.index = cy->query_index;
        r.frame = cy->frame;
        r.id = cy->query_id;
        fs_cycle_stats now;
        snapshot(cy, &now);
        diff(cy, &now, &cy->query_snap, &r.s);
        r.s.cycles = ready + cy->est - cy->query_issue;
        r.s.query_latency_max = lat;
        cy->record_fn(cy->record_user, &r);
    }
    cy->query_index++;
}

void fs_cycle_query_wait(void *user, fs_context *c, GLuint id)
{
    fs_cycle *cy = user;
    (void)c;
    for (int i = 0; i < cy->nqready; i++)
        if (cy->qready[i].id == id) {
            close_triangle(cy);
            wait_until(cy, cy->qready[i].ready);
            return;
        }
}

/* ---- frames ---- */

void fs_cycle_frame_end(fs_cycle *cy, fs_cycle_stats *out)
{
    cy->watch.mask.quiet = false;
    close_draw(cy);
    close_triangle(cy);
    fs_cyc_charge_estimated_draws(cy);

    wait_until(cy, fs_cyc_time(cy)); /* swap: the frame is done when drained */
    if (cy->sig)
        fs_signals_frame_end(cy->sig, fs_cyc_time(cy));
    fs_cycle_stats now;
    snapshot(cy, &now);
    diff(cy, &now, &cy->frame_snap, out);
    cy->frame_snap = now;
    for (int u = 0; u < FS_U_COUNT; u++)
        for (int i = 0; i < cy->u[u].n; i++)
            cy->u[u].st[i].in.hwm = 0;
    cy->rtri.in.hwm = 0;
    fs_cyc_sample_frame_end(cy, out->cycles);
    cy->frame++;
    if (cy->sig)
        fs_signals_frame_begin(cy->sig, cy->frame, fs_cyc_time(cy));
    cy->frame_skipped = cy->frame_sampling && !fs_cyc_frame_simulated(cy, cy->frame);
}
