/*
 * The pixel pack/unpack module (pipeline/pixel_transfer.c) against OSMesa
 * (llvmpipe) at tolerance 0: every GL 1.2 packed type (GL 1.5 spec table
 * 3.8) and the common formats with every component type (tables 3.5, 3.6),
 * through glTexImage2D, glTexSubImage2D, glReadPixels and glGetTexImage,
 * under default and non-default pixel-store state (row length, skip pixels
 * and rows, alignment 1/2/4/8, swap bytes); the byte counts the command
 * table uses against what OSMesa reads and writes; the errors of 3.6.4.
 */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include <sys/mman.h>
#include <unistd.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/pixel_transfer.h"
#include "../driver/gl_call.h"

#define TW 64
#define TH 64

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Client data: random bytes, or for GL_FLOAT random values in [-0.25, 1.25]
 * with some exactly 0, 1 and halfway between 8-bit steps. */
static void fill(uint8_t *p, size_t n, GLenum type, uint32_t seed)
{
    uint32_t s = seed | 1u;
    if (type != GL_FLOAT) {
        for (size_t i = 0; i < n; i++)
            p[i] = (uint8_t)rng(&s);
        return;
    }
    for (size_t i = 0; i + 4 <= n; i += 4) {
        uint32_t r = rng(&s);
        float f;
        switch (r & 7) {
        case 0: f = 0.0f; break;
        case 1: f = 1.0f; break;
        case 2: f = ((float)(r >> 8 & 255) + 0.5f) / 255.0f; break;
        default: f = (float)(r >> 8) / 16777216.0f * 1.5f - 0.25f; break;
        }
        memcpy(p + i, &f, 4);
    }
}

static const GLenum color_formats[] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                       GL_RGB, GL_BGR, GL_RGBA, GL_BGRA};
static const GLenum comp_types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                    GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
static const struct { GLenum type, format; } packed[] = {
    {GL_UNSIGNED_BYTE_3_3_2, GL_RGB}, {GL_UNSIGNED_BYTE_2_3_3_REV, GL_RGB},
    {GL_UNSIGNED_SHORT_5_6_5, GL_RGB}, {GL_UNSIGNED_SHORT_5_6_5_REV, GL_RGB},
    {GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA}, {GL_UNSIGNED_SHORT_4_4_4_4, GL_BGRA},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_RGBA}, {GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_BGRA},
    {GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA}, {GL_UNSIGNED_SHORT_5_5_5_1, GL_BGRA},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_RGBA}, {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_BGRA},
    {GL_UNSIGNED_INT_8_8_8_8, GL_RGBA}, {GL_UNSIGNED_INT_8_8_8_8, GL_BGRA},
    {GL_UNSIGNED_INT_8_8_8_8_REV, GL_RGBA}, {GL_UNSIGNED_INT_8_8_8_8_REV, GL_BGRA},
    {GL_UNSIGNED_INT_10_10_10_2, GL_RGBA}, {GL_UNSIGNED_INT_10_10_10_2, GL_BGRA},
    {GL_UNSIGNED_INT_2_10_10_10_REV, GL_RGBA}, {GL_UNSIGNED_INT_2_10_10_10_REV, GL_BGRA},
};
#define N_COMP ((int)(sizeof color_formats / sizeof color_formats[0] * (sizeof comp_types / sizeof comp_types[0])))
#define N_PAIRS (N_COMP + (int)(sizeof packed / sizeof packed[0]))

/* Pair i of the colour formats with every type, then the packed types. */
static void pair(int i, GLenum *format, GLenum *type)
{
    int nt = (int)(sizeof comp_types / sizeof comp_types[0]);
    if (i < N_COMP) {
        *format = color_formats[i / nt];
        *type = comp_types[i % nt];
    } else {
        *format = packed[i - N_COMP].format;
        *type = packed[i - N_COMP].type;
    }
}

/* Pixel-store states: the default, each alignment, and row length, skips
 * and swapped bytes together. */
typedef struct store_case { const char *name; GLint align, row_length, skip_pixels, skip_rows, swap; } store_case;
static const store_case stores[] = {
    {"default", 4, 0, 0, 0, 0},
    {"align 1", 1, 0, 0, 0, 0},
    {"align 2, row length 67, skip 3 pixels 2 rows", 2, 67, 3, 2, 0},
    {"align 8, row length 65, skip 1 pixel 5 rows", 8, 65, 1, 5, 0},
    {"align 8, row length 65, swap bytes", 8, 65, 0, 0, 1},
    {"align 1, swap bytes", 1, 0, 0, 0, 1},
};
#define N_STORES ((int)(sizeof stores / sizeof stores[0]))
/* Packing also with swapped bytes and skips together (Mesa's upload path
 * gets that combination wrong, its pack paths do not). */
static const store_case pack_stores[N_STORES + 1] = {
    stores[0], stores[1], stores[2], stores[3], stores[4], stores[5],
    {"align 4, row length 70, skip 2 pixels 3 rows, swap bytes", 4, 70, 2, 3, 1},
};

static void set_store(fs_context *c, bool pack, const store_case *s)
{
    G(PixelStorei, pack ? GL_PACK_ALIGNMENT : GL_UNPACK_ALIGNMENT, s->align);
    G(PixelStorei, pack ? GL_PACK_ROW_LENGTH : GL_UNPACK_ROW_LENGTH, s->row_length);
    G(PixelStorei, pack ? GL_PACK_SKIP_PIXELS : GL_UNPACK_SKIP_PIXELS, s->skip_pixels);
    G(PixelStorei, pack ? GL_PACK_SKIP_ROWS : GL_UNPACK_SKIP_ROWS, s->skip_rows);
    G(PixelStorei, pack ? GL_PACK_SWAP_BYTES : GL_UNPACK_SWAP_BYTES, s->swap);
}

static fs_pixel_store store_of(const store_case *s)
{
    return (fs_pixel_store){.alignment = s->align, .row_length = s->row_length, .skip_pixels = s->skip_pixels,
                            .skip_rows = s->skip_rows, .swap_bytes = s->swap != 0};
}

/* A full-window quad textured NEAREST with REPLACE: each pixel shows one
 * texel as the sampler reads it. */
static void draw_textured(fs_context *c)
{
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(Enable, GL_TEXTURE_2D);
    G(ClearColor, 0.0f, 0.0f, 0.0f, 0.0f);
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

static long fb_differ(const both *b)
{
    long d = 0;
    for (long i = 0; i < (long)TW * TH * 4; i++)
        d += b->c->fb.color[i] != b->o.color[i];
    return d;
}

/* Image data as big as the layout says plus slack, so that a layout that
 * is too small shows as a difference rather than a read past the end. */
static uint8_t *client_image(const store_case *s, int w, int h, GLenum format, GLenum type, uint32_t seed,
                             size_t *bytes)
{
    fs_pixel_store ps = store_of(s);
    *bytes = (size_t)fs_pixel_image_bytes(&ps, 2, w, h, 1, format, type) + 256;
    uint8_t *p = malloc(*bytes);
    if (p)
        fill(p, *bytes, type, seed);
    return p;
}

/* glTexImage2D (sub = false) or a glTexSubImage2D into a random RGBA8 image
 * (sub = true) of every pair under every store, with internal format ifmt,
 * drawn and compared; returns the cases that differ. */
static int upload_cases(GLint ifmt, bool sub)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        return -1;
    }
    int bad = 0;
    uint8_t base[TW * TH * 4];
    fill(base, sizeof base, GL_UNSIGNED_BYTE, 77);
    for (int si = 0; si < N_STORES; si++)
        for (int i = 0; i < N_PAIRS; i++) {
            GLenum format, type;
            pair(i, &format, &type);
            int w = sub ? 40 : TW, h = sub ? 30 : TH;
            size_t bytes;
            uint8_t *img = client_image(&stores[si], w, h, format, type, (uint32_t)(i * 131 + si * 7 + 1), &bytes);
            if (!img)
                return -1;
            GLenum err[2];
            for (int side = 0; side < 2; side++) {
                fs_context *c = side ? b.c : NULL;
                store_case dflt = stores[0];
                if (sub) {
                    set_store(c, false, &dflt);
                    G(TexImage2D, GL_TEXTURE_2D, 0, ifmt, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
                }
                set_store(c, false, &stores[si]);
                if (sub)
                    G(TexSubImage2D, GL_TEXTURE_2D, 0, 5, 9, w, h, format, type, img);
                else
                    G(TexImage2D, GL_TEXTURE_2D, 0, ifmt, w, h, 0, format, type, img);
                err[side] = get_error(c);
                draw_textured(c);
                set_store(c, false, &dflt);
            }
            long d = fb_differ(&b);
            if (d || err[0] != err[1] || err[1] != GL_NO_ERROR) {
                if (bad++ < 8)
                    fprintf(stderr, "  %s ifmt %#x format %#x type %#x [%s]: %ld bytes differ, errors %#x/%#x\n",
                            sub ? "TexSubImage2D" : "TexImage2D", (unsigned)ifmt, format, type, stores[si].name, d,
                            err[0], err[1]);
                for (long k = 0; d && k < (long)TW * TH * 4; k++)
                    if (b.c->fb.color[k] != b.o.color[k]) {
                        fprintf(stderr, "    first at byte %ld: osmesa %u fragsim %u\n", k, b.o.color[k],
                                b.c->fb.color[k]);
                        break;
                    }
            }
            free(img);
        }
    both_close(&b);
    return bad;
}

TEST(teximage_vs_osmesa)
{
    static const GLint ifmts[] = {GL_RGBA, GL_RGBA8, GL_RGB, GL_LUMINANCE_ALPHA, GL_INTENSITY};
    int total = 0;
    for (int k = 0; k < 5; k++) {
        int bad = upload_cases(ifmts[k], false);
        REQUIRE(bad >= 0);
        printf("  TexImage2D internal format %#x: %d of %d pairs x stores differ\n", (unsigned)ifmts[k], bad,
               N_PAIRS * N_STORES);
        total += bad;
    }
    CHECK_EQ_INT(total, 0);
}

TEST(texsubimage_vs_osmesa)
{
    static const GLint ifmts[] = {GL_RGBA8, GL_LUMINANCE8_ALPHA8};
    int total = 0;
    for (int k = 0; k < 2; k++) {
        int bad = upload_cases(ifmts[k], true);
        REQUIRE(bad >= 0);
        printf("  TexSubImage2D internal format %#x: %d of %d pairs x stores differ\n", (unsigned)ifmts[k], bad,
               N_PAIRS * N_STORES);
        total += bad;
    }
    CHECK_EQ_INT(total, 0);
}

/* Output bytes written: a call run twice, over buffers prefilled with 0x00
 * and 0xff; a byte is written where the two agree.  The first written byte
 * at or after `from`, or -1. */
static long first_written_from(const uint8_t *a, const uint8_t *b, size_t from, size_t n)
{
    for (size_t i = from; i < n; i++)
        if (a[i] == b[i])
            return (long)i;
    return -1;
}

/* Compares the bytes a pack command writes on both sides for every pair
 * and store; `run` issues the command on one side into buf. */
typedef void (*pack_fn)(fs_context *c, GLenum format, GLenum type, void *buf, const void *user);

static int pack_cases(check_state *check_st_, both *b, const char *what, pack_fn run, const void *user,
                      const GLenum *formats, int nformats, const GLenum *types, int ntypes, int w, int h,
                      bool with_packed)
{
    int bad = 0;
    int npairs = nformats * ntypes + (with_packed ? (int)(sizeof packed / sizeof packed[0]) : 0);
    for (int si = 0; si < N_STORES + 1; si++)
        for (int i = 0; i < npairs; i++) {
            GLenum format = i < nformats * ntypes ? formats[i / ntypes] : packed[i - nformats * ntypes].format;
            GLenum type = i < nformats * ntypes ? types[i % ntypes] : packed[i - nformats * ntypes].type;
            fs_pixel_store ps = store_of(&pack_stores[si]);
            int64_t count = fs_pixel_image_bytes(&ps, 2, w, h, 1, format, type);
            CHECK(count > 0);
            if (count <= 0)
                return bad + 1;
            size_t n = (size_t)count + 64;
            uint8_t *buf[2][2];
            GLenum err[2];
            for (int side = 0; side < 2; side++) {
                fs_context *c = side ? b->c : NULL;
                set_store(c, true, &pack_stores[si]);
                for (int pre = 0; pre < 2; pre++) {
                    buf[side][pre] = malloc(n);
                    if (!buf[side][pre])
                        abort();
                    memset(buf[side][pre], pre ? 0xff : 0x00, n);
                    run(c, format, type, buf[side][pre], user);
                }
                err[side] = get_error(c);
                store_case dflt = stores[0];
                set_store(c, true, &dflt);
            }
            long d = 0;
            for (size_t k = 0; k < n; k++)
                d += (buf[0][0][k] != buf[1][0][k]) + (buf[0][1][k] != buf[1][1][k]);
            /* The byte count: OSMesa writes the last byte of it and none after. */
            bool last = buf[0][0][count - 1] == buf[0][1][count - 1];
            bool extent_ok = last && first_written_from(buf[0][0], buf[0][1], (size_t)count, n) < 0;
            if (d || !extent_ok || err[0] != err[1] || err[0] != GL_NO_ERROR) {
                if (bad++ < 8) {
                    fprintf(stderr, "  %s format %#x type %#x [%s]: %ld bytes differ, errors %#x/%#x, count %ld%s\n",
                            what, format, type, pack_stores[si].name, d, err[0], err[1], (long)count,
                            extent_ok ? "" : " (OSMesa writes another extent)");
                    for (size_t k = 0; d && k < n; k++)
                        if (buf[0][0][k] != buf[1][0][k]) {
                            fprintf(stderr, "    first at byte %zu: osmesa %02x fragsim %02x\n", k, buf[0][0][k],
                                    buf[1][0][k]);
                            break;
                        }
                }
            }
            for (int side = 0; side < 2; side++)
                for (int pre = 0; pre < 2; pre++)
                    free(buf[side][pre]);
        }
    return bad;
}

typedef struct rect { GLint x, y; GLsizei w, h; } rect;

static void run_read(fs_context *c, GLenum format, GLenum type, void *buf, const void *user)
{
    const rect *r = user;
    G(ReadPixels, r->x, r->y, r->w, r->h, format, type, buf);
}

/* The same random RGBA8 picture in both framebuffers (through a texture). */
static bool same_picture(check_state *check_st_, both *b)
{
    uint8_t tex[TW * TH * 4];
    fill(tex, sizeof tex, GL_UNSIGNED_BYTE, 4242);
    for (int side = 0; side < 2; side++) {
        fs_context *c = side ? b->c : NULL;
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        draw_textured(c);
        G(Disable, GL_TEXTURE_2D);
    }
    CHECK_EQ_INT(fb_differ(b), 0);
    return fb_differ(b) == 0;
}

TEST(readpixels_color_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        REQUIRE(false);
    }
    if (!same_picture(check_st_, &b)) {
        both_close(&b);
        return;
    }
    rect r = {2, 3, 45, 37};
    int bad = pack_cases(check_st_, &b, "ReadPixels", run_read, &r, color_formats, 10, comp_types, 7, r.w, r.h, true);
    printf("  ReadPixels colour: %d of %d pairs x stores differ\n", bad, N_PAIRS * (N_STORES + 1));
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

TEST(readpixels_depth_stencil_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        REQUIRE(false);
    }
    /* A depth ramp across the window on OSMesa, copied into the model;
     * stencil values from scissored clears on both. */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_QUADS);
    glVertex3f(-1.0f, -1.0f, -1.0f);
    glVertex3f(1.0f, -1.0f, 0.3f);
    glVertex3f(1.0f, 1.0f, 1.0f);
    glVertex3f(-1.0f, 1.0f, -0.2f);
    glEnd();
    glFinish();
    GLint dw, dh, bpv;
    void *dp;
    REQUIRE(OSMesaGetDepthBuffer(b.o.ctx, &dw, &dh, &bpv, &dp) && bpv == 4);
    for (int i = 0; i < TW * TH; i++)
        b.c->fb.depth[i] = ((const uint32_t *)dp)[i] & 0xffffffu;
    for (int side = 0; side < 2; side++) {
        fs_context *c = side ? b.c : NULL;
        G(Enable, GL_SCISSOR_TEST);
        for (int k = 0; k < 8; k++) {
            G(Scissor, k * 7, k * 5, 20, 30);
            G(ClearStencil, k * 37 + 3);
            G(Clear, GL_STENCIL_BUFFER_BIT);
        }
        G(Disable, GL_SCISSOR_TEST);
    }
    rect r = {1, 2, 50, 41};
    static const GLenum depth_f[] = {GL_DEPTH_COMPONENT}, stencil_f[] = {GL_STENCIL_INDEX};
    /* Not GL_BITMAP: Mesa 22 reports it unsupported for every pixel
     * (tested against the closed form in stencil_bitmap_pack). */
    static const GLenum stencil_t[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                       GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
    int bad = pack_cases(check_st_, &b, "ReadPixels depth", run_read, &r, depth_f, 1, comp_types, 7, r.w, r.h, false);
    printf("  ReadPixels depth: %d of %d types x stores differ\n", bad, 7 * (N_STORES + 1));
    int bads = pack_cases(check_st_, &b, "ReadPixels stencil", run_read, &r, stencil_f, 1, stencil_t, 7, r.w, r.h,
                          false);
    printf("  ReadPixels stencil: %d of %d types x stores differ\n", bads, 7 * (N_STORES + 1));
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(bads, 0);
    both_close(&b);
}

static void run_get(fs_context *c, GLenum format, GLenum type, void *buf, const void *user)
{
    (void)user;
    G(GetTexImage, GL_TEXTURE_2D, 0, format, type, buf);
}

TEST(gettexImage_vs_osmesa)
{
    static const GLint ifmts[] = {GL_RGBA8, GL_RGB8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8, GL_ALPHA8, GL_INTENSITY8};
    static const GLenum lum_f[] = {GL_LUMINANCE, GL_LUMINANCE_ALPHA};
    static const GLenum other_f[] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA};
    int total = 0;
    for (int k = 0; k < 6; k++) {
        both b;
        if (!both_open(&b)) {
            both_close(&b);
            REQUIRE(false);
        }
        uint8_t tex[32 * 16 * 4];
        fill(tex, sizeof tex, GL_UNSIGNED_BYTE, (uint32_t)(k + 9));
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            G(TexImage2D, GL_TEXTURE_2D, 0, ifmts[k], 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        }
        int bad = pack_cases(check_st_, &b, "GetTexImage", run_get, NULL, other_f, 8, comp_types, 7, 32, 16, true);
        bad += pack_cases(check_st_, &b, "GetTexImage", run_get, NULL, lum_f, 2, comp_types, 7, 32, 16, false);
        printf("  GetTexImage internal format %#x: %d pairs x stores differ\n", (unsigned)ifmts[k], bad);
        total += bad;
        both_close(&b);
    }
    CHECK_EQ_INT(total, 0);
}

/* 3.6.4's errors on both: packed types with a format of the wrong
 * component count, unknown enums, BITMAP with a colour format. */
TEST(errors_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        REQUIRE(false);
    }
    static const struct { GLenum format, type; } cases[] = {
        {GL_RGBA, GL_UNSIGNED_SHORT_5_6_5}, {GL_BGR, GL_UNSIGNED_SHORT_5_6_5}, {GL_RGB, GL_UNSIGNED_INT_8_8_8_8},
        {GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2}, {GL_BGRA, GL_UNSIGNED_BYTE_2_3_3_REV},
        {GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4}, {GL_LUMINANCE_ALPHA, GL_UNSIGNED_INT_2_10_10_10_REV},
        {GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5}, {GL_STENCIL_INDEX, GL_UNSIGNED_INT_8_8_8_8},
        {GL_RGBA, 0x1234}, {0x1234, GL_UNSIGNED_BYTE}, {GL_RGBA, GL_BITMAP}, {GL_RGB, GL_UNSIGNED_BYTE},
        {GL_DEPTH_COMPONENT, GL_FLOAT}, {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE}, {GL_COLOR_INDEX, GL_BITMAP},
    };
    static uint8_t px[16 * 16 * 16];
    int bad = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        GLenum e[2][4];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
            (void)get_error(c);
            G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, cases[i].format, cases[i].type, px);
            e[side][0] = get_error(c);
            G(TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 4, 4, cases[i].format, cases[i].type, px);
            e[side][1] = get_error(c);
            if (cases[i].format != GL_COLOR_INDEX)
                G(ReadPixels, 0, 0, 4, 4, cases[i].format, cases[i].type, px);
            e[side][2] = get_error(c);
            if (cases[i].format != GL_COLOR_INDEX)
                G(GetTexImage, GL_TEXTURE_2D, 0, cases[i].format, cases[i].type, px);
            e[side][3] = get_error(c);
        }
        /* Mesa 22's glReadPixels and glGetTexImage of GL_COLOR_INDEX are an
         * internal error ("Unexpected format"), no reference. */
        int nk = cases[i].format == GL_COLOR_INDEX ? 2 : 4;
        for (int k = 0; k < nk; k++)
            if (e[0][k] != e[1][k] && bad++ < 10)
                fprintf(stderr, "  format %#x type %#x command %d: osmesa %#x fragsim %#x\n", cases[i].format,
                        cases[i].type, k, e[0][k], e[1][k]);
    }
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

/* The byte count of glTexImage2D against what OSMesa reads: the image ends
 * right at a page that may not be read, so a count that is too small
 * crashes OSMesa; and closed forms of 3.6.4 for the skips. */
TEST(teximage_bytes_bound_osmesa_reads)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        REQUIRE(false);
    }
    long page = sysconf(_SC_PAGESIZE);
    for (int si = 0; si < N_STORES; si++)
        for (int i = 0; i < N_PAIRS; i++) {
            GLenum format, type;
            pair(i, &format, &type);
            fs_pixel_store ps = store_of(&stores[si]);
            int64_t count = fs_pixel_image_bytes(&ps, 2, 16, 8, 1, format, type);
            size_t span = ((size_t)count + (size_t)page - 1) / (size_t)page * (size_t)page + (size_t)page;
            uint8_t *m = mmap(NULL, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            REQUIRE(m != MAP_FAILED);
            mprotect(m + span - page, (size_t)page, PROT_NONE);
            uint8_t *img = m + span - page - count;
            fill(img, (size_t)count, type, 5);
            set_store(NULL, false, &stores[si]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 8, 0, format, type, img);
            CHECK_EQ_INT(glGetError(), GL_NO_ERROR);
            munmap(m, span);
        }
    /* 3.6.4: skip pixels and rows move the start; the last row has no
     * padding. RGB bytes, row length 10, alignment 4: rows of 32 bytes. */
    fs_pixel_store ps = {.alignment = 4, .row_length = 10, .skip_pixels = 2, .skip_rows = 3};
    CHECK_EQ_INT(fs_pixel_image_bytes(&ps, 2, 5, 4, 1, GL_RGB, GL_UNSIGNED_BYTE), 32 * 3 + 2 * 3 + 32 * 3 + 15);
    /* Bitmaps count bits: 20 pixels + 3 skipped = 23 bits in 3 bytes, rows
     * of ceil(20 / 8) = 3 bytes padded to 4. */
    ps = (fs_pixel_store){.alignment = 4, .skip_pixels = 3};
    CHECK_EQ_INT(fs_pixel_image_bytes(&ps, 2, 20, 2, 1, GL_STENCIL_INDEX, GL_BITMAP), 4 + 3);
    /* 3D only: skip images and image height. */
    ps = (fs_pixel_store){.alignment = 1, .image_height = 6, .skip_images = 1};
    CHECK_EQ_INT(fs_pixel_image_bytes(&ps, 3, 2, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE), 48 + 48 + 2 * 8 + 8);
    CHECK_EQ_INT(fs_pixel_image_bytes(&ps, 2, 2, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE), 2 * 8 + 8);
    /* The command table's helper follows the context's state. */
    fsglPixelStorei(b.c, GL_UNPACK_SKIP_ROWS, 2);
    fsglPixelStorei(b.c, GL_UNPACK_ALIGNMENT, 1);
    CHECK_EQ_INT(fs_teximage_bytes(b.c, 3, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5), 3 * 2 * 4);
    both_close(&b);
}

/* Stencil indices as GL_BITMAP (4.3.2: one bit each, the index's least
 * significant bit; bit 7 of a byte first unless PACK_LSB_FIRST), with
 * skip pixels counting bits and rows padded to the alignment.  Mesa 22
 * does not implement this read (it reports the pair unsupported), so the
 * closed form is the reference. */
TEST(stencil_bitmap_pack)
{
    fs_context *c = fs_context_create(NULL, 16, 2);
    REQUIRE(c);
    for (int i = 0; i < 32; i++)
        c->fb.stencil[i] = (uint8_t)(i % 3 == 0 ? 1 : 2 * i); /* odd only where i % 3 == 0 */
    for (int lsb = 0; lsb < 2; lsb++) {
        uint8_t buf[8];
        memset(buf, 0xaa, sizeof buf);
        fsglPixelStorei(c, GL_PACK_LSB_FIRST, lsb);
        fsglPixelStorei(c, GL_PACK_SKIP_PIXELS, 3);
        fsglPixelStorei(c, GL_PACK_ALIGNMENT, 4);
        /* 10 pixels of each row after 3 skipped bits: bits 3..12 of bytes
         * 0..1 of each 4-byte row. */
        fsglReadPixels(c, 0, 0, 10, 2, GL_STENCIL_INDEX, GL_BITMAP, buf);
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        CHECK_EQ_INT(fs_readpixels_bytes(c, 10, 2, GL_STENCIL_INDEX, GL_BITMAP), 4 + 2);
        for (int y = 0; y < 2; y++)
            for (int b = 0; b < 16; b++) {
                int bit = lsb ? (buf[y * 4 + b / 8] >> (b % 8)) & 1 : (buf[y * 4 + b / 8] >> (7 - b % 8)) & 1;
                int x = b - 3;
                int want = x >= 0 && x < 10 ? (y * 16 + x) % 3 == 0 : (lsb ? (0xaa >> (b % 8)) & 1
                                                                             : (0xaa >> (7 - b % 8)) & 1);
                CHECK_EQ_INT(bit, want);
            }
        CHECK_EQ_INT(buf[2], 0xaa); /* row padding untouched */
    }
    fs_context_destroy(c);
}

/* A display list replays glTexImage2D with the whole unpack state it was
 * compiled under (GL 1.5 spec 5.4), skips and swapped bytes included. */
TEST(display_list_keeps_unpack_skips)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        REQUIRE(false);
    }
    static const store_case s = {"row length 70, skip 2 pixels 3 rows, swap", 2, 70, 2, 3, 1};
    size_t bytes;
    uint8_t *img = client_image(&s, TW, TH, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 99, &bytes);
    REQUIRE(img);
    for (int side = 0; side < 2; side++) {
        fs_context *c = side ? b.c : NULL;
        set_store(c, false, &s);
        G(NewList, 1, GL_COMPILE);
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, TW, TH, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, img);
        G0(EndList);
        store_case dflt = stores[0];
        set_store(c, false, &dflt);
        G(CallList, 1);
        draw_textured(c);
    }
    CHECK_EQ_INT(fb_differ(&b), 0);
    free(img);
    both_close(&b);
}

/* Skips and row lengths near 2^31 (a bad trace) make images no pointer can
 * address: their byte count is 0 and nothing is read or written, instead
 * of an int64 overflow and a write far outside the buffer. */
TEST(huge_pixel_store_reads_and_writes_nothing)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    uint8_t buf[64 * 16];
    memset(buf, 0x5a, sizeof buf);
    fsglPixelStorei(c, GL_PACK_ROW_LENGTH, 2147483647);
    fsglPixelStorei(c, GL_PACK_SKIP_ROWS, 2147483647);
    fsglPixelStorei(c, GL_UNPACK_ROW_LENGTH, 2147483647);
    fsglPixelStorei(c, GL_UNPACK_SKIP_ROWS, 2147483647);
    fsglPixelStorei(c, GL_UNPACK_SKIP_PIXELS, 2147483647);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(fs_readpixels_bytes(c, 8, 8, GL_RGBA, GL_FLOAT), 0);
    CHECK_EQ_INT(fs_teximage_bytes(c, 8, 8, GL_RGBA, GL_FLOAT), 0);
    fsglReadPixels(c, 0, 0, 8, 8, GL_RGBA, GL_FLOAT, buf);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, buf);
    fsglGetTexImage(c, GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, buf);
    for (size_t i = 0; i < sizeof buf; i++)
        if (buf[i] != 0x5a) {
            CHECK_EQ_INT(buf[i], 0x5a);
            break;
        }
    /* Within 2^60 bytes the count is exact: 2^28 - 1 skipped rows of
     * 2^28 RGBA pixels each. */
    fs_pixel_store ps = {.alignment = 1, .row_length = 1 << 28, .skip_rows = (1 << 28) - 1};
    CHECK_EQ_INT(fs_pixel_image_bytes(&ps, 2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE),
                 ((int64_t)1 << 28) * 4 * ((1 << 28) - 1) + 4);
    fs_context_destroy(c);
}

/* llvmpipe stores 16-bit and 10-bit client data given with an unsized
 * internal format at that precision; the model's 8-bit storage is exact
 * for NEAREST/REPLACE (teximage_vs_osmesa) but is counted unsupported,
 * since filtering and the environment see the extra bits on llvmpipe. */
TEST(wide_texels_counted)
{
    fs_context *c = fs_context_create(NULL, 4, 4);
    REQUIRE(c);
    static uint16_t px[4 * 4 * 4];
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT, px);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, px);
    CHECK_EQ_INT(c->stats.unsupported_calls, 0);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT, px);
    fsglTexImage2D(c, GL_TEXTURE_2D, 0, 4, 4, 4, 0, GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, px);
    CHECK_EQ_INT(c->stats.unsupported_calls, 2);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

/* Unpacking indices and depth (for glDrawPixels): what the packers wrote
 * reads back (stencil in every type, bits with and without LSB first), and
 * table 2.9's depth conversions, under skips, row length and swapped
 * bytes. */
TEST(unpack_index_and_depth_closed_form)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP};
    uint8_t st[21];
    for (int i = 0; i < 21; i++)
        st[i] = (uint8_t)(i * 11 % 128);
    for (int t = 0; t < 8; t++)
        for (int swap = 0; swap < 2; swap++) {
            fs_pixel_store ps = {.alignment = 2, .row_length = 9, .skip_pixels = 2, .skip_rows = 1,
                                 .swap_bytes = swap != 0, .lsb_first = swap != 0};
            fs_pixel_layout l;
            REQUIRE(fs_pixel_layout_init(&l, &ps, 2, 7, 3, 1, GL_STENCIL_INDEX, types[t]));
            uint8_t buf[512];
            memset(buf, 0, sizeof buf);
            CHECK(fs_pixel_layout_bytes(&l) <= (int64_t)sizeof buf);
            for (int y = 0; y < 3; y++)
                fs_pixel_pack_stencil(&l, buf, y, 0, 7, st + 7 * y);
            for (int y = 0; y < 3; y++) {
                uint32_t idx[7];
                fs_pixel_unpack_index(&l, buf, 0, y, 0, 7, idx);
                for (int x = 0; x < 7; x++) {
                    uint32_t want = st[7 * y + x];
                    if (types[t] == GL_BITMAP)
                        want &= 1;
                    CHECK_EQ_UINT(idx[x], want);
                }
            }
        }
    /* Depth: unsigned c / (2^b - 1), signed (2c + 1) / (2^b - 1), clamped. */
    fs_pixel_store ps = {.alignment = 4, .swap_bytes = true};
    fs_pixel_layout l;
    REQUIRE(fs_pixel_layout_init(&l, &ps, 2, 3, 1, 1, GL_DEPTH_COMPONENT, GL_SHORT));
    const uint8_t shorts[6] = {0x40, 0x00, 0x80, 0x00, 0xff, 0xff}; /* big-endian 16384, -32768, -1 */
    float d[3];
    fs_pixel_unpack_depth(&l, shorts, 0, 0, 0, 3, d);
    CHECK(d[0] == (float)(32769.0 / 65535.0));
    CHECK(d[1] == 0.0f);
    CHECK(d[2] == 0.0f);
    ps.swap_bytes = false;
    REQUIRE(fs_pixel_layout_init(&l, &ps, 2, 3, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE));
    const uint8_t bytes[3] = {0, 51, 255};
    fs_pixel_unpack_depth(&l, bytes, 0, 0, 0, 3, d);
    CHECK(d[0] == 0.0f && d[1] == 0.2f && d[2] == 1.0f);
    REQUIRE(fs_pixel_layout_init(&l, &ps, 2, 3, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT));
    const float fl[3] = {-0.5f, 0.25f, NAN};
    fs_pixel_unpack_depth(&l, fl, 0, 0, 0, 3, d);
    CHECK(d[0] == 0.0f && d[1] == 0.25f && d[2] == 0.0f);
}

TEST_LIST = {
    TEST_ENTRY(teximage_vs_osmesa),
    TEST_ENTRY(texsubimage_vs_osmesa),
    TEST_ENTRY(readpixels_color_vs_osmesa),
    TEST_ENTRY(readpixels_depth_stencil_vs_osmesa),
    TEST_ENTRY(gettexImage_vs_osmesa),
    TEST_ENTRY(errors_vs_osmesa),
    TEST_ENTRY(teximage_bytes_bound_osmesa_reads),
    TEST_ENTRY(stencil_bitmap_pack),
    TEST_ENTRY(display_list_keeps_unpack_skips),
    TEST_ENTRY(huge_pixel_store_reads_and_writes_nothing),
    TEST_ENTRY(wide_texels_counted),
    TEST_ENTRY(unpack_index_and_depth_closed_form),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
