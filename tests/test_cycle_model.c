/*
 * The cycle-level model (rtl_model/) against closed-form values and
 * brute-force counts:
 *  - the FIFO recurrence: one stage with service s and N items takes
 *    N*s + latency; two stages with a depth-1 FIFO run at the bottleneck's
 *    rate (first stage's service + N * the slower one); busy + stalled +
 *    idle adds up; high-water marks;
 *  - memory bandwidth: N transfers of b bytes at B bytes per cycle end at
 *    ceil(N*b/B);
 *  - the Occlusion Engines: a rectangle of W x H pixels tested against T
 *    tiles by E engines costs W*H*ceil(T/E) cycles (pixels counted here by
 *    testing each pixel centre against the rectangle);
 *  - glRenderMode's drain: the synchronisation cost computed by hand for a
 *    single point through a pipeline of known latencies.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../driver/run_config.h"
#include "../driver/gl_call.h"
#include "../driver/cli.h"
#include "../driver/replay.h"
#include "../driver/trace.h"
#include "trace_build.h"
#include "../rtl_model/cycle_internal.h"
#include "../pipeline/vertex_internal.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

TEST(single_stage_closed_form)
{
    for (uint32_t s = 0; s < 5; s++) {
        for (uint32_t lat = 0; lat < 30; lat += 7) {
            fs_cyc_stage st;
            CHECK(fs_cyc_stage_init(&st, lat, 4) == 0);
            const uint64_t N = 1000;
            uint64_t last = 0;
            for (uint64_t i = 0; i < N; i++)
                last = fs_cyc_step(&st, 0, s, 0, false, NULL);
            CHECK_EQ_UINT(last, N * s + lat);
            CHECK_EQ_UINT(st.busy, N * s);
            CHECK_EQ_UINT(st.stalled, 0);
            fs_cyc_stage_free(&st);
        }
    }
}

static void two_stage(check_state *check_st_, uint64_t a, uint64_t b, uint64_t N)
{
    fs_cyc_stage A, B;
    CHECK(fs_cyc_stage_init(&A, 0, 1) == 0);
    CHECK(fs_cyc_stage_init(&B, 0, 1) == 0); /* the FIFO between A and B holds one item */
    uint64_t done = 0;
    for (uint64_t i = 0; i < N; i++) {
        uint64_t t = fs_cyc_step(&A, 0, a, 0, false, &B);
        done = fs_cyc_step(&B, t, b, 0, false, NULL);
    }
    /* The slower stage sets the rate; the first item pays the other one. */
    uint64_t expect = a + b + (N - 1) * (a > b ? a : b);
    CHECK_EQ_UINT(done, expect);
    CHECK_EQ_UINT(A.busy, N * a);
    CHECK_EQ_UINT(B.busy, N * b);
    /* A stage either works, holds finished work (stalled) or waits: */
    CHECK(A.busy + A.stalled <= done);
    /* With b >= 2a, A is blocked by the full FIFO from the third item on:
     * item 2 finishes at 3a and waits for B to start item 1 at a + b
     * (b - 2a); every later item finishes a after B started item i-2 and
     * waits for item i-1, b later (b - a). */
    if (b >= 2 * a)
        CHECK_EQ_UINT(A.stalled, (b - 2 * a) + (N - 3) * (b - a));
    else if (a >= b)
        CHECK_EQ_UINT(A.stalled, 0);
    CHECK_EQ_UINT(B.in.hwm, 1);
    fs_cyc_stage_free(&A);
    fs_cyc_stage_free(&B);
}

TEST(two_stage_bottleneck)
{
    two_stage(check_st_, 2, 7, 100);
    two_stage(check_st_, 7, 2, 100);
    two_stage(check_st_, 3, 3, 50);
}

TEST(fifo_high_water_mark)
{
    /* A fast producer (service 1) before a slow consumer (service 10) with
     * a FIFO of depth 8: the FIFO fills to 8 and the producer stalls. */
    fs_cyc_stage A, B;
    CHECK(fs_cyc_stage_init(&A, 0, 1) == 0);
    CHECK(fs_cyc_stage_init(&B, 0, 8) == 0);
    for (int i = 0; i < 100; i++)
        fs_cyc_step(&B, fs_cyc_step(&A, 0, 1, 0, false, &B), 10, 0, false, NULL);
    CHECK_EQ_UINT(B.in.hwm, 8);
    CHECK_EQ_UINT(B.free, 1 + 100 * 10);
    fs_cyc_stage_free(&A);
    fs_cyc_stage_free(&B);
}

TEST(memory_bandwidth)
{
    fs_cyc_mem m;
    fs_cyc_mem_init(&m, 8, 20);
    uint64_t end = 0;
    for (int i = 0; i < 1000; i++)
        end = fs_cyc_mem_reserve(&m, 0, 12); /* 12 bytes at 8 per cycle: 1.5 cycles each */
    CHECK_EQ_UINT(end, 1500);
    /* a transfer after an idle gap starts at its request time */
    CHECK_EQ_UINT(fs_cyc_mem_reserve(&m, 5000, 16), 5002);
    /* a bandwidth that is no power of two (a division, not a shift):
     * 7 bytes at 12 per cycle, 7/12 cycle each, the last partly used
     * cycle counting whole */
    fs_cyc_mem_init(&m, 12, 20);
    for (int i = 1; i <= 100; i++) {
        end = fs_cyc_mem_reserve(&m, 0, 7);
        CHECK_EQ_UINT(end, (uint64_t)(7 * i + 11) / 12);
    }
}

/* Window coordinates of pixel edges as NDC (identity matrices). */
#define WN 64
static float ndc(int px) { return 2.0f * (float)px / (float)WN - 1.0f; }

static fs_context *new_context_sized(const fs_run_config *cfg, int w, fs_cycle **cy, fs_cycle_mode mode)
{
    fs_context *c = fs_context_create(&cfg->gl, w, w);
    char err[256];
    *cy = fs_cycle_create(&cfg->cycle, mode, err, sizeof err);
    if (!*cy)
        fprintf(stderr, "%s\n", err);
    fs_cycle_attach(*cy, c);
    fsglViewport(c, 0, 0, w, w);
    return c;
}

static fs_context *new_context(const fs_run_config *cfg, fs_cycle **cy, fs_cycle_mode mode)
{
    return new_context_sized(cfg, WN, cy, mode);
}

/* A one-frame model (tile sampling in sampled mode) rasterizing one
 * tile_size-pixel tile in `tiles` and simulating one draw of a kind in
 * `every`. */
static fs_context *tile_sampled_context(int tiles, int tile_size, int every, fs_cycle **cy, fs_cycle_mode mode)
{
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    cfg.cycle.sampling_tiles = tiles;
    cfg.cycle.sampling_tile_size = tile_size;
    cfg.cycle.sampling_every = every;
    fs_context *c = new_context(&cfg, cy, mode);
    fs_cycle_set_frames(*cy, 1);
    return c;
}

/* Enters GL_BRIEF_OCCLUSION with T occlusion tiles, each the whole window. */
#define MAX_TILES 13
static void brief_occlusion_tiles(fs_context *c, int T)
{
    GLint tiles[MAX_TILES * 4];
    GLsizei sizes[MAX_TILES];
    static GLuint store[MAX_TILES][16];
    GLuint *bufs[MAX_TILES];
    if (T > MAX_TILES)
        T = MAX_TILES;
    for (int t = 0; t < T; t++) {
        tiles[4 * t] = tiles[4 * t + 1] = 0;
        tiles[4 * t + 2] = tiles[4 * t + 3] = WN;
        sizes[t] = 16;
        bufs[t] = store[t];
    }
    fsglScissors(c, T, tiles);
    fsglOcclusionBuffers(c, sizes, bufs);
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
}

TEST(occlusion_engines_ceil_t_over_e)
{
    static const int T_list[] = {1, 3, 5, 8, 13};
    for (int E = 1; E <= 4; E++) {
        for (size_t ti = 0; ti < sizeof T_list / sizeof T_list[0]; ti++) {
            int T = T_list[ti];
            fs_run_config cfg;
            fs_run_config_defaults(&cfg);
            cfg.gl.occlusion_engines = E;
            fs_cycle *cy;
            fs_context *c = new_context(&cfg, &cy, FS_CYCLE_FULL);
            brief_occlusion_tiles(c, T);
            const int x0 = 8, x1 = 40, y0 = 6, y1 = 31;
            fsglBegin(c, GL_QUADS);
            fsglVertex2f(c, ndc(x0), ndc(y0));
            fsglVertex2f(c, ndc(x1), ndc(y0));
            fsglVertex2f(c, ndc(x1), ndc(y1));
            fsglVertex2f(c, ndc(x0), ndc(y1));
            fsglEnd(c);
            fsglRenderMode(c, GL_RENDER);
            CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
            /* brute force: pixel centres inside the rectangle */
            uint64_t pixels = 0;
            for (int y = 0; y < WN; y++)
                for (int x = 0; x < WN; x++)
                    pixels += x + 0.5 > x0 && x + 0.5 < x1 && y + 0.5 > y0 && y + 0.5 < y1;
            fs_cycle_stats s;
            fs_cycle_totals(cy, &s);
            CHECK_EQ_UINT(s.occlusion_test_cycles, pixels * (uint64_t)((T + E - 1) / E));
            CHECK_EQ_UINT(s.occlusion_write_cycles, 0); /* brief mode writes no hit list */
            CHECK(s.occlusion_busy >= s.occlusion_test_cycles);
            fs_cycle_destroy(cy);
            fs_context_destroy(c);
        }
    }
}

/* Only latencies and unit services; memory wide enough to cost one cycle
 * (the drain tests' set-up). */
static void drain_config(fs_run_config *cfg)
{
    fs_run_config_defaults(cfg);
    cfg->cycle.frontend_cycles_per_vertex = 1;
    cfg->cycle.frontend_latency = cfg->cycle.setup_latency = cfg->cycle.raster_latency = 0;
    cfg->cycle.setup_cycles_per_triangle = 1;
    cfg->cycle.raster_fragments_per_cycle = 1;
    cfg->cycle.fragment_cycles_per_fragment = 1;
    cfg->cycle.fragment_latency = 100;
    cfg->cycle.occlusion_latency = 0;
    cfg->cycle.occlusion_merge_board_latency = 7;
    cfg->cycle.occlusion_merge_global_latency = 11;
    cfg->cycle.memory_bytes_per_cycle = 65536;
    cfg->cycle.memory_latency = 0;
}

TEST(rendermode_drain)
{
    /* Only latencies and unit services; memory wide enough to cost one
     * cycle.  One point: front end 1 (1 vertex), setup 1, fragment
     * generator 1, per-fragment 1, fragment latency 100, Occlusion Engines
     * ceil(T/E), merges M = 7 + 11.
     *   glRenderMode(BRIEF): nothing in flight, waits the merge: M.
     *   the point: front end [M, M+1), setup [M+1, M+2), generator
     *   [M+2, M+3), per-fragment [M+3, M+4) + 100, engines
     *   [M+104, M+104+k).
     *   glRenderMode(RENDER): issued when the front end took the point
     *   (M+1), results ready at M+104+k, merged M later. */
    for (int T = 1; T <= 6; T++) {
        fs_run_config cfg;
        drain_config(&cfg);
        cfg.gl.occlusion_engines = 2;
        fs_cycle *cy;
        fs_context *c = new_context(&cfg, &cy, FS_CYCLE_FULL);
        brief_occlusion_tiles(c, T);
        fsglBegin(c, GL_POINTS);
        fsglVertex2f(c, (ndc(20) + ndc(21)) / 2, (ndc(9) + ndc(10)) / 2);
        fsglEnd(c);
        fsglRenderMode(c, GL_RENDER);
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        CHECK_EQ_UINT(c->stats.occlusion_fragments, 1);
        uint64_t M = 18, k = (uint64_t)(T + 1) / 2;
        uint64_t first = M, second = (M + 104 + k + M) - (M + 1);
        fs_cycle_stats s;
        fs_cycle_totals(cy, &s);
        CHECK_EQ_UINT(s.rendermode_sync_cycles, first + second);
        CHECK_EQ_UINT(s.syncs, 2);
        CHECK_EQ_UINT(s.cycles, M + 104 + k + M);
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
}

/* GL_SELECT (VFC in selection mode, Huettner 1999, 3.1.6): entering the
 * mode drains what was drawn before, leaving it returns the hit records.
 * With rendermode_drain's latencies: the point leaves the per-fragment
 * stage at 104; glRenderMode(GL_SELECT) is issued when the front end took
 * it (1) and waits to 104 + M; nothing is in flight in selection mode (its
 * primitives are not rasterized), so glRenderMode(GL_RENDER) waits M. */
TEST(rendermode_drain_select)
{
    fs_run_config cfg;
    drain_config(&cfg);
    fs_cycle *cy;
    fs_context *c = new_context(&cfg, &cy, FS_CYCLE_FULL);
    fsglBegin(c, GL_POINTS);
    fsglVertex2f(c, (ndc(20) + ndc(21)) / 2, (ndc(9) + ndc(10)) / 2);
    fsglEnd(c);
    GLuint hits[8];
    fsglSelectBuffer(c, 8, hits);
    fsglRenderMode(c, GL_SELECT);
    fsglBegin(c, GL_POINTS);
    fsglVertex2f(c, 0.0f, 0.0f);
    fsglEnd(c);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    uint64_t M = 18;
    fs_cycle_stats s;
    fs_cycle_totals(cy, &s);
    CHECK_EQ_UINT(s.syncs, 2);
    CHECK_EQ_UINT(s.rendermode_sync_cycles, (104 + M - 1) + M);
    fs_cycle_destroy(cy);
    fs_context_destroy(c);
}

TEST(tile_sample_lattice)
{
    /* Sampled mode's tile sample: exactly one tile in every block of N
     * tiles (w x h, w the largest divisor of N <= sqrt N), every quad of a
     * tile sharing its tile's fate, and the sampled position not the same
     * in every block (brute-force count over 8 x 8 blocks). */
    static const int N_list[] = {2, 3, 4, 8, 16};
    for (size_t ni = 0; ni < sizeof N_list / sizeof N_list[0]; ni++) {
        int N = N_list[ni], w = 1;
        for (int d = 1; d * d <= N; d++)
            if (N % d == 0)
                w = d;
        int h = N / w;
        fs_run_config cfg;
        fs_run_config_defaults(&cfg);
        cfg.cycle.sampling_tiles = N;
        cfg.cycle.sampling_tile_size = 8;
        char err[256];
        fs_cycle *cy = fs_cycle_create(&cfg.cycle, FS_CYCLE_SAMPLED, err, sizeof err);
        CHECK(cy != NULL);
        if (!cy)
            continue;
        fs_cycle_set_frames(cy, 1);
        int positions = 0, first = -1;
        for (int by = 0; by < 8; by++)
            for (int bx = 0; bx < 8; bx++) {
                int in = 0, where = -1;
                for (int y = 0; y < h; y++)
                    for (int x = 0; x < w; x++) {
                        int tx = bx * w + x, ty = by * h + y;
                        bool s0 = !fs_cycle_quad_skipped(cy, tx * 8, ty * 8);
                        CHECK_EQ_INT(!fs_cycle_quad_skipped(cy, tx * 8 + 6, ty * 8 + 6), s0);
                        if (s0) {
                            in++;
                            where = y * w + x;
                        }
                    }
                CHECK_EQ_INT(in, 1);
                if (first < 0)
                    first = where;
                positions += where != first;
            }
        CHECK(positions > 0);
        fs_cycle_destroy(cy);
    }
    /* full cycle mode never skips */
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    char err[256];
    fs_cycle *cy = fs_cycle_create(&cfg.cycle, FS_CYCLE_FULL, err, sizeof err);
    fs_cycle_set_frames(cy, 1);
    CHECK(!fs_cycle_quad_skipped(cy, 16, 0));
    fs_cycle_destroy(cy);
}

TEST(tile_sample_full_screen)
{
    /* A screen-filling rectangle drawn 16 times: with one tile in 4
     * rasterized, the functional pipeline sees exactly the sampled quarter,
     * and the model charges about every fragment (16 W x H from the
     * triangles' areas, whose rounding to quads is the 2% tolerance) and
     * stays within 2% of full cycle mode's cycles for this uniform load. */
    uint64_t cycles[2] = {0, 0};
    for (int m = 0; m < 2; m++) {
        fs_cycle *cy;
        fs_context *c = tile_sampled_context(4, 16, 1, &cy, m ? FS_CYCLE_SAMPLED : FS_CYCLE_FULL);
        for (int r = 0; r < 16; r++) {
            fsglBegin(c, GL_QUADS);
            fsglVertex2f(c, ndc(0), ndc(0));
            fsglVertex2f(c, ndc(WN), ndc(0));
            fsglVertex2f(c, ndc(WN), ndc(WN));
            fsglVertex2f(c, ndc(0), ndc(WN));
            fsglEnd(c);
        }
        fs_cycle_stats f;
        fs_cycle_frame_end(cy, &f);
        fs_cycle_stats s;
        fs_cycle_totals(cy, &s);
        double want = 16.0 * WN * WN;
        CHECK(fabs((double)s.fragments - want) <= 0.02 * want);
        CHECK_EQ_UINT(c->stats.fragments_generated, m ? 16u * WN * WN / 4 : 16u * WN * WN);
        cycles[m] = s.cycles;
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
    CHECK(cycles[0] > 0);
    double e = fabs((double)cycles[1] - (double)cycles[0]) / (double)cycles[0];
    if (!(e <= 0.02))
        fprintf(stderr, "  sampled %llu vs full %llu cycles\n", (unsigned long long)cycles[1],
                (unsigned long long)cycles[0]);
    CHECK(e <= 0.02);
}

TEST(tile_sample_clear)
{
    /* In tile sampling, glClear writes the sampled tiles (inside the
     * scissor box) and nothing else, which nothing renders; without it, the
     * whole scissor box.  Brute force over every pixel against the sample's
     * own answer (fs_cycle_quad_skipped). */
    for (int m = 0; m < 2; m++) {
        fs_cycle *cy;
        fs_context *c = tile_sampled_context(4, 8, 1, &cy, m ? FS_CYCLE_SAMPLED : FS_CYCLE_FULL);
        memset(c->fb.color, 7, (size_t)WN * WN * 4);
        for (size_t i = 0; i < (size_t)WN * WN; i++)
            c->fb.depth[i] = 5;
        fsglClearColor(c, 1.0f, 0.0f, 1.0f, 0.0f);
        fsglClearDepth(c, 1.0);
        fsglEnable(c, GL_SCISSOR_TEST);
        fsglScissor(c, 3, 5, WN - 9, WN - 6);
        fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        CHECK_EQ_INT((int)fsglGetError(c), GL_NO_ERROR);
        int cleared = 0, bad = 0;
        for (int y = 0; y < WN; y++)
            for (int x = 0; x < WN; x++) {
                bool in = x >= 3 && x < WN - 6 && y >= 5 && y < WN - 1 && !(m && fs_cycle_quad_skipped(cy, x, y));
                const uint8_t *p = &c->fb.color[((size_t)y * WN + (size_t)x) * 4];
                uint32_t z = c->fb.depth[(size_t)y * WN + (size_t)x];
                if (in)
                    bad += !(p[0] == 255 && p[1] == 0 && p[2] == 255 && p[3] == 0 && z == c->fb.depth_max);
                else
                    bad += !(p[0] == 7 && p[1] == 7 && p[2] == 7 && p[3] == 7 && z == 5);
                cleared += in;
            }
        CHECK_EQ_INT(bad, 0);
        /* a quarter of the tiles, cut by the box's edges */
        CHECK(m ? cleared > 0 && cleared < (WN - 9) * (WN - 6) / 2 : cleared == (WN - 9) * (WN - 6));
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
}

/* A grid of lit 8 x 8 quads drawn from client arrays (normal and colour
 * per vertex, GL_COLOR_MATERIAL): how 1, glDrawArrays per row; 2,
 * glDrawElements per row (dense indices); 3, glDrawElements per column
 * (indices spread over the arrays: fetched in index order). */
enum { GRID_Q = WN / 8, GRID_V = GRID_Q * GRID_Q * 4 };
static void lit_grid_arrays(fs_context *c, int how, float (*pos)[2], float (*nrm)[3], uint8_t (*col)[4])
{
    for (int q = 0; q < GRID_Q * GRID_Q; q++) {
        int gx = (q % GRID_Q) * 8, gy = (q / GRID_Q) * 8;
        for (int k = 0; k < 4; k++) {
            int x = gx + (k == 1 || k == 2 ? 8 : 0), y = gy + (k >= 2 ? 8 : 0), i = q * 4 + k;
            pos[i][0] = ndc(x);
            pos[i][1] = ndc(y);
            nrm[i][0] = (float)(x - WN / 2) / WN;
            nrm[i][1] = (float)(y - WN / 2) / WN;
            nrm[i][2] = 1.0f;
            col[i][0] = (uint8_t)(60 + 2 * x);
            col[i][1] = (uint8_t)(40 + 3 * y);
            col[i][2] = (uint8_t)(200 - k * 30);
            col[i][3] = 255;
        }
    }
    fsglEnable(c, GL_COLOR_MATERIAL);
    fsglEnableClientState(c, GL_VERTEX_ARRAY);
    fsglEnableClientState(c, GL_NORMAL_ARRAY);
    fsglEnableClientState(c, GL_COLOR_ARRAY);
    fsglVertexPointer(c, 2, GL_FLOAT, 0, pos);
    fsglNormalPointer(c, GL_FLOAT, 0, nrm);
    fsglColorPointer(c, 4, GL_UNSIGNED_BYTE, 0, col);
    for (int r = 0; r < GRID_Q; r++) {
        if (how == 1) {
            fsglDrawArrays(c, GL_QUADS, r * GRID_Q * 4, GRID_Q * 4);
            continue;
        }
        GLushort idx[GRID_Q * 6];
        for (int j = 0; j < GRID_Q; j++) {
            int q = how == 2 ? r * GRID_Q + j : j * GRID_Q + r;
            static const int tri[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; k++)
                idx[j * 6 + k] = (GLushort)(q * 4 + tri[k]);
        }
        fsglDrawElements(c, GL_TRIANGLES, GRID_Q * 6, GL_UNSIGNED_SHORT, idx);
    }
}

static void lighting_exact_case(check_state *check_st_, int how)
{
    uint8_t img[2][WN * WN * 4];
    fs_context *cs = NULL;
    fs_cycle *cys = NULL;
    float pos[GRID_V][2], nrm[GRID_V][3];
    uint8_t col[GRID_V][4];
    for (int m = 0; m < 2; m++) {
        fs_cycle *cy;
        fs_context *c = tile_sampled_context(16, 4, 1, &cy, m ? FS_CYCLE_SAMPLED : FS_CYCLE_FULL);
        const float lpos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
        fsglEnable(c, GL_LIGHTING);
        fsglEnable(c, GL_LIGHT0);
        fsglLightfv(c, GL_LIGHT0, GL_POSITION, lpos);
        if (how)
            lit_grid_arrays(c, how, pos, nrm, col);
        else
            for (int gy = 0; gy < WN; gy += 8)
                for (int gx = 0; gx < WN; gx += 8) {
                    fsglBegin(c, GL_QUADS);
                    fsglNormal3f(c, (float)(gx - WN / 2) / WN, (float)(gy - WN / 2) / WN, 1.0f);
                    fsglVertex2f(c, ndc(gx), ndc(gy));
                    fsglVertex2f(c, ndc(gx + 8), ndc(gy));
                    fsglVertex2f(c, ndc(gx + 8), ndc(gy + 8));
                    fsglVertex2f(c, ndc(gx), ndc(gy + 8));
                    fsglEnd(c);
                }
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        memcpy(img[m], c->fb.color, sizeof img[m]);
        if (m) {
            cs = c;
            cys = cy;
        } else {
            fs_cycle_destroy(cy);
            fs_context_destroy(c);
        }
    }
    int compared = 0, lit = 0, unrendered = 0;
    for (int y = 0; y < WN; y++)
        for (int x = 0; x < WN; x++) {
            const uint8_t *a = &img[0][(y * WN + x) * 4], *b = &img[1][(y * WN + x) * 4];
            if (fs_cycle_quad_skipped(cys, x & ~1, y & ~1)) {
                unrendered += b[0] == 0 && b[1] == 0 && b[2] == 0;
                continue;
            }
            compared++;
            lit += b[0] != 0;
            CHECK(memcmp(a, b, 4) == 0);
        }
    CHECK_EQ_INT(compared, WN * WN / 16);
    CHECK_EQ_INT(lit, compared);
    CHECK_EQ_INT(unrendered, WN * WN - compared);
    fs_cycle_destroy(cys);
    fs_context_destroy(cs);
}

TEST(tile_sample_lighting_exact)
{
    /* Lit quads of 8 x 8 pixels, each its own batch, most of which reach
     * no sampled tile and so skip lighting in sampled mode: every pixel of
     * a sampled tile must still equal full cycle mode's (the functional
     * image), and the sample must leave other pixels unrendered.  The
     * same from client arrays, whose lazy vertices fetch their normals and
     * colours only when lit (a wrong array element gives a wrong colour). */
    for (int how = 0; how < 4; how++)
        lighting_exact_case(check_st_, how);
}

static void count_tri(void *user, const fs_rvertex *a, const fs_rvertex *b, const fs_rvertex *d)
{
    (void)a, (void)b, (void)d;
    ++*(int *)user;
}

TEST(tile_sample_charged_triangles_as_rasterized)
{
    /* Small triangles of every winding, some degenerate, some partly or
     * wholly off screen, with back faces culled, drawn from an array in
     * sampled mode: those outside the sampled tiles are only snapped and
     * charged their area (fs_raster_triangle_dropped).  A rasterizer hook
     * sends every triangle through fs_raster_triangle instead; both runs
     * must give the same cycles and the same triangle counts. */
    enum { NT = 400 };
    float pos[NT * 3][2];
    uint32_t r = 12345;
    for (int t = 0; t < NT; t++) {
        float px[3], py[3];
        for (int k = 0; k < 3; k++) {
            r = r * 1103515245u + 12345u;
            float u = (float)((r >> 8) % 1100) / 100.0f; /* 0 .. 11 pixels */
            r = r * 1103515245u + 12345u;
            float v = (float)((r >> 8) % 1100) / 100.0f;
            px[k] = k ? px[0] + u - 5.5f : u * (WN + 16) / 11.0f - 8.0f;
            py[k] = k ? py[0] + v - 5.5f : v * (WN + 16) / 11.0f - 8.0f;
        }
        if (t % 10 == 9)
            px[2] = px[1], py[2] = py[1]; /* degenerate */
        for (int k = 0; k < 3; k++) {
            pos[t * 3 + k][0] = 2.0f * px[k] / WN - 1.0f;
            pos[t * 3 + k][1] = 2.0f * py[k] / WN - 1.0f;
        }
    }
    uint64_t cycles[2];
    uint64_t counts[2][3];
    int hooked = 0;
    for (int run = 0; run < 2; run++) {
        fs_cycle *cy;
        fs_context *c = tile_sampled_context(16, 4, 1, &cy, FS_CYCLE_SAMPLED);
        if (run)
            fs_vs(c)->tri_hook = count_tri, fs_vs(c)->hook_user = &hooked;
        fsglEnable(c, GL_CULL_FACE);
        fsglEnable(c, GL_DEPTH_TEST);
        fsglEnableClientState(c, GL_VERTEX_ARRAY);
        fsglVertexPointer(c, 2, GL_FLOAT, 0, pos);
        for (int k = 0; k < 4; k++)
            fsglDrawArrays(c, GL_TRIANGLES, k * NT / 4 * 3, NT / 4 * 3);
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        fs_cycle_stats f, t;
        fs_cycle_frame_end(cy, &f);
        fs_cycle_totals(cy, &t);
        cycles[run] = t.cycles;
        counts[run][0] = c->stats.triangles_rasterized;
        counts[run][1] = c->stats.triangles_culled;
        counts[run][2] = t.fragments;
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
    CHECK(hooked > NT / 2); /* the hooked run rasterized most triangles */
    CHECK(counts[0][0] > 0 && counts[0][1] > NT / 4);
    CHECK(cycles[0] > 0);
    CHECK_EQ_UINT(cycles[0], cycles[1]);
    for (int k = 0; k < 3; k++)
        CHECK_EQ_UINT(counts[0][k], counts[1][k]);
}

TEST(draw_sample_fill_keeps_sampled_tiles_exact)
{
    /* Fifteen screen-filling quads of one kind, back to front, each in its
     * own colour, with the depth test on.  Run 0: full cycle mode; run 1:
     * tile sampling alone (one tile in 4 rasterized); run 2: the same with
     * one draw in 4 simulated.  The estimated draws still run in the
     * sampled tiles, so there depth and colour end as the last draw, an
     * estimated one, left them: exactly full cycle mode's (a skipped
     * instead of filled draw leaves the last simulated draw's values).  And
     * estimating draws from their work adds little to tile sampling's own
     * error (which is 2.5% on this small uniform scene). */
    enum { NDRAW = 15 };
    static uint8_t img[3][WN * WN * 4];
    static uint32_t depth[3][WN * WN];
    fs_cycle *cys = NULL;
    fs_context *cs = NULL;
    uint64_t cycles[3] = {0, 0, 0}, estimated = 0;
    for (int m = 0; m < 3; m++) {
        fs_cycle *cy;
        fs_context *c = tile_sampled_context(4, 16, m == 2 ? 4 : 1, &cy, m ? FS_CYCLE_SAMPLED : FS_CYCLE_FULL);
        fsglEnable(c, GL_DEPTH_TEST);
        fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (int r = 0; r < NDRAW; r++) {
            float z = 0.9f - 0.1f * (float)r;
            fsglColor3ub(c, (GLubyte)(16 * r + 8), (GLubyte)(255 - 16 * r), 100);
            fsglBegin(c, GL_QUADS);
            fsglVertex3f(c, ndc(0), ndc(0), z);
            fsglVertex3f(c, ndc(WN), ndc(0), z);
            fsglVertex3f(c, ndc(WN), ndc(WN), z);
            fsglVertex3f(c, ndc(0), ndc(WN), z);
            fsglEnd(c);
        }
        fs_cycle_stats f;
        fs_cycle_frame_end(cy, &f);
        cycles[m] = f.cycles;
        if (m == 2)
            estimated = f.draws_estimated;
        memcpy(img[m], c->fb.color, sizeof img[m]);
        memcpy(depth[m], c->fb.depth, sizeof depth[m]);
        if (m == 2) {
            cs = c;
            cys = cy;
        } else {
            fs_cycle_destroy(cy);
            fs_context_destroy(c);
        }
    }
    CHECK(estimated >= NDRAW / 2);
    int compared = 0, wrong = 0;
    for (int i = 0; i < WN * WN; i++) {
        if (fs_cycle_quad_skipped(cys, (i % WN) & ~1, (i / WN) & ~1))
            continue;
        compared++;
        wrong += memcmp(&img[0][i * 4], &img[2][i * 4], 4) != 0 || depth[0][i] != depth[2][i];
    }
    CHECK_EQ_INT(compared, WN * WN / 4);
    CHECK_EQ_INT(wrong, 0);
    CHECK(cycles[0] > 0 && cycles[1] > 0);
    double e = fabs((double)cycles[2] - (double)cycles[1]) / (double)cycles[1];
    if (!(e <= 0.01))
        fprintf(stderr, "  draw and tile sampling %llu vs tile sampling %llu cycles\n",
                (unsigned long long)cycles[2], (unsigned long long)cycles[1]);
    CHECK(e <= 0.01);
    fs_cycle_destroy(cys);
    fs_context_destroy(cs);
}


/* Huettner 1999, footnote 5 of 3.1.10: reading a 500x500 buffer takes
 * 0.0254 s on an O2 and 0.00322 s on an InfiniteReality; a 100x100 one
 * 2.1294e-05 s and 0.0001762 s.  The virtual occlusion buffer read is of
 * the stencil buffer (3.2), one byte per pixel.  configs/o2.ini and
 * infinite_reality.ini reproduce the four times: glReadPixels of the
 * stencil, its read-back cycles at the config's clock, within 0.05%. */
TEST(readback_reproduces_footnote_5)
{
    static const struct { const char *ini; int side; double seconds; } want[] = {
        {"configs/o2.ini", 500, 0.0254},
        {"configs/o2.ini", 100, 2.1294e-05},
        {"configs/infinite_reality.ini", 500, 0.00322},
        {"configs/infinite_reality.ini", 100, 0.0001762},
    };
    static uint8_t img[500 * 500];
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        fs_run_config cfg;
        char err[512];
        fs_run_config_defaults(&cfg);
        if (fs_run_config_load(&cfg, want[k].ini, err, sizeof err) != 0)
            SKIP("configs/ not found (run from the repository root)");
        REQUIRE(fs_run_config_check(&cfg, err, sizeof err) == 0);
        REQUIRE(cfg.cycle.clock_khz > 0 && cfg.cycle.readback_ps_per_byte > 0);
        fs_cycle *cy;
        fs_context *c = new_context_sized(&cfg, 512, &cy, FS_CYCLE_FULL);
        REQUIRE(cy != NULL);
        fsglReadPixels(c, 0, 0, want[k].side, want[k].side, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, img);
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        fs_cycle_stats st;
        fs_cycle_totals(cy, &st);
        double sec = (double)st.readback_cycles / ((double)cfg.cycle.clock_khz * 1000.0);
        printf("    %s, %dx%d: %llu cycles, %.7g s (dissertation %.7g s)\n", want[k].ini, want[k].side, want[k].side,
               (unsigned long long)st.readback_cycles, sec, want[k].seconds);
        CHECK(fabs(sec / want[k].seconds - 1.0) < 0.0005);
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
}

/* The calibrated cost in closed form: setup, the fast bytes, the rest;
 * rounded up to whole cycles; the key without a clock is refused. */
TEST(readback_closed_form)
{
    fs_cycle_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.clock_khz = 100000; /* 100 MHz: 10 ns per cycle */
    cfg.readback_setup_ns = 1000;
    cfg.readback_fast_bytes = 100;
    cfg.readback_fast_ps_per_byte = 1000;
    cfg.readback_ps_per_byte = 20000;
    /* 1000 ns + 50 ns = 105 cycles; 1000 + 100 + 2 * 20 ns = 114 cycles */
    CHECK_EQ_UINT(fs_cyc_readback_cycles(&cfg, 50), 105);
    CHECK_EQ_UINT(fs_cyc_readback_cycles(&cfg, 102), 114);
    CHECK_EQ_UINT(fs_cyc_readback_cycles(&cfg, 0), 100);
    cfg.readback_setup_ns = 1; /* 0.1 cycle rounds up to 1 */
    cfg.readback_fast_bytes = 0;
    CHECK_EQ_UINT(fs_cyc_readback_cycles(&cfg, 0), 1);
    /* 2^40 bytes at 10^9 ps each at 10 GHz: no overflow, saturates */
    cfg.clock_khz = 10000000;
    cfg.readback_ps_per_byte = 1000000000;
    CHECK(fs_cyc_readback_cycles(&cfg, (uint64_t)1 << 40) > ((uint64_t)1 << 60));
    fs_run_config rc;
    char err[256];
    fs_run_config_defaults(&rc);
    rc.cycle.readback_ps_per_byte = 5;
    CHECK(fs_run_config_check(&rc, err, sizeof err) != 0);
    CHECK(strstr(err, "clock.khz") != NULL);
}

/* One frame of the warm-up test: `quads` screen-filling quads after a
 * clear, with materials set between their vertices (the immediate-mode
 * path that lights vertex runs apart). */
static void warmup_frame(fs_context *c, int quads)
{
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int r = 0; r < quads; r++) {
        float z = 0.9f - 0.1f * (float)r;
        const float red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
        fsglBegin(c, GL_QUADS);
        fsglVertex3f(c, ndc(0), ndc(0), z);
        fsglVertex3f(c, ndc(WN), ndc(0), z);
        fsglMaterialfv(c, GL_FRONT_AND_BACK, GL_DIFFUSE, red);
        fsglVertex3f(c, ndc(WN), ndc(WN), z);
        fsglMaterialfv(c, GL_FRONT_AND_BACK, GL_DIFFUSE, blue);
        fsglVertex3f(c, ndc(0), ndc(WN), z);
        fsglEnd(c);
    }
}

/* A run of the frame-sampling tests: nf frames of warmup_frame (frame 0
 * with first_quads quads, the others with one), the draws of the frames
 * sampled mode skips left out as the driver leaves them out
 * (fs_cycle_frame_skipped); lit: depth test and one light on. */
typedef struct frames_run {
    uint64_t total, cycles[16], frags[16]; /* per frame: cycles, fragments rasterized */
    uint64_t after[16];                  /* per frame after fs_cycle_finish (skipped: estimated) */
    bool skipped[16];
    GLenum error;                        /* glGetError after the last frame */
    double estimate;                     /* fs_cycle_error_estimate at the end */
    fs_cycle_config next;                /* fs_cycle_config_denser's next pass */
    bool denser;                         /* and whether it found one */
} frames_run;

/* nf (<= 16) frames, frame f of quads[f] quads; sig: the frames'
 * signatures as the driver gives them (fs_cycle_set_frame_signatures,
 * both the kind and the exact one), or NULL for none. */
static frames_run run_frames_sig(const fs_run_config *cfg, fs_cycle_mode mode, int nf, const int *quads, bool lit,
                                 const uint64_t *sig)
{
    frames_run r = {0};
    fs_cycle *cy;
    fs_context *c = new_context(cfg, &cy, mode);
    fs_cycle_set_frame_signatures(cy, sig, sig, sig ? (uint64_t)nf : 0);
    fs_cycle_set_frames(cy, (uint64_t)nf);
    if (lit) {
        fsglEnable(c, GL_DEPTH_TEST);
        fsglEnable(c, GL_LIGHTING);
        fsglEnable(c, GL_LIGHT0);
    }
    for (int f = 0; f < nf && f < 16; f++) {
        uint64_t before = c->stats.fragments_generated;
        r.skipped[f] = fs_cycle_frame_skipped(cy);
        if (!r.skipped[f])
            warmup_frame(c, quads[f]);
        fs_cycle_stats st;
        fs_cycle_frame_end(cy, &st);
        r.cycles[f] = st.cycles;
        r.frags[f] = c->stats.fragments_generated - before;
    }
    r.error = fsglGetError(c);
    fs_cycle_finish(cy);
    for (int f = 0; f < nf && f < 16; f++) {
        bool sk;
        r.after[f] = mode == FS_CYCLE_SAMPLED ? fs_cycle_frame_cycles(cy, (uint64_t)f, &sk) : r.cycles[f];
    }
    fs_cycle_stats t;
    fs_cycle_totals(cy, &t);
    r.total = t.cycles;
    r.estimate = fs_cycle_error_estimate(cy);
    r.next = cfg->cycle;
    r.denser = fs_cycle_config_denser(cy, &r.next);
    fs_cycle_destroy(cy);
    fs_context_destroy(c);
    return r;
}

static frames_run run_frames_of(const fs_run_config *cfg, fs_cycle_mode mode, int nf, const int *quads, bool lit)
{
    return run_frames_sig(cfg, mode, nf, quads, lit, NULL);
}

static frames_run run_frames(const fs_run_config *cfg, fs_cycle_mode mode, int nf, int first_quads, bool lit)
{
    int quads[16];
    for (int f = 0; f < 16; f++)
        quads[f] = f == 0 ? first_quads : 1;
    return run_frames_of(cfg, mode, nf, quads, lit);
}

TEST(frame_sampling_warmup_frame)
{
    /* Eight frames: frame 0 draws 6 quads (a warm-up, as frame 0 of most
     * corpus programs is), frames 1-7 one each.  Sampled mode with
     * sampling.frames = 3 simulates frames 0, 1, 4 and 7 and skips the
     * others' draws (the driver's rule, fs_cycle_frame_skipped); frames
     * 1-7 cost the same in full cycle mode, so interpolating them between
     * simulated steady frames is exact: the total equals full cycle mode's.
     * Interpolating from frame 0 (the earlier rule) put frames 2 and 3 on
     * the line from the warm-up to frame 4.  With tile sampling inside the
     * frames too, the quads with materials between their vertices must
     * still reach the sampled tiles (they were all dropped). */
    enum { NF = 8 };
    static const bool simulated[NF] = {1, 1, 0, 0, 1, 0, 0, 1};
    frames_run run[3];
    uint64_t frags[3] = {0, 0, 0}; /* in the frames sampled mode simulates */
    for (int m = 0; m < 3; m++) {
        fs_run_config cfg;
        fs_run_config_defaults(&cfg);
        cfg.cycle.sampling_frames = 3;
        cfg.cycle.sampling_frame_tiles = m == 2 ? 4 : 1;
        cfg.cycle.sampling_tile_size = 8;
        run[m] = run_frames(&cfg, m ? FS_CYCLE_SAMPLED : FS_CYCLE_FULL, NF, 6, true);
        CHECK_EQ_INT(run[m].error, GL_NO_ERROR);
        for (int f = 0; f < NF; f++) {
            if (m)
                CHECK_EQ_INT(!run[m].skipped[f], simulated[f]);
            if (simulated[f])
                frags[m] += run[m].frags[f];
        }
    }
    CHECK(run[0].cycles[0] > run[0].cycles[1] * 2);
    for (int f = 2; f < NF; f++)
        CHECK_EQ_UINT(run[0].cycles[f], run[0].cycles[1]);
    CHECK(run[0].total > 0);
    CHECK_EQ_UINT(run[1].total, run[0].total);
    CHECK_EQ_UINT(frags[1], frags[0]);
    /* one tile in 4 rasterized: about a quarter of the fragments, not none */
    CHECK(frags[2] > frags[0] / 8 && frags[2] < frags[0] / 2);
}

TEST(frame_sampling_short_traces)
{
    /* 3 to 5 frames: too few to sample with an estimate, simulated in full
     * (no frame skipped, no tile or draw sampling: the cycles equal full
     * cycle mode's); 6 frames: frames 0, 1, 3 and 5 simulated (step
     * (6 - 2) / 2 = 2 under the default 7); 1 frame: tile sampling. */
    for (int nf = 1; nf <= 6; nf++) {
        fs_run_config cfg;
        fs_run_config_defaults(&cfg);
        char err[256];
        fs_cycle *cy = fs_cycle_create(&cfg.cycle, FS_CYCLE_SAMPLED, err, sizeof err);
        CHECK(cy != NULL);
        if (!cy)
            continue;
        fs_cycle_set_frames(cy, (uint64_t)nf);
        CHECK_EQ_INT(fs_cycle_too_short(cy), nf >= 3 && nf <= 5);
        fs_cycle_destroy(cy);
        frames_run full = run_frames(&cfg, FS_CYCLE_FULL, nf, 3, false);
        frames_run smp = run_frames(&cfg, FS_CYCLE_SAMPLED, nf, 3, false);
        CHECK_EQ_INT(full.error, GL_NO_ERROR);
        CHECK_EQ_INT(smp.error, GL_NO_ERROR);
        int skipped = 0;
        for (int f = 0; f < nf; f++) {
            if (smp.skipped[f])
                CHECK_EQ_INT(nf == 6 && (f == 2 || f == 4), 1);
            skipped += smp.skipped[f];
        }
        CHECK_EQ_INT(skipped, nf == 6 ? 2 : 0);
        CHECK(full.total > 0);
        if (nf >= 3 && nf <= 5)
            CHECK_EQ_UINT(smp.total, full.total);
        if (nf == 1)
            CHECK(smp.total != full.total); /* tile-sampled: an estimate */
    }
}

/* Sampled mode on 16 frames, frame f drawing quads[f] full-screen quads,
 * then fs_cycle_config_denser's passes until the estimate is within
 * bound (or nothing is left to sample); the last pass in *last, its
 * configuration in *cfg_last; returns the passes, negative when a pass's
 * error against full cycle mode (full_total) lay outside its estimate or
 * a GL error occurred. */
static int resample_run(const int *quads, double bound, uint64_t full_total, frames_run *last, fs_cycle_config *cfg_last)
{
    fs_run_config pc;
    fs_run_config_defaults(&pc);
    int passes = 0;
    bool bad = false;
    for (;;) {
        *last = run_frames_of(&pc, FS_CYCLE_SAMPLED, 16, quads, true);
        passes++;
        double err = ((double)last->total - (double)full_total) / (double)full_total;
        if (fabs(err) > last->estimate || last->error != GL_NO_ERROR) {
            fprintf(stderr, "    pass %d: error %+.4f%% outside its estimate %.4f%%\n", passes, 100 * err,
                    100 * last->estimate);
            bad = true;
        }
        if (last->estimate <= bound || !last->denser || passes > 20)
            break;
        pc.cycle = last->next;
    }
    *cfg_last = pc.cycle;
    return bad ? -passes : passes;
}

TEST(max_error_resamples)
{
    /* Work that scatters by about 10% from frame to frame (10 to 13 quads):
     * with the default step 7 sampled mode simulates frames 0, 1, 8 and 15
     * of 16, whose one residual is 0 by chance (10, 11, 12 quads on a
     * line) while the trace between is not (-3.0%); with one residual the
     * steady frames' scatter stands in, and the 95% interval (t, 2 degrees
     * of freedom) is 18%.  Above a 5% bound the next pass halves the step
     * (-0.7%, 3.2%), within the bound by sampling.  A bound of 0.001%
     * cannot be met by sampling: the ladder ends at full simulation
     * (estimate 0, full cycle mode's cycles, nothing denser).  Before the
     * interval (the curvature bound alone) the first pass reported 0 for
     * an error of -3.0%. */
    static const int quads[16] = {16, 10, 11, 10, 10, 11, 12, 11, 11, 12, 12, 11, 12, 13, 12, 12};
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    frames_run full = run_frames_of(&cfg, FS_CYCLE_FULL, 16, quads, true), r;
    CHECK(full.total > 0);
    fs_cycle_config last;
    CHECK(resample_run(quads, 0.05, full.total, &r, &last) == 2);
    CHECK(r.estimate <= 0.05);
    CHECK(last.sampling_frames > 1); /* met by sampling, not by simulating all */
    int passes = resample_run(quads, 1e-5, full.total, &r, &last);
    CHECK(passes > 2);
    CHECK_EQ_UINT(r.total, full.total);
    CHECK(r.estimate == 0.0);
    CHECK_EQ_INT(last.sampling_frames, 1);
    CHECK(!r.denser);
}

TEST(max_error_frame_aliasing_known)
{
    /* Known limit (docs/cycle_model.md): the simulated frames 1, 8 and 15
     * all draw 1 quad and the frames between 1 to 4: nothing in the sample
     * shows the others' work, its scatter is 0, and the estimate is 0 for
     * an error of -27.7%.  Systematic frame sampling aliases with work of
     * the step's period; no estimate from the sample can see it.  This
     * check fails when the estimate comes to cover it. */
    static const int quads[16] = {6, 1, 3, 1, 2, 1, 4, 1, 1, 3, 1, 2, 1, 1, 4, 1};
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    frames_run full = run_frames_of(&cfg, FS_CYCLE_FULL, 16, quads, true);
    frames_run smp = run_frames_of(&cfg, FS_CYCLE_SAMPLED, 16, quads, true);
    double err = ((double)smp.total - (double)full.total) / (double)full.total;
    CHECK(err < -0.2);
    CHECK(smp.estimate < fabs(err));
}

/* The signatures of frames of quads[f] quads as the driver would hash
 * them: frames of as many quads make the same calls. */
static void quad_signatures(const int *quads, int nf, uint64_t *sig)
{
    for (int f = 0; f < nf; f++)
        sig[f] = 0x9e3779b97f4a7c15ull * (uint64_t)(quads[f] + 1);
}

TEST(frame_clusters_repeated_kinds)
{
    /* Frame 0 a warm-up (6 quads), then frames of three kinds, A (1 quad,
     * 8 frames), B (3 quads, 4 frames) and C (8 quads, 3 frames), each
     * kind an exact repeat of its calls.  With the signatures sampled mode
     * simulates frame 0 and the first and last frame of each kind (7 of
     * 16; two, not one, so that the kind's spread has a degree of
     * freedom), and each skipped frame gets its own kind's cycles: every
     * frame's estimate equals full cycle mode's, so does the total, and
     * the estimate is 0.  Without signatures (one sequence, frames 1, 8
     * and 15 of kind A simulated) the kinds alias with the step: the
     * total misses by more than 25%, under an estimate of 20%. */
    static const int quads[16] = {6, 1, 3, 1, 8, 1, 3, 1, 8, 1, 3, 1, 8, 1, 3, 1};
    static const bool simulated[16] = {1, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1};
    uint64_t sig[16];
    quad_signatures(quads, 16, sig);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    cfg.cycle.sampling_frame_tiles = 1; /* simulated frames exact: only the clusters estimate */
    frames_run full = run_frames_of(&cfg, FS_CYCLE_FULL, 16, quads, true);
    frames_run smp = run_frames_sig(&cfg, FS_CYCLE_SAMPLED, 16, quads, true, sig);
    frames_run nosig = run_frames_of(&cfg, FS_CYCLE_SAMPLED, 16, quads, true);
    CHECK_EQ_INT(full.error, GL_NO_ERROR);
    CHECK_EQ_INT(smp.error, GL_NO_ERROR);
    int nsim = 0;
    for (int f = 0; f < 16; f++) {
        CHECK_EQ_INT(!smp.skipped[f], simulated[f]);
        nsim += !smp.skipped[f];
        /* the weights: each skipped frame stands for itself at its kind's cost */
        CHECK_EQ_UINT(smp.after[f], full.cycles[f]);
    }
    CHECK_EQ_INT(nsim, 7);
    /* full cycle mode: the frames of a kind cost the same, the kinds not */
    CHECK(full.cycles[4] > 2 * full.cycles[2] && full.cycles[2] > full.cycles[1]);
    CHECK_EQ_UINT(smp.total, full.total);
    CHECK(smp.estimate == 0.0);
    double err = ((double)nosig.total - (double)full.total) / (double)full.total;
    fprintf(stderr, "    three kinds without signatures: error %+.2f%%, estimate %.2f%%\n", 100 * err,
            100 * nosig.estimate);
    CHECK(fabs(err) > 0.25);
}

TEST(frame_clusters_weights)
{
    /* Kinds of very different cost in unequal numbers: 9 frames of 1 quad,
     * 3 of 12 quads, 3 of 5.  A representative weighted by the wrong count
     * (each kind's cost once, or the kinds' mean for every frame) misses
     * the total by more than 30%; weighted by its kind's frames the total
     * is full cycle mode's.  The kinds' frames interleave irregularly, so
     * a cluster's skipped frames lie between frames of other kinds. */
    static const int quads[16] = {6, 1, 12, 1, 1, 5, 1, 12, 1, 5, 1, 1, 12, 1, 5, 1};
    uint64_t sig[16];
    quad_signatures(quads, 16, sig);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    cfg.cycle.sampling_frame_tiles = 1;
    frames_run full = run_frames_of(&cfg, FS_CYCLE_FULL, 16, quads, true);
    frames_run smp = run_frames_sig(&cfg, FS_CYCLE_SAMPLED, 16, quads, true, sig);
    int nsim = 0;
    double mean_kinds = 0;
    for (int f = 0; f < 16; f++) {
        nsim += !smp.skipped[f];
        CHECK_EQ_UINT(smp.after[f], full.cycles[f]);
    }
    CHECK_EQ_INT(nsim, 7);
    mean_kinds = ((double)full.cycles[1] + (double)full.cycles[2] + (double)full.cycles[5]) / 3.0;
    double wrong = (double)full.cycles[0] + 15.0 * mean_kinds;
    CHECK(fabs(wrong - (double)full.total) > 0.3 * (double)full.total);
    CHECK_EQ_UINT(smp.total, full.total);
    CHECK(smp.estimate == 0.0);
}

TEST(frame_clusters_kinds_not_repeats)
{
    /* The aliasing trace of max_error_frame_aliasing_known with its
     * signatures: its 1-quad frames are one cluster (first and last
     * simulated), the frames of 2, 3 and 4 quads (two each, too few for a
     * cluster) one sequence in frame order.  The error, -27.7% without
     * signatures under an estimate of 0, is now within its estimate. */
    static const int quads[16] = {6, 1, 3, 1, 2, 1, 4, 1, 1, 3, 1, 2, 1, 1, 4, 1};
    uint64_t sig[16];
    quad_signatures(quads, 16, sig);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    frames_run full = run_frames_of(&cfg, FS_CYCLE_FULL, 16, quads, true);
    frames_run smp = run_frames_sig(&cfg, FS_CYCLE_SAMPLED, 16, quads, true, sig);
    double err = ((double)smp.total - (double)full.total) / (double)full.total;
    fprintf(stderr, "    aliasing trace with signatures: error %+.2f%%, estimate %.2f%%\n", 100 * err,
            100 * smp.estimate);
    CHECK(fabs(err) <= smp.estimate);
    CHECK(fabs(err) < 0.05);
}

/* A trace of frames drawing tris[f] triangles each (frame 0 also sets the
 * viewport), written with the trace writer; 0 or -1. */
static int write_kinds_trace(const char *path, const int *tris, int nf)
{
    char err[256];
    fs_trace_writer *w = fs_trace_create(path, err, sizeof err);
    if (!w)
        return -1;
    fs_tval vp[4] = {tb_ival(0), tb_ival(0), tb_ival(WN), tb_ival(WN)};
    tb_write_call(w, "glViewport", 4, vp, 0);
    fs_tval cap = tb_eval(GL_DEPTH_TEST, "GL_DEPTH_TEST");
    tb_write_call(w, "glEnable", 1, &cap, 0);
    for (int f = 0; f < nf; f++) {
        fs_tval mask = tb_ival(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        tb_write_call(w, "glClear", 1, &mask, 0);
        for (int t = 0; t < tris[f]; t++) {
            fs_tval m = tb_eval(GL_TRIANGLES, "GL_TRIANGLES");
            tb_write_call(w, "glBegin", 1, &m, 0);
            static const float v[3][2] = {{-1, -1}, {1, -1}, {-1, 1}};
            for (int i = 0; i < 3; i++) {
                fs_tval a[3] = {tb_fval(v[i][0]), tb_fval(v[i][1]), tb_fval(0.9 - 0.05 * t)};
                tb_write_call(w, "glVertex3f", 3, a, 0);
            }
            tb_write_call(w, "glEnd", 0, NULL, 0);
        }
        fs_tval sw[2] = {tb_ival(0), tb_ival(0)};
        tb_write_call(w, "glXSwapBuffers", 2, sw, 0);
    }
    return fs_trace_finish(w);
}

/* Replays a trace as `fragsim replay --mode` does (the driver's
 * signatures, its skipping of the frames sampled mode interpolates);
 * the total cycles, *est the error estimate, *simulated the frames run. */
static uint64_t replay_cycles(const char *path, const fs_run_config *cfg, fs_cycle_mode mode, double *est,
                              int *simulated)
{
    char err[256];
    fs_replayer *r = fs_replay_open(path, NULL, err, sizeof err);
    if (!r)
        return 0;
    const fs_replay_info *info = fs_replay_info_get(r);
    fs_context *c = fs_context_create(&cfg->gl, info->width, info->height);
    fs_cli_cycle *h = c ? fs_cli_cycle_begin(mode, &cfg->cycle, c, NULL, r, false, err, sizeof err) : NULL;
    uint64_t total = 0;
    *simulated = 0;
    if (h) {
        fs_call call;
        fs_replay_event ev;
        bool drew = false;
        while ((ev = fs_replay_next(r, &call)) == FS_REPLAY_CALL || ev == FS_REPLAY_FRAME_END) {
            if (ev == FS_REPLAY_FRAME_END) {
                *simulated += drew;
                drew = false;
                fs_cli_cycle_frame(h, 0);
            } else if (!fs_cli_cycle_skip(h, c, call.cmd)) {
                drew |= call.cmd == FS_CMD_Begin;
                fs_submit(c, &call);
            }
        }
        fs_cycle_stats t;
        *est = fs_cli_cycle_totals(h, &t);
        total = t.cycles;
        fs_cli_cycle_end(h);
    }
    fs_context_destroy(c);
    fs_replay_close(r);
    return total;
}

TEST(frame_clusters_from_a_trace)
{
    /* End to end: a trace whose frames come in three kinds, A (1
     * triangle), B (3), C (6), each an exact repeat, replayed through the
     * driver's signatures (pass 1 hashes the calls) and frame skipping.
     * Sampled mode simulates frame 0 and the first and last frame of each
     * kind (7 of 20) and its total equals full cycle mode's, estimate 0. */
    static const int tris[20] = {2, 1, 3, 6, 1, 3, 6, 1, 1, 3, 6, 1, 3, 1, 6, 1, 3, 1, 6, 1};
    char path[256];
    snprintf(path, sizeof path, "/tmp/fragsim_test_cycle_kinds_%d.trace", (int)getpid());
    REQUIRE(write_kinds_trace(path, tris, 20) == 0);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    cfg.cycle.sampling_frame_tiles = 1; /* simulated frames exact */
    double est_full, est;
    int sim_full, sim;
    uint64_t full = replay_cycles(path, &cfg, FS_CYCLE_FULL, &est_full, &sim_full);
    uint64_t smp = replay_cycles(path, &cfg, FS_CYCLE_SAMPLED, &est, &sim);
    CHECK(full > 0);
    CHECK_EQ_INT(sim_full, 20);
    CHECK_EQ_INT(sim, 7);
    CHECK_EQ_UINT(smp, full);
    CHECK(est == 0.0);
    unlink(path);
}

TEST_LIST = {
    TEST_ENTRY(readback_reproduces_footnote_5),
    TEST_ENTRY(readback_closed_form),
    TEST_ENTRY(single_stage_closed_form),
    TEST_ENTRY(two_stage_bottleneck),
    TEST_ENTRY(fifo_high_water_mark),
    TEST_ENTRY(memory_bandwidth),
    TEST_ENTRY(occlusion_engines_ceil_t_over_e),
    TEST_ENTRY(rendermode_drain),
    TEST_ENTRY(rendermode_drain_select),
    TEST_ENTRY(tile_sample_lattice),
    TEST_ENTRY(tile_sample_full_screen),
    TEST_ENTRY(tile_sample_clear),
    TEST_ENTRY(tile_sample_lighting_exact),
    TEST_ENTRY(tile_sample_charged_triangles_as_rasterized),
    TEST_ENTRY(draw_sample_fill_keeps_sampled_tiles_exact),
    TEST_ENTRY(frame_sampling_warmup_frame),
    TEST_ENTRY(frame_sampling_short_traces),
    TEST_ENTRY(max_error_resamples),
    TEST_ENTRY(max_error_frame_aliasing_known),
    TEST_ENTRY(frame_clusters_repeated_kinds),
    TEST_ENTRY(frame_clusters_weights),
    TEST_ENTRY(frame_clusters_kinds_not_repeats),
    TEST_ENTRY(frame_clusters_from_a_trace),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
