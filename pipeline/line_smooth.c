/*
 * Antialiased lines (GL 1.5 spec 3.4.4, GL_LINE_SMOOTH) as llvmpipe draws
 * them (Mesa 22.3, draw_pipe_aaline.c and nir_lower_aaline_fs, read for the
 * rule; measured against OSMesa in tests/test_lines_points.c):
 *
 * The spec leaves the coverage computation to the implementation.  Mesa's
 * draw module replaces each (clipped) segment by a rectangle: the segment
 * lengthened by half a pixel at each end, and as wide as
 * 2 * hw with hw = 1 for widths up to 1, else w / 2 + 1/2.  The rectangle
 * is two triangles that the ordinary triangle setup rasterizes (fill rule,
 * attribute planes) without culling or polygon offset.  Each corner carries
 * one more attribute (x, y, z, w) = (+-hw, hw, +-hl, hl), hl = half the
 * length plus 1/2 (the length itself below a length of 1), and the fragment shader ends by multiplying the
 * fragment's alpha by
 *     clamp(y - |x|, 0, 1) * clamp(w - |z|, 0, 1),
 * a tent across the line and along it, so a pixel centre on the line gets
 * full coverage for widths of 1 and more and the end points get half.
 * Colour, depth and texture coordinates are the end points' on both
 * corners of each end (the ends are not re-interpolated).
 */
#include <math.h>
#include "rasterizer_priv.h"

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

/* nir_fsat: NaN goes to 0. */
static inline float sat(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

static void line_coverage(fs_quad *q)
{
    for (int i = 0; i < 4; i++) {
        if (!(q->mask & (1u << i)))
            continue;
        const float *a = q->aa[i];
        float across = sat(a[1] - fabsf(a[0]));
        float along = sat(a[3] - fabsf(a[2]));
        q->color[i][3] = q->color[i][3] * (across * along);
    }
}

/* The half width of the rectangle, from the line width the state tracker
 * hands on (clamped to GL_SMOOTH_LINE_WIDTH_RANGE, [1, 255] on llvmpipe). */
static float half_width(float width)
{
    if (!(width >= 1.0f))
        width = 1.0f;
    if (width > 255.0f)
        width = 255.0f;
    return width <= 1.0f ? 1.0f : 0.5f * width + 0.5f;
}

void fs_raster_line_smooth(fs_context *c, const fs_rvertex *va, const fs_rvertex *vb)
{
    const fs_raster_state *r = &c->raster;
    const int H = c->fb.height;
    fs_rvertex v[4] = {*va, *va, *vb, *vb};
    float x0 = va->x, y0 = r->use_y_raster ? va->y_raster : fs_raster_y(H, va->y);
    float x1 = vb->x, y1 = r->use_y_raster ? vb->y_raster : fs_raster_y(H, vb->y);
    if (!(fabsf(x0) < 1e6f) || !(fabsf(y0) < 1e6f) || !(fabsf(x1) < 1e6f) || !(fabsf(y1) < 1e6f)) {
        c->stats.triangles_culled++;
        return;
    }
    c->stats.lines_rasterized++;
    /* In llvmpipe's frame (y down), in its order of operations. */
    float dx = x1 - x0, dy = y1 - y0;
    float length = sqrtf(dx * dx + dy * dy);
    float ca = dx / length, sa = dy / length;
    /* Segments shorter than a pixel (the line stipple's pieces, short
     * segments of strips) get hl = length instead, so that a segment of
     * length near 0 gets coverage near 0 (draw_pipe_aaline.c of Mesa 22.3;
     * measured: it makes 30 stippled smooth scenes of 30 match, less one
     * pixel by one unit, and 5 of the 2D and perspective smooth scenes). */
    float hl = 0.5f * length;
    hl = hl < 0.5f ? 2.0f * hl : hl + 0.5f;
    float tw = half_width(r->line_width), tl = 0.5f;
    /* Corners 0, 1 at the first end, 2, 3 at the second; 0 and 2 on one
     * side of the segment, 1 and 3 on the other. */
    const float sl[4] = {-tl, -tl, tl, tl}, sw[4] = {tw, -tw, tw, -tw};
    const float ex[4] = {x0, x0, x1, x1}, ey[4] = {y0, y0, y1, y1};
    float aa[4][4];
    for (int i = 0; i < 4; i++) {
        float ox = sl[i] * ca - sw[i] * sa;
        float oy = sl[i] * sa + sw[i] * ca;
        v[i].x = ex[i] + ox;
        v[i].y_raster = ey[i] + oy;
        aa[i][0] = i & 1 ? tw : -tw;
        aa[i][1] = tw;
        aa[i][2] = i < 2 ? -hl : hl;
        aa[i][3] = hl;
    }
    /* The draw module's two triangles, (2, 1, 0) and (3, 1, 2). */
    static const int tris[2][3] = {{2, 1, 0}, {3, 1, 2}};
    fs_raster_quad_aa(c, v, aa, tris, line_coverage);
}
