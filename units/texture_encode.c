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

void fs_tex_encode_rgtc_channel(uint8_t blk[8], const uint8_t v[16], int nx, int ny)
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
    if ((lo > hi && !(has0 && has255)) || (lo == hi && !has0 && !has255)) {
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
