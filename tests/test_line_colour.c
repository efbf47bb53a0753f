/*
 * Colours whose value x 255 lies near a half (0.1 -> 25.5, 0.5 -> 127.5) on
 * lines and triangles under a perspective projection, smooth shading, the
 * same colour at every vertex (as xscreensaver's boxed draws its grid):
 * drawn by fragsim and by OSMesa (llvmpipe) with the same calls and compared
 * pixel for pixel, tolerance 0.  Interpolating c/w and 1/w and dividing
 * (GL 1.5 spec 3.5.1 eq. 3.7) may land one ulp below c, which rounds to the
 * lower 8-bit value; the reference decides what the model must do.
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
    GLenum prim;
    bool flush;
} scene;

static void draw_scene(fs_context *c, const void *user, int w, int h)
{
    const scene *sc = user;
    rng r = {sc->seed * 2654435761u + 5};
    scene_view(c, w, h, true);
    G(Disable, GL_DEPTH_TEST);
    const float cols[3][3] = {{0.1f, 0.1f, 0.6f}, {0.2f, 0.5f, 0.2f}, {0.3f, 0.7f, 0.9f}};
    for (int draw = 0; draw < 12; draw++) {
        const float *col = cols[rnd(&r) % 3];
        G(Color3f, col[0], col[1], col[2]);
        G(Begin, sc->prim);
        int n = sc->prim == GL_LINES ? 2 : 3;
        for (int i = 0; i < n; i++)
            G(Vertex3f, rnd_in(&r, -1.2f, 1.2f), rnd_in(&r, -1.2f, 1.2f), rnd_in(&r, -1.4f, 1.4f));
        G0(End);
        /* A command that makes Mesa flush its buffered vertices (its matrix
         * commands do): without one, a glColor between two primitives
         * makes Mesa's vertex buffer carry the colour per vertex, and the
         * next primitive's colour is interpolated after all (not modelled). */
        if (sc->flush)
            G(Translatef, 0, 0, 0);
    }
    G0(Finish);
}

TEST(constant_colour_perspective_lines_vs_osmesa)
{
    scene base = {0, GL_LINES, true};
    seeded_run r = {draw_scene, &base, &base.seed, 64, 48, 7, 5, "ccol_lines"};
    check_seeded_runs(check_st_, &r, 1, 40);
}

TEST(constant_colour_perspective_triangles_vs_osmesa)
{
    scene base = {0, GL_TRIANGLES, true};
    seeded_run r = {draw_scene, &base, &base.seed, 64, 48, 7, 5, "ccol_tris"};
    check_seeded_runs(check_st_, &r, 1, 40);
}

TEST_LIST = {
    TEST_ENTRY(constant_colour_perspective_lines_vs_osmesa),
    TEST_ENTRY(constant_colour_perspective_triangles_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
