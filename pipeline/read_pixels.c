/*
 * Reading pixels (GL 1.5 spec 4.3.2): glReadPixels for GL_RGBA/
 * GL_UNSIGNED_BYTE, GL_DEPTH_COMPONENT (GL_UNSIGNED_INT, GL_UNSIGNED_SHORT,
 * GL_FLOAT) and GL_STENCIL_INDEX/GL_UNSIGNED_BYTE, packed with
 * GL_PACK_ALIGNMENT (4.3.2 "Final conversion", 3.6.4 table 3.5 for the row
 * layout).  Other legal format/type pairs are counted as unsupported.
 * Depth conversions follow Mesa's (checked against OSMesa by the tests).
 */
#include <math.h>
#include "fragment_stages.h"

/* Components per pixel of a GL 1.5 format, 0 if the enum is not a format. */
static int format_components(GLenum format)
{
    switch (format) {
    case GL_COLOR_INDEX: case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT:
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE:
        return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    default: return 0;
    }
}

/* Bytes per component, or per pixel for packed types (negated), 0 if the enum
 * is not a GL 1.5 pixel type.  GL_BITMAP is reported as 0: it is only legal
 * with colour or stencil index and fragsim has neither path. */
static int type_bytes(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV: return -1;
    case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV: return -2;
    case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV: return -4;
    default: return 0;
    }
}

static int64_t pixel_bytes(GLenum format, GLenum type)
{
    int n = format_components(format), t = type_bytes(type);
    if (n == 0 || t == 0)
        return 0;
    return t < 0 ? -t : (int64_t)n * t;
}

static int64_t row_stride(const fs_context *c, GLsizei w, int64_t bpp)
{
    int64_t a = c->pack_alignment;
    if (a != 1 && a != 2 && a != 4 && a != 8)
        a = 4;
    /* GL_PACK_ROW_LENGTH, when positive, replaces the width (table 4.5). */
    int64_t len = c->pack_row_length > 0 ? c->pack_row_length : w;
    return (len * bpp + a - 1) / a * a;
}

int64_t fs_readpixels_bytes(fs_context *c, GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    int64_t bpp = pixel_bytes(format, type);
    if (bpp == 0 || w <= 0 || h <= 0)
        return 0;
    /* The last row needs no padding (GL reads/writes only w pixels of it). */
    return row_stride(c, w, bpp) * (h - 1) + (int64_t)w * bpp;
}

/* Depth in buffer units to GL_UNSIGNED_INT: Mesa replicates the top bits into
 * the low bits, so depth_max maps to 0xffffffff. */
static uint32_t depth_to_uint(uint32_t z, int bits)
{
    if (bits >= 32)
        return z;
    uint32_t v = z << (32 - bits);
    for (int b = bits; b < 32; b += bits)
        v |= (z << (32 - bits)) >> b;
    return v;
}

void fs_exec_ReadPixels(fs_context *c, GLint x, GLint y, GLsizei width, GLsizei height,
                        GLenum format, GLenum type, GLvoid *pixels)
{
    /* GL_BITMAP is a legal type, but only with the index formats. */
    bool bitmap_ok = type == GL_BITMAP && (format == GL_STENCIL_INDEX || format == GL_COLOR_INDEX);
    if (format_components(format) == 0 || (type_bytes(type) == 0 && !bitmap_ok)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    /* Packed types need a format with a matching component count (3.6.4). */
    int t = type_bytes(type);
    if (t < 0) {
        int n = format_components(format);
        bool rgb_only = type == GL_UNSIGNED_BYTE_3_3_2 || type == GL_UNSIGNED_BYTE_2_3_3_REV ||
                        type == GL_UNSIGNED_SHORT_5_6_5 || type == GL_UNSIGNED_SHORT_5_6_5_REV;
        if ((rgb_only && format != GL_RGB) ||
            (!rgb_only && format != GL_RGBA && format != GL_BGRA) || n < 3) {
            fs_error(c, GL_INVALID_OPERATION);
            return;
        }
    }
    /* Colour index reads need a colour-index framebuffer, stencil reads a
     * stencil buffer (4.3.2). */
    if (format == GL_COLOR_INDEX || (format == GL_STENCIL_INDEX && c->fb.stencil_bits == 0)) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    bool ok = (format == GL_RGBA && type == GL_UNSIGNED_BYTE) ||
              (format == GL_DEPTH_COMPONENT &&
               (type == GL_UNSIGNED_INT || type == GL_UNSIGNED_SHORT || type == GL_FLOAT)) ||
              (format == GL_STENCIL_INDEX && type == GL_UNSIGNED_BYTE);
    if (!ok) {
        fs_unsupported(c, "glReadPixels(format/type)");
        return;
    }
    if (!pixels || width == 0 || height == 0)
        return;

    const fs_framebuffer *fb = &c->fb;
    int64_t bpp = pixel_bytes(format, type);
    int64_t stride = row_stride(c, width, bpp);
    if (c->cycle)
        fs_cycle_read_pixels(c->cycle, c, (uint64_t)width * (uint64_t)height * (uint64_t)bpp);
    /* Pixels outside the window are undefined in GL; they are left as they
     * were in the caller's buffer. */
    int64_t cx0 = x < 0 ? 0 : x, cy0 = y < 0 ? 0 : y;
    int64_t cx1 = (int64_t)x + width, cy1 = (int64_t)y + height;
    if (cx1 > fb->width) cx1 = fb->width;
    if (cy1 > fb->height) cy1 = fb->height;
    for (int64_t wy = cy0; wy < cy1; wy++) {
        uint8_t *row = (uint8_t *)pixels + (wy - y) * stride;
        size_t base = (size_t)wy * (size_t)fb->width;
        for (int64_t wx = cx0; wx < cx1; wx++) {
            uint8_t *out = row + (wx - x) * bpp;
            size_t i = base + (size_t)wx;
            if (format == GL_RGBA) {
                memcpy(out, fb->color + i * 4, 4);
            } else if (format == GL_STENCIL_INDEX) {
                *out = fb->stencil[i];
            } else if (type == GL_UNSIGNED_INT) {
                uint32_t v = depth_to_uint(fb->depth[i], fb->depth_bits);
                memcpy(out, &v, 4);
            } else if (type == GL_UNSIGNED_SHORT) {
                /* Through the float value, then scaled and rounded in float
                 * as Mesa packs it: the float rounding of f * 65535 can reach
                 * a .5 tie that exact arithmetic would not. */
                float f = (float)((double)fb->depth[i] / (double)fb->depth_max);
                uint16_t v = (uint16_t)lrintf(f * 65535.0f);
                memcpy(out, &v, 2);
            } else {
                float v = (float)((double)fb->depth[i] / (double)fb->depth_max);
                memcpy(out, &v, 4);
            }
        }
    }
}
