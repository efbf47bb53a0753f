/*
 * glLoadTransposeMatrix{f,d} and glMultTransposeMatrix{f,d} (GL 1.3; GL 1.5
 * spec 2.11.2) against OSMesa (llvmpipe), at tolerance 0: random sequences
 * on every matrix mode, immediately and from display lists, leave the same
 * matrices (glGetFloatv of GL_*_MATRIX and GL_TRANSPOSE_*_MATRIX) and the
 * same errors; a transposed load draws the same image as the plain one.
 */
#include <GL/osmesa.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

static uint32_t rnd(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s ^ (*s >> 15);
}
static double rnd_real(uint32_t *s) { return ((double)(rnd(s) >> 8) / 16777216.0) * 4.0 - 2.0; }

typedef struct rec { float v[8192]; int n; } rec;

static void dump(fs_context *c, rec *r)
{
    static const GLenum names[] = {GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_TEXTURE_MATRIX,
                                   GL_TRANSPOSE_MODELVIEW_MATRIX, GL_TRANSPOSE_PROJECTION_MATRIX,
                                   GL_TRANSPOSE_TEXTURE_MATRIX};
    for (int i = 0; i < 6; i++) {
        GLfloat m[16];
        G(GetFloatv, names[i], m);
        for (int k = 0; k < 16 && r->n < 8192; k++)
            r->v[r->n++] = m[k];
    }
    if (r->n < 8192)
        r->v[r->n++] = (float)(c ? fsglGetError(c) : glGetError());
}

/* One random step: a transposed load or multiply in f or d, or a mode. */
static void step(fs_context *c, uint32_t *s)
{
    static const GLenum modes[] = {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE};
    GLfloat f[16];
    GLdouble d[16];
    for (int k = 0; k < 16; k++) {
        d[k] = rnd_real(s);
        f[k] = (GLfloat)rnd_real(s);
    }
    switch (rnd(s) % 5) {
    case 0: G(MatrixMode, modes[rnd(s) % 3]); break;
    case 1: G(LoadTransposeMatrixf, f); break;
    case 2: G(LoadTransposeMatrixd, d); break;
    case 3: G(MultTransposeMatrixf, f); break;
    default: G(MultTransposeMatrixd, d); break;
    }
}

static void sequence(fs_context *c, rec *r, uint32_t seed)
{
    uint32_t s = seed;
    r->n = 0;
    for (int i = 0; i < 24; i++) {
        step(c, &s);
        dump(c, r);
    }
    /* The same steps compiled (nothing changes), then called. */
    G(NewList, 1, GL_COMPILE);
    for (int i = 0; i < 24; i++)
        step(c, &s);
    G0(EndList);
    dump(c, r);
    G(CallList, 1);
    dump(c, r);
    /* Not between glBegin and glEnd (GL_INVALID_OPERATION). */
    GLfloat id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    G(Begin, GL_POINTS);
    G(LoadTransposeMatrixf, id);
    G0(End);
    dump(c, r);
}

TEST(transpose_matrices_vs_osmesa)
{
    static rec ref, mine;
    for (uint32_t seed = 1; seed <= 10; seed++) {
        osm o;
        if (!osm_open(&o, 8, 8)) {
            osm_close(&o);
            SKIP("no OSMesa context");
        }
        fs_context *c = NULL;
        sequence(c, &ref, seed);
        c = fs_context_create(NULL, 8, 8);
        REQUIRE(c);
        sequence(c, &mine, seed);
        CHECK_EQ_INT(mine.n, ref.n);
        int bad = 0;
        for (int i = 0; i < mine.n && i < ref.n; i++)
            if (memcmp(&mine.v[i], &ref.v[i], sizeof(float)) != 0 && bad++ < 5)
                CHECK_FAIL_("seed %u value %d: %.9g (model) != %.9g (OSMesa)", seed, i, mine.v[i], ref.v[i]);
        fs_context_destroy(c);
        osm_close(&o);
    }
}

/* A perspective set with glLoadTransposeMatrixd and a modelview with
 * glMultTransposeMatrixf draw a shaded triangle fan. */
static void draw_fan(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    G(Viewport, 0, 0, w, h);
    const double n = 1.0, f = 10.0;
    GLdouble proj[16] = {1.2, 0, 0, 0, 0, 1.2, 0, 0, 0, 0, -(f + n) / (f - n), -2 * f * n / (f - n), 0, 0, -1, 0};
    GLfloat mv[16] = {0.8f, -0.6f, 0, 0.1f, 0.6f, 0.8f, 0, -0.2f, 0, 0, 1, -3.0f, 0, 0, 0, 1};
    G(MatrixMode, GL_PROJECTION);
    G(LoadTransposeMatrixd, proj);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(MultTransposeMatrixf, mv);
    G(Begin, GL_TRIANGLE_FAN);
    G(Color3f, 1, 1, 1);
    G(Vertex3f, 0, 0, 0);
    for (int i = 0; i <= 12; i++) {
        float a = (float)i * 0.5235988f;
        G(Color3f, 0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.3f);
        G(Vertex3f, cosf(a), sinf(a), 0.3f * sinf(2 * a));
    }
    G0(End);
}

TEST(transposed_matrices_draw_vs_osmesa)
{
    osm_pair p;
    if (!osm_pair_render(&p, 48, 48, NULL, draw_fan, NULL))
        SKIP("no OSMesa context");
    CHECK_EQ_INT(p.d.differ, 0);
    CHECK(img_lit_pixels(p.ref.color, 48L * 48) > 100);
    osm_pair_close(&p);
}

TEST_LIST = {
    TEST_ENTRY(transpose_matrices_vs_osmesa),
    TEST_ENTRY(transposed_matrices_draw_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
