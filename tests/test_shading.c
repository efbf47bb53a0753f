/*
 * Shading and primitive rules found by replaying real programs (issue 17),
 * each drawn by fragsim and by OSMesa (llvmpipe) with the same calls and
 * compared pixel for pixel, tolerance 0:
 *  - glMaterial between glBegin and glEnd (GL 1.5 spec 2.6.3), per face and
 *    per vertex, in immediate mode and in a display list;
 *  - GL_FLAT shading's colour as a constant under perspective (2.14.7),
 *    seen through blending of alpha 0.9;
 *  - wide points whose vertex lies outside the clip volume (2.12, 3.3).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

typedef osm_scene_fn scene_fn;

/* Renders on both and returns the pixels that differ at all (-1 when a
 * context cannot be made); *errors gets the model's glGetError. */
static long compare(scene_fn scene, int w, int h, const char *name, GLenum *errors)
{
    return osm_compare_scene(scene, w, h, name, "FS_SHADING_DUMP", "shading", errors);
}

/* ---- glMaterial between Begin and End ---- */

static void lit_setup(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.1f, 0.1f, 0.15f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1, 1, -0.75, 0.75, 2, 10);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -5);
    G(Enable, GL_DEPTH_TEST);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    const float pos[4] = {1, 2, 3, 0}, spec[4] = {1, 1, 1, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, pos);
    G(Lightfv, GL_LIGHT0, GL_SPECULAR, spec);
}

static void mat(fs_context *c, GLenum face, GLenum pname, float r, float g, float b, float a)
{
    const float v[4] = {r, g, b, a};
    G(Materialfv, face, pname, v);
}

/* A cube of quads with one material per face (set before each face's
 * vertices, as real programs do), seen at an angle. */
static void cube_faces(fs_context *c)
{
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    static const float col[6][3] = {{0.9f, 0.2f, 0.1f}, {0.1f, 0.8f, 0.2f}, {0.2f, 0.3f, 0.9f},
                                    {0.8f, 0.8f, 0.1f}, {0.7f, 0.1f, 0.7f}, {0.1f, 0.7f, 0.7f}};
    G(Begin, GL_QUADS);
    for (int f = 0; f < 6; f++) {
        mat(c, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, col[f][0], col[f][1], col[f][2], 1);
        if (f == 2)
            G(Materialf, GL_FRONT, GL_SHININESS, 12.0f);
        G(Normal3fv, n[f]);
        /* Two axes spanning the face. */
        float u[3] = {n[f][1], n[f][2], n[f][0]}, v[3];
        v[0] = n[f][1] * u[2] - n[f][2] * u[1];
        v[1] = n[f][2] * u[0] - n[f][0] * u[2];
        v[2] = n[f][0] * u[1] - n[f][1] * u[0];
        static const float s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; k++)
            G(Vertex3f, 0.6f * (n[f][0] + s[k][0] * u[0] + s[k][1] * v[0]),
              0.6f * (n[f][1] + s[k][0] * u[1] + s[k][1] * v[1]),
              0.6f * (n[f][2] + s[k][0] * u[2] + s[k][1] * v[2]));
    }
    G0(End);
}

/* A triangle strip whose material changes from vertex to vertex, so that
 * triangles straddle the changes (per-vertex material). */
static void strip_per_vertex(fs_context *c)
{
    G(Normal3f, 0, 0.3f, 1);
    G(Begin, GL_TRIANGLE_STRIP);
    for (int i = 0; i < 8; i++) {
        float t = (float)i / 7;
        if (i % 3 != 1) {
            mat(c, GL_FRONT_AND_BACK, GL_DIFFUSE, t, 1 - t, 0.5f, 1);
            mat(c, GL_FRONT, GL_EMISSION, 0.1f * (float)(i % 2), 0, 0.2f * t, 1);
            mat(c, GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, t, 1);
        }
        G(Vertex3f, -1.3f + 2.6f * t, (i & 1) ? -0.6f : -0.95f, 0.5f);
    }
    G0(End);
}

static void scene_material_immediate(fs_context *c, int w, int h)
{
    lit_setup(c, w, h);
    G0(PushMatrix);
    G(Translatef, -0.5f, 0.25f, 0);
    G(Rotatef, 30, 1, 0, 0);
    G(Rotatef, -40, 0, 1, 0);
    cube_faces(c);
    G0(PopMatrix);
    strip_per_vertex(c);
}

/* The same primitives compiled into a display list (GL_COMPILE) and
 * called twice. */
static void scene_material_list(fs_context *c, int w, int h)
{
    lit_setup(c, w, h);
    GLuint l = GR(GenLists, 1);
    G(NewList, l, GL_COMPILE);
    cube_faces(c);
    G0(EndList);
    G0(PushMatrix);
    G(Translatef, -0.9f, 0.2f, 0);
    G(Rotatef, 25, 1, 1, 0);
    G(CallList, l);
    G0(PopMatrix);
    G0(PushMatrix);
    G(Translatef, 0.9f, 0.2f, 0);
    G(Rotatef, -35, 0, 1, 1);
    G(CallList, l);
    G0(PopMatrix);
    G(NewList, l + 1, GL_COMPILE_AND_EXECUTE);
    strip_per_vertex(c);
    G0(EndList);
}

/* With GL_COLOR_MATERIAL tracking the diffuse colour, glMaterial between
 * Begin and End changes the other properties per vertex, and the tracked
 * one follows glColor. */
static void scene_material_color_tracking(fs_context *c, int w, int h)
{
    lit_setup(c, w, h);
    G(ColorMaterial, GL_FRONT, GL_DIFFUSE);
    G(Enable, GL_COLOR_MATERIAL);
    G(Normal3f, 0.2f, 0.2f, 1);
    G(Begin, GL_TRIANGLE_STRIP);
    for (int i = 0; i < 8; i++) {
        float t = (float)i / 7;
        G(Color3f, 0.3f + 0.5f * t, 0.2f, 0.8f - 0.5f * t);
        if (i % 2 == 0) {
            mat(c, GL_FRONT, GL_AMBIENT, 0.1f, t, 0.3f, 1);
            mat(c, GL_FRONT, GL_DIFFUSE, 1, 1, 0, 1); /* tracked: the colour wins */
            mat(c, GL_FRONT, GL_SPECULAR, t, 0.6f, 0.6f, 1);
            G(Materialf, GL_FRONT, GL_SHININESS, 4.0f + 20.0f * t);
        }
        G(Vertex3f, -1.3f + 2.6f * t, (i & 1) ? 0.7f : -0.7f, 0);
    }
    G0(End);
}

TEST(material_between_begin_end_vs_osmesa)
{
    GLenum err;
    CHECK_EQ_INT(compare(scene_material_immediate, 96, 72, "material_immediate", &err), 0);
    CHECK_EQ_INT(err, GL_NO_ERROR);
    CHECK_EQ_INT(compare(scene_material_list, 96, 72, "material_list", &err), 0);
    CHECK_EQ_INT(err, GL_NO_ERROR);
    CHECK_EQ_INT(compare(scene_material_color_tracking, 96, 72, "material_tracking", &err), 0);
    CHECK_EQ_INT(err, GL_NO_ERROR);
}

/* ---- flat shading under perspective ---- */

/* Flat-shaded, blended triangles, lines and points at several depths of a
 * perspective projection, provoking colours with alpha 0.9 (and others)
 * over a grey background: an interpolated 0.89999992 blends one level off. */
static void scene_flat_blend(fs_context *c, int w, int h)
{
    osm_frustum_scene(c, w, h, 0.5f, 0.5f, 0.5f, 20);
    G(ShadeModel, GL_FLAT);
    G(Enable, GL_BLEND);
    G(BlendFunc, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    static const float alpha[4] = {0.9f, 0.3f, 0.7f, 0.55f};
    for (int i = 0; i < 4; i++) {
        float x = -0.9f + 0.45f * (float)i;
        G(Begin, GL_TRIANGLES);
        G(Color4f, 0.2f, 0.9f, 0.1f, 0.2f);
        G(Vertex3f, x, -0.9f, -1.5f);
        G(Color4f, 0.7f, 0.1f, 0.3f, 0.6f);
        G(Vertex3f, x + 0.4f, -0.8f, -6.0f);
        G(Color4f, 0.3f + 0.1f * (float)i, 0.6f, 0.9f, alpha[i]); /* provoking */
        G(Vertex3f, x + 0.1f, 0.2f, -3.0f - (float)i);
        G0(End);
    }
    G(LineWidth, 1);
    G(Begin, GL_LINES);
    G(Color4f, 1, 0, 0, 0.2f);
    G(Vertex3f, -0.9f, 0.5f, -1.2f);
    G(Color4f, 0.3f, 0.8f, 0.6f, 0.9f);
    G(Vertex3f, 0.9f, 0.7f, -9.0f);
    G0(End);
    G(PointSize, 5);
    G(Begin, GL_POINTS);
    for (int i = 0; i < 6; i++) {
        G(Color4f, 0.1f * (float)i, 0.35f, 0.8f, 0.9f);
        G(Vertex3f, -0.8f + 0.3f * (float)i, 0.85f, -1.5f - 2.0f * (float)i);
    }
    G0(End);
}

TEST(flat_shading_constant_colour_vs_osmesa)
{
    GLenum err;
    CHECK_EQ_INT(compare(scene_flat_blend, 64, 64, "flat_blend", &err), 0);
    CHECK_EQ_INT(err, GL_NO_ERROR);
}

/* ---- wide points and the clip volume ---- */

/* Size-9 points centred just outside, on and just inside each edge of the
 * window, then of a viewport smaller than the window (a point inside the
 * viewport but near its edge draws its whole square beyond it). */
static void scene_wide_points(fs_context *c, int w, int h)
{
    G(ClearColor, 0, 0, 0, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Ortho, 0, w, 0, h, -1, 1);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(PointSize, 9);
    static const float d[] = {-0.4f, -0.01f, 0.0f, 0.01f, 0.4f};
    G(Begin, GL_POINTS);
    for (int k = 0; k < 5; k++) {
        float y = 6.0f + 5.0f * (float)k;
        G(Color3f, 1, 0.2f * (float)k, 0);
        G(Vertex2f, d[k], y);
        G(Vertex2f, (float)w - d[k], y);
        G(Vertex2f, y, d[k]);
        G(Vertex2f, y, (float)h - d[k]);
    }
    G0(End);
    G(Viewport, 8, 8, 16, 16);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Ortho, 0, 16, 0, 16, -1, 1);
    G(MatrixMode, GL_MODELVIEW);
    G(Color3f, 0, 1, 1);
    G(Begin, GL_POINTS);
    G(Vertex2f, -0.4f, 8);
    G(Vertex2f, 0.4f, 4);
    G(Vertex2f, 16.4f, 8);
    G(Vertex2f, 15.6f, 12);
    G0(End);
}

TEST(wide_points_outside_clip_volume_vs_osmesa)
{
    GLenum err;
    CHECK_EQ_INT(compare(scene_wide_points, 40, 40, "wide_points", &err), 0);
    CHECK_EQ_INT(err, GL_NO_ERROR);
}

TEST_LIST = {
    TEST_ENTRY(material_between_begin_end_vs_osmesa),
    TEST_ENTRY(flat_shading_constant_colour_vs_osmesa),
    TEST_ENTRY(wide_points_outside_clip_volume_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
