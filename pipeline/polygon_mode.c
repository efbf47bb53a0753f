/*
 * Polygon modes (GL 1.5 spec 3.5.4) and polygon offset on the draw-module
 * route (3.5.5), as llvmpipe does them: with a polygon mode other than
 * GL_FILL on either face, Mesa's lp_state_rasterizer.c hands triangles,
 * polygon offset and two-sided colour to the draw module's pipeline
 * stages (draw_pipe_cull.c, _offset.c, _unfilled.c, read for the rules),
 * which run on each clipped triangle in this order:
 *  - cull: facing from the sign of the unsnapped window-space
 *    determinant, e = v0 - v2, f = v1 - v2, det = ex*fy - ey*fx in
 *    llvmpipe's y-down frame (det < 0: counter-clockwise in GL's frame);
 *    a zero determinant draws nothing;
 *  - offset: for the face's mode (GL_POLYGON_OFFSET_FILL, _LINE or _POINT)
 *    o = m * factor + r * units with m = max(|dz/dx|, |dz/dy|) from the
 *    vertices' plane and r = 2 / (2^bits - 1), added to each vertex's
 *    depth, clamped to [0, 1];
 *  - polygon mode of the face: filled (the triangle goes on to llvmpipe's
 *    setup, rasterizer.c), or its edges as lines in the order
 *    v2->v0, v0->v1, v1->v2, or its vertices as points v0, v1, v2, each
 *    only when flagged (the decomposition's boundary edge and the edge
 *    flag of the vertex it starts at, fs_raster_polygon's edges).
 * The lines and points are then rasterized as any line or point
 * (rasterize_line.c, rasterize_point.c) with the triangle's colours: with
 * flat shading every vertex already carries the triangle's provoking
 * colour (clip.c), which is what the draw module's flat-shade stage does
 * before its unfilled stage.
 */
#include <math.h>
#include "rasterizer_priv.h"

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

static inline float saturate(float z) { return z < 0.0f ? 0.0f : z > 1.0f ? 1.0f : z; }

/* The draw module's offset of a triangle (positions in llvmpipe's frame). */
static float draw_offset(const fs_context *c, const fs_rvertex *const v[3], const float *x, const float *y,
                         float det)
{
    const fs_raster_state *r = &c->raster;
    float inv_det = 1.0f / det;
    float ex = x[0] - x[2], ey = y[0] - y[2], ez = v[0]->z - v[2]->z;
    float fx = x[1] - x[2], fy = y[1] - y[2], fz = v[1]->z - v[2]->z;
    float a = ey * fz - ez * fy;
    float b = ez * fx - ex * fz;
    float dzdx = fabsf(a * inv_det), dzdy = fabsf(b * inv_det);
    float m = dzdx > dzdy ? dzdx : dzdy;
    float mult = m * r->offset_factor;
    double mrd = c->fb.depth_bits > 0 ? 1.0 / (double)((1ull << c->fb.depth_bits) - 1) : 0.0;
    float units = (float)((double)r->offset_units * mrd * 2.0);
    return units + mult;
}

void fs_raster_polygon(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2,
                       unsigned edges)
{
    const fs_raster_state *r = &c->raster;
    const int H = c->fb.height;
    const fs_rvertex *const v[3] = {v0, v1, v2};
    float x[3], y[3];
    for (int i = 0; i < 3; i++) {
        x[i] = v[i]->x;
        y[i] = r->use_y_raster ? v[i]->y_raster : fs_raster_y(H, v[i]->y);
    }
    float ex = x[0] - x[2], ey = y[0] - y[2], fx = x[1] - x[2], fy = y[1] - y[2];
    float det = ex * fy - ey * fx;
    if (!(det < 0.0f || det > 0.0f)) {
        c->stats.triangles_culled++;
        return;
    }
    bool front = (det < 0.0f) == (r->front_face == GL_CCW);
    if (fs_raster_culled(r, front)) {
        c->stats.triangles_culled++;
        return;
    }
    GLenum mode = fs_raster_face_mode(r, !front);
    /* The line stipple stage comes after culling: a triangle the
     * decomposition or the clipper marks restarts the counter, the edges
     * of one triangle (and of the second of a quad) go on counting; a
     * filled triangle or a point reaching the stage restarts it too
     * (draw_pipe_stipple.c's tri and point functions). */
    if (fs_raster_line_stippled(c) && (c->raster.stipple_reset || mode != GL_LINE))
        c->raster.stipple_counter = 0;
    c->raster.stipple_reset = false;
    /* Off the draw module's stages (only its decomposition), llvmpipe's
     * triangle setup applies the fill offset.  On them, the offset stage
     * takes the enable of the first triangle's mode for every triangle
     * that follows it in the draw (draw_pipe_offset.c decides once). */
    if (c->raster.offset_latch < 0)
        c->raster.offset_latch = mode == GL_FILL ? r->offset_fill : mode == GL_LINE ? r->offset_line : r->offset_point;
    bool offset = fs_raster_draw_pipeline(r) && c->raster.offset_latch > 0;
    fs_rvertex o[3] = {*v0, *v1, *v2};
    /* The offset is added to the vertices' depth, as the draw module does. */
    if (offset) {
        float zoffset = draw_offset(c, v, x, y, det);
        for (int i = 0; i < 3; i++)
            o[i].z = saturate(o[i].z + zoffset);
    }
    switch (mode) {
    case GL_LINE:
        if (edges & 4u)
            fs_raster_line(c, &o[2], &o[0]);
        if (edges & 1u)
            fs_raster_line(c, &o[0], &o[1]);
        if (edges & 2u)
            fs_raster_line(c, &o[1], &o[2]);
        break;
    case GL_POINT:
        for (int i = 0; i < 3; i++)
            if (edges & (1u << i))
                /* With attenuation, each vertex's derived size (3.3). */
                fs_raster_point_sized(c, &o[i], fs_point_attenuated(r) ? o[i].point_size : fs_point_size(r));
        break;
    default:
        fs_raster_triangle(c, &o[0], &o[1], &o[2]);
        break;
    }
}
