/*
 * Wide lines (GL 1.5 spec 3.4.2) drawn by fragsim and by OSMesa (llvmpipe)
 * with the same calls and compared pixel for pixel, tolerance 0, on random
 * widths (fractional ones included), positions, primitive types, shading,
 * depth and near/far clipping, and as the edges of GL_LINE polygons
 * (3.5.4); lines in window coordinates with ends on pixel centres and
 * corners and beyond the window.
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
    /* End points inside the window (lines beyond it and ends on pixel
     * centres and corners are draw_ends_scene's); the clipped scenes clip
     * by the near and far planes only. */
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

/* Lines in window coordinates (an orthographic projection onto the
 * window, or onto a viewport inset by 5 pixels) with ends on pixel centres,
 * on pixel corners or anywhere, up to 15 pixels beyond the window, of
 * widths 1 to 7: the end-point rule of lines between pixel centres and the
 * clipping of lines at the view volume's x/y planes (clip.c). */
static void draw_ends_scene(fs_context *c, const void *user, int w, int h)
{
    const scene *sc = user;
    rng r = {sc->seed * 2654435761u + 11};
    scene_view(c, w, h, false);
    int inset = sc->seed % 4 == 3 ? 5 : 0;
    G(Viewport, inset, inset, w - 2 * inset, h - 2 * inset);
    G(MatrixMode, GL_PROJECTION);
    G(Ortho, 0, w, 0, h, -1, 1);
    G(MatrixMode, GL_MODELVIEW);
    for (int draw = 0; draw < 12; draw++) {
        G(LineWidth, draw % 3 ? 1.0f : (float)(1 + rnd(&r) % 7));
        G(ShadeModel, rnd(&r) & 1 ? GL_FLAT : GL_SMOOTH);
        int place = (int)(rnd(&r) % 3); /* centres, corners, anywhere */
        float m = sc->clipped ? 15.0f : -1.0f;
        G(Begin, GL_LINES);
        for (int i = 0; i < 2; i++) {
            G(Color4f, rndf(&r), rndf(&r), rndf(&r), 1);
            float x = rnd_in(&r, -m, (float)w + m), y = rnd_in(&r, -m, (float)h + m);
            if (place < 2) {
                x = floorf(x) + (place ? 0.0f : 0.5f);
                y = floorf(y) + (place ? 0.0f : 0.5f);
            }
            G(Vertex3f, x, y, rnd_in(&r, -0.9f, 0.9f));
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

TEST(line_ends_on_pixel_centres_vs_osmesa)
{
    scene base = {0, 0, false, false};
    seeded_run r = {draw_ends_scene, &base, &base.seed, 40, 32, 7, 5, "line_ends"};
    check_seeded_runs(check_st_, &r, 1, 60);
}

TEST(lines_beyond_window_vs_osmesa)
{
    scene base = {0, 0, false, true};
    seeded_run r = {draw_ends_scene, &base, &base.seed, 40, 32, 7, 5, "line_clip"};
    check_seeded_runs(check_st_, &r, 100, 60);
}

TEST(wide_polygon_edges_vs_osmesa) { check_scenes(check_st_, (scene){0, 6.0f, true, true}, 200, 30); }

TEST_LIST = {
    TEST_ENTRY(wide_lines_vs_osmesa),
    TEST_ENTRY(wide_lines_clipped_vs_osmesa),
    TEST_ENTRY(wide_polygon_edges_vs_osmesa),
    TEST_ENTRY(line_ends_on_pixel_centres_vs_osmesa),
    TEST_ENTRY(lines_beyond_window_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
