/*
 * Scene generators (traces/): each scene at small scale is written to a
 * temporary directory through the library API, then checked for
 *   - its size: the triangles per frame equal the scene's target (the
 *     budget fitting is exact), and count-only mode reports the same as the
 *     real capture (so `scenegen --list` and docs/scenes.md are truthful);
 *   - determinism: a second generation is byte-identical;
 *   - read-back: the trace reader decodes it without error, with the calls
 *     and frames the generator issued, and an independent triangle count
 *     over the decoded calls (primitives, draws, display lists expanded at
 *     glCallList) equals the generator's.
 * Paper scale is checked in count-only mode against the papers' numbers.
 *
 * The scene sources are compiled into this test (the test link line has
 * the library but not traces/), all but traces/scenegen.c, which has main.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "../traces/sg.c"
#include "../traces/sg_scenes.c"
#include "../traces/scene_city.c"
#include "../traces/scene_cathedral.c"
#include "../traces/scene_forest.c"
#include "../traces/scene_garbage.c"
#include "../traces/scene_terrain.c"
#include "../traces/scene_demo.c"
#include "../traces/scene_textured.c"
#include "../traces/scene_bench.c"
#include "../driver/trace.h"

typedef struct readback {
    uint64_t calls;          /* real calls, excluding frame ends and gl*Pointer */
    uint64_t pointer_calls;  /* real (non-fake) gl*Pointer calls */
    uint64_t frames;
    uint64_t tris;
    int error;
    char msg[256];
} readback;

static uint64_t tv_uint(const fs_tval *v)
{
    if (!v) return 0;
    switch (v->type) {
    case FS_TV_SINT:
    case FS_TV_ENUM: return (uint64_t)v->i;
    case FS_TV_UINT:
    case FS_TV_BITMASK: return v->u;
    case FS_TV_FLOAT:
    case FS_TV_DOUBLE: return (uint64_t)v->d;
    default: return 0;
    }
}

/* Counts triangles from decoded calls alone: no fragsim statistics and no
 * sg emitter involved. */
static void read_trace(const char *path, readback *rb)
{
    memset(rb, 0, sizeof *rb);
    char err[256];
    fs_trace_reader *r = fs_trace_open(path, err, sizeof err);
    if (!r) {
        rb->error = 1;
        snprintf(rb->msg, sizeof rb->msg, "%s", err);
        return;
    }
    enum { MAXL = 4096 };
    uint64_t *lists = calloc(MAXL, sizeof *lists);
    uint64_t prim_verts = 0, compile_tris = 0;
    GLenum mode = 0;
    unsigned compiling = 0;
    fs_tcall call;
    int rc;
    while ((rc = fs_trace_next(r, &call)) == 1) {
        const char *n = call.name;
        if (call.flags & FS_TCALL_FAKE) continue;
        if (!strcmp(n, "glXSwapBuffers")) {
            rb->frames++;
            continue;
        }
        size_t len = strlen(n);
        if (len > 7 && !strcmp(n + len - 7, "Pointer")) {
            rb->pointer_calls++;
            continue;
        }
        rb->calls++;
        uint64_t t = 0;
        if (!strcmp(n, "glBegin")) {
            mode = (GLenum)tv_uint(&call.args[0]);
            prim_verts = 0;
        } else if (!strncmp(n, "glVertex", 8) || !strcmp(n, "glArrayElement")) {
            prim_verts++;
        } else if (!strcmp(n, "glEnd")) {
            t = sg_prim_tris(mode, prim_verts);
        } else if (!strcmp(n, "glDrawArrays")) {
            t = sg_prim_tris((GLenum)tv_uint(&call.args[0]), tv_uint(&call.args[2]));
        } else if (!strcmp(n, "glDrawElements")) {
            t = sg_prim_tris((GLenum)tv_uint(&call.args[0]), tv_uint(&call.args[1]));
        } else if (!strcmp(n, "glNewList")) {
            compiling = (unsigned)tv_uint(&call.args[0]);
            compile_tris = 0;
            if (compiling >= MAXL || tv_uint(&call.args[1]) != GL_COMPILE) rb->error = 2;
        } else if (!strcmp(n, "glEndList")) {
            if (compiling && compiling < MAXL) lists[compiling] = compile_tris;
            compiling = 0;
        } else if (!strcmp(n, "glCallList")) {
            unsigned l = (unsigned)tv_uint(&call.args[0]);
            t = l < MAXL ? lists[l] : 0;
        }
        if (compiling) compile_tris += t;
        else rb->tris += t;
    }
    if (rc < 0) {
        rb->error = 1;
        snprintf(rb->msg, sizeof rb->msg, "%s", fs_trace_error(r));
    } else if (rb->error == 2) {
        snprintf(rb->msg, sizeof rb->msg, "unexpected glNewList");
    }
    free(lists);
    fs_trace_close(r);
}

static int same_file(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int same = fa && fb;
    while (same) {
        int ca = fgetc(fa), cb = fgetc(fb);
        if (ca != cb) same = 0;
        if (ca == EOF || cb == EOF) break;
    }
    if (fa) fclose(fa);
    if (fb) fclose(fb);
    return same;
}

static long file_size(const char *p)
{
    FILE *f = fopen(p, "rb");
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fclose(f);
    return n;
}

static void check_scene(check_state *check_st_, const char *name)
{
    const sg_scene *sc = sg_find_scene(name);
    REQUIRE(sc != NULL);
    char dir[] = "/tmp/fs_scenes_XXXXXX";
    REQUIRE(mkdtemp(dir) != NULL);
    char a[256], b[256], err[512] = "";
    snprintf(a, sizeof a, "%s/%s_a.trace", dir, name);
    snprintf(b, sizeof b, "%s/%s_b.trace", dir, name);
    sg_params p;
    REQUIRE(sg_default_params(sc, "small", &p) == 0);

    sg_report ra, rb, rc;
    int ok = sg_generate(sc, &p, a, &ra, err, sizeof err);
    if (ok != 0) fprintf(stderr, "  %s: %s\n", name, err);
    REQUIRE(ok == 0);
    CHECK(file_size(a) > 0);
    CHECK_EQ_INT(ra.frames, p.frames);
    CHECK(ra.tris_total > 0);
    /* Every frame draws the whole model. */
    CHECK_EQ_UINT(ra.min_frame_tris, ra.max_frame_tris);
    CHECK_EQ_UINT(ra.tris_total, ra.max_frame_tris * (uint64_t)p.frames);
    /* Budget fitting is exact except for the fixed demo. */
    if (sc->run != sg_scene_demo) CHECK_EQ_UINT(ra.max_frame_tris, p.target);
    /* Small means small: a few thousand triangles at most 256x256. */
    CHECK(ra.max_frame_tris <= 8000);
    CHECK(p.width <= 256 && p.height <= 256);

    REQUIRE(sg_count(sc, &p, &rc, err, sizeof err) == 0);
    CHECK_EQ_UINT(rc.tris_total, ra.tris_total);
    CHECK_EQ_UINT(rc.calls, ra.calls);

    REQUIRE(sg_generate(sc, &p, b, &rb, err, sizeof err) == 0);
    CHECK(same_file(a, b));

    readback t;
    read_trace(a, &t);
    if (t.error) fprintf(stderr, "  %s: read back: %s\n", name, t.msg);
    CHECK_EQ_INT(t.error, 0);
    CHECK_EQ_UINT(t.frames, (uint64_t)ra.frames);
    CHECK_EQ_UINT(t.calls, ra.calls - ra.pointer_calls);
    CHECK_EQ_UINT(t.tris, ra.tris_total);

    unlink(a);
    unlink(b);
    rmdir(dir);
}

TEST(city) { check_scene(check_st_, "city"); }
TEST(norwich) { check_scene(check_st_, "norwich"); }
TEST(cathedrals) { check_scene(check_st_, "cathedrals"); }
TEST(forest) { check_scene(check_st_, "forest"); }
TEST(garbage) { check_scene(check_st_, "garbage"); }
TEST(terrain) { check_scene(check_st_, "terrain"); }
TEST(demo) { check_scene(check_st_, "demo"); }
TEST(textured) { check_scene(check_st_, "textured"); }
TEST(bench8) { check_scene(check_st_, "bench8"); }
TEST(bench32) { check_scene(check_st_, "bench32"); }

/* Paper scale, counted without rendering: the papers' triangle counts. */
TEST(paper_counts)
{
    for (int i = 0; i < sg_scene_count; i++) {
        const sg_scene *sc = &sg_scenes[i];
        sg_params p;
        sg_report r;
        char err[512] = "";
        REQUIRE(sg_default_params(sc, "paper", &p) == 0);
        int rc = sg_count(sc, &p, &r, err, sizeof err);
        if (rc != 0) fprintf(stderr, "  %s: %s\n", sc->name, err);
        CHECK_EQ_INT(rc, 0);
        if (sc->paper_tris) CHECK_EQ_UINT(r.max_frame_tris, sc->paper_tris);
        else if (sc->run != sg_scene_demo) CHECK_EQ_UINT(r.max_frame_tris, 100000);
    }
}

/* The counting rule itself (GL 1.5 spec 2.6.1), since the read-back check
 * shares it with the emitter. */
TEST(prim_tris)
{
    CHECK_EQ_UINT(sg_prim_tris(GL_TRIANGLES, 7), 2);
    CHECK_EQ_UINT(sg_prim_tris(GL_TRIANGLE_STRIP, 5), 3);
    CHECK_EQ_UINT(sg_prim_tris(GL_TRIANGLE_FAN, 2), 0);
    CHECK_EQ_UINT(sg_prim_tris(GL_POLYGON, 6), 4);
    CHECK_EQ_UINT(sg_prim_tris(GL_QUADS, 9), 4);
    CHECK_EQ_UINT(sg_prim_tris(GL_QUAD_STRIP, 7), 4);
    CHECK_EQ_UINT(sg_prim_tris(GL_QUAD_STRIP, 3), 0);
    CHECK_EQ_UINT(sg_prim_tris(GL_LINES, 8), 0);
}

/* A different seed must give a different scene (the seed is really used). */
TEST(seed_changes_scene)
{
    const sg_scene *sc = sg_find_scene("garbage");
    REQUIRE(sc != NULL);
    char dir[] = "/tmp/fs_scenes_XXXXXX";
    REQUIRE(mkdtemp(dir) != NULL);
    char a[256], b[256], err[512];
    snprintf(a, sizeof a, "%s/s1.trace", dir);
    snprintf(b, sizeof b, "%s/s2.trace", dir);
    sg_params p;
    sg_report r;
    REQUIRE(sg_default_params(sc, "small", &p) == 0);
    REQUIRE(sg_generate(sc, &p, a, &r, err, sizeof err) == 0);
    p.seed = 2;
    REQUIRE(sg_generate(sc, &p, b, &r, err, sizeof err) == 0);
    CHECK(!same_file(a, b));
    unlink(a);
    unlink(b);
    rmdir(dir);
}

TEST_LIST = {
    TEST_ENTRY(prim_tris), TEST_ENTRY(city), TEST_ENTRY(norwich), TEST_ENTRY(cathedrals),
    TEST_ENTRY(forest), TEST_ENTRY(garbage), TEST_ENTRY(terrain), TEST_ENTRY(demo), TEST_ENTRY(textured),
    TEST_ENTRY(bench8), TEST_ENTRY(bench32), TEST_ENTRY(paper_counts), TEST_ENTRY(seed_changes_scene),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
