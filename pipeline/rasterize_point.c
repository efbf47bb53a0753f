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

/* nir_lower_aapoint_fs: the distance d = s^2 + t^2 from the centre in
 * the unit square's coordinates kills the fragment beyond 1; otherwise
 * alpha is multiplied by (1 - d) / (1 - k) where d <= k and by 1 beyond
 * (llvmpipe 22.3's select, measured: the inner disc, not the rim, gets the
 * factor, which is at least 1 there and saturates at the colour
 * conversion). */
static void point_coverage(fs_quad *q)
{
    for (int i = 0; i < 4; i++) {
        if (!(q->mask & (1u << i)))
            continue;
        const float *a = q->aa[i];
        float d = a[0] * a[0] + a[1] * a[1];
        if (a[3] < d) {
            q->mask &= ~(1u << i);
            continue;
        }
        float inv = 1.0f / (a[3] - a[2]);
        float cov = inv * (a[3] - d);
        float sel = a[2] >= d ? cov : a[3];
        q->color[i][3] = q->color[i][3] * sel;
    }
}

/* GL_POINT_SMOOTH (3.3.1) as Mesa's draw module does it for llvmpipe
 * (draw_pipe_aapoint.c, read for the rule): a square of half side
 * radius = size / 2 (1 for sizes up to 2) around the vertex, two triangles
 * through the triangle setup with culling and offset off, whose corners
 * carry (+-1, +-1, k, 1), k = (1 - 1 / radius)^2 (measured: the squared
 * inner radius, computed as 1 - 2/r + 1/r^2); point_coverage ends the
 * fragment shader. */
static void raster_point_smooth(fs_context *c, const fs_rvertex *v, float x, float y, float size)
{
    float radius = size <= 2.0f ? 1.0f : 0.5f * size;
    float k = 1.0f / radius;
    k = 1.0f - 2.0f * k + k * k;
    fs_rvertex q[4] = {*v, *v, *v, *v};
    const float sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    float aa[4][4];
    for (int i = 0; i < 4; i++) {
        q[i].x = sx[i] < 0 ? x - radius : x + radius;
        q[i].y_raster = sy[i] < 0 ? y - radius : y + radius;
        aa[i][0] = sx[i];
        aa[i][1] = sy[i];
        aa[i][2] = k;
        aa[i][3] = 1.0f;
    }
    static const int tris[2][3] = {{0, 1, 2}, {0, 2, 3}};
    fs_raster_quad_aa(c, q, (const float(*)[4])aa, tris, point_coverage);
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
    if (r->point_smooth) {
        /* The state tracker clamps the size to GL_SMOOTH_POINT_SIZE_RANGE. */
        raster_point_smooth(c, v, x, y, size >= 1.0f ? size : 1.0f);
        return;
    }

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
    s.stipple = NULL; /* polygon stipple: filled polygons only (3.5.6) */
    s.height = H;
    s.use_tex = r->interpolate_tex;
    s.use_fog = r->interpolate_fog;
    s.tex_mask = r->tex_mask;
    s.zoffset = 0.0f;
    s.aa_shade = NULL;
    fs_plane_constant(&s.z, v->z);
    /* Perspective-correct constants are stored premultiplied by 1/w and
     * divided by the (constant) interpolated 1/w, as llvmpipe does. */
    s.perspective = v->inv_w != 1.0f;
    fs_plane_constant(&s.w, v->inv_w);
    fs_plane_constant(&s.fog, s.perspective ? v->fog * v->inv_w : v->fog);
    /* Flat shading: the colour itself (fs_raster_state.flat_color). */
    /* Constant attributes likewise (fs_raster_state.const_attribs). */
    s.color_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR);
    s.color2_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR2);
    s.tex_constant = r->const_attribs / FS_ATTR_TEX(0);
    s.use_color2 = r->interpolate_color2;
    for (int k = 0; k < 4; k++) {
        fs_plane_constant(&s.color[k], s.perspective && !s.color_constant ? v->color[k] * v->inv_w : v->color[k]);
        if (k < 3)
            fs_plane_constant(&s.color2[k], s.perspective && !s.color2_constant ? v->color2[k] * v->inv_w : v->color2[k]);
        if (s.use_tex)
            FS_FOR_EACH_UNIT(u, s.tex_mask)
                fs_plane_constant(&s.tex[u][k], s.perspective && !(s.tex_constant & (1u << u)) ? v->tex[u][k] * v->inv_w
                                                                                                 : v->tex[u][k]);
    }
    fs_raster_planes(c, &s, &e);
}
