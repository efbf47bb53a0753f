/*
 * The dissertation's uses of the Occlusion Unit (Huettner 1999, 3.2-3.3),
 * run as tests on the GL_FRAGSIM_occlusion_unit extension:
 *  - occlusion-driven rendering of a bounding-volume hierarchy: render a
 *    node's box in GL_BRIEF_OCCLUSION, read NOHC, descend only if visible;
 *  - ray casting only through the pixels GL_VERBOSE_OCCLUSION lists.
 * (The 13-tile quadtree of Fig. 3.14 and the collision detection of 3.3.2
 * are in test_occlusion_unit.c.)  Counts are meaningful with back-face
 * culling on and convex volumes, as the text says.
 */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"
#include "../driver/capture.h"
#include "../driver/replay.h"
#include <unistd.h>

#define W 128
#define H 128

/* An axis-aligned box with outward (counter-clockwise) faces. */
static void box(fs_context *c, const float lo[3], const float hi[3])
{
    static const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    float v[8][3];
    for (int i = 0; i < 8; i++) {
        v[i][0] = i & 4 ? hi[0] : lo[0];
        v[i][1] = i & 2 ? hi[1] : lo[1];
        v[i][2] = i & 1 ? hi[2] : lo[2];
    }
    fsglBegin(c, GL_QUADS);
    for (int f = 0; f < 6; f++)
        for (int k = 0; k < 4; k++)
            fsglVertex3fv(c, v[faces[f][k]]);
    fsglEnd(c);
}

static void setup(fs_context *c)
{
    fsglEnable(c, GL_DEPTH_TEST);
    fsglEnable(c, GL_CULL_FACE);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglFrustum(c, -1, 1, -1, 1, 1, 100);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTranslatef(c, 0, 0, -6);
    fsglRotatef(c, 25, 1, 0, 0);
    fsglRotatef(c, 30, 0, 1, 0);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* NOHC of one box drawn in GL_BRIEF_OCCLUSION (one tile: the window). */
static GLuint box_nohc(fs_context *c, const float lo[3], const float hi[3])
{
    GLuint rec[GL_OCCLUSION_RECORD_WORDS];
    GLuint *bufs[1] = {rec};
    GLint sizes[1] = {GL_OCCLUSION_RECORD_WORDS};
    fsglOcclusionBuffers(c, sizes, (const GLvoid *)bufs);
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    box(c, lo, hi);
    fsglRenderMode(c, GL_RENDER);
    return rec[GL_OCCLUSION_RECORD_NOHC];
}

/* A 4x4 grid of groups of 8 small boxes behind a wall that hides the
 * left half; the hierarchy has a node per group and a leaf per box. */
#define GROUPS 16
#define PER 8
typedef struct scene { float lo[GROUPS][PER][3], hi[GROUPS][PER][3], glo[GROUPS][3], ghi[GROUPS][3]; } scene;

static void make_scene(scene *s)
{
    unsigned seed = 7;
    for (int g = 0; g < GROUPS; g++) {
        float cx = -1.5f + (float)(g % 4), cz = -2.5f - (float)(g / 4);
        for (int k = 0; k < 3; k++) {
            s->glo[g][k] = 1e9f;
            s->ghi[g][k] = -1e9f;
        }
        for (int b = 0; b < PER; b++) {
            seed = seed * 1103515245u + 12345u;
            float x = cx + (float)((seed >> 8) % 60) / 100.0f - 0.3f;
            seed = seed * 1103515245u + 12345u;
            float z = cz + (float)((seed >> 8) % 60) / 100.0f - 0.3f;
            float y = -0.5f + (float)(b % 4) * 0.25f;
            float lo[3] = {x - 0.08f, y - 0.08f, z - 0.08f}, hi[3] = {x + 0.08f, y + 0.08f, z + 0.08f};
            for (int k = 0; k < 3; k++) {
                s->lo[g][b][k] = lo[k];
                s->hi[g][b][k] = hi[k];
                if (lo[k] < s->glo[g][k]) s->glo[g][k] = lo[k];
                if (hi[k] > s->ghi[g][k]) s->ghi[g][k] = hi[k];
            }
        }
    }
}

static void draw_wall(fs_context *c)
{
    static const float lo[3] = {-3.0f, -1.5f, -1.6f}, hi[3] = {0.6f, 1.5f, -1.4f};
    fsglColor3f(c, 0.6f, 0.6f, 0.6f);
    box(c, lo, hi);
}

TEST(bvh_occlusion_culling_draws_the_same_image)
{
    static scene s;
    make_scene(&s);
    /* Reference: everything drawn. */
    fs_context *all = fs_context_create(NULL, W, H);
    REQUIRE(all != NULL);
    setup(all);
    draw_wall(all);
    for (int g = 0; g < GROUPS; g++)
        for (int b = 0; b < PER; b++) {
            fsglColor3f(all, 0.2f + 0.05f * (float)(g % 8), 0.3f + 0.08f * (float)b, 0.5f);
            box(all, s.lo[g][b], s.hi[g][b]);
        }
    /* Occlusion-driven: the wall first (the big occluder), then each group
     * whose box has NOHC > 0, then within it each box whose own box does. */
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c != NULL);
    setup(c);
    draw_wall(c);
    int groups_culled = 0, boxes_culled = 0, boxes_drawn = 0;
    for (int g = 0; g < GROUPS; g++) {
        if (box_nohc(c, s.glo[g], s.ghi[g]) == 0) {
            groups_culled++;
            continue;
        }
        for (int b = 0; b < PER; b++) {
            if (box_nohc(c, s.lo[g][b], s.hi[g][b]) == 0) {
                boxes_culled++;
                continue;
            }
            fsglColor3f(c, 0.2f + 0.05f * (float)(g % 8), 0.3f + 0.08f * (float)b, 0.5f);
            box(c, s.lo[g][b], s.hi[g][b]);
            boxes_drawn++;
        }
    }
    printf("    %d of %d groups culled, %d boxes culled inside visible groups, %d drawn\n",
           groups_culled, GROUPS, boxes_culled, boxes_drawn);
    CHECK(groups_culled > 0);
    CHECK(boxes_drawn > 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    /* Culling is conservative: the image and the depth buffer are identical. */
    CHECK(memcmp(c->fb.color, all->fb.color, (size_t)W * H * 4) == 0);
    CHECK(memcmp(c->fb.depth, all->fb.depth, (size_t)W * H * sizeof *c->fb.depth) == 0);
    fs_context_destroy(c);
    fs_context_destroy(all);
}

TEST(ray_casting_through_the_listed_pixels)
{
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c != NULL);
    setup(c);
    draw_wall(c);
    /* An object's bounding box in GL_VERBOSE_OCCLUSION: the list holds the
     * pixels where the box is visible; only those need a ray. */
    static const float lo[3] = {0.0f, -0.7f, -1.0f}, hi[3] = {1.4f, 0.7f, 0.4f};
    size_t words = 9 + 2 * (size_t)W * H;
    GLuint *rec = malloc(words * sizeof *rec);
    REQUIRE(rec != NULL);
    GLuint *bufs[1] = {rec};
    GLint sizes[1] = {(GLint)words};
    fsglOcclusionBuffers(c, sizes, (const GLvoid *)bufs);
    fsglRenderMode(c, GL_VERBOSE_OCCLUSION);
    box(c, lo, hi);
    GLint overflowed = fsglRenderMode(c, GL_RENDER);
    CHECK_EQ_INT(overflowed, 0);
    GLuint nohc = rec[GL_OCCLUSION_RECORD_NOHC];
    /* Independent recount: draw the box for real and count changed depths. */
    static uint32_t before[W * H];
    memcpy(before, c->fb.depth, sizeof before);
    box(c, lo, hi);
    static unsigned char visible[W * H];
    GLuint recount = 0;
    for (int i = 0; i < W * H; i++) {
        visible[i] = c->fb.depth[i] != before[i];
        recount += visible[i];
    }
    CHECK_EQ_UINT(nohc, recount);
    /* Walk the list: every listed pixel is a visible one, none twice, and
     * it ends with the terminator right after NOHC pairs. */
    static unsigned char seen[W * H];
    memset(seen, 0, sizeof seen);
    GLuint n = 0;
    const GLuint *p = rec + GL_OCCLUSION_RECORD_WORDS;
    while (*p != GL_OCCLUSION_LIST_END && n < recount + 1) {
        GLuint x = p[0], y = p[1];
        p += 2;
        n++;
        REQUIRE(x < W && y < H);
        CHECK(visible[y * W + x]);
        CHECK(!seen[y * W + x]);
        seen[y * W + x] = 1;
    }
    CHECK_EQ_UINT(n, nohc);
    /* A ray caster for the object inside the box needs rays through exactly
     * these pixels: the list is the visible part of the box, nothing more. */
    printf("    %u pixels listed of %d (%.1f%%): the only pixels that need a ray\n", n, W * H,
           100.0 * n / (W * H));
    CHECK(n > 0 && n < (GLuint)(W * H));
    free(rec);
    fs_context_destroy(c);
}

/* Capture of the occlusion-driven run: apitrace dump names the extension's
 * calls and enums, and replaying the trace gives the same framebuffer. */
TEST(capture_of_occlusion_calls_replays)
{
    static scene s;
    make_scene(&s);
    char path[128], err[256];
    snprintf(path, sizeof path, "/tmp/fragsim_occ_capture_%d.trace", (int)getpid());
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c != NULL);
    REQUIRE(fs_capture_open(c, path, err, sizeof err) == 0);
    fsglViewport(c, 0, 0, W, H);
    setup(c);
    draw_wall(c);
    fsglEnable(c, GL_OCCLUSION_TEST_HP);
    for (int g = 0; g < GROUPS; g++)
        if (box_nohc(c, s.glo[g], s.ghi[g]) > 0)
            for (int b = 0; b < PER; b++)
                box(c, s.lo[g][b], s.hi[g][b]);
    fs_capture_frame_end(c);
    REQUIRE(fs_capture_close(c) == 0);

    FILE *p = popen("command -v apitrace >/dev/null 2>&1 && echo yes", "r");
    char yes[8] = "";
    if (p) {
        if (!fgets(yes, sizeof yes, p))
            yes[0] = '\0';
        pclose(p);
    }
    if (yes[0] == 'y') {
        char cmd[256], line[4096];
        snprintf(cmd, sizeof cmd, "apitrace dump --color=never '%s'", path);
        p = popen(cmd, "r");
        REQUIRE(p != NULL);
        int brief = 0, buffers = 0, hp = 0;
        while (fgets(line, sizeof line, p)) {
            brief |= strstr(line, "glRenderMode(mode = GL_BRIEF_OCCLUSION)") != NULL;
            buffers |= strstr(line, "glOcclusionBuffers(") != NULL;
            hp |= strstr(line, "glEnable(cap = GL_OCCLUSION_TEST_HP)") != NULL;
        }
        pclose(p);
        CHECK(brief);
        CHECK(buffers);
        CHECK(hp);
    }

    fs_replayer *r = fs_replay_open(path, NULL, err, sizeof err);
    if (!r)
        fprintf(stderr, "  %s\n", err);
    REQUIRE(r != NULL);
    fs_context *d = fs_context_create(NULL, W, H);
    REQUIRE(d != NULL);
    fs_call call;
    fs_replay_event ev;
    while ((ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR)
        if (ev == FS_REPLAY_CALL)
            CHECK_EQ_INT(fs_submit(d, &call), 0);
    CHECK(ev == FS_REPLAY_EOF);
    CHECK(memcmp(c->fb.color, d->fb.color, (size_t)W * H * 4) == 0);
    CHECK(memcmp(c->fb.depth, d->fb.depth, (size_t)W * H * sizeof *c->fb.depth) == 0);
    fs_replay_close(r);
    fs_context_destroy(d);
    fs_context_destroy(c);
    unlink(path);
}

TEST_LIST = {
    TEST_ENTRY(capture_of_occlusion_calls_replays),
    TEST_ENTRY(bvh_occlusion_culling_draws_the_same_image),
    TEST_ENTRY(ray_casting_through_the_listed_pixels),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
