/*
 * Evaluators (GL 1.5 spec 5.1, pipeline/evaluator.c) against OSMesa
 * (llvmpipe) at tolerance 0: curves and surfaces of random control points,
 * orders 1..8, every target, glEvalCoord in each form, glEvalPoint and
 * glEvalMesh in each mode, GL_AUTO_NORMAL with lighting, display lists that
 * keep their own control points; the vertices compared bit for bit through
 * GL_FEEDBACK (window position, colour, texture coordinates) and the
 * images pixel for pixel; glGetMap, the grid state, glPushAttrib(GL_EVAL_BIT)
 * and the errors value for value.
 */
#define GL_GLEXT_PROTOTYPES
#include "check.h"
#include "osmesa_util.h"

#define COMPARE_SCENE(fn, w, h, name) OSM_CHECK_SCENE(fn, w, h, name, "FS_EVAL_DUMP", "eval")

static uint32_t rng;
static float rnd(void) /* in [-1, 1) */
{
    rng = rng * 1664525u + 1013904223u;
    return (float)(rng >> 8) / (float)(1u << 23) - 1.0f;
}

/* Control points in [-scale, scale), w (every fourth of a VERTEX_4 map) in
 * [0.6, 1.4). */
static void fill_points(float *p, int n, int k, float scale, bool rational)
{
    for (int i = 0; i < n; i++)
        p[i] = (rational && k == 4 && i % 4 == 3) ? 1.0f + 0.4f * rnd() : scale * rnd();
}

/* The window cleared (depth too), glOrtho(-2, 2, -2, 2, -10, 10). */
static void ortho_scene(fs_context *c, int w, int h)
{
    osm_frustum_scene(c, w, h, 0.1f, 0.1f, 0.2f, 20);
    G(Clear, GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Ortho, -2, 2, -2, 2, -10, 10);
    G(MatrixMode, GL_MODELVIEW);
}

static const GLenum tex1[4] = {GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
                               GL_MAP1_TEXTURE_COORD_4};
static const GLenum tex2[4] = {GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
                               GL_MAP2_TEXTURE_COORD_4};

/* Curves: for each order 1..8 a vertex map (3 or 4 components, strides
 * above the components, float and double), a colour map, a texture map
 * of 1..4 components and a normal map (lit), drawn by glEvalMesh1 in both
 * modes and by glEvalCoord1/glEvalPoint1 in every form. */
static void s_curves(fs_context *c, int w, int h)
{
    rng = 12345;
    ortho_scene(c, w, h);
    for (int order = 1; order <= 8; order++) {
        float p[8 * 6], q[8 * 6], t[8 * 5];
        double d[8 * 5];
        bool v4 = order % 2 == 0;
        int kv = v4 ? 4 : 3;
        fill_points(p, order * (kv + 2), kv + 2, 1.8f, false);
        for (int i = 0; i < order; i++)
            if (v4)
                p[i * (kv + 2) + 3] = 1.0f + 0.4f * rnd();
        float u1 = -0.5f + 0.25f * (float)order, u2 = u1 + 1.0f + 0.3f * rnd();
        G(Map1f, v4 ? GL_MAP1_VERTEX_4 : GL_MAP1_VERTEX_3, u1, u2, kv + 2, order, p);
        for (int i = 0; i < order * 4; i++)
            q[i] = 0.5f + 0.5f * rnd();
        G(Map1f, GL_MAP1_COLOR_4, u1, u2, 4, order, q);
        int kt = 1 + order % 4;
        for (int i = 0; i < order * (kt + 1); i++)
            d[i] = 2.0 * rnd();
        G(Map1d, tex1[kt - 1], u1, u2, kt + 1, order, d);
        fill_points(t, order * 3, 3, 1.0f, false);
        G(Map1f, GL_MAP1_NORMAL, u1, u2, 3, order, t);
        G(Enable, v4 ? GL_MAP1_VERTEX_4 : GL_MAP1_VERTEX_3);
        G(Enable, tex1[kt - 1]);
        G(Enable, order % 3 ? GL_MAP1_COLOR_4 : GL_MAP1_NORMAL);
        if (order % 3 == 0) {
            G(Enable, GL_LIGHTING);
            G(Enable, GL_LIGHT0);
        }
        G(MapGrid1f, 5 + order, u1, u2);
        G(EvalMesh1, order % 2 ? GL_LINE : GL_POINT, 0, 5 + order);
        G(MapGrid1d, 7, (double)u1 - 0.2, (double)u2 + 0.1);
        G(EvalMesh1, GL_POINT, 1, 6);
        G(Begin, GL_LINE_STRIP);
        GLfloat uf = u1 + 0.1f;
        GLdouble ud = u1 + 0.37;
        G(EvalCoord1f, u1);
        G(EvalCoord1fv, &uf);
        G(EvalCoord1d, (double)u1 + 0.61);
        G(EvalCoord1dv, &ud);
        G(EvalPoint1, 3);
        G(EvalCoord1f, u2);
        G0(End);
        G(Disable, GL_LIGHTING);
        G(Disable, GL_MAP1_COLOR_4);
        G(Disable, GL_MAP1_NORMAL);
        G(Disable, tex1[kt - 1]);
        G(Disable, GL_MAP1_VERTEX_3);
        G(Disable, GL_MAP1_VERTEX_4);
    }
}

/* Surfaces: order pairs 1..8 (uorder above, below and equal to vorder),
 * VERTEX_3 and VERTEX_4, colour, texture and normal maps, with and
 * without GL_AUTO_NORMAL under lighting, drawn by glEvalMesh2 in every
 * mode and by glEvalCoord2/glEvalPoint2. */
static const int orders2[][2] = {{1, 1}, {2, 2}, {3, 3}, {4, 4}, {2, 5}, {5, 2}, {3, 6}, {7, 3}, {1, 4},
                                 {4, 1}, {8, 8}, {6, 8}, {8, 5}, {2, 3}, {3, 2}};
#define N_ORDERS2 ((int)(sizeof orders2 / sizeof orders2[0]))

static void surface_maps(fs_context *c, int uo, int vo, bool v4, int kt, float u1, float u2, float v1, float v2)
{
    float p[8 * 8 * 4], q[8 * 8 * 4], n[8 * 8 * 3];
    double d[8 * 8 * 4];
    int kv = v4 ? 4 : 3;
    fill_points(p, uo * vo * kv, kv, 1.6f, v4);
    /* ustride vo * kv, vstride kv: the points u-major */
    G(Map2f, v4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3, u1, u2, vo * kv, uo, v1, v2, kv, vo, p);
    for (int i = 0; i < uo * vo * 4; i++)
        q[i] = 0.5f + 0.5f * rnd();
    /* v-major this time: ustride 4, vstride 4 * uo */
    G(Map2f, GL_MAP2_COLOR_4, u1, u2, 4, uo, v1, v2, 4 * uo, vo, q);
    for (int i = 0; i < uo * vo * kt; i++)
        d[i] = 2.0 * rnd();
    G(Map2d, tex2[kt - 1], u1, u2, vo * kt, uo, v1, v2, kt, vo, d);
    fill_points(n, uo * vo * 3, 3, 1.0f, false);
    G(Map2f, GL_MAP2_NORMAL, u1, u2, vo * 3, uo, v1, v2, 3, vo, n);
}

static void s_surfaces(fs_context *c, int w, int h)
{
    rng = 777;
    ortho_scene(c, w, h);
    G(Enable, GL_DEPTH_TEST);
    G(Enable, GL_LIGHT0);
    /* One-sided: the order-1 directions make degenerate triangles, whose
     * facing (and so two-sided colour) is not the evaluators' business. */
    for (int s = 0; s < N_ORDERS2; s++) {
        int uo = orders2[s][0], vo = orders2[s][1];
        bool v4 = s % 2 == 1;
        int kt = 1 + s % 4;
        float u1 = -1.0f + 0.1f * (float)s, u2 = u1 + 2.0f, v1 = 0.5f, v2 = v1 - 1.5f - 0.05f * (float)s;
        surface_maps(c, uo, vo, v4, kt, u1, u2, v1, v2);
        G(Enable, v4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3);
        G(Enable, tex2[kt - 1]);
        bool lit = s % 3 != 0;
        /* Auto normals need a derivative in each direction (order >= 2:
         * llvmpipe reads past an order-1 net, see evaluator.c). */
        bool autonormal = lit && s % 3 == 1 && uo > 1 && vo > 1;
        if (lit) {
            G(Enable, GL_LIGHTING);
            G(Enable, GL_MAP2_NORMAL);
        } else {
            G(Enable, GL_MAP2_COLOR_4);
        }
        if (autonormal)
            G(Enable, GL_AUTO_NORMAL);
        G(MapGrid2f, 3 + s % 4, u1, u2, 2 + s % 5, v1, v2);
        GLenum mode = s % 3 == 0 ? GL_FILL : s % 3 == 1 ? GL_LINE : GL_POINT;
        G(EvalMesh2, GL_FILL, 0, 3 + s % 4, 0, 2 + s % 5);
        G(EvalMesh2, mode, 1, 2 + s % 4, 0, 1 + s % 5);
        G(MapGrid2d, 4, (double)u1, (double)u2 + 0.3, 3, (double)v1, (double)v2);
        G(Begin, GL_TRIANGLE_STRIP);
        GLfloat uv[2] = {u1 + 0.3f, v1 - 0.2f};
        GLdouble uvd[2] = {(double)u1 + 0.7, (double)v1 - 0.9};
        G(EvalCoord2f, u1, v1);
        G(EvalCoord2fv, uv);
        G(EvalCoord2d, (double)u1 + 1.1, (double)v1 - 0.4);
        G(EvalCoord2dv, uvd);
        G(EvalPoint2, 2, 1);
        G(EvalPoint2, 3, 3);
        G0(End);
        G(Disable, GL_AUTO_NORMAL);
        G(Disable, GL_LIGHTING);
        G(Disable, GL_MAP2_NORMAL);
        G(Disable, GL_MAP2_COLOR_4);
        G(Disable, tex2[kt - 1]);
        G(Disable, GL_MAP2_VERTEX_3);
        G(Disable, GL_MAP2_VERTEX_4);
    }
}

/* Display lists: glMap compiled into a list keeps the points as they were
 * at the call (the array is changed before the list is called); glEvalMesh
 * and glEvalCoord in a list evaluate the maps current when it runs;
 * GL_COMPILE_AND_EXECUTE too. */
static void s_lists(fs_context *c, int w, int h)
{
    rng = 4242;
    ortho_scene(c, w, h);
    float p[6 * 3], q[4 * 4 * 3];
    fill_points(p, 18, 3, 1.8f, false);
    fill_points(q, 48, 3, 1.5f, false);
    G(NewList, 1, GL_COMPILE);
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 6, p);
    G(Map2f, GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, q);
    G0(EndList);
    for (int i = 0; i < 18; i++)
        p[i] = -p[i];
    for (int i = 0; i < 48; i++)
        q[i] = 0.5f * q[i];
    G(NewList, 2, GL_COMPILE);
    G(Color3f, 1, 1, 0);
    G(EvalMesh1, GL_LINE, 0, 20);
    G(Begin, GL_LINE_STRIP);
    for (int i = 0; i <= 30; i++)
        G(EvalCoord1f, (float)i / 30.0f);
    G0(End);
    G(Color3f, 0, 1, 1);
    G(EvalMesh2, GL_LINE, 0, 6, 0, 5);
    G0(EndList);
    G(Enable, GL_MAP1_VERTEX_3);
    G(Enable, GL_MAP2_VERTEX_3);
    G(MapGrid1f, 20, 0, 1);
    G(MapGrid2f, 6, 0, 1, 5, 0, 1);
    G(CallList, 2); /* the maps glMap set directly: still the initial ones */
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 6, p);
    G(CallList, 2);
    G(CallList, 1); /* the points as compiled */
    G(CallList, 2);
    /* (A glEvalMesh compiled with GL_COMPILE_AND_EXECUTE is left out:
     * Mesa then also compiles the glBegin/glEvalCoord/glEnd its execution
     * issues, so the list draws the mesh twice, once as one merged strip;
     * measured in GL_FEEDBACK, 28 triangles more.) */
    G(NewList, 3, GL_COMPILE_AND_EXECUTE);
    G(Map2f, GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, q);
    G(Translatef, 0.3f, 0.2f, 0);
    G0(EndList);
    G(EvalMesh2, GL_FILL, 1, 4, 1, 3);
    G(CallList, 3);
    G(EvalMesh2, GL_FILL, 1, 4, 1, 3);
}

TEST(curves_vs_osmesa) { COMPARE_SCENE(s_curves, 96, 96, "curves"); }
TEST(surfaces_vs_osmesa) { COMPARE_SCENE(s_surfaces, 96, 96, "surfaces"); }
TEST(display_lists_vs_osmesa) { COMPARE_SCENE(s_lists, 96, 96, "lists"); }

/* The same scenes in GL_FEEDBACK (GL_4D_COLOR_TEXTURE): every evaluated
 * vertex's window position, colour and texture coordinates, bit for bit. */
#define FB_SIZE 200000
static int feedback_of(fs_context *c, osm_scene_fn scene, GLfloat *buf)
{
    G(FeedbackBuffer, FB_SIZE, GL_4D_COLOR_TEXTURE, buf);
    GR(RenderMode, GL_FEEDBACK);
    scene(c, 96, 96);
    return GR(RenderMode, GL_RENDER);
}

static void compare_feedback(check_state *check_st_, osm_scene_fn scene, const char *name)
{
    static GLfloat ref[FB_SIZE], mine[FB_SIZE];
    osm o;
    if (!osm_open(&o, 96, 96)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    fs_context *c = NULL;
    int nref = feedback_of(c, scene, ref);
    osm_close(&o);
    c = fs_context_create(NULL, 96, 96);
    REQUIRE(c);
    int nmine = feedback_of(c, scene, mine);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
    CHECK_EQ_INT(nmine, nref);
    CHECK(nref > 1000);
    int bad = 0;
    for (int i = 0; i < nref && i < nmine; i++)
        if (memcmp(&ref[i], &mine[i], sizeof ref[i]) != 0 && bad++ < 8)
            CHECK_FAIL_("%s value %d: OSMesa %.9g, fragsim %.9g", name, i, ref[i], mine[i]);
    printf("  %s: %d feedback values, %d differ\n", name, nref, bad);
}

TEST(curves_feedback_vs_osmesa) { compare_feedback(check_st_, s_curves, "curves"); }
TEST(surfaces_feedback_vs_osmesa) { compare_feedback(check_st_, s_surfaces, "surfaces"); }
TEST(display_lists_feedback_vs_osmesa) { compare_feedback(check_st_, s_lists, "lists"); }

/* ---- state: glGetMap, the grids, GL_EVAL_BIT, errors ---- */

static const GLenum all_targets[18] = {
    GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP1_INDEX, GL_MAP1_COLOR_4, GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_MAP2_INDEX, GL_MAP2_COLOR_4, GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4};

#define MAXV 40000
static void record(fs_context *c, double *out, int *n)
{
    GLfloat f[3600];
    GLdouble d[3600];
    GLint iv[3600];
    for (int t = 0; t < 18; t++) {
        GLenum queries[3] = {GL_ORDER, GL_DOMAIN, GL_COEFF};
        for (int q = 0; q < 3; q++) {
            GLint order[2] = {1, 1};
            G(GetMapiv, all_targets[t], GL_ORDER, order);
            int cnt = q == 0 ? (t < 9 ? 1 : 2) : q == 1 ? (t < 9 ? 2 : 4) : order[0] * (t < 9 ? 1 : order[1]) * 4;
            memset(f, 0, sizeof f);
            memset(d, 0, sizeof d);
            memset(iv, 0, sizeof iv);
            G(GetMapfv, all_targets[t], queries[q], f);
            G(GetMapdv, all_targets[t], queries[q], d);
            G(GetMapiv, all_targets[t], queries[q], iv);
            for (int i = 0; i < cnt && *n + 3 < MAXV; i++) {
                out[(*n)++] = f[i];
                out[(*n)++] = d[i];
                out[(*n)++] = iv[i];
            }
        }
        out[(*n)++] = GR(IsEnabled, all_targets[t]);
    }
    static const GLenum grid[5] = {GL_MAP1_GRID_DOMAIN, GL_MAP1_GRID_SEGMENTS, GL_MAP2_GRID_DOMAIN,
                                   GL_MAP2_GRID_SEGMENTS, GL_AUTO_NORMAL};
    for (int g = 0; g < 5; g++) {
        GLfloat gf[4] = {0};
        GLint gi[4] = {0};
        G(GetFloatv, grid[g], gf);
        G(GetIntegerv, grid[g], gi);
        for (int i = 0; i < 4; i++) {
            out[(*n)++] = gf[i];
            out[(*n)++] = gi[i];
        }
    }
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
}

static void state_calls(fs_context *c, double *out, int *n)
{
    rng = 99;
    float p[30 * 30 * 4];
    double dp[30 * 4];
    *n = 0;
    record(c, out, n); /* initial values */
    for (int t = 0; t < 18; t++) {
        int uo = 1 + (t * 7) % 9, vo = 1 + (t * 5) % 6;
        fill_points(p, 30 * 30 * 4, 4, 40.0f, false);
        if (t < 9) {
            G(Map1f, all_targets[t], -1.5f + (float)t, 2.25f, 5, uo, p);
        } else {
            G(Map2f, all_targets[t], 0.5f, -3.75f, 4 * vo + 1, uo, 7.5f, 1.0f + (float)t, 4, vo, p);
        }
        G(Enable, all_targets[t]);
    }
    for (int i = 0; i < 30 * 4; i++)
        dp[i] = 100.0 * rnd();
    G(Map1d, GL_MAP1_VERTEX_4, 0.125, -7.5, 4, 30, dp);
    G(MapGrid1f, 17, 0.25f, -3.5f);
    G(MapGrid2d, 3, 1.5, 2.5, 9, -0.5, 4.75);
    G(Enable, GL_AUTO_NORMAL);
    record(c, out, n);
    /* GL_EVAL_BIT saves the enables and grids, not the maps. */
    G(PushAttrib, GL_EVAL_BIT);
    G(MapGrid1f, 3, 5, 6);
    G(MapGrid2f, 4, 5, 6, 7, 8, 9);
    G(Disable, GL_AUTO_NORMAL);
    G(Disable, GL_MAP2_COLOR_4);
    G(Map1f, GL_MAP1_COLOR_4, 3, 4, 4, 2, p);
    record(c, out, n);
    G0(PopAttrib);
    record(c, out, n);
    G(PushAttrib, GL_ENABLE_BIT);
    G(Disable, GL_MAP1_VERTEX_3);
    G(Disable, GL_AUTO_NORMAL);
    G0(PopAttrib);
    record(c, out, n);
    /* Errors, one at a time (each recorded). */
    G(Map1f, GL_MAP1_VERTEX_3, 1, 1, 3, 2, p);          /* u1 == u2 */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 0, p);          /* order 0 */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 31, p);         /* order > GL_MAX_EVAL_ORDER */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 2, 3, p);          /* stride < 3 */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_MAP2_VERTEX_3, 0, 1, 3, 3, p);          /* a MAP2 target */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_TEXTURE_2D, 0, 1, 3, 3, p);             /* no map */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_TEXTURE_2D, 0, 0, 3, 3, p);             /* the domain first */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 3, NULL);       /* no points */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map2f, GL_MAP2_VERTEX_3, 0, 1, 3, 2, 2, 2, 9, 2, p); /* v1 == v2 */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map2f, GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, p); /* vstride < 3 */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map2f, GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 33, p); /* vorder */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Map2f, GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, p); /* a MAP1 target */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(ActiveTexture, GL_TEXTURE1);
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 2, p);          /* unit 1 active */
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(ActiveTexture, GL_TEXTURE0);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(MapGrid1f, 0, 0, 1);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(MapGrid2f, 2, 0, 1, -1, 0, 1);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(EvalMesh1, GL_FILL, 0, 2);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(EvalMesh2, GL_LINE_STRIP, 0, 2, 0, 2);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    GLfloat f[4];
    G(GetMapfv, GL_TEXTURE_2D, GL_ORDER, f);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(GetMapfv, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_3, f);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Begin, GL_POINTS);
    G(EvalMesh1, GL_POINT, 0, 2);
    G(EvalCoord1f, 0.5f);
    G0(End);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Begin, GL_POINTS);
    G(Map1f, GL_MAP1_VERTEX_3, 0, 1, 3, 2, p);
    G(MapGrid1f, 2, 0, 1);
    G0(End);
    out[(*n)++] = (c ? fsglGetError(c) : glGetError());
    record(c, out, n); /* nothing the errors refused changed */
}

TEST(state_and_errors_vs_osmesa)
{
    static double ref[MAXV], mine[MAXV];
    int nref = 0, nmine = 0;
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    state_calls(NULL, ref, &nref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    state_calls(c, mine, &nmine);
    fs_context_destroy(c);
    CHECK_EQ_INT(nmine, nref);
    int bad = 0;
    for (int i = 0; i < nref && i < nmine; i++)
        if (ref[i] != mine[i] && bad++ < 8)
            CHECK_FAIL_("value %d: OSMesa %.9g, fragsim %.9g", i, ref[i], mine[i]);
    printf("  %d values compared, %d differ\n", nref, bad);
}

TEST_LIST = {
    TEST_ENTRY(curves_vs_osmesa),
    TEST_ENTRY(surfaces_vs_osmesa),
    TEST_ENTRY(display_lists_vs_osmesa),
    TEST_ENTRY(curves_feedback_vs_osmesa),
    TEST_ENTRY(surfaces_feedback_vs_osmesa),
    TEST_ENTRY(display_lists_feedback_vs_osmesa),
    TEST_ENTRY(state_and_errors_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
