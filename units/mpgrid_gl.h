/*
 * GL_FRAGSIM_mp_grid's attachment to the texture unit (units/mpgrid_gl.c):
 * an fs_tex_object whose `mpgrid` field is set is an MP-Grid texture; its
 * level descriptors carry the virtual size n*tile x m*tile (>> level) and no
 * texels; the sampler (texture_sample.c) reads its texels through
 * fs_mpgrid_gl_texel, i.e. through the CTR and pointer table.
 */
#ifndef FS_MPGRID_GL_H
#define FS_MPGRID_GL_H
#include <stdbool.h>
#include <stdint.h>

struct fs_tex_object;

struct fs_mpgrid_tex;

/* What a quad's texel reads did to the CTR (Huettner 1999 4.1.4): reloads,
 * pointer thrashing, substitutions of a coarser resident level. */
typedef struct fs_mpgrid_work {
    uint64_t reloads, thrashing, substitutions;
} fs_mpgrid_work;

/* Texel (x, y) of level `level` (texels across the whole grid) as RGBA8
 * through g's CTR, which the read updates; tmp receives it, the return
 * value points to it, and w counts what the read did (the texture object
 * itself is not changed: the sampler reads it as const). */
const uint8_t *fs_mpgrid_gl_texel(struct fs_mpgrid_tex *g, fs_mpgrid_work *w, int level, int x, int y,
                                  uint8_t tmp[4]);
/* A quad's reads done: w into the context's statistics. */
void fs_mpgrid_gl_work_done(struct fs_mpgrid_tex *g, const fs_mpgrid_work *w);
/* Completeness of an MP-Grid texture object (docs/extensions/mp_grid.txt,
 * "Texture Completeness"); sets t->complete and t->last_level. */
bool fs_mpgrid_gl_complete(struct fs_tex_object *t);
/* Frees the object's MP-Grid (texture deletion). */
void fs_mpgrid_gl_release(struct fs_tex_object *t);
#endif
