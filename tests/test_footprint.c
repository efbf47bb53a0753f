/*
 * Fast footprint filtering (units/footprint*.c, Huettner 1999 4.3).
 * Oracles: triangle areas by the shoelace formula, per-texel coverage by
 * dense point sampling, mirrored and rotated triangles, the closed form of
 * eq. 4.14-4.17, brute-force box averages, brute-force recounts of the
 * corner positions behind Table 4.3 and the table's own printed factors.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "../driver/cli.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../units/footprint.h"
#include "../units/texture_priv.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"

static double shoelace(const double x[3], const double y[3])
{
    return fabs((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])) * 0.5;
}

static void pos_xy(const fs_fp_rom *r, int x, int y, double *fx, double *fy)
{
    *fx = x + (r->midpoint ? 0.5 : 0.0);
    *fy = y + (r->midpoint ? 0.5 : 0.0);
}

static bool border(const fs_fp_rom *r, int x, int y)
{
    return x == 0 || y == 0 || x == r->px - 1 || y == r->py - 1;
}

/* Every stored vector sums to its triangle's area within half a unit of
 * the last place per texel; the count of vectors is pb(pb-1)(p-2). */
static void check_rom_sums(check_state *check_st_, int a, int b, bool ms)
{
    fs_fp_rom r;
    REQUIRE(fs_fp_rom_build(&r, a, b, ms) == 0);
    long long seen = 0;
    int worst = 0;
    for (int k1 = 0; k1 < r.p; k1++)
        for (int k2 = 0; k2 < r.p; k2++)
            for (int k3 = 0; k3 < r.p; k3++) {
                int x[3] = {k1 % r.px, k2 % r.px, k3 % r.px}, y[3] = {k1 / r.px, k2 / r.px, k3 / r.px};
                const uint8_t *w = fs_fp_rom_lookup(&r, x, y);
                bool stored = k1 != k2 && k1 != k3 && k2 != k3 && border(&r, x[0], y[0]) && border(&r, x[1], y[1]);
                if (!stored) {
                    if (w)
                        worst = 1000;
                    continue;
                }
                seen++;
                if (!w) {
                    worst = 1000;
                    continue;
                }
                double tx[3], ty[3];
                for (int i = 0; i < 3; i++)
                    pos_xy(&r, x[i], y[i], &tx[i], &ty[i]);
                long s = 0;
                int nz = 0;
                for (int i = 0; i < a * b; i++) {
                    s += w[i];
                    nz += w[i] != 0;
                }
                double err = fabs(s / 255.0 - shoelace(tx, ty));
                /* each weight is off by at most half a step */
                if (err > (nz + 1) * 0.5 / 255.0 + 1e-9)
                    worst = 1000;
            }
    CHECK_EQ_INT(worst, 0);
    fs_fp_count c;
    fs_fp_count_shape(a, b, ms, &c);
    CHECK_EQ_INT(seen, c.vectors);
    CHECK_EQ_INT((long long)r.vectors, c.vectors);
    /* The pointer structure: stage 1 has one entry per border position,
     * stage 2 one per ordered border pair, stage 3 one per stored triangle;
     * every pointer stays inside the next stage and stage 3 reaches every
     * vector exactly once. */
    long long pb = 0;
    for (int k = 0; k < r.p; k++)
        pb += border(&r, k % r.px, k / r.px);
    CHECK_EQ_INT(r.pb, pb);
    CHECK_EQ_INT(c.pointers, pb + pb * (pb - 1) + (long long)r.vectors);
    char *hit = calloc(r.vectors, 1);
    REQUIRE(hit);
    long bad_ptr = 0;
    for (long long i = 0; i < pb; i++)
        bad_ptr += (long long)r.stage1[i] + (pb - 1) > pb * (pb - 1);
    for (long long i = 0; i < pb * (pb - 1); i++)
        bad_ptr += r.stage2[i] + (uint64_t)(r.p - 2) > (uint64_t)r.vectors;
    for (size_t i = 0; i < r.vectors; i++) {
        if (r.stage3[i] >= r.vectors || hit[r.stage3[i]])
            bad_ptr++;
        else
            hit[r.stage3[i]] = 1;
    }
    CHECK_EQ_INT(bad_ptr, 0);
    free(hit);
    fs_fp_rom_free(&r);
}

TEST(rom_vectors_sum_to_triangle_area)
{
    for (int M = 8; M <= 32; M *= 2)
        for (int ms = 0; ms < 2; ms++) {
            int a[8], b[8];
            int n = fs_fp_shapes(M, ms, a, b);
            CHECK(n >= 1);
            for (int i = 0; i < n; i++)
                check_rom_sums(check_st_, a[i], b[i], ms);
        }
}

/* Per texel: the ROM weight against the fraction of a 256x256 grid of
 * sample points inside the triangle (independent of the clipping code). */
TEST(rom_weights_match_point_sampling)
{
    fs_fp_rom r;
    REQUIRE(fs_fp_rom_build(&r, 4, 4, false) == 0);
    uint32_t seed = 12345;
    for (int t = 0; t < 40; t++) {
        int x[3], y[3];
        do {
            for (int i = 0; i < 3; i++) {
                seed = seed * 1103515245u + 12345u;
                x[i] = (int)((seed >> 16) % 5u);
                seed = seed * 1103515245u + 12345u;
                y[i] = (int)((seed >> 16) % 5u);
            }
        } while (!fs_fp_rom_lookup(&r, x, y));
        const uint8_t *w = fs_fp_rom_lookup(&r, x, y);
        double tx[3] = {x[0], x[1], x[2]}, ty[3] = {y[0], y[1], y[2]};
        double d = (tx[1] - tx[0]) * (ty[2] - ty[0]) - (tx[2] - tx[0]) * (ty[1] - ty[0]);
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 4; i++) {
                int in = 0;
                const int N = 256;
                for (int sy = 0; sy < N; sy++)
                    for (int sx = 0; sx < N; sx++) {
                        double px = i + (sx + 0.5) / N, py = j + (sy + 0.5) / N;
                        double e0 = (tx[1] - tx[0]) * (py - ty[0]) - (ty[1] - ty[0]) * (px - tx[0]);
                        double e1 = (tx[2] - tx[1]) * (py - ty[1]) - (ty[2] - ty[1]) * (px - tx[1]);
                        double e2 = (tx[0] - tx[2]) * (py - ty[2]) - (ty[0] - ty[2]) * (px - tx[2]);
                        if (d != 0 && ((d > 0 && e0 >= 0 && e1 >= 0 && e2 >= 0) || (d < 0 && e0 <= 0 && e1 <= 0 && e2 <= 0)))
                            in++;
                    }
                double cov = (double)in / (N * N);
                CHECK_NEAR(w[i + 4 * j] / 255.0, cov, 0.5 / 255.0 + 2.0 / N);
            }
    }
    fs_fp_rom_free(&r);
}

/* Mirrored and rotated triangles have mirrored and rotated vectors; the
 * same triangle in two differently shaped tables has the same coverage;
 * a permutation of the corners finds the same weights. */
TEST(rom_symmetric_cases_agree)
{
    for (int ms = 0; ms < 2; ms++) {
        fs_fp_rom sq, lg;
        REQUIRE(fs_fp_rom_build(&sq, 4, 4, ms) == 0);
        REQUIRE(fs_fp_rom_build(&lg, 2, 8, ms) == 0);
        int bad = 0, tested = 0;
        int n = sq.px;
        for (int k1 = 0; k1 < sq.p; k1++)
            for (int k2 = 0; k2 < sq.p; k2++)
                for (int k3 = 0; k3 < sq.p; k3++) {
                    int x[3] = {k1 % n, k2 % n, k3 % n}, y[3] = {k1 / n, k2 / n, k3 / n};
                    const uint8_t *w = fs_fp_rom_lookup(&sq, x, y);
                    if (!w)
                        continue;
                    tested++;
                    /* mirror x: x -> n-1-x, texel i -> 3-i */
                    int mx[3], rx[3], ry[3];
                    for (int i = 0; i < 3; i++) {
                        mx[i] = n - 1 - x[i];
                        /* rotate by 90 degrees: (x, y) -> (n-1-y, x) */
                        rx[i] = n - 1 - y[i];
                        ry[i] = x[i];
                    }
                    const uint8_t *wm = fs_fp_rom_lookup(&sq, mx, y);
                    const uint8_t *wr = fs_fp_rom_lookup(&sq, rx, ry);
                    int px[3] = {x[1], x[0], x[2]}, py[3] = {y[1], y[0], y[2]};
                    const uint8_t *wp = fs_fp_rom_lookup(&sq, px, py);
                    if (!wm || !wr || !wp) {
                        bad++;
                        continue;
                    }
                    for (int j = 0; j < 4; j++)
                        for (int i = 0; i < 4; i++) {
                            int v = w[i + 4 * j];
                            if (abs(v - wm[(3 - i) + 4 * j]) > 1 || abs(v - wr[(3 - j) + 4 * i]) > 1 ||
                                v != wp[i + 4 * j])
                                bad++;
                        }
                    /* The same triangle in the 2x8 table (columns 0-1 of
                     * the 4x4 grid fit when every x is small enough). */
                    bool fits = true;
                    for (int i = 0; i < 3; i++)
                        fits = fits && x[i] < lg.px;
                    const uint8_t *wl = fits ? fs_fp_rom_lookup(&lg, x, y) : NULL;
                    if (wl)
                        for (int j = 0; j < 4; j++)
                            for (int i = 0; i < 2; i++)
                                if (abs(w[i + 4 * j] - wl[i + 2 * j]) > 1)
                                    bad++;
                }
        CHECK(tested > 1000);
        CHECK_EQ_INT(bad, 0);
        fs_fp_rom_free(&sq);
        fs_fp_rom_free(&lg);
    }
}

TEST(lambda_matches_eq_4_14_to_4_17)
{
    /* Closed form: m = log2(u / sqrt(M u / v)), n = log2(v / (M / sqrt(M u / v)));
     * both equal log2(sqrt(u v / M)), so lambda = ceil(log2(u v / M) / 2). */
    static const struct { double u, v; int M, lambda; } cases[] = {
        {64, 4, 16, 2},   /* uv/M = 16 */
        {100, 10, 16, 3}, /* 62.5 -> 2.98 */
        {8, 8, 64, 0},
        {3, 3, 16, 0},    /* ceil(-0.415) = 0 */
        {1, 1, 16, -2},   /* eq. 4.17 unclamped: ceil(-2) */
        {1000, 1, 8, 4},  /* 125 -> 3.48 */
        {1024, 1024, 32, 8}, /* 32768 -> 7.5 */
        {2, 1024, 8, 4},  /* 256 -> 4 exactly */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double m, n;
        int l = fs_footprint_lambda(cases[i].u, cases[i].v, cases[i].M, &m, &n);
        CHECK_EQ_INT(l, cases[i].lambda);
        double a = sqrt(cases[i].M * cases[i].u / cases[i].v);
        CHECK_NEAR(m, log2(cases[i].u / a), 1e-12);
        CHECK_NEAR(n, log2(cases[i].v / (cases[i].M / a)), 1e-12);
    }
    CHECK_EQ_INT(fs_footprint_lambda(0, 5, 16, NULL, NULL), 0);
    CHECK_EQ_INT(fs_footprint_lambda(NAN, 5, 16, NULL, NULL), 0);
    CHECK_EQ_INT(fs_footprint_lambda(INFINITY, 5, 16, NULL, NULL), 0);
}

/* ---- the filter on textures ---- */

static fs_mip_owned make_texture(int w, int h, bool constant, const uint8_t c[4])
{
    uint8_t *img = malloc((size_t)w * h * 4);
    uint32_t seed = 777;
    for (int i = 0; i < w * h * 4; i++) {
        seed = seed * 1664525u + 1013904223u;
        img[i] = constant ? c[i % 4] : (uint8_t)(seed >> 24);
    }
    fs_mip_owned m;
    int rc = fs_mip_build_box(&m, img, w, h, GL_REPEAT);
    free(img);
    if (rc != 0)
        memset(&m, 0, sizeof m);
    return m;
}

static void set_corners(fs_footprint *fp, const double cu[4], const double cv[4])
{
    memset(fp, 0, sizeof *fp);
    for (int k = 0; k < 4; k++) {
        fp->corner_u[k] = cu[k];
        fp->corner_v[k] = cv[k];
        fp->u += cu[k] / 4;
        fp->v += cv[k] / 4;
    }
    /* corners (x-.5,y-.5), (x+.5,y-.5), (x+.5,y+.5), (x-.5,y+.5) */
    fp->dudx = (cu[1] - cu[0] + cu[2] - cu[3]) / 2;
    fp->dvdx = (cv[1] - cv[0] + cv[2] - cv[3]) / 2;
    fp->dudy = (cu[3] - cu[0] + cu[2] - cu[1]) / 2;
    fp->dvdy = (cv[3] - cv[0] + cv[2] - cv[1]) / 2;
}

static void random_footprint(uint32_t *seed, fs_footprint *fp, double scale)
{
    double r[6];
    for (int i = 0; i < 6; i++) {
        *seed = *seed * 1664525u + 1013904223u;
        r[i] = (*seed >> 8) / 16777216.0;
    }
    memset(fp, 0, sizeof *fp);
    fp->u = r[0] * 256;
    fp->v = r[1] * 256;
    double ang = r[2] * 6.2831853, len = pow(2.0, r[3] * scale), ratio = 1.0 + r[4] * 30.0;
    fp->dudx = len * cos(ang);
    fp->dvdx = len * sin(ang);
    fp->dudy = -len / ratio * sin(ang + r[5] - 0.5);
    fp->dvdy = len / ratio * cos(ang + r[5] - 0.5);
    fs_footprint_affine_corners(fp);
}

TEST(constant_texture_filters_to_itself)
{
    static const uint8_t col[4] = {200, 17, 99, 255};
    fs_mip_owned tex = make_texture(128, 64, true, col);
    REQUIRE(tex.store);
    for (int M = 8; M <= 64; M *= 2)
        for (int ms = 0; ms < 2; ms++)
            for (int hy = 0; hy < 2; hy++) {
                fs_footprint_filter *f = fs_footprint_filter_create(M, ms, hy);
                REQUIRE(f);
                uint32_t seed = 99;
                int bad = 0, fp_cls = 0;
                for (int i = 0; i < 3000; i++) {
                    fs_footprint fp;
                    random_footprint(&seed, &fp, 7.0);
                    fs_filter_out o;
                    fs_filter_footprint(&tex.view, &fp, f, &o);
                    for (int ch = 0; ch < 4; ch++)
                        if (!(fabs(o.rgba[ch] - col[ch] / 255.0) < 1e-5))
                            bad++;
                    fp_cls += o.cls == FS_FP_CLASS_FOOTPRINT || o.cls == FS_FP_CLASS_FOOTPRINT_2M;
                }
                CHECK_EQ_INT(bad, 0);
                CHECK(fp_cls > 500); /* the footprint path was exercised */
                fs_footprint_filter_destroy(f);
            }
    fs_mip_free(&tex);
}

/* Axis-aligned footprints covering whole level-0 texels: the box average. */
TEST(whole_texel_footprint_is_box_average)
{
    fs_mip_owned tex = make_texture(64, 64, false, NULL);
    REQUIRE(tex.store);
    static const struct { double u0, v0, u1, v1; int M; bool hybrid; } cases[] = {
        {8, 8, 12, 10, 16, false},  /* 4x2 texels */
        {3, 20, 11, 21, 16, true},  /* 8x1: anisotropic, so the hybrid filters it */
        {30, 5, 31, 13, 8, true},   /* 1x8 */
        {0, 60, 4, 64, 16, false},  /* 4x4 at the texture's corner */
        {16, 16, 32, 18, 32, true}, /* 16x2 */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        fs_footprint_filter *f = fs_footprint_filter_create(cases[c].M, false, cases[c].hybrid);
        REQUIRE(f);
        double cu[4] = {cases[c].u0, cases[c].u1, cases[c].u1, cases[c].u0};
        double cv[4] = {cases[c].v0, cases[c].v0, cases[c].v1, cases[c].v1};
        fs_footprint fp;
        set_corners(&fp, cu, cv);
        fs_filter_out o;
        fs_filter_footprint(&tex.view, &fp, f, &o);
        double sum[4] = {0, 0, 0, 0};
        int n = 0;
        for (int y = (int)cases[c].v0; y < (int)cases[c].v1; y++)
            for (int x = (int)cases[c].u0; x < (int)cases[c].u1; x++, n++)
                for (int ch = 0; ch < 4; ch++)
                    sum[ch] += tex.view.texels[0][(y * 64 + x) * 4 + ch] / 255.0;
        CHECK(o.cls == FS_FP_CLASS_FOOTPRINT);
        CHECK_EQ_INT((int)o.level, 0);
        CHECK_EQ_INT(o.texels, cases[c].M);
        /* Texels cut by the split diagonal get two rounded halves (128 +
         * 128 for 127.5 + 127.5), so the weights are uniform only within
         * the 8-bit quantisation. */
        for (int ch = 0; ch < 4; ch++)
            CHECK_NEAR(o.rgba[ch], sum[ch] / n, 1.0 / 255.0);
        fs_footprint_filter_destroy(f);
    }
    fs_mip_free(&tex);
}

static bool out_defined(const fs_filter_out *o, int levels)
{
    for (int ch = 0; ch < 4; ch++)
        if (!(o->rgba[ch] >= 0.0f && o->rgba[ch] <= 1.0f))
            return false;
    return o->texels >= 1 && o->level >= 0.0f && o->level <= levels - 1 && o->cls >= FS_FP_CLASS_BILINEAR0 &&
           o->cls <= FS_FP_CLASS_FOOTPRINT_2M;
}

TEST(degenerate_footprints_are_defined)
{
    fs_mip_owned tex = make_texture(64, 64, false, NULL);
    REQUIRE(tex.store);
    const double inf = INFINITY, nan = NAN;
    static const double J[][4] = {
        {0, 0, 0, 0},          /* zero area, a point */
        {3, 3, 6, 6},          /* collinear corners */
        {0, 40, 0, 0},         /* a segment */
        {1000, 0, 0, 1},       /* anisotropy 1:1000 */
        {0.001, 0, 0, 1},      /* 1000:1 the other way, below a texel */
        {707, 707, -0.7, 0.7}, /* 1:1000, diagonal */
        {1e300, 0, 0, 1e300},  /* huge */
        {1e-300, 0, 0, 1e-300},
    };
    double special[][4] = {{nan, 0, 0, 1}, {inf, 0, 0, 1}, {inf, -inf, inf, inf}, {nan, nan, nan, nan}};
    for (int M = 8; M <= 64; M *= 2)
        for (int ms = 0; ms < 2; ms++)
            for (int hy = 0; hy < 2; hy++) {
                fs_footprint_filter *f = fs_footprint_filter_create(M, ms, hy);
                REQUIRE(f);
                for (size_t i = 0; i < sizeof J / sizeof J[0] + 4; i++) {
                    const double *j = i < sizeof J / sizeof J[0] ? J[i] : special[i - sizeof J / sizeof J[0]];
                    fs_footprint fp = {0};
                    fp.u = 20.3;
                    fp.v = 41.7;
                    fp.dudx = j[0];
                    fp.dudy = j[1];
                    fp.dvdx = j[2];
                    fp.dvdy = j[3];
                    fs_footprint_affine_corners(&fp);
                    fs_filter_out o;
                    fs_filter_footprint(&tex.view, &fp, f, &o);
                    if (!out_defined(&o, tex.view.levels))
                        CHECK_FAIL_("M=%d ms=%d hybrid=%d case %zu: rgba %g %g %g %g level %g texels %d", M, ms, hy,
                                    i, o.rgba[0], o.rgba[1], o.rgba[2], o.rgba[3], o.level, o.texels);
                }
                /* NaN centre and corners */
                fs_footprint fp = {0};
                fp.u = fp.v = nan;
                for (int k = 0; k < 4; k++)
                    fp.corner_u[k] = fp.corner_v[k] = nan;
                fs_filter_out o;
                fs_filter_footprint(&tex.view, &fp, f, &o);
                CHECK(out_defined(&o, tex.view.levels));
                fs_footprint_filter_destroy(f);
            }
    CHECK(fs_footprint_filter_create(12, false, false) == NULL);
    CHECK(fs_footprint_filter_create(0, true, true) == NULL);
    CHECK(fs_footprint_filter_create(128, false, true) == NULL);
    fs_mip_free(&tex);
}

/* The hybrid's classes: magnification, isotropic, anisotropic. */
TEST(hybrid_selects_by_shape)
{
    fs_mip_owned tex = make_texture(64, 64, false, NULL);
    REQUIRE(tex.store);
    fs_footprint_filter *f = fs_footprint_filter_create(16, false, true);
    REQUIRE(f);
    fs_footprint fp = {0};
    fp.u = fp.v = 30;
    fs_filter_out o;
    fp.dudx = fp.dvdy = 0.5;
    fs_footprint_affine_corners(&fp);
    fs_filter_footprint(&tex.view, &fp, f, &o);
    CHECK_EQ_INT(o.cls, FS_FP_CLASS_BILINEAR0);
    CHECK_EQ_INT(o.texels, 4);
    fp.dudx = fp.dvdy = 4;
    fs_footprint_affine_corners(&fp);
    fs_filter_footprint(&tex.view, &fp, f, &o);
    CHECK_EQ_INT(o.cls, FS_FP_CLASS_TRILINEAR);
    CHECK_NEAR(o.level, 2.0, 1e-9);
    fp.dudx = 8;
    fp.dvdy = 1.5;
    fs_footprint_affine_corners(&fp);
    fs_filter_footprint(&tex.view, &fp, f, &o);
    CHECK(o.cls == FS_FP_CLASS_FOOTPRINT || o.cls == FS_FP_CLASS_FOOTPRINT_2M);
    int lookups = -1;
    fs_footprint_filter_run(f, &tex.view, &fp, &o, &lookups);
    CHECK(lookups >= 1 && lookups <= 2);
    fs_footprint_filter_destroy(f);
    fs_mip_free(&tex);
}

/* ---- Table 4.3 ---- */

/* Positions of a grid and those on its border, by enumeration. */
static void recount(int a, int b, bool ms, long long *p, long long *pb)
{
    int px = ms ? a : a + 1, py = ms ? b : b + 1;
    *p = *pb = 0;
    for (int y = 0; y < py; y++)
        for (int x = 0; x < px; x++) {
            (*p)++;
            *pb += x == 0 || y == 0 || x == px - 1 || y == py - 1;
        }
}

TEST(table_4_3_counts)
{
    int consistent = 0;
    for (int i = 0; i < fs_fp_paper_table_rows; i++) {
        const fs_fp_paper_row *r = &fs_fp_paper_table[i];
        /* The printed products are the printed factors multiplied. */
        CHECK_EQ_INT(r->f1 * r->f2 * r->f3 * r->M, r->weights);
        int a, b;
        fs_fp_paper_shape(r, &a, &b);
        CHECK_EQ_INT(a * b, r->M);
        long long p, pb;
        recount(a, b, r->midpoint, &p, &pb);
        fs_fp_count c;
        fs_fp_count_shape(a, b, r->midpoint, &c);
        CHECK_EQ_INT(c.p, p);
        CHECK_EQ_INT(c.pb, pb);
        CHECK_EQ_INT(c.weights, pb * (pb - 1) * (p - 2) * r->M);
        bool self_consistent = r->f1 == pb && r->f2 == pb - 1 && r->f3 == p - 2;
        if (self_consistent) {
            consistent++;
            CHECK_EQ_INT(c.weights, r->weights);
        }
        /* The printed pointer counts are the unreduced structure's
         * p + p(p-1) + p(p-1)(p-2), except the two M = 16 mid-point rows
         * (3,136 for 3,616, the text's own count in 4.3.4). */
        if (r->midpoint && r->M == 16) {
            CHECK_EQ_INT(c.pointers_full, 3616);
            CHECK(r->pointers != c.pointers_full);
        } else {
            CHECK_EQ_INT(c.pointers_full, r->pointers);
        }
    }
    /* I 5x5, I 3x9 and I 5x9 are the rows whose factors do not follow from
     * their own grid: 12*11*23 where the 5x5 grid has 16 border positions,
     * 20*19*23 where 3x9 has 27 positions (25 = 27-2), 24*23*49 where 5x9
     * has 45 (43). */
    CHECK_EQ_INT(consistent, fs_fp_paper_table_rows - 3);
    /* The text's numbers (4.3.4): 25*24*23*22 = 303,600 quadrilaterals,
     * 16 + 16*15 + 16*15*14 = 3616 pointers. */
    fs_fp_count c;
    fs_fp_count_shape(4, 4, true, &c);
    CHECK_EQ_INT(c.pointers_full, 16 + 16 * 15 + 16 * 15 * 14);
    CHECK_EQ_INT(c.weights, 29568);
}


/* ---- GL_FRAGSIM_footprint_filter ---- */

TEST(gl_parameters_and_errors)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    CHECK(strstr((const char *)fsglGetString(c, GL_EXTENSIONS), "GL_FRAGSIM_footprint_filter") != NULL);
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    const fs_tex_object *t = fs_tex_bound_2d(c);
    CHECK_EQ_INT(t->footprint_budget, 16);
    CHECK_EQ_INT(t->footprint_snap, GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, 32);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(t->footprint_budget, 32);
    static const GLint bad[] = {0, 1, 12, 33, -16, 128, 4, 65536};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, bad[i]);
        CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
        CHECK_EQ_INT(t->footprint_budget, 32);
    }
    fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, 16.5f);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    CHECK_EQ_INT(t->footprint_budget, 32);
    fsglTexParameterf(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, 64.0f);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(t->footprint_budget, 64);
    GLint q = 0;
    fsglGetTexParameteriv(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, &q);
    CHECK_EQ_INT(q, 64);
    fsglGetTexParameteriv(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM, &q);
    CHECK_EQ_INT(q, GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM, GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(t->footprint_snap, GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM, GL_LINEAR);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    CHECK_EQ_INT(t->footprint_snap, GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_FOOTPRINT_HYBRID_FRAGSIM);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK_EQ_INT(t->min_filter, GL_FOOTPRINT_HYBRID_FRAGSIM);
    /* Not a magnification filter (the footprint filters minify only). */
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_FOOTPRINT_FRAGSIM);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    CHECK_EQ_INT(t->mag_filter, GL_LINEAR);
    /* A bad min filter leaves the footprint filter selected. */
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_FOOTPRINT_FRAGSIM + 15);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    CHECK_EQ_INT(t->min_filter, GL_FOOTPRINT_HYBRID_FRAGSIM);
    fs_context_destroy(c);
}

/* A tilted, minified quad with a constant-colour MIPmapped texture: every
 * textured pixel has that colour, and every pixel went through one of the
 * filter's classes. */
static void draw_plane(fs_context *c, GLenum minf, int M, GLenum snap, const uint8_t col[4])
{
    fsglViewport(c, 0, 0, 64, 48);
    fsglClearColor(c, 0.0f, 0.0f, 1.0f, 1.0f);
    fsglClear(c, GL_COLOR_BUFFER_BIT);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglFrustum(c, -1.0, 1.0, -0.75, 0.75, 1.0, 100.0);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTranslatef(c, 0, -1, -3);
    fsglRotatef(c, -75, 1, 0, 0);
    fsglRotatef(c, 30, 0, 0, 1);
    fsglBindTexture(c, GL_TEXTURE_2D, 5);
    uint8_t *px = malloc(64 * 64 * 4);
    for (int i = 0; i < 64 * 64; i++)
        memcpy(px + 4 * i, col, 4);
    for (int l = 0, s = 64; s >= 1; l++, s /= 2)
        fsglTexImage2D(c, GL_TEXTURE_2D, l, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    free(px);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)minf);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, M);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM, (GLint)snap);
    fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fsglEnable(c, GL_TEXTURE_2D);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, 0, 0);
    fsglVertex3f(c, -20, -20, 0);
    fsglTexCoord2f(c, 40, 0);
    fsglVertex3f(c, 20, -20, 0);
    fsglTexCoord2f(c, 40, 40);
    fsglVertex3f(c, 20, 20, 0);
    fsglTexCoord2f(c, 0, 40);
    fsglVertex3f(c, -20, 20, 0);
    fsglEnd(c);
}

TEST(gl_constant_texture_renders_its_colour)
{
    static const uint8_t col[4] = {200, 120, 40, 255};
    static const GLenum filters[2] = {GL_FOOTPRINT_FRAGSIM, GL_FOOTPRINT_HYBRID_FRAGSIM};
    static const GLenum snaps[2] = {GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM, GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM};
    for (int fi = 0; fi < 2; fi++)
        for (int M = 8; M <= 64; M *= 2)
            for (int si = 0; si < 2; si++) {
                fs_context *c = fs_context_create(NULL, 64, 48);
                REQUIRE(c);
                draw_plane(c, filters[fi], M, snaps[si], col);
                CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
                long textured = 0, wrong = 0;
                for (int i = 0; i < 64 * 48; i++) {
                    const uint8_t *p = c->fb.color + 4 * i;
                    if (p[0] == 0 && p[1] == 0 && p[2] == 255)
                        continue; /* background */
                    textured++;
                    wrong += memcmp(p, col, 4) != 0;
                }
                const fs_stats *st = &c->stats;
                uint64_t classes = st->tex_fp_bilinear0 + st->tex_fp_trilinear + st->tex_fp_footprint +
                                   st->tex_fp_footprint_2m;
                CHECK(textured > 1000);
                CHECK_EQ_INT(wrong, 0);
                /* Minified pixels go through the filter, magnified ones
                 * (near the viewer) through the mag filter. */
                CHECK(classes > 0 && classes <= (uint64_t)textured);
                CHECK(st->tex_fp_footprint + st->tex_fp_footprint_2m > 0);
                CHECK(st->tex_fp_rom_lookups > 0);
                CHECK(st->tex_fp_texels >= 4 * classes);
                if (wrong || !(st->tex_fp_footprint > 0))
                    fprintf(stderr, "  filter %d M %d snap %d: %ld textured, %ld wrong, classes %llu/%llu/%llu/%llu\n", fi,
                            M, si, textured, wrong, (unsigned long long)st->tex_fp_bilinear0,
                            (unsigned long long)st->tex_fp_trilinear, (unsigned long long)st->tex_fp_footprint,
                            (unsigned long long)st->tex_fp_footprint_2m);
                fs_context_destroy(c);
            }
}

/* docs/footprint_rom.md is what `fragsim rom --markdown` prints now. */
static char *slurp(FILE *f, long *n)
{
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)*n + 1);
    if (b && fread(b, 1, (size_t)*n, f) != (size_t)*n) {
        free(b);
        b = NULL;
    }
    return b;
}

TEST(rom_doc_is_current)
{
    char bad[] = "--bogus";
    char *bargv[] = {bad, NULL};
    CHECK_EQ_INT(fs_cli_rom(1, bargv), 2);
    FILE *doc = fopen("docs/footprint_rom.md", "rb");
    if (!doc)
        SKIP("docs/footprint_rom.md not found (run from the repository root)");
    long nd = 0, nt = 0;
    char *want = slurp(doc, &nd);
    fclose(doc);
    char path[] = "/tmp/fs_rom_XXXXXX";
    int fd = mkstemp(path);
    REQUIRE(fd >= 0 && want);
    fflush(stdout);
    int saved = dup(1);
    dup2(fd, 1);
    char md[] = "--markdown";
    char *argv[] = {md, NULL};
    int rc = fs_cli_rom(1, argv);
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    close(fd);
    FILE *f = fopen(path, "rb");
    char *got = f ? slurp(f, &nt) : NULL;
    if (f)
        fclose(f);
    unlink(path);
    CHECK_EQ_INT(rc, 0);
    REQUIRE(got);
    if (nd != nt || memcmp(want, got, (size_t)nd) != 0)
        CHECK_FAIL_("%s", "docs/footprint_rom.md is stale: regenerate with build/fragsim rom --markdown > docs/footprint_rom.md");
    free(want);
    free(got);
}

/* Through GL: an orthographic quad whose pixels each cover exactly 4 x 1
 * level-0 texels (u = 4x + 2, v = y + 0.5 at pixel centres) renders the
 * brute-force box average of those texels, within the 8-bit weights and
 * the colour buffer's rounding. */
TEST(gl_whole_texel_footprints_are_box_averages)
{
    enum { TW = 128, TH = 16, VW = 32, VH = 16 };
    uint8_t *img = malloc(TW * TH * 4);
    REQUIRE(img);
    uint32_t seed = 4242;
    for (int i = 0; i < TW * TH * 4; i++) {
        seed = seed * 1664525u + 1013904223u;
        img[i] = (uint8_t)(seed >> 24);
    }
    fs_mip_owned mip;
    REQUIRE(fs_mip_build_box(&mip, img, TW, TH, GL_REPEAT) == 0);
    static const GLenum filters[2] = {GL_FOOTPRINT_FRAGSIM, GL_FOOTPRINT_HYBRID_FRAGSIM};
    for (int fi = 0; fi < 2; fi++)
        for (int M = 8; M <= 32; M *= 2) {
            fs_context *c = fs_context_create(NULL, VW, VH);
            REQUIRE(c);
            fsglViewport(c, 0, 0, VW, VH);
            fsglMatrixMode(c, GL_PROJECTION);
            fsglLoadIdentity(c);
            fsglOrtho(c, 0, VW, 0, VH, -1, 1);
            fsglMatrixMode(c, GL_MODELVIEW);
            fsglLoadIdentity(c);
            fsglBindTexture(c, GL_TEXTURE_2D, 1);
            for (int l = 0; l < mip.view.levels; l++)
                fsglTexImage2D(c, GL_TEXTURE_2D, l, GL_RGBA, mip.view.width[l], mip.view.height[l], 0, GL_RGBA,
                               GL_UNSIGNED_BYTE, mip.view.texels[l]);
            fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filters[fi]);
            fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, M);
            fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
            fsglEnable(c, GL_TEXTURE_2D);
            fsglBegin(c, GL_QUADS);
            fsglTexCoord2f(c, 0, 0);
            fsglVertex2f(c, 0, 0);
            fsglTexCoord2f(c, 1, 0);
            fsglVertex2f(c, VW, 0);
            fsglTexCoord2f(c, 1, 1);
            fsglVertex2f(c, VW, VH);
            fsglTexCoord2f(c, 0, 1);
            fsglVertex2f(c, 0, VH);
            fsglEnd(c);
            CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
            int worst = 0;
            for (int y = 0; y < VH; y++)
                for (int x = 0; x < VW; x++)
                    for (int ch = 0; ch < 4; ch++) {
                        int sum = 0;
                        for (int k = 0; k < 4; k++)
                            sum += img[(y * TW + 4 * x + k) * 4 + ch];
                        int d = abs((int)c->fb.color[(y * VW + x) * 4 + ch] - (int)lround(sum / 4.0));
                        worst = d > worst ? d : worst;
                    }
            CHECK(worst <= 1);
            CHECK_EQ_INT(c->stats.tex_fp_footprint, VW * VH);
            CHECK_EQ_INT(c->stats.tex_fp_texels, (uint64_t)VW * VH * M);
            if (worst > 1)
                fprintf(stderr, "  filter %d M %d: largest difference %d\n", fi, M, worst);
            fs_context_destroy(c);
        }
    fs_mip_free(&mip);
    free(img);
}

/* A rotated, elongated footprint (4.3.6, Fig. 4.32): its bounding box is
 * far larger than it, so the filter cuts it in two and gives each half its
 * own array at a finer level than eq. 4.17 gives for the whole box.  On a
 * linear ramp in u (texel i holds i/255; box MIPmapping keeps a ramp
 * linear, texel centres on the same line) every normalised coverage
 * average is the ramp at the coverage's centroid, so the box filter over
 * the footprint is the ramp at the parallelogram's centre (closed form);
 * snapping moves each corner by at most half a texel of the level used. */
TEST(distorted_footprint_uses_two_finer_arrays)
{
    uint8_t *img = malloc(256 * 256 * 4);
    REQUIRE(img);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++)
            for (int ch = 0; ch < 4; ch++)
                img[(y * 256 + x) * 4 + ch] = (uint8_t)(ch == 3 ? 255 : x);
    fs_mip_owned tex;
    REQUIRE(fs_mip_build_box(&tex, img, 256, 256, GL_CLAMP_TO_EDGE) == 0);
    /* Long axis 48 texels at 45 and 135 degrees, short axis 3 texels. */
    static const double dir[2][2] = {{0.70710678, 0.70710678}, {-0.70710678, 0.70710678}};
    /* M = 16 only: with M = 32 the halves of this 45-degree strip are
     * diamonds that fit no single array, so the whole footprint is
     * filtered in one step (not what this test is about). */
    for (int M = 16; M <= 16; M *= 2)
        for (int d = 0; d < 2; d++) {
            fs_footprint_filter *f = fs_footprint_filter_create(M, false, false);
            REQUIRE(f);
            fs_footprint fp = {0};
            fp.u = 127.3;
            fp.v = 131.6;
            fp.dudx = 48 * dir[d][0];
            fp.dvdx = 48 * dir[d][1];
            fp.dudy = -3 * dir[d][1];
            fp.dvdy = 3 * dir[d][0];
            fs_footprint_affine_corners(&fp);
            double u0 = 1e9, u1 = -1e9, v0 = 1e9, v1 = -1e9;
            for (int k = 0; k < 4; k++) {
                u0 = fmin(u0, fp.corner_u[k]);
                u1 = fmax(u1, fp.corner_u[k]);
                v0 = fmin(v0, fp.corner_v[k]);
                v1 = fmax(v1, fp.corner_v[k]);
            }
            int whole = fs_footprint_lambda(u1 - u0, v1 - v0, M, NULL, NULL);
            fs_filter_out o;
            int lookups = 0;
            fs_footprint_filter_run(f, &tex.view, &fp, &o, &lookups);
            CHECK_EQ_INT(o.cls, FS_FP_CLASS_FOOTPRINT_2M);
            CHECK(o.level < whole);
            CHECK(o.texels > M && o.texels <= 2 * M);
            CHECK(lookups >= 2 && lookups <= 4);
            double lev = ceil(o.level);
            double tol = (0.5 * pow(2.0, lev) + 1.0) / 255.0;
            CHECK_NEAR(o.rgba[0], (fp.u - 0.5) / 255.0, tol);
            fs_footprint_filter_destroy(f);
        }
    /* Thin diagonal footprints (0.3 texels wide) snap to zero area at
     * every level eq. 4.17 allows; they are widened to one or two texels
     * along their own direction and still footprint-filtered (not
     * MIPmapped), the centroid moving by at most a texel of the level. */
    for (int M = 8; M <= 32; M *= 2)
        for (int deg = 20; deg <= 70; deg += 25) {
            fs_footprint_filter *f = fs_footprint_filter_create(M, false, false);
            REQUIRE(f);
            double c = cos(deg * 3.14159265358979 / 180), s = sin(deg * 3.14159265358979 / 180);
            fs_footprint fp = {0};
            fp.u = 120.6;
            fp.v = 97.2;
            fp.dudx = 40 * c;
            fp.dvdx = 40 * s;
            fp.dudy = -0.3 * s;
            fp.dvdy = 0.3 * c;
            fs_footprint_affine_corners(&fp);
            fs_filter_out o;
            fs_footprint_filter_run(f, &tex.view, &fp, &o, NULL);
            CHECK(o.cls == FS_FP_CLASS_FOOTPRINT || o.cls == FS_FP_CLASS_FOOTPRINT_2M);
            CHECK(o.texels <= 2 * M);
            double tol = (pow(2.0, ceil(o.level)) + 1.0) / 255.0;
            CHECK_NEAR(o.rgba[0], (fp.u - 0.5) / 255.0, tol);
            fs_footprint_filter_destroy(f);
        }
    fs_mip_free(&tex);
    free(img);
}

TEST_LIST = {
    TEST_ENTRY(rom_vectors_sum_to_triangle_area),
    TEST_ENTRY(rom_weights_match_point_sampling),
    TEST_ENTRY(rom_symmetric_cases_agree),
    TEST_ENTRY(lambda_matches_eq_4_14_to_4_17),
    TEST_ENTRY(constant_texture_filters_to_itself),
    TEST_ENTRY(whole_texel_footprint_is_box_average),
    TEST_ENTRY(degenerate_footprints_are_defined),
    TEST_ENTRY(hybrid_selects_by_shape),
    TEST_ENTRY(distorted_footprint_uses_two_finer_arrays),
    TEST_ENTRY(table_4_3_counts),
    TEST_ENTRY(rom_doc_is_current),
    TEST_ENTRY(gl_parameters_and_errors),
    TEST_ENTRY(gl_constant_texture_renders_its_colour),
    TEST_ENTRY(gl_whole_texel_footprints_are_box_averages),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
