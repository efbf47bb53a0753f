/*
 * The active texture units (GL 1.5 spec 2.7 and 3.8.13): glActiveTexture
 * and glClientActiveTexture.  fragsim has FS_MAX_TEXTURE_UNITS fixed-function
 * units (8, GL_MAX_TEXTURE_UNITS as llvmpipe reports it); GL_TEXTUREi for
 * another i is GL_INVALID_ENUM (2.7).  (OSMesa's glActiveTexture also takes
 * the units up to GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, 192, which only
 * shaders sample; fragsim has no shaders and refuses them.)
 */
#include "context.h"

static bool select_unit(fs_context *c, GLenum texture, GLenum *unit)
{
    if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + FS_MAX_TEXTURE_UNITS) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    *unit = texture;
    return true;
}

int fs_active_unit(const fs_context *c) { return (int)(c->st.active_texture - GL_TEXTURE0); }
int fs_client_active_unit(const fs_context *c) { return (int)(c->st.client_active_texture - GL_TEXTURE0); }

void fs_exec_ActiveTexture(fs_context *c, GLenum texture)
{
    if (select_unit(c, texture, &c->st.active_texture))
        fs_state_mark(c, GL_TEXTURE_BIT);
}

void fs_exec_ClientActiveTexture(fs_context *c, GLenum texture)
{
    if (select_unit(c, texture, &c->st.client_active_texture))
        fs_state_mark(c, FS_CLIENT_VERTEX_ARRAY);
}
