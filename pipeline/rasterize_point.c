/*
 * Points (GL 1.5 spec 3.3), modelled on llvmpipe's lp_setup_point.c (Mesa
 * 22.3, read for the rules): GL compatibility contexts use the legacy
 * point rule (measured against OSMesa in tests/test_rasterizer.c, points:
 * the sprite-style square with a fill rule differs), every attribute is
 * constant over the point.
 */
#include <math.h>
#include "rasterizer_priv.h"

/* llvmpipe's util_iround on x86-64: round half away from zero, after the
 * float multiply by the fixed-point scale. */
static inline int64_t iround(float f)
{
    return f >= 0.0f ? (int64_t)(f + 0.5f) : (int64_t)(f - 0.5f);
}

void fs_raster_point(fs_context *c, const fs_rvertex *v)
{
    const fs_raster_state *r = &c->raster;
    const int W = c->fb.width, H = c->fb.height;
    const int order = r->subpixel_bits;
    const float one = (float)(1 << order);
    float x = v->x;
    float y = r->use_y_raster ? v->y_raster : fs_raster_y(H, v->y);
    float size = r->point_size;
    /* llvmpipe's LP_MAX_POINT_WIDTH. */
    if (size > 255.0f)
        size = 255.0f;
    if (!(fabsf(x) < 1e6f) || !(fabsf(y) < 1e6f)) {
        c->stats.triangles_culled++;
        return;
    }
    c->stats.points_rasterized++;

    /* GL's legacy (non-sprite) point rule, GL 1.5 spec 3.3: the size is
     * rounded to an integer (halves down); an odd-sized point covers the
     * pixels around the one containing the vertex, an even-sized one is
     * centred on the nearest pixel corner.  The point is drawn as its
     * whole box (llvmpipe's rectangle path): no fill rule applies. */
    const int adj = 1;
    const int64_t half = (1 << order) / 2;
    int64_t fw = (iround(size * one) + half - 1) & ~(int64_t)((1 << order) - 1);
    if (fw < (1 << order))
        fw = 1 << order;
    int64_t iw = fw >> order;
    int64_t xs = iround(x * one), ys = iround(y * one) - adj;
    int64_t bx0, by0;
    if (iw & 1) {
        bx0 = fs_floor_shift(xs, order) - (iw - 1) / 2;
        by0 = fs_floor_shift(ys, order) - (iw - 1) / 2;
    } else {
        bx0 = fs_floor_shift(xs + half, order) - iw / 2;
        by0 = fs_floor_shift(ys + half, order) - iw / 2;
    }
    int64_t bx1 = bx0 + iw - 1, by1 = by0 + iw - 1;
    fs_edge_planes e;
    if (!fs_window_box(bx0, by0, bx1, by1, W, H, &e.x0, &e.x1, &e.y0, &e.y1))
        return;
    e.n = 0; /* the box alone */

    fs_prim_setup s;
    s.front = true;
    s.height = H;
    s.use_tex = r->interpolate_tex;
    s.use_fog = r->interpolate_fog;
    s.tex_mask = r->tex_mask;
    s.zoffset = 0.0f;
    fs_plane_constant(&s.z, v->z);
    /* Perspective-correct constants are stored premultiplied by 1/w and
     * divided by the (constant) interpolated 1/w, as llvmpipe does. */
    s.perspective = v->inv_w != 1.0f;
    fs_plane_constant(&s.w, v->inv_w);
    fs_plane_constant(&s.fog, s.perspective ? v->fog * v->inv_w : v->fog);
    /* Flat shading: the colour itself (fs_raster_state.flat_color). */
    s.color_constant = r->flat_color;
    s.use_color2 = r->interpolate_color2;
    for (int k = 0; k < 4; k++) {
        fs_plane_constant(&s.color[k], s.perspective && !s.color_constant ? v->color[k] * v->inv_w : v->color[k]);
        if (k < 3)
            fs_plane_constant(&s.color2[k], s.perspective && !s.color_constant ? v->color2[k] * v->inv_w : v->color2[k]);
        if (s.use_tex)
            FS_FOR_EACH_UNIT(u, s.tex_mask)
                fs_plane_constant(&s.tex[u][k], s.perspective ? v->tex[u][k] * v->inv_w : v->tex[u][k]);
    }
    fs_raster_planes(c, &s, &e);
}
