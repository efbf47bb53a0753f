/*
 * The generic compressed internal formats (GL 1.5 spec 3.8.1, table 3.17)
 * against OSMesa (llvmpipe, Mesa 22.3), which stores them on 2D images as
 * block formats compressed with Mesa's encoders (units/texture_encode.c):
 * GL_COMPRESSED_RED / _RG as RGTC1 / RGTC2, _LUMINANCE / _LUMINANCE_ALPHA
 * as LATC1 / LATC2.  Images of several sizes (non-multiples of 4, 1x1) and
 * patterns (random, gradients, flat, two colours, noise, extremes, flat
 * with +-3 noise) are
 * uploaded by glTexImage2D, updated by glTexSubImage2D, copied by
 * glCopyTexImage2D and glCopyTexSubImage2D; glGetTexImage's texels and
 * glGetCompressedTexImage's blocks are compared at tolerance 0.
 *
 * Blocks are compared as far as they are defined: Mesa leaves the codes
 * of the pixels outside a partial block and, in its one-value shortcut,
 * the second endpoint byte as the memory held them (measured: they differ
 * between runs of OSMesa), so those are left out on both sides.
 */
#include "check.h"
#include "osmesa_util.h"
#include "test_rng.h"
#include <GL/glext.h>

enum { WIN = 64, CAP = 600000, BLOCK_MARK = -1000 };

/* kind: how a block is read (RGTC / LATC channel blocks, or S3TC: DXT1's
 * colour block, DXT3's 4-bit alpha then colour, DXT5's alpha channel
 * block then colour). */
enum kind { K_CHANNELS, K_DXT1, K_DXT3, K_DXT5 };
typedef struct fmt_case { GLenum generic, stored; const char *name; enum kind kind; } fmt_case;
static const fmt_case fmts[] = {
    {GL_COMPRESSED_RED, GL_COMPRESSED_RED_RGTC1, "red_rgtc1", K_CHANNELS},
    {GL_COMPRESSED_RG, GL_COMPRESSED_RG_RGTC2, "rg_rgtc2", K_CHANNELS},
    {GL_COMPRESSED_LUMINANCE, GL_COMPRESSED_LUMINANCE_LATC1_EXT, "luminance_latc1", K_CHANNELS},
    {GL_COMPRESSED_LUMINANCE_ALPHA, GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT, "luminance_alpha_latc2", K_CHANNELS},
    /* S3TC: the generic RGB / RGBA (stored as DXT1 / DXT5), and the
     * explicit formats through the same uncompressed upload paths */
    {GL_COMPRESSED_RGB, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, "rgb_dxt1", K_DXT1},
    {GL_COMPRESSED_RGBA, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, "rgba_dxt5", K_DXT5},
    {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, "rgba_dxt1", K_DXT1},
    {GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, "rgba_dxt3", K_DXT3},
};
enum { NFMT = (int)(sizeof fmts / sizeof fmts[0]), NCHAN = 4 };

static const int sizes[][2] = {{16, 16}, {6, 6}, {13, 7}, {1, 1}, {2, 3}, {64, 32}, {5, 12}, {8, 4}};
enum { NSIZES = (int)(sizeof sizes / sizeof sizes[0]), NPAT = 9 };

/* What a run reads: the texels (glGetTexImage) or the blocks. */
enum part { PART_TEXELS, PART_BLOCKS };
static const fmt_case *cur;
static enum part cur_part;
/* Which pixels and blocks a run reads: those of the whole blocks, or
 * those of the partial blocks at the right and top edges. */
static bool cur_partial;

static bool in_partial(int x, int y, int w, int h) { return x >= w / 4 * 4 || y >= h / 4 * 4; }

static void put(double *v, int *n, double x)
{
    if (*n < CAP)
        v[*n] = x;
    (*n)++;
}

/* An RGBA8 w x h image of pattern p. */
static void pattern(int p, int w, int h, uint32_t seed, uint8_t *img)
{
    rng r = {0x9e3779b97f4a7c15ull ^ seed};
    uint8_t a[4], b[4];
    for (int k = 0; k < 4; k++)
        a[k] = (uint8_t)rnd(&r), b[k] = (uint8_t)rnd(&r);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int k = 0; k < 4; k++) {
                int v;
                switch (p) {
                case 0: v = (int)(rnd(&r) & 255); break;                                    /* random */
                case 1: v = (x * 255 / (w > 1 ? w - 1 : 1) + k * 40 + y * 7) & 255; break;  /* gradient */
                case 2: v = a[k]; break;                                                     /* flat */
                case 3: v = (rnd(&r) & 1) ? a[k] : b[k]; break;                              /* two colours */
                case 4: v = 128 + (int)(rnd(&r) % 9) - 4; break;                             /* noise */
                case 5: { int s = (int)(rnd(&r) % 3); v = s == 0 ? 0 : s == 1 ? 255 : (int)(rnd(&r) & 255); } break;
                case 6: v = k == 3 ? 255 : (k == 0 ? 0 : (int)(rnd(&r) & 255)); break;      /* flat extremes */
                case 7: v = (x * 16 + y * 9 + (int)(rnd(&r) % 31)) % 256; break;           /* ramp + noise */
                default: v = a[k] + (int)(rnd(&r) % 7) - 3; v = v < 0 ? 0 : v > 255 ? 255 : v; break;
                    /* a flat colour + noise of +-3: S3TC's base colours end close and are pushed apart */
                }
                img[((size_t)y * (size_t)w + (size_t)x) * 4 + (size_t)k] = (uint8_t)v;
            }
}

/* One 8-byte channel block as 18 values, what Mesa leaves undefined as -1:
 * the endpoints, then the sixteen 3-bit codes (inside nx x ny). */
static void put_channel_block(double *v, int *n, const uint8_t *blk, int nx, int ny)
{
    uint64_t bits = 0;
    for (int i = 7; i >= 2; i--)
        bits = bits << 8 | blk[i];
    bool all0 = true;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            all0 = all0 && ((bits >> (3 * (4 * j + i))) & 7) == 0;
    put(v, n, BLOCK_MARK);
    put(v, n, blk[0]);
    put(v, n, all0 ? -1 : blk[1]);
    for (int p = 0; p < 16; p++)
        put(v, n, (p % 4) < nx && (p / 4) < ny ? (double)((bits >> (3 * p)) & 7) : -1);
}

/* An S3TC colour block (8 bytes) as 19 values: the two 565 endpoints,
 * then the sixteen 2-bit codes (inside nx x ny, else -1: Mesa codes only
 * the pixels inside). */
static void put_colour_block(double *v, int *n, const uint8_t *blk, int nx, int ny)
{
    uint32_t bits = blk[4] | (uint32_t)blk[5] << 8 | (uint32_t)blk[6] << 16 | (uint32_t)blk[7] << 24;
    put(v, n, BLOCK_MARK);
    put(v, n, blk[0] | blk[1] << 8);
    put(v, n, blk[2] | blk[3] << 8);
    for (int p = 0; p < 16; p++)
        put(v, n, (p % 4) < nx && (p / 4) < ny ? (double)((bits >> (2 * p)) & 3) : -1);
}

/* DXT3's alpha half: the 4-bit alphas inside nx x ny. */
static void put_dxt3_alpha(double *v, int *n, const uint8_t *blk, int nx, int ny)
{
    put(v, n, BLOCK_MARK);
    for (int p = 0; p < 16; p++)
        put(v, n, (p % 4) < nx && (p / 4) < ny ? (double)((blk[p / 2] >> (4 * (p % 2))) & 15) : -1);
}

static GLenum err_of(fs_context *c) { return c ? fsglGetError(c) : glGetError(); }

/* The part read of the bound 2D texture's level 0 (w x h). */
static void read_level(fs_context *c, double *v, int *n, int w, int h)
{
    static uint8_t out[WIN * WIN * 4 + 16];
    if (cur_part == PART_TEXELS) {
        memset(out, 0xcd, sizeof out);
        G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
        for (int i = 0; i < w * h * 4; i++)
            if (in_partial(i / 4 % w, i / 4 / w, w, h) == cur_partial)
                put(v, n, out[i]);
        put(v, n, out[w * h * 4]); /* nothing written past the image */
    } else {
        GLint ifmt = 0, size = 0;
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &ifmt);
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
        put(v, n, ifmt);
        put(v, n, size);
        int bw = (w + 3) / 4, bh = (h + 3) / 4, chans = size / (bw * bh * 8);
        memset(out, 0, sizeof out);
        if (size > 0 && size <= (int)sizeof out)
            G(GetCompressedTexImage, GL_TEXTURE_2D, 0, out);
        for (int by = 0; by < bh; by++)
            for (int bx = 0; bx < bw; bx++) {
                if (in_partial(4 * bx, 4 * by, w, h) != cur_partial || chans > 2)
                    continue;
                int nx = w - 4 * bx < 4 ? w - 4 * bx : 4, ny = h - 4 * by < 4 ? h - 4 * by : 4;
                const uint8_t *blk = out + (by * bw + bx) * chans * 8;
                switch (cur->kind) {
                case K_CHANNELS:
                    for (int k = 0; k < chans; k++)
                        put_channel_block(v, n, blk + k * 8, nx, ny);
                    break;
                case K_DXT1: put_colour_block(v, n, blk, nx, ny); break;
                case K_DXT3:
                    put_dxt3_alpha(v, n, blk, nx, ny);
                    put_colour_block(v, n, blk + 8, nx, ny);
                    break;
                case K_DXT5:
                    put_channel_block(v, n, blk, nx, ny);
                    put_colour_block(v, n, blk + 8, nx, ny);
                    break;
                }
            }
    }
    put(v, n, err_of(c));
}

/* Every size and pattern through the four upload paths. */
static void uploads(fs_context *c, double *v, int *n)
{
    static uint8_t img[WIN * WIN * 4], sub[WIN * WIN * 4];
    G(Disable, GL_DITHER);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    for (int s = 0; s < NSIZES; s++)
        for (int p = 0; p < NPAT; p++) {
            int w = sizes[s][0], h = sizes[s][1];
            uint32_t seed = (uint32_t)(s * 16 + p);
            pattern(p, w, h, seed, img);
            G(BindTexture, GL_TEXTURE_2D, 1 + (GLuint)(s * NPAT + p));
            G(TexImage2D, GL_TEXTURE_2D, 0, (GLint)cur->generic, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
            read_level(c, v, n, w, h);
            /* glTexSubImage2D: the last block column / row to the edge,
             * then an aligned 4x4 block inside */
            int x0 = ((w - 1) / 4) * 4, y0 = ((h - 1) / 4) * 4;
            pattern((p + 3) % NPAT, w - x0, h - y0, seed + 1000, sub);
            G(TexSubImage2D, GL_TEXTURE_2D, 0, x0, y0, w - x0, h - y0, GL_RGBA, GL_UNSIGNED_BYTE, sub);
            if (w >= 8 && h >= 8) {
                pattern((p + 5) % NPAT, 4, 4, seed + 2000, sub);
                G(TexSubImage2D, GL_TEXTURE_2D, 0, 4, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, sub);
            }
            read_level(c, v, n, w, h);
            /* glCopyTexImage2D of the image drawn into the window, then
             * glCopyTexSubImage2D of a block of it elsewhere */
            G(RasterPos2f, -1.0f, -1.0f);
            G(DrawPixels, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img);
            G(CopyTexImage2D, GL_TEXTURE_2D, 0, cur->generic, 0, 0, w, h, 0);
            read_level(c, v, n, w, h);
            if (w >= 8 && h >= 4) {
                G(CopyTexSubImage2D, GL_TEXTURE_2D, 0, 4, 0, 1, 1, 4, h < 8 ? h : 4);
                read_level(c, v, n, w, h);
            }
        }
}

/* Runs uploads() for format f on both, reading `part`; the count of
 * values (or 18-value blocks) that differ and their total. */
static bool compare_part(int f, enum part part, bool partial, long *differ, long *total)
{
    static double ref[CAP], mine[CAP];
    int nr, nm;
    cur = &fmts[f];
    cur_part = part;
    cur_partial = partial;
    if (!osm_run_values(uploads, WIN, WIN, ref, &nr, mine, &nm) || nr != nm || nr > CAP)
        return false;
    /* texels: value by value; blocks: by channel block (each starts
     * with BLOCK_MARK; the level's format, size and error values count
     * with the block before them) */
    *differ = *total = 0;
    bool blocks = part == PART_BLOCKS, same = true, any = false;
    for (int i = 0; i <= nr; i++) {
        bool boundary = i == nr || !blocks || ref[i] == BLOCK_MARK;
        if (boundary && any) {
            (*total)++;
            *differ += !same;
            same = true;
            any = false;
        }
        if (i == nr)
            break;
        any = true;
        if (ref[i] != mine[i]) {
            if (same && getenv("ENCODE_DEBUG"))
                fprintf(stderr, "value %d: OSMesa %g, fragsim %g\n", i, ref[i], mine[i]);
            same = false;
        }
    }
    return true;
}

static void check_format(check_state *check_st_, int f)
{
    long dt, tt, db, tb, pdt, ptt, pdb, ptb;
    REQUIRE(compare_part(f, PART_TEXELS, false, &dt, &tt));
    REQUIRE(compare_part(f, PART_BLOCKS, false, &db, &tb));
    REQUIRE(compare_part(f, PART_TEXELS, true, &pdt, &ptt));
    REQUIRE(compare_part(f, PART_BLOCKS, true, &pdb, &ptb));
    printf("  %s: whole blocks: %ld of %ld texel values, %ld of %ld blocks differ; partial blocks: %ld of %ld texel "
           "values, %ld of %ld blocks differ\n",
           fmts[f].name, dt, tt, db, tb, pdt, ptt, pdb, ptb);
    CHECK_EQ_INT(dt, 0);
    CHECK_EQ_INT(db, 0);
}

/* glCompressedTexImage2D of random RGTC / LATC blocks (both endpoint
 * orders, every code), read back by glGetTexImage and drawn: the decoder
 * of the blocks alone. */
static void given_blocks(fs_context *c, double *v, int *n)
{
    enum { S = 16 };
    static uint8_t data[S * S], out[S * S * 4];
    rng r = {77};
    for (int f = 0; f < NCHAN; f++) {
        int bytes = (S / 4) * (S / 4) * (f % 2 ? 16 : 8);
        for (int i = 0; i < bytes; i++)
            data[i] = (uint8_t)rnd(&r);
        G(BindTexture, GL_TEXTURE_2D, 100 + (GLuint)f);
        G(CompressedTexImage2D, GL_TEXTURE_2D, 0, fmts[f].stored, S, S, 0, bytes, data);
        put(v, n, err_of(c));
        memset(out, 0, sizeof out);
        G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
        for (int i = 0; i < S * S * 4; i++)
            put(v, n, out[i]);
    }
}

TEST(given_blocks_vs_osmesa) { OSM_CHECK_VALUES(given_blocks, 8, 8, NCHAN * (16 * 16 * 4 + 1)); }

/* Sampling: each format's texture of every pattern, 32 x 32, drawn
 * NEAREST at one texel per pixel and LINEAR tilted and minified, with
 * GL_REPLACE; the images compared at tolerance 0. */
static void draw_sampled(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    static uint8_t img[32 * 32 * 4];
    G(Viewport, 0, 0, w, h);
    G(Enable, GL_TEXTURE_2D);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < NFMT; f++)
        for (int p = 0; p < NPAT; p++) {
            pattern(p, 32, 32, (uint32_t)(f * 16 + p + 500), img);
            G(BindTexture, GL_TEXTURE_2D, 1 + (GLuint)(f * NPAT + p));
            G(TexImage2D, GL_TEXTURE_2D, 0, (GLint)fmts[f].generic, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
            bool linear = p % 2;
            G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
            G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
            /* tile (f, p) of a 4 x 8 grid of 32 x 32 pixels */
            float x0 = -1.0f + 2.0f * (float)(p * 32) / (float)w, y0 = -1.0f + 2.0f * (float)(f * 32) / (float)h;
            float dx = 64.0f / (float)w, dy = 64.0f / (float)h, t = linear ? 0.3f : 0.0f;
            G(Begin, GL_QUADS);
            G(TexCoord2f, 0.0f, 0.0f); G(Vertex2f, x0, y0);
            G(TexCoord2f, 1.0f + t, t); G(Vertex2f, x0 + dx, y0);
            G(TexCoord2f, 1.0f, 1.0f + t); G(Vertex2f, x0 + dx, y0 + dy);
            G(TexCoord2f, -t, 1.0f); G(Vertex2f, x0, y0 + dy);
            G0(End);
        }
}

TEST(sampled_vs_osmesa)
{
    osm_pair p;
    REQUIRE(osm_pair_render(&p, 32 * NPAT, 32 * NFMT, NULL, draw_sampled, NULL));
    printf("  sampled: %ld of %ld pixels differ (max %d)\n", p.d.differ, p.d.pixels, p.d.maxd);
    CHECK_EQ_INT(p.d.differ, 0);
    osm_pair_close(&p);
}

TEST(red_rgtc1_vs_osmesa) { check_format(check_st_, 0); }
TEST(rg_rgtc2_vs_osmesa) { check_format(check_st_, 1); }
TEST(luminance_latc1_vs_osmesa) { check_format(check_st_, 2); }
TEST(luminance_alpha_latc2_vs_osmesa) { check_format(check_st_, 3); }
TEST(rgb_dxt1_vs_osmesa) { check_format(check_st_, 4); }
TEST(rgba_dxt5_vs_osmesa) { check_format(check_st_, 5); }
TEST(rgba_dxt1_vs_osmesa) { check_format(check_st_, 6); }
TEST(rgba_dxt3_vs_osmesa) { check_format(check_st_, 7); }

TEST_LIST = {
    TEST_ENTRY(red_rgtc1_vs_osmesa),
    TEST_ENTRY(rg_rgtc2_vs_osmesa),
    TEST_ENTRY(luminance_latc1_vs_osmesa),
    TEST_ENTRY(luminance_alpha_latc2_vs_osmesa),
    TEST_ENTRY(rgb_dxt1_vs_osmesa),
    TEST_ENTRY(rgba_dxt5_vs_osmesa),
    TEST_ENTRY(rgba_dxt1_vs_osmesa),
    TEST_ENTRY(rgba_dxt3_vs_osmesa),
    TEST_ENTRY(sampled_vs_osmesa),
    TEST_ENTRY(given_blocks_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
