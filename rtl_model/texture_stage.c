/*
 * Texture unit of a raster board: reads the texels of each covered pixel's
 * footprint (1 per level for NEAREST, 4 for LINEAR, two levels for the
 * MIPMAP_LINEAR filters: trilinear is 8) within the texel budget M per
 * cycle, through the texture cache (texture_cache.c: size, ways, line,
 * banks after Igehy, Eldridge, Proudfoot 1998).  Missed lines are read from
 * texture memory (its bandwidth and latency; O2 prefetches texels, which
 * hides the latency but not the bandwidth).
 *
 * The filtered values and the texels read come from the functional texture
 * unit: its record of each pixel's texels after wrapping and clamping
 * (units/texture_reads.h; a GL_CLAMP border texel is the border colour and
 * no memory read).  This file only lays them out in memory: synthetic,
 * deterministic addresses from texture name, level offset, row-major RGBA8
 * texels.
 *
 * The fast-footprint filter (units/footprint_filter.c) reports the texel
 * rectangles it read (its a x b arrays, or the 2x2 blocks of its bilinear
 * and trilinear classes) and its weighting-ROM lookups; the unit reads the
 * distinct texels after wrapping, M per cycle, and the ROM's pipelined
 * three-stage lookup (Huettner 1999, 4.3.5, Fig. 4.31) runs beside the
 * texel fetch: texture.rom_ports lookups per cycle, texture.rom_stage_latency
 * cycles more latency for a quad that used it.  MP-Grid CTR reloads
 * (4.1.4) cost texture.ctr_reload_cycles each (a pointer-table read).
 */
#include <math.h>
#include <stdlib.h>
#include "cycle_internal.h"
#include "../units/texture_filter.h"
#include "../units/texture_reads.h"

static bool pow2(long v) { return v > 0 && (v & (v - 1)) == 0; }

int fs_cyc_texture_init(fs_cycle *cy, char *err, size_t errlen)
{
    const fs_cycle_config *g = &cy->cfg;
    int n = cy->u[FS_U_texture].n;
    cy->cache = calloc((size_t)n, sizeof *cy->cache);
    if (!cy->cache) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    if (g->texture_cache_bytes == 0)
        return 0;
    if (!pow2(g->texture_cache_bytes) || !pow2(g->texture_cache_line_bytes) || !pow2(g->texture_cache_ways) ||
        !pow2(g->texture_cache_banks) || g->texture_cache_line_bytes > g->texture_cache_bytes ||
        g->texture_cache_ways > g->texture_cache_bytes / g->texture_cache_line_bytes) {
        snprintf(err, errlen, "texture.cache_bytes, cache_line_bytes, cache_ways, cache_banks: each a power of "
                              "two, a line no larger than the cache, no more ways than lines");
        return -1;
    }
    const fs_cyc_mem *m = cy->texmem;
    fs_tex_cache_config tc = {(unsigned)g->texture_cache_bytes, (unsigned)g->texture_cache_line_bytes,
                              (unsigned)g->texture_cache_ways, (unsigned)g->texture_cache_banks, m->latency,
                              (unsigned)(pow2((long)m->bw) ? m->bw : 1)};
    for (int i = 0; i < n; i++) {
        cy->cache[i] = fs_tex_cache_create(&tc);
        if (!cy->cache[i]) {
            snprintf(err, errlen, "texture cache: configuration rejected by the cache model");
            return -1;
        }
    }
    return 0;
}

void fs_cyc_texture_free(fs_cycle *cy)
{
    if (!cy->cache)
        return;
    for (int i = 0; i < cy->u[FS_U_texture].n; i++)
        fs_tex_cache_destroy(cy->cache[i]);
    free(cy->cache);
    cy->cache = NULL;
}

/* Synthetic address of texel (0, 0) of a level. */
static uint64_t level_base(const struct fs_tex_object *t, int level)
{
    uint64_t base = ((uint64_t)fs_tex_object_name(t) + 1) << 36;
    for (int l = 0; l < level; l++) {
        int w, h;
        (void)fs_tex_level_size(t, l, &w, &h);
        base += (uint64_t)w * (uint64_t)h * 4u;
    }
    return base;
}

/* After one quad's texel groups went through the cache (or straight to
 * memory when there is none): the bytes read from memory and the misses
 * since `before`, added to the run's counters; returns the bank-conflict
 * cycles the groups cost.  Without a cache every texel is a miss and
 * *bytes already holds the texels' bytes. */
static uint64_t cache_settle(fs_cycle *cy, fs_tex_cache *cache, const fs_tex_cache_stats *before,
                             uint64_t texels, uint64_t *bytes, uint64_t *misses)
{
    if (!cache) {
        *misses = texels;
        return 0;
    }
    fs_tex_cache_stats after;
    fs_tex_cache_get_stats(cache, &after);
    *bytes = after.bytes_from_memory - before->bytes_from_memory;
    *misses = after.misses - before->misses;
    cy->acc.tex_cache_accesses += after.accesses - before->accesses;
    cy->acc.tex_cache_hits += after.hits - before->hits;
    cy->acc.tex_bank_conflicts += after.bank_conflicts - before->bank_conflicts;
    return after.bank_conflicts - before->bank_conflicts;
}

void fs_cycle_texture(void *user, const struct fs_tex_object *t, const fs_quad *q, const fs_tex_reads *r)
{
    fs_cycle *cy = user;
    if (!cy->cfg.texture_present)
        return;
    /* The texture unit of the board owning the quad's image engine. */
    int board = fs_cyc_route(cy, q->x, q->y) / (int)cy->cfg.fragment_image_engines;
    cy->u[FS_U_texture].st[board].latency = (uint32_t)cy->cfg.texture_latency; /* no ROM stage */
    fs_tex_cache *cache = cy->cache ? cy->cache[board] : NULL;
    uint64_t texels = 0, service = 0, bytes = 0, misses = 0;
    uint64_t M = (uint64_t)cy->cfg.texture_texels_per_cycle;
    fs_tex_cache_stats before = {0};
    if (cache)
        fs_tex_cache_get_stats(cache, &before);
    uint64_t base[FS_TEX_MAX_LEVELS];
    int width[FS_TEX_MAX_LEVELS], height;
    int bases = 0; /* levels whose base and width are known */
    for (int i = 0; i < 4; i++) {
        unsigned n = r->n[i];
        if (!n)
            continue;
        uint64_t a[FS_TEX_READS_MAX];
        for (unsigned k = 0; k < n; k++) {
            const struct fs_tex_read *e = &r->texel[i][k];
            for (; bases <= e->level; bases++) {
                base[bases] = level_base(t, bases);
                (void)fs_tex_level_size(t, bases, &width[bases], &height);
            }
            a[k] = base[e->level] + ((uint64_t)e->y * (uint64_t)width[e->level] + (uint64_t)e->x) * 4u;
        }
        texels += n;
        service += (n + M - 1) / M;
        if (cache)
            (void)fs_tex_cache_access_group(cache, a, n);
        else
            bytes += 4u * n;
    }
    service += cache_settle(cy, cache, &before, texels, &bytes, &misses);
    cy->acc.tex_texels += texels;
    cy->acc.tex_bytes += bytes;
    /* Added up: the texture unit may sample a quad in two halves (quads at
     * odd rows, units/texture_sample.c). */
    cy->tex_pending = true;
    cy->tex_service += service;
    cy->tex_bytes += bytes;
    cy->tex_misses += misses;
}

unsigned fs_cyc_footprint_addresses(const struct fs_tex_object *t, const fs_filter_out *o, uint64_t *a,
                                    unsigned cap)
{
    unsigned n = 0;
    for (int r = 0; r < o->nrects && r < 2; r++) {
        const struct fs_filter_rect *rc = &o->rect[r];
        int w, h;
        if (rc->w <= 0 || rc->h <= 0 || !fs_tex_level_size(t, rc->level, &w, &h))
            continue;
        uint64_t base = level_base(t, rc->level);
        /* The texels the filter read: wrapped as the unit's filter view
         * wraps them. */
        for (int j = 0; j < rc->h; j++)
            for (int i = 0; i < rc->w && n < cap; i++) {
                int x = rc->x0 + i, y = rc->y0 + j;
                fs_tex_footprint_texel(t, rc->level, &x, &y);
                a[n++] = base + ((uint64_t)y * (uint64_t)w + (uint64_t)x) * 4u;
            }
    }
    /* Distinct addresses: a texel of two overlapping arrays, or one folded
     * onto another by wrapping, is read once.  Insertion sort: the rows come
     * nearly sorted. */
    for (unsigned i = 1; i < n; i++) {
        uint64_t v = a[i];
        unsigned k = i;
        for (; k > 0 && a[k - 1] > v; k--)
            a[k] = a[k - 1];
        a[k] = v;
    }
    unsigned m = 0;
    for (unsigned i = 0; i < n; i++)
        if (m == 0 || a[m - 1] != a[i])
            a[m++] = a[i];
    return m;
}

void fs_cycle_texture_footprint(void *user, const struct fs_tex_object *t, const fs_quad *q, const fs_filter_out *out)
{
    fs_cycle *cy = user;
    if (!cy->cfg.texture_present)
        return;
    int board = fs_cyc_route(cy, q->x, q->y) / (int)cy->cfg.fragment_image_engines;
    fs_tex_cache *cache = cy->cache ? cy->cache[board] : NULL;
    uint64_t M = (uint64_t)cy->cfg.texture_texels_per_cycle, ports = (uint64_t)cy->cfg.texture_rom_ports;
    uint64_t texels = 0, fetch = 0, bytes = 0, misses = 0, lookups = 0;
    fs_tex_cache_stats before = {0};
    if (cache)
        fs_tex_cache_get_stats(cache, &before);
    for (int i = 0; i < 4; i++) {
        if (!(q->mask >> i & 1u))
            continue;
        uint64_t a[FS_CYC_FP_MAX_TEXELS];
        unsigned n = fs_cyc_footprint_addresses(t, &out[i], a, FS_CYC_FP_MAX_TEXELS);
        texels += n;
        fetch += (n + M - 1) / M;
        lookups += out[i].rom_lookups > 0 ? (uint64_t)out[i].rom_lookups : 0;
        if (cache)
            (void)fs_tex_cache_access_group(cache, a, n);
        else
            bytes += 4u * n;
    }
    fetch += cache_settle(cy, cache, &before, texels, &bytes, &misses);
    /* The ROM lookup is a pipeline stage ahead of the texel array and the
     * evaluator (4.3.5): the quad occupies the unit for the longer of the
     * two, and the ROM's stages lengthen the pipeline when it is used. */
    uint64_t rom = (lookups + ports - 1) / ports;
    cy->u[FS_U_texture].st[board].latency =
        (uint32_t)(cy->cfg.texture_latency + (lookups ? cy->cfg.texture_rom_stage_latency : 0));
    cy->acc.tex_texels += texels;
    cy->acc.tex_bytes += bytes;
    cy->tex_pending = true;
    cy->tex_service += fetch > rom ? fetch : rom;
    cy->tex_bytes += bytes;
    cy->tex_misses += misses;
}

void fs_cycle_ctr_reloads(void *user, uint64_t n)
{
    fs_cycle *cy = user;
    if (!cy->cfg.texture_present || !n)
        return;
    /* Each reload reads one pointer-table entry before the texel can be
     * addressed (4.1.4): the texture unit waits for it. */
    cy->acc.ctr_reloads += n;
    cy->sig_ctr += n;
    cy->tex_pending = true;
    cy->tex_service += n * (uint64_t)cy->cfg.texture_ctr_reload_cycles;
}
