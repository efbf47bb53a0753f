/* Points (GL 1.5 spec 3.3): placeholder until the llvmpipe point rules are modelled. */
#include "rasterizer_priv.h"

void fs_raster_point(fs_context *c, const fs_rvertex *v)
{
    (void)v;
    c->stats.points_rasterized++;
}
