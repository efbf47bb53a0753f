/*
 * The trace reader's two parsers (driver/trace_read.c, fs_trace_set_parser):
 * the fast paths must decode every trace exactly as the general parser
 * alone does, since the general parser is the reference (style anchor 6: a
 * fast path beside a plain one, and a test holding them equal).  Every test
 * trace is read through both and each call compared field by field (number,
 * thread, name, argument names, values with their signatures, flags, stream
 * offsets, output arguments), then replayed on the model through both: the
 * same events, images, depth buffers and counters per frame.  Damaged
 * traces (cut at many points) must fail with the same message at the same
 * call.
 *
 * Traces: the conformance corpus (every .trace in tests/conformance's
 * folders), the .trace files of tests/data, every scenegen scene ($SCENEGEN or
 * $FRAGSIM_BUILD/scenegen), a scene repacked in apitrace's zlib container,
 * and the paths in $FS_PARSER_TRACES (colon-separated; tests/cli_shim.sh
 * passes the shim's capture).
 */
#include <glob.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "../driver/trace.h"
#include "../driver/replay.h"
#include "../pipeline/context.h"

static const char *tmp_dir(void)
{
    static char dir[64];
    if (!dir[0]) {
        snprintf(dir, sizeof dir, "/tmp/fs_parsers_test_XXXXXX");
        if (!mkdtemp(dir))
            snprintf(dir, sizeof dir, "/tmp");
    }
    return dir;
}

static int str_same(const char *a, const char *b)
{
    return a == b || (a && b && strcmp(a, b) == 0);
}

static int sig_same(const fs_tsig *a, const fs_tsig *b)
{
    if (!a || !b)
        return a == b;
    if (!str_same(a->name, b->name) || a->n != b->n || !a->names != !b->names || !a->values != !b->values)
        return 0;
    for (unsigned i = 0; i < a->n; i++)
        if ((a->names && !str_same(a->names[i], b->names[i])) || (a->values && a->values[i] != b->values[i]))
            return 0;
    return 1;
}

/* Equal in everything a reader fills in, by type (trace.h says where each
 * type keeps its data); doubles by their bits. */
static int val_same(const fs_tval *a, const fs_tval *b)
{
    if (a->type != b->type || !str_same(a->enum_name, b->enum_name) || !sig_same(a->sig, b->sig))
        return 0;
    switch (a->type) {
    case FS_TV_SINT:
    case FS_TV_ENUM:
        return a->i == b->i;
    case FS_TV_UINT:
    case FS_TV_OPAQUE:
    case FS_TV_BITMASK:
        return a->u == b->u;
    case FS_TV_FLOAT:
    case FS_TV_DOUBLE:
        return memcmp(&a->d, &b->d, sizeof a->d) == 0;
    case FS_TV_STRING:
    case FS_TV_BLOB:
        return a->str.len == b->str.len && (!a->str.len || memcmp(a->str.ptr, b->str.ptr, a->str.len) == 0);
    case FS_TV_ARRAY:
    case FS_TV_STRUCT:
    case FS_TV_REPR:
    case FS_TV_WSTRING:
        if (a->arr.n != b->arr.n)
            return 0;
        for (size_t i = 0; i < a->arr.n; i++)
            if (!val_same(&a->arr.elems[i], &b->arr.elems[i]))
                return 0;
        return 1;
    default:
        return 1;
    }
}

/* NULL when a and b are the same call, else the first field that differs. */
static const char *call_diff(const fs_tcall *a, const fs_tcall *b)
{
    if (a->no != b->no) return "number";
    if (a->thread != b->thread) return "thread";
    if (!str_same(a->name, b->name)) return "name";
    if (a->nargs != b->nargs) return "nargs";
    if (a->flags != b->flags) return "flags";
    if (a->offset != b->offset) return "offset";
    if (a->out_args != b->out_args) return "out_args";
    if (a->has_ret != b->has_ret || (a->has_ret && !val_same(&a->ret, &b->ret))) return "return value";
    for (unsigned k = 0; k < a->nargs; k++) {
        if (!str_same(a->arg_names ? a->arg_names[k] : NULL, b->arg_names ? b->arg_names[k] : NULL))
            return "argument name";
        if (!a->args != !b->args || (a->args && !val_same(&a->args[k], &b->args[k])))
            return "argument";
    }
    return NULL;
}

/* Reads path through both parsers side by side; returns the calls read,
 * -1 after reporting a difference. */
static long compare_decoded(check_state *check_st_, const char *path)
{
    char err[600];
    fs_trace_reader *g = fs_trace_open(path, err, sizeof err), *f = fs_trace_open(path, err, sizeof err);
    if (!g || !f) {
        /* the header is read before either parser runs: both fail alike */
        CHECK(!g && !f);
        fs_trace_close(g);
        fs_trace_close(f);
        return 0;
    }
    fs_trace_set_parser(g, FS_TRACE_PARSER_GENERAL);
    fs_trace_set_parser(f, FS_TRACE_PARSER_FAST);
    long n = 0;
    for (;; n++) {
        fs_tcall cg, cf;
        int kg = fs_trace_next(g, &cg), kf = fs_trace_next(f, &cf);
        const char *d = kg != kf ? "result" : kg == 1 ? call_diff(&cg, &cf) : NULL;
        if (!d && kg < 0 && !str_same(fs_trace_error(g), fs_trace_error(f)))
            d = "error message";
        if (!d && kg == 0 && !str_same(fs_trace_warning(g), fs_trace_warning(f)))
            d = "warning";
        if (d) {
            CHECK_FAIL_("%s: call %ld (%s): %s differs (general %d %s, fast %d %s)", path, n,
                        kg == 1 ? cg.name : "-", d, kg, kg < 0 ? fs_trace_error(g) : "", kf,
                        kf < 0 ? fs_trace_error(f) : "");
            n = -1;
            break;
        }
        if (kg != 1)
            break;
    }
    fs_trace_close(g);
    fs_trace_close(f);
    return n;
}

static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        h = (h ^ ((const unsigned char *)p)[i]) * 1099511628211ull; /* FNV-1a */
    return h;
}

/* What a replay on the model gives: its events, and per frame the colour
 * and depth buffers and the counters. */
typedef struct replay_digest {
    int open_failed;
    char err[600];
    uint64_t events, frames, h;
} replay_digest;

static void replay_on_model(const char *path, fs_trace_parser parser, replay_digest *d)
{
    memset(d, 0, sizeof *d);
    fs_replay_opts o = {NULL, 0, 0, 0};
    o.parser = parser;
    fs_replayer *r = fs_replay_open(path, &o, d->err, sizeof d->err);
    if (!r) {
        d->open_failed = 1;
        return;
    }
    const fs_replay_info *info = fs_replay_info_get(r);
    fs_config cfg;
    fs_config_defaults(&cfg);
    fs_context *c = fs_context_create(&cfg, info->width, info->height);
    if (!c) {
        snprintf(d->err, sizeof d->err, "no context");
        fs_replay_close(r);
        return;
    }
    fs_context_set_double_buffered(c, info->double_buffered);
    size_t px = (size_t)info->width * (size_t)info->height;
    fs_call call;
    fs_replay_event ev;
    while ((ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR) {
        d->events++;
        d->h = mix(d->h, &ev, sizeof ev);
        if (ev == FS_REPLAY_CALL) {
            d->h = mix(d->h, &call.cmd, sizeof call.cmd);
            fs_submit(c, &call);
        } else if (ev == FS_REPLAY_FRAME_END) {
            d->frames++;
            d->h = mix(d->h, c->fb.color, px * 4);
            d->h = mix(d->h, c->fb.depth, px * sizeof *c->fb.depth);
            d->h = mix(d->h, &c->stats, sizeof c->stats);
            memset(&c->stats, 0, sizeof c->stats);
        }
    }
    if (ev == FS_REPLAY_ERROR)
        snprintf(d->err, sizeof d->err, "%s", fs_replay_error(r));
    fs_context_destroy(c);
    fs_replay_close(r);
}

static void compare_replays(check_state *check_st_, const char *path)
{
    replay_digest g, f;
    replay_on_model(path, FS_TRACE_PARSER_GENERAL, &g);
    replay_on_model(path, FS_TRACE_PARSER_FAST, &f);
    if (g.open_failed != f.open_failed || g.events != f.events || g.frames != f.frames || g.h != f.h ||
        strcmp(g.err, f.err) != 0)
        CHECK_FAIL_("%s: replays differ: general %llu events %llu frames '%s', fast %llu events %llu frames '%s'",
                    path, (unsigned long long)g.events, (unsigned long long)g.frames, g.err,
                    (unsigned long long)f.events, (unsigned long long)f.frames, f.err);
}

/* Both comparisons on every file matching pattern; the number of files. */
static size_t compare_glob(check_state *check_st_, const char *pattern, bool replay, long *calls)
{
    glob_t gl;
    size_t n = 0;
    if (glob(pattern, 0, NULL, &gl) != 0)
        return 0;
    for (size_t i = 0; i < gl.gl_pathc; i++, n++) {
        long k = compare_decoded(check_st_, gl.gl_pathv[i]);
        if (k > 0)
            *calls += k;
        if (replay)
            compare_replays(check_st_, gl.gl_pathv[i]);
    }
    globfree(&gl);
    return n;
}

/* ---- tests ---- */

TEST(conformance_corpus)
{
    long calls = 0;
    size_t n = compare_glob(check_st_, "tests/conformance/*/*.trace", true, &calls);
    if (n == 0)
        SKIP("no tests/conformance/*/*.trace here (run from the repository's root)");
    printf("     %zu conformance traces, %ld calls, identical\n", n, calls);
    CHECK(calls > 0);
}

TEST(test_data_traces)
{
    long calls = 0;
    size_t n = compare_glob(check_st_, "tests/data/*.trace", true, &calls);
    if (n == 0)
        SKIP("no tests/data/*.trace");
}

static const char *scenegen_path(char *buf, size_t n)
{
    const char *s = getenv("SCENEGEN"), *b = getenv("FRAGSIM_BUILD");
    if (s && *s)
        snprintf(buf, n, "%s", s);
    else
        snprintf(buf, n, "%s/scenegen", b && *b ? b : "build");
    return access(buf, X_OK) == 0 ? buf : NULL;
}

static const char *const scenes[] = {"city", "norwich", "cathedrals", "forest", "garbage",
                                     "terrain", "demo", "textured", "bench8", "bench32"};

/* Writes scene's small trace into the temporary directory; its path, or
 * NULL when scenegen is not there or failed. */
static const char *scene_trace(const char *scene, char *path, size_t n)
{
    char gen[4096], cmd[8400];
    if (!scenegen_path(gen, sizeof gen))
        return NULL;
    snprintf(path, n, "%s/%s.trace", tmp_dir(), scene);
    if (access(path, R_OK) == 0)
        return path;
    snprintf(cmd, sizeof cmd, "'%s' %s --scale small -o '%s' >/dev/null", gen, scene, path);
    return system(cmd) == 0 ? path : NULL;
}

TEST(scenegen_traces)
{
    char path[4096];
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        if (!scene_trace(scenes[i], path, sizeof path))
            SKIP("no scenegen ($SCENEGEN or $FRAGSIM_BUILD/scenegen)");
        CHECK(compare_decoded(check_st_, path) > 10);
        compare_replays(check_st_, path);
    }
}

TEST(zlib_container)
{
    char path[4096], z[4200], cmd[8600];
    if (!scene_trace("textured", path, sizeof path))
        SKIP("no scenegen");
    if (system("command -v apitrace >/dev/null 2>&1") != 0)
        SKIP("no apitrace to repack with");
    snprintf(z, sizeof z, "%s/textured_zlib.trace", tmp_dir());
    snprintf(cmd, sizeof cmd, "apitrace repack --zlib '%s' '%s' >/dev/null 2>&1", path, z);
    REQUIRE(system(cmd) == 0);
    CHECK(compare_decoded(check_st_, z) > 1000);
    compare_replays(check_st_, z);
}

/* A trace cut at many points: each prefix fails (or, cut at a chunk
 * boundary inside an event, ends with a warning) at the same call with the
 * same message through both parsers. */
TEST(cut_traces_fail_alike)
{
    char path[4096], cut[4200];
    if (!scene_trace("demo", path, sizeof path))
        SKIP("no scenegen");
    FILE *in = fopen(path, "rb");
    REQUIRE(in != NULL);
    fseek(in, 0, SEEK_END);
    long size = ftell(in);
    rewind(in);
    unsigned char *all = malloc((size_t)size);
    REQUIRE(all && fread(all, 1, (size_t)size, in) == (size_t)size);
    fclose(in);
    snprintf(cut, sizeof cut, "%s/cut.trace", tmp_dir());
    for (int k = 1; k < 64; k++) {
        long len = size * k / 64 + (k % 7); /* spread over the file, not on chunk boundaries only */
        FILE *o = fopen(cut, "wb");
        REQUIRE(o != NULL);
        fwrite(all, 1, (size_t)len, o);
        fclose(o);
        compare_decoded(check_st_, cut);
    }
    free(all);
}

/* Any trace named in $FS_PARSER_TRACES (tests/cli_shim.sh: the shim's capture). */
TEST(named_traces)
{
    const char *list = getenv("FS_PARSER_TRACES");
    if (!list || !*list)
        SKIP("FS_PARSER_TRACES not set (tests/cli_shim.sh sets it)");
    char *copy = strdup(list), *save = NULL;
    REQUIRE(copy != NULL);
    for (char *p = strtok_r(copy, ":", &save); p; p = strtok_r(NULL, ":", &save)) {
        CHECK(compare_decoded(check_st_, p) > 0);
        compare_replays(check_st_, p);
    }
    free(copy);
}

TEST_LIST = {
    TEST_ENTRY(conformance_corpus),
    TEST_ENTRY(test_data_traces),
    TEST_ENTRY(scenegen_traces),
    TEST_ENTRY(zlib_container),
    TEST_ENTRY(cut_traces_fail_alike),
    TEST_ENTRY(named_traces),
    TEST_END,
};

/* the generated traces go with the directory made for them */
static void remove_tmp_dir(void)
{
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp_dir());
    if (strcmp(tmp_dir(), "/tmp") != 0 && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmp_dir());
}

int main(int argc, char **argv)
{
    atexit(remove_tmp_dir);
    return check_main(argc, argv, test_list);
}
