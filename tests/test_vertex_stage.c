/*
 * Vertex stage tests (GL 1.5 spec chapter 2): matrices against closed
 * forms, glRotate against the spec formula, lighting of one vertex against
 * the 2.14.1 equation in double, clipping against an exact recomputation,
 * GL errors, bad input, and whole scenes rendered by fragsim and by OSMesa
 * (llvmpipe) in the same process and compared pixel by pixel.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../pipeline/vertex_internal.h"

/* ------------------------------------------------------------ helpers */
static fs_context *ctx(int w, int h)
{
    return fs_context_create(NULL, w, h);
}

static const float *top_mv(fs_context *c) { return fs_current_matrix(c, GL_MODELVIEW)->m; }
static const float *top_proj(fs_context *c) { return fs_current_matrix(c, GL_PROJECTION)->m; }

static void dmul(double r[16], const double a[16], const double b[16])
{
    double t[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += a[k * 4 + i] * b[j * 4 + k];
            t[j * 4 + i] = s;
        }
    memcpy(r, t, sizeof t);
}

/* ------------------------------------------------------------ matrices */
TEST(matrix_defaults_and_products)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    for (int i = 0; i < 16; i++) CHECK_EQ_INT(top_mv(c)[i], (i % 5 == 0) ? 1 : 0);
    GLenum mode = c->xf.matrix_mode;
    CHECK_EQ_INT(mode, GL_MODELVIEW);
    float a[16], b[16];
    double da[16], db[16], dr[16];
    for (int i = 0; i < 16; i++) {
        a[i] = (float)(i + 1) * 0.25f;          /* exactly representable, products exact */
        b[i] = (float)((i * 7) % 11) - 5.0f;
        da[i] = a[i];
        db[i] = b[i];
    }
    fsglLoadMatrixf(c, a);
    fsglMultMatrixf(c, b);
    dmul(dr, da, db);
    for (int i = 0; i < 16; i++) CHECK_NEAR(top_mv(c)[i], dr[i], 0);
    /* Translate then scale equals T * S. */
    fsglLoadIdentity(c);
    fsglTranslatef(c, 1.5f, -2.0f, 3.0f);
    fsglScalef(c, 2.0f, 4.0f, 0.5f);
    const float want[16] = {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0.5f, 0, 1.5f, -2, 3, 1};
    for (int i = 0; i < 16; i++) CHECK_NEAR(top_mv(c)[i], want[i], 0);
    /* Double entry points convert to float. */
    double dm[16];
    for (int i = 0; i < 16; i++) dm[i] = 0.1 * i;
    fsglLoadMatrixd(c, dm);
    for (int i = 0; i < 16; i++) CHECK_EQ_INT(top_mv(c)[i] == (float)(0.1 * i), 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

TEST(rotate_matches_spec_formula)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    const float axes[][3] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -2}, {1, 2, 3}, {-0.3f, 0.5f, 0.8f}};
    const float angles[] = {30, -45, 90, 123.5f, 270, 1e-3f};
    for (size_t ai = 0; ai < sizeof axes / sizeof axes[0]; ai++)
        for (size_t gi = 0; gi < sizeof angles / sizeof angles[0]; gi++) {
            fsglLoadIdentity(c);
            fsglRotatef(c, angles[gi], axes[ai][0], axes[ai][1], axes[ai][2]);
            /* GL 1.5 spec 2.11.2: R = uu^T + cos(a)(I - uu^T) + sin(a)S. */
            double x = axes[ai][0], y = axes[ai][1], z = axes[ai][2];
            double l = sqrt(x * x + y * y + z * z);
            x /= l; y /= l; z /= l;
            double a = angles[gi] * 3.14159265358979323846 / 180.0, co = cos(a), si = sin(a);
            double u[3] = {x, y, z}, S[3][3] = {{0, -z, y}, {z, 0, -x}, {-y, x, 0}};
            for (int r = 0; r < 3; r++)
                for (int k = 0; k < 3; k++) {
                    double e = u[r] * u[k] + co * ((r == k) - u[r] * u[k]) + si * S[r][k];
                    CHECK_NEAR(top_mv(c)[k * 4 + r], e, 2e-6);
                }
            CHECK_EQ_INT(top_mv(c)[15], 1);
        }
    /* A zero axis leaves the matrix unchanged. */
    fsglLoadIdentity(c);
    fsglRotatef(c, 45, 0, 0, 0);
    CHECK_EQ_INT(top_mv(c)[0], 1);
    fs_context_destroy(c);
}

TEST(frustum_and_ortho_closed_form)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    fsglMatrixMode(c, GL_PROJECTION);
    double l = -1.5, r = 2.5, b = -1, t = 3, n = 0.5, f = 20;
    fsglFrustum(c, l, r, b, t, n, f);
    const float *m = top_proj(c);
    CHECK_NEAR(m[0], 2 * n / (r - l), 1e-6);
    CHECK_NEAR(m[5], 2 * n / (t - b), 1e-6);
    CHECK_NEAR(m[8], (r + l) / (r - l), 1e-6);
    CHECK_NEAR(m[9], (t + b) / (t - b), 1e-6);
    CHECK_NEAR(m[10], -(f + n) / (f - n), 1e-6);
    CHECK_NEAR(m[14], -2 * f * n / (f - n), 1e-5);
    CHECK_EQ_INT(m[11], -1);
    CHECK_EQ_INT(m[15], 0);
    fsglLoadIdentity(c);
    fsglOrtho(c, l, r, b, t, n, f);
    CHECK_NEAR(m[0], 2 / (r - l), 1e-7);
    CHECK_NEAR(m[5], 2 / (t - b), 1e-7);
    CHECK_NEAR(m[10], -2 / (f - n), 1e-7);
    CHECK_NEAR(m[12], -(r + l) / (r - l), 1e-7);
    CHECK_NEAR(m[13], -(t + b) / (t - b), 1e-7);
    CHECK_NEAR(m[14], -(f + n) / (f - n), 1e-7);
    CHECK_EQ_INT(m[15], 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    /* INVALID_VALUE rules (2.11.2) leave the matrix alone. */
    float before = m[0];
    fsglFrustum(c, l, r, b, t, 0, f);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglFrustum(c, l, r, b, t, -1, f);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglFrustum(c, l, l, b, t, n, f);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglFrustum(c, l, r, b, t, n, n);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglOrtho(c, l, r, b, b, n, f);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglOrtho(c, l, r, b, t, n, n);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglOrtho(c, l, r, b, t, -1, 1); /* negative near is fine for Ortho */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    (void)before;
    fs_context_destroy(c);
}

TEST(matrix_stack_errors)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    fsglPopMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_STACK_UNDERFLOW);
    for (int i = 0; i < FS_MODELVIEW_STACK_DEPTH - 1; i++) fsglPushMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglTranslatef(c, 1, 2, 3);
    fsglPushMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_STACK_OVERFLOW);
    CHECK_EQ_INT(top_mv(c)[12], 1); /* the failed push changed nothing */
    fsglPopMatrix(c);
    CHECK_EQ_INT(top_mv(c)[12], 0);
    fsglMatrixMode(c, GL_TEXTURE);
    for (int i = 0; i < FS_TEXTURE_STACK_DEPTH - 1; i++) fsglPushMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglPushMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_STACK_OVERFLOW);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglPopMatrix(c);
    CHECK_EQ_INT(fsglGetError(c), GL_STACK_UNDERFLOW);
    fsglMatrixMode(c, GL_COLOR);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fs_context_destroy(c);
}

/* ------------------------------------------------------------ lighting */
TEST(lighting_single_vertex_vs_equation)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    /* Material and two lights: a directional one and a positional spot with
     * attenuation, local viewer on. */
    const float ma[4] = {0.3f, 0.2f, 0.1f, 1}, md[4] = {0.7f, 0.5f, 0.3f, 0.6f}, ms[4] = {0.5f, 0.6f, 0.7f, 1},
                me[4] = {0.05f, 0.0f, 0.1f, 1}, lm[4] = {0.1f, 0.15f, 0.2f, 1};
    const float sh = 17;
    fsglMaterialfv(c, GL_FRONT, GL_AMBIENT, ma);
    fsglMaterialfv(c, GL_FRONT, GL_DIFFUSE, md);
    fsglMaterialfv(c, GL_FRONT, GL_SPECULAR, ms);
    fsglMaterialfv(c, GL_FRONT, GL_EMISSION, me);
    fsglMaterialf(c, GL_FRONT, GL_SHININESS, sh);
    fsglLightModelfv(c, GL_LIGHT_MODEL_AMBIENT, lm);
    fsglLightModeli(c, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    const float l0p[4] = {1, 2, 3, 0}, l0d[4] = {0.9f, 0.8f, 0.7f, 1}, l0a[4] = {0.1f, 0.1f, 0.1f, 1};
    const float l1p[4] = {0.5f, 1, 2, 1}, l1d[4] = {0.4f, 0.6f, 0.9f, 1}, l1s[4] = {1, 1, 1, 1}, sd[3] = {-0.2f, -0.4f, -1};
    fsglLightfv(c, GL_LIGHT0, GL_POSITION, l0p);
    fsglLightfv(c, GL_LIGHT0, GL_DIFFUSE, l0d);
    fsglLightfv(c, GL_LIGHT0, GL_AMBIENT, l0a);
    fsglLightfv(c, GL_LIGHT1, GL_POSITION, l1p);
    fsglLightfv(c, GL_LIGHT1, GL_DIFFUSE, l1d);
    fsglLightfv(c, GL_LIGHT1, GL_SPECULAR, l1s);
    fsglLightfv(c, GL_LIGHT1, GL_SPOT_DIRECTION, sd);
    fsglLightf(c, GL_LIGHT1, GL_SPOT_CUTOFF, 60);
    fsglLightf(c, GL_LIGHT1, GL_SPOT_EXPONENT, 3);
    fsglLightf(c, GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    fsglLightf(c, GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglEnable(c, GL_LIGHTING);
    fsglEnable(c, GL_LIGHT0);
    fsglEnable(c, GL_LIGHT1);
    fs_vs_setup s;
    memset(&s, 0, sizeof s); /* fs_vs_prepare keeps a cache in it */
    fs_vs_prepare(c, &s);
    const double P[3] = {0.1, -0.2, -0.5}, N0[3] = {0.2, 0.3, 1.0};
    double nl = sqrt(N0[0] * N0[0] + N0[1] * N0[1] + N0[2] * N0[2]);
    double N[3] = {N0[0] / nl, N0[1] / nl, N0[2] / nl};
    float eye[4] = {(float)P[0], (float)P[1], (float)P[2], 1}, nf[3] = {(float)N[0], (float)N[1], (float)N[2]};
    float col[4] = {1, 1, 1, 1}, out[2][4];
    fs_light_vertex(&s, eye, nf, col, out, NULL);
    /* The equation of 2.14.1 in double. */
    double res[3];
    for (int k = 0; k < 3; k++) res[k] = me[k] + ma[k] * lm[k];
    const float *lp[2] = {l0p, l1p}, *ld[2] = {l0d, l1d};
    const float zero[4] = {0, 0, 0, 1}, one[4] = {1, 1, 1, 1}, *ls[2] = {one, l1s}, *la[2] = {l0a, zero};
    /* LIGHT0's specular defaults to 1, LIGHT1's ambient to 0. */
    for (int i = 0; i < 2; i++) {
        double VP[3], att = 1, spot = 1;
        if (lp[i][3] == 0) {
            for (int k = 0; k < 3; k++) VP[k] = lp[i][k];
        } else {
            for (int k = 0; k < 3; k++) VP[k] = lp[i][k] - P[k];
            double d = sqrt(VP[0] * VP[0] + VP[1] * VP[1] + VP[2] * VP[2]);
            att = 1.0 / (1 + 0.2 * d + 0.05 * d * d);
            double sl = sqrt(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]);
            double cosang = -(VP[0] * sd[0] + VP[1] * sd[1] + VP[2] * sd[2]) / (d * sl);
            spot = cosang >= cos(60 * 3.14159265358979323846 / 180) ? pow(cosang, 3) : 0;
        }
        double vl = sqrt(VP[0] * VP[0] + VP[1] * VP[1] + VP[2] * VP[2]);
        for (int k = 0; k < 3; k++) VP[k] /= vl;
        double ndl = N[0] * VP[0] + N[1] * VP[1] + N[2] * VP[2];
        double V[3] = {-P[0], -P[1], -P[2]}, vvl = sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
        double H[3];
        for (int k = 0; k < 3; k++) H[k] = VP[k] + V[k] / vvl;
        double hl = sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
        double ndh = (N[0] * H[0] + N[1] * H[1] + N[2] * H[2]) / hl;
        double f = ndl != 0 ? 1 : 0;
        for (int k = 0; k < 3; k++)
            res[k] += att * spot * (ma[k] * la[i][k] + (ndl > 0 ? ndl : 0) * md[k] * ld[i][k] +
                                    f * (ndh > 0 ? pow(ndh, sh) : 0) * ms[k] * ls[i][k]);
    }
    for (int k = 0; k < 3; k++) {
        double e = res[k] < 0 ? 0 : res[k] > 1 ? 1 : res[k];
        CHECK_NEAR(out[0][k], e, 2e-5);
    }
    CHECK_NEAR(out[0][3], md[3], 0);
    fs_context_destroy(c);
}

TEST(lighting_errors_and_counts)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    fsglLightf(c, GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 10);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglLightf(c, GL_LIGHT0, GL_SPOT_CUTOFF, 95);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglLightf(c, GL_LIGHT0, GL_SPOT_EXPONENT, 129);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglLightf(c, GL_LIGHT0, GL_CONSTANT_ATTENUATION, -1);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglLightf(c, GL_LIGHT0, GL_POSITION, 1);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglMaterialf(c, GL_FRONT, GL_SHININESS, 200);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglMaterialf(c, GL_LEFT, GL_SHININESS, 2);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglColorMaterial(c, GL_FRONT, GL_POSITION);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglShadeModel(c, GL_LINE);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    CHECK_EQ_INT(fs_light_param_count(GL_POSITION), 4);
    CHECK_EQ_INT(fs_light_param_count(GL_SPOT_DIRECTION), 3);
    CHECK_EQ_INT(fs_light_param_count(GL_SPOT_CUTOFF), 1);
    CHECK_EQ_INT(fs_lightmodel_param_count(GL_LIGHT_MODEL_AMBIENT), 4);
    CHECK_EQ_INT(fs_lightmodel_param_count(GL_LIGHT_MODEL_TWO_SIDE), 1);
    CHECK_EQ_INT(fs_material_param_count(GL_AMBIENT_AND_DIFFUSE), 4);
    CHECK_EQ_INT(fs_material_param_count(GL_SHININESS), 1);
    CHECK_EQ_INT(fs_material_param_count(GL_POSITION), 0);
    CHECK_EQ_INT(fs_index_bytes(10, GL_UNSIGNED_SHORT), 20);
    CHECK_EQ_INT(fs_index_bytes(-1, GL_UNSIGNED_INT), 0);
    CHECK_EQ_INT(fs_index_bytes(3, GL_FLOAT), 0);
    CHECK_EQ_INT(fs_calllists_bytes(4, GL_3_BYTES), 12);
    CHECK_EQ_INT(fs_type_size(GL_DOUBLE), 8);
    fs_context_destroy(c);
}

/* ------------------------------------------------------------ clipping */
typedef struct captured { int n; fs_rvertex v[64][3]; } captured;
static void capture_tri(void *u, const fs_rvertex *a, const fs_rvertex *b, const fs_rvertex *d)
{
    captured *cp = u;
    if (cp->n < 64) {
        cp->v[cp->n][0] = *a;
        cp->v[cp->n][1] = *b;
        cp->v[cp->n][2] = *d;
    }
    cp->n++;
}

TEST(clip_near_plane_exact)
{
    fs_context *c = ctx(100, 100);
    REQUIRE(c);
    captured cp = {0};
    fs_vs(c)->tri_hook = capture_tri;
    fs_vs(c)->hook_user = &cp;
    fsglViewport(c, 0, 0, 100, 100);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglFrustum(c, -1, 1, -1, 1, 1, 10);
    fsglMatrixMode(c, GL_MODELVIEW);
    /* One vertex in front of the near plane (z_eye = -0.5): the triangle
     * becomes a quadrilateral, two triangles. */
    const float V[3][3] = {{-0.5f, -0.5f, -3}, {0.5f, -0.5f, -3}, {0, 0.2f, -0.5f}};
    const float C[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    fsglBegin(c, GL_TRIANGLES);
    for (int i = 0; i < 3; i++) { fsglColor3fv(c, C[i]); fsglVertex3fv(c, V[i]); }
    fsglEnd(c);
    CHECK_EQ_INT(cp.n, 2);
    CHECK_EQ_INT(c->stats.triangles_clipped, 1);
    /* Every emitted vertex is an input vertex or lies on z_clip = -w_clip,
     * i.e. window z = 0, at the exact intersection of an edge with the
     * near plane (recomputed here in double). */
    double P[16];
    for (int i = 0; i < 16; i++) P[i] = top_proj(c)[i];
    int on_plane = 0;
    for (int t = 0; t < cp.n && t < 64; t++)
        for (int k = 0; k < 3; k++) {
            const fs_rvertex *r = &cp.v[t][k];
            if (fabs(r->z) < 1e-6) {
                on_plane++;
                /* Which edge: from the inside vertex i to the outside vertex 2. */
                double best = 1e9;
                for (int i = 0; i < 2; i++) {
                    double ca[4], cb[4];
                    for (int q = 0; q < 4; q++) {
                        ca[q] = P[q] * V[i][0] + P[4 + q] * V[i][1] + P[8 + q] * V[i][2] + P[12 + q];
                        cb[q] = P[q] * V[2][0] + P[4 + q] * V[2][1] + P[8 + q] * V[2][2] + P[12 + q];
                    }
                    double da = ca[2] + ca[3], db = cb[2] + cb[3], tt = da / (da - db);
                    double cx = ca[0] + tt * (cb[0] - ca[0]), cy = ca[1] + tt * (cb[1] - ca[1]), cw = ca[3] + tt * (cb[3] - ca[3]);
                    double wx = cx / cw * 50 + 50, wy = cy / cw * 50 + 50;
                    double e = fabs(wx - r->x) + fabs(wy - r->y);
                    double col_i = 1 - tt, col_2 = tt; /* colour along the edge, in clip space */
                    e += fabs(r->color[2] - col_2) + fabs(r->color[i] - col_i);
                    if (e < best) best = e;
                }
                CHECK_NEAR(best, 0, 1e-3);
            }
        }
    /* The clipped polygon v0, v1, n1, n2 is fanned as (v1,n1,v0), (n1,n2,v0). */
    CHECK_EQ_INT(on_plane, 3);
    /* Entirely behind the eye: rejected without output. */
    cp.n = 0;
    fsglBegin(c, GL_TRIANGLES);
    fsglVertex3f(c, 0, 0, 1); fsglVertex3f(c, 1, 0, 1); fsglVertex3f(c, 0, 1, 1);
    fsglEnd(c);
    CHECK_EQ_INT(cp.n, 0);
    CHECK_EQ_INT(c->stats.triangles_rejected, 1);
    fs_context_destroy(c);
}

TEST(bad_coordinates_do_not_crash)
{
    fs_context *c = ctx(64, 64);
    REQUIRE(c);
    captured cp = {0};
    fs_vs(c)->tri_hook = capture_tri;
    fs_vs(c)->hook_user = &cp;
    fsglMatrixMode(c, GL_PROJECTION);
    fsglFrustum(c, -1, 1, -1, 1, 1, 10);
    fsglMatrixMode(c, GL_MODELVIEW);
    const float bad[] = {NAN, INFINITY, -INFINITY, 1e38f, -1e38f, 0};
    int nb = (int)(sizeof bad / sizeof bad[0]);
    GLenum modes[] = {GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_QUADS, GL_POLYGON};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        fsglBegin(c, modes[m]);
        for (int i = 0; i < nb; i++)
            for (int j = 0; j < nb; j++) {
                fsglVertex4f(c, bad[i], bad[j], -2, 1);
                fsglVertex4f(c, 0.1f, bad[i], bad[j], 1);
                fsglVertex4f(c, 0.2f, 0.3f, -3, bad[j]);
            }
        fsglEnd(c);
    }
    /* Whatever reached the rasterizer is finite. */
    int finite = 1;
    for (int t = 0; t < cp.n && t < 64; t++)
        for (int k = 0; k < 3; k++)
            finite &= isfinite(cp.v[t][k].x) && isfinite(cp.v[t][k].y) && isfinite(cp.v[t][k].z);
    CHECK(finite);
    CHECK(c->stats.triangles_rejected > 0);
    /* A NaN matrix too. */
    float nanm[16];
    for (int i = 0; i < 16; i++) nanm[i] = NAN;
    fsglLoadMatrixf(c, nanm);
    fsglBegin(c, GL_TRIANGLES);
    fsglVertex3f(c, 0, 0, 0); fsglVertex3f(c, 1, 0, 0); fsglVertex3f(c, 0, 1, 0);
    fsglEnd(c);
    fs_context_destroy(c);
}

/* ------------------------------------------------------------ errors */
TEST(begin_end_and_array_errors)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    fsglEnd(c);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglBegin(c, GL_POLYGON + 1);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglBegin(c, GL_TRIANGLES);
    fsglBegin(c, GL_TRIANGLES);
    fsglEnd(c);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    CHECK_EQ_INT(c->prim.inside_begin, 0);
    fsglBegin(c, GL_TRIANGLES);
    fsglMatrixMode(c, GL_PROJECTION); /* not allowed between Begin and End */
    fsglEnd(c);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    float v[12] = {0};
    fsglVertexPointer(c, 3, GL_FLOAT, 0, v);
    fsglEnableClientState(c, GL_VERTEX_ARRAY);
    fsglDrawArrays(c, GL_TRIANGLES, 0, -1);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglDrawArrays(c, 0x1234, 0, 3);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    GLubyte idx[3] = {0, 1, 2};
    fsglDrawElements(c, GL_TRIANGLES, 3, GL_FLOAT, idx);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglDrawElements(c, GL_TRIANGLES, -3, GL_UNSIGNED_BYTE, idx);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglDrawRangeElements(c, GL_TRIANGLES, 2, 1, 3, GL_UNSIGNED_BYTE, idx);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    /* GL 1.5 2.8: a negative count is INVALID_VALUE for DrawRangeElements too. */
    fsglDrawRangeElements(c, GL_TRIANGLES, 0, 2, -3, GL_UNSIGNED_BYTE, idx);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglVertexPointer(c, 5, GL_FLOAT, 0, v);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglVertexPointer(c, 3, GL_UNSIGNED_BYTE, 0, v);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglColorPointer(c, 2, GL_FLOAT, 0, v);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglEnableClientState(c, GL_TEXTURE_2D);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglViewport(c, 0, 0, -1, 4);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(c->stats.vertices, 3);
    /* A NULL array (there are no buffer objects to offset into) is refused
     * and counted by name rather than read. */
    fsglVertexPointer(c, 3, GL_FLOAT, 0, NULL);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(c->stats.vertices, 3);
    CHECK(c->unsupported_feature_count == 1 &&
          strcmp(c->unsupported_feature[0].name, "glDrawArrays (client array shorter than the draw reads)") == 0);
    /* The same while a list is compiled and executed: refused once, neither
     * compiled nor run; from a good array, run once now and once per call
     * of the list. */
    fsglNewList(c, 1, GL_COMPILE_AND_EXECUTE);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3);
    fsglVertexPointer(c, 3, GL_FLOAT, 0, v);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3);
    fsglEndList(c);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_UINT(c->unsupported_feature[0].count, 2);
    CHECK_EQ_INT(c->stats.vertices, 6);
    fsglCallList(c, 1);
    CHECK_EQ_INT(c->stats.vertices, 9);
    fs_context_destroy(c);
}

/* glArrayElement reads only the enabled arrays (GL 1.5 spec 2.8): found by
 * tests/fuzz/fuzz_gl.c, it read the disabled (NULL) vertex array. */
TEST(array_element_reads_enabled_arrays_only)
{
    fs_context *c = ctx(8, 8);
    REQUIRE(c);
    fsglColor4f(c, 0.25f, 0.5f, 0.75f, 1.0f);
    fsglArrayElement(c, 1000); /* no array enabled: nothing happens */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK(c->current.color[0] == 0.25f && c->current.color[2] == 0.75f);
    /* Only the colour array: element 1 becomes the current colour. */
    const float col[8] = {0, 0, 0, 1, 1.0f, 0.0f, 0.5f, 1.0f};
    fsglColorPointer(c, 4, GL_FLOAT, 0, col);
    fsglEnableClientState(c, GL_COLOR_ARRAY);
    fsglArrayElement(c, 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK(c->current.color[0] == 1.0f && c->current.color[1] == 0.0f && c->current.color[2] == 0.5f);
    CHECK_EQ_INT(c->stats.vertices, 0);
    fs_context_destroy(c);
}

/* glGenLists of a huge range fails with GL_OUT_OF_MEMORY and changes
 * nothing, instead of allocating 2^31 lists (found by fuzz_gl). */
TEST(gen_lists_huge_range_is_out_of_memory)
{
    fs_context *c = ctx(8, 8);
    REQUIRE(c);
    CHECK_EQ_UINT(fsglGenLists(c, 2147483647), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    CHECK_EQ_UINT(fsglGenLists(c, -1), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    CHECK_EQ_UINT(fsglGenLists(c, 3), 1); /* names 1..3: nothing was reserved */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglDeleteLists(c, 1, 3);
    CHECK_EQ_UINT(fsglGenLists(c, 1 << 20), 1); /* the whole allowance, after deleting */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_UINT(fsglGenLists(c, 1), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    fs_context_destroy(c);
}

/* glDeleteLists of a huge range deletes the lists in it without probing
 * every name (2^31 probes took minutes; found by fuzz_gl), and names do not
 * wrap past 2^32 - 1. */
TEST(delete_lists_huge_range_is_quick)
{
    fs_context *c = ctx(8, 8);
    REQUIRE(c);
    CHECK_EQ_UINT(fsglGenLists(c, 3), 1);
    fsglNewList(c, 1000, GL_COMPILE);
    fsglEndList(c);
    fsglNewList(c, 0xffffffffu, GL_COMPILE);
    fsglEndList(c);
    fsglDeleteLists(c, 2, 2147483647); /* 2, 3 and 1000; not 1, not 2^32 - 1 */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK(fsglIsList(c, 1));
    CHECK(!fsglIsList(c, 2) && !fsglIsList(c, 3) && !fsglIsList(c, 1000));
    CHECK(fsglIsList(c, 0xffffffffu));
    fsglDeleteLists(c, 0xfffffff0u, 100); /* up to 2^32 - 1, no wrap to 1 */
    CHECK(!fsglIsList(c, 0xffffffffu));
    CHECK(fsglIsList(c, 1));
    fs_context_destroy(c);
}

TEST(color_conversions_table_2_9)
{
    fs_context *c = ctx(16, 16);
    REQUIRE(c);
    fsglColor4ub(c, 255, 0, 128, 51);
    CHECK_NEAR(c->current.color[2], 128.0 / 255, 1e-7);
    CHECK_NEAR(c->current.color[3], 0.2, 1e-7);
    fsglColor4b(c, 127, -128, 0, -1);
    CHECK_NEAR(c->current.color[0], 1, 1e-7);
    CHECK_NEAR(c->current.color[1], -1, 1e-7);
    CHECK_NEAR(c->current.color[2], 1.0 / 255, 1e-7);
    CHECK_NEAR(c->current.color[3], -1.0 / 255, 1e-7);
    fsglColor3us(c, 65535, 0, 32768);
    CHECK_NEAR(c->current.color[2], 32768.0 / 65535, 1e-7);
    CHECK_NEAR(c->current.color[3], 1, 0);
    fsglColor3s(c, 32767, -32768, 0);
    CHECK_NEAR(c->current.color[0], 1, 1e-7);
    CHECK_NEAR(c->current.color[1], -1, 1e-7);
    fsglColor4ui(c, 0xffffffffu, 0, 0x80000000u, 0);
    CHECK_NEAR(c->current.color[0], 1, 1e-7);
    CHECK_NEAR(c->current.color[2], 0.5, 1e-7);
    fsglColor3i(c, 2147483647, -2147483647 - 1, 0);
    CHECK_NEAR(c->current.color[0], 1, 1e-7);
    CHECK_NEAR(c->current.color[1], -1, 1e-7);
    fsglNormal3b(c, 127, -128, 0);
    CHECK_NEAR(c->current.normal[0], 1, 1e-7);
    CHECK_NEAR(c->current.normal[1], -1, 1e-7);
    fs_context_destroy(c);
}

/* ------------------------------------------------------------ OSMesa scenes */
/* The same scene code drives fragsim (c != NULL) and OSMesa (c == NULL):
 * G() and G0() from osmesa_util.h. */

typedef void (*scene_fn)(fs_context *c, int w, int h);

static void common_setup(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.1f, 0.1f, 0.15f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 40.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -8);
}

static void scene_lit_sphere(fs_context *c, int w, int h)
{
    common_setup(c, w, h);
    const float lp[4] = {2, 3, 4, 0}, lp1[4] = {-2, 1, 1, 1}, spec[4] = {1, 1, 1, 1}, red[4] = {0.8f, 0.2f, 0.1f, 1};
    const float d1[4] = {0.2f, 0.3f, 0.9f, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, lp);
    G(Lightfv, GL_LIGHT1, GL_POSITION, lp1);
    G(Lightfv, GL_LIGHT1, GL_DIFFUSE, d1);
    G(Lightf, GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    G(Enable, GL_LIGHT1);
    G(Enable, GL_NORMALIZE);
    G(Materialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    G(Materialfv, GL_FRONT, GL_SPECULAR, spec);
    G(Materialf, GL_FRONT, GL_SHININESS, 40);
    G(Rotatef, 20, 1, 0.3f, 0);
    G(Scalef, 2.5f, 2.5f, 2.5f);
    const int S = 24, T = 16;
    for (int j = 0; j < T; j++) {
        double a0 = 3.14159265358979 * j / T - 1.5707963, a1 = 3.14159265358979 * (j + 1) / T - 1.5707963;
        G(Begin, GL_QUAD_STRIP);
        for (int i = 0; i <= S; i++) {
            double b = 2 * 3.14159265358979 * i / S;
            float x0 = (float)(cos(a0) * cos(b)), y0 = (float)sin(a0), z0 = (float)(cos(a0) * sin(b));
            float x1 = (float)(cos(a1) * cos(b)), y1 = (float)sin(a1), z1 = (float)(cos(a1) * sin(b));
            G(Normal3f, x1, y1, z1);
            G(Vertex3f, x1, y1, z1);
            G(Normal3f, x0, y0, z0);
            G(Vertex3f, x0, y0, z0);
        }
        G0(End);
    }
}

/* glxgears-like: flat-shaded lit quads and quad strips (a toothed ring). */
static void gear(fs_context *c, float inner, float outer, float width, int teeth, float tooth)
{
    float r0 = inner, r1 = outer - tooth / 2, r2 = outer + tooth / 2;
    float da = 2 * 3.14159265f / teeth / 4;
    G(Normal3f, 0, 0, 1);
    G(Begin, GL_QUAD_STRIP);
    for (int i = 0; i <= teeth; i++) {
        float a = i * 2 * 3.14159265f / teeth;
        G(Vertex3f, r0 * cosf(a), r0 * sinf(a), width * 0.5f);
        G(Vertex3f, r1 * cosf(a), r1 * sinf(a), width * 0.5f);
        if (i < teeth) {
            G(Vertex3f, r0 * cosf(a), r0 * sinf(a), width * 0.5f);
            G(Vertex3f, r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), width * 0.5f);
        }
    }
    G0(End);
    G(Begin, GL_QUADS);
    for (int i = 0; i < teeth; i++) {
        float a = i * 2 * 3.14159265f / teeth;
        G(Vertex3f, r1 * cosf(a), r1 * sinf(a), width * 0.5f);
        G(Vertex3f, r2 * cosf(a + da), r2 * sinf(a + da), width * 0.5f);
        G(Vertex3f, r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), width * 0.5f);
        G(Vertex3f, r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), width * 0.5f);
    }
    G0(End);
    G(Begin, GL_QUAD_STRIP);
    for (int i = 0; i < teeth; i++) {
        float a = i * 2 * 3.14159265f / teeth;
        G(Vertex3f, r1 * cosf(a), r1 * sinf(a), width * 0.5f);
        G(Vertex3f, r1 * cosf(a), r1 * sinf(a), -width * 0.5f);
        float u = r2 * cosf(a + da) - r1 * cosf(a), v = r2 * sinf(a + da) - r1 * sinf(a);
        float len = sqrtf(u * u + v * v);
        G(Normal3f, v / len, -u / len, 0);
        G(Vertex3f, r2 * cosf(a + da), r2 * sinf(a + da), width * 0.5f);
        G(Vertex3f, r2 * cosf(a + da), r2 * sinf(a + da), -width * 0.5f);
        G(Normal3f, cosf(a), sinf(a), 0);
        G(Vertex3f, r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), width * 0.5f);
        G(Vertex3f, r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), -width * 0.5f);
        G(Normal3f, cosf(a + 3 * da), sinf(a + 3 * da), 0);
        G(Vertex3f, r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), width * 0.5f);
        G(Vertex3f, r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), -width * 0.5f);
    }
    G(Vertex3f, r1, 0, width * 0.5f);
    G(Vertex3f, r1, 0, -width * 0.5f);
    G0(End);
}

static void scene_gears(fs_context *c, int w, int h)
{
    common_setup(c, w, h);
    const float pos[4] = {5, 5, 10, 0}, red[4] = {0.8f, 0.1f, 0, 1}, green[4] = {0, 0.8f, 0.2f, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, pos);
    G(Enable, GL_CULL_FACE);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    G(ShadeModel, GL_FLAT);
    G(Rotatef, 20, 1, 0, 0);
    G(Rotatef, 30, 0, 1, 0);
    G0(PushMatrix);
    G(Translatef, -1.5f, -1, 0);
    G(Materialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    gear(c, 0.5f, 2, 1, 20, 0.35f);
    G0(PopMatrix);
    G0(PushMatrix);
    G(Translatef, 2.1f, -1.1f, 0);
    G(Rotatef, 9, 0, 0, 1);
    G(Materialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    gear(c, 0.25f, 1, 1.5f, 10, 0.3f);
    G0(PopMatrix);
}

/* Smooth colours, triangles crossing the near plane and the window edges. */
static void scene_clipping(fs_context *c, int w, int h)
{
    common_setup(c, w, h);
    G(Rotatef, 35, 0, 1, 0);
    G(Begin, GL_TRIANGLES);
    for (int i = 0; i < 12; i++) {
        float a = i * 0.52f, z = -3 + (float)i * 1.2f;
        G(Color3f, 1, 0.2f * (i % 5), 0);
        G(Vertex3f, -6 + i * 1.1f, -5.0f + (i % 3), z);
        G(Color3f, 0, 1, 0.1f * i);
        G(Vertex3f, 5 * cosf(a), 6, z + 4);
        G(Color3f, 0.3f, 0, 1);
        G(Vertex3f, 7 - i * 0.3f, 2 * sinf(a), 9 - i);
    }
    G0(End);
    G(Begin, GL_QUADS);
    G(Color3f, 1, 1, 0); G(Vertex3f, -9, -9, -5);
    G(Color3f, 0, 1, 1); G(Vertex3f, 9, -9, -5);
    G(Color3f, 1, 0, 1); G(Vertex3f, 9, -1, 10);
    G(Color3f, 1, 1, 1); G(Vertex3f, -9, -1, 10);
    G0(End);
}

/* Vertex arrays: a grid of quads with DrawArrays and of triangles with
 * DrawElements, smooth colours. */
static void scene_arrays(fs_context *c, int w, int h)
{
    common_setup(c, w, h);
    G(Rotatef, -40, 1, 0, 0);
    enum { N = 12 };
    static float pos[N * N * 4][3], col[N * N * 4][4];
    static float gp[(N + 1) * (N + 1)][3];
    static GLubyte gc[(N + 1) * (N + 1)][4];
    static GLushort idx[N * N * 6];
    int k = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
            for (int q = 0; q < 4; q++) {
                float x = -3 + (i + di[q]) * 0.5f, y = -3 + (j + dj[q]) * 0.5f;
                pos[k][0] = x; pos[k][1] = y; pos[k][2] = 0.3f * sinf(x * y);
                col[k][0] = (float)q / 3; col[k][1] = (float)i / N; col[k][2] = (float)j / N; col[k][3] = 1;
                k++;
            }
        }
    G(VertexPointer, 3, GL_FLOAT, 0, pos);
    G(ColorPointer, 4, GL_FLOAT, 0, col);
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    /* FS_VS_PART=1 or 2 renders one draw alone, to locate differences. */
    if (!getenv("FS_VS_PART") || atoi(getenv("FS_VS_PART")) & 1)
        G(DrawArrays, GL_QUADS, 0, k);
    G(Translatef, 0.2f, 0.1f, 1.5f);
    G(Scalef, 0.5f, 0.5f, 0.5f);
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int v = j * (N + 1) + i;
            gp[v][0] = -3 + i * 0.5f; gp[v][1] = -3 + j * 0.5f; gp[v][2] = 0.4f * cosf((float)(i + j));
            gc[v][0] = (GLubyte)(i * 20); gc[v][1] = (GLubyte)(j * 20); gc[v][2] = (GLubyte)(255 - i * 10); gc[v][3] = 255;
        }
    int n = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int v = j * (N + 1) + i;
            GLushort q[6] = {(GLushort)v, (GLushort)(v + 1), (GLushort)(v + N + 2), (GLushort)v, (GLushort)(v + N + 2), (GLushort)(v + N + 1)};
            memcpy(&idx[n], q, sizeof q);
            n += 6;
        }
    G(VertexPointer, 3, GL_FLOAT, 0, gp);
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, 0, gc);
    if (!getenv("FS_VS_PART") || atoi(getenv("FS_VS_PART")) & 2)
        G(DrawElements, GL_TRIANGLES, n, GL_UNSIGNED_SHORT, idx);
    G(DisableClientState, GL_VERTEX_ARRAY);
    G(DisableClientState, GL_COLOR_ARRAY);
}

/* Two-sided lighting with colour material, polygons and fans. */
static void scene_two_side(fs_context *c, int w, int h)
{
    common_setup(c, w, h);
    const float pos[4] = {0, 0, 5, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, pos);
    G(LightModeli, GL_LIGHT_MODEL_TWO_SIDE, 1);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    G(Enable, GL_COLOR_MATERIAL);
    G(Rotatef, 60, 0, 1, 0);
    G(Begin, GL_POLYGON);
    for (int i = 0; i < 7; i++) {
        float a = i * 2 * 3.14159265f / 7;
        G(Color3f, 0.5f + 0.5f * cosf(a), 0.5f, 0.5f + 0.5f * sinf(a));
        G(Normal3f, 0, 0, 1);
        G(Vertex3f, -1.5f + 1.4f * cosf(a), 1.4f * sinf(a), 0);
    }
    G0(End);
    G(Begin, GL_TRIANGLE_FAN);
    G(Color3f, 1, 1, 1);
    G(Normal3f, 0, 0, -1);
    G(Vertex3f, 1.5f, 0, 0);
    for (int i = 0; i <= 8; i++) {
        float a = i * 2 * 3.14159265f / 8;
        G(Color3f, 0.2f, 0.5f + 0.5f * sinf(a), 0.8f);
        G(Vertex3f, 1.5f + 1.3f * sinf(a), 1.3f * cosf(a), 0);
    }
    G0(End);
}

typedef struct cmp_result { long differ, differ_gt1, coverage; int maxd; } cmp_result;

/* osm_pair's drawing callback: user is the scene function. */
static void draw_scene(fs_context *c, const void *user, int w, int h)
{
    const scene_fn *fn = user;
    (*fn)(c, w, h);
}

static int render_compare(scene_fn scene, int w, int h, cmp_result *res, const char *name)
{
    memset(res, 0, sizeof *res);
    osm_pair p;
    if (!osm_pair_render(&p, w, h, ctx, draw_scene, &scene))
        return -1;
    res->differ = p.d.differ;
    res->differ_gt1 = p.d.differ_gt1;
    res->maxd = p.d.maxd;
    printf("  %-12s %dx%d: %ld pixels differ (%ld by more than 1/255), max %d; %llu triangles in, %llu clipped\n",
           name, w, h, res->differ, res->differ_gt1, res->maxd, (unsigned long long)p.c->stats.triangles_in,
           (unsigned long long)p.c->stats.triangles_clipped);
    if (getenv("FS_VS_DUMP")) {
        char fn[256];
        snprintf(fn, sizeof fn, "/tmp/vs_%s.ppm", name);
        img_dump_ppm(fn, p.ref.color, p.c->fb.color, w, h, 1, false);
    }
    osm_pair_close(&p);
    return 0;
}

/* Coverage must match exactly; colours within 1/255. */
#define SCENE_TEST(nm, fn, w, h)                                  \
    TEST(nm)                                                      \
    {                                                             \
        cmp_result r;                                             \
        REQUIRE(render_compare(fn, w, h, &r, #nm) == 0);          \
        CHECK_EQ_INT(r.differ_gt1, 0);                            \
    }

SCENE_TEST(lit_sphere_vs_osmesa, scene_lit_sphere, 160, 120)
SCENE_TEST(gears_vs_osmesa, scene_gears, 200, 150)
SCENE_TEST(clipping_vs_osmesa, scene_clipping, 160, 120)
SCENE_TEST(arrays_vs_osmesa, scene_arrays, 160, 120)
SCENE_TEST(two_side_vs_osmesa, scene_two_side, 160, 120)

/* ------------------------------------------------------------ speed */
TEST(draw_arrays_100k_triangles)
{
    fs_context *c = ctx(256, 256);
    REQUIRE(c);
    enum { NT = 100000 };
    float *v = malloc(sizeof(float) * 3 * 3 * NT);
    REQUIRE(v);
    unsigned seed = 7;
    for (int i = 0; i < NT; i++) {
        float cx = (float)(rand_r(&seed) % 1000) / 500 - 1, cy = (float)(rand_r(&seed) % 1000) / 500 - 1;
        for (int k = 0; k < 3; k++) {
            v[(i * 3 + k) * 3 + 0] = cx + 0.01f * (k == 1);
            v[(i * 3 + k) * 3 + 1] = cy + 0.01f * (k == 2);
            v[(i * 3 + k) * 3 + 2] = 0;
        }
    }
    fsglVertexPointer(c, 3, GL_FLOAT, 0, v);
    fsglEnableClientState(c, GL_VERTEX_ARRAY);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3 * NT);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double ms = (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) / 1e6;
    printf("  DrawArrays of %d triangles: %.1f ms (vertex stage and rasterizer)\n", NT, ms);
    CHECK_EQ_UINT(c->stats.triangles_in, NT);
    CHECK_EQ_UINT(c->stats.vertices, 3 * NT);
    free(v);
    fs_context_destroy(c);
}

/* Bit for bit, except that any NaN equals any NaN: a NaN's sign and
 * payload differ between library and instruction (and between compilers)
 * and carry nothing, since such a vertex is culled. */
static bool same_floats(const float *a, const float *b, int n)
{
    for (int i = 0; i < n; i++)
        if (!(isnan(a[i]) && isnan(b[i])) && memcmp(&a[i], &b[i], sizeof a[i]) != 0)
            return false;
    return true;
}

/* The FMA variant of the batch transform (chosen at run time) and the
 * library-fmaf one give the same bits for every vertex, extreme ones too. */
/* A tile mask for the test: one tile in 16, by a formula. */
static bool one_tile_in_16(const void *user, uint32_t tx, uint32_t ty)
{
    (void)user;
    return (tx * 7u + ty * 3u) % 16u == 0;
}

/* Whether a batch may make fragments in a masked tile, by brute force: a
 * batch wholly outside one clip plane makes none, one partly outside any is
 * left to the clipper, and otherwise some pixel of its window box, one
 * pixel wider on each side, lies in a masked tile. */
static bool batch_meets(const fs_pvert *v, int n, const fs_tile_mask *m)
{
    unsigned any = 0, all = ~0u;
    float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int i = 0; i < n; i++) {
        any |= v[i].mask;
        all &= v[i].mask;
        x0 = fminf(x0, v[i].win[0]), x1 = fmaxf(x1, v[i].win[0]);
        y0 = fminf(y0, v[i].win[1]), y1 = fmaxf(y1, v[i].win[1]);
    }
    if (all)
        return false;
    if (any)
        return true;
    for (int py = y0 - 1.0f > 0.0f ? (int)(y0 - 1.0f) : 0; py <= (int)(y1 + 1.0f); py++)
        for (int px = x0 - 1.0f > 0.0f ? (int)(x0 - 1.0f) : 0; px <= (int)(x1 + 1.0f); px++)
            if (m->off_map(NULL, (uint32_t)px >> m->shift, (uint32_t)py >> m->shift))
                return true;
    return false;
}

TEST(fma_variant_identical)
{
    fs_context *c = ctx(640, 480);
    REQUIRE(c);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglFrustum(c, -1.1, 0.9, -0.7, 0.8, 1.3, 90.0);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglRotatef(c, 33, 0.3f, 1, 0.2f);
    fsglTranslatef(c, 0.7f, -0.4f, -5.0f);
    fsglEnable(c, GL_LIGHTING);
    fsglEnable(c, GL_LIGHT0);
    enum { N = 20000 };
    fs_ivert *in = calloc(N, sizeof *in);
    fs_pvert *a = calloc(N, sizeof *a), *b = calloc(N, sizeof *b);
    REQUIRE(in && a && b);
    uint32_t r = 12345;
    const float odd[] = {0.0f, -0.0f, 1e30f, -1e30f, 1e-30f, INFINITY, -INFINITY, NAN};
    for (int i = 0; i < N; i++) {
        for (int k = 0; k < 4; k++) {
            r = r * 1664525u + 1013904223u;
            float v = ((float)(r >> 8) / 16777216.0f - 0.5f) * (k == 3 ? 2.0f : 40.0f);
            in[i].obj[k] = (i % 97 == 0) ? odd[(i / 97 + k) % 8] : v;
        }
        if (i % 3)
            in[i].obj[3] = 1.0f;
        in[i].nrm[0] = 0.2f;
        in[i].nrm[1] = 0.9f;
        in[i].nrm[2] = 0.3f;
        for (int k = 0; k < 4; k++)
            in[i].col[k] = 0.5f;
    }
    fs_vs_setup s;
    memset(&s, 0, sizeof s);
    fs_vs_prepare(c, &s);
    /* The plain loop (no FMA, no AVX2) is the reference for the variants. */
    bool hw = s.has_fma, avx2 = s.has_avx2;
    s.has_fma = s.has_avx2 = false;
    fs_vs_process(&s, in, a, N, NULL);
    s.has_fma = hw;
    s.has_avx2 = avx2;
    fs_vs_process(&s, in, b, N, NULL);
    long differ = 0;
    for (int i = 0; i < N; i++) {
        bool same = a[i].mask == b[i].mask && same_floats(a[i].clip, b[i].clip, 4) && same_floats(a[i].win, b[i].win, 5) &&
                    same_floats(a[i].col[0], b[i].col[0], 4) && same_floats(a[i].col[1], b[i].col[1], 4) &&
                    same_floats(a[i].tc[0], b[i].tc[0], 4);
        differ += !same;
    }
    printf("    fma_variant_identical: %d vertices, hardware FMA %s, AVX2 %s, %ld differ\n", N, hw ? "yes" : "no",
           avx2 ? "yes" : "no", differ);
    CHECK_EQ_INT(differ, 0);
    /* Under a tile mask (lazy vertices: positions only) the positions and
     * clip masks are the full pass's, in batches of every length mod 8, and
     * a batch is lazy exactly when its box, one pixel wider, meets a
     * masked tile (brute force over the box's pixels). */
    const fs_tile_mask tiles = {true, false, 4, 0, 0, NULL, one_tile_in_16, NULL};
    long batches = 0, needed = 0;
    differ = 0;
    for (int at = 0, n = 1; at + n <= N; at += n, n = n % 37 + 1) {
        s.has_fma = s.has_avx2 = false;
        fs_vs_process(&s, in + at, a + at, (size_t)n, NULL);
        s.has_fma = hw;
        s.has_avx2 = avx2;
        bool lazy = fs_vs_process(&s, in + at, b + at, (size_t)n, &tiles);
        batches++;
        needed += lazy;
        differ += lazy != batch_meets(b + at, n, &tiles);
        for (int i = at; i < at + n; i++)
            differ += !(a[i].mask == b[i].mask && b[i].lazy == lazy && same_floats(a[i].clip, b[i].clip, 4) &&
                        same_floats(a[i].win, b[i].win, 5));
    }
    printf("    tile mask position pass: %ld batches (%ld meet the mask), %ld differ\n", batches, needed, differ);
    CHECK(needed > 0 && needed < batches);
    CHECK_EQ_INT(differ, 0);
    free(in);
    free(a);
    free(b);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(matrix_defaults_and_products),
    TEST_ENTRY(rotate_matches_spec_formula),
    TEST_ENTRY(frustum_and_ortho_closed_form),
    TEST_ENTRY(matrix_stack_errors),
    TEST_ENTRY(lighting_single_vertex_vs_equation),
    TEST_ENTRY(lighting_errors_and_counts),
    TEST_ENTRY(clip_near_plane_exact),
    TEST_ENTRY(bad_coordinates_do_not_crash),
    TEST_ENTRY(begin_end_and_array_errors),
    TEST_ENTRY(array_element_reads_enabled_arrays_only),
    TEST_ENTRY(gen_lists_huge_range_is_out_of_memory),
    TEST_ENTRY(delete_lists_huge_range_is_quick),
    TEST_ENTRY(color_conversions_table_2_9),
    TEST_ENTRY(lit_sphere_vs_osmesa),
    TEST_ENTRY(gears_vs_osmesa),
    TEST_ENTRY(clipping_vs_osmesa),
    TEST_ENTRY(arrays_vs_osmesa),
    TEST_ENTRY(two_side_vs_osmesa),
    TEST_ENTRY(draw_arrays_100k_triangles),
    TEST_ENTRY(fma_variant_identical),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
