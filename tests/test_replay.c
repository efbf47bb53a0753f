/*
 * Replay (driver/replay.c): frame boundaries, window size, calls fragsim
 * cannot execute counted by name, draws whose client arrays a trace did not
 * record refused rather than read, and arguments shorter than a command
 * reads reported as malformed before anything executes.  Traces are written
 * with the trace writer, so each case is exactly what the test says.
 */
#include <stdlib.h>
#include <unistd.h>
#include <jansson.h>
#include "check.h"
#include "trace_build.h"
#include "../driver/replay.h"
#include "../driver/trace.h"
#include "../pipeline/context.h"


typedef struct tb {
    fs_trace_writer *w;
    char path[256];
} tb;

static int tb_open(tb *t, const char *name)
{
    char err[256];
    snprintf(t->path, sizeof t->path, "/tmp/fragsim_test_replay_%d_%s.trace", (int)getpid(), name);
    t->w = fs_trace_create(t->path, err, sizeof err);
    return t->w ? 0 : -1;
}


static void call(tb *t, const char *name, int n, const fs_tval *args, uint32_t flags)
{
    tb_write_call(t->w, name, n, args, flags);
}

static void viewport(tb *t, int w, int h)
{
    fs_tval a[4] = {tb_ival(0), tb_ival(0), tb_ival(w), tb_ival(h)};
    call(t, "glViewport", 4, a, 0);
}

static void triangle(tb *t)
{
    fs_tval m = tb_eval(GL_TRIANGLES, "GL_TRIANGLES");
    call(t, "glBegin", 1, &m, 0);
    static const float v[3][2] = {{-1, -1}, {1, -1}, {0, 1}};
    for (int i = 0; i < 3; i++) {
        fs_tval a[2] = {tb_fval(v[i][0]), tb_fval(v[i][1])};
        call(t, "glVertex2f", 2, a, 0);
    }
    call(t, "glEnd", 0, NULL, 0);
}

typedef struct run_result {
    int calls, frames, error;
    char err[512];
    char skipped[4096];
    uint64_t skipped_total;
    int width, height;
    uint64_t digest; /* of every event: commands, arguments, the data they point to */
    bool from_record;
} run_result;

static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        h = (h ^ ((const unsigned char *)p)[i]) * 1099511628211ull; /* FNV-1a */
    return h;
}

static uint64_t event_digest(uint64_t h, fs_replay_event ev, const fs_call *c)
{
    h = mix(h, &ev, sizeof ev);
    if (ev != FS_REPLAY_CALL)
        return h;
    h = mix(h, &c->cmd, sizeof c->cmd);
    h = mix(h, &c->nargs, sizeof c->nargs);
    h = mix(h, &c->flags, sizeof c->flags);
    for (int k = 0; k < FS_MAX_ARGS; k++) {
        const fs_arg *a = &c->a[k];
        int kind = k < c->nargs ? fs_cmd_table[c->cmd].kinds[k] : -1;
        size_t es = kind >= 0 ? fs_kind_elem_size(kind) : 0;
        size_t bytes = kind == FS_K_CPTR && a->is_data ? a->count : es * a->count;
        h = mix(h, &a->count, sizeof a->count);
        h = mix(h, &a->is_data, sizeof a->is_data);
        if ((es || (kind == FS_K_CPTR && a->is_data)) && a->p)
            h = mix(h, a->p, bytes); /* where the data lives may differ, not what it is */
        else
            h = mix(h, &a->i, sizeof a->i);
    }
    return mix(h, &c->ret, sizeof c->ret);
}

static void run_once(const char *path, const char *frame_end, size_t max_record, run_result *res)
{
    memset(res, 0, sizeof *res);
    fs_replay_opts o = {frame_end, 0, 0, max_record};
    fs_replayer *r = fs_replay_open(path, &o, res->err, sizeof res->err);
    if (!r) {
        res->error = 1;
        return;
    }
    res->width = fs_replay_info_get(r)->width;
    res->height = fs_replay_info_get(r)->height;
    res->from_record = fs_replay_info_get(r)->from_record;
    fs_call c;
    fs_replay_event ev;
    while ((ev = fs_replay_next(r, &c)) != FS_REPLAY_EOF) {
        if (ev == FS_REPLAY_ERROR) {
            res->error = 2;
            snprintf(res->err, sizeof res->err, "%s", fs_replay_error(r));
            break;
        }
        if (ev == FS_REPLAY_CALL) res->calls++;
        if (ev == FS_REPLAY_FRAME_END) res->frames++;
        res->digest = event_digest(res->digest, ev, &c);
    }
    json_t *skipped = fs_replay_skipped_json(r);
    char *text = skipped ? json_dumps(skipped, 0) : NULL; /* one line: {"name": {"count": N, ...}, ...} */
    snprintf(res->skipped, sizeof res->skipped, "%s", text ? text : "(out of memory)");
    free(text);
    json_decref(skipped);
    res->skipped_total = fs_replay_skipped_total(r);
    fs_replay_close(r);
}

/* Replays twice: pass 2 from pass 1's record of decoded calls (the default)
 * and, with a record limit of one byte, from the file; both must give the
 * same events, arguments and data. */
static void run(check_state *check_st_, const char *path, const char *frame_end, run_result *res)
{
    run_result file;
    run_once(path, frame_end, 1, &file);
    run_once(path, frame_end, 0, res);
    CHECK_EQ_INT(res->error, file.error);
    CHECK_EQ_INT(res->calls, file.calls);
    CHECK_EQ_INT(res->frames, file.frames);
    CHECK(res->digest == file.digest);
    CHECK_STR(res->skipped, file.skipped);
    CHECK_STR(res->err, file.err);
    CHECK(!file.from_record);
    CHECK(res->error == 1 || res->from_record); /* else the comparison compared the file with itself */
}

/* Finishes the trace being built, replays it without error and checks its
 * frame count; false when the trace could not be written. */
static bool finish_and_run(check_state *check_st_, tb *t, run_result *r, int frames)
{
    if (fs_trace_finish(t->w) != 0)
        return false;
    run(check_st_, t->path, NULL, r);
    CHECK_EQ_INT(r->error, 0);
    CHECK_EQ_INT(r->frames, frames);
    return true;
}

TEST(frames_from_swaps_and_size_from_viewport)
{
    tb t;
    REQUIRE(tb_open(&t, "swaps") == 0);
    viewport(&t, 64, 48);
    for (int f = 0; f < 3; f++) {
        triangle(&t);
        fs_tval a[2] = {tb_ival(0), tb_ival(0)};
        call(&t, "glXSwapBuffers", 2, a, 0);
        call(&t, "glFinish", 0, NULL, 0); /* swaps win over glFinish */
    }
    run_result r;
    REQUIRE(finish_and_run(check_st_, &t, &r, 3));
    CHECK_EQ_INT(r.width, 64);
    CHECK_EQ_INT(r.height, 48);
    CHECK(strstr(r.skipped, "glXSwapBuffers") != NULL);
    CHECK_EQ_UINT(r.skipped_total, 0); /* window-system calls are not "unsupported" */
    run(check_st_, t.path, "glFinish", &r);
    CHECK_EQ_INT(r.frames, 3);
    unlink(t.path);
}

TEST(frames_from_glfinish_without_swaps)
{
    tb t;
    REQUIRE(tb_open(&t, "finish") == 0);
    viewport(&t, 32, 32);
    for (int f = 0; f < 4; f++) {
        triangle(&t);
        call(&t, "glFinish", 0, NULL, 0);
    }
    run_result r;
    REQUIRE(finish_and_run(check_st_, &t, &r, 4));
    unlink(t.path);
}

/* A trace's function names are any bytes: the skipped list stays valid JSON
 * (RFC 8259: '"', '\\' and control characters escaped; text UTF-8, so a
 * byte that is not is written as '?'), and reads back as the names. */
TEST(skipped_names_are_valid_json)
{
    tb t;
    REQUIRE(tb_open(&t, "names") == 0);
    viewport(&t, 16, 16);
    call(&t, "glQuote\"d\\Name\001", 0, NULL, 0);
    call(&t, "glLatin1\xe9", 0, NULL, 0);
    triangle(&t);
    run_result r;
    REQUIRE(finish_and_run(check_st_, &t, &r, 1));
    json_error_t e;
    json_t *o = json_loads(r.skipped, 0, &e);
    if (!o)
        CHECK_FAIL_("not JSON: %s: %s", e.text, r.skipped);
    CHECK(json_integer_value(json_object_get(json_object_get(o, "glQuote\"d\\Name\001"), "count")) == 1);
    CHECK(json_integer_value(json_object_get(json_object_get(o, "glLatin1?"), "count")) == 1);
    json_decref(o);
    unlink(t.path);
}

TEST(unknown_calls_are_counted_by_name)
{
    tb t;
    REQUIRE(tb_open(&t, "unknown") == 0);
    viewport(&t, 16, 16);
    /* glPrimitiveRestartNV: an extension command fragsim does not have. */
    call(&t, "glPrimitiveRestartNV", 0, NULL, 0);
    call(&t, "glPrimitiveRestartNV", 0, NULL, 0);
    call(&t, "glNoSuchCall", 0, NULL, 0);
    triangle(&t);
    REQUIRE(fs_trace_finish(t.w) == 0);
    run_result r;
    run(check_st_, t.path, NULL, &r);
    CHECK_EQ_INT(r.error, 0);
    CHECK(strstr(r.skipped, "\"glPrimitiveRestartNV\": {\"count\": 2") != NULL);
    CHECK(strstr(r.skipped, "glNoSuchCall") != NULL);
    CHECK_EQ_UINT(r.skipped_total, 3);
    CHECK_EQ_INT(r.frames, 1); /* no boundary at all: the whole trace is one frame */
    unlink(t.path);
}

TEST(draw_without_recorded_arrays_is_refused)
{
    tb t;
    REQUIRE(tb_open(&t, "arrays") == 0);
    viewport(&t, 16, 16);
    fs_tval p[4] = {tb_ival(3), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), tb_ival(0)};
    p[3].type = FS_TV_OPAQUE;
    p[3].u = 0x1234; /* an address in the traced program: must never be read */
    call(&t, "glVertexPointer", 4, p, 0);
    fs_tval e = tb_eval(GL_VERTEX_ARRAY, "GL_VERTEX_ARRAY");
    call(&t, "glEnableClientState", 1, &e, 0);
    fs_tval d[3] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(0), tb_ival(3)};
    call(&t, "glDrawArrays", 3, d, 0);
    /* Recorded data too short for the draw: refused as well. */
    static const float short_data[3] = {0, 0, 0};
    fs_tval q[4] = {tb_ival(3), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), tb_ival(0)};
    q[3].type = FS_TV_BLOB;
    q[3].str.ptr = (const char *)short_data;
    q[3].str.len = sizeof short_data;
    call(&t, "glVertexPointer", 4, q, 1 /* fake */);
    call(&t, "glDrawArrays", 3, d, 0);
    REQUIRE(fs_trace_finish(t.w) == 0);
    run_result r;
    run(check_st_, t.path, NULL, &r);
    CHECK_EQ_INT(r.error, 0);
    CHECK(strstr(r.skipped, "glDrawArrays (client arrays not recorded in the trace)\": {\"count\": 2") != NULL);
    unlink(t.path);
}

#define blob tb_blob

static uint64_t unsupported_count(const fs_context *c, const char *name)
{
    for (int i = 0; i < c->unsupported_feature_count; i++)
        if (strcmp(c->unsupported_feature[i].name, name) == 0)
            return c->unsupported_feature[i].count;
    return 0;
}

/* GL rejects a pointer call whose size is out of range, or one issued
 * between glBegin and glEnd; the array keeps its old, shorter data.  The
 * replayer cannot tell and lets the long draws through, so the dispatcher
 * must refuse them (the data the array holds ends at vertex 3) and a later
 * draw must still see the first call's triangle, not the rejected zeros. */
TEST(rejected_pointer_call_keeps_the_arrays_data)
{
    tb t;
    REQUIRE(tb_open(&t, "rejected") == 0);
    viewport(&t, 16, 16);
    static const float tri[6] = {-1, -1, 3, -1, -1, 3}; /* covers the window */
    static const float zeros[600];
    fs_tval good[4] = {tb_ival(2), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), blob(tri, sizeof tri)};
    call(&t, "glVertexPointer", 4, good, 0);
    fs_tval e = tb_eval(GL_VERTEX_ARRAY, "GL_VERTEX_ARRAY");
    call(&t, "glEnableClientState", 1, &e, 0);
    fs_tval bad_size[4] = {tb_ival(1), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), blob(zeros, sizeof zeros)};
    call(&t, "glVertexPointer", 4, bad_size, 0);
    fs_tval long_draw[3] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(0), tb_ival(297)};
    call(&t, "glDrawArrays", 3, long_draw, 0);
    fs_tval m = tb_eval(GL_POINTS, "GL_POINTS");
    call(&t, "glBegin", 1, &m, 0);
    fs_tval in_begin[4] = {tb_ival(2), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), blob(zeros, sizeof zeros)};
    call(&t, "glVertexPointer", 4, in_begin, 0);
    call(&t, "glEnd", 0, NULL, 0);
    call(&t, "glDrawArrays", 3, long_draw, 0);
    fs_tval draw[3] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(0), tb_ival(3)};
    call(&t, "glDrawArrays", 3, draw, 0);
    REQUIRE(fs_trace_finish(t.w) == 0);
    for (size_t max_record = 0; max_record < 2; max_record++) { /* record, then file */
        char err[512];
        fs_replay_opts o = {NULL, 0, 0, max_record};
        fs_replayer *r = fs_replay_open(t.path, &o, err, sizeof err);
        REQUIRE(r);
        CHECK(fs_replay_info_get(r)->from_record == (max_record == 0));
        fs_context *c = fs_context_create(NULL, 16, 16);
        REQUIRE(c);
        fs_call x;
        fs_replay_event ev;
        while ((ev = fs_replay_next(r, &x)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR)
            if (ev == FS_REPLAY_CALL)
                fs_submit(c, &x);
        CHECK(ev == FS_REPLAY_EOF);
        CHECK_EQ_UINT(fs_replay_skipped_total(r), 0); /* the replayer let both long draws through */
        CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
        CHECK_EQ_UINT(unsupported_count(c, "glDrawArrays (client array shorter than the draw reads)"), 2);
        CHECK_EQ_UINT(c->stats.vertices, 3);
        GLubyte px[4] = {0};
        fsglReadPixels(c, 8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        CHECK_EQ_INT(px[0], 255); /* the first call's triangle, in the default white */
        fs_context_destroy(c);
        fs_replay_close(r);
    }
    unlink(t.path);
}

TEST(short_array_argument_is_malformed)
{
    tb t;
    REQUIRE(tb_open(&t, "short") == 0);
    viewport(&t, 16, 16);
    fs_tval elems[3] = {tb_fval(1), tb_fval(2), tb_fval(3)};
    fs_tval m;
    memset(&m, 0, sizeof m);
    m.type = FS_TV_ARRAY;
    m.arr.elems = elems;
    m.arr.n = 3; /* glLoadMatrixf reads 16 */
    call(&t, "glLoadMatrixf", 1, &m, 0);
    triangle(&t);
    REQUIRE(fs_trace_finish(t.w) == 0);
    run_result r;
    run(check_st_, t.path, NULL, &r);
    CHECK_EQ_INT(r.error, 1); /* found by the first pass: nothing executed */
    CHECK(strstr(r.err, "glLoadMatrixf") != NULL);
    CHECK(strstr(r.err, "offset") != NULL);
    unlink(t.path);
}

TEST(no_viewport_and_no_size_is_an_error)
{
    tb t;
    REQUIRE(tb_open(&t, "nosize") == 0);
    triangle(&t);
    REQUIRE(fs_trace_finish(t.w) == 0);
    run_result r;
    run(check_st_, t.path, NULL, &r);
    CHECK_EQ_INT(r.error, 1);
    CHECK(strstr(r.err, "--size") != NULL);
    unlink(t.path);
}

/* Every kind of argument pass 2 takes from pass 1's record: scalars,
 * arrays decoded into C arrays, blobs (vertex data, an image), an
 * address never read, a string, unknown calls and skipped draws. */
TEST(record_replays_what_the_file_holds)
{
    tb t;
    REQUIRE(tb_open(&t, "record") == 0);
    viewport(&t, 32, 32);
    fs_tval elems[16];
    for (int i = 0; i < 16; i++)
        elems[i] = tb_fval(i == 0 || i == 5 || i == 10 || i == 15 ? 1 : 0.25 * i);
    fs_tval m;
    memset(&m, 0, sizeof m);
    m.type = FS_TV_ARRAY;
    m.arr.elems = elems;
    m.arr.n = 16;
    call(&t, "glLoadMatrixf", 1, &m, 0);
    static const float verts[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    static const unsigned char texels[4 * 4 * 4] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    for (int f = 0; f < 2; f++) {
        fs_tval vp[4] = {tb_ival(3), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), tb_ival(0)};
        vp[3].type = FS_TV_BLOB;
        vp[3].str.ptr = (const char *)verts;
        vp[3].str.len = f ? sizeof verts : 0; /* an empty blob: the draw is then refused */
        call(&t, "glVertexPointer", 4, vp, 1);
        fs_tval e = tb_eval(GL_VERTEX_ARRAY, "GL_VERTEX_ARRAY");
        call(&t, "glEnableClientState", 1, &e, 0);
        fs_tval d[3] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(0), tb_ival(3)};
        call(&t, "glDrawArrays", 3, d, 0);
        fs_tval ti[9] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_ival(0), tb_ival(GL_RGBA), tb_ival(4), tb_ival(4), tb_ival(0),
                         tb_eval(GL_RGBA, "GL_RGBA"), tb_eval(GL_UNSIGNED_BYTE, "GL_UNSIGNED_BYTE"), tb_ival(0)};
        ti[8].type = FS_TV_BLOB;
        ti[8].str.ptr = (const char *)texels;
        ti[8].str.len = sizeof texels;
        call(&t, "glTexImage2D", 9, ti, 0);
        fs_tval s;
        memset(&s, 0, sizeof s);
        s.type = FS_TV_STRING;
        s.str.ptr = "frame";
        s.str.len = 5;
        call(&t, "glStringMarkerGREMEDY", 1, &s, 0);
        triangle(&t);
        fs_tval a[2] = {tb_ival(0), tb_ival(0)};
        call(&t, "glXSwapBuffers", 2, a, 0);
    }
    run_result r;
    REQUIRE(finish_and_run(check_st_, &t, &r, 2));
    CHECK(strstr(r.skipped, "glDrawArrays (client arrays not recorded in the trace)\": {\"count\": 1") != NULL);
    CHECK(strstr(r.skipped, "glStringMarkerGREMEDY") != NULL);
    unlink(t.path);
}

/* The driver's state in the context (pipeline/context.h keeps it opaque):
 * the display lists install the driver's destructor, no command counts as
 * unsupported while every one has an executor, and sampled mode's skippable
 * calls are the draws, what glBegin/glEnd allow, glBegin, glClear and
 * glReadPixels, none of them while a list is compiled. */
TEST(driver_state_in_the_context)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    CHECK(c->driver_free == NULL);
    fsglNewList(c, 1, GL_COMPILE);
    fsglEndList(c);
    CHECK(c->driver_free == fs_driver_state_free);
    for (int i = -1; i <= FS_CMD_COUNT; i++)
        CHECK_EQ_UINT(fs_cmd_unsupported(c, i), 0);
    static const int skip[] = {FS_CMD_Begin, FS_CMD_End, FS_CMD_Vertex3f, FS_CMD_Color4ub, FS_CMD_DrawArrays,
                               FS_CMD_DrawElements, FS_CMD_CallList, FS_CMD_Clear, FS_CMD_ReadPixels};
    static const int keep[] = {FS_CMD_Enable, FS_CMD_Viewport, FS_CMD_BindTexture, FS_CMD_Finish, FS_CMD_NewList};
    for (size_t i = 0; i < sizeof skip / sizeof skip[0]; i++)
        CHECK(fs_cmd_skippable(c, skip[i]));
    for (size_t i = 0; i < sizeof keep / sizeof keep[0]; i++)
        CHECK(!fs_cmd_skippable(c, keep[i]));
    CHECK(!fs_cmd_skippable(c, -1) && !fs_cmd_skippable(c, FS_CMD_COUNT));
    fsglNewList(c, 2, GL_COMPILE_AND_EXECUTE);
    for (size_t i = 0; i < sizeof skip / sizeof skip[0]; i++)
        CHECK(!fs_cmd_skippable(c, skip[i]));
    fsglEndList(c);
    CHECK(fs_cmd_skippable(c, FS_CMD_Clear));
    fs_context_destroy(c); /* frees both lists (make sanitize) */
}

/* Sampled mode's frame signatures (fs_replay_frame_signatures): frames
 * of the same calls have the same exact and kind signatures; a frame that
 * differs only in a floating-point argument has the kind of the others
 * but not their exact signature; one that differs in an integer (a vertex
 * count, a mode) is of another kind.  The signatures are per frame of the
 * frame end chosen (swaps here; glFinish when the trace has no swaps). */
TEST(frame_signatures_of_kinds_and_repeats)
{
    tb t;
    REQUIRE(tb_open(&t, "signatures") == 0);
    viewport(&t, 32, 32);
    /* frames: A A A' B A (A': A with another colour; B: two triangles) */
    static const int tris[5] = {1, 1, 1, 2, 1};
    for (int f = 0; f < 5; f++) {
        fs_tval c[3] = {tb_fval(f == 2 ? 0.5f : 1.0f), tb_fval(0), tb_fval(0)};
        call(&t, "glColor3f", 3, c, 0);
        for (int i = 0; i < tris[f]; i++)
            triangle(&t);
        fs_tval a[2] = {tb_ival(0), tb_ival(0)};
        call(&t, "glXSwapBuffers", 2, a, 0);
        call(&t, "glFinish", 0, NULL, 0);
    }
    REQUIRE(fs_trace_finish(t.w) == 0);
    char err[512];
    for (int fin = 0; fin < 2; fin++) {
        fs_replay_opts o = {fin ? "glFinish" : NULL, 0, 0, 0};
        fs_replayer *r = fs_replay_open(t.path, &o, err, sizeof err);
        REQUIRE(r != NULL);
        const uint64_t *kind, *exact;
        CHECK_EQ_UINT(fs_replay_frame_signatures(r, &kind, &exact), 5);
        /* frame 0 carries the viewport: another frame than the others */
        CHECK(exact[1] == exact[4] && kind[1] == kind[4]);
        CHECK(exact[0] != exact[1]);
        CHECK(kind[2] == kind[1] && exact[2] != exact[1]);
        CHECK(kind[3] != kind[1]);
        fs_replay_close(r);
    }
    unlink(t.path);
}

TEST_LIST = {
    TEST_ENTRY(frames_from_swaps_and_size_from_viewport),
    TEST_ENTRY(driver_state_in_the_context),
    TEST_ENTRY(frames_from_glfinish_without_swaps),
    TEST_ENTRY(unknown_calls_are_counted_by_name),
    TEST_ENTRY(draw_without_recorded_arrays_is_refused),
    TEST_ENTRY(rejected_pointer_call_keeps_the_arrays_data),
    TEST_ENTRY(short_array_argument_is_malformed),
    TEST_ENTRY(no_viewport_and_no_size_is_an_error),
    TEST_ENTRY(record_replays_what_the_file_holds),
    TEST_ENTRY(skipped_names_are_valid_json),
    TEST_ENTRY(frame_signatures_of_kinds_and_repeats),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
