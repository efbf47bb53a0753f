/*
 * The GL 1.2-1.4 level-of-detail state of texture objects (units/texture_lod.c,
 * select_lod in units/texture_sample.c) against OSMesa (llvmpipe) at
 * tolerance 0: TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, TEXTURE_MIN_LOD,
 * TEXTURE_MAX_LOD, the object's and the unit's TEXTURE_LOD_BIAS (GL 1.5 spec
 * 3.8.8-3.8.10) and GENERATE_MIPMAP (3.8.8): their glGet answers and errors,
 * the images drawn with random values of all of them, and the levels
 * glGetTexImage reads back after automatic generation.
 */
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* A log of values both implementations produce from the same calls. */
typedef struct vlog { double v[16384]; int n; } vlog;

static void vrec(vlog *l, double v)
{
    if (l->n < 16384)
        l->v[l->n++] = v;
}

static void log_error(vlog *l, fs_context *c) { vrec(l, (double)(c ? fsglGetError(c) : glGetError())); }

/* Every LOD parameter of the bound texture in both forms, and the unit's
 * bias in both forms. */
static void log_lod_state(vlog *l, fs_context *c)
{
    static const GLenum pn[] = {GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_MIN_LOD,
                                GL_TEXTURE_MAX_LOD, GL_TEXTURE_LOD_BIAS, GL_GENERATE_MIPMAP};
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        GLint iv = 0x5a5a5a5a;
        GLfloat fv = -7.0f;
        G(GetTexParameteriv, GL_TEXTURE_2D, pn[i], &iv);
        G(GetTexParameterfv, GL_TEXTURE_2D, pn[i], &fv);
        vrec(l, iv);
        vrec(l, fv);
    }
    GLint iv = 0x5a5a5a5a;
    GLfloat fv = -7.0f;
    G(GetTexEnviv, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &iv);
    G(GetTexEnvfv, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &fv);
    vrec(l, iv);
    vrec(l, fv);
    log_error(l, c);
}

static void lod_param_sequence(fs_context *c, vlog *l)
{
    static const GLenum pn[] = {GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_MIN_LOD,
                                GL_TEXTURE_MAX_LOD, GL_TEXTURE_LOD_BIAS, GL_GENERATE_MIPMAP};
    static const float vals[] = {0.0f, 0.3f, 0.5f, 1.0f, 2.5f, 2.6f, -0.7f, -2.5f, -3.0f, 7.0f, 20.0f, -20.0f,
                                 1e10f, -1e10f, 1000.0f, 0.49f};
    uint32_t seed = 99;
    G(BindTexture, GL_TEXTURE_2D, 3);
    log_lod_state(l, c);
    for (int i = 0; i < 300; i++) {
        GLenum p = pn[rng(&seed) % 6];
        float v = vals[rng(&seed) % (sizeof vals / sizeof vals[0])];
        switch (rng(&seed) % 5) {
        case 0: G(TexParameterf, GL_TEXTURE_2D, p, v); break;
        case 1: G(TexParameteri, GL_TEXTURE_2D, p, (GLint)v); break;
        case 2: G(TexParameterfv, GL_TEXTURE_2D, p, &v); break;
        case 3: G(TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v); break;
        default: {
            GLint iv = (GLint)v;
            G(TexParameteriv, GL_TEXTURE_2D, p, &iv);
            break;
        }
        }
        log_error(l, c);
        log_lod_state(l, c);
    }
    /* Errors: a pname the filter control lacks, the bias on TEXTURE_ENV. */
    G(TexEnvi, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    log_error(l, c);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1);
    log_error(l, c);
    /* glPushAttrib(GL_TEXTURE_BIT) keeps them all (6.1.14). */
    G(PushAttrib, GL_TEXTURE_BIT);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 5);
    G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 3.25f);
    G(TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    G(TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.5f);
    G0(PopAttrib);
    log_lod_state(l, c);
}

static void compare_logs(check_state *check_st_, const vlog *a, const vlog *b)
{
    CHECK_EQ_INT(a->n, b->n);
    for (int i = 0; i < a->n && i < b->n; i++)
        if (!(a->v[i] == b->v[i])) {
            CHECK_FAIL_("value %d of %d: fragsim %.9g, OSMesa %.9g", i, a->n, a->v[i], b->v[i]);
            return;
        }
    printf("  %d values equal\n", a->n);
}

/* One call sequence on OSMesa and on the model, the logs compared. */
static void run_logged(check_state *check_st_, void (*seq)(fs_context *c, vlog *l))
{
    static vlog ref, mine;
    ref.n = mine.n = 0;
    osm o;
    REQUIRE(osm_open(&o, 8, 8));
    seq(NULL, &ref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    seq(c, &mine);
    fs_context_destroy(c);
    compare_logs(check_st_, &mine, &ref);
}

TEST(lod_parameters_vs_osmesa) { run_logged(check_st_, lod_param_sequence); }

/* ---- images: random level-of-detail state on a tilted MIPmapped quad ---- */

typedef struct lod_case {
    uint32_t seed;
    int size_log2w, size_log2h;
    int base, maxl, defined_from;   /* levels defined_from.. are given */
    float min_lod, max_lod, bias, unit_bias;
    GLenum min_filter, mag_filter, wrap;
    float tilt, scale;
    int generate;                   /* levels made by GENERATE_MIPMAP */
} lod_case;

static void fill_level(uint32_t seed, int lvl, int w, int h, uint8_t *px)
{
    uint32_t s = seed * 31u + (uint32_t)lvl * 977u;
    uint8_t base[3] = {(uint8_t)(40 * lvl), (uint8_t)(255 - 30 * lvl), (uint8_t)(lvl * 70)};
    for (int i = 0; i < w * h; i++) {
        uint32_t r = rng(&s);
        px[i * 4 + 0] = (uint8_t)(base[0] + (r & 31));
        px[i * 4 + 1] = (uint8_t)(base[1] - ((r >> 5) & 31));
        px[i * 4 + 2] = (uint8_t)(base[2] + ((r >> 10) & 63));
        px[i * 4 + 3] = (uint8_t)(r >> 16);
    }
}

static void draw_lod_case(fs_context *c, const void *user, int w, int h)
{
    const lod_case *k = user;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.1f, 0.2f, 0.3f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 60.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -3);
    G(Rotatef, -k->tilt, 1, 0, 0);
    G(BindTexture, GL_TEXTURE_2D, 1);
    int tw = 1 << k->size_log2w, th = 1 << k->size_log2h;
    uint8_t *px = malloc((size_t)tw * (size_t)th * 4);
    if (k->generate)
        G(TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, k->base);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, k->maxl);
    for (int lvl = 0, lw = tw, lh = th;; lvl++) {
        if (lvl >= k->defined_from && (!k->generate || lvl == k->base)) {
            fill_level(k->seed, lvl, lw, lh, px);
            G(TexImage2D, GL_TEXTURE_2D, lvl, GL_RGBA, lw, lh, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        }
        if (lw == 1 && lh == 1)
            break;
        lw = lw > 1 ? lw / 2 : 1;
        lh = lh > 1 ? lh / 2 : 1;
    }
    free(px);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)k->min_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)k->mag_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)k->wrap);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)k->wrap);
    G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, k->min_lod);
    G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, k->max_lod);
    G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, k->bias);
    G(TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, k->unit_bias);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(Enable, GL_TEXTURE_2D);
    float s = k->scale;
    G(Begin, GL_QUADS);
    G(TexCoord2f, -0.5f, -0.5f);
    G(Vertex3f, -s, -s, 0);
    G(TexCoord2f, 3.0f, -0.5f);
    G(Vertex3f, s, -s, 0);
    G(TexCoord2f, 3.0f, 3.0f);
    G(Vertex3f, s, s * 4, 0);
    G(TexCoord2f, -0.5f, 3.0f);
    G(Vertex3f, -s, s * 4, 0);
    G0(End);
}

static void random_lod_case(uint32_t seed, lod_case *k)
{
    static const GLenum minf[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                  GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP};
    static const float lods[] = {-1000.0f, -1.0f, 0.0f, 0.5f, 1.0f, 1.25f, 2.0f, 2.5f, 3.0f, 4.75f, 1000.0f};
    static const float biases[] = {0.0f, 0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 2.3f, -3.7f, 0.001f, 20.0f};
    memset(k, 0, sizeof *k);
    k->seed = seed;
    k->size_log2w = 3 + (int)(rng(&seed) % 4);
    k->size_log2h = 2 + (int)(rng(&seed) % 5);
    int levels = (k->size_log2w > k->size_log2h ? k->size_log2w : k->size_log2h) + 1;
    k->base = (int)(rng(&seed) % 4);
    k->maxl = rng(&seed) % 3 ? 1000 : k->base + (int)(rng(&seed) % (unsigned)levels);
    k->generate = rng(&seed) % 4 == 0;
    k->defined_from = k->generate ? 0 : rng(&seed) % 3 ? k->base : 0;
    k->min_lod = lods[rng(&seed) % 11];
    k->max_lod = lods[rng(&seed) % 11];
    k->bias = biases[rng(&seed) % 10];
    k->unit_bias = biases[rng(&seed) % 10];
    k->min_filter = minf[rng(&seed) % 6];
    k->mag_filter = rng(&seed) % 2 ? GL_LINEAR : GL_NEAREST;
    k->wrap = wraps[rng(&seed) % 3];
    k->tilt = (float)(rng(&seed) % 80);
    k->scale = 0.3f + (float)(rng(&seed) % 100) / 80.0f;
}

TEST(lod_images_vs_osmesa)
{
    int bad = 0;
    long differ = 0;
    for (uint32_t i = 0; i < 80; i++) {
        lod_case k;
        random_lod_case(1000u + i, &k);
        osm_pair p;
        REQUIRE(osm_pair_render(&p, 96, 80, NULL, draw_lod_case, &k));
        if (p.d.differ) {
            bad++;
            differ += p.d.differ;
            fprintf(stderr, "  case %u: %ld pixels differ (max %d): %dx%d base %d max %d from %d gen %d lod [%g, %g] "
                    "bias %g unit %g min %#x mag %#x wrap %#x\n", i, p.d.differ, p.d.maxd, 1 << k.size_log2w,
                    1 << k.size_log2h, k.base, k.maxl, k.defined_from, k.generate, (double)k.min_lod,
                    (double)k.max_lod, (double)k.bias, (double)k.unit_bias, k.min_filter, k.mag_filter, k.wrap);
        }
        osm_pair_close(&p);
    }
    if (bad)
        CHECK_FAIL_("%d of 80 cases differ from OSMesa (%ld pixels)", bad, differ);
}

/* ---- GENERATE_MIPMAP: the generated levels read back ---- */

static void log_levels(vlog *l, fs_context *c, int w, int h, uint8_t *buf)
{
    for (int lvl = 0;; lvl++) {
        GLint lw = -1, lh = -1;
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, lvl, GL_TEXTURE_WIDTH, &lw);
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, lvl, GL_TEXTURE_HEIGHT, &lh);
        vrec(l, lw);
        vrec(l, lh);
        if (lw > 0 && lh > 0) {
            memset(buf, 0xa5, (size_t)lw * (size_t)lh * 4);
            G(GetTexImage, GL_TEXTURE_2D, lvl, GL_RGBA, GL_UNSIGNED_BYTE, buf);
            uint32_t sum = 0;
            for (long i = 0; i < (long)lw * lh * 4; i++)
                sum = sum * 31u + buf[i];
            vrec(l, sum);
        }
        if (w == 1 && h == 1)
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    log_error(l, c);
}

static void generate_sequence(fs_context *c, vlog *l)
{
    static const GLint formats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY,
                                    GL_RGBA8};
    uint32_t seed = 4242;
    uint8_t *px = malloc(128 * 64 * 4), *buf = malloc(128 * 64 * 4);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    for (int t = 0; t < 14; t++) {
        int w = 1 << (rng(&seed) % 8), h = 1 << (rng(&seed) % 7);
        GLint f = formats[rng(&seed) % 7];
        int base = (int)(rng(&seed) % 2);
        G(BindTexture, GL_TEXTURE_2D, (GLuint)(10 + t));
        G(TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, base);
        if (t % 5 == 4) /* generation stops at MAX_LEVEL */
            G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, base + 2);
        for (int i = 0; i < w * h * 4; i++)
            px[i] = (uint8_t)(rng(&seed) >> 3);
        /* A level other than the base generates nothing. */
        G(TexImage2D, GL_TEXTURE_2D, base + 1, f, w > 1 ? w / 2 : 1, h > 1 ? h / 2 : 1, 0, GL_RGBA,
          GL_UNSIGNED_BYTE, px);
        G(TexImage2D, GL_TEXTURE_2D, base, f, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        log_levels(l, c, w, h, buf);
        /* glTexSubImage2D of the base regenerates. */
        int sw = w > 2 ? w / 2 : w, sh = h > 2 ? h / 2 : h;
        for (int i = 0; i < sw * sh * 4; i++)
            px[i] = (uint8_t)rng(&seed);
        G(TexSubImage2D, GL_TEXTURE_2D, base, w - sw, 0, sw, sh, GL_RGBA, GL_UNSIGNED_BYTE, px);
        log_levels(l, c, w, h, buf);
    }
    /* GENERATE_MIPMAP off: TexSubImage2D leaves the levels below alone. */
    G(TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    log_levels(l, c, 128, 64, buf);
    free(px);
    free(buf);
}

TEST(generate_mipmap_vs_osmesa) { run_logged(check_st_, generate_sequence); }

TEST_LIST = {
    TEST_ENTRY(lod_parameters_vs_osmesa),
    TEST_ENTRY(lod_images_vs_osmesa),
    TEST_ENTRY(generate_mipmap_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
