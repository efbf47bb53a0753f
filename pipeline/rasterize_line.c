/* Line segments (GL 1.5 spec 3.4): placeholder until the llvmpipe line rules are modelled. */
#include "rasterizer_priv.h"

void fs_raster_line(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1)
{
    (void)v0;
    (void)v1;
    c->stats.lines_rasterized++;
}
