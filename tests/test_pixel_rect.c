/*
 * Pixel rectangles against OSMesa (llvmpipe), at tolerance 0: the current
 * raster position of glRasterPos and glWindowPos (GL 1.5 spec 2.13, every
 * value of table 6.5's raster state, bit for bit), and the images of
 * glBitmap (3.7) and glDrawPixels (3.6).
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"

static unsigned rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (*s >> 8) & 0xffffu;
}
static int pick(unsigned *s, int n) { return (int)(rnd(s) % (unsigned)n); }
static float rndf(unsigned *s, float lo, float hi) { return lo + (hi - lo) * (float)rnd(s) / 65535.0f; }

static const GLenum k_raster_names[] = {GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_POSITION_VALID,
                                        GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_TEXTURE_COORDS,
                                        GL_CURRENT_RASTER_DISTANCE, GL_CURRENT_RASTER_INDEX};
#define RASTER_VALUES 15 /* 4 + 1 + 4 + 4 + 1 + 1 */

static int get_raster_state(fs_context *c, float *out)
{
    static const int counts[] = {4, 1, 4, 4, 1, 1};
    int n = 0;
    for (int i = 0; i < 6; i++) {
        float v[4] = {0};
        G(GetFloatv, k_raster_names[i], v);
        memcpy(out + n, v, sizeof(float) * (size_t)counts[i]);
        n += counts[i];
    }
    return n;
}

/* One random raster position command, of the 40. */
static void random_raster_pos(fs_context *c, unsigned *s, float lo, float hi)
{
    float v[4] = {rndf(s, lo, hi), rndf(s, lo, hi), rndf(s, -1.5f, 1.5f), rndf(s, 0.25f, 3)};
    if (pick(s, 12) == 0)
        v[pick(s, 4)] = pick(s, 2) ? NAN : 0.0f;
    double d[4] = {v[0], v[1], v[2], v[3]};
    GLint iv[4] = {(GLint)v[0], (GLint)v[1], (GLint)v[2], (GLint)v[3] + 1};
    GLshort sv[4] = {(GLshort)iv[0], (GLshort)iv[1], (GLshort)iv[2], (GLshort)iv[3]};
    switch (pick(s, 20)) {
    case 0: G(RasterPos2f, v[0], v[1]); break;
    case 1: G(RasterPos3f, v[0], v[1], v[2]); break;
    case 2: G(RasterPos4f, v[0], v[1], v[2], v[3]); break;
    case 3: G(RasterPos2d, d[0], d[1]); break;
    case 4: G(RasterPos3dv, d); break;
    case 5: G(RasterPos4dv, d); break;
    case 6: G(RasterPos2i, iv[0], iv[1]); break;
    case 7: G(RasterPos3iv, iv); break;
    case 8: G(RasterPos4s, sv[0], sv[1], sv[2], sv[3]); break;
    case 9: G(RasterPos2sv, sv); break;
    case 10: G(RasterPos4fv, v); break;
    case 11: G(WindowPos2f, v[0], v[1]); break;
    case 12: G(WindowPos3f, v[0], v[1], v[2]); break;
    case 13: G(WindowPos3dv, d); break;
    case 14: G(WindowPos2iv, iv); break;
    case 15: G(WindowPos3s, sv[0], sv[1], sv[2]); break;
    case 16: G(WindowPos2dv, d); break;
    case 17: G(WindowPos3fv, v); break;
    case 18: G(RasterPos3s, sv[0], sv[1], sv[2]); break;
    default: G(RasterPos4i, iv[0], iv[1], iv[2], iv[3]); break;
    }
}

/* Random transformation, lighting, current attributes and depth range. */
static void random_vertex_setup(fs_context *c, unsigned *s, int w, int h)
{
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    if (pick(s, 2))
        G(Ortho, 0, w, 0, h, -1, 1);
    else
        G(Frustum, -1, 1, -1, 1, 1, 10);
    G(MatrixMode, GL_TEXTURE);
    G0(LoadIdentity);
    if (pick(s, 2))
        G(Scalef, rndf(s, -2, 2), rndf(s, -2, 2), rndf(s, -2, 2));
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, rndf(s, -2, 2), rndf(s, -2, 2), rndf(s, -4, 0));
    G(Rotatef, rndf(s, 0, 90), rndf(s, -1, 1), rndf(s, -1, 1), 1);
    G(Color4f, rndf(s, -0.2f, 1.2f), rndf(s, 0, 1), rndf(s, 0, 1), rndf(s, 0, 1));
    G(TexCoord4f, rndf(s, -2, 2), rndf(s, -2, 2), rndf(s, -2, 2), rndf(s, 0.5f, 2));
    G(Normal3f, rndf(s, -1, 1), rndf(s, -1, 1), 1);
    if (pick(s, 3) == 0) {
        G(Enable, GL_LIGHTING);
        G(Enable, GL_LIGHT0);
    } else {
        G(Disable, GL_LIGHTING);
    }
    G(DepthRange, rndf(s, 0, 0.5f), rndf(s, 0.5f, 1));
}

/* Runs fn on a new OSMesa context (c NULL: the gl* calls go there), then on
 * a new model context, with the same seed: the values into want and got.
 * 0, or 1 without an OSMesa context, 2 without a model one. */
typedef void (*both_fn)(fs_context *c, unsigned seed, float *out);
static int on_both(both_fn fn, unsigned seed, int w, int h, float *want, float *got)
{
    for (int pass = 0; pass < 2; pass++) {
        osm o;
        fs_context *c = NULL;
        if (!osm_open(&o, w, h)) {
            osm_close(&o);
            return 1;
        }
        if (pass && !(c = fs_context_create(NULL, w, h))) {
            osm_close(&o);
            return 2;
        }
        fn(c, seed, pass ? got : want);
        if (c)
            fs_context_destroy(c);
        osm_close(&o);
    }
    return 0;
}

enum { RP_W = 64, RP_H = 48, RP_STEPS = 30 };

/* The initial raster state, then RP_STEPS random raster positions (with a
 * random vertex set-up now and then), each read back. */
static void raster_position_steps(fs_context *c, unsigned seed, float *outp)
{
    float (*out)[RASTER_VALUES] = (float (*)[RASTER_VALUES])outp;
    unsigned s = seed;
    get_raster_state(c, out[0]); /* the initial values */
    for (int i = 1; i <= RP_STEPS; i++) {
        if (pick(&s, 4) == 0)
            random_vertex_setup(c, &s, RP_W, RP_H);
        random_raster_pos(c, &s, pick(&s, 2) ? -80.0f : -1.5f, pick(&s, 2) ? 80.0f : 1.5f);
        get_raster_state(c, out[i]);
    }
}

TEST(raster_position_vs_osmesa)
{
    enum { SEEDS = 20, STEPS = RP_STEPS };
    long compared = 0, differ = 0, colour_ulps = 0;
    for (unsigned seed = 1; seed <= SEEDS; seed++) {
        float want[STEPS + 1][RASTER_VALUES], got[STEPS + 1][RASTER_VALUES];
        int rc = on_both(raster_position_steps, seed, RP_W, RP_H, &want[0][0], &got[0][0]);
        if (rc == 1)
            SKIP("no OSMesa context");
        REQUIRE(rc == 0);
        for (int i = 0; i <= STEPS; i++)
            for (int k = 0; k < RASTER_VALUES; k++) {
                compared++;
                if (memcmp(&want[i][k], &got[i][k], sizeof(float)) == 0)
                    continue;
                /* A lit colour (values 5-8) may differ in its last bits:
                 * the state tracker lights the raster position with the
                 * draw module's own vertex program, not llvmpipe's. */
                if (k >= 5 && k <= 8 && fabsf(want[i][k] - got[i][k]) <= 2.5e-7f) {
                    colour_ulps++;
                    continue;
                }
                if (differ++ < 10)
                    fprintf(stderr, "  seed %u step %d value %d: osmesa %.9g fragsim %.9g\n", seed, i, k,
                            want[i][k], got[i][k]);
            }
    }
    printf("  %ld raster position values compared, %ld differ, %ld lit colour values by 1-2 ulps\n", compared,
           differ, colour_ulps);
    CHECK_EQ_INT(differ, 0);
}

/* GL 1.3 keeps raster texture coordinates per texture unit (2.13, table
 * 6.5 "n x"); GL_CURRENT_RASTER_TEXTURE_COORDS answers for the active
 * unit.  Random current coordinates, texture matrices and enables per
 * unit (with and without a complete texture bound), texture generation
 * on some, then every unit's
 * value after glRasterPos or glWindowPos, bit for bit. */
enum { RT_W = 32, RT_H = 32, RT_UNITS = 8 };

/* Random coordinates, texture matrices, enables and generation per unit,
 * a glRasterPos or glWindowPos, then every unit's raster coordinates. */
static void raster_texcoords_case(fs_context *c, unsigned seed, float *out)
{
    enum { W = RT_W, H = RT_H, UNITS = RT_UNITS };
    static const uint8_t texel[4] = {10, 20, 30, 255};
    unsigned s = seed;
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, rndf(&s, -0.5f, 0.5f), rndf(&s, -0.5f, 0.5f), 0);
    for (int u = 0; u < UNITS; u++) {
        G(ActiveTexture, GL_TEXTURE0 + u);
        G(MultiTexCoord4f, GL_TEXTURE0 + u, rndf(&s, -2, 2), rndf(&s, -2, 2), rndf(&s, -2, 2),
          rndf(&s, 0.5f, 2));
        G(MatrixMode, GL_TEXTURE);
        G0(LoadIdentity);
        if (pick(&s, 2)) {
            G(Translatef, rndf(&s, -1, 1), rndf(&s, -1, 1), rndf(&s, -1, 1));
            G(Scalef, rndf(&s, -2, 2), rndf(&s, -2, 2), rndf(&s, -2, 2));
        }
        int en = pick(&s, 3); /* 0 off, 1 on without a texture, 2 on with a complete one */
        if (en == 2) {
            G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        }
        if (en)
            G(Enable, GL_TEXTURE_2D);
        if (pick(&s, 4) == 0) { /* generated s or t, object or eye linear */
            GLenum coord = pick(&s, 2) ? GL_S : GL_T;
            G(TexGeni, coord, GL_TEXTURE_GEN_MODE, pick(&s, 2) ? GL_OBJECT_LINEAR : GL_EYE_LINEAR);
            G(Enable, coord == GL_S ? GL_TEXTURE_GEN_S : GL_TEXTURE_GEN_T);
        }
    }
    G(MatrixMode, GL_MODELVIEW);
    G(ActiveTexture, GL_TEXTURE0 + pick(&s, UNITS));
    if (pick(&s, 4) == 0)
        G(WindowPos2f, rndf(&s, 0, W), rndf(&s, 0, H));
    else
        G(RasterPos3f, rndf(&s, -0.9f, 0.9f), rndf(&s, -0.9f, 0.9f), rndf(&s, -0.9f, 0.9f));
    for (int u = 0; u < UNITS; u++) {
        G(ActiveTexture, GL_TEXTURE0 + u);
        G(GetFloatv, GL_CURRENT_RASTER_TEXTURE_COORDS, out + 4 * u);
    }
}

TEST(raster_texcoords_per_unit_vs_osmesa)
{
    enum { SEEDS = 40, UNITS = RT_UNITS };
    long compared = 0, differ = 0;
    for (unsigned seed = 1; seed <= SEEDS; seed++) {
        float out[2][UNITS][4];
        int rc = on_both(raster_texcoords_case, seed, RT_W, RT_H, &out[0][0][0], &out[1][0][0]);
        if (rc == 1)
            SKIP("no OSMesa context");
        REQUIRE(rc == 0);
        for (int u = 0; u < UNITS; u++)
            for (int k = 0; k < 4; k++) {
                compared++;
                if (memcmp(&out[0][u][k], &out[1][u][k], sizeof(float)) != 0 && differ++ < 10)
                    fprintf(stderr, "  seed %u unit %d value %d: osmesa %.9g fragsim %.9g\n", seed, u, k,
                            out[0][u][k], out[1][u][k]);
            }
    }
    printf("  %ld raster texture coordinates compared, %ld differ\n", compared, differ);
    CHECK_EQ_INT(differ, 0);
}

/* ---- images: glBitmap and glDrawPixels ---- */

/* Colour and depth of both, compared; depth read back as 32-bit unsigned
 * (the 24-bit values scaled exactly). */
typedef struct rect_case { unsigned seed; bool dlist; int kind; } rect_case;

static void read_depth(fs_context *c, int w, int h, GLuint *out)
{
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    G(ReadPixels, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out);
}

static void random_fragment_ops(fs_context *c, unsigned *s)
{
    G(ClearColor, 0.1f, 0.2f, 0.3f, 0.4f);
    G(ClearDepth, 0.5);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (pick(s, 2)) {
        G(Enable, GL_DEPTH_TEST);
        G(DepthFunc, pick(s, 2) ? GL_LESS : GL_GREATER);
    } else {
        G(Disable, GL_DEPTH_TEST);
    }
    if (pick(s, 3) == 0) {
        G(Enable, GL_BLEND);
        G(BlendFunc, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else {
        G(Disable, GL_BLEND);
    }
    G(Color4f, rndf(s, 0, 1), rndf(s, 0, 1), rndf(s, 0, 1), rndf(s, 0, 1));
}

static void random_unpack(fs_context *c, unsigned *s)
{
    static const int align[] = {1, 2, 4, 8};
    G(PixelStorei, GL_UNPACK_ALIGNMENT, align[pick(s, 4)]);
    G(PixelStorei, GL_UNPACK_LSB_FIRST, pick(s, 2));
    G(PixelStorei, GL_UNPACK_SKIP_PIXELS, pick(s, 3));
    G(PixelStorei, GL_UNPACK_SKIP_ROWS, pick(s, 3));
    G(PixelStorei, GL_UNPACK_ROW_LENGTH, pick(s, 2) ? 0 : 48);
}

static void draw_bitmaps(fs_context *c, const void *user, int w, int h)
{
    const rect_case *rc = user;
    unsigned s = rc->seed;
    static uint8_t bits[48 * 48];
    for (size_t i = 0; i < sizeof bits; i++)
        bits[i] = (uint8_t)rnd(&s);
    random_fragment_ops(c, &s);
    random_unpack(c, &s);
    if (rc->dlist)
        G(NewList, 1, GL_COMPILE);
    for (int k = 0; k < 12; k++) {
        if (pick(&s, 2))
            G(WindowPos3f, rndf(&s, -8, (float)w), rndf(&s, -8, (float)h), rndf(&s, 0, 1));
        G(Color4f, rndf(&s, 0, 1), rndf(&s, 0, 1), rndf(&s, 0, 1), rndf(&s, 0, 1));
        if (pick(&s, 3) == 0)
            G(RasterPos2f, rndf(&s, -1.2f, 1.2f), rndf(&s, -1.2f, 1.2f)); /* the colour above, invalid outside */
        G(Bitmap, pick(&s, 20), pick(&s, 20), rndf(&s, -4, 4), rndf(&s, -4, 4), rndf(&s, -9, 9),
          rndf(&s, -9, 9), bits);
    }
    if (rc->dlist) {
        G0(EndList);
        G(PixelStorei, GL_UNPACK_ALIGNMENT, 4); /* the list keeps the image as compiled */
        G(CallList, 1);
    }
    G0(Finish);
}

/* Formats and types of 3.6 (tables 3.5, 3.6, 3.8), and zooms whose pixel
 * centres never fall between two image columns except at +-1. */
static const GLenum k_formats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA,
                                   GL_LUMINANCE, GL_LUMINANCE_ALPHA};
/* GL_INT is left out: llvmpipe's glDrawPixels converts it through a float
 * texture, fragsim as glTexImage2D does (a known difference, counted by
 * drawpixels_every_format_type_vs_osmesa). */
static const GLenum k_types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_FLOAT};
static const GLenum k_packed[][2] = {
    {GL_RGB, GL_UNSIGNED_BYTE_3_3_2}, {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV}, {GL_RGB, GL_UNSIGNED_SHORT_5_6_5},
    {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV}, {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4}, {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV},
    {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1}, {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV}, {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8},
    {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV}, {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2}, {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV},
};
static const float k_zooms[] = {1, 1, -1, 2, -2, 3};

static void draw_images(fs_context *c, const void *user, int w, int h)
{
    const rect_case *rc = user;
    unsigned s = rc->seed;
    static float img[40 * 40 * 4];
    static uint8_t raw[40 * 40 * 16];
    for (size_t i = 0; i < sizeof raw; i++)
        raw[i] = (uint8_t)rnd(&s);
    for (size_t i = 0; i < sizeof img / sizeof img[0]; i++)
        img[i] = rndf(&s, -0.25f, 1.25f);
    random_fragment_ops(c, &s);
    random_unpack(c, &s);
    if (rc->dlist)
        G(NewList, 1, GL_COMPILE);
    for (int k = 0; k < 8; k++) {
        float zx = k_zooms[pick(&s, 6)], zy = k_zooms[pick(&s, 6)];
        G(PixelZoom, zx, zy);
        bool whole = (zx == 1 || zx == -1) && (zy == 1 || zy == -1);
        float x = whole ? rndf(&s, -8, (float)w) : (float)(pick(&s, w + 8) - 8);
        float y = whole ? rndf(&s, -8, (float)h) : (float)(pick(&s, h + 8) - 8);
        G(WindowPos3f, x, y, rndf(&s, 0, 1));
        int iw = pick(&s, 20), ih = pick(&s, 20);
        if (rc->kind == 1) {
            G(DrawPixels, iw, ih, GL_DEPTH_COMPONENT, pick(&s, 2) ? GL_FLOAT : GL_UNSIGNED_SHORT,
              pick(&s, 2) ? (const void *)img : raw);
        } else if (pick(&s, 3) == 0) {
            int p = pick(&s, 12);
            G(DrawPixels, iw, ih, k_packed[p][0], k_packed[p][1], raw);
        } else {
            GLenum t = k_types[pick(&s, 6)];
            G(DrawPixels, iw, ih, k_formats[pick(&s, 10)], t, t == GL_FLOAT ? (const void *)img : raw);
        }
    }
    if (rc->dlist) {
        G0(EndList);
        G(CallList, 1);
    }
    G0(Finish);
}

static void check_rect_case(check_state *check_st_, void (*draw)(fs_context *, const void *, int, int),
                            const char *what, int kind)
{
    enum { W = 61, H = 47 };
    long pixels = 0, differ = 0, zdiffer = 0, zoff = 0;
    static GLuint zref[W * H], zmine[W * H];
    for (unsigned seed = 1; seed <= 24; seed++) {
        rect_case rc = {seed * 7919u, seed % 3 == 0, kind};
        osm_pair p;
        if (!osm_pair_render(&p, W, H, NULL, draw, &rc))
            SKIP("no OSMesa context");
        read_depth(p.c, W, H, zmine);
        fs_context *c = NULL;
        read_depth(c, W, H, zref);
        long dz = 0;
        for (int i = 0; i < W * H; i++) {
            /* glDrawPixels' depths may be one unit off (see below) */
            bool near = kind == 1 && (zref[i] >> 8) + 1 >= (zmine[i] >> 8) && (zmine[i] >> 8) + 1 >= (zref[i] >> 8);
            dz += zref[i] != zmine[i] && !near;
            zoff += zref[i] != zmine[i] && near;
        }
        if ((p.d.differ || dz) && differ + zdiffer < 1) {
            fprintf(stderr, "  %s seed %u: %ld pixels, %ld depths differ\n", what, seed, p.d.differ, dz);
            for (int i = 0; i < W * H; i++)
                if (memcmp(p.c->fb.color + i * 4, p.ref.color + i * 4, 4) || zref[i] != zmine[i]) {
                    const uint8_t *a = p.ref.color + i * 4, *b = p.c->fb.color + i * 4;
                    fprintf(stderr, "    first at (%d, %d): osmesa %d %d %d %d z %u, fragsim %d %d %d %d z %u\n",
                            i % W, i / W, a[0], a[1], a[2], a[3], zref[i], b[0], b[1], b[2], b[3], zmine[i]);
                    break;
                }
        }
        pixels += p.d.pixels;
        differ += p.d.differ;
        zdiffer += dz;
        osm_pair_close(&p);
    }
    printf("  %s: %ld of %ld pixels and %ld depths differ from OSMesa\n", what, differ, pixels, zdiffer);
    /* A known difference: a depth of glDrawPixels(GL_DEPTH_COMPONENT) one
     * unit off now and then (1 in 68,808 measured), from the depth
     * texture llvmpipe draws it through. */
    if (kind == 1)
        printf("  %ld depths one unit off\n", zoff);
    CHECK(zoff * 10000 <= pixels);
    CHECK_EQ_INT(differ, 0);
    CHECK_EQ_INT(zdiffer, 0);
}

TEST(bitmap_vs_osmesa) { check_rect_case(check_st_, draw_bitmaps, "glBitmap", 0); }
TEST(drawpixels_color_vs_osmesa) { check_rect_case(check_st_, draw_images, "glDrawPixels colour", 0); }
TEST(drawpixels_depth_vs_osmesa) { check_rect_case(check_st_, draw_images, "glDrawPixels depth", 1); }

/* Every format and type pair of tables 3.5-3.8 at zoom 1: one image of
 * random bytes (random floats for GL_FLOAT) per pair, each on its own. */
typedef struct pair_case { GLenum format, type; } pair_case;

static void draw_one_pair(fs_context *c, const void *user, int w, int h)
{
    const pair_case *pc = user;
    (void)w;
    (void)h;
    static uint8_t raw[64 * 8 * 16];
    static float img[64 * 8 * 4];
    unsigned s = pc->format * 31u + pc->type;
    for (size_t i = 0; i < sizeof raw; i++)
        raw[i] = (uint8_t)rnd(&s);
    for (size_t i = 0; i < sizeof img / sizeof img[0]; i++)
        img[i] = rndf(&s, -0.25f, 1.25f);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(WindowPos2i, 0, 0);
    G(DrawPixels, 64, 8, pc->format, pc->type, pc->type == GL_FLOAT ? (const void *)img : raw);
    G0(Finish);
}

TEST(drawpixels_every_format_type_vs_osmesa)
{
    pair_case cases[sizeof k_formats / sizeof k_formats[0] * (sizeof k_types / sizeof k_types[0] + 1) + 12];
    int n = 0;
    for (size_t f = 0; f < sizeof k_formats / sizeof k_formats[0]; f++)
        for (size_t t = 0; t < sizeof k_types / sizeof k_types[0]; t++)
            cases[n++] = (pair_case){k_formats[f], k_types[t]};
    for (int p = 0; p < 12; p++)
        cases[n++] = (pair_case){k_packed[p][0], k_packed[p][1]};
    int known = n;
    for (size_t f = 0; f < sizeof k_formats / sizeof k_formats[0]; f++)
        cases[n++] = (pair_case){k_formats[f], GL_INT};
    long differ = 0, int_differ = 0;
    for (int i = 0; i < n; i++) {
        osm_pair p;
        if (!osm_pair_render(&p, 64, 8, NULL, draw_one_pair, &cases[i]))
            SKIP("no OSMesa context");
        if (i >= known) {
            int_differ += p.d.differ;
            CHECK(p.d.maxd <= 1);
        } else {
            if (p.d.differ)
                fprintf(stderr, "  format 0x%x type 0x%x: %ld of %ld pixels differ (max %d)\n", cases[i].format,
                        cases[i].type, p.d.differ, p.d.pixels, p.d.maxd);
            differ += p.d.differ;
        }
        osm_pair_close(&p);
    }
    printf("  %d format/type pairs, %ld pixels differ from OSMesa; GL_INT (known, by 1): %ld of %d\n", known, differ,
           int_differ, (n - known) * 512);
    CHECK_EQ_INT(differ, 0);
}

TEST_LIST = {
    TEST_ENTRY(raster_position_vs_osmesa),
    TEST_ENTRY(raster_texcoords_per_unit_vs_osmesa),
    TEST_ENTRY(bitmap_vs_osmesa),
    TEST_ENTRY(drawpixels_every_format_type_vs_osmesa),
    TEST_ENTRY(drawpixels_color_vs_osmesa),
    TEST_ENTRY(drawpixels_depth_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
