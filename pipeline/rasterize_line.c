/*
 * Line segments (GL 1.5 spec 3.4, 3.4.2 for wide lines), modelled on
 * llvmpipe's lp_setup_line.c (Mesa 22.3, read for the rules): a
 * non-antialiased line of any width is a parallelogram of width w
 * (rounded half away from zero to an integer, at least 1) along the minor
 * axis, centred on the segment (GL's wide-line rule),
 * whose end edges are moved by half a pixel so that the diamond-exit rule
 * (3.4.1) decides whether the first and last pixels are drawn; it is then
 * rasterized with the triangle fill convention.  Attributes are planes along
 * the major axis ("preferred wide-lines formula").
 */
#include <math.h>
#include "rasterizer_priv.h"
#include "raster_threads.h"

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

/* llvmpipe's util_iround on x86-64: round half away from zero. */
static inline int64_t iround(float f)
{
    return f >= 0.0f ? (int64_t)(f + 0.5f) : (int64_t)(f - 0.5f);
}

static inline bool sgn(float x) { return x >= 0.0f; }
static inline float fracf(float f) { return f - floorf(f); }

typedef struct line_info {
    float dx, dy, ooa;
    float x1, y1;   /* first vertex position (before any swap) */
} line_info;

/* lp_setup_line.c linear_coef: planes relative to the first vertex. */
static void line_coef(fs_plane *p, const line_info *li, float a1, float a2)
{
    float da21 = a1 - a2;
    float t1 = da21 * li->dx;
    float dadx = t1 * li->ooa;
    float t2 = da21 * li->dy;
    float dady = t2 * li->ooa;
    float ax = dadx * (li->x1 - 0.5f);
    float ay = dady * (li->y1 - 0.5f);
    float sum = ax + ay;
    p->a0 = a1 - sum;
    p->dadx = dadx;
    p->dady = dady;
    p->constant = dadx == 0.0f && dady == 0.0f && p->a0 == a1;
}

/* The n planes of a colour (primary, or the secondary's r, g, b): the
 * provoking (last) vertex's as constants when flat, else divided by w when
 * the line has perspective. */
static void line_color_planes(fs_plane *p, int n, const line_info *li, const float *ca, const float *cb,
                              const fs_rvertex *va, const fs_rvertex *vb, const fs_prim_setup *s, bool constant)
{
    for (int k = 0; k < n; k++) {
        if (constant)
            fs_plane_constant(&p[k], cb[k]);
        else if (s->perspective)
            line_coef(&p[k], li, ca[k] * va->inv_w, cb[k] * vb->inv_w);
        else
            line_coef(&p[k], li, ca[k], cb[k]);
    }
}

/* One segment, as llvmpipe's line setup draws it. */
static void raster_segment(fs_context *c, const fs_rvertex *va, const fs_rvertex *vb)
{
    const fs_raster_state *r = &c->raster;
    const int W = c->fb.width, H = c->fb.height;
    const int order = r->subpixel_bits;
    const float one = (float)(1 << order);
    if (r->line_smooth) {
        fs_raster_line_smooth(c, va, vb); /* GL_LINE_SMOOTH: line_smooth.c */
        return;
    }
    /* Any width: the parallelogram's minor-axis extent is the width
     * rounded to whole pixels, at least one (llvmpipe draws wide lines
     * itself: its draw module's wide-line threshold is never reached). */
    float width = r->line_width > 1.0f ? r->line_width : 1.0f;
    float p1x = va->x, p1y = r->use_y_raster ? va->y_raster : fs_raster_y(H, va->y);
    float p2x = vb->x, p2y = r->use_y_raster ? vb->y_raster : fs_raster_y(H, vb->y);
    if (!(fabsf(p1x) < 1e6f) || !(fabsf(p1y) < 1e6f) || !(fabsf(p2x) < 1e6f) || !(fabsf(p2y) < 1e6f)) {
        c->stats.triangles_culled++;
        return;
    }
    c->stats.lines_rasterized++;
    float dx = p1x - p2x, dy = p1y - p2y;
    float area = dx * dx + dy * dy;
    if (area == 0.0f)
        return;
    line_info li;
    li.ooa = 1.0f / area;
    li.dx = dx;
    li.dy = dy;
    li.x1 = p1x;
    li.y1 = p1y;

    /* Diamond-exit tests in llvmpipe's frame (y down), with x1diff etc. the
     * offsets of the end points from their pixel centres. */
    float x1diff = p1x - floorf(p1x) - 0.5f, y1diff = p1y - floorf(p1y) - 0.5f;
    float x2diff = p2x - floorf(p2x) - 0.5f, y2diff = p2y - floorf(p2y) - 0.5f;
    int64_t fw = iround(width) * (1 << order);
    float x_off = 0, y_off = 0, x_off_end = 0, y_off_end = 0;
    float v1x = p1x, v1y = p1y, v2x = p2x, v2y = p2y;
    int64_t x[4], y[4];
    bool draw_start, draw_end, will_start, will_end;
    if (fabsf(dx) >= fabsf(dy)) {
        /* x-major */
        float dydx = dy / dx;
        if (y2diff == -0.5f && dy < 0.0f)
            y2diff = 0.5f;
        if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
            draw_start = true;
        else if (sgn(x1diff) == sgn(-dx))
            draw_start = false;
        else if (sgn(-y1diff) != sgn(dy))
            draw_start = true;
        else {
            float yi = fracf(p1y) + x1diff * dydx;
            draw_start = yi < 1.0f && yi > 0.0f;
        }
        if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
            draw_end = false;
        else if (sgn(x2diff) != sgn(-dx))
            draw_end = false;
        else if (sgn(-y2diff) == sgn(dy))
            draw_end = true;
        else {
            float yi = fracf(p2y) + x2diff * dydx;
            draw_end = yi < 1.0f && yi > 0.0f;
        }
        float t = dydx * dydx;
        float t1 = 1.0f + t;
        li.dx = li.dx * t1;
        li.dy = 0.0f;
        if (dx < 0.0f) {
            v1x = p2x; v1y = p2y; v2x = p1x; v2y = p1y;
            will_start = x1diff <= 0.0f;
            if (will_start != draw_start) {
                x_off_end = -x1diff - 0.5f;
                y_off_end = x_off_end * dydx;
            }
            /* An end on its pixel centre's column counts as drawn
             * already (measured: lines between pixel centres with
             * dx < 0 then move that end by half a pixel, which decides
             * the pixel centres the edges pass exactly through). */
            will_end = x2diff >= 0.0f;
            if (will_end != draw_end) {
                x_off = -x2diff - 0.5f;
                y_off = x_off * dydx;
            }
        } else {
            will_start = x1diff > 0.0f;
            if (will_start != draw_start) {
                x_off = -x1diff + 0.5f;
                y_off = x_off * dydx;
            }
            will_end = x2diff <= 0.0f;
            if (will_end != draw_end) {
                x_off_end = -x2diff + 0.5f;
                y_off_end = x_off_end * dydx;
            }
        }
        x[0] = iround((v1x + x_off - 0.5f) * one);
        x[1] = iround((v2x + x_off_end - 0.5f) * one);
        x[2] = x[1];
        x[3] = x[0];
        y[0] = iround((v1y + y_off - 0.5f) * one) - fw / 2;
        y[1] = iround((v2y + y_off_end - 0.5f) * one) - fw / 2;
        y[2] = y[1] + fw;
        y[3] = y[0] + fw;
    } else {
        /* y-major */
        float dxdy = dx / dy;
        if (x2diff == -0.5f && dx < 0.0f)
            x2diff = 0.5f;
        if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
            draw_start = true;
        else if (sgn(-y1diff) == sgn(dy))
            draw_start = false;
        else if (sgn(x1diff) != sgn(-dx))
            draw_start = true;
        else {
            float xi = fracf(p1x) + y1diff * dxdy;
            draw_start = xi < 1.0f && xi > 0.0f;
        }
        if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
            draw_end = false;
        else if (sgn(-y2diff) != sgn(dy))
            draw_end = false;
        else if (sgn(x2diff) == sgn(-dx))
            draw_end = true;
        else {
            float xi = fracf(p2x) + y2diff * dxdy;
            draw_end = xi < 1.0f && xi >= 0.0f;
        }
        float t = dxdy * dxdy;
        float t1 = 1.0f + t;
        li.dx = 0.0f;
        li.dy = li.dy * t1;
        /* GL's bottom-left convention is llvmpipe's bottom_edge_rule. */
        if (dy > 0.0f) {
            v1x = p2x; v1y = p2y; v2x = p1x; v2y = p1y;
            will_start = y1diff >= 0.0f;
            will_end = y2diff <= 0.0f; /* as for x-major lines */
            if (will_start != draw_start) {
                y_off_end = -y1diff + 0.5f;
                x_off_end = y_off_end * dxdy;
            }
            if (will_end != draw_end) {
                y_off = -y2diff + 0.5f;
                x_off = y_off * dxdy;
            }
        } else {
            will_start = y1diff < 0.0f;
            will_end = y2diff >= 0.0f;
            if (will_start != draw_start) {
                y_off = -y1diff - 0.5f;
                x_off = y_off * dxdy;
            }
            if (will_end != draw_end) {
                y_off_end = -y2diff - 0.5f;
                x_off_end = y_off_end * dxdy;
            }
        }
        x[0] = iround((v1x + x_off - 0.5f) * one) - fw / 2;
        x[1] = iround((v2x + x_off_end - 0.5f) * one) - fw / 2;
        x[2] = x[1] + fw;
        x[3] = x[0] + fw;
        y[0] = iround((v1y + y_off - 0.5f) * one);
        y[1] = iround((v2y + y_off_end - 0.5f) * one);
        y[2] = y[1];
        y[3] = y[0];
    }

    /* Bounding box (llvmpipe rounds both ends up for lines). */
    const int adj = 1;
    int64_t minx, maxx, miny, maxy;
    fs_corner_box(x, y, 4, &minx, &maxx, &miny, &maxy);
    const int64_t round_up = (1 << order) - 1;
    int64_t bx0 = fs_floor_shift(minx + round_up, order);
    int64_t bx1 = fs_floor_shift(maxx + round_up, order) - 1;
    int64_t by0 = fs_floor_shift(miny + round_up + adj, order);
    int64_t by1 = fs_floor_shift(maxy + round_up + adj, order) - 1;
    fs_edge_planes e;
    if (!fs_window_box(bx0, by0, bx1, by1, W, H, &e.x0, &e.x1, &e.y0, &e.y1))
        return;
    e.n = 4;
    for (int i = 0; i < 4; i++)
        fs_edge_plane(&e, i, x[i], y[i], x[(i + 1) & 3], y[(i + 1) & 3], order);

    /* Attribute planes from the vertices in their original order. */
    fs_prim_setup s;
    s.front = true;
    s.stipple = NULL; /* polygon stipple: filled polygons only (3.5.6) */
    s.height = H;
    s.use_tex = r->interpolate_tex;
    s.use_fog = r->interpolate_fog;
    s.tex_mask = r->tex_mask;
    s.zoffset = 0.0f;
    s.aa_shade = NULL;
    line_coef(&s.z, &li, va->z, vb->z);
    s.perspective = !(va->inv_w == 1.0f && vb->inv_w == 1.0f);
    if (s.perspective)
        line_coef(&s.w, &li, va->inv_w, vb->inv_w);
    if (s.use_fog && s.perspective)
        line_coef(&s.fog, &li, va->fog * va->inv_w, vb->fog * vb->inv_w);
    else if (s.use_fog)
        line_coef(&s.fog, &li, va->fog, vb->fog);
    /* Flat shading: the provoking colour as a constant (fs_raster_state.flat_color). */
    /* Constant attributes likewise (fs_raster_state.const_attribs). */
    s.color_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR);
    s.color2_constant = r->flat_color || (r->const_attribs & FS_ATTR_COLOR2);
    s.tex_constant = r->const_attribs / FS_ATTR_TEX(0);
    s.use_color2 = r->interpolate_color2;
    line_color_planes(s.color, 4, &li, va->color, vb->color, va, vb, &s, s.color_constant);
    if (s.use_color2)
        line_color_planes(s.color2, 3, &li, va->color2, vb->color2, va, vb, &s, s.color2_constant);
    for (int k = 0; k < 4; k++) {
        if (s.use_tex)
            FS_FOR_EACH_UNIT(u, s.tex_mask) {
                if (s.tex_constant & (1u << u))
                    fs_plane_constant(&s.tex[u][k], va->tex[u][k]);
                else if (s.perspective)
                    line_coef(&s.tex[u][k], &li, va->tex[u][k] * va->inv_w, vb->tex[u][k] * vb->inv_w);
                else
                    line_coef(&s.tex[u][k], &li, va->tex[u][k], vb->tex[u][k]);
            }
    }
    fs_raster_planes(c, &s, &e);
}

/*
 * Line stipple (GL 1.5 spec 3.4.2) as llvmpipe does it: its draw module's
 * stipple stage (draw_pipe_stipple.c, Mesa 22.3, read for the rule) runs
 * after clipping and polygon mode and before the antialiased-line stage,
 * and cuts each segment into the pieces whose pixels the pattern keeps,
 * which the line setup then draws as ordinary segments (their ends by the
 * diamond-exit rule, their width, their smoothing):
 *  - the segment's length l is max(|dx|, |dy|) in window coordinates (the
 *    major axis, as the spec counts), the Euclidean length for smooth
 *    lines; n = ceil(l) pixels, none when l is not finite;
 *  - pixel i (0 <= i < n) is on when bit ((s + i) / r) mod 16 of the
 *    pattern is 1, with s the stipple counter and r the repeat;
 *  - each run of on pixels from i0 to i1 (exclusive) becomes the piece
 *    from parameter i0 / l to i1 / l (to 1 for a run that reaches the
 *    end), its vertices interpolated linearly in window space (positions,
 *    1/w, colours, texture coordinates, fog alike); an end at parameter 0
 *    or 1 is the segment's own vertex;
 *  - then s += n.
 * The counter is set to 0 where a primitive starts (fs_raster_state.
 * stipple_reset): each segment of GL_LINES, the first of a strip or loop
 * (so a loop's closing segment goes on counting), and for polygon edges
 * each triangle the draw module marks (every triangle of GL_TRIANGLES,
 * strips and fans, the first of each quad, the first of a polygon, the
 * first of each clipped triangle's fan; polygon_mode.c).  A segment
 * wholly outside the view volume never reaches the stage: its mark is
 * lost and the counter runs on from the previous draw.
 * Mesa enables the stage only when the pattern is not all ones.
 */
static inline bool stipple_on(unsigned counter, unsigned pattern, unsigned repeat)
{
    return (pattern >> ((counter / repeat) & 0xfu)) & 1u;
}

bool fs_raster_line_stippled(const fs_context *c)
{
    return c->raster.line_stipple && (c->st.line_stipple_pattern & 0xffffu) != 0xffffu;
}

/* The vertex at parameter t from a to b (draw_pipe_stipple.c's
 * screen_interp); y_raster is llvmpipe's y-down window y. */
static void stipple_vertex(fs_rvertex *d, float t, const fs_rvertex *a, const fs_rvertex *b, int units)
{
#define L(f) d->f = a->f + t * (b->f - a->f)
    *d = *a;
    L(x);
    L(y);
    L(y_raster);
    L(z);
    L(inv_w);
    L(fog);
    for (int k = 0; k < 4; k++) {
        L(color[k]);
        L(color2[k]);
        for (int u = 0; u < units; u++)
            L(tex[u][k]);
    }
#undef L
}

static void stipple_piece(fs_context *c, const fs_rvertex *a, const fs_rvertex *b, float t0, float t1)
{
    fs_rvertex p0, p1;
    const int units = c->raster.tex_units;
    if (t0 > 0.0f)
        stipple_vertex(&p0, t0, a, b, units);
    if (t1 < 1.0f)
        stipple_vertex(&p1, t1, a, b, units);
    raster_segment(c, t0 > 0.0f ? &p0 : a, t1 < 1.0f ? &p1 : b);
}

void fs_raster_line(fs_context *c, const fs_rvertex *va, const fs_rvertex *vb)
{
    if (c->par_recording) /* earlier triangles first (raster_threads.h) */
        fs_par_draw_end(c);
    fs_raster_state *r = &c->raster;
    if (!fs_raster_line_stippled(c)) {
        raster_segment(c, va, vb);
        return;
    }
    if (r->stipple_reset)
        r->stipple_counter = 0;
    r->stipple_reset = false;
    /* Positions in llvmpipe's frame, which the pieces are cut in. */
    const int H = c->fb.height;
    fs_rvertex a = *va, b = *vb;
    if (!r->use_y_raster) {
        a.y_raster = fs_raster_y(H, va->y);
        b.y_raster = fs_raster_y(H, vb->y);
    }
    float length;
    if (r->line_smooth) {
        float dx = b.x - a.x, dy = b.y_raster - a.y_raster;
        length = sqrtf(dx * dx + dy * dy);
    } else {
        float dx = a.x > b.x ? a.x - b.x : b.x - a.x;
        float dy = a.y_raster > b.y_raster ? a.y_raster - b.y_raster : b.y_raster - a.y_raster;
        length = dx > dy ? dx : dy;
    }
    int n = isfinite(length) ? (int)ceilf(length) : 0;
    const unsigned pattern = c->st.line_stipple_pattern, repeat = (unsigned)c->st.line_stipple_repeat;
    const bool saved_yr = r->use_y_raster;
    r->use_y_raster = true;
    bool on = false;
    int start = 0;
    for (int i = 0; i < n; i++) {
        bool bit = stipple_on(r->stipple_counter + (unsigned)i, pattern, repeat);
        if (bit == on)
            continue;
        if (on)
            stipple_piece(c, &a, &b, (float)start / length, (float)i / length);
        else
            start = i;
        on = bit;
    }
    if (on && (float)start < length)
        stipple_piece(c, &a, &b, (float)start / length, 1.0f);
    r->use_y_raster = saved_yr;
    r->stipple_counter += (unsigned)n;
}
