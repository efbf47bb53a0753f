/*
 * The framebuffer: RGBA8 colour, depth (16 or 24 bits) and stencil (8 bits).
 * Row 0 is the bottom row (GL window coordinates, like OSMesa's default
 * OSMESA_Y_UP), so glReadPixels and OSMesa's buffers index the same way.
 * Colour pixels are stored as bytes R,G,B,A (GL_RGBA/GL_UNSIGNED_BYTE order).
 */
#ifndef FS_FRAMEBUFFER_H
#define FS_FRAMEBUFFER_H
#include <stdint.h>

typedef struct fs_framebuffer {
    int width, height;
    int depth_bits, stencil_bits;
    uint32_t depth_max;  /* 2^depth_bits - 1 */
    uint8_t *color;      /* width*height*4 bytes */
    uint32_t *depth;     /* width*height values in [0, depth_max] */
    uint8_t *stencil;    /* width*height values */
} fs_framebuffer;

/* Allocates (or reallocates) the buffers; contents are zero.  Returns 0 or -1. */
int fs_framebuffer_init(fs_framebuffer *fb, int width, int height, int depth_bits, int stencil_bits);
void fs_framebuffer_free(fs_framebuffer *fb);
#endif
