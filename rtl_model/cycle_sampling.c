/*
 * The sampling estimator of sampled mode (docs/cycle_model.md): the tile
 * sample and its tables, spread timing of tile-sampled triangles from the
 * cost pools, draw sampling (kinds, the frame's sequence, the estimated
 * draws' cycles), frame sampling (interpolated frames) and the error
 * estimates.  The observer (cycle_observer.c) asks it at draw, triangle,
 * quad and frame granularity; it times its estimates on the FIFO engine
 * (cycle_fifo.h).
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "cycle_internal.h"
#include "../pipeline/context.h"

/* The per-screen tables of the tile sample, once it and the screen are
 * known: the per-tile work of the error estimate (no estimate without
 * memory for it) and the map of sampled tiles (the hash answers without). */
void fs_cyc_tile_tables_alloc(fs_cycle *cy)
{
    free(cy->tile_work);
    free(cy->tile_map);
    cy->tile_work = NULL;
    cy->tile_map = NULL;
    cy->watch.mask.map = NULL;
    cy->watch.mask.map_w = cy->watch.mask.map_h = 0;
    if (cy->tiles.every <= 1 || cy->fb_width <= 0 || cy->fb_height <= 0)
        return;
    int side = 1 << cy->watch.mask.shift;
    cy->tiles_x = (cy->fb_width + side - 1) / side;
    cy->tiles_y = (cy->fb_height + side - 1) / side;
    size_t n = (size_t)cy->tiles_x * (size_t)cy->tiles_y;
    cy->tile_work = calloc(2 * n, sizeof *cy->tile_work); /* work, fragments */
    cy->tile_map = calloc(n + 3, 1); /* + 3: fs_tile_mask.map */
    if (!cy->tile_map)
        return; /* the hash alone answers */
    for (int ty = 0; ty < cy->tiles_y; ty++)
        for (int tx = 0; tx < cy->tiles_x; tx++)
            cy->tile_map[(size_t)ty * (size_t)cy->tiles_x + (size_t)tx] =
                fs_cycle_tile_hashed(&cy->tiles, (uint32_t)tx, (uint32_t)ty);
    cy->watch.mask.map = cy->tile_map;
    cy->watch.mask.map_w = (uint32_t)cy->tiles_x;
    cy->watch.mask.map_h = (uint32_t)cy->tiles_y;
}

/* Sampled mode's tile sample: one tile in each block of n tiles, the
 * block as square as n allows (width: the largest divisor of n <= sqrt(n)). */
static void set_tiles(fs_cycle *cy, uint32_t n)
{
    if (n < 1)
        n = 1;
    uint32_t st = 1;
    for (uint32_t d = 1; d * d <= n; d++)
        if (n % d == 0)
            st = d;
    int sh = 0;
    while ((2 << sh) <= cy->cfg.sampling_tile_size)
        sh++;
    cy->tiles.every = n > 1 ? n : 1;
    cy->watch.mask.on = cy->tiles.every > 1;
    cy->kq = (double)cy->tiles.every;
    cy->kq_stale = false;
    double window = FS_CYC_POOL_WINDOW / (double)cy->tiles.every;
    cy->pool_keep = 1.0 - 1.0 / (window > FS_CYC_POOL_MIN ? window : FS_CYC_POOL_MIN);
    cy->tiles.step = st;
    cy->watch.mask.shift = sh;
    fs_cyc_tile_tables_alloc(cy);
}

/* ---- tile sampling: spread timing ---- */

static uint64_t mix64(uint64_t h)
{
    /* splitmix64 finaliser */
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

static fs_cyc_pool *pool_of(fs_cycle *cy, uint64_t flags)
{
    uint64_t key = flags + 1;
    uint64_t h = mix64(key);
    for (int i = 0; i < FS_CYC_POOLS; i++) {
        fs_cyc_pool *p = &cy->pools[(h + (uint64_t)i) & (FS_CYC_POOLS - 1)];
        if (p->key == key)
            return p;
        if (!p->key) {
            p->key = key;
            return p;
        }
    }
    return &cy->pool_any; /* more kinds than slots: the kinds share one */
}

/* One sampled quad's costs into a pool.  An exponential weight per quad
 * rather than sums per draw: city draws 50,000 buildings of a few sampled
 * quads each. */
static void pool_add(fs_cyc_pool *p, const fs_cyc_pool *q, double keep)
{
    double *d = &p->quads;
    const double *v = &q->quads;
    for (size_t i = 0; i < (sizeof *p - offsetof(fs_cyc_pool, quads)) / sizeof(double); i++)
        d[i] = d[i] * keep + v[i];
}

/* Whole units of v, the fraction carried to the next call on this slot. */
static uint64_t take(fs_cycle *cy, int slot, double v)
{
    double t = cy->carry[slot] + v, f;
    /* Below 2^62 (and not negative: v >= 0) truncation is floor, one
     * instruction where floor is a dozen without SSE4.1. */
    if (t >= 0.0 && t < 4611686018427387904.0)
        f = (double)(int64_t)t;
    else
        f = floor(t);
    cy->carry[slot] = t - f;
    return (uint64_t)f;
}

/* One item of q quads of the current triangle on image engine e, at the
 * pool's cost per quad. */
static void spread_item(fs_cycle *cy, const fs_cyc_pool *p, int e, double q)
{
    int b = e / (int)cy->cfg.fragment_image_engines;
    double per = q / p->quads;
    fs_cyc_stage *rs = &cy->u[FS_U_raster].st[b];
    fs_cyc_stage *ts = 2.0 * p->tex_quads > p->quads ? &cy->u[FS_U_texture].st[b] : NULL;
    fs_cyc_stage *fs = &cy->u[FS_U_fragment].st[e];
    fs_cyc_stage *os = 2.0 * p->occ_quads > p->quads ? &cy->u[FS_U_occlusion].st[e] : NULL;
    uint64_t arr = cy->tri_arrival;
    if (!cy->tri_started) {
        fs_cyc_fifo_push(&cy->rtri.in, arr > rs->free ? arr : rs->free);
        cy->tri_started = true;
    }
    /* llround for q >= 0 (half away from zero), inline: a libm call per
     * triangle showed in the profile.  q - floor(q) is exact below 2^52. */
    double qf = floor(q);
    uint64_t m = (uint64_t)qf + (q - qf >= 0.5);
    if (m < 1)
        m = 1;
    uint64_t r = take(cy, FS_CARRY_raster, p->raster * per);
    uint64_t a = fs_cyc_step_n(rs, arr, r, r, 0, false, ts ? ts : fs, m);
    if (ts) {
        cy->u[FS_U_texture].active = true;
        uint64_t t = take(cy, FS_CARRY_tex, p->tex * per), to = take(cy, FS_CARRY_tex_occ, p->tex_occ * per);
        a = fs_cyc_step_n(ts, a, t, to > t ? to : t, take(cy, FS_CARRY_tex_bytes, p->tex_bytes * per),
                 2.0 * p->tex_miss > p->tex_quads && !cy->cfg.memory_prefetch, fs, m);
    }
    uint64_t bytes = take(cy, FS_CARRY_frag_bytes, p->frag_bytes * per);
    uint64_t f = take(cy, FS_CARRY_frag, p->frag * per), fo = take(cy, FS_CARRY_frag_occ, p->frag_occ * per);
    a = fs_cyc_step_n(fs, a, f, fo > f ? fo : f, bytes, 2.0 * p->frag_reads > p->quads, os, m);
    cy->acc.fb_bytes += bytes;
    if (os) {
        cy->u[FS_U_occlusion].active = true;
        uint64_t o = take(cy, FS_CARRY_occ, p->occ * per);
        a = fs_cyc_step_n(os, a, o, o, 0, false, NULL, m);
        if (2.0 * p->occ_writes > p->occ_quads)
            a += (uint64_t)cy->cfg.occlusion_write_latency;
    }
    if (a > cy->done)
        cy->done = a;
    cy->acc.quads += take(cy, FS_CARRY_quads, q);
    cy->acc.fragments += take(cy, FS_CARRY_frags, p->frags * per);
}

/* The costs a triangle's estimate uses: its state's pool once it holds a
 * few quads, else all states' together. */
static const fs_cyc_pool *estimate_pool(const fs_cycle *cy)
{
    return cy->pool_cur && cy->pool_cur->quads >= 8.0 ? cy->pool_cur : &cy->pool_any;
}

/* Unit cycles of a pool's quads, memory traffic in cycles of bandwidth:
 * the work a draw's estimate and the tiles' error estimate weigh. */
static double pool_work(const fs_cycle *cy, const fs_cyc_pool *p)
{
    return p->raster + p->tex + p->frag + p->frag_bytes / (double)cy->cfg.memory_bytes_per_cycle;
}

/* Work of `area` pixels at the current pool's cost per fragment: the
 * measure of a draw that estimates filled draws (draw_by_work).  From the
 * areas, which are exact, and not from the sampled quads themselves, whose
 * work varied by about 6% from draw to draw on bench32 (a sixteenth of a
 * draw's area lands in the sampled tiles) where the true cycles fell
 * smoothly. */
static void work_add_area(fs_cycle *cy, const fs_cyc_pool *p, double area)
{
    /* The work per fragment is kept until a sampled quad changes the pools:
     * a filled draw charges every triangle, and two divisions each showed
     * in the profile. */
    if (p != cy->wpf_pool) {
        cy->wpf_pool = p;
        cy->wpf = p->frags > 0 ? pool_work(cy, p) / p->frags : 0.0;
    }
    if (p->frags > 0 && area > 0)
        cy->draw_work += area * cy->wpf;
}

/* Times the current tile-sampled triangle as its estimated quads, spread
 * over it instead of lumped on the few quads that fell in sampled tiles:
 * charging 1 triangle in 16 with 16 times its work made the pipeline see
 * bursts that stalled the front end where the real, even load did not
 * (garbage came out 10% high).  Its fragments are its exact area (the
 * pixel-centre rule makes that unbiased; scaling it by the sampled
 * fragments per area, a ratio estimator, added the noise of few tiles:
 * demo -12%); what a quad costs comes from the recent sampled quads of
 * draws with the same fragment state.  Items of about `every` quads keep
 * the units overlapping within a big triangle as they would quad by quad. */
void fs_cyc_spread_triangle(fs_cycle *cy)
{
    cy->tri_est = false;
    cy->area_done += cy->area_cur;
    cy->frags_done += cy->frags_cur;
    double area = cy->area_cur;
    cy->area_cur = cy->frags_cur = 0;
    /* The lumped charging of lines and points (fs_cycle_quad) scales by
     * areas over sampled fragments. */
    cy->kq_stale = true;
    const fs_cyc_pool *p = estimate_pool(cy);
    if (p->quads <= 0 || p->frags <= 0 || !(area > 0))
        return;
    if (cy->seq_work)
        work_add_area(cy, p, area);
    double q = area * p->quads / p->frags;
    double chunk = cy->tiles.every > 4 ? (double)cy->tiles.every : 4.0;
    double nch = 1, qc = q; /* q <= chunk: what the divisions below give, without them */
    if (q > chunk) {
        nch = ceil(q / chunk);
        qc = q / nch;
    }
    int n = cy->engines_total;
    int e0 = fs_cyc_route(cy, cy->tri_cx & ~1, cy->tri_cy & ~1);
    /* Small items go whole to one engine, from the triangle's own on; with
     * several interleaved engines this is an approximation (with frame
     * sampling, tile sampling is then off: fs_cycle_set_frames). */
    for (uint64_t i = 0; i < (uint64_t)nch; i++) {
        if (n > 1 && qc >= (double)n) {
            for (int e = 0; e < n; e++)
                spread_item(cy, p, e, qc / n);
        } else {
            spread_item(cy, p, (int)(((uint64_t)e0 + i) % (uint64_t)n), qc);
        }
    }
}

/* The state that decides what a fragment costs. */
static uint64_t state_flags(const fs_context *c)
{
    const fs_fragment_state *f = &c->frag;
    return (uint64_t)f->depth_enabled | (uint64_t)f->depth_write << 1 | (uint64_t)f->blend_enabled << 2 |
           (uint64_t)f->alpha_enabled << 3 | (uint64_t)f->stencil_enabled << 4 |
           (uint64_t)f->scissor_enabled << 5 | (uint64_t)f->suppress_writes << 6 |
           (uint64_t)c->raster.interpolate_tex << 7 | (uint64_t)c->raster.cull_enabled << 8 |
           (uint64_t)(c->occlusion_hook != NULL) << 9 | (uint64_t)f->logic_op_enabled << 10;
}

static fs_cyc_kind *kind_of(fs_cycle *cy, const fs_context *c, GLenum mode, size_t n)
{
    uint64_t flags = state_flags(c);
    uint64_t key = ((uint64_t)n << 16 | flags << 4 | (uint64_t)mode) + 1;
    uint64_t h = mix64(key);
    for (uint64_t i = 0; i < 64; i++) {
        fs_cyc_kind *k = &cy->kinds[(h + i) & (FS_CYC_KINDS - 1)];
        if (k->key == key)
            return k;
        if (k->key == 0) {
            k->key = key;
            return k;
        }
    }
    return NULL; /* table crowded: simulate */
}

/* Appends a draw to this frame's sequence; false when out of memory (the
 * draw then counts nothing). */
static bool seq_push(fs_cycle *cy, fs_cyc_kind *k, double c)
{
    if (cy->nseq == cy->seq_cap) {
        size_t cap = cy->seq_cap ? cy->seq_cap * 2 : 256;
        struct fs_cyc_seq *s = realloc(cy->seq, cap * sizeof *s);
        if (!s)
            return false;
        cy->seq = s;
        cy->seq_cap = cap;
    }
    cy->seq[cy->nseq].k = k;
    cy->seq[cy->nseq].w = -1.0;
    cy->seq[cy->nseq++].c = c;
    return true;
}

/* The draw whose work was arriving is over: its entry keeps it. */
static void seq_close_work(fs_cycle *cy)
{
    if (cy->seq_work && cy->seq_work <= cy->nseq)
        cy->seq[cy->seq_work - 1].w = cy->draw_work;
    cy->seq_work = 0;
    cy->draw_work = 0.0;
}

/* The nearest simulated draw of kind k before (dir -1) or after (+1)
 * entry i, or -1. */
static ptrdiff_t seq_simulated(const fs_cycle *cy, const fs_cyc_kind *k, ptrdiff_t i, int dir)
{
    for (ptrdiff_t j = i + dir; j >= 0 && j < (ptrdiff_t)cy->nseq; j += dir)
        if (cy->seq[j].k == k && cy->seq[j].c >= 0.0)
            return j;
    return -1;
}

/* A filled draw i from its work w (work_add_area): on the line through two
 * simulated draws of its kind in (work, cycles), the two around it or the
 * two nearest on one side.  Cost drifts with the draw order as the depth
 * buffer fills, and linear interpolation of cycles by place missed that
 * curve by +2.3% on bench32; a ratio c/w instead missed a draw whose cycles
 * the front end decides, whatever its fragments (bench8 +1.6%).  The slope
 * is kept between 0 (work does not show) and the larger ratio (it all
 * shows); the two ends' predictions are then blended by place.  False
 * where no two simulated draws measured work. */
static bool draw_by_work(const fs_cycle *cy, const fs_cyc_kind *k, ptrdiff_t a, ptrdiff_t b, ptrdiff_t i,
                         double *e, double *d)
{
    if (a < 0 && b < 0)
        return false;
    ptrdiff_t p = a, q = b;
    if (p < 0) { p = b; q = seq_simulated(cy, k, b, +1); }
    else if (q < 0) { q = a; p = seq_simulated(cy, k, a, -1); }
    if (p < 0 || q < 0)
        return false;
    const struct fs_cyc_seq *P = &cy->seq[p], *Q = &cy->seq[q];
    if (!(P->w > 0.0) || !(Q->w > 0.0))
        return false;
    double smax = fmax(P->c / P->w, Q->c / Q->w);
    double dw = Q->w - P->w;
    double s = fabs(dw) > 1e-9 * (P->w + Q->w) ? (Q->c - P->c) / dw : 0.0;
    s = fmin(fmax(s, 0.0), smax);
    double w = cy->seq[i].w;
    double ep = P->c + s * (w - P->w), eq = Q->c + s * (w - Q->w);
    double t = (double)(i - p) / (double)(q - p);
    t = fmin(fmax(t, 0.0), 1.0);
    *e = fmax(0.0, ep + (eq - ep) * t);
    *d = (eq - ep) / 4.0;
    return true;
}

/* Each estimated draw of the frame, from the nearest simulated draws of its
 * kind before and after it (by place in the frame): a filled draw from its
 * work (draw_by_work), a skipped one linear between their cycles, or the
 * nearer one's at either end.  Uncertainty: a quarter of the step between
 * them, or the kind's spread at an end. */
void fs_cyc_charge_estimated_draws(fs_cycle *cy)
{
    seq_close_work(cy);
    size_t n = cy->nseq;
    double total = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (cy->seq[i].c >= 0.0)
            continue;
        fs_cyc_kind *k = cy->seq[i].k;
        ptrdiff_t a = seq_simulated(cy, k, (ptrdiff_t)i, -1), b = seq_simulated(cy, k, (ptrdiff_t)i, +1);
        double e, d;
        if (cy->seq[i].w >= 0.0 && draw_by_work(cy, k, a, b, (ptrdiff_t)i, &e, &d)) {
            /* estimated from its own work */
        } else if (a >= 0 && b >= 0) {
            double ca = cy->seq[a].c, cb = cy->seq[b].c;
            e = ca + (cb - ca) * (double)((ptrdiff_t)i - a) / (double)(b - a);
            d = (cb - ca) / 4.0;
        } else {
            e = a >= 0 ? cy->seq[a].c : b >= 0 ? cy->seq[b].c : k->sum / (double)k->nsamp;
            double m = (double)k->nsamp, mean = k->sum / m;
            d = m > 1 ? sqrt(fmax(0.0, (k->sumsq - m * mean * mean) / (m - 1.0))) : 0.0;
        }
        total += e;
        cy->draw_var += d * d;
    }
    uint64_t t = (uint64_t)llround(total);
    cy->est += t;
    cy->acc.estimated_cycles += t;
    cy->nseq = 0;
    cy->seq_open = 0;
}

/* Whether a draw leaves state that the per-fragment work of later draws
 * depends on: depth (written only while the depth test is on) or stencil. */
static bool draw_writes_tests(const fs_context *c)
{
    const fs_fragment_state *f = &c->frag;
    return (f->depth_enabled && f->depth_write) || f->stencil_enabled;
}

int fs_cyc_sample_draw(fs_cycle *cy, const fs_context *c, GLenum mode, size_t n)
{
    seq_close_work(cy);
    cy->watch.mask.quiet = false;
    if (cy->tiles.every > 1)
        cy->pool_cur = pool_of(cy, state_flags(c));
    if (cy->mode != FS_CYCLE_SAMPLED || cy->frame_sampling || cy->too_short || cy->cfg.sampling_every <= 1)
        return -1;
    fs_cyc_kind *k = kind_of(cy, c, mode, n);
    if (!k)
        return -1;
    k->seen++;
    if (k->nsamp >= (uint64_t)cy->cfg.sampling_min_samples && k->seen % (uint64_t)cy->cfg.sampling_every != 0) {
        /* Estimated at the frame end, between the simulated draws of its
         * kind before and after it (cost drifts with the draw order: later
         * draws meet a fuller depth buffer). */
        uint64_t e = (uint64_t)llround(k->sum / (double)k->nsamp);
        bool listed = seq_push(cy, k, -1.0);
        cy->acc.draws_estimated++;
        if (cy->record_draws)
            fs_cyc_emit_draw(cy, true, e);
        cy->draw_index++;
        /* Skipped, a draw that hides later ones leaves holes in the depth
         * buffer, and the simulated draws after it came out 16% high
         * (bench32).  Filled in the sampled tiles, it costs about half a
         * simulated draw (docs/cycle_model.md). */
        cy->watch.mask.quiet = cy->tiles.every > 1 && draw_writes_tests(c) && !c->occlusion_hook;
        if (cy->watch.mask.quiet && listed)
            cy->seq_work = cy->nseq;
        return cy->watch.mask.quiet;
    }
    cy->draw_kind = k;
    cy->draw_sampled = true;
    cy->seq_open = seq_push(cy, k, 0.0) ? cy->nseq : 0;
    cy->seq_work = cy->seq_open;
    return -1;
}

void fs_cycle_triangle_area(void *user, double area, int x, int y)
{
    fs_cycle *cy = user;
    if (cy->watch.mask.quiet) {
        work_add_area(cy, estimate_pool(cy), area);
        return;
    }
    if (cy->tri_est)
        fs_cyc_spread_triangle(cy); /* the previous piece of a clipped triangle */
    cy->area_cur = area;
    cy->frags_cur = 0;
    cy->tri_cx = x;
    cy->tri_cy = y;
    cy->tri_est = true;
}

/* Tile sampling's error estimate: unscaled work w and the fragments of a
 * sampled quad at its tile. */
void fs_cyc_tile_work_add(fs_cycle *cy, const fs_quad *q, double w, unsigned frags)
{
    if (!cy->tile_work)
        return;
    int tx = q->x >> cy->watch.mask.shift, ty = q->y >> cy->watch.mask.shift;
    if (tx >= 0 && ty >= 0 && tx < cy->tiles_x && ty < cy->tiles_y) {
        double *t = &cy->tile_work[2 * ((size_t)ty * (size_t)cy->tiles_x + (size_t)tx)];
        t[0] += w;
        t[1] += frags;
    }
}

/* Tile sampling: a sampled quad of a triangle timed by spread_triangle.
 * Its costs go into the pools; the units see it as part of its triangle's
 * estimate. */
void fs_cyc_sample_quad(fs_cycle *cy, fs_context *c, const fs_quad *q, unsigned n, unsigned reaching,
                        unsigned passed, unsigned written, bool fill)
{
    fs_cyc_pool v = {0};
    v.quads = 1.0;
    v.frags = (double)n;
    v.raster = (double)fs_cyc_raster_cycles(&cy->cfg, n);
    /* What the quad occupies a stage for: its memory time where that is
     * longer (a train's sums would hide quads limited by memory behind
     * quads limited by service). */
    uint64_t bw = cy->fbmem[0].bw, tbw = cy->texmem[0].bw;
    if (cy->tex_pending) {
        uint64_t tm = (cy->tex_bytes + tbw - 1) / tbw;
        v.tex_quads = 1.0;
        v.tex = (double)cy->tex_service;
        v.tex_bytes = (double)cy->tex_bytes;
        v.tex_miss = cy->tex_misses ? 1.0 : 0.0;
        v.tex_occ = (double)(tm > cy->tex_service ? tm : cy->tex_service);
        cy->tex_pending = false;
        cy->tex_service = cy->tex_bytes = cy->tex_misses = 0;
    }
    uint64_t service, bytes;
    bool reads;
    fs_cyc_fragment_work(c, cy, reaching, passed, written, &service, &bytes, &reads);
    uint64_t fm = (bytes + bw - 1) / bw;
    v.frag = (double)service;
    v.frag_bytes = (double)bytes;
    v.frag_reads = reads ? 1.0 : 0.0;
    v.frag_occ = (double)(fm > service ? fm : service);
    if (cy->occ_pending) {
        uint64_t os;
        bool writes;
        fs_cyc_occlusion_quad_end(cy, &os, &writes);
        v.occ_quads = 1.0;
        v.occ = (double)os;
        v.occ_writes = writes ? 1.0 : 0.0;
    }
    fs_cyc_pool *p = cy->pool_cur ? cy->pool_cur : &cy->pool_any;
    pool_add(p, &v, cy->pool_keep);
    cy->wpf_pool = NULL;
    if (p != &cy->pool_any)
        pool_add(&cy->pool_any, &v, cy->pool_keep);
    if (fill)
        return; /* its triangle has no area charged: only the costs count */
    cy->frags_cur += n;
    fs_cyc_tile_work_add(cy, q, pool_work(cy, &v), n);
}

double fs_cyc_lump_factor(fs_cycle *cy)
{
    if (cy->kq_stale) {
        cy->kq = cy->frags_done >= 256 && cy->area_done > 0 ? cy->area_done / cy->frags_done : (double)cy->tiles.every;
        cy->kq_stale = false;
    }
    return cy->kq;
}

/* Tile sampling's sampling error of one frame, as a standard error of its
 * cycles.  Spread timing is a ratio estimator (Cochran, Sampling
 * Techniques, 3rd ed., 6.2-6.4): every triangle's exact area times the work
 * per fragment R of the sampled tiles, so its error is that of R, whose
 * variance comes from the residuals d = w - R f of the sampled tiles (w:
 * work, f: fragments): V = N^2 n s_d^2 (1 - 1/N) for the total over
 * N = every * n tiles (eq. 6.9, the sampled tiles treated as a simple
 * random sample, conservative for the jittered one).  The spread of the
 * work itself (eq. 2.8, the earlier estimate) counted the tiles' different
 * areas, which the exact areas remove: 22% on forest (O2) for an error of
 * -1.5%.  Its relative error is applied to the frame's cycles.  This is
 * the noise of the sample only, not a bias of the cost pools (textured,
 * docs/cycle_model.md). */
static double tile_frame_error(fs_cycle *cy, uint64_t frame_cycles)
{
    double n = 0, sw = 0, sf = 0, sww = 0, swf = 0, sff = 0, N = (double)cy->tiles.every;
    for (int ty = 0; ty < cy->tiles_y; ty++)
        for (int tx = 0; tx < cy->tiles_x; tx++) {
            if (!fs_tile_mask_has(&cy->watch.mask, (uint32_t)tx, (uint32_t)ty))
                continue;
            const double *t = &cy->tile_work[2 * ((size_t)ty * (size_t)cy->tiles_x + (size_t)tx)];
            n++;
            sw += t[0];
            sf += t[1];
            sww += t[0] * t[0];
            swf += t[0] * t[1];
            sff += t[1] * t[1];
        }
    memset(cy->tile_work, 0, 2 * (size_t)cy->tiles_x * (size_t)cy->tiles_y * sizeof *cy->tile_work);
    if (n < 2 || sw <= 0 || sf <= 0)
        return 0.0;
    /* sum of (w - R f)^2 with R = sw / sf, from the sums */
    double R = sw / sf, sdd = sww - 2.0 * R * swf + R * R * sff;
    double s2 = sdd / (n - 1);
    double var = N * N * n * (s2 > 0 ? s2 : 0) * (1.0 - 1.0 / N);
    double rel = sqrt(var) / (N * sw);
    return rel * (double)frame_cycles;
}

void fs_cyc_sample_frame_end(fs_cycle *cy, uint64_t frame_cycles)
{
    double te = 0.0;
    if (cy->tiles.every > 1 && cy->tile_work && !cy->frame_skipped)
        te = tile_frame_error(cy, frame_cycles);
    if (!cy->frame_sampling) {
        cy->tile_var += te * te;
        return;
    }
    if (cy->frames_done == cy->frame_cap) {
        uint64_t cap = cy->frame_cap ? cy->frame_cap * 2 : 64;
        uint64_t *fc = realloc(cy->frame_cycles, cap * sizeof *fc);
        if (fc)
            cy->frame_cycles = fc;
        bool *fsk = realloc(cy->frame_was_skipped, cap * sizeof *fsk);
        if (fsk)
            cy->frame_was_skipped = fsk;
        double *fte = realloc(cy->frame_tile_err, cap * sizeof *fte);
        if (fte)
            cy->frame_tile_err = fte;
        if (fc && fsk && fte)
            cy->frame_cap = cap;
    }
    if (cy->frames_done < cy->frame_cap) {
        cy->frame_tile_err[cy->frames_done] = te;
        cy->frame_cycles[cy->frames_done] = frame_cycles;
        cy->frame_was_skipped[cy->frames_done] = cy->frame_skipped;
        cy->frames_done++;
    }
}

/* ---- sampled mode: frames ---- */

/* Frames are interpolated in sequences (fs_cycle_set_frames): frame 0 of
 * a captured program is a warm-up more often than not (it carries the
 * uploads, list compilations and first clears: in full cycle mode on O2,
 * frame 0 of 26 of the 31 programs of the conformance corpus costs
 * 1.27-2.99x the mean of the three frames after it, polyhedra's 0.08x),
 * so it is simulated and in no sequence; frame 1 starts the steady part
 * the skipped frames are interpolated in. */
bool fs_cyc_frame_simulated(const fs_cycle *cy, uint64_t f)
{
    return f >= cy->nplan || cy->plan_sim[f];
}

void fs_cycle_set_frame_signatures(fs_cycle *cy, const uint64_t *kind, const uint64_t *exact, uint64_t n)
{
    free(cy->sig_kind);
    free(cy->sig_exact);
    cy->nsig = 0;
    cy->sig_kind = n && kind && exact ? malloc(n * sizeof *cy->sig_kind) : NULL;
    cy->sig_exact = cy->sig_kind ? malloc(n * sizeof *cy->sig_exact) : NULL;
    if (!cy->sig_exact) { /* none, or out of memory: one sequence, as without signatures */
        free(cy->sig_kind);
        cy->sig_kind = NULL;
        return;
    }
    memcpy(cy->sig_kind, kind, n * sizeof *kind);
    memcpy(cy->sig_exact, exact, n * sizeof *exact);
    cy->nsig = n;
}

/* Which members j of a sequence of m frames (in frame order) are
 * simulated: the first, every step-th and the last.  A sequence of exact
 * repeats (the same calls, arguments and data: the same work but for the
 * state a frame finds, the texture cache, an uncleared buffer) needs only
 * its first and last, whose difference measures that state's effect;
 * any other the step sampling.frames, at most (m - 1) / 2: every skipped
 * frame then lies between simulated frames with a third one beyond, which
 * the error estimate's second difference needs (seq_finish).  A sequence
 * of fewer frames (2 to 4 others) has no such step and is simulated in
 * full: with two steady frames the estimate cannot see a frame that breaks
 * the line (4-frame corpus programs: errors to 0.8% under estimates of
 * 0.2%). */
static void seq_plan(fs_cycle *cy, const uint64_t *f, uint64_t m, bool exact)
{
    uint64_t cfg = (uint64_t)cy->cfg.sampling_frames, most = exact ? m - 1 : (m - 1) / 2;
    uint64_t step = exact || cfg > most ? most : cfg;
    uint32_t s = cy->nseqs++;
    for (uint64_t j = 0; j < m; j++) {
        cy->plan_seq[f[j]] = s;
        cy->plan_sim[f[j]] = step < 2 || j % step == 0 || j + 1 == m;
    }
    if (!exact && step > cy->frame_step)
        cy->frame_step = step;
}

typedef struct sig_frame { uint64_t key, f; } sig_frame;

static int sig_frame_cmp(const void *pa, const void *pb)
{
    const sig_frame *a = pa, *b = pb;
    return a->key != b->key ? (a->key < b->key ? -1 : 1) : (a->f > b->f) - (a->f < b->f);
}

/* Frames 1.. not yet in a sequence whose signature key[] is shared by at
 * least `least` of them become one sequence per signature (clusters of
 * frames with the same work, as MEGsim clusters frames); e and members:
 * room for the frames. */
static void group_frames(fs_cycle *cy, const uint64_t *key, uint64_t least, bool exact, sig_frame *e,
                         uint64_t *members)
{
    uint64_t n = 0;
    for (uint64_t f = 1; f < cy->nplan; f++)
        if (cy->plan_seq[f] == FS_CYC_NO_SEQ)
            e[n++] = (sig_frame){key[f], f};
    qsort(e, n, sizeof *e, sig_frame_cmp);
    for (uint64_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && e[j].key == e[i].key; j++)
            ;
        if (j - i < least)
            continue;
        for (uint64_t k = i; k < j; k++)
            members[k - i] = e[k].f;
        seq_plan(cy, members, j - i, exact);
    }
}

void fs_cycle_set_frames(fs_cycle *cy, uint64_t frames)
{
    cy->nframes_trace = frames;
    free(cy->plan_seq);
    free(cy->plan_sim);
    cy->plan_seq = NULL;
    cy->plan_sim = NULL;
    cy->nplan = 0;
    cy->nseqs = 0;
    cy->frame_step = 0;
    bool sampled = cy->mode == FS_CYCLE_SAMPLED && frames >= 3 && cy->cfg.sampling_frames > 1;
    bool skips = false;
    if (sampled) {
        cy->plan_seq = malloc(frames * sizeof *cy->plan_seq);
        cy->plan_sim = malloc(frames * sizeof *cy->plan_sim);
        sig_frame *e = malloc(frames * sizeof *e);
        uint64_t *rest = malloc(frames * sizeof *rest);
        if (cy->plan_seq && cy->plan_sim && e && rest) {
            cy->nplan = frames;
            for (uint64_t f = 0; f < frames; f++) {
                cy->plan_seq[f] = FS_CYC_NO_SEQ;
                cy->plan_sim[f] = true;
            }
            /* Clusters by signature (the driver's, fs_cycle_set_frame_signatures):
             * exact repeats of 3 or more, then kinds of 5 or more (the fewest
             * that sample); the other frames are one sequence, interpolated in
             * frame order as without signatures. */
            if (cy->nsig >= frames) {
                group_frames(cy, cy->sig_exact, 3, true, e, rest);
                group_frames(cy, cy->sig_kind, 5, false, e, rest);
            }
            uint64_t m = 0;
            for (uint64_t f = 1; f < frames; f++)
                if (cy->plan_seq[f] == FS_CYC_NO_SEQ)
                    rest[m++] = f;
            if (m)
                seq_plan(cy, rest, m, false);
            for (uint64_t f = 0; f < frames; f++)
                skips |= !cy->plan_sim[f];
        }
        free(e);
        free(rest);
    }
    if (!cy->nplan) { /* no plan (out of memory too): nothing skipped */
        free(cy->plan_seq);
        free(cy->plan_sim);
        cy->plan_seq = NULL;
        cy->plan_sim = NULL;
    }
    /* A trace no sequence of which can skip a frame (3 to 5 frames without
     * repeats) is simulated in full and says so, rather than report an
     * error it cannot bound; draws and tiles are not sampled either
     * (biased there: docs/sampling.md). */
    cy->too_short = sampled && !skips;
    cy->frame_sampling = sampled && !cy->too_short;
    cy->frame_skipped = cy->frame_sampling && !fs_cyc_frame_simulated(cy, cy->frame);
    /* Inside sampled frames, tile sampling only on one image engine: dealing
     * a triangle's estimated quads to many interleaved engines is biased
     * (InfiniteReality: textured +32%, demo -23% depending on the dealing,
     * docs/cycle_model.md), and frame sampling alone is within 2% there. */
    if (cy->mode == FS_CYCLE_SAMPLED)
        set_tiles(cy, (uint32_t)(cy->too_short ? 1
                                 : !cy->frame_sampling ? cy->cfg.sampling_tiles
                                 : cy->engines_total == 1 ? cy->cfg.sampling_frame_tiles : 1));
}

bool fs_cycle_too_short(const fs_cycle *cy)
{
    return cy->too_short;
}

bool fs_cycle_frame_skipped(const fs_cycle *cy)
{
    return cy->frame_skipped;
}

/* Student's t, two-sided 95%, for df = 1..30 degrees of freedom; beyond,
 * z + (z^3 + z) / (4 df) (the first term of its expansion in 1/df). */
static double t95(int df)
{
    static const double t[30] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                 2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
    return df < 1 ? FS_CYC_Z95 : df <= 30 ? t[df - 1] : FS_CYC_Z95 + 2.37 / df;
}

/* A frame of a sequence in fs_cycle_finish: its cycles, whether it was
 * skipped, its tile error and its weight in the interpolated frames. */
typedef struct seq_frame { double c, te, coef; bool skipped; } seq_frame;

/* The frames' error as a sample's variance: each simulated frame s_j
 * between two others is a test of the interpolation, its residual
 * r_j = c(s_j) - the line through its neighbours.  If frames scatter
 * about a smooth line with variance s^2, r_j has variance
 * s^2 (1 + wl^2 + wr^2) (wl, wr: the line's weights of the neighbours), so
 * s^2 is estimated from the residuals with one degree of freedom each.
 * An interpolated frame then misses by its own scatter and by its
 * endpoints': the total misses with variance
 * s^2 (skipped frames + sum over simulated frames of coef^2).  This is
 * what the curvature bound does not see: textured on InfiniteReality
 * scatters by 1-3% from frame to frame, and the bound (0.21%) was a third
 * of the error (+0.62%, docs/sampling.md).  The tile errors of the
 * simulated frames carry into the frames interpolated from them (weight
 * 1 + coef).  Returns the standard error, *df its degrees of freedom. */
static double seq_noise(fs_cycle *cy, const seq_frame *s, uint64_t m, int *df)
{
    uint64_t nskip = 0;
    double r2 = 0, cs2 = 0, sum = 0, sumsq = 0;
    int nr = 0, ns = 0;
    uint64_t p = UINT64_MAX, q = UINT64_MAX; /* the last two simulated frames */
    for (uint64_t f = 0; f < m; f++) {
        if (s[f].skipped) {
            nskip++;
            continue;
        }
        double k = s[f].coef, te = s[f].te * (1.0 + k);
        cs2 += k * k;
        cy->tile_var += te * te;
        ns++;
        sum += s[f].c;
        sumsq += s[f].c * s[f].c;
        if (p != UINT64_MAX && q != UINT64_MAX) {
            double h = (double)(f - p), wl = (double)(f - q) / h, wr = (double)(q - p) / h;
            double r = s[q].c - wl * s[p].c - wr * s[f].c;
            r2 += r * r / (1.0 + wl * wl + wr * wr);
            nr++;
        }
        p = q;
        q = f;
    }
    /* One residual can be 0 by chance (frames 1, 8, 15 of 10, 11, 12 quads
     * lie on a line; the trace between them did not, -3.0%): below two,
     * the simulated frames' scatter about their mean stands in, which
     * overstates a trend but is what three frames can tell (two: the
     * first and last of exact repeats, one degree of freedom). */
    double s2 = nr > 0 ? r2 / nr : 0.0;
    if (nr < 2 && ns >= 2) {
        s2 = fmax(s2, (sumsq - sum * sum / ns) / (ns - 1));
        nr = ns - 1;
    }
    *df = nr;
    return nr > 0 ? sqrt(fmax(s2, 0.0) * ((double)nskip + cs2)) : 0.0;
}

/* One sequence's skipped frames, linear between its simulated frames
 * a < f < b around them (by place in the sequence); returns the cycles
 * they add, *half the 95% half-width of their error: the larger of the
 * curvature bound and Student's t times the scatter's standard error
 * (seq_noise; with 2 residuals t is 4.3, which is what 2 residuals can
 * tell). */
static double seq_finish(fs_cycle *cy, seq_frame *s, uint64_t m, double *half)
{
    double add = 0;
    for (uint64_t f = 0; f < m; f++) {
        if (!s[f].skipped)
            continue;
        uint64_t a = f, b = f;
        while (a > 0 && s[a].skipped)
            a--;
        while (b + 1 < m && s[b].skipped)
            b++;
        double ca = s[a].c, cb = s[b].skipped ? ca : s[b].c;
        double w = b > a ? (double)(f - a) / (double)(b - a) : 0.0;
        s[f].c = (double)llround(ca + w * (cb - ca));
        s[a].coef += s[b].skipped ? 1.0 : 1.0 - w;
        s[b].coef += s[b].skipped ? 0.0 : w;
        add += s[f].c;
    }
    /* Error: linear interpolation of a curve c(t) misses
     * c''/2 (t - a)(b - t) at t (the interpolation remainder), the same sign
     * across a segment and, where the curvature keeps its sign, across
     * segments: the misses are summed, not added in quadrature.  c'' of a
     * segment is the larger second difference at its two ends (from the
     * simulated frames around it).  The step rule (seq_plan) gives every
     * skipped frame three simulated frames; fewer are left only for exact
     * repeats (first and last) and when the trace ends before the frame
     * count it announced, and then the estimate falls back to a quarter of
     * the step per interpolated frame (which cannot see a trace that turns
     * between two samples: docs/cycle_model.md). */
    int nsim = 0;
    double err = 0;
    for (uint64_t f = 0; f < m; f++)
        nsim += !s[f].skipped;
    double prev_k = -1;
    for (uint64_t a = 0; a < m;) {
        uint64_t b = a + 1;
        while (b < m && s[b].skipped)
            b++;
        if (b >= m)
            break;
        double ca = s[a].c, cb = s[b].c;
        double h = (double)(b - a), sumprod = 0;
        for (uint64_t f = a + 1; f < b; f++)
            sumprod += (double)(f - a) * (double)(b - f);
        /* second differences at a (with the segment before) and at b
         * (with the segment after) */
        double k = prev_k;
        uint64_t c2 = b + 1;
        while (c2 < m && s[c2].skipped)
            c2++;
        double kb = -1;
        if (c2 < m) {
            double cc = s[c2].c, h2 = (double)(c2 - b);
            kb = fabs((cc - cb) / h2 - (cb - ca) / h) / ((h + h2) / 2.0);
        }
        if (kb > k)
            k = kb;
        if (nsim < 3 || k < 0)
            err += fabs(cb - ca) / 4.0 * (double)(b - a - 1);
        else
            err += 0.5 * k * sumprod;
        prev_k = kb;
        a = b;
    }
    cy->frame_error += err;
    int df;
    double sd = seq_noise(cy, s, m, &df);
    *half = fmax(err, t95(df) * sd);
    return add;
}

void fs_cycle_finish(fs_cycle *cy)
{
    if (!cy->frame_sampling || cy->finished)
        return;
    cy->finished = true;
    uint64_t n = cy->frames_done < cy->nplan ? cy->frames_done : cy->nplan;
    /* the frames of each sequence in frame order: counted, then placed */
    uint64_t *start = calloc((size_t)cy->nseqs + 1, sizeof *start), *order = malloc((n ? n : 1) * sizeof *order);
    seq_frame *s = malloc((n ? n : 1) * sizeof *s);
    if (!start || !order || !s) {
        /* out of memory: the skipped frames stay at 0 cycles, and the
         * estimate says the frames are unknown */
        cy->frame_half = (double)fs_cyc_now_total(cy);
        free(start);
        free(order);
        free(s);
        return;
    }
    for (uint64_t f = 0; f < n; f++) {
        if (cy->plan_seq[f] != FS_CYC_NO_SEQ)
            start[cy->plan_seq[f] + 1]++;
        else if (!cy->frame_was_skipped[f]) /* frame 0: its tile error alone */
            cy->tile_var += cy->frame_tile_err[f] * cy->frame_tile_err[f];
    }
    for (uint32_t q = 0; q < cy->nseqs; q++)
        start[q + 1] += start[q];
    for (uint64_t f = 0; f < n; f++)
        if (cy->plan_seq[f] != FS_CYC_NO_SEQ)
            order[start[cy->plan_seq[f]]++] = f;
    /* start[q] is now the end of sequence q */
    uint64_t add = 0, from = 0;
    cy->frame_error = cy->frame_half = 0;
    for (uint32_t q = 0; q < cy->nseqs; q++) {
        uint64_t m = start[q] - from;
        const uint64_t *idx = order + from;
        for (uint64_t j = 0; j < m; j++)
            s[j] = (seq_frame){(double)cy->frame_cycles[idx[j]], cy->frame_tile_err[idx[j]], 0.0,
                               cy->frame_was_skipped[idx[j]]};
        double half;
        add += (uint64_t)seq_finish(cy, s, m, &half);
        /* Sequences are clusters of different work: their errors are
         * summed, not added in quadrature (conservative where they are
         * independent). */
        cy->frame_half += half;
        for (uint64_t j = 0; j < m; j++)
            if (s[j].skipped)
                cy->frame_cycles[idx[j]] = (uint64_t)s[j].c;
        from = start[q];
    }
    cy->est += add;
    cy->acc.estimated_cycles += add;
    free(start);
    free(order);
    free(s);
}

uint64_t fs_cycle_frame_cycles(const fs_cycle *cy, uint64_t f, bool *skipped)
{
    if (!cy->frame_sampling || f >= cy->frames_done) {
        *skipped = false;
        return 0;
    }
    *skipped = cy->frame_was_skipped[f];
    return cy->frame_cycles[f];
}

void fs_cycle_error_parts(const fs_cycle *cy, double part[FS_CYCLE_ERR_PARTS])
{
    double total = (double)fs_cyc_now_total(cy);
    for (int i = 0; i < FS_CYCLE_ERR_PARTS; i++)
        part[i] = 0.0;
    if (cy->mode != FS_CYCLE_SAMPLED || !(total > 0))
        return;
    /* Frames: the larger of the curvature bound and the interval of their
     * scatter (t with the residuals' degrees of freedom: with 2 residuals
     * it is 4.3 standard errors, which is what 2 residuals can tell). */
    part[FS_CYCLE_ERR_FRAMES] = cy->frame_half / total;
    /* Tiles: hundreds of sampled tiles per frame, the normal quantile. */
    part[FS_CYCLE_ERR_TILES] = FS_CYC_Z95 * sqrt(cy->tile_var) / total;
    part[FS_CYCLE_ERR_DRAWS] = FS_CYC_Z95 * sqrt(cy->draw_var) / total;
}

double fs_cycle_error_estimate(const fs_cycle *cy)
{
    /* The parts are independent: their half-widths add in quadrature. */
    double part[FS_CYCLE_ERR_PARTS], v = 0;
    fs_cycle_error_parts(cy, part);
    for (int i = 0; i < FS_CYCLE_ERR_PARTS; i++)
        v += part[i] * part[i];
    return sqrt(v);
}

/* The next pass of --max-error: the setting that samples more where the
 * estimate is largest.  Frames: the step halved (the curvature bound
 * falls with its square, the scatter's with more residuals and fewer
 * skipped frames); below 2 nothing is left to skip.  Tiles inside frames:
 * off, not denser: on textured (O2) frame_tiles 2-16 came out 3-6.5% low,
 * denser no better (a bias of the cost pools, not noise).  Tiles of 1-2
 * frame traces: a quarter as many tiles per sampled tile (the standard
 * error falls by half).  Draws: one in a quarter as many.  Returns false
 * when cfg is already full simulation. */
bool fs_cycle_config_denser(const fs_cycle *cy, fs_cycle_config *cfg)
{
    double part[FS_CYCLE_ERR_PARTS];
    fs_cycle_error_parts(cy, part);
    long *knob[FS_CYCLE_ERR_PARTS] = {&cfg->sampling_frames, NULL, &cfg->sampling_every};
    bool frames_on = cy->frame_sampling;
    knob[FS_CYCLE_ERR_TILES] = frames_on ? &cfg->sampling_frame_tiles : &cfg->sampling_tiles;
    /* the largest part whose setting can still sample more */
    for (int tries = 0; tries < FS_CYCLE_ERR_PARTS; tries++) {
        int best = -1;
        for (int i = 0; i < FS_CYCLE_ERR_PARTS; i++)
            if (knob[i] && *knob[i] > 1 && (best < 0 || part[i] > part[best]))
                best = i;
        if (best < 0)
            break;
        long *k = knob[best];
        if (best == FS_CYCLE_ERR_FRAMES) {
            if (!frames_on) { /* frames = 1 already means no frame sampling */
                knob[best] = NULL;
                continue;
            }
            /* the step in effect (cfg may ask for more than the trace allows) */
            long step = (long)cy->frame_step / 2;
            if (step >= 2) {
                *k = step;
                return true;
            }
            /* nothing left to skip: full simulation */
            cfg->sampling_frames = cfg->sampling_tiles = cfg->sampling_frame_tiles = cfg->sampling_every = 1;
            return true;
        }
        if (best == FS_CYCLE_ERR_TILES && frames_on) {
            *k = 1;
            return true;
        }
        *k = *k >= 4 ? *k / 4 : 1;
        return true;
    }
    /* no part left (all 0): whatever still samples goes */
    if (cfg->sampling_frames > 1 || cfg->sampling_tiles > 1 || cfg->sampling_frame_tiles > 1 || cfg->sampling_every > 1) {
        cfg->sampling_frames = cfg->sampling_tiles = cfg->sampling_frame_tiles = cfg->sampling_every = 1;
        return true;
    }
    return false;
}
