/*
 * Pixel transfer (pipeline/pixel_map.c; GL 1.5 spec 3.6.3, 3.6.5) against
 * OSMesa (llvmpipe) at tolerance 0: glPixelTransfer state and glPixelMap*
 * tables through every glGet form, with their errors; the operations on
 * glTexImage2D / glTexSubImage2D uploads (scale, bias, MAP_COLOR, colour
 * index images through the I_TO_* maps with shift and offset), drawn and
 * compared; glDrawPixels of colour index images; glPushAttrib(GL_PIXEL_MODE_BIT) and display lists.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/pixel_map.h"
#include "../pipeline/pixel_transfer.h"

#define TW 32
#define TH 32

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* A float in [lo, hi), sometimes exactly a step of 1/255 or a half step. */
static float rnd(uint32_t *s, float lo, float hi)
{
    uint32_t r = rng(s);
    if ((r & 7) == 0)
        return (float)(r >> 8 & 255) / 255.0f;
    if ((r & 7) == 1)
        return ((float)(r >> 8 & 255) + 0.5f) / 255.0f;
    return lo + (hi - lo) * (float)(r >> 8) / 16777216.0f;
}

static GLenum get_error(fs_context *c) { return c ? fsglGetError(c) : glGetError(); }

typedef struct both { osm o; fs_context *c; } both;

static bool both_open(both *b)
{
    memset(b, 0, sizeof *b);
    if (!osm_open(&b->o, TW, TH)) {
        osm_close(&b->o);
        return false;
    }
    b->c = fs_context_create(NULL, TW, TH);
    return b->c != NULL;
}

static void both_close(both *b)
{
    fs_context_destroy(b->c);
    osm_close(&b->o);
}

static long fb_differ(const both *b, int *first)
{
    long d = 0;
    *first = -1;
    for (int i = 0; i < TW * TH * 4; i++)
        if (b->c->fb.color[i] != b->o.color[i] && d++ == 0)
            *first = i;
    return d;
}

/* ---- state ---- */

static const GLenum xfer_names[] = {GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE,
                                    GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE, GL_DEPTH_SCALE, GL_RED_BIAS,
                                    GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS, GL_DEPTH_BIAS};
#define N_XFER ((int)(sizeof xfer_names / sizeof xfer_names[0]))

/* Every map, its size and its entries in the three forms, and the
 * transfer state as floats and integers: the number of values that
 * differ between OSMesa and the model. */
static int compare_state(fs_context *m)
{
    int bad = 0;
    for (GLenum map = GL_PIXEL_MAP_I_TO_I; map <= GL_PIXEL_MAP_A_TO_A; map++) {
        GLint size[2];
        GLfloat f[2][FS_PIXEL_MAP_MAX];
        GLuint u[2][FS_PIXEL_MAP_MAX];
        GLushort us[2][FS_PIXEL_MAP_MAX];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? m : NULL;
            memset(f[side], 0, sizeof f[side]);
            memset(u[side], 0, sizeof u[side]);
            memset(us[side], 0, sizeof us[side]);
            G(GetIntegerv, GL_PIXEL_MAP_I_TO_I_SIZE + (map - GL_PIXEL_MAP_I_TO_I), &size[side]);
            G(GetPixelMapfv, map, f[side]);
            G(GetPixelMapuiv, map, u[side]);
            G(GetPixelMapusv, map, us[side]);
        }
        if (size[0] != size[1]) {
            if (bad++ < 10)
                fprintf(stderr, "  map %#x: size %d / %d\n", map, size[0], size[1]);
            continue;
        }
        for (int i = 0; i < size[0]; i++)
            if (memcmp(&f[0][i], &f[1][i], 4) || u[0][i] != u[1][i] || us[0][i] != us[1][i]) {
                if (bad++ < 10)
                    fprintf(stderr, "  map %#x [%d]: osmesa %a %u %u, fragsim %a %u %u\n", map, i, f[0][i], u[0][i],
                            us[0][i], f[1][i], u[1][i], us[1][i]);
            }
    }
    for (int k = 0; k < N_XFER; k++) {
        GLfloat f[2];
        GLint i[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? m : NULL;
            G(GetFloatv, xfer_names[k], &f[side]);
            G(GetIntegerv, xfer_names[k], &i[side]);
        }
        if (memcmp(&f[0], &f[1], 4) || i[0] != i[1]) {
            if (bad++ < 10)
                fprintf(stderr, "  %#x: osmesa %a %d, fragsim %a %d\n", xfer_names[k], f[0], i[0], f[1], i[1]);
        }
    }
    return bad;
}

/* Random glPixelMap{fv,uiv,usv} calls, sizes valid and not (0, 3, 257,
 * non-powers of two), maps valid and not; every call's error compared. */
static int random_maps(fs_context *m, uint32_t *s, int calls)
{
    int bad = 0;
    for (int n = 0; n < calls; n++) {
        uint32_t r = rng(s);
        GLenum map = r % 23 == 0 ? GL_TEXTURE_2D : GL_PIXEL_MAP_I_TO_I + (r >> 5) % 10;
        static const GLsizei sizes[] = {1, 2, 4, 8, 16, 64, 256, 3, 5, 100, 0, 257, -1};
        GLsizei size = sizes[(r >> 10) % 13];
        GLfloat f[FS_PIXEL_MAP_MAX];
        GLuint u[FS_PIXEL_MAP_MAX];
        GLushort us[FS_PIXEL_MAP_MAX];
        for (int i = 0; i < FS_PIXEL_MAP_MAX; i++) {
            f[i] = (r >> 20) & 1 ? rnd(s, -300.0f, 300.0f) : rnd(s, -0.25f, 1.25f);
            u[i] = rng(s) >> (rng(s) & 31);
            us[i] = (GLushort)(rng(s) >> (rng(s) & 15));
        }
        int form = (int)((r >> 16) % 3);
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? m : NULL;
            if (form == 0)
                G(PixelMapfv, map, size, f);
            else if (form == 1)
                G(PixelMapuiv, map, size, u);
            else
                G(PixelMapusv, map, size, us);
            err[side] = get_error(c);
        }
        if (err[0] != err[1] && bad++ < 10)
            fprintf(stderr, "  glPixelMap form %d map %#x size %d: error %#x / %#x\n", form, map, size, err[0],
                    err[1]);
    }
    return bad;
}

TEST(pixel_maps_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context");
    }
    CHECK_EQ_INT(compare_state(b.c), 0); /* the initial state */
    uint32_t s = 12345;
    int bad = 0;
    for (int round = 0; round < 40; round++) {
        bad += random_maps(b.c, &s, 5);
        bad += compare_state(b.c);
    }
    CHECK_EQ_INT(bad, 0);
    GLint max[2];
    glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, &max[0]);
    fsglGetIntegerv(b.c, GL_MAX_PIXEL_MAP_TABLE, &max[1]);
    CHECK_EQ_INT(max[1], max[0]);
    both_close(&b);
}

TEST(pixel_transfer_state_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context");
    }
    uint32_t s = 777;
    int bad = 0;
    for (int n = 0; n < 300; n++) {
        uint32_t r = rng(&s);
        GLenum pname = r % 17 == 0 ? GL_TEXTURE_2D : xfer_names[(r >> 5) % N_XFER];
        float v = (r >> 12) & 1 ? rnd(&s, -3.0f, 3.0f) : (float)((int)(rng(&s) % 200) - 100) / 8.0f;
        GLint iv = (GLint)(rng(&s) % 41) - 20;
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            if ((r >> 13) & 1)
                G(PixelTransferi, pname, iv);
            else
                G(PixelTransferf, pname, v);
            err[side] = get_error(c);
        }
        if (err[0] != err[1] && bad++ < 10)
            fprintf(stderr, "  glPixelTransfer %#x: error %#x / %#x\n", pname, err[0], err[1]);
        if (n % 10 == 0)
            bad += compare_state(b.c);
    }
    bad += compare_state(b.c);
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

/* ---- the operations on texture uploads ---- */

/* A full-window quad textured NEAREST with REPLACE: each pixel shows one
 * texel. */
static void draw_textured(fs_context *c)
{
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(Enable, GL_TEXTURE_2D);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(Begin, GL_QUADS);
    G(TexCoord2f, 0.0f, 0.0f); G(Vertex2f, -1.0f, -1.0f);
    G(TexCoord2f, 1.0f, 0.0f); G(Vertex2f, 1.0f, -1.0f);
    G(TexCoord2f, 1.0f, 1.0f); G(Vertex2f, 1.0f, 1.0f);
    G(TexCoord2f, 0.0f, 1.0f); G(Vertex2f, -1.0f, 1.0f);
    G0(End);
    if (!c)
        glFinish();
}

/* Random scale and bias (often out of [0, 1] results), MAP_COLOR with
 * random colour maps of random power-of-two sizes, or both. */
static void random_transfer(fs_context *c, uint32_t seed, bool maps)
{
    uint32_t s = seed * 2654435761u | 1u;
    for (int k = 0; k < 4; k++) {
        G(PixelTransferf, xfer_names[4 + k], rnd(&s, -1.5f, 3.0f));
        G(PixelTransferf, xfer_names[9 + k], rnd(&s, -0.6f, 0.6f));
    }
    G(PixelTransferi, GL_MAP_COLOR, maps);
    for (int k = 0; maps && k < 4; k++) {
        GLsizei size = 1 << (rng(&s) % 9);
        GLfloat v[FS_PIXEL_MAP_MAX];
        for (int i = 0; i < size; i++)
            v[i] = rnd(&s, 0.0f, 1.0f);
        G(PixelMapfv, GL_PIXEL_MAP_R_TO_R + k, size, v);
    }
}

static void identity_transfer(fs_context *c)
{
    for (int k = 0; k < 4; k++) {
        G(PixelTransferf, xfer_names[4 + k], 1.0f);
        G(PixelTransferf, xfer_names[9 + k], 0.0f);
    }
    G(PixelTransferi, GL_MAP_COLOR, 0);
}

static const struct { GLenum format, type; } upload_pairs[] = {
    {GL_RGBA, GL_FLOAT}, {GL_RGBA, GL_UNSIGNED_BYTE}, {GL_RGB, GL_UNSIGNED_SHORT}, {GL_BGRA, GL_BYTE},
    {GL_LUMINANCE, GL_FLOAT}, {GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE}, {GL_ALPHA, GL_SHORT},
    {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4}, {GL_RGB, GL_UNSIGNED_BYTE_3_3_2}, {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV},
    {GL_RED, GL_INT}, {GL_RGBA, GL_UNSIGNED_INT},
};
#define N_UPLOAD ((int)(sizeof upload_pairs / sizeof upload_pairs[0]))

/* Client data for a pair: random bytes, or for GL_FLOAT random floats in
 * [-0.25, 1.25]. */
static void fill(void *p, size_t n, GLenum type, uint32_t seed)
{
    uint32_t s = seed | 1u;
    uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        b[i] = (uint8_t)rng(&s);
    if (type == GL_FLOAT)
        for (size_t i = 0; i + 4 <= n; i += 4) {
            float f = rnd(&s, -0.25f, 1.25f);
            memcpy(b + i, &f, 4);
        }
}

/* Uploads of every pair under random transfers (scale and bias, maps, or
 * both; with glTexSubImage2D when sub), internal format ifmt; returns the
 * cases that differ from OSMesa. */
static int upload_cases(GLint ifmt, bool sub, bool maps, uint32_t seed)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        return -1;
    }
    int bad = 0;
    static uint8_t img[TW * TH * 16];
    for (int i = 0; i < N_UPLOAD; i++) {
        /* An unsized internal format with a packed type is stored as the
         * type's bits by llvmpipe (texel formats, not the transfer). */
        if ((ifmt == GL_RGBA || ifmt == GL_RGB) && upload_pairs[i].type > GL_FLOAT)
            continue;
        fill(img, sizeof img, upload_pairs[i].type, seed + (uint32_t)i * 31);
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            random_transfer(c, seed * 7 + (uint32_t)i, maps);
            if (sub) {
                G(TexImage2D, GL_TEXTURE_2D, 0, ifmt, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
                G(TexSubImage2D, GL_TEXTURE_2D, 0, 3, 5, 20, 17, upload_pairs[i].format, upload_pairs[i].type, img);
            } else {
                G(TexImage2D, GL_TEXTURE_2D, 0, ifmt, TW, TH, 0, upload_pairs[i].format, upload_pairs[i].type, img);
            }
            err[side] = get_error(c);
            identity_transfer(c);
            draw_textured(c);
        }
        int first;
        long d = fb_differ(&b, &first);
        if ((d || err[0] != err[1]) && bad++ < 6)
            fprintf(stderr, "  ifmt %#x %#x/%#x%s%s: %ld bytes differ (first %d: osmesa %u fragsim %u), errors %#x/%#x\n",
                    (unsigned)ifmt, upload_pairs[i].format, upload_pairs[i].type, sub ? " sub" : "",
                    maps ? " maps" : "", d, first, first >= 0 ? b.o.color[first] : 0,
                    first >= 0 ? b.c->fb.color[first] : 0, err[0], err[1]);
    }
    both_close(&b);
    return bad;
}

TEST(teximage_scale_bias_vs_osmesa)
{
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        static const GLint ifmts[] = {GL_RGBA, GL_RGB8, GL_RGBA8};
        int n = upload_cases(ifmts[k], false, false, 100u + (uint32_t)k);
        REQUIRE(n >= 0);
        bad += n;
    }
    CHECK_EQ_INT(bad, 0);
}

TEST(teximage_map_color_vs_osmesa)
{
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        static const GLint ifmts[] = {GL_RGBA8, GL_RGBA8, GL_LUMINANCE8_ALPHA8};
        int n = upload_cases(ifmts[k], k == 1, true, 200u + (uint32_t)k);
        REQUIRE(n >= 0);
        bad += n;
    }
    CHECK_EQ_INT(bad, 0);
}

/* COLOR_INDEX images of every index type (GL_BITMAP included) through
 * random I_TO_R/G/B/A maps, index shift and offset (3.6.5), while scale
 * and bias are set too (they do not apply to indices). */
TEST(teximage_color_index_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context");
    }
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP};
    static uint8_t img[TW * TH * 4];
    uint32_t s = 4242;
    int bad = 0;
    for (int n = 0; n < 24; n++) {
        GLenum type = types[n % 8];
        fill(img, sizeof img, GL_UNSIGNED_BYTE, (uint32_t)n + 9);
        if (type == GL_FLOAT)
            for (int i = 0; i < TW * TH; i++) {
                float f = (float)(rng(&s) % 600) / 2.0f - 20.0f;
                memcpy(img + 4 * i, &f, 4);
            }
        uint32_t seed = rng(&s);
        GLint shift = (GLint)(rng(&s) % 9) - 4, offset = (GLint)(rng(&s) % 40) - 10;
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            uint32_t ms = seed;
            for (int k = 0; k < 4; k++) {
                GLsizei size = 1 << (rng(&ms) % 9);
                GLfloat v[FS_PIXEL_MAP_MAX];
                for (int i = 0; i < size; i++)
                    v[i] = rnd(&ms, 0.0f, 1.0f);
                G(PixelMapfv, GL_PIXEL_MAP_I_TO_R + k, size, v);
            }
            G(PixelTransferi, GL_INDEX_SHIFT, shift);
            G(PixelTransferi, GL_INDEX_OFFSET, offset);
            G(PixelTransferf, GL_RED_SCALE, 0.5f);
            G(PixelTransferf, GL_GREEN_BIAS, 0.25f);
            G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
            if (n & 8)
                G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_COLOR_INDEX, type, img);
            else {
                G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
                G(TexSubImage2D, GL_TEXTURE_2D, 0, 2, 1, 27, 29, GL_COLOR_INDEX, type, img);
            }
            err[side] = get_error(c);
            G(PixelTransferf, GL_RED_SCALE, 1.0f);
            G(PixelTransferf, GL_GREEN_BIAS, 0.0f);
            draw_textured(c);
        }
        int first;
        long d = fb_differ(&b, &first);
        if ((d || err[0] != err[1]) && bad++ < 6)
            fprintf(stderr, "  COLOR_INDEX %#x shift %d offset %d: %ld bytes differ (first %d: osmesa %u fragsim %u), errors %#x/%#x\n",
                    type, shift, offset, d, first, first >= 0 ? b.o.color[first] : 0,
                    first >= 0 ? b.c->fb.color[first] : 0, err[0], err[1]);
    }
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

/* glDrawPixels of COLOR_INDEX images in RGBA mode (3.6.4, 3.6.5): every
 * index type, GL_BITMAP included, through random I_TO_R/G/B/A maps, index
 * shift and offset (which llvmpipe ignores here, unlike glTexImage),
 * MAP_COLOR on or off and scale and bias set (neither applies to
 * indices), drawn at a raster position inside the window.  GL_BYTE and
 * GL_BITMAP differ (known, pipeline/pixel_rect.c): counted, not failed. */
TEST(drawpixels_color_index_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context");
    }
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP};
    static uint8_t img[TW * TH * 4];
    uint32_t s = 777;
    int bad = 0, known = 0;
    for (int n = 0; n < 32; n++) {
        GLenum type = types[n % 8];
        fill(img, sizeof img, GL_UNSIGNED_BYTE, (uint32_t)n + 31);
        if (type == GL_FLOAT)
            for (int i = 0; i < TW * TH; i++) {
                float f = (float)(rng(&s) % 600) / 2.0f - 20.0f;
                memcpy(img + 4 * i, &f, 4);
            }
        uint32_t seed = rng(&s);
        GLint shift = (GLint)(rng(&s) % 9) - 4, offset = (GLint)(rng(&s) % 40) - 10;
        GLint map_color = (GLint)(rng(&s) & 1);
        GLint px = (GLint)(rng(&s) % 6), py = (GLint)(rng(&s) % 6);
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            uint32_t ms = seed;
            for (int k = 0; k < 4; k++) {
                GLsizei size = 1 << (rng(&ms) % 9);
                GLfloat v[FS_PIXEL_MAP_MAX];
                for (int i = 0; i < size; i++)
                    v[i] = rnd(&ms, 0.0f, 1.0f);
                G(PixelMapfv, GL_PIXEL_MAP_I_TO_R + k, size, v);
            }
            G(ClearColor, 0.25f, 0.5f, 0.75f, 1.0f);
            G(Clear, GL_COLOR_BUFFER_BIT);
            G(PixelTransferi, GL_INDEX_SHIFT, shift);
            G(PixelTransferi, GL_INDEX_OFFSET, offset);
            G(PixelTransferi, GL_MAP_COLOR, map_color);
            G(PixelTransferf, GL_RED_SCALE, 0.5f);
            G(PixelTransferf, GL_GREEN_BIAS, 0.25f);
            G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
            G(WindowPos2i, px, py);
            G(DrawPixels, 27, 26, GL_COLOR_INDEX, type, img);
            err[side] = get_error(c);
            G(PixelTransferi, GL_INDEX_SHIFT, 0);
            G(PixelTransferi, GL_INDEX_OFFSET, 0);
            G(PixelTransferi, GL_MAP_COLOR, 0);
            G(PixelTransferf, GL_RED_SCALE, 1.0f);
            G(PixelTransferf, GL_GREEN_BIAS, 0.0f);
            G0(Finish);
        }
        int first;
        long d = fb_differ(&b, &first);
        if (d && err[0] == err[1] && (type == GL_BYTE || type == GL_BITMAP)) {
            known++;
            continue;
        }
        if ((d || err[0] != err[1]) && bad++ < 6)
            fprintf(stderr, "  glDrawPixels COLOR_INDEX %#x shift %d offset %d map_color %d: %ld bytes differ (first %d: osmesa %u fragsim %u), errors %#x/%#x\n",
                    type, shift, offset, map_color, d, first, first >= 0 ? b.o.color[first] : 0,
                    first >= 0 ? b.c->fb.color[first] : 0, err[0], err[1]);
    }
    printf("  32 glDrawPixels(GL_COLOR_INDEX) cases, %d differ from OSMesa; GL_BYTE and GL_BITMAP (known): %d of 8\n",
           bad, known);
    CHECK_EQ_INT(bad, 0);
    /* The known differences are listed so that their going away shows. */
    CHECK_EQ_INT(known, 8);
    both_close(&b);
}

/* glPushAttrib(GL_PIXEL_MODE_BIT) saves and restores the transfer state
 * and the maps (table 6.24); glPixelMap and glPixelTransfer are compiled
 * into display lists (5.4). */
TEST(push_pop_and_display_lists)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    const GLfloat v[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    fsglPixelMapfv(c, GL_PIXEL_MAP_G_TO_G, 4, v);
    fsglPixelTransferf(c, GL_RED_SCALE, 2.0f);
    fsglPushAttrib(c, GL_PIXEL_MODE_BIT);
    const GLfloat w[2] = {0.0f, 0.125f};
    fsglPixelMapfv(c, GL_PIXEL_MAP_G_TO_G, 2, w);
    fsglPixelTransferf(c, GL_RED_SCALE, 3.0f);
    fsglPopAttrib(c);
    GLfloat got[4] = {0};
    GLint size = 0;
    fsglGetPixelMapfv(c, GL_PIXEL_MAP_G_TO_G, got);
    fsglGetIntegerv(c, GL_PIXEL_MAP_G_TO_G_SIZE, &size);
    CHECK_EQ_INT(size, 4);
    CHECK(memcmp(got, v, sizeof v) == 0);
    GLfloat scale = 0.0f;
    fsglGetFloatv(c, GL_RED_SCALE, &scale);
    CHECK(scale == 2.0f);

    fsglNewList(c, 1, GL_COMPILE);
    fsglPixelMapfv(c, GL_PIXEL_MAP_B_TO_B, 2, w);
    fsglPixelTransferi(c, GL_INDEX_SHIFT, 3);
    fsglEndList(c);
    fsglGetIntegerv(c, GL_PIXEL_MAP_B_TO_B_SIZE, &size);
    CHECK_EQ_INT(size, 1); /* compiled, not executed */
    fsglCallList(c, 1);
    fsglGetIntegerv(c, GL_PIXEL_MAP_B_TO_B_SIZE, &size);
    CHECK_EQ_INT(size, 2);
    GLint shift = 0;
    fsglGetIntegerv(c, GL_INDEX_SHIFT, &shift);
    CHECK_EQ_INT(shift, 3);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(pixel_maps_vs_osmesa),
    TEST_ENTRY(pixel_transfer_state_vs_osmesa),
    TEST_ENTRY(teximage_scale_bias_vs_osmesa),
    TEST_ENTRY(teximage_map_color_vs_osmesa),
    TEST_ENTRY(teximage_color_index_vs_osmesa),
    TEST_ENTRY(drawpixels_color_index_vs_osmesa),
    TEST_ENTRY(push_pop_and_display_lists),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
