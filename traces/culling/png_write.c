/* A minimal PNG writer (PNG spec, ISO/IEC 15948: signature, IHDR, one IDAT
 * of zlib-compressed filter-0 scanlines, IEND): 8-bit RGBA, top row first. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include "cull.h"

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static int chunk(FILE *f, const char *type, const unsigned char *data, uint32_t len)
{
    unsigned char hdr[8];
    put32(hdr, len);
    memcpy(hdr + 4, type, 4);
    uLong crc = crc32(crc32(0L, Z_NULL, 0), hdr + 4, 4);
    if (len) crc = crc32(crc, data, len);
    unsigned char tail[4];
    put32(tail, (uint32_t)crc);
    return fwrite(hdr, 1, 8, f) == 8 && (!len || fwrite(data, 1, len, f) == len) && fwrite(tail, 1, 4, f) == 4;
}

int cull_write_png(const char *path, const unsigned char *rgba, int w, int h)
{
    size_t stride = (size_t)w * 4, raw_len = (stride + 1) * (size_t)h;
    unsigned char *raw = malloc(raw_len);
    uLongf z_len = compressBound((uLong)raw_len);
    unsigned char *z = malloc(z_len);
    int ok = raw && z;
    for (int y = 0; ok && y < h; y++) {
        raw[(stride + 1) * (size_t)y] = 0; /* filter type None */
        memcpy(raw + (stride + 1) * (size_t)y + 1, rgba + stride * (size_t)y, stride);
    }
    ok = ok && compress2(z, &z_len, raw, (uLong)raw_len, 6) == Z_OK;
    FILE *f = ok ? fopen(path, "wb") : NULL;
    if (f) {
        static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
        unsigned char ihdr[13];
        put32(ihdr, (uint32_t)w);
        put32(ihdr + 4, (uint32_t)h);
        ihdr[8] = 8;  /* bit depth */
        ihdr[9] = 6;  /* colour type RGBA */
        ihdr[10] = ihdr[11] = ihdr[12] = 0;
        ok = fwrite(sig, 1, 8, f) == 8 && chunk(f, "IHDR", ihdr, 13) && chunk(f, "IDAT", z, (uint32_t)z_len) &&
             chunk(f, "IEND", NULL, 0);
        ok = fclose(f) == 0 && ok;
    } else {
        ok = 0;
    }
    free(raw);
    free(z);
    return ok ? 0 : -1;
}
