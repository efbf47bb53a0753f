/*
 * Occlusion Engine (Huettner 1999, 3.3, Fig. 3.17): the per-tile registers
 * and their reset.  The per-fragment step is inline in occlusion_engine.h
 * because the unit runs it for every fragment and tile.
 */
#include "occlusion_engine.h"

void fs_occe_tile_reset(fs_occu_tile *t)
{
    t->nohc = t->phc = 0;
    t->nohc_overflow = t->phc_overflow = false;
    /* Min registers start at their largest value and max registers at zero,
     * so the first hit sets both (the comparators of Fig. 3.17). */
    t->xmin = t->ymin = t->zmin = UINT32_MAX;
    t->xmax = t->ymax = t->zmax = 0;
    t->list_count = 0;
    t->list_overflow = false;
}

unsigned fs_occe_fragment(fs_occu_engine *e, fs_occu_tile *tiles, int ntiles, int stride,
                          uint32_t cmax, int x, int y, uint32_t z, bool passed, int *hit_tiles,
                          uint64_t *projection_hits)
{
    unsigned nhits = 0;
    uint64_t ph = 0;
    e->fragments++;
    for (int t = e->index; t < ntiles; t += stride) {
        e->tile_tests++;
        if (fs_occe_tile_fragment(&tiles[t], cmax, x, y, z, passed, &ph))
            hit_tiles[nhits++] = t;
    }
    e->hits += nhits;
    e->projection_hits += ph;
    *projection_hits = ph;
    return nhits;
}
