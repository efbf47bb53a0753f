/*
 * Shared arithmetic of the texture filters (texture_filter.h): wrapped texel
 * fetch, bilinear and trilinear on a read-only MIPmap, the isotropic level
 * of detail.  Double precision: this path serves the filter study and the
 * footprint filters, whose point is quality, not llvmpipe's bit pattern
 * (the GL sampler that must match llvmpipe is texture_sample.c).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "texture_filter.h"

static int is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

int fs_mip_build_box(fs_mip_owned *out, const uint8_t *rgba, int w, int h, GLenum wrap)
{
    memset(out, 0, sizeof *out);
    if (!rgba || !is_pow2(w) || !is_pow2(h) || w > FS_TEX_MAX_SIZE || h > FS_TEX_MAX_SIZE)
        return -1;
    size_t total = 0;
    int levels = 0;
    for (int lw = w, lh = h;; lw = lw > 1 ? lw / 2 : 1, lh = lh > 1 ? lh / 2 : 1) {
        total += (size_t)lw * lh * 4;
        levels++;
        if (lw == 1 && lh == 1)
            break;
    }
    out->store = malloc(total);
    if (!out->store)
        return -1;
    fs_mip_view *v = &out->view;
    v->levels = levels;
    v->wrap_s = v->wrap_t = wrap;
    uint8_t *p = out->store;
    memcpy(p, rgba, (size_t)w * h * 4);
    v->width[0] = w;
    v->height[0] = h;
    v->texels[0] = p;
    for (int l = 1; l < levels; l++) {
        int pw = v->width[l - 1], ph = v->height[l - 1];
        int lw = pw > 1 ? pw / 2 : 1, lh = ph > 1 ? ph / 2 : 1;
        const uint8_t *src = v->texels[l - 1];
        p += (size_t)pw * ph * 4;
        /* A 1-texel-wide side averages only along the other axis. */
        int sx = pw > 1 ? 1 : 0, sy = ph > 1 ? 1 : 0;
        for (int y = 0; y < lh; y++)
            for (int x = 0; x < lw; x++)
                for (int ch = 0; ch < 4; ch++) {
                    int x0 = sx ? 2 * x : x, y0 = sy ? 2 * y : y;
                    unsigned s = src[((size_t)y0 * pw + x0) * 4 + ch] + src[((size_t)y0 * pw + x0 + sx) * 4 + ch] +
                                 src[((size_t)(y0 + sy) * pw + x0) * 4 + ch] +
                                 src[((size_t)(y0 + sy) * pw + x0 + sx) * 4 + ch];
                    p[((size_t)y * lw + x) * 4 + ch] = (uint8_t)((s + 2) / 4);
                }
        v->width[l] = lw;
        v->height[l] = lh;
        v->texels[l] = p;
    }
    return 0;
}

void fs_mip_free(fs_mip_owned *m)
{
    free(m->store);
    memset(m, 0, sizeof *m);
}

static int wrap_index(int i, int n, GLenum wrap)
{
    if (wrap == GL_REPEAT) {
        i %= n;
        return i < 0 ? i + n : i;
    }
    return i < 0 ? 0 : i >= n ? n - 1 : i;
}

void fs_mip_fetch(const fs_mip_view *m, int level, int x, int y, float out[4])
{
    level = level < 0 ? 0 : level >= m->levels ? m->levels - 1 : level;
    int w = m->width[level], h = m->height[level];
    x = wrap_index(x, w, m->wrap_s);
    y = wrap_index(y, h, m->wrap_t);
    const uint8_t *t = m->texels[level] + ((size_t)y * w + x) * 4;
    for (int ch = 0; ch < 4; ch++)
        out[ch] = t[ch] * (1.0f / 255.0f);
}

/* Keeps a coordinate finite and within a range where the int conversion is
 * defined; a huge or NaN coordinate samples some defined texel instead of
 * invoking undefined behaviour. */
static double sane(double x)
{
    if (!(x == x))
        return 0.0;
    return x > 1e9 ? 1e9 : x < -1e9 ? -1e9 : x;
}

/* The clamped level, the block's first texel and the weights of the
 * second: the texel choice of eq. 3.22, shared by the filter and by
 * fs_mip_bilinear_block's report of what it reads. */
static int bilinear_setup(const fs_mip_view *m, int level, double u, double v, int *i0, int *j0, double *a,
                          double *b)
{
    level = level < 0 ? 0 : level >= m->levels ? m->levels - 1 : level;
    /* Level-0 texels to this level's texels, then GL's -0.5 (eq. 3.22). */
    double x = sane(u) * m->width[level] / m->width[0] - 0.5;
    double y = sane(v) * m->height[level] / m->height[0] - 0.5;
    double fx = floor(x), fy = floor(y);
    *i0 = (int)fx;
    *j0 = (int)fy;
    *a = x - fx;
    *b = y - fy;
    return level;
}

int fs_mip_bilinear_block(const fs_mip_view *m, int level, double u, double v, int *x0, int *y0)
{
    double a, b;
    return bilinear_setup(m, level, u, v, x0, y0, &a, &b);
}

int fs_mip_trilinear_levels(const fs_mip_view *m, double lambda, int levels[2])
{
    double top = m->levels - 1;
    if (!(lambda > 0.0) || lambda >= top) {
        levels[0] = lambda >= top ? (int)top : 0;
        return 1;
    }
    levels[0] = (int)floor(lambda);
    levels[1] = levels[0] + 1;
    return 2;
}

int fs_mip_bilinear(const fs_mip_view *m, int level, double u, double v, float out[4])
{
    int i0, j0;
    double a, b;
    level = bilinear_setup(m, level, u, v, &i0, &j0, &a, &b);
    float t00[4], t10[4], t01[4], t11[4];
    fs_mip_fetch(m, level, i0, j0, t00);
    fs_mip_fetch(m, level, i0 + 1, j0, t10);
    fs_mip_fetch(m, level, i0, j0 + 1, t01);
    fs_mip_fetch(m, level, i0 + 1, j0 + 1, t11);
    for (int ch = 0; ch < 4; ch++)
        out[ch] = (float)((1 - a) * (1 - b) * t00[ch] + a * (1 - b) * t10[ch] + (1 - a) * b * t01[ch] +
                          a * b * t11[ch]);
    return 4;
}

int fs_mip_trilinear(const fs_mip_view *m, double lambda, double u, double v, float out[4])
{
    int lv[2];
    if (fs_mip_trilinear_levels(m, lambda, lv) == 1)
        return fs_mip_bilinear(m, lv[0], u, v, out);
    int l0 = lv[0];
    double f = lambda - l0;
    float c0[4], c1[4];
    fs_mip_bilinear(m, l0, u, v, c0);
    fs_mip_bilinear(m, l0 + 1, u, v, c1);
    for (int ch = 0; ch < 4; ch++)
        out[ch] = (float)((1 - f) * c0[ch] + f * c1[ch]);
    return 8;
}

double fs_footprint_lambda_iso(const fs_footprint *fp)
{
    /* Huettner eq. 4.10 (Heckbert's q); GL 1.5 spec eq. 3.19 for rho. */
    double qx = hypot(fp->dudx, fp->dvdx), qy = hypot(fp->dudy, fp->dvdy);
    double q = qx > qy ? qx : qy;
    if (!(q > 0.0))
        return 0.0;
    if (isinf(q))
        return 64.0;
    return log2(q);
}

void fs_footprint_affine_corners(fs_footprint *fp)
{
    static const double sx[4] = {-0.5, 0.5, 0.5, -0.5}, sy[4] = {-0.5, -0.5, 0.5, 0.5};
    for (int i = 0; i < 4; i++) {
        fp->corner_u[i] = fp->u + sx[i] * fp->dudx + sy[i] * fp->dudy;
        fp->corner_v[i] = fp->v + sx[i] * fp->dvdx + sy[i] * fp->dvdy;
    }
}
