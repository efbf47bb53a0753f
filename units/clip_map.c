/*
 * The Clip-Map memory model (Tanner, Migdal, Jones, "The Clipmap", SIGGRAPH
 * 1998), as Huettner 1999, 4.1.2 compares it with the MP-Grid: the image is
 * scaled to a square power of two; levels larger than the clip size are
 * clipped to clip x clip texels around the clip centre, the levels below
 * are stored whole.
 */
#include "mpgrid.h"

static bool is_pow2(int64_t x) { return x > 0 && (x & (x - 1)) == 0; }

uint64_t fs_clip_map_bytes(int64_t size, int64_t clip, int bytes_per_texel)
{
    if (!is_pow2(size) || !is_pow2(clip) || clip > size || size > ((int64_t)1 << 30) || bytes_per_texel <= 0)
        return 0;
    uint64_t b = 0;
    for (int64_t s = size;; s /= 2) {
        int64_t side = s < clip ? s : clip;
        b += (uint64_t)side * (uint64_t)side * (uint64_t)bytes_per_texel;
        if (s == 1)
            break;
    }
    return b;
}

int64_t fs_clip_map_scaled_size(int64_t w, int64_t h)
{
    /* 4.1.2: Clip-Maps must be square powers of two; scaling down would
     * lose information, so the larger side is rounded up. */
    if (w <= 0 || h <= 0 || w > ((int64_t)1 << 30) || h > ((int64_t)1 << 30))
        return 0;
    int64_t s = 1, big = w > h ? w : h;
    while (s < big)
        s *= 2;
    return s;
}
