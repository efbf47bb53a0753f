/*
 * Shared by the rasterizer files (rasterizer.c, rasterize_line.c,
 * rasterize_point.c): the attribute planes and the quad emitter, so lines,
 * points and triangles interpolate and quantise exactly the same way.
 *
 * The model follows llvmpipe (Mesa 22.3, lp_setup_*.c and lp_state_setup.c,
 * read for facts only): primitives are set up in llvmpipe's own window frame,
 * which for OSMesa's window-system buffer has y pointing down
 * (y_raster = height - y_gl), and every float operation is done in the same
 * order and precision so that depth and colours come out bit-identical.
 */
#ifndef FS_RASTERIZER_PRIV_H
#define FS_RASTERIZER_PRIV_H
#include <stdint.h>
#include <stdbool.h>
#include "context.h"

/* An attribute plane a(x, y) = a0 + dadx*x + dady*y at integer pixel
 * coordinates of the raster frame (the pixel-centre half offset is folded
 * into a0, as llvmpipe's setup does). */
typedef struct fs_plane {
    float a0, dadx, dady;
    bool constant;  /* dadx == dady == 0: a(x, y) == a0 exactly */
} fs_plane;

typedef struct fs_prim_setup {
    fs_plane z, w, color[4];
    fs_plane tex[FS_MAX_TEXTURE_UNITS][4]; /* the units in tex_mask */
    fs_plane fog;        /* the fog coordinate, when use_fog */
    bool use_fog;        /* interpolate it (fs_raster_state.interpolate_fog) */
    fs_plane color2[3];  /* the secondary colour, when use_color2 (as color[]) */
    bool use_color2;
    float zoffset;       /* polygon offset, added after interpolation */
    bool perspective;    /* false when every 1/w is 1: the division is exact then */
    bool color_constant; /* flat shading or a constant colour: colour planes constant, not divided by 1/w */
    bool color2_constant; /* the same for the secondary colour */
    unsigned tex_constant; /* units whose coordinates are constants (fs_raster_state.const_attribs) */
    bool use_tex;        /* interpolate texture coordinates */
    unsigned tex_mask;   /* of these units (fs_raster_state.tex_mask) */
    bool front;
    int height;          /* framebuffer height, for the y flip */
    /* Antialiased lines and points (line_smooth.c, rasterize_point.c):
     * llvmpipe draws them as triangles carrying one more generic attribute,
     * interpolated like a texture coordinate into fs_quad.aa, from which
     * the primitive's coverage rule (aa_shade, after texturing) scales the
     * fragment's alpha or kills it.  aa_shade NULL: no such attribute. */
    fs_plane aa[4];
    void (*aa_shade)(fs_quad *q);
    /* Filled polygons with GL_POLYGON_STIPPLE on: fs_raster_state.stipple,
     * which masks each quad; NULL otherwise (lines, points). */
    const uint32_t *stipple;
} fs_prim_setup;

/* Quantises a window depth like llvmpipe's unorm depth conversion. */
uint32_t fs_raster_quantize_depth(float z, int depth_bits);

/* Fills q->z, colours (and texture coordinates) for the pixels in q->mask,
 * counts the quad and hands it to the per-fragment operations. */
void fs_raster_emit_quad(fs_context *c, const fs_prim_setup *s, fs_quad *q);

/* A filled triangle (fs_raster_triangle's setup and coverage) whose
 * vertices v[i] also carry the attribute aa[i] (fs_prim_setup.aa_shade):
 * the triangles of a smooth line or point, which llvmpipe's draw module
 * hands to the triangle setup with culling, polygon offset and stipple
 * off (draw_get_rasterizer_no_cull). */
void fs_raster_triangle_aa(fs_context *c, const fs_rvertex *const v[3], const float aa[3][4],
                           void (*aa_shade)(fs_quad *q));

/* The two triangles tris[0], tris[1] (indices into v and aa) of a smooth
 * line's or point's quad, through fs_raster_triangle_aa. */
void fs_raster_quad_aa(fs_context *c, const fs_rvertex v[4], const float aa[4][4], const int tris[2][3],
                       void (*aa_shade)(fs_quad *q));

/* A segment with GL_LINE_SMOOTH (line_smooth.c), from fs_raster_line. */
void fs_raster_line_smooth(fs_context *c, const fs_rvertex *va, const fs_rvertex *vb);

/* Flat (constant) planes, used by points and lines whose attributes llvmpipe
 * sets up per primitive. */
void fs_plane_constant(fs_plane *p, float v);

/* A convex region given by edge planes in the raster frame, as llvmpipe
 * bins lines (4 planes) and points (4 planes): pixel (x, y) is inside when
 * c - dcdx*x + dcdy*y > 0 for every plane (fill-rule bias in c, dcdx and
 * dcdy already scaled to whole pixels). */
typedef struct fs_edge_planes {
    int n;
    int64_t c[4], dcdx[4], dcdy[4];
    int x0, x1, y0, y1; /* raster-frame bounding box, inclusive, on screen */
} fs_edge_planes;

/* The inclusive box of fixed-point corners (x[i], y[i]), i < n. */
static inline void fs_corner_box(const int64_t *x, const int64_t *y, int n, int64_t *minx, int64_t *maxx,
                                 int64_t *miny, int64_t *maxy)
{
    *minx = *maxx = x[0];
    *miny = *maxy = y[0];
    for (int i = 1; i < n; i++) {
        if (x[i] < *minx) *minx = x[i];
        if (x[i] > *maxx) *maxx = x[i];
        if (y[i] < *miny) *miny = y[i];
        if (y[i] > *maxy) *maxy = y[i];
    }
}

/* Pixel ownership (GL 1.5 spec 4.1.1): clips the inclusive pixel box to the
 * W x H window into *x0..*y1; false when nothing of it is on screen. */
static inline bool fs_window_box(int64_t bx0, int64_t by0, int64_t bx1, int64_t by1, int W, int H, int *x0,
                                 int *x1, int *y0, int *y1)
{
    if (bx0 < 0) bx0 = 0;
    if (by0 < 0) by0 = 0;
    if (bx1 > W - 1) bx1 = W - 1;
    if (by1 > H - 1) by1 = H - 1;
    if (bx0 > bx1 || by0 > by1)
        return false;
    *x0 = (int)bx0;
    *x1 = (int)bx1;
    *y0 = (int)by0;
    *y1 = (int)by1;
    return true;
}

/* Adds the fill-rule bias and scales one plane through fixed-point corners
 * (xa, ya) -> (xb, yb) (llvmpipe's plane setup shared by all primitives). */
void fs_edge_plane(fs_edge_planes *e, int i, int64_t xa, int64_t ya, int64_t xb, int64_t yb, int order);

/* Emits the quads of the region (per-pixel evaluation; lines and points are
 * thin, so their bounding boxes are small or sparse). */
void fs_raster_planes(fs_context *c, const fs_prim_setup *s, const fs_edge_planes *e);

/* Floor division by 2^s that is defined for negative values. */
static inline int64_t fs_floor_shift(int64_t v, int s)
{
    return v >= 0 ? v >> s : -(((-v) - 1) >> s) - 1;
}

/* The vertical frame flip between GL window coordinates and llvmpipe's raster
 * frame: OSMesa renders to a window-system buffer, which Mesa's state tracker
 * draws upside down and OSMesa flips back on read (measured: see
 * tests/test_rasterizer.c, test fill_convention). */
static inline float fs_raster_y(int height, float y_gl) { return (float)height - y_gl; }
static inline int fs_raster_row_to_gl(int height, int row) { return height - 1 - row; }
#endif
