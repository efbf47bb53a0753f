/*
 * Block encoders: the blocks llvmpipe (Mesa 22.3) stores when an image is
 * uploaded into a compressed internal format (a generic one of table 3.17,
 * GL 1.5 spec 3.8.1, which Mesa maps to a block format on 2D, cube map and
 * 3D images, or a block format named explicitly): glTexImage,
 * glCopyTexImage and the sub-image updates compress the texels with
 * Mesa's own encoders, and sampling decodes those blocks.  GL leaves the
 * encoder open; bit-exact rendering needs Mesa's choices, so these follow
 * its algorithms, written from their description here (facts read from
 * Mesa's src/util/texcompress_rgtc_tmp.h, included by
 * src/util/format/u_format_rgtc.c and src/mesa/main/texcompress_rgtc.c;
 * measured block for block through OSMesa, tests/test_texture_encode.c).
 *
 * RGTC / LATC channel (one 8-byte block: two 8-bit endpoints e0, e1 and
 * sixteen 3-bit codes, pixel (i, j) at bits 16 + 3 (4 j + i)).  Mesa does
 * not search the endpoints; it tries up to three fixed candidates and
 * keeps the one with the least summed squared error (ties to the earlier):
 *
 *   0. Shortcut: when the block holds no value strictly between 0 and 255
 *      but only one of those two, or a single such value and neither
 *      extreme, e0 is the first pixel's value and every code 0 (e1 is not
 *      written at all: its byte keeps what the memory held).
 *   1. Eight-value mode (e0 > e1): e0 the largest inner value (255 if a
 *      pixel is 255), e1 the smallest (0 if a pixel is 0).  Each pixel is
 *      coded by cuts t_a = floor((e1 (2a+1) + e0 (13-2a)) / 14), a = 0..6,
 *      taken in order: v > t_0 is code 0 (e0), v > t_a code a+1 for a of
 *      1..6, else code 1 (e1); its reconstruction for the error is
 *      floor((e0 (8-c) + e1 (c-1)) / 7) (not the decoder's value).
 *   2. Six-value mode (e0 <= e1), tried when error 1 is 32 or more:
 *      e0, e1 the smallest and largest inner values; 0 and 255 are
 *      codes 6 and 7 (no error); otherwise cuts u_a = floor((e0 (9-2a) +
 *      e1 (2a+1)) / 10), a = 0..4: v <= u_0 code 0, v <= u_a code a+1,
 *      else code 1, reconstructed as floor((e0 (5-k) + e1 k) / 5), k the
 *      step (0 for e0 .. 5 for e1).
 *   3. Six-value mode with moved endpoints, tried when errors 1 and 2 are
 *      both above 96: from lo, hi = the smallest value above r/28 and the
 *      largest below 255 - r/28 (r the inner range; 1 and 254 if none
 *      qualify), each endpoint moves by the truncated mean difference of
 *      the pixels coded near it (not those at most lo/2 or above
 *      (255 + hi)/2, which will be codes 6 and 7), clamped to 0..255; the
 *      pixels are then coded as in 2 with those endpoints, v <= lo/2 as
 *      code 6 and v > (255 + hi)/2 as code 7 (their errors v and 255 - v).
 *
 * Only the pixels inside the image are coded (a partial block at an edge:
 * Mesa leaves the codes of the others as whatever its stack held; here
 * they are 0, which no texel reads).  Mesa keeps the cut values in the
 * channel's type (8 bits), the endpoint sums in 16-bit integers; the
 * arithmetic below is the same in int, with the 8-bit casts kept where
 * they can change a value.
 */
#include <string.h>
#include "texture_priv.h"

/* The cuts of six-value mode between lo and hi (modes 2 and 3). */
static void six_cuts(int lo, int hi, int cut[5])
{
    for (int a = 0; a < 5; a++)
        cut[a] = (uint8_t)((lo * (9 - 2 * a) + hi * (2 * a + 1)) / 10);
}

/* The code and reconstructed value of v between lo and hi in six-value
 * mode (after the 0 / 255 cases, which the modes treat differently). */
static int six_code(int v, int lo, int hi, const int cut[5], int *rec)
{
    for (int a = 0; a < 5; a++)
        if (v <= cut[a]) {
            *rec = (lo * (5 - a) + hi * a) / 5;
            return a == 0 ? 0 : a + 1;
        }
    *rec = hi;
    return 1;
}

static void pack_codes(uint8_t blk[8], int e0, int e1, const uint8_t code[16])
{
    uint64_t bits = 0;
    for (int p = 15; p >= 0; p--)
        bits = bits << 3 | (code[p] & 7u);
    blk[0] = (uint8_t)e0;
    blk[1] = (uint8_t)e1;
    for (int k = 0; k < 6; k++)
        blk[2 + k] = (uint8_t)(bits >> (8 * k));
}

/* One channel block; single: whether the one-value shortcut also takes a
 * block of a single inner value (RGTC's encoder does, DXT5's alpha
 * encoder does not: it only takes blocks of 0s or of 255s). */
static void channel_block(uint8_t blk[8], const uint8_t v[16], int nx, int ny, bool single)
{
    int lo = 255, hi = 0; /* the inner values' range */
    bool has0 = false, has255 = false;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int x = v[4 * j + i];
            if (x == 0)
                has0 = true;
            else if (x == 255)
                has255 = true;
            else {
                hi = x > hi ? x : hi;
                lo = x < lo ? x : lo;
            }
        }
    /* 0. the shortcut (byte 1 written as 0 here: Mesa leaves it) */
    if ((lo > hi && !(has0 && has255)) || (single && lo == hi && !has0 && !has255)) {
        memset(blk, 0, 8);
        blk[0] = v[0];
        return;
    }
    uint8_t code1[16] = {0}, code2[16] = {0}, code3[16] = {0};
    unsigned err1 = 0, err2 = 0xffffffffu, err3 = 0xffffffffu;
    /* 1. eight-value mode */
    int e1 = has0 ? 0 : lo, e0 = has255 ? 255 : hi;
    int cut8[7];
    for (int a = 0; a < 7; a++)
        cut8[a] = (e1 * (2 * a + 1) + e0 * (13 - 2 * a)) / 14;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int x = v[4 * j + i], c = 1, rec = e1;
            for (int a = 0; a < 7; a++)
                if (x > cut8[a]) {
                    c = a == 0 ? 0 : a + 1;
                    rec = a == 0 ? e0 : (e0 * (7 - a) + e1 * a) / 7;
                    break;
                }
            code1[4 * j + i] = (uint8_t)c;
            err1 += (unsigned)((x - rec) * (x - rec));
        }
    int tlo = 0, thi = 0;
    if (err1 >= 32) {
        /* 2. six-value mode between the inner extremes */
        int cut[5];
        six_cuts(lo, hi, cut);
        err2 = 0;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                int x = v[4 * j + i], rec = x, c;
                if (x == 0)
                    c = 6;
                else if (x == 255)
                    c = 7;
                else
                    c = six_code(x, lo, hi, cut, &rec);
                code2[4 * j + i] = (uint8_t)c;
                err2 += (unsigned)((x - rec) * (x - rec));
            }
        if (err2 > 96 && err1 > 96) {
            /* 3. six-value mode with the endpoints moved */
            int r28 = (hi - lo) / 28;
            tlo = 255;
            thi = 0;
            for (int j = 0; j < ny; j++)
                for (int i = 0; i < nx; i++) {
                    int x = v[4 * j + i];
                    if (x > thi && x < 255 - r28)
                        thi = x;
                    if (x < tlo && x > r28)
                        tlo = x;
                }
            if (thi <= tlo) {
                tlo = 1;
                thi = 254;
            }
            six_cuts(tlo, thi, cut);
            int sum_lo = 0, sum_hi = 0, n_lo = 0, n_hi = 0;
            for (int j = 0; j < ny; j++)
                for (int i = 0; i < nx; i++) {
                    int x = v[4 * j + i], rec;
                    if (x <= tlo / 2 || x > (255 + thi) / 2)
                        continue;
                    int c = six_code(x, tlo, thi, cut, &rec);
                    if (c != 1) { /* near the low end: codes 0, 2..5 */
                        sum_lo += x - rec;
                        n_lo++;
                    }
                    if (c != 0) { /* near the high end: codes 2..5, 1 */
                        sum_hi += x - rec;
                        n_hi++;
                    }
                }
            tlo += sum_lo / (n_lo ? n_lo : 1);
            tlo = tlo < 0 ? 0 : tlo;
            thi += sum_hi / (n_hi ? n_hi : 1);
            thi = thi > 255 ? 255 : thi;
            six_cuts(tlo, thi, cut);
            err3 = 0;
            for (int j = 0; j < ny; j++)
                for (int i = 0; i < nx; i++) {
                    int x = v[4 * j + i], rec, c;
                    if (x <= tlo / 2)
                        c = 6, rec = 0;
                    else if (x > (255 + thi) / 2)
                        c = 7, rec = 255;
                    else
                        c = six_code(x, tlo, thi, cut, &rec);
                    code3[4 * j + i] = (uint8_t)c;
                    err3 += (unsigned)((x - rec) * (x - rec));
                }
        }
    }
    if (err1 <= err2 && err1 <= err3)
        pack_codes(blk, e0, e1, code1);
    else if (err2 <= err3)
        pack_codes(blk, lo, hi, code2);
    else
        pack_codes(blk, tlo, thi, code3);
}

void fs_tex_encode_rgtc_channel(uint8_t blk[8], const uint8_t v[16], int nx, int ny)
{
    channel_block(blk, v, nx, ny, true);
}

void fs_tex_encode_dxt5_alpha(uint8_t blk[8], const uint8_t v[16], int nx, int ny)
{
    channel_block(blk, v, nx, ny, false);
}

void fs_tex_encode_dxt3_alpha(uint8_t blk[8], const uint8_t px[16][4])
{
    /* EXT_texture_compression_s3tc's DXT3 alpha: 4 bits a pixel, Mesa
     * keeps the top four of each alpha. */
    for (int k = 0; k < 8; k++)
        blk[k] = (uint8_t)((px[2 * k][3] >> 4) | (px[2 * k + 1][3] & 0xf0));
}

/* ---- S3TC colour blocks (DXT1, and the colour half of DXT3 / DXT5) ----
 *
 * Mesa's encoder (libtxc_dxtn's, src/util/format/texcompress_s3tc_tmp.h,
 * facts read there) measures colours by a luminance-weighted squared
 * distance, 4 dr^2 + 16 dg^2 + db^2 (wdist below), and:
 *
 *   1. takes as base colours the block's pixels of the largest and the
 *      smallest weighted length 4 r^2 + 16 g^2 + b^2 (both start as the
 *      first pixel; a later pixel replaces the high one when strictly
 *      longer, else the low one when strictly shorter; an RGBA_DXT1 pixel
 *      of alpha <= 127 is skipped and marks the block as having alpha);
 *   2. orders them by their 565 value (a the smaller, ties swapped), codes
 *      each pixel to the nearest of a, b, (2a + b)/3, (a + 2b)/3 (8-bit
 *      values, truncated; ties to the earlier), sums the signed per-channel
 *      differences weighted 3:0, 2:1, 1:2, 0:3 towards a and b, and moves
 *      each by its sum over its weight count (truncated toward zero,
 *      clamped to 0..255);
 *   3. when the two end within 8 / 4 / 8 of each other (r / g / b), pushes
 *      them apart by a factor (2, 3 or 4 by the largest difference, green
 *      counted twice) times the differences, each clamped to 255 (the red
 *      test compares red with the other colour's green: Mesa's);
 *   4. orders them again, the right side's blue shifted with the whole
 *      565 value (Mesa's parenthesis), truncates both to 565 (not
 *      expanded: 8-bit values with the low bits 0), makes color0 the
 *      larger 565 value and codes each pixel among the four colours as in
 *      2 (error summed); for DXT1 also among color0, color1 and their
 *      average (b0 + b1)/2 with code 3 for RGBA_DXT1 pixels of alpha <=
 *      127, and writes that three-colour block (color1 first) when its
 *      error is strictly smaller or the block has alpha.
 *
 * Only the pixels inside the image take part; the codes of the others are
 * 0 (Mesa builds the code word from the inside pixels only). */

static unsigned wdist(const uint8_t *p, const int *c)
{
    int dr = p[0] - c[0], dg = p[1] - c[1], db = p[2] - c[2];
    return (unsigned)(dr * dr * 4 + dg * dg * 16 + db * db);
}

static int pack565(const int *c) { return (c[0] & 0xf8) << 8 | (c[1] & 0xfc) << 3 | c[2] >> 3; }

static void four_colours(const int a[3], const int b[3], int cv[4][3])
{
    for (int k = 0; k < 3; k++) {
        cv[0][k] = a[k];
        cv[1][k] = b[k];
        cv[2][k] = (a[k] * 2 + b[k]) / 3;
        cv[3][k] = (a[k] + b[k] * 2) / 3;
    }
}

/* The nearest of the first n colours (ties to the earlier). */
static int nearest(const uint8_t *p, int cv[][3], int n, unsigned *err)
{
    unsigned best = 0xffffffffu;
    int enc = 0;
    for (int c = 0; c < n; c++) {
        unsigned e = wdist(p, cv[c]);
        if (e < best) {
            best = e;
            enc = c;
        }
    }
    *err = best;
    return enc;
}

static int iabs(int x) { return x < 0 ? -x : x; }

/* Step 2 and 3: the refined base colours (in t[0], t[1]). */
static void refine(const uint8_t px[16][4], int nx, int ny, int t[2][3])
{
    int cv[4][3], lin[2][3] = {{0}}, nr[2] = {0, 0};
    four_colours(t[0], t[1], cv);
    /* the weight of a pixel's error towards a and b, by its code */
    static const int wa[4] = {3, 0, 2, 1}, wb[4] = {0, 3, 1, 2};
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const uint8_t *p = px[4 * j + i];
            unsigned e;
            int enc = nearest(p, cv, 4, &e);
            for (int k = 0; k < 3; k++) {
                lin[0][k] += wa[enc] * (p[k] - cv[enc][k]);
                lin[1][k] += wb[enc] * (p[k] - cv[enc][k]);
            }
            nr[0] += wa[enc];
            nr[1] += wb[enc];
        }
    for (int s = 0; s < 2; s++)
        for (int k = 0; k < 3; k++) {
            int v = t[s][k] + lin[s][k] / (nr[s] ? nr[s] : 1);
            t[s][k] = v <= 0 ? 0 : v >= 255 ? 255 : v;
        }
    int dr = iabs(t[0][0] - t[1][0]), dg = iabs(t[0][1] - t[1][1]), db = iabs(t[0][2] - t[1][2]);
    if (dr < 8 && dg < 4 && db < 8) {
        /* so close they might become one 565 value: push them apart */
        dg *= 2;
        int m = dr > dg ? dr : dg;
        m = m > db ? m : db;
        if (m > 0) {
            int f = m > 4 ? 2 : m > 2 ? 3 : 4;
            int hi = t[1][1] >= t[0][1] ? 1 : 0, lo = 1 - hi;
            t[hi][1] = t[hi][1] + f * dg <= 255 ? t[hi][1] + f * dg : 255;
            int r = t[hi][0] - t[lo][1] > 0 ? hi : lo; /* red against green: Mesa's */
            t[r][0] = t[r][0] + f * dr <= 255 ? t[r][0] + f * dr : 255;
            int b = t[hi][2] - t[lo][2] > 0 ? hi : lo;
            t[b][2] = t[b][2] + f * db <= 255 ? t[b][2] + f * db : 255;
        }
    }
}

void fs_tex_encode_dxt_colour(uint8_t blk[8], const uint8_t px[16][4], int nx, int ny, int mode)
{
    bool punch = mode == FS_DXT_RGBA1, alpha = false;
    /* 1. the longest and shortest pixels */
    const uint8_t *lo = px[0], *hi = px[0];
    unsigned lowcv = (unsigned)(px[0][0] * px[0][0] * 4 + px[0][1] * px[0][1] * 16 + px[0][2] * px[0][2]);
    unsigned highcv = lowcv;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const uint8_t *p = px[4 * j + i];
            if (punch && p[3] <= 127) {
                alpha = true;
                continue;
            }
            unsigned v = (unsigned)(p[0] * p[0] * 4 + p[1] * p[1] * 16 + p[2] * p[2]);
            if (v > highcv) {
                highcv = v;
                hi = p;
            } else if (v < lowcv) {
                lowcv = v;
                lo = p;
            }
        }
    /* 2. ordered by 565 value (ties swapped), refined */
    int t[2][3];
    int lo3[3] = {lo[0], lo[1], lo[2]}, hi3[3] = {hi[0], hi[1], hi[2]};
    bool keep = pack565(lo3) < pack565(hi3);
    memcpy(t[0], keep ? lo3 : hi3, sizeof t[0]);
    memcpy(t[1], keep ? hi3 : lo3, sizeof t[1]);
    refine(px, nx, ny, t);
    /* 4. ordered again (the right side's blue shifted with the rest) */
    int rhs = ((t[1][0] & 0xf8) << 8 | (t[1][1] & 0xfc) << 3 | t[1][2]) >> 3;
    int b[2][3];
    bool first = pack565(t[0]) < rhs;
    for (int k = 0; k < 3; k++) {
        int m = k == 1 ? 0xfc : 0xf8;
        b[0][k] = (first ? t[0][k] : t[1][k]) & m;
        b[1][k] = (first ? t[1][k] : t[0][k]) & m;
    }
    int c0 = pack565(b[0]), c1 = pack565(b[1]);
    if (c0 < c1) {
        int tmp[3];
        memcpy(tmp, b[0], sizeof tmp);
        memcpy(b[0], b[1], sizeof tmp);
        memcpy(b[1], tmp, sizeof tmp);
        int tc = c0;
        c0 = c1;
        c1 = tc;
    }
    int cv[4][3];
    four_colours(b[0], b[1], cv);
    uint32_t bits = 0, bits2 = 0;
    unsigned err = 0, err2 = 0xffffffffu;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            unsigned e;
            int enc = nearest(px[4 * j + i], cv, 4, &e);
            err += e;
            bits |= (uint32_t)enc << (2 * (4 * j + i));
        }
    if (mode != FS_DXT_FOUR) {
        for (int k = 0; k < 3; k++) {
            cv[2][k] = (b[0][k] + b[1][k]) / 2;
            cv[3][k] = 0;
        }
        err2 = 0;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                const uint8_t *p = px[4 * j + i];
                unsigned e = 0;
                int enc = 3;
                if (!(punch && p[3] <= 127)) {
                    enc = nearest(p, cv, 3, &e);
                    enc = enc > 1 ? enc : enc ^ 1; /* color0 and color1 swap places */
                }
                err2 += e;
                bits2 |= (uint32_t)enc << (2 * (4 * j + i));
            }
    }
    bool three = err > err2 || alpha;
    int w0 = three ? c1 : c0, w1 = three ? c0 : c1;
    uint32_t w = three ? bits2 : bits;
    blk[0] = (uint8_t)w0;
    blk[1] = (uint8_t)(w0 >> 8);
    blk[2] = (uint8_t)w1;
    blk[3] = (uint8_t)(w1 >> 8);
    for (int k = 0; k < 4; k++)
        blk[4 + k] = (uint8_t)(w >> (8 * k));
}
