/*
 * MP-Grid layout, pointer table and current texture register (Huettner
 * 1999, 4.1.1 and 4.1.4; see mpgrid.h).
 */
#include <stdlib.h>
#include <string.h>
#include "mpgrid.h"

static bool is_pow2(int64_t x) { return x > 0 && (x & (x - 1)) == 0; }

static int log2i(int64_t x)
{
    int l = 0;
    while (x > 1) {
        x >>= 1;
        l++;
    }
    return l;
}

int fs_mpgrid_make_layout(int n, int m, int tile_w, int tile_h, fs_mpgrid_layout *out)
{
    if (n <= 0 || m <= 0 || n > FS_MPGRID_MAX_PYRAMIDS || m > FS_MPGRID_MAX_PYRAMIDS || !is_pow2(tile_w) ||
        !is_pow2(tile_h) || tile_w > FS_MPGRID_MAX_TILE || tile_h > FS_MPGRID_MAX_TILE)
        return -1;
    out->tile_w = tile_w;
    out->tile_h = tile_h;
    out->n = n;
    out->m = m;
    /* All pyramids share one level count (4.1.4): down to 1x1. */
    out->levels = log2i(tile_w > tile_h ? tile_w : tile_h) + 1;
    out->scaled_w = (int64_t)n * tile_w;
    out->scaled_h = (int64_t)m * tile_h;
    return 0;
}

int fs_mpgrid_choose_layout(int64_t img_w, int64_t img_h, int min_tile, int max_tile, fs_mpgrid_layout *out)
{
    if (img_w <= 0 || img_h <= 0 || !is_pow2(min_tile) || !is_pow2(max_tile) || min_tile > max_tile ||
        max_tile > FS_MPGRID_MAX_TILE)
        return -1;
    /* 4.1.1: "the biggest tile size possible that increases the image size
     * in the scaling phase in a minimal way" -- sides chosen independently,
     * so 1024x512 beats 1024x1024 when it scales less. */
    bool found = false;
    fs_mpgrid_layout best = {0};
    int64_t best_area = 0; /* <= (4096 * 4096)^2: fits */
    for (int tw = max_tile; tw >= min_tile; tw /= 2)
        for (int th = max_tile; th >= min_tile; th /= 2) {
            int64_t n = (img_w + tw - 1) / tw, m = (img_h + th - 1) / th;
            fs_mpgrid_layout L;
            if (n > FS_MPGRID_MAX_PYRAMIDS || m > FS_MPGRID_MAX_PYRAMIDS ||
                fs_mpgrid_make_layout((int)n, (int)m, tw, th, &L) < 0)
                continue;
            int64_t area = L.scaled_w * L.scaled_h;
            int64_t tile = (int64_t)tw * th, btile = (int64_t)best.tile_w * best.tile_h;
            if (!found || area < best_area || (area == best_area && tile > btile) ||
                (area == best_area && tile == btile && tw > best.tile_w)) {
                best = L;
                best_area = area;
                found = true;
            }
        }
    if (!found)
        return -1;
    *out = best;
    return 0;
}

int fs_mpgrid_level_w(const fs_mpgrid_layout *L, int level)
{
    int w = L->tile_w >> level;
    return w > 1 ? w : 1;
}

int fs_mpgrid_level_h(const fs_mpgrid_layout *L, int level)
{
    int h = L->tile_h >> level;
    return h > 1 ? h : 1;
}

uint64_t fs_mpgrid_pyramid_bytes(const fs_mpgrid_layout *L, int first, int bytes_per_texel)
{
    uint64_t b = 0;
    for (int l = first < 0 ? 0 : first; l < L->levels; l++)
        b += (uint64_t)fs_mpgrid_level_w(L, l) * (uint64_t)fs_mpgrid_level_h(L, l) * (uint64_t)bytes_per_texel;
    return b;
}

uint64_t fs_mpgrid_table_bytes(int levels, int64_t n, int64_t m, int pointer_bytes, int extension_bytes)
{
    /* 4.1.4: levels * n * m entries of (pointer + extension size). */
    if (levels <= 0 || n <= 0 || m <= 0 || pointer_bytes < 0 || extension_bytes < 0)
        return 0;
    return (uint64_t)levels * (uint64_t)n * (uint64_t)m * (uint64_t)(pointer_bytes + extension_bytes);
}

/* ---- the grid ---- */

static size_t idx(const fs_mpgrid *g, int level, int i, int j)
{
    return ((size_t)level * (size_t)g->L.m + (size_t)j) * (size_t)g->L.n + (size_t)i;
}

bool fs_mpgrid_level_merged(const fs_mpgrid *g, int level)
{
    int w = fs_mpgrid_level_w(&g->L, level), h = fs_mpgrid_level_h(&g->L, level);
    return g->merge_side > 0 && (w > h ? w : h) <= g->merge_side;
}

int fs_mpgrid_init(fs_mpgrid *g, const fs_mpgrid_layout *L, int bytes_per_texel, int merge_side, int merge_block)
{
    memset(g, 0, sizeof *g);
    fs_mpgrid_layout chk;
    if (!L || fs_mpgrid_make_layout(L->n, L->m, L->tile_w, L->tile_h, &chk) < 0 || bytes_per_texel <= 0 ||
        bytes_per_texel > 16 || merge_side < 0 || merge_block < 0 || merge_block > FS_MPGRID_MAX_PYRAMIDS ||
        (merge_side > 0 && merge_block < 1))
        return -1;
    g->L = chk;
    g->bytes_per_texel = bytes_per_texel;
    g->merge_side = merge_side;
    g->merge_block = merge_side > 0 ? merge_block : 1;
    size_t cnt = (size_t)chk.levels * (size_t)chk.n * (size_t)chk.m;
    g->src = calloc(cnt, sizeof *g->src);
    g->table = calloc(cnt, sizeof *g->table);
    g->finest = malloc((size_t)chk.n * (size_t)chk.m * sizeof *g->finest);
    if (!g->src || !g->table || !g->finest) {
        fs_mpgrid_free(g);
        return -1;
    }
    for (int l = 0; l < chk.levels; l++) {
        int B = fs_mpgrid_level_merged(g, l) ? g->merge_block : 1;
        for (int j = 0; j < chk.m; j++)
            for (int i = 0; i < chk.n; i++) {
                fs_mpgrid_entry *e = &g->table[idx(g, l, i, j)];
                e->i0 = i / B * B;
                e->j0 = j / B * B;
                e->ext_i = e->i0 + B <= chk.n ? B : chk.n - e->i0;
                e->ext_j = e->j0 + B <= chk.m ? B : chk.m - e->j0;
                e->pitch = e->ext_i * fs_mpgrid_level_w(&chk, l);
            }
    }
    for (int p = 0; p < chk.n * chk.m; p++)
        g->finest[p] = chk.levels;
    return 0;
}

void fs_mpgrid_free(fs_mpgrid *g)
{
    if (g->table && g->src) {
        size_t cnt = (size_t)g->L.levels * (size_t)g->L.n * (size_t)g->L.m;
        for (size_t k = 0; k < cnt; k++) {
            fs_mpgrid_entry *e = &g->table[k];
            int i = (int)(k % (size_t)g->L.n), j = (int)(k / (size_t)g->L.n % (size_t)g->L.m);
            /* A merged block's store belongs to its first pyramid's entry. */
            if (e->texels && i == e->i0 && j == e->j0)
                free(e->texels);
            free(g->src[k]);
        }
    }
    free(g->src);
    free(g->table);
    free(g->finest);
    memset(g, 0, sizeof *g);
}

const fs_mpgrid_entry *fs_mpgrid_entry_at(const fs_mpgrid *g, int level, int i, int j)
{
    if (level < 0 || level >= g->L.levels || i < 0 || j < 0 || i >= g->L.n || j >= g->L.m)
        return NULL;
    return &g->table[idx(g, level, i, j)];
}

/* Copies pyramid (i, j)'s source image of a level into its place in the
 * entry's store. */
static void copy_in(fs_mpgrid *g, int level, int i, int j)
{
    fs_mpgrid_entry *e = &g->table[idx(g, level, i, j)];
    const uint8_t *s = g->src[idx(g, level, i, j)];
    int lw = fs_mpgrid_level_w(&g->L, level), lh = fs_mpgrid_level_h(&g->L, level);
    for (int y = 0; y < lh; y++)
        memcpy(e->texels + (((size_t)(j - e->j0) * lh + y) * (size_t)e->pitch + (size_t)(i - e->i0) * lw) * 4,
               s + (size_t)y * lw * 4, (size_t)lw * 4);
}

static uint64_t level_bytes(const fs_mpgrid *g, int level)
{
    return (uint64_t)fs_mpgrid_level_w(&g->L, level) * (uint64_t)fs_mpgrid_level_h(&g->L, level) *
           (uint64_t)g->bytes_per_texel;
}

int fs_mpgrid_set_image(fs_mpgrid *g, int i, int j, int level, const uint8_t *rgba)
{
    if (!rgba || !fs_mpgrid_entry_at(g, level, i, j))
        return -1;
    int lw = fs_mpgrid_level_w(&g->L, level), lh = fs_mpgrid_level_h(&g->L, level);
    size_t k = idx(g, level, i, j);
    size_t bytes = (size_t)lw * lh * 4;
    bool first = g->src[k] == NULL;
    if (first) {
        g->src[k] = malloc(bytes);
        if (!g->src[k])
            return -1;
    }
    memcpy(g->src[k], rgba, bytes);
    fs_mpgrid_entry *e = &g->table[k];
    if (fs_mpgrid_level_merged(g, level)) {
        /* Merged low levels are resident from the moment they exist: one
         * block per merge_block^2 pyramids, shared by their entries. */
        if (!e->texels) {
            uint8_t *blk = calloc((size_t)e->ext_i * lw * (size_t)e->ext_j * lh, 4);
            if (!blk) {
                if (first) {
                    free(g->src[k]);
                    g->src[k] = NULL;
                }
                return -1;
            }
            for (int jj = e->j0; jj < e->j0 + e->ext_j; jj++)
                for (int ii = e->i0; ii < e->i0 + e->ext_i; ii++)
                    g->table[idx(g, level, ii, jj)].texels = blk;
        }
        if (first) {
            g->bytes_resident += level_bytes(g, level);
            g->levels_loaded++;
        }
        copy_in(g, level, i, j);
    } else if (e->texels) {
        copy_in(g, level, i, j);
    }
    return 0;
}

int fs_mpgrid_set_finest(fs_mpgrid *g, int i, int j, int finest)
{
    if (!fs_mpgrid_entry_at(g, 0, i, j))
        return -1;
    finest = finest < 0 ? 0 : finest > g->L.levels ? g->L.levels : finest;
    int lowest_loaded = g->L.levels;
    for (int l = 0; l < g->L.levels; l++) {
        if (fs_mpgrid_level_merged(g, l))
            continue;
        size_t k = idx(g, l, i, j);
        fs_mpgrid_entry *e = &g->table[k];
        if (l >= finest && !e->texels && g->src[k]) {
            e->texels = malloc((size_t)fs_mpgrid_level_w(&g->L, l) * (size_t)fs_mpgrid_level_h(&g->L, l) * 4);
            if (!e->texels)
                return -1;
            copy_in(g, l, i, j);
            g->bytes_resident += level_bytes(g, l);
            g->levels_loaded++;
        } else if (l < finest && e->texels) {
            free(e->texels);
            e->texels = NULL;
            g->bytes_resident -= level_bytes(g, l);
            g->levels_freed++;
        }
        if (e->texels && l < lowest_loaded)
            lowest_loaded = l;
    }
    g->finest[j * g->L.n + i] = lowest_loaded;
    return 0;
}

/* ---- the CTR ---- */

void fs_mpgrid_ctr_reset(fs_mpgrid_ctr *r)
{
    memset(r, 0, sizeof *r);
    for (int l = 0; l < FS_MPGRID_MAX_LEVELS; l++)
        r->lv[l].prev_i = r->lv[l].prev_j = -1;
}

/* The CTR's pointer for (level, i, j): reloaded when (i, j) leaves the
 * comparators' extent (4.1.4). */
static const fs_mpgrid_entry *ctr_entry(const fs_mpgrid *g, fs_mpgrid_ctr *r, int level, int i, int j)
{
    struct fs_mpgrid_ctr_level *c = &r->lv[level];
    /* Inside the comparators' extent the register's pointer is used as it
     * is: for a merged block it addresses every pyramid of the block. */
    if (c->valid && i >= c->i0 && i < c->i0 + c->ext_i && j >= c->j0 && j < c->j0 + c->ext_j)
        return c->entry;
    const fs_mpgrid_entry *e = &g->table[idx(g, level, i, j)];
    r->reloads++;
    if (c->valid && c->prev_i == e->i0 && c->prev_j == e->j0)
        r->thrashing++;
    c->prev_i = c->valid ? c->i0 : -1;
    c->prev_j = c->valid ? c->j0 : -1;
    c->valid = true;
    c->i = i;
    c->j = j;
    c->i0 = e->i0;
    c->j0 = e->j0;
    c->ext_i = e->ext_i;
    c->ext_j = e->ext_j;
    c->entry = e;
    return e;
}

int fs_mpgrid_fetch(const fs_mpgrid *g, fs_mpgrid_ctr *r, int level, int64_t x, int64_t y, uint8_t out[4])
{
    memset(out, 0, 4);
    if (!g->table)
        return -1;
    level = level < 0 ? 0 : level >= g->L.levels ? g->L.levels - 1 : level;
    int lw = fs_mpgrid_level_w(&g->L, level), lh = fs_mpgrid_level_h(&g->L, level);
    int64_t W = (int64_t)g->L.n * lw, H = (int64_t)g->L.m * lh;
    x = x < 0 ? 0 : x >= W ? W - 1 : x;
    y = y < 0 ? 0 : y >= H ? H - 1 : y;
    /* The truncated coordinate selects the pyramid. */
    int i = (int)(x / lw), j = (int)(y / lh);
    int xl = (int)(x - (int64_t)i * lw), yl = (int)(y - (int64_t)j * lh);
    for (int l = level; l < g->L.levels; l++) {
        const fs_mpgrid_entry *e = ctr_entry(g, r, l, i, j);
        if (e->texels) {
            if (l != level)
                r->substitutions++;
            int cw = fs_mpgrid_level_w(&g->L, l), ch = fs_mpgrid_level_h(&g->L, l);
            memcpy(out,
                   e->texels + (((size_t)(j - e->j0) * ch + yl) * (size_t)e->pitch + (size_t)(i - e->i0) * cw + xl) * 4,
                   4);
            return l;
        }
        /* The best resident level is the next coarser one that exists:
         * the texel covering (xl, yl) there. */
        if (l + 1 < g->L.levels) {
            if (fs_mpgrid_level_w(&g->L, l + 1) < fs_mpgrid_level_w(&g->L, l))
                xl >>= 1;
            if (fs_mpgrid_level_h(&g->L, l + 1) < fs_mpgrid_level_h(&g->L, l))
                yl >>= 1;
        }
    }
    r->misses++;
    return -1;
}
