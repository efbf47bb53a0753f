/*
 * The split of threaded rasterization (pipeline/raster_threads.h): the
 * same random triangles, drawn by one context with raster.threads 1 and by
 * others with 2, 3 and 8, give byte-identical colour and depth buffers and
 * identical statistics, with depth test and blending (order-dependent
 * per pixel), an odd framebuffer height (bands against llvmpipe's quad
 * alignment), and triangles that cross many bands; and the threaded
 * contexts really ran batches in parallel.  A draw below the size
 * threshold stays on the calling thread, and raster.threads 1 never
 * records.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../pipeline/raster_threads.h"
#include "../driver/gl_call.h"

typedef struct rng { uint64_t s; } rng;
static uint32_t rnd(rng *r)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return (uint32_t)(r->s >> 11);
}
static float rndf(rng *r) { return (float)(rnd(r) & 0xffffff) / 16777216.0f; }

static fs_context *make(long threads, int w, int h, bool blend)
{
    fs_config cfg;
    fs_config_defaults(&cfg);
    cfg.raster_threads = threads;
    fs_context *c = fs_context_create(&cfg, w, h);
    if (!c)
        return NULL;
    fsglViewport(c, 0, 0, w, h);
    fsglEnable(c, GL_DEPTH_TEST);
    fsglDepthFunc(c, GL_LEQUAL);
    if (blend) {
        fsglEnable(c, GL_BLEND);
        fsglBlendFunc(c, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    fsglClearColor(c, 0.1f, 0.2f, 0.3f, 1.0f);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return c;
}

/* ntri random triangles of up to `size` pixels a side, in NDC, as one
 * glBegin(GL_TRIANGLES) draw. */
static void draw(fs_context *c, uint64_t seed, int ntri, float size, int w)
{
    rng r = {seed};
    float s = 2.0f * size / (float)w;
    fsglBegin(c, GL_TRIANGLES);
    for (int t = 0; t < ntri; t++) {
        float cx = rndf(&r) * 2.2f - 1.1f, cy = rndf(&r) * 2.2f - 1.1f;
        for (int k = 0; k < 3; k++) {
            fsglColor4f(c, rndf(&r), rndf(&r), rndf(&r), rndf(&r));
            fsglVertex3f(c, cx + (rndf(&r) - 0.5f) * s, cy + (rndf(&r) - 0.5f) * s, rndf(&r) * 2.0f - 1.0f);
        }
    }
    fsglEnd(c);
}

static bool same(check_state *check_st_, const fs_context *a, const fs_context *b)
{
    size_t n = (size_t)a->fb.width * (size_t)a->fb.height;
    CHECK(memcmp(a->fb.color, b->fb.color, n * 4) == 0);
    CHECK(memcmp(a->fb.depth, b->fb.depth, n * sizeof a->fb.depth[0]) == 0);
    CHECK(memcmp(&a->stats, &b->stats, sizeof a->stats) == 0);
    return memcmp(a->fb.color, b->fb.color, n * 4) == 0 && memcmp(&a->stats, &b->stats, sizeof a->stats) == 0;
}

static void run_split(check_state *check_st_, int w, int h, bool blend, int ntri, float size)
{
    fs_context *one = make(1, w, h, blend);
    REQUIRE(one);
    draw(one, 7, ntri, size, w);
    unsigned long par, ser;
    fs_par_counts(one, &par, &ser);
    CHECK_EQ_UINT(par + ser, 0); /* threads 1: nothing recorded */
    const long counts[] = {2, 3, 8};
    for (int i = 0; i < 3; i++) {
        fs_context *c = make(counts[i], w, h, blend);
        REQUIRE(c);
        draw(c, 7, ntri, size, w);
        if (!same(check_st_, one, c))
            fprintf(stderr, "threads %ld differ (%dx%d blend %d)\n", counts[i], w, h, blend);
        fs_par_counts(c, &par, &ser);
        CHECK(par > 0);
        fs_context_destroy(c);
    }
    fs_context_destroy(one);
}

TEST(depth_even_height) { run_split(check_st_, 320, 240, false, 3000, 60.0f); }
TEST(blend_odd_height) { run_split(check_st_, 257, 131, true, 3000, 60.0f); }
/* Large triangles over every band, more than one batch (FS_PAR_BATCH). */
TEST(large_many_batches) { run_split(check_st_, 200, 150, true, FS_PAR_BATCH + 500, 300.0f); }

TEST(small_draw_stays_serial)
{
    fs_context *c = make(2, 256, 256, false);
    REQUIRE(c);
    draw(c, 3, 4, 4.0f, 256);
    unsigned long par, ser;
    fs_par_counts(c, &par, &ser);
    CHECK_EQ_UINT(par, 0);
    CHECK_EQ_UINT(ser, 1);
    fs_context_destroy(c);
}

TEST(resolve)
{
    CHECK_EQ_INT(fs_par_resolve_threads(1), 1);
    CHECK_EQ_INT(fs_par_resolve_threads(3), 3);
    CHECK(fs_par_resolve_threads(0) >= 1 && fs_par_resolve_threads(0) <= 8);
    CHECK_EQ_INT(fs_par_resolve_threads(64), 8);
}

TEST_LIST = {
    TEST_ENTRY(depth_even_height),
    TEST_ENTRY(blend_odd_height),
    TEST_ENTRY(large_many_batches),
    TEST_ENTRY(small_draw_stays_serial),
    TEST_ENTRY(resolve),
    TEST_END
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, test_list);
}
