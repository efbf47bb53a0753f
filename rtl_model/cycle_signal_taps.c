/*
 * The cycle model's signals (signals.def, docs/signals.md): the taps that
 * connect each stage, FIFO and memory of the FIFO engine to the signal
 * writer (cycle_signals.c), and the observer's events (draws, queries,
 * render modes, CTR reloads, the Occlusion Unit's engines and bus).  Only
 * what fs_cycle_signals_attach set up runs: without signals the engine
 * tests one NULL pointer per item.
 */
#include <stdlib.h>
#include "cycle_internal.h"
#include "../units/occlusion_unit.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

/* Each unit's busy signal; its stalled and FIFO signals follow it
 * (cycle_signals.h). */
static const int unit_busy_sig[FS_U_COUNT] = {
#define FS_CUNIT(name, meaning) FS_SIG_##name##_busy,
#include "cycle_stats.def"
#undef FS_CUNIT
};

/* The earliest cycle a change can still be reported at: every stage's
 * next item starts at or after its last departure, and nothing starts
 * before the host's command time (cycle_signals.h). */
static uint64_t horizon(const void *model)
{
    const fs_cycle *cy = model;
    uint64_t h = UINT64_MAX;
    for (int u = 0; u < FS_U_COUNT; u++)
        for (int i = 0; i < cy->u[u].n; i++) {
            uint64_t f = cy->u[u].st[i].free > cy->cmd ? cy->u[u].st[i].free : cy->cmd;
            if (f < h)
                h = f;
        }
    return h;
}

static fs_sig_tap *tap(fs_cycle *cy, size_t *k, int busy, int fifo, int inst)
{
    fs_sig_tap *t = &cy->taps[(*k)++];
    *t = (fs_sig_tap){cy->sig, busy, busy + 1, fifo, inst, 0};
    return t;
}

int fs_cycle_signals_attach(fs_cycle *cy, fs_signals *w)
{
    if (cy->mode != FS_CYCLE_FULL || cy->sig)
        return -1;
    size_t n = 1 + (size_t)cy->nmem;
    for (int u = 0; u < FS_U_COUNT; u++)
        n += (size_t)cy->u[u].n;
    cy->taps = calloc(n, sizeof *cy->taps);
    if (!cy->taps)
        return -1;
    cy->sig = w;
    size_t k = 0;
    for (int u = 0; u < FS_U_COUNT; u++) {
        int b = unit_busy_sig[u];
        fs_signals_set_instances(w, b, cy->u[u].n);
        fs_signals_set_instances(w, b + 1, cy->u[u].n);
        fs_signals_set_instances(w, b + 2, u == FS_U_raster ? 1 : cy->u[u].n);
        for (int i = 0; i < cy->u[u].n; i++)
            cy->u[u].st[i].in.tap = tap(cy, &k, b, b + 2, i);
    }
    /* The fragment generators take triangles from one FIFO (rtri), which
     * is what raster_fifo_hwm counts. */
    cy->rtri.in.tap = tap(cy, &k, FS_SIG_raster_busy, FS_SIG_raster_fifo, 0);
    fs_signals_set_instances(w, FS_SIG_memory_busy, cy->nmem);
    for (int i = 0; i < cy->nmem; i++)
        cy->fbmem[i].tap = tap(cy, &k, FS_SIG_memory_busy, FS_SIG_memory_busy, i);
    fs_signals_set_instances(w, FS_SIG_occlusion_engines_busy, cy->engines_total);
    fs_signals_set_instances(w, FS_SIG_occu_control_busy, cy->engines_total);
    fs_signals_set_horizon(w, horizon, cy);
    fs_signals_frame_begin(w, cy->frame, fs_cyc_time(cy));
    return 0;
}

void fs_cyc_signal_free(fs_cycle *cy) { free(cy->taps); }

void fs_cyc_signal_texture(fs_cycle *cy, uint64_t t)
{
    if (cy->sig_ctr)
        fs_signals_put(cy->sig, t, FS_SIG_ctr_reloads, 0, (int64_t)cy->sig_ctr);
    cy->sig_ctr = 0;
}

static void interval(fs_signals *w, int sig, int inst, uint64_t t, uint64_t len)
{
    if (!len)
        return;
    fs_signals_put(w, t, sig, inst, 1);
    fs_signals_put(w, t + len, sig, inst, -1);
}

void fs_cyc_signal_occlusion(fs_cycle *cy, int e, uint64_t t)
{
    /* The engines and OccU Control start together and overlap
     * (occlusion_stage.c): each is busy its own cycles from the start. */
    interval(cy->sig, FS_SIG_occlusion_engines_busy, e, t, cy->occ_last_tests);
    interval(cy->sig, FS_SIG_occu_control_busy, e, t, cy->occ_last_writes);
}

void fs_cyc_signal_render_mode(fs_cycle *cy, GLenum mode, uint64_t t)
{
    int v = mode == GL_BRIEF_OCCLUSION ? 1 : mode == GL_VERBOSE_OCCLUSION ? 2 : 0;
    fs_signals_put(cy->sig, t, FS_SIG_occu_mode, 0, v);
}

void fs_cyc_signal_draw(fs_cycle *cy, const fs_context *c, uint64_t t)
{
    fs_signals_put(cy->sig, t, FS_SIG_draw_start, 0, 1);
    fs_cyc_signal_render_mode(cy, fs_occlusion_render_mode(c), t);
}

void fs_cyc_signal_query_end(fs_cycle *cy, const fs_context *c, uint64_t issue, uint64_t ready)
{
    uint64_t samples = 0;
    fs_occlusion_query_result(c, cy->query_id, &samples);
    fs_signals_put(cy->sig, issue, FS_SIG_query_end, 0, 1);
    fs_signals_put(cy->sig, ready, FS_SIG_query_done, 0, 1);
    fs_signals_put(cy->sig, ready, FS_SIG_occlusion_result, 0, samples != 0);
}
