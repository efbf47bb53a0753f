/*
 * The fragments of pixel rectangles: glBitmap (GL 1.5 spec 3.7),
 * glDrawPixels (3.6) and glCopyPixels (4.3.3).  Each makes fragments at window pixels, with the
 * current raster position's depth, colour and texture coordinates where
 * the image does not give them (3.6.5, 3.7), and sends them through the
 * per-fragment operations (4.1) in 2x2 quads like any primitive: the
 * Occlusion Unit's attachment point counts them and the observer sees
 * the draw and its quads.  An invalid raster position draws nothing
 * (2.13), and glBitmap then does not move it either.
 *
 * Where the fragments land, measured on OSMesa (tests/test_pixel_rect.c):
 * - glBitmap: the image's lower left pixel is floor(x_r + 0.0001 - x_orig)
 *   (the same in y), Mesa's epsilon against a position a rounding below
 *   an integer; a set bit makes a fragment, a clear one none.
 * - glDrawPixels: the rectangle spans x_r to x_r + zoom_x * width (and in
 *   y); a column is drawn when its centre c has x_r < c <= x_r + zoom_x w
 *   (x_r + zoom_x w < c <= x_r for a negative zoom), and shows image
 *   column ceil((c - x_r) / zoom_x) - 1 (floor of it for a negative zoom).
 *   Exact for any position at zoom +-1; llvmpipe draws the image as a
 *   textured quad, and a centre falling exactly between two image columns
 *   at other zooms may take either (measured: zoom 1.5 takes the left one,
 *   0.5 the right one).
 * - glCopyPixels draws the pixels it reads as glDrawPixels would an image
 *   of them; stencil indices, for both, are written, not tested.
 */
#include <math.h>
#include <stdlib.h>
#include "fragment_stages.h"
#include "pixel_transfer.h"
#include "pixel_map.h"
#include "rasterizer_priv.h"
#include "../units/texture_unit.h"

/* What a rectangle gives its fragments: per window pixel, whether it is
 * drawn and its colour and depth (start with the raster position's). */
typedef bool (*rect_frag_fn)(fs_context *c, const void *user, int x, int y, float rgba[4], uint32_t *z);

/* Window pixels [x0, x1) x [y0, y1), clipped to the window, in quads. */
static void rect_fragments(fs_context *c, int64_t x0, int64_t y0, int64_t x1, int64_t y1, rect_frag_fn frag,
                           const void *user)
{
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > c->fb.width) x1 = c->fb.width;
    if (y1 > c->fb.height) y1 = c->fb.height;
    if (x0 >= x1 || y0 >= y1)
        return;
    if (c->observer && c->observer->ops->draw && !c->observer->ops->draw(c->observer->user, c, GL_QUADS, 4))
        return;
    const fs_raster_pos *r = &c->rpos;
    /* The state tracker draws the rectangle as a quad at clip z 2 z_r - 1
     * through a viewport of depth scale and offset 1/2. */
    volatile float zc = r->win[2] * 2.0f - 1.0f;
    uint32_t z = fs_raster_quantize_depth(zc * 0.5f + 0.5f, c->fb.depth_bits);
    for (int64_t qy = y0 & ~1; qy < y1; qy += 2) {
        for (int64_t qx = x0 & ~1; qx < x1; qx += 2) {
            if (c->observer && fs_tile_mask_drops_quad(&c->observer->mask, (int)qx, (int)qy))
                continue;
            fs_quad q;
            memset(&q, 0, sizeof q);
            q.x = (int)qx;
            q.y = (int)qy;
            q.front_facing = true;
            for (int i = 0; i < 4; i++) {
                int x = (int)qx + (i & 1), y = (int)qy + (i >> 1);
                memcpy(q.color[i], r->color, sizeof q.color[i]);
                /* Each unit samples its own raster texture
                 * coordinates (3.6.4, 2.13; raster_pos.c). */
                for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
                    memcpy(q.unit[u].tex[i], r->tex[u], sizeof q.unit[u].tex[i]);
                q.z[i] = z;
                if (x >= x0 && x < x1 && y >= y0 && y < y1 && frag(c, user, x, y, q.color[i], &q.z[i]))
                    q.mask |= 1u << i;
            }
            if (!q.mask)
                continue;
            c->stats.quads_generated++;
            c->stats.fragments_generated += fs_popcount4(q.mask);
            if (c->raster.interpolate_tex)
                fs_texture_quad(c, &q);
            fs_quad_work w = fs_fragment_quad(c, &q);
            FS_OBSERVE(c, quad, c, &q, &w);
        }
    }
}

/* ---- glBitmap (3.7) ---- */

/* floor(v) as an integer, far outside any window (NaN included) clamped. */
static int64_t floor_clamped(float v)
{
    double f = floor((double)v);
    return f > -1e9 && f < 1e9 ? (int64_t)f : (f > 0 ? (int64_t)1e9 : (int64_t)-1e9);
}

typedef struct bitmap_src {
    fs_pixel_layout l;
    const void *bits;
    int64_t x0, y0;
} bitmap_src;

static bool bitmap_frag(fs_context *c, const void *user, int x, int y, float rgba[4], uint32_t *z)
{
    (void)c; (void)rgba; (void)z;
    const bitmap_src *b = user;
    uint32_t bit;
    fs_pixel_unpack_index(&b->l, b->bits, 0, y - b->y0, x - b->x0, 1, &bit);
    return bit != 0;
}

void fs_exec_Bitmap(fs_context *c, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                    GLfloat ymove, const GLubyte *bitmap)
{
    fs_modelview_analyse(c);
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    fs_raster_pos *r = &c->rpos;
    if (!r->valid)
        return; /* 3.7: no fragments, the raster position does not move */
    if (bitmap && width > 0 && height > 0) {
        bitmap_src b;
        fs_pixel_store ps = fs_pixel_store_unpack(c);
        if (fs_pixel_layout_init(&b.l, &ps, 2, width, height, 1, GL_COLOR_INDEX, GL_BITMAP)) {
            b.bits = bitmap;
            b.x0 = floor_clamped(r->win[0] + 0.0001f - xorig);
            b.y0 = floor_clamped(r->win[1] + 0.0001f - yorig);
            rect_fragments(c, b.x0, b.y0, b.x0 + width, b.y0 + height, bitmap_frag, &b);
        }
    }
    r->win[0] += xmove;
    r->win[1] += ymove;
}

/* ---- glDrawPixels (3.6) ---- */

/* A window-space span of a zoomed image, snapped to llvmpipe's 1/256
 * subpixels: the pixels whose centres c have lo < c <= hi (measured for
 * both signs of the zoom; table in the header). */
static void zoomed_span(float start, float zoom, int64_t n, int64_t *p0, int64_t *p1)
{
    float end = start + zoom * (float)n;
    double lo = start < end ? start : end, hi = start < end ? end : start;
    lo = nearbyint(lo * 256.0) / 256.0;
    hi = nearbyint(hi * 256.0) / 256.0;
    /* Far outside any window: clamp before converting to integers. */
    lo = lo < -1e9 ? -1e9 : lo > 1e9 ? 1e9 : lo;
    hi = hi < -1e9 ? -1e9 : hi > 1e9 ? 1e9 : hi;
    *p0 = (int64_t)floor(lo - 0.5) + 1;
    *p1 = (int64_t)floor(hi - 0.5) + 1; /* exclusive */
}

/* The image of glDrawPixels (client memory under the unpack state) or of
 * glCopyPixels (a copy of the window's pixels it reads, 4.3.3), as groups
 * (i, j) of a width x height image drawn at (x0, y0) with the zoom. */
typedef struct image_src {
    int64_t width, height;
    float x0, y0, zoom_x, zoom_y;  /* the raster position and the zoom */
    int kind;                      /* FS_PIXEL_COLOR, _COLOR_INDEX, _DEPTH or _STENCIL */
    /* glDrawPixels */
    fs_pixel_layout l;
    const void *pixels;
    /* glCopyPixels: groups [ci, ci + cw) x [cj, cj + ch) lie in the window
     * and were copied (RGBA8, depth units or stencil indices); the others
     * make no fragments. */
    const void *copy;
    int64_t ci, cj, cw, ch;
} image_src;

/* The image column (row) a pixel centre c shows: a positive zoom covers
 * centres in (x_r, x_r + zoom w], a negative one (x_r + zoom w, x_r], so
 * the window's upper end is inside either way, and the column counts
 * from the raster position. */
static double zoomed_index(double c, float start, float zoom)
{
    double t = (c - start) / zoom;
    return zoom > 0 ? ceil(t) - 1.0 : floor(t);
}

/* The image group window pixel (x, y) shows, as the offset of a copied
 * group in *copied for glCopyPixels; false when there is none. */
static bool image_group(const image_src *m, int x, int y, int64_t *col, int64_t *row, size_t *copied)
{
    double i = zoomed_index((double)x + 0.5, m->x0, m->zoom_x), j = zoomed_index((double)y + 0.5, m->y0, m->zoom_y);
    if (!(i >= 0 && i < (double)m->width && j >= 0 && j < (double)m->height))
        return false;
    *col = (int64_t)i;
    *row = (int64_t)j;
    if (!m->copy)
        return true;
    int64_t ci = *col - m->ci, cj = *row - m->cj;
    if (ci < 0 || cj < 0 || ci >= m->cw || cj >= m->ch)
        return false;
    *copied = (size_t)(cj * m->cw + ci);
    return true;
}

static bool image_frag(fs_context *c, const void *user, int x, int y, float rgba[4], uint32_t *z)
{
    const image_src *m = user;
    int64_t i, j;
    size_t k = 0;
    if (!image_group(m, x, y, &i, &j, &k))
        return false;
    if (m->kind == FS_PIXEL_DEPTH) {
        if (m->copy) {
            *z = ((const uint32_t *)m->copy)[k];
        } else {
            float d;
            fs_pixel_unpack_depth(&m->l, m->pixels, 0, j, i, 1, &d);
            *z = fs_raster_quantize_depth(d, c->fb.depth_bits);
        }
        return true;
    }
    uint8_t v[4];
    if (m->copy) {
        memcpy(v, (const uint8_t *)m->copy + k * 4, 4);
    } else if (m->kind == FS_PIXEL_COLOR_INDEX) {
        /* In RGBA mode indices become colours through the I_TO_R/G/B/A
         * maps whatever MAP_COLOR says (3.6.5 "Color Index Lookup":
         * rasterized groups must be RGBA).  3.6.5 shifts and offsets them
         * first; llvmpipe does not (INDEX_SHIFT and INDEX_OFFSET change
         * nothing: measured, tests/test_pixel_map.c
         * drawpixels_color_index_vs_osmesa), and nor does the model.
         * Exact for every index type but GL_BYTE (llvmpipe's colours
         * differ by 1 or 2 in a quarter of the bytes) and GL_BITMAP with
         * maps larger than 2 entries (other entries): not found yet. */
        uint32_t idx;
        float f[4];
        fs_pixel_unpack_index(&m->l, m->pixels, 0, j, i, 1, &idx);
        fs_pixel_map_index_to_rgba(c, &idx, 1, f);
        for (int n = 0; n < 4; n++)
            v[n] = fs_pixel_float_to_8(f[n]);
    } else {
        fs_pixel_unpack_rgba8(&m->l, m->pixels, 0, j, i, 1, v);
    }
    for (int n = 0; n < 4; n++)
        rgba[n] = (float)v[n] / 255.0f;
    return true;
}

/* Stencil indices are written, not tested (3.6.5 "Final conversion" and
 * 4.3.1): the pixel ownership and scissor tests and the stencil write
 * mask decide which values change. */
static void draw_stencil(fs_context *c, const image_src *m, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    fs_framebuffer *fb = &c->fb;
    int sx0 = 0, sy0 = 0, sx1 = fb->width, sy1 = fb->height;
    if (c->frag.scissor_enabled && !fs_scissor_rect(c, &sx0, &sy0, &sx1, &sy1))
        return;
    x0 = x0 > sx0 ? x0 : sx0;
    y0 = y0 > sy0 ? y0 : sy0;
    x1 = x1 < sx1 ? x1 : sx1;
    y1 = y1 < sy1 ? y1 : sy1;
    uint8_t wm = (uint8_t)c->frag.stencil_write_mask;
    for (int64_t y = y0; y < y1; y++)
        for (int64_t x = x0; x < x1; x++) {
            int64_t i, j;
            size_t k = 0;
            if (!image_group(m, (int)x, (int)y, &i, &j, &k))
                continue;
            uint32_t idx;
            if (m->copy)
                idx = ((const uint8_t *)m->copy)[k];
            else
                fs_pixel_unpack_index(&m->l, m->pixels, 0, j, i, 1, &idx);
            uint8_t *p = &fb->stencil[(size_t)y * (size_t)fb->width + (size_t)x];
            *p = (uint8_t)((*p & ~wm) | ((uint8_t)idx & wm));
        }
}

/* The errors of 3.6.4 in Mesa's order; GL_NO_ERROR when the image may be
 * drawn. */
static GLenum drawpixels_error(const fs_context *c, GLsizei width, GLsizei height, GLenum format, GLenum type)
{
    if (width < 0 || height < 0)
        return GL_INVALID_VALUE;
    GLenum err = fs_pixel_check(format, type);
    if (err != GL_NO_ERROR)
        return err;
    bool ds = format == GL_DEPTH_STENCIL; /* EXT_packed_depth_stencil: both buffers */
    if (((format == GL_STENCIL_INDEX || ds) && c->fb.stencil_bits == 0) ||
        ((format == GL_DEPTH_COMPONENT || ds) && c->fb.depth_bits == 0))
        return GL_INVALID_OPERATION;
    return GL_NO_ERROR;
}

/* Draws image m (its groups, kind and copy set) at the raster position
 * with the pixel zoom (3.6.5): stencil indices written, colours and
 * depths as fragments. */
static void draw_image(fs_context *c, image_src *m)
{
    const fs_raster_pos *r = &c->rpos;
    /* The columns count from the snapped position, as the quad's do. */
    m->x0 = (float)(nearbyint((double)r->win[0] * 256.0) / 256.0);
    m->y0 = (float)(nearbyint((double)r->win[1] * 256.0) / 256.0);
    m->zoom_x = c->st.zoom[0];
    m->zoom_y = c->st.zoom[1];
    if (m->zoom_x == 0.0f || m->zoom_y == 0.0f || !isfinite(m->x0 + m->y0 + m->zoom_x + m->zoom_y))
        return; /* a zero zoom covers no pixel centre */
    int64_t x0, x1, y0, y1;
    zoomed_span(m->x0, m->zoom_x, m->width, &x0, &x1);
    zoomed_span(m->y0, m->zoom_y, m->height, &y0, &y1);
    if (m->kind == FS_PIXEL_STENCIL)
        draw_stencil(c, m, x0 > 0 ? x0 : 0, y0 > 0 ? y0 : 0, x1 < c->fb.width ? x1 : c->fb.width,
                     y1 < c->fb.height ? y1 : c->fb.height);
    else
        rect_fragments(c, x0, y0, x1, y1, image_frag, m);
}

void fs_exec_DrawPixels(fs_context *c, GLsizei width, GLsizei height, GLenum format, GLenum type,
                        const GLvoid *pixels)
{
    fs_modelview_analyse(c);
    GLenum err = drawpixels_error(c, width, height, format, type);
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    if (!c->rpos.valid || !pixels || width == 0 || height == 0)
        return; /* 3.6.4: an invalid raster position draws nothing */
    int kind = fs_pixel_format_kind(format);
    if (kind == FS_PIXEL_DEPTH_STENCIL) { /* accepted by llvmpipe (measured), not modelled */
        fs_unsupported(c, "glDrawPixels(GL_DEPTH_STENCIL)");
        return;
    }
    image_src m;
    memset(&m, 0, sizeof m);
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    if (!fs_pixel_layout_init(&m.l, &ps, 2, width, height, 1, format, type))
        return;
    m.pixels = pixels;
    m.width = width;
    m.height = height;
    m.kind = kind;
    draw_image(c, &m);
}

/* ---- glCopyPixels (4.3.3) ---- */

/* Copies the part of the source rectangle inside the window (the rest is
 * undefined in GL; it makes no fragments here) before anything is drawn,
 * so an overlapping destination reads the old pixels. */
static void *copy_source(const fs_context *c, image_src *m, GLint x, GLint y)
{
    const fs_framebuffer *fb = &c->fb;
    int64_t i0 = x < 0 ? -(int64_t)x : 0, j0 = y < 0 ? -(int64_t)y : 0;
    int64_t i1 = m->width < (int64_t)fb->width - x ? m->width : (int64_t)fb->width - x;
    int64_t j1 = m->height < (int64_t)fb->height - y ? m->height : (int64_t)fb->height - y;
    m->ci = i0;
    m->cj = j0;
    m->cw = i1 > i0 ? i1 - i0 : 0;
    m->ch = j1 > j0 ? j1 - j0 : 0;
    size_t elem = m->kind == FS_PIXEL_COLOR ? 4 : m->kind == FS_PIXEL_DEPTH ? 4 : 1;
    uint8_t *copy = malloc((size_t)(m->cw * m->ch) * elem + 1);
    if (!copy)
        return NULL;
    for (int64_t j = 0; j < m->ch; j++) {
        size_t src = (size_t)(y + m->cj + j) * (size_t)fb->width + (size_t)(x + m->ci);
        uint8_t *dst = copy + (size_t)(j * m->cw) * elem;
        size_t n = (size_t)m->cw;
        if (m->kind == FS_PIXEL_COLOR)
            memcpy(dst, fb->color + src * 4, n * 4);
        else if (m->kind == FS_PIXEL_DEPTH)
            memcpy(dst, fb->depth + src, n * 4);
        else
            memcpy(dst, fb->stencil + src, n);
    }
    return copy;
}

void fs_exec_CopyPixels(fs_context *c, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type)
{
    fs_modelview_analyse(c);
    int kind = type == GL_COLOR ? FS_PIXEL_COLOR : type == GL_DEPTH ? FS_PIXEL_DEPTH
             : type == GL_STENCIL ? FS_PIXEL_STENCIL : 0;
    /* EXT_packed_depth_stencil's DEPTH_STENCIL and NV_copy_depth_to_color's
     * types, which llvmpipe accepts (measured), are not modelled. */
    bool ds = type == GL_DEPTH_STENCIL || type == GL_DEPTH_STENCIL_TO_RGBA_NV || type == GL_DEPTH_STENCIL_TO_BGRA_NV;
    if (!kind && !ds) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if ((kind == FS_PIXEL_DEPTH && c->fb.depth_bits == 0) || (kind == FS_PIXEL_STENCIL && c->fb.stencil_bits == 0) ||
        (ds && (c->fb.depth_bits == 0 || c->fb.stencil_bits == 0))) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (ds) {
        fs_unsupported(c, "glCopyPixels(GL_DEPTH_STENCIL)");
        return;
    }
    if (!c->rpos.valid || width == 0 || height == 0)
        return;
    image_src m;
    memset(&m, 0, sizeof m);
    m.width = width;
    m.height = height;
    m.kind = kind;
    void *copy = copy_source(c, &m, x, y);
    if (!copy) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    m.copy = copy;
    draw_image(c, &m);
    free(copy);
}
