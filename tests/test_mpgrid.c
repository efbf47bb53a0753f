/*
 * The MP-Grid (units/mpgrid*.c, clip_map.c; Huettner 1999, 4.1) and its GL
 * extension GL_FRAGSIM_mp_grid (docs/extensions/mp_grid.txt).
 *
 * Oracles: one big texture box-filtered by fs_mip_build_box (texel
 * equality wherever levels are resident), brute-force recounts of pyramid
 * border crossings along scans (CTR reloads, thrashing), closed forms for a
 * camera looking straight down (residency) and for the memory example's
 * full MIPmap and Clip-Map, a per-pixel ray cast for the adapted MP-Grid,
 * and an ordinary GL texture rendered by the same pipeline.
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
#include "../units/mpgrid.h"
#include "../units/texture_filter.h"
#include "../units/texture_unit.h"
#include "../glext/GL_FRAGSIM_mp_grid.h"

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static uint8_t *random_rgba(int w, int h, uint32_t seed)
{
    uint8_t *p = malloc((size_t)w * h * 4);
    for (size_t k = 0; p && k < (size_t)w * h * 4; k++)
        p[k] = (uint8_t)rng(&seed);
    return p;
}

/* Copies the tile (i, j) of tw x th out of a W-wide RGBA image. */
static void cut_tile(const uint8_t *big, int W, int i, int j, int tw, int th, uint8_t *out)
{
    for (int y = 0; y < th; y++)
        memcpy(out + (size_t)y * tw * 4, big + (((size_t)j * th + y) * W + (size_t)i * tw) * 4, (size_t)tw * 4);
}

/* A grid whose pyramids are the box-filtered tiles of `big` (each tile
 * filtered on its own by fs_mip_build_box). */
static int grid_from_big(fs_mpgrid *g, const uint8_t *big, int n, int m, int tw, int th, int merge_side,
                         int merge_block)
{
    fs_mpgrid_layout L;
    if (fs_mpgrid_make_layout(n, m, tw, th, &L) < 0 || fs_mpgrid_init(g, &L, 4, merge_side, merge_block) < 0)
        return -1;
    uint8_t *tile = malloc((size_t)tw * th * 4);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            fs_mip_owned mo;
            cut_tile(big, n * tw, i, j, tw, th, tile);
            if (fs_mip_build_box(&mo, tile, tw, th, GL_CLAMP_TO_EDGE) < 0 || mo.view.levels != L.levels) {
                free(tile);
                return -1;
            }
            for (int l = 0; l < L.levels; l++)
                fs_mpgrid_set_image(g, i, j, l, mo.view.texels[l]);
            fs_mip_free(&mo);
        }
    free(tile);
    return 0;
}

TEST(layout_minimal_scaling)
{
    fs_mpgrid_layout L;
    /* The paper's example: 5120 = 5 x 1024 exactly. */
    REQUIRE(fs_mpgrid_choose_layout(5120, 5120, 512, 1024, &L) == 0);
    CHECK_EQ_INT(L.tile_w, 1024);
    CHECK_EQ_INT(L.tile_h, 1024);
    CHECK_EQ_INT(L.n, 5);
    CHECK_EQ_INT(L.m, 5);
    CHECK_EQ_INT(L.levels, 11);
    /* 3000 x 1500: width 3 x 1024 = 3072 either way (the larger tile wins),
     * height 3 x 512 = 1536 < 2 x 1024 = 2048: a 1024 x 512 tile. */
    REQUIRE(fs_mpgrid_choose_layout(3000, 1500, 512, 1024, &L) == 0);
    CHECK_EQ_INT(L.tile_w, 1024);
    CHECK_EQ_INT(L.tile_h, 512);
    CHECK_EQ_INT(L.n, 3);
    CHECK_EQ_INT(L.m, 3);
    CHECK_EQ_INT(L.levels, 11);
    /* Brute force over every tile pair: no other choice scales less. */
    for (int64_t w = 1; w <= 5000; w += 611)
        for (int64_t h = 1; h <= 5000; h += 733) {
            REQUIRE(fs_mpgrid_choose_layout(w, h, 64, 1024, &L) == 0);
            int64_t area = L.scaled_w * L.scaled_h;
            CHECK(L.scaled_w >= w && L.scaled_h >= h);
            for (int tw = 64; tw <= 1024; tw *= 2)
                for (int th = 64; th <= 1024; th *= 2) {
                    int64_t a = (w + tw - 1) / tw * tw * ((h + th - 1) / th * th);
                    CHECK(a >= area);
                    if (a == area)
                        CHECK((int64_t)tw * th <= (int64_t)L.tile_w * L.tile_h);
                }
        }
}

TEST(layout_bad_input)
{
    fs_mpgrid_layout L;
    CHECK_EQ_INT(fs_mpgrid_choose_layout(0, 100, 64, 1024, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_choose_layout(100, -5, 64, 1024, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_choose_layout(100, 100, 100, 1024, &L), -1);  /* not a power of two */
    CHECK_EQ_INT(fs_mpgrid_choose_layout(100, 100, 2048, 1024, &L), -1); /* min > max */
    CHECK_EQ_INT(fs_mpgrid_choose_layout(INT64_MAX / 2, 100, 64, 1024, &L), -1); /* too many pyramids */
    CHECK_EQ_INT(fs_mpgrid_make_layout(0, 1, 16, 16, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_make_layout(1, -1, 16, 16, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_make_layout(1, 1, 0, 16, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_make_layout(1, 1, 24, 16, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_make_layout(FS_MPGRID_MAX_PYRAMIDS + 1, 1, 16, 16, &L), -1);
    CHECK_EQ_INT(fs_mpgrid_make_layout(1, 1, 16, FS_MPGRID_MAX_TILE * 2, &L), -1);
    fs_mpgrid g;
    REQUIRE(fs_mpgrid_make_layout(2, 2, 8, 8, &L) == 0);
    CHECK_EQ_INT(fs_mpgrid_init(&g, &L, 0, 0, 0), -1);
    CHECK_EQ_INT(fs_mpgrid_init(&g, &L, 4, -1, 0), -1);
    CHECK_EQ_INT(fs_mpgrid_init(&g, &L, 4, 2, 0), -1);
    REQUIRE(fs_mpgrid_init(&g, &L, 4, 0, 0) == 0);
    uint8_t px[8 * 8 * 4] = {0};
    CHECK_EQ_INT(fs_mpgrid_set_image(&g, 2, 0, 0, px), -1);
    CHECK_EQ_INT(fs_mpgrid_set_image(&g, 0, 0, 4, px), -1);
    CHECK_EQ_INT(fs_mpgrid_set_image(&g, 0, 0, 0, NULL), -1);
    CHECK_EQ_INT(fs_mpgrid_set_finest(&g, -1, 0, 0), -1);
    fs_mpgrid_ctr r;
    fs_mpgrid_ctr_reset(&r);
    uint8_t out[4];
    /* Nothing resident: a defined miss, no crash, even far outside. */
    CHECK_EQ_INT(fs_mpgrid_fetch(&g, &r, 99, INT64_MAX, INT64_MIN, out), -1);
    CHECK_EQ_UINT(r.misses, 1);
    fs_mpgrid_free(&g);
}

/* Every texel at every level of an MP-Grid equals the big box-filtered
 * texture's where the level is resident (levels where a pyramid level is a
 * block of the big level: both sides >= 1 texel per pyramid), and the
 * substituted coarser texel elsewhere. */
static void compare_with_big(check_state *check_st_, int n, int m, int tw, int th)
{
    int W = n * tw, H = m * th;
    uint8_t *big = random_rgba(W, H, 77u + (uint32_t)(n * 31 + m));
    fs_mip_owned ref;
    REQUIRE(big && fs_mip_build_box(&ref, big, W, H, GL_CLAMP_TO_EDGE) == 0);
    fs_mpgrid g;
    REQUIRE(grid_from_big(&g, big, n, m, tw, th, 0, 0) == 0);
    /* Block-equivalent levels: until the shorter tile side is 1. */
    int eq_levels = 0;
    while ((tw >> eq_levels) >= 1 && (th >> eq_levels) >= 1)
        eq_levels++;
    /* Residency: a varied finest level per pyramid. */
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++)
            REQUIRE(fs_mpgrid_set_finest(&g, i, j, (i + 2 * j) % eq_levels) == 0);
    fs_mpgrid_ctr r;
    fs_mpgrid_ctr_reset(&r);
    long bad = 0, subst = 0, checked = 0;
    for (int l = 0; l < eq_levels; l++) {
        int lw = tw >> l, lh = th >> l;
        for (int y = 0; y < m * lh; y++)
            for (int x = 0; x < n * lw; x++) {
                int i = x / lw, j = y / lh;
                int finest = (i + 2 * j) % eq_levels;
                int use = l > finest ? l : finest;
                if (use != l)
                    subst++;
                uint8_t got[4];
                int lv = fs_mpgrid_fetch(&g, &r, l, x, y, got);
                const uint8_t *want = ref.view.texels[use] +
                                      ((size_t)(y >> (use - l)) * ref.view.width[use] + (size_t)(x >> (use - l))) * 4;
                checked++;
                if (lv != use || memcmp(got, want, 4) != 0)
                    bad++;
            }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_UINT(r.substitutions, subst);
    CHECK(checked > 0 && (n * m == 1 || subst > 0));
    fs_mip_free(&ref);
    fs_mpgrid_free(&g);
    free(big);
}

TEST(texels_equal_big_texture)
{
    compare_with_big(check_st_, 4, 2, 16, 16);
    compare_with_big(check_st_, 2, 4, 32, 8); /* non-square tiles */
    compare_with_big(check_st_, 1, 1, 8, 8);
}

/* Brute-force recount: the CTR loads an entry whenever the pyramid (block
 * for merged levels) of a fetch differs from the previous fetch's on that
 * level; thrashing is a load of the block loaded two loads before. */
static void scan_counts(check_state *check_st_, int merge_side, int merge_block)
{
    const int n = 4, m = 3, tw = 8, th = 8;
    uint8_t *big = random_rgba(n * tw, m * th, 5);
    fs_mpgrid g;
    REQUIRE(grid_from_big(&g, big, n, m, tw, th, merge_side, merge_block) == 0);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++)
            REQUIRE(fs_mpgrid_set_finest(&g, i, j, 0) == 0);
    for (int l = 0; l < g.L.levels; l++) {
        fs_mpgrid_ctr r;
        fs_mpgrid_ctr_reset(&r);
        int lw = fs_mpgrid_level_w(&g.L, l), lh = fs_mpgrid_level_h(&g.L, l);
        int B = merge_side > 0 && (lw > lh ? lw : lh) <= merge_side ? merge_block : 1;
        long loads = 0, thrash = 0;
        int hist[2] = {-1, -1}; /* the last two loaded blocks */
        uint32_t seed = 9;
        /* A raster scan, then a random walk (which goes back and forth). */
        for (int pass = 0; pass < 2; pass++) {
            int steps = pass == 0 ? n * lw * m * lh : 2000;
            int64_t x = 0, y = 0;
            for (int k = 0; k < steps; k++) {
                if (pass == 0) {
                    x = k % (n * lw);
                    y = k / (n * lw);
                } else {
                    x = (int64_t)(rng(&seed) % (uint32_t)(n * lw));
                    y = (int64_t)(rng(&seed) % (uint32_t)(m * lh));
                }
                int block = (int)(y / lh / B) * 1000 + (int)(x / lw / B);
                if (block != hist[1]) {
                    loads++;
                    if (block == hist[0])
                        thrash++;
                    hist[0] = hist[1];
                    hist[1] = block;
                }
                uint8_t out[4];
                CHECK_EQ_INT(fs_mpgrid_fetch(&g, &r, l, x, y, out), l);
            }
        }
        CHECK_EQ_UINT(r.reloads, loads);
        CHECK_EQ_UINT(r.thrashing, thrash);
        CHECK_EQ_UINT(r.substitutions, 0);
    }
    fs_mpgrid_free(&g);
    free(big);
}

TEST(ctr_reloads_equal_border_crossings)
{
    scan_counts(check_st_, 0, 0);
}

TEST(merged_levels_avoid_reloads)
{
    scan_counts(check_st_, 2, 2);
    scan_counts(check_st_, 4, 4); /* one block covers the whole 4 x 3 grid */
    /* With a block covering the whole grid the low levels never reload
     * after the first load. */
    const int n = 4, m = 3;
    uint8_t *big = random_rgba(n * 8, m * 8, 6);
    fs_mpgrid g;
    REQUIRE(grid_from_big(&g, big, n, m, 8, 8, 2, 4) == 0);
    fs_mpgrid_ctr r;
    fs_mpgrid_ctr_reset(&r);
    uint8_t out[4];
    for (int x = 0; x < n * 2; x++)
        for (int y = 0; y < m * 2; y++)
            CHECK_EQ_INT(fs_mpgrid_fetch(&g, &r, 2, x, y, out), 2);
    CHECK_EQ_UINT(r.reloads, 1);
    /* merged levels are resident without any set_finest */
    CHECK(g.bytes_resident == (uint64_t)n * m * (4 + 1) * 4);
    fs_mpgrid_free(&g);
    free(big);
}

/* Looking straight down from height H with fovy 90 at a square pyramid of
 * side s centred in the view: the projected extent is s / (2 H tan 45) * V
 * pixels (V the viewport side). */
TEST(residency_closed_form)
{
    fs_mpgrid_layout L;
    REQUIRE(fs_mpgrid_make_layout(1, 1, 1024, 1024, &L) == 0);
    const double s = 1000.0, V = 1024.0;
    struct { double H; int level; } cases[] = {
        {2000.0, 2},  /* 256 px exactly: r = 256, level 2 */
        {1900.0, 1},  /* 269.5 px -> 512 */
        {4000.0, 3},  /* 128 px */
        {700.0, 0},   /* 731 px -> 1024 */
        {300000.0, 9} /* 1.7 px -> 2: level 9 */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        fs_mpgrid_camera cam;
        const double eye[3] = {500, 500, cases[k].H}, ctr[3] = {500, 500, 0}, up[3] = {0, 1, 0};
        REQUIRE(fs_mpgrid_camera_lookat(&cam, eye, ctr, up, 90.0, 1.0, 1e6, 1024, 1024) == 0);
        double lo[3] = {0, 0, 0}, hi[3] = {s, s, 0};
        double e = fs_mpgrid_projected_extent(&cam, lo, hi);
        CHECK_NEAR(e, s / (2.0 * cases[k].H) * V, 1e-6 * V);
        CHECK_EQ_INT(fs_mpgrid_needed_level(&L, e), cases[k].level);
    }
    /* Behind the viewer: no level.  Huge and tiny extents clamp. */
    fs_mpgrid_camera cam;
    const double eye[3] = {500, 500, 2000}, ctr[3] = {500, 500, 0}, up[3] = {0, 1, 0};
    REQUIRE(fs_mpgrid_camera_lookat(&cam, eye, ctr, up, 90.0, 1.0, 1e6, 1024, 1024) == 0);
    double blo[3] = {0, 0, 3000}, bhi[3] = {1000, 1000, 3000};
    CHECK_EQ_INT(fs_mpgrid_projected_extent(&cam, blo, bhi), 0);
    CHECK_EQ_INT(fs_mpgrid_needed_level(&L, 0.0), L.levels);
    CHECK_EQ_INT(fs_mpgrid_needed_level(&L, 1e9), 0);
    CHECK_EQ_INT(fs_mpgrid_needed_level(&L, 0.3), L.levels - 1);

    /* Adaptation: a 2 x 1 grid of 16x16 tiles, one pyramid occluded; the
     * loads and frees follow from the closed form level by level. */
    fs_mpgrid_layout L2;
    REQUIRE(fs_mpgrid_make_layout(2, 1, 16, 16, &L2) == 0);
    uint8_t *big = random_rgba(32, 16, 3);
    fs_mpgrid g;
    REQUIRE(grid_from_big(&g, big, 2, 1, 16, 16, 0, 0) == 0);
    CHECK_EQ_UINT(g.bytes_resident, 0);
    fs_mpgrid_box boxes[2] = {{{0, 0, 0}, {1000, 1000, 0}, false, false},
                              {{1000, 0, 0}, {2000, 1000, 0}, true, false}};
    fs_mpgrid_camera c2;
    /* 1000 units at height 4000, fovy 90, 64 px viewport: 8 px -> level 1. */
    const double e2[3] = {500, 500, 4000}, u2[3] = {0, 1, 0};
    REQUIRE(fs_mpgrid_camera_lookat(&c2, e2, ctr, u2, 90.0, 1.0, 1e6, 64, 64) == 0);
    fs_mpgrid_frame fr;
    REQUIRE(fs_mpgrid_adapt(&g, &c2, boxes, 0, &fr) == 0);
    CHECK_EQ_INT(g.finest[0], 1);
    CHECK_EQ_INT(g.finest[1], L2.levels);
    CHECK_EQ_UINT(fr.levels_loaded, 4);   /* 8x8, 4x4, 2x2, 1x1 */
    CHECK_EQ_UINT(fr.bytes_resident, 4 * (64 + 16 + 4 + 1));
    CHECK_EQ_INT(fr.pyramids_visible, 1);
    /* Coming closer (height 1000: 32 px -> level 0), the other unoccluded. */
    boxes[1].occluded = false;
    const double e3[3] = {500, 500, 1000};
    REQUIRE(fs_mpgrid_camera_lookat(&c2, e3, ctr, u2, 90.0, 1.0, 1e6, 64, 64) == 0);
    REQUIRE(fs_mpgrid_adapt(&g, &c2, boxes, 0, &fr) == 0);
    CHECK_EQ_INT(g.finest[0], 0);
    CHECK_EQ_UINT(fr.levels_loaded, 1 + (uint64_t)(L2.levels - g.finest[1]));
    /* Moving away frees them again. */
    const double e4[3] = {500, 500, 1e5};
    REQUIRE(fs_mpgrid_camera_lookat(&c2, e4, ctr, u2, 90.0, 1.0, 1e6, 64, 64) == 0);
    REQUIRE(fs_mpgrid_adapt(&g, &c2, boxes, 0, &fr) == 0);
    CHECK(fr.levels_freed > 0);
    CHECK_EQ_UINT(g.levels_loaded - g.levels_freed, (uint64_t)(2 * L2.levels - g.finest[0] - g.finest[1]));
    /* keep_side keeps the small levels of an occluded pyramid. */
    boxes[0].occluded = boxes[1].occluded = true;
    REQUIRE(fs_mpgrid_adapt(&g, &c2, boxes, 2, &fr) == 0);
    CHECK_EQ_UINT(g.bytes_resident, 2 * 4 * (4 + 1));
    fs_mpgrid_free(&g);
    free(big);
}

TEST(bad_camera_and_boxes)
{
    fs_mpgrid_camera cam;
    const double ok[3] = {0, 0, 1000}, ctr[3] = {1, 1, 0}, up[3] = {0, 0, 1};
    const double nan3[3] = {NAN, 0, 0}, inf3[3] = {INFINITY, 0, 0};
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, nan3, ctr, up, 45, 1, 100, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, inf3, up, 45, 1, 100, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ok, up, 45, 1, 100, 64, 64), -1);      /* eye == centre */
    const double upz[3] = {0, 0, 1}, down[3] = {0, 0, 0};
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, down, upz, 45, 1, 100, 64, 64), -1);  /* up parallel */
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, NAN, 1, 100, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, 180, 1, 100, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, 45, 0, 100, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, 45, 10, 5, 64, 64), -1);
    CHECK_EQ_INT(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, 45, 1, 100, 0, 64), -1);
    REQUIRE(fs_mpgrid_camera_lookat(&cam, ok, ctr, up, 45, 1, 100, 64, 64) == 0);
    double lo[3] = {0, 0, 0}, hi[3] = {NAN, 1, 1};
    CHECK(fs_mpgrid_projected_extent(&cam, lo, hi) < 0);
    fs_mpgrid_camera bad = cam;
    bad.m[5] = INFINITY;
    double hi2[3] = {1, 1, 1};
    CHECK(fs_mpgrid_projected_extent(&bad, lo, hi2) < 0);
    /* Adaptation with a NaN box fails and changes nothing. */
    fs_mpgrid_layout L;
    REQUIRE(fs_mpgrid_make_layout(2, 1, 4, 4, &L) == 0);
    uint8_t *big = random_rgba(8, 4, 1);
    fs_mpgrid g;
    REQUIRE(grid_from_big(&g, big, 2, 1, 4, 4, 0, 0) == 0);
    fs_mpgrid_box boxes[2] = {{{0, 0, 0}, {1, 1, 0}, false, false}, {{0, 0, 0}, {NAN, 1, 0}, false, false}};
    CHECK_EQ_INT(fs_mpgrid_adapt(&g, &cam, boxes, 0, NULL), -1);
    CHECK_EQ_UINT(g.levels_loaded, 0);
    uint64_t bytes;
    CHECK_EQ_INT(fs_mpgrid_adapted_bytes(&L, &cam, boxes, 1, 0, &bytes, NULL), -1);
    fs_mpgrid_free(&g);
    free(big);
    /* Table and Clip-Map sizes reject nonsense. */
    CHECK_EQ_UINT(fs_mpgrid_table_bytes(0, 100, 100, 4, 4), 0);
    CHECK_EQ_UINT(fs_clip_map_bytes(5000, 2048, 1), 0);
    CHECK_EQ_UINT(fs_clip_map_bytes(1024, 2048, 1), 0);
    CHECK_EQ_UINT(fs_clip_map_scaled_size(0, 5), 0);
}

/* ---- the memory example (Huettner 1999, 4.1.2 and 4.1.4) ---- */

static int example_camera(fs_mpgrid_camera *cam)
{
    const double eye[3] = {0, 0, 1000}, ctr[3] = {2500, 2500, 0}, up[3] = {0, 0, 1};
    return fs_mpgrid_camera_lookat(cam, eye, ctr, up, 45.0, 1.0, 10000.0, 1024, 1024);
}

TEST(memory_example_closed_forms)
{
    fs_mpgrid_layout L;
    REQUIRE(fs_mpgrid_choose_layout(5120, 5120, 512, 1024, &L) == 0);
    /* Full MIPmap: sum_{k=0}^{10} 4^k = (4^11 - 1) / 3 per pyramid. */
    uint64_t geo = ((1ull << 22) - 1) / 3;
    CHECK_EQ_UINT(fs_mpgrid_pyramid_bytes(&L, 0, 1), geo);
    CHECK_EQ_UINT(25 * geo, 34952525ull);
    /* The paper's 34,952,550 is 25 x ceil(4/3 x 1024^2): one byte more per
     * pyramid than the exact sum (docs/mp_grid.md). */
    CHECK_EQ_UINT(25 * ((4ull * 1024 * 1024 + 2) / 3), 34952550ull);
    /* Clip-Map: 8192^2 with clip 2048: three clipped levels (8192, 4096,
     * 2048) of 2048^2 plus the full pyramid of 1024^2 below. */
    CHECK_EQ_INT(fs_clip_map_scaled_size(5120, 5120), 8192);
    CHECK_EQ_UINT(fs_clip_map_bytes(8192, 2048, 1), 3ull * 2048 * 2048 + geo);
    CHECK_EQ_UINT(fs_clip_map_bytes(8192, 2048, 1), 13981013ull);
    /* Table size example of 4.1.4. */
    CHECK_EQ_UINT(fs_mpgrid_table_bytes(11, 100, 100, 4, 4), 880000ull);
}

/* Independent oracle for the adapted MP-Grid: cast a ray through every
 * pixel centre onto the ground plane and take the bounding box of the
 * pixels that see each pyramid; its extent (+1 pixel for the pixel
 * itself) rounded up to a power of two gives the needed resolution.  The
 * analytic projection and the pixel sampling may differ only where an
 * extent lies within 1 pixel of a power of two. */
TEST(memory_example_adapted)
{
    fs_mpgrid_layout L;
    REQUIRE(fs_mpgrid_choose_layout(5120, 5120, 512, 1024, &L) == 0);
    fs_mpgrid_camera cam;
    REQUIRE(example_camera(&cam) == 0);
    fs_mpgrid_box boxes[25];
    memset(boxes, 0, sizeof boxes);
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 5; i++) {
            boxes[j * 5 + i].lo[0] = i * 1000.0;
            boxes[j * 5 + i].hi[0] = (i + 1) * 1000.0;
            boxes[j * 5 + i].lo[1] = j * 1000.0;
            boxes[j * 5 + i].hi[1] = (j + 1) * 1000.0;
        }
    uint64_t bytes = 0;
    int needed[25];
    REQUIRE(fs_mpgrid_adapted_bytes(&L, &cam, boxes, 1, 0, &bytes, needed) == 0);

    /* Ray casting with the camera frame built here (gluLookAt's s, u, f). */
    double f[3] = {2500, 2500, -1000}, fl = sqrt(2500.0 * 2500 * 2 + 1e6);
    for (int k = 0; k < 3; k++)
        f[k] /= fl;
    double s[3] = {f[1], -f[0], 0}, sl = hypot(s[0], s[1]);
    s[0] /= sl;
    s[1] /= sl;
    double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    double tn = tan(22.5 * 3.14159265358979323846 / 180.0);
    int xmin[25], xmax[25], ymin[25], ymax[25];
    for (int p = 0; p < 25; p++) {
        xmin[p] = ymin[p] = 1 << 20;
        xmax[p] = ymax[p] = -1;
    }
    for (int py = 0; py < 1024; py++)
        for (int px = 0; px < 1024; px++) {
            double a = ((px + 0.5) / 512.0 - 1.0) * tn, b = ((py + 0.5) / 512.0 - 1.0) * tn;
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = f[k] + a * s[k] + b * u[k];
            if (!(d[2] < 0))
                continue;
            double t = -1000.0 / d[2];
            double X = t * d[0], Y = t * d[1];
            if (X < 0 || Y < 0 || X >= 5000 || Y >= 5000)
                continue;
            int p = (int)(Y / 1000) * 5 + (int)(X / 1000);
            xmin[p] = px < xmin[p] ? px : xmin[p];
            xmax[p] = px > xmax[p] ? px : xmax[p];
            ymin[p] = py < ymin[p] ? py : ymin[p];
            ymax[p] = py > ymax[p] ? py : ymax[p];
        }
    int ambiguous = 0;
    for (int p = 0; p < 25; p++) {
        int lv = L.levels;
        if (xmax[p] >= 0) {
            int e = (xmax[p] - xmin[p] > ymax[p] - ymin[p] ? xmax[p] - xmin[p] : ymax[p] - ymin[p]) + 1;
            int r = 1;
            while (r < e)
                r *= 2;
            lv = 10;
            for (int q = r; q > 1 && lv > 0; q /= 2)
                lv--;
            if ((e & (e - 1)) == 0 || ((e - 1) & (e - 2)) == 0 || ((e + 1) & e) == 0)
                ambiguous++;
            else
                CHECK_EQ_INT(needed[p], lv);
        } else {
            CHECK_EQ_INT(needed[p], L.levels);
        }
    }
    printf("  adapted MP-Grid %llu bytes (paper 6,198,605: %+.2f %%), %d pyramids within a pixel of a power of two\n",
           (unsigned long long)bytes, 100.0 * ((double)bytes - 6198605.0) / 6198605.0, ambiguous);
    CHECK(ambiguous <= 6);
    /* Known gap (docs/mp_grid.md): the paper's number is 12 % below what
     * its stated rule gives for its stated camera; kept as a band so a
     * change of the rule or the camera is noticed. */
    CHECK(bytes > 6198605ull * 95 / 100 && bytes < 6198605ull * 115 / 100);
}

/* docs/mp_grid.md carries `fragsim mpgrid --markdown` verbatim: every line
 * the command prints must be in the page (numbers are never hand-edited). */
TEST(doc_is_current)
{
    char bad[] = "--fov", badv[] = "nan";
    char *bargv[] = {bad, badv, NULL};
    CHECK_EQ_INT(fs_cli_mpgrid(2, bargv), 2);
    FILE *doc = fopen("docs/mp_grid.md", "rb");
    if (!doc)
        SKIP("docs/mp_grid.md not found (run from the repository root)");
    static char page[1 << 16], out[1 << 14];
    size_t np = fread(page, 1, sizeof page - 1, doc);
    fclose(doc);
    page[np] = 0;
    char path[] = "/tmp/fs_mpgrid_XXXXXX";
    int fd = mkstemp(path);
    REQUIRE(fd >= 0);
    fflush(stdout);
    int saved = dup(1);
    dup2(fd, 1);
    char md[] = "--markdown";
    char *argv[] = {md, NULL};
    int rc = fs_cli_mpgrid(1, argv);
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    close(fd);
    FILE *f = fopen(path, "rb");
    size_t no = f ? fread(out, 1, sizeof out - 1, f) : 0;
    if (f)
        fclose(f);
    unlink(path);
    out[no] = 0;
    CHECK_EQ_INT(rc, 0);
    REQUIRE(no > 0);
    int lines = 0;
    for (char *line = strtok(out, "\n"); line; line = strtok(NULL, "\n")) {
        lines++;
        if (!strstr(page, line))
            CHECK_FAIL_("docs/mp_grid.md is stale (regenerate with build/fragsim mpgrid --markdown): missing \"%s\"",
                        line);
    }
    CHECK(lines > 10);
}

/* ---- the GL extension ---- */

static GLenum err(fs_context *c) { return fsglGetError(c); }

static void upload_big(fs_context *c, const fs_mip_owned *mo, int levels)
{
    for (int l = 0; l < levels; l++)
        fsglTexImage2D(c, GL_TEXTURE_2D, l, GL_RGBA, mo->view.width[l], mo->view.height[l], 0, GL_RGBA,
                       GL_UNSIGNED_BYTE, mo->view.texels[l]);
}

static int upload_grid(fs_context *c, const uint8_t *big, int n, int m, int tw, int th, int merge_side)
{
    fsglMPGridTexture(c, GL_TEXTURE_2D, n, m, tw, th, GL_RGBA);
    if (merge_side) {
        fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_MERGE_BLOCK, 2);
        fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_MERGE_SIDE, merge_side);
    }
    uint8_t *tile = malloc((size_t)tw * th * 4);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            fs_mip_owned mo;
            cut_tile(big, n * tw, i, j, tw, th, tile);
            if (fs_mip_build_box(&mo, tile, tw, th, GL_CLAMP_TO_EDGE) < 0) {
                free(tile);
                return -1;
            }
            for (int l = 0; l < mo.view.levels; l++)
                fsglMPGridImage(c, GL_TEXTURE_2D, i, j, l, mo.view.width[l], mo.view.height[l], GL_RGBA,
                                GL_UNSIGNED_BYTE, mo.view.texels[l]);
            fs_mip_free(&mo);
        }
    free(tile);
    return 0;
}

/* The square [lo, hi]^2 at z = 0 with texture coordinates 0..1. */
static void tex_square(fs_context *c, float lo, float hi)
{
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, 0, 0);
    fsglVertex3f(c, lo, lo, 0);
    fsglTexCoord2f(c, 1, 0);
    fsglVertex3f(c, hi, lo, 0);
    fsglTexCoord2f(c, 1, 1);
    fsglVertex3f(c, hi, hi, 0);
    fsglTexCoord2f(c, 0, 1);
    fsglVertex3f(c, lo, hi, 0);
    fsglEnd(c);
}

static void draw_quad_mag(fs_context *c, GLenum min_filter, GLenum mag_filter, float tilt)
{
    fsglViewport(c, 0, 0, 96, 96);
    fsglClearColor(c, 0.2f, 0.1f, 0.3f, 1);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglFrustum(c, -1, 1, -1, 1, 2, 40);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTranslatef(c, 0, 0, -4);
    fsglRotatef(c, -tilt, 1, 0, 0);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min_filter);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag_filter);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fsglEnable(c, GL_TEXTURE_2D);
    tex_square(c, -1.8f, 1.8f);
    fsglDisable(c, GL_TEXTURE_2D);
}

static void draw_quad(fs_context *c, GLenum min_filter, float tilt)
{
    draw_quad_mag(c, min_filter, min_filter == GL_LINEAR_MIPMAP_LINEAR ? GL_LINEAR : GL_NEAREST, tilt);
}

/* An MP-Grid-textured quad renders exactly like the same image uploaded as
 * one ordinary texture (levels resident): NEAREST filters, and also
 * trilinear, whose bilinear footprints straddle pyramid borders. */
TEST(gl_quad_matches_ordinary_texture)
{
    const int n = 2, m = 2, tw = 32, th = 32, W = n * tw, H = m * th;
    uint8_t *big = random_rgba(W, H, 123);
    fs_mip_owned mo;
    REQUIRE(big && fs_mip_build_box(&mo, big, W, H, GL_CLAMP_TO_EDGE) == 0);
    GLenum filters[3] = {GL_NEAREST, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR};
    float tilts[3] = {0.0f, 60.0f, 60.0f};
    for (int fi = 0; fi < 3; fi++)
        for (int ti = 0; ti < 3; ti++) {
            int merge = ti == 2 ? 8 : 0; /* levels of 8x8 and less merged */
            fs_context *a = fs_context_create(NULL, 96, 96), *b = fs_context_create(NULL, 96, 96);
            REQUIRE(a && b);
            fsglPixelStorei(a, GL_UNPACK_ALIGNMENT, 1);
            fsglPixelStorei(b, GL_UNPACK_ALIGNMENT, 1);
            fsglBindTexture(a, GL_TEXTURE_2D, 1);
            /* The ordinary texture's level 6 (1x1) has no MP-Grid
             * counterpart; the quad stays below lambda 5. */
            upload_big(a, &mo, mo.view.levels);
            fsglBindTexture(b, GL_TEXTURE_2D, 1);
            REQUIRE(upload_grid(b, big, n, m, tw, th, merge) == 0);
            GLint mv = -1;
            fsglGetMPGridiv(b, GL_TEXTURE_2D, GL_MPGRID_MERGE_SIDE, &mv);
            CHECK_EQ_INT(mv, merge);
            fsglGetMPGridiv(b, GL_TEXTURE_2D, GL_MPGRID_MERGE_BLOCK, &mv);
            CHECK_EQ_INT(mv, merge ? 2 : 4);
            CHECK_EQ_INT(err(b), GL_NO_ERROR);
            draw_quad(a, filters[fi], tilts[ti]);
            draw_quad(b, filters[fi], tilts[ti]);
            CHECK_EQ_INT(err(a), GL_NO_ERROR);
            CHECK_EQ_INT(err(b), GL_NO_ERROR);
            CHECK(fs_texture_quads_sampled(b) > 0);
            CHECK_EQ_UINT(fs_texture_quads_incomplete(b), 0);
            long differ = 0;
            for (size_t k = 0; k < (size_t)96 * 96 * 4; k++)
                differ += a->fb.color[k] != b->fb.color[k];
            CHECK_EQ_INT(differ, 0);
            GLint reloads = 0;
            fsglGetMPGridiv(b, GL_TEXTURE_2D, GL_MPGRID_CTR_RELOADS, &reloads);
            CHECK(reloads > 0);
            CHECK_EQ_UINT(b->stats.mpgrid_ctr_reloads, (uint64_t)reloads);
            fs_context_destroy(a);
            fs_context_destroy(b);
        }
    fs_mip_free(&mo);
    free(big);
}

/* A 2 x 2 MP-Grid of 32 x 32 pyramids from a 64 x 64 image, bound as
 * texture `name`, for the GL adaptation tests. */
static int grid_2x2(fs_context *c, const uint8_t *big, GLuint name)
{
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    fsglBindTexture(c, GL_TEXTURE_2D, name);
    return upload_grid(c, big, 2, 2, 32, 32, 0);
}

/* Boxes in object space: pyramid (i, j) covers [i, i+1] x [j, j+1] of a
 * 2 x 2 square. */
static void unit_square_boxes(fs_context *c)
{
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            GLfloat box[6] = {(GLfloat)i, (GLfloat)j, 0, (GLfloat)i + 1, (GLfloat)j + 1, 0};
            fsglMPGridBoundingBox(c, GL_TEXTURE_2D, i, j, box, GL_FALSE);
        }
}

/* A 96 x 96 view of that square from `dist` away: each unit square is
 * 96 * 2 / dist / 2 pixels wide. */
static void camera_at(fs_context *c, float dist)
{
    fsglViewport(c, 0, 0, 96, 96);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglFrustum(c, -1, 1, -1, 1, 2, 400);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTranslatef(c, -1, -1, -dist);
}

/* Adaptation through the GL: a far-away viewer frees the fine levels and
 * the sampler substitutes the best resident one. */
TEST(gl_adapt_and_substitute)
{
    fs_context *c = fs_context_create(NULL, 96, 96);
    REQUIRE(c);
    uint8_t *big = random_rgba(64, 64, 9);
    REQUIRE(big && grid_2x2(c, big, 3) == 0);
    GLint v = 0;
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_BYTES_RESIDENT, &v);
    CHECK_EQ_INT(v, 4 * 4 * ((4 * 32 * 32 - 1) / 3)); /* everything resident at first */
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_IMAGES_MISSING, &v);
    CHECK_EQ_INT(v, 0);
    /* The viewer far away. */
    unit_square_boxes(c);
    camera_at(c, 96); /* each unit square: 96 * 2 / 96 / 2 = 1 px */
    fsglMPGridAdapt(c, GL_TEXTURE_2D);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_BYTES_RESIDENT, &v);
    CHECK_EQ_INT(v, 4 * 4 * 1); /* only the 1x1 levels: extent 1 px */
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS_FREED, &v);
    CHECK_EQ_INT(v, 4 * 5);
    CHECK_EQ_UINT(c->stats.mpgrid_levels_freed, 20);
    /* Sampling level 0 now substitutes. */
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    fsglEnable(c, GL_TEXTURE_2D);
    fsglLoadIdentity(c);
    fsglTranslatef(c, 0, 0, -4);
    tex_square(c, -1, 1);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_SUBSTITUTIONS, &v);
    CHECK(v > 0);
    CHECK_EQ_UINT(c->stats.mpgrid_substitutions, (uint64_t)v);
    CHECK(strstr((const char *)fsglGetString(c, GL_EXTENSIONS), "GL_FRAGSIM_mp_grid") != NULL);
    fs_context_destroy(c);
    free(big);
}

static void unit_quad(fs_context *c) { tex_square(c, 0, 2); }

/* GL_MPGRID_AUTO_ADAPT: the grid adapts before texturing when the camera
 * changed, and only then; a NaN camera leaves it as it is. */
TEST(gl_auto_adapt)
{
    fs_context *c = fs_context_create(NULL, 96, 96);
    REQUIRE(c);
    uint8_t *big = random_rgba(64, 64, 11);
    REQUIRE(big && grid_2x2(c, big, 4) == 0);
    unit_square_boxes(c);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_AUTO_ADAPT, 2);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_AUTO_ADAPT, GL_TRUE);
    GLint v = 0;
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_AUTO_ADAPT, &v);
    CHECK_EQ_INT(v, GL_TRUE);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    fsglEnable(c, GL_TEXTURE_2D);
    camera_at(c, 96); /* unit square ~1 px: only 1x1 levels */
    unit_quad(c);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_BYTES_RESIDENT, &v);
    CHECK_EQ_INT(v, 4 * 4);
    GLint loaded0 = 0, freed0 = 0;
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS_LOADED, &loaded0);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS_FREED, &freed0);
    unit_quad(c); /* same camera: no adaptation */
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS_FREED, &v);
    CHECK_EQ_INT(v, freed0);
    /* Closer: each unit square 96 * 2 / 6 / 2 = 16 px -> 16x16 levels. */
    fsglLoadIdentity(c);
    fsglTranslatef(c, -1, -1, -6);
    unit_quad(c);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_BYTES_RESIDENT, &v);
    CHECK_EQ_INT(v, 4 * 4 * ((4 * 16 * 16 - 1) / 3));
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS_LOADED, &v);
    CHECK_EQ_INT(v - loaded0, 4 * 4);
    /* A NaN camera: no adaptation, no crash, the grid as it was. */
    fsglLoadIdentity(c);
    fsglTranslatef(c, NAN, 0, -6);
    unit_quad(c);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_BYTES_RESIDENT, &v);
    CHECK_EQ_INT(v, 4 * 4 * ((4 * 16 * 16 - 1) / 3));
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fs_context_destroy(c);
    free(big);
}

static void repeat_scene(fs_context *c)
{
    fsglViewport(c, 0, 0, 64, 64);
    fsglClear(c, GL_COLOR_BUFFER_BIT);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglOrtho(c, -1, 1, -1, 1, -1, 1);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fsglTexEnvi(c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fsglEnable(c, GL_TEXTURE_2D);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, -0.5f, -0.5f);
    fsglVertex2f(c, -1, -1);
    fsglTexCoord2f(c, 1.5f, -0.5f);
    fsglVertex2f(c, 1, -1);
    fsglTexCoord2f(c, 1.5f, 1.5f);
    fsglVertex2f(c, 1, 1);
    fsglTexCoord2f(c, -0.5f, 1.5f);
    fsglVertex2f(c, -1, 1);
    fsglEnd(c);
}

/* REPEAT (the initial wrap mode) on a power-of-two grid samples like the
 * ordinary texture; on a 3 x 1 grid it makes the texture incomplete, and
 * CLAMP_TO_EDGE makes it complete again (Issue 5 of the spec). */
TEST(gl_repeat_needs_power_of_two_grid)
{
    uint8_t *big = random_rgba(64, 64, 21);
    fs_mip_owned mo;
    REQUIRE(big && fs_mip_build_box(&mo, big, 64, 64, GL_REPEAT) == 0);
    fs_context *a = fs_context_create(NULL, 64, 64), *b = fs_context_create(NULL, 64, 64);
    REQUIRE(a && b);
    fsglPixelStorei(a, GL_UNPACK_ALIGNMENT, 1);
    fsglPixelStorei(b, GL_UNPACK_ALIGNMENT, 1);
    fsglBindTexture(a, GL_TEXTURE_2D, 1);
    upload_big(a, &mo, mo.view.levels);
    fsglBindTexture(b, GL_TEXTURE_2D, 1);
    REQUIRE(upload_grid(b, big, 2, 2, 32, 32, 0) == 0);
    repeat_scene(a);
    repeat_scene(b);
    long differ = 0;
    for (size_t k = 0; k < (size_t)64 * 64 * 4; k++)
        differ += a->fb.color[k] != b->fb.color[k];
    CHECK_EQ_INT(differ, 0);
    CHECK(fs_texture_quads_sampled(b) > 0);
    fs_context_destroy(a);
    fs_context_destroy(b);

    fs_context *c = fs_context_create(NULL, 64, 64);
    REQUIRE(c);
    uint8_t *wide = random_rgba(48, 16, 22);
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    fsglBindTexture(c, GL_TEXTURE_2D, 2);
    REQUIRE(upload_grid(c, wide, 3, 1, 16, 16, 0) == 0);
    repeat_scene(c);
    CHECK_EQ_INT(fs_texture_quads_sampled(c), 0);
    CHECK(fs_texture_quads_incomplete(c) > 0);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    repeat_scene(c);
    CHECK(fs_texture_quads_sampled(c) > 0);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fs_context_destroy(c);
    fs_mip_free(&mo);
    free(big);
    free(wide);
}

/* The errors of docs/extensions/mp_grid.txt, "Errors". */
TEST(gl_errors)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    uint8_t px[16 * 16 * 4] = {0};
    GLint v = -7;
    GLfloat box[6] = {0, 0, 0, 1, 1, 1};
    /* Texture object 0 cannot be an MP-Grid. */
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglBindTexture(c, GL_TEXTURE_2D, 5);
    /* Not an MP-Grid yet. */
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglMPGridAdapt(c, GL_TEXTURE_2D);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglMPGridBoundingBox(c, GL_TEXTURE_2D, 0, 0, box, GL_FALSE);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_KEEP_SIDE, 4);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS, &v);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    CHECK_EQ_INT(v, -7);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MAX_MPGRID_PYRAMIDS, &v);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    CHECK_EQ_INT(v, 1024);
    /* glMPGridTexture's arguments. */
    fsglMPGridTexture(c, GL_TEXTURE_1D, 2, 2, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 0, 2, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, -1, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 1025, 2, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 24, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 16, 8192, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 16, 16, 12345);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS, &v);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION); /* still not an MP-Grid */
    fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 16, 16, GL_RGBA);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_LEVELS, &v);
    CHECK_EQ_INT(v, 5);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_IMAGES_MISSING, &v);
    CHECK_EQ_INT(v, 2 * 2 * 5);
    /* glMPGridImage's arguments. */
    fsglMPGridImage(c, GL_TEXTURE_2D, 2, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, -1, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 1, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px); /* level 1 is 8x8 */
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, 0x1234, px);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, px);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_MPGRID_IMAGES_MISSING, &v);
    CHECK_EQ_INT(v, 2 * 2 * 5); /* nothing changed */
    fsglMPGridImage(c, GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    /* Merging only before the first image. */
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_MERGE_SIDE, 2);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, 2);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_KEEP_SIDE, -1);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridParameteri(c, GL_TEXTURE_2D, GL_MPGRID_KEEP_SIDE, 4);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    /* Boxes. */
    GLfloat nanbox[6] = {0, 0, 0, NAN, 1, 1}, inverted[6] = {1, 0, 0, 0, 1, 1};
    fsglMPGridBoundingBox(c, GL_TEXTURE_2D, 0, 0, nanbox, GL_FALSE);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridBoundingBox(c, GL_TEXTURE_2D, 0, 0, inverted, GL_FALSE);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridBoundingBox(c, GL_TEXTURE_2D, 3, 0, box, GL_FALSE);
    CHECK_EQ_INT(err(c), GL_INVALID_VALUE);
    fsglMPGridBoundingBox(c, GL_TEXTURE_2D, 0, 0, box, GL_TRUE);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    /* Queries. */
    fsglGetMPGridiv(c, GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &v);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    fsglGetMPGridiv(c, GL_PROXY_TEXTURE_2D, GL_MPGRID_LEVELS, &v);
    CHECK_EQ_INT(err(c), GL_INVALID_ENUM);
    /* An incomplete MP-Grid (images missing) textures nothing. */
    fsglEnable(c, GL_TEXTURE_2D);
    fsglBegin(c, GL_TRIANGLES);
    fsglVertex2f(c, -1, -1);
    fsglVertex2f(c, 1, -1);
    fsglVertex2f(c, 0, 1);
    fsglEnd(c);
    CHECK(fs_texture_quads_incomplete(c) > 0);
    CHECK_EQ_INT(fs_texture_quads_sampled(c), 0);
    /* Not between Begin and End. */
    fsglBegin(c, GL_POINTS);
    fsglMPGridAdapt(c, GL_TEXTURE_2D);
    fsglEnd(c);
    CHECK_EQ_INT(err(c), GL_INVALID_OPERATION);
    /* Deleting the object frees the grid (run under ASan by `make sanitize`). */
    GLuint name = 5;
    fsglDeleteTextures(c, 1, &name);
    CHECK_EQ_INT(err(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(layout_minimal_scaling),
    TEST_ENTRY(layout_bad_input),
    TEST_ENTRY(texels_equal_big_texture),
    TEST_ENTRY(ctr_reloads_equal_border_crossings),
    TEST_ENTRY(merged_levels_avoid_reloads),
    TEST_ENTRY(residency_closed_form),
    TEST_ENTRY(bad_camera_and_boxes),
    TEST_ENTRY(memory_example_closed_forms),
    TEST_ENTRY(memory_example_adapted),
    TEST_ENTRY(doc_is_current),
    TEST_ENTRY(gl_quad_matches_ordinary_texture),
    TEST_ENTRY(gl_adapt_and_substitute),
    TEST_ENTRY(gl_auto_adapt),
    TEST_ENTRY(gl_repeat_needs_power_of_two_grid),
    TEST_ENTRY(gl_errors),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
