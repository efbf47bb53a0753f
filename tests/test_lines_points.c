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
#include "seeded_scenes.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"


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
    scene_view(c, w, h, sc->clipped);
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

/* The run of scenes like `base` from seed `first` on. */
static void check_scenes(check_state *check_st_, scene base, unsigned first, unsigned count)
{
    seeded_run r = {draw_scene, &base, &base.seed, 61, 47, 6, 6, "lines"};
    check_seeded_runs(check_st_, &r, first, count);
}

TEST(wide_lines_vs_osmesa) { check_scenes(check_st_, (scene){0, 9.0f, false, false}, 1, 40); }

TEST(wide_lines_clipped_vs_osmesa) { check_scenes(check_st_, (scene){0, 12.0f, false, true}, 100, 30); }

TEST(wide_polygon_edges_vs_osmesa) { check_scenes(check_st_, (scene){0, 6.0f, true, true}, 200, 30); }

TEST_LIST = {
    TEST_ENTRY(wide_lines_vs_osmesa),
    TEST_ENTRY(wide_lines_clipped_vs_osmesa),
    TEST_ENTRY(wide_polygon_edges_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
