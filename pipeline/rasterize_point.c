/*
 * Points (GL 1.5 spec 3.3), modelled on llvmpipe's lp_setup_point.c (Mesa
 * 22.3, read for the rules): GL compatibility contexts use the legacy
 * point rule (measured against OSMesa in tests/test_rasterizer.c, points:
 * the sprite-style square with a fill rule differs), every attribute is
 * constant over the point.
 */
#include <math.h>
#include "rasterizer_priv.h"
#include "raster_threads.h"

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
static void raster_point_smooth(fs_context *c, const fs_rvertex *v, float x, float y, float size, bool per_vertex)
{
    /* A size of the vertex's own (distance attenuation) is halved as it
     * is: the stage reads the vertex's size output, which no clamp to the
     * smooth range has touched (measured on OSMesa: attenuated smooth
     * points below size 2 are drawn smaller). */
    float radius = per_vertex ? 0.5f * size : size <= 2.0f ? 1.0f : 0.5f * size;
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

/* The attributes of a point: constant planes (every attribute is the
 * vertex's), and on a point sprite the coordinates of the units with
 * GL_COORD_REPLACE, which llvmpipe's point setup makes vary across the
 * square (lp_setup_point.c's texcoord_coef, read for the rule): s from 0
 * at its left edge to 1 at its right, t likewise from its top edge down
 * (GL_UPPER_LEFT, in the raster frame, whose y points down) or up
 * (GL_LOWER_LEFT), with slope 1/width for the width in fixed point, and
 * r = 0, q = 1 (GL 2.0 spec 3.3). */
static void point_setup(fs_context *c, fs_prim_setup *s, const fs_rvertex *v, float y, bool sprite, int64_t fw)
{
    const fs_raster_state *r = &c->raster;
    s->front = true;
    s->stipple = NULL; /* polygon stipple: filled polygons only (3.5.6) */
    s->height = c->fb.height;
    s->use_tex = r->interpolate_tex;
    s->use_fog = r->interpolate_fog;
    s->tex_mask = r->tex_mask;
    s->zoffset = 0.0f;
    s->aa_shade = NULL;
    fs_plane_constant(&s->z, v->z);
    /* Perspective-correct constants are stored premultiplied by 1/w and
     * divided by the (constant) interpolated 1/w, as llvmpipe does. */
    s->perspective = v->inv_w != 1.0f;
    fs_plane_constant(&s->w, v->inv_w);
    fs_plane_constant(&s->fog, s->perspective ? v->fog * v->inv_w : v->fog);
    /* Flat shading: the colour itself (fs_raster_state.flat_color). */
    /* Constant attributes likewise (fs_raster_state.const_attribs).  With
     * GL_POINT_SPRITE on, Mesa's fragment program reads every texture
     * coordinate as an input (any may be replaced), so none is constant. */
    s->color_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR);
    s->color2_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR2);
    s->tex_constant = sprite ? 0u : r->const_attribs / FS_ATTR_TEX(0);
    s->use_color2 = r->interpolate_color2;
    for (int k = 0; k < 4; k++) {
        fs_plane_constant(&s->color[k], s->perspective && !s->color_constant ? v->color[k] * v->inv_w : v->color[k]);
        if (k < 3)
            fs_plane_constant(&s->color2[k], s->perspective && !s->color2_constant ? v->color2[k] * v->inv_w : v->color2[k]);
        if (s->use_tex)
            FS_FOR_EACH_UNIT(u, s->tex_mask)
                fs_plane_constant(&s->tex[u][k], s->perspective && !(s->tex_constant & (1u << u)) ? v->tex[u][k] * v->inv_w
                                                                                                   : v->tex[u][k]);
    }
    if (!sprite || !s->use_tex || !(s->tex_mask & r->coord_replace))
        return;
    const float w0 = v->inv_w;
    const float step = (float)(1 << r->subpixel_bits) / (float)fw;
    /* Relative to the pixel-centre offset, as the planes are. */
    const float x0 = v->x - 0.5f, y0 = y - 0.5f;
    const float dt = r->sprite_origin == GL_LOWER_LEFT ? -step : step;
    FS_FOR_EACH_UNIT(u, s->tex_mask & r->coord_replace) {
        fs_plane *p = s->tex[u];
        p[0].dadx = step;
        p[0].dady = 0.0f;
        p[0].a0 = 0.5f - (step * x0 + 0.0f * y0);
        p[1].dadx = 0.0f;
        p[1].dady = dt;
        p[1].a0 = 0.5f - (0.0f * x0 + dt * y0);
        for (int k = 0; k < 2; k++) {
            if (s->perspective) {
                p[k].dadx *= w0;
                p[k].dady *= w0;
                p[k].a0 *= w0;
            }
            p[k].constant = false;
        }
        fs_plane_constant(&p[2], 0.0f);
        fs_plane_constant(&p[3], s->perspective ? w0 : 1.0f);
    }
}

/* A point sprite (GL 2.0 spec 3.3): llvmpipe rasterizes it as a square
 * (lp_setup_point.c's non-legacy path): the centre, offset by the half
 * pixel, and the width are snapped to fixed point (the width at least one
 * pixel), the square's left edge is x - width/2 in whole subpixels, and
 * its pixels are those whose centres lie in it by GL's fill rule as
 * llvmpipe has it for OSMesa's buffer: left and bottom (raster-frame
 * larger y) edges in, right and top edges out. */
static void raster_sprite(fs_context *c, const fs_rvertex *v, float x, float y, float size)
{
    const fs_raster_state *r = &c->raster;
    const int order = r->subpixel_bits;
    const float one = (float)(1 << order);
    int64_t fw = iround(size * one);
    if (fw < (1 << order))
        fw = 1 << order;
    int64_t x0 = iround((x - 0.5f) * one) - fw / 2;
    int64_t y0 = iround((y - 0.5f) * one) - fw / 2;
    int64_t x1 = x0 + fw, y1 = y0 + fw;
    const int64_t m = (1 << order) - 1;
    /* Columns with x0 <= px < x1, rows with y0 < py <= y1 (subpixels). */
    int64_t bx0 = fs_floor_shift(x0 + m, order), bx1 = fs_floor_shift(x1 + m, order) - 1;
    int64_t by0 = fs_floor_shift(y0, order) + 1, by1 = fs_floor_shift(y1, order);
    fs_edge_planes e;
    if (!fs_window_box(bx0, by0, bx1, by1, c->fb.width, c->fb.height, &e.x0, &e.x1, &e.y0, &e.y1))
        return;
    e.n = 0;
    fs_prim_setup s;
    point_setup(c, &s, v, y, true, fw);
    fs_raster_planes(c, &s, &e);
}

void fs_raster_point(fs_context *c, const fs_rvertex *v)
{
    if (c->par_recording) /* earlier triangles first (raster_threads.h) */
        fs_par_draw_end(c);
    fs_raster_point_sized(c, v, fs_point_size(&c->raster));
}

void fs_raster_point_sized(fs_context *c, const fs_rvertex *v, float size)
{
    if (c->par_recording) /* earlier triangles first (raster_threads.h) */
        fs_par_draw_end(c);
    const fs_raster_state *r = &c->raster;
    const int W = c->fb.width, H = c->fb.height;
    const int order = r->subpixel_bits;
    const float one = (float)(1 << order);
    float x = v->x;
    float y = r->use_y_raster ? v->y_raster : fs_raster_y(H, v->y);
    /* llvmpipe's LP_MAX_POINT_WIDTH. */
    if (size > 255.0f)
        size = 255.0f;
    if (!(fabsf(x) < 1e6f) || !(fabsf(y) < 1e6f)) {
        c->stats.triangles_culled++;
        return;
    }
    c->stats.points_rasterized++;
    /* Mesa's state tracker turns smoothing off for sprites. */
    if (r->point_sprite) {
        raster_sprite(c, v, x, y, size);
        return;
    }
    if (r->point_smooth) {
        /* The state tracker clamps its size to GL_SMOOTH_POINT_SIZE_RANGE,
         * not a vertex's. */
        bool per_vertex = fs_point_attenuated(r);
        raster_point_smooth(c, v, x, y, per_vertex || size >= 1.0f ? size : 1.0f, per_vertex);
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
    point_setup(c, &s, v, y, false, fw);
    fs_raster_planes(c, &s, &e);
}
