/*
 * Triangle setup: a fixed time per assembled triangle (edge and plane
 * equations), culled, clipped and rejected triangles included since setup
 * decides their fate.  With several raster boards every board's fragment
 * generator receives every triangle (InfiniteReality broadcasts them), so
 * one setup stage feeds them all.
 */
#include "cycle_internal.h"

uint64_t fs_cyc_setup_cycles(const fs_cycle_config *cfg)
{
    return (uint64_t)cfg->setup_cycles_per_triangle;
}
