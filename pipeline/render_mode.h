/*
 * Selection and feedback (GL 1.5 spec 5.2, 5.3): glRenderMode(GL_SELECT)
 * and glRenderMode(GL_FEEDBACK), the name stack, glPassThrough.  In either
 * mode the primitives that survive clipping and culling go to
 * pipeline/render_mode.c instead of the rasterizer (clip.c hands them over),
 * so no fragment is made and nothing is written to the framebuffer.  The
 * Occlusion Unit's modes (GL_BRIEF/GL_VERBOSE_OCCLUSION) are
 * units/occlusion_gl.c's; glRenderMode there calls into this file.
 */
#ifndef FS_RENDER_MODE_H
#define FS_RENDER_MODE_H
#include <stdbool.h>
#include <GL/gl.h>
#include "rasterizer.h"

/* GL_MAX_NAME_STACK_DEPTH as OSMesa (llvmpipe) reports it. */
#define FS_MAX_NAME_STACK_DEPTH 64

typedef struct fs_render_mode_state {
    GLenum mode;            /* GL_RENDER, GL_SELECT or GL_FEEDBACK */
    /* Selection (5.2).  select_count counts the words of hit records,
     * also those past select_size that were not written (glRenderMode
     * then returns -1). */
    GLuint *select_buf;     /* NULL: written nowhere (a replayed trace) */
    GLint select_size;      /* GL_SELECTION_BUFFER_SIZE */
    GLuint select_count, hits;
    bool hit;
    float hit_min, hit_max; /* window z of the primitives since the last record */
    GLint name_depth;       /* GL_NAME_STACK_DEPTH */
    GLuint names[FS_MAX_NAME_STACK_DEPTH];
    /* Feedback (5.3). */
    GLfloat *feedback_buf;  /* NULL: written nowhere (a replayed trace) */
    GLint feedback_size;    /* GL_FEEDBACK_BUFFER_SIZE */
    GLenum feedback_type;   /* GL_FEEDBACK_BUFFER_TYPE */
    GLuint feedback_count;
} fs_render_mode_state;

typedef struct fs_context fs_context;

void fs_render_mode_init(fs_context *c);
/* Whether glRenderMode(mode) may enter mode: GL_SELECT and GL_FEEDBACK
 * need a buffer of nonzero size (else GL_INVALID_OPERATION, though the mode
 * is entered: measured on OSMesa). */
bool fs_render_mode_may_enter(const fs_context *c, GLenum mode);
/* Leaves GL_SELECT or GL_FEEDBACK (writing the last hit record) and enters
 * mode when it is one of them; returns glRenderMode's value for the mode
 * left (0 from any other). */
GLint fs_render_mode_switch(fs_context *c, GLenum mode);
/* The buffers, for glSelectBuffer/glFeedbackBuffer and for the replayer,
 * which gives NULL (the traced program's memory is not ours) and
 * untracked true, so that no GL_INVALID_VALUE is raised for it. */
void fs_render_mode_select_buffer(fs_context *c, GLsizei size, GLuint *buffer);
void fs_render_mode_feedback_buffer(fs_context *c, GLsizei size, GLenum type, GLfloat *buffer, bool untracked);

/* The primitives of the vertex stage after clipping, in either mode. */
void fs_render_mode_triangle(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2);
void fs_render_mode_line(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1);
void fs_render_mode_point(fs_context *c, const fs_rvertex *v);
/* A valid raster position used by glBitmap (GL_BITMAP_TOKEN),
 * glDrawPixels (GL_DRAW_PIXEL_TOKEN) or glCopyPixels (GL_COPY_PIXEL_TOKEN):
 * a hit in selection, the token and the vertex in feedback. */
void fs_render_mode_pixels(fs_context *c, GLenum token, const fs_rvertex *v);

/* Whether primitives go to this file instead of the rasterizer. */
static inline bool fs_render_mode_diverts(const fs_render_mode_state *s)
{
    return s->mode != GL_RENDER;
}
#endif
