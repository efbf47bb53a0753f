/*
 * Reference texture filters and the study's ground-plane scene
 * (texture_reference.h).  Every filter samples through texture_filter.c's
 * fs_mip_bilinear / fs_mip_trilinear / fs_mip_fetch, so the study compares
 * footprint shapes and weights, not different interpolation code.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "texture_reference.h"

#define PI 3.14159265358979323846

/* ---- common ------------------------------------------------------------ */

static bool finite4(double a, double b, double c, double d)
{
    return isfinite(a) && isfinite(b) && isfinite(c) && isfinite(d);
}

/* A copy of the footprint whose centre is finite and bounded, so that any
 * filter reads defined texels; reports whether the Jacobian is usable. */
static bool sanitize(const fs_footprint *in, fs_footprint *fp)
{
    *fp = *in;
    if (!isfinite(fp->u) || fabs(fp->u) > 1e9)
        fp->u = 0;
    if (!isfinite(fp->v) || fabs(fp->v) > 1e9)
        fp->v = 0;
    return finite4(fp->dudx, fp->dvdx, fp->dudy, fp->dvdy) &&
           fabs(fp->dudx) + fabs(fp->dvdx) + fabs(fp->dudy) + fabs(fp->dvdy) < 1e12;
}

static void out_init(fs_filter_out *out)
{
    memset(out, 0, sizeof *out);
}

/* Unusable derivatives (NaN, infinite, absurd): the footprint covers "all of
 * the texture", whose prefiltered value is the top level. */
static void fallback_top(const fs_mip_view *m, const fs_footprint *fp, fs_filter_out *out)
{
    out_init(out);
    int top = m->levels - 1;
    out->texels = fs_mip_bilinear(m, top, fp->u, fp->v, out->rgba);
    out->level = (float)top;
}

/* Distinct texel addresses touched by one pixel, for the study's cost
 * column.  The addressing mirrors fs_mip_bilinear (GL 1.5 eq. 3.22 and the
 * view's wrap modes); it only counts, the colours come from fs_mip_*. */
#define SET_SLOTS 1024
typedef struct texel_set {
    uint64_t key[SET_SLOTS];
    int used[SET_SLOTS];
    int n;
} texel_set;

static void set_clear(texel_set *s)
{
    for (int i = 0; i < s->n; i++)
        s->key[s->used[i]] = 0;
    s->n = 0;
}

static void set_add(texel_set *s, int level, int x, int y)
{
    uint64_t k = ((uint64_t)(level + 1) << 48) | ((uint64_t)(uint32_t)y << 24) | (uint32_t)x;
    uint32_t h = (uint32_t)((k * 0x9E3779B97F4A7C15ull) >> 40) & (SET_SLOTS - 1);
    if (s->n >= SET_SLOTS / 2)
        return;    /* cannot happen with the filters' probe limits */
    while (s->key[h]) {
        if (s->key[h] == k)
            return;
        h = (h + 1) & (SET_SLOTS - 1);
    }
    s->key[h] = k;
    s->used[s->n++] = (int)h;
}

static int wrap_coord(int i, int n, GLenum wrap)
{
    if (wrap == GL_REPEAT)
        return i & (n - 1);    /* levels are powers of two */
    return i < 0 ? 0 : i >= n ? n - 1 : i;
}

static void count_bilinear(texel_set *s, const fs_mip_view *m, int level, double u, double v)
{
    level = level < 0 ? 0 : level >= m->levels ? m->levels - 1 : level;
    int w = m->width[level], h = m->height[level];
    double x = u * w / m->width[0] - 0.5, y = v * h / m->height[0] - 0.5;
    x = x > 1e9 ? 1e9 : x < -1e9 ? -1e9 : x;
    y = y > 1e9 ? 1e9 : y < -1e9 ? -1e9 : y;
    int i0 = (int)floor(x), j0 = (int)floor(y);
    for (int dj = 0; dj < 2; dj++)
        for (int di = 0; di < 2; di++)
            set_add(s, level, wrap_coord(i0 + di, w, m->wrap_s), wrap_coord(j0 + dj, h, m->wrap_t));
}

/* Same level choice as fs_mip_trilinear. */
static void count_trilinear(texel_set *s, const fs_mip_view *m, double lambda, double u, double v)
{
    int top = m->levels - 1;
    if (!(lambda > 0.0))
        count_bilinear(s, m, 0, u, v);
    else if (lambda >= top)
        count_bilinear(s, m, top, u, v);
    else {
        int l0 = (int)floor(lambda);
        count_bilinear(s, m, l0, u, v);
        count_bilinear(s, m, l0 + 1, u, v);
    }
}

/* N trilinear probes at level lambda, centred on the footprint centre and
 * spaced (du, dv), equally weighted: the sampling both footprint assembly
 * and the EXT N-probe filter use. */
static void probe_filter(const fs_mip_view *m, const fs_footprint *fp, int n, double lambda, double du,
                         double dv, fs_filter_out *out)
{
    out_init(out);
    double acc[4] = {0, 0, 0, 0};
    texel_set set;
    memset(set.key, 0, sizeof set.key);
    set.n = 0;
    for (int i = 0; i < n; i++) {
        double o = i - (n - 1) * 0.5;
        double u = fp->u + o * du, v = fp->v + o * dv;
        float c[4];
        fs_mip_trilinear(m, lambda, u, v, c);
        count_trilinear(&set, m, lambda, u, v);
        for (int ch = 0; ch < 4; ch++)
            acc[ch] += c[ch];
    }
    for (int ch = 0; ch < 4; ch++)
        out->rgba[ch] = (float)(acc[ch] / n);
    out->texels = set.n;
    double top = m->levels - 1;
    out->level = (float)(!(lambda > 0) ? 0 : lambda > top ? top : lambda);
    out->cls = n;
    set_clear(&set);
}

/* ---- footprint assembly -------------------------------------------------- */

/* Dissertation eq. 4.12-4.13 after Texram: the pixel is the parallelogram
 * spanned by r1 = (du/dx, dv/dx) and r2 = (du/dy, dv/dy), with diagonals
 * d1 = r1 + r2 and d2 = r1 - r2.  Our reading of eq. 4.13: q is the
 * smallest of the four lengths |r1|, |r2|, |d1|, |d2| (the side of the
 * square MIPmap texel, a lower bound of the parallelogram's width), N the
 * longer side over q rounded to the nearest power of two (in the log
 * domain), and the N probes step along the longer of r1, r2 by r / N at
 * level log2 q.  When N exceeds max_n, N = max_n and q grows to
 * max(|r1|,|r2|) / N so the probes still cover the footprint. */
int fs_fa_plan(const fs_footprint *fp, const fs_fa_params *p, double *lambda, double *du, double *dv)
{
    int max_n = p && p->max_n >= 1 ? (p->max_n > 64 ? 64 : p->max_n) : 16;
    double l1 = hypot(fp->dudx, fp->dvdx), l2 = hypot(fp->dudy, fp->dvdy);
    double d1 = hypot(fp->dudx + fp->dudy, fp->dvdx + fp->dvdy);
    double d2 = hypot(fp->dudx - fp->dudy, fp->dvdx - fp->dvdy);
    double lmax = l1 > l2 ? l1 : l2;
    double rx = l1 >= l2 ? fp->dudx : fp->dudy, ry = l1 >= l2 ? fp->dvdx : fp->dvdy;
    double q = fmin(fmin(l1, l2), fmin(d1, d2));
    int n = 1;
    if (!(lmax > 0) || !isfinite(lmax)) {
        *lambda = isfinite(lmax) ? 0.0 : 1e3;
        *du = *dv = 0;
        return 1;
    }
    double e = q > 0 ? round(log2(lmax / q)) : INFINITY;
    if (e > log2(max_n)) {
        n = max_n;
        q = lmax / n;
    } else
        n = 1 << (int)e;
    *lambda = q > 0 ? log2(q) : 0.0;
    *du = rx / n;
    *dv = ry / n;
    return n;
}

void fs_filter_footprint_assembly(const fs_mip_view *m, const fs_footprint *in, const void *params,
                                  fs_filter_out *out)
{
    fs_footprint fp;
    if (!sanitize(in, &fp)) {
        fallback_top(m, &fp, out);
        return;
    }
    double lambda, du, dv;
    int n = fs_fa_plan(&fp, params, &lambda, &du, &dv);
    probe_filter(m, &fp, n, lambda, du, dv, out);
}

/* ---- EXT_texture_filter_anisotropic-style N-probe ------------------------ */

/* The extension's recommended implementation (Issues section):
 * Px = |r1|, Py = |r2|, Pmax = max, Pmin = min,
 * N = min(ceil(Pmax / Pmin), maxAniso), lambda' = log2(Pmax / N),
 * N probes along the major axis averaged.  max_aniso 1 is GL's isotropic
 * filtering (N = 1, lambda' = log2 Pmax = fs_footprint_lambda_iso). */
int fs_aniso_plan(const fs_footprint *fp, const fs_aniso_params *p, double *lambda, double *du, double *dv)
{
    double maxa = p && p->max_aniso >= 1 ? floor(p->max_aniso) : 1;
    if (maxa > 64)
        maxa = 64;    /* the probe counter's capacity */
    double px = hypot(fp->dudx, fp->dvdx), py = hypot(fp->dudy, fp->dvdy);
    double pmax = px > py ? px : py, pmin = px > py ? py : px;
    double rx = px >= py ? fp->dudx : fp->dudy, ry = px >= py ? fp->dvdx : fp->dvdy;
    if (!(pmax > 0) || !isfinite(pmax)) {
        *lambda = isfinite(pmax) ? 0.0 : 1e3;
        *du = *dv = 0;
        return 1;
    }
    double ratio = pmin > 0 ? ceil(pmax / pmin) : maxa;
    int n = (int)(ratio < maxa ? ratio : maxa);
    *lambda = log2(pmax / n);
    *du = rx / n;
    *dv = ry / n;
    return n;
}

void fs_filter_aniso(const fs_mip_view *m, const fs_footprint *in, const void *params, fs_filter_out *out)
{
    fs_footprint fp;
    if (!sanitize(in, &fp)) {
        fallback_top(m, &fp, out);
        return;
    }
    double lambda, du, dv;
    int n = fs_aniso_plan(&fp, params, &lambda, &du, &dv);
    probe_filter(m, &fp, n, lambda, du, dv, out);
}

/* ---- EWA ----------------------------------------------------------------- */

static const fs_ewa_params ewa_default = {0.5, 2.0, 0.5, 1.0, 16.0, 4096};

/* Heckbert 1989, 3.5.8: a circular Gaussian on the screen maps through the
 * Jacobian J to an elliptical Gaussian in texture space with covariance
 * sigma^2 J J^T; its inverse gives Q = A du^2 + B du dv + C dv^2 (eq. 3.12,
 * with F folded into the covariance).  Adding min_sigma^2 to both axes is
 * the convolution with a reconstruction Gaussian (his "minimum radius"
 * fix for magnification), so the kernel never falls between texels. */
int fs_ewa_setup(const fs_mip_view *m, const fs_footprint *in, const fs_ewa_params *p, fs_ewa_kernel *k)
{
    memset(k, 0, sizeof *k);
    if (!p)
        p = &ewa_default;
    double sig = p->sigma_px > 0 && isfinite(p->sigma_px) ? p->sigma_px : ewa_default.sigma_px;
    double rad = p->radius > 0 && isfinite(p->radius) ? p->radius : ewa_default.radius;
    double rmin = p->min_sigma > 0 && isfinite(p->min_sigma) ? p->min_sigma : ewa_default.min_sigma;
    double minor_t = p->minor_texels > 0 && isfinite(p->minor_texels) ? p->minor_texels : ewa_default.minor_texels;
    double maxa = p->max_aniso >= 1 && isfinite(p->max_aniso) ? p->max_aniso : ewa_default.max_aniso;
    int max_texels = p->max_texels >= 16 ? p->max_texels : ewa_default.max_texels;
    fs_footprint fp;
    if (!sanitize(in, &fp))
        return -1;
    double s2 = sig * sig;
    double suu = s2 * (fp.dudx * fp.dudx + fp.dudy * fp.dudy);
    double suv = s2 * (fp.dudx * fp.dvdx + fp.dudy * fp.dvdy);
    double svv = s2 * (fp.dvdx * fp.dvdx + fp.dvdy * fp.dvdy);
    /* Eigenvalues of the level-0 covariance: the axes' variances. */
    double half_tr = 0.5 * (suu + svv), det0 = suu * svv - suv * suv;
    double disc = sqrt(fmax(half_tr * half_tr - det0, 0.0));
    double major = sqrt(half_tr + disc), minor = sqrt(fmax(half_tr - disc, 0.0));
    double eff = fmax(minor, major / maxa);
    int top = m->levels - 1;
    int level = eff > minor_t ? (int)floor(log2(eff / minor_t)) : 0;
    if (level > top)
        level = top;
    for (;; level++) {
        double sx = (double)m->width[level] / m->width[0], sy = (double)m->height[level] / m->height[0];
        double a = suu * sx * sx + rmin * rmin, b = suv * sx * sy, c = svv * sy * sy + rmin * rmin;
        double det = a * c - b * b;
        double eu = rad * sqrt(a), ev = rad * sqrt(c);
        k->level = level;
        k->cu = fp.u * sx;
        k->cv = fp.v * sy;
        k->A = c / det;
        k->B = -2 * b / det;
        k->C = a / det;
        k->q_max = rad * rad;
        k->det_sigma = det;
        double x0 = ceil(k->cu - eu - 0.5), x1 = floor(k->cu + eu - 0.5);
        double y0 = ceil(k->cv - ev - 0.5), y1 = floor(k->cv + ev - 0.5);
        double count = (x1 - x0 + 1) * (y1 - y0 + 1);
        if (count <= max_texels || level >= top) {
            if (!(count <= max_texels))
                return -1;    /* even the top level is too wide: caller falls back */
            k->x0 = (int)x0;
            k->x1 = (int)x1;
            k->y0 = (int)y0;
            k->y1 = (int)y1;
            return 0;
        }
    }
}

void fs_filter_ewa(const fs_mip_view *m, const fs_footprint *in, const void *params, fs_filter_out *out)
{
    fs_ewa_kernel k;
    if (fs_ewa_setup(m, in, params, &k) != 0) {
        fs_footprint fp;
        sanitize(in, &fp);
        fallback_top(m, &fp, out);
        return;
    }
    out_init(out);
    double acc[4] = {0, 0, 0, 0}, wsum = 0;
    int n = 0;
    for (int y = k.y0; y <= k.y1; y++) {
        double dv = y + 0.5 - k.cv;
        for (int x = k.x0; x <= k.x1; x++) {
            double du = x + 0.5 - k.cu;
            double q = k.A * du * du + k.B * du * dv + k.C * dv * dv;
            if (q > k.q_max)
                continue;
            double w = exp(-0.5 * q);
            float t[4];
            fs_mip_fetch(m, k.level, x, y, t);
            for (int ch = 0; ch < 4; ch++)
                acc[ch] += w * t[ch];
            wsum += w;
            n++;
        }
    }
    if (!(wsum > 0)) {
        /* A truncation radius below half a texel can miss every centre. */
        out->texels = fs_mip_bilinear(m, k.level, k.cu * m->width[0] / m->width[k.level],
                                      k.cv * m->height[0] / m->height[k.level], out->rgba);
    } else {
        for (int ch = 0; ch < 4; ch++)
            out->rgba[ch] = (float)(acc[ch] / wsum);
        out->texels = n;
    }
    out->level = (float)k.level;
    out->cls = n;
}

/* ---- ground truth --------------------------------------------------------- */

/* Heckbert 1989, 2.2.3 ("square to quadrilateral"): the projective map
 * (s, t) -> ((a s + b t + c) / (g s + h t + 1), (d s + e t + f) / (...))
 * taking (0,0), (1,0), (1,1), (0,1) to corners 0..3.  Corner order is
 * fs_footprint's: (x-.5,y-.5), (x+.5,y-.5), (x+.5,y+.5), (x-.5,y+.5). */
bool fs_homography_from_corners(const fs_footprint *fp, fs_homography *H)
{
    const double *x = fp->corner_u, *y = fp->corner_v;
    for (int i = 0; i < 4; i++)
        if (!isfinite(x[i]) || !isfinite(y[i]) || fabs(x[i]) > 1e9 || fabs(y[i]) > 1e9)
            return false;
    double sx = x[0] - x[1] + x[2] - x[3], sy = y[0] - y[1] + y[2] - y[3];
    double scale = fabs(x[1] - x[0]) + fabs(x[3] - x[0]) + fabs(y[1] - y[0]) + fabs(y[3] - y[0]);
    if (!(scale > 0))
        return false;
    if (fabs(sx) <= 1e-12 * scale && fabs(sy) <= 1e-12 * scale) {
        H->g = H->h = 0;
    } else {
        double dx1 = x[1] - x[2], dx2 = x[3] - x[2], dy1 = y[1] - y[2], dy2 = y[3] - y[2];
        double den = dx1 * dy2 - dy1 * dx2;
        if (!(fabs(den) > 1e-300))
            return false;
        H->g = (sx * dy2 - sy * dx2) / den;
        H->h = (dx1 * sy - dy1 * sx) / den;
    }
    H->a = x[1] - x[0] + H->g * x[1];
    H->b = x[3] - x[0] + H->h * x[3];
    H->c = x[0];
    H->d = y[1] - y[0] + H->g * y[1];
    H->e = y[3] - y[0] + H->h * y[3];
    H->f = y[0];
    /* The denominator is linear in (s, t) and 1 at (0,0): positive at the
     * other three corners means positive on the whole square, i.e. the map
     * does not pass through infinity (a non-convex or folded "quad"). */
    if (!(1 + H->g > 1e-9 && 1 + H->h > 1e-9 && 1 + H->g + H->h > 1e-9))
        return false;
    /* A degenerate quad (collinear corners) has a singular map. */
    double j = H->a * H->e - H->b * H->d;
    return isfinite(j) && fabs(j) > 1e-18 * scale * scale;
}

void fs_homography_map(const fs_homography *H, double s, double t, double *u, double *v)
{
    double w = H->g * s + H->h * t + 1;
    *u = (H->a * s + H->b * t + H->c) / w;
    *v = (H->d * s + H->e * t + H->f) / w;
}

uint32_t fs_hash32(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

static double edge_len(const fs_footprint *fp, int i, int j)
{
    return hypot(fp->corner_u[j] - fp->corner_u[i], fp->corner_v[j] - fp->corner_v[i]);
}

void fs_filter_truth(const fs_mip_view *m, const fs_footprint *in, const void *params, fs_filter_out *out)
{
    static const fs_truth_params def = {16, 64, 0.5, 1};
    const fs_truth_params *p = params ? params : &def;
    int min_n = p->min_n >= 1 && p->min_n <= 4096 ? p->min_n : def.min_n;
    int max_n = p->max_n >= min_n && p->max_n <= 4096 ? p->max_n : min_n;
    double spacing = p->spacing > 0 && isfinite(p->spacing) ? p->spacing : def.spacing;
    fs_footprint fp;
    bool jac = sanitize(in, &fp);
    fs_homography H;
    if (!fs_homography_from_corners(&fp, &H)) {
        if (!jac) {
            fallback_top(m, &fp, out);
            return;
        }
        fs_footprint_affine_corners(&fp);
        if (!fs_homography_from_corners(&fp, &H)) {
            /* Zero-area footprint: the preimage is a point. */
            out_init(out);
            out->texels = fs_mip_bilinear(m, 0, fp.u, fp.v, out->rgba);
            out->cls = 1;
            return;
        }
    }
    double es = fmax(edge_len(&fp, 0, 1), edge_len(&fp, 3, 2));
    double et = fmax(edge_len(&fp, 0, 3), edge_len(&fp, 1, 2));
    double fs_ = ceil(es / spacing), ft = ceil(et / spacing);
    int ns = fs_ < min_n ? min_n : fs_ > max_n ? max_n : (int)fs_;
    int nt = ft < min_n ? min_n : ft > max_n ? max_n : (int)ft;
    /* Per-pixel jitter seed from the centre, so neighbouring pixels do not
     * share one pattern; deterministic for a given footprint. */
    uint32_t seed = fs_hash32(p->seed ^ fs_hash32((uint32_t)(int64_t)floor(fp.u * 64) ^
                                            fs_hash32((uint32_t)(int64_t)floor(fp.v * 64))));
    double acc[4] = {0, 0, 0, 0};
    for (int j = 0; j < nt; j++)
        for (int i = 0; i < ns; i++) {
            uint32_t r = fs_hash32(seed ^ (uint32_t)(j * 4099 + i));
            uint32_t r2 = fs_hash32(r + 0x9e3779b9u);
            double s = (i + (r >> 8) * (1.0 / 16777216.0)) / ns;
            double t = (j + (r2 >> 8) * (1.0 / 16777216.0)) / nt;
            double u, v;
            float c[4];
            fs_homography_map(&H, s, t, &u, &v);
            fs_mip_bilinear(m, 0, u, v, c);
            for (int ch = 0; ch < 4; ch++)
                acc[ch] += c[ch];
        }
    out_init(out);
    double inv = 1.0 / ((double)ns * nt);
    for (int ch = 0; ch < 4; ch++)
        out->rgba[ch] = (float)(acc[ch] * inv);
    out->texels = 4 * ns * nt;
    out->cls = ns * nt;
}

/* ---- ground-plane scene --------------------------------------------------- */

int fs_ground_scene_check(const fs_ground_scene *s, char *err, size_t errlen)
{
    const char *why = NULL;
    if (s->width < 1 || s->height < 1 || s->width > 16384 || s->height > 16384)
        why = "image size must be 1..16384";
    else if (!(s->eye_height > 0) || !isfinite(s->eye_height))
        why = "eye height must be positive";
    else if (!(s->pitch_deg > 0 && s->pitch_deg < 90))
        why = "pitch must be in (0, 90) degrees";
    else if (!(s->fov_y_deg > 0 && s->fov_y_deg < 170))
        why = "vertical field of view must be in (0, 170) degrees";
    else if (!(s->texels_per_unit > 0) || !isfinite(s->texels_per_unit))
        why = "texture scale must be positive";
    else if (!(s->far_dist > 0) || !isfinite(s->far_dist))
        why = "far distance must be positive";
    else if (!finite4(s->tex_rotate_deg, s->u0, s->v0, 0))
        why = "texture rotation and offset must be finite";
    if (why) {
        snprintf(err, errlen, "ground scene: %s", why);
        return -1;
    }
    return 0;
}

/* Camera: eye (0, 0, h), forward f = (0, cos p, -sin p), up (0, sin p,
 * cos p), right (1, 0, 0).  Screen (x, y) is the direction
 * f + sx right + sy up with sx, sy the NDC position times the half-extent
 * of the view; the ray meets z = 0 at t = h / (sin p - sy cos p). */
typedef struct cam {
    double sp, cp, tx, ty, sx0, sy0, k, cg, sg;
} cam;

static void cam_init(const fs_ground_scene *s, cam *c)
{
    double p = s->pitch_deg * PI / 180, th = tan(s->fov_y_deg * PI / 360);
    double aspect = (double)s->width / s->height;
    c->sp = sin(p);
    c->cp = cos(p);
    c->tx = 2 * th * aspect / s->width;    /* d sx / dx */
    c->ty = 2 * th / s->height;            /* d sy / dy */
    c->sx0 = -th * aspect;
    c->sy0 = -th;
    c->k = s->texels_per_unit;
    double g = s->tex_rotate_deg * PI / 180;
    c->cg = cos(g);
    c->sg = sin(g);
}

static bool cam_ground(const fs_ground_scene *s, const cam *c, double x, double y, double *X, double *Y,
                       double *D)
{
    double sx = c->sx0 + x * c->tx, sy = c->sy0 + y * c->ty;
    *D = c->sp - sy * c->cp;
    if (!(*D > 1e-12))
        return false;
    *X = s->eye_height * sx / *D;
    *Y = s->eye_height * (c->cp + sy * c->sp) / *D;
    return true;
}

static void to_tex(const fs_ground_scene *s, const cam *c, double X, double Y, double *u, double *v)
{
    *u = s->u0 + c->k * (X * c->cg - Y * c->sg);
    *v = s->v0 + c->k * (X * c->sg + Y * c->cg);
}

bool fs_ground_map(const fs_ground_scene *s, double x, double y, double *u, double *v)
{
    cam c;
    cam_init(s, &c);
    double X, Y, D;
    if (!cam_ground(s, &c, x, y, &X, &Y, &D))
        return false;
    to_tex(s, &c, X, Y, u, v);
    return true;
}

bool fs_ground_pixel_visible(const fs_ground_scene *s, int px, int py)
{
    cam c;
    cam_init(s, &c);
    double X, Y, D;
    if (!cam_ground(s, &c, px + 0.5, py + 0.5, &X, &Y, &D) || Y > s->far_dist)
        return false;
    /* The top edge is the farther one (D falls as y grows). */
    return cam_ground(s, &c, px + 0.5, py + 1.0, &X, &Y, &D);
}

bool fs_ground_footprint(const fs_ground_scene *s, int px, int py, fs_footprint *fp)
{
    if (!fs_ground_pixel_visible(s, px, py))
        return false;
    cam c;
    cam_init(s, &c);
    double x = px + 0.5, y = py + 0.5, X, Y, D;
    if (!cam_ground(s, &c, x, y, &X, &Y, &D))
        return false;
    to_tex(s, &c, X, Y, &fp->u, &fp->v);
    /* Derivatives of X = h sx / D, Y = h (cos p + sy sin p) / D with
     * D = sin p - sy cos p: dX/dx = h tx / D, dX/dy = h sx ty cos p / D^2,
     * dY/dx = 0, dY/dy = h ty (sin^2 p + cos^2 p) / D^2. */
    double h = s->eye_height, sx = c.sx0 + x * c.tx;
    double dXdx = h * c.tx / D, dXdy = h * sx * c.ty * c.cp / (D * D), dYdy = h * c.ty / (D * D);
    fp->dudx = c.k * (dXdx * c.cg);
    fp->dvdx = c.k * (dXdx * c.sg);
    fp->dudy = c.k * (dXdy * c.cg - dYdy * c.sg);
    fp->dvdy = c.k * (dXdy * c.sg + dYdy * c.cg);
    static const double ox[4] = {-0.5, 0.5, 0.5, -0.5}, oy[4] = {-0.5, -0.5, 0.5, 0.5};
    for (int i = 0; i < 4; i++) {
        if (!cam_ground(s, &c, x + ox[i], y + oy[i], &X, &Y, &D))
            return false;
        to_tex(s, &c, X, Y, &fp->corner_u[i], &fp->corner_v[i]);
    }
    return true;
}

/* ---- comparison ------------------------------------------------------------ */

double fs_psnr_rgb(const float *a, const float *b, const uint8_t *mask, size_t pixels)
{
    double sq = 0;
    size_t n = 0;
    for (size_t i = 0; i < pixels; i++) {
        if (mask && !mask[i])
            continue;
        for (int ch = 0; ch < 3; ch++) {
            double d = (double)a[4 * i + ch] - b[4 * i + ch];
            sq += d * d;
        }
        n++;
    }
    if (!n)
        return NAN;
    double mse = sq / (3.0 * n);
    return mse > 0 ? 10.0 * log10(1.0 / mse) : INFINITY;
}
