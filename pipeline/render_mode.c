/*
 * Selection (GL 1.5 spec 5.2) and feedback (5.3).
 *
 * What llvmpipe (Mesa 22.3.6) does, measured on OSMesa and held by
 * tests/test_render_mode.c:
 *  - Primitives reach selection and feedback after clipping against all
 *    six view-volume planes (lines too: no guard band), after culling, and
 *    decomposed as Mesa's draw pipeline decomposes them (quads (0,1,3),
 *    (1,2,3), polygons and clipped polygons as fans): every polygon is a
 *    GL_POLYGON_TOKEN of 3 vertices.  Degenerate triangles are kept unless
 *    culling is on.
 *  - Lines are GL_LINE_TOKEN, each segment apart; GL_LINE_RESET_TOKEN is
 *    never written (not even with line stipple on).
 *  - A hit record is count, min z, max z, the names from the bottom of the
 *    stack.  A window z in [0,1] becomes an unsigned int as the float
 *    product z * 2^32 truncated to a 64-bit integer and taken modulo 2^32:
 *    0.75 is 3221225472, 0.3f is 1288490240, 1.0 is 0 (not 2^32 - 1), and
 *    the -5.96e-8 a vertex clipped at the near plane can get is 2^32 - 256.
 *  - Words past the buffer's end are counted, not written; glRenderMode
 *    returns -1 when the count exceeds the size (a full buffer is no
 *    overflow), else the hits or the values written.
 *  - Leaving selection empties the name stack.  glPopName on an empty
 *    stack is GL_STACK_UNDERFLOW, glLoadName on one GL_INVALID_OPERATION,
 *    glPushName on a full one GL_STACK_OVERFLOW, and a refused command
 *    writes no hit record; outside GL_SELECT they are ignored without an
 *    error.
 */
#include <math.h>
#include <string.h>
#include "render_mode.h"
#include "context.h"

void fs_render_mode_init(fs_context *c)
{
    fs_render_mode_state *s = &c->rmode;
    memset(s, 0, sizeof *s);
    s->mode = GL_RENDER;
    s->feedback_type = GL_2D;
    s->hit_min = 1.0f;
    s->hit_max = 0.0f;
}

bool fs_render_mode_may_enter(const fs_context *c, GLenum mode)
{
    if (mode == GL_SELECT)
        return c->rmode.select_size > 0;
    if (mode == GL_FEEDBACK)
        return c->rmode.feedback_size > 0;
    return true;
}

/* ---- selection (5.2) ---- */

static void select_word(fs_render_mode_state *s, GLuint w)
{
    if (s->select_count < (GLuint)s->select_size && s->select_buf)
        s->select_buf[s->select_count] = w;
    s->select_count++;
}

/* A window z in [0,1] as the hit record holds it (measured; see the top). */
static GLuint hit_depth(float z)
{
    float scaled = z * 4294967296.0f;
    if (!(fabsf(scaled) < 9.2e18f))
        return 0; /* NaN: no such z reaches here (clipping drops it) */
    return (GLuint)(uint64_t)(int64_t)scaled;
}

static void write_hit_record(fs_render_mode_state *s)
{
    select_word(s, (GLuint)s->name_depth);
    select_word(s, hit_depth(s->hit_min));
    select_word(s, hit_depth(s->hit_max));
    for (GLint i = 0; i < s->name_depth; i++)
        select_word(s, s->names[i]);
    s->hits++;
    s->hit = false;
    s->hit_min = 1.0f;
    s->hit_max = 0.0f;
}

static void hit_z(fs_render_mode_state *s, float z)
{
    s->hit = true;
    if (z < s->hit_min)
        s->hit_min = z;
    if (z > s->hit_max)
        s->hit_max = z;
}

/* The name-stack commands change the stack only in GL_SELECT; each first
 * writes the record of the hits under the old stack (5.2), unless it is
 * refused: then the hits carry on into the next record (measured). */
static bool name_command(fs_context *c, bool refused, GLenum error)
{
    fs_render_mode_state *s = &c->rmode;
    if (s->mode != GL_SELECT)
        return false;
    if (refused) {
        fs_error(c, error);
        return false;
    }
    if (s->hit)
        write_hit_record(s);
    return true;
}

void fs_exec_InitNames(fs_context *c)
{
    if (name_command(c, false, GL_NO_ERROR))
        c->rmode.name_depth = 0;
}

void fs_exec_PushName(fs_context *c, GLuint name)
{
    fs_render_mode_state *s = &c->rmode;
    if (name_command(c, s->name_depth >= FS_MAX_NAME_STACK_DEPTH, GL_STACK_OVERFLOW))
        s->names[s->name_depth++] = name;
}

void fs_exec_PopName(fs_context *c)
{
    fs_render_mode_state *s = &c->rmode;
    if (name_command(c, s->name_depth == 0, GL_STACK_UNDERFLOW))
        s->name_depth--;
}

void fs_exec_LoadName(fs_context *c, GLuint name)
{
    fs_render_mode_state *s = &c->rmode;
    if (name_command(c, s->name_depth == 0, GL_INVALID_OPERATION))
        s->names[s->name_depth - 1] = name;
}

void fs_render_mode_select_buffer(fs_context *c, GLsizei size, GLuint *buffer)
{
    fs_render_mode_state *s = &c->rmode;
    if (s->mode == GL_SELECT) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (size < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    s->select_buf = buffer;
    s->select_size = size;
}

void fs_exec_SelectBuffer(fs_context *c, GLsizei size, GLuint *buffer)
{
    fs_render_mode_select_buffer(c, size, buffer);
}

/* ---- feedback (5.3) ---- */

static void feedback_value(fs_render_mode_state *s, GLfloat v)
{
    if (s->feedback_count < (GLuint)s->feedback_size && s->feedback_buf)
        s->feedback_buf[s->feedback_count] = v;
    s->feedback_count++;
}

/* One vertex as the buffer's type asks (table 5.2): window x, y, z, the
 * clip w (1 / (1/w), as llvmpipe recovers it), RGBA, s t r q. */
static void feedback_vertex(const fs_context *c, fs_render_mode_state *s, const fs_rvertex *v)
{
    GLenum t = s->feedback_type;
    feedback_value(s, v->x);
    /* llvmpipe works in its y-down frame and flips back: height - y,
     * which differs from GL's y in the last bit now and then. */
    feedback_value(s, (float)c->fb.height - v->y_raster);
    if (t != GL_2D)
        feedback_value(s, v->z);
    if (t == GL_4D_COLOR_TEXTURE)
        feedback_value(s, 1.0f / v->inv_w);
    if (t == GL_3D_COLOR || t == GL_3D_COLOR_TEXTURE || t == GL_4D_COLOR_TEXTURE)
        for (int k = 0; k < 4; k++)
            feedback_value(s, v->color[k]);
    if (t == GL_3D_COLOR_TEXTURE || t == GL_4D_COLOR_TEXTURE)
        for (int k = 0; k < 4; k++)
            feedback_value(s, v->tex[0][k]); /* unit 0's (GL 1.5 spec 5.3) */
}

void fs_render_mode_feedback_buffer(fs_context *c, GLsizei size, GLenum type, GLfloat *buffer, bool untracked)
{
    fs_render_mode_state *s = &c->rmode;
    /* Mesa's order of the checks, measured: mode, size, buffer, type. */
    if (s->mode == GL_FEEDBACK) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (size < 0 || (!buffer && !untracked && size > 0)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    switch (type) {
    case GL_2D: case GL_3D: case GL_3D_COLOR: case GL_3D_COLOR_TEXTURE: case GL_4D_COLOR_TEXTURE:
        break;
    default:
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    s->feedback_buf = buffer;
    s->feedback_size = size;
    s->feedback_type = type;
}

void fs_exec_FeedbackBuffer(fs_context *c, GLsizei size, GLenum type, GLfloat *buffer)
{
    fs_render_mode_feedback_buffer(c, size, type, buffer, false);
}

void fs_exec_PassThrough(fs_context *c, GLfloat token)
{
    fs_render_mode_state *s = &c->rmode;
    if (s->mode != GL_FEEDBACK)
        return;
    feedback_value(s, (GLfloat)GL_PASS_THROUGH_TOKEN);
    feedback_value(s, token);
}

/* ---- glRenderMode (5.2, 5.3) ---- */

GLint fs_render_mode_switch(fs_context *c, GLenum mode)
{
    fs_render_mode_state *s = &c->rmode;
    GLint ret = 0;
    if (s->mode == GL_SELECT) {
        if (s->hit)
            write_hit_record(s);
        ret = s->select_count > (GLuint)s->select_size ? -1 : (GLint)s->hits;
        s->select_count = s->hits = 0;
        s->name_depth = 0;
    } else if (s->mode == GL_FEEDBACK) {
        ret = s->feedback_count > (GLuint)s->feedback_size ? -1 : (GLint)s->feedback_count;
        s->feedback_count = 0;
    }
    s->mode = mode == GL_SELECT || mode == GL_FEEDBACK ? mode : (GLenum)GL_RENDER;
    return ret;
}

/* ---- the primitives ---- */

/* Culling (3.5.1) on the window positions in llvmpipe's y-down frame,
 * where a counter-clockwise triangle of GL's frame has a negative area. */
static bool culled(const fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2)
{
    if (!c->raster.cull_enabled)
        return false;
    float det = (v0->x - v2->x) * (v1->y_raster - v2->y_raster) - (v0->y_raster - v2->y_raster) * (v1->x - v2->x);
    if (!(det != 0.0f))
        return true;
    bool front = (c->raster.front_face == GL_CCW) == (det < 0.0f);
    return fs_raster_culled(&c->raster, front);
}

void fs_render_mode_triangle(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2)
{
    fs_render_mode_state *s = &c->rmode;
    if (culled(c, v0, v1, v2))
        return;
    if (s->mode == GL_SELECT) {
        hit_z(s, v0->z);
        hit_z(s, v1->z);
        hit_z(s, v2->z);
        return;
    }
    feedback_value(s, (GLfloat)GL_POLYGON_TOKEN);
    feedback_value(s, 3.0f);
    feedback_vertex(c, s, v0);
    feedback_vertex(c, s, v1);
    feedback_vertex(c, s, v2);
}

void fs_render_mode_line(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1)
{
    fs_render_mode_state *s = &c->rmode;
    if (s->mode == GL_SELECT) {
        hit_z(s, v0->z);
        hit_z(s, v1->z);
        return;
    }
    feedback_value(s, (GLfloat)GL_LINE_TOKEN);
    feedback_vertex(c, s, v0);
    feedback_vertex(c, s, v1);
}

void fs_render_mode_pixels(fs_context *c, GLenum token, const fs_rvertex *v)
{
    fs_render_mode_state *s = &c->rmode;
    if (s->mode == GL_SELECT) {
        hit_z(s, v->z);
        return;
    }
    feedback_value(s, (GLfloat)token);
    feedback_vertex(c, s, v);
}

void fs_render_mode_point(fs_context *c, const fs_rvertex *v)
{
    fs_render_mode_pixels(c, GL_POINT_TOKEN, v);
}
