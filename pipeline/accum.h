/*
 * The accumulation buffer (GL 1.5 spec 4.2.4; pipeline/accum.c): glAccum
 * and the GL_ACCUM_BUFFER_BIT part of glClear.  A context has one when its
 * configuration asks for accumulation bits (framebuffer.accum_bits, which
 * the shim sets from OSMesaCreateContextExt's accumBits): 16 signed bits
 * per component, as llvmpipe's OSMesa contexts have; the conformance
 * references' contexts have none.
 */
#ifndef FS_ACCUM_H
#define FS_ACCUM_H
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

typedef struct fs_accum_state {
    GLint bits[4];      /* GL_ACCUM_RED_BITS ... ALPHA: 16 each, or 0 */
    /* width x height RGBA values c * 32767 (signed normalized), made and
     * zeroed on first use and again when the window's size changes. */
    int16_t *buf;
    int w, h;
} fs_accum_state;

/* Clears [x0, x1) x [y0, y1) (the scissor box) to the clear value. */
void fs_accum_clear(fs_context *c, int x0, int y0, int x1, int y1);
void fs_accum_free(fs_context *c);
#endif
