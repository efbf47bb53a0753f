/*
 * glMultiTexCoord (GL 1.5 spec 2.7): the current texture coordinates of
 * any texture unit, as glTexCoord sets unit 0's (pipeline/immediate.c).
 * Missing coordinates are t = r = 0, q = 1; integer forms convert
 * directly, not as normalized values (2.7, table 2.9 applies to colours).
 *
 * The unit is target & 7, without an error for a target outside
 * GL_TEXTURE0 .. GL_TEXTURE7: the spec leaves that undefined, and Mesa
 * indexes its attributes so (measured on OSMesa: glMultiTexCoord2f with
 * GL_TEXTURE9 sets unit 1's coordinates, with 7 unit 7's, no error).
 */
#include "vertex_internal.h"

_Static_assert(FS_MAX_TEXTURE_UNITS == 8, "the unit of a target is its low three bits");

static void multi(fs_context *c, GLenum target, float s, float t, float r, float q)
{
    fs_current_texcoord(c, (int)(target & 7u), s, t, r, q);
}

/* The sixteen forms of one argument type T, suffix SUF. */
#define FS_MULTI_TEXCOORDS(SUF, T)                                                                    \
    void fs_exec_MultiTexCoord1##SUF(fs_context *c, GLenum target, T s)                             \
    {                                                                                               \
        multi(c, target, (float)s, 0.0f, 0.0f, 1.0f);                                               \
    }                                                                                               \
    void fs_exec_MultiTexCoord2##SUF(fs_context *c, GLenum target, T s, T t)                        \
    {                                                                                               \
        multi(c, target, (float)s, (float)t, 0.0f, 1.0f);                                           \
    }                                                                                               \
    void fs_exec_MultiTexCoord3##SUF(fs_context *c, GLenum target, T s, T t, T r)                   \
    {                                                                                               \
        multi(c, target, (float)s, (float)t, (float)r, 1.0f);                                       \
    }                                                                                               \
    void fs_exec_MultiTexCoord4##SUF(fs_context *c, GLenum target, T s, T t, T r, T q)              \
    {                                                                                               \
        multi(c, target, (float)s, (float)t, (float)r, (float)q);                                   \
    }                                                                                               \
    void fs_exec_MultiTexCoord1##SUF##v(fs_context *c, GLenum target, const T *v)                   \
    {                                                                                               \
        multi(c, target, (float)v[0], 0.0f, 0.0f, 1.0f);                                            \
    }                                                                                               \
    void fs_exec_MultiTexCoord2##SUF##v(fs_context *c, GLenum target, const T *v)                   \
    {                                                                                               \
        multi(c, target, (float)v[0], (float)v[1], 0.0f, 1.0f);                                     \
    }                                                                                               \
    void fs_exec_MultiTexCoord3##SUF##v(fs_context *c, GLenum target, const T *v)                   \
    {                                                                                               \
        multi(c, target, (float)v[0], (float)v[1], (float)v[2], 1.0f);                              \
    }                                                                                               \
    void fs_exec_MultiTexCoord4##SUF##v(fs_context *c, GLenum target, const T *v)                   \
    {                                                                                               \
        multi(c, target, (float)v[0], (float)v[1], (float)v[2], (float)v[3]);                       \
    }

FS_MULTI_TEXCOORDS(s, GLshort)
FS_MULTI_TEXCOORDS(i, GLint)
FS_MULTI_TEXCOORDS(f, GLfloat)
FS_MULTI_TEXCOORDS(d, GLdouble)
