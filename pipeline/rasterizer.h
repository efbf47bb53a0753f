/*
 * Rasterization (GL 1.5 spec 3.3-3.5): triangles, lines and points from
 * window-space vertices to 2x2 fragment quads.
 *
 * Interface contract between stages:
 *   vertex stage -> rasterizer: fs_rvertex in window coordinates, after
 *     clipping, perspective division, viewport and depth-range transforms,
 *     lighting and clamping.  Flat shading is already applied (the vertex stage
 *     copies the provoking vertex's colour), so the rasterizer always
 *     interpolates.
 *   rasterizer -> per-fragment operations: fs_quad, handed to
 *     fs_fragment_quad() (fragment_ops.h).
 */
#ifndef FS_RASTERIZER_H
#define FS_RASTERIZER_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

/* GL_MAX_TEXTURE_UNITS: the fixed-function texture units, as llvmpipe's
 * compatibility context reports them (measured on OSMesa: GL_MAX_TEXTURE_UNITS
 * and GL_MAX_TEXTURE_COORDS 8).  Each has its own coordinates, matrix
 * stack, binding and environment (GL 1.5 spec 2.7, 2.10.2, 3.8.13). */
#define FS_MAX_TEXTURE_UNITS 8
/* Runs the statement after it with u = each set bit of mask, lowest first
 * (texturing applies unit after unit, 3.8.13). */
#define FS_FOR_EACH_UNIT(u, mask)                                                   \
    for (unsigned u##_left_ = (mask), u = 0; u##_left_ && ((u = (unsigned)__builtin_ctz(u##_left_)), 1); \
         u##_left_ &= u##_left_ - 1)

typedef struct fs_rvertex {
    float x, y;     /* window coordinates in pixels, GL y-up */
    float z;        /* window depth in [0,1] (after glDepthRange) */
    float inv_w;    /* 1 / clip w, for perspective-correct interpolation */
    float color[4]; /* RGBA, clamped to [0,1] */
    /* s, t, r, q of each texture unit (after its texture matrix); only the
     * units below fs_raster_state.tex_units are set. */
    float tex[FS_MAX_TEXTURE_UNITS][4];
    /* Optional, read only when fs_raster_state.use_y_raster is set: the
     * window y in llvmpipe's y-down frame exactly as llvmpipe computes it,
     * fma(y_ndc, -height/2, fb_height - (viewport_y + height/2)).  Deriving
     * it from y (fb_height - y) rounds twice, which moves about 1 depth
     * value in 20 by one unit and rare edge pixels when the viewport
     * scale makes y_ndc * height/2 inexact. */
    float y_raster;
    /* Fog (GL 1.5 spec 3.10), read only while fs_raster_state.interpolate_fog
     * is set: the vertex's fog coordinate c (pipeline/fog.c). */
    float fog;
    /* The secondary colour (3.9), read only while interpolate_color2 is set. */
    float color2[4];
    /* The vertex's derived point size (GL 1.5 spec 3.3), set by the vertex
     * stage and read only for points while the distance attenuation is on
     * (fs_point_attenuated). */
    float point_size;
} fs_rvertex;

/* One texture unit's coordinates in a quad. */
typedef struct fs_quad_tex {
    float tex[4][4];    /* [pixel][strq], interpolated perspective-correctly (not divided by q) */
    /* Only when the framebuffer height is odd: strq of the two pixels of
     * the row below the quad (y - 1) and above it (y + 2).  llvmpipe's 2x2
     * quads are aligned in its y-down frame, so with an odd height they
     * pair row y with y - 1 and row y + 1 with y + 2; lambda comes from
     * those pairs (units/texture_sample.c). */
    float tex_below[2][4], tex_above[2][4];
    /* Only while fs_raster_state.tex_pair_lod is set: strq of the quad
     * that shares llvmpipe's 8-wide vector with this one (the other half
     * of its 4x4 block's row of quads: columns (x ^ 2), (x ^ 2) + 1) in
     * rows y - 1 .. y + 2, as [row - (y - 1)][column] (rows y - 1 and
     * y + 2 only for odd heights).  Its lambda decides how llvmpipe's
     * float path samples this quad (units/texture_sample.c). */
    float tex_pair[4][2][4];
} fs_quad_tex;

/* Pixel i of a quad: 0 = (x,y), 1 = (x+1,y), 2 = (x,y+1), 3 = (x+1,y+1). */
typedef struct fs_quad {
    int x, y;           /* lower-left pixel; both even */
    unsigned mask;      /* bit i set: pixel i is covered */
    bool front_facing;
    uint32_t z[4];      /* depth in the depth buffer's fixed-point units */
    float color[4][4];  /* [pixel][rgba] in [0,1] */
    /* The coordinates of the texture units in fs_raster_state.tex_mask
     * (the others are left unset). */
    fs_quad_tex unit[FS_MAX_TEXTURE_UNITS];
    /* Only while fs_raster_state.interpolate_fog is set: the fog coordinate
     * of each covered pixel, interpolated perspective-correctly like a
     * colour (pipeline/fog.c applies it after texturing, GL 1.5 spec 3.10). */
    float fog[4];
    /* Only while fs_raster_state.interpolate_color2 is set: the secondary
     * colour's r, g, b of each covered pixel, interpolated as the colour is
     * (pipeline/color_sum.c adds it after texturing, GL 1.5 spec 3.9). */
    float color2[4][3];
    /* Only for smooth lines and points (fs_prim_setup.aa_shade): their
     * coverage attribute at each covered pixel. */
    float aa[4][4];
} fs_quad;

/* Rasterizer state set by glCullFace, glFrontFace, glPolygonOffset,
 * glPolygonMode, glPointSize, glLineWidth and glEnable. */
typedef struct fs_raster_state {
    bool cull_enabled;          /* GL_CULL_FACE */
    GLenum cull_mode;           /* GL_BACK */
    GLenum front_face;          /* GL_CCW */
    bool offset_fill;           /* GL_POLYGON_OFFSET_FILL */
    bool offset_line, offset_point; /* GL_POLYGON_OFFSET_LINE, _POINT (3.5.5) */
    /* The draw module's offset stage decides whether to offset from the
     * first triangle it sees after a flush (per draw here): -1 undecided,
     * else 0 or 1 for the rest of the draw (polygon_mode.c). */
    signed char offset_latch;
    float offset_factor, offset_units;
    GLenum polygon_mode[2];     /* front, back: GL_FILL */
    float point_size, line_width;
    /* GL 1.4 point parameters (GL 1.5 spec 3.3, pipeline/point_state.c):
     * GL_POINT_SIZE_MIN, _MAX, GL_POINT_FADE_THRESHOLD_SIZE and the
     * distance attenuation's a, b, c; and GL 2.0's point sprites (GL 2.0
     * spec 3.3): GL_POINT_SPRITE, GL_POINT_SPRITE_COORD_ORIGIN and each
     * unit's GL_COORD_REPLACE (bit u). */
    float point_size_min, point_size_max, point_fade_threshold;
    float point_atten[3];
    bool point_sprite;
    GLenum sprite_origin;
    unsigned coord_replace;
    /* GL_LINE_SMOOTH and GL_POINT_SMOOTH (3.4.4, 3.3.1): llvmpipe's
     * coverage (line_smooth.c, rasterize_point.c). */
    bool line_smooth, point_smooth;
    /* GL_LINE_STIPPLE (3.4.2; pattern and repeat in fs_stored_state) and
     * the stipple counter s, as llvmpipe's draw module keeps it
     * (rasterize_line.c): whole pixels counted along each segment's major
     * axis, kept across segments and draws, and set to 0 only when a
     * primitive that starts a new stipple reaches the stipple stage:
     * stipple_reset is that mark, set by primitive assembly (primitive.c,
     * clip.c) for the line or triangle it hands on next. */
    bool line_stipple;
    bool stipple_reset;
    unsigned stipple_counter;
    /* GL_POLYGON_SMOOTH (3.5.6): stored only; llvmpipe draws polygons the
     * same with it (measured on OSMesa, blending on and off: identical
     * bytes), having no antialiased-triangle stage. */
    bool polygon_smooth;
    /* GL_POLYGON_STIPPLE and glPolygonStipple's pattern (3.5.6): row r is
     * window rows y with y mod 32 = r, bit k of it window columns x with x
     * mod 32 = k; a fragment of a filled polygon is kept only where the
     * bit is 1.  Initially all ones (table 6.14). */
    bool polygon_stipple;
    uint32_t stipple[32];
    int subpixel_bits;          /* from the config, default 8 */
    /* Set by texturing when a texture unit is enabled: interpolating the four
     * texture coordinates costs as much as the colour, so it is skipped
     * while nothing reads them (fs_quad.unit is then left unset).
     * tex_mask: bit u for each enabled unit u, whose coordinates the
     * rasterizer interpolates; tex_units: 1 + the highest enabled unit (at
     * least 1), the units whose coordinates the vertex stage carries. */
    bool interpolate_tex;
    unsigned tex_mask;
    int tex_units;
    /* Set by texturing when fs_quad.tex_pair is needed (see there). */
    bool tex_pair_lod;
    /* Set by the vertex stage while GL_FOG is enabled: the fog coordinate
     * is interpolated into fs_quad.fog (skipped otherwise). */
    bool interpolate_fog;
    /* Set by the vertex stage while the colour sum is on (color_sum.c). */
    bool interpolate_color2;
    /* Selects the plain per-pixel reference rasterizer instead of the
     * incremental one; both must give identical quads (tests hold them
     * equal). */
    bool reference_path;
    /* The vertex stage fills fs_rvertex.y_raster (see there). */
    bool use_y_raster;
    /* GL_FLAT shading (GL 1.5 spec 2.14.7), set by the vertex stage per
     * draw: every vertex carries the provoking colour, which llvmpipe
     * uses as a constant (LP_INTERP_CONSTANT) instead of interpolating it
     * with perspective, where (c/w)/(1/w) need not give c back. */
    bool flat_color;
    /* The attributes (FS_ATTR_*) llvmpipe takes as constants for the draw,
     * set by the vertex stage per draw (fs_vs_constant_attribs): Mesa's
     * fixed-function fragment program reads an input the vertex stage does
     * not vary (no array, not given between Begin and End, not computed by
     * lighting, texgen or a texture matrix) from the current value instead
     * of interpolating it, so no (a/w)/(1/w) rounding. */
    unsigned const_attribs;
    /* The CPU has FMA instructions: attribute evaluation uses them (llvmpipe
     * does), otherwise an exact-in-practice double emulation.  Set by
     * fs_raster_state_init; tests clear it to compare the two. */
    bool has_fma;
    /* ... and AVX2 as well: the vertex stage transforms positions 8 at a
     * time (same bits as one at a time; tests clear it to compare). */
    bool has_avx2;
    /* Threaded rasterization (raster_threads.h): while band_n > 1 this
     * thread emits only the quads of GL rows y with
     * (y >> FS_PAR_BAND_SHIFT) mod band_n == band_i; 0 (always, on one
     * thread): every quad. */
    int band_n, band_i;
} fs_raster_state;

/* Whether a polygon of this facing is culled (GL 1.5 spec 3.5.1: culling
 * by facing). */
static inline bool fs_raster_culled(const fs_raster_state *r, bool front)
{
    if (!r->cull_enabled)
        return false;
    switch (r->cull_mode) {
    case GL_FRONT: return front;
    case GL_BACK: return !front;
    case GL_FRONT_AND_BACK: return true;
    default: return false;
    }
}

/* fs_raster_state.const_attribs, and the attributes a draw varies
 * (fs_prim_state.vtx_attribs): primary colour, secondary colour, the
 * texture coordinates of unit u. */
#define FS_ATTR_COLOR 1u
#define FS_ATTR_COLOR2 2u
#define FS_ATTR_TEX(u) (4u << (u))

void fs_raster_state_init(fs_raster_state *r, int subpixel_bits);

/* Whether triangles take llvmpipe's draw-module route (Mesa's
 * lp_state_rasterizer.c hands polygon modes POINT and LINE to the draw
 * module's pipeline stages): polygon offset and the polygon mode are then
 * applied to the clipped triangle's vertices (pipeline/polygon_mode.c),
 * not by the triangle setup. */
/* The polygon mode llvmpipe uses for a face: Mesa's state tracker gives a
 * culled face the other face's mode (so culling the face whose mode is
 * not GL_FILL leaves the triangle setup's route). */
static inline GLenum fs_raster_face_mode(const fs_raster_state *r, bool back)
{
    GLenum front_mode = r->polygon_mode[0], back_mode = r->polygon_mode[1];
    if (r->cull_enabled && r->cull_mode != GL_BACK)
        front_mode = back_mode;
    if (r->cull_enabled && r->cull_mode != GL_FRONT)
        back_mode = front_mode;
    return back ? back_mode : front_mode;
}

static inline bool fs_raster_draw_pipeline(const fs_raster_state *r)
{
    return fs_raster_face_mode(r, false) != GL_FILL || fs_raster_face_mode(r, true) != GL_FILL;
}

/* Edge bits of a triangle handed to fs_raster_polygon: bit i draws edge
 * v[i] -> v[i+1 mod 3] in GL_LINE mode and vertex v[i] in GL_POINT mode
 * (the decomposition's boundary edges and the vertices' edge flags, GL 1.5
 * spec 2.6.2 and 3.5.4, already combined). */
#define FS_EDGES_ALL 7u
/* Set in the edges the vertex stage hands on (clip.c) when the triangle
 * takes the draw module's route to fs_raster_polygon. */
#define FS_EDGES_ROUTE 0x40u
/* In what primitive assembly hands on (primitive.c, never to the
 * rasterizer): the triangle starts a primitive, as the draw module's
 * decomposition marks one for the line stipple (DRAW_PIPE_RESET_STIPPLE):
 * each triangle of GL_TRIANGLES, strips and fans, the first of each quad
 * and of a polygon. */
#define FS_EDGES_RESET 0x80u
/* The draw module's post-clip stages for one triangle (polygon_mode.c):
 * facing and culling, polygon offset, then the face's polygon mode:
 * filled, its flagged edges as lines, or its flagged vertices as points. */
void fs_raster_polygon(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2,
                       unsigned edges);

/* Decides facing, culls, applies polygon offset and rasterizes.  Vertices are
 * in the order the primitive gave them (their winding decides facing). */
void fs_raster_triangle(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2);
/* While the observer's tile mask is on (observer.h): a triangle known to
 * make no fragment in a masked tile is only snapped, culled and its area
 * reported, as fs_raster_triangle would, from its window x and y in
 * llvmpipe's frame (fs_rvertex.y_raster). */
void fs_raster_triangle_dropped(fs_context *c, const float x[3], const float y_raster[3]);
void fs_raster_line(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1);
/* Whether GL_LINE_STIPPLE cuts lines (rasterize_line.c). */
bool fs_raster_line_stippled(const fs_context *c);
void fs_raster_point(fs_context *c, const fs_rvertex *v);
/* The same with the point's size given (fs_raster_point takes
 * fs_point_size's): a size the vertex stage derived (point_state.c). */
void fs_raster_point_sized(fs_context *c, const fs_rvertex *v, float size);
/* point_state.c: whether the distance attenuation is not (1, 0, 0), so
 * each vertex has its own size (GL 1.5 spec 3.3), and the size of a point
 * without attenuation: GL_POINT_SIZE clamped to [GL_POINT_SIZE_MIN,
 * GL_POINT_SIZE_MAX]. */
bool fs_point_attenuated(const fs_raster_state *r);
float fs_point_size(const fs_raster_state *r);
/* The smallest and largest of three window coordinates: a triangle's
 * bounding box (primitive.c's tile test, raster_threads.c's batch size). */
static inline float fs_lo3(float a, float b, float c)
{
    float m = b < a ? b : a;
    return c < m ? c : m;
}

static inline float fs_hi3(float a, float b, float c)
{
    float m = b > a ? b : a;
    return c > m ? c : m;
}

#endif
