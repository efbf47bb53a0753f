/*
 * The texture unit's part of threaded rasterization (pipeline/raster_threads.h):
 * what must happen before the fork, the per-thread copy of the unit's
 * counters and their sum at the join.
 *
 * Sampling reads texture objects only, with three exceptions, all handled
 * here: the completeness a texture object caches on first use (3.8.10,
 * fs_tex_complete), computed on the calling thread before the fork; the
 * unit's quad counters, counted per thread; and MP-Grid's current texture
 * register and the footprint filters' lazily made ROMs, whose draws stay
 * on one thread (fs_texture_par_safe).
 */
#include <string.h>
#include "texture_priv.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"

bool fs_texture_par_safe(fs_context *c)
{
    struct fs_texture_state *st = c->texture;
    if (!st || !c->raster.interpolate_tex)
        return true;
    FS_FOR_EACH_UNIT(u, c->raster.tex_mask) {
        int k = fs_tex_unit_target(&st->unit[u]);
        if (k < 0)
            continue;
        fs_tex_object *t = st->unit[u].bound[k];
        if (!t || t->mpgrid || t->min_filter == GL_FOOTPRINT_FRAGSIM || t->min_filter == GL_FOOTPRINT_HYBRID_FRAGSIM)
            return false;
        fs_tex_complete(t); /* caches t->complete before the threads read it */
    }
    return true;
}

size_t fs_texture_state_bytes(void) { return sizeof(struct fs_texture_state); }

void fs_texture_fork(const fs_context *c, struct fs_texture_state *dst)
{
    memcpy(dst, c->texture, sizeof *dst);
    dst->quads_sampled = dst->quads_incomplete = dst->quads_fast = 0;
}

void fs_texture_join(fs_context *c, const struct fs_texture_state *w)
{
    c->texture->quads_sampled += w->quads_sampled;
    c->texture->quads_incomplete += w->quads_incomplete;
    c->texture->quads_fast += w->quads_fast;
}
