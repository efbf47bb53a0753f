/*
 * The cycle model's texture unit for the proposed texture hardware
 * (rtl_model/texture_stage.c, docs/cycle_model.md):
 *  - fast-footprint filter: the texels the unit reads for a pixel are the
 *    filter's reported rectangles, counted here by brute force (every
 *    texel wrapped with % and clamps, distinct (level, x, y) triples by
 *    pairwise comparison); never more than the filter's own texel count,
 *    and equal to it when the rectangles lie inside their levels;
 *  - the weighting ROM's stages add exactly texture.rom_stage_latency to
 *    one quad in an empty pipeline, and with one port the unit is busy one
 *    cycle per ROM lookup (the functional counter tex_fp_rom_lookups);
 *  - MP-Grid: CTR reloads on a scan of single pixels equal a brute-force
 *    count of pyramid changes along the scan, and cost texture.ctr_reload_cycles
 *    each of texture unit time;
 *  - cycle mode renders a footprint-filtered plane bit-identically to
 *    functional mode, with the same functional counters.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../driver/run_config.h"
#include "../driver/gl_call.h"
#include "../rtl_model/cycle_internal.h"
#include "../units/footprint.h"
#include "../units/texture_priv.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"
#include "../glext/GL_FRAGSIM_mp_grid.h"

static uint32_t rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static double unit(uint32_t *s) { return (double)rng(s) / 16777216.0; }

/* Uploads a w x h RGBA texture with every level down to 1x1 (random
 * texels; the values do not matter for the addresses). */
static void upload_mipmaps(fs_context *c, int w, int h, uint32_t seed)
{
    fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
    uint8_t *p = malloc((size_t)w * (size_t)h * 4);
    for (int l = 0, lw = w, lh = h;; l++) {
        for (size_t k = 0; p && k < (size_t)lw * (size_t)lh * 4; k++)
            p[k] = (uint8_t)rng(&seed);
        fsglTexImage2D(c, GL_TEXTURE_2D, l, GL_RGBA, lw, lh, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
        if (lw == 1 && lh == 1)
            break;
        lw = lw > 1 ? lw / 2 : 1;
        lh = lh > 1 ? lh / 2 : 1;
    }
    free(p);
}

static int wrap_ref(int v, int n, GLenum mode)
{
    if (mode == GL_REPEAT)
        return ((v % n) + n) % n;
    return v < 0 ? 0 : v > n - 1 ? n - 1 : v;
}

/* Distinct texels of o's rectangles after wrapping, by brute force. */
static int brute_texels(const fs_tex_object *t, const fs_filter_out *o, bool *inside)
{
    static int tri[3 * 512];
    int n = 0;
    *inside = true;
    GLenum ws = t->wrap_s == GL_REPEAT ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    GLenum wt = t->wrap_t == GL_REPEAT ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    for (int r = 0; r < o->nrects; r++) {
        const struct fs_filter_rect *rc = &o->rect[r];
        int W = t->level[rc->level].width, H = t->level[rc->level].height;
        if (rc->x0 < 0 || rc->y0 < 0 || rc->x0 + rc->w > W || rc->y0 + rc->h > H)
            *inside = false;
        for (int j = 0; j < rc->h; j++)
            for (int i = 0; i < rc->w; i++) {
                int L = rc->level, x = wrap_ref(rc->x0 + i, W, ws), y = wrap_ref(rc->y0 + j, H, wt);
                bool seen = false;
                for (int k = 0; k < n && !seen; k++)
                    seen = tri[3 * k] == L && tri[3 * k + 1] == x && tri[3 * k + 2] == y;
                if (!seen && n < 512) {
                    tri[3 * n] = L;
                    tri[3 * n + 1] = x;
                    tri[3 * n + 2] = y;
                    n++;
                }
            }
    }
    return n;
}

/* A context with texture 5 bound: a w x h MIPmapped texture with the
 * min filter and wrap modes given; NULL when it cannot be made. */
static fs_context *texture_5(int w, int h, uint32_t seed, GLenum min, GLenum wrap_s, GLenum wrap_t)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    if (!c)
        return NULL;
    fsglBindTexture(c, GL_TEXTURE_2D, 5);
    upload_mipmaps(c, w, h, seed);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap_s);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap_t);
    if (fsglGetError(c) != GL_NO_ERROR || !fs_tex_complete(fs_tex_bound_2d(c))) {
        fs_context_destroy(c);
        return NULL;
    }
    return c;
}

TEST(footprint_texels_brute_force)
{
    /* A non-square texture, REPEAT in s and CLAMP_TO_EDGE in t. */
    fs_context *c = texture_5(128, 32, 11, GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, GL_CLAMP_TO_EDGE);
    REQUIRE(c);
    fs_tex_object *t = fs_tex_bound_2d(c);
    fs_mip_view mv;
    memset(&mv, 0, sizeof mv);
    mv.levels = t->last_level + 1;
    for (int l = 0; l < mv.levels; l++) {
        mv.width[l] = t->level[l].width;
        mv.height[l] = t->level[l].height;
        mv.texels[l] = t->level[l].texels;
    }
    mv.wrap_s = GL_REPEAT;
    mv.wrap_t = GL_CLAMP_TO_EDGE;
    static const int Ms[4] = {8, 16, 32, 64};
    uint32_t seed = 7;
    long cases = 0, equal_inside = 0, classes[4] = {0, 0, 0, 0};
    for (int mi = 0; mi < 4; mi++)
        for (int hybrid = 0; hybrid < 2; hybrid++) {
            fs_footprint_filter *f = fs_footprint_filter_create(Ms[mi], false, hybrid);
            REQUIRE(f);
            for (int k = 0; k < 400; k++) {
                fs_footprint fp;
                memset(&fp, 0, sizeof fp);
                /* Half the centres in the middle of the texture, half
                 * anywhere (wrapped and clamped); magnified to long. */
                double spread = k & 1 ? 3.0 : 0.5, off = k & 1 ? -1.0 : 0.25;
                fp.u = (unit(&seed) * spread + off) * 128.0;
                fp.v = (unit(&seed) * spread + off) * 32.0;
                double len = exp(unit(&seed) * 6.0 - 2.0), ratio = 1.0 + unit(&seed) * 15.0;
                double a = unit(&seed) * 6.283;
                if (k % 5 == 0)
                    ratio = 1.0; /* isotropic: the hybrid MIPmaps */
                fp.dudx = len * cos(a);
                fp.dvdx = len * sin(a);
                fp.dudy = -len / ratio * sin(a);
                fp.dvdy = len / ratio * cos(a);
                fs_footprint_affine_corners(&fp);
                fs_filter_out o;
                int lookups = 0;
                fs_footprint_filter_run(f, &mv, &fp, &o, &lookups);
                CHECK(o.nrects >= 1 && o.nrects <= 2);
                CHECK_EQ_INT(o.rom_lookups, lookups);
                uint64_t a_hook[FS_CYC_FP_MAX_TEXELS];
                unsigned n = fs_cyc_footprint_addresses(t, &o, a_hook, FS_CYC_FP_MAX_TEXELS);
                bool inside;
                int brute = brute_texels(t, &o, &inside);
                CHECK_EQ_INT((int)n, brute);
                CHECK((int)n <= o.texels);
                if (inside) {
                    CHECK_EQ_INT((int)n, o.texels);
                    equal_inside++;
                }
                classes[o.cls]++;
                cases++;
            }
            fs_footprint_filter_destroy(f);
        }
    /* The sample reaches every kind of rectangle set the filter reports. */
    CHECK(equal_inside > cases / 4);
    CHECK(classes[FS_FP_CLASS_TRILINEAR] > 0 && classes[FS_FP_CLASS_FOOTPRINT] > 0 &&
          classes[FS_FP_CLASS_FOOTPRINT_2M] > 0 && classes[FS_FP_CLASS_BILINEAR0] > 0);
    fs_context_destroy(c);
}

/* ---- one footprint-filtered quad through the pipeline ---- */

#define WN 64
static float ndc(int px) { return 2.0f * (float)px / (float)WN - 1.0f; }

/* Min and mag filter, wrap in s and t, and GL_TEXTURE_2D enabled. */
static void filter_wrap_enable(fs_context *c, GLenum filter, GLenum wrap)
{
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
    fsglEnable(c, GL_TEXTURE_2D);
}

static fs_context *cycle_context(const fs_run_config *cfg, fs_cycle **cy)
{
    fs_context *c = fs_context_create(&cfg->gl, WN, WN);
    if (!c)
        return NULL;
    char err[256];
    *cy = fs_cycle_create(&cfg->cycle, FS_CYCLE_FULL, err, sizeof err);
    if (!*cy) {
        fprintf(stderr, "%s\n", err);
        fs_context_destroy(c);
        return NULL;
    }
    fs_cycle_attach(*cy, c);
    fsglViewport(c, 0, 0, WN, WN);
    return c;
}

/* One 2x2 quad, strongly anisotropic (16 x 1 texels per pixel), footprint
 * filter with budget 16; returns the cycle totals and the ROM lookups.
 * One triangle that covers exactly the pixel centres (8.5 | 9.5, 8.5 |
 * 9.5): base y = 8 from x = 7.35 to 10.65, apex (9, 10.3); at y = 8.5 it
 * spans [7.71, 10.29], at y = 9.5 [8.43, 9.57]. */
static void one_footprint_quad(const fs_run_config *cfg, fs_cycle_stats *s, uint64_t *lookups)
{
    fs_cycle *cy;
    fs_context *c = cycle_context(cfg, &cy);
    if (!c)
        return;
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    upload_mipmaps(c, 64, 64, 3);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_FOOTPRINT_FRAGSIM);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, 16);
    fsglEnable(c, GL_TEXTURE_2D);
    static const float v[3][2] = {{7.35f, 8.0f}, {10.65f, 8.0f}, {9.0f, 10.3f}};
    fsglBegin(c, GL_TRIANGLES);
    for (int k = 0; k < 3; k++) {
        fsglTexCoord2f(c, v[k][0] * 0.25f, v[k][1] / 64.0f);
        fsglVertex2f(c, 2.0f * v[k][0] / WN - 1.0f, 2.0f * v[k][1] / WN - 1.0f);
    }
    fsglEnd(c);
    fs_cycle_totals(cy, s);
    *lookups = c->stats.tex_fp_rom_lookups;
    fs_cycle_destroy(cy);
    fs_context_destroy(c);
}

TEST(rom_stage_latency_closed_form)
{
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    cfg.cycle.texture_texels_per_cycle = 64; /* a pixel's array in one cycle */
    cfg.cycle.texture_cache_bytes = 0;       /* no bank conflicts */
    cfg.cycle.texture_rom_ports = 1;
    cfg.cycle.texture_rom_stage_latency = 0;
    fs_cycle_stats base, s;
    uint64_t lookups = 0, l2 = 0;
    one_footprint_quad(&cfg, &base, &lookups);
    CHECK_EQ_UINT(base.quads, 1);
    /* Every pixel made at least one lookup, so with one port the ROM (not
     * the 4 one-cycle texel fetches) sets the unit's busy time. */
    CHECK(lookups > 4);
    CHECK_EQ_UINT(base.texture_busy, lookups);
    static const long lat[] = {1, 3, 17, 250};
    for (size_t i = 0; i < sizeof lat / sizeof lat[0]; i++) {
        cfg.cycle.texture_rom_stage_latency = lat[i];
        one_footprint_quad(&cfg, &s, &l2);
        CHECK_EQ_UINT(l2, lookups);
        CHECK_EQ_UINT(s.cycles, base.cycles + (uint64_t)lat[i]);
        CHECK_EQ_UINT(s.texture_busy, base.texture_busy);
    }
    /* Two ports: half the cycles, rounded up. */
    cfg.cycle.texture_rom_stage_latency = 0;
    cfg.cycle.texture_rom_ports = 2;
    one_footprint_quad(&cfg, &s, &l2);
    CHECK_EQ_UINT(s.texture_busy, (lookups + 1) / 2 > 4 ? (lookups + 1) / 2 : 4);
}

/* ---- MP-Grid CTR reloads ---- */

/* The scan: rows of pixels, left to right or back. */
static const int scan_rows[][3] = {{10, 0, 64}, {40, 63, -1}, {20, 30, 41}, {50, 10, 21}, {33, 63, 20}, {2, 0, 64}};
#define NROWS ((int)(sizeof scan_rows / sizeof scan_rows[0]))

TEST(ctr_reload_cycles_brute_force)
{
    /* A 2 x 2 grid of 32 x 32 pyramids over the 64 x 64 window, texel (x,
     * y) at pixel (x, y), NEAREST, one point per pixel in scan order.  The
     * CTR reloads whenever a fetch's pyramid differs from the one it holds
     * (Huettner 1999, 4.1.4; level 0 only here). */
    int ci = -1, cj = -1;
    uint64_t brute = 0;
    for (int r = 0; r < NROWS; r++) {
        int y = scan_rows[r][0], step = scan_rows[r][2] > scan_rows[r][1] ? 1 : -1;
        for (int x = scan_rows[r][1]; x != scan_rows[r][2]; x += step) {
            int i = x / 32, j = y / 32;
            if (i != ci || j != cj)
                brute++;
            ci = i;
            cj = j;
        }
    }
    uint64_t busy[2] = {0, 0};
    static const long cost[2] = {0, 9};
    for (int run = 0; run < 2; run++) {
        fs_run_config cfg;
        fs_run_config_defaults(&cfg);
        cfg.cycle.texture_ctr_reload_cycles = cost[run];
        fs_cycle *cy;
        fs_context *c = cycle_context(&cfg, &cy);
        REQUIRE(c);
        fsglPixelStorei(c, GL_UNPACK_ALIGNMENT, 1);
        fsglBindTexture(c, GL_TEXTURE_2D, 2);
        fsglMPGridTexture(c, GL_TEXTURE_2D, 2, 2, 32, 32, GL_RGBA);
        uint8_t *img = calloc(32 * 32 * 4, 1);
        REQUIRE(img);
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 2; i++)
                for (int l = 0, sz = 32; sz >= 1; l++, sz /= 2)
                    fsglMPGridImage(c, GL_TEXTURE_2D, i, j, l, sz, sz, GL_RGBA, GL_UNSIGNED_BYTE, img);
        free(img);
        filter_wrap_enable(c, GL_NEAREST, GL_CLAMP_TO_EDGE);
        fsglBegin(c, GL_POINTS);
        for (int r = 0; r < NROWS; r++) {
            int y = scan_rows[r][0], step = scan_rows[r][2] > scan_rows[r][1] ? 1 : -1;
            for (int x = scan_rows[r][1]; x != scan_rows[r][2]; x += step) {
                fsglTexCoord2f(c, ((float)x + 0.5f) / WN, ((float)y + 0.5f) / WN);
                fsglVertex2f(c, (ndc(x) + ndc(x + 1)) / 2, (ndc(y) + ndc(y + 1)) / 2);
            }
        }
        fsglEnd(c);
        CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
        fs_cycle_stats s;
        fs_cycle_totals(cy, &s);
        CHECK(brute > (uint64_t)NROWS);
        CHECK_EQ_UINT(c->stats.mpgrid_ctr_reloads, brute);
        CHECK_EQ_UINT(s.ctr_reloads, brute);
        busy[run] = s.texture_busy;
        fs_cycle_destroy(cy);
        fs_context_destroy(c);
    }
    CHECK_EQ_UINT(busy[1] - busy[0], brute * (uint64_t)cost[1]);
}

/* ---- the texels the unit reads: GL_CLAMP's border ---- */

/* Texels read for a window-filling quad of a 4 x 4 GL_CLAMP texture,
 * GL_LINEAR, texture coordinates s = t from lo to hi (magnified). */
static uint64_t clamp_texels(float lo, float hi)
{
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    fs_cycle *cy;
    fs_context *c = cycle_context(&cfg, &cy);
    if (!c)
        return 0;
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    upload_mipmaps(c, 4, 4, 5);
    filter_wrap_enable(c, GL_LINEAR, GL_CLAMP);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, lo, lo);
    fsglVertex2f(c, -1, -1);
    fsglTexCoord2f(c, hi, lo);
    fsglVertex2f(c, 1, -1);
    fsglTexCoord2f(c, hi, hi);
    fsglVertex2f(c, 1, 1);
    fsglTexCoord2f(c, lo, hi);
    fsglVertex2f(c, -1, 1);
    fsglEnd(c);
    fs_cycle_stats s;
    fs_cycle_totals(cy, &s);
    uint64_t frags = c->stats.fragments_generated;
    fs_cycle_destroy(cy);
    fs_context_destroy(c);
    return frags == (uint64_t)WN * WN ? s.tex_texels : 0;
}

TEST(clamp_border_texels_not_read)
{
    /* GL 1.5 spec 3.8.7 and 3.8.8: GL_CLAMP clamps u = s * 4 to [0, 4]; the
     * LINEAR pair is i0 = floor(u - 1/2), i1 = i0 + 1, and a texel outside
     * [0, 4) is the border colour, not a texel of the image.  Below 0 (u
     * clamped to 0) and above 1 (u = 4) each axis has one image texel:
     * one texel read per fragment; inside (u in [1, 3]) four.  The cycle
     * model counted four everywhere: it clamped the border texels to the
     * edge and read them. */
    CHECK_EQ_UINT(clamp_texels(-2.0f, -1.0f), (uint64_t)WN * WN);
    CHECK_EQ_UINT(clamp_texels(2.0f, 3.0f), (uint64_t)WN * WN);
    CHECK_EQ_UINT(clamp_texels(0.25f, 0.75f), 4u * WN * WN);
}

/* ---- cycle mode against functional mode ---- */

static void plane(fs_context *c, GLenum filter, int M)
{
    fsglViewport(c, 0, 0, WN, WN);
    fsglClearColor(c, 0.2f, 0.3f, 0.4f, 1.0f);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fsglBindTexture(c, GL_TEXTURE_2D, 1);
    upload_mipmaps(c, 64, 64, 21);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, M);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    fsglTexParameteri(c, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    fsglEnable(c, GL_TEXTURE_2D);
    fsglEnable(c, GL_DEPTH_TEST);
    fsglMatrixMode(c, GL_PROJECTION);
    fsglLoadIdentity(c);
    fsglFrustum(c, -1, 1, -1, 1, 1, 100);
    fsglMatrixMode(c, GL_MODELVIEW);
    fsglLoadIdentity(c);
    fsglTranslatef(c, 0, -1, -2);
    fsglRotatef(c, -80.0f, 1, 0, 0);
    fsglRotatef(c, 25.0f, 0, 0, 1);
    fsglBegin(c, GL_QUADS);
    fsglTexCoord2f(c, 0, 0);
    fsglVertex3f(c, -4, -4, 0);
    fsglTexCoord2f(c, 6, 0);
    fsglVertex3f(c, 4, -4, 0);
    fsglTexCoord2f(c, 6, 6);
    fsglVertex3f(c, 4, 40, 0);
    fsglTexCoord2f(c, 0, 6);
    fsglVertex3f(c, -4, 40, 0);
    fsglEnd(c);
}

TEST(cycle_mode_bit_identical_footprint)
{
    static const GLenum filters[2] = {GL_FOOTPRINT_FRAGSIM, GL_FOOTPRINT_HYBRID_FRAGSIM};
    static const int Ms[3] = {8, 16, 32};
    for (int fi = 0; fi < 2; fi++)
        for (int mi = 0; mi < 3; mi++) {
            fs_run_config cfg;
            fs_run_config_defaults(&cfg);
            fs_context *a = fs_context_create(&cfg.gl, WN, WN);
            fs_cycle *cy;
            fs_context *b = cycle_context(&cfg, &cy);
            REQUIRE(a && b);
            plane(a, filters[fi], Ms[mi]);
            plane(b, filters[fi], Ms[mi]);
            CHECK_EQ_INT(fsglGetError(a), GL_NO_ERROR);
            CHECK_EQ_INT(fsglGetError(b), GL_NO_ERROR);
            CHECK(memcmp(a->fb.color, b->fb.color, (size_t)WN * WN * 4) == 0);
            CHECK(a->stats.tex_fp_footprint + a->stats.tex_fp_footprint_2m > 0);
            CHECK_EQ_UINT(a->stats.tex_fp_texels, b->stats.tex_fp_texels);
            CHECK_EQ_UINT(a->stats.tex_fp_rom_lookups, b->stats.tex_fp_rom_lookups);
            CHECK_EQ_UINT(a->stats.fragments_written, b->stats.fragments_written);
            fs_cycle_stats s;
            fs_cycle_totals(cy, &s);
            /* The unit read some texels, never more than the filter says. */
            CHECK(s.tex_texels > 0 && s.tex_texels <= b->stats.tex_fp_texels);
            fs_cycle_destroy(cy);
            fs_context_destroy(a);
            fs_context_destroy(b);
        }
}

/* The texture unit's answers for the cycle model's memory layout
 * (units/texture_unit.h): level sizes as glTexImage2D gave them, false
 * outside the complete chain, and the footprint filters' wrapping, against
 * wrap_ref (REPEAT modulo the size, everything else clamped to the edge). */
TEST(texture_layout_queries)
{
    fs_context *c = texture_5(16, 4, 3, GL_NEAREST_MIPMAP_NEAREST, GL_REPEAT, GL_CLAMP);
    REQUIRE(c);
    const fs_tex_object *t = fs_tex_bound_2d(c);
    CHECK_EQ_UINT(fs_tex_object_name(t), 5);
    static const int want[6][2] = {{16, 4}, {8, 2}, {4, 1}, {2, 1}, {1, 1}, {0, 0}};
    for (int l = 0; l < 6; l++) {
        int w = -1, h = -1;
        CHECK_EQ_INT(fs_tex_level_size(t, l, &w, &h), l < 5);
        CHECK_EQ_INT(w, want[l][0]);
        CHECK_EQ_INT(h, want[l][1]);
    }
    int w = -1, h = -1;
    CHECK(!fs_tex_level_size(t, -1, &w, &h) && w == 0 && h == 0);
    CHECK(!fs_tex_level_size(t, FS_TEX_MAX_LEVELS, &w, &h) && w == 0 && h == 0);
    for (int l = 0; l < 5; l++)
        for (int v = -20; v <= 20; v++) {
            int x = v, y = v;
            fs_tex_footprint_texel(t, l, &x, &y);
            CHECK_EQ_INT(x, wrap_ref(v, want[l][0], GL_REPEAT));
            CHECK_EQ_INT(y, wrap_ref(v, want[l][1], GL_CLAMP_TO_EDGE));
        }
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(footprint_texels_brute_force),
    TEST_ENTRY(texture_layout_queries),
    TEST_ENTRY(rom_stage_latency_closed_form),
    TEST_ENTRY(ctr_reload_cycles_brute_force),
    TEST_ENTRY(clamp_border_texels_not_read),
    TEST_ENTRY(cycle_mode_bit_identical_footprint),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
