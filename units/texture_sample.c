/*
 * Texture sampling (GL 1.5 spec 3.8.5-3.8.9) and the texture environment
 * (3.8.13), modelled on llvmpipe as OSMesa 22.3 uses it (gallivm
 * lp_bld_sample.c, lp_bld_sample_aos.c, lp_bld_sample_soa.c, lp_bld_arit.c;
 * read for the rules, not copied; facts and measurements in
 * tests/test_texture.c):
 *
 * - The texture coordinates are divided by q (Mesa's fixed-function
 *   fragment program samples projectively: s * (1/q)).
 * - lambda is computed once per 2x2 quad (llvmpipe's default "quad lod")
 *   from the differences of the quad's upper-left pixel (in llvmpipe's
 *   y-down frame) to its right and lower neighbours, scaled by the level-0
 *   size: rho^2 = max(dsdx^2 + dtdx^2, dsdy^2 + dtdy^2), exact (no "rho
 *   approximation" and no "brilinear" by default).  For the MIPMAP_NEAREST
 *   filters the level is iround(log2(rho)) taken from the float exponent of
 *   rho^2; for MIPMAP_LINEAR lambda = 0.5 * fast_log2(rho^2), a piece-wise
 *   linear log2 exact at powers of two.  Magnification is rho^2 <= 1
 *   (c = 0, GL 1.5's c = 0.5 case is not applied).
 * - 8-bit textures with REPEAT or CLAMP_TO_EDGE are filtered in fixed point
 *   ("AoS" path): NEAREST takes floor(s * w); LINEAR takes
 *   round(s * w * 256) - 128 as a 24.8 fixed-point texel position, whose 8
 *   fraction bits are the bilinear weights; lerps are 8-bit with rounding;
 *   the two MIPmap levels are blended with weight trunc(frac(lambda)*256).
 * - GL_CLAMP, CLAMP_TO_BORDER or MIRRORED_REPEAT on either axis (with any
 *   filter) is filtered in float, as llvmpipe's "SoA" path does; LINEAR
 *   with CLAMP and CLAMP_TO_BORDER then reaches the border colour (NEAREST
 *   too with CLAMP_TO_BORDER), taken as a texel of the image's base format.  With min and mag image
 *   filters that differ, a quad's NEAREST pixels go through the LINEAR code
 *   (rounded weights) when the quad sharing its 8-wide vector uses LINEAR.
 * - With an odd framebuffer height llvmpipe's quads are one row off the
 *   model's; each row takes lambda from the quad llvmpipe puts it in.
 * - The texel becomes a float c/255 and the environment is computed in
 *   float; the colour buffer conversion rounds it (fragment_stages.h).
 *   GL_COMBINE's arithmetic is texture_combine.c's.
 */
#include <math.h>
#include <string.h>
#include "texture_priv.h"
#include "footprint.h"
#include "mpgrid_gl.h"
#include "texture_reads.h"
#include "texture_depth.h"
#include "texel_format.h"
#include "../pipeline/context.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#ifdef __clang__
/* Every float operation must round separately, as llvmpipe's do. */
#pragma STDC FP_CONTRACT OFF
#endif

static inline uint32_t float_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static inline float bits_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* float -> int32 like cvttps2dq/cvtps2dq: out of range or NaN gives
 * INT32_MIN ("integer indefinite"). */
static inline int32_t to_int_floor(float v)
{
    if (!(v >= -2147483648.0f && v < 2147483648.0f))
        return INT32_MIN;
    return (int32_t)floorf(v);
}

static inline int32_t to_int_round_even(float v)
{
    if (!(v >= -2147483648.0f && v < 2147483648.0f))
        return INT32_MIN;
    return (int32_t)nearbyintf(v);
}

/* ---- lambda (3.8.8) ---- */

typedef struct lod_result {
    bool minified;    /* lambda > c: the min filter applies */
    int level0, level1;
    int weight8;      /* AoS blend weight of level1, 0..255 */
    float weightf;    /* the same weight in float (SoA path) */
} lod_result;

static int exponent_of(float x, int bias)
{
    /* floor(log2(x)) + bias from the IEEE exponent field (no denormal
     * special case, as llvmpipe's lp_build_extract_exponent). */
    return (int)((float_bits(x) >> 23) & 0xffu) - 127 + bias;
}

static float fast_log2(float x)
{
    /* log2(x) ~ (floor(log2(x)) - 1) + x / 2^floor(log2(x)) */
    float ipart = (float)exponent_of(x, -1);
    float fpart = bits_float((float_bits(x) & 0x007fffffu) | 0x3f800000u);
    return ipart + fpart;
}

/* The levels of a MIPmap filter from lambda (3.8.9): d = base + lambda,
 * rounded for MIPMAP_NEAREST (ip from the caller), floor and fraction
 * for MIPMAP_LINEAR, clamped to [first_level, last_level] with the
 * fraction zeroed at either end (gallivm's order). */
static void lod_levels(const fs_tex_object *t, bool linear, float lod, int ip, lod_result *r)
{
    int first = t->first_level, last = t->last_level;
    if (!linear) {
        int l = ip < 0 ? first : ip > last - first ? last : first + ip;
        r->level0 = r->level1 = l;
        return;
    }
    float fl = floorf(lod);
    float fpart = lod - fl;
    if (!(fl >= 0.0f)) { /* below the base level (or NaN) */
        r->level0 = r->level1 = first;
        fpart = 0.0f;
    } else if (fl >= (float)(last - first)) {
        r->level0 = r->level1 = last;
        fpart = 0.0f;
    } else {
        r->level0 = first + (int)fl;
        r->level1 = r->level0 + 1;
    }
    r->weightf = fpart;
    r->weight8 = (int)(fpart * 256.0f);
}

/* lambda (3.8.8) and the levels it selects, as llvmpipe computes them
 * (gallivm lp_build_lod_selector): with no bias and no clamp that can
 * apply, MIPMAP_NEAREST takes its level from the float exponent of rho^2
 * and the min/mag decision is rho^2 > 1; otherwise lambda =
 * 0.5 * fast_log2(rho^2) + bias, clamped to MAX_LOD then MIN_LOD (equal
 * limits replace lambda), and MIPMAP_NEAREST rounds it to even.  rho is
 * scaled by the base level's size (3.8.9: level_base is level 0 of the
 * pyramid lambda describes). */
static float cube_rho2(const fs_tex_object *t, const float (*st)[4], int pix);

static void select_lod(const fs_tex_object *t, const fs_tex_lod *lp, const float (*st)[4], int pix, lod_result *r)
{
    const fs_tex_image *b = &t->level[t->first_level];
    const float *s = st[0], *tt = st[1], *rr = st[2];
    /* llvmpipe's quad is (upper-left, upper-right, lower-left, lower-right)
     * in its y-down frame, i.e. fs_quad pixels 2, 3, 0, 1. */
    /* A rectangle's s and t are in texels already (unnorm_axis), yet
     * llvmpipe scales their derivatives by the size as a normalized
     * coordinate's (measured: test_texture_rect sampled_vs_osmesa, 18 of
     * 36 scenes with min != mag differed with the derivatives unscaled,
     * 0 scaled), so a rectangle is minified almost everywhere. */
    float fw = (float)b->width, fh = (float)b->height;
    float dsdx = (s[3] - s[2]) * fw, dsdy = (s[0] - s[2]) * fw;
    float dtdx = (tt[3] - tt[2]) * fh, dtdy = (tt[0] - tt[2]) * fh;
    float rx = dsdx * dsdx + dtdx * dtdx;
    float ry = dsdy * dsdy + dtdy * dtdy;
    if (t->target == FS_TEX_3D) {
        /* 3D adds the r derivatives scaled by the depth, after s and t
         * (gallivm lp_build_rho). */
        float fd = (float)b->depth;
        float drdx = (rr[3] - rr[2]) * fd, drdy = (rr[0] - rr[2]) * fd;
        rx = rx + drdx * drdx;
        ry = ry + drdy * drdy;
    }
    float rho2 = t->target == FS_TEX_CUBE ? cube_rho2(t, st, pix) : rx > ry ? rx : ry;
    GLenum mf = t->min_filter;
    bool mip_none = mf == GL_NEAREST || mf == GL_LINEAR;
    bool mip_nearest = mf == GL_NEAREST_MIPMAP_NEAREST || mf == GL_LINEAR_MIPMAP_NEAREST;
    r->level0 = r->level1 = t->first_level;
    r->weight8 = 0;
    r->weightf = 0.0f;
    bool plain = lp->bias == 0.0f && !lp->apply_min && !lp->apply_max;
    if (plain && (mip_none || mip_nearest)) {
        r->minified = rho2 > 1.0f;
        if (mip_nearest) /* iround(log2(sqrt(rho2))) = (floor(log2(rho2)) + 1) >> 1 */
            lod_levels(t, false, 0.0f, exponent_of(rho2, 1) >> 1, r);
        return;
    }
    float lod;
    if (lp->fixed) {
        lod = lp->min_lod;
    } else {
        lod = fast_log2(rho2) * 0.5f + lp->bias;
        if (lp->apply_max)
            lod = lod < lp->max_lod ? lod : lp->max_lod;
        if (lp->apply_min)
            lod = lod > lp->min_lod ? lod : lp->min_lod;
    }
    r->minified = lod > 0.0f;
    if (!mip_none)
        lod_levels(t, !mip_nearest, lod, mip_nearest ? to_int_round_even(lod) : 0, r);
}

/* ---- cube maps (3.8.6) ---- */

/* A MIPmap min filter.  A cube map with one takes each pixel's levels from
 * its own derivatives (measured against OSMesa: 47 of 60 random scenes
 * exact per pixel, 33 of 60 with the quad's upper-left pixel's lambda as
 * for the other targets; the min/mag choice stays per quad, not measured). */
static bool mip_linear_or_nearest(GLenum mf) { return mf != GL_NEAREST && mf != GL_LINEAR; }

/* The face a direction (s, t, r) selects and its major axis (0 s, 1 t,
 * 2 r): table 3.19's largest magnitude, with llvmpipe's ties (gallivm
 * lp_build_cube_lookup): r wins when |r| >= max(|s|, |t|), else s when
 * |s| > |t|, else t; the face is POSITIVE_X + 2 * axis, + 1 when the major
 * coordinate's sign bit is set (-0 included). */
static int cube_face(const float d[3], int *axis)
{
    float as = fabsf(d[0]), at = fabsf(d[1]), ar = fabsf(d[2]);
    float m = as > at ? as : at;
    *axis = ar >= m ? 2 : as > at ? 0 : 1;
    return 2 * *axis + (signbit(d[*axis]) ? 1 : 0);
}

/* Table 3.19's sc and tc of v (a direction or its derivative) on the face
 * of axis whose major coordinate has sign bit neg. */
static void cube_sc_tc(const float v[3], int axis, bool neg, float *sc, float *tc)
{
    switch (axis) {
    case 0: *sc = neg ? v[2] : -v[2]; *tc = -v[1]; break;
    case 1: *sc = v[0]; *tc = neg ? -v[2] : v[2]; break;
    default: *sc = neg ? -v[0] : v[0]; *tc = -v[1]; break;
    }
}

/* A pixel's face and its (s, t) on it: sc * |0.5 / ma| + 0.5, as llvmpipe
 * rounds it (a multiply and an add; 0.5 * (1 / ma) equals 0.5 / ma). */
static int cube_coords(const float d[3], float out[2])
{
    int axis, face = cube_face(d, &axis);
    float sc, tc;
    cube_sc_tc(d, axis, face & 1, &sc, &tc);
    float ima = fabsf(0.5f * (1.0f / d[axis]));
    out[0] = sc * ima + 0.5f;
    out[1] = tc * ima + 0.5f;
    return face;
}

/* rho^2 of a cube map at pixel pix of a quad (fs_quad order; llvmpipe's
 * upper-left is pixel 2): its face, and the derivatives of the face coordinates by the quotient rule,
 * d(s) = (d(sc) - sc * d(ma) / ma) * (0.5 / ma) (with d the differences to
 * the right and lower pixels), scaled by the base level's size; the sum of
 * squares per direction, the larger one, 0 when infinite or NaN. */
static float cube_rho2(const fs_tex_object *t, const float (*st)[4], int pix)
{
    const float d[3] = {st[0][pix], st[1][pix], st[2][pix]};
    float dx[3], dy[3];
    bool top = pix >= 2, left = pix == 0 || pix == 2;
    for (int a = 0; a < 3; a++) {
        /* its row's difference right minus left, its column's lower
         * minus upper (gallivm lp_build_ddx/ddy are per row and column) */
        dx[a] = top ? st[a][3] - st[a][2] : st[a][1] - st[a][0];
        dy[a] = left ? st[a][0] - st[a][2] : st[a][1] - st[a][3];
    }
    int axis, face = cube_face(d, &axis);
    bool neg = face & 1;
    float ima = 1.0f / d[axis], imahalf = 0.5f * ima;
    float sc, tc;
    cube_sc_tc(d, axis, neg, &sc, &tc);
    const fs_tex_image *b = &t->level[t->first_level];
    const float size[2] = {(float)b->width, (float)b->height};
    float rho[2];
    const float *dv[2] = {dx, dy};
    for (int k = 0; k < 2; k++) {
        float dsc, dtc;
        cube_sc_tc(dv[k], axis, neg, &dsc, &dtc);
        float madivma = dv[k][axis] * ima;
        float ds = (dsc - madivma * sc) * imahalf, dt = (dtc - madivma * tc) * imahalf;
        ds = ds * size[0];
        dt = dt * size[1];
        rho[k] = ds * ds + dt * dt;
    }
    float rho2 = rho[0] > rho[1] ? rho[0] : rho[1];
    return isinf(rho2) || isnan(rho2) ? 0.0f : rho2;
}

/* ---- fixed-point filtering (llvmpipe's AoS path) ---- */

static inline int lerp8(int w, int a, int b)
{
    /* 8.8 fixed-point lerp with rounding of the product (x86 pmulhrsw of
     * w and (b - a) << 7), wrapped to 8 bits. */
    return (a + ((w * (b - a) + 128) >> 8)) & 0xff;
}

/* ARB_texture_non_power_of_two's REPEAT: gallivm wraps a power-of-two
 * axis by masking the integer coordinate, and any other by the fraction of
 * s first (it knows which from the base level's size).  NEAREST takes
 * fract(s) held below 1 (lp_build_fract_safe: s - floor(s) can round to 1
 * for tiny negative s), times the size, truncated; the clamp of the result
 * keeps a NaN coordinate inside the image (GL leaves its texel undefined). */
static inline float fract_safe(float s)
{
    float fr = s - floorf(s);
    return fr < 0x1.fffffep-1f ? fr : 0x1.fffffep-1f; /* a NaN takes the bound too */
}

static inline int repeat_npot_nearest(float s, int len)
{
    int x = to_int_floor(fract_safe(s) * (float)len);
    return x < 0 ? 0 : x > len - 1 ? len - 1 : x;
}

/* LINEAR's pair on a repeated non-power-of-two axis: the first texel of a
 * pair below 0 (after the half-texel shift) is the last one, and the
 * second of the last is the first (gallivm's selects in place of a
 * modulo). */
static inline void repeat_npot_pair(int x0, int len, int *i0, int *i1)
{
    x0 = x0 < 0 ? len - 1 : x0 > len - 1 ? len - 1 : x0;
    *i0 = x0;
    *i1 = x0 != len - 1 ? x0 + 1 : 0;
}

static inline int wrap_nearest(int x, int len, GLenum wrap)
{
    if (wrap == GL_REPEAT)
        return x & (len - 1);
    return x < 0 ? 0 : x > len - 1 ? len - 1 : x;
}

/* The texel reads of one quad: the object, read only, and for an MP-Grid
 * object its CTR, the one state a texel read changes (GL_FRAGSIM_mp_grid:
 * texels come through the CTR and pointer table, units/mpgrid_gl.h), with
 * the record of what the reads did to it (mpgrid NULL otherwise); with a
 * observer (pipeline/observer.h), the record of the texels read by pixel `pixel` (reads, else
 * NULL; units/texture_reads.h).  dims and wrap[] are the texture's
 * dimensions and their wraps; an axis the target does not have has size 1,
 * coordinate 0 and GL_REPEAT, which reads texel 0 with any filter and
 * leaves every lerp exact (a lerp of a texel with itself), so 1D and 2D
 * textures take the 3D code's results with fewer reads. */
typedef struct tex_fetch {
    const fs_tex_object *t;
    struct fs_mpgrid_tex *mpgrid;
    fs_mpgrid_work work;
    fs_tex_reads *reads;
    int pixel;
    int dims;
    int face;         /* the cube map face the pixel samples (0 otherwise) */
    GLenum wrap[3];
    bool pot[3]; /* each axis of the base level a power of two */
    float ref;        /* a depth texture's reference r/q at the pixel (texture_depth.h) */
    bool unnorm;      /* a rectangle texture: s and t in texels, not scaled by the size */
} tex_fetch;

/* ARB_texture_rectangle, 3.8.7-3.8.8 of its spec: s and t are texel
 * coordinates (u = s, v = t), not fractions of the size, and only the
 * clamping wraps exist.  gallivm (normalized_coords false) skips the
 * multiplication by the size and wraps as for a normalized coordinate:
 * NEAREST floors, the 8-bit LINEAR rounds s * 256.  An axis the target
 * lacks (r) keeps its normalized code. */
static inline bool unnorm_axis(const tex_fetch *f, int a) { return f->unnorm && a < 2; }

/* An image's size along axis a (0 s, 1 t, 2 r). */
static inline int image_len(const fs_tex_image *img, int a) { return a == 0 ? img->width : a == 1 ? img->height : img->depth; }

/* Address of texel (x, y, z) of a level (an MP-Grid's comes into tmp).
 * The record for the cycle model keeps (level, x, y): it lays out 2D
 * levels (units/texture_reads.h). */
static inline const uint8_t *texel_at(tex_fetch *f, const fs_tex_image *img, const int xyz[3], uint8_t tmp[4])
{
    int x = xyz[0], y = xyz[1];
    if (f->reads && f->reads->n[f->pixel] < FS_TEX_READS_MAX) {
        struct fs_tex_read *r = &f->reads->texel[f->pixel][f->reads->n[f->pixel]++];
        r->level = (int)(img - fs_tex_levels(f->t, f->face));
        r->x = x;
        r->y = y;
    }
    if (f->mpgrid)
        return fs_mpgrid_gl_texel(f->mpgrid, &f->work, (int)(img - f->t->level), x, y, tmp);
    return img->texels + (((size_t)xyz[2] * (size_t)img->height + (size_t)y) * (size_t)img->width + (size_t)x) * 4;
}

/* NEAREST's texel on one axis of the 8-bit path from s: floor(s * len)
 * wrapped, or fract(s)'s on a repeated non-power-of-two axis. */
static inline int nearest_coord8(float s, int len, GLenum wrap, bool pot)
{
    return wrap == GL_REPEAT && !pot ? repeat_npot_nearest(s, len) : wrap_nearest(to_int_floor(s * (float)len), len, wrap);
}

static void sample_nearest8(tex_fetch *f, const fs_tex_image *img, const float st[3], uint8_t out[4])
{
    int xyz[3];
    for (int a = 0; a < 3; a++)
        xyz[a] = unnorm_axis(f, a) ? wrap_nearest(to_int_floor(st[a]), image_len(img, a), GL_CLAMP_TO_EDGE)
                                   : nearest_coord8(st[a], image_len(img, a), f->wrap[a], f->pot[a]);
    uint8_t tmp[4];
    memcpy(out, texel_at(f, img, xyz, tmp), 4);
}

/* LINEAR's texel position on one axis of the 8-bit path before rounding:
 * s * len in 8.8 fixed point, or on a repeated axis that is not a power of
 * two fract(s)'s (gallivm lp_build_coord_repeat_npot_linear_int). */
static inline float linear_pos8(float s, int len, GLenum wrap, bool pot)
{
    if (wrap == GL_REPEAT && !pot)
        return (s - floorf(s)) * (float)len * 256.0f;
    return s * (float)(len << 8);
}

/* The pair and weight from the rounded position v: less half a texel, the
 * 8 fraction bits the weight, the pair wrapped (a power-of-two REPEAT by
 * mask) or clamped. */
static inline void linear_pair8(int32_t v, int len, GLenum wrap, bool pot, int *i0, int *i1, int *frac)
{
    v = (int32_t)((uint32_t)v - 128u);
    *frac = v & 0xff;
    int x0 = (int)(v >> 8);
    if (wrap == GL_REPEAT && !pot) {
        repeat_npot_pair(x0, len, i0, i1);
    } else if (wrap == GL_REPEAT) {
        *i0 = x0 & (len - 1);
        *i1 = (x0 + 1) & (len - 1);
    } else {
        *i0 = x0 < 0 ? 0 : x0 > len - 1 ? len - 1 : x0;
        int x1 = x0 + 1;
        *i1 = x1 < 0 ? 0 : x1 > len - 1 ? len - 1 : x1;
    }
}

static void linear_coord8(float s, int len, GLenum wrap, bool pot, int *i0, int *i1, int *frac)
{
    linear_pair8(to_int_round_even(linear_pos8(s, len, wrap, pot)), len, wrap, pot, i0, i1, frac);
}

/* The texel pair i[axis][0..1] and weight w[axis] of LINEAR on each axis. */
typedef struct linear_taps {
    int i[3][2];
} linear_taps;

/* Bilinear in slice k of the taps (8-bit lerps along s, then t). */
static void bilinear8(tex_fetch *f, const fs_tex_image *img, const linear_taps *tp, int k, const int w[3],
                      int out[4])
{
    uint8_t m[4][4];
    const uint8_t *tx[4];
    for (int j = 0; j < 4; j++) {
        const int xyz[3] = {tp->i[0][j & 1], tp->i[1][j >> 1], tp->i[2][k]};
        tx[j] = texel_at(f, img, xyz, m[j]);
    }
    for (int c = 0; c < 4; c++) {
        int a = lerp8(w[0], tx[0][c], tx[1][c]);
        int b = lerp8(w[0], tx[2][c], tx[3][c]);
        out[c] = lerp8(w[1], a, b);
    }
}

static void sample_linear8(tex_fetch *f, const fs_tex_image *img, const float st[3], uint8_t out[4])
{
    linear_taps tp;
    int w[3];
    for (int a = 0; a < 3; a++) {
        if (unnorm_axis(f, a)) /* the 8-bit path has CLAMP_TO_EDGE only (fs_tex_simple_wraps) */
            linear_pair8(to_int_round_even(st[a] * 256.0f), image_len(img, a), GL_CLAMP_TO_EDGE, true, &tp.i[a][0],
                         &tp.i[a][1], &w[a]);
        else
            linear_coord8(st[a], image_len(img, a), f->wrap[a], f->pot[a], &tp.i[a][0], &tp.i[a][1], &w[a]);
    }
    int v0[4];
    bilinear8(f, img, &tp, 0, w, v0);
    if (f->dims == 3) {
        /* 3D: the two slices' bilinear results lerped along r, 8 texels
         * (3.8.8 eq. 3.23). */
        int v1[4];
        bilinear8(f, img, &tp, 1, w, v1);
        for (int c = 0; c < 4; c++)
            v0[c] = lerp8(w[2], v0[c], v1[c]);
    }
    for (int c = 0; c < 4; c++)
        out[c] = (uint8_t)v0[c];
}

static void sample_level8(tex_fetch *f, int level, GLenum filter, const float st[3], uint8_t out[4])
{
    const fs_tex_object *t = f->t;
    if (filter == GL_NEAREST)
        sample_nearest8(f, &fs_tex_levels(t, f->face)[level], st, out);
    else
        sample_linear8(f, &fs_tex_levels(t, f->face)[level], st, out);
}

/* ---- float filtering with a border (llvmpipe's SoA path for GL_CLAMP) ---- */

static void fetch_f(tex_fetch *f, const fs_tex_image *img, const int xyz[3], float out[4])
{
    const fs_tex_object *t = f->t;
    bool outside = xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0 || xyz[0] >= img->width || xyz[1] >= img->height ||
                   xyz[2] >= img->depth;
    if (img->base_format == GL_DEPTH_COMPONENT) {
        /* A depth texel (the border's depth is its R), compared with the
         * reference before filtering (GL 1.4 3.8.14). */
        uint8_t tmp[4];
        float d = outside ? t->border[0] : fs_tex_depth_texel(img, texel_at(f, img, xyz, tmp));
        out[0] = out[1] = out[2] = out[3] = fs_tex_depth_filtered_value(t, f->ref, d);
        return;
    }
    if (outside) {
        /* 3.8.7: the border colour is taken as a texel of the image's base
         * format, expanded like the stored texels (texture_priv.h), as
         * Mesa converts it for the sampler. */
        const float *b = t->border;
        switch (img->base_format) {
        case GL_LUMINANCE: out[0] = out[1] = out[2] = b[0]; out[3] = 1.0f; break;
        case GL_LUMINANCE_ALPHA: out[0] = out[1] = out[2] = b[0]; out[3] = b[3]; break;
        case GL_INTENSITY: out[0] = out[1] = out[2] = out[3] = b[0]; break;
        case GL_ALPHA: out[0] = out[1] = out[2] = 0.0f; out[3] = b[3]; break;
        case GL_RGB: memcpy(out, b, 3 * sizeof(float)); out[3] = 1.0f; break;
        default: memcpy(out, b, 4 * sizeof(float)); break;
        }
        return;
    }
    uint8_t tmp[4];
    const uint8_t *p = texel_at(f, img, xyz, tmp);
    if (img->wide && !f->mpgrid) {
        /* A format stored above 8 bits: its own values (texture_priv.h). */
        const uint16_t *q = img->wide + (p - img->texels);
        for (int k = 0; k < 4; k++)
            out[k] = fs_texel_wide_float(q[k], img->wide_bits[k]);
        return;
    }
    for (int k = 0; k < 4; k++)
        out[k] = (float)p[k] * (1.0f / 255.0f);
}

/* MIRRORED_REPEAT's fold of s into [0, 1] (GL 1.5 spec 3.8.7, mirror(a)
 * of table 3.19 before scaling), as gallivm lp_build_coord_mirror computes
 * it: |2 * (s/2 - round_even(s/2))|, NaN giving 0. */
static float mirror_coord(float s)
{
    float h = s * 0.5f;
    float fr = h - nearbyintf(h);
    float m = fabsf(fr + fr);
    return m > 0.0f ? m : 0.0f;
}

/* NEAREST's texel x = floor(u) clamped by a clamping wrap: into the image,
 * or for CLAMP_TO_BORDER to [-1, len], which fetch_f answers with the
 * border outside [0, len). */
static inline int nearest_clamp(int x, int len, GLenum wrap)
{
    if (wrap == GL_CLAMP_TO_BORDER)
        return x < -1 ? -1 : x > len ? len : x;
    return x < 0 ? 0 : x >= len ? len - 1 : x;
}

static void linear_clamp_f(float u, int len, GLenum wrap, int *i0, int *i1, float *frac);

/* The texel NEAREST takes on one axis in the float path (3.8.7); outside
 * [0, len) for CLAMP_TO_BORDER, which fetch_f answers with the border. */
static int nearest_coord_f(float s, int len, GLenum wrap, bool pot)
{
    float lf = (float)len;
    switch (wrap) {
    case GL_REPEAT:
        return pot ? to_int_floor(s * lf) & (len - 1) : repeat_npot_nearest(s, len);
    case GL_MIRRORED_REPEAT: {
        int x = to_int_floor(mirror_coord(s) * lf); /* truncation: the fold is >= 0 */
        return x < len - 1 ? x : len - 1;
    }
    case GL_CLAMP_TO_BORDER:
        return nearest_clamp(to_int_floor(s * lf), len, wrap);
    case GL_MIRROR_CLAMP_EXT:
    case GL_MIRROR_CLAMP_TO_EDGE_EXT: {
        /* EXT_texture_mirror_clamp: mirror once about 0, then clamp; for
         * NEAREST both clamp to the edge texel (gallivm: |s * len|
         * truncated, min len - 1). The clamp in float first keeps the
         * conversion defined for huge s. */
        float u = fabsf(s * lf);
        int x = u < lf ? to_int_floor(u) : len - 1;
        return x < len - 1 ? x : len - 1;
    }
    case GL_MIRROR_CLAMP_TO_BORDER_EXT: {
        /* |s * len| truncated; len and beyond read the border. */
        float u = fabsf(s * lf);
        return u < lf ? to_int_floor(u) : len;
    }
    default: /* CLAMP, CLAMP_TO_EDGE */
        return nearest_clamp(to_int_floor(s * lf), len, wrap);
    }
}

/* The texel pair and weight of LINEAR on one axis in the float path
 * (3.8.8, eq. 3.22), by gallivm's rules for each wrap mode. */
static void linear_coord_f(float s, int len, GLenum wrap, bool pot, int *i0, int *i1, float *frac)
{
    float lf = (float)len;
    float u = s * lf;
    if (wrap == GL_MIRRORED_REPEAT) {
        /* Folded, scaled, then the pair clamped into the image. */
        u = mirror_coord(s) * lf - 0.5f;
        float fl = floorf(u);
        *frac = u - fl;
        int x0 = to_int_floor(fl);
        *i0 = x0 > 0 ? x0 : 0;
        *i1 = x0 + 1 < len - 1 ? x0 + 1 : len - 1;
        return;
    }
    if (wrap == GL_MIRROR_CLAMP_EXT || wrap == GL_MIRROR_CLAMP_TO_EDGE_EXT ||
        wrap == GL_MIRROR_CLAMP_TO_BORDER_EXT) {
        /* EXT_texture_mirror_clamp in gallivm's order: |s * len|, clamped
         * to len (MIRROR_CLAMP: a pair may reach the border past it, as
         * GL_CLAMP's), less half a texel; TO_EDGE then clamps at 0 and
         * keeps the pair in the image; TO_BORDER reads the border beyond
         * len (its clamp at len + 1 changes no texel, it keeps the
         * conversion defined). */
        u = fabsf(u);
        float hi = wrap == GL_MIRROR_CLAMP_TO_BORDER_EXT ? lf + 1.0f : lf;
        u = u < hi ? u : hi;
        u = u - 0.5f;
        if (wrap == GL_MIRROR_CLAMP_TO_EDGE_EXT && !(u > 0.0f))
            u = 0.0f;
        float fl = floorf(u);
        *frac = u - fl;
        *i0 = to_int_floor(fl);
        *i1 = *i0 + 1;
        if (wrap == GL_MIRROR_CLAMP_TO_EDGE_EXT && *i1 > len - 1)
            *i1 = len - 1;
        return;
    }
    if (wrap == GL_REPEAT && !pot) {
        /* fract(s) scaled, less half a texel; a pair below 0 (or a NaN)
         * starts at the last texel (gallivm's float REPEAT for sizes not
         * powers of two). */
        u = (s - floorf(s)) * lf - 0.5f;
        float fl = floorf(u);
        *frac = u - fl;
        repeat_npot_pair(u < 0.0f || u != u ? -1 : to_int_floor(fl), len, i0, i1);
        return;
    }
    if (wrap == GL_REPEAT) {
        /* The float path also filters a REPEAT axis when the other one
         * clamps. */
        u = u - 0.5f;
        float fl = floorf(u);
        *frac = u - fl;
        int x0 = to_int_floor(fl);
        *i0 = x0 & (len - 1);
        *i1 = (x0 + 1) & (len - 1);
        return;
    }
    linear_clamp_f(u, len, wrap, i0, i1, frac);
}

/* LINEAR's pair and weight from the texel-space coordinate u for the
 * clamping wraps (CLAMP_TO_BORDER, CLAMP, CLAMP_TO_EDGE). */
static void linear_clamp_f(float u, int len, GLenum wrap, int *i0, int *i1, float *frac)
{
    float lf = (float)len;
    if (wrap == GL_CLAMP_TO_BORDER) {
        /* Clamped to [-1, len + 1] in texel space after the half-texel
         * shift: a pair outside the image reads the border colour. */
        u = u - 0.5f;
        u = u < -1.0f ? -1.0f : u > lf + 1.0f ? lf + 1.0f : u;
        float fl = floorf(u);
        *frac = u - fl;
        *i0 = to_int_floor(fl);
        *i1 = *i0 + 1;
        return;
    }
    if (wrap == GL_CLAMP) {
        /* 3.8.7: clamp to [0, 1] in texel space, then the border may be
         * reached by one of the two texels. */
        u = u < 0.0f ? 0.0f : u > lf ? lf : u;
        u = u - 0.5f;
        float fl = floorf(u);
        *frac = u - fl;
        *i0 = to_int_floor(fl);
        *i1 = *i0 + 1;
        return;
    }
    /* CLAMP_TO_EDGE */
    u = u < 0.5f ? 0.5f : u > lf - 0.5f ? lf - 0.5f : u;
    u = u - 0.5f;
    float fl = floorf(u);
    *frac = u - fl;
    int x0 = to_int_floor(fl);
    *i0 = x0;
    *i1 = x0 + 1 < len ? x0 + 1 : len - 1;
}

static inline float lerpf(float w, float a, float b) { return a + w * (b - a); }

/* Bilinear in slice k of the taps, in float (lerps along s, then t). */
static void bilinear_f(tex_fetch *f, const fs_tex_image *img, const linear_taps *tp, int k, const float w[3],
                       float out[4])
{
    float v[4][4];
    for (int j = 0; j < 4; j++) {
        const int xyz[3] = {tp->i[0][j & 1], tp->i[1][j >> 1], tp->i[2][k]};
        fetch_f(f, img, xyz, v[j]);
    }
    for (int c = 0; c < 4; c++)
        out[c] = lerpf(w[1], lerpf(w[0], v[0][c], v[1][c]), lerpf(w[0], v[2][c], v[3][c]));
}

/* LINEAR in float from the taps and weights: bilinear, and for 3D the two
 * slices lerped along r (3.8.8 eq. 3.23). */
static void linear_taps_f(tex_fetch *f, const fs_tex_image *img, const linear_taps *tp, const float w[3],
                          float out[4])
{
    bilinear_f(f, img, tp, 0, w, out);
    if (f->dims == 3) {
        float v1[4];
        bilinear_f(f, img, tp, 1, w, v1);
        for (int c = 0; c < 4; c++)
            out[c] = lerpf(w[2], out[c], v1[c]);
    }
}

static void sample_level_f(tex_fetch *f, int level, GLenum filter, const float st[3], float out[4])
{
    const fs_tex_image *img = &fs_tex_levels(f->t, f->face)[level];
    if (filter == GL_NEAREST) {
        int xyz[3];
        for (int a = 0; a < 3; a++)
            xyz[a] = unnorm_axis(f, a) ? nearest_clamp(to_int_floor(st[a]), image_len(img, a), f->wrap[a])
                                       : nearest_coord_f(st[a], image_len(img, a), f->wrap[a], f->pot[a]);
        fetch_f(f, img, xyz, out);
        return;
    }
    linear_taps tp;
    float w[3];
    for (int a = 0; a < 3; a++) {
        if (unnorm_axis(f, a))
            linear_clamp_f(st[a], image_len(img, a), f->wrap[a], &tp.i[a][0], &tp.i[a][1], &w[a]);
        else
            linear_coord_f(st[a], image_len(img, a), f->wrap[a], f->pot[a], &tp.i[a][0], &tp.i[a][1], &w[a]);
    }
    linear_taps_f(f, img, &tp, w, out);
}

/* NEAREST the way llvmpipe's float path computes it for the nearest pixels
 * of a vector that also has LINEAR pixels (fs_tex_pair_decides): the
 * LINEAR code with each weight rounded to 0 or 1 (a fraction of exactly
 * 0.5 keeps the first texel), so GL_CLAMP below 0 reaches the border and
 * a weight of 1 gives a + (b - a), not always b. */
static void sample_nearest_via_linear_f(tex_fetch *f, int level, const float st[3], float out[4])
{
    const fs_tex_image *img = &fs_tex_levels(f->t, f->face)[level];
    linear_taps tp;
    float w[3];
    for (int a = 0; a < 3; a++) {
        linear_coord_f(st[a], image_len(img, a), f->wrap[a], f->pot[a], &tp.i[a][0], &tp.i[a][1], &w[a]);
        w[a] = w[a] > 0.5f ? 1.0f : 0.0f;
    }
    linear_taps_f(f, img, &tp, w, out);
}

static void sample_level_fv(tex_fetch *f, int level, GLenum filter, bool via_linear, const float st[3],
                            float out[4])
{
    if (via_linear && filter == GL_NEAREST)
        sample_nearest_via_linear_f(f, level, st, out);
    else
        sample_level_f(f, level, filter, st, out);
}

/* ---- texture environment (3.8.13, tables 3.22 and 3.23) ---- */

static inline float clamp01(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }

static void apply_env(const fs_tex_env *env, GLenum base, const float tex[4], float col[4])
{
    const float *cc = env->color;
    float lt = tex[0], at = tex[3];
    switch (env->mode) {
    case GL_REPLACE:
        switch (base) {
        case GL_ALPHA: col[3] = at; break;
        case GL_LUMINANCE: case GL_RGB: col[0] = tex[0]; col[1] = tex[1]; col[2] = tex[2]; break;
        default: memcpy(col, tex, 4 * sizeof(float)); break;
        }
        break;
    case GL_MODULATE:
        if (base != GL_ALPHA)
            for (int k = 0; k < 3; k++)
                col[k] = col[k] * tex[k];
        if (base != GL_LUMINANCE && base != GL_RGB)
            col[3] = col[3] * at;
        break;
    case GL_DECAL:
        /* Undefined for the one- and two-component formats; Mesa passes
         * the fragment through. */
        if (base == GL_RGB)
            for (int k = 0; k < 3; k++)
                col[k] = tex[k];
        else if (base == GL_RGBA)
            for (int k = 0; k < 3; k++)
                col[k] = lerpf(at, col[k], tex[k]);
        break;
    case GL_BLEND:
        if (base != GL_ALPHA)
            for (int k = 0; k < 3; k++)
                col[k] = lerpf(tex[k], col[k], cc[k]);
        if (base == GL_INTENSITY)
            col[3] = lerpf(lt, col[3], cc[3]);
        else if (base != GL_LUMINANCE && base != GL_RGB)
            col[3] = col[3] * at;
        break;
    case GL_ADD:
        if (base != GL_ALPHA)
            for (int k = 0; k < 3; k++)
                col[k] = clamp01(col[k] + tex[k]);
        if (base == GL_INTENSITY)
            col[3] = clamp01(col[3] + at);
        else if (base != GL_LUMINANCE && base != GL_RGB)
            col[3] = col[3] * at;
        break;
    default:
        break;
    }
}

/* ---- GL_FRAGSIM_footprint_filter (units/footprint.h) ---- */

/* The bound object's complete pyramid, read-only (texture_filter.h): its
 * level 0 is the base level (3.8.9). */
static void tex_mip_view(const fs_tex_object *t, fs_mip_view *v)
{
    memset(v, 0, sizeof *v);
    v->levels = t->last_level - t->first_level + 1;
    for (int l = 0; l < v->levels; l++) {
        const fs_tex_image *img = &t->level[t->first_level + l];
        v->width[l] = img->width;
        v->height[l] = img->height;
        v->texels[l] = img->texels;
    }
    /* GL_CLAMP has no border colour in the footprint filters (edge texels,
     * see the extension's Issues). */
    v->wrap_s = t->wrap_s == GL_REPEAT ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    v->wrap_t = t->wrap_t == GL_REPEAT ? GL_REPEAT : GL_CLAMP_TO_EDGE;
}

static int footprint_wrap(int v, int size, GLenum mode)
{
    if (mode == GL_REPEAT) {
        /* A modulo that is never negative: sizes need not be powers of two
         * (ARB_texture_non_power_of_two). */
        int m = v % size;
        return m < 0 ? m + size : m;
    }
    return v < 0 ? 0 : v >= size ? size - 1 : v;
}

/* The wrapping tex_mip_view gives the footprint filters. */
void fs_tex_footprint_texel(const fs_tex_object *t, int level, int *x, int *y)
{
    *x = footprint_wrap(*x, t->level[level].width, t->wrap_s);
    *y = footprint_wrap(*y, t->level[level].height, t->wrap_t);
}

/* Samples the covered pixels of a minified quad with the footprint filter:
 * each pixel's footprint is the parallelogram of the quad's differences
 * along its own row and column (the affine footprint, texture_filter.h). */
static void footprint_quad(fs_context *c, fs_tex_object *t, fs_quad *q, const float s[4], const float tt[4],
                           float (*texel)[4])
{
    struct fs_texture_state *st = c->texture;
    int mi = t->footprint_budget == 8 ? 0 : t->footprint_budget == 16 ? 1 : t->footprint_budget == 32 ? 2 : 3;
    int snap = t->footprint_snap == GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM;
    int hybrid = t->min_filter == GL_FOOTPRINT_HYBRID_FRAGSIM;
    fs_footprint_filter **fp = &st->footprint[mi][snap][hybrid];
    if (!*fp) {
        *fp = fs_footprint_filter_create(t->footprint_budget, snap, hybrid);
        if (!*fp)
            fs_error(c, GL_OUT_OF_MEMORY); /* the pixels are sampled trilinearly below */
    }
    fs_mip_view mv;
    tex_mip_view(t, &mv);
    const fs_tex_image *b = &t->level[t->first_level];
    double w = b->width, h = b->height;
    fs_filter_out fo[4]; /* what each pixel read, for the observer */
    for (int i = 0; i < 4; i++) {
        if (!(q->mask & (1u << i)))
            continue;
        /* fs_quad pixels: 0 (x,y), 1 (x+1,y), 2 (x,y+1), 3 (x+1,y+1). */
        int row = i & 2, col = i & 1;
        fs_footprint f;
        memset(&f, 0, sizeof f);
        f.u = (double)s[i] * w;
        f.v = (double)tt[i] * h;
        f.dudx = ((double)s[row + 1] - s[row]) * w;
        f.dvdx = ((double)tt[row + 1] - tt[row]) * h;
        f.dudy = ((double)s[col + 2] - s[col]) * w;
        f.dvdy = ((double)tt[col + 2] - tt[col]) * h;
        fs_footprint_affine_corners(&f);
        fs_filter_out o;
        int lookups = 0;
        if (*fp)
            fs_footprint_filter_run(*fp, &mv, &f, &o, &lookups);
        else
            fs_filter_footprint(&mv, &f, NULL, &o);
        for (int r = 0; r < o.nrects && r < 2; r++)
            o.rect[r].level += t->first_level; /* the object's level numbers */
        switch (o.cls) {
        case FS_FP_CLASS_BILINEAR0: c->stats.tex_fp_bilinear0++; break;
        case FS_FP_CLASS_TRILINEAR: c->stats.tex_fp_trilinear++; break;
        case FS_FP_CLASS_FOOTPRINT: c->stats.tex_fp_footprint++; break;
        default: c->stats.tex_fp_footprint_2m++; break;
        }
        c->stats.tex_fp_texels += (uint64_t)o.texels;
        c->stats.tex_fp_rom_lookups += (uint64_t)lookups;
        memcpy(texel[i], o.rgba, sizeof o.rgba);
        if (c->observer)
            fo[i] = o;
    }
    FS_OBSERVE(c, texture_footprint, t, q, fo);
}

/* ---- per quad ---- */

/* The coordinates a texture of dims dimensions samples at the four pixels
 * of v: (s, t, r) divided by q (Mesa's fixed-function program samples
 * projectively); the coordinates of the axes a target lacks are 0
 * (tex_fetch). */
static void project_coords(int dims, const float (*v[4])[4], float st[3][4])
{
    float oq[4];
    for (int i = 0; i < 4; i++)
        oq[i] = 1.0f / (*v[i])[3];
    for (int a = 0; a < 3; a++)
        for (int i = 0; i < 4; i++)
            st[a][i] = a < dims ? (*v[i])[a] * oq[i] : 0.0f;
}

/* Whether this NEAREST quad in llvmpipe's float path goes through the
 * LINEAR code: when the quad sharing its vector (rows y, y+1 of
 * fs_quad.tex_pair) uses LINEAR, i.e. takes the image filter that is
 * LINEAR. */
static bool nearest_via_linear(const fs_tex_object *t, const fs_tex_lod *lp, int dims, const fs_quad_tex *qt)
{
    const float (*v[4])[4];
    for (int i = 0; i < 4; i++)
        v[i] = &qt->tex_pair[1 + (i >> 1)][i & 1];
    float pst[3][4];
    project_coords(t->target == FS_TEX_CUBE ? 3 : dims, v, pst);
    lod_result other;
    select_lod(t, lp, (const float(*)[4])pst, 2, &other);
    GLenum mf = t->min_filter;
    bool min_linear = mf == GL_LINEAR || mf == GL_LINEAR_MIPMAP_NEAREST || mf == GL_LINEAR_MIPMAP_LINEAR;
    return other.minified == min_linear;
}

/* Whether a texture is sampled from its stored values above 8 bits
 * (texture_priv.h): llvmpipe filters only 8-bit normalized formats in
 * fixed point (gallivm's AoS path needs a format that fits 8-bit unorm),
 * these always in float, whatever the wraps. */
static bool tex_wide(const fs_tex_object *t)
{
    const fs_tex_image *b = &t->level[t->first_level];
    return b->wide && !t->mpgrid && (b->wide_bits[0] > 8 || b->wide_bits[3] > 8);
}

/* One pixel's texel from the selected levels: the float path or the 8-bit
 * one, the two levels blended for a MIPMAP_LINEAR filter. */
static void sample_pixel(tex_fetch *f, const lod_result *lr, GLenum img_filter, bool mip_linear, bool float_path,
                         bool via_linear, const float st[3], float tex[4])
{
    if (float_path) {
        sample_level_fv(f, lr->level0, img_filter, via_linear, st, tex);
        if (mip_linear && lr->weightf > 0.0f) {
            float t1[4];
            sample_level_fv(f, lr->level1, img_filter, via_linear, st, t1);
            for (int k = 0; k < 4; k++)
                tex[k] = lerpf(lr->weightf, tex[k], t1[k]);
        }
        return;
    }
    uint8_t v[4];
    sample_level8(f, lr->level0, img_filter, st, v);
    if (mip_linear && lr->weight8 > 0) {
        uint8_t v1[4];
        sample_level8(f, lr->level1, img_filter, st, v1);
        for (int k = 0; k < 4; k++)
            v[k] = (uint8_t)lerp8(lr->weight8, v[k], v1[k]);
    }
    for (int k = 0; k < 4; k++)
        tex[k] = (float)v[k] * (1.0f / 255.0f);
}

/* ---- the quad's 8-bit path (issue 23) ---- */

/* What sample_pixel computes on its 8-bit path, for the four pixels of a
 * quad at once, when nothing but the texels is wanted: a 1D or 2D texture
 * of 8-bit texels (not depth, not MP-Grid, whose reads go through the CTR)
 * with no observer recording the reads.  The same conversions, wraps and
 * lerps as sample_level8's (shared helpers above), so the same bits
 * (tests/test_texture_fast.c holds the two paths equal; a context can keep
 * the reference path, fs_texture_set_generic).  Pixels outside the quad's
 * mask are sampled too: every index is wrapped or clamped into the image
 * whatever the coordinate, and their texels are not used. */

/* to_int_round_even and to_int_floor of four values. */
static inline void round_even4(const float v[4], int32_t out[4])
{
#if defined(__SSE2__)
    /* cvtps2dq rounds in the current mode (nearest even, as nearbyintf
     * does) and gives INT32_MIN out of range or for NaN. */
    _mm_storeu_si128((__m128i *)out, _mm_cvtps_epi32(_mm_loadu_ps(v)));
#else
    for (int i = 0; i < 4; i++)
        out[i] = to_int_round_even(v[i]);
#endif
}

static inline void floor4(const float v[4], int32_t out[4])
{
#if defined(__SSE2__)
    /* Truncation less 1 where it rounded up (negative non-integers); below
     * -2^31 truncation's INT32_MIN would become INT32_MAX, so those take
     * INT32_MIN again; 2^31 and up and NaN stay INT32_MIN. */
    __m128 x = _mm_loadu_ps(v);
    __m128i t = _mm_cvttps_epi32(x);
    t = _mm_add_epi32(t, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(t), x)));
    __m128i low = _mm_castps_si128(_mm_cmplt_ps(x, _mm_set1_ps(-2147483648.0f)));
    t = _mm_or_si128(_mm_andnot_si128(low, t), _mm_and_si128(low, _mm_set1_epi32(INT32_MIN)));
    _mm_storeu_si128((__m128i *)out, t);
#else
    for (int i = 0; i < 4; i++)
        out[i] = to_int_floor(v[i]);
#endif
}

/* lerp8 without its wrap: a + ((w (b - a) + 128) >> 8) is
 * (a (256 - w) + b w + 128) >> 8, whose terms are never negative and
 * whose sum stays below 2^16 for a, b <= 255 and w <= 256, so it is
 * computed modulo 2^16 (eight to a vector register, pmullw). */
static inline uint16_t lerp8u(uint16_t w, uint16_t a, uint16_t b)
{
    uint16_t sum = (uint16_t)((uint16_t)(a * (uint16_t)(256 - w)) + (uint16_t)(b * w) + 128u);
    return (uint16_t)(sum >> 8);
}

/* One axis of the quad: NEAREST's texels or LINEAR's pairs and weights.
 * Each loop calls the shared helper with the common wraps as constants, so
 * that the compiler specialises it (one helper, no copies). */
static inline void nearest_axis4(const float s[4], int len, GLenum wrap, bool pot, int32_t x[4])
{
    if (wrap == GL_REPEAT && !pot) {
        for (int i = 0; i < 4; i++)
            x[i] = nearest_coord8(s[i], len, GL_REPEAT, false);
        return;
    }
    float u[4];
    for (int i = 0; i < 4; i++)
        u[i] = s[i] * (float)len;
    floor4(u, x);
    for (int i = 0; i < 4; i++)
        x[i] = wrap_nearest(x[i], len, wrap);
}

static inline void linear_axis4(const float s[4], int len, GLenum wrap, bool pot, int i0[4], int i1[4],
                                int frac[4])
{
    bool npot = wrap == GL_REPEAT && !pot;
#if defined(__SSE2__)
    if (!npot) {
        /* linear_pos8 and linear_pair8 in four lanes, the same operations
         * (the subtraction wraps as the uint32 one does, srai is >>). */
        __m128i v = _mm_cvtps_epi32(_mm_mul_ps(_mm_loadu_ps(s), _mm_set1_ps((float)(len << 8))));
        v = _mm_sub_epi32(v, _mm_set1_epi32(128));
        _mm_storeu_si128((__m128i *)frac, _mm_and_si128(v, _mm_set1_epi32(0xff)));
        __m128i hi = _mm_set1_epi32(len - 1);
        __m128i x[2] = {_mm_srai_epi32(v, 8), _mm_add_epi32(_mm_srai_epi32(v, 8), _mm_set1_epi32(1))};
        for (int k = 0; k < 2; k++) {
            if (wrap == GL_REPEAT) {
                x[k] = _mm_and_si128(x[k], hi);
            } else { /* above len - 1: len - 1; then below 0: 0 */
                __m128i above = _mm_cmpgt_epi32(x[k], hi);
                x[k] = _mm_or_si128(_mm_andnot_si128(above, x[k]), _mm_and_si128(above, hi));
                x[k] = _mm_andnot_si128(_mm_cmpgt_epi32(_mm_setzero_si128(), x[k]), x[k]);
            }
        }
        _mm_storeu_si128((__m128i *)i0, x[0]);
        _mm_storeu_si128((__m128i *)i1, x[1]);
        return;
    }
#endif
    float u[4];
    int32_t v[4];
    for (int i = 0; i < 4; i++)
        u[i] = npot ? linear_pos8(s[i], len, GL_REPEAT, false) : linear_pos8(s[i], len, GL_CLAMP_TO_EDGE, true);
    round_even4(u, v);
    if (npot) {
        for (int i = 0; i < 4; i++)
            linear_pair8(v[i], len, GL_REPEAT, false, &i0[i], &i1[i], &frac[i]);
    } else if (wrap == GL_REPEAT) {
        for (int i = 0; i < 4; i++)
            linear_pair8(v[i], len, GL_REPEAT, true, &i0[i], &i1[i], &frac[i]);
    } else {
        for (int i = 0; i < 4; i++)
            linear_pair8(v[i], len, GL_CLAMP_TO_EDGE, true, &i0[i], &i1[i], &frac[i]);
    }
}

/* The quad's texels of one level, RGBA per pixel (sample_level8). */
static void level_quad8(const fs_tex_image *img, GLenum filter, const GLenum wrap[2], const bool pot[2],
                        const float (*st)[4], uint16_t out[16])
{
    const uint8_t *tx = img->texels;
    size_t w = (size_t)img->width;
    if (filter == GL_NEAREST) {
        int32_t x[4], y[4];
        nearest_axis4(st[0], img->width, wrap[0], pot[0], x);
        nearest_axis4(st[1], img->height, wrap[1], pot[1], y);
        uint8_t t8[16];
        for (int i = 0; i < 4; i++)
            memcpy(&t8[4 * i], tx + ((size_t)y[i] * w + (size_t)x[i]) * 4, 4);
        for (int k = 0; k < 16; k++)
            out[k] = t8[k];
        return;
    }
    int x[2][4], y[2][4], fx[4], fy[4];
    linear_axis4(st[0], img->width, wrap[0], pot[0], x[0], x[1], fx);
    linear_axis4(st[1], img->height, wrap[1], pot[1], y[0], y[1], fy);
    /* tap[j]: the texels (x[j & 1], y[j >> 1]) of the four pixels, as
     * bilinear8 takes them, a texel to a 4-byte copy. */
    uint8_t tap[4][16];
    uint16_t wx[16], wy[16];
    for (int i = 0; i < 4; i++) {
        const uint8_t *row0 = tx + (size_t)y[0][i] * w * 4, *row1 = tx + (size_t)y[1][i] * w * 4;
        size_t x0 = (size_t)x[0][i] * 4, x1 = (size_t)x[1][i] * 4;
        memcpy(&tap[0][4 * i], row0 + x0, 4);
        memcpy(&tap[1][4 * i], row0 + x1, 4);
        memcpy(&tap[2][4 * i], row1 + x0, 4);
        memcpy(&tap[3][4 * i], row1 + x1, 4);
        for (int k = 0; k < 4; k++) {
            wx[4 * i + k] = (uint16_t)fx[i];
            wy[4 * i + k] = (uint16_t)fy[i];
        }
    }
    for (int k = 0; k < 16; k++)
        out[k] = lerp8u(wy[k], lerp8u(wx[k], tap[0][k], tap[1][k]), lerp8u(wx[k], tap[2][k], tap[3][k]));
}

/* sample_pixel's 8-bit path for the quad: the levels, their blend, the
 * texel as c/255, into texel[pixel][u]. */
static void sample_quad8(const fs_tex_object *t, const lod_result *lr, GLenum img_filter, bool mip_linear,
                         const GLenum wrap[2], const bool pot[2], const float (*st)[4],
                         float (*texel)[FS_MAX_TEXTURE_UNITS][4], int u)
{
    uint16_t v[16];
    level_quad8(&t->level[lr->level0], img_filter, wrap, pot, st, v);
    if (mip_linear && lr->weight8 > 0) {
        uint16_t v1[16];
        level_quad8(&t->level[lr->level1], img_filter, wrap, pot, st, v1);
        for (int k = 0; k < 16; k++)
            v[k] = lerp8u((uint16_t)lr->weight8, v[k], v1[k]);
    }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            texel[i][u][k] = (float)v[4 * i + k] * (1.0f / 255.0f);
}

void fs_texture_set_generic(fs_context *c, bool generic) { c->texture->generic = generic; }
uint64_t fs_texture_quads_fast(const fs_context *c) { return c->texture->quads_fast; }

/* The texels of enabled unit u for the covered pixels of a quad whose
 * coordinates for the unit are qt, into texel[pixel][u] (RGBA in [0, 1]);
 * false when the unit's texture is incomplete.  The unit samples the
 * target of highest priority that is enabled (3.8.15). */
static bool sample_unit(fs_context *c, fs_quad *q, int u, const fs_quad_tex *qt,
                        float (*texel)[FS_MAX_TEXTURE_UNITS][4])
{
    struct fs_texture_state *st = c->texture;
    fs_tex_object *t = st->unit[u].bound[fs_tex_unit_target(&st->unit[u])];
    if (!fs_tex_complete(t)) {
        /* 3.8.10: texturing is as if disabled for the unit. */
        st->quads_incomplete++;
        return false;
    }
    st->quads_sampled++;
    int dims = fs_tex_target_dims(t->target);
    bool cube = t->target == FS_TEX_CUBE; /* (s, t, r) is a direction; its face is a 2D image */
    const float (*v[4])[4];
    for (int i = 0; i < 4; i++)
        v[i] = &qt->tex[i];
    float str[3][4];
    project_coords(cube ? 3 : dims, v, str);
    fs_tex_lod lp;
    fs_tex_lod_params(t, fs_tex_unit_lod_bias(c, u), &lp);
    lod_result lr;
    bool rect = t->target == FS_TEX_RECT;
    select_lod(t, &lp, (const float(*)[4])str, 2, &lr);
    GLenum mf = t->min_filter;
    if ((mf == GL_FOOTPRINT_FRAGSIM || mf == GL_FOOTPRINT_HYBRID_FRAGSIM) && lr.minified) {
        float fp[4][4];
        footprint_quad(c, t, q, str[0], str[1], fp);
        for (int i = 0; i < 4; i++)
            memcpy(texel[i][u], fp[i], sizeof fp[i]);
        return true;
    }
    GLenum img_filter = (mf == GL_LINEAR || mf == GL_LINEAR_MIPMAP_NEAREST || mf == GL_LINEAR_MIPMAP_LINEAR)
                            ? GL_LINEAR : GL_NEAREST;
    bool mip_linear = mf == GL_NEAREST_MIPMAP_LINEAR || mf == GL_LINEAR_MIPMAP_LINEAR;
    if (!lr.minified && t->mag_filter != img_filter) {
        /* Magnification: lambda <= 0 selects the base level, one image,
         * mag filter (3.8.9). */
        img_filter = t->mag_filter;
        mip_linear = false;
        lr.level0 = lr.level1 = t->first_level;
    }
    /* llvmpipe filters in 8-bit fixed point only with the "simple" wraps
     * REPEAT and CLAMP_TO_EDGE (gallivm lp_is_simple_wrap_mode); another
     * wrap (CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT) on any axis the
     * target has takes the float path, whatever the filter (its MIPmap
     * blend then rounds differently, and LINEAR may reach the border). */
    bool depth = t->level[t->first_level].base_format == GL_DEPTH_COMPONENT;
    bool float_path = !fs_tex_simple_wraps(t) || depth || tex_wide(t); /* depth: texture_depth.c */
    bool via_linear = !rect && float_path && img_filter == GL_NEAREST && c->raster.tex_pair_lod && fs_tex_pair_decides(t) &&
                      nearest_via_linear(t, &lp, dims, qt);
    fs_tex_reads reads;
    tex_fetch f = {t, t->mpgrid, {0, 0, 0}, c->observer ? &reads : NULL, 0, dims, 0,
                   {fs_tex_wrap_of(t, 0), dims > 1 ? fs_tex_wrap_of(t, 1) : GL_REPEAT, dims > 2 ? fs_tex_wrap_of(t, 2) : GL_REPEAT}, {false, false, false}, 0.0f};
    for (int a = 0; a < 3; a++) {
        int len = image_len(&t->level[t->first_level], a);
        f.pot[a] = (len & (len - 1)) == 0;
    }
    f.unnorm = rect;
    if (!float_path && !st->generic && (t->target == FS_TEX_2D || t->target == FS_TEX_1D) && !f.mpgrid &&
        !c->observer) {
        st->quads_fast++;
        sample_quad8(t, &lr, img_filter, mip_linear, f.wrap, f.pot, (const float(*)[4])str, texel, u);
        return true;
    }
    if (c->observer)
        memset(reads.n, 0, sizeof reads.n);
    for (int i = 0; i < 4; i++) {
        if (!(q->mask & (1u << i)))
            continue;
        f.pixel = i;
        float sti[3] = {str[0][i], str[1][i], str[2][i]};
        if (cube && mip_linear_or_nearest(mf)) /* per-pixel levels (cube_rho2) */
            select_lod(t, &lp, (const float(*)[4])str, i, &lr);
        if (cube) {
            /* 3.8.6: the face's (s, t), filtered in that face alone with
             * its wraps (GL 1.5 has no seamless filtering). */
            const float d[3] = {sti[0], sti[1], sti[2]};
            f.face = cube_coords(d, sti);
            sti[2] = 0.0f;
        }
        if (depth) /* divided by q as the coordinates are (texture_depth.h) */
            f.ref = fs_tex_depth_ref(t, qt->tex[i][fs_tex_depth_ref_coord(dims)] * (1.0f / qt->tex[i][3]));
        sample_pixel(&f, &lr, img_filter, mip_linear, float_path, via_linear, sti, texel[i][u]);
        if (depth)
            fs_tex_depth_mode_apply(t, texel[i][u]);
    }
    if (f.mpgrid)
        fs_mpgrid_gl_work_done(f.mpgrid, &f.work);
    FS_OBSERVE(c, texture, t, q, &reads);
    if (f.work.reloads)
        FS_OBSERVE(c, ctr_reloads, f.work.reloads);
    return true;
}

/* EXT_texture_swizzle: each component of the filtered texel (border
 * included, as llvmpipe's sampler view swizzles the sampler's result)
 * from the source its swizzle names, before the environment. */
static void apply_swizzle(const fs_tex_object *t, float (*texel)[FS_MAX_TEXTURE_UNITS][4], int u)
{
    const GLenum *sw = t->swizzle;
    if (sw[0] == GL_RED && sw[1] == GL_GREEN && sw[2] == GL_BLUE && sw[3] == GL_ALPHA)
        return;
    for (int i = 0; i < 4; i++) {
        float in[4], *out = texel[i][u];
        memcpy(in, out, sizeof in);
        for (int k = 0; k < 4; k++)
            out[k] = sw[k] == GL_ZERO ? 0.0f : sw[k] == GL_ONE ? 1.0f : in[sw[k] - GL_RED];
    }
}

/* 3.8.13: every enabled unit's texel first (a GL_COMBINE source may name
 * another unit's, the crossbar), then the environments unit after unit,
 * each on the previous one's result; tc[u] holds unit u's coordinates. */
static void texture_units(fs_context *c, fs_quad *q, const fs_quad_tex *tc)
{
    float texel[4][FS_MAX_TEXTURE_UNITS][4];
    unsigned valid = 0;
    FS_FOR_EACH_UNIT(u, c->raster.tex_mask)
        if (sample_unit(c, q, (int)u, &tc[u], texel)) {
            valid |= 1u << u;
            apply_swizzle(c->texture->unit[u].bound[fs_tex_unit_target(&c->texture->unit[u])], texel, (int)u);
        }
    if (!valid)
        return;
    const struct fs_texture_state *st = c->texture;
    float primary[4][4]; /* GL_PRIMARY_COLOR: the colour before texturing */
    memcpy(primary, q->color, sizeof primary);
    FS_FOR_EACH_UNIT(u, valid) {
        const fs_tex_env *env = &st->unit[u].env;
        const fs_tex_object *t = st->unit[u].bound[fs_tex_unit_target(&st->unit[u])];
        GLenum base = t->level[t->first_level].base_format;
        /* ARB_texture_rg's RED and RG take the environment of RGB, their
         * missing components being 0 (Mesa's texenv, as measured). */
        if (base == GL_RED || base == GL_RG)
            base = GL_RGB;
        if (base == GL_DEPTH_COMPONENT) /* 3.8.13: as its DEPTH_TEXTURE_MODE */
            base = fs_tex_depth_env_base(t);
        for (int i = 0; i < 4; i++) {
            if (!(q->mask & (1u << i)))
                continue;
            if (env->mode == GL_COMBINE) {
                fs_combine_inputs in = {(int)u, valid, (const float(*)[4])texel[i], primary[i], q->color[i]};
                float out[4];
                fs_tex_combine(env, &in, out);
                memcpy(q->color[i], out, sizeof out);
            } else {
                apply_env(env, base, texel[i][u], q->color[i]);
            }
        }
    }
}

/* llvmpipe's 2x2 quads are aligned in its y-down frame (rasterizer_priv.h):
 * with an odd framebuffer height they are one row off the model's.  Each
 * row of the model's quad is then textured as part of the quad llvmpipe
 * puts it in, completed by the row the rasterizer evaluated next to it
 * (fs_quad.tex_below/tex_above), so lambda (3.8.8) comes from the same
 * differences.  quads_sampled then counts llvmpipe's quads. */
void fs_texture_quad(fs_context *c, fs_quad *q)
{
    /* 3.8.13: each enabled unit's result is the next one's fragment colour. */
    if (!(c->fb.height & 1)) {
        texture_units(c, q, q->unit);
        return;
    }
    for (int half = 0; half < 2; half++) {
        /* half 0: row y is the upper row of the quad over rows y-1, y;
         * half 1: row y+1 is the lower row of the quad over y+1, y+2. */
        unsigned row_mask = half ? (q->mask >> 2) & 3u : q->mask & 3u;
        if (!row_mask)
            continue;
        int own = half ? 0 : 2, other = half ? 2 : 0, src = half ? 2 : 0;
        /* The quad llvmpipe shades: its colours, depths and position (its
         * coordinates are built per unit below, not copied). */
        fs_quad h;
        h.x = q->x;
        h.y = half ? q->y + 1 : q->y - 1;
        h.mask = row_mask << own;
        h.front_facing = q->front_facing;
        for (int j = 0; j < 2; j++) {
            memcpy(h.color[own + j], q->color[src + j], sizeof h.color[0]);
            h.z[own + j] = q->z[src + j];
        }
        fs_quad_tex ht[FS_MAX_TEXTURE_UNITS];
        FS_FOR_EACH_UNIT(u, c->raster.tex_mask) {
            const fs_quad_tex *qt = &q->unit[u];
            for (int j = 0; j < 2; j++) {
                memcpy(ht[u].tex[own + j], qt->tex[src + j], sizeof ht[u].tex[0]);
                memcpy(ht[u].tex[other + j], half ? qt->tex_above[j] : qt->tex_below[j], sizeof ht[u].tex[0]);
            }
            /* The partner quad's rows move with the quad (fs_quad_tex.tex_pair). */
            memcpy(ht[u].tex_pair[1], qt->tex_pair[half ? 2 : 0], sizeof ht[u].tex_pair[0]);
            memcpy(ht[u].tex_pair[2], qt->tex_pair[half ? 3 : 1], sizeof ht[u].tex_pair[0]);
        }
        texture_units(c, &h, ht);
        for (int j = 0; j < 2; j++)
            memcpy(q->color[src + j], h.color[own + j], sizeof h.color[0]);
    }
}
