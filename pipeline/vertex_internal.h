/*
 * Private interface between the files of the vertex stage (GL 1.5 spec
 * chapter 2): the per-vertex records that flow from attribute fetch
 * (immediate.c, vertex_array.c) through transformation and lighting
 * (transform in vertex_array.c's fs_vs_process, lighting.c) to primitive
 * assembly (primitive.c) and clipping (clip.c).
 */
#ifndef FS_VERTEX_INTERNAL_H
#define FS_VERTEX_INTERNAL_H
#include <math.h>
#include <string.h>
#include <stddef.h>
#include <stdint.h>
#include "context.h"

#define FS_PI 3.14159265358979323846

/* Colour components of each type as floats (GL 1.5 spec table 2.9). */
#define UB2F(x) ((float)(x) / 255.0f)
/* Signed bytes are scaled by the float nearest 1/255, not divided by 255:
 * the two differ in the last bit for about a third of the values, and
 * OSMesa's current colour and normal are the product (measured,
 * tests/test_gl_forms.c: 100 gives 0.788235366, not 0.788235307). */
#define B2F(x) ((2.0f * (float)(x) + 1.0f) * (1.0f / 255.0f))
#define US2F(x) ((float)(x) / 65535.0f)
#define S2F(x) ((2.0f * (float)(x) + 1.0f) / 65535.0f)
#define UI2F(x) ((float)((double)(x) / 4294967295.0))
#define I2F(x) ((float)((2.0 * (double)(x) + 1.0) / 4294967295.0))

/* A vertex as submitted: object position and the attributes current when
 * it was specified. */
/* x86 builds carry FMA and AVX2 variants of the vertex stage's loop,
 * chosen at run time (fs_vs_setup.has_fma, has_avx2): the four fmaf of a
 * vertex's viewport transform become one instruction each instead of
 * library calls, and positions are transformed 8 vertices at a time.  Each
 * variant does the same IEEE operations in the same order (fmaf rounds once
 * either way), so the bits are the same (test: fma_variant_identical). */
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define FS_VS_HAVE_FMA 1
#include <immintrin.h>
#else
#define FS_VS_HAVE_FMA 0
#endif

typedef struct fs_ivert {
    float obj[4];
    float col[4];
    float nrm[3];
    float tc[FS_MAX_TEXTURE_UNITS][4]; /* the first fs_vs_setup.ntex units are set */
    /* GL 1.4 (2.7): the secondary colour (alpha 1) and the fog coordinate.
     * (The edge flag, 2.6.2, is fs_vs_setup.edge's.) */
    float col2[4];
    float fogc;
} fs_ivert;

/* A vertex after transformation and lighting. */
typedef struct fs_pvert {
    float clip[4];
    float win[5];     /* x, y, z in window space, 1/w, and y in llvmpipe's y-down frame
                         (fs_rvertex.y_raster); valid when mask == 0 */
    float col[2][4];  /* front and back colour, clamped */
    float tc[FS_MAX_TEXTURE_UNITS][4]; /* the first fs_vs_setup.ntex units */
    /* Fog (GL 1.5 spec 3.10), set while GL_FOG is enabled (fs_vs_setup.fog):
     * the fog coordinate c, |z_e| or the vertex's fog coordinate. */
    float fog;
    /* The secondary colour (3.9), front and back, clamped, set while
     * fs_vs_setup.color_sum is (pipeline/color_sum.c). */
    float col2[2][4];
    /* The point size: derived from the eye distance (GL 1.5 spec 3.3)
     * while fs_vs_setup.points_attenuated, else fs_vs_setup.point_size. */
    float psize;
    unsigned mask;    /* bit i: outside clip plane i (clip.c's order; bits
                         FS_CLIP_USER_BIT + i: user plane i) */
    bool lazy;        /* col and tc not computed yet (fs_vs_process under a tile mask) */
} fs_pvert;

typedef struct fs_light_setup {
    float amb[4], dif[4], spe[4];   /* light colours (material applied per vertex) */
    float pos[4];                   /* eye position, x y z divided by w when positional */
    /* Directional lights: the normalised direction and half vector, in eye
     * or object space (fs_vs_setup.light_object_space). */
    float vp_inf[3], h_inf[3];
    float spot_dir[3];              /* normalised */
    float cos_cutoff, spot_exp;
    float att[3];
    bool positional, spot;
    bool attenuated;                /* attenuation other than (1, 0, 0) */
} fs_light_setup;

/* State derived once per draw from the GL state. */
typedef struct fs_vs_setup {
    float mvp[16];      /* projection * modelview, float, as Mesa */
    float mv[16];
    float nmat[9];      /* rows of the inverse transpose (upper 3x3) */
    float nscale;       /* GL_RESCALE_NORMAL factor */
    float nmat_of[16];  /* the modelview nmat and nscale were computed from */
    unsigned nmat_flags; /* and its flags (fs_matrix.flags) */
    float mv_inv[16];   /* its inverse (fs_mat_invert_gl) */
    bool mv_rigid;      /* the modelview preserves lengths (fs_mat_invert_gl) */
    /* Lighting in object space (lighting.c, fs_lighting_spaces): normals
     * untransformed, directional lights brought to the object. */
    bool light_object_space;
    bool has_fma;       /* the CPU has FMA: fs_vs_process's FMA variant */
    bool has_avx2;      /* ... and AVX2: positions 8 at a time */
    bool nmat_valid;
    /* The texture units whose coordinates are carried: 1 + the highest
     * enabled unit, at least 1 (fs_raster_state.tex_units), and each one's
     * texture matrix (2.10.2). */
    int ntex;
    float tex[FS_MAX_TEXTURE_UNITS][16];
    bool tex_identity[FS_MAX_TEXTURE_UNITS];
    float vp_scale[3], vp_trans[3];
    float yr_scale, yr_trans; /* viewport y in llvmpipe's y-down frame */
    /* lighting */
    bool lighting, two_side, local_viewer, need_eye, normalize, rescale;
    int nlights;
    fs_light_setup light[FS_MAX_LIGHTS];
    float model_ambient[4];
    fs_material mat[2];
    int cm_face_mask;   /* bit 0 front, bit 1 back: faces tracking the colour */
    GLenum cm_mode;
    bool flat;
    /* Flat shading with GL_FIRST_VERTEX_CONVENTION (glProvokingVertex):
     * lines, triangles, strips and fans take the first vertex's colour
     * (primitive.c, clip.c). */
    bool flat_first;
    /* Fog (3.10): GL_FOG is enabled, so each vertex gets its fog
     * coordinate (fs_pvert.fog). */
    bool fog;
    bool fog_from_coord; /* GL_FOG_COORD_SRC is GL_FOG_COORD */
    /* The colour sum (3.9) is on: GL_COLOR_SUM, or lighting with
     * GL_SEPARATE_SPECULAR_COLOR; each vertex gets fs_pvert.col2. */
    bool color_sum;
    bool separate_specular; /* lighting's specular term goes to col2 (2.14.1) */
    /* Texture coordinate generation (GL 1.5 spec 2.11.4, pipeline/texgen.c):
     * some unit below ntex generates a coordinate; one of them from the eye
     * position or normal; each coordinate's FS_TG_* and plane. */
    bool texgen, texgen_eye, texgen_normal;
    float texgen_nmat[9], texgen_nscale; /* the generation's normal matrix (texgen.c) */
    unsigned char texgen_mode[FS_MAX_TEXTURE_UNITS][4];
    float texgen_plane[FS_MAX_TEXTURE_UNITS][4][4];
    /* Per-draw input: the batch vertices' edge flags (GL 1.5 spec 2.6.2),
     * or NULL when every vertex has the current edge flag.  Reset by
     * fs_vs_prepare. */
    const uint8_t *edge;
    /* Per-draw input: shade the batch's vertices (colours, texture
     * coordinates, fog, point size) only when a triangle that is not
     * wholly outside one clip plane reads them (fs_vs_defer_shading).
     * Reset by fs_vs_prepare. */
    bool defer;
    /* User clip planes (GL 1.5 spec 2.11; clip_plane.c): the enabled
     * planes as fs_pvert.mask bits (0 when none is, and then no vertex
     * pays for them) and each one's clip-space coefficients. */
    unsigned ucp_mask;
    float ucp[FS_MAX_CLIP_PLANES][4];
    /* Point distance attenuation (3.3, point_state.c): on (the
     * coefficients are not (1, 0, 0)), the coefficients, GL_POINT_SIZE
     * (attenuated as it is, clamped when not: point_state.c) and the
     * bounds. */
    bool points_attenuated;
    float point_atten[3], point_size, point_size_min, point_size_max;
} fs_vs_setup;

/* The material from batch vertex `start` on, after a glMaterial between
 * Begin and End (immediate.c). */
typedef struct fs_mat_seg {
    size_t start;
    fs_material mat[2];
} fs_mat_seg;

/* Growable buffers kept across draws (no per-vertex allocation). */
typedef struct fs_vs_impl {
    fs_ivert *iv;
    size_t iv_n, iv_cap;
    /* Immediate mode: each batch vertex's edge flag, kept only once one
     * of them is false (NULL edges until then: all true).  An array draw
     * with the edge flag array enabled fills it from the array
     * (vertex_array.c), as no immediate batch is open then. */
    uint8_t *iv_edge;
    size_t iv_edge_cap;
    bool iv_edge_used;
    /* glMaterial between Begin and End (GL 1.5 spec 2.6.3) applies to the
     * vertices that follow: the materials of the batch, in order (none
     * when the primitive changed no material). */
    fs_mat_seg *mat_seg;
    size_t mat_seg_n, mat_seg_cap;
    fs_pvert *pv;
    size_t pv_cap;
    uint32_t *idx;
    size_t idx_cap;
    fs_vs_setup setup;
    /* An array draw under the observer's tile mask fetches positions only;
     * a lazy vertex fetches its other attributes when it is lit
     * (fs_vs_attributes).  Batch vertex k is array element
     * src_indices[k] (of src_type) or, without indices, src_first + k. */
    bool deferred;
    size_t src_first;
    const void *src_indices;
    GLenum src_type;
    /* fs_vs_set_eager: every vertex shaded in fs_vs_process, as the
     * reference the deferred shading is tested against. */
    bool eager;
    /* Tests observe what reaches the rasterizer through this (NULL in use). */
    void (*tri_hook)(void *user, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2);
    void *hook_user;
} fs_vs_impl;

static inline fs_vs_impl *fs_vs(fs_context *c) { return (fs_vs_impl *)c->prim.impl; }

/* Buffer growth; returns false when out of memory. */
bool fs_vs_reserve_iv(fs_context *c, size_t n);
bool fs_vs_reserve_pv(fs_context *c, size_t n);
bool fs_vs_reserve_idx(fs_context *c, size_t n);
bool fs_vs_reserve_edge(fs_context *c, size_t n); /* iv_edge */

/* matrix.c */
void fs_mat_identity(float m[16]);
void fs_mat_mul(float r[16], const float a[16], const float b[16]); /* r = a * b */
bool fs_mat_invert(float r[16], const float m[16]);
/* Mesa's matrix flags (m_matrix.c), kept in fs_matrix.flags by the
 * matrix commands: what built the matrix (the geometry bits), that its
 * values decide instead (DIRTY: after glLoadMatrix or glMultMatrix, until
 * the next analysis), that it is the identity of glLoadIdentity (which
 * keeps the geometry bits: Mesa clears only its dirty bits). */
enum {
    FS_MATF_TRANSLATION = 1, FS_MATF_ROTATION = 2, FS_MATF_UNIFORM_SCALE = 4, FS_MATF_GENERAL_SCALE = 8,
    FS_MATF_GENERAL_3D = 16, FS_MATF_PERSPECTIVE = 32, FS_MATF_GENERAL = 64,
    FS_MATF_DIRTY = 128, FS_MATF_IDENTITY = 256
};
/* matrix_inverse.c: the inverse as llvmpipe's GL front end computes it
 * (Mesa's matrix classes, in float, chosen from m's values); true when m
 * preserves lengths (a rotation and a translation at most), whose normals
 * need no rescaling. */
bool fs_mat_invert_gl(float out[16], const float m[16]);
/* The same for a stack matrix as Mesa analyses it when it is used: by its
 * flags, or from its values when they are dirty (the flags are then
 * replaced by the values' and kept, as Mesa does). */
bool fs_matrix_invert(float out[16], fs_matrix *m);
/* A dirty matrix classified by its values now (Mesa's _math_matrix_analyse). */
void fs_matrix_analyse(fs_matrix *m);
/* Transforms with the accumulation order Mesa's vertex program uses. */
static inline void fs_mat_xform4(float o[4], const float m[16], const float v[4])
{
    for (int r = 0; r < 4; r++) {
        float a = m[r] * v[0];
        a = a + m[4 + r] * v[1];
        a = a + m[8 + r] * v[2];
        a = a + m[12 + r] * v[3];
        o[r] = a;
    }
}

/* viewport.c */
void fs_viewport_xform(fs_context *c, float scale[3], float trans[3]);

/* color_sum.c: sets s->color_sum and s->separate_specular from the GL
 * state, and the rasterizer's interpolate_color2 (marking the fragment key
 * stale when it changes). */
void fs_color_sum_setup(fs_context *c, fs_vs_setup *s);

/* lighting.c */
void fs_lighting_setup(fs_context *c, fs_vs_setup *s);
/* The eye position (when s->need_eye; else left as it is) and the eye
 * normal of a vertex, for lighting (2.14) and texture coordinate
 * generation (2.11.4): the normal times the inverse transpose of the
 * modelview, then normalised (GL_NORMALIZE) or rescaled
 * (GL_RESCALE_NORMAL), as llvmpipe's vertex shader does. */
/* llvmpipe's dot product of three: the products summed from the last
 * component to the first (texgen.c measured it). */
static inline float fs_vs_dot3(const float a[3], const float b[3])
{
    float d = a[2] * b[2];
    d = d + a[1] * b[1];
    return d + a[0] * b[0];
}

/* The vertex program's normalisation: the dot product, 1/sqrt, a product
 * (a zero vector stays zero, where the program would give NaN). */
static inline void fs_vs_normalize3(float v[3])
{
    float d = fs_vs_dot3(v, v);
    if (d > 0.0f) {
        float q = 1.0f / sqrtf(d);
        v[0] *= q; v[1] *= q; v[2] *= q;
    }
}

static inline void fs_vs_eye_normal(const fs_vs_setup *s, const fs_ivert *v, float eye[4], float nrm[3])
{
    if (s->need_eye)
        fs_mat_xform4(eye, s->mv, v->obj);
    if (s->light_object_space) {
        /* Mesa lights in object space when nothing needs eye coordinates
         * and the modelview preserves lengths: the normal as given. */
        memcpy(nrm, v->nrm, 3 * sizeof(float));
    } else {
        for (int r = 0; r < 3; r++)
            nrm[r] = fs_vs_dot3(&s->nmat[r * 3], v->nrm);
        if (s->rescale && !s->normalize) {
            nrm[0] *= s->nscale; nrm[1] *= s->nscale; nrm[2] *= s->nscale;
        }
    }
    if (s->normalize)
        fs_vs_normalize3(nrm);
}
/* texgen.c: the generation's per-draw state (after fs_lighting_setup:
 * it asks for the eye position), and one vertex's texture coordinates
 * of every unit below s->ntex, generated and then transformed by the
 * texture matrices; eye is lighting's when s->lighting, else
 * computed here; the normal is its own (texgen.c's texgen_normal). */
enum { FS_TG_NONE, FS_TG_OBJECT, FS_TG_EYE, FS_TG_SPHERE, FS_TG_REFLECTION, FS_TG_NORMAL };
void fs_texgen_setup(fs_context *c, fs_vs_setup *s);
void fs_texgen_vertex(const fs_vs_setup *s, const fs_ivert *v, float eye[4], fs_pvert *o);
/* immediate.c: glMaterial changed the material between Begin and End;
 * `before` is the material it replaced. */
void fs_vs_material_changed(fs_context *c, const fs_material before[2]);
/* Lights one vertex: eye position (when s->need_eye), eye normal, vertex
 * colour; writes clamped front and (if two-sided) back colours, and with
 * s->separate_specular the specular terms apart into spec (2.14.1). */
void fs_light_vertex(const fs_vs_setup *s, const float eye[4], const float n[3],
                     const float col[4], float out[2][4], float spec[2][4]);
/* After fs_lighting_setup, fs_texgen_setup and the modelview's inverse
 * (s->mv_inv, s->mv_rigid): chooses eye or object space as Mesa does and
 * puts the directional lights' vectors there. */
void fs_lighting_spaces(fs_vs_setup *s);

/* vertex_array.c: transformation of a batch of vertices.  s persists from
 * draw to draw (it caches the normal matrix): zero it before its first use. */
void fs_vs_prepare(fs_context *c, fs_vs_setup *s);
/* After fs_vs_prepare (which clears it): fs_raster_state.const_attribs of
 * a draw whose vertices vary the attributes `varying` (FS_ATTR_*: the
 * enabled arrays, or immediate mode's vertex format). */
void fs_vs_constant_attribs(fs_context *c, const fs_vs_setup *s, unsigned varying);
/* tiles: NULL, or the observer's tile mask (fs_vs_tile_mask, observer.h),
 * with which a batch that cannot reach a masked tile skips its lighting,
 * and one that may leaves it to fs_prim_draw per triangle (the vertices
 * are then `lazy`; returns true). */
bool fs_vs_process(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out, size_t n, const fs_tile_mask *tiles);
const fs_tile_mask *fs_vs_tile_mask(const fs_context *c, GLenum mode);
/* Whether a draw in `mode` without a tile mask may shade its vertices
 * only as its triangles need them (s->defer; vertex_array.c). */
bool fs_vs_defer_shading(fs_context *c, GLenum mode);
/* Colours and texture coordinates of lazy vertex k of the batch (its
 * inputs fetched first when the draw deferred them). */
void fs_vs_attributes(fs_context *c, const fs_vs_setup *s, fs_ivert *iv, fs_pvert *pv, size_t k);
/* Whether a window-space box can make fragments in a masked tile. */
bool fs_vs_box_masked(const fs_tile_mask *t, float x0, float y0, float x1, float y1);

/* point_state.c: the size of a vertex at eye-plane distance d while
 * s->points_attenuated. */
float fs_point_derived_size(const fs_vs_setup *s, float d);

/* primitive.c: assembles a primitive from processed vertices.  idx may be
 * NULL (vertices in order).  elements: the draw came as indices (glDrawElements
 * or a display list), which Mesa splits quads differently for.  iv: the
 * input vertices when fs_vs_process left the attributes lazy, else NULL. */
void fs_prim_draw(fs_context *c, const fs_vs_setup *s, GLenum mode, fs_pvert *pv, fs_ivert *iv,
                  const uint32_t *idx, size_t count, bool elements);
bool fs_prim_mode_valid(GLenum mode);
/* clip.c */
unsigned fs_clip_mask(const float clip[4]);
/* clip_plane.c: the user planes of a draw into s (ucp_mask, ucp), and the
 * mask bits of the planes a clip position is outside. */
#define FS_CLIP_USER_BIT 6
void fs_clip_plane_setup(const fs_context *c, fs_vs_setup *s);
unsigned fs_clip_user_mask(const fs_vs_setup *s, const float clip[4]);
/* edges: 0 for the triangle setup's route; on the draw module's
 * (FS_EDGES_ROUTE set, rasterizer.h) bits 0-2 the triangle's boundary
 * edges (edge i from vertex i to vertex i+1 mod 3, as the primitive's
 * decomposition gives them) and bits 3-5 the three vertices' edge flags
 * (GL 1.5 spec 2.6.2). */
void fs_clip_triangle(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0,
                      const fs_pvert *v1, const fs_pvert *v2, int provoking, unsigned edges);
void fs_clip_line(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0, const fs_pvert *v1);
/* Emits an unclipped triangle (all masks zero). provoking: index 0..2 of the
 * vertex whose colour flat shading uses, or -1 for smooth shading. */
void fs_emit_triangle(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0,
                      const fs_pvert *v1, const fs_pvert *v2, int provoking, unsigned edges);
void fs_emit_line(fs_context *c, const fs_vs_setup *s, const fs_pvert *v0, const fs_pvert *v1);
void fs_emit_point(fs_context *c, const fs_vs_setup *s, const fs_pvert *v);
/* The executors of the current attributes (immediate.c; prototypes as the
 * command table generates them in driver/gl_call.h, which the pipeline
 * does not include), which glArrayElement calls (GL 1.5 spec 2.8), and
 * glBegin/glEnd, which glEvalMesh calls (5.1, evaluator.c). */
void fs_exec_Begin(fs_context *c, GLenum mode);
void fs_exec_End(fs_context *c);
void fs_exec_Color4fv(fs_context *c, const GLfloat *v);
void fs_exec_Normal3fv(fs_context *c, const GLfloat *v);
void fs_exec_Vertex4fv(fs_context *c, const GLfloat *v);
void fs_exec_EdgeFlag(fs_context *c, GLboolean flag);
/* Sets the current texture coordinates of a unit (immediate.c). */
void fs_current_texcoord(fs_context *c, int unit, float s, float t, float r, float q);
#endif
