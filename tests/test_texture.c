/*
 * The texture unit (units/texture_*.c) against OSMesa (llvmpipe) in the same
 * process: textured quads at several scales and perspective tilts, every
 * min and mag filter, every wrap mode, every environment mode and base
 * format, checkerboard and random textures of 1x1..256x256, MIPmaps; and
 * the GL errors of the texture commands.
 *
 * Each scene prints the pixels that differ from OSMesa and the largest
 * channel difference.  Required (issue 4): NEAREST filters exact, all
 * other cases within 1 of 255.
 */
#include <GL/osmesa.h>
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../units/texture_unit.h"

#define G(name, ...) do { if (c) fsgl##name(c, __VA_ARGS__); else gl##name(__VA_ARGS__); } while (0)
#define G0(name) do { if (c) fsgl##name(c); else gl##name(); } while (0)

typedef struct tex_case {
    const char *name;
    int size;              /* texture is size x size (power of two) */
    int content;           /* 0 checkerboard, 1 random, 2 smooth gradient */
    GLint internal;        /* internal format */
    GLenum format;         /* client format of the image */
    GLenum min_filter, mag_filter, wrap;
    GLenum env;
    float scale;           /* quad half-size in object units */
    float tilt;            /* rotation about x in degrees (perspective) */
    float repeat;          /* texture coordinates span [-lo, repeat] */
    float lo;
    int rotate_z;          /* rotation about z in degrees */
    int no_mipmaps;        /* define only level 0 (incomplete with a MIPMAP filter) */
} tex_case;

static uint32_t rng_next(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* Level `lvl` of the test texture: level 0 from the content rule, each
 * further level an independent pattern so a wrong level shows. */
static void make_level(const tex_case *tc, int lvl, int w, int h, uint8_t *px, int comps)
{
    uint32_t seed = 12345u + 977u * (uint32_t)lvl + (uint32_t)tc->size;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t v[4];
            if (tc->content == 0) {
                int on = ((x >> (lvl ? 0 : (tc->size >= 16 ? 2 : 0))) ^ (y >> (lvl ? 0 : (tc->size >= 16 ? 2 : 0)))) & 1;
                v[0] = on ? 230 : (uint8_t)(20 + 30 * lvl);
                v[1] = on ? (uint8_t)(200 - 20 * lvl) : 40;
                v[2] = on ? 60 : (uint8_t)(180 + 5 * lvl);
                v[3] = on ? 255 : 128;
            } else if (tc->content == 1) {
                uint32_t r = rng_next(&seed);
                v[0] = (uint8_t)r;
                v[1] = (uint8_t)(r >> 8);
                v[2] = (uint8_t)(r >> 16);
                v[3] = (uint8_t)(rng_next(&seed) >> 4);
            } else {
                v[0] = (uint8_t)(x * 255 / (w > 1 ? w - 1 : 1));
                v[1] = (uint8_t)(y * 255 / (h > 1 ? h - 1 : 1));
                v[2] = (uint8_t)(40 * lvl);
                v[3] = (uint8_t)(255 - (x + y) * 100 / (w + h));
            }
            uint8_t *p = px + ((size_t)y * (size_t)w + (size_t)x) * (size_t)comps;
            if (comps == 4) memcpy(p, v, 4);
            else if (comps == 3) memcpy(p, v, 3);
            else if (comps == 2) { p[0] = v[0]; p[1] = v[3]; }
            else p[0] = tc->format == GL_ALPHA ? v[3] : v[0];
        }
}

static int comps_of(GLenum f)
{
    return f == GL_RGBA ? 4 : f == GL_RGB ? 3 : f == GL_LUMINANCE_ALPHA ? 2 : 1;
}

static const tex_case *g_case; /* the case being drawn (read-only, set per test) */

static void draw_case(fs_context *c, int w, int h)
{
    const tex_case *tc = g_case;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.2f, 0.1f, 0.3f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 40.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -4);
    G(Rotatef, -tc->tilt, 1, 0, 0);
    G(Rotatef, (float)tc->rotate_z, 0, 0, 1);

    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(BindTexture, GL_TEXTURE_2D, 7);
    int comps = comps_of(tc->format);
    uint8_t *px = malloc((size_t)tc->size * (size_t)tc->size * 4);
    int lw = tc->size, lh = tc->size;
    for (int lvl = 0;; lvl++) {
        make_level(tc, lvl, lw, lh, px, comps);
        G(TexImage2D, GL_TEXTURE_2D, lvl, tc->internal, lw, lh, 0, tc->format, GL_UNSIGNED_BYTE, px);
        if (tc->no_mipmaps || (lw == 1 && lh == 1))
            break;
        lw = lw > 1 ? lw / 2 : 1;
        lh = lh > 1 ? lh / 2 : 1;
    }
    free(px);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)tc->min_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)tc->mag_filter);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)tc->wrap);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)tc->wrap);
    const float border[4] = {0.9f, 0.5f, 0.1f, 0.7f};
    G(TexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)tc->env);
    const float envc[4] = {0.2f, 0.8f, 0.6f, 0.4f};
    G(TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    G(Enable, GL_TEXTURE_2D);

    float s = tc->scale, r = tc->repeat, lo = -tc->lo;
    G(Begin, GL_QUADS);
    G(Color4f, 1.0f, 0.8f, 0.6f, 0.9f);
    G(TexCoord2f, lo, lo);
    G(Vertex3f, -s, -s, 0);
    G(Color4f, 0.3f, 0.9f, 0.5f, 0.6f);
    G(TexCoord2f, r, lo);
    G(Vertex3f, s, -s, 0);
    G(Color4f, 0.7f, 0.2f, 1.0f, 1.0f);
    G(TexCoord2f, r, r);
    G(Vertex3f, s, s, 0);
    G(Color4f, 0.5f, 0.5f, 0.1f, 0.3f);
    G(TexCoord2f, lo, r);
    G(Vertex3f, -s, s, 0);
    G0(End);
    G(Disable, GL_TEXTURE_2D);
}

typedef struct cmp_result { long differ, differ_gt1, covered; int maxd; } cmp_result;

static int render_compare(const tex_case *tc, int w, int h, cmp_result *res)
{
    memset(res, 0, sizeof *res);
    g_case = tc;
    uint8_t *ref = calloc((size_t)w * h, 4);
    OSMesaContext oc = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!oc || !ref || !OSMesaMakeCurrent(oc, ref, GL_UNSIGNED_BYTE, w, h)) {
        free(ref);
        return -1;
    }
    draw_case(NULL, w, h);
    glFinish();
    fs_context *c = fs_context_create(NULL, w, h);
    if (!c) {
        OSMesaDestroyContext(oc);
        free(ref);
        return -1;
    }
    draw_case(c, w, h);
    const uint8_t *mine = c->fb.color;
    for (long i = 0; i < (long)w * h; i++) {
        int d = 0;
        for (int k = 0; k < 4; k++) {
            int e = abs((int)mine[i * 4 + k] - (int)ref[i * 4 + k]);
            d = e > d ? e : d;
        }
        if (d) res->differ++;
        if (d > 1) res->differ_gt1++;
        if (d > res->maxd) res->maxd = d;
    }
    res->covered = (long)c->stats.fragments_generated;
    printf("  %-34s %7ld fragments, %6ld differ (%6ld by more than 1), max %3d\n", tc->name, res->covered,
           res->differ, res->differ_gt1, res->maxd);
    if (getenv("FS_TEX_DUMP")) {
        char fn[256];
        snprintf(fn, sizeof fn, "/tmp/tex_%s.ppm", tc->name);
        FILE *f = fopen(fn, "wb");
        if (f) {
            fprintf(f, "P6 %d %d 255\n", w * 3, h);
            for (int y = h - 1; y >= 0; y--)
                for (int x = 0; x < 3 * w; x++) {
                    uint8_t dp[3];
                    const uint8_t *p;
                    if (x < w) p = &ref[((long)y * w + x) * 4];
                    else if (x < 2 * w) p = &mine[((long)y * w + x - w) * 4];
                    else {
                        long o = ((long)y * w + x - 2 * w) * 4;
                        int d = 0;
                        for (int k = 0; k < 4; k++) {
                            int e = abs((int)mine[o + k] - (int)ref[o + k]);
                            d = e > d ? e : d;
                        }
                        dp[0] = d > 1 ? 255 : 0;
                        dp[1] = d == 1 ? 255 : 0;
                        dp[2] = 0;
                        p = dp;
                    }
                    fwrite(p, 1, 3, f);
                }
            fclose(f);
        }
    }
    fs_context_destroy(c);
    OSMesaDestroyContext(oc);
    free(ref);
    return 0;
}

static bool nearest_only(const tex_case *tc)
{
    return (tc->min_filter == GL_NEAREST || tc->min_filter == GL_NEAREST_MIPMAP_NEAREST) &&
           tc->mag_filter == GL_NEAREST;
}

/* Runs cases; NEAREST (no blending of texels anywhere) must be exact, the
 * rest within 1. */
static void run_cases(check_state *check_st_, const tex_case *cases, int n, int w, int h)
{
    long total = 0, differ = 0;
    for (int i = 0; i < n; i++) {
        cmp_result r;
        REQUIRE(render_compare(&cases[i], w, h, &r) == 0);
        CHECK(r.covered > 0);
        if (nearest_only(&cases[i]) && r.differ != 0)
            CHECK_FAIL_("%s: NEAREST must be exact, %ld pixels differ", cases[i].name, r.differ);
        if (r.differ_gt1 != 0)
            CHECK_FAIL_("%s: %ld pixels differ by more than 1", cases[i].name, r.differ_gt1);
        total += (long)w * h;
        differ += r.differ;
    }
    printf("  all: %ld of %ld pixels differ\n", differ, total);
}

#define W 160
#define H 120

/* name, size, content, internal, format, min, mag, wrap, env, scale, tilt, repeat, lo, rot, nomip */
TEST(filters_magnified)
{
    static const tex_case cases[] = {
        {"mag_nearest_checker8", 8, 0, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 0, 1},
        {"mag_nearest_random16_rot", 16, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 17, 1},
        {"mag_linear_checker8", 8, 0, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 0, 1},
        {"mag_linear_random16_rot", 16, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 17, 1},
        {"mag_linear_gradient4_tilt", 4, 2, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 50, 1, 0, 0, 1},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

TEST(filters_minified)
{
    static const tex_case cases[] = {
        {"min_nearest_random64", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.0f, 0, 4, 0, 0, 1},
        {"min_linear_random64", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.0f, 0, 4, 0, 0, 1},
        {"min_nmn_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0},
        {"min_lmn_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0},
        {"min_nml_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0},
        {"min_lml_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0},
        {"min_lml_checker256_tilt", 256, 0, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 75, 8, 0, 0, 0},
        {"min_nml_gradient128_rot", 128, 2, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.0f, 30, 3, 0, 33, 0},
        {"min_lml_random256_flat", 256, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 0.7f, 0, 2, 0, 10, 0},
        {"min_nmn_mag_linear_tilt", 32, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 1, 0, 0, 0},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

TEST(wrap_modes)
{
    static const tex_case cases[] = {
        {"wrap_repeat_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_clamp_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_CLAMP, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_edge_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_repeat_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_clamp_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_CLAMP, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_edge_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1},
        {"wrap_clamp_lml_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP, GL_REPLACE, 1.5f, 70, 1.5f, 0.5f, 0, 0},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

TEST(env_modes_and_formats)
{
    static const GLenum envs[] = {GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND, GL_ADD};
    static const char *env_names[] = {"modulate", "decal", "replace", "blend", "add"};
    static const struct { GLint internal; GLenum format; const char *name; } fmts[] = {
        {GL_RGBA, GL_RGBA, "rgba"}, {GL_RGB, GL_RGB, "rgb"}, {GL_LUMINANCE, GL_LUMINANCE, "lum"},
        {GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, "lum_alpha"}, {GL_ALPHA, GL_ALPHA, "alpha"},
        {GL_INTENSITY, GL_LUMINANCE, "intensity"}, {4, GL_RGBA, "4"}, {3, GL_RGB, "3"}, {1, GL_LUMINANCE, "1"},
        {2, GL_LUMINANCE_ALPHA, "2"}, {GL_RGBA8, GL_RGBA, "rgba8"},
    };
    static char names[5 * 11][48];
    tex_case cases[5 * 11];
    int n = 0;
    for (int e = 0; e < 5; e++)
        for (int f = 0; f < 11; f++) {
            snprintf(names[n], sizeof names[n], "env_%s_%s", env_names[e], fmts[f].name);
            tex_case tc = {names[n], 16, 1, fmts[f].internal, fmts[f].format, GL_LINEAR, GL_LINEAR, GL_REPEAT, envs[e],
                           1.5f, 30, 1, 0, 0, 1};
            cases[n++] = tc;
        }
    run_cases(check_st_, cases, n, W, H);
}

TEST(sizes)
{
    static char names[9][48];
    tex_case cases[18];
    int n = 0;
    for (int l = 0; l <= 8; l++) {
        snprintf(names[l], sizeof names[l], "size_%d_lml_tilt", 1 << l);
        tex_case tc = {names[l], 1 << l, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE,
                       1.5f, 65, 2, 0, 10, 0};
        cases[n++] = tc;
        tc.min_filter = GL_NEAREST_MIPMAP_NEAREST;
        tc.mag_filter = GL_NEAREST;
        tc.env = GL_REPLACE;
        tc.name = names[l] + 0; /* same label, different filter: printed twice */
        cases[n++] = tc;
    }
    run_cases(check_st_, cases, n, W, H);
}

TEST(incomplete_texture)
{
    /* Level 0 only with a MIPMAP min filter: incomplete (GL 1.5 spec
     * 3.8.10), so texturing is off for the unit. */
    static const tex_case cases[] = {
        {"incomplete_mipmap", 16, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE, 1.5f, 30, 1, 0, 0, 1},
    };
    run_cases(check_st_, cases, 1, W, H);
}

/* ---- errors (GL 1.5 spec 2.5, 3.8): the call sets the error and changes
 * nothing ---- */

static GLenum err(fs_context *c) { return fsglGetError(c); }

TEST(errors)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    uint8_t px[64 * 4] = {0};
    fsglBindTexture(c, GL_TEXTURE_2D, 3);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglTexImage2D(c, GL_TEXTURE_1D + 99, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA + 100, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_DOUBLE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, 5, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexImage2D(c, GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexImage2D(c, GL_TEXTURE_2D, FS_TEX_MAX_LEVELS, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexSubImage2D(c, GL_TEXTURE_2D, 0, 2, 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglTexSubImage2D(c, GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglTexEnvi(c, GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglBindTexture(c, GL_RGBA, 3);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    GLuint names[2];
    fsglGenTextures(c, -1, names);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglDeleteTextures(c, -1, names);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglCopyTexImage2D(c, GL_TEXTURE_2D, 0, 4, 0, 0, 4, 4, 0);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    /* Nothing changed: the 4x4 image and the default parameters stand,
     * and the texture is used (complete with NEAREST). */
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    CHECK_EQ_INT(fsglIsTexture(c, 3), GL_TRUE);
    fsglGenTextures(c, 2, names);
    CHECK(names[0] != 0 && names[1] != 0 && names[0] != names[1] && names[0] != 3 && names[1] != 3);
    CHECK_EQ_INT(fsglIsTexture(c, names[0]), GL_FALSE); /* not bound yet */
    fsglDeleteTextures(c, 1, (GLuint[]){3});
    CHECK_EQ_INT(fsglIsTexture(c, 3), GL_FALSE);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

TEST(unpack_and_subimage)
{
    /* Row length, alignment, TexSubImage2D, CopyTexImage2D: the texels read
     * back through a REPLACE/NEAREST quad drawn pixel-for-texel. */
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    CHECK_EQ_INT(fs_teximage_bytes(c, 3, 2, GL_RGB, GL_UNSIGNED_BYTE), 12 + 9);
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    CHECK_EQ_INT(fs_teximage_bytes(c, 3, 2, GL_RGB, GL_UNSIGNED_BYTE), 18);
    fsglPixelStorei(c, GL_UNPACK_ROW_LENGTH, 5);
    CHECK_EQ_INT(fs_teximage_bytes(c, 3, 2, GL_RGB, GL_UNSIGNED_BYTE), 15 + 9);
    /* 4x4 luminance texture read from rows of 6 with alignment 8. */
    fsglPixelStorei(c, GL_UNPACK_ROW_LENGTH, 6);
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 8);
    uint8_t lum[8 * 4];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 8; x++)
            lum[y * 8 + x] = (uint8_t)(x < 4 ? 10 * y + x : 0xEE);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    fsglPixelStorei(c, GL_UNPACK_ROW_LENGTH, 0);
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    const uint8_t sub[2] = {200, 201};
    fsglTexSubImage2D(c, GL_TEXTURE_2D, 0, 1, 3, 2, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, sub);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fsglEnable(c, GL_TEXTURE_2D);
    CHECK_EQ_INT(fsglIsEnabled(c, GL_TEXTURE_2D), GL_TRUE);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglOrtho(c, 0, 8, 0, 8, -1, 1);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, 0, 0); fsglVertex2f(c, 0, 0);
    fsglTexCoord2f(c, 1, 0); fsglVertex2f(c, 4, 0);
    fsglTexCoord2f(c, 1, 1); fsglVertex2f(c, 4, 4);
    fsglTexCoord2f(c, 0, 1); fsglVertex2f(c, 0, 4);
    fsglEnd(c);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            int want = (y == 3 && (x == 1 || x == 2)) ? 199 + x : 10 * y + x;
            CHECK_EQ_INT(c->fb.color[(y * 8 + x) * 4], want);
        }
    /* CopyTexImage2D of the rendered 4x4 block, drawn again at (4, 4). */
    fsglCopyTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, 0, 0); fsglVertex2f(c, 4, 4);
    fsglTexCoord2f(c, 1, 0); fsglVertex2f(c, 8, 4);
    fsglTexCoord2f(c, 1, 1); fsglVertex2f(c, 8, 8);
    fsglTexCoord2f(c, 0, 1); fsglVertex2f(c, 4, 8);
    fsglEnd(c);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++)
            CHECK_EQ_INT(c->fb.color[((y + 4) * 8 + x + 4) * 4], c->fb.color[(y * 8 + x) * 4]);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(filters_magnified),
    TEST_ENTRY(filters_minified),
    TEST_ENTRY(wrap_modes),
    TEST_ENTRY(env_modes_and_formats),
    TEST_ENTRY(sizes),
    TEST_ENTRY(incomplete_texture),
    TEST_ENTRY(errors),
    TEST_ENTRY(unpack_and_subimage),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
