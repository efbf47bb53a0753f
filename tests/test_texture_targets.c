/*
 * Texture targets GL_TEXTURE_1D and GL_TEXTURE_3D (GL 1.5 spec 3.8.1-3.8.2,
 * 3.8.7-3.8.9, 3.8.11, 3.8.15; units/texture_target.c, texture_object.c,
 * texture_sample.c) against OSMesa (llvmpipe) at tolerance 0: random
 * images of random sizes (with and without a border, full MIPmap chains),
 * every min and mag filter, every wrap mode on s, t and r, projective
 * coordinates, enables of several targets at once (3.8.15's priority);
 * the image commands (glTexSubImage1D/3D, glCopyTexImage1D,
 * glCopyTexSubImage1D/3D, glGetTexImage with the pack image height and
 * skipped images, proxies, level parameters, errors); bindings, enables and
 * wrap r through glGet and glPushAttrib/glPopAttrib; images compiled into
 * display lists.
 */
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};
static const GLenum min_filters[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                     GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};

typedef struct target_case {
    uint32_t seed;
    GLenum target;             /* GL_TEXTURE_1D or GL_TEXTURE_3D */
    int w, h, d, border;       /* level 0 without its border */
    GLint internal;
    GLenum wrap[3], min_filter, mag_filter, env;
    float tilt, lo, hi, q[4];
    bool with_2d;              /* a 2D texture enabled too (priority, 3.8.15) */
    bool in_list;              /* the images through a display list */
} target_case;

static bool is_mipmap(GLenum f) { return f != GL_NEAREST && f != GL_LINEAR; }

/* Level `level` of the case's texture, as random texels with a border of
 * k->border texels. */
static void define_level(fs_context *c, const target_case *k, int level, uint32_t *s)
{
    int b = level == 0 ? k->border : 0;
    int w = (k->w >> level ? k->w >> level : 1) + 2 * b;
    int h = k->target == GL_TEXTURE_3D ? (k->h >> level ? k->h >> level : 1) + 2 * b : 1;
    int d = k->target == GL_TEXTURE_3D ? (k->d >> level ? k->d >> level : 1) + 2 * b : 1;
    uint8_t *px = malloc((size_t)w * (size_t)h * (size_t)d * 4);
    for (int i = 0; i < w * h * d * 4; i++)
        px[i] = (uint8_t)rng(s);
    if (k->target == GL_TEXTURE_1D)
        G(TexImage1D, GL_TEXTURE_1D, level, k->internal, w, b, GL_RGBA, GL_UNSIGNED_BYTE, px);
    else
        G(TexImage3D, GL_TEXTURE_3D, level, k->internal, w, h, d, b, GL_RGBA, GL_UNSIGNED_BYTE, px);
    free(px);
}

static void define_texture(fs_context *c, const target_case *k)
{
    uint32_t s = k->seed;
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(BindTexture, k->target, 7);
    int levels = 1;
    if (is_mipmap(k->min_filter)) {
        int m = k->w > k->h ? k->w : k->h;
        m = m > k->d ? m : k->d;
        while ((1 << (levels - 1)) < m)
            levels++;
    }
    if (k->in_list) {
        GLuint list = 3;
        G(NewList, list, GL_COMPILE);
        for (int l = 0; l < levels; l++)
            define_level(c, k, l, &s);
        G0(EndList);
        G(PixelStorei, GL_UNPACK_ALIGNMENT, 8); /* the list keeps the unpack state it was compiled with */
        G(CallList, list);
    } else {
        for (int l = 0; l < levels; l++)
            define_level(c, k, l, &s);
    }
    G(TexParameteri, k->target, GL_TEXTURE_MIN_FILTER, (GLint)k->min_filter);
    G(TexParameteri, k->target, GL_TEXTURE_MAG_FILTER, (GLint)k->mag_filter);
    G(TexParameteri, k->target, GL_TEXTURE_WRAP_S, (GLint)k->wrap[0]);
    G(TexParameteri, k->target, GL_TEXTURE_WRAP_T, (GLint)k->wrap[1]);
    G(TexParameteri, k->target, GL_TEXTURE_WRAP_R, (GLint)k->wrap[2]);
    float border[4];
    for (int i = 0; i < 4; i++)
        border[i] = (float)(rng(&s) % 256) / 255.0f;
    G(TexParameterfv, k->target, GL_TEXTURE_BORDER_COLOR, border);
    G(Enable, k->target);
    if (k->with_2d) {
        /* A 2D texture of one colour: the unit must sample the 3D one over
         * it, and the 2D one over a 1D texture. */
        static const uint8_t green[4] = {0, 255, 0, 255};
        G(BindTexture, GL_TEXTURE_2D, 8);
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        G(Enable, GL_TEXTURE_2D);
    }
}

static void draw_target_case(fs_context *c, const void *user, int w, int h)
{
    const target_case *k = user;
    define_texture(c, k);
    osm_tilted_view(c, w, h, k->env, k->tilt);
    /* s across, t up, r along the diagonal, q per corner (projective). */
    static const float corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    G(Begin, GL_QUADS);
    G(Color4f, 0.9f, 0.7f, 0.5f, 0.8f);
    for (int i = 0; i < 4; i++) {
        float u = k->lo + (k->hi - k->lo) * corner[i][0], v = k->lo + (k->hi - k->lo) * corner[i][1];
        float r = k->lo + (k->hi - k->lo) * (corner[i][0] + corner[i][1]) * 0.5f;
        float q = k->q[i];
        G(TexCoord4f, u * q, v * q, r * q, q);
        G(Vertex3f, -1.2f + 2.4f * corner[i][0], -1.0f + 2.0f * corner[i][1], 0);
    }
    G0(End);
}

static void random_target_case(uint32_t seed, target_case *k)
{
    static const GLint formats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY};
    /* DECAL and BLEND are left out as in test_texture_wrap.c: their
     * arithmetic is off by 1 in some pixels (the environment's). */
    static const GLenum envs[] = {GL_REPLACE, GL_MODULATE};
    memset(k, 0, sizeof *k);
    k->seed = seed;
    k->target = rng(&seed) % 2 ? GL_TEXTURE_3D : GL_TEXTURE_1D;
    bool three = k->target == GL_TEXTURE_3D;
    k->border = rng(&seed) % 5 == 0;
    k->w = 1 << (rng(&seed) % (three ? 5 : 7));
    k->h = three ? 1 << (rng(&seed) % 5) : 1;
    k->d = three ? 1 << (rng(&seed) % 5) : 1;
    k->internal = formats[rng(&seed) % 6];
    for (int a = 0; a < 3; a++)
        k->wrap[a] = wraps[rng(&seed) % 5];
    k->min_filter = min_filters[rng(&seed) % 6];
    k->mag_filter = rng(&seed) % 2 ? GL_LINEAR : GL_NEAREST;
    k->env = envs[rng(&seed) % 2];
    k->tilt = (float)(rng(&seed) % 75);
    k->lo = -(float)(rng(&seed) % 30) / 10.0f;
    k->hi = 0.5f + (float)(rng(&seed) % 40) / 10.0f;
    bool proj = rng(&seed) % 2;
    for (int i = 0; i < 4; i++)
        k->q[i] = proj ? 0.5f + (float)(rng(&seed) % 16) / 10.0f : 1.0f;
    k->with_2d = rng(&seed) % 4 == 0;
    k->in_list = rng(&seed) % 4 == 0;
}

static void report_case(int i, const osm_pair *p, const target_case *k)
{
    fprintf(stderr,
            "  case %d: %ld pixels differ (max %d): %s %dx%dx%d border %d fmt %#x wrap %#x %#x %#x min %#x mag %#x "
            "env %#x [%g, %g] q %g %g 2d %d list %d\n",
            i, p->d.differ, p->d.maxd, k->target == GL_TEXTURE_1D ? "1D" : "3D", k->w, k->h, k->d, k->border,
            k->internal, k->wrap[0], k->wrap[1], k->wrap[2], k->min_filter, k->mag_filter, k->env, (double)k->lo,
            (double)k->hi, (double)k->q[0], (double)k->q[2], k->with_2d, k->in_list);
}

/* Case i drawn on both at w x h: 1 when it differs (reported), 0 when
 * not, -1 when no context could be made. */
static int run_case(int i, const target_case *k, int w, int h)
{
    osm_pair p;
    if (!osm_pair_render(&p, w, h, NULL, draw_target_case, k))
        return -1;
    int differs = p.d.differ != 0;
    if (differs)
        report_case(i, &p, k);
    osm_pair_close(&p);
    return differs;
}

/* Random cases; FRAGSIM_TARGET_CASES=n runs n of them. */
TEST(targets_vs_osmesa)
{
    const char *env = getenv("FRAGSIM_TARGET_CASES");
    int bad = 0, n = env ? atoi(env) : 240;
    for (int i = 0; i < n; i++) {
        target_case k;
        random_target_case(9100u + (uint32_t)i, &k);
        int r = run_case(i, &k, 72, 56);
        REQUIRE(r >= 0);
        bad += r;
    }
    if (bad)
        CHECK_FAIL_("%d of %d cases differ from OSMesa", bad, n);
}

/* Every wrap mode on each axis of a 3D texture and on s of a 1D one, with
 * both image filters and a MIPmap filter. */
TEST(wrap_each_axis_vs_osmesa)
{
    int bad = 0, n = 0;
    for (int t = 0; t < 2; t++)
        for (int axis = 0; axis < (t ? 3 : 1); axis++)
            for (int wr = 0; wr < 5; wr++)
                for (int f = 0; f < 3; f++) {
                    target_case k;
                    memset(&k, 0, sizeof k);
                    k.seed = (uint32_t)(100 * t + 20 * axis + 4 * wr + f);
                    k.target = t ? GL_TEXTURE_3D : GL_TEXTURE_1D;
                    k.w = 8;
                    k.h = t ? 4 : 1;
                    k.d = t ? 4 : 1;
                    k.internal = GL_RGBA;
                    k.wrap[0] = k.wrap[1] = k.wrap[2] = GL_REPEAT;
                    k.wrap[axis] = wraps[wr];
                    k.min_filter = f == 2 ? GL_LINEAR_MIPMAP_LINEAR : f ? GL_LINEAR : GL_NEAREST;
                    k.mag_filter = f ? GL_NEAREST : GL_LINEAR;
                    k.env = GL_REPLACE;
                    k.tilt = (float)(30 * f);
                    k.lo = -1.7f;
                    k.hi = 2.6f;
                    k.q[0] = k.q[1] = k.q[2] = k.q[3] = 1.0f;
                    int r = run_case(n++, &k, 64, 48);
                    REQUIRE(r >= 0);
                    bad += r;
                }
    if (bad)
        CHECK_FAIL_("%d of %d cases differ from OSMesa", bad, n);
}

/* ---- images and queries ---- */

#define GERR() ((double)(c ? fsglGetError(c) : glGetError()))

static void level_params(fs_context *c, GLenum target, int level, double *v, int *n)
{
    static const GLenum pn[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH, GL_TEXTURE_BORDER,
                                GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE,
                                GL_TEXTURE_LUMINANCE_SIZE};
    osm_level_params(c, target, level, pn, 8, v, n);
}


static void image_commands(fs_context *c, double *v, int *n)
{
    uint8_t px[20 * 10 * 6 * 4];
    for (int i = 0; i < (int)sizeof px; i++)
        px[i] = (uint8_t)(i * 37 + (i >> 5));
    /* The framebuffer's colours, to copy from. */
    G(ClearColor, 0.2f, 0.4f, 0.6f, 0.8f);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(Begin, GL_TRIANGLES);
    G(Color3f, 1, 0, 0);
    G(Vertex2f, -1, -1);
    G(Color3f, 0, 1, 0);
    G(Vertex2f, 1, -1);
    G(Color3f, 0, 0, 1);
    G(Vertex2f, -1, 1);
    G0(End);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    /* 1D: an image, a part replaced, copied rows, a border. */
    G(BindTexture, GL_TEXTURE_1D, 4);
    G(TexImage1D, GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    G(TexSubImage1D, GL_TEXTURE_1D, 0, 3, 7, GL_RGB, GL_UNSIGNED_BYTE, px + 100);
    level_params(c, GL_TEXTURE_1D, 0, v, n);
    osm_get_image(c, GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    G(CopyTexSubImage1D, GL_TEXTURE_1D, 0, 2, 5, 3, 9);
    osm_get_image(c, GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    G(CopyTexImage1D, GL_TEXTURE_1D, 1, GL_RGB, 4, 6, 8, 0);
    level_params(c, GL_TEXTURE_1D, 1, v, n);
    osm_get_image(c, GL_TEXTURE_1D, 1, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    G(CopyTexImage1D, GL_TEXTURE_1D, 2, GL_LUMINANCE, 1, 2, 6, 1);
    level_params(c, GL_TEXTURE_1D, 2, v, n);
    osm_get_image(c, GL_TEXTURE_1D, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, v, n);
    G(TexImage1D, GL_TEXTURE_1D, 3, GL_LUMINANCE_ALPHA, 10, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    level_params(c, GL_TEXTURE_1D, 3, v, n);
    osm_get_image(c, GL_TEXTURE_1D, 3, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, v, n);
    /* 3D: an image with unpack image height and skipped images, parts. */
    G(BindTexture, GL_TEXTURE_3D, 5);
    G(PixelStorei, GL_UNPACK_IMAGE_HEIGHT, 10);
    G(PixelStorei, GL_UNPACK_SKIP_IMAGES, 1);
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_RGBA, 8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    G(PixelStorei, GL_UNPACK_IMAGE_HEIGHT, 0);
    G(PixelStorei, GL_UNPACK_SKIP_IMAGES, 0);
    level_params(c, GL_TEXTURE_3D, 0, v, n);
    osm_get_image(c, GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    G(TexSubImage3D, GL_TEXTURE_3D, 0, 1, 2, 1, 5, 2, 3, GL_RGBA, GL_UNSIGNED_BYTE, px + 400);
    G(CopyTexSubImage3D, GL_TEXTURE_3D, 0, 2, 1, 3, 4, 5, 6, 3);
    G(PixelStorei, GL_PACK_IMAGE_HEIGHT, 6);
    G(PixelStorei, GL_PACK_SKIP_IMAGES, 2);
    osm_get_image(c, GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    G(PixelStorei, GL_PACK_IMAGE_HEIGHT, 0);
    G(PixelStorei, GL_PACK_SKIP_IMAGES, 0);
    G(TexImage3D, GL_TEXTURE_3D, 1, GL_INTENSITY, 6, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    level_params(c, GL_TEXTURE_3D, 1, v, n);
    osm_get_image(c, GL_TEXTURE_3D, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, v, n);
    /* Proxies: a size accepted, one refused (no error), an error. */
    G(TexImage1D, GL_PROXY_TEXTURE_1D, 0, GL_RGB, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_params(c, GL_PROXY_TEXTURE_1D, 0, v, n);
    G(TexImage1D, GL_PROXY_TEXTURE_1D, 0, GL_RGB, 65536, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_params(c, GL_PROXY_TEXTURE_1D, 0, v, n);
    G(TexImage3D, GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 32, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_params(c, GL_PROXY_TEXTURE_3D, 0, v, n);
    G(TexImage3D, GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 4096, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_params(c, GL_PROXY_TEXTURE_3D, 0, v, n);
    G(TexImage3D, GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 32, 16, 8, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    v[(*n)++] = GERR();
    /* Errors (nothing changes): wrong targets, bad sizes (too large or
     * negative: OSMesa takes sizes other than 2^n + 2 border,
     * ARB_texture_non_power_of_two, which the model refuses as for 2D
     * images), offsets outside,
     * a texture bound before to another target, proxies where none is
     * allowed. */
    G(TexImage1D, GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexImage3D, GL_TEXTURE_1D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_RGBA, 4, 4096, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexImage3D, GL_TEXTURE_3D, 12, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexSubImage3D, GL_TEXTURE_3D, 0, 6, 0, 0, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 3, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexSubImage3D, GL_TEXTURE_3D, 2, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexSubImage1D, GL_PROXY_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(TexSubImage1D, GL_TEXTURE_1D, 0, 14, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(CopyTexImage1D, GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 0);
    v[(*n)++] = GERR();
    G(CopyTexImage1D, GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 8192, 3);
    v[(*n)++] = GERR();
    G(CopyTexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 4, 0, 0, 2, 2);
    v[(*n)++] = GERR();
    G(BindTexture, GL_TEXTURE_3D, 4); /* texture 4 is a 1D texture */
    v[(*n)++] = GERR();
    G(BindTexture, GL_PROXY_TEXTURE_3D, 0);
    v[(*n)++] = GERR();
    G(GetTexImage, GL_PROXY_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[(*n)++] = GERR();
    G(GetTexLevelParameteriv, GL_TEXTURE_3D, 12, GL_TEXTURE_WIDTH, (GLint *)(void *)px);
    v[(*n)++] = GERR();
    GLint iv = -1;
    G(GetTexParameteriv, GL_PROXY_TEXTURE_3D, GL_TEXTURE_WRAP_R, &iv);
    v[(*n)++] = GERR();
    G(GetIntegerv, GL_TEXTURE_BINDING_3D, &iv);
    v[(*n)++] = iv;
    osm_get_image(c, GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
    osm_get_image(c, GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, v, n);
}

TEST(image_commands_vs_osmesa) { OSM_CHECK_VALUES(image_commands, 32, 24, 512); }

/* ---- state: glGet and the attribute stack ---- */

static void get_target_state(fs_context *c, double *v, int *n)
{
    static const GLenum names[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_BINDING_1D,
                                   GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_3D, GL_MAX_3D_TEXTURE_SIZE};
    for (int u = 0; u < 2; u++) {
        G(ActiveTexture, GL_TEXTURE0 + (GLenum)u);
        for (int i = 0; i < 7; i++) {
            GLint iv = -1;
            G(GetIntegerv, names[i], &iv);
            v[(*n)++] = iv;
        }
        static const GLenum targets[] = {GL_TEXTURE_1D, GL_TEXTURE_3D};
        for (int t = 0; t < 2; t++) {
            static const GLenum pn[] = {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R,
                                        GL_TEXTURE_MIN_FILTER};
            for (int i = 0; i < 4; i++) {
                GLint iv = -1;
                G(GetTexParameteriv, targets[t], pn[i], &iv);
                v[(*n)++] = iv;
            }
        }
        v[(*n)++] = GR(IsEnabled, GL_TEXTURE_3D);
    }
    G(ActiveTexture, GL_TEXTURE0);
    v[(*n)++] = GERR();
}

static void target_state(fs_context *c, double *v, int *n)
{
    get_target_state(c, v, n);
    G(BindTexture, GL_TEXTURE_1D, 3);
    G(BindTexture, GL_TEXTURE_3D, 9);
    G(TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    G(TexParameteri, GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    G(Enable, GL_TEXTURE_3D);
    G(ActiveTexture, GL_TEXTURE1);
    G(Enable, GL_TEXTURE_1D);
    G(BindTexture, GL_TEXTURE_3D, 11);
    G(TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    G(ActiveTexture, GL_TEXTURE0);
    get_target_state(c, v, n);
    G(PushAttrib, GL_TEXTURE_BIT | GL_ENABLE_BIT);
    G(BindTexture, GL_TEXTURE_1D, 0);
    G(BindTexture, GL_TEXTURE_3D, 12);
    G(TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
    G(Disable, GL_TEXTURE_3D);
    G(ActiveTexture, GL_TEXTURE1);
    G(Disable, GL_TEXTURE_1D);
    G(TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(ActiveTexture, GL_TEXTURE0);
    get_target_state(c, v, n);
    G0(PopAttrib);
    get_target_state(c, v, n);
    G(BindTexture, GL_TEXTURE_3D, 12);
    get_target_state(c, v, n);
    /* The footprint filters are 2D only (docs/extensions/footprint_filter.txt);
     * OSMesa knows no such enum: INVALID_ENUM on both. */
    G(TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_FOOTPRINT_FRAGSIM);
    v[(*n)++] = GERR();
    G(TexParameteri, GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_FOOTPRINT_HYBRID_FRAGSIM);
    v[(*n)++] = GERR();
    get_target_state(c, v, n);
}

TEST(target_state_vs_osmesa) { OSM_CHECK_VALUES(target_state, 32, 24, 512); }

TEST_LIST = {
    TEST_ENTRY(targets_vs_osmesa),
    TEST_ENTRY(wrap_each_axis_vs_osmesa),
    TEST_ENTRY(image_commands_vs_osmesa),
    TEST_ENTRY(target_state_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
