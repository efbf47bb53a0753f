/*
 * Selecting the colour buffers to draw to and to read from (GL 1.5 spec
 * 4.2.1 glDrawBuffer, 4.3.2 glReadBuffer) and whether the window is
 * double-buffered (table 6.34).
 *
 * The model has one colour buffer, which serves as front and back: a
 * program that draws to the back buffer and swaps sees its image, as on
 * OSMesa, whose single-buffered context maps GL_BACK onto its one buffer.
 * Which names are accepted was measured on OSMesa (Mesa 22.3.6; tests in
 * tests/test_gl_state.c): the left front and back buffers in every
 * spelling and GL_NONE are accepted for both commands, right (stereo) and
 * auxiliary buffers and framebuffer-object attachments are names of
 * buffers this window does not have (GL_INVALID_OPERATION), anything else
 * is GL_INVALID_ENUM.  GL_NONE as the draw buffer writes no colour
 * (pipeline/fragment_ops.c, clear.c).
 */
#include "context.h"

void fs_context_set_double_buffered(fs_context *c, bool double_buffered)
{
    c->double_buffered = double_buffered;
    /* 4.2.1 / 4.3.2: initially GL_BACK when there is a back buffer,
     * else GL_FRONT (OSMesa answers GL_FRONT). */
    c->draw_buffer = c->read_buffer = double_buffered ? GL_BACK : GL_FRONT;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
}

/* 0 when the window has buffer `b`, else the GL error naming it gives. */
static GLenum buffer_error(GLenum b)
{
    switch (b) {
    case GL_NONE: case GL_FRONT_LEFT: case GL_BACK_LEFT: case GL_FRONT: case GL_BACK: case GL_LEFT:
    case GL_FRONT_AND_BACK:
        return GL_NO_ERROR;
    case GL_FRONT_RIGHT: case GL_BACK_RIGHT: case GL_RIGHT:
    case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
        return GL_INVALID_OPERATION; /* no stereo, GL_AUX_BUFFERS 0 */
    default:
        /* GL_COLOR_ATTACHMENT0 .. 31 (0x8CE0 .. 0x8CFF) are accepted names
         * of buffers a window has not (as Mesa answers for it). */
        return b >= 0x8CE0 && b <= 0x8CFF ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
    }
}

void fs_exec_DrawBuffer(fs_context *c, GLenum mode)
{
    GLenum e = buffer_error(mode);
    if (e != GL_NO_ERROR) {
        fs_error(c, e);
        return;
    }
    c->draw_buffer = mode;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

void fs_exec_ReadBuffer(fs_context *c, GLenum mode)
{
    /* 4.3.2 lists neither GL_NONE nor GL_FRONT_AND_BACK for reading;
     * Mesa accepts both (and glReadPixels then reads no colour buffer or
     * the front one). */
    GLenum e = buffer_error(mode);
    if (e != GL_NO_ERROR) {
        fs_error(c, e);
        return;
    }
    c->read_buffer = mode;
    fs_state_mark(c, GL_PIXEL_MODE_BIT);
}
