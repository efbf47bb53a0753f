/*
 * Fragment generators: one per raster board, `fragments_per_cycle`
 * fragments per cycle, and the framebuffer interleave that decides which
 * image engine (and so which board) owns a pixel.
 */
#include "cycle_internal.h"

uint64_t fs_cyc_raster_cycles(const fs_cycle_config *cfg, unsigned fragments)
{
    uint64_t r = (uint64_t)cfg->raster_fragments_per_cycle;
    return (fragments + r - 1) / r;
}

/* Squares of interleave x interleave pixels go to the image engines in a
 * diagonal pattern, so neither a row nor a column of squares lands on one
 * engine (InfiniteReality interleaves its image engines in 2D).  The
 * interleave is even, so a quad (even x, y) stays on one engine. */
int fs_cyc_route(const fs_cycle *cy, int x, int y)
{
    int n = cy->engines_total;
    if (n == 1)
        return 0;
    int il = (int)cy->cfg.fragment_interleave;
    unsigned ix = (unsigned)x / (unsigned)il, iy = (unsigned)y / (unsigned)il;
    return (int)((ix + iy) % (unsigned)n);
}
