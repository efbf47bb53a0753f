/*
 * The cycle-level model on the command line: `fragsim replay --mode
 * functional|cycle|sampled [--csv FILE]` (cli_main.c parses the options and
 * calls these at the run's start, each frame end and the statistics write).
 * Statistics per frame, per draw and per occlusion query go to the JSON
 * statistics file ("cycle" object) and, with --csv, to one CSV row each.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>
#include "cli.h"
#include "gl_call.h"
#include "replay.h"
#include "../pipeline/context.h"

struct fs_cli_cycle {
    fs_cycle *cy;
    fs_cycle_mode mode;
    FILE *csv;
    json_t *draws_json;  /* draw and query records for the statistics file */
    json_t *queries_json;
    uint64_t ndraws, nqueries;
    struct { uint64_t frame; fs_cycle_stats s; } *frames;
    size_t nframes, cap;
    long clock_khz;      /* clock.khz: results in seconds too when not 0 */
    long max_error;      /* sampling.max_error, 1/100 % */
    const fs_cli_passes *passes; /* the run's passes so far (fs_cli_cycle_resample), or NULL */
};

int fs_cli_cycle_mode(const char *name, int *mode)
{
    if (!strcmp(name, "functional"))
        *mode = -1;
    else if (!strcmp(name, "cycle"))
        *mode = FS_CYCLE_FULL;
    else if (!strcmp(name, "sampled"))
        *mode = FS_CYCLE_SAMPLED;
    else
        return -1;
    return 0;
}

static void csv_row(FILE *f, const char *kind, uint64_t index, uint64_t frame, unsigned id, uint64_t vertices,
                    bool estimated, const fs_cycle_stats *s)
{
    fprintf(f, "%s,%llu,%llu,%u,%llu,%d", kind, (unsigned long long)index, (unsigned long long)frame, id,
            (unsigned long long)vertices, estimated ? 1 : 0);
    fs_cycle_stats_write_csv(f, s);
    fputc('\n', f);
}

/* The cycle statistics added to the JSON object o, in the table's order;
 * o itself, or NULL (o freed) when out of memory. */
static json_t *with_stats(json_t *o, const fs_cycle_stats *s)
{
    for (int i = 0; o && i < fs_cycle_stat_count; i++) {
        uint64_t v = *(const uint64_t *)((const char *)s + fs_cycle_stat_table[i].offset);
        if (json_object_set_new(o, fs_cycle_stat_table[i].name, json_integer((json_int_t)v)) != 0) {
            json_decref(o);
            o = NULL;
        }
    }
    return o;
}

static void on_record(void *user, const fs_cycle_record *r)
{
    fs_cli_cycle *h = user;
    bool draw = r->kind == FS_CYCLE_DRAW;
    json_t *j = draw ? h->draws_json : h->queries_json;
    uint64_t *n = draw ? &h->ndraws : &h->nqueries;
    if (j) {
        json_t *o = json_pack("{s:I, s:I, s:I}", "index", (json_int_t)r->index, "frame", (json_int_t)r->frame,
                              draw ? "mode" : "query", (json_int_t)r->id);
        if (o && draw && (json_object_set_new(o, "vertices", json_integer((json_int_t)r->vertices)) |
                          json_object_set_new(o, "estimated", json_boolean(r->estimated))) != 0) {
            json_decref(o);
            o = NULL;
        }
        json_array_append_new(j, with_stats(o, &r->s)); /* out of memory: the record is left out */
    }
    (*n)++;
    if (h->csv)
        csv_row(h->csv, draw ? "draw" : "query", r->index, r->frame, r->id, r->vertices, r->estimated, &r->s);
}

bool fs_cli_cycle_skip(const fs_cli_cycle *h, const fs_context *c, int cmd)
{
    return h && fs_cycle_frame_skipped(h->cy) && fs_cmd_skippable(c, cmd);
}

fs_cli_cycle *fs_cli_cycle_begin(int mode, const fs_cycle_config *cfg, fs_context *c, const char *csv_path,
                                 const fs_replayer *r, bool draw_stats, char *err, size_t errlen)
{
    fs_cli_cycle *h = calloc(1, sizeof *h);
    if (!h) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    h->mode = (fs_cycle_mode)mode;
    h->clock_khz = cfg->clock_khz;
    h->max_error = cfg->sampling_max_error;
    h->cy = fs_cycle_create(cfg, h->mode, err, errlen);
    if (!h->cy) {
        free(h);
        return NULL;
    }
    h->draws_json = json_array();
    h->queries_json = json_array();
    if (csv_path) {
        h->csv = fopen(csv_path, "w");
        if (!h->csv) {
            snprintf(err, errlen, "cannot write %s", csv_path);
            fs_cli_cycle_end(h);
            return NULL;
        }
        fprintf(h->csv, "kind,index,frame,id,vertices,estimated");
        fs_cycle_stats_write_csv_header(h->csv);
        fputc('\n', h->csv);
    }
    fs_cycle_set_record_fn(h->cy, on_record, h, draw_stats);
    const uint64_t *kind, *exact;
    uint64_t nsig = fs_replay_frame_signatures(r, &kind, &exact);
    fs_cycle_set_frame_signatures(h->cy, kind, exact, nsig);
    fs_cycle_set_frames(h->cy, fs_replay_info_get(r)->frames);
    fs_cycle_attach(h->cy, c);
    return h;
}

void fs_cli_cycle_frame(fs_cli_cycle *h, long frame)
{
    fs_cycle_stats s;
    fs_cycle_frame_end(h->cy, &s);
    if (h->nframes == h->cap) {
        size_t cap = h->cap ? h->cap * 2 : 16;
        void *p = realloc(h->frames, cap * sizeof *h->frames);
        if (!p)
            return;
        h->frames = p;
        h->cap = cap;
    }
    h->frames[h->nframes].frame = (uint64_t)frame;
    h->frames[h->nframes++].s = s;
}

/* Whether a pass ran with nothing sampled. */
static bool pass_full(const fs_cli_passes *ps, int i)
{
    return ps->p[i].frames <= 1 && ps->p[i].frame_tiles <= 1 && ps->p[i].tiles <= 1 && ps->p[i].every <= 1;
}

/* The final pass simulated everything because sampling could not meet the
 * bound (a pass before it sampled). */
static bool gave_up(const fs_cli_passes *ps)
{
    return ps && ps->n > 1 && pass_full(ps, ps->n - 1);
}

/* sampled mode's "max_error" object: the bound, whether the estimate met
 * it, whether it took full simulation, and the passes. */
static json_t *passes_json(const fs_cli_cycle *h, double estimate)
{
    json_t *arr = json_array();
    for (int i = 0; h->passes && i < h->passes->n; i++)
        json_array_append_new(arr, json_pack("{s:I, s:I, s:I, s:I, s:f, s:{s:f, s:f, s:f}}", "frames",
                                             (json_int_t)h->passes->p[i].frames, "frame_tiles",
                                             (json_int_t)h->passes->p[i].frame_tiles, "tiles",
                                             (json_int_t)h->passes->p[i].tiles, "every",
                                             (json_int_t)h->passes->p[i].every, "error_estimate",
                                             h->passes->p[i].estimate, "parts", "frames",
                                             h->passes->p[i].part[FS_CYCLE_ERR_FRAMES], "tiles",
                                             h->passes->p[i].part[FS_CYCLE_ERR_TILES], "draws",
                                             h->passes->p[i].part[FS_CYCLE_ERR_DRAWS]));
    double bound = (double)h->max_error / 10000.0;
    return json_pack("{s:f, s:b, s:b, s:b, s:o}", "bound", bound, "met", h->max_error <= 0 || estimate <= bound,
                     "resampled", h->passes && h->passes->n > 1, "cannot_by_sampling", gave_up(h->passes),
                     "passes", arr);
}

bool fs_cli_cycle_resample(fs_cli_cycle *h, fs_cycle_config *cfg, fs_cli_passes *passes)
{
    fs_cycle_stats t;
    double e = fs_cli_cycle_totals(h, &t);
    h->passes = passes;
    if (passes->n < FS_CLI_MAX_PASSES) {
        passes->p[passes->n].frames = cfg->sampling_frames;
        passes->p[passes->n].frame_tiles = cfg->sampling_frame_tiles;
        passes->p[passes->n].tiles = cfg->sampling_tiles;
        passes->p[passes->n].every = cfg->sampling_every;
        fs_cycle_error_parts(h->cy, passes->p[passes->n].part);
        passes->p[passes->n++].estimate = e;
    }
    /* the estimate as reported ("%.6f") against the bound */
    if (h->mode != FS_CYCLE_SAMPLED || cfg->sampling_max_error <= 0 ||
        llround(e * 1e6) <= cfg->sampling_max_error * 100 || passes->n >= FS_CLI_MAX_PASSES)
        return false;
    return fs_cycle_config_denser(h->cy, cfg);
}

int fs_cli_max_error_set(const char *percent, char *buf, size_t len)
{
    char *end;
    double p = strtod(percent, &end);
    if (end == percent || *end || !(p >= 0.0 && p <= 100.0))
        return -1;
    snprintf(buf, len, "sampling.max_error=%ld", (long)llround(p * 100.0));
    return 0;
}

int fs_cli_cycle_json(fs_cli_cycle *h, json_t *into)
{
    fs_cycle_finish(h->cy);
    json_t *frames = json_array();
    /* Frames sampled mode skipped: their interpolated cycles. */
    for (size_t i = 0; i < h->nframes; i++) {
        bool skipped;
        uint64_t cyc = fs_cycle_frame_cycles(h->cy, h->frames[i].frame, &skipped);
        if (skipped) {
            memset(&h->frames[i].s, 0, sizeof h->frames[i].s);
            h->frames[i].s.cycles = h->frames[i].s.estimated_cycles = cyc;
        }
        if (h->csv)
            csv_row(h->csv, "frame", h->frames[i].frame, h->frames[i].frame, 0, 0, skipped, &h->frames[i].s);
        json_array_append_new(frames, with_stats(json_pack("{s:I}", "frame", (json_int_t)h->frames[i].frame),
                                                 &h->frames[i].s));
    }
    fs_cycle_stats t;
    double error_estimate = fs_cli_cycle_totals(h, &t);
    if (h->csv) {
        csv_row(h->csv, "total", 0, 0, 0, 0, false, &t);
        fflush(h->csv);
    }
    /* error_estimate: the value "%.6f" printed (see cli_main.c, fs_json_fixed) */
    char e[32];
    snprintf(e, sizeof e, "%.6f", error_estimate);
    json_t *cycle = json_pack("{s:s, s:b, s:f, s:o, s:o, s:O, s:O}", "mode",
                              h->mode == FS_CYCLE_SAMPLED ? "sampled" : "cycle", "too_short_to_sample",
                              fs_cycle_too_short(h->cy), "error_estimate", strtod(e, NULL),
                              "totals", with_stats(json_object(), &t), "frames", frames, "queries", h->queries_json,
                              "draws", h->draws_json);
    if (cycle && h->mode == FS_CYCLE_SAMPLED && json_object_set_new(cycle, "max_error", passes_json(h, error_estimate)) != 0) {
        json_decref(cycle);
        cycle = NULL;
    }
    /* With a clock the totals in seconds and frames per second too (the
     * dissertation's tables are in seconds and fps, 3.1.9). */
    if (cycle && h->clock_khz > 0) {
        double sec = (double)t.cycles / ((double)h->clock_khz * 1000.0);
        json_object_set_new(cycle, "clock_khz", json_integer(h->clock_khz));
        json_object_set_new(cycle, "seconds", json_real(sec));
        json_object_set_new(cycle, "frames_per_second",
                            json_real(sec > 0 && h->nframes ? (double)h->nframes / sec : 0.0));
    }
    return json_object_set_new(into, "cycle", cycle);
}

double fs_cli_cycle_totals(fs_cli_cycle *h, fs_cycle_stats *t)
{
    fs_cycle_finish(h->cy);
    fs_cycle_totals(h->cy, t);
    return fs_cycle_error_estimate(h->cy);
}

void fs_cli_cycle_summary(fs_cli_cycle *h, FILE *f, double seconds)
{
    fs_cycle_stats t;
    double error_estimate = fs_cli_cycle_totals(h, &t);
    fprintf(f, "fragsim: %s mode: %llu cycles (%llu estimated, error estimate %.2f%%), %.1f M cycles/s\n",
            h->mode == FS_CYCLE_SAMPLED ? "sampled" : "cycle", (unsigned long long)t.cycles,
            (unsigned long long)t.estimated_cycles, 100.0 * error_estimate,
            seconds > 0 ? (double)t.cycles / seconds / 1e6 : 0.0);
    const fs_cli_passes *ps = h->passes;
    if (ps && ps->n > 1)
        fprintf(f, "fragsim: sampled mode: --max-error %.2f%%: %d passes, estimates", h->max_error / 100.0, ps->n);
    for (int i = 0; ps && ps->n > 1 && i < ps->n; i++)
        fprintf(f, " %.2f%%%s", 100.0 * ps->p[i].estimate, i + 1 < ps->n ? "," : "\n");
    if (gave_up(ps))
        fprintf(f, "fragsim: sampled mode: cannot meet --max-error %.2f%% by sampling: simulated in full\n",
                h->max_error / 100.0);
    else if (h->max_error > 0 && llround(error_estimate * 1e6) > h->max_error * 100)
        fprintf(f, "fragsim: sampled mode: cannot meet --max-error %.2f%%: the estimate stays above it after %d passes\n",
                h->max_error / 100.0, ps ? ps->n : 1);
    if (fs_cycle_too_short(h->cy))
        fprintf(f, "fragsim: sampled mode: %zu frames are too few to sample (6 or more, or 1 or 2) with an error "
                   "estimate: simulated in full\n", h->nframes);
    if (h->clock_khz > 0) {
        double sec = (double)t.cycles / ((double)h->clock_khz * 1000.0);
        fprintf(f, "fragsim: at %.3f MHz: %.6f s simulated, %zu frame%s, %.2f frames/s\n", h->clock_khz / 1000.0, sec,
                h->nframes, h->nframes == 1 ? "" : "s", sec > 0 ? (double)h->nframes / sec : 0.0);
    }
}

fs_cycle *fs_cli_cycle_model(fs_cli_cycle *h) { return h->cy; }

void fs_cli_cycle_end(fs_cli_cycle *h)
{
    if (!h)
        return;
    if (h->csv)
        fclose(h->csv);
    json_decref(h->draws_json);
    json_decref(h->queries_json);
    fs_cycle_destroy(h->cy);
    free(h->frames);
    free(h);
}
