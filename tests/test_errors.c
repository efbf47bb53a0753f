/*
 * GL errors named by the call that raised them (driver/error_log.c, the
 * replay's "errors" list) and glretrace's snapshots (`fragsim replay
 * --snapshot CALLSET`, driver/callset.c).  Call numbers are checked against
 * `apitrace dump`, which is the numbering both features promise; the traces
 * are written with the trace writer, so each case is what the test says.
 */
#include <dirent.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <jansson.h>
#include "check.h"
#include "trace_build.h"
#include "../driver/callset.h"
#include "../driver/error_log.h"
#include "../driver/image.h"
#include "../driver/trace.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

static char fragsim[1024];
static char tmpdir[64];

static int have_cmd(const char *cmd)
{
    char line[256];
    snprintf(line, sizeof line, "command -v %s >/dev/null 2>&1", cmd);
    return system(line) == 0;
}

/* ---- the error log on the library ---- */

TEST(error_log_names_the_call)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c != NULL);
    fs_error_log log = {0};
    fs_error_log_attach(&log, c);
    log.call = 5;
    log.command = "glEnable";
    fsglEnable(c, 0x1234); /* not a capability: GL_INVALID_ENUM (GL 1.5 spec 2.5) */
    log.call = 6;
    log.command = "glNewList";
    fsglNewList(c, 1, GL_COMPILE);
    log.call = 7;
    log.command = "glLineWidth";
    fsglLineWidth(c, -1.0f); /* compiled: the error comes when the list executes (5.4) */
    log.call = 8;
    log.command = "glEndList";
    fsglEndList(c);
    log.call = 9;
    log.command = "glCallList";
    fsglCallList(c, 1); /* GL_INVALID_VALUE (3.4), raised by the list's glLineWidth */
    log.call = 10;
    log.command = "glPopMatrix";
    fsglPopMatrix(c); /* GL_STACK_UNDERFLOW (2.11.2) */
    CHECK_EQ_UINT(log.total, 3);
    REQUIRE(log.n == 3);
    CHECK_EQ_UINT(log.entries[0].call, 5);
    CHECK_STR(log.entries[0].command, "glEnable");
    CHECK_EQ_UINT(log.entries[0].error, GL_INVALID_ENUM);
    CHECK_EQ_UINT(log.entries[1].call, 9);
    CHECK_STR(log.entries[1].command, "glCallList");
    CHECK_EQ_UINT(log.entries[1].error, GL_INVALID_VALUE);
    CHECK_EQ_UINT(log.entries[2].call, 10);
    CHECK_EQ_UINT(log.entries[2].error, GL_STACK_UNDERFLOW);
    /* more than FS_ERROR_LOG_MAX: all counted, the first kept */
    for (int i = 0; i < FS_ERROR_LOG_MAX + 5; i++) {
        log.call = 100 + (uint64_t)i;
        fsglEnable(c, 0x1234);
    }
    CHECK_EQ_UINT(log.total, FS_ERROR_LOG_MAX + 8);
    CHECK_EQ_UINT(log.n, FS_ERROR_LOG_MAX);
    CHECK_EQ_UINT(log.entries[FS_ERROR_LOG_MAX - 1].call, 100 + FS_ERROR_LOG_MAX - 4);
    fs_error_log_free(&log);
    fs_context_destroy(c);
}

/* ---- traces ---- */

typedef struct tb {
    fs_trace_writer *w;
    char path[256];
    int n;                 /* calls written */
    const char *names[256];
} tb;


/* Writes a call; returns its ordinal in the trace. */
static int call(tb *t, const char *name, int n, const fs_tval *args)
{
    tb_write_call(t->w, name, n, args, 0);
    if (t->n < 256)
        t->names[t->n] = name;
    return t->n++;
}

static void triangle(tb *t)
{
    fs_tval m = tb_eval(GL_TRIANGLES, "GL_TRIANGLES");
    call(t, "glBegin", 1, &m);
    static const float v[3][2] = {{-1, -1}, {1, -1}, {0, 1}};
    for (int i = 0; i < 3; i++) {
        fs_tval a[2] = {tb_fval(v[i][0]), tb_fval(v[i][1])};
        call(t, "glVertex2f", 2, a);
    }
    call(t, "glEnd", 0, NULL);
}

typedef struct expected { int ordinal; GLenum error; } expected;

/* Three frames ending in glXSwapBuffers, draws of several kinds, an unknown
 * call, and invalid calls; *exp gets the invalid ones. */
static int write_trace(tb *t, const char *name, expected *exp, int *nexp)
{
    char err[256];
    snprintf(t->path, sizeof t->path, "%s/%s.trace", tmpdir, name);
    t->w = fs_trace_create(t->path, err, sizeof err);
    if (!t->w)
        return -1;
    t->n = 0;
    *nexp = 0;
    fs_tval vp[4] = {tb_ival(0), tb_ival(0), tb_ival(16), tb_ival(12)};
    call(t, "glViewport", 4, vp);
    fs_tval list[2] = {tb_ival(1), tb_eval(GL_COMPILE, "GL_COMPILE")};
    call(t, "glNewList", 2, list);
    fs_tval neg = tb_fval(-1);
    call(t, "glLineWidth", 1, &neg);
    call(t, "glEndList", 0, NULL);
    for (int f = 0; f < 3; f++) {
        fs_tval cc[4] = {tb_fval(0.25 * f), tb_fval(0.5), tb_fval(0.75), tb_fval(0.5)};
        call(t, "glClearColor", 4, cc);
        fs_tval bits = tb_ival(GL_COLOR_BUFFER_BIT);
        call(t, "glClear", 1, &bits);
        if (f == 0) {
            fs_tval bad = tb_ival(0x1234); /* not a capability: GL_INVALID_ENUM (2.5) */
            exp[(*nexp)++] = (expected){call(t, "glEnable", 1, &bad), GL_INVALID_ENUM};
        }
        fs_tval col[3] = {tb_fval(1), tb_fval(0.5), tb_fval(0)};
        call(t, "glColor3f", 3, col);
        triangle(t);
        if (f == 1) {
            call(t, "glFragsimNoSuchCall", 0, NULL); /* numbered, not executed */
            /* the list's glLineWidth(-1): GL_INVALID_VALUE (3.4), the glCallList's */
            fs_tval one = tb_ival(1);
            exp[(*nexp)++] = (expected){call(t, "glCallList", 1, &one), GL_INVALID_VALUE};
            exp[(*nexp)++] = (expected){call(t, "glPopMatrix", 0, NULL), GL_STACK_UNDERFLOW};
            fs_tval m = tb_eval(GL_TRIANGLES, "GL_TRIANGLES");
            call(t, "glBegin", 1, &m);
            fs_tval dt = tb_eval(GL_DEPTH_TEST, "GL_DEPTH_TEST");
            /* glEnable between glBegin and glEnd: GL_INVALID_OPERATION (2.6.3) */
            exp[(*nexp)++] = (expected){call(t, "glEnable", 1, &dt), GL_INVALID_OPERATION};
            call(t, "glEnd", 0, NULL);
        }
        fs_tval r[4] = {tb_fval(-0.5), tb_fval(-0.5), tb_fval(0.25), tb_fval(0.5)};
        call(t, "glRectf", 4, r);
        call(t, "glXSwapBuffers", 0, NULL);
    }
    return fs_trace_finish(t->w);
}

/* apitrace dump's call numbers and names, in order.  Returns the count. */
static int dump_calls(const char *path, uint64_t *nos, char (*names)[64], int max)
{
    char cmd[600], line[4096];
    snprintf(cmd, sizeof cmd, "apitrace dump --color=never --verbose '%s' 2>/dev/null", path);
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    int n = 0;
    while (fgets(line, sizeof line, p)) {
        unsigned long long no;
        char name[64];
        if (sscanf(line, "%llu %63[A-Za-z0-9_](", &no, name) == 2 && n < max) {
            nos[n] = no;
            snprintf(names[n], 64, "%s", name);
            n++;
        }
    }
    pclose(p);
    return n;
}

static int run(const char *args, const char *trace, const char *log)
{
    static char cmd[8192];
    if ((size_t)snprintf(cmd, sizeof cmd, "'%s' replay --quiet %s '%s' >'%s' 2>&1", fragsim, args, trace,
                         log) >= sizeof cmd)
        return -1;
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    s[fread(s, 1, (size_t)n, f)] = '\0';
    fclose(f);
    return s;
}

TEST(replay_errors_numbered_as_apitrace_dump)
{
    if (!have_cmd("apitrace"))
        SKIP("apitrace is not installed");
    tb t;
    expected exp[8];
    int nexp;
    REQUIRE(write_trace(&t, "errors", exp, &nexp) == 0);
    static uint64_t nos[256];
    static char names[256][64];
    int n = dump_calls(t.path, nos, names, 256);
    CHECK_EQ_INT(n, t.n);
    REQUIRE(n == t.n);
    char out[300], log[300], json[400];
    snprintf(out, sizeof out, "%s/out_errors", tmpdir);
    snprintf(log, sizeof log, "%s/errors.log", tmpdir);
    snprintf(json, sizeof json, "%s/stats.json", out);
    char args[400];
    snprintf(args, sizeof args, "--out '%s'", out);
    CHECK_EQ_INT(run(args, t.path, log), 0);
    char *l = slurp(log);
    json_error_t jerr;
    json_t *s = json_load_file(json, 0, &jerr);
    if (!s)
        CHECK_FAIL_("%s: %s", json, jerr.text);
    REQUIRE(s && l);
    const json_t *list = json_object_get(s, "errors");
    CHECK_EQ_INT(json_integer_value(json_object_get(s, "errors_total")), 4);
    CHECK_EQ_INT(json_array_size(list), nexp); /* no more entries */
    for (int i = 0; i < nexp && i < (int)json_array_size(list); i++) {
        const expected *x = &exp[i];
        const json_t *at = json_array_get(list, (size_t)i);
        char want[200], b[16];
        CHECK_EQ_UINT(json_integer_value(json_object_get(at, "call")), nos[x->ordinal]);
        CHECK_STR(json_string_value(json_object_get(at, "command")), names[x->ordinal]);
        CHECK_STR(json_string_value(json_object_get(at, "error")), fs_error_name(x->error, b));
        /* stderr, as glretrace warns */
        snprintf(want, sizeof want, "%llu: warning: glGetError(%s) = %s\n",
                 (unsigned long long)nos[x->ordinal], names[x->ordinal], fs_error_name(x->error, b));
        if (!strstr(l, want))
            CHECK_FAIL_("stderr lacks \"%.*s\": %s", (int)strlen(want) - 1, want, l);
    }
    json_decref(s);
    free(l);
}

/* The files DIR holds, as call numbers, sorted. */
static int list_snapshots(const char *dir, uint64_t *nos, int max)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0;
    struct dirent *de;
    while ((de = readdir(d))) {
        unsigned long long no;
        char tail[8];
        if (strlen(de->d_name) == 14 && sscanf(de->d_name, "%10llu%7s", &no, tail) == 2 &&
            !strcmp(tail, ".png") && n < max)
            nos[n++] = no;
    }
    closedir(d);
    for (int i = 1; i < n; i++)
        for (int k = i; k > 0 && nos[k - 1] > nos[k]; k--) {
            uint64_t x = nos[k];
            nos[k] = nos[k - 1];
            nos[k - 1] = x;
        }
    return n;
}

static void check_set(check_state *check_st_, const char *trace, const char *spec, const char *tag,
                      const uint64_t *want, int nwant)
{
    char dir[300], log[300], args[700];
    snprintf(dir, sizeof dir, "%s/snap_%s", tmpdir, tag);
    snprintf(log, sizeof log, "%s/snap_%s.log", tmpdir, tag);
    snprintf(args, sizeof args, "--out '%s/o_%s' --snapshot-prefix '%s/' --snapshot '%s'", tmpdir, tag, dir, spec);
    int rc = run(args, trace, log);
    CHECK_EQ_INT(rc, 0);
    uint64_t got[256];
    int n = list_snapshots(dir, got, 256);
    int same = n == nwant;
    for (int i = 0; same && i < n; i++)
        same = got[i] == want[i];
    if (!same) {
        CHECK_FAIL_("--snapshot '%s': %d snapshots, %d expected", spec, n, nwant);
        for (int i = 0; i < n || i < nwant; i++)
            fprintf(stderr, "    %d: got %lld want %lld\n", i, i < n ? (long long)got[i] : -1LL,
                    i < nwant ? (long long)want[i] : -1LL);
    }
}

/* --snapshot frame / draw / numbers, ranges and steps write exactly the calls
 * apitrace dump numbers so: frame = the swaps, draw = glretrace's draw calls
 * (glClear, glEnd, glRect*, glCallList, glDraw*; trace_parser_flags.cpp). */
TEST(snapshot_call_sets_match_apitrace_dump)
{
    if (!have_cmd("apitrace"))
        SKIP("apitrace is not installed");
    tb t;
    expected exp[8];
    int nexp;
    REQUIRE(write_trace(&t, "snap", exp, &nexp) == 0);
    static uint64_t nos[256];
    static char names[256][64];
    int n = dump_calls(t.path, nos, names, 256);
    REQUIRE(n == t.n);
    uint64_t want[256];
    int nw = 0;
    for (int i = 0; i < n; i++)
        if (!strcmp(names[i], "glXSwapBuffers"))
            want[nw++] = nos[i];
    CHECK_EQ_INT(nw, 3);
    check_set(check_st_, t.path, "frame", "frame", want, nw);
    nw = 0;
    for (int i = 0; i < n; i++)
        if (!strcmp(names[i], "glClear") || !strcmp(names[i], "glEnd") || !strcmp(names[i], "glRectf") ||
            !strcmp(names[i], "glCallList"))
            want[nw++] = nos[i];
    CHECK(nw >= 10);
    check_set(check_st_, t.path, "draw", "draw", want, nw);
    /* a range with a step counts from the range's start; a list; a range to the end */
    nw = 0;
    for (uint64_t k = 3; k <= 20; k += 4)
        want[nw++] = k;
    check_set(check_st_, t.path, "3-20/4", "step", want, nw);
    uint64_t w2[] = {0, 7, 9};
    check_set(check_st_, t.path, "9, 0 7", "list", w2, 3);
    nw = 0;
    for (int i = 0; i < n; i++)
        if (nos[i] >= 40)
            want[nw++] = nos[i];
    check_set(check_st_, t.path, "40-", "open", want, nw);
    nw = 0;
    for (int i = 0; i < n; i++)
        if (nos[i] >= 10 && nos[i] <= 30 && (!strcmp(names[i], "glClear") || !strcmp(names[i], "glEnd") ||
                                             !strcmp(names[i], "glRectf") || !strcmp(names[i], "glCallList")))
            want[nw++] = nos[i];
    check_set(check_st_, t.path, "10-30/draw", "rdraw", want, nw);
    for (int i = 0; i < n; i++)
        want[i] = nos[i];
    check_set(check_st_, t.path, "*", "all", want, n);

    /* the snapshot at a swap is the frame's image, RGB, top row first */
    char snap[400], frame[400];
    uint64_t swap1 = 0;
    for (int i = 0, k = 0; i < n; i++)
        if (!strcmp(names[i], "glXSwapBuffers") && k++ == 1)
            swap1 = nos[i];
    snprintf(snap, sizeof snap, "%s/snap_frame/%010llu.png", tmpdir, (unsigned long long)swap1);
    snprintf(frame, sizeof frame, "%s/o_frame/frame_0001.png", tmpdir);
    uint8_t *a = NULL, *b = NULL;
    int wa, ha, wb, hb;
    char err[512];
    REQUIRE(fs_image_read(snap, &a, &wa, &ha, err, sizeof err) == 0);
    REQUIRE(fs_image_read(frame, &b, &wb, &hb, err, sizeof err) == 0);
    CHECK_EQ_INT(wa, 16);
    CHECK_EQ_INT(ha, 12);
    CHECK(wa == wb && ha == hb);
    long bad = 0;
    for (int i = 0; i < wa * ha && wa == wb && ha == hb; i++)
        bad += memcmp(a + 4 * i, b + 4 * i, 3) != 0;
    CHECK_EQ_INT(bad, 0);
    free(a);
    free(b);
    FILE *f = fopen(snap, "rb");
    unsigned char head[26] = {0};
    REQUIRE(f != NULL);
    CHECK_EQ_INT(fread(head, 1, 26, f), 26);
    fclose(f);
    CHECK_EQ_INT(head[25], 2); /* PNG colour type 2: RGB, as glretrace writes */
    /* --snapshot-alpha: RGBA */
    char log[300], args[600];
    snprintf(log, sizeof log, "%s/alpha.log", tmpdir);
    snprintf(args, sizeof args, "--out '%s/o_alpha' --snapshot-alpha --snapshot %llu", tmpdir,
             (unsigned long long)swap1);
    CHECK_EQ_INT(run(args, t.path, log), 0);
    snprintf(snap, sizeof snap, "%s/o_alpha/%010llu.png", tmpdir, (unsigned long long)swap1);
    f = fopen(snap, "rb");
    REQUIRE(f != NULL);
    CHECK_EQ_INT(fread(head, 1, 26, f), 26);
    fclose(f);
    CHECK_EQ_INT(head[25], 6);
}

TEST(bad_call_sets_are_errors)
{
    static const char *const bad[] = {"", "5-3", "abc", "1-2/0", "frame/2x", "3-a", "Frame", "-5",
                                      "99999999999999999999999", "1,,@/nonexistent/file"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fs_callset cs = {0};
        char err[512] = "";
        if (fs_callset_parse(&cs, bad[i], err, sizeof err) != -1)
            CHECK_FAIL_("'%s' accepted", bad[i]);
        else if (!strstr(err, "call set"))
            CHECK_FAIL_("'%s': message \"%s\"", bad[i], err);
        fs_callset_free(&cs);
    }
    /* what parses, and what it holds */
    fs_callset cs = {0};
    char err[512];
    REQUIRE(fs_callset_parse(&cs, " 0-10/5 , 20-, draw 7", err, sizeof err) == 0);
    CHECK(fs_callset_contains(&cs, 0, 0) && fs_callset_contains(&cs, 5, 0) && fs_callset_contains(&cs, 10, 0));
    CHECK(!fs_callset_contains(&cs, 3, 0) && !fs_callset_contains(&cs, 15, 0));
    CHECK(fs_callset_contains(&cs, 7, 0) && fs_callset_contains(&cs, 12345, 0));
    CHECK(fs_callset_contains(&cs, 13, FS_CALL_RENDER) && !fs_callset_contains(&cs, 13, FS_CALL_END_FRAME));
    fs_callset_free(&cs);
    /* apitrace's call flags by name */
    CHECK_EQ_UINT(fs_call_flags("glDrawArrays"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glDrawRangeElementsEXT"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glMultiDrawElements"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glCallLists"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glRectiv"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glEvalMesh2"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glDrawPixels"), FS_CALL_RENDER);
    CHECK_EQ_UINT(fs_call_flags("glClearColor"), 0);
    CHECK_EQ_UINT(fs_call_flags("glEndList"), 0);
    CHECK_EQ_UINT(fs_call_flags("glDrawBuffer"), 0);
    CHECK_EQ_UINT(fs_call_flags("glXSwapBuffers"), FS_CALL_END_FRAME | FS_CALL_SWAP_RENDERTARGET);
    CHECK_EQ_UINT(fs_call_flags("glBindFramebufferEXT"), FS_CALL_SWAP_RENDERTARGET);
    CHECK_EQ_UINT(fs_call_flags("glFinish"), 0);
    /* and on the command line: exit 2 and the message */
    if (fragsim[0] && access(fragsim, X_OK) == 0) {
        char log[300];
        snprintf(log, sizeof log, "%s/badset.log", tmpdir);
        CHECK_EQ_INT(run("--snapshot 5-3", "/nonexistent.trace", log), 2);
        char *l = slurp(log);
        CHECK(l && strstr(l, "--snapshot: bad call set '5-3'"));
        free(l);
    }
}

/* A trace's glGenTextures/glGenBuffers/glGenQueries with a huge n and no
 * output buffer: GL_OUT_OF_MEMORY (more than FS_MAX_NAMES names), and the
 * dispatcher's output space stays within FS_GEN_COUNT's bound, so the
 * context's scratch is not grown to gigabytes first (make fuzz's slow
 * units: 3.5 s and 1 GB each before FS_GEN_COUNT). */
TEST(huge_gen_counts_refused_without_scratch)
{
    static const uint16_t cmds[] = {FS_CMD_GenTextures, FS_CMD_GenBuffers, FS_CMD_GenQueries};
    static const int64_t counts[] = {(int64_t)1 << 28, 0x7fffffff, FS_GEN_NAMES_MAX + 1};
    for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++)
        for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++) {
            fs_context *c = fs_context_create(NULL, 8, 8);
            CHECK(c != NULL);
            fs_call call;
            memset(&call, 0, sizeof call);
            call.cmd = cmds[i];
            call.nargs = 2;
            call.a[0].i = counts[k];
            call.a[1].out = NULL; /* as from a trace */
            fs_submit(c, &call);
            CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
            /* Space for FS_GEN_NAMES_MAX + 1 names at most, not n. */
            CHECK(c->scratch_size <= (size_t)(FS_GEN_NAMES_MAX + 1) * sizeof(GLuint));
            fs_context_destroy(c);
        }
}

TEST_LIST = {
    TEST_ENTRY(error_log_names_the_call),
    TEST_ENTRY(replay_errors_numbered_as_apitrace_dump),
    TEST_ENTRY(snapshot_call_sets_match_apitrace_dump),
    TEST_ENTRY(bad_call_sets_are_errors),
    TEST_ENTRY(huge_gen_counts_refused_without_scratch),
    TEST_END,
};

int main(int argc, char **argv)
{
    const char *env = getenv("FRAGSIM");
    if (env)
        snprintf(fragsim, sizeof fragsim, "%s", env);
    else {
        /* BUILD/tests/test_errors -> BUILD/fragsim */
        snprintf(fragsim, sizeof fragsim, "%s", argv[0]);
        char *slash = strrchr(fragsim, '/');
        if (slash)
            snprintf(slash, sizeof fragsim - (size_t)(slash - fragsim), "/../fragsim");
    }
    snprintf(tmpdir, sizeof tmpdir, "/tmp/fs_errors_test_XXXXXX");
    if (!mkdtemp(tmpdir))
        snprintf(tmpdir, sizeof tmpdir, "/tmp");
    int rc = check_main(argc, argv, test_list);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (!getenv("KEEP") && strncmp(tmpdir, "/tmp/fs_errors_test_", 20) == 0)
        (void)system(cmd);
    return rc;
}
