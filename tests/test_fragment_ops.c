/*
 * Per-fragment operations (GL 1.5 spec 4.1-4.3) against the GL spec's
 * closed-form rules and against OSMesa/llvmpipe in the same process.
 *
 * fragsim is fed quads built directly (one covered pixel per quad, or whole
 * quads), so these tests measure the fragment stage alone: depth values are
 * taken from what llvmpipe stored for the same primitive, not recomputed.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../pipeline/fragment_stages.h"

/* ---------------------------------------------------------------- helpers */

/* A window-sized orthographic projection on top of osm_open. */
static bool osm_open_ortho(osm *o, int w, int h)
{
    if (!osm_open(o, w, h))
        return false;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DITHER); /* no effect in llvmpipe either way; kept equal below */
    glEnable(GL_DITHER);
    return true;
}

/* Points of size 1 at pixel centres, colours and depths per point. */
static void osm_points(int n, const float *xyz, const float *rgba)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, xyz);
    glColorPointer(4, GL_FLOAT, 0, rgba);
    glDrawArrays(GL_POINTS, 0, n);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
}

/* Writes RGBA8 into OSMesa's colour buffer with every fragment operation
 * that could alter it switched off; the caller's state is restored. */
static void osm_put_rgba(const osm *o, const uint8_t *rgba)
{
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glDisable(GL_BLEND);
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(1, 1, 1, 1);
    glWindowPos2i(0, 0);
    glDrawPixels(o->w, o->h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPopAttrib();
}

static void osm_read_rgba(const osm *o, uint8_t *out)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, o->w, o->h, GL_RGBA, GL_UNSIGNED_BYTE, out);
}

/* Raw depth values (low 24 bits of each 32-bit word). */
static void osm_read_depth_raw(const osm *o, uint32_t *out)
{
    GLint w, h, bpv;
    void *p;
    glFinish();
    if (!OSMesaGetDepthBuffer(o->ctx, &w, &h, &bpv, &p) || bpv != 4) {
        memset(out, 0xff, (size_t)o->w * (size_t)o->h * 4);
        return;
    }
    const uint32_t *src = p;
    for (int i = 0; i < o->w * o->h; i++)
        out[i] = src[i] & 0xffffffu;
}

static void osm_read_stencil(const osm *o, uint8_t *out)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, o->w, o->h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out);
}

/* One fragment at pixel (x,y) as a quad with one covered pixel. */
static void frag_pixel(fs_context *c, int x, int y, const float rgba[4], uint32_t z)
{
    fs_quad q;
    memset(&q, 0, sizeof q);
    q.x = x & ~1;
    q.y = y & ~1;
    int i = (x & 1) | ((y & 1) << 1);
    q.mask = 1u << i;
    q.front_facing = true;
    q.z[i] = z;
    memcpy(q.color[i], rgba, sizeof q.color[i]);
    fs_fragment_quad(c, &q);
}

static uint32_t rng_next(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static float rng_unit(uint32_t *s)
{
    return (float)(rng_next(s) >> 8) / 16777215.0f;
}

static const GLenum k_factors[] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA,
    GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
};
#define N_FACTORS (int)(sizeof k_factors / sizeof k_factors[0])

static const GLenum k_funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const GLenum k_sops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR,
                                GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};

/* Counts differing bytes and the largest difference. */
static long count_diff(const uint8_t *a, const uint8_t *b, size_t n, int *maxd)
{
    long d = 0;
    *maxd = 0;
    for (size_t i = 0; i < n; i++) {
        if (a[i] != b[i]) {
            d++;
            int e = abs((int)a[i] - (int)b[i]);
            if (e > *maxd)
                *maxd = e;
        }
    }
    return d;
}

/* ------------------------------------------- conversion and blending vs OSMesa */

#define SW 256
#define SH 256

/* Float colour -> unorm8: a fine sweep of [0,1] plus every rounding tie
 * (k + 0.5)/255 and its float neighbours. */
TEST(color_conversion_vs_osmesa)
{
    osm o;
    REQUIRE(osm_open_ortho(&o, SW, SH));
    fs_context *c = fs_context_create(NULL, SW, SH);
    REQUIRE(c);
    int n = SW * SH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint8_t *ref = malloc((size_t)n * 4);
    REQUIRE(xyz && col && ref);
    for (int i = 0; i < n; i++) {
        float v;
        if (i < n / 2) {
            v = (float)i / (float)(n / 2 - 1);
        } else {
            int k = ((i - n / 2) / 64) % 255, j = (i - n / 2) % 64;
            v = ((float)k + 0.5f) / 255.0f;
            for (int t = 0; t < j - 32; t++) v = nextafterf(v, 2.0f);
            for (int t = 0; t < 32 - j; t++) v = nextafterf(v, -1.0f);
        }
        xyz[i * 3] = (float)(i % SW) + 0.5f;
        xyz[i * 3 + 1] = (float)(i / SW) + 0.5f;
        xyz[i * 3 + 2] = 0.0f;
        float rgba[4] = {v, 1.0f - v, v * 0.5f, fminf(1.0f, v * 3.0f)};
        memcpy(col + i * 4, rgba, sizeof rgba);
        frag_pixel(c, i % SW, i / SW, rgba, 0);
    }
    osm_points(n, xyz, col);
    osm_read_rgba(&o, ref);
    int maxd;
    long d = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
    printf("  colour conversion: %ld of %d values differ from OSMesa (max %d)\n", d, n * 4, maxd);
    CHECK_EQ_INT(d, 0);
    CHECK_EQ_INT(c->stats.fragments_written, n);
    free(xyz);
    free(col);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* Random destination bytes (with 0 and 255 mixed in) and source floats
 * (with 0 and 1) for n pixels. */
static void random_blend_inputs(uint32_t *seed, int n, uint8_t *dst, float *col)
{
    for (int i = 0; i < n * 4; i++) {
        int v = (int)(rng_next(seed) & 255u);
        if (i % 32 < 4) v = 0;
        else if (i % 32 < 8) v = 255;
        dst[i] = (uint8_t)v;
        float s = rng_unit(seed);
        if (i % 29 == 0) s = 1.0f;
        else if (i % 31 == 0) s = 0.0f;
        col[i] = s;
    }
}

/* The blend tests' buffers for a w x h grid: one point at each pixel
 * centre (xyz), source colours (col), destination and reference bytes.
 * False when out of memory (what was allocated is freed). */
static bool blend_buffers(int w, int h, float **xyz, float **col, uint8_t **dst, uint8_t **ref)
{
    size_t n = (size_t)w * (size_t)h;
    *xyz = malloc(sizeof(float) * 3 * n);
    *col = malloc(sizeof(float) * 4 * n);
    *dst = malloc(n * 4);
    *ref = malloc(n * 4);
    if (!*xyz || !*col || !*dst || !*ref) {
        free(*xyz);
        free(*col);
        free(*dst);
        free(*ref);
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        (*xyz)[i * 3] = (float)(i % (size_t)w) + 0.5f;
        (*xyz)[i * 3 + 1] = (float)(i / (size_t)w) + 0.5f;
        (*xyz)[i * 3 + 2] = 0.0f;
    }
    return true;
}

/* Every (sfactor, dfactor) pair Mesa accepts (GL_SRC_ALPHA_SATURATE as a
 * destination factor too), random source floats and
 * destination bytes (with 0 and 255 mixed in). */
TEST(blend_all_factor_pairs_vs_osmesa)
{
    enum { BW = 128, BH = 128 };
    osm o;
    REQUIRE(osm_open_ortho(&o, BW, BH));
    fs_context *c = fs_context_create(NULL, BW, BH);
    REQUIRE(c);
    int n = BW * BH;
    float *xyz, *col;
    uint8_t *dst, *ref;
    REQUIRE(blend_buffers(BW, BH, &xyz, &col, &dst, &ref));
    uint32_t seed = 0x1234567u;
    long total = 0, diff = 0;
    int maxd_all = 0, pairs = 0;
    for (int a = 0; a < N_FACTORS; a++) {
        for (int b = 0; b < N_FACTORS; b++) {
            pairs++;
            random_blend_inputs(&seed, n, dst, col);
            osm_put_rgba(&o, dst);
            glEnable(GL_BLEND);
            glBlendFunc(k_factors[a], k_factors[b]);
            osm_points(n, xyz, col);
            glDisable(GL_BLEND);
            osm_read_rgba(&o, ref);

            memcpy(c->fb.color, dst, (size_t)n * 4);
            c->frag.blend_enabled = true;
            fs_exec_BlendFunc(c, k_factors[a], k_factors[b]);
            CHECK_EQ_INT(c->error, GL_NO_ERROR);
            for (int i = 0; i < n; i++)
                frag_pixel(c, i % BW, i / BW, col + i * 4, 0);
            int maxd;
            long d = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
            if (d)
                fprintf(stderr, "  blend 0x%x/0x%x: %ld bytes differ (max %d)\n",
                        k_factors[a], k_factors[b], d, maxd);
            diff += d;
            total += n * 4;
            if (maxd > maxd_all) maxd_all = maxd;
        }
    }
    printf("  blending: %d factor pairs, %ld of %ld values differ from OSMesa (max %d)\n",
           pairs, diff, total, maxd_all);
    CHECK_EQ_INT(diff, 0);
    CHECK(maxd_all <= 1);
    free(xyz);
    free(col);
    free(dst);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* GL 1.4's blending (4.1.8): every equation of table 4.1 with random
 * separate RGB and alpha factors (SRC_ALPHA_SATURATE as a destination
 * factor too, which Mesa accepts) and random constant colours, some on the
 * rounding ties (k + 0.5)/255 of the conversion to 8 bits, some outside
 * [0,1] (clamped when specified). */
static void set_blend(fs_context *c, const GLenum f[4], GLenum eq, const float cc[4])
{
    G(Enable, GL_BLEND);
    G(BlendFuncSeparate, f[0], f[1], f[2], f[3]);
    G(BlendEquation, eq);
    G(BlendColor, cc[0], cc[1], cc[2], cc[3]);
}

TEST(blend_equations_separate_constant_vs_osmesa)
{
    enum { BW = 64, BH = 64 };
    static const GLenum eqs[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    osm o;
    REQUIRE(osm_open_ortho(&o, BW, BH));
    fs_context *c = fs_context_create(NULL, BW, BH);
    REQUIRE(c);
    int n = BW * BH;
    float *xyz, *col;
    uint8_t *dst, *ref;
    REQUIRE(blend_buffers(BW, BH, &xyz, &col, &dst, &ref));
    uint32_t seed = 0x2468aceu;
    long total = 0, diff = 0;
    for (int e = 0; e < 5; e++) {
        for (int t = 0; t < 48; t++) {
            GLenum f[4];
            float cc[4];
            for (int k = 0; k < 4; k++) {
                f[k] = k_factors[rng_next(&seed) % N_FACTORS];
                unsigned r = rng_next(&seed) % 4;
                cc[k] = r == 0 ? ((float)(rng_next(&seed) % 255) + 0.5f) / 255.0f
                        : r == 1 ? rng_unit(&seed) * 2.0f - 0.5f : rng_unit(&seed);
            }
            random_blend_inputs(&seed, n, dst, col);
            osm_put_rgba(&o, dst);
            set_blend(NULL, f, eqs[e], cc);
            osm_points(n, xyz, col);
            glDisable(GL_BLEND);
            osm_read_rgba(&o, ref);

            memcpy(c->fb.color, dst, (size_t)n * 4);
            set_blend(c, f, eqs[e], cc);
            CHECK_EQ_INT(c->error, GL_NO_ERROR);
            for (int i = 0; i < n; i++)
                frag_pixel(c, i % BW, i / BW, col + i * 4, 0);
            int maxd;
            long d = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
            if (d)
                fprintf(stderr, "  eq 0x%x factors 0x%x 0x%x 0x%x 0x%x cc %g %g %g %g: %ld bytes differ (max %d)\n",
                        eqs[e], f[0], f[1], f[2], f[3], cc[0], cc[1], cc[2], cc[3], d, maxd);
            diff += d;
            total += n * 4;
        }
    }
    printf("  blend equations, separate factors, constant colour: %ld of %ld values differ from OSMesa\n", diff,
           total);
    CHECK_EQ_INT(diff, 0);
    free(xyz);
    free(col);
    free(dst);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* The common transparency pair, exhaustively over (src, dst) for a sweep of
 * alphas. */
TEST(blend_src_alpha_exhaustive_vs_osmesa)
{
    osm o;
    REQUIRE(osm_open_ortho(&o, SW, SH));
    fs_context *c = fs_context_create(NULL, SW, SH);
    REQUIRE(c);
    int n = SW * SH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint8_t *dst = malloc((size_t)n * 4), *ref = malloc((size_t)n * 4);
    REQUIRE(xyz && col && dst && ref);
    long diff = 0, total = 0;
    for (int alpha = 0; alpha < 256; alpha += 5) {
        for (int i = 0; i < n; i++) {
            xyz[i * 3] = (float)(i % SW) + 0.5f;
            xyz[i * 3 + 1] = (float)(i / SW) + 0.5f;
            xyz[i * 3 + 2] = 0.0f;
            dst[i * 4] = (uint8_t)(i % 256);
            dst[i * 4 + 1] = (uint8_t)(i / 256);
            dst[i * 4 + 2] = (uint8_t)(i * 7);
            dst[i * 4 + 3] = (uint8_t)(i * 13);
            col[i * 4] = (float)(i / 256) / 255.0f;
            col[i * 4 + 1] = (float)(i % 256) / 255.0f;
            col[i * 4 + 2] = (float)((i * 3) & 255) / 255.0f;
            col[i * 4 + 3] = (float)alpha / 255.0f;
        }
        osm_put_rgba(&o, dst);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        osm_points(n, xyz, col);
        glDisable(GL_BLEND);
        osm_read_rgba(&o, ref);
        memcpy(c->fb.color, dst, (size_t)n * 4);
        c->frag.blend_enabled = true;
        fs_exec_BlendFunc(c, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for (int i = 0; i < n; i++)
            frag_pixel(c, i % SW, i / SW, col + i * 4, 0);
        int maxd;
        diff += count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
        total += n * 4;
    }
    printf("  SRC_ALPHA/ONE_MINUS_SRC_ALPHA: %ld of %ld values differ from OSMesa\n", diff, total);
    CHECK_EQ_INT(diff, 0);
    free(xyz);
    free(col);
    free(dst);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* Alpha test: which fragments survive, for fragment alphas a few ulps and a
 * few 1/255 steps around several references. */
TEST(alpha_test_vs_osmesa)
{
    enum { AW = 64, AH = 64 };
    static const float refs[] = {0.0f, 0.5f, 1.0f / 3.0f, 0.2f, 128.0f / 255.0f, 1.0f};
    osm o;
    REQUIRE(osm_open_ortho(&o, AW, AH));
    fs_context *c = fs_context_create(NULL, AW, AH);
    REQUIRE(c);
    int n = AW * AH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint8_t *zero = calloc((size_t)n, 4), *ref = malloc((size_t)n * 4);
    REQUIRE(xyz && col && zero && ref);
    long diff = 0;
    int cases = 0;
    for (size_t r = 0; r < sizeof refs / sizeof refs[0]; r++) {
        for (int i = 0; i < n; i++) {
            int j = i % 64, k = (i / 64) % 16;
            float a = refs[r] + (float)(k - 8) / 510.0f;
            for (int t = 0; t < j - 32; t++) a = nextafterf(a, 2.0f);
            for (int t = 0; t < 32 - j; t++) a = nextafterf(a, -1.0f);
            if (i >= 1024) a = refs[r]; /* exact equality cases */
            a = a < 0.0f ? 0.0f : (a > 1.0f ? 1.0f : a);
            xyz[i * 3] = (float)(i % AW) + 0.5f;
            xyz[i * 3 + 1] = (float)(i / AW) + 0.5f;
            xyz[i * 3 + 2] = 0.0f;
            col[i * 4] = col[i * 4 + 1] = col[i * 4 + 2] = 1.0f;
            col[i * 4 + 3] = a;
        }
        for (int f = 0; f < 8; f++) {
            cases++;
            osm_put_rgba(&o, zero);
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(k_funcs[f], refs[r]);
            osm_points(n, xyz, col);
            glDisable(GL_ALPHA_TEST);
            osm_read_rgba(&o, ref);
            memset(c->fb.color, 0, (size_t)n * 4);
            c->frag.alpha_enabled = true;
            fs_exec_AlphaFunc(c, k_funcs[f], refs[r]);
            for (int i = 0; i < n; i++)
                frag_pixel(c, i % AW, i / AW, col + i * 4, 0);
            int maxd;
            long d = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
            if (d)
                fprintf(stderr, "  alpha func 0x%x ref %.9g: %ld bytes differ\n", k_funcs[f], refs[r], d);
            diff += d;
        }
    }
    printf("  alpha test: %d func/ref cases, %ld bytes differ from OSMesa\n", cases, diff);
    CHECK_EQ_INT(diff, 0);
    free(xyz);
    free(col);
    free(zero);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

TEST(logic_ops_vs_osmesa)
{
    enum { LW = 64, LH = 64 };
    osm o;
    REQUIRE(osm_open_ortho(&o, LW, LH));
    fs_context *c = fs_context_create(NULL, LW, LH);
    REQUIRE(c);
    int n = LW * LH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint8_t *dst = malloc((size_t)n * 4), *ref = malloc((size_t)n * 4);
    REQUIRE(xyz && col && dst && ref);
    uint32_t seed = 99;
    long diff = 0;
    for (GLenum op = GL_CLEAR; op <= GL_SET; op++) {
        for (int i = 0; i < n; i++) {
            xyz[i * 3] = (float)(i % LW) + 0.5f;
            xyz[i * 3 + 1] = (float)(i / LW) + 0.5f;
            xyz[i * 3 + 2] = 0.0f;
            for (int k = 0; k < 4; k++) {
                dst[i * 4 + k] = (uint8_t)rng_next(&seed);
                col[i * 4 + k] = rng_unit(&seed);
            }
        }
        osm_put_rgba(&o, dst);
        glEnable(GL_COLOR_LOGIC_OP);
        glEnable(GL_BLEND); /* logic op takes precedence over blending */
        glBlendFunc(GL_ONE, GL_ONE);
        glLogicOp(op);
        osm_points(n, xyz, col);
        glDisable(GL_COLOR_LOGIC_OP);
        glDisable(GL_BLEND);
        osm_read_rgba(&o, ref);
        memcpy(c->fb.color, dst, (size_t)n * 4);
        c->frag.logic_op_enabled = true;
        c->frag.blend_enabled = true;
        fs_exec_BlendFunc(c, GL_ONE, GL_ONE);
        fs_exec_LogicOp(c, op);
        for (int i = 0; i < n; i++)
            frag_pixel(c, i % LW, i / LW, col + i * 4, 0);
        int maxd;
        long d = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
        if (d)
            fprintf(stderr, "  logic op 0x%x: %ld bytes differ\n", op, d);
        diff += d;
    }
    printf("  logic ops: 16 ops, %ld bytes differ from OSMesa\n", diff);
    CHECK_EQ_INT(diff, 0);
    free(xyz);
    free(col);
    free(dst);
    free(ref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* ------------------------------------------ a random scene of all the stages */

typedef struct scene_state {
    bool depth, stencil, alpha, blend, logic, scissor;
    GLenum depth_func, alpha_func, stencil_func, sfail, zfail, zpass, bsrc, bdst, lop;
    bool depth_mask;
    GLboolean cmask[4];
    GLint sref, scissor_box[4];
    GLuint svmask, swmask;
    float aref;
} scene_state;

static void random_state(scene_state *s, uint32_t *seed, int w, int h)
{
    uint32_t r = rng_next(seed);
    s->depth = r & 1;
    s->stencil = (r >> 1) & 1;
    s->alpha = ((r >> 2) & 3) == 0;
    s->blend = ((r >> 4) & 3) == 0;
    s->logic = ((r >> 6) & 7) == 0;
    s->scissor = ((r >> 9) & 3) == 0;
    s->depth_mask = ((r >> 11) & 3) != 0;
    s->depth_func = k_funcs[rng_next(seed) % 8];
    s->alpha_func = k_funcs[rng_next(seed) % 8];
    s->stencil_func = k_funcs[rng_next(seed) % 8];
    s->sfail = k_sops[rng_next(seed) % 8];
    s->zfail = k_sops[rng_next(seed) % 8];
    s->zpass = k_sops[rng_next(seed) % 8];
    do {
        s->bsrc = k_factors[rng_next(seed) % N_FACTORS];
        s->bdst = k_factors[rng_next(seed) % N_FACTORS];
    } while (s->bdst == GL_SRC_ALPHA_SATURATE);
    s->lop = GL_CLEAR + rng_next(seed) % 16;
    for (int k = 0; k < 4; k++)
        s->cmask[k] = (rng_next(seed) % 5) != 0;
    s->sref = (GLint)(rng_next(seed) % 300) - 20;
    s->svmask = (rng_next(seed) & 1) ? 0xffffffffu : rng_next(seed);
    s->swmask = (rng_next(seed) & 1) ? 0xffffffffu : rng_next(seed);
    s->aref = (float)(rng_next(seed) % 256) / 255.0f;
    s->scissor_box[0] = (GLint)(rng_next(seed) % (unsigned)w) - 4;
    s->scissor_box[1] = (GLint)(rng_next(seed) % (unsigned)h) - 4;
    s->scissor_box[2] = (GLint)(rng_next(seed) % (unsigned)w);
    s->scissor_box[3] = (GLint)(rng_next(seed) % (unsigned)h);
}

static void gl_toggle(GLenum cap, bool on)
{
    if (on) glEnable(cap);
    else glDisable(cap);
}

static void apply_osmesa(const scene_state *s)
{
    gl_toggle(GL_DEPTH_TEST, s->depth);
    gl_toggle(GL_STENCIL_TEST, s->stencil);
    gl_toggle(GL_ALPHA_TEST, s->alpha);
    gl_toggle(GL_BLEND, s->blend);
    gl_toggle(GL_COLOR_LOGIC_OP, s->logic);
    gl_toggle(GL_SCISSOR_TEST, s->scissor);
    glDepthFunc(s->depth_func);
    glDepthMask(s->depth_mask);
    glAlphaFunc(s->alpha_func, s->aref);
    glStencilFunc(s->stencil_func, s->sref, s->svmask);
    glStencilOp(s->sfail, s->zfail, s->zpass);
    glStencilMask(s->swmask);
    glBlendFunc(s->bsrc, s->bdst);
    glLogicOp(s->lop);
    glColorMask(s->cmask[0], s->cmask[1], s->cmask[2], s->cmask[3]);
    glScissor(s->scissor_box[0], s->scissor_box[1], s->scissor_box[2], s->scissor_box[3]);
}

static void apply_fragsim(fs_context *c, const scene_state *s)
{
    c->frag.depth_enabled = s->depth;
    c->frag.stencil_enabled = s->stencil;
    c->frag.alpha_enabled = s->alpha;
    c->frag.blend_enabled = s->blend;
    c->frag.logic_op_enabled = s->logic;
    c->frag.scissor_enabled = s->scissor;
    fs_exec_DepthFunc(c, s->depth_func);
    fs_exec_DepthMask(c, s->depth_mask);
    fs_exec_AlphaFunc(c, s->alpha_func, s->aref);
    fs_exec_StencilFunc(c, s->stencil_func, s->sref, s->svmask);
    fs_exec_StencilOp(c, s->sfail, s->zfail, s->zpass);
    fs_exec_StencilMask(c, s->swmask);
    fs_exec_BlendFunc(c, s->bsrc, s->bdst);
    fs_exec_LogicOp(c, s->lop);
    fs_exec_ColorMask(c, s->cmask[0], s->cmask[1], s->cmask[2], s->cmask[3]);
    fs_exec_Scissor(c, s->scissor_box[0], s->scissor_box[1], s->scissor_box[2], s->scissor_box[3]);
}

/* Random state and random point sets drawn into both, comparing colour,
 * depth and stencil after every draw.  Depth values for fragsim are the ones
 * llvmpipe stores for the same window z (measured first). */
TEST(random_scene_vs_osmesa)
{
    enum { RW = 48, RH = 40, NZ = 16, DRAWS = 300 };
    osm o;
    REQUIRE(osm_open_ortho(&o, RW, RH));
    fs_context *c = fs_context_create(NULL, RW, RH);
    REQUIRE(c);
    int n = RW * RH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint32_t *zraw = malloc((size_t)n * 4), *zunits = malloc((size_t)n * 4);
    uint8_t *ref = malloc((size_t)n * 4), *sref = malloc((size_t)n);
    REQUIRE(xyz && col && zraw && zunits && ref && sref);

    /* The depth llvmpipe stores for each of NZ window depths. */
    float zs[NZ];
    uint32_t zu[NZ];
    for (int k = 0; k < NZ; k++)
        zs[k] = -0.9f + 1.8f * (float)k / (float)(NZ - 1) + (k % 3 == 1 ? 1e-4f : 0.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (int k = 0; k < NZ; k++) {
        float p[3] = {(float)k + 0.5f, 0.5f, zs[k]}, cc[4] = {1, 1, 1, 1};
        osm_points(1, p, cc);
    }
    osm_read_depth_raw(&o, zraw);
    for (int k = 0; k < NZ; k++)
        zu[k] = zraw[k];

    uint32_t seed = 0xC0FFEEu;
    long cdiff = 0, zdiff = 0, sdiff = 0;
    int draws = 0, reported = 0;
    for (int round = 0; round < 4; round++) {
        /* Same start for both: clear OSMesa, copy its buffers. */
        glDisable(GL_SCISSOR_TEST);
        glColorMask(1, 1, 1, 1);
        glDepthMask(1);
        glStencilMask(0xff);
        glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
        glClearDepth(0.75);
        glClearStencil(round * 50);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        osm_read_rgba(&o, c->fb.color);
        osm_read_depth_raw(&o, c->fb.depth);
        osm_read_stencil(&o, c->fb.stencil);

        for (int d = 0; d < DRAWS / 4; d++) {
            scene_state s;
            random_state(&s, &seed, RW, RH);
            apply_osmesa(&s);
            apply_fragsim(c, &s);
            CHECK_EQ_INT(c->error, GL_NO_ERROR);
            /* A random subset of pixels, each at most once per draw. */
            int m = 0;
            for (int i = 0; i < n; i++) {
                if (rng_next(&seed) % 3 == 0)
                    continue;
                int k = (int)(rng_next(&seed) % NZ);
                xyz[m * 3] = (float)(i % RW) + 0.5f;
                xyz[m * 3 + 1] = (float)(i / RW) + 0.5f;
                xyz[m * 3 + 2] = zs[k];
                zunits[m] = zu[k];
                for (int ch = 0; ch < 4; ch++) {
                    float v = (float)(rng_next(&seed) % 256) / 255.0f;
                    if (rng_next(&seed) & 1) v = rng_unit(&seed);
                    col[m * 4 + ch] = v;
                }
                m++;
            }
            osm_points(m, xyz, col);
            for (int j = 0; j < m; j++)
                frag_pixel(c, (int)xyz[j * 3], (int)xyz[j * 3 + 1], col + j * 4, zunits[j]);
            osm_read_rgba(&o, ref);
            osm_read_depth_raw(&o, zraw);
            osm_read_stencil(&o, sref);
            int maxd;
            long dc = count_diff(ref, c->fb.color, (size_t)n * 4, &maxd);
            long dz = 0, ds = count_diff(sref, c->fb.stencil, (size_t)n, &maxd);
            for (int i = 0; i < n; i++)
                dz += zraw[i] != c->fb.depth[i];
            if ((dc || dz || ds) && reported++ < 3)
                fprintf(stderr, "  draw %d: %ld colour, %ld depth, %ld stencil differ; depth %d/0x%x/%d "
                        "stencil %d/0x%x ref %d vm 0x%x wm 0x%x ops 0x%x/0x%x/0x%x alpha %d/0x%x/%g "
                        "blend %d 0x%x/0x%x logic %d/0x%x scissor %d mask %d%d%d%d\n",
                        draws, dc, dz, ds, s.depth, s.depth_func, s.depth_mask, s.stencil,
                        s.stencil_func, s.sref, s.svmask, s.swmask, s.sfail, s.zfail, s.zpass,
                        s.alpha, s.alpha_func, s.aref, s.blend, s.bsrc, s.bdst, s.logic, s.lop,
                        s.scissor, s.cmask[0], s.cmask[1], s.cmask[2], s.cmask[3]);
            cdiff += dc;
            zdiff += dz;
            sdiff += ds;
            /* Resynchronise so that one difference is not counted again. */
            memcpy(c->fb.color, ref, (size_t)n * 4);
            memcpy(c->fb.depth, zraw, (size_t)n * 4);
            memcpy(c->fb.stencil, sref, (size_t)n);
            draws++;
        }
    }
    printf("  random scene: %d draws, differing values: colour %ld, depth %ld, stencil %ld\n",
           draws, cdiff, zdiff, sdiff);
    CHECK_EQ_INT(cdiff, 0);
    CHECK_EQ_INT(zdiff, 0);
    CHECK_EQ_INT(sdiff, 0);
    free(xyz);
    free(col);
    free(zraw);
    free(zunits);
    free(ref);
    free(sref);
    fs_context_destroy(c);
    osm_close(&o);
}

/* ------------------------------------------------------------------ clear */

/* Clear colours (a sweep plus every rounding tie and its neighbours), both a
 * full clear and a scissored, colour-masked one, since a GL implementation may
 * take different routes for the two. */
TEST(clear_color_vs_osmesa)
{
    enum { CW = 8, CH = 8 };
    osm o;
    REQUIRE(osm_open_ortho(&o, CW, CH));
    fs_context *c = fs_context_create(NULL, CW, CH);
    REQUIRE(c);
    uint8_t ref[CW * CH * 4];
    long diff = 0, total = 0;
    for (int i = 0; i < 3000; i++) {
        float v[4];
        for (int k = 0; k < 4; k++) {
            int j = i * 4 + k;
            if (j < 4000) {
                v[k] = (float)j / 3999.0f;
            } else {
                v[k] = ((float)((j / 16) % 255) + 0.5f) / 255.0f;
                for (int t = 0; t < j % 16 - 8; t++) v[k] = nextafterf(v[k], 2.0f);
                for (int t = 0; t < 8 - j % 16; t++) v[k] = nextafterf(v[k], -1.0f);
            }
        }
        bool partial = i & 1;
        glClearColor(v[0], v[1], v[2], v[3]);
        fs_exec_ClearColor(c, v[0], v[1], v[2], v[3]);
        gl_toggle(GL_SCISSOR_TEST, partial);
        glScissor(1, 2, 5, 4);
        glColorMask(1, 1, (GLboolean)!partial, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        c->frag.scissor_enabled = partial;
        fs_exec_Scissor(c, 1, 2, 5, 4);
        fs_exec_ColorMask(c, 1, 1, (GLboolean)!partial, 1);
        fs_exec_Clear(c, GL_COLOR_BUFFER_BIT);
        osm_read_rgba(&o, ref);
        int maxd;
        long d = count_diff(ref, c->fb.color, sizeof ref, &maxd);
        if (d && diff == 0)
            fprintf(stderr, "  clear %.9g %.9g %.9g %.9g (%s): %ld bytes differ\n", v[0], v[1], v[2], v[3],
                    partial ? "scissored" : "full", d);
        diff += d;
        total += (long)sizeof ref;
    }
    printf("  clear colour: %ld of %ld bytes differ from OSMesa\n", diff, total);
    CHECK_EQ_INT(diff, 0);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(1, 1, 1, 1);
    fs_context_destroy(c);
    osm_close(&o);
}

TEST(clear_depth_stencil_vs_osmesa)
{
    enum { CW = 8, CH = 8 };
    osm o;
    REQUIRE(osm_open_ortho(&o, CW, CH));
    fs_context *c = fs_context_create(NULL, CW, CH);
    REQUIRE(c);
    uint32_t zref[CW * CH];
    uint8_t sref[CW * CH];
    long zd = 0, sd = 0, zd_scissored = 0;
    uint32_t zmax_scissored = 0;
    for (int i = 0; i < 2000; i++) {
        double z = (double)i / 1999.0;
        if (i % 3 == 1) z = ((double)(i * 8191 % 16777215) + 0.5) / 16777215.0; /* ties */
        if (i % 3 == 2) z = nextafter((double)(i * 4099 % 16777215) / 16777215.0, 2.0);
        bool partial = i & 1;
        GLint sv = i * 7 - 300;
        GLuint wm = partial ? 0x5au : 0xffu;
        glClearDepth(z);
        glClearStencil(sv);
        glStencilMask(wm);
        gl_toggle(GL_SCISSOR_TEST, partial);
        glScissor(2, 1, 3, 6);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        fs_exec_ClearDepth(c, z);
        fs_exec_ClearStencil(c, sv);
        fs_exec_StencilMask(c, wm);
        c->frag.scissor_enabled = partial;
        fs_exec_Scissor(c, 2, 1, 3, 6);
        fs_exec_Clear(c, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        osm_read_depth_raw(&o, zref);
        osm_read_stencil(&o, sref);
        long dz = 0, ds = 0;
        for (int p = 0; p < CW * CH; p++) {
            uint32_t e = zref[p] > c->fb.depth[p] ? zref[p] - c->fb.depth[p] : c->fb.depth[p] - zref[p];
            if (partial) {
                zd_scissored += e != 0;
                if (e > zmax_scissored) zmax_scissored = e;
            } else {
                dz += e != 0;
            }
            ds += sref[p] != c->fb.stencil[p];
        }
        /* Keep the next scissored clear's outside pixels comparable. */
        memcpy(c->fb.depth, zref, sizeof zref);
        if ((dz || ds) && zd + sd == 0)
            fprintf(stderr, "  clear depth %.17g (%s): osmesa 0x%x fragsim 0x%x; stencil %d\n", z,
                    partial ? "scissored" : "full", zref[2 * CW + 2], c->fb.depth[2 * CW + 2], sv);
        zd += dz;
        sd += ds;
    }
    printf("  clear depth/stencil: full clears: %ld depth values differ; scissored clears: %ld of %d "
           "depth values differ (max %u unit); %ld stencil values differ\n",
           zd, zd_scissored, 1000 * CW * CH, zmax_scissored, sd);
    CHECK_EQ_INT(zd, 0);
    CHECK(zmax_scissored <= 1); /* known: llvmpipe's scissored clear rounds differently */
    CHECK_EQ_INT(sd, 0);
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0xff);
    fs_context_destroy(c);
    osm_close(&o);
}

/* GL 4.2.3 closed form: clear writes exactly the scissor box (clipped to the
 * window) through the write masks, ignores the per-fragment tests, and
 * depth/stencil writes follow DepthMask/StencilMask. */
TEST(clear_scissor_and_masks)
{
    fs_context *c = fs_context_create(NULL, 10, 7);
    REQUIRE(c);
    memset(c->fb.color, 0x11, 10 * 7 * 4);
    memset(c->fb.stencil, 0xf0, 10 * 7);
    for (int i = 0; i < 70; i++) c->fb.depth[i] = 5;
    c->frag.scissor_enabled = true;
    c->frag.depth_enabled = c->frag.stencil_enabled = c->frag.alpha_enabled = true;
    c->frag.blend_enabled = c->frag.logic_op_enabled = true;
    fs_exec_DepthFunc(c, GL_NEVER);
    fs_exec_StencilFunc(c, GL_NEVER, 0, 0xff);
    fs_exec_AlphaFunc(c, GL_NEVER, 0);
    fs_exec_LogicOp(c, GL_NOOP);
    fs_exec_Scissor(c, -2, 3, 5, 100); /* clipped to x 0..2, y 3..6 */
    fs_exec_ColorMask(c, 1, 0, 1, 0);
    fs_exec_ClearColor(c, 1.0f, 1.0f, 0.0f, 1.0f);
    fs_exec_ClearStencil(c, 0x1ff); /* only the low 8 bits count */
    fs_exec_StencilMask(c, 0x0f);
    fs_exec_ClearDepth(c, 2.0); /* clamped to 1 */
    fs_exec_DepthMask(c, GL_FALSE);
    fs_exec_Clear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    CHECK_EQ_INT(c->error, GL_NO_ERROR);
    CHECK_EQ_INT(c->stats.clears, 1);
    long bad = 0;
    for (int y = 0; y < 7; y++) {
        for (int x = 0; x < 10; x++) {
            int i = y * 10 + x;
            bool in = x < 3 && y >= 3;
            const uint8_t *p = c->fb.color + i * 4;
            uint8_t want[4] = {in ? 255 : 0x11, 0x11, in ? 0 : 0x11, 0x11};
            bad += memcmp(p, want, 4) != 0;
            bad += c->fb.stencil[i] != (in ? 0xff : 0xf0);
            bad += c->fb.depth[i] != 5; /* depth mask off */
        }
    }
    CHECK_EQ_INT(bad, 0);
    fs_exec_DepthMask(c, GL_TRUE);
    fs_exec_Clear(c, GL_DEPTH_BUFFER_BIT);
    CHECK_EQ_UINT(c->fb.depth[3 * 10 + 0], 0xffffffu);
    CHECK_EQ_UINT(c->fb.depth[3 * 10 + 3], 5);
    /* An empty scissor box clears nothing. */
    fs_exec_Scissor(c, 4, 4, 0, 3);
    fs_exec_ColorMask(c, 1, 1, 1, 1);
    fs_exec_Clear(c, GL_COLOR_BUFFER_BIT);
    CHECK_EQ_INT(c->fb.color[(4 * 10 + 4) * 4 + 1], 0x11);
    /* Without the scissor test the whole window is cleared. */
    c->frag.scissor_enabled = false;
    fs_exec_Clear(c, GL_COLOR_BUFFER_BIT);
    CHECK_EQ_INT(c->fb.color[(6 * 10 + 9) * 4 + 1], 255);
    CHECK_EQ_INT(c->fb.color[0], 255);
    fs_context_destroy(c);
}

/* ------------------------------------------------------------- read pixels */

/* Depth read back in every supported type, from identical depth contents. */
TEST(read_pixels_depth_vs_osmesa)
{
    enum { RW = 64, RH = 32 };
    osm o;
    REQUIRE(osm_open_ortho(&o, RW, RH));
    fs_context *c = fs_context_create(NULL, RW, RH);
    REQUIRE(c);
    int n = RW * RH;
    float *xyz = malloc(sizeof(float) * 3 * (size_t)n), *col = malloc(sizeof(float) * 4 * (size_t)n);
    uint32_t *a = malloc((size_t)n * 4), *b = malloc((size_t)n * 4);
    REQUIRE(xyz && col && a && b);
    uint32_t seed = 7;
    for (int i = 0; i < n; i++) {
        xyz[i * 3] = (float)(i % RW) + 0.5f;
        xyz[i * 3 + 1] = (float)(i / RW) + 0.5f;
        float z = rng_unit(&seed) * 2.0f - 1.0f;
        if (i < 8) z = (i & 1) ? 1.0f : -1.0f; /* the extremes */
        xyz[i * 3 + 2] = z;
        col[i * 4] = col[i * 4 + 1] = col[i * 4 + 2] = col[i * 4 + 3] = 1.0f;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    osm_points(n, xyz, col);
    glDisable(GL_DEPTH_TEST);
    osm_read_depth_raw(&o, c->fb.depth);
    static const GLenum types[] = {GL_UNSIGNED_INT, GL_UNSIGNED_SHORT, GL_FLOAT};
    for (int t = 0; t < 3; t++) {
        size_t bytes = (size_t)n * (types[t] == GL_UNSIGNED_SHORT ? 2 : 4);
        memset(a, 0, (size_t)n * 4);
        memset(b, 0, (size_t)n * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, RW, RH, GL_DEPTH_COMPONENT, types[t], a);
        c->pack_alignment = 4;
        fs_exec_ReadPixels(c, 0, 0, RW, RH, GL_DEPTH_COMPONENT, types[t], b);
        CHECK_EQ_INT(c->error, GL_NO_ERROR);
        int maxd;
        long d = count_diff((uint8_t *)a, (uint8_t *)b, bytes, &maxd);
        if (d) {
            for (int i = 0; i < n; i++) {
                uint32_t va = 0, vb = 0;
                size_t sz = types[t] == GL_UNSIGNED_SHORT ? 2 : 4;
                memcpy(&va, (uint8_t *)a + i * sz, sz);
                memcpy(&vb, (uint8_t *)b + i * sz, sz);
                if (va != vb) {
                    fprintf(stderr, "  depth type 0x%x: raw 0x%06x osmesa 0x%08x fragsim 0x%08x\n", types[t],
                            c->fb.depth[i], va, vb);
                    break;
                }
            }
        }
        printf("  ReadPixels depth type 0x%x: %ld bytes differ from OSMesa\n", types[t], d);
        CHECK_EQ_INT(d, 0);
    }
    free(xyz);
    free(col);
    free(a);
    free(b);
    fs_context_destroy(c);
    osm_close(&o);
}

/* Row layout with GL_PACK_ALIGNMENT (GL 1.5 spec 3.6.4/4.3.2), clipping at the
 * window edge, and the byte count helper. */
TEST(read_pixels_layout)
{
    fs_context *c = fs_context_create(NULL, 5, 4);
    REQUIRE(c);
    for (int i = 0; i < 20; i++) {
        for (int k = 0; k < 4; k++) c->fb.color[i * 4 + k] = (uint8_t)(i * 4 + k);
        c->fb.stencil[i] = (uint8_t)(200 + i);
        c->fb.depth[i] = (uint32_t)i * 0x10101u;
    }
    static const int aligns[] = {1, 2, 4, 8};
    for (int ai = 0; ai < 4; ai++) {
        int al = aligns[ai];
        c->pack_alignment = al;
        /* 3 stencil bytes per row: stride rounds 3 up to the alignment. */
        int stride = (3 + al - 1) / al * al;
        CHECK_EQ_INT(fs_readpixels_bytes(c, 3, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE), stride + 3);
        uint8_t buf[64];
        memset(buf, 0xee, sizeof buf);
        fs_exec_ReadPixels(c, 1, 1, 3, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, buf);
        for (int y = 0; y < 2; y++)
            for (int x = 0; x < 3; x++)
                CHECK_EQ_INT(buf[y * stride + x], 200 + (y + 1) * 5 + x + 1);
        for (int p = 3; p < stride; p++)
            CHECK_EQ_INT(buf[p], 0xee); /* padding untouched */
        CHECK_EQ_INT(buf[stride + 3], 0xee);
        /* 3 RGBA pixels = 12 bytes: stride 16 only for alignment 8. */
        int rs = (12 + al - 1) / al * al;
        CHECK_EQ_INT(fs_readpixels_bytes(c, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE), rs * 2 + 12);
        memset(buf, 0xee, sizeof buf);
        fs_exec_ReadPixels(c, 2, 0, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, buf);
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 12; x++)
                CHECK_EQ_INT(buf[y * rs + x], ((y * 5 + 2) * 4 + x) & 255);
    }
    /* Partly outside the window: outside pixels are left alone. */
    c->pack_alignment = 1;
    uint8_t b2[4 * 4];
    memset(b2, 0xee, sizeof b2);
    fs_exec_ReadPixels(c, 4, 3, 2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b2);
    CHECK_EQ_INT(b2[0], 200 + 3 * 5 + 4);
    CHECK_EQ_INT(b2[1], 0xee);
    CHECK_EQ_INT(b2[2], 0xee);
    CHECK_EQ_INT(b2[3], 0xee);
    /* 24-bit depth as GL_UNSIGNED_INT: the top bits replicate down, so the
     * maximum reads as 0xffffffff. */
    c->fb.depth[0] = 0xffffff;
    c->fb.depth[1] = 0x800000;
    uint32_t z[2];
    fs_exec_ReadPixels(c, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
    CHECK_EQ_UINT(z[0], 0xffffffffu);
    CHECK_EQ_UINT(z[1], 0x80000080u);
    float fz[4]; /* also one RGB pixel as GL_FLOAT below */
    fs_exec_ReadPixels(c, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, fz);
    CHECK(fz[0] == 1.0f);
    CHECK_NEAR(fz[1], 0x800000 / 16777215.0, 1e-7);
    CHECK_EQ_INT(fs_readpixels_bytes(c, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT), 16);
    CHECK_EQ_INT(fs_readpixels_bytes(c, -1, 2, GL_RGBA, GL_UNSIGNED_BYTE), 0);
    CHECK_EQ_INT(fs_readpixels_bytes(c, 2, 2, 0x1234, GL_UNSIGNED_BYTE), 0);
    /* Every legal pair is read (pipeline/pixel_transfer.c; compared with
     * OSMesa by tests/test_pixel_transfer.c). */
    fs_exec_ReadPixels(c, 0, 0, 1, 1, GL_RGB, GL_FLOAT, fz);
    CHECK_EQ_INT(c->error, GL_NO_ERROR);
    CHECK_EQ_INT(c->stats.unsupported_calls, 0);
    fs_context_destroy(c);
}

/* --------------------------------------------------------------- GL errors */

typedef struct err_case {
    const char *what;
    int cmd;
} err_case;

/* Runs call number i on OSMesa (gl) or fragsim (c != NULL). */
static void error_call(fs_context *c, int i, void *buf)
{
#define BOTH(glcall, fscall) do { if (c) fscall; else glcall; } while (0)
    switch (i) {
    case 0: BOTH(glScissor(0, 0, -1, 5), fs_exec_Scissor(c, 0, 0, -1, 5)); break;
    case 1: BOTH(glScissor(0, 0, 4, -5), fs_exec_Scissor(c, 0, 0, 4, -5)); break;
    case 2: BOTH(glAlphaFunc(GL_ZERO, 0.5f), fs_exec_AlphaFunc(c, GL_ZERO, 0.5f)); break;
    case 3: BOTH(glAlphaFunc(GL_ALWAYS + 1, 0.5f), fs_exec_AlphaFunc(c, GL_ALWAYS + 1, 0.5f)); break;
    case 4: BOTH(glStencilFunc(GL_KEEP, 1, 1), fs_exec_StencilFunc(c, GL_KEEP, 1, 1)); break;
    case 5: BOTH(glStencilOp(GL_LESS, GL_KEEP, GL_KEEP), fs_exec_StencilOp(c, GL_LESS, GL_KEEP, GL_KEEP)); break;
    case 6: BOTH(glStencilOp(GL_KEEP, 0x1234, GL_KEEP), fs_exec_StencilOp(c, GL_KEEP, 0x1234, GL_KEEP)); break;
    case 7: BOTH(glStencilOp(GL_KEEP, GL_KEEP, GL_ONE), fs_exec_StencilOp(c, GL_KEEP, GL_KEEP, GL_ONE)); break;
    case 8: BOTH(glDepthFunc(GL_NEVER - 1), fs_exec_DepthFunc(c, GL_NEVER - 1)); break;
    case 9: BOTH(glBlendFunc(GL_LESS, GL_ONE), fs_exec_BlendFunc(c, GL_LESS, GL_ONE)); break;
    case 10: BOTH(glBlendFunc(GL_ONE, 0x1234), fs_exec_BlendFunc(c, GL_ONE, 0x1234)); break;
    case 11: BOTH(glLogicOp(GL_SET + 1), fs_exec_LogicOp(c, GL_SET + 1)); break;
    case 12: BOTH(glLogicOp(GL_CLEAR - 1), fs_exec_LogicOp(c, GL_CLEAR - 1)); break;
    case 13: BOTH(glClear(0x1), fs_exec_Clear(c, 0x1)); break;
    case 14: BOTH(glClear(GL_COLOR_BUFFER_BIT | 0x80000000u), fs_exec_Clear(c, GL_COLOR_BUFFER_BIT | 0x80000000u)); break;
    case 15: BOTH(glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, buf),
                  fs_exec_ReadPixels(c, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, buf)); break;
    case 16: BOTH(glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, buf),
                  fs_exec_ReadPixels(c, 0, 0, 1, 1, GL_RGBA, 0x1234, buf)); break;
    case 17: BOTH(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf),
                  fs_exec_ReadPixels(c, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf)); break;
    case 18: BOTH(glReadPixels(0, 0, 1, -1, GL_DEPTH_COMPONENT, GL_FLOAT, buf),
                  fs_exec_ReadPixels(c, 0, 0, 1, -1, GL_DEPTH_COMPONENT, GL_FLOAT, buf)); break;
    case 19: BOTH(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, buf),
                  fs_exec_ReadPixels(c, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, buf)); break;
    case 20: BOTH(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, buf),
                  fs_exec_ReadPixels(c, 0, 0, 1, 1, GL_RGBA, GL_BITMAP, buf)); break;
    /* Valid calls: no error. */
    case 21: BOTH(glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE), fs_exec_BlendFunc(c, GL_SRC_ALPHA_SATURATE, GL_ONE)); break;
    case 22: BOTH(glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT), fs_exec_StencilOp(c, GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT)); break;
    case 23: BOTH(glClear(GL_ACCUM_BUFFER_BIT), fs_exec_Clear(c, GL_ACCUM_BUFFER_BIT)); break;
    case 24: BOTH(glScissor(-5, -5, 0, 0), fs_exec_Scissor(c, -5, -5, 0, 0)); break;
    case 25: BOTH(glReadPixels(0, 0, 0, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, buf),
                  fs_exec_ReadPixels(c, 0, 0, 0, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, buf)); break;
    /* GL 1.4's blending commands (4.1.8). */
    case 26: BOTH(glBlendEquation(GL_ONE), fs_exec_BlendEquation(c, GL_ONE)); break;
    case 27: BOTH(glBlendEquation(GL_LOGIC_OP), fs_exec_BlendEquation(c, GL_LOGIC_OP)); break;
    case 28: BOTH(glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_LESS),
                  fs_exec_BlendFuncSeparate(c, GL_ONE, GL_ONE, GL_ONE, GL_LESS)); break;
    case 29: BOTH(glBlendFuncSeparate(0x1234, GL_ONE, GL_ONE, GL_ONE),
                  fs_exec_BlendFuncSeparate(c, 0x1234, GL_ONE, GL_ONE, GL_ONE)); break;
    case 30: BOTH(glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE), fs_exec_BlendFunc(c, GL_ONE, GL_SRC_ALPHA_SATURATE)); break;
    case 31: BOTH(glBlendEquation(GL_MAX), fs_exec_BlendEquation(c, GL_MAX)); break;
    case 32: BOTH(glBlendColor(NAN, -1.0f, 2.0f, 0.5f), fs_exec_BlendColor(c, NAN, -1.0f, 2.0f, 0.5f)); break;
    default: break;
    }
#undef BOTH
}
#define N_ERROR_CASES 33

/* Each erroneous call raises the same error as Mesa and changes no state. */
TEST(gl_errors_match_osmesa)
{
    osm o;
    REQUIRE(osm_open_ortho(&o, 8, 8));
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    uint8_t buf[64];
    while (glGetError() != GL_NO_ERROR) {}
    for (int i = 0; i < N_ERROR_CASES; i++) {
        error_call(NULL, i, buf);
        GLenum want = glGetError();
        fs_fragment_state before = c->frag;
        c->error = GL_NO_ERROR;
        error_call(c, i, buf);
        if (c->error != want)
            fprintf(stderr, "  error case %d: osmesa 0x%x fragsim 0x%x\n", i, want, c->error);
        CHECK_EQ_INT(c->error, want);
        if (want != GL_NO_ERROR)
            CHECK(memcmp(&before, &c->frag, sizeof before) == 0);
    }
    CHECK(c->stats.gl_errors > 0);
    fs_context_destroy(c);
    osm_close(&o);
}

/* ------------------------------------------------- closed-form stage rules */

/* Stencil ops (GL 1.5 spec 4.1.5): INCR/DECR saturate, the _WRAP forms wrap,
 * INVERT flips, REPLACE writes the clamped reference, all through the write
 * mask; the test compares (ref & mask) with (stored & mask). */
TEST(stencil_ops_closed_form)
{
    fs_context *c = fs_context_create(NULL, 2, 2);
    REQUIRE(c);
    static const int stored_vals[] = {0, 1, 127, 128, 254, 255};
    static const GLuint wmasks[] = {0xffffffffu, 0x0f, 0xf0, 0};
    static const GLint refs[] = {-5, 0, 77, 255, 1000};
    long bad = 0;
    float white[4] = {1, 1, 1, 1};
    c->frag.stencil_enabled = true;
    for (int oi = 0; oi < 8; oi++) {
        GLenum op = k_sops[oi];
        for (size_t si = 0; si < 6; si++) {
            for (size_t wi = 0; wi < 4; wi++) {
                for (size_t ri = 0; ri < 5; ri++) {
                    unsigned s0 = (unsigned)stored_vals[si], wm = wmasks[wi] & 255u;
                    unsigned ref = (unsigned)(refs[ri] < 0 ? 0 : refs[ri] > 255 ? 255 : refs[ri]);
                    unsigned v;
                    switch (op) {
                    case GL_ZERO: v = 0; break;
                    case GL_REPLACE: v = ref; break;
                    case GL_INCR: v = s0 == 255 ? 255 : s0 + 1; break;
                    case GL_DECR: v = s0 == 0 ? 0 : s0 - 1; break;
                    case GL_INVERT: v = 255 - s0; break;
                    case GL_INCR_WRAP: v = (s0 + 1) % 256; break;
                    case GL_DECR_WRAP: v = (s0 + 255) % 256; break;
                    default: v = s0; break;
                    }
                    unsigned want = (s0 & ~wm & 255u) | (v & wm);
                    /* zpass: stencil ALWAYS, depth off */
                    fs_exec_StencilFunc(c, GL_ALWAYS, refs[ri], 0xff);
                    fs_exec_StencilOp(c, GL_KEEP, GL_KEEP, op);
                    fs_exec_StencilMask(c, wmasks[wi]);
                    c->frag.depth_enabled = false;
                    c->fb.stencil[0] = (uint8_t)s0;
                    frag_pixel(c, 0, 0, white, 0);
                    bad += c->fb.stencil[0] != want;
                    /* fail: stencil NEVER */
                    fs_exec_StencilFunc(c, GL_NEVER, refs[ri], 0xff);
                    fs_exec_StencilOp(c, op, GL_KEEP, GL_KEEP);
                    c->fb.stencil[1] = (uint8_t)s0;
                    frag_pixel(c, 1, 0, white, 0);
                    bad += c->fb.stencil[1] != want;
                    /* zfail: stencil ALWAYS, depth NEVER */
                    fs_exec_StencilFunc(c, GL_ALWAYS, refs[ri], 0xff);
                    fs_exec_StencilOp(c, GL_KEEP, op, GL_KEEP);
                    c->frag.depth_enabled = true;
                    fs_exec_DepthFunc(c, GL_NEVER);
                    c->fb.stencil[2] = (uint8_t)s0;
                    frag_pixel(c, 0, 1, white, 0);
                    bad += c->fb.stencil[2] != want;
                }
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    /* Functions with a value mask. */
    c->frag.depth_enabled = false;
    fs_exec_StencilOp(c, GL_KEEP, GL_KEEP, GL_KEEP);
    bad = 0;
    for (int f = 0; f < 8; f++) {
        for (unsigned st = 0; st < 256; st += 17) {
            for (int r = -3; r < 300; r += 37) {
                GLuint vm = (GLuint)(r * 2654435761u) | 0x3u;
                unsigned rr = (unsigned)(r < 0 ? 0 : r > 255 ? 255 : r) & vm, ss = st & vm;
                bool want;
                switch (k_funcs[f]) {
                case GL_NEVER: want = false; break;
                case GL_LESS: want = rr < ss; break;
                case GL_EQUAL: want = rr == ss; break;
                case GL_LEQUAL: want = rr <= ss; break;
                case GL_GREATER: want = rr > ss; break;
                case GL_NOTEQUAL: want = rr != ss; break;
                case GL_GEQUAL: want = rr >= ss; break;
                default: want = true; break;
                }
                fs_exec_StencilFunc(c, k_funcs[f], r, vm);
                c->fb.stencil[3] = (uint8_t)st;
                memset(c->fb.color + 12, 0, 4);
                frag_pixel(c, 1, 1, white, 0);
                bad += (c->fb.color[12] == 255) != want;
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(c->stats.killed_stencil > 0);
    fs_context_destroy(c);
}

/* Depth functions (4.1.6) and the depth mask, with the unsigned compare at
 * the ends of the range; a disabled depth test writes no depth. */
TEST(depth_funcs_closed_form)
{
    fs_context *c = fs_context_create(NULL, 2, 2);
    REQUIRE(c);
    static const uint32_t vals[] = {0, 1, 0x7fffff, 0x800000, 0xfffffe, 0xffffff};
    float col[4] = {1, 0, 0, 1};
    long bad = 0;
    c->frag.depth_enabled = true;
    for (int f = 0; f < 8; f++) {
        for (int a = 0; a < 6; a++) {
            for (int b = 0; b < 6; b++) {
                for (int wr = 0; wr < 2; wr++) {
                    uint32_t z = vals[a], st = vals[b];
                    bool want;
                    switch (k_funcs[f]) {
                    case GL_NEVER: want = false; break;
                    case GL_LESS: want = z < st; break;
                    case GL_EQUAL: want = z == st; break;
                    case GL_LEQUAL: want = z <= st; break;
                    case GL_GREATER: want = z > st; break;
                    case GL_NOTEQUAL: want = z != st; break;
                    case GL_GEQUAL: want = z >= st; break;
                    default: want = true; break;
                    }
                    fs_exec_DepthFunc(c, k_funcs[f]);
                    fs_exec_DepthMask(c, (GLboolean)wr);
                    /* LESS/LEQUAL take the fast path here (the quad is
                     * inside the window); the others the general one. */
                    c->fb.depth[3] = st;
                    memset(c->fb.color + 12, 0, 4);
                    uint64_t passed0 = c->stats.fragments_passed_depth;
                    frag_pixel(c, 1, 1, col, z);
                    bool passed = c->fb.color[12] == 255;
                    bad += passed != want;
                    bad += (c->stats.fragments_passed_depth - passed0) != (uint64_t)want;
                    bad += c->fb.depth[3] != (want && wr ? z : st);
                }
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    c->frag.depth_enabled = false;
    fs_exec_DepthFunc(c, GL_NEVER);
    c->fb.depth[0] = 9;
    frag_pixel(c, 0, 0, col, 3);
    CHECK_EQ_INT(c->fb.depth[0], 9);
    CHECK_EQ_INT(c->fb.color[0], 255);
    fs_context_destroy(c);
}

/* Logic ops (4.1.10, table 4.4): opcode - GL_CLEAR is the truth table, bit
 * (1-s)*2 + (1-d) giving the result for source bit s and destination bit d. */
TEST(logic_op_truth_table)
{
    fs_context *c = fs_context_create(NULL, 2, 2);
    REQUIRE(c);
    c->frag.logic_op_enabled = true;
    long bad = 0;
    for (GLenum op = GL_CLEAR; op <= GL_SET; op++) {
        unsigned table = op - GL_CLEAR;
        fs_exec_LogicOp(c, op);
        for (unsigned sv = 0; sv < 256; sv += 5) {
            for (unsigned dv = 0; dv < 256; dv += 3) {
                float col[4] = {(float)sv / 255.0f, (float)sv / 255.0f, 0.0f, 1.0f};
                memset(c->fb.color, (int)dv, 4);
                frag_pixel(c, 0, 0, col, 0);
                unsigned want = 0;
                for (int bit = 0; bit < 8; bit++) {
                    unsigned s1 = sv >> bit & 1u, d1 = dv >> bit & 1u;
                    want |= (table >> ((1u - s1) * 2u + (1u - d1)) & 1u) << bit;
                }
                bad += c->fb.color[0] != want;
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    fs_context_destroy(c);
}

/* Scissor (4.1.2), pixel ownership (4.1.1), colour mask (4.2.2) and the kill
 * counters, on whole quads. */
TEST(scissor_ownership_masks)
{
    fs_context *c = fs_context_create(NULL, 5, 5);
    REQUIRE(c);
    fs_quad q;
    memset(&q, 0, sizeof q);
    for (int i = 0; i < 4; i++) {
        q.color[i][0] = 1.0f;
        q.color[i][1] = 0.5f;
        q.color[i][3] = 1.0f;
    }
    /* Quad at (4,4): only pixel 0 is inside the 5x5 window. */
    q.x = 4;
    q.y = 4;
    q.mask = 0xf;
    fs_fragment_quad(c, &q);
    CHECK_EQ_INT(c->stats.killed_ownership, 3);
    CHECK_EQ_INT(c->stats.fragments_written, 1);
    CHECK_EQ_INT(c->fb.color[(4 * 5 + 4) * 4], 255);
    /* Negative quad position. */
    q.x = -2;
    q.y = 0;
    fs_fragment_quad(c, &q);
    CHECK_EQ_INT(c->stats.killed_ownership, 7);
    /* Scissor box (1,1) 1x2: of the quad at (0,0) only pixel 3 survives;
     * of the quad at (0,2) only pixel 1. */
    c->frag.scissor_enabled = true;
    fs_exec_Scissor(c, 1, 1, 1, 2);
    q.x = 0;
    q.y = 0;
    fs_fragment_quad(c, &q);
    q.y = 2;
    fs_fragment_quad(c, &q);
    CHECK_EQ_INT(c->stats.killed_scissor, 6);
    CHECK_EQ_INT(c->fb.color[(1 * 5 + 1) * 4], 255);
    CHECK_EQ_INT(c->fb.color[(2 * 5 + 1) * 4], 255);
    CHECK_EQ_INT(c->fb.color[(1 * 5 + 0) * 4], 0);
    CHECK_EQ_INT(c->fb.color[(2 * 5 + 0) * 4], 0);
    /* Colour mask: only green written. */
    c->frag.scissor_enabled = false;
    fs_exec_ColorMask(c, 0, 1, 0, 0);
    q.x = 2;
    q.y = 0;
    q.mask = 0x1;
    fs_fragment_quad(c, &q);
    CHECK_EQ_INT(c->fb.color[2 * 4 + 0], 0);
    CHECK_EQ_INT(c->fb.color[2 * 4 + 1], 128);
    CHECK_EQ_INT(c->fb.color[2 * 4 + 3], 0);
    /* Alpha test kills count too. */
    fs_exec_ColorMask(c, 1, 1, 1, 1);
    c->frag.alpha_enabled = true;
    fs_exec_AlphaFunc(c, GL_LESS, 0.5f);
    q.mask = 0xf;
    fs_fragment_quad(c, &q);
    CHECK_EQ_INT(c->stats.killed_alpha, 4);
    fs_context_destroy(c);
}

/* GL state defaults (GL 1.5 spec tables 6.19-6.21). */
TEST(fragment_state_defaults)
{
    fs_fragment_state f;
    memset(&f, 0x5a, sizeof f);
    fs_fragment_state_init(&f);
    CHECK(!f.scissor_enabled && !f.alpha_enabled && !f.stencil_enabled && !f.depth_enabled);
    CHECK(!f.blend_enabled && !f.logic_op_enabled && f.dither_enabled);
    CHECK_EQ_INT(f.alpha_func, GL_ALWAYS);
    CHECK_EQ_INT(f.stencil_func, GL_ALWAYS);
    CHECK_EQ_UINT(f.stencil_value_mask, 0xffu); /* as OSMesa reports them */
    CHECK_EQ_UINT(f.stencil_write_mask, 0xffu);
    CHECK_EQ_INT(f.stencil_fail, GL_KEEP);
    CHECK_EQ_INT(f.depth_func, GL_LESS);
    CHECK(f.depth_write);
    CHECK_EQ_INT(f.blend_src, GL_ONE);
    CHECK_EQ_INT(f.blend_dst, GL_ZERO);
    CHECK_EQ_INT(f.logic_op, GL_COPY);
    CHECK(f.color_mask[0] && f.color_mask[3]);
    CHECK(f.clear_depth == 1.0);
    CHECK_EQ_INT(f.clear_stencil, 0);
}

/* Occlusion Unit attachment point: called once per quad that reaches it,
 * with the masks that reached and passed the depth test. */
typedef struct hook_log { int calls; unsigned tested, passed; } hook_log;
static void log_hook(fs_context *c, void *user, const fs_quad *q, unsigned tested, unsigned passed)
{
    (void)c;
    (void)q;
    hook_log *l = user;
    l->calls++;
    l->tested = tested;
    l->passed = passed;
}

TEST(occlusion_hook)
{
    for (int general = 0; general < 2; general++) {
        fs_context *c = fs_context_create(NULL, 4, 4);
        REQUIRE(c);
        hook_log log = {0, 0, 0};
        c->occlusion_hook = log_hook;
        c->occlusion_user = &log;
        c->frag.depth_enabled = true;
        c->frag.stencil_enabled = general; /* forces the general path */
        for (int i = 0; i < 16; i++) c->fb.depth[i] = 100;
        fs_quad q;
        memset(&q, 0, sizeof q);
        q.mask = 0xb;
        q.z[0] = 50;
        q.z[1] = 150;
        q.z[3] = 99;
        fs_fragment_quad(c, &q);
        CHECK_EQ_INT(log.calls, 1);
        CHECK_EQ_UINT(log.tested, 0xb);
        CHECK_EQ_UINT(log.passed, 0x9);
        CHECK_EQ_INT(c->stats.fragments_passed_depth, 2);
        CHECK_EQ_INT(c->stats.killed_depth, 1);
        fs_context_destroy(c);
    }
}

/* ------------------------------------------------ fast paths == general path */

static void random_quad(fs_quad *q, uint32_t *seed, int w, int h)
{
    memset(q, 0, sizeof *q);
    q->x = (int)(rng_next(seed) % (unsigned)(w + 2)) - 2;
    q->y = (int)(rng_next(seed) % (unsigned)(h + 2)) - 2;
    q->x &= ~1;
    q->y &= ~1;
    q->mask = rng_next(seed) & 0xf;
    for (int i = 0; i < 4; i++) {
        q->z[i] = rng_next(seed) & 0xffffff;
        if (rng_next(seed) % 4 == 0) q->z[i] = 0x800000;
        for (int k = 0; k < 4; k++) q->color[i][k] = rng_unit(seed);
    }
}

TEST(fast_paths_equal_general)
{
    enum { FW = 20, FH = 14 };
    fs_context *a = fs_context_create(NULL, FW, FH), *b = fs_context_create(NULL, FW, FH);
    REQUIRE(a && b);
    uint32_t seed = 4242;
    long bad = 0;
    for (int round = 0; round < 200; round++) {
        scene_state s;
        random_state(&s, &seed, FW, FH);
        /* Mostly the states the fast paths take. */
        if (round % 3 != 2) {
            s.stencil = s.alpha = s.blend = s.logic = s.scissor = false;
            s.cmask[0] = s.cmask[1] = s.cmask[2] = s.cmask[3] = 1;
            s.depth_mask = round % 5 != 0;
            s.depth_func = (round & 1) ? GL_LESS : GL_LEQUAL;
        }
        apply_fragsim(a, &s);
        apply_fragsim(b, &s);
        for (int i = 0; i < 300; i++) {
            fs_quad q, q2;
            random_quad(&q, &seed, FW, FH);
            q2 = q;
            fs_fragment_quad(a, &q);
            fs_fragment_quad_general(b, &q2);
        }
        bad += memcmp(a->fb.color, b->fb.color, FW * FH * 4) != 0;
        bad += memcmp(a->fb.depth, b->fb.depth, FW * FH * 4) != 0;
        bad += memcmp(a->fb.stencil, b->fb.stencil, FW * FH) != 0;
        bad += memcmp(&a->stats, &b->stats, sizeof a->stats) != 0;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(a->stats.fragments_written > 10000);
    fs_context_destroy(a);
    fs_context_destroy(b);
}

/* The record fs_fragment_quad returns for the observers (the cycle model)
 * holds what the stages counted for that quad: the fragments the pixel
 * ownership, scissor and alpha tests discarded, those that passed every
 * test, those written; on the fast paths and the general one, also with
 * writes suppressed (occlusion modes) and with glDrawBuffer(GL_NONE). */
static bool work_matches(fs_context *c, fs_quad *q, bool general)
{
    fs_stats before = c->stats;
    fs_quad_work w = general ? fs_fragment_quad_general(c, q) : fs_fragment_quad(c, q);
    const fs_stats *a = &c->stats;
    uint64_t early = (a->killed_ownership - before.killed_ownership) + (a->killed_scissor - before.killed_scissor) +
                     (a->killed_alpha - before.killed_alpha);
    return w.killed_early == early && w.passed == a->fragments_passed_depth - before.fragments_passed_depth &&
           w.written == a->fragments_written - before.fragments_written;
}

TEST(quad_work_record_matches_counters)
{
    enum { FW = 20, FH = 14 };
    fs_context *c = fs_context_create(NULL, FW, FH);
    REQUIRE(c);
    const GLenum draw_buffer = c->draw_buffer;
    uint32_t seed = 777;
    long bad = 0, quads = 0;
    for (int round = 0; round < 120; round++) {
        scene_state s;
        random_state(&s, &seed, FW, FH);
        if (round % 3 == 0) { /* the fast paths' states */
            s.stencil = s.alpha = s.blend = s.logic = s.scissor = false;
            s.cmask[0] = s.cmask[1] = s.cmask[2] = s.cmask[3] = 1;
        }
        apply_fragsim(c, &s);
        c->frag.suppress_writes = round % 7 == 5;
        c->draw_buffer = round % 11 == 4 ? GL_NONE : draw_buffer;
        for (int i = 0; i < 100; i++, quads++) {
            fs_quad q;
            random_quad(&q, &seed, FW, FH);
            bad += !work_matches(c, &q, i & 1);
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(c->stats.fragments_written > 1000 && c->stats.killed_ownership > 0 && quads == 12000);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(color_conversion_vs_osmesa),
    TEST_ENTRY(blend_all_factor_pairs_vs_osmesa),
    TEST_ENTRY(blend_src_alpha_exhaustive_vs_osmesa),
    TEST_ENTRY(blend_equations_separate_constant_vs_osmesa),
    TEST_ENTRY(alpha_test_vs_osmesa),
    TEST_ENTRY(logic_ops_vs_osmesa),
    TEST_ENTRY(random_scene_vs_osmesa),
    TEST_ENTRY(clear_color_vs_osmesa),
    TEST_ENTRY(clear_depth_stencil_vs_osmesa),
    TEST_ENTRY(clear_scissor_and_masks),
    TEST_ENTRY(read_pixels_depth_vs_osmesa),
    TEST_ENTRY(read_pixels_layout),
    TEST_ENTRY(gl_errors_match_osmesa),
    TEST_ENTRY(stencil_ops_closed_form),
    TEST_ENTRY(depth_funcs_closed_form),
    TEST_ENTRY(logic_op_truth_table),
    TEST_ENTRY(scissor_ownership_masks),
    TEST_ENTRY(fragment_state_defaults),
    TEST_ENTRY(occlusion_hook),
    TEST_ENTRY(fast_paths_equal_general),
    TEST_ENTRY(quad_work_record_matches_counters),
    TEST_END,
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, test_list);
}
