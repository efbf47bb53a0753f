/*
 * Polygon modes GL_POINT and GL_LINE (GL 1.5 spec 3.5.4) with culling,
 * facing, edge flags (2.6.2), flat and smooth shading, clipping, and
 * polygon offset for points, lines and fills (3.5.5), drawn by fragsim and
 * by OSMesa (llvmpipe) with the same calls and compared pixel for pixel,
 * tolerance 0, on random scenes.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "seeded_scenes.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"


/* What a scene varies. */
typedef struct scene {
    unsigned seed;
    bool edge_flags;   /* random per-vertex edge flags */
    bool offsets;      /* random polygon offset enables and values */
    bool clipped;      /* vertices beyond the view volume */
    bool perspective;
} scene;

static const GLenum modes[3] = {GL_POINT, GL_LINE, GL_FILL};
static const GLenum prims[7] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                GL_QUAD_STRIP, GL_POLYGON, GL_TRIANGLES};

static void draw_scene(fs_context *c, const void *user, int w, int h)
{
    const scene *sc = user;
    rng r = {sc->seed * 2654435761u + 1};
    scene_view(c, w, h, sc->perspective);
    G(DepthFunc, GL_LEQUAL);
    float extent = sc->clipped ? 1.6f : 0.95f;
    /* FS_POLYMODE_DRAWS=N keeps only draw N of each scene (to look at one). */
    const char *only = getenv("FS_POLYMODE_DRAWS");
    for (int draw = 0; draw < 12; draw++) {
        bool shown = !only || draw == atoi(only);
        G(ColorMask, shown, shown, shown, shown);
        G(DepthMask, shown);
        G(PolygonMode, GL_FRONT, modes[rnd(&r) % 3]);
        G(PolygonMode, GL_BACK, modes[rnd(&r) % 3]);
        G(ShadeModel, rnd(&r) & 1 ? GL_FLAT : GL_SMOOTH);
        G(FrontFace, rnd(&r) & 1 ? GL_CW : GL_CCW);
        if (rnd(&r) % 3 == 0) {
            G(Enable, GL_CULL_FACE);
            G(CullFace, rnd(&r) & 1 ? GL_FRONT : GL_BACK);
        } else {
            G(Disable, GL_CULL_FACE);
        }
        if (sc->offsets) {
            const GLenum caps[3] = {GL_POLYGON_OFFSET_POINT, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_FILL};
            for (int k = 0; k < 3; k++) {
                if (rnd(&r) & 1)
                    G(Enable, caps[k]);
                else
                    G(Disable, caps[k]);
            }
            G(PolygonOffset, rnd_in(&r, -4, 4), rnd_in(&r, -50, 50));
        }
        GLenum prim = prims[rnd(&r) % 7];
        int n = 3 + (int)(rnd(&r) % 9);
        if (getenv("FS_POLYMODE_VERBOSE") && !c) {
            GLint pm[2], ff, cf, sm;
            glGetIntegerv(GL_POLYGON_MODE, pm); glGetIntegerv(GL_FRONT_FACE, &ff); glGetIntegerv(GL_CULL_FACE_MODE, &cf);
            glGetIntegerv(GL_SHADE_MODEL, &sm);
            float of, ou;
            glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &of); glGetFloatv(GL_POLYGON_OFFSET_UNITS, &ou);
            printf("draw %d prim %x n %d modes %x %x ff %x cull %d/%x shade %x offset %d%d%d %g %g\n", draw, prim, n, pm[0], pm[1], ff, glIsEnabled(GL_CULL_FACE), cf, sm,
                   glIsEnabled(GL_POLYGON_OFFSET_POINT), glIsEnabled(GL_POLYGON_OFFSET_LINE), glIsEnabled(GL_POLYGON_OFFSET_FILL), of, ou);
        }
        G(Begin, prim);
        float cx = rnd_in(&r, -0.6f, 0.6f), cy = rnd_in(&r, -0.6f, 0.6f);
        for (int i = 0; i < n; i++) {
            if (sc->edge_flags)
                G(EdgeFlag, rnd(&r) % 3 != 0);
            G(Color4f, rndf(&r), rndf(&r), rndf(&r), 1);
            float x, y;
            if (prim == GL_POLYGON || prim == GL_TRIANGLE_FAN) {
                /* Convex: points around a centre in order. */
                float a = 6.2831853f * (float)i / (float)n + rnd_in(&r, 0, 0.3f);
                float rad = rnd_in(&r, 0.2f, extent);
                x = cx + rad * __builtin_cosf(a);
                y = cy + rad * __builtin_sinf(a);
            } else {
                x = rnd_in(&r, -extent, extent);
                y = rnd_in(&r, -extent, extent);
            }
            G(Vertex3f, x, y, rnd_in(&r, -0.9f, 0.9f));
        }
        G0(End);
    }
    G(EdgeFlag, GL_TRUE);
    G0(Finish);
}

/* The run of scenes like `base` from seed `first` on. */
static void check_scenes(check_state *check_st_, scene base, unsigned first, unsigned count)
{
    seeded_run r = {draw_scene, &base, &base.seed, 64, 48, 7, 5, "polymode"};
    check_seeded_runs(check_st_, &r, first, count);
}

TEST(modes_and_culling_vs_osmesa) { check_scenes(check_st_, (scene){0, false, false, false, false}, 1, 40); }
TEST(edge_flags_vs_osmesa) { check_scenes(check_st_, (scene){0, true, false, false, false}, 100, 40); }
TEST(clipped_perspective_vs_osmesa) { check_scenes(check_st_, (scene){0, true, false, true, true}, 200, 40); }
TEST(polygon_offset_vs_osmesa) { check_scenes(check_st_, (scene){0, true, true, true, true}, 300, 40); }

TEST_LIST = {
    TEST_ENTRY(modes_and_culling_vs_osmesa),
    TEST_ENTRY(edge_flags_vs_osmesa),
    TEST_ENTRY(clipped_perspective_vs_osmesa),
    TEST_ENTRY(polygon_offset_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
