/*
 * PNG files (driver/image_oiio.cpp): what is written must be the
 * framebuffer's bytes.  The oracle is an independent decoder here (the PNG
 * specification's chunks, zlib's inflate and the five row filters), not
 * OpenImageIO itself; OpenImageIO's reader must agree with it.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>
#include "check.h"
#include "../driver/image.h"

static const char *tmp_png(const char *name)
{
    static char path[256];
    snprintf(path, sizeof path, "/tmp/fs_image_test_%ld_%s", (long)getpid(), name);
    return path;
}

static uint32_t be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Decodes an 8-bit, non-interlaced RGB or RGBA PNG: pixels top row first,
 * *channels 3 or 4.  Returns NULL on anything else. */
static unsigned char *png_decode(const char *path, int *w, int *h, int *channels)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *file = malloc((size_t)n), *idat = malloc((size_t)n), *pix = NULL, *raw = NULL;
    size_t nidat = 0;
    int ok = fread(file, 1, (size_t)n, f) == (size_t)n && n > 8 &&
             memcmp(file, "\x89PNG\r\n\x1a\n", 8) == 0;
    fclose(f);
    int nc = 0;
    for (long at = 8; ok && at + 12 <= n;) {
        uint32_t len = be32(file + at);
        const unsigned char *type = file + at + 4, *d = file + at + 8;
        if (at + 12 + (long)len > n)
            ok = 0;
        else if (memcmp(type, "IHDR", 4) == 0) {
            *w = (int)be32(d);
            *h = (int)be32(d + 4);
            nc = d[9] == 6 ? 4 : d[9] == 2 ? 3 : 0;
            ok = d[8] == 8 && nc && d[12] == 0;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            memcpy(idat + nidat, d, len);
            nidat += len;
        }
        at += 12 + (long)len;
    }
    if (ok) {
        size_t stride = (size_t)*w * (size_t)nc;
        uLongf rawlen = (uLongf)((stride + 1) * (size_t)*h);
        raw = malloc(rawlen);
        pix = malloc(stride * (size_t)*h);
        ok = uncompress(raw, &rawlen, idat, (uLong)nidat) == Z_OK &&
             rawlen == (stride + 1) * (size_t)*h;
        for (int y = 0; ok && y < *h; y++) {
            const unsigned char *s = raw + (size_t)y * (stride + 1) + 1;
            unsigned char *o = pix + (size_t)y * stride, *up = y ? o - stride : NULL;
            int filter = s[-1];
            for (size_t i = 0; i < stride; i++) {
                int a = i >= (size_t)nc ? o[i - (size_t)nc] : 0, b = up ? up[i] : 0;
                int c = up && i >= (size_t)nc ? up[i - (size_t)nc] : 0, p;
                switch (filter) {
                case 0: p = 0; break;
                case 1: p = a; break;
                case 2: p = b; break;
                case 3: p = (a + b) / 2; break;
                case 4: p = paeth(a, b, c); break;
                default: ok = 0; p = 0;
                }
                o[i] = (unsigned char)(s[i] + p);
            }
        }
    }
    free(file);
    free(idat);
    free(raw);
    if (!ok) {
        free(pix);
        return NULL;
    }
    *channels = nc;
    return pix;
}

/* A framebuffer (bottom row first) of every alpha value, alpha 0 and 255
 * included, with RGB unrelated to alpha (e.g. 200 under alpha 3). */
static uint8_t *test_framebuffer(int w, int h)
{
    uint8_t *fb = malloc((size_t)w * (size_t)h * 4);
    unsigned seed = 99;
    for (int i = 0; i < w * h; i++) {
        for (int ch = 0; ch < 3; ch++) {
            seed = seed * 1103515245u + 12345u;
            fb[4 * i + ch] = (uint8_t)(seed >> 16);
        }
        fb[4 * i + 3] = (uint8_t)(i % 256);
    }
    fb[3] = 0;
    fb[7] = 255;
    fb[8] = 200; fb[9] = 100; fb[10] = 50; fb[11] = 3;
    return fb;
}

TEST(png_rgba_is_the_framebuffer_byte_for_byte)
{
    const int w = 37, h = 19;
    uint8_t *fb = test_framebuffer(w, h);
    char err[512];
    const char *path = tmp_png("rgba.png");
    REQUIRE(fs_image_write_png(path, fb, w, h, err, sizeof err) == 0);
    int dw = 0, dh = 0, nc = 0;
    unsigned char *pix = png_decode(path, &dw, &dh, &nc);
    REQUIRE(pix != NULL);
    CHECK_EQ_INT(dw, w);
    CHECK_EQ_INT(dh, h);
    CHECK_EQ_INT(nc, 4);
    long bad = 0;
    for (int y = 0; y < h; y++) /* the file's first row is GL's top row */
        bad += memcmp(pix + (size_t)y * w * 4, fb + (size_t)(h - 1 - y) * w * 4, (size_t)w * 4) != 0;
    CHECK_EQ_INT(bad, 0);
    /* OpenImageIO's reader, with unassociated alpha, gives the same bytes */
    uint8_t *back = NULL;
    int bw = 0, bh = 0;
    REQUIRE(fs_image_read(path, &back, &bw, &bh, err, sizeof err) == 0);
    CHECK_EQ_INT(bw, w);
    CHECK_EQ_INT(bh, h);
    CHECK(memcmp(back, fb, (size_t)w * h * 4) == 0);
    free(back);
    free(pix);
    free(fb);
    unlink(path);
}

/* RGB (glretrace's snapshot format): the colour without alpha. */
TEST(png_rgb_drops_alpha_only)
{
    const int w = 5, h = 4;
    uint8_t *fb = test_framebuffer(w, h);
    char err[512];
    const char *path = tmp_png("rgb.png");
    REQUIRE(fs_image_write_png_channels(path, fb, w, h, 3, err, sizeof err) == 0);
    int dw = 0, dh = 0, nc = 0;
    unsigned char *pix = png_decode(path, &dw, &dh, &nc);
    REQUIRE(pix != NULL);
    CHECK_EQ_INT(nc, 3);
    long bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            bad += memcmp(pix + ((size_t)y * w + x) * 3, fb + ((size_t)(h - 1 - y) * w + x) * 4, 3) != 0;
    CHECK_EQ_INT(bad, 0);
    CHECK(fs_image_write_png_channels(path, fb, w, h, 2, err, sizeof err) == -1);
    free(pix);
    free(fb);
    unlink(path);
}

TEST_LIST = {
    TEST_ENTRY(png_rgba_is_the_framebuffer_byte_for_byte),
    TEST_ENTRY(png_rgb_drops_alpha_only),
    TEST_END,
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, test_list);
}
