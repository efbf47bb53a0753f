/*
 * Texture unit of a raster board: reads the texels of each covered pixel's
 * footprint (1 per level for NEAREST, 4 for LINEAR, two levels for the
 * MIPMAP_LINEAR filters: trilinear is 8) within the texel budget M per
 * cycle, through the texture cache (texture_cache.c: size, ways, line,
 * banks after Igehy, Eldridge, Proudfoot 1998).  Missed lines are read from
 * texture memory (its bandwidth and latency; O2 prefetches texels, which
 * hides the latency but not the bandwidth).
 *
 * The filtered values come from the functional texture unit; this file only
 * needs the texel addresses, taken from each pixel's s, t at the level the
 * unit chose.  Addresses are synthetic and deterministic: texture name,
 * level offset, row-major RGBA8 texels.
 */
#include <math.h>
#include <stdlib.h>
#include "cycle_internal.h"
#include "../units/texture_priv.h"

static bool pow2(long v) { return v > 0 && (v & (v - 1)) == 0; }

int fs_cyc_texture_init(fs_cycle *cy, char *err, size_t errlen)
{
    const fs_config *g = &cy->cfg;
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

static inline int wrap(int v, int size, GLenum mode)
{
    if (mode == GL_REPEAT)
        return v & (size - 1); /* sizes are powers of two (GL 1.5 spec 3.8.1) */
    return v < 0 ? 0 : v >= size ? size - 1 : v;
}

/* Appends the addresses of one pixel's footprint at one level. */
static unsigned footprint(const fs_tex_object *t, int level, bool linear, float s, float tt, uint64_t *a)
{
    uint64_t base = ((uint64_t)t->name + 1) << 36;
    for (int l = 0; l < level; l++)
        base += (uint64_t)t->level[l].width * (uint64_t)t->level[l].height * 4u;
    const fs_tex_image *img = &t->level[level];
    int w = img->width, h = img->height;
    if (w <= 0 || h <= 0)
        return 0;
    float fs = s * (float)w, ft = tt * (float)h;
    if (!(fabsf(fs) < 1e9f) || !(fabsf(ft) < 1e9f))
        fs = ft = 0.0f; /* NaN or huge coordinates: any texel, the cost is the same */
    if (!linear) {
        int x = wrap((int)floorf(fs), w, t->wrap_s), y = wrap((int)floorf(ft), h, t->wrap_t);
        a[0] = base + ((uint64_t)y * (uint64_t)w + (uint64_t)x) * 4u;
        return 1;
    }
    int x0 = (int)floorf(fs - 0.5f), y0 = (int)floorf(ft - 0.5f);
    int xs[2] = {wrap(x0, w, t->wrap_s), wrap(x0 + 1, w, t->wrap_s)};
    int ys[2] = {wrap(y0, h, t->wrap_t), wrap(y0 + 1, h, t->wrap_t)};
    for (int k = 0; k < 4; k++)
        a[k] = base + ((uint64_t)ys[k >> 1] * (uint64_t)w + (uint64_t)xs[k & 1]) * 4u;
    return 4;
}

void fs_cycle_texture(fs_cycle *cy, const struct fs_tex_object *t, int level0, int level1, GLenum filter,
                      const fs_quad *q, const float s[4], const float tt[4])
{
    if (!cy->cfg.texture_present)
        return;
    bool linear = filter == GL_LINEAR;
    unsigned mask = q->mask;
    /* The texture unit of the board owning the quad's image engine. */
    int board = fs_cyc_route(cy, q->x, q->y) / (int)cy->cfg.fragment_image_engines;
    fs_tex_cache *cache = cy->cache ? cy->cache[board] : NULL;
    uint64_t texels = 0, service = 0, bytes = 0, misses = 0;
    uint64_t M = (uint64_t)cy->cfg.texture_texels_per_cycle;
    fs_tex_cache_stats before = {0}, after = {0};
    if (cache)
        fs_tex_cache_get_stats(cache, &before);
    for (int i = 0; i < 4; i++) {
        if (!(mask >> i & 1u))
            continue;
        uint64_t a[8];
        unsigned n = footprint(t, level0, linear, s[i], tt[i], a);
        if (level1 >= 0)
            n += footprint(t, level1, linear, s[i], tt[i], a + n);
        texels += n;
        service += (n + M - 1) / M;
        if (cache)
            (void)fs_tex_cache_access_group(cache, a, n);
        else
            bytes += 4u * n;
    }
    if (cache) {
        fs_tex_cache_get_stats(cache, &after);
        bytes = after.bytes_from_memory - before.bytes_from_memory;
        misses = after.misses - before.misses;
        service += after.bank_conflicts - before.bank_conflicts;
        cy->acc.tex_cache_accesses += after.accesses - before.accesses;
        cy->acc.tex_cache_hits += after.hits - before.hits;
        cy->acc.tex_bank_conflicts += after.bank_conflicts - before.bank_conflicts;
    } else {
        misses = texels;
    }
    cy->acc.tex_texels += texels;
    cy->acc.tex_bytes += bytes;
    /* Added up: the texture unit may sample a quad in two halves (quads at
     * odd rows, units/texture_sample.c). */
    cy->tex_pending = true;
    cy->tex_service += service;
    cy->tex_bytes += bytes;
    cy->tex_misses += misses;
}
