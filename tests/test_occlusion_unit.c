/*
 * The Occlusion Unit (units/occlusion_*.c) and GL_FRAGSIM_occlusion_unit
 * (docs/extensions/occlusion_unit.txt), after Huettner 1999, 3.2-3.3:
 *   - every error the spec names, with the state left unchanged;
 *   - the GL 1.5 query commands against OSMesa in this process (errors,
 *     names, glIsQuery);
 *   - random box scenes (fixed seeds): NOHC == the GL 1.5 query of fragsim
 *     == OSMesa's GL_SAMPLES_PASSED; per tile, NOHC, bounding box and z
 *     range == a brute-force recount from the depth buffer after drawing
 *     the box normally, PHC == the pixels the box alone covers in the tile,
 *     and the verbose hit list == the recounted pixel set, identical for 1,
 *     2 and 5 engines;
 *   - counter saturation, hit-list overflow, the -1 terminator and
 *     glRenderMode's return value;
 *   - the framebuffer is bit-identical before and after an occlusion pass;
 *   - the dissertation's examples: the quadtree of 13 tiles (Fig. 3.14) and
 *     collision detection with 3x3 heading tiles (3.3.2, Fig. 3.20).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../units/occlusion_unit.h"
#include "../driver/osmesa_ref.h"
#include "../driver/gl_call.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

#define W 128
#define H 128

/* One drawing routine for both renderers: t->c set means fragsim, NULL
 * means the current OSMesa context through the real gl* entry points. */
typedef struct tgt { fs_context *c; } tgt;
#define G(t, name, ...) ((t)->c ? fsgl##name((t)->c, __VA_ARGS__) : gl##name(__VA_ARGS__))
#define G0(t, name) ((t)->c ? fsgl##name((t)->c) : gl##name())

static uint64_t rng_next(uint64_t *s)
{
    /* splitmix64: a fixed, portable sequence per seed */
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static float rnd(uint64_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(rng_next(s) >> 40) / (float)(1u << 24);
}

/* An axis-aligned box with outward-facing counter-clockwise quads. */
static void draw_box(tgt *t, const float lo[3], const float hi[3])
{
    static const int face[6][4][3] = {
        {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}},
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}},
        {{0, 1, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
    };
    G(t, Begin, GL_QUADS);
    for (int f = 0; f < 6; f++)
        for (int v = 0; v < 4; v++)
            G(t, Vertex3f, face[f][v][0] ? hi[0] : lo[0], face[f][v][1] ? hi[1] : lo[1],
              face[f][v][2] ? hi[2] : lo[2]);
    G0(t, End);
}

static void random_box(uint64_t *s, float lo[3], float hi[3], float zmin, float zmax)
{
    for (int k = 0; k < 3; k++) {
        float a = k < 2 ? rnd(s, -1.2f, 1.0f) : rnd(s, zmin, zmax);
        float e = k < 2 ? rnd(s, 0.05f, 0.8f) : rnd(s, 0.1f, 1.5f);
        lo[k] = a;
        hi[k] = a + e;
    }
}

/* Perspective camera looking down -z, culling back faces (3.2: counting
 * needs back-face culling and convex volumes). */
static void setup_view(tgt *t, float angle)
{
    G(t, Viewport, 0, 0, W, H);
    G(t, MatrixMode, GL_PROJECTION);
    G0(t, LoadIdentity);
    G(t, Frustum, -0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    G(t, MatrixMode, GL_MODELVIEW);
    G0(t, LoadIdentity);
    G(t, Translatef, 0.0f, 0.0f, -3.0f);
    G(t, Rotatef, angle, 0.3f, 1.0f, 0.1f);
    G(t, Enable, GL_DEPTH_TEST);
    G(t, Enable, GL_CULL_FACE);
    G(t, ClearColor, 0.0f, 0.0f, 0.0f, 0.0f);
    G(t, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static void draw_scene(tgt *t, uint64_t seed, int nboxes)
{
    uint64_t s = seed;
    for (int i = 0; i < nboxes; i++) {
        float lo[3], hi[3];
        random_box(&s, lo, hi, -1.5f, 0.5f);
        G(t, Color3f, rnd(&s, 0.1f, 1.0f), rnd(&s, 0.1f, 1.0f), rnd(&s, 0.1f, 1.0f));
        draw_box(t, lo, hi);
    }
}

static fs_context *new_ctx(int engines, int counter_bits)
{
    fs_config cfg;
    fs_config_defaults(&cfg);
    cfg.occlusion_engines = engines;
    cfg.occlusion_counter_bits = counter_bits;
    return fs_context_create(&cfg, W, H);
}

static uint64_t fb_hash(const fs_context *c)
{
    uint64_t h = 1469598103934665603ull;
    size_t n = (size_t)c->fb.width * (size_t)c->fb.height;
    const uint8_t *parts[3] = {c->fb.color, (const uint8_t *)c->fb.depth, c->fb.stencil};
    size_t sizes[3] = {n * 4, n * 4, n};
    for (int p = 0; p < 3; p++)
        for (size_t i = 0; i < sizes[p]; i++)
            h = (h ^ parts[p][i]) * 1099511628211ull;
    return h;
}

/* ------------------------------------------------------------- errors */

TEST(errors_and_state)
{
    fs_context *c = new_ctx(1, 32);
    REQUIRE(c);
    GLint v = -1;
    fsglGetIntegerv(c, GL_MAX_OCCLUSION_TILES, &v);
    CHECK_EQ_INT(v, 64);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_RENDER);
    fsglGetIntegerv(c, GL_OCCLUSION_COUNTER_BITS, &v);
    CHECK_EQ_INT(v, 32);
    CHECK(strstr((const char *)fsglGetString(c, GL_EXTENSIONS), "GL_FRAGSIM_occlusion_unit") != NULL);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);

    GLint tiles[8] = {0, 0, 64, 64, 64, 64, 64, 64};
    fsglScissors(c, 2, tiles);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    /* negative count, too many tiles, negative size: INVALID_VALUE, tiles kept */
    fsglScissors(c, -1, NULL);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    GLint *many = calloc(65 * 4, sizeof *many);
    REQUIRE(many);
    fsglScissors(c, 65, many);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    free(many);
    GLint bad[8] = {0, 0, 4, 4, 0, 0, 4, -1};
    fsglScissors(c, 2, bad);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglGetIntegerv(c, GL_OCCLUSION_TILE_COUNT, &v);
    CHECK_EQ_INT(v, 2);

    /* an occlusion mode before glOcclusionBuffers: INVALID_OPERATION */
    CHECK_EQ_INT(fsglRenderMode(c, GL_BRIEF_OCCLUSION), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_RENDER);
    /* buffer sizes below 8: INVALID_VALUE */
    GLuint b0[16], b1[16];
    GLuint *bufs[2] = {b0, b1};
    GLsizei small[2] = {8, 7};
    fsglOcclusionBuffers(c, small, bufs);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    CHECK_EQ_INT(fsglRenderMode(c, GL_BRIEF_OCCLUSION), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    GLsizei sizes[2] = {8, 16};
    fsglOcclusionBuffers(c, sizes, bufs);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    /* unknown mode: INVALID_ENUM */
    CHECK_EQ_INT(fsglRenderMode(c, GL_TEXTURE_2D), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_ENUM);
    /* buffers no longer match the tiles: INVALID_OPERATION */
    fsglScissors(c, 1, tiles);
    CHECK_EQ_INT(fsglRenderMode(c, GL_VERBOSE_OCCLUSION), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglScissors(c, 2, tiles);

    CHECK_EQ_INT(fsglRenderMode(c, GL_VERBOSE_OCCLUSION), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_VERBOSE_OCCLUSION);
    /* changing tiles or buffers in an occlusion mode: INVALID_OPERATION */
    fsglScissors(c, 1, tiles);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglOcclusionBuffers(c, sizes, bufs);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglGetIntegerv(c, GL_OCCLUSION_TILE_COUNT, &v);
    CHECK_EQ_INT(v, 2);
    /* between Begin and End: INVALID_OPERATION for every new command */
    fsglBegin(c, GL_TRIANGLES);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0);
    fsglScissors(c, 1, tiles);
    fsglOcclusionBuffers(c, sizes, bufs);
    GLuint q;
    fsglGenQueries(c, 1, &q);
    fsglEnd(c);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_VERBOSE_OCCLUSION);
    /* leaving: no overflow, records written (-1 right after the header) */
    memset(b0, 0xAB, sizeof b0);
    memset(b1, 0xAB, sizeof b1);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0);
    CHECK_EQ_UINT(b0[0], 0);
    CHECK_EQ_UINT(b0[2], 0xFFFFFFFFu); /* empty box: min registers all ones */
    CHECK_EQ_UINT(b0[3], 0);
    CHECK_EQ_UINT(b0[8], 0xABABABABu); /* size 8: no room for the terminator */
    CHECK_EQ_UINT(b1[8], 0xFFFFFFFFu);
    CHECK_EQ_UINT(b1[9], 0xABABABABu);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0);
    /* GL_SELECT beside the occlusion modes (pipeline/render_mode.c):
     * without glSelectBuffer it is GL_INVALID_OPERATION, and entered all
     * the same, as OSMesa does (tests/test_render_mode.c) */
    CHECK_EQ_INT(fsglRenderMode(c, GL_SELECT), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_OPERATION);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_SELECT);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0);
    fsglGetIntegerv(c, GL_RENDER_MODE, &v);
    CHECK_EQ_INT(v, GL_RENDER);
    /* glScissors(0) returns to the scissor box as the only tile */
    fsglScissors(c, 0, NULL);
    fsglGetIntegerv(c, GL_OCCLUSION_TILE_COUNT, &v);
    CHECK_EQ_INT(v, 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

/* The GL 1.5 query commands: each step's error and value against OSMesa. */
TEST(query_errors_vs_osmesa)
{
    char err[256];
    fs_osmesa *o = fs_osmesa_create(W, H, 24, 8, err, sizeof err);
    if (!o)
        SKIP("no OSMesa context");
    fs_context *c = new_ctx(1, 32);
    REQUIRE(c);
    tgt tm = {c}, tr = {NULL};
    tgt *ts[2] = {&tm, &tr};
    GLuint res[2][32];
    GLenum errs[2][32];
    for (int k = 0; k < 2; k++) {
        tgt *t = ts[k];
        int n = 0;
        GLuint ids[4] = {0}, more[2] = {0}, u = 12345;
        GLint iv = 12345;
#define STEP(val) do { res[k][n] = (GLuint)(val); errs[k][n] = G0(t, GetError); n++; } while (0)
        G(t, GenQueries, -1, ids);                     STEP(0);
        G(t, GenQueries, 3, ids);                      STEP(ids[0] * 100 + ids[2]);
        STEP(G(t, IsQuery, ids[0]));
        G(t, BeginQuery, GL_TEXTURE_2D, ids[0]);       STEP(0);
        G(t, BeginQuery, GL_SAMPLES_PASSED, 0);        STEP(0);
        G(t, BeginQuery, GL_SAMPLES_PASSED, ids[0]);   STEP(0);
        G(t, BeginQuery, GL_SAMPLES_PASSED, ids[1]);   STEP(0);
        G(t, GetQueryObjectuiv, ids[0], GL_QUERY_RESULT, &u); STEP(u);
        G(t, GetQueryiv, GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &iv); STEP(iv);
        G(t, GetQueryiv, GL_TEXTURE_2D, GL_CURRENT_QUERY, &iv); STEP(0);
        G(t, GetQueryiv, GL_SAMPLES_PASSED, GL_TEXTURE_2D, &iv); STEP(0);
        G(t, EndQuery, GL_TEXTURE_2D);                 STEP(0);
        G(t, EndQuery, GL_SAMPLES_PASSED);             STEP(0);
        G(t, EndQuery, GL_SAMPLES_PASSED);             STEP(0);
        G(t, GetQueryObjectuiv, ids[0], GL_QUERY_RESULT, &u); STEP(u);
        G(t, GetQueryObjectuiv, ids[0], GL_QUERY_RESULT_AVAILABLE, &u); STEP(u);
        G(t, GetQueryObjectiv, ids[0], GL_TEXTURE_2D, &iv); STEP(0);
        G(t, GetQueryObjectiv, ids[1], GL_QUERY_RESULT, &iv); STEP(0);
        G(t, GetQueryObjectiv, 999, GL_QUERY_RESULT, &iv); STEP(0);
        STEP(G(t, IsQuery, ids[0]));
        STEP(G(t, IsQuery, ids[1]));
        STEP(G(t, IsQuery, 0));
        G(t, BeginQuery, GL_SAMPLES_PASSED, 10);       STEP(0);
        G(t, EndQuery, GL_SAMPLES_PASSED);             STEP(0);
        STEP(G(t, IsQuery, 10));
        G(t, GenQueries, 2, more);                     STEP(more[0] * 100 + more[1]);
        G(t, DeleteQueries, -1, ids);                  STEP(0);
        G(t, BeginQuery, GL_SAMPLES_PASSED, ids[2]);   STEP(0);
        G(t, DeleteQueries, 3, ids);                   STEP(0);
        G(t, GetQueryiv, GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &iv); STEP(iv);
        STEP(G(t, IsQuery, ids[0]));
        G(t, GenQueries, 1, more);                     STEP(more[0]);
#undef STEP
        CHECK_EQ_INT(n, 32);
    }
    for (int i = 0; i < 32; i++) {
        if (res[0][i] != res[1][i] || errs[0][i] != errs[1][i])
            fprintf(stderr, "  step %d: fragsim %u/0x%x, OSMesa %u/0x%x\n", i, res[0][i], errs[0][i], res[1][i],
                    errs[1][i]);
        CHECK_EQ_UINT(res[0][i], res[1][i]);
        CHECK_EQ_UINT(errs[0][i], errs[1][i]);
    }
    fs_context_destroy(c);
    fs_osmesa_destroy(o);
}

/* -------------------------------------------- counters on random scenes */

/* Tiles: the whole window, four quadrants and random rectangles. */
static int make_tiles(uint64_t *s, GLint *tiles)
{
    int n = 0;
    GLint fixed[5][4] = {{0, 0, W, H}, {0, 0, W / 2, H / 2}, {W / 2, 0, W / 2, H / 2},
                         {0, H / 2, W / 2, H / 2}, {W / 2, H / 2, W / 2, H / 2}};
    for (int i = 0; i < 5; i++, n++)
        memcpy(tiles + 4 * n, fixed[i], sizeof fixed[i]);
    for (int i = 0; i < 4; i++, n++) {
        GLint x = (GLint)(rng_next(s) % W) - 8, y = (GLint)(rng_next(s) % H) - 8;
        GLint w = (GLint)(rng_next(s) % 64), h = (GLint)(rng_next(s) % 64);
        GLint r[4] = {x, y, w, h};
        memcpy(tiles + 4 * n, r, sizeof r);
    }
    return n;
}

static int inside(const GLint *r, int x, int y)
{
    return x >= r[0] && x < (int64_t)r[0] + r[2] && y >= r[1] && y < (int64_t)r[1] + r[3];
}

enum { NT = 9, BUF = 2 * W * H + 16 };

typedef struct totals { long queries, nohc_sum, phc_sum, tiles_checked, hits_listed; } totals;

/* One seed: scene + query boxes.  Checks everything the header lists. */
static void check_seed(check_state *check_st_, uint64_t seed, fs_osmesa *o, totals *tot)
{
    fs_context *c = new_ctx(1, 32), *c2 = new_ctx(2, 32), *c5 = new_ctx(5, 32);
    fs_context *cref = new_ctx(1, 32), *calone = new_ctx(1, 32);
    REQUIRE(c && c2 && c5 && cref && calone);
    fs_context *occ[3] = {c, c2, c5};
    float angle = (float)(seed * 37 % 360);
    tgt tr = {NULL};
    setup_view(&tr, angle);
    draw_scene(&tr, seed, 12);
    for (int k = 0; k < 3; k++) {
        tgt tm = {occ[k]};
        setup_view(&tm, angle);
        draw_scene(&tm, seed, 12);
    }
    tgt tref = {cref};
    setup_view(&tref, angle);
    draw_scene(&tref, seed, 12);
    /* the scene itself equals OSMesa's (sanity: same geometry) */
    const uint8_t *ocol = fs_osmesa_color(o);
    long cdiff = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++)
        cdiff += ocol[i] != c->fb.color[i];
    CHECK_EQ_INT(cdiff, 0);

    uint64_t s = seed ^ 0x5151;
    GLint tiles[NT * 4];
    int nt = make_tiles(&s, tiles);
    GLuint *buf[3][NT];
    GLsizei sizes[NT];
    for (int k = 0; k < 3; k++)
        for (int t = 0; t < nt; t++)
            buf[k][t] = malloc(BUF * sizeof(GLuint));
    for (int t = 0; t < nt; t++)
        sizes[t] = BUF;
    for (int k = 0; k < 3; k++) {
        fsglScissors(occ[k], nt, tiles);
        fsglOcclusionBuffers(occ[k], sizes, buf[k]);
    }
    GLuint qm, qo;
    fsglGenQueries(c, 1, &qm);
    glGenQueries(1, &qo);
    for (int b = 0; b < 6; b++) {
        float lo[3], hi[3];
        random_box(&s, lo, hi, -1.0f, 1.0f);
        int verbose = b & 1;
        /* OSMesa and fragsim's GL 1.5 query, with writes masked as
         * occlusion-query programs do */
        tgt tm = {c};
        tgt *qt[2] = {&tr, &tm};
        for (int k = 0; k < 2; k++) {
            G(qt[k], ColorMask, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            G(qt[k], DepthMask, GL_FALSE);
            G(qt[k], BeginQuery, GL_SAMPLES_PASSED, k ? qm : qo);
            draw_box(qt[k], lo, hi);
            G(qt[k], EndQuery, GL_SAMPLES_PASSED);
            G(qt[k], ColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            G(qt[k], DepthMask, GL_TRUE);
        }
        GLuint osm_samples = 0, fs_samples = 0;
        glGetQueryObjectuiv(qo, GL_QUERY_RESULT, &osm_samples);
        fsglGetQueryObjectuiv(c, qm, GL_QUERY_RESULT, &fs_samples);
        CHECK_EQ_UINT(fs_samples, osm_samples);
        /* the occlusion pass on three engine counts */
        for (int k = 0; k < 3; k++) {
            tgt t = {occ[k]};
            uint64_t before = fb_hash(occ[k]);
            G(&t, RenderMode, verbose ? GL_VERBOSE_OCCLUSION : GL_BRIEF_OCCLUSION);
            draw_box(&t, lo, hi);
            GLint ret = G(&t, RenderMode, GL_RENDER);
            CHECK_EQ_INT(ret, 0);
            CHECK_EQ_UINT(fb_hash(occ[k]), before);
            CHECK_EQ_INT(fsglGetError(occ[k]), GL_NO_ERROR);
        }
        CHECK_EQ_UINT(buf[0][0][0], osm_samples); /* tile 0 is the window */
        /* brute force: draw the box normally over the scene and alone */
        size_t n = (size_t)W * H;
        uint32_t *z0 = malloc(n * sizeof *z0);
        REQUIRE(z0);
        memcpy(z0, cref->fb.depth, n * sizeof *z0);
        G(&tref, Color3f, 1.0f, 0.0f, 1.0f);
        draw_box(&tref, lo, hi);
        tgt ta = {calone};
        setup_view(&ta, angle);
        G(&ta, Color3f, 1.0f, 1.0f, 1.0f);
        draw_box(&ta, lo, hi);
        for (int t = 0; t < nt; t++) {
            const GLint *r = tiles + 4 * t;
            uint32_t nohc = 0, phc = 0, xmin = UINT32_MAX, xmax = 0, ymin = UINT32_MAX, ymax = 0,
                     zmin = UINT32_MAX, zmax = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    if (!inside(r, x, y))
                        continue;
                    size_t i = (size_t)y * W + (size_t)x;
                    phc += calone->fb.color[i * 4] == 255;
                    if (cref->fb.depth[i] != z0[i]) { /* LESS passed: depth changed */
                        uint32_t z = cref->fb.depth[i];
                        nohc++;
                        if ((uint32_t)x < xmin) xmin = (uint32_t)x;
                        if ((uint32_t)x > xmax) xmax = (uint32_t)x;
                        if ((uint32_t)y < ymin) ymin = (uint32_t)y;
                        if ((uint32_t)y > ymax) ymax = (uint32_t)y;
                        if (z < zmin) zmin = z;
                        if (z > zmax) zmax = z;
                    }
                }
            const GLuint *rec = buf[0][t];
            GLuint want[8] = {nohc, phc, xmin, xmax, ymin, ymax, zmin, zmax};
            for (int w = 0; w < 8; w++)
                CHECK_EQ_UINT(rec[w], want[w]);
            tot->nohc_sum += nohc;
            tot->phc_sum += phc;
            tot->tiles_checked++;
            if (verbose) {
                /* the list is the recounted set, each pixel once, then -1 */
                uint32_t k = 0;
                for (; rec[8 + 2 * k] != 0xFFFFFFFFu && k < nohc + 1; k++) {
                    uint32_t x = rec[8 + 2 * k], y = rec[9 + 2 * k];
                    size_t i = (size_t)y * W + x;
                    CHECK(x < W && y < H && inside(r, (int)x, (int)y) && cref->fb.depth[i] != z0[i]);
                }
                CHECK_EQ_UINT(k, nohc);
                tot->hits_listed += k;
            }
            /* identical records whatever the engine count */
            size_t words = 8 + (verbose ? 2 * (size_t)nohc + 1 : 0);
            CHECK(memcmp(buf[0][t], buf[1][t], words * sizeof(GLuint)) == 0);
            CHECK(memcmp(buf[0][t], buf[2][t], words * sizeof(GLuint)) == 0);
        }
        /* restore the reference's depth for the next box */
        memcpy(cref->fb.depth, z0, n * sizeof *z0);
        fsglClear(calone, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        free(z0);
        tot->queries++;
    }
    /* round robin: 9 tiles on 5 engines own 2,2,2,2,1 */
    const fs_occu *u = fs_occlusion_unit(c5);
    int own[5] = {2, 2, 2, 2, 1};
    for (int e = 0; e < 5; e++)
        CHECK_EQ_INT(u->engines[e].ntiles, own[e]);
    for (int k = 0; k < 3; k++) {
        for (int t = 0; t < nt; t++)
            free(buf[k][t]);
        fs_context_destroy(occ[k]);
    }
    fs_context_destroy(cref);
    fs_context_destroy(calone);
}

TEST(random_boxes_counters_vs_recount_and_osmesa)
{
    char err[256];
    fs_osmesa *o = fs_osmesa_create(W, H, 24, 8, err, sizeof err);
    if (!o)
        SKIP("no OSMesa context");
    totals tot = {0};
    for (uint64_t seed = 1; seed <= 8; seed++)
        check_seed(check_st_, seed, o, &tot);
    printf("  %ld query boxes, %ld tiles: sum NOHC %ld, sum PHC %ld, %ld hits listed; all equal to the recount\n",
           tot.queries, tot.tiles_checked, tot.nohc_sum, tot.phc_sum, tot.hits_listed);
    CHECK(tot.nohc_sum > 1000 && tot.phc_sum > tot.nohc_sum);
    fs_osmesa_destroy(o);
}

/* -------------------------------------------------- overflow behaviour */

TEST(saturation_overflow_and_terminator)
{
    fs_context *c = new_ctx(2, 4); /* counters saturate at 15 */
    REQUIRE(c);
    tgt t = {c};
    setup_view(&t, 0.0f);
    GLint tiles[12] = {0, 0, W, H, 60, 60, 2, 2, 0, 0, 1, 1};
    GLuint b[3][64];
    GLuint *bufs[3] = {b[0], b[1], b[2]};
    GLsizei sizes[3] = {12, 64, 9};
    fsglScissors(c, 3, tiles);
    fsglOcclusionBuffers(c, sizes, bufs);
    memset(b, 0xCD, sizeof b);
    float lo[3] = {-0.3f, -0.3f, 0.0f}, hi[3] = {0.3f, 0.3f, 0.2f};
    fsglRenderMode(c, GL_VERBOSE_OCCLUSION);
    draw_box(&t, lo, hi);
    /* tile 0 saturates and its list (1 hit) overflows; tile 1 (4 pixels)
     * fits; tile 2 sees nothing */
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 1);
    CHECK_EQ_UINT(b[0][0], 15);
    CHECK_EQ_UINT(b[0][1], 15);
    CHECK(b[0][8] < W && b[0][9] < H);
    CHECK_EQ_UINT(b[0][10], 0xFFFFFFFFu);
    CHECK_EQ_UINT(b[0][11], 0xCDCDCDCDu);
    CHECK_EQ_UINT(b[1][0], 4);
    CHECK_EQ_UINT(b[1][1], 4);
    CHECK_EQ_UINT(b[1][2], 60);
    CHECK_EQ_UINT(b[1][3], 61);
    CHECK_EQ_UINT(b[1][16], 0xFFFFFFFFu);
    CHECK_EQ_UINT(b[2][0], 0);
    CHECK_EQ_UINT(b[2][8], 0xFFFFFFFFu);
    CHECK(c->occlusion_hook == NULL && !c->frag.suppress_writes);
    /* brief: only the saturated tile overflows; the list is not written */
    memset(b, 0xCD, sizeof b);
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    draw_box(&t, lo, hi);
    CHECK_EQ_INT(fsglRenderMode(c, GL_VERBOSE_OCCLUSION), 1); /* switching modes returns too */
    CHECK_EQ_UINT(b[0][0], 15);
    CHECK_EQ_UINT(b[0][8], 0xCDCDCDCDu);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0); /* nothing drawn in the verbose pass */
    CHECK_EQ_UINT(b[1][0], 0);
    CHECK(c->stats.occlusion_overflows == 2);
    fs_context_destroy(c);
}

/* The framebuffer (colour, depth, stencil) does not change in an
 * occlusion mode, whatever the state: clears, stencil ops, blending. */
TEST(framebuffer_unchanged)
{
    fs_context *c = new_ctx(1, 32);
    REQUIRE(c);
    tgt t = {c};
    setup_view(&t, 30.0f);
    draw_scene(&t, 99, 10);
    uint64_t h = fb_hash(c), written = c->stats.fragments_written;
    GLuint b[8];
    GLuint *bufs[1] = {b};
    GLsizei size = 8;
    fsglOcclusionBuffers(c, &size, bufs);
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    fsglEnable(c, GL_STENCIL_TEST);
    fsglStencilOp(c, GL_INCR, GL_INCR, GL_INCR);
    draw_scene(&t, 7, 10);
    fsglDisable(c, GL_STENCIL_TEST);
    fsglEnable(c, GL_BLEND);
    fsglBlendFunc(c, GL_ONE, GL_ONE);
    draw_scene(&t, 8, 10);
    fsglDisable(c, GL_DEPTH_TEST);
    draw_scene(&t, 9, 10);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    CHECK_EQ_UINT(c->stats.fragments_written, written);
    fsglRenderMode(c, GL_RENDER);
    CHECK_EQ_UINT(fb_hash(c), h);
    CHECK(b[0] > 0 && b[0] < b[1]); /* tests ran against the unchanged depth buffer */
    /* and rendering works again afterwards */
    fsglClear(c, GL_COLOR_BUFFER_BIT);
    CHECK(fb_hash(c) != h);
    fs_context_destroy(c);
}

/* ---------------------------------------------- the dissertation's examples */

/* Fig. 3.14: a quadtree of occlusion tiles t0..t12 -- the window t0, its
 * quadrants t1..t4, and the quadrants of t1 and t4 (t5..t8, t9..t12).  One
 * brief pass answers the whole hierarchy: every parent's NOHC is the sum of
 * its children's, and an occluder in the upper left hides exactly those
 * tiles. */
TEST(example_quadtree_13_tiles)
{
    fs_context *c = new_ctx(4, 32);
    REQUIRE(c);
    tgt t = {c};
    G(&t, Viewport, 0, 0, W, H);
    G(&t, MatrixMode, GL_PROJECTION);
    G0(&t, LoadIdentity);
    G(&t, Ortho, 0.0, W, 0.0, H, -10.0, 10.0);
    G(&t, MatrixMode, GL_MODELVIEW);
    G0(&t, LoadIdentity);
    G(&t, Enable, GL_DEPTH_TEST);
    G(&t, Enable, GL_CULL_FACE);
    G(&t, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    /* occluder: the upper-left quadrant t3, in front */
    float olo[3] = {0, H / 2, 5}, ohi[3] = {W / 2, H, 6};
    draw_box(&t, olo, ohi);
    GLint tiles[13 * 4];
    const int h = W / 2, q = W / 4;
    GLint quads[4][2] = {{0, 0}, {h, 0}, {0, h}, {h, h}};
    GLint spec[13][4] = {{0, 0, W, H}};
    for (int i = 0; i < 4; i++) {
        GLint r[4] = {quads[i][0], quads[i][1], h, h};
        memcpy(spec[1 + i], r, sizeof r);
        GLint base = i == 0 ? 5 : i == 3 ? 9 : -1;
        if (base < 0)
            continue;
        for (int j = 0; j < 4; j++) {
            GLint s[4] = {quads[i][0] + (j & 1) * q, quads[i][1] + (j >> 1) * q, q, q};
            memcpy(spec[base + j], s, sizeof s);
        }
    }
    memcpy(tiles, spec, sizeof spec);
    GLuint b[13][8];
    GLuint *bufs[13];
    GLsizei sizes[13];
    for (int i = 0; i < 13; i++) {
        bufs[i] = b[i];
        sizes[i] = 8;
    }
    fsglScissors(c, 13, tiles);
    fsglOcclusionBuffers(c, sizes, bufs);
    /* the tested object: a box covering the whole window, behind the occluder */
    float lo[3] = {0, 0, 0}, hi[3] = {W, H, 1};
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    draw_box(&t, lo, hi);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 0);
    CHECK_EQ_UINT(b[0][1], W * H);
    CHECK_EQ_UINT(b[0][0], W * H - h * h);
    CHECK_EQ_UINT(b[3][0], 0);                      /* t3 hidden */
    CHECK_EQ_UINT(b[1][0] + b[2][0] + b[3][0] + b[4][0], b[0][0]);
    CHECK_EQ_UINT(b[5][0] + b[6][0] + b[7][0] + b[8][0], b[1][0]);
    CHECK_EQ_UINT(b[9][0] + b[10][0] + b[11][0] + b[12][0], b[4][0]);
    CHECK_EQ_UINT(b[4][0], h * h);
    CHECK_EQ_UINT(b[0][2], 0);
    CHECK_EQ_UINT(b[0][3], W - 1);
    CHECK_EQ_UINT(b[0][5], H - 1);
    const fs_occu *u = fs_occlusion_unit(c);
    CHECK_EQ_INT(u->engines[0].ntiles, 4); /* t0, t4, t8, t12 */
    CHECK_EQ_INT(u->engines[3].ntiles, 3);
    fs_context_destroy(c);
}

/* 3.3.2, Fig. 3.20: collision detection.  The screen is split into 3x3
 * heading tiles; a customised view volume from the near plane to one step
 * ahead is rendered in GL_BRIEF_OCCLUSION with back-face culling off.  A
 * tile whose NOHC differs from its PHC has an obstacle within a step. */
TEST(example_collision_detection)
{
    fs_context *c = new_ctx(3, 32);
    REQUIRE(c);
    tgt t = {c};
    G(&t, Viewport, 0, 0, W, H);
    G(&t, MatrixMode, GL_PROJECTION);
    G0(&t, LoadIdentity);
    G(&t, Frustum, -1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    G(&t, MatrixMode, GL_MODELVIEW);
    G0(&t, LoadIdentity);
    G(&t, Enable, GL_DEPTH_TEST);
    G(&t, Enable, GL_CULL_FACE);
    G(&t, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    /* a pillar 3 units ahead, to the right (only in the right column), and
     * a wall 50 units ahead everywhere */
    float plo[3] = {1.5f, -0.5f, -3.5f}, phi[3] = {2.5f, 0.5f, -3.0f};
    draw_box(&t, plo, phi);
    float wlo[3] = {-60, -60, -51}, whi[3] = {60, 60, -50};
    draw_box(&t, wlo, whi);
    GLint tiles[9 * 4];
    for (int i = 0; i < 9; i++) {
        GLint r[4] = {(i % 3) * W / 3, (i / 3) * H / 3, i % 3 == 2 ? W - 2 * (W / 3) : W / 3,
                      i / 3 == 2 ? H - 2 * (H / 3) : H / 3};
        memcpy(tiles + 4 * i, r, sizeof r);
    }
    GLuint b[9][8];
    GLuint *bufs[9];
    GLsizei sizes[9];
    for (int i = 0; i < 9; i++) {
        bufs[i] = b[i];
        sizes[i] = 8;
    }
    fsglScissors(c, 9, tiles);
    fsglOcclusionBuffers(c, sizes, bufs);
    /* the step volume: near plane (z = -1) to 5 units ahead, filling the
     * frustum; culling off so its far side is tested too */
    G(&t, Disable, GL_CULL_FACE);
    float step = 5.0f;
    float vlo[3] = {-step * 1.01f, -step * 1.01f, -step}, vhi[3] = {step * 1.01f, step * 1.01f, -1.001f};
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    draw_box(&t, vlo, vhi);
    fsglRenderMode(c, GL_RENDER);
    int collide[9];
    for (int i = 0; i < 9; i++)
        collide[i] = b[i][0] != b[i][1];
    /* the pillar projects to x in [1.5/3.5, 2.5/3] of the half-width: the
     * right column's middle row only */
    printf("  collision tiles (row-major from the bottom left):");
    for (int i = 0; i < 9; i++)
        printf(" %d", collide[i]);
    printf("\n");
    for (int i = 0; i < 9; i++)
        CHECK_EQ_INT(collide[i], i == 5);
    /* and a step shorter than the distance to the pillar collides nowhere */
    step = 2.5f;
    vlo[2] = -step;
    fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    draw_box(&t, vlo, vhi);
    fsglRenderMode(c, GL_RENDER);
    for (int i = 0; i < 9; i++)
        CHECK_EQ_UINT(b[i][0], b[i][1]);
    fs_context_destroy(c);
}

/* glOcclusionBuffers' pointer array as data from a trace holds no
 * addresses of this process: the records stay in the unit instead of being
 * written through them at glRenderMode (found by tests/fuzz/fuzz_gl.c). */
TEST(occlusion_buffers_from_trace_data_are_not_written)
{
    fs_context *c = new_ctx(1, 32);
    REQUIRE(c);
    GLint tile[4] = {0, 0, W, H};
    fsglScissors(c, 1, tile);
    GLint sizes[1] = {16};
    unsigned char junk[8];
    memset(junk, 0x41, sizeof junk); /* the pointer 0x4141414141414141 */
    fs_call call = {0};
    call.cmd = FS_CMD_OcclusionBuffers;
    call.nargs = 2;
    call.a[0].p = sizes;
    call.a[0].count = 1;
    call.a[1].p = junk;
    call.a[1].count = sizeof junk;
    call.a[1].is_data = 1;
    CHECK_EQ_INT(fs_submit(c, &call), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglRenderMode(c, GL_VERBOSE_OCCLUSION);
    fsglBegin(c, GL_TRIANGLES);
    fsglVertex2f(c, -1, -1);
    fsglVertex2f(c, 1, -1);
    fsglVertex2f(c, 0, 1);
    fsglEnd(c);
    CHECK_EQ_INT(fsglRenderMode(c, GL_RENDER), 1); /* one tile's record, kept by the unit */
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

/* A replayed glGenQueries(1.6e9, ...) has no output buffer: the dispatcher
 * must not allocate its 6.4 GB of scratch output first (found by
 * tests/fuzz/fuzz_gl.c as an out-of-memory) but raise GL_OUT_OF_MEMORY. */
TEST(gen_queries_from_trace_huge_count_allocates_nothing)
{
    fs_context *c = new_ctx(1, 32);
    REQUIRE(c);
    fs_call call = {0};
    call.cmd = FS_CMD_GenQueriesARB;
    call.nargs = 2;
    call.a[0].i = 1600000000;
    call.a[1].out = NULL;
    CHECK_EQ_INT(fs_submit(c, &call), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    CHECK(c->scratch_size < ((size_t)1 << 30));
    fs_context_destroy(c);
}

/* The dispatcher gives a pointer argument's trace data a meaning for the
 * client-array pointer calls (copied into the context) and drops it for
 * glOcclusionBuffers (above) and glInterleavedArrays (counted unsupported).  A new command with a pointer argument must
 * be added there too, or its trace data would be taken for addresses. */
TEST(every_pointer_argument_has_a_rule_for_trace_data)
{
    for (int cmd = 0; cmd < FS_CMD_COUNT; cmd++) {
        const fs_cmd_info *info = &fs_cmd_table[cmd];
        int pk, slot = fs_pointer_slot(cmd, &pk);
        for (int k = 0; k < info->nargs; k++) {
            if (info->kinds[k] != FS_K_CPTR)
                continue;
            bool ruled = (slot >= 0 && k == pk) || (cmd == FS_CMD_OcclusionBuffers && k == 1) ||
                         (cmd == FS_CMD_InterleavedArrays && k == 2);
            if (!ruled)
                fprintf(stderr, "  %s argument %d (%s): no rule for trace data\n", info->name, k,
                        info->argnames[k]);
            CHECK(ruled);
        }
    }
}

TEST_LIST = {
    TEST_ENTRY(errors_and_state),
    TEST_ENTRY(occlusion_buffers_from_trace_data_are_not_written),
    TEST_ENTRY(gen_queries_from_trace_huge_count_allocates_nothing),
    TEST_ENTRY(every_pointer_argument_has_a_rule_for_trace_data),
    TEST_ENTRY(query_errors_vs_osmesa),
    TEST_ENTRY(random_boxes_counters_vs_recount_and_osmesa),
    TEST_ENTRY(saturation_overflow_and_terminator),
    TEST_ENTRY(framebuffer_unchanged),
    TEST_ENTRY(example_quadtree_13_tiles),
    TEST_ENTRY(example_collision_detection),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
