/*
 * Compressed textures (units/texture_compressed.c) against OSMesa
 * (llvmpipe), at tolerance 0: random blocks of each S3TC format (both
 * DXT1 colour modes, both DXT5 alpha modes, equal endpoints) sampled
 * NEAREST and LINEAR, magnified, minified and MIPmapped; sub-image
 * updates; glGetTexImage of the decoded level and the round trip of
 * glGetCompressedTexImage; the level queries; a display list carrying the
 * calls; and the GL errors of the seven commands.
 *
 * Known differences, each checked so that the check fails when it goes
 * away: OSMesa lists and accepts 12 formats (FXT1, S3TC, ETC2/EAC), the
 * model the four S3TC ones (GL_NUM_COMPRESSED_TEXTURE_FORMATS 3: 12 on
 * OSMesa; FXT1 and ETC2 INVALID_ENUM on the model, accepted by OSMesa).
 *
 * FS_CTEX_DUMP=1 writes both images and their difference to
 * /tmp/ctex_<name>.ppm.
 */
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../driver/osmesa_ref.h"
#include "../driver/replay.h"
#include "trace_build.h"
#include <unistd.h>
#include <GL/glext.h>

static const GLenum formats[4] = {GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
                                  GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT};
static const char *format_names[4] = {"rgb_dxt1", "rgba_dxt1", "dxt3", "dxt5"};

static int block_bytes(GLenum f) { return f == GL_COMPRESSED_RGB_S3TC_DXT1_EXT || f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT ? 8 : 16; }
static int image_bytes(GLenum f, int w, int h) { return ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(f); }

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* n random blocks of format f; every fourth colour block has its
 * endpoints ordered the other way than chance gave, every eighth equal
 * endpoints, so that both DXT1 modes and the tie occur; DXT5 alpha blocks
 * likewise. */
static void random_blocks(GLenum f, int n, uint32_t seed, uint8_t *out)
{
    int bb = block_bytes(f);
    for (int i = 0; i < n * bb; i++)
        out[i] = (uint8_t)rng(&seed);
    for (int b = 0; b < n; b++) {
        uint8_t *blk = out + b * bb;
        uint8_t *col = bb == 16 ? blk + 8 : blk;
        if (b % 8 == 7) {
            col[2] = col[0];
            col[3] = col[1];
        } else if (b % 4 == 3) {
            uint8_t t0 = col[0], t1 = col[1];
            col[0] = col[2], col[1] = col[3], col[2] = t0, col[3] = t1;
        }
        if (f == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
            if (b % 8 == 5)
                blk[1] = blk[0];
            else if (b % 3 == 1) {
                uint8_t t = blk[0];
                blk[0] = blk[1], blk[1] = t;
            }
        }
    }
}

/* ---- scenes ---- */

static GLenum cur_format;
static GLenum cur_min, cur_mag;
static int cur_size;          /* the texture is cur_size x cur_size */
static int cur_h;             /* its height when not 0 (non-power-of-two cases) */
static int cur_mipmaps;       /* define every level down to 1x1 */
static int cur_subimage;      /* replace parts of level 0 after the upload */
static int cur_list;          /* upload through a display list */
static float cur_scale, cur_tilt, cur_rot;

static void upload(fs_context *c)
{
    int size = cur_size;
    uint8_t *data = malloc((size_t)image_bytes(cur_format, size, size > cur_h ? size : cur_h));
    if (cur_h) {
        int n = image_bytes(cur_format, size, cur_h);
        random_blocks(cur_format, n / block_bytes(cur_format), 555u + (uint32_t)cur_format, data);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 0, cur_format, size, cur_h, 0, n, data);
        free(data);
        return;
    }
    for (int lvl = 0;; lvl++) {
        random_blocks(cur_format, image_bytes(cur_format, size, size) / block_bytes(cur_format),
                      1234u + 77u * (uint32_t)lvl + (uint32_t)cur_format, data);
        G(CompressedTexImage2D, GL_TEXTURE_2D, lvl, cur_format, size, size, 0, image_bytes(cur_format, size, size), data);
        if (!cur_mipmaps || size == 1)
            break;
        size /= 2;
    }
    if (cur_subimage) {
        /* One block in the middle, a 8x4 row of blocks at the left edge,
         * and (MIPmapped) the whole 2x2 level, whose width is not a
         * multiple of 4 but is the image's. */
        random_blocks(cur_format, 2, 999u, data);
        G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 8, 4, 4, cur_format, block_bytes(cur_format), data);
        G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 8, 4, cur_format, 2 * block_bytes(cur_format), data);
        if (cur_mipmaps && cur_size >= 2) {
            int lvl = 0;
            for (int s = cur_size; s > 2; s /= 2)
                lvl++;
            G(CompressedTexSubImage2D, GL_TEXTURE_2D, lvl, 0, 0, 2, 2, cur_format, block_bytes(cur_format), data);
        }
    }
    free(data);
}

static void scene(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.2f, 0.1f, 0.3f, 0.5f);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 40.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -4);
    G(Rotatef, -cur_tilt, 1, 0, 0);
    G(Rotatef, cur_rot, 0, 0, 1);
    G(BindTexture, GL_TEXTURE_2D, 3);
    if (cur_list) {
        G(NewList, 5, GL_COMPILE);
        upload(c);
        G0(EndList);
        G(CallList, 5);
    } else {
        upload(c);
    }
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)cur_min);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)cur_mag);
    if (cur_h) {
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(Enable, GL_TEXTURE_2D);
    float s = cur_scale, r = cur_h ? 1.7f : 1.0f, lo = cur_h ? -0.3f : 0.0f;
    G(Begin, GL_QUADS);
    G(TexCoord2f, lo, lo);
    G(Vertex3f, -s, -s, 0);
    G(TexCoord2f, r, lo);
    G(Vertex3f, s, -s, 0);
    G(TexCoord2f, r, r);
    G(Vertex3f, s, s, 0);
    G(TexCoord2f, lo, r);
    G(Vertex3f, -s, s, 0);
    G0(End);
    G(Disable, GL_TEXTURE_2D);
}

typedef struct scene_case {
    const char *name;
    GLenum min, mag;
    int size, mipmaps, subimage, list;
    float scale, tilt, rot;
    int h; /* a non-power-of-two size x h image, REPEAT and CLAMP_TO_EDGE */
} scene_case;

static void run_scenes(check_state *check_st_, const scene_case *cases, int n)
{
    for (int f = 0; f < 4; f++)
        for (int i = 0; i < n; i++) {
            const scene_case *sc = &cases[i];
            cur_format = formats[f];
            cur_min = sc->min, cur_mag = sc->mag;
            cur_size = sc->size, cur_mipmaps = sc->mipmaps, cur_subimage = sc->subimage, cur_list = sc->list;
            cur_h = sc->h;
            cur_scale = sc->scale, cur_tilt = sc->tilt, cur_rot = sc->rot;
            char name[64];
            snprintf(name, sizeof name, "%s_%s", format_names[f], sc->name);
            GLenum err = GL_NO_ERROR;
            CHECK_EQ_INT(osm_compare_scene(scene, 160, 120, name, "FS_CTEX_DUMP", "ctex", &err), 0);
            CHECK_EQ_INT(err, GL_NO_ERROR);
        }
}

/* name, min, mag, size, mipmaps, subimage, list, scale, tilt, rot */
TEST(nearest_vs_osmesa)
{
    static const scene_case cases[] = {
        {"mag_nearest", GL_NEAREST, GL_NEAREST, 32, 0, 0, 0, 1.5f, 0, 0},
        {"mag_nearest_rot", GL_NEAREST, GL_NEAREST, 16, 0, 0, 0, 1.5f, 20, 17},
        {"min_nearest", GL_NEAREST, GL_NEAREST, 256, 0, 0, 0, 1.0f, 0, 0},
        {"nmn_tilt", GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 64, 1, 0, 0, 1.5f, 70, 0},
    };
    run_scenes(check_st_, cases, (int)(sizeof cases / sizeof cases[0]));
}

TEST(linear_vs_osmesa)
{
    static const scene_case cases[] = {
        {"mag_linear", GL_LINEAR, GL_LINEAR, 16, 0, 0, 0, 1.5f, 0, 0},
        {"mag_linear_rot", GL_LINEAR, GL_LINEAR, 8, 0, 0, 0, 1.5f, 30, 17},
        {"min_linear", GL_LINEAR, GL_LINEAR, 128, 0, 0, 0, 1.0f, 0, 10},
        {"lml_tilt", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 64, 1, 0, 0, 1.5f, 70, 0},
        {"lmn_tilt", GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 32, 1, 0, 0, 1.5f, 60, 33},
    };
    run_scenes(check_st_, cases, (int)(sizeof cases / sizeof cases[0]));
}

TEST(subimage_vs_osmesa)
{
    static const scene_case cases[] = {
        {"sub_nearest", GL_NEAREST, GL_NEAREST, 16, 0, 1, 0, 1.5f, 0, 0},
        {"sub_lml", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16, 1, 1, 0, 1.5f, 70, 0},
    };
    run_scenes(check_st_, cases, (int)(sizeof cases / sizeof cases[0]));
}

/* ARB_texture_non_power_of_two: sizes that are no multiple of 4 have
 * partial blocks at the edges (EXT_texture_compression_s3tc). */
TEST(non_power_of_two_vs_osmesa)
{
    static const scene_case cases[] = {
        {"npot_nearest_12x20", GL_NEAREST, GL_NEAREST, 12, 0, 0, 0, 1.5f, 0, 0, 20},
        {"npot_nearest_6x10_rot", GL_NEAREST, GL_NEAREST, 6, 0, 0, 0, 1.5f, 20, 17, 10},
        {"npot_linear_13x7", GL_LINEAR, GL_LINEAR, 13, 0, 0, 0, 1.5f, 30, 11, 7},
    };
    run_scenes(check_st_, cases, (int)(sizeof cases / sizeof cases[0]));
}

/* Display lists carry the blocks (GL 1.5 spec 5.4: the image is copied
 * when the list is compiled). */
TEST(display_list_vs_osmesa)
{
    static const scene_case cases[] = {
        {"list_sub_nearest", GL_NEAREST, GL_NEAREST, 16, 1, 1, 1, 1.5f, 0, 0},
    };
    run_scenes(check_st_, cases, (int)(sizeof cases / sizeof cases[0]));
}

/* ---- values: decoded texels, round trips, queries, errors ---- */

static void put(double *v, int *n, double x) { v[(*n)++] = x; }

static GLenum err_of(fs_context *c) { return c ? fsglGetError(c) : glGetError(); }

/* glGetTexImage of a level of random blocks of every format: every
 * decoded texel, on both. */
static void decoded_texels(fs_context *c, double *v, int *n)
{
    enum { S = 64 };
    static uint8_t data[S * S], out[S * S * 4];
    for (int f = 0; f < 4; f++) {
        random_blocks(formats[f], image_bytes(formats[f], S, S) / block_bytes(formats[f]), 42u + (uint32_t)f, data);
        G(BindTexture, GL_TEXTURE_2D, 10 + f);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 0, formats[f], S, S, 0, image_bytes(formats[f], S, S), data);
        memset(out, 0, sizeof out);
        G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
        for (int i = 0; i < S * S * 4; i++)
            put(v, n, out[i]);
        put(v, n, err_of(c));
    }
}

TEST(decoded_texels_vs_osmesa)
{
    OSM_CHECK_VALUES(decoded_texels, 8, 8, 4 * (64 * 64 * 4 + 1));
}

/* glGetCompressedTexImage gives back the blocks as given, also after a
 * sub-image update and for a 1x1 level; the model checks them against
 * the data too (on both, so OSMesa's answer is the same). */
static void round_trip(fs_context *c, double *v, int *n)
{
    static uint8_t data[16 * 16], sub[64], out[16 * 16 + 64];
    for (int f = 0; f < 4; f++) {
        GLenum fmt = formats[f];
        int bytes = image_bytes(fmt, 16, 16), bb = block_bytes(fmt);
        random_blocks(fmt, bytes / bb, 7u + (uint32_t)f, data);
        random_blocks(fmt, 4, 99u + (uint32_t)f, sub);
        G(BindTexture, GL_TEXTURE_2D, 20 + f);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 0, fmt, 16, 16, 0, bytes, data);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 4, fmt, 1, 1, 0, bb, sub);
        /* blocks (1, 2) and (2, 2): a 8x4 box at (4, 8) */
        G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 8, 8, 4, fmt, 2 * bb, sub + bb);
        memcpy(data + (2 * 4 + 1) * bb, sub + bb, (size_t)(2 * bb));
        memset(out, 0xcd, sizeof out);
        G(GetCompressedTexImage, GL_TEXTURE_2D, 0, out);
        put(v, n, memcmp(out, data, (size_t)bytes) == 0);
        put(v, n, out[bytes]); /* nothing written past the image */
        memset(out, 0xcd, sizeof out);
        G(GetCompressedTexImage, GL_TEXTURE_2D, 4, out);
        put(v, n, memcmp(out, sub, (size_t)bb) == 0);
        put(v, n, out[bb]);
        put(v, n, err_of(c));
    }
}

TEST(get_compressed_round_trip_vs_osmesa)
{
    OSM_CHECK_VALUES(round_trip, 8, 8, 64);
}

/* The level queries (table 6.18) of each format, of an uncompressed
 * level and of a proxy, and glGet's format list on both. */
static void level_queries(fs_context *c, double *v, int *n)
{
    static const GLenum pnames[] = {GL_TEXTURE_COMPRESSED, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, GL_TEXTURE_INTERNAL_FORMAT,
                                    GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
                                    GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                                    GL_TEXTURE_INTENSITY_SIZE, GL_TEXTURE_BORDER};
    static uint8_t data[32 * 32];
    for (int f = 0; f < 4; f++) {
        GLenum fmt = formats[f];
        random_blocks(fmt, 64, 5u, data);
        G(BindTexture, GL_TEXTURE_2D, 30 + f);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 0, fmt, 8, 4, 0, image_bytes(fmt, 8, 4), data);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 1, fmt, 4, 2, 0, image_bytes(fmt, 4, 2), data);
        G(CompressedTexImage2D, GL_PROXY_TEXTURE_2D, 0, fmt, 16, 16, 0, image_bytes(fmt, 16, 16), NULL);
        for (int lvl = 0; lvl < 2; lvl++)
            for (size_t k = 0; k < sizeof pnames / sizeof pnames[0]; k++) {
                GLint x = -7;
                G(GetTexLevelParameteriv, GL_TEXTURE_2D, lvl, pnames[k], &x);
                put(v, n, x);
                GLint p = -7;
                G(GetTexLevelParameteriv, GL_PROXY_TEXTURE_2D, lvl, pnames[k], &p);
                put(v, n, p);
                put(v, n, err_of(c));
            }
    }
    /* an uncompressed level: not compressed, its size INVALID_OPERATION */
    G(BindTexture, GL_TEXTURE_2D, 40);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    GLint x = -7;
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &x);
    put(v, n, x);
    put(v, n, err_of(c));
    x = -7;
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &x);
    put(v, n, x);
    put(v, n, err_of(c));
    /* a compressed level replaced by glTexImage is no longer compressed */
    G(BindTexture, GL_TEXTURE_2D, 30);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    x = -7;
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &x);
    put(v, n, x);
    G(GetCompressedTexImage, GL_TEXTURE_2D, 0, data);
    put(v, n, err_of(c));
    /* a compressed level 1 rewritten by GL_GENERATE_MIPMAP from an
     * uncompressed base is no longer compressed */
    G(BindTexture, GL_TEXTURE_2D, 41);
    G(CompressedTexImage2D, GL_TEXTURE_2D, 1, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, 8, data);
    G(TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    x = -7;
    G(GetTexLevelParameteriv, GL_TEXTURE_2D, 1, GL_TEXTURE_COMPRESSED, &x);
    put(v, n, x);
    G(GetCompressedTexImage, GL_TEXTURE_2D, 1, data);
    put(v, n, err_of(c));
}

TEST(level_queries_vs_osmesa)
{
    OSM_CHECK_VALUES(level_queries, 8, 8, 4 * 2 * 12 * 3 + 16);
}

/* One faulty call after another, each error read on both. */
static void error_calls(fs_context *c, double *v, int *n)
{
    static uint8_t d[4096];
    const GLenum F1 = GL_COMPRESSED_RGB_S3TC_DXT1_EXT, F5 = GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
#define E_(call) do { call; put(v, n, err_of(c)); } while (0)
    G(BindTexture, GL_TEXTURE_2D, 50);
    /* glCompressedTexImage2D */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d));          /* fine */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 31, d));          /* imageSize */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 33, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F5, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, 32, d));     /* not compressed */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 8, 8, 0, 32, d)); /* generic */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, 0x1234, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_1D, 0, F1, 8, 8, 0, 32, d));          /* target */
    E_(G(CompressedTexImage2D, GL_TEXTURE_3D, 0, F1, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, 0x1234, 0, F1, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 1, 32, d));          /* border */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, -1, F1, 8, 8, 0, 32, d));         /* level */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 13, F1, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, -4, 8, 0, 32, d));         /* size */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 1, 1, 0, 8, d));           /* 1x1: one block */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 2, 4, 0, 8, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 0, 0, 0, 0, d));           /* empty */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 6, 10, 0, 48, d));         /* non-power-of-two */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 8, 2, 2, F1, 8, d));     /* the partial corner block */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 2, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 2, 2, F1, 8, d));     /* height 2 inside */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 6, 10, 0, 40, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 31, NULL));       /* imageSize, no data */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 1, 31, d));          /* border before imageSize */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, -1, F1, 8, 8, 0, 31, d));         /* imageSize before level */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, -1, 0x1234, 8, 8, 0, 32, d));     /* format before level */
    E_(G(CompressedTexImage2D, GL_PROXY_TEXTURE_2D, 0, F1, 8, 8, 0, 33, d));    /* proxy: imageSize */
    E_(G(CompressedTexImage2D, GL_PROXY_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d));
    /* glCompressedTexImage1D and 3D: S3TC is 2D only */
    E_(G(CompressedTexImage1D, GL_TEXTURE_1D, 0, F1, 4, 0, 8, d));
    E_(G(CompressedTexImage1D, GL_TEXTURE_2D, 0, F1, 4, 0, 8, d));
    E_(G(CompressedTexImage1D, GL_TEXTURE_1D, 0, 0x1234, 4, 0, 8, d));
    E_(G(CompressedTexImage1D, GL_TEXTURE_1D, -1, F1, 4, 0, 8, d));
    E_(G(CompressedTexImage3D, GL_TEXTURE_3D, 0, F1, 4, 4, 1, 0, 8, d));
    E_(G(CompressedTexImage3D, GL_TEXTURE_2D, 0, F1, 4, 4, 1, 0, 8, d));
    E_(G(CompressedTexImage3D, GL_TEXTURE_3D, 0, F5, 4, 4, 4, 0, 64, d));
    /* glCompressedTexSubImage2D on the 8x8 DXT1 level 0 */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 1, F1, 4, 4, 0, 8, d));
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 2, F1, 2, 2, 0, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 4, 4, F1, 8, d));     /* fine */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 8, 8, F1, 32, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 4, 4, F1, 16, d));    /* imageSize */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 4, 4, F5, 16, d));    /* not the level's */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 4, 4, GL_RGBA, 8, d)); /* not compressed */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 2, 4, 4, 4, F1, 8, d));     /* off the blocks */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 2, 4, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 2, 4, F1, 8, d));     /* width 2 inside */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 8, 4, F1, 16, d));    /* outside */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, -4, 0, 4, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 12, 4, F1, 24, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 2, 0, 0, 2, 2, F1, 8, d));     /* the 2x2 level, whole */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 2, 0, 0, 1, 1, F1, 8, d));     /* 1x1 inside it */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 3, 0, 0, 1, 1, F1, 8, d));     /* undefined level */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, -1, 0, 0, 4, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, 4, 0x1234, 8, d));
    E_(G(CompressedTexSubImage2D, GL_PROXY_TEXTURE_2D, 0, 0, 0, 4, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_1D, 0, 0, 0, 4, 4, F1, 8, d));
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, 4, F1, 8, NULL));  /* no data: nothing read */
    /* several faults: which error wins */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 3, 0, 0, 4, 4, 0x1234, 8, d)); /* format, undefined level */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, 4, F5, 7, d));     /* imageSize, format */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 2, 0, 4, 4, F1, 7, d));     /* imageSize, alignment */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 6, 0, 4, 4, F1, 8, d));     /* outside, alignment */
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, -4, F1, 8, d));    /* negative height */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, 0x1234, 8, 8, 1, 32, d));      /* format, border */
    E_(G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, -4, 8, 0, -8, d));
    /* glCompressedTexSubImage1D and 3D */
    E_(G(CompressedTexSubImage1D, GL_TEXTURE_1D, 0, 0, 4, F1, 8, d));
    E_(G(CompressedTexSubImage1D, GL_TEXTURE_2D, 0, 0, 4, F1, 8, d));
    E_(G(CompressedTexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 1, F1, 8, d));
    E_(G(CompressedTexSubImage3D, GL_TEXTURE_2D, 0, 0, 0, 0, 4, 4, 1, F1, 8, d));
    E_(G(CompressedTexSubImage1D, GL_TEXTURE_1D, -1, 0, 4, 0x1234, 8, d));
    E_(G(GetCompressedTexImage, GL_TEXTURE_3D, 0, d));                          /* undefined 3D level */
    G(BindTexture, GL_TEXTURE_3D, 52);
    G(TexImage3D, GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, d);
    E_(G(CompressedTexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 1, F1, 8, d));
    E_(G(CompressedTexSubImage3D, GL_TEXTURE_3D, -1, 0, 0, 0, 4, 4, 1, F1, 8, d));
    E_(G(GetCompressedTexImage, GL_TEXTURE_3D, 0, d));
    /* a subimage into an uncompressed level */
    G(BindTexture, GL_TEXTURE_2D, 51);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, d);
    E_(G(CompressedTexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, 4, F1, 8, d));
    /* glGetCompressedTexImage */
    E_(G(GetCompressedTexImage, GL_TEXTURE_2D, 0, d));                           /* uncompressed */
    G(BindTexture, GL_TEXTURE_2D, 50);
    E_(G(GetCompressedTexImage, GL_TEXTURE_2D, 0, d));                           /* fine */
    E_(G(GetCompressedTexImage, GL_TEXTURE_2D, -1, d));
    E_(G(GetCompressedTexImage, GL_TEXTURE_2D, 13, d));
    E_(G(GetCompressedTexImage, GL_PROXY_TEXTURE_2D, 0, d));
    E_(G(GetCompressedTexImage, 0x1234, 0, d));
    E_(G(GetCompressedTexImage, GL_TEXTURE_1D, 0, d));                           /* undefined level */
    /* inside glBegin/glEnd */
    G(Begin, GL_TRIANGLES);
    G(CompressedTexImage2D, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d);
    G0(End);
    put(v, n, err_of(c));
#undef E_
}

TEST(errors_vs_osmesa)
{
    OSM_CHECK_VALUES(error_calls, 8, 8, 160);
}

/* ---- a trace carries the calls ---- */

/* A trace written with fragsim's writer (the blobs as apitrace records
 * them) replayed on the model and on OSMesa through the reference
 * dispatcher, as `fragsim check` does: the same image, no GL error. */
TEST(trace_replay_vs_osmesa)
{
    char path[256], err[256];
    snprintf(path, sizeof path, "/tmp/fragsim_test_ctex_%d.trace", (int)getpid());
    fs_trace_writer *w = fs_trace_create(path, err, sizeof err);
    REQUIRE(w);
    static uint8_t data[16 * 16], sub[16];
    const GLenum fmt = GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    random_blocks(fmt, 16, 31u, data);
    random_blocks(fmt, 1, 32u, sub);
    fs_tval v4[4] = {tb_ival(0), tb_ival(0), tb_ival(32), tb_ival(32)};
    tb_write_call(w, "glViewport", 4, v4, 0);
    fs_tval bind[2] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_ival(4)};
    tb_write_call(w, "glBindTexture", 2, bind, 0);
    fs_tval img[8] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_ival(0), tb_eval(fmt, "GL_COMPRESSED_RGBA_S3TC_DXT5_EXT"),
                      tb_ival(16), tb_ival(16), tb_ival(0), tb_ival(256), tb_blob(data, 256)};
    tb_write_call(w, "glCompressedTexImage2D", 8, img, 0);
    fs_tval simg[9] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_ival(0), tb_ival(8), tb_ival(4), tb_ival(4),
                       tb_ival(4), tb_eval(fmt, "GL_COMPRESSED_RGBA_S3TC_DXT5_EXT"), tb_ival(16), tb_blob(sub, 16)};
    tb_write_call(w, "glCompressedTexSubImage2D", 9, simg, 0);
    fs_tval get[3] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_ival(0), tb_opaque(0x1000)};
    tb_write_call(w, "glGetCompressedTexImage", 3, get, 0);
    static const struct { GLenum p; int v; } params[] = {{GL_TEXTURE_MIN_FILTER, GL_NEAREST}, {GL_TEXTURE_MAG_FILTER, GL_NEAREST}};
    for (int i = 0; i < 2; i++) {
        fs_tval tp[3] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D"), tb_eval(params[i].p, "p"), tb_ival(params[i].v)};
        tb_write_call(w, "glTexParameteri", 3, tp, 0);
    }
    fs_tval env[3] = {tb_eval(GL_TEXTURE_ENV, "GL_TEXTURE_ENV"), tb_eval(GL_TEXTURE_ENV_MODE, "GL_TEXTURE_ENV_MODE"),
                      tb_eval(GL_REPLACE, "GL_REPLACE")};
    tb_write_call(w, "glTexEnvi", 3, env, 0);
    fs_tval en[1] = {tb_eval(GL_TEXTURE_2D, "GL_TEXTURE_2D")};
    tb_write_call(w, "glEnable", 1, en, 0);
    fs_tval mode[1] = {tb_eval(GL_QUADS, "GL_QUADS")};
    tb_write_call(w, "glBegin", 1, mode, 0);
    static const float q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; i++) {
        fs_tval tc[2] = {tb_fval(q[i][0]), tb_fval(q[i][1])};
        tb_write_call(w, "glTexCoord2f", 2, tc, 0);
        fs_tval vx[2] = {tb_fval(q[i][0] * 2 - 1), tb_fval(q[i][1] * 2 - 1)};
        tb_write_call(w, "glVertex2f", 2, vx, 0);
    }
    tb_write_call(w, "glEnd", 0, NULL, 0);
    tb_write_call(w, "glFinish", 0, NULL, 0);
    REQUIRE(fs_trace_finish(w) == 0);

    fs_replay_opts o = {NULL, 0, 0, 0};
    fs_replayer *r = fs_replay_open(path, &o, err, sizeof err);
    if (!r)
        printf("  %s\n", err);
    REQUIRE(r);
    int w_ = fs_replay_info_get(r)->width, h_ = fs_replay_info_get(r)->height;
    CHECK_EQ_INT(w_, 32);
    fs_osmesa *ref = fs_osmesa_create(w_, h_, 24, 8, err, sizeof err);
    fs_context *c = fs_context_create(NULL, w_, h_);
    REQUIRE(ref && c);
    fs_call call;
    fs_replay_event ev;
    int calls = 0, malformed = 0;
    while ((ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR) {
        if (ev != FS_REPLAY_CALL)
            continue;
        calls++;
        malformed += fs_submit(c, &call) != 0;
        fs_osmesa_dispatch(ref, &call);
    }
    CHECK(ev == FS_REPLAY_EOF);
    CHECK_EQ_INT(calls, 20);
    CHECK_EQ_INT(malformed, 0);
    CHECK_EQ_UINT(fs_replay_skipped_total(r), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(glGetError(), GL_NO_ERROR);
    glFinish();
    img_diff d = {0};
    img_compare(c->fb.color, fs_osmesa_color(ref), (long)w_ * h_, &d);
    printf("  trace: %ld of %ld pixels differ, %ld lit\n", d.differ, d.pixels, img_lit_pixels(c->fb.color, (long)w_ * h_));
    CHECK_EQ_INT(d.differ, 0);
    CHECK(img_lit_pixels(c->fb.color, (long)w_ * h_) > (long)w_ * h_ / 2);
    /* the model holds the blocks the trace gave, the sub-image included */
    uint8_t got[256];
    memcpy(data + (1 * 4 + 2) * 16, sub, 16);
    fsglGetCompressedTexImage(c, GL_TEXTURE_2D, 0, got);
    CHECK(memcmp(got, data, 256) == 0);
    fs_context_destroy(c);
    fs_osmesa_destroy(ref);
    fs_replay_close(r);
    unlink(path);
}

/* What the model does not do is counted as unsupported, not done
 * silently: GL_GENERATE_MIPMAP of a compressed level; the usual calls,
 * and glTexSubImage2D and glCopyTexSubImage2D into an S3TC level (which
 * the model re-encodes with Mesa's S3TC encoder, as llvmpipe does,
 * units/texture_encode.c), count nothing. */
TEST(not_modelled_is_counted)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    static uint8_t d[16 * 16 * 4];
    const GLenum F1 = GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    fsglCompressedTexImage2D(c, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d);
    fsglCompressedTexSubImage2D(c, GL_TEXTURE_2D, 0, 0, 0, 4, 4, F1, 8, d);
    uint8_t got[32];
    fsglGetCompressedTexImage(c, GL_TEXTURE_2D, 0, got);
    CHECK_EQ_UINT(c->stats.unsupported_calls, 0);
    fsglTexSubImage2D(c, GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, d);
    CHECK_EQ_UINT(c->stats.unsupported_calls, 0);
    fsglCopyTexSubImage2D(c, GL_TEXTURE_2D, 0, 0, 0, 0, 0, 4, 4);
    CHECK_EQ_UINT(c->stats.unsupported_calls, 0);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    fsglCompressedTexImage2D(c, GL_TEXTURE_2D, 0, F1, 8, 8, 0, 32, d);
    CHECK_EQ_UINT(c->stats.unsupported_calls, 1);
    GLint w = -1;
    fsglGetTexLevelParameteriv(c, GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &w);
    CHECK_EQ_INT(w, 0); /* no level generated */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

/* ---- known differences ---- */

/* What OSMesa lists and accepts beyond the model's S3TC formats: FXT1 and
 * ETC2/EAC are accepted by OSMesa and refused by the model (INVALID_ENUM:
 * no decoder, units/texture_compressed.c).  Fails when either side
 * changes. */
static void other_formats(fs_context *c, double *v, int *n)
{
    GLint num = -1, list[32];
    G(GetIntegerv, GL_NUM_COMPRESSED_TEXTURE_FORMATS, &num);
    put(v, n, num);
    memset(list, 0, sizeof list);
    G(GetIntegerv, GL_COMPRESSED_TEXTURE_FORMATS, list);
    for (int i = 0; i < 3; i++)
        put(v, n, list[i]);
    static uint8_t d[64];
    /* GL_COMPRESSED_RGB_FXT1_3DFX (8x4 blocks of 16 bytes), GL_COMPRESSED_RGB8_ETC2 */
    G(CompressedTexImage2D, GL_TEXTURE_2D, 0, 0x86B0, 8, 4, 0, 16, d);
    put(v, n, err_of(c));
    G(CompressedTexImage2D, GL_TEXTURE_2D, 0, 0x9274, 4, 4, 0, 8, d);
    put(v, n, err_of(c));
}

TEST(known_differences)
{
    double ref[16], mine[16];
    int nr, nm;
    REQUIRE(osm_run_values(other_formats, 8, 8, ref, &nr, mine, &nm));
    REQUIRE(nr == 6 && nm == 6);
    /* OSMesa: 12 formats, the first S3TC one after FXT1's two */
    CHECK_EQ_INT((int)ref[0], 12);
    CHECK_EQ_INT((int)mine[0], 3);
    CHECK_EQ_INT((int)mine[1], GL_COMPRESSED_RGB_S3TC_DXT1_EXT);
    CHECK_EQ_INT((int)mine[2], GL_COMPRESSED_RGBA_S3TC_DXT3_EXT);
    CHECK_EQ_INT((int)mine[3], GL_COMPRESSED_RGBA_S3TC_DXT5_EXT);
    CHECK_EQ_INT((int)ref[4], GL_NO_ERROR);
    CHECK_EQ_INT((int)ref[5], GL_NO_ERROR);
    CHECK_EQ_INT((int)mine[4], GL_INVALID_ENUM);
    CHECK_EQ_INT((int)mine[5], GL_INVALID_ENUM);
}

TEST_LIST = {
    TEST_ENTRY(nearest_vs_osmesa),
    TEST_ENTRY(linear_vs_osmesa),
    TEST_ENTRY(subimage_vs_osmesa),
    TEST_ENTRY(non_power_of_two_vs_osmesa),
    TEST_ENTRY(display_list_vs_osmesa),
    TEST_ENTRY(decoded_texels_vs_osmesa),
    TEST_ENTRY(get_compressed_round_trip_vs_osmesa),
    TEST_ENTRY(level_queries_vs_osmesa),
    TEST_ENTRY(errors_vs_osmesa),
    TEST_ENTRY(trace_replay_vs_osmesa),
    TEST_ENTRY(not_modelled_is_counted),
    TEST_ENTRY(known_differences),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
