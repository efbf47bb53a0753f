/*
 * Framebuffer storage (GL 1.5 spec 4.1 and 4.2): RGBA8 colour, depth and
 * stencil, row 0 at the bottom like OSMesa's OSMESA_Y_UP buffers.
 */
#include <stdlib.h>
#include <string.h>
#include "framebuffer.h"

int fs_framebuffer_init(fs_framebuffer *fb, int width, int height, int depth_bits, int stencil_bits)
{
    if (width <= 0 || height <= 0 || (depth_bits != 16 && depth_bits != 24) ||
        stencil_bits < 0 || stencil_bits > 8)
        return -1;
    size_t n = (size_t)width * (size_t)height;
    /* Allocate first, free the old buffers after, so that a failed resize
     * leaves the previous framebuffer usable. */
    uint8_t *color = calloc(n, 4);
    uint32_t *depth = calloc(n, sizeof *depth);
    uint8_t *stencil = calloc(n, 1);
    if (!color || !depth || !stencil) {
        free(color);
        free(depth);
        free(stencil);
        return -1;
    }
    fs_framebuffer_free(fb);
    fb->width = width;
    fb->height = height;
    fb->depth_bits = depth_bits;
    fb->stencil_bits = stencil_bits;
    fb->depth_max = (uint32_t)((1ull << depth_bits) - 1);
    fb->color = color;
    fb->depth = depth;
    fb->stencil = stencil;
    return 0;
}

void fs_framebuffer_free(fs_framebuffer *fb)
{
    free(fb->color);
    free(fb->depth);
    free(fb->stencil);
    fb->color = NULL;
    fb->depth = NULL;
    fb->stencil = NULL;
    fb->width = fb->height = 0;
}
