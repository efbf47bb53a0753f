/*
 * Texture coordinate generation (GL 1.5 spec 2.11.4): the state of each
 * texture unit's four generated coordinates s, t, r, q, set by glTexGen
 * and read by glGetTexGen (pipeline/texgen.c), and applied by the vertex
 * stage before the texture matrix (vertex_internal.h's fs_texgen_vertex).
 */
#ifndef FS_TEXGEN_H
#define FS_TEXGEN_H
#include <stdbool.h>
#include <GL/gl.h>

typedef struct fs_texgen_coord {
    GLenum mode;             /* GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR initially */
    float object_plane[4];   /* GL_OBJECT_PLANE as given */
    float eye_plane[4];      /* GL_EYE_PLANE times the inverse modelview of its glTexGen */
} fs_texgen_coord;

/* One texture unit's generation: GL_TEXTURE_GEN_S .. _Q and each
 * coordinate's mode and planes (table 6.17). */
typedef struct fs_texgen_unit {
    bool enabled[4];
    fs_texgen_coord coord[4];
} fs_texgen_unit;

struct fs_context;
/* The initial planes and modes of every unit (table 6.17): s's planes
 * (1, 0, 0, 0), t's (0, 1, 0, 0), r's and q's zero, every mode
 * GL_EYE_LINEAR. */
void fs_texgen_init(struct fs_context *c);
#endif
