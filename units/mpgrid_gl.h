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

/* Texel (x, y) of level `level` (texels across the whole grid) as RGBA8;
 * tmp receives it, the return value points to it. */
const uint8_t *fs_mpgrid_gl_texel(const struct fs_tex_object *t, int level, int x, int y, uint8_t tmp[4]);
/* Completeness of an MP-Grid texture object (docs/extensions/mp_grid.txt,
 * "Texture Completeness"); sets t->complete and t->last_level. */
bool fs_mpgrid_gl_complete(struct fs_tex_object *t);
/* Frees the object's MP-Grid (texture deletion). */
void fs_mpgrid_gl_release(struct fs_tex_object *t);
#endif
