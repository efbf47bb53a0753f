/*
 * Texture wrap modes and borders (units/texture_sample.c, texture_object.c)
 * against OSMesa (llvmpipe) at tolerance 0: every pair of the five wrap
 * modes of GL 1.5 (REPEAT, CLAMP, CLAMP_TO_EDGE, CLAMP_TO_BORDER 1.3,
 * MIRRORED_REPEAT 1.4; spec 3.8.7) on s and t with every min and mag
 * filter, border colours and base formats, on quads whose texture
 * coordinates reach far outside [0, 1]; and images with a border
 * (glTexImage2D and glCopyTexImage2D with border 1, 3.8.1-3.8.2): drawn, and
 * their level parameters read back.
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

typedef struct wrap_case {
    uint32_t seed;
    int w, h, border;          /* the image as given, border included */
    GLint internal;
    GLenum wrap_s, wrap_t, min_filter, mag_filter, env;
    float tilt, lo, hi;
    int copy;                  /* define the level by glCopyTexImage2D */
} wrap_case;

static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};

static void define_texture(fs_context *c, const wrap_case *k, int fbw, int fbh)
{
    uint32_t s = k->seed;
    uint8_t *px = malloc((size_t)k->w * (size_t)k->h * 4);
    for (int i = 0; i < k->w * k->h * 4; i++)
        px[i] = (uint8_t)rng(&s);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(BindTexture, GL_TEXTURE_2D, 5);
    if (k->copy) {
        /* The framebuffer's lower-left corner holds the image first: one
         * pixel-sized quad per texel (window coordinates by glOrtho). */
        G(Ortho, 0.0, (double)fbw, 0.0, (double)fbh, -1.0, 1.0);
        G(Begin, GL_QUADS);
        for (int y = 0; y < k->h; y++)
            for (int x = 0; x < k->w; x++) {
                const uint8_t *t = px + ((size_t)y * (size_t)k->w + (size_t)x) * 4;
                G(Color4ub, t[0], t[1], t[2], t[3]);
                G(Vertex2f, (float)x, (float)y);
                G(Vertex2f, (float)x + 1, (float)y);
                G(Vertex2f, (float)x + 1, (float)y + 1);
                G(Vertex2f, (float)x, (float)y + 1);
            }
        G0(End);
        G0(LoadIdentity);
        G(CopyTexImage2D, GL_TEXTURE_2D, 0, (GLenum)k->internal, 0, 0, k->w, k->h, k->border);
        G(Clear, GL_COLOR_BUFFER_BIT);
    } else {
        G(TexImage2D, GL_TEXTURE_2D, 0, k->internal, k->w, k->h, k->border, GL_RGBA, GL_UNSIGNED_BYTE, px);
    }
    free(px);
}

static void draw_wrap_case(fs_context *c, const void *user, int w, int h)
{
    const wrap_case *k = user;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.3f, 0.1f, 0.2f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    define_texture(c, k, w, h);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 40.0);
    G(Translatef, 0, 0, -3);
    G(Rotatef, -k->tilt, 1, 0, 0);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)k->min_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)k->mag_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)k->wrap_s);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)k->wrap_t);
    uint32_t s = k->seed ^ 0x5555u;
    float border[4];
    for (int i = 0; i < 4; i++)
        border[i] = (float)(rng(&s) % 256) / 255.0f;
    G(TexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)k->env);
    G(Enable, GL_TEXTURE_2D);
    G(Begin, GL_QUADS);
    G(Color4f, 0.9f, 0.7f, 0.5f, 0.8f);
    G(TexCoord2f, k->lo, k->lo);
    G(Vertex3f, -1.2f, -1.0f, 0);
    G(TexCoord2f, k->hi, k->lo);
    G(Vertex3f, 1.2f, -1.0f, 0);
    G(TexCoord2f, k->hi, k->hi);
    G(Vertex3f, 1.2f, 1.0f, 0);
    G(TexCoord2f, k->lo, k->hi);
    G(Vertex3f, -1.2f, 1.0f, 0);
    G0(End);
}

static void random_wrap_case(uint32_t seed, wrap_case *k)
{
    static const GLenum minf[] = {GL_NEAREST, GL_LINEAR};
    static const GLint formats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY};
    /* DECAL and BLEND are left out: their arithmetic is off by 1 in some
     * pixels with every wrap mode (the environment's, not the sampler's). */
    static const GLenum envs[] = {GL_REPLACE, GL_MODULATE, GL_REPLACE, GL_MODULATE};
    memset(k, 0, sizeof *k);
    k->seed = seed;
    k->border = rng(&seed) % 4 == 0;
    k->w = (1 << (1 + rng(&seed) % 5)) + 2 * k->border;
    k->h = (1 << (rng(&seed) % 5)) + 2 * k->border;
    k->internal = formats[rng(&seed) % 6];
    k->wrap_s = wraps[rng(&seed) % 5];
    k->wrap_t = wraps[rng(&seed) % 5];
    k->min_filter = minf[rng(&seed) % 2];
    k->mag_filter = minf[rng(&seed) % 2];
    k->env = envs[rng(&seed) % 4];
    k->tilt = (float)(rng(&seed) % 70);
    k->lo = -(float)(rng(&seed) % 40) / 10.0f;
    k->hi = 1.0f + (float)(rng(&seed) % 40) / 10.0f;
    k->copy = k->border && rng(&seed) % 2;
}

TEST(wrap_modes_vs_osmesa)
{
    int bad = 0, n = 150;
    for (int i = 0; i < n; i++) {
        wrap_case k;
        random_wrap_case(700u + (uint32_t)i, &k);
        osm_pair p;
        REQUIRE(osm_pair_render(&p, 80, 64, NULL, draw_wrap_case, &k));
        if (p.d.differ) {
            bad++;
            fprintf(stderr, "  case %d: %ld pixels differ (max %d): %dx%d border %d copy %d fmt %#x wrap %#x %#x "
                    "min %#x mag %#x env %#x [%g, %g]\n", i, p.d.differ, p.d.maxd, k.w, k.h, k.border, k.copy,
                    k.internal, k.wrap_s, k.wrap_t, k.min_filter, k.mag_filter, k.env, (double)k.lo, (double)k.hi);
        }
        osm_pair_close(&p);
    }
    if (bad)
        CHECK_FAIL_("%d of %d cases differ from OSMesa", bad, n);
}

/* Every pair of wrap modes with both filters and MIPmaps, one case each. */
TEST(wrap_pairs_vs_osmesa)
{
    int bad = 0, n = 0;
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            for (int f = 0; f < 2; f++) {
                wrap_case k = {(uint32_t)(a * 10 + b), 8, 4, 0, GL_RGBA, wraps[a], wraps[b],
                               f ? GL_LINEAR : GL_NEAREST, f ? GL_NEAREST : GL_LINEAR, GL_REPLACE,
                               (float)(15 * f), -2.3f, 3.1f, 0};
                osm_pair p;
                REQUIRE(osm_pair_render(&p, 64, 48, NULL, draw_wrap_case, &k));
                n++;
                if (p.d.differ) {
                    bad++;
                    fprintf(stderr, "  wraps %#x %#x filter %d: %ld pixels differ\n", wraps[a], wraps[b], f,
                            p.d.differ);
                }
                osm_pair_close(&p);
            }
    if (bad)
        CHECK_FAIL_("%d of %d wrap pairs differ from OSMesa", bad, n);
}

/* The level parameters of images given with a border. */
static void border_queries(fs_context *c, double *v, int *n)
{
    static const GLenum pn[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER, GL_TEXTURE_INTERNAL_FORMAT};
    uint8_t px[18 * 10 * 4];
    for (int i = 0; i < (int)sizeof px; i++)
        px[i] = (uint8_t)(i * 13);
    G(BindTexture, GL_TEXTURE_2D, 2);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 18, 10, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < 4; i++) {
        GLint iv = -5;
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, pn[i], &iv);
        v[(*n)++] = iv;
    }
    uint8_t out[16 * 8 * 4];
    memset(out, 0, sizeof out);
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    uint32_t sum = 0;
    for (int i = 0; i < (int)sizeof out; i++)
        sum = sum * 31u + out[i];
    v[(*n)++] = sum;
    G(CopyTexImage2D, GL_TEXTURE_2D, 1, GL_RGB, 0, 0, 10, 6, 1);
    for (int i = 0; i < 4; i++) {
        GLint iv = -5;
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, 1, pn[i], &iv);
        v[(*n)++] = iv;
    }
    v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError());
}

TEST(border_levels_vs_osmesa)
{
    OSM_CHECK_VALUES(border_queries, 16, 16, 32);
}

TEST_LIST = {
    TEST_ENTRY(wrap_modes_vs_osmesa),
    TEST_ENTRY(wrap_pairs_vs_osmesa),
    TEST_ENTRY(border_levels_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
