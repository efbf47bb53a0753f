/*
 * Texture targets (GL 1.5 spec 3.8.1-3.8.2, 3.8.6, 3.8.11, 3.8.15): which target a
 * GL enum names (a cube map face too) and its image dimensions, the largest image of each, the
 * target a unit samples when several are enabled, and the 1D and 3D image
 * commands (glTexImage1D/3D, glTexSubImage1D/3D, glCopyTexImage1D,
 * glCopyTexSubImage1D/3D), which texture_object.c's image code of every
 * target executes.  1D images are stored as one row (height 1), 3D images
 * as depth slices of width x height texels (units/texture_priv.h).
 *
 * The MP-Grid (GL_FRAGSIM_mp_grid) and the footprint filters
 * (GL_FRAGSIM_footprint_filter) are 2D only: glTexParameter refuses the
 * footprint min filters for the 1D and 3D targets.
 */
#include "texture_priv.h"

bool fs_tex_target_of(GLenum target, fs_tex_target_info *ti)
{
    switch (target) {
    case GL_TEXTURE_1D: *ti = (fs_tex_target_info){FS_TEX_1D, false, 1, 0}; return true;
    case GL_TEXTURE_2D: *ti = (fs_tex_target_info){FS_TEX_2D, false, 2, 0}; return true;
    case GL_TEXTURE_3D: *ti = (fs_tex_target_info){FS_TEX_3D, false, 3, 0}; return true;
    case GL_TEXTURE_CUBE_MAP: *ti = (fs_tex_target_info){FS_TEX_CUBE, false, 2, 0}; return true;
    case GL_PROXY_TEXTURE_1D: *ti = (fs_tex_target_info){FS_TEX_1D, true, 1, 0}; return true;
    case GL_PROXY_TEXTURE_2D: *ti = (fs_tex_target_info){FS_TEX_2D, true, 2, 0}; return true;
    case GL_PROXY_TEXTURE_3D: *ti = (fs_tex_target_info){FS_TEX_3D, true, 3, 0}; return true;
    case GL_PROXY_TEXTURE_CUBE_MAP: *ti = (fs_tex_target_info){FS_TEX_CUBE, true, 2, 0}; return true;
    case GL_TEXTURE_RECTANGLE: *ti = (fs_tex_target_info){FS_TEX_RECT, false, 2, 0}; return true;
    case GL_PROXY_TEXTURE_RECTANGLE: *ti = (fs_tex_target_info){FS_TEX_RECT, true, 2, 0}; return true;
    default: return false;
    }
}

bool fs_tex_image_target_of(GLenum target, fs_tex_target_info *ti)
{
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target < GL_TEXTURE_CUBE_MAP_POSITIVE_X + FS_TEX_FACES) {
        *ti = (fs_tex_target_info){FS_TEX_CUBE, false, 2, (int)(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X)};
        return true;
    }
    return target != GL_TEXTURE_CUBE_MAP && fs_tex_target_of(target, ti);
}

/* GL_MAX_3D_TEXTURE_SIZE is 2048 on OSMesa (pipeline/state.def); 1D
 * images share GL_MAX_TEXTURE_SIZE with 2D ones (3.8.1). */
int fs_tex_target_max_log2(enum fs_tex_target k) { return k == FS_TEX_3D ? 11 : FS_TEX_MAX_LOG2; }

int fs_tex_target_dims(enum fs_tex_target k) { return k == FS_TEX_1D ? 1 : k == FS_TEX_3D ? 3 : 2; }

int fs_tex_unit_target(const fs_tex_unit *tu)
{
    /* 3.8.15: "If TEXTURE_CUBE_MAP is enabled, the cube map texture is
     * used; otherwise if TEXTURE_3D is enabled, the three-dimensional
     * texture is used; otherwise if TEXTURE_2D is enabled ...; otherwise if
     * TEXTURE_1D is enabled, the one-dimensional texture is used."
     * ARB_texture_rectangle puts TEXTURE_RECTANGLE between 3D and 2D. */
    static const enum fs_tex_target priority[] = {FS_TEX_CUBE, FS_TEX_3D, FS_TEX_RECT, FS_TEX_2D, FS_TEX_1D};
    for (int i = 0; i < (int)(sizeof priority / sizeof priority[0]); i++)
        if (tu->enabled[priority[i]])
            return (int)priority[i];
    return -1;
}

void fs_exec_TexImage1D(fs_context *c, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    fs_tex_image_nd(c, 1, target, level, internalformat, width, 1, 1, border, format, type, pixels);
}

void fs_exec_TexImage3D(fs_context *c, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                        const GLvoid *pixels)
{
    fs_tex_image_nd(c, 3, target, level, internalformat, width, height, depth, border, format, type, pixels);
}

void fs_exec_TexSubImage1D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                           GLenum type, const GLvoid *pixels)
{
    const GLint off[3] = {xoffset, 0, 0};
    fs_tex_subimage_nd(c, 1, target, level, off, width, 1, 1, format, type, pixels);
}

void fs_exec_TexSubImage3D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                           GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                           const GLvoid *pixels)
{
    const GLint off[3] = {xoffset, yoffset, zoffset};
    fs_tex_subimage_nd(c, 3, target, level, off, width, height, depth, format, type, pixels);
}

void fs_exec_CopyTexImage1D(fs_context *c, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                            GLsizei width, GLint border)
{
    /* 3.8.2: one row of the framebuffer, at y. */
    fs_tex_copy_image_nd(c, 1, target, level, internalformat, x, y, width, 1, border);
}

void fs_exec_CopyTexSubImage1D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                               GLsizei width)
{
    const GLint off[3] = {xoffset, 0, 0};
    fs_tex_copy_subimage_nd(c, 1, target, level, off, x, y, width, 1);
}

void fs_exec_CopyTexSubImage3D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                               GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height)
{
    /* 3.8.2: the rectangle replaces part of slice zoffset. */
    const GLint off[3] = {xoffset, yoffset, zoffset};
    fs_tex_copy_subimage_nd(c, 3, target, level, off, x, y, width, height);
}
