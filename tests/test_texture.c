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
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../units/texture_unit.h"

typedef struct tex_case {
    const char *name;
    int size;              /* texture is size x size */
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
    GLenum wrap_t;         /* T's wrap when not 0, else wrap */
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

static void draw_case(fs_context *c, const void *user, int w, int h)
{
    const tex_case *tc = user;
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
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)(tc->wrap_t ? tc->wrap_t : tc->wrap));
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
    osm_pair p;
    if (!osm_pair_render(&p, w, h, NULL, draw_case, tc))
        return -1;
    res->differ = p.d.differ;
    res->differ_gt1 = p.d.differ_gt1;
    res->maxd = p.d.maxd;
    res->covered = (long)p.c->stats.fragments_generated;
    printf("  %-34s %7ld fragments, %6ld differ (%6ld by more than 1), max %3d\n", tc->name, res->covered,
           res->differ, res->differ_gt1, res->maxd);
    if (getenv("FS_TEX_DUMP")) {
        char fn[256];
        snprintf(fn, sizeof fn, "/tmp/tex_%s.ppm", tc->name);
        img_dump_ppm(fn, p.ref.color, p.c->fb.color, w, h, 1, true);
    }
    osm_pair_close(&p);
    return 0;
}

static bool nearest_only(const tex_case *tc)
{
    return (tc->min_filter == GL_NEAREST || tc->min_filter == GL_NEAREST_MIPMAP_NEAREST) &&
           tc->mag_filter == GL_NEAREST;
}

/* Runs cases; NEAREST (no blending of texels anywhere) must be exact, the
 * rest within 1, or exact too with all_exact. */
static void run_cases_tol(check_state *check_st_, const tex_case *cases, int n, int w, int h, bool all_exact)
{
    long total = 0, differ = 0;
    for (int i = 0; i < n; i++) {
        cmp_result r;
        REQUIRE(render_compare(&cases[i], w, h, &r) == 0);
        CHECK(r.covered > 0);
        if ((all_exact || nearest_only(&cases[i])) && r.differ != 0)
            CHECK_FAIL_("%s: must be exact, %ld pixels differ", cases[i].name, r.differ);
        if (r.differ_gt1 != 0)
            CHECK_FAIL_("%s: %ld pixels differ by more than 1", cases[i].name, r.differ_gt1);
        total += (long)w * h;
        differ += r.differ;
    }
    printf("  all: %ld of %ld pixels differ\n", differ, total);
}

static void run_cases(check_state *check_st_, const tex_case *cases, int n, int w, int h)
{
    run_cases_tol(check_st_, cases, n, w, h, false);
}

#define W 160
#define H 120

/* name, size, content, internal, format, min, mag, wrap, env, scale, tilt, repeat, lo, rot, nomip */
TEST(filters_magnified)
{
    static const tex_case cases[] = {
        {"mag_nearest_checker8", 8, 0, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 0, 1, 0},
        {"mag_nearest_random16_rot", 16, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 17, 1, 0},
        {"mag_linear_checker8", 8, 0, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 0, 1, 0},
        {"mag_linear_random16_rot", 16, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 0, 1, 0, 17, 1, 0},
        {"mag_linear_gradient4_tilt", 4, 2, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 50, 1, 0, 0, 1, 0},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

TEST(filters_minified)
{
    static const tex_case cases[] = {
        {"min_nearest_random64", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.0f, 0, 4, 0, 0, 1, 0},
        {"min_linear_random64", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.0f, 0, 4, 0, 0, 1, 0},
        {"min_nmn_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0, 0},
        {"min_lmn_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0, 0},
        {"min_nml_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0, 0},
        {"min_lml_random64_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0, 0},
        {"min_lml_checker256_tilt", 256, 0, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 75, 8, 0, 0, 0, 0},
        {"min_nml_gradient128_rot", 128, 2, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.0f, 30, 3, 0, 33, 0, 0},
        {"min_lml_random256_flat", 256, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 0.7f, 0, 2, 0, 10, 0, 0},
        {"min_nmn_mag_linear_tilt", 32, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 70, 1, 0, 0, 0, 0},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

TEST(wrap_modes)
{
    static const tex_case cases[] = {
        {"wrap_repeat_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_clamp_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_CLAMP, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_edge_nearest", 8, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_repeat_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_clamp_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_CLAMP, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_edge_linear", 8, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
        {"wrap_clamp_lml_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP, GL_REPLACE, 1.5f, 70, 1.5f, 0.5f, 0, 0, 0},
    };
    run_cases(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H);
}

/* ARB_texture_non_power_of_two (Mesa exposes it on every context, and
 * captured programs upload such images): REPEAT on an axis whose size is
 * not a power of two wraps the fraction of s (gallivm), in the 8-bit path
 * (REPEAT, CLAMP_TO_EDGE) and in the float one (another wrap on the other
 * axis); MIPmaps halve with the floor (3.8.10). */
TEST(non_power_of_two)
{
    static const tex_case cases[] = {
        {"npot13_repeat_nearest", 13, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 20, 2.5f, 1.5f, 7, 1, 0},
        {"npot13_repeat_linear", 13, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 20, 2.5f, 1.5f, 7, 1, 0},
        {"npot24_repeat_lml_tilt", 24, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE, 1.5f, 70, 6, 0.3f, 10, 0, 0},
        {"npot100_edge_nmn_tilt", 100, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_REPLACE, 1.5f, 70, 4, 0, 0, 0, 0},
        {"npot13_float_repeat_nearest", 13, 1, GL_RGBA, GL_RGBA, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 20, 2.5f, 1.5f, 7, 1, GL_CLAMP},
        {"npot13_float_repeat_linear", 13, 1, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.5f, 20, 2.5f, 1.5f, 7, 1, GL_MIRRORED_REPEAT},
        {"npot5_clamp_linear", 5, 2, GL_RGBA, GL_RGBA, GL_LINEAR, GL_LINEAR, GL_CLAMP, GL_REPLACE, 1.5f, 20, 1.5f, 0.5f, 0, 1, 0},
    };
    run_cases_tol(check_st_, cases, (int)(sizeof cases / sizeof cases[0]), W, H, true);
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
                           1.5f, 30, 1, 0, 0, 1, 0};
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
                       1.5f, 65, 2, 0, 10, 0, 0};
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
        {"incomplete_mipmap", 16, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE, 1.5f, 30, 1, 0, 0, 1, 0},
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
    /* ARB_texture_non_power_of_two: any size is an image. */
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
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

/* ---- queries (GL 1.5 spec 6.1.3, 6.1.4) against OSMesa: the same call
 * sequence on both, every result and every glGetError logged; the logs
 * must be identical.  Output buffers start filled with a sentinel so that
 * what a call leaves alone (on an error, or the row padding) counts too.
 * Implementation limits (GL_MAX_TEXTURE_SIZE: 4096 here, 16384 in
 * llvmpipe; levels 13-14 exist only there) and the sizes of formats below
 * 8 bits (stored at 8 here) are left out. ---- */

typedef struct qlog { uint8_t *data; size_t n, cap; char what[16384][64]; size_t at[16384]; int entries; } qlog;

static void qrec(qlog *q, const char *what, const void *p, size_t bytes)
{
    if (q->n + bytes > q->cap) {
        size_t cap = (q->n + bytes) * 2 + 4096;
        uint8_t *d = realloc(q->data, cap);
        if (!d)
            return;
        q->data = d;
        q->cap = cap;
    }
    memcpy(q->data + q->n, p, bytes);
    if (q->entries < 16384) {
        snprintf(q->what[q->entries], sizeof q->what[0], "%.63s", what);
        q->at[q->entries++] = q->n;
    }
    q->n += bytes;
}

static void qerr(qlog *q, fs_context *c, const char *what)
{
    GLenum e = c ? fsglGetError(c) : glGetError();
    char w[64];
    snprintf(w, sizeof w, "err after %.40s", what);
    qrec(q, w, &e, sizeof e);
}

#define SENT 0x5A5A5A5A

static void query_params(qlog *q, fs_context *c, const char *tag)
{
    static const GLenum pn[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
                                GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY, GL_TEXTURE_RESIDENT,
                                GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL,
                                GL_GENERATE_MIPMAP};
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        GLint iv[4] = {SENT, SENT, SENT, SENT};
        GLfloat fv[4] = {-7, -7, -7, -7};
        G(GetTexParameteriv, GL_TEXTURE_2D, pn[i], iv);
        G(GetTexParameterfv, GL_TEXTURE_2D, pn[i], fv);
        char w[48];
        snprintf(w, sizeof w, "%s texparam %#x", tag, pn[i]);
        qrec(q, w, iv, sizeof iv);
        qrec(q, w, fv, sizeof fv);
        qerr(q, c, w);
    }
    GLint iv[4] = {SENT, SENT, SENT, SENT};
    GLfloat fv[4] = {-7, -7, -7, -7};
    G(GetTexEnviv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, fv);
    qrec(q, "env mode", iv, sizeof iv);
    qrec(q, "env mode", fv, sizeof fv);
    G(GetTexEnviv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, iv);
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, fv);
    qrec(q, "env color", iv, sizeof iv);
    qrec(q, "env color", fv, sizeof fv);
    GLint b = SENT;
    G(GetIntegerv, GL_TEXTURE_BINDING_2D, &b);
    qrec(q, "binding", &b, sizeof b);
    qerr(q, c, tag);
}

static void query_levels(qlog *q, fs_context *c, const char *tag)
{
    static const GLenum pn[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH, GL_TEXTURE_INTERNAL_FORMAT,
                                GL_TEXTURE_BORDER, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                                GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_COMPRESSED};
    static const GLint levels[] = {0, 1, 12};
    for (size_t l = 0; l < 3; l++)
        for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
            GLint iv = SENT;
            GLfloat fv = -7;
            G(GetTexLevelParameteriv, GL_TEXTURE_2D, levels[l], pn[i], &iv);
            G(GetTexLevelParameterfv, GL_TEXTURE_2D, levels[l], pn[i], &fv);
            char w[48];
            snprintf(w, sizeof w, "%s level %d %#x", tag, levels[l], pn[i]);
            qrec(q, w, &iv, sizeof iv);
            qrec(q, w, &fv, sizeof fv);
            qerr(q, c, w);
        }
}

/* glGetTexImage of level 0 in every format and type (and the packed types
 * with the formats they go with) under one pack state. */
static void query_images(qlog *q, fs_context *c, const char *tag, int w, int h)
{
    static const GLenum fmts[] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA,
                                  GL_LUMINANCE, GL_LUMINANCE_ALPHA};
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT,
                                   GL_FLOAT};
    static const struct { GLenum type, format; } packed[] = {
        {GL_UNSIGNED_BYTE_3_3_2, GL_RGB}, {GL_UNSIGNED_BYTE_2_3_3_REV, GL_RGB},
        {GL_UNSIGNED_SHORT_5_6_5, GL_RGB}, {GL_UNSIGNED_SHORT_5_6_5_REV, GL_RGB},
        {GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA}, {GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_BGRA},
        {GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA}, {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_BGRA},
        {GL_UNSIGNED_INT_8_8_8_8, GL_RGBA}, {GL_UNSIGNED_INT_8_8_8_8_REV, GL_BGRA},
        {GL_UNSIGNED_INT_10_10_10_2, GL_RGBA}, {GL_UNSIGNED_INT_2_10_10_10_REV, GL_BGRA},
    };
    size_t bytes = (size_t)(w + 16) * (size_t)h * 16 + 64;
    uint8_t *buf = malloc(bytes);
    if (!buf)
        return;
    for (size_t f = 0; f < sizeof fmts / sizeof fmts[0] + sizeof packed / sizeof packed[0]; f++) {
        size_t nt = f < sizeof fmts / sizeof fmts[0] ? sizeof types / sizeof types[0] : 1;
        for (size_t t = 0; t < nt; t++) {
            GLenum format = f < 10 ? fmts[f] : packed[f - 10].format;
            GLenum type = f < 10 ? types[t] : packed[f - 10].type;
            memset(buf, 0xA5, bytes);
            G(GetTexImage, GL_TEXTURE_2D, 0, format, type, buf);
            char wh[48];
            snprintf(wh, sizeof wh, "%s image %#x %#x", tag, format, type);
            qrec(q, wh, buf, bytes);
            qerr(q, c, wh);
        }
    }
    free(buf);
}

static void query_sequence(qlog *q, fs_context *c)
{
    query_params(q, c, "default");
    GLuint names[3] = {0, 0, 0};
    G(GenTextures, 3, names);
    for (int i = 0; i < 3; i++) {
        GLboolean is = GR(IsTexture, names[i]);
        qrec(q, "is genned", &is, sizeof is);
    }
    G(BindTexture, GL_TEXTURE_2D, names[1]);
    GLboolean is = GR(IsTexture, names[1]);
    qrec(q, "is bound", &is, sizeof is);
    query_params(q, c, "bound");
    query_levels(q, c, "empty");

    uint8_t px[8 * 4 * 4];
    uint32_t seed = 99;
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (uint8_t)rng_next(&seed);
    px[0] = 0; px[1] = 255; px[2] = 128; px[3] = 127; /* the ends and the middle of the range */
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    static const struct { GLint internal; const char *name; } fmts[] = {
        {GL_RGBA, "rgba"}, {GL_RGB, "rgb"}, {GL_LUMINANCE, "lum"}, {GL_LUMINANCE_ALPHA, "lum_alpha"},
        {GL_ALPHA, "alpha"}, {GL_INTENSITY, "intensity"}, {1, "1"}, {2, "2"}, {3, "3"}, {4, "4"},
        {GL_RGBA8, "rgba8"}, {GL_RGB8, "rgb8"}, {GL_LUMINANCE8, "lum8"}, {GL_ALPHA8, "alpha8"},
        {GL_INTENSITY8, "intensity8"}, {GL_LUMINANCE8_ALPHA8, "lum8_alpha8"},
    };
    for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
        G(TexImage2D, GL_TEXTURE_2D, 0, fmts[f].internal, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        qerr(q, c, fmts[f].name);
        query_levels(q, c, fmts[f].name);
        query_images(q, c, fmts[f].name, 8, 4);
    }
    /* Pack state: alignment and row length change the layout. */
    static const struct { int w, h, align, len; } packs[] = {
        {2, 1, 4, 0}, {2, 2, 8, 0}, {2, 2, 2, 0}, {4, 2, 4, 7}, {1, 4, 8, 3}, {8, 4, 1, 11},
    };
    for (size_t p = 0; p < sizeof packs / sizeof packs[0]; p++) {
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, packs[p].w, packs[p].h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        G(PixelStorei, GL_PACK_ALIGNMENT, packs[p].align);
        G(PixelStorei, GL_PACK_ROW_LENGTH, packs[p].len);
        char tag[48];
        snprintf(tag, sizeof tag, "pack %zu", p);
        query_images(q, c, tag, packs[p].len > packs[p].w ? packs[p].len : packs[p].w, packs[p].h);
        GLint v[2] = {SENT, SENT};
        G(GetIntegerv, GL_PACK_ALIGNMENT, &v[0]);
        G(GetIntegerv, GL_PACK_ROW_LENGTH, &v[1]);
        qrec(q, tag, v, sizeof v);
    }
    G(PixelStorei, GL_PACK_ALIGNMENT, 4);
    G(PixelStorei, GL_PACK_ROW_LENGTH, 0);

    /* Set parameters, read them back (colours clamp to [0, 1]). */
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const GLfloat border[4] = {0.7f, 0.25f, -1.0f, 2.0f};
    G(TexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.3f);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    const GLfloat envc[4] = {0.1f, 0.9f, 0.333f, 1.0f};
    G(TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    const GLint border_i[4] = {2147483647, 0, 1073741823, -5};
    G(BindTexture, GL_TEXTURE_2D, names[2]);
    G(TexParameteriv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border_i);
    query_params(q, c, "names[2]");
    G(BindTexture, GL_TEXTURE_2D, names[1]);
    query_params(q, c, "set");

    /* Priorities: zero and unused names are skipped, values clamp. */
    const GLuint pn[4] = {names[1], 0, 999, names[2]};
    const GLclampf pv[4] = {0.2f, 0.5f, 0.6f, 1.5f};
    G(PrioritizeTextures, 4, pn, pv);
    qerr(q, c, "prioritize");
    query_params(q, c, "prioritized 1");
    G(BindTexture, GL_TEXTURE_2D, names[2]);
    query_params(q, c, "prioritized 2");
    G(PrioritizeTextures, -1, pn, pv);
    qerr(q, c, "prioritize -1");

    /* Residency: all resident, residences untouched; 0 or unused names and
     * n < 0 are INVALID_VALUE. */
    GLboolean res[4] = {7, 7, 7, 7};
    GLboolean all = GR(AreTexturesResident, 2, names + 1, res);
    qrec(q, "resident", &all, sizeof all);
    qrec(q, "resident", res, sizeof res);
    qerr(q, c, "resident");
    const GLuint bad1[2] = {names[1], 0}, bad2[2] = {names[1], 4242};
    all = GR(AreTexturesResident, 2, bad1, res);
    qrec(q, "resident 0", &all, sizeof all);
    qerr(q, c, "resident 0");
    all = GR(AreTexturesResident, 2, bad2, res);
    qrec(q, "resident unused", &all, sizeof all);
    qerr(q, c, "resident unused");
    all = GR(AreTexturesResident, -1, bad2, res);
    qrec(q, "resident -1", &all, sizeof all);
    qrec(q, "resident", res, sizeof res);
    qerr(q, c, "resident -1");

    /* Errors: the output is left alone. */
    GLint iv[4] = {SENT, SENT, SENT, SENT};
    GLfloat fv[4] = {-7, -7, -7, -7};
    G(GetTexParameteriv, GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, iv);
    qerr(q, c, "texparam target");
    G(GetTexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, fv);
    qerr(q, c, "texparam pname");
    G(GetTexLevelParameteriv, GL_TEXTURE_ENV, 0, GL_TEXTURE_WIDTH, iv);
    qerr(q, c, "level target");
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, iv);
    qerr(q, c, "level -1");
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 20, GL_TEXTURE_WIDTH, iv);
    qerr(q, c, "level 20");
    /* Mesa's glGetTexLevelParameterfv writes 0 on an error; the model
     * leaves the output alone (2.5), checked in query_errors_change_nothing. */
    GLfloat fv_mesa_writes = -7;
    G(GetTexLevelParameterfv, GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &fv_mesa_writes);
    qerr(q, c, "level pname");
    G(GetTexEnviv, GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, iv);
    qerr(q, c, "env target");
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, fv);
    qerr(q, c, "env pname");
    uint8_t img[64 * 16];
    static const struct { GLenum target; GLint level; GLenum format, type; const char *what; } bad[] = {
        {GL_TEXTURE_ENV, 0, GL_RGBA, GL_UNSIGNED_BYTE, "image target"},
        {GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, "image proxy"},
        {GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, "image level -1"},
        {GL_TEXTURE_2D, 20, GL_RGBA, GL_UNSIGNED_BYTE, "image level 20"},
        {GL_TEXTURE_2D, 0, 0x1234, GL_UNSIGNED_BYTE, "image format"},
        {GL_TEXTURE_2D, 0, GL_RGBA, 0x1234, "image type"},
        {GL_TEXTURE_2D, 0, GL_RGBA, GL_BITMAP, "image bitmap"},
        {GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, "image 565 rgba"},
        {GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, "image 4444 rgb"},
        {GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_INT_8_8_8_8, "image 8888 lum"},
        {GL_TEXTURE_2D, 3, GL_RGBA, GL_UNSIGNED_BYTE, "image undefined level"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memset(img, 0xA5, sizeof img);
        G(GetTexImage, bad[i].target, bad[i].level, bad[i].format, bad[i].type, img);
        qrec(q, bad[i].what, img, sizeof img);
        qerr(q, c, bad[i].what);
    }
    qrec(q, "error outputs", iv, sizeof iv);
    qrec(q, "error outputs", fv, sizeof fv);

    /* Between Begin and End every query is INVALID_OPERATION (2.6.3). */
    G(Begin, GL_TRIANGLES);
    G(GetTexParameteriv, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv);
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, iv);
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, fv);
    memset(img, 0xA5, sizeof img);
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    G(PrioritizeTextures, 1, names + 2, pv);
    G0(End);
    qerr(q, c, "inside begin/end");
    qrec(q, "begin/end outputs", iv, sizeof iv);
    qrec(q, "begin/end outputs", fv, sizeof fv);
    qrec(q, "begin/end outputs", img, sizeof img);
    query_params(q, c, "after begin/end");

    /* Deleting the bound texture binds 0. */
    G(DeleteTextures, 1, names + 2);
    is = GR(IsTexture, names[2]);
    qrec(q, "is deleted", &is, sizeof is);
    query_params(q, c, "deleted");
    query_levels(q, c, "deleted");
}

TEST(queries_vs_osmesa)
{
    static qlog ref, mine;
    free(ref.data);
    free(mine.data);
    memset(&ref, 0, sizeof ref);
    memset(&mine, 0, sizeof mine);
    osm o;
    if (!osm_open(&o, 16, 16))
        osm_close(&o);
    REQUIRE(o.ctx);
    query_sequence(&ref, NULL);
    GLint max = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    query_sequence(&mine, c);
    GLint mymax = 0;
    fsglGetIntegerv(c, GL_MAX_TEXTURE_SIZE, &mymax);
    CHECK_EQ_INT(mymax, FS_TEX_MAX_SIZE);
    CHECK(max >= 64 && mymax >= 64); /* the GL minimum (table 6.32) */
    fs_context_destroy(c);
    CHECK_EQ_INT(mine.n, ref.n);
    CHECK_EQ_INT(mine.entries, ref.entries);
    int shown = 0;
    long differ = 0;
    for (int i = 0; i < ref.entries && i < mine.entries; i++) {
        size_t end = i + 1 < ref.entries ? ref.at[i + 1] : ref.n;
        size_t len = end - ref.at[i];
        if (ref.at[i] != mine.at[i] || memcmp(ref.data + ref.at[i], mine.data + mine.at[i], len) != 0) {
            differ++;
            if (shown++ < (getenv("FS_Q_ALL") ? 100000 : 12)) {
                char a[64] = "", b[64] = "";
                for (size_t k = 0; k < len && k < 16; k++) {
                    snprintf(a + strlen(a), sizeof a - strlen(a), "%02x", ref.data[ref.at[i] + k]);
                    snprintf(b + strlen(b), sizeof b - strlen(b), "%02x", mine.data[mine.at[i] + k]);
                }
                CHECK_FAIL_("%s: OSMesa %s.. model %s..", ref.what[i], a, b);
            }
        }
    }
    printf("  %d query results (%zu bytes) compared, %ld differ\n", ref.entries, ref.n, differ);
    free(ref.data);
    free(mine.data);
    ref.data = mine.data = NULL;
}

TEST(odd_framebuffer_sizes)
{
    /* Lambda comes from 2x2 quads; the model's quads must line up with
     * llvmpipe's (y-down raster) also when the window height is odd. */
    static const struct { int w, h; } sizes[] = {{63, 37}, {101, 99}, {1, 1}, {2, 3}, {3, 2}, {17, 64}};
    static const tex_case base[] = {
        {"odd_lml_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE, 1.5f, 70, 4, 0, 10, 0, 0},
        {"odd_nmn_tilt", 64, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 1.5f, 70, 4, 0, 10, 0, 0},
        {"odd_nml_rot", 128, 2, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPLACE, 1.0f, 30, 3, 0, 33, 0, 0},
        {"odd_lmn_checker", 256, 0, GL_RGBA, GL_RGBA, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_DECAL, 1.5f, 75, 8, 0, 0, 0, 0},
        {"odd_nmn_small", 16, 1, GL_RGBA, GL_RGBA, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPLACE, 0.3f, 40, 9, 0, 5, 0, 0},
    };
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        printf("  %dx%d:\n", sizes[i].w, sizes[i].h);
        /* Tiny windows: only the large quads are sure to cover a pixel. */
        int n = sizes[i].w * sizes[i].h < 64 ? 3 : (int)(sizeof base / sizeof base[0]);
        run_cases(check_st_, base, n, sizes[i].w, sizes[i].h);
    }
}

/* GL 1.5 spec 5.4: glTexImage2D and glTexSubImage2D in a display list take
 * their pixels by the unpack state at compile time; changing it before
 * glCallList changes nothing.  Same sequence on OSMesa and the model; the
 * texels (glGetTexImage) and the drawn image must be identical. */
static void list_sequence(fs_context *c, uint8_t *texels, size_t tbytes)
{
    uint8_t src[8 * 8 * 4];
    for (size_t i = 0; i < sizeof src; i++)
        src[i] = (uint8_t)(i * 37u + 11u);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(PixelStorei, GL_UNPACK_ROW_LENGTH, 6);
    G(NewList, 5, GL_COMPILE);
    G(BindTexture, GL_TEXTURE_2D, 9);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, src);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 4); /* not compiled: executes now (5.4) */
    G(PixelStorei, GL_UNPACK_ROW_LENGTH, 3);
    G(TexSubImage2D, GL_TEXTURE_2D, 0, 1, 1, 2, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, src + 100);
    G0(EndList);
    /* Another unpack state at execution time. */
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 8);
    G(PixelStorei, GL_UNPACK_ROW_LENGTH, 0);
    G(CallList, 5);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(Enable, GL_TEXTURE_2D);
    G(MatrixMode, GL_PROJECTION);
    G(Ortho, 0, 8, 0, 8, -1, 1);
    G(Begin, GL_QUADS);
    G(TexCoord2f, 0, 0); G(Vertex2f, 0, 0);
    G(TexCoord2f, 1, 0); G(Vertex2f, 8, 0);
    G(TexCoord2f, 1, 1); G(Vertex2f, 8, 8);
    G(TexCoord2f, 0, 1); G(Vertex2f, 0, 8);
    G0(End);
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    memset(texels, 0xA5, tbytes);
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

TEST(display_list_unpack_state)
{
    uint8_t ref[8 * 8 * 4], ref_tex[4 * 4 * 4 + 16], mine_tex[4 * 4 * 4 + 16];
    osm o;
    if (!osm_open(&o, 8, 8))
        osm_close(&o);
    REQUIRE(o.ctx);
    list_sequence(NULL, ref_tex, sizeof ref_tex);
    GLenum ref_err = glGetError();
    glFinish();
    memcpy(ref, o.color, sizeof ref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    list_sequence(c, mine_tex, sizeof mine_tex);
    CHECK_EQ_INT(fsglGetError(c), ref_err);
    CHECK_EQ_INT(ref_err, GL_NO_ERROR);
    CHECK(memcmp(ref_tex, mine_tex, sizeof ref_tex) == 0);
    CHECK(memcmp(ref, c->fb.color, sizeof ref) == 0);
    /* And against the closed form: texel (1, 0) of the RGB image is bytes
     * 3..5 of row 0, texel (0, 1) starts at 6 * 3 (row length 6, alignment 1);
     * the luminance sub-image row 1 starts 4 bytes after row 0 (row length
     * 3 bytes, padded to the alignment 4). */
    CHECK_EQ_INT(mine_tex[4 * 1 + 0], (uint8_t)(3 * 37 + 11));
    CHECK_EQ_INT(mine_tex[4 * 4 + 0], (uint8_t)(18 * 37 + 11));
    CHECK_EQ_INT(mine_tex[(2 * 4 + 1) * 4 + 0], (uint8_t)((100 + 4) * 37 + 11));
    fs_context_destroy(c);
}

TEST(luminance_uint_readback)
{
    /* 6.1.4 with table 6.1 and 4.3.2: L = R, and an 8-bit value x becomes
     * x * (2^32 - 1) / 255, which llvmpipe computes in float: x * (1/255)
     * times 2^32 - 1 rounded to float, so 1.0 reaches 2^32 and wraps to 0
     * (queries_vs_osmesa compares with OSMesa). */
    fs_context *c = fs_context_create(NULL, 4, 4);
    REQUIRE(c);
    const uint8_t px[4 * 2] = {0, 9, 9, 9, 255, 7, 7, 200};
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    uint32_t out[4] = {1, 1, 1, 1};
    fsglGetTexImage(c, GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_INT, out);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_UINT(out[0], 0u);
    CHECK_EQ_UINT(out[1], (uint32_t)llrintf(9.0f * (1.0f / 255.0f) * 4294967295.0f));
    CHECK_EQ_UINT(out[2], 0u);
    CHECK_EQ_UINT(out[3], (uint32_t)llrintf(200.0f * (1.0f / 255.0f) * 4294967295.0f));
    CHECK(out[1] != 9u * 0x01010101u); /* 24 bits of precision, not the exact product */
    fs_context_destroy(c);
}

TEST(query_errors_change_nothing)
{
    fs_context *c = fs_context_create(NULL, 4, 4);
    REQUIRE(c);
    GLfloat fv = -7;
    GLint iv = -7;
    fsglGetTexLevelParameterfv(c, GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &fv);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    fsglGetTexLevelParameterfv(c, GL_TEXTURE_2D, 20, GL_TEXTURE_WIDTH, &fv);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglGetTexLevelParameteriv(c, GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &iv);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    CHECK(fv == -7.0f);
    CHECK_EQ_INT(iv, -7);
    fs_context_destroy(c);
}

/* Float forms given an enum outside GLenum's range (NaN, infinite,
 * negative, huge): GL 1.5 2.5 makes it INVALID_ENUM and the call changes
 * nothing; converting such a float to an integer would be undefined in C
 * (UBSan in `make sanitize` catches a regression).  NaN colours and
 * priorities are clamped to a defined value, never stored as NaN. */
TEST(nonfinite_float_parameters)
{
    fs_context *c = fs_context_create(NULL, 4, 4);
    REQUIRE(c);
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    const float bad[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, -9728.0f};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, bad[i]);
        CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
        fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, bad[i]);
        CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
        fsglTexEnvf(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, bad[i]);
        CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    }
    GLint iv = 0;
    fsglGetTexParameteriv(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &iv);
    CHECK_EQ_INT(iv, GL_NEAREST_MIPMAP_LINEAR); /* the initial value, 3.8.11 */
    fsglGetTexParameteriv(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &iv);
    CHECK_EQ_INT(iv, GL_REPEAT);
    fsglGetTexEnviv(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &iv);
    CHECK_EQ_INT(iv, GL_MODULATE);
    fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (float)GL_LINEAR);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    const GLfloat nan4[4] = {NAN, NAN, 2.0f, -1.0f};
    fsglTexParameterfv(c, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, nan4);
    fsglTexEnvfv(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, nan4);
    fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, NAN);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    GLfloat fv[4];
    fsglGetTexParameterfv(c, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, fv);
    for (int k = 0; k < 4; k++)
        CHECK(fv[k] >= 0.0f && fv[k] <= 1.0f);
    fsglGetTexEnvfv(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, fv);
    for (int k = 0; k < 4; k++)
        CHECK(fv[k] >= 0.0f && fv[k] <= 1.0f);
    CHECK(fv[2] == 1.0f && fv[3] == 0.0f);
    fsglGetTexParameterfv(c, GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, fv);
    CHECK(fv[0] >= 0.0f && fv[0] <= 1.0f);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(filters_magnified),
    TEST_ENTRY(filters_minified),
    TEST_ENTRY(wrap_modes),
    TEST_ENTRY(non_power_of_two),
    TEST_ENTRY(env_modes_and_formats),
    TEST_ENTRY(sizes),
    TEST_ENTRY(incomplete_texture),
    TEST_ENTRY(errors),
    TEST_ENTRY(unpack_and_subimage),
    TEST_ENTRY(queries_vs_osmesa),
    TEST_ENTRY(luminance_uint_readback),
    TEST_ENTRY(odd_framebuffer_sizes),
    TEST_ENTRY(display_list_unpack_state),
    TEST_ENTRY(query_errors_change_nothing),
    TEST_ENTRY(nonfinite_float_parameters),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
