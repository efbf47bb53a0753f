/*
 * Rasterizer state commands: glCullFace, glFrontFace (GL 1.5 spec 3.5.1),
 * glPolygonOffset (3.5.5), glPolygonMode (3.5.4), glPointSize (3.3),
 * glLineWidth (3.4), glPolygonStipple and glGetPolygonStipple (3.5.6).
 * Errors follow GL 1.5 spec 2.5: the offending call has no other effect.
 */
#include "context.h"
#include "pixel_transfer.h"

void fs_exec_CullFace(fs_context *c, GLenum mode)
{
    if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->raster.cull_mode = mode;
}

void fs_exec_FrontFace(fs_context *c, GLenum mode)
{
    if (mode != GL_CW && mode != GL_CCW) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->raster.front_face = mode;
}

void fs_exec_PolygonOffset(fs_context *c, GLfloat factor, GLfloat units)
{
    /* No error cases (GL 1.5 spec 3.5.5). */
    c->raster.offset_factor = factor;
    c->raster.offset_units = units;
}

void fs_exec_PolygonMode(fs_context *c, GLenum face, GLenum mode)
{
    if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
        (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (face != GL_BACK)
        c->raster.polygon_mode[0] = mode;
    if (face != GL_FRONT)
        c->raster.polygon_mode[1] = mode;
}

void fs_exec_PointSize(fs_context *c, GLfloat size)
{
    /* GL 1.5 spec 3.3: size <= 0 is INVALID_VALUE (a NaN is rejected too). */
    if (!(size > 0.0f)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->raster.point_size = size;
}

void fs_exec_LineWidth(fs_context *c, GLfloat width)
{
    /* GL 1.5 spec 3.4.2: width <= 0 is INVALID_VALUE. */
    if (!(width > 0.0f)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->raster.line_width = width;
}

void fs_exec_LineStipple(fs_context *c, GLint factor, GLushort pattern)
{
    /* GL 1.5 spec 3.4.2: no error; the factor is clamped to [1, 256].  The
     * stipple itself: pipeline/rasterize_line.c. */
    c->st.line_stipple_repeat = factor < 1 ? 1 : factor > 256 ? 256 : factor;
    c->st.line_stipple_pattern = pattern;
    fs_state_mark(c, GL_LINE_BIT);
}

/* ---- polygon stipple (GL 1.5 spec 3.5.6) ---- */

void fs_exec_PolygonStipple(fs_context *c, const GLubyte *mask)
{
    /* 3.5.6: the pattern is unpacked like a 32x32 glBitmap image (3.6.4,
     * "Unpacking of bitmaps": the unpack state's row length, skips,
     * alignment and LSB-first apply; no pixel transfer).  A null pointer
     * without a pixel buffer reads nothing and leaves the pattern. */
    if (!mask)
        return;
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, 2, 32, 32, 1, GL_COLOR_INDEX, GL_BITMAP))
        return;
    for (int y = 0; y < 32; y++) {
        uint32_t bits[32], row = 0;
        fs_pixel_unpack_index(&l, mask, 0, y, 0, 32, bits);
        for (int x = 0; x < 32; x++)
            row |= (bits[x] & 1u) << x;
        c->raster.stipple[y] = row;
    }
    fs_state_mark(c, GL_POLYGON_STIPPLE_BIT);
}

void fs_exec_GetPolygonStipple(fs_context *c, GLubyte *mask)
{
    /* 6.1.6: the pattern is packed as a 32x32 bitmap under the pack state
     * (4.3.2); only the pattern's bits are written, the other bits of the
     * bytes they share are left as they were. */
    if (!mask)
        return;
    fs_pixel_store ps = fs_pixel_store_pack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, 2, 32, 32, 1, GL_COLOR_INDEX, GL_BITMAP))
        return;
    for (int y = 0; y < 32; y++) {
        int64_t bit = l.origin + (int64_t)y * l.row_stride * 8;
        for (int x = 0; x < 32; x++, bit++) {
            int shift = l.lsb_first ? (int)(bit & 7) : 7 - (int)(bit & 7);
            GLubyte b = (GLubyte)(1u << shift);
            if ((c->raster.stipple[y] >> x) & 1u)
                mask[bit >> 3] |= b;
            else
                mask[bit >> 3] &= (GLubyte)~b;
        }
    }
}
