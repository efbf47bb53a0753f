/*
 * The Occlusion Unit and OccU Control (Huettner 1999, 3.3 "The New
 * Occlusion Unit", Figs. 3.16-3.17).  Functional model: every fragment from
 * the depth test goes to every engine; engine e owns tiles e, e+E, ...
 * (round robin); each hit an engine reports goes through OccU Control,
 * which serialises the writes of the engines into the tiles' occlusion
 * buffers in a fixed order (pixel order within the quad, then engine
 * index, then the engine's tile order).  Since every tile has a buffer of
 * its own, each list holds its tile's hits in fragment arrival order
 * whatever the number of engines: results do not depend on the engine
 * count, only the work per engine does.
 */
#include <stdlib.h>
#include <string.h>
#include "occlusion_unit.h"

fs_occu *fs_occu_create(int engines, int counter_bits, int max_tiles)
{
    if (engines < 1 || engines > 4096 || counter_bits < 1 || counter_bits > 32 || max_tiles < 1 ||
        max_tiles > (1 << 20))
        return NULL;
    fs_occu *u = calloc(1, sizeof *u);
    if (!u)
        return NULL;
    u->nengines = engines;
    u->counter_max = counter_bits == 32 ? UINT32_MAX : (1u << counter_bits) - 1u;
    u->max_tiles = max_tiles;
    u->engines = calloc((size_t)engines, sizeof *u->engines);
    u->tiles = calloc((size_t)max_tiles, sizeof *u->tiles);
    u->hit_scratch = calloc((size_t)max_tiles, sizeof *u->hit_scratch);
    if (!u->engines || !u->tiles || !u->hit_scratch) {
        fs_occu_destroy(u);
        return NULL;
    }
    for (int e = 0; e < engines; e++)
        u->engines[e].index = e;
    for (int t = 0; t < max_tiles; t++)
        fs_occe_tile_reset(&u->tiles[t]);
    return u;
}

void fs_occu_destroy(fs_occu *u)
{
    if (!u)
        return;
    if (u->tiles)
        for (int t = 0; t < u->max_tiles; t++)
            free(u->tiles[t].list);
    free(u->tiles);
    free(u->engines);
    free(u->hit_scratch);
    free(u);
}

uint32_t fs_occu_list_capacity(size_t size)
{
    /* 8 words of brief record, then pairs, and one word kept for the -1
     * terminator (3.2.1: a full list still ends with -1). */
    if (size < 9)
        return 0;
    size_t k = (size - 9) / 2;
    return k > UINT32_MAX ? UINT32_MAX : (uint32_t)k;
}

int fs_occu_begin(fs_occu *u, int n, const GLint *rects, const uint32_t *list_capacity, bool verbose)
{
    if (n < 1 || n > u->max_tiles)
        return -1;
    u->ntiles = n;
    u->verbose = verbose;
    for (int t = 0; t < n; t++) {
        fs_occu_tile *tl = &u->tiles[t];
        const GLint *r = rects + 4 * t;
        /* 64-bit: x + width may exceed GLint for legal arguments. */
        tl->x0 = r[0];
        tl->y0 = r[1];
        tl->x1 = (int64_t)r[0] + r[2];
        tl->y1 = (int64_t)r[1] + r[3];
        tl->list_capacity = verbose && list_capacity ? list_capacity[t] : 0;
        fs_occe_tile_reset(tl);
    }
    for (int e = 0; e < u->nengines; e++) {
        int owned = 0;
        for (int t = e; t < n; t += u->nengines)
            owned++;
        u->engines[e].ntiles = owned;
    }
    return 0;
}

/* OccU Control: one hit-list write of engine e for tile t.  Lists grow on
 * demand so that a huge buffer size costs nothing until hits arrive. */
static void control_write(fs_occu *u, int e, int t, int x, int y, fs_stats *stats)
{
    fs_occu_tile *tl = &u->tiles[t];
    uint32_t slot = tl->list_count;
    bool stored = slot < tl->list_capacity;
    if (stored && slot >= tl->list_alloc) {
        uint32_t want = tl->list_alloc ? tl->list_alloc * 2 : 64;
        if (want > tl->list_capacity)
            want = tl->list_capacity;
        uint32_t *p = realloc(tl->list, (size_t)want * 2 * sizeof *p);
        if (!p) {
            stored = false; /* out of memory: reported as an overflow */
        } else {
            tl->list = p;
            tl->list_alloc = want;
        }
    }
    if (stored) {
        tl->list[2 * slot] = (uint32_t)x;
        tl->list[2 * slot + 1] = (uint32_t)y;
        tl->list_count++;
        if (stats)
            stats->occlusion_hit_writes++;
    } else {
        tl->list_overflow = true;
    }
    if (u->hooks.control_write)
        u->hooks.control_write(u->hooks.user, e, t, x, y, slot, stored);
}

void fs_occu_quad(fs_occu *u, const fs_quad *q, unsigned tested, unsigned passed, fs_stats *stats)
{
    const int n = u->ntiles, ne = u->nengines;
    for (int i = 0; i < 4; i++) {
        if (!(tested >> i & 1u))
            continue;
        int x = q->x + (i & 1), y = q->y + (i >> 1);
        uint32_t z = q->z[i];
        bool pass = (passed >> i & 1u) != 0;
        for (int e = 0; e < ne; e++) {
            fs_occu_engine *eng = &u->engines[e];
            uint64_t ph;
            unsigned nh = fs_occe_fragment(eng, u->tiles, n, ne, u->counter_max, x, y, z, pass, u->hit_scratch, &ph);
            if (u->hooks.engine_fragment)
                u->hooks.engine_fragment(u->hooks.user, e, x, y, (unsigned)eng->ntiles, nh);
            if (u->verbose)
                for (unsigned h = 0; h < nh; h++)
                    control_write(u, e, u->hit_scratch[h], x, y, stats);
            if (stats) {
                stats->occlusion_hits += nh;
                stats->occlusion_projection_hits += ph;
            }
        }
        if (stats) {
            stats->occlusion_fragments++;
            stats->occlusion_tile_tests += (uint64_t)n;
        }
    }
}

bool fs_occu_tile_overflowed(const fs_occu *u, int t)
{
    const fs_occu_tile *tl = &u->tiles[t];
    return tl->nohc_overflow || tl->phc_overflow || tl->list_overflow;
}

size_t fs_occu_write_record(const fs_occu *u, int t, GLuint *buf, size_t size)
{
    const fs_occu_tile *tl = &u->tiles[t];
    if (size < 8)
        return 0;
    GLuint rec[8] = {tl->nohc, tl->phc, tl->xmin, tl->xmax, tl->ymin, tl->ymax, tl->zmin, tl->zmax};
    if (buf)
        memcpy(buf, rec, sizeof rec);
    size_t w = 8;
    if (!u->verbose)
        return w;
    /* list_count <= list_capacity = fs_occu_list_capacity(size), so the
     * pairs and the terminator fit. */
    uint32_t n = tl->list_count;
    if (buf && n)
        memcpy(buf + w, tl->list, (size_t)n * 2 * sizeof *buf);
    w += (size_t)n * 2;
    if (w < size) {
        if (buf)
            buf[w] = 0xFFFFFFFFu;
        w++;
    }
    return w;
}
