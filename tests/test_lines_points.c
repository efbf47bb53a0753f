/*
 * Wide lines (GL 1.5 spec 3.4.2) drawn by fragsim and by OSMesa (llvmpipe)
 * with the same calls and compared pixel for pixel, tolerance 0, on random
 * widths (fractional ones included), positions, primitive types, shading,
 * depth and near/far clipping, and as the edges of GL_LINE polygons
 * (3.5.4).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

typedef struct rng { uint64_t s; } rng;
static uint32_t rnd(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(r->s >> 33);
}
static float rndf(rng *r) { return (float)(rnd(r) & 0xffffff) / 16777216.0f; }
static float rnd_in(rng *r, float lo, float hi) { return lo + (hi - lo) * rndf(r); }

typedef struct scene {
    unsigned seed;
    float max_width;
    bool polygons;  /* GL_LINE polygons instead of line primitives */
    bool clipped;   /* end points beyond the view volume, perspective */
} scene;

static void draw_scene(fs_context *c, const void *user, int w, int h)
{
    const scene *sc = user;
    rng r = {sc->seed * 2654435761u + 7};
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.05f, 0.1f, 0.15f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    if (sc->clipped)
        G(Frustum, -1, 1, -1, 1, 1.5, 6);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    if (sc->clipped)
        G(Translatef, 0, 0, -3);
    G(Enable, GL_DEPTH_TEST);
    if (sc->polygons)
        G(PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
    const GLenum prims[3] = {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP};
    const GLenum polys[3] = {GL_TRIANGLES, GL_QUADS, GL_POLYGON};
    /* End points inside the window: lines with an end point beyond it
     * (fs_clip_line's guard-band path) and lines through pixel corners
     * (the diamond-exit tie) differ from llvmpipe in a few pixels at any
     * width, width 1 included; that is not this test's subject.  The
     * clipped scenes clip by the near and far planes only. */
    float extent = 0.9f;
    for (int draw = 0; draw < 10; draw++) {
        /* Whole, half and arbitrary widths (rounding of halves). */
        float wd = rnd_in(&r, 0.3f, sc->max_width);
        if (rnd(&r) % 3 == 0)
            wd = (float)(int)wd + 0.5f;
        G(LineWidth, wd);
        G(ShadeModel, rnd(&r) & 1 ? GL_FLAT : GL_SMOOTH);
        GLenum prim = sc->polygons ? polys[rnd(&r) % 3] : prims[rnd(&r) % 3];
        int n = 2 + (int)(rnd(&r) % 7);
        if (sc->polygons && n < 3)
            n = 3;
        G(Begin, prim);
        for (int i = 0; i < n; i++) {
            G(Color4f, rndf(&r), rndf(&r), rndf(&r), 1);
            float x = rnd_in(&r, -extent, extent), y = rnd_in(&r, -extent, extent);
            float zr = sc->clipped && !sc->polygons ? 2.5f : 0.9f;
            G(Vertex3f, x, y, rnd_in(&r, -zr, zr));
        }
        G0(End);
    }
    G0(Finish);
}

static int run_scenes(scene base, unsigned first, unsigned count, long *lit)
{
    int bad = 0;
    for (unsigned k = 0; k < count; k++) {
        scene sc = base;
        sc.seed = first + k;
        osm_pair p;
        if (!osm_pair_render(&p, 61 + (int)(k % 3) * 6, 47 + (int)(k % 2) * 6, NULL, draw_scene, &sc))
            return -1;
        if (p.d.differ) {
            bad++;
            printf("  seed %u: %ld pixels differ (max %d)\n", sc.seed, p.d.differ, p.d.maxd);
            if (getenv("FS_LINES_DUMP")) {
                char fn[128];
                snprintf(fn, sizeof fn, "/tmp/lines_%u.ppm", sc.seed);
                img_dump_ppm(fn, p.ref.color, p.c->fb.color, p.ref.w, p.ref.h, 4, true);
            }
        }
        for (long i = 0; i < (long)p.ref.w * p.ref.h; i++)
            *lit += p.ref.color[i * 4] != 13 || p.ref.color[i * 4 + 2] != 38;
        osm_pair_close(&p);
    }
    return bad;
}

TEST(wide_lines_vs_osmesa)
{
    long lit = 0;
    int bad = run_scenes((scene){0, 9.0f, false, false}, 1, 40, &lit);
    REQUIRE(bad >= 0);
    CHECK_EQ_INT(bad, 0);
    CHECK(lit > 0);
}

TEST(wide_lines_clipped_vs_osmesa)
{
    long lit = 0;
    int bad = run_scenes((scene){0, 12.0f, false, true}, 100, 30, &lit);
    REQUIRE(bad >= 0);
    CHECK_EQ_INT(bad, 0);
    CHECK(lit > 0);
}

TEST(wide_polygon_edges_vs_osmesa)
{
    long lit = 0;
    int bad = run_scenes((scene){0, 6.0f, true, true}, 200, 30, &lit);
    REQUIRE(bad >= 0);
    CHECK_EQ_INT(bad, 0);
    CHECK(lit > 0);
}

TEST_LIST = {
    TEST_ENTRY(wide_lines_vs_osmesa),
    TEST_ENTRY(wide_lines_clipped_vs_osmesa),
    TEST_ENTRY(wide_polygon_edges_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
