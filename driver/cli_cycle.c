/*
 * The cycle-level model on the command line: `fragsim replay --mode
 * functional|cycle|sampled [--csv FILE]` (cli_main.c parses the options and
 * calls these at the run's start, each frame end and the statistics write).
 * Statistics per frame, per draw and per occlusion query go to the JSON
 * statistics file ("cycle" object) and, with --csv, to one CSV row each.
 */
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "../pipeline/context.h"

struct fs_cli_cycle {
    fs_cycle *cy;
    fs_cycle_mode mode;
    FILE *csv;
    FILE *draws_json;    /* draw and query records, JSON lines, copied at the end */
    FILE *queries_json;
    uint64_t ndraws, nqueries;
    struct { uint64_t frame; fs_cycle_stats s; } *frames;
    size_t nframes, cap;
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

static void on_record(void *user, const fs_cycle_record *r)
{
    fs_cli_cycle *h = user;
    bool draw = r->kind == FS_CYCLE_DRAW;
    FILE *j = draw ? h->draws_json : h->queries_json;
    uint64_t *n = draw ? &h->ndraws : &h->nqueries;
    if (j) {
        fprintf(j, "%s\n      {\"index\": %llu, \"frame\": %llu, \"%s\": %u, ", *n ? "," : "",
                (unsigned long long)r->index, (unsigned long long)r->frame, draw ? "mode" : "query", r->id);
        if (draw)
            fprintf(j, "\"vertices\": %llu, \"estimated\": %s, ", (unsigned long long)r->vertices,
                    r->estimated ? "true" : "false");
        fs_cycle_stats_write_json(j, &r->s);
        fputc('}', j);
    }
    (*n)++;
    if (h->csv)
        csv_row(h->csv, draw ? "draw" : "query", r->index, r->frame, r->id, r->vertices, r->estimated, &r->s);
}

bool fs_cli_cycle_skip(const fs_cli_cycle *h, const fs_context *c, int cmd)
{
    return h && fs_cycle_skip_call(h->cy, c, cmd);
}

fs_cli_cycle *fs_cli_cycle_begin(int mode, const fs_config *cfg, fs_context *c, const char *csv_path,
                                 uint64_t trace_frames, bool draw_stats, char *err, size_t errlen)
{
    fs_cli_cycle *h = calloc(1, sizeof *h);
    if (!h) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    h->mode = (fs_cycle_mode)mode;
    h->cy = fs_cycle_create(cfg, h->mode, err, errlen);
    if (!h->cy) {
        free(h);
        return NULL;
    }
    h->draws_json = tmpfile();
    h->queries_json = tmpfile();
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
    fs_cycle_set_frames(h->cy, trace_frames);
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

static void copy_file(FILE *from, FILE *to)
{
    char buf[65536];
    size_t n;
    if (!from)
        return;
    rewind(from);
    while ((n = fread(buf, 1, sizeof buf, from)) > 0)
        fwrite(buf, 1, n, to);
}

void fs_cli_cycle_write_json(fs_cli_cycle *h, FILE *f)
{
    fs_cycle_finish(h->cy);
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
    }
    fs_cycle_stats t;
    fs_cycle_totals(h->cy, &t);
    fprintf(f, "  \"cycle\": {\n    \"mode\": \"%s\",\n    \"error_estimate\": %.6f,\n    \"totals\": {",
            h->mode == FS_CYCLE_SAMPLED ? "sampled" : "cycle", fs_cycle_error_estimate(h->cy));
    fs_cycle_stats_write_json(f, &t);
    fprintf(f, "},\n    \"frames\": [");
    for (size_t i = 0; i < h->nframes; i++) {
        fprintf(f, "%s\n      {\"frame\": %llu, ", i ? "," : "", (unsigned long long)h->frames[i].frame);
        fs_cycle_stats_write_json(f, &h->frames[i].s);
        fputc('}', f);
    }
    fprintf(f, "%s],\n    \"queries\": [", h->nframes ? "\n    " : "");
    copy_file(h->queries_json, f);
    fprintf(f, "%s],\n    \"draws\": [", h->nqueries ? "\n    " : "");
    copy_file(h->draws_json, f);
    fprintf(f, "%s]\n  },\n", h->ndraws ? "\n    " : "");
    if (h->csv) {
        csv_row(h->csv, "total", 0, 0, 0, 0, false, &t);
        fflush(h->csv);
    }
}

void fs_cli_cycle_summary(fs_cli_cycle *h, FILE *f, double seconds)
{
    fs_cycle_finish(h->cy);
    fs_cycle_stats t;
    fs_cycle_totals(h->cy, &t);
    fprintf(f, "fragsim: %s mode: %llu cycles (%llu estimated, error estimate %.2f%%), %.1f M cycles/s\n",
            h->mode == FS_CYCLE_SAMPLED ? "sampled" : "cycle", (unsigned long long)t.cycles,
            (unsigned long long)t.estimated_cycles, 100.0 * fs_cycle_error_estimate(h->cy),
            seconds > 0 ? (double)t.cycles / seconds / 1e6 : 0.0);
}

void fs_cli_cycle_end(fs_cli_cycle *h)
{
    if (!h)
        return;
    if (h->csv)
        fclose(h->csv);
    if (h->draws_json)
        fclose(h->draws_json);
    if (h->queries_json)
        fclose(h->queries_json);
    fs_cycle_destroy(h->cy);
    free(h->frames);
    free(h);
}
