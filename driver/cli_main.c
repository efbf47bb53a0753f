/*
 * The fragsim command line: replay, check, diff, config, stats.
 * Every subcommand answers --help.  Errors are one line on stderr and a
 * non-zero exit; statistics are still written when a run fails part-way.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "../pipeline/context.h"
#include "image.h"
#include "../rtl_model/cycle_signals.h"
#include "osmesa_ref.h"
#include "cli.h"
#include "replay.h"
#include "callset.h"
#include "error_log.h"
#include "json_text.h"
#include "run_config.h"

/* Exact by default: fragsim must render as llvmpipe does; pixels off by
 * exactly 1 are reported apart ("within 1") so that a rounding difference is
 * told from a real one, but they fail the check unless --tolerance 1. */
#define DEFAULT_TOLERANCE 0

typedef struct cli_opts {
    const char *config_file;
    const char *sets[32];
    int nsets;
    char max_error_set[48];   /* --max-error P as the --set of sampling.max_error */
    long frame_first, frame_last; /* inclusive; last -1 = to the end */
    const char *frame_end;
    int width, height;
    const char *out_dir;
    const char *stats_file;
    const char *trace;
    int tolerance;
    bool quiet;
    int mode;                 /* -1 functional, else fs_cycle_mode (--mode) */
    const char *csv_file;     /* --csv: cycle statistics as CSV */
    bool draw_stats;          /* --draw-stats: cycle statistics per draw too */
    fs_cli_cycle *cycle;      /* the cycle model of the run, NULL in functional mode */
    const fs_cycle_config *cycle_pass; /* sampled mode's pass after the first (--max-error), or NULL */
    /* --snapshot CALLSET / --snapshot-prefix P: glretrace's snapshots,
     * P%010u.png after each call of the set (callset.h). */
    fs_callset snaps;
    bool snapshot;
    const char *snapshot_prefix;
    bool snapshot_alpha;
    fs_trace_parser parser;   /* --reader */
    long threads;             /* --threads: raster.threads before --config and --set (0: the CPUs) */
    fs_cli_signal_opts sig;   /* --vcd, --gpio and their options (cli_signals.c) */
} cli_opts;

#define THREADS_HELP                                                                      \
    "  --threads N        threads rasterizing large filled draws in functional mode (default\n" \
    "                     0: the online CPUs, at most 8; 1: one thread); the same images and\n" \
    "                     statistics for any N.  Cycle and sampled mode run on one thread\n"   \
    "                     (the cycle observer is not thread safe); raster.threads overrides\n"

static const char *prog = "fragsim";

static void usage_replay(FILE *f, bool check)
{
    fprintf(f,
            "usage: fragsim %s [options] TRACE\n"
            "\n"
            "%s"
            "options:\n"
            "  --config FILE      INI configuration (see `fragsim config --list`)\n"
            "  --set SEC.KEY=VAL  override one configuration key (repeatable)\n"
            "  --frames A-B       frames to output (first frame is 0; A, A-, -B also work)\n"
            "  --frame-end CALL   call that ends a frame (default: swap calls, else glFinish)\n"
            "  --size WxH         window size (default: from the first glViewport)\n"
            "  --out DIR          output directory (default: out)\n"
            "  --stats FILE       statistics JSON (default: DIR/%s.json)\n"
            "%s"
            "  --mode M           functional (default), cycle (the cycle-level model, rtl_model/:\n"
            "                     cycles per frame, draw and query; same images and counters) or\n"
            "                     sampled (one frame in sampling.frames simulated, the frames\n"
            "                     between skipped and their cycles interpolated; 1-2 frame traces:\n"
            "                     one screen tile in sampling.tiles rasterized and timed, the\n"
            "                     others estimated from triangle areas).  Skipped work is NOT\n"
            "                     rendered: images and functional counters are incomplete;\n"
            "                     cycles come with an error estimate (docs/cycle_model.md)\n"
            "  --max-error P      sampled mode: the largest error estimate accepted, in percent\n"
            "                     (sampling.max_error; default 2): above it the trace is replayed\n"
            "                     with denser sampling, or in full (the run says so); 0: one pass\n"
            "  --csv FILE         cycle statistics, one row per frame and query (with --mode)\n"
            "  --draw-stats       cycle statistics per draw too (JSON and CSV; large for big traces)\n"
            "  --snapshot CALLSET write the colour buffer after each call of CALLSET (glretrace's\n"
            "                     call sets: frame, draw, N, A-B, A-B/S, A-B/draw, *, lists with\n"
            "                     commas; numbers as `apitrace dump` prints them) to\n"
            "                     DIR/NNNNNNNNNN.png (the call number, 10 digits), RGB, top row first\n"
            "  --snapshot-prefix P  snapshot file names start with P (default DIR/; a prefix\n"
            "                     alone snapshots every frame, as glretrace does)\n"
            "  --snapshot-alpha   snapshots with alpha (RGBA, unassociated)\n"
            "  --reader R         the trace reader's parser: fast (default) or general (the\n"
            "                     reference the fast one is held equal to; slower)\n"
            THREADS_HELP
            "  --quiet            no progress line\n"
            "GL errors are printed as glretrace prints them (N: warning: glGetError(glName) = ERR;\n"
            "the first 10) and listed with call number, command and error in the statistics file.\n",
            check ? "check" : "replay",
            check ? "Replays TRACE on the model and on OSMesa (llvmpipe, in this process) and\n"
                    "reports per frame: pixels whose colour differs, the largest channel\n"
                    "difference, PSNR and pixels whose depth differs.  Exit status 0 only when\n"
                    "every frame's largest colour difference is within the tolerance (3 when\n"
                    "not); for such frames DIR gets model_N.png, osmesa_N.png and diff_N.png.\n"
                    "Pixels off by exactly 1 in their largest channel are counted apart (\"by 1\")\n"
                    "from those off by more.\n\n"
                  : "Replays TRACE on the model; writes DIR/frame_NNNN.png per frame and a JSON\n"
                    "statistics file (per frame counters, unsupported calls by name).\n\n",
            check ? "check" : "stats",
            check ? "  --tolerance N      largest allowed colour difference per channel (default 0)\n" : "");
    fs_cli_signals_usage(f);
}

/* --threads N: 0..8; -1 (printed) for anything else. */
static int parse_threads(const char *v, long *threads)
{
    char *end;
    long n = v ? strtol(v, &end, 10) : -1;
    if (!v || !*v || *end || n < 0 || n > 8) {
        fprintf(stderr, "%s: --threads '%s': expected 0 (the CPUs) to 8\n", prog, v ? v : "");
        return -1;
    }
    *threads = n;
    return 0;
}

/* --reader fast|general; -1 (printed) for anything else. */
static int parse_reader(const char *v, fs_trace_parser *parser)
{
    if (!strcmp(v, "fast"))
        *parser = FS_TRACE_PARSER_FAST;
    else if (!strcmp(v, "general"))
        *parser = FS_TRACE_PARSER_GENERAL;
    else {
        fprintf(stderr, "%s: --reader '%s': expected fast or general\n", prog, v);
        return -1;
    }
    return 0;
}

/* Returns 0, 1 when --help was printed, -1 on a usage error. */
static int parse_opts(int argc, char **argv, cli_opts *o, bool check)
{
    memset(o, 0, sizeof *o);
    o->frame_last = -1;
    o->out_dir = "out";
    o->tolerance = DEFAULT_TOLERANCE;
    o->mode = -1;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        int taken;
#define NEEDV()                                                              \
    do {                                                                     \
        if (!v) {                                                            \
            fprintf(stderr, "%s: %s needs a value\n", prog, a);              \
            return -1;                                                       \
        }                                                                    \
        i++;                                                                 \
    } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage_replay(stdout, check);
            return 1;
        } else if (!strcmp(a, "--config")) {
            NEEDV();
            o->config_file = v;
        } else if (!strcmp(a, "--set")) {
            NEEDV();
            if (o->nsets == 32) {
                fprintf(stderr, "%s: too many --set options\n", prog);
                return -1;
            }
            o->sets[o->nsets++] = v;
        } else if (!strcmp(a, "--max-error")) {
            NEEDV();
            if (o->nsets == 32 || fs_cli_max_error_set(v, o->max_error_set, sizeof o->max_error_set) != 0) {
                fprintf(stderr, "%s: --max-error '%s': expected a percentage from 0 to 100\n", prog, v);
                return -1;
            }
            o->sets[o->nsets++] = o->max_error_set;
        } else if (!strcmp(a, "--frames")) {
            NEEDV();
            if (fs_cli_parse_frames(v, &o->frame_first, &o->frame_last) != 0) {
                fprintf(stderr, "%s: --frames '%s': expected A-B, A, A- or -B with A <= B\n", prog, v);
                return -1;
            }
        } else if (!strcmp(a, "--frame-end")) {
            NEEDV();
            o->frame_end = v;
        } else if (!strcmp(a, "--size")) {
            NEEDV();
            char *end;
            long w = strtol(v, &end, 10), h = 0;
            if (*end == 'x')
                h = strtol(end + 1, &end, 10);
            if (*end || w <= 0 || h <= 0 || w > 16384 || h > 16384) {
                fprintf(stderr, "%s: --size '%s': expected WxH, each 1..16384\n", prog, v);
                return -1;
            }
            o->width = (int)w;
            o->height = (int)h;
        } else if (!strcmp(a, "--out")) {
            NEEDV();
            o->out_dir = v;
        } else if (!strcmp(a, "--stats")) {
            NEEDV();
            o->stats_file = v;
        } else if (check && !strcmp(a, "--tolerance")) {
            NEEDV();
            char *end;
            long t = strtol(v, &end, 10);
            if (*end || t < 0 || t > 255) {
                fprintf(stderr, "%s: --tolerance '%s': expected 0..255\n", prog, v);
                return -1;
            }
            o->tolerance = (int)t;
        } else if (!strcmp(a, "--mode")) {
            NEEDV();
            if (fs_cli_cycle_mode(v, &o->mode) != 0) {
                fprintf(stderr, "%s: --mode '%s': expected functional, cycle or sampled\n", prog, v);
                return -1;
            }
        } else if (!strcmp(a, "--csv")) {
            NEEDV();
            o->csv_file = v;
        } else if (!strcmp(a, "--draw-stats")) {
            o->draw_stats = true;
        } else if (!strcmp(a, "--quiet")) {
            o->quiet = true;
        } else if (!strcmp(a, "--snapshot")) {
            NEEDV();
            char cerr[512];
            if (fs_callset_parse(&o->snaps, v, cerr, sizeof cerr) != 0) {
                fprintf(stderr, "%s: --snapshot: %s\n", prog, cerr);
                fs_callset_free(&o->snaps);
                return -1;
            }
            o->snapshot = true;
        } else if (!strcmp(a, "--snapshot-prefix")) {
            NEEDV();
            o->snapshot_prefix = v;
        } else if (!strcmp(a, "--snapshot-alpha")) {
            o->snapshot_alpha = true;
        } else if (!strcmp(a, "--reader")) {
            NEEDV();
            if (parse_reader(v, &o->parser) != 0)
                return -1;
        } else if (!strcmp(a, "--threads")) {
            NEEDV();
            if (parse_threads(v, &o->threads) != 0)
                return -1;
        } else if ((taken = fs_cli_signals_option(&o->sig, a, v)) != 0) {
            if (taken < 0)
                return -1;
            i++;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "%s: unknown option %s (see --help)\n", prog, a);
            return -1;
        } else if (!o->trace) {
            o->trace = a;
        } else {
            fprintf(stderr, "%s: more than one trace given (%s, %s)\n", prog, o->trace, a);
            return -1;
        }
#undef NEEDV
    }
    if (!o->trace) {
        fprintf(stderr, "%s: no trace given (see --help)\n", prog);
        fs_callset_free(&o->snaps);
        return -1;
    }
    if (o->snapshot_prefix && !o->snapshot) {
        /* glretrace: a prefix without a call set snapshots every frame */
        char cerr[512];
        fs_callset_parse(&o->snaps, "frame", cerr, sizeof cerr);
        o->snapshot = true;
    }
    return 0;
}

/* glretrace's snapshot (retrace_main.cpp takeSnapshot): PREFIX%010u.png,
 * named by the call number, after the call executed. */
static int take_snapshot(const cli_opts *o, const fs_context *c, uint64_t call_no, char *err, size_t errlen)
{
    char path[4200];
    if (o->snapshot_prefix)
        snprintf(path, sizeof path, "%s%010llu.png", o->snapshot_prefix, (unsigned long long)call_no);
    else
        snprintf(path, sizeof path, "%s/%010llu.png", o->out_dir, (unsigned long long)call_no);
    return fs_image_write_png_channels(path, c->fb.color, c->fb.width, c->fb.height,
                                       o->snapshot_alpha ? 4 : 3, err, errlen);
}

static int make_dir(const char *dir)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

typedef struct frame_record {
    long frame;
    fs_stats stats;
    fs_image_diff diff;
    bool has_diff;
    bool within;
    int64_t samples_ref; /* OSMesa's GL_SAMPLES_PASSED for the frame, -1 if not measured */
} frame_record;

/*
 * The statistics file is written with jansson.  Its reals were printed
 * with a fixed number of decimals ("%.3f", "%.6f"); they are still rounded
 * so (fixed_real) and written with 15 significant digits, which gives back
 * that decimal text less trailing zeros, and reads back as the same double
 * as the old text did.
 */
#define JSON_FLAGS (JSON_INDENT(2) | JSON_REAL_PRECISION(15))

static json_t *fixed_real(double v, int decimals)
{
    char t[64];
    snprintf(t, sizeof t, "%.*f", decimals, v);
    return json_real(strtod(t, NULL));
}

/* Calls and features not executed, by name: {"glName": count, ...}. */
static json_t *unsupported_json(const fs_context *c)
{
    json_t *o = json_object();
    int rc = 0;
    for (int i = 0; i < FS_CMD_COUNT; i++)
        if (fs_cmd_unsupported(c, i))
            rc |= json_object_set_new(o, fs_cmd_table[i].name, json_integer((json_int_t)fs_cmd_unsupported(c, i)));
    for (int i = 0; i < c->unsupported_feature_count; i++)
        rc |= json_object_set_new(o, c->unsupported_feature[i].name,
                                  json_integer((json_int_t)c->unsupported_feature[i].count));
    if (rc) {
        json_decref(o);
        return NULL;
    }
    return o;
}

/* One frame of the statistics file; check's comparison with OSMesa too. */
static json_t *frame_json(const frame_record *fr, bool check)
{
    char image[64];
    snprintf(image, sizeof image, "frame_%04ld.png", fr->frame);
    json_t *o = json_pack("{s:I}", "frame", (json_int_t)fr->frame);
    int rc = !o || (!check && json_object_set_new(o, "image", json_string(image)) != 0);
    if (!rc && fr->has_diff) {
        const fs_image_diff *d = &fr->diff;
        json_t *psnr = isinf(d->psnr) ? json_string("999.000 (identical)") : fixed_real(d->psnr, 3);
        rc = json_object_update_new(o, json_pack("{s:I, s:I, s:I, s:i, s:o, s:I, s:I, s:b}", "pixels_differ",
                                                 (json_int_t)d->pixels_differ, "pixels_within_1",
                                                 (json_int_t)d->pixels_within_1, "pixels_beyond_1",
                                                 (json_int_t)d->pixels_beyond_1, "max_color_diff", d->max_diff,
                                                 "psnr_db", psnr, "depth_differ", (json_int_t)d->depth_differ,
                                                 "samples_passed_osmesa", (json_int_t)fr->samples_ref,
                                                 "within_tolerance", fr->within)) != 0;
    }
    if (!rc)
        rc = json_object_set_new(o, "stats", fs_stats_json(&fr->stats)) != 0;
    if (rc) {
        json_decref(o);
        return NULL;
    }
    return o;
}

static int write_stats(const char *path, const cli_opts *o, const fs_run_config *cfg, const fs_replay_info *info,
                       const fs_context *c, const fs_replayer *r, const frame_record *frames,
                       size_t nframes, bool check, const char *status, const fs_error_log *errs)
{
    json_t *list = json_array();
    fs_stats total;
    memset(&total, 0, sizeof total);
    int rc = !list;
    for (size_t i = 0; i < nframes && !rc; i++) {
        fs_stats_add(&total, &frames[i].stats);
        rc = json_array_append_new(list, frame_json(&frames[i], check)) != 0;
    }
    json_t *doc = json_pack("{s:o, s:s, s:[i, i], s:o, s:I, s:o, s:o, s:o, s:o}", "trace", fs_json_text(o->trace),
                            "status", status, "size", info->width, info->height, "frame_end",
                            fs_json_text(info->frame_end), "trace_calls", (json_int_t)info->calls, "frames", list,
                            "totals", fs_stats_json(&total), "unsupported", unsupported_json(c),
                            "skipped_trace_calls", fs_replay_skipped_json(r));
    /* Every GL error with the call that raised it (numbered as apitrace
     * dump numbers calls; an error inside a display list is its glCallList's). */
    rc |= !doc || fs_error_log_json(errs, doc) != 0 || (o->cycle && fs_cli_cycle_json(o->cycle, doc) != 0);
    /* The effective configuration, so any run can be reproduced. */
    rc |= !doc || json_object_set_new(doc, "config", fs_run_config_json(cfg)) != 0;
    if (rc) {
        fprintf(stderr, "%s: out of memory writing %s\n", prog, path);
        json_decref(doc);
        return -1;
    }
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "%s: cannot write %s: %s\n", prog, path, strerror(errno));
        json_decref(doc);
        return -1;
    }
    rc = json_dumpf(doc, f, JSON_FLAGS) != 0 || fputc('\n', f) == EOF;
    json_decref(doc);
    if (fclose(f) != 0 || rc) {
        fprintf(stderr, "%s: error writing %s\n", prog, path);
        return -1;
    }
    return 0;
}

static void print_unsupported(FILE *f, const fs_context *c, const fs_replayer *r)
{
    bool any = fs_replay_skipped_total(r) > 0 || c->unsupported_feature_count > 0;
    for (int i = 0; i < FS_CMD_COUNT && !any; i++)
        any = fs_cmd_unsupported(c, i) != 0;
    if (!any)
        return;
    fprintf(f, "%s: calls not executed or not fully modelled:\n", prog);
    for (int i = 0; i < FS_CMD_COUNT; i++)
        if (fs_cmd_unsupported(c, i))
            fprintf(f, "  %-48s %10llu  (not implemented)\n", fs_cmd_table[i].name,
                    (unsigned long long)fs_cmd_unsupported(c, i));
    for (int i = 0; i < c->unsupported_feature_count; i++)
        fprintf(f, "  %-48s %10llu  (not modelled)\n", c->unsupported_feature[i].name,
                (unsigned long long)c->unsupported_feature[i].count);
    fs_replay_print_skipped(r, f);
}

/* For a frame beyond tolerance, writes the model's image, OSMesa's and a
 * difference image (differing pixels white on black, scaled by 8) so the
 * user can see where they disagree. */
static int save_mismatch(const char *dir, long frame, const uint8_t *model, const uint8_t *ref, int w, int h)
{
    char path[4200], err[512];
    size_t n = (size_t)w * (size_t)h;
    uint8_t *d = malloc(n * 4);
    if (!d)
        return -1;
    for (size_t i = 0; i < n; i++) {
        int m = 0;
        for (int ch = 0; ch < 4; ch++) {
            int x = abs((int)model[4 * i + ch] - (int)ref[4 * i + ch]);
            if (x > m)
                m = x;
        }
        int v = m * 8 > 255 ? 255 : m * 8;
        d[4 * i] = d[4 * i + 1] = d[4 * i + 2] = (uint8_t)v;
        d[4 * i + 3] = 255;
    }
    int rc = 0;
    snprintf(path, sizeof path, "%s/model_%04ld.png", dir, frame);
    rc |= fs_image_write_png(path, model, w, h, err, sizeof err);
    snprintf(path, sizeof path, "%s/osmesa_%04ld.png", dir, frame);
    rc |= fs_image_write_png(path, ref, w, h, err, sizeof err);
    snprintf(path, sizeof path, "%s/diff_%04ld.png", dir, frame);
    rc |= fs_image_write_png(path, d, w, h, err, sizeof err);
    free(d);
    return rc ? -1 : 0;
}

/*
 * The one replay loop of replay, check and bench (bench's floor too): each
 * call of the trace goes to the model, to OSMesa, to both or to neither,
 * and frames end where the replayer says.  The commands differ only in
 * these options and in what they do after a call and at a frame end.
 */
typedef struct replay_loop replay_loop;
struct replay_loop {
    fs_replayer *r;
    fs_context *model;       /* executes the calls, or NULL */
    fs_osmesa *ref;          /* executes them too (check) or alone (bench on OSMesa), or NULL */
    fs_cli_cycle *cycle;     /* --mode: its frames end here, sampled mode skips calls; or NULL */
    fs_error_log *errs;      /* told each call's number and name before it runs, or NULL */
    const char *trace;       /* for messages */
    long frame_first, frame_last; /* frames given to at_frame; the run stops after frame_last (-1: none) */
    bool reset_stats;        /* the model's counters start from 0 at each frame */
    bool progress;           /* a progress line on stderr */
    /* After each call executed or skipped; non-zero stops the run (the
     * callback printed why).  NULL: nothing. */
    int (*after_call)(replay_loop *L, uint64_t call_no, unsigned flags);
    /* At the end of each frame from frame_first on; non-zero stops the run. */
    int (*at_frame)(replay_loop *L, long frame);
    void *user;
    uint64_t frames;         /* out: frames ended */
};

/* 0 at the end of the trace or of the frame range; 1 when the run stopped
 * on an error (printed). */
static int replay_loop_run(replay_loop *L)
{
    uint64_t trace_frames = fs_replay_info_get(L->r)->frames;
    double t0 = now_seconds(), last_progress = t0;
    long frame = 0;
    fs_call call;
    int rc = 0;
    for (;;) {
        if (L->frame_last >= 0 && frame > L->frame_last)
            break;
        fs_replay_event ev = fs_replay_next(L->r, &call);
        if (ev == FS_REPLAY_ERROR) {
            fprintf(stderr, "%s: %s\n", prog, fs_replay_error(L->r));
            rc = 1;
            break;
        }
        if (ev == FS_REPLAY_EOF)
            break;
        if (ev != FS_REPLAY_FRAME_END) {
            /* sampled mode skips the calls of a frame that is interpolated */
            bool skip = ev == FS_REPLAY_SKIPPED || (L->model && fs_cli_cycle_skip(L->cycle, L->model, call.cmd));
            uint64_t no = fs_replay_call_no(L->r);
            if (L->errs) {
                L->errs->call = no;
                L->errs->command = fs_replay_call_name(L->r);
            }
            if (!skip && L->model && fs_submit(L->model, &call) != 0) {
                fprintf(stderr, "%s: %s: malformed arguments to %s\n", prog, L->trace,
                        fs_cmd_table[call.cmd].name);
                rc = 1;
                break;
            }
            if (!skip && L->ref)
                fs_osmesa_dispatch(L->ref, &call);
            if (L->after_call && (rc = L->after_call(L, no, fs_replay_call_flags(L->r))) != 0)
                break;
            continue;
        }
        if (frame >= L->frame_first) {
            if (L->cycle)
                fs_cli_cycle_frame(L->cycle, frame);
            if (L->at_frame && (rc = L->at_frame(L, frame)) != 0)
                break;
        }
        if (L->reset_stats)
            memset(&L->model->stats, 0, sizeof L->model->stats);
        frame++;
        L->frames++;
        double t = now_seconds();
        if (L->progress && t - last_progress > 0.5) {
            fprintf(stderr, "\rframe %ld/%llu  %.1f s", frame, (unsigned long long)trace_frames, t - t0);
            last_progress = t;
        }
    }
    if (L->progress)
        fprintf(stderr, "\r%60s\r", "");
    return rc;
}

/* What replay and check keep of a run for the statistics file and the
 * closing line (replay_loop.user). */
typedef struct replay_run {
    const cli_opts *o;
    const fs_replay_info *info;
    bool count_samples;      /* OSMesa counts each frame's samples passed (check) */
    frame_record *frames;    /* the frames in the range */
    size_t nframes, cap;
    bool all_within;
    size_t frames_exact, frames_within_1, frames_beyond_1;
    uint64_t pixels_by_1;
    uint64_t snapshots;
} replay_run;

static int snapshot_after_call(replay_loop *L, uint64_t call_no, unsigned flags)
{
    replay_run *run = L->user;
    char err[1024];
    if (!fs_callset_contains(&run->o->snaps, call_no, flags))
        return 0;
    if (take_snapshot(run->o, L->model, call_no, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    run->snapshots++;
    return 0;
}

/* The frame's record, with the model's counters of the frame; NULL when out
 * of memory (printed). */
static frame_record *new_frame(replay_loop *L, long frame)
{
    replay_run *run = L->user;
    if (run->nframes == run->cap) {
        frame_record *nf = realloc(run->frames, 2 * run->cap * sizeof *run->frames);
        if (!nf) {
            fprintf(stderr, "%s: out of memory\n", prog);
            return NULL;
        }
        run->frames = nf;
        run->cap *= 2;
    }
    frame_record *fr = &run->frames[run->nframes++];
    memset(fr, 0, sizeof *fr);
    fr->frame = frame;
    fr->stats = L->model->stats;
    return fr;
}

/* replay: the frame's image as DIR/frame_NNNN.png */
static int write_frame(replay_loop *L, long frame)
{
    replay_run *run = L->user;
    char path[4200], err[1024];
    if (!new_frame(L, frame))
        return 1;
    snprintf(path, sizeof path, "%s/frame_%04ld.png", run->o->out_dir, frame);
    if (fs_image_write_png(path, L->model->fb.color, run->info->width, run->info->height, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    return 0;
}

/* check: the frame's colours, depths and samples passed against OSMesa's,
 * one line on stdout; images of the frame when beyond tolerance. */
static int check_frame(replay_loop *L, long frame)
{
    replay_run *run = L->user;
    const cli_opts *o = run->o;
    int w = run->info->width, h = run->info->height;
    fs_context *c = L->model;
    fs_osmesa *ref = L->ref;
    char err[64];
    frame_record *fr = new_frame(L, frame);
    if (!fr)
        return 1;
    fs_image_compare(c->fb.color, fs_osmesa_color(ref), w, h, &fr->diff);
    const uint32_t *d = fs_osmesa_depth(ref);
    if (d)
        fs_depth_compare(c->fb.depth, d, w, h, &fr->diff);
    fr->has_diff = true;
    fr->samples_ref = run->count_samples ? fs_osmesa_samples_end(ref) : -1;
    if (run->count_samples)
        fs_osmesa_samples_begin(ref);
    bool samples_ok = !run->count_samples || fr->samples_ref == (int64_t)fr->stats.fragments_passed_depth;
    fr->within = fr->diff.max_diff <= o->tolerance && samples_ok;
    run->all_within &= fr->within;
    run->frames_exact += fr->diff.max_diff == 0;
    run->frames_within_1 += fr->diff.max_diff == 1;
    run->frames_beyond_1 += fr->diff.max_diff > 1;
    run->pixels_by_1 += fr->diff.pixels_within_1;
    if (!fr->within && save_mismatch(o->out_dir, frame, c->fb.color, fs_osmesa_color(ref), w, h) != 0)
        fprintf(stderr, "%s: could not write the mismatch images to %s\n", prog, o->out_dir);
    char samples[96] = "";
    if (run->count_samples)
        snprintf(samples, sizeof samples, ", samples passed %llu%s%lld",
                 (unsigned long long)fr->stats.fragments_passed_depth,
                 samples_ok ? " = OSMesa " : " != OSMesa ", (long long)fr->samples_ref);
    printf("frame %4ld: %8llu pixels differ (%llu by 1, %llu by more), max diff %3d, PSNR %s, "
           "%llu depth values differ%s%s\n",
           frame, (unsigned long long)fr->diff.pixels_differ, (unsigned long long)fr->diff.pixels_within_1,
           (unsigned long long)fr->diff.pixels_beyond_1, fr->diff.max_diff,
           isinf(fr->diff.psnr) ? "identical" : (snprintf(err, sizeof err, "%.2f dB", fr->diff.psnr), err),
           (unsigned long long)fr->diff.depth_differ, samples, fr->within ? "" : "  <-- beyond tolerance");
    return 0;
}

/* The run configuration of replay and bench: defaults, the --config file,
 * the --set assignments, checked.  0, or -1 with the error printed. */
static int load_run_config(fs_run_config *cfg, const char *file, const char *const *sets, int nsets, long threads)
{
    char err[1024];
    fs_run_config_defaults(cfg);
    cfg->gl.raster_threads = threads;
    int bad = file && fs_run_config_load(cfg, file, err, sizeof err) != 0;
    for (int i = 0; !bad && i < nsets; i++)
        bad = fs_run_config_set(cfg, sets[i], err, sizeof err) != 0;
    if (bad || fs_run_config_check(cfg, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return -1;
    }
    return 0;
}

/* What a replay or check run holds open; replay_session_close releases
 * whatever of it was opened, in the reverse order. */
typedef struct replay_session {
    fs_run_config cfg;
    fs_replayer *r;
    const fs_replay_info *info;
    fs_context *c;
    fs_osmesa *ref;
    fs_cli_signals *sig;
    char stats_path[4096];
} replay_session;

static int replay_session_close(replay_session *S, cli_opts *o)
{
    char err[1024];
    int rc = 0;
    fs_cli_cycle_end(o->cycle); /* before the signals: its last edges go to them */
    o->cycle = NULL;
    if (S->sig && fs_cli_signals_close(S->sig, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        rc = -1;
    }
    fs_osmesa_destroy(S->ref);
    fs_context_destroy(S->c);
    fs_replay_close(S->r);
    memset(S, 0, sizeof *S);
    return rc;
}

/* The directory of the snapshot prefix (empty when it has none). */
static void snapshot_dir(const cli_opts *o, char *dir, size_t len)
{
    dir[0] = 0;
    const char *slash = o->snapshot_prefix ? strrchr(o->snapshot_prefix, '/') : NULL;
    if (slash)
        snprintf(dir, len, "%.*s", (int)(slash - o->snapshot_prefix), o->snapshot_prefix);
}

/* Opens everything a run needs, each error before anything is written.
 * Returns 0, or the exit status (the error printed; S is closed). */
static int replay_session_open(replay_session *S, cli_opts *o, bool check)
{
    char err[1024];
    memset(S, 0, sizeof *S);
    if (load_run_config(&S->cfg, o->config_file, o->sets, o->nsets, o->threads) != 0)
        return 2;
    if (o->cycle_pass)
        S->cfg.cycle = *o->cycle_pass;
    fs_replay_opts ro = {o->frame_end, o->width ? o->width : (int)S->cfg.gl.framebuffer_width,
                         o->height ? o->height : (int)S->cfg.gl.framebuffer_height};
    ro.report_skipped = o->snapshot; /* glretrace snapshots at calls fragsim skips too */
    ro.parser = o->parser;
    if (!(S->r = fs_replay_open(o->trace, &ro, err, sizeof err))) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    S->info = fs_replay_info_get(S->r);
    if (S->info->warning[0])
        fprintf(stderr, "%s: warning: %s\n", prog, S->info->warning);
    int rc = 0;
    if (!(S->c = fs_context_create(&S->cfg.gl, S->info->width, S->info->height))) {
        fprintf(stderr, "%s: cannot create a %dx%d context\n", prog, S->info->width, S->info->height);
        rc = 1;
        goto fail;
    }
    fs_context_set_double_buffered(S->c, S->info->double_buffered); /* as the captured context */
    if (check && !(S->ref = fs_osmesa_create(S->info->width, S->info->height, (int)S->cfg.gl.framebuffer_depth_bits,
                                             (int)S->cfg.gl.framebuffer_stencil_bits, err, sizeof err))) {
        fprintf(stderr, "%s: %s\n", prog, err);
        rc = 1;
        goto fail;
    }
    /* The signal options' errors (a missing GPIO chip, a line in use, an
     * unknown signal...) come before anything is written. */
    bool sig_failed;
    S->sig = fs_cli_signals_open(&o->sig, o->mode, o->trace, o->config_file, &sig_failed, err, sizeof err);
    if (sig_failed) {
        fprintf(stderr, "%s: %s\n", prog, err);
        rc = 2;
        goto fail;
    }
    char snap_dir[4096];
    snapshot_dir(o, snap_dir, sizeof snap_dir);
    if (make_dir(o->out_dir) != 0 || (snap_dir[0] && make_dir(snap_dir) != 0)) {
        fprintf(stderr, "%s: cannot create %s: %s\n", prog, snap_dir[0] ? snap_dir : o->out_dir, strerror(errno));
        rc = 1;
        goto fail;
    }
    if ((o->mode >= 0 && !(o->cycle = fs_cli_cycle_begin(o->mode, &S->cfg.cycle, S->c, o->csv_file, S->r,
                                                         o->draw_stats, err, sizeof err))) ||
        (S->sig && fs_cli_signals_attach(S->sig, o->cycle, err, sizeof err) != 0)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        rc = 2;
        goto fail;
    }
    if (o->stats_file)
        snprintf(S->stats_path, sizeof S->stats_path, "%s", o->stats_file);
    else
        snprintf(S->stats_path, sizeof S->stats_path, "%s/%s.json", o->out_dir, check ? "check" : "stats");
    return 0;
fail:
    replay_session_close(S, o);
    return rc;
}

/* What a finished run says on stderr (and, for check, on stdout). */
static void report_run(const replay_session *S, const cli_opts *o, const replay_run *run, const fs_error_log *errs,
                       bool check, int rc, double seconds)
{
    const fs_replay_info *info = S->info;
    size_t nframes = run->nframes;
    if (check && S->ref && nframes)
        printf("colour: %zu frame%s exact, %zu within 1 (%llu pixels off by 1), %zu off by more; tolerance %d\n",
               run->frames_exact, run->frames_exact == 1 ? "" : "s", run->frames_within_1,
               (unsigned long long)run->pixels_by_1, run->frames_beyond_1, o->tolerance);
    print_unsupported(stderr, S->c, S->r);
    fs_error_log_summary(errs, stderr, prog);
    if (o->snapshot)
        fprintf(stderr, "%s: %llu snapshot%s written\n", prog, (unsigned long long)run->snapshots,
                run->snapshots == 1 ? "" : "s");
    if (rc == 0 || rc == 3)
        fprintf(stderr, "%s: %zu frame%s (%dx%d) in %.2f s; %s%s; statistics in %s\n", prog, nframes,
                nframes == 1 ? "" : "s", info->width, info->height, seconds, check ? "compared with OSMesa" : "images in ",
                check ? "" : o->out_dir, S->stats_path);
    if (nframes == 0 && rc == 0)
        fprintf(stderr, "%s: warning: no frame in the selected range\n", prog);
    if (o->cycle)
        fs_cli_cycle_summary(o->cycle, stderr, seconds);
}

static int run_replay(int argc, char **argv, bool check)
{
    cli_opts o;
    int p = parse_opts(argc, argv, &o, check);
    if (p)
        return p > 0 ? 0 : 2;
    replay_session S;
    fs_cli_passes passes = {0};
    fs_cycle_config pass_cfg;
    double t0 = now_seconds();
pass:;
    int rc = replay_session_open(&S, &o, check);
    if (rc != 0) {
        fs_callset_free(&o.snaps);
        return rc;
    }
    replay_run run = {&o, S.info, S.ref && !S.info->uses_queries};
    run.cap = 16;
    run.frames = malloc(run.cap * sizeof *run.frames);
    run.all_within = true;
    const char *status = "ok";
    /* Per frame, OSMesa counts GL_SAMPLES_PASSED with a query of its own, to
     * compare with the fragments that passed the model's depth and stencil
     * tests (what NOHC and occlusion queries count).  A trace that runs its
     * own queries is left alone: a second active query would be an error. */
    if (run.count_samples)
        fs_osmesa_samples_begin(S.ref);
    fs_error_log errs = {0};
    errs.print = stderr;
    errs.print_max = 10;
    fs_error_log_attach(&errs, S.c);
    replay_loop loop = {S.r, S.c, S.ref, o.cycle, &errs, o.trace, o.frame_first, o.frame_last, true,
                        !o.quiet && isatty(2), o.snapshot ? snapshot_after_call : NULL,
                        check ? check_frame : write_frame, &run};
    if (!run.frames || replay_loop_run(&loop) != 0) {
        if (!run.frames)
            fprintf(stderr, "%s: out of memory\n", prog);
        status = "error";
        rc = 1;
    }
    /* sampling.max_error: a pass whose estimate is above it is replayed,
     * from a fresh session, with denser sampling (its images, CSV and
     * signals are written again); only the last pass writes statistics. */
    pass_cfg = S.cfg.cycle;
    if (rc == 0 && o.cycle && fs_cli_cycle_resample(o.cycle, &pass_cfg, &passes)) {
        fs_error_log_free(&errs);
        free(run.frames);
        S.c->error_hook = NULL;
        replay_session_close(&S, &o);
        o.cycle_pass = &pass_cfg;
        goto pass;
    }
    if (rc == 0 && check && !run.all_within) {
        status = "beyond tolerance";
        rc = 3;
    }
    S.c->error_hook = NULL;
    if (write_stats(S.stats_path, &o, &S.cfg, S.info, S.c, S.r, run.frames, run.nframes, check, status, &errs) != 0 &&
        rc == 0)
        rc = 1;
    report_run(&S, &o, &run, &errs, check, rc, now_seconds() - t0);
    fs_error_log_free(&errs);
    fs_callset_free(&o.snaps);
    free(run.frames);
    if (replay_session_close(&S, &o) != 0 && rc == 0)
        rc = 1;
    return rc;
}

static int run_diff(int argc, char **argv)
{
    if (argc >= 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h"))) {
        printf("usage: fragsim diff A B\n\nCompares two images (any format OpenImageIO reads):\n"
               "pixels that differ, the largest channel difference and PSNR.\n"
               "Exit status 0 when identical, 1 when they differ, 2 on error.\n");
        return 0;
    }
    if (argc != 2) {
        fprintf(stderr, "%s: diff needs two images (see --help)\n", prog);
        return 2;
    }
    char err[1024];
    uint8_t *a = NULL, *b = NULL;
    int wa, ha, wb, hb;
    if (fs_image_read(argv[0], &a, &wa, &ha, err, sizeof err) != 0 ||
        fs_image_read(argv[1], &b, &wb, &hb, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        free(a);
        return 2;
    }
    if (wa != wb || ha != hb) {
        fprintf(stderr, "%s: sizes differ: %dx%d vs %dx%d\n", prog, wa, ha, wb, hb);
        free(a);
        free(b);
        return 1;
    }
    fs_image_diff d;
    memset(&d, 0, sizeof d);
    fs_image_compare(a, b, wa, ha, &d);
    if (isinf(d.psnr))
        printf("identical (%dx%d)\n", wa, ha);
    else
        printf("%llu of %llu pixels differ, max diff %d, PSNR %.2f dB\n",
               (unsigned long long)d.pixels_differ, (unsigned long long)d.pixels, d.max_diff, d.psnr);
    free(a);
    free(b);
    return d.pixels_differ ? 1 : 0;
}

/* `fragsim bench`: times the replay of a trace on one engine, so that
 * scripts/bench.sh can run the model, llvmpipe and softpipe in separate
 * processes (Mesa picks its driver once per process from GALLIUM_DRIVER). */
/* Seconds to go through TRACE's calls `repeat` times without executing
 * one (after fs_replay_open has decoded them): the part of a bench replay
 * no mode can avoid (its ceiling on speed-ups).  Negative when the trace
 * cannot be read. */
static double time_floor(const char *trace, const fs_replay_opts *ro, long repeat)
{
    double seconds = 0;
    char err[1024];
    for (long rep = 0; rep < repeat; rep++) {
        fs_replayer *r = fs_replay_open(trace, ro, err, sizeof err);
        if (!r)
            return -1;
        replay_loop loop = {.r = r, .trace = trace, .frame_last = -1};
        double t0 = now_seconds();
        int rc = replay_loop_run(&loop);
        seconds += now_seconds() - t0;
        fs_replay_close(r);
        if (rc != 0)
            return -1;
    }
    return seconds;
}

/* bench on OSMesa: glFinish at each frame end, since llvmpipe renders lazily */
static int finish_osmesa_frame(replay_loop *L, long frame)
{
    (void)frame;
    (void)fs_osmesa_color(L->ref);
    return 0;
}

typedef struct bench_opts {
    const char *engine, *trace, *config_file;
    int cycle_mode; /* --mode: as `fragsim replay --mode`; -1 functional */
    char max_error_set[48]; /* --max-error P as a --set of sampling.max_error, or "" */
    long repeat;
    int width, height;
    fs_trace_parser parser;
    long threads; /* --threads, as for replay */
} bench_opts;

/* 0, 1 after --help, or -1 on a bad argument (printed). */
static int parse_bench_opts(int argc, char **argv, bench_opts *o)
{
    *o = (bench_opts){"model", NULL, NULL, -1, "", 1, 0, 0, FS_TRACE_PARSER_FAST, 0};
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: fragsim bench [--engine model|osmesa] [--repeat N] [--size WxH]\n"
                   "                     [--mode functional|cycle|sampled] [--config FILE]\n"
                   "                     [--max-error P] [--reader fast|general] [--threads N] TRACE\n\n"
                   "Replays TRACE once untimed, then N times on one engine, and prints one JSON\nline: seconds of"
                   " rendering (from the decoded calls), load_seconds (opening the\ntrace: decoding and"
                   " validating it, the same for every engine), floor_seconds\n(going through the decoded"
                   " calls without executing them: no engine can be\nfaster), frames, and the model's"
                   " fragment count.  `make bench` compares the engines.\n\n" THREADS_HELP);
            return 1;
        } else if (!strcmp(argv[i], "--engine") && i + 1 < argc) {
            o->engine = argv[++i];
        } else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) {
            o->repeat = strtol(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--mode") && i + 1 < argc) {
            if (fs_cli_cycle_mode(argv[++i], &o->cycle_mode) != 0) {
                fprintf(stderr, "%s: bench: --mode: expected functional, cycle or sampled\n", prog);
                return -1;
            }
        } else if (!strcmp(argv[i], "--config") && i + 1 < argc) {
            o->config_file = argv[++i];
        } else if (!strcmp(argv[i], "--max-error") && i + 1 < argc) {
            if (fs_cli_max_error_set(argv[++i], o->max_error_set, sizeof o->max_error_set) != 0) {
                fprintf(stderr, "%s: bench: --max-error '%s': expected a percentage from 0 to 100\n", prog, argv[i]);
                return -1;
            }
        } else if (!strcmp(argv[i], "--reader") && i + 1 < argc) {
            if (parse_reader(argv[++i], &o->parser) != 0)
                return -1;
        } else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
            if (parse_threads(argv[++i], &o->threads) != 0)
                return -1;
        } else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &o->width, &o->height) != 2 || o->width <= 0 || o->height <= 0) {
                fprintf(stderr, "%s: --size: expected WxH\n", prog);
                return -1;
            }
        } else if (argv[i][0] != '-' && !o->trace) {
            o->trace = argv[i];
        } else {
            fprintf(stderr, "%s: bench: bad argument %s (see --help)\n", prog, argv[i]);
            return -1;
        }
    }
    if (!o->trace || o->repeat < 1 || (strcmp(o->engine, "model") && strcmp(o->engine, "osmesa"))) {
        fprintf(stderr, "%s: bench: need a trace, --repeat >= 1 and --engine model|osmesa\n", prog);
        return -1;
    }
    return 0;
}

/* One engine's state over the repetitions of a bench run. */
typedef struct bench_run {
    const bench_opts *o;
    fs_run_config cfg;
    fs_replay_opts ro;
    bool model;
    fs_context *c;
    fs_osmesa *ref;
    fs_cli_cycle *cy;
    fs_cycle_stats cstats;
    double cerror, seconds, load;
    fs_cli_passes passes;    /* sampled mode's passes of the last repetition */
    uint64_t frames, fragments;
    const char *renderer;
} bench_run;

/* Repetition `rep` (-1: the untimed warm-up: llvmpipe compiles its shader
 * variants with LLVM on first use, which is not rendering throughput).
 * 0, or -1 with the error printed. */
static int bench_repetition(bench_run *B, long rep)
{
    char err[1024];
    /* sampling.max_error: passes until the estimate is within it, each
     * timed (the speed-up is over all of them) */
    fs_cycle_config pass = B->cfg.cycle;
    B->passes.n = 0;
again:;
    double tl = now_seconds();
    fs_replayer *r = fs_replay_open(B->o->trace, &B->ro, err, sizeof err);
    if (rep >= 0)
        B->load += now_seconds() - tl;
    if (!r) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return -1;
    }
    const fs_replay_info *info = fs_replay_info_get(r);
    if (B->model) {
        /* A fresh context per repetition: a trace need not leave the state
         * it found (a trimmed capture ends with rubik's matrices pushed,
         * and a second replay on the same context drew 10,189 fragments
         * instead of 247,440). */
        fs_cli_cycle_end(B->cy);
        B->cy = NULL;
        fs_context_destroy(B->c);
        if ((B->c = fs_context_create(&B->cfg.gl, info->width, info->height)))
            fs_context_set_double_buffered(B->c, info->double_buffered);
    }
    if (B->c && B->o->cycle_mode >= 0) {
        /* A fresh model per repetition: each reports the same cycles. */
        B->cy = fs_cli_cycle_begin(B->o->cycle_mode, &pass, B->c, NULL, r, false, err, sizeof err);
        if (!B->cy) {
            fprintf(stderr, "%s: %s\n", prog, err);
            fs_replay_close(r);
            return -1;
        }
    }
    if (!B->ref && !B->model) {
        B->ref = fs_osmesa_create(info->width, info->height, 24, 8, err, sizeof err);
        if (B->ref)
            B->renderer = (const char *)glGetString(GL_RENDERER);
    }
    if ((B->model && !B->c) || (!B->model && !B->ref)) {
        fprintf(stderr, "%s: cannot create the %s context\n", prog, B->o->engine);
        fs_replay_close(r);
        return -1;
    }
    /* The model's counters run over every frame (not reset per frame). */
    replay_loop loop = {.r = r, .model = B->c, .ref = B->ref, .cycle = B->cy, .trace = B->o->trace, .frame_last = -1,
                        .at_frame = B->model ? NULL : finish_osmesa_frame};
    double t0 = now_seconds();
    int rc = replay_loop_run(&loop);
    double t1 = now_seconds();
    fs_replay_close(r);
    if (rc != 0)
        return -1;
    if (rep >= 0)
        B->seconds += t1 - t0;
    if (B->cy && fs_cli_cycle_resample(B->cy, &pass, &B->passes))
        goto again;
    if (B->cy)
        B->cerror = fs_cli_cycle_totals(B->cy, &B->cstats);
    if (rep >= 0) {
        B->frames += loop.frames;
        if (B->c)
            B->fragments += B->c->stats.fragments_generated;
    }
    return 0;
}

static int run_bench(int argc, char **argv)
{
    bench_opts o;
    int p = parse_bench_opts(argc, argv, &o);
    if (p)
        return p > 0 ? 0 : 2;
    bench_run B = {.o = &o, .model = !strcmp(o.engine, "model"), .renderer = "fragsim"};
    const char *max_error = o.max_error_set;
    if (load_run_config(&B.cfg, o.config_file, &max_error, max_error[0] ? 1 : 0, o.threads) != 0)
        return 2;
    B.ro = (fs_replay_opts){NULL, o.width, o.height, 0};
    B.ro.parser = o.parser;
    int rc = 0;
    for (long rep = -1; rep < o.repeat && rc == 0; rep++)
        rc = bench_repetition(&B, rep);
    if (rc == 0) {
        /* fragments: summed over the timed repetitions, a context each */
        uint64_t fragments = B.fragments;
        double floor_s = time_floor(o.trace, &B.ro, o.repeat);
        /* one line (scripts/bench.sh reads it with sed); reals as "%.6f" printed them */
        json_t *line = json_pack("{s:s, s:s, s:o, s:o, s:o, s:I, s:I, s:I, s:I, s:o}", "engine", o.engine, "renderer",
                                 B.renderer, "seconds", fixed_real(B.seconds, 6), "load_seconds", fixed_real(B.load, 6),
                                 "floor_seconds", fixed_real(floor_s, 6), "frames", (json_int_t)B.frames, "fragments",
                                 (json_int_t)fragments, "cycles", (json_int_t)B.cstats.cycles, "estimated_cycles",
                                 (json_int_t)B.cstats.estimated_cycles, "error_estimate", fixed_real(B.cerror, 6));
        if (line && B.cy && o.cycle_mode == FS_CYCLE_SAMPLED)
            json_object_set_new(line, "passes", json_integer(B.passes.n));
        if (!line || json_dumpf(line, stdout, JSON_REAL_PRECISION(15)) != 0)
            fprintf(stderr, "%s: bench: out of memory\n", prog);
        putchar('\n');
        json_decref(line);
    }
    fs_cli_cycle_end(B.cy);
    fs_context_destroy(B.c);
    fs_osmesa_destroy(B.ref);
    return rc ? 1 : 0;
}

static int run_config(int argc, char **argv)
{
    if (argc == 1 && !strcmp(argv[0], "--list")) {
        fs_run_config_list(stdout);
        return 0;
    }
    if (argc == 1 && !strcmp(argv[0], "--defaults")) {
        fs_run_config_write_defaults_ini(stdout);
        return 0;
    }
    printf("usage: fragsim config --list | --defaults (every key as an INI file: configs/default.ini)\n");
    return argc == 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h")) ? 0 : 2;
}

static int run_stats(int argc, char **argv)
{
    if (argc == 1 && !strcmp(argv[0], "--list")) {
        fs_stats_list(stdout);
        printf("\ncycle-level model (`replay --mode cycle|sampled`), per frame, draw and query:\n");
        fs_cycle_stats_list(stdout);
        printf("\nper run, beside \"frames\" and \"totals\":\n");
        printf("%-24s %-10s %s\n", "errors_total", "errors", "GL errors raised in the run");
        printf("%-24s %-10s %s\n", "errors", "list",
               "each GL error, the first 10000: {\"call\": N, \"command\": \"glName\", \"error\": \"GL_...\"},"
               " N as `apitrace dump` numbers calls (an error inside a display list: its glCallList)");
        printf("\nper frame of `fragsim check`:\n");
        printf("%-24s %-10s %s\n", "pixels_differ", "pixels", "pixels whose colour differs from OSMesa's");
        printf("%-24s %-10s %s\n", "pixels_within_1", "pixels", "of those, pixels off by exactly 1 in their largest channel");
        printf("%-24s %-10s %s\n", "pixels_beyond_1", "pixels", "pixels off by more than 1 in some channel");
        return 0;
    }
    printf("usage: fragsim stats --list\n");
    return argc == 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h")) ? 0 : 2;
}

static int run_signals(int argc, char **argv)
{
    bool md = argc == 2 && !strcmp(argv[1], "--markdown");
    if ((argc == 1 || md) && !strcmp(argv[0], "--list")) {
        fs_signals_list(stdout, md);
        return 0;
    }
    printf("usage: fragsim signals --list [--markdown]\n"
           "The cycle model's signals (`replay --mode cycle --vcd`, `--gpio`; docs/signals.md).\n");
    return argc == 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h")) ? 0 : 2;
}

static int run_replay_only(int argc, char **argv) { return run_replay(argc, argv, false); }
static int run_check(int argc, char **argv) { return run_replay(argc, argv, true); }

/* Every subcommand, one row each: a new command is a new row (and usually a
 * new driver/cli_NAME.c declaring its entry point in cli.h).  argv[0] of
 * the entry point is the first argument after the command name. */
static const struct cli_command {
    const char *name, *synopsis, *summary;
    int (*run)(int argc, char **argv);
} commands[] = {
    {"replay", "TRACE", "render an apitrace trace on the model; write PNGs and statistics", run_replay_only},
    {"check", "TRACE", "render on the model and on OSMesa (llvmpipe) and compare per frame", run_check},
    {"diff", "A B", "compare two images (OpenImageIO)", run_diff},
    {"bench", "TRACE", "time a replay on the model or on OSMesa (used by `make bench`)", run_bench},
    {"config", "--list", "list every configuration key with its default and meaning", run_config},
    {"stats", "--list", "list every statistic with its unit and meaning", run_stats},
    {"signals", "--list", "list the cycle model's signals (VCD, GPIO)", run_signals},
    {"study-filters", "[--out DIR]", "texture filter quality/cost study (used by `make study-filters`)", fs_cli_study_filters},
    {"sweep", "SPEC.ini", "run a grid of configurations x traces as jobs; CSV and plots", fs_cli_sweep},
    {"mpgrid", "[--markdown]", "MP-Grid vs MIPmap vs Clip-Map memory example (Huettner 1999, 4.1.2)", fs_cli_mpgrid},
    {"rom", "[--markdown]", "fast-footprint weighting ROM sizes: Table 4.3 of Huettner 1999 next to fragsim's", fs_cli_rom},
};

static void usage_main(FILE *f)
{
    fprintf(f, "usage: fragsim COMMAND [options]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        char head[64];
        snprintf(head, sizeof head, "%s %s", commands[i].name, commands[i].synopsis);
        fprintf(f, "  %-20s %s\n", head, commands[i].summary);
    }
    fprintf(f, "\n`fragsim COMMAND --help` describes each command.\n");
}

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage_main(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name))
            return commands[i].run(argc - 2, argv + 2);
    fprintf(stderr, "%s: unknown command '%s' (see fragsim --help)\n", prog, argv[1]);
    return 2;
}
