/*
 * Reference texture filters and the ground-plane scene
 * (units/texture_reference.c) against closed-form oracles: constant and
 * linear-ramp textures, hand-computed footprint-assembly plans, GL's
 * trilinear filter for isotropic footprints, the Gaussian integral for the
 * EWA weights, a forward projection (look-at + perspective) for the ray
 * mapping, finite differences for the Jacobian, hand-computed PSNR.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "check.h"
#include "../units/texture_reference.h"

#define PI 3.14159265358979323846

/* Texture kinds: 0 constant (51, 102, 153, 255); 1 ramp (R = x, G = y,
 * one step of 1/255 per texel); 2 pseudo-random. */
static int make_tex(fs_mip_owned *t, int w, int h, int kind, GLenum wrap)
{
    uint8_t *p = malloc((size_t)w * h * 4);
    uint32_t r = 12345;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *q = p + ((size_t)y * w + x) * 4;
            if (kind == 0) {
                q[0] = 51, q[1] = 102, q[2] = 153, q[3] = 255;
            } else if (kind == 1) {
                q[0] = (uint8_t)x, q[1] = (uint8_t)y, q[2] = 0, q[3] = 255;
            } else {
                for (int ch = 0; ch < 4; ch++) {
                    r = r * 1664525u + 1013904223u;
                    q[ch] = (uint8_t)(r >> 24);
                }
            }
        }
    int rc = fs_mip_build_box(t, p, w, h, wrap);
    free(p);
    return rc;
}

static fs_footprint affine_fp(double u, double v, double dudx, double dvdx, double dudy, double dvdy)
{
    fs_footprint fp = {u, v, dudx, dvdx, dudy, dvdy, {0}, {0}};
    fs_footprint_affine_corners(&fp);
    return fp;
}

static const fs_fa_params fa16 = {16};
static const fs_aniso_params an16 = {16};
static const fs_ewa_params ewa = {0.5, 2.0, 0.5, 1.0, 16.0, 4096};
static const fs_truth_params truth = {16, 64, 0.5, 7};

typedef struct named_filter { const char *name; fs_filter_fn *fn; const void *params; } named_filter;
static const named_filter filters[] = {
    {"assembly", fs_filter_footprint_assembly, &fa16},
    {"aniso16", fs_filter_aniso, &an16},
    {"ewa", fs_filter_ewa, &ewa},
    {"truth", fs_filter_truth, &truth},
};
#define NFILTERS (int)(sizeof filters / sizeof filters[0])

TEST(constant_texture_gives_constant)
{
    fs_mip_owned t;
    REQUIRE(make_tex(&t, 64, 32, 0, GL_REPEAT) == 0);
    fs_footprint fps[] = {
        affine_fp(10.2, 7.9, 0.3, 0, 0, 0.3),          /* magnified */
        affine_fp(10.2, 7.9, 4, 0, 0, 4),              /* isotropic minified */
        affine_fp(30.5, 3.1, 1, 0.5, -20, 40),         /* anisotropic, rotated */
        affine_fp(-300, 900, 200, 0, 0, 300),          /* larger than the texture */
    };
    fs_ground_scene s = {64, 64, 1.0, 20, 60, 40, 25, 3, 5, 50};
    fs_footprint persp;
    REQUIRE(fs_ground_footprint(&s, 30, 40, &persp));
    for (int f = 0; f < NFILTERS; f++)
        for (int i = 0; i < 5; i++) {
            fs_filter_out o;
            filters[f].fn(&t.view, i < 4 ? &fps[i] : &persp, filters[f].params, &o);
            CHECK_NEAR(o.rgba[0], 51 / 255.0, 1e-6);
            CHECK_NEAR(o.rgba[1], 102 / 255.0, 1e-6);
            CHECK_NEAR(o.rgba[2], 153 / 255.0, 1e-6);
            CHECK_NEAR(o.rgba[3], 1.0, 1e-6);
            CHECK(o.texels >= 1);
        }
    fs_mip_free(&t);
}

/* The box mean of a linear function over a parallelogram is its value at
 * the centre; bilinear reconstruction of a ramp is the ramp itself away from
 * the edges (texel x holds x/255 at centre x + 0.5). */
TEST(truth_of_ramp_is_analytic_mean)
{
    fs_mip_owned t;
    REQUIRE(make_tex(&t, 256, 256, 1, GL_CLAMP_TO_EDGE) == 0);
    fs_footprint fps[] = {
        affine_fp(100.3, 80.7, 6, 2, -1, 3),
        affine_fp(150.0, 40.25, 0.2, 0.1, 0.05, 0.3),
        affine_fp(60.9, 120.1, 1, 0, 30, 25),
    };
    for (int i = 0; i < 3; i++) {
        fs_filter_out o;
        fs_filter_truth(&t.view, &fps[i], &truth, &o);
        CHECK_NEAR(o.rgba[0], (fps[i].u - 0.5) / 255.0, 2e-5);
        CHECK_NEAR(o.rgba[1], (fps[i].v - 0.5) / 255.0, 2e-5);
        CHECK(o.cls >= 256);
    }
    /* EWA's kernel is symmetric about a texel centre: same mean. */
    fs_ewa_params big = ewa;
    big.minor_texels = 8;
    fs_footprint fp = affine_fp(100.5, 80.5, 6, 2, -1, 3);
    fs_filter_out o;
    fs_filter_ewa(&t.view, &fp, &big, &o);
    CHECK_NEAR(o.rgba[0], 100 / 255.0, 1e-6);
    CHECK_NEAR(o.rgba[1], 80 / 255.0, 1e-6);
    CHECK_EQ_INT(o.level, 0);
    fs_mip_free(&t);
}

TEST(nprobe_isotropic_is_trilinear)
{
    fs_mip_owned t;
    REQUIRE(make_tex(&t, 128, 128, 2, GL_REPEAT) == 0);
    fs_footprint fps[] = {
        affine_fp(17.3, 99.1, 3, 0, 0, 3),
        affine_fp(17.3, 99.1, 2, 1, -1, 2),
        affine_fp(5.5, 6.5, 0.4, 0, 0, 0.4),
    };
    for (int i = 0; i < 3; i++) {
        double l, du, dv;
        CHECK_EQ_INT(fs_aniso_plan(&fps[i], &an16, &l, &du, &dv), 1);
        fs_filter_out o;
        fs_filter_aniso(&t.view, &fps[i], &an16, &o);
        float ref[4];
        int n = fs_mip_trilinear(&t.view, fs_footprint_lambda_iso(&fps[i]), fps[i].u, fps[i].v, ref);
        for (int ch = 0; ch < 4; ch++)
            CHECK(o.rgba[ch] == ref[ch]);
        CHECK_EQ_INT(o.texels, n);
    }
    /* max_aniso 1 is GL's isotropic filter even for a long footprint. */
    fs_aniso_params one = {1};
    fs_footprint fp = affine_fp(40.1, 20.2, 1, 0, 3, 12);
    fs_filter_out o;
    fs_filter_aniso(&t.view, &fp, &one, &o);
    float ref[4];
    fs_mip_trilinear(&t.view, fs_footprint_lambda_iso(&fp), fp.u, fp.v, ref);
    for (int ch = 0; ch < 4; ch++)
        CHECK(o.rgba[ch] == ref[ch]);
    fs_mip_free(&t);
}

/* EXT rule by hand: Px = 1, Py = 5.5 -> N = ceil(5.5) = 6, lambda =
 * log2(5.5 / 6); clamped at 4: lambda = log2(5.5 / 4). */
TEST(nprobe_plan_by_hand)
{
    fs_footprint fp = affine_fp(0, 0, 1, 0, 0, 5.5);
    double l, du, dv;
    CHECK_EQ_INT(fs_aniso_plan(&fp, &an16, &l, &du, &dv), 6);
    CHECK_NEAR(l, log2(5.5 / 6), 1e-12);
    CHECK_NEAR(du, 0, 1e-12);
    CHECK_NEAR(dv, 5.5 / 6, 1e-12);
    fs_aniso_params four = {4};
    CHECK_EQ_INT(fs_aniso_plan(&fp, &four, &l, &du, &dv), 4);
    CHECK_NEAR(l, log2(5.5 / 4), 1e-12);
}

TEST(assembly_plan_by_hand)
{
    double l, du, dv;
    /* r1 = (8,0), r2 = (0,1): q = 1, N = 8, level 0, step (1, 0). */
    fs_footprint a = affine_fp(0, 0, 8, 0, 0, 1);
    CHECK_EQ_INT(fs_fa_plan(&a, &fa16, &l, &du, &dv), 8);
    CHECK_NEAR(l, 0, 1e-12);
    CHECK_NEAR(du, 1, 1e-12);
    CHECK_NEAR(dv, 0, 1e-12);
    /* r1 = (1,1), r2 = (6,-6): q = |r1| = sqrt 2, ratio 6 -> 2^round(2.585)
     * = 8, level log2 sqrt 2 = 0.5, step r2 / 8. */
    fs_footprint b = affine_fp(0, 0, 1, 1, 6, -6);
    CHECK_EQ_INT(fs_fa_plan(&b, &fa16, &l, &du, &dv), 8);
    CHECK_NEAR(l, 0.5, 1e-12);
    CHECK_NEAR(du, 0.75, 1e-12);
    CHECK_NEAR(dv, -0.75, 1e-12);
    /* Sheared r1 = (8,0), r2 = (8,1): the diagonal d2 = (0,-1) is the
     * shortest, q = 1, ratio |r2| = 8.06 -> N = 8, step r2 / 8. */
    fs_footprint c = affine_fp(0, 0, 8, 0, 8, 1);
    CHECK_EQ_INT(fs_fa_plan(&c, &fa16, &l, &du, &dv), 8);
    CHECK_NEAR(l, 0, 1e-12);
    CHECK_NEAR(du, 1, 1e-12);
    CHECK_NEAR(dv, 0.125, 1e-12);
    /* Clamped: max_n 4 with ratio 32: N = 4, q = 32 / 4 = 8, level 3. */
    fs_fa_params four = {4};
    fs_footprint d = affine_fp(0, 0, 32, 0, 0, 1);
    CHECK_EQ_INT(fs_fa_plan(&d, &four, &l, &du, &dv), 4);
    CHECK_NEAR(l, 3, 1e-12);
    CHECK_NEAR(du, 8, 1e-12);
    /* Ratio 2.9 rounds (log domain: 1.54) to 4; 2.7 (1.43) to 2. */
    fs_footprint e = affine_fp(0, 0, 2.9, 0, 0, 1);
    CHECK_EQ_INT(fs_fa_plan(&e, &fa16, &l, &du, &dv), 4);
    fs_footprint f = affine_fp(0, 0, 0, 1, 2.7, 0);
    CHECK_EQ_INT(fs_fa_plan(&f, &fa16, &l, &du, &dv), 2);
    CHECK_NEAR(du, 1.35, 1e-12);
}

/* Unnormalised Gaussian weights over the texel grid against the integral
 * of the truncated 2-D Gaussian: 2 pi sqrt(det S) (1 - exp(-R^2/2)); the
 * normalised weights then sum to 1. */
TEST(ewa_weights_match_gaussian_integral)
{
    fs_mip_owned t;
    REQUIRE(make_tex(&t, 256, 256, 0, GL_REPEAT) == 0);
    fs_ewa_params p = ewa;
    p.minor_texels = 16;
    fs_footprint fps[] = {affine_fp(100.2, 90.7, 20, 8, -5, 30), affine_fp(10.5, 200.1, 12, 0, 0, 12)};
    for (int i = 0; i < 2; i++) {
        fs_ewa_kernel k;
        REQUIRE(fs_ewa_setup(&t.view, &fps[i], &p, &k) == 0);
        CHECK_EQ_INT(k.level, 0);
        double sum = 0;
        int n = 0;
        for (int y = k.y0; y <= k.y1; y++)
            for (int x = k.x0; x <= k.x1; x++) {
                double du = x + 0.5 - k.cu, dv = y + 0.5 - k.cv;
                double q = k.A * du * du + k.B * du * dv + k.C * dv * dv;
                if (q <= k.q_max) {
                    sum += exp(-0.5 * q);
                    n++;
                }
            }
        double integral = 2 * PI * sqrt(k.det_sigma) * (1 - exp(-0.5 * k.q_max));
        CHECK_NEAR(sum / integral, 1.0, 0.02);
        /* Covariance by hand: 0.25 J J^T + 0.25 I. */
        const fs_footprint *f = &fps[i];
        double a = 0.25 * (f->dudx * f->dudx + f->dudy * f->dudy) + 0.25;
        double b = 0.25 * (f->dudx * f->dvdx + f->dudy * f->dvdy);
        double c = 0.25 * (f->dvdx * f->dvdx + f->dvdy * f->dvdy) + 0.25;
        CHECK_NEAR(k.det_sigma, a * c - b * b, 1e-9 * a * c);
        fs_filter_out o;
        fs_filter_ewa(&t.view, &fps[i], &p, &o);
        CHECK_EQ_INT(o.texels, n);
    }
    fs_mip_free(&t);
}

/* One bright texel: the filter's output is that texel's normalised
 * weight, computed here from the covariance by hand. */
TEST(ewa_impulse_weight_by_hand)
{
    uint8_t *img = calloc(64 * 64, 4);
    REQUIRE(img);
    img[(30 * 64 + 20) * 4] = 255;
    fs_mip_owned t;
    int rc = fs_mip_build_box(&t, img, 64, 64, GL_REPEAT);
    free(img);
    REQUIRE(rc == 0);
    fs_ewa_params p = ewa;
    p.minor_texels = 8;
    double J[4] = {3, 1, -1, 4};    /* dudx, dvdx, dudy, dvdy */
    fs_footprint fp = affine_fp(21.8, 29.8, J[0], J[1], J[2], J[3]);
    double a = 0.25 * (J[0] * J[0] + J[2] * J[2]) + 0.25, b = 0.25 * (J[0] * J[1] + J[2] * J[3]);
    double c = 0.25 * (J[1] * J[1] + J[3] * J[3]) + 0.25, det = a * c - b * b;
    double sum = 0, w_imp = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            double du = x + 0.5 - fp.u, dv = y + 0.5 - fp.v;
            double q = (c * du * du - 2 * b * du * dv + a * dv * dv) / det;
            if (q > 4)
                continue;
            sum += exp(-0.5 * q);
            if (x == 20 && y == 30)
                w_imp = exp(-0.5 * q);
        }
    fs_filter_out o;
    fs_filter_ewa(&t.view, &fp, &p, &o);
    CHECK(w_imp > 0);
    CHECK_NEAR(o.rgba[0], w_imp / sum, 1e-6);
    CHECK_NEAR(o.rgba[1], 0, 1e-9);
    fs_mip_free(&t);
}

static fs_ground_scene scene(void)
{
    fs_ground_scene s = {600, 400, 1.5, 17, 60, 200, 30, 11, -7, 80};
    return s;
}

/* Forward projection of the plane point: look-at basis and a perspective
 * divide, the inverse of the ray intersection fs_ground_map does. */
static void project(const fs_ground_scene *s, double u, double v, double *x, double *y)
{
    double g = s->tex_rotate_deg * PI / 180, k = s->texels_per_unit;
    double uu = (u - s->u0) / k, vv = (v - s->v0) / k;
    double X = uu * cos(g) + vv * sin(g), Y = -uu * sin(g) + vv * cos(g), Z = -s->eye_height;
    double p = s->pitch_deg * PI / 180;
    double xc = X, yc = Y * sin(p) + Z * cos(p), zc = Y * cos(p) - Z * sin(p);
    double th = tan(s->fov_y_deg * PI / 360), asp = (double)s->width / s->height;
    *x = s->width * 0.5 * (1 + xc / (zc * th * asp));
    *y = s->height * 0.5 * (1 + yc / (zc * th));
}

TEST(ground_mapping_inverts_projection)
{
    fs_ground_scene s = scene();
    char err[128];
    REQUIRE(fs_ground_scene_check(&s, err, sizeof err) == 0);
    int hits = 0;
    for (double y = 0.25; y < 400; y += 37.3)
        for (double x = 0.1; x < 600; x += 53.7) {
            double u, v;
            if (!fs_ground_map(&s, x, y, &u, &v))
                continue;
            hits++;
            double px, py;
            project(&s, u, v, &px, &py);
            CHECK_NEAR(px, x, 1e-7);
            CHECK_NEAR(py, y, 1e-7);
        }
    CHECK(hits > 50);
    /* Above the horizon (pitch 17 < half fov 30): no intersection. */
    double u, v;
    CHECK(!fs_ground_map(&s, 300, 399, &u, &v));
}

TEST(ground_footprint_jacobian_and_corners)
{
    fs_ground_scene s = scene();
    int visible = 0;
    for (int py = 0; py < 400; py += 13)
        for (int px = 0; px < 600; px += 41) {
            fs_footprint fp;
            if (!fs_ground_footprint(&s, px, py, &fp))
                continue;
            visible++;
            const double e = 1e-4;
            double u1, v1, u2, v2;
            REQUIRE(fs_ground_map(&s, px + 0.5 + e, py + 0.5, &u1, &v1));
            REQUIRE(fs_ground_map(&s, px + 0.5 - e, py + 0.5, &u2, &v2));
            double scale = 1e-6 * (1 + fabs(fp.dudx) + fabs(fp.dvdx) + fabs(fp.dudy) + fabs(fp.dvdy));
            CHECK_NEAR((u1 - u2) / (2 * e), fp.dudx, scale);
            CHECK_NEAR((v1 - v2) / (2 * e), fp.dvdx, scale);
            REQUIRE(fs_ground_map(&s, px + 0.5, py + 0.5 + e, &u1, &v1));
            REQUIRE(fs_ground_map(&s, px + 0.5, py + 0.5 - e, &u2, &v2));
            CHECK_NEAR((u1 - u2) / (2 * e), fp.dudy, scale * 10);
            CHECK_NEAR((v1 - v2) / (2 * e), fp.dvdy, scale * 10);
            /* The mapping is projective: the square-to-quad map through the
             * four corners sends the square's centre to the pixel centre. */
            fs_homography H;
            REQUIRE(fs_homography_from_corners(&fp, &H));
            double u, v;
            fs_homography_map(&H, 0.5, 0.5, &u, &v);
            CHECK_NEAR(u, fp.u, 1e-6 * (1 + fabs(fp.u)));
            CHECK_NEAR(v, fp.v, 1e-6 * (1 + fabs(fp.v)));
            fs_homography_map(&H, 0.25, 0.8, &u, &v);
            double ue, ve;
            REQUIRE(fs_ground_map(&s, px + 0.25, py + 0.8, &ue, &ve));
            CHECK_NEAR(u, ue, 1e-6 * (1 + fabs(ue)));
            CHECK_NEAR(v, ve, 1e-6 * (1 + fabs(ve)));
        }
    CHECK(visible > 100);
}

TEST(degenerate_footprints_give_finite_colours)
{
    fs_mip_owned t;
    REQUIRE(make_tex(&t, 64, 64, 2, GL_REPEAT) == 0);
    double nan = NAN, inf = INFINITY;
    fs_footprint fps[] = {
        affine_fp(nan, 3, 1, 0, 0, 1),
        affine_fp(3, inf, 1, 0, 0, 1),
        affine_fp(3, 4, nan, 0, 0, 1),
        affine_fp(3, 4, inf, inf, 0, 1),
        affine_fp(3, 4, 0, 0, 0, 0),            /* zero area */
        affine_fp(3, 4, 2, 1, 4, 2),            /* collinear: rank 1 */
        affine_fp(3, 4, 1000, 0, 0, 1),         /* 1:1000 */
        affine_fp(3, 4, 0.001, 0, 0, 1),
        affine_fp(1e300, -1e300, 1e200, 0, 0, 1e200),
        affine_fp(3, 4, -1e-300, 1e-300, 0, 0),
    };
    fs_footprint bad_corners = affine_fp(3, 4, 2, 0, 0, 2);
    bad_corners.corner_u[2] = nan;
    fs_footprint folded = affine_fp(3, 4, 2, 0, 0, 2);
    folded.corner_u[1] = -5;    /* a bow-tie */
    for (int f = 0; f < NFILTERS; f++)
        for (int i = 0; i < 12; i++) {
            const fs_footprint *fp = i < 10 ? &fps[i] : i == 10 ? &bad_corners : &folded;
            fs_filter_out o;
            filters[f].fn(&t.view, fp, filters[f].params, &o);
            for (int ch = 0; ch < 4; ch++)
                if (!(o.rgba[ch] >= 0 && o.rgba[ch] <= 1))
                    CHECK_FAIL_("%s footprint %d channel %d: %g", filters[f].name, i, ch, o.rgba[ch]);
            CHECK(isfinite(o.level));
        }
    fs_mip_free(&t);
}

TEST(psnr_by_hand)
{
    float a[8] = {0, 0, 0, 1, 0.5f, 0.5f, 0.5f, 1};
    float b[8] = {0.1f, 0, 0, 0, 0.5f, 0.5f, 0.5f, 0};
    uint8_t all[2] = {1, 1}, second[2] = {0, 1}, none[2] = {0, 0};
    /* MSE = 0.01 / (3 * 2): PSNR = 10 log10(600); alpha is ignored. */
    double d = (double)0.1f;
    CHECK_NEAR(fs_psnr_rgb(a, b, all, 2), 10 * log10(6.0 / (d * d)), 1e-9);
    CHECK_NEAR(fs_psnr_rgb(a, b, NULL, 2), 27.7815125, 1e-5);
    CHECK(isinf(fs_psnr_rgb(a, b, second, 2)));
    CHECK(isnan(fs_psnr_rgb(a, b, none, 2)));
}

TEST(scene_check_rejects_bad_input)
{
    char err[128];
    fs_ground_scene s = scene();
    s.pitch_deg = 95;
    CHECK(fs_ground_scene_check(&s, err, sizeof err) == -1);
    s = scene();
    s.eye_height = NAN;
    CHECK(fs_ground_scene_check(&s, err, sizeof err) == -1);
    s = scene();
    s.width = 0;
    CHECK(fs_ground_scene_check(&s, err, sizeof err) == -1);
    s = scene();
    s.texels_per_unit = INFINITY;
    CHECK(fs_ground_scene_check(&s, err, sizeof err) == -1);
}

TEST_LIST = {
    TEST_ENTRY(constant_texture_gives_constant),
    TEST_ENTRY(truth_of_ramp_is_analytic_mean),
    TEST_ENTRY(nprobe_isotropic_is_trilinear),
    TEST_ENTRY(nprobe_plan_by_hand),
    TEST_ENTRY(assembly_plan_by_hand),
    TEST_ENTRY(ewa_weights_match_gaussian_integral),
    TEST_ENTRY(ewa_impulse_weight_by_hand),
    TEST_ENTRY(ground_mapping_inverts_projection),
    TEST_ENTRY(ground_footprint_jacobian_and_corners),
    TEST_ENTRY(degenerate_footprints_give_finite_colours),
    TEST_ENTRY(psnr_by_hand),
    TEST_ENTRY(scene_check_rejects_bad_input),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
