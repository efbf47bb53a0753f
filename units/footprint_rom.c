/*
 * The weighting ROM of fast footprint filtering (Huettner 1999, 4.3.4,
 * Fig. 4.30-4.31, Table 4.3): for an a x b texel array T, one vector of
 * a*b 8-bit weights per triangle whose corners are snapped positions, and
 * the three-stage pointer structure (one stage per corner) that finds it.
 *
 * Which triangles are stored.  The dissertation stores a triangle when its
 * first two corners lie on the border of T ("two corners always lie on the
 * border", 4.3.4) and the third anywhere else, in that order, without using
 * the symmetry of triangles (4.3.5: no corner reordering hardware).  So the
 * ROM holds pb * (pb-1) * (p-2) vectors for p positions of which pb are on
 * the border: exactly the counting behind the "size of W" column of Table
 * 4.3.  The pointer structure is compact: stage 1 has an entry per border
 * position, stage 2 per ordered pair of border positions, stage 3 per
 * stored triangle, so it encodes only combinations that can occur.
 *
 * The weight of a texel is the exact area of the texel covered by the
 * triangle (in texel units, so a vector sums to the triangle's area),
 * rounded to 8 bits: 255 is a fully covered texel (4.3.4, "a single byte
 * value in [0..255] ... linearly scaled to [0..1]").
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "footprint.h"

/* ---- exact coverage ---- */

/* Clips polygon (n vertices) to the half-plane s * (coord - c) <= 0 on
 * axis `axis` (Sutherland-Hodgman); returns the new vertex count. */
static int clip_half(const double *ix, const double *iy, int n, double *ox, double *oy, int axis, double c,
                     double s)
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        double pk = s * ((axis ? iy[k] : ix[k]) - c), pl = s * ((axis ? iy[l] : ix[l]) - c);
        bool ink = pk <= 0.0, inl = pl <= 0.0;
        if (ink) {
            ox[m] = ix[k];
            oy[m] = iy[k];
            m++;
        }
        if (ink != inl) {
            /* The crossing point; on the clip axis it is exactly c. */
            double t = pk / (pk - pl);
            if (axis) {
                ox[m] = ix[k] + t * (ix[l] - ix[k]);
                oy[m] = c;
            } else {
                ox[m] = c;
                oy[m] = iy[k] + t * (iy[l] - iy[k]);
            }
            m++;
        }
    }
    return m;
}

double fs_fp_triangle_texel_coverage(const double tx[3], const double ty[3], int i, int j)
{
    /* A triangle clipped by 4 half-planes has at most 7 vertices. */
    double ax[12], ay[12], bx[12], by[12];
    memcpy(ax, tx, 3 * sizeof *tx);
    memcpy(ay, ty, 3 * sizeof *ty);
    int n = 3;
    n = clip_half(ax, ay, n, bx, by, 0, (double)i, -1.0);
    n = clip_half(bx, by, n, ax, ay, 0, (double)i + 1.0, 1.0);
    n = clip_half(ax, ay, n, bx, by, 1, (double)j, -1.0);
    n = clip_half(bx, by, n, ax, ay, 1, (double)j + 1.0, 1.0);
    if (n < 3)
        return 0.0;
    double s = 0.0;
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        s += ax[k] * ay[l] - ax[l] * ay[k];
    }
    return fabs(s) * 0.5;
}

/* ---- counting (Table 4.3) ---- */

static void positions(int a, int b, bool midpoint, int *px, int *py)
{
    *px = midpoint ? a : a + 1;
    *py = midpoint ? b : b + 1;
}

void fs_fp_count_shape(int a, int b, bool midpoint, fs_fp_count *out)
{
    memset(out, 0, sizeof *out);
    out->a = a;
    out->b = b;
    out->midpoint = midpoint;
    if (a < 1 || b < 1)
        return;
    int px, py;
    positions(a, b, midpoint, &px, &py);
    long long p = (long long)px * py;
    long long inner = (px > 2 ? px - 2 : 0) * (long long)(py > 2 ? py - 2 : 0);
    long long pb = p - inner;
    out->p = p;
    out->pb = pb;
    out->vectors = pb >= 2 && p >= 3 ? pb * (pb - 1) * (p - 2) : 0;
    out->weights = out->vectors * a * b;
    out->pointers_full = p + p * (p - 1) + p * (p - 1) * (p - 2);
    out->pointers = pb + pb * (pb - 1) + out->vectors;
}

/* Table 4.3 of the dissertation, every row as printed (factors, product,
 * pointers).  "MS gx x gy" names the texel array, "I gx x gy" the grid of
 * integer positions, i.e. (a+1) x (b+1). */
const fs_fp_paper_row fs_fp_paper_table[] = {
    {8, true, 2, 4, 8, 7, 6, 2688, 400},
    {8, false, 3, 5, 12, 11, 13, 13728, 2955},
    {16, true, 4, 4, 12, 11, 14, 29568, 3136},
    {16, true, 2, 8, 16, 15, 14, 53760, 3136},
    {16, false, 5, 5, 12, 11, 23, 48576, 14425},
    {16, false, 3, 9, 20, 19, 23, 139840, 18279},
    {32, true, 2, 16, 32, 31, 30, 952320, 30784},
    {32, true, 4, 8, 20, 19, 30, 364800, 30784},
    {32, false, 3, 17, 36, 35, 49, 1975680, 127551},
    {32, false, 5, 9, 24, 23, 49, 865536, 87165},
    {64, true, 8, 8, 28, 27, 62, 2999808, 254080},
    {64, false, 9, 9, 32, 31, 79, 5015552, 518481},
};
const int fs_fp_paper_table_rows = (int)(sizeof fs_fp_paper_table / sizeof fs_fp_paper_table[0]);

void fs_fp_paper_shape(const fs_fp_paper_row *r, int *a, int *b)
{
    *a = r->midpoint ? r->gx : r->gx - 1;
    *b = r->midpoint ? r->gy : r->gy - 1;
}

int fs_fp_shapes(int M, bool midpoint, int a[8], int b[8])
{
    /* Every power-of-two array with a*b = M and a <= b (the transposed one
     * reads the same ROM, 4.3.4: "2x8 and 8x2 are the same due to
     * symmetry").  A one-texel-wide array is useful only with integer
     * positions (all mid-points of one row are collinear). */
    int n = 0;
    for (int x = midpoint ? 2 : 1; x * x <= M && n < 8; x *= 2) {
        fs_fp_count c;
        fs_fp_count_shape(x, M / x, midpoint, &c);
        /* Tables above FS_FP_ROM_MAX_WEIGHTS are counted, not generated
         * (M = 64: I 1x64 would take 137 MB). */
        if (M % x == 0 && c.weights <= FS_FP_ROM_MAX_WEIGHTS) {
            a[n] = x;
            b[n] = M / x;
            n++;
        }
    }
    return n;
}

/* ---- the ROM ---- */

void fs_fp_rom_free(fs_fp_rom *r)
{
    free(r->border_rank);
    free(r->stage1);
    free(r->stage2);
    free(r->stage3);
    free(r->w);
    memset(r, 0, sizeof *r);
}

bool fs_fp_rom_on_border(const fs_fp_rom *r, int x, int y)
{
    return x >= 0 && y >= 0 && x < r->px && y < r->py && (x == 0 || y == 0 || x == r->px - 1 || y == r->py - 1);
}

static void position_xy(const fs_fp_rom *r, int k, double *x, double *y)
{
    double off = r->midpoint ? 0.5 : 0.0;
    *x = (double)(k % r->px) + off;
    *y = (double)(k / r->px) + off;
}

static void compute_vector(const fs_fp_rom *r, int k1, int k2, int k3, uint8_t *out)
{
    double tx[3], ty[3];
    position_xy(r, k1, &tx[0], &ty[0]);
    position_xy(r, k2, &tx[1], &ty[1]);
    position_xy(r, k3, &tx[2], &ty[2]);
    memset(out, 0, (size_t)r->a * r->b);
    double x0 = fmin(tx[0], fmin(tx[1], tx[2])), x1 = fmax(tx[0], fmax(tx[1], tx[2]));
    double y0 = fmin(ty[0], fmin(ty[1], ty[2])), y1 = fmax(ty[0], fmax(ty[1], ty[2]));
    /* Only texels the triangle's bounding box touches can be covered. */
    int i0 = (int)floor(x0), i1 = (int)ceil(x1), j0 = (int)floor(y0), j1 = (int)ceil(y1);
    for (int j = j0 < 0 ? 0 : j0; j < j1 && j < r->b; j++)
        for (int i = i0 < 0 ? 0 : i0; i < i1 && i < r->a; i++) {
            double c = fs_fp_triangle_texel_coverage(tx, ty, i, j);
            long q = lround(c * 255.0);
            out[i + j * r->a] = (uint8_t)(q < 0 ? 0 : q > 255 ? 255 : q);
        }
}

int fs_fp_rom_build(fs_fp_rom *r, int a, int b, bool midpoint)
{
    memset(r, 0, sizeof *r);
    if (a < 1 || b < 1 || a * b > 64 || (midpoint && (a < 2 || b < 2)))
        return -1;
    fs_fp_count cnt;
    fs_fp_count_shape(a, b, midpoint, &cnt);
    r->a = a;
    r->b = b;
    r->midpoint = midpoint;
    positions(a, b, midpoint, &r->px, &r->py);
    r->p = (int)cnt.p;
    r->pb = (int)cnt.pb;
    int p = r->p, pb = r->pb;
    size_t n2 = (size_t)pb * (size_t)(pb - 1), n3 = (size_t)cnt.vectors, M = (size_t)a * b;
    r->border_rank = malloc((size_t)p * sizeof *r->border_rank);
    r->stage1 = malloc((size_t)pb * sizeof *r->stage1);
    r->stage2 = malloc(n2 * sizeof *r->stage2);
    r->stage3 = malloc(n3 * sizeof *r->stage3);
    r->w = malloc(n3 * M);
    int *border_pos = malloc((size_t)pb * sizeof *border_pos);
    /* The same corner set in another order has the same coverage: computed
     * once, copied (the ROM itself keeps the paper's ordered layout). */
    int32_t *first = malloc((size_t)p * p * p * sizeof *first);
    if (!r->border_rank || !r->stage1 || !r->stage2 || !r->stage3 || !r->w || !border_pos || !first) {
        free(border_pos);
        free(first);
        fs_fp_rom_free(r);
        return -1;
    }
    for (size_t k = 0; k < (size_t)p * p * p; k++)
        first[k] = -1;
    int nb = 0;
    for (int k = 0; k < p; k++) {
        bool on = fs_fp_rom_on_border(r, k % r->px, k / r->px);
        r->border_rank[k] = (int16_t)(on ? nb : -1);
        if (on)
            border_pos[nb++] = k;
    }
    size_t v = 0;
    for (int b1 = 0; b1 < pb; b1++) {
        r->stage1[b1] = (uint32_t)((size_t)b1 * (size_t)(pb - 1));
        for (int b2 = 0; b2 < pb; b2++) {
            if (b2 == b1)
                continue;
            size_t s2 = r->stage1[b1] + (size_t)(b2 - (b2 > b1));
            r->stage2[s2] = (uint32_t)(s2 * (size_t)(p - 2));
            int k1 = border_pos[b1], k2 = border_pos[b2];
            for (int k3 = 0; k3 < p; k3++) {
                if (k3 == k1 || k3 == k2)
                    continue;
                size_t s3 = r->stage2[s2] + (size_t)(k3 - (k3 > k1) - (k3 > k2));
                r->stage3[s3] = (uint32_t)v;
                int lo = k1 < k2 ? k1 : k2, hi = k1 < k2 ? k2 : k1;
                int s0 = k3 < lo ? k3 : lo, s2b = k3 > hi ? k3 : hi, s1 = k1 + k2 + k3 - s0 - s2b;
                size_t key = ((size_t)s0 * p + s1) * p + s2b;
                if (first[key] >= 0)
                    memcpy(r->w + v * M, r->w + (size_t)first[key] * M, M);
                else {
                    compute_vector(r, k1, k2, k3, r->w + v * M);
                    first[key] = (int32_t)v;
                }
                v++;
            }
        }
    }
    r->vectors = v;
    free(border_pos);
    free(first);
    return 0;
}

const uint8_t *fs_fp_rom_lookup(const fs_fp_rom *r, const int x[3], const int y[3])
{
    if (!r->w)
        return NULL;
    int k[3];
    for (int i = 0; i < 3; i++) {
        if (x[i] < 0 || y[i] < 0 || x[i] >= r->px || y[i] >= r->py)
            return NULL;
        k[i] = x[i] + y[i] * r->px;
    }
    if (k[0] == k[1] || k[0] == k[2] || k[1] == k[2])
        return NULL;
    int b1 = r->border_rank[k[0]], b2 = r->border_rank[k[1]];
    if (b1 < 0 || b2 < 0)
        return NULL;
    /* Stage 1 by the first corner, stage 2 by the second (ranked among the
     * border positions without the first), stage 3 by the third (ranked
     * among all positions without the first two). */
    uint32_t s2 = r->stage1[b1] + (uint32_t)(b2 - (b2 > b1));
    uint32_t s3 = r->stage2[s2] + (uint32_t)(k[2] - (k[2] > k[0]) - (k[2] > k[1]));
    return r->w + (size_t)r->stage3[s3] * (size_t)r->a * (size_t)r->b;
}
