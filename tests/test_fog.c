/*
 * Fog (GL 1.5 spec 3.10) against OSMesa (llvmpipe) at tolerance 0: the
 * three modes from the fragment's eye distance on triangles, lines and
 * points, with perspective and orthographic projections (eye z of either
 * sign), smooth and flat shading, textured fragments, and parameter
 * corner cases (start == end, end < start, density 0, large densities).
 * Each scene draws the same calls on OSMesa and on the model.
 */
#include "check.h"
#include "osmesa_util.h"

/* The fog state of one scene: mode, density, start, end, colour. */
typedef struct fog_params {
    GLenum mode;
    float density, start, end;
    float color[4];
} fog_params;

static void set_fog(fs_context *c, const fog_params *f)
{
    G(Enable, GL_FOG);
    G(Fogi, GL_FOG_MODE, (GLint)f->mode);
    G(Fogf, GL_FOG_DENSITY, f->density);
    G(Fogf, GL_FOG_START, f->start);
    G(Fogf, GL_FOG_END, f->end);
    G(Fogfv, GL_FOG_COLOR, f->color);
}

/* A floor receding from z_e = -1.2 to -40 in a frustum, smooth colours,
 * then a row of lines and points above it at several depths. */
static void receding(fs_context *c, int w, int h, const fog_params *f)
{
    osm_frustum_scene(c, w, h, 0.2f, 0.3f, 0.4f, 50);
    G(Rotatef, 7, 0, 1, 0);
    set_fog(c, f);
    G(Begin, GL_TRIANGLE_STRIP);
    G(Color4f, 1, 0.9f, 0.1f, 1);
    G(Vertex3f, -3, -1, -1.2f);
    G(Color4f, 0.1f, 1, 0.6f, 0.5f);
    G(Vertex3f, 3, -1, -1.2f);
    G(Color4f, 0.9f, 0.2f, 1, 0.8f);
    G(Vertex3f, -30, -1, -40);
    G(Color4f, 1, 1, 1, 1);
    G(Vertex3f, 30, -1, -40);
    G0(End);
    G(Begin, GL_LINES);
    for (int i = 0; i < 6; i++) {
        float z = -1.5f - 4.0f * (float)i;
        G(Color3f, 1, 0.15f * (float)i, 0.3f);
        G(Vertex3f, -2, 0.2f + 0.1f * (float)i, z);
        G(Color3f, 0.2f, 1, 0.15f * (float)i);
        G(Vertex3f, 2, 0.5f, z - 8);
    }
    G0(End);
    G(PointSize, 3);
    G(Begin, GL_POINTS);
    for (int i = 0; i < 12; i++) {
        G(Color3f, 0.9f, 0.8f, 0.08f * (float)i);
        G(Vertex3f, -1.5f + 0.25f * (float)i, 0.8f, -1.3f - 3.0f * (float)i);
    }
    G0(End);
}

static const fog_params fog_linear = {GL_LINEAR, 1, 2, 30, {0.6f, 0.7f, 0.8f, 0.5f}};
static const fog_params fog_exp = {GL_EXP, 0.07f, 0, 1, {0.9f, 0.5f, 0.1f, 0}};
static const fog_params fog_exp2 = {GL_EXP2, 0.05f, 0, 1, {0.3f, 0.9f, 0.2f, 1}};
static const fog_params linear_reversed = {GL_LINEAR, 1, 25, 3, {1, 1, 1, 1}};
static const fog_params linear_degenerate = {GL_LINEAR, 1, 5, 5, {1, 0, 0, 1}};
static const fog_params exp_dense = {GL_EXP, 2.5f, 0, 1, {0, 0, 1, 1}};
static const fog_params exp2_zero = {GL_EXP2, 0, 0, 1, {0, 1, 0, 1}};

static void s_linear(fs_context *c, int w, int h) { receding(c, w, h, &fog_linear); }
static void s_exp(fs_context *c, int w, int h) { receding(c, w, h, &fog_exp); }
static void s_exp2(fs_context *c, int w, int h) { receding(c, w, h, &fog_exp2); }
static void s_reversed(fs_context *c, int w, int h) { receding(c, w, h, &linear_reversed); }
static void s_degenerate(fs_context *c, int w, int h) { receding(c, w, h, &linear_degenerate); }
static void s_dense(fs_context *c, int w, int h) { receding(c, w, h, &exp_dense); }
static void s_zero(fs_context *c, int w, int h) { receding(c, w, h, &exp2_zero); }

#define COMPARE_SCENE(fn, w, h, name) OSM_CHECK_SCENE(fn, w, h, name, "FS_FOG_DUMP", "fog")

TEST(linear_fog_vs_osmesa) { COMPARE_SCENE(s_linear, 96, 80, "linear"); }
TEST(exp_fog_vs_osmesa) { COMPARE_SCENE(s_exp, 96, 80, "exp"); }
TEST(exp2_fog_vs_osmesa) { COMPARE_SCENE(s_exp2, 96, 80, "exp2"); }

TEST(fog_parameter_corners_vs_osmesa)
{
    COMPARE_SCENE(s_reversed, 64, 48, "linear_reversed");
    COMPARE_SCENE(s_degenerate, 64, 48, "linear_start_eq_end");
    COMPARE_SCENE(s_dense, 64, 48, "exp_dense");
    COMPARE_SCENE(s_zero, 64, 48, "exp2_density_0");
}

/* An orthographic volume around the eye: quads at z_e > 0 and z_e < 0
 * (the distance is |z_e|), flat shaded, on black. */
static void s_ortho_flat(fs_context *c, int w, int h)
{
    osm_frustum_scene(c, w, h, 0, 0, 0, 20);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Ortho, -1, 1, -1, 1, -10, 10); /* instead of the frustum */
    G(MatrixMode, GL_MODELVIEW);
    G(ShadeModel, GL_FLAT);
    const fog_params f = {GL_LINEAR, 1, 0, 9, {0.25f, 0.5f, 0.75f, 1}};
    set_fog(c, &f);
    G(Begin, GL_QUADS);
    G(Color3f, 1, 1, 0);
    G(Vertex3f, -1, -1, 8);
    G(Vertex3f, 0, -1, 8);
    G(Vertex3f, 0, 1, -1);
    G(Vertex3f, -1, 1, -1);
    G(Color3f, 0, 1, 1);
    G(Vertex3f, 0, -1, -8);
    G(Vertex3f, 1, -1, -8);
    G(Vertex3f, 1, 1, 3);
    G(Vertex3f, 0, 1, 3);
    G0(End);
}

TEST(ortho_flat_fog_vs_osmesa) { COMPARE_SCENE(s_ortho_flat, 64, 64, "ortho_flat"); }

/* A textured (GL_MODULATE) floor: fog applies to the textured colour. */
static void s_textured(fs_context *c, int w, int h)
{
    uint8_t tex[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        tex[i * 4 + 0] = (uint8_t)(i * 4);
        tex[i * 4 + 1] = (uint8_t)(255 - i * 3);
        tex[i * 4 + 2] = (uint8_t)((i & 1) ? 255 : 40);
        tex[i * 4 + 3] = 255;
    }
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(Enable, GL_TEXTURE_2D);
    G(Viewport, 0, 0, w, h);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1, 1, -1, 1, 1, 30);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    const fog_params f = {GL_EXP2, 0.12f, 0, 1, {0.5f, 0.5f, 0.5f, 1}};
    set_fog(c, &f);
    G(Color3f, 1, 0.8f, 0.9f);
    G(Begin, GL_QUADS);
    G(TexCoord2f, 0, 0);
    G(Vertex3f, -2, -1, -1.1f);
    G(TexCoord2f, 1, 0);
    G(Vertex3f, 2, -1, -1.1f);
    G(TexCoord2f, 1, 4);
    G(Vertex3f, 12, -1, -28);
    G(TexCoord2f, 0, 4);
    G(Vertex3f, -12, -1, -28);
    G0(End);
}

TEST(textured_fog_vs_osmesa) { COMPARE_SCENE(s_textured, 80, 64, "textured"); }

TEST_LIST = {
    TEST_ENTRY(linear_fog_vs_osmesa),
    TEST_ENTRY(exp_fog_vs_osmesa),
    TEST_ENTRY(exp2_fog_vs_osmesa),
    TEST_ENTRY(fog_parameter_corners_vs_osmesa),
    TEST_ENTRY(ortho_flat_fog_vs_osmesa),
    TEST_ENTRY(textured_fog_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
