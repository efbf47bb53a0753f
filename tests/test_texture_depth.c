/*
 * Depth textures and ARB_shadow (GL 1.4 spec 3.8.1, 3.8.4, 3.8.14;
 * units/texture_depth.c) against OSMesa (llvmpipe), tolerance 0: random
 * depth textures in each depth internal format (and unsized
 * DEPTH_COMPONENT from each client type, and ARB_depth_buffer_float's
 * DEPTH_COMPONENT32F, which llvmpipe offers) drawn with random r per vertex,
 * every compare function and COMPARE_MODE NONE, every DEPTH_TEXTURE_MODE,
 * NEAREST and LINEAR, MIPmaps; the parameters' state and errors.
 */
#include <stdint.h>
#include <stdlib.h>
#include "check.h"
#include "osmesa_util.h"
#include "test_rng.h"
#include <GL/glext.h>

#define W 48
#define H 48
#define TS 8 /* texture size */

typedef struct depth_case {
    GLint internal;
    GLenum type;          /* client type of the depth data */
    GLenum compare_mode;  /* GL_NONE or GL_COMPARE_R_TO_TEXTURE */
    GLenum func;
    GLenum mode;          /* DEPTH_TEXTURE_MODE */
    GLenum min_filter, mag_filter;
    GLenum env;
    GLenum wrap;
    uint64_t seed;
    float r_lo, r_hi;     /* range of the random r of the vertices */
    bool equal_r;         /* all vertices take r = one stored texel's depth */
    float q;              /* the vertices' q (projective) */
    float tilt;           /* rotation about x (degrees): minification */
    float span;           /* half the s and t range over the quad (0: 0.6) */
} depth_case;

/* Client depth data of n texels of a type, random in [0, 1] (a few at 0
 * and 1 exactly). */
static void make_depth(rng *g, GLenum type, int n, void *out)
{
    for (int i = 0; i < n; i++) {
        int k = rndi(g, 16);
        float f = k == 0 ? 0.0f : k == 1 ? 1.0f : rndf(g, 0.0f, 1.0f);
        switch (type) {
        case GL_UNSIGNED_SHORT: ((uint16_t *)out)[i] = (uint16_t)(k < 2 ? (k ? 65535 : 0) : rnd(g)); break;
        case GL_UNSIGNED_INT: ((uint32_t *)out)[i] = k < 2 ? (k ? 0xffffffffu : 0) : rnd(g); break;
        case GL_UNSIGNED_BYTE: ((uint8_t *)out)[i] = (uint8_t)(k < 2 ? (k ? 255 : 0) : rnd(g)); break;
        case GL_SHORT: ((int16_t *)out)[i] = (int16_t)rnd(g); break;
        /* EXT_packed_depth_stencil: depth in the top 24 bits, a random stencil below. */
        case GL_UNSIGNED_INT_24_8: ((uint32_t *)out)[i] = k < 2 ? (k ? 0xffffff00u : 0) | (rnd(g) & 0xff) : rnd(g); break;
        /* ARB_depth_buffer_float: a float depth (some outside [0, 1]), a stencil word. */
        case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
            ((float *)out)[2 * i] = k == 2 ? -0.25f : k == 3 ? 1.5f : f;
            ((uint32_t *)out)[2 * i + 1] = rnd(g);
            break;
        default: ((float *)out)[i] = k == 2 ? -0.25f : k == 3 ? 1.5f : f; break;
        }
    }
}

static void draw_depth(fs_context *c, const void *user, int w, int h)
{
    const depth_case *dc = user;
    rng g = {dc->seed};
    osm_frustum_scene(c, w, h, 0.2f, 0.3f, 0.4f, 10);
    GLuint tex;
    G(GenTextures, 1, &tex);
    G(BindTexture, GL_TEXTURE_2D, tex);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    static uint32_t data[2 * TS * TS];
    bool ds = dc->type == GL_UNSIGNED_INT_24_8 || dc->type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
    bool mip = dc->min_filter != GL_NEAREST && dc->min_filter != GL_LINEAR;
    for (int l = 0, s = TS; s >= 1 && (l == 0 || mip); l++, s /= 2) {
        make_depth(&g, dc->type, s * s, data);
        G(TexImage2D, GL_TEXTURE_2D, l, dc->internal, s, s, 0, ds ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT, dc->type,
          data);
    }
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)dc->min_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)dc->mag_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)dc->wrap);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)dc->wrap);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, (GLint)dc->compare_mode);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)dc->func);
    G(TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, (GLint)dc->mode);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)dc->env);
    G(Enable, GL_TEXTURE_2D);
    float req = 0.0f;
    if (dc->equal_r) {
        /* One texel's depth as the sampler reads it, through glGetTexImage. */
        static float back[TS * TS];
        G(GetTexImage, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
        req = back[rndi(&g, TS * TS)];
    }
    G(Translatef, 0, 0, -2.5f);
    G(Rotatef, dc->tilt, 1, 0, 0);
    G(Begin, GL_QUADS);
    static const float v[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; i++) {
        float r = dc->equal_r ? req : rndf(&g, dc->r_lo, dc->r_hi);
        float span = dc->span > 0.0f ? dc->span : 0.6f;
        float s = v[i][0] * span + 0.5f, t = v[i][1] * span + 0.5f, q = dc->q;
        G(Color4f, 0.9f, 0.7f, 0.5f, 0.6f);
        G(TexCoord4f, s * q, t * q, r * q, q);
        G(Vertex2f, v[i][0], v[i][1]);
    }
    G0(End);
    G(DeleteTextures, 1, &tex);
}

/* Renders one case on both; the pixels that differ (-1: no context). */
static long run_case(const depth_case *dc, GLenum *err)
{
    osm_pair p;
    if (!osm_pair_render(&p, W, H, NULL, draw_depth, dc))
        return -1;
    long d = p.d.differ;
    *err = fsglGetError(p.c);
    if (d && getenv("DEPTHTEX_DUMP")) {
        img_dump_ppm("/tmp/depthtex.ppm", p.ref.color, p.c->fb.color, W, H, 4, true);
        for (int i = 0; i < W * H; i++)
            if (memcmp(p.ref.color + 4 * i, p.c->fb.color + 4 * i, 4))
                printf("    pixel (%d, %d): OSMesa %d %d %d %d, fragsim %d %d %d %d\n", i % W, i / W,
                       p.ref.color[4 * i], p.ref.color[4 * i + 1], p.ref.color[4 * i + 2], p.ref.color[4 * i + 3],
                       p.c->fb.color[4 * i], p.c->fb.color[4 * i + 1], p.c->fb.color[4 * i + 2],
                       p.c->fb.color[4 * i + 3]);
    }
    osm_pair_close(&p);
    return d;
}

static const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const GLenum modes[] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA};
static const struct { GLint internal; GLenum type; } formats[] = {
    {GL_DEPTH_COMPONENT16, GL_FLOAT}, {GL_DEPTH_COMPONENT24, GL_FLOAT}, {GL_DEPTH_COMPONENT32, GL_FLOAT},
    {GL_DEPTH_COMPONENT16, GL_UNSIGNED_SHORT}, {GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT},
    {GL_DEPTH_COMPONENT32, GL_UNSIGNED_INT}, {GL_DEPTH_COMPONENT16, GL_UNSIGNED_INT},
    {GL_DEPTH_COMPONENT32, GL_UNSIGNED_SHORT}, {GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT},
    {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT}, {GL_DEPTH_COMPONENT, GL_FLOAT}, {GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE},
    {GL_DEPTH_COMPONENT24, GL_SHORT}, {GL_DEPTH_COMPONENT32F, GL_FLOAT}, {GL_DEPTH_COMPONENT32F, GL_UNSIGNED_SHORT},
    /* GL_DEPTH_STENCIL data (EXT_packed_depth_stencil, ARB_depth_buffer_float)
     * into the depth-stencil formats and into depth ones; DEPTH_COMPONENT
     * data into a depth-stencil format. */
    {GL_DEPTH24_STENCIL8, GL_UNSIGNED_INT_24_8}, {GL_DEPTH24_STENCIL8, GL_FLOAT_32_UNSIGNED_INT_24_8_REV},
    {GL_DEPTH32F_STENCIL8, GL_FLOAT_32_UNSIGNED_INT_24_8_REV}, {GL_DEPTH32F_STENCIL8, GL_UNSIGNED_INT_24_8},
    {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8}, {GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV},
    {GL_DEPTH_COMPONENT16, GL_UNSIGNED_INT_24_8}, {GL_DEPTH_COMPONENT32, GL_UNSIGNED_INT_24_8},
    {GL_DEPTH_COMPONENT32F, GL_FLOAT_32_UNSIGNED_INT_24_8_REV}, {GL_DEPTH_COMPONENT24, GL_FLOAT_32_UNSIGNED_INT_24_8_REV},
    {GL_DEPTH24_STENCIL8, GL_FLOAT}, {GL_DEPTH32F_STENCIL8, GL_UNSIGNED_SHORT},
};
#define NFORMATS (int)(sizeof formats / sizeof formats[0])

/* Cases over a grid, counted; each that differs is printed, and the
 * pixels that differ summed into *pixels. */
static int run_grid_pixels(const depth_case *base, int nfuncs_from, bool all_formats, bool all_modes, int *ncases,
                           long *pixels)
{
    int bad = 0;
    for (int f = 0; f < (all_formats ? NFORMATS : 3); f++)
        for (int cf = nfuncs_from; cf < 8; cf++)
            for (int m = 0; m < (all_modes ? 3 : 1); m++) {
                depth_case dc = *base;
                dc.internal = formats[f].internal;
                dc.type = formats[f].type;
                if (cf >= 0) {
                    dc.compare_mode = GL_COMPARE_R_TO_TEXTURE;
                    dc.func = funcs[cf];
                } else {
                    dc.compare_mode = GL_NONE;
                }
                dc.mode = modes[m];
                dc.seed = base->seed + 1000u * (uint64_t)f + 31u * (uint64_t)(cf + 1) + (uint64_t)m;
                GLenum err = GL_NO_ERROR;
                long d = run_case(&dc, &err);
                (*ncases)++;
                *pixels += d;
                if (d != 0 || err != GL_NO_ERROR) {
                    printf("  differs: internal %#x type %#x compare %#x func %#x mode %#x min %#x mag %#x: %ld "
                           "pixels, error %#x\n",
                           (unsigned)dc.internal, dc.type, dc.compare_mode, dc.func, dc.mode, dc.min_filter,
                           dc.mag_filter, d, err);
                    bad++;
                }
            }
    return bad;
}

/* The same, every case required exact. */
static void run_grid(check_state *check_st_, const depth_case *base, int nfuncs_from, bool all_formats,
                     bool all_modes, int *ncases)
{
    long pixels = 0;
    CHECK_EQ_INT(run_grid_pixels(base, nfuncs_from, all_formats, all_modes, ncases, &pixels), 0);
}

static const depth_case base_case = {
    .func = GL_LEQUAL, .min_filter = GL_NEAREST, .mag_filter = GL_NEAREST, .env = GL_MODULATE,
    .wrap = GL_REPEAT, .seed = 1, .r_lo = -0.2f, .r_hi = 1.2f, .q = 1.0f,
};

TEST(nearest_every_format_func_mode)
{
    int n = 0;
    run_grid(check_st_, &base_case, -1, true, true, &n);
    printf("  %d cases\n", n);
}

TEST(linear_every_format_func_mode)
{
    depth_case b = base_case;
    b.min_filter = b.mag_filter = GL_LINEAR;
    b.seed = 2;
    int n = 0;
    run_grid(check_st_, &b, -1, true, true, &n);
    printf("  %d cases\n", n);
}

TEST(equal_reference_ties)
{
    /* r equal to a stored texel's depth: EQUAL, NOTEQUAL, LEQUAL and
     * GEQUAL then depend on how the reference and the texel are compared. */
    int n = 0;
    for (int filt = 0; filt < 2; filt++) {
        depth_case b = base_case;
        b.equal_r = true;
        b.min_filter = b.mag_filter = filt ? GL_LINEAR : GL_NEAREST;
        b.seed = 3 + (uint64_t)filt;
        run_grid(check_st_, &b, 0, true, false, &n);
    }
    printf("  %d cases\n", n);
}

/* Known difference: with q = 1.7 and a tilt, one pixel of four cases
 * (EQUAL with LINEAR_MIPMAP_NEAREST in the three sized formats, GEQUAL with
 * NEAREST_MIPMAP_LINEAR in DEPTH_COMPONENT24) differs by 1 in green.  It is
 * the pixel where the clamped reference r/q crosses 1.0, the depth of the
 * texels stored as 1: there the model's r/q and llvmpipe's round to
 * different sides of 1.0 (measured: with q = 1, 2, 0.5 or 3 no pixel
 * differs, and computing r/q as a division instead of r * (1/q) changes
 * nothing; suspected: the perspective interpolation of r*q, one ulp).
 * The check fails when the difference goes away. */
TEST(mipmaps_projective_clamp_edge)
{
    int n = 0, bad = 0;
    long pixels = 0;
    static const GLenum mins[] = {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR};
    for (int i = 0; i < 4; i++) {
        depth_case b = base_case;
        b.min_filter = mins[i];
        b.mag_filter = GL_LINEAR;
        b.tilt = -70.0f;
        b.q = 1.7f;
        b.wrap = i & 1 ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        b.seed = 10 + (uint64_t)i;
        bad += run_grid_pixels(&b, -1, false, false, &n, &pixels);
    }
    printf("  %d cases, %d differ (known: 4, 1 pixel each)\n", n, bad);
    CHECK_EQ_INT(bad, 4);
    CHECK_EQ_INT(pixels, 4);
    /* The same scenes with q = 2: exact. */
    for (int i = 0; i < 4; i++) {
        depth_case b = base_case;
        b.min_filter = mins[i];
        b.mag_filter = GL_LINEAR;
        b.tilt = -70.0f;
        b.q = 2.0f;
        b.wrap = i & 1 ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        b.seed = 10 + (uint64_t)i;
        run_grid(check_st_, &b, -1, false, false, &n);
    }
}

TEST(min_mag_filters_differ)
{
    /* A tilted quad with minified and magnified pixels, min and mag image
     * filters different: llvmpipe's float path then samples a quad's
     * NEAREST pixels through its LINEAR code when the quad sharing its
     * vector is LINEAR (texture_sample.c). */
    int n = 0;
    for (int i = 0; i < 4; i++) {
        depth_case b = base_case;
        b.min_filter = i & 1 ? GL_NEAREST : GL_LINEAR;
        b.mag_filter = i & 1 ? GL_LINEAR : GL_NEAREST;
        b.wrap = i & 2 ? GL_CLAMP : GL_REPEAT;
        b.tilt = -70.0f;
        b.span = 2.0f;
        b.seed = 30 + (uint64_t)i;
        run_grid(check_st_, &b, -1, false, false, &n);
    }
    printf("  %d cases\n", n);
}

/* A depth texture copied from the depth buffer (glCopyTexImage2D and
 * glCopyTexSubImage2D, GL 1.4 3.8.2), or a 1D one, drawn with a compare. */
typedef struct copy_case {
    GLint internal;
    GLenum func, filter;
    bool sub, one_d;
    uint64_t seed;
} copy_case;

static void draw_copy(fs_context *c, const void *user, int w, int h)
{
    const copy_case *cc = user;
    rng g = {cc->seed};
    osm_frustum_scene(c, w, h, 0.1f, 0.1f, 0.1f, 10);
    G(Clear, GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(Translatef, 0, 0, -2.0f);
    /* Depths to copy: two tilted, crossing quads. */
    for (int k = 0; k < 2; k++) {
        G0(PushMatrix);
        G(Rotatef, k ? 50.0f : -40.0f, 1, 0.3f, 0);
        G(Begin, GL_QUADS);
        G(Vertex2f, -1, -1);
        G(Vertex2f, 1, -1);
        G(Vertex2f, 1, 1);
        G(Vertex2f, -1, 1);
        G0(End);
        G0(PopMatrix);
    }
    G(Disable, GL_DEPTH_TEST);
    GLuint tex;
    G(GenTextures, 1, &tex);
    GLenum target = cc->one_d ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    G(BindTexture, target, tex);
    if (cc->one_d) {
        static float d[16];
        for (int i = 0; i < 16; i++)
            d[i] = rndf(&g, 0.0f, 1.0f);
        G(TexImage1D, GL_TEXTURE_1D, 0, cc->internal, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    } else if (cc->sub) {
        G(TexImage2D, GL_TEXTURE_2D, 0, cc->internal, 32, 32, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
        G(CopyTexSubImage2D, GL_TEXTURE_2D, 0, 4, 2, 8, 10, 24, 28);
    } else {
        G(CopyTexImage2D, GL_TEXTURE_2D, 0, cc->internal, 8, 8, 32, 32, 0);
    }
    G(TexParameteri, target, GL_TEXTURE_MIN_FILTER, (GLint)cc->filter);
    G(TexParameteri, target, GL_TEXTURE_MAG_FILTER, (GLint)cc->filter);
    G(TexParameteri, target, GL_TEXTURE_COMPARE_MODE, cc->func ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
    if (cc->func)
        G(TexParameteri, target, GL_TEXTURE_COMPARE_FUNC, (GLint)cc->func);
    G(Enable, target);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -2.0f);
    G(Begin, GL_QUADS);
    static const float v[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; i++) {
        G(TexCoord3f, v[i][0] * 0.5f + 0.5f, v[i][1] * 0.5f + 0.5f, rndf(&g, 0.0f, 1.0f));
        G(Vertex2f, v[i][0], v[i][1]);
    }
    G0(End);
    G(DeleteTextures, 1, &tex);
}

TEST(copied_and_1d_depth_textures)
{
    static const GLint ifs[] = {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32,
                                GL_DEPTH_COMPONENT32F};
    int n = 0, bad = 0;
    for (int kind = 0; kind < 3; kind++)
        for (int i = 0; i < 5; i++)
            for (int f = 0; f < 9; f++)
                for (int filt = 0; filt < 2; filt++) {
                    copy_case cc = {ifs[i], f ? funcs[f - 1] : 0, filt ? GL_LINEAR : GL_NEAREST, kind == 1,
                                    kind == 2, 500u + 10u * (uint64_t)f + (uint64_t)i};
                    osm_pair p;
                    REQUIRE(osm_pair_render(&p, W, H, NULL, draw_copy, &cc));
                    GLenum err = fsglGetError(p.c);
                    n++;
                    if (p.d.differ || err) {
                        printf("  differs: kind %d internal %#x func %#x filter %#x: %ld pixels, max %d, error %#x\n",
                               kind, (unsigned)cc.internal, cc.func, cc.filter, p.d.differ, p.d.maxd, err);
                        bad++;
                    }
                    osm_pair_close(&p);
                }
    printf("  %d cases\n", n);
    CHECK_EQ_INT(bad, 0);
}

TEST(environments)
{
    static const GLenum envs[] = {GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD};
    int n = 0;
    for (int i = 0; i < 4; i++) {
        depth_case b = base_case;
        b.env = envs[i];
        b.min_filter = b.mag_filter = GL_LINEAR;
        b.seed = 20 + (uint64_t)i;
        run_grid(check_st_, &b, 6, false, true, &n);
    }
    printf("  %d cases\n", n);
}

/* Parameters, level sizes, push/pop and the errors of the commands, as
 * values read on both. */
static void depth_state(fs_context *c, double *out, int *n)
{
#define PUT(v) (out[(*n)++] = (double)(v))
#define ERR() PUT(c ? fsglGetError(c) : glGetError())
    GLint iv = -1;
    GLfloat fv = -1;
    static const GLenum pn[] = {GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC};
    for (int k = 0; k < 3; k++) {
        G(GetTexParameteriv, GL_TEXTURE_2D, pn[k], &iv);
        PUT(iv);
    }
    /* Every value each parameter takes, and some it does not. */
    static const GLint mode_v[] = {GL_INTENSITY, GL_ALPHA, GL_RED, GL_LUMINANCE, GL_RGBA, GL_DEPTH_COMPONENT, 0};
    static const GLint cmp_v[] = {GL_COMPARE_R_TO_TEXTURE, GL_NONE, GL_LEQUAL, 1};
    static const GLint func_v[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
                                   GL_ALWAYS, GL_NEVER - 1, GL_ALWAYS + 1, GL_NONE};
    for (int k = 0; k < (int)(sizeof mode_v / sizeof *mode_v); k++) {
        G(TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, mode_v[k]);
        ERR();
        G(GetTexParameterfv, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &fv);
        PUT(fv);
    }
    for (int k = 0; k < (int)(sizeof cmp_v / sizeof *cmp_v); k++) {
        G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, (float)cmp_v[k]);
        ERR();
        G(GetTexParameteriv, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &iv);
        PUT(iv);
    }
    for (int k = 0; k < (int)(sizeof func_v / sizeof *func_v); k++) {
        G(TexParameteriv, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &func_v[k]);
        ERR();
        G(GetTexParameteriv, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &iv);
        PUT(iv);
    }
    /* The texture attribute group keeps them (6.1.14). */
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    G(TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    G(PushAttrib, GL_TEXTURE_BIT);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    G(TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NEVER);
    G0(PopAttrib);
    for (int k = 0; k < 3; k++) {
        G(GetTexParameteriv, GL_TEXTURE_2D, pn[k], &iv);
        PUT(iv);
    }
    /* Sizes of each format (table 6.18), 1D and 2D, proxies. */
    static const GLint ifs[] = {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32,
                                GL_DEPTH_COMPONENT32F};
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_FLOAT, GL_SHORT};
    static const GLenum sizes[] = {GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_RED_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                                   GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_INTENSITY_SIZE, GL_TEXTURE_INTERNAL_FORMAT};
    static uint32_t zeros[64];
    for (int i = 0; i < 5; i++)
        for (int t = 0; t < 5; t++) {
            G(TexImage2D, GL_TEXTURE_2D, 0, ifs[i], 4, 2, 0, GL_DEPTH_COMPONENT, types[t], zeros);
            ERR();
            G(TexImage1D, GL_TEXTURE_1D, 0, ifs[i], 4, 0, GL_DEPTH_COMPONENT, types[t], zeros);
            ERR();
            for (int k = 0; k < 6; k++) {
                G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, sizes[k], &iv);
                PUT(iv);
                G(GetTexLevelParameteriv, GL_TEXTURE_1D, 0, sizes[k], &iv);
                PUT(iv);
            }
        }
    G(TexImage2D, GL_PROXY_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    ERR();
    G(GetTexLevelParameteriv, GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &iv);
    PUT(iv);
    /* 3.8.1: depth data needs a depth internal format and the reverse;
     * no 3D depth textures (proxy too). */
    float f = 0.5f;
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_LUMINANCE, GL_FLOAT, &f);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 2, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE_3_3_2, &f);
    ERR();
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 1, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    G(TexImage3D, GL_PROXY_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 1, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, &f);
    ERR();
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    uint8_t px[4];
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    ERR();
    /* glCopyTexImage from the depth buffer: the sizes it gives. */
    G(CopyTexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);
    ERR();
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &iv);
    PUT(iv);
    G(CopyTexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32, 0, 0, 4, 4, 0);
    ERR();
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &iv);
    PUT(iv);
#undef PUT
#undef ERR
}

TEST(state_sizes_errors_vs_osmesa)
{
    OSM_CHECK_VALUES(depth_state, 8, 8, 1024);
}

/* glGetTexImage(DEPTH_COMPONENT, FLOAT) of each format: the stored depth
 * as Mesa reads it back (the upload rules of texture_depth.c). */
static void depth_readback(fs_context *c, double *out, int *n)
{
    rng g = {77};
    static uint32_t data[128];
    static float back[64];
    for (int f = 0; f < NFORMATS; f++) {
        GLenum type = formats[f].type;
        bool ds = type == GL_UNSIGNED_INT_24_8 || type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
        make_depth(&g, type, 64, data);
        G(TexImage2D, GL_TEXTURE_2D, 0, formats[f].internal, 8, 8, 0, ds ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT, type,
          data);
        G(GetTexImage, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
        for (int i = 0; i < 64; i++)
            out[(*n)++] = back[i];
    }
    /* Depth scale and bias apply to the upload (3.8.1, 3.6.5). */
    G(PixelTransferf, GL_DEPTH_SCALE, 0.5f);
    G(PixelTransferf, GL_DEPTH_BIAS, 0.25f);
    make_depth(&g, GL_UNSIGNED_SHORT, 64, data);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 8, 8, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, data);
    G(PixelTransferf, GL_DEPTH_SCALE, 1.0f);
    G(PixelTransferf, GL_DEPTH_BIAS, 0.0f);
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
    for (int i = 0; i < 64; i++)
        out[(*n)++] = back[i];
}

TEST(upload_readback_vs_osmesa)
{
    OSM_CHECK_VALUES(depth_readback, 8, 8, 64 * (NFORMATS + 1));
}

/* EXT_packed_depth_stencil outside textures: glReadPixels(GL_DEPTH_STENCIL)
 * of a depth and stencil buffer drawn by tilted quads, in both packed
 * types, and the errors of the DEPTH_STENCIL format and its types in
 * every pixel command (measured on OSMesa; values compared exactly). */
static void depth_stencil_pixels(fs_context *c, double *out, int *n)
{
#define ERR() (out[(*n)++] = (double)(c ? fsglGetError(c) : glGetError()))
    static uint32_t data[2 * 16 * 16], back[2 * 16 * 16];
    osm_frustum_scene(c, 16, 16, 0.1f, 0.2f, 0.3f, 10);
    G(ClearStencil, 3);
    G(Clear, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(Enable, GL_STENCIL_TEST);
    G(StencilOp, GL_KEEP, GL_KEEP, GL_REPLACE);
    G(Translatef, 0, 0, -2.0f);
    for (int k = 0; k < 2; k++) {
        G(StencilFunc, GL_ALWAYS, 17 + 100 * k, 0xff);
        G0(PushMatrix);
        G(Rotatef, k ? 50.0f : -40.0f, 1, 0.3f, 0);
        G(Begin, GL_QUADS);
        G(Vertex2f, -1, -1);
        G(Vertex2f, 1, -1);
        G(Vertex2f, 1, 1);
        G(Vertex2f, -1, 1);
        G0(End);
        G0(PopMatrix);
    }
    static const GLenum types[] = {GL_UNSIGNED_INT_24_8, GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
    for (int t = 0; t < 2; t++) {
        memset(back, 0xee, sizeof back);
        G(ReadPixels, 0, 0, 16, 16, GL_DEPTH_STENCIL, types[t], back);
        ERR();
        for (int i = 0; i < (t ? 512 : 256); i++)
            out[(*n)++] = back[i];
    }
    G(ReadPixels, 0, 0, 4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, back);
    ERR();
    G(ReadPixels, 0, 0, 4, 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, back);
    ERR();
    G(ReadPixels, 0, 0, 4, 4, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, back);
    ERR();
    G(DrawPixels, 4, 4, GL_DEPTH_STENCIL, GL_FLOAT, data);
    ERR();
    G(DrawPixels, 4, 4, GL_DEPTH_STENCIL, GL_BITMAP, data);
    ERR();
    G(CopyPixels, 0, 0, 4, 4, GL_DEPTH_STENCIL);
    ERR();
    G(Disable, GL_DEPTH_TEST);
    G(Disable, GL_STENCIL_TEST);
    /* Texture commands. */
    GLuint tex;
    G(GenTextures, 1, &tex);
    G(BindTexture, GL_TEXTURE_2D, tex);
    static const GLenum bad_types[] = {GL_UNSIGNED_INT, GL_BYTE, GL_BITMAP, GL_UNSIGNED_SHORT_5_6_5, GL_FLOAT};
    for (int i = 0; i < 5; i++) {
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL, bad_types[i], data);
        ERR();
    }
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, data);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, data);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    ERR();
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, data);
    ERR();
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_DEPTH24_STENCIL8, 4, 4, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, data);
    ERR();
    static const GLint ds_formats[] = {GL_DEPTH_STENCIL, GL_DEPTH24_STENCIL8, GL_DEPTH32F_STENCIL8};
    for (int f = 0; f < 3; f++)
        for (int t = 0; t < 2; t++) {
            G(TexImage2D, GL_TEXTURE_2D, 0, ds_formats[f], 4, 4, 0, GL_DEPTH_STENCIL, types[t], data);
            ERR();
            GLint iv = -5;
            G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &iv);
            out[(*n)++] = iv;
            G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &iv);
            out[(*n)++] = iv;
        }
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, data);
    ERR();
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, data);
    ERR();
    G(CopyTexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 0, 0, 4, 4, 0);
    ERR();
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
    ERR();
    for (int i = 0; i < 16; i++)
        out[(*n)++] = ((float *)back)[i];
    G(DeleteTextures, 1, &tex);
#undef ERR
}

TEST(depth_stencil_pixels_vs_osmesa)
{
    OSM_CHECK_VALUES(depth_stencil_pixels, 16, 16, 1024);
}

TEST_LIST = {
    TEST_ENTRY(depth_stencil_pixels_vs_osmesa),
    TEST_ENTRY(nearest_every_format_func_mode),
    TEST_ENTRY(linear_every_format_func_mode),
    TEST_ENTRY(equal_reference_ties),
    TEST_ENTRY(mipmaps_projective_clamp_edge),
    TEST_ENTRY(min_mag_filters_differ),
    TEST_ENTRY(copied_and_1d_depth_textures),
    TEST_ENTRY(environments),
    TEST_ENTRY(state_sizes_errors_vs_osmesa),
    TEST_ENTRY(upload_readback_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
