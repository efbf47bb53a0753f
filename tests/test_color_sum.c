/*
 * The secondary colour, the colour sum (GL 1.5 spec 2.7, 3.9) and the
 * fog coordinate (2.7, 3.10) against OSMesa (llvmpipe): the current
 * values as glGet answers them, images at tolerance 0 from immediate mode
 * and from the GL 1.4 arrays, and the errors of the pointer commands.
 */
#define GL_GLEXT_PROTOTYPES
#include "check.h"
#include "osmesa_util.h"

#define COMPARE_SCENE(fn, w, h, name) OSM_CHECK_SCENE(fn, w, h, name, "FS_COLOR_SUM_DUMP", "color_sum")

static void perspective(fs_context *c, int w, int h) { osm_frustum_scene(c, w, h, 0.1f, 0.1f, 0.1f, 20); }

/* Immediate mode: secondary colours of every type, sums above 1, smooth
 * and flat, with and without GL_COLOR_SUM, with fog from the depth. */
static void s_immediate(fs_context *c, int w, int h)
{
    perspective(c, w, h);
    G(Enable, GL_COLOR_SUM);
    G(Begin, GL_TRIANGLES);
    G(Color3f, 0.8f, 0.2f, 0.1f);
    G(SecondaryColor3f, 0.6f, 0.1f, 0.2f);
    G(Vertex3f, -3, -3, -3);
    G(SecondaryColor3ub, 10, 200, 255);
    G(Vertex3f, 3, -3, -3);
    G(Color3f, 0.1f, 0.5f, 0.9f);
    G(SecondaryColor3s, 12000, -400, 32767);
    G(Vertex3f, 0, 3, -12);
    G0(End);
    G(ShadeModel, GL_FLAT);
    G(Begin, GL_QUADS);
    G(SecondaryColor3d, 0.25, 0.5, 0.125);
    G(Vertex3f, -0.9f, 0.1f, -1.5f);
    G(SecondaryColor3b, 100, -100, 50);
    G(Vertex3f, -0.3f, 0.1f, -1.5f);
    G(SecondaryColor3i, 1 << 30, 1 << 29, -5);
    G(Vertex3f, -0.3f, 0.7f, -1.5f);
    G(SecondaryColor3us, 60000, 100, 30000);
    G(Vertex3f, -0.9f, 0.7f, -1.5f);
    G0(End);
    G(ShadeModel, GL_SMOOTH);
    G(Disable, GL_COLOR_SUM); /* the secondary colour is ignored */
    G(Begin, GL_TRIANGLES);
    G(SecondaryColor3f, 1, 1, 1);
    G(Vertex3f, 0.2f, 0.2f, -1.5f);
    G(Vertex3f, 0.8f, 0.2f, -1.5f);
    G(Vertex3f, 0.5f, 0.8f, -1.5f);
    G0(End);
}

static void s_fogged(fs_context *c, int w, int h)
{
    G(Enable, GL_FOG);
    G(Fogi, GL_FOG_MODE, GL_LINEAR);
    G(Fogf, GL_FOG_START, 1);
    G(Fogf, GL_FOG_END, 14);
    s_immediate(c, w, h);
}

TEST(color_sum_immediate_vs_osmesa) { COMPARE_SCENE(s_immediate, 64, 64, "immediate"); }
TEST(color_sum_with_fog_vs_osmesa) { COMPARE_SCENE(s_fogged, 64, 64, "fogged"); }

/* The fog coordinate as the source: signed coordinates (|c| is used), a
 * coordinate per vertex, and depth fog after switching back. */
static void s_fog_coord(fs_context *c, int w, int h)
{
    perspective(c, w, h);
    G(Enable, GL_FOG);
    G(Fogi, GL_FOG_MODE, GL_EXP);
    G(Fogf, GL_FOG_DENSITY, 0.4f);
    const float fc[4] = {0.9f, 0.8f, 0.2f, 1};
    G(Fogfv, GL_FOG_COLOR, fc);
    G(Fogi, GL_FOG_COORD_SRC, GL_FOG_COORD);
    G(Color3f, 0.2f, 0.3f, 1);
    G(Begin, GL_TRIANGLES);
    G(FogCoordf, -4);
    G(Vertex3f, -3, -3, -3);
    G(FogCoordd, 0.5);
    G(Vertex3f, 3, -3, -3);
    const float f2 = 9;
    G(FogCoordfv, &f2);
    G(Vertex3f, 0, 3, -12);
    G0(End);
    G(Fogi, GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    G(Begin, GL_TRIANGLES);
    G(Vertex3f, 0.2f, 0.2f, -1.5f);
    G(Vertex3f, 0.8f, 0.2f, -3.5f);
    G(Vertex3f, 0.5f, 0.8f, -1.5f);
    G0(End);
}

TEST(fog_coordinate_immediate_vs_osmesa) { COMPARE_SCENE(s_fog_coord, 64, 64, "fog_coord"); }


/* The GL 1.4 arrays: byte RGBA and float RGB secondary colours, a double
 * fog coordinate array, from glDrawArrays and glDrawElements; the index
 * and edge flag arrays enabled beside them change nothing. */
static void s_arrays(fs_context *c, int w, int h)
{
    perspective(c, w, h);
    static const float pos[] = {-3, -3, -3, 3, -3, -3, 0, 3, -12, 0.2f, 0.2f, -1.5f, 0.8f, 0.2f, -3.5f, 0.5f, 0.8f, -1.5f};
    static const float col[] = {0.8f, 0.2f, 0.1f, 0.3f, 0.9f, 0.4f, 0.1f, 0.5f, 0.9f,
                                0.5f, 0.5f, 0.5f, 0.9f, 0.1f, 0.2f, 0.2f, 0.2f, 0.8f};
    static const GLubyte sec_ub[] = {200, 10, 30, 0, 20, 250, 100, 99, 5, 5, 240, 7,
                                     90, 0, 200, 1, 255, 255, 0, 2, 0, 128, 64, 3};
    static const float sec_f[] = {0.5f, 0.1f, 0.2f, 0.1f, 0.7f, 0, 0.3f, 0.3f, 0.9f,
                                  0, 0.6f, 0.1f, 0.4f, 0, 0.3f, 0.2f, 0.9f, 0.4f};
    static const double fogc[] = {-6, 1, 4, 0.5, 3, 8};
    static const GLubyte edge[] = {1, 0, 1, 0, 1, 0};
    static const float index[] = {1, 2, 3, 4, 5, 6};
    static const GLushort idx[] = {3, 4, 5, 0, 1, 2};
    G(Enable, GL_COLOR_SUM);
    G(Enable, GL_FOG);
    G(Fogi, GL_FOG_MODE, GL_LINEAR);
    G(Fogf, GL_FOG_START, 0);
    G(Fogf, GL_FOG_END, 10);
    G(Fogi, GL_FOG_COORD_SRC, GL_FOG_COORD);
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(EnableClientState, GL_SECONDARY_COLOR_ARRAY);
    G(EnableClientState, GL_FOG_COORD_ARRAY);
    G(EnableClientState, GL_EDGE_FLAG_ARRAY);
    G(EnableClientState, GL_INDEX_ARRAY);
    G(VertexPointer, 3, GL_FLOAT, 0, pos);
    G(ColorPointer, 3, GL_FLOAT, 0, col);
    G(SecondaryColorPointer, 4, GL_UNSIGNED_BYTE, 0, sec_ub);
    G(FogCoordPointer, GL_DOUBLE, 0, fogc);
    G(EdgeFlagPointer, 0, edge);
    G(IndexPointer, GL_FLOAT, 0, index);
    G(DrawArrays, GL_TRIANGLES, 0, 6);
    G(SecondaryColorPointer, 3, GL_FLOAT, 12, sec_f);
    G(Fogi, GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    G(Translatef, 0.3f, -0.2f, -0.5f);
    G(DrawElements, GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
}

TEST(gl14_arrays_vs_osmesa) { COMPARE_SCENE(s_arrays, 64, 64, "arrays"); }

/* Lighting with GL_SEPARATE_SPECULAR_COLOR: the specular term is added
 * after texturing (a GL_MODULATE texture darkens the rest only), then
 * GL_SINGLE_COLOR with GL_COLOR_SUM enabled (no secondary colour from
 * lighting). */
static void s_separate_specular(fs_context *c, int w, int h)
{
    uint8_t tex[4 * 4 * 4];
    for (int i = 0; i < 16; i++) {
        tex[i * 4 + 0] = (uint8_t)(40 + i * 12);
        tex[i * 4 + 1] = (uint8_t)(i & 1 ? 200 : 60);
        tex[i * 4 + 2] = 90;
        tex[i * 4 + 3] = 255;
    }
    perspective(c, w, h);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(Enable, GL_TEXTURE_2D);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    const float lp[4] = {1, 2, 1, 0}, spec[4] = {1, 0.9f, 0.7f, 1}, dif[4] = {0.6f, 0.6f, 0.9f, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, lp);
    G(Lightfv, GL_LIGHT0, GL_SPECULAR, spec);
    G(Materialfv, GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    G(Materialfv, GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    G(Materialf, GL_FRONT_AND_BACK, GL_SHININESS, 12);
    G(LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    for (int pass = 0; pass < 2; pass++) {
        G(Begin, GL_QUADS);
        for (int i = 0; i < 4; i++) {
            float x = (float)(i & 1) * 2 - 1 + (float)pass * 0.4f, y = (float)(i >> 1) * 2 - 1;
            G(Normal3f, x * 0.5f, y * 0.5f, 1);
            G(TexCoord2f, (float)(i & 1), (float)(i >> 1));
            G(Vertex3f, x * 1.5f, y * 1.5f, -3.0f - (float)pass);
        }
        G0(End);
        G(LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
        G(Enable, GL_COLOR_SUM);
        G(SecondaryColor3f, 0.5f, 0.5f, 0.5f);
    }
}

TEST(separate_specular_vs_osmesa) { COMPARE_SCENE(s_separate_specular, 64, 64, "separate_specular"); }

/* glGet of the current values and of the arrays, and the pointer
 * commands' errors, after each call as OSMesa answers.  Not compared: a
 * negative stride, for which OSMesa raises GL_INVALID_VALUE and yet sets
 * the array (measured: size 3, GL_FLOAT, stride -1 after
 * glSecondaryColorPointer(3, GL_FLOAT, -1, p)); fragsim leaves it as it
 * was, as 2.8 says, since a draw cannot fetch with a negative stride. */
static void run_state_calls(fs_context *c, float *out, int *n)
{
    static const GLenum q[] = {GL_CURRENT_SECONDARY_COLOR, GL_CURRENT_FOG_COORD, GL_SECONDARY_COLOR_ARRAY_SIZE,
                               GL_SECONDARY_COLOR_ARRAY_TYPE, GL_SECONDARY_COLOR_ARRAY_STRIDE,
                               GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY_STRIDE, GL_EDGE_FLAG_ARRAY_STRIDE,
                               GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY,
                               GL_FOG_COORD_ARRAY, GL_EDGE_FLAG_ARRAY, GL_INDEX_ARRAY};
    static const float d[16];
    *n = 0;
#define STEP(call)                                                     \
    do {                                                               \
        call;                                                          \
        out[(*n)++] = (float)(c ? fsglGetError(c) : glGetError());                         \
        for (size_t k_ = 0; k_ < sizeof q / sizeof q[0]; k_++) {       \
            float v_[4] = {0, 0, 0, 0};                                \
            G(GetFloatv, q[k_], v_);                                   \
            for (int j_ = 0; j_ < 4; j_++)                             \
                out[(*n)++] = v_[j_];                                  \
        }                                                              \
    } while (0)
    STEP((void)0);
    STEP(G(SecondaryColor3f, 0.5f, 2.0f, -1.0f));
    STEP(G(SecondaryColor3ubv, (const GLubyte[3]){255, 0, 128}));
    STEP(G(SecondaryColor3iv, (const GLint[3]){-7, 1 << 30, 0}));
    STEP(G(FogCoordd, -3.5));
    STEP(G(FogCoorddv, (const GLdouble[1]){7.25}));
    STEP(G(SecondaryColorPointer, 4, GL_UNSIGNED_SHORT, 8, d));
    STEP(G(SecondaryColorPointer, 2, GL_FLOAT, 0, d));
    STEP(G(SecondaryColorPointer, 3, GL_2_BYTES, 0, d));
    STEP(G(FogCoordPointer, GL_DOUBLE, 16, d));
    STEP(G(FogCoordPointer, GL_INT, 0, d));
    STEP(G(EdgeFlagPointer, 7, d));
    STEP(G(IndexPointer, GL_SHORT, 6, d));
    STEP(G(IndexPointer, GL_BYTE, 0, d));
    STEP(G(IndexPointer, GL_UNSIGNED_INT, 0, d));
    STEP(G(EnableClientState, GL_SECONDARY_COLOR_ARRAY));
    STEP(G(EnableClientState, GL_FOG_COORD_ARRAY));
    STEP(G(EnableClientState, GL_EDGE_FLAG_ARRAY));
    STEP(G(EnableClientState, GL_INDEX_ARRAY));
    STEP(G(PushClientAttrib, GL_CLIENT_VERTEX_ARRAY_BIT));
    STEP(G(DisableClientState, GL_FOG_COORD_ARRAY));
    STEP(G(FogCoordPointer, GL_FLOAT, 4, d));
    STEP(G0(PopClientAttrib));
    STEP(G(PushAttrib, GL_CURRENT_BIT));
    STEP(G(SecondaryColor3f, 0, 0.25f, 1));
    STEP(G(FogCoordf, 2));
    STEP(G0(PopAttrib));
#undef STEP
}

TEST(gl14_state_and_errors_vs_osmesa)
{
    static float ref[32 * 57], mine[32 * 57];
    int nref = 0, nmine = 0;
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    run_state_calls(NULL, ref, &nref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    run_state_calls(c, mine, &nmine);
    fs_context_destroy(c);
    CHECK_EQ_INT(nmine, nref);
    int bad = 0;
    for (int i = 0; i < nref && i < nmine; i++)
        if (ref[i] != mine[i] && bad++ < 8)
            CHECK_FAIL_("value %d (call %d): OSMesa %g, fragsim %g", i, i / 57, ref[i], mine[i]);
    printf("  %d values compared, %d differ\n", nref, bad);
}

TEST_LIST = {
    TEST_ENTRY(color_sum_immediate_vs_osmesa),
    TEST_ENTRY(color_sum_with_fog_vs_osmesa),
    TEST_ENTRY(fog_coordinate_immediate_vs_osmesa),
    TEST_ENTRY(gl14_arrays_vs_osmesa),
    TEST_ENTRY(separate_specular_vs_osmesa),
    TEST_ENTRY(gl14_state_and_errors_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
