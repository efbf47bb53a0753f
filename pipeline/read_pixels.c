/*
 * Reading pixels (GL 1.5 spec 4.3.2): glReadPixels of the colour, depth
 * and stencil buffers in every format and type, placed in client memory by
 * the pack state (pixel_transfer.h, which does the conversions of 4.3.2
 * "Final conversion" as llvmpipe does).  Colour index reads are refused:
 * the framebuffer is RGBA (4.3.2).
 */
#include "fragment_stages.h"
#include "pixel_transfer.h"

int64_t fs_readpixels_bytes(fs_context *c, GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    fs_pixel_store ps = fs_pixel_store_pack(c);
    return fs_pixel_image_bytes(&ps, 2, w, h, 1, format, type);
}

void fs_exec_ReadPixels(fs_context *c, GLint x, GLint y, GLsizei width, GLsizei height,
                        GLenum format, GLenum type, GLvoid *pixels)
{
    fs_modelview_analyse(c);
    GLenum err = fs_pixel_check(format, type);
    if (err == GL_INVALID_ENUM) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    /* Packed types need a format with a matching component count (3.6.4). */
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    /* Colour index reads need a colour-index framebuffer, stencil reads a
     * stencil buffer (4.3.2). */
    bool ds = format == GL_DEPTH_STENCIL; /* EXT_packed_depth_stencil: both buffers */
    if (format == GL_COLOR_INDEX || ((format == GL_STENCIL_INDEX || ds) && c->fb.stencil_bits == 0) ||
        (ds && c->fb.depth_bits == 0)) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    /* glReadBuffer(GL_NONE) leaves no colour buffer to read (as Mesa
     * answers; pipeline/buffer_select.c). */
    if (c->read_buffer == GL_NONE && format != GL_DEPTH_COMPONENT && format != GL_STENCIL_INDEX && !ds) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (!pixels || width == 0 || height == 0)
        return;

    const fs_framebuffer *fb = &c->fb;
    fs_pixel_store ps = fs_pixel_store_pack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, 2, width, height, 1, format, type))
        return; /* an image too large to address: nothing written */
    if (c->observer) {
        uint64_t n = (uint64_t)width * (uint64_t)height;
        FS_OBSERVE(c, read_pixels, c, l.group_bytes ? n * (uint64_t)l.group_bytes : (n + 7) / 8);
    }
    /* Pixels outside the window are undefined in GL; they are left as they
     * were in the caller's buffer. */
    int64_t cx0 = x < 0 ? 0 : x, cy0 = y < 0 ? 0 : y;
    int64_t cx1 = (int64_t)x + width, cy1 = (int64_t)y + height;
    if (cx1 > fb->width) cx1 = fb->width;
    if (cy1 > fb->height) cy1 = fb->height;
    for (int64_t wy = cy0; wy < cy1; wy++) {
        size_t i = (size_t)wy * (size_t)fb->width + (size_t)cx0;
        int64_t row = wy - y, col = cx0 - x, n = cx1 - cx0;
        if (format == GL_STENCIL_INDEX)
            fs_pixel_pack_stencil(&l, pixels, row, col, n, fb->stencil + i);
        else if (ds)
            fs_pixel_pack_depth_stencil(&l, pixels, row, col, n, fb->depth + i, fb->depth_bits, fb->stencil + i);
        else if (format == GL_DEPTH_COMPONENT)
            fs_pixel_pack_depth(&l, pixels, row, col, n, fb->depth + i, fb->depth_bits);
        else
            fs_pixel_pack_rgba8(&l, pixels, row, col, n, fb->color + i * 4, FS_PACK_LUMINANCE_SUM);
    }
}
