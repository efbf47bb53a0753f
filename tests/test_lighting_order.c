/*
 * Lit vertex colours bit for bit as llvmpipe computes them: Mesa's
 * fixed-function vertex program (ffvertex_prog.c) sums the lighting terms
 * in its own order, lights in object space when nothing needs eye
 * coordinates, and transforms normals by an inverse whose method follows
 * the flags the matrix commands left (m_matrix.c); the model does the same
 * (pipeline/lighting.c, pipeline/matrix_inverse.c), and its POW (specular
 * and spot exponents) is gallivm's polynomial exp2(log2(x) y)
 * (pipeline/vp_pow.c).  Oracle: the colours
 * OSMesa returns in GL_FEEDBACK mode (GL_3D_COLOR), the vertex program's
 * outputs, compared at tolerance 0 over 300 seeded vertices per case.
 */
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"

enum {
    C_ROTATE = 1,          /* two rotations in the modelview */
    C_SCALE4 = 2,          /* glScalef(4, 4, 4): eye space, not length preserving */
    C_DIRECTIONAL = 4,     /* w = 0: object space under a rigid modelview */
    C_NORMALIZE = 8,       /* GL_NORMALIZE with normals of any length */
    C_SHININESS = 16,      /* a specular term (POW; exponent cur_shin) */
    C_ATTENUATION = 32,    /* distance attenuation */
    C_SPOT = 64,           /* a spot light (POW; exponent cur_spot_exp) */
    C_SIERPINSKI = 128,    /* sierpinski3d's modelview: three rotations */
    C_CONST_NORMAL = 256,  /* one normal per triangle, given before glBegin */
    C_AXES = 512,          /* normals (+-1, +-1, +-1) */
    C_MINUS_ZERO = 1024,   /* glMultMatrixf of an identity written with -0 first */
    C_CLEAR = 2048,        /* a glClear between (Mesa analyses the matrix there) */
    C_RESCALE = 4096,      /* GL_RESCALE_NORMAL */
    C_LOCAL_VIEWER = 8192, /* GL_LIGHT_MODEL_LOCAL_VIEWER (with C_SHININESS) */
    C_TWO_SIDE = 16384,    /* GL_LIGHT_MODEL_TWO_SIDE, the back with its own shininess 7 */
    C_SEPARATE = 32768,    /* GL_SEPARATE_SPECULAR_COLOR (colours of GL_3D_COLOR are the primary) */
    C_CAMERA = 65536,      /* boxed's camera: glMultMatrixf of a rotation, analysed with what follows */
    C_PUSH = 131072,       /* glPushMatrix before the scale (Mesa analyses the matrix it copies) */
    C_BOXED = 262144,      /* boxed's modelview: camera, a far translation, push, translate, scale 3 */
};

static int cur_case;
/* boxed's camera rotation (glMultMatrixf at call 2955 of its capture). */
static const float boxed_cam[16] = {-0.8653435f, 0.2442258f, -0.4376463f, 0, 0, 0.8732332f, 0.4873024f, 0,
                                    0.5011792f, 0.4216839f, -0.7556467f, 0, 0, 0, 0, 1};
static float cur_shin = 20.0f, cur_spot_exp = 2.0f;
static uint32_t rng_state;

static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) / 16777216.0f;
}

/* Draws 100 lit triangles in feedback mode and appends their vertices'
 * RGB to v. */
static void lit_feedback(fs_context *c, double *v, int *n)
{
    static float fb[200000];
    const int k = cur_case;
    rng_state = 1234u;
    G(Viewport, 0, 0, 64, 64);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    if (k & C_BOXED)
        G(Frustum, -1.2435, 1.2435, -0.9326, 0.9326, 2, 1000); /* boxed's perspective */
    else
        G(Frustum, -1, 1, -1, 1, 1, 100);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    const float lpos[4] = {-4, 3, 10, (k & C_DIRECTIONAL) ? 0.0f : 1.0f};
    if (k & C_MINUS_ZERO) {
        static const float mz[16] = {1, 0, -0.0f, 0, -0.0f, 1, -0.0f, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        G(MultMatrixf, mz);
        G(Translated, -0.0, -0.0, -30.0);
        G(Scalef, 1, 1, 1);
        if (k & C_CLEAR)
            G(Clear, GL_COLOR_BUFFER_BIT);
        G(Lightfv, GL_LIGHT0, GL_POSITION, lpos);
        G0(PushMatrix);
    } else {
        G(Lightfv, GL_LIGHT0, GL_POSITION, lpos);
    }
    if (k & C_BOXED) {
        G(MultMatrixf, boxed_cam);
        G(Translated, 132.4724426269531, -159.9700164794922, 226.4253540039062);
        /* boxed's lights, given under the camera: at the eye, or from +y. */
        const float bpos[4] = {0, (k & C_DIRECTIONAL) ? 1.0f : 0.0f, 0, (k & C_DIRECTIONAL) ? 0.0f : 1.0f};
        G(Lightfv, GL_LIGHT0, GL_POSITION, bpos);
        G0(PushMatrix);
        G(Translatef, 4.406446f, 5.952302f, 1.165314f);
        G(Scalef, 3, 3, 3);
    } else if (k & C_SIERPINSKI) {
        static const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        G(Translatef, -4.767981f, -2.072593f, -5.102578f);
        G(MultMatrixf, id);
        G(Rotatef, 142.6435f, 1, 0, 0);
        G(Rotatef, 180.3264f, 0, 1, 0);
        G(Rotatef, 153.3583f, 0, 0, 1);
    } else {
        G(Translatef, 0.1f, -0.2f, -5.0f);
    }
    if (k & C_CAMERA) {
        G(MultMatrixf, boxed_cam);
    }
    if (k & C_ROTATE) {
        G(Rotatef, 41.3f, 1, 0, 0);
        G(Rotatef, 33.0f, 0, 1, 0);
    }
    if (k & C_PUSH)
        G0(PushMatrix);
    if (k & C_SCALE4)
        G(Scalef, 4, 4, 4);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    if (k & C_NORMALIZE)
        G(Enable, GL_NORMALIZE);
    if (k & C_RESCALE)
        G(Enable, GL_RESCALE_NORMAL);
    const float amb[4] = {0.0956f, 0.1227f, 0.6349f, 1}, lamb[4] = {0.2f, 0.1f, 0.3f, 1};
    G(Materialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, amb);
    G(Lightfv, GL_LIGHT0, GL_AMBIENT, lamb);
    if (k & C_SHININESS) {
        const float sp[4] = {0.5f, 0.6f, 0.7f, 1};
        G(Materialf, GL_FRONT, GL_SHININESS, cur_shin);
        G(Materialfv, GL_FRONT, GL_SPECULAR, sp);
    }
    if (k & C_TWO_SIDE) {
        const float bamb[4] = {0.3f, 0.2f, 0.1f, 1}, bsp[4] = {0.9f, 0.4f, 0.6f, 1};
        G(LightModeli, GL_LIGHT_MODEL_TWO_SIDE, 1);
        G(Materialfv, GL_BACK, GL_AMBIENT_AND_DIFFUSE, bamb);
        G(Materialf, GL_BACK, GL_SHININESS, 7.0f);
        G(Materialfv, GL_BACK, GL_SPECULAR, bsp);
    }
    if (k & C_SEPARATE)
        G(LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    if (k & C_LOCAL_VIEWER)
        G(LightModeli, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    if (k & C_ATTENUATION) {
        G(Lightf, GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
        G(Lightf, GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.01f);
    }
    if (k & C_SPOT) {
        const float sd[3] = {0.4f, -0.3f, -1.0f};
        G(Lightf, GL_LIGHT0, GL_SPOT_CUTOFF, 80.0f);
        G(Lightf, GL_LIGHT0, GL_SPOT_EXPONENT, cur_spot_exp);
        G(Lightfv, GL_LIGHT0, GL_SPOT_DIRECTION, sd);
    }
    G(FeedbackBuffer, 200000, GL_3D_COLOR, fb);
    G(RenderMode, GL_FEEDBACK);
    if (!(k & C_CONST_NORMAL))
        G(Begin, GL_TRIANGLES);
    for (int i = 0; i < 300; i++) {
        float nx = rnd() - 0.5f, ny = rnd() - 0.5f, nz = rnd() * 0.5f + 0.5f;
        if (!(k & C_NORMALIZE)) {
            float l = sqrtf(nx * nx + ny * ny + nz * nz);
            nx /= l, ny /= l, nz /= l;
        }
        if (k & C_AXES) {
            nx = (i & 1) ? 1.0f : -1.0f;
            ny = (i & 2) ? 1.0f : -1.0f;
            nz = (i & 4) ? 1.0f : -1.0f;
        }
        if ((k & C_CONST_NORMAL) && i % 3 == 0) {
            G(Normal3f, nx, ny, nz);
            G(Begin, GL_TRIANGLES);
        }
        if (!(k & C_CONST_NORMAL))
            G(Normal3f, nx, ny, nz);
        G(Vertex3f, rnd() * 0.4f - 0.2f, rnd() * 0.4f - 0.2f, rnd() * 0.4f - 0.2f);
        if ((k & C_CONST_NORMAL) && i % 3 == 2)
            G0(End);
    }
    if (!(k & C_CONST_NORMAL))
        G0(End);
    int m = GR(RenderMode, GL_RENDER);
    for (int i = 0; i < m && *n < 4000;) {
        int nv = (int)fb[i + 1];
        for (int j = 0; j < nv; j++)
            for (int q = 3; q < 6; q++)
                v[(*n)++] = fb[i + 2 + 7 * j + q];
        i += 2 + 7 * nv;
    }
}

/* Runs case k on both; the number of colour values that differ (-1: no
 * OSMesa context), with the count of lit values (some channel above the
 * scene colour's) in *lit. */
static long differ_in(int k, int *count)
{
    static double ref[5000], mine[5000];
    int nr = 0, nm = 0;
    cur_case = k;
    if (!osm_run_values(lit_feedback, 64, 64, ref, &nr, mine, &nm))
        return -1;
    long d = nr == nm ? 0 : labs((long)nr - nm);
    for (int i = 0; i < nr && i < nm; i++)
        d += ref[i] != mine[i];
    *count = nr;
    return d;
}

/* A case: the flags and the two exponents (unused without C_SHININESS,
 * C_SPOT). */
typedef struct lcase { int k; float shin, spot; } lcase;

TEST(lighting_exact)
{
    static const lcase cases[] = {
        {0, 0, 0}, {C_ROTATE, 0, 0}, {C_SCALE4, 0, 0}, {C_ROTATE | C_SCALE4, 0, 0}, {C_DIRECTIONAL, 0, 0},
        {C_DIRECTIONAL | C_ROTATE, 0, 0}, {C_DIRECTIONAL | C_SCALE4, 0, 0}, {C_NORMALIZE, 0, 0},
        {C_NORMALIZE | C_ROTATE | C_SCALE4, 0, 0}, {C_RESCALE | C_SCALE4, 0, 0},
        {C_RESCALE | C_SCALE4 | C_ROTATE, 0, 0}, {C_DIRECTIONAL | C_NORMALIZE | C_ROTATE, 0, 0},
        {C_ATTENUATION, 0, 0}, {C_ATTENUATION | C_SCALE4, 0, 0}, {C_ATTENUATION | C_ROTATE | C_SCALE4, 0, 0},
        {C_ATTENUATION | C_DIRECTIONAL, 0, 0}, {C_SIERPINSKI, 0, 0}, {C_SIERPINSKI | C_SCALE4, 0, 0},
        {C_SIERPINSKI | C_SCALE4 | C_NORMALIZE, 0, 0}, {C_SIERPINSKI | C_SCALE4 | C_NORMALIZE | C_CONST_NORMAL, 0, 0},
        {C_SIERPINSKI | C_SCALE4 | C_NORMALIZE | C_CONST_NORMAL | C_AXES, 0, 0},
        {C_MINUS_ZERO | C_SIERPINSKI | C_SCALE4 | C_NORMALIZE, 0, 0},
        {C_MINUS_ZERO | C_CLEAR | C_SIERPINSKI | C_SCALE4, 0, 0},
        {C_MINUS_ZERO | C_SIERPINSKI | C_SCALE4 | C_NORMALIZE | C_CONST_NORMAL | C_AXES, 0, 0},
        /* POW: the specular factor (LIT) and the spot factor. */
        {C_SHININESS, 20, 0}, {C_SHININESS, 1, 0}, {C_SHININESS, 5, 0}, {C_SHININESS, 128, 0},
        {C_SHININESS, 0.5f, 0}, {C_SHININESS, 37.3f, 0},
        {C_SHININESS | C_DIRECTIONAL | C_ROTATE, 20, 0}, {C_SHININESS | C_LOCAL_VIEWER, 5, 0},
        {C_SHININESS | C_ATTENUATION | C_SCALE4 | C_NORMALIZE, 20, 0},
        {C_SHININESS | C_SEPARATE | C_ROTATE, 20, 0}, /* the specular term leaves the primary colour */
        {C_SPOT, 0, 2}, {C_SPOT, 0, 0.5f}, {C_SPOT, 0, 10}, {C_SPOT, 0, 1}, {C_SPOT, 0, 128},
        {C_SPOT, 0, 0}, /* exp2(0) is 1 exactly */
        {C_SPOT | C_DIRECTIONAL, 0, 10}, {C_SPOT | C_ATTENUATION | C_SHININESS, 5, 10},
        {C_SPOT | C_SHININESS | C_LOCAL_VIEWER | C_ROTATE, 128, 0.5f},
        {C_CAMERA, 0, 0}, {C_CAMERA | C_SCALE4, 0, 0}, {C_CAMERA | C_SCALE4 | C_DIRECTIONAL, 0, 0},
        {C_CAMERA | C_PUSH | C_SCALE4, 0, 0}, {C_CAMERA | C_PUSH | C_SCALE4 | C_DIRECTIONAL, 0, 0},
        {C_BOXED, 0, 0}, {C_BOXED | C_DIRECTIONAL, 0, 0},
        {C_TWO_SIDE | C_SHININESS, 20, 0}, {C_TWO_SIDE, 0, 0}, {C_TWO_SIDE | C_SPOT | C_SHININESS | C_ROTATE, 1, 2},
    };
    long total = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int count = 0;
        cur_shin = cases[i].shin;
        cur_spot_exp = cases[i].spot;
        long d = differ_in(cases[i].k, &count);
        if (d < 0)
            SKIP("no OSMesa context");
        CHECK(count >= 900);
        if (d)
            CHECK_FAIL_("case %d (shininess %g, spot exponent %g): %ld of %d colour values differ", cases[i].k,
                        (double)cases[i].shin, (double)cases[i].spot, d, count);
        total += count;
    }
    printf("    %zu cases, %ld colour values\n", sizeof cases / sizeof cases[0], total);
}

TEST_LIST = {
    TEST_ENTRY(lighting_exact),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
