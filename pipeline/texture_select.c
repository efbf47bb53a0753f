/*
 * The active texture units (GL 1.5 spec 2.7 and 3.8.13): glActiveTexture
 * and glClientActiveTexture.  fragsim has one texture unit
 * (GL_MAX_TEXTURE_UNITS 1), so GL_TEXTURE0 is the only unit they take;
 * another is GL_INVALID_ENUM (2.7).
 */
#include "context.h"

static bool select_unit(fs_context *c, GLenum texture, GLenum *unit)
{
    if (texture != GL_TEXTURE0) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    *unit = texture;
    return true;
}

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
