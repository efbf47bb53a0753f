/* Image and depth comparison statistics used by `fragsim check` and `fragsim diff`. */
#include <math.h>
#include <stdlib.h>
#include "image.h"

void fs_image_compare(const uint8_t *a, const uint8_t *b, int width, int height, fs_image_diff *out)
{
    uint64_t n = (uint64_t)width * (uint64_t)height, differ = 0, by1 = 0;
    double sq = 0;
    int maxd = 0;
    for (uint64_t i = 0; i < n; i++) {
        int pm = 0;
        for (int ch = 0; ch < 4; ch++) {
            int d = abs((int)a[4 * i + ch] - (int)b[4 * i + ch]);
            if (d > pm)
                pm = d;
            if (ch < 3)
                sq += (double)d * d;
        }
        if (pm > maxd)
            maxd = pm;
        differ += pm != 0;
        by1 += pm == 1;
    }
    out->pixels = n;
    out->pixels_differ = differ;
    out->pixels_within_1 = by1;
    out->pixels_beyond_1 = differ - by1;
    out->max_diff = maxd;
    double mse = n ? sq / (3.0 * (double)n) : 0;
    out->psnr = mse > 0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
}

void fs_depth_compare(const uint32_t *a, const uint32_t *b, int width, int height, fs_image_diff *out)
{
    uint64_t n = (uint64_t)width * (uint64_t)height, differ = 0;
    uint32_t maxd = 0;
    for (uint64_t i = 0; i < n; i++) {
        uint32_t d = a[i] > b[i] ? a[i] - b[i] : b[i] - a[i];
        differ += d != 0;
        if (d > maxd)
            maxd = d;
    }
    out->depth_differ = differ;
    out->depth_max_diff = maxd;
}
