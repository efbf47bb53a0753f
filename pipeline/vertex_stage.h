/*
 * The vertex stage (GL 1.5 spec chapter 2): current attributes, immediate
 * mode and client arrays, matrix stacks, lighting, primitive assembly,
 * clipping, perspective division, viewport.  Its output goes to the
 * rasterizer (rasterizer.h) as fs_rvertex.
 *
 * Files: matrix.c (2.11), lighting.c (2.14), immediate.c (2.6-2.7),
 * vertex_array.c (2.8), primitive.c (assembly, flat shading 2.14.7),
 * clip.c (2.12), clip_plane.c (user clip planes, 2.11), viewport.c (2.11.1).
 */
#ifndef FS_VERTEX_STAGE_H
#define FS_VERTEX_STAGE_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>
#include "rasterizer.h"

#define FS_MODELVIEW_STACK_DEPTH 32
#define FS_PROJECTION_STACK_DEPTH 32  /* GL minimum is 2; Mesa (the reference) allows 32 */
#define FS_TEXTURE_STACK_DEPTH 10
#define FS_MAX_LIGHTS 8
#define FS_MAX_CLIP_PLANES 8 /* GL_MAX_CLIP_PLANES as OSMesa (llvmpipe) reports it */

/* Column-major, as GL; flags are Mesa's record of how the matrix was built
 * (FS_MATF_*, pipeline/matrix.c), which chooses its inversion method. */
typedef struct fs_matrix {
    float m[16];
    unsigned flags;
} fs_matrix;

typedef struct fs_transform_state {
    GLenum matrix_mode;
    fs_matrix modelview[FS_MODELVIEW_STACK_DEPTH];
    fs_matrix projection[FS_PROJECTION_STACK_DEPTH];
    /* One texture matrix stack per texture unit (GL 1.5 spec 2.10.2);
     * glMatrixMode(GL_TEXTURE) selects the active unit's. */
    fs_matrix texture[FS_MAX_TEXTURE_UNITS][FS_TEXTURE_STACK_DEPTH];
    int modelview_top, projection_top; /* index of the current matrix */
    int texture_top[FS_MAX_TEXTURE_UNITS];
    GLint viewport[4];       /* the framebuffer size until glViewport (see viewport_set) */
    bool viewport_set;       /* glViewport called; before that the first draw
                              * takes the framebuffer size, as OSMesa's first
                              * MakeCurrent does */
    double depth_range[2];
    bool normalize, rescale_normal;
    /* User clip planes (GL 1.5 spec 2.11; pipeline/clip_plane.c): each
     * plane's eye-space coefficients, as glClipPlane transformed them,
     * and GL_CLIP_PLANEi. */
    float clip_plane[FS_MAX_CLIP_PLANES][4];
    bool clip_enabled[FS_MAX_CLIP_PLANES];
} fs_transform_state;

typedef struct fs_light {
    bool enabled;
    float ambient[4], diffuse[4], specular[4];
    float position[4];       /* eye coordinates (transformed when specified) */
    float spot_direction[3]; /* eye coordinates */
    float spot_exponent, spot_cutoff;
    float attenuation[3];    /* constant, linear, quadratic */
} fs_light;

typedef struct fs_material {
    float ambient[4], diffuse[4], specular[4], emission[4];
    float shininess;
} fs_material;

typedef struct fs_lighting_state {
    bool enabled;            /* GL_LIGHTING */
    fs_light light[FS_MAX_LIGHTS];
    float model_ambient[4];
    bool local_viewer, two_side;
    GLenum color_control;       /* GL_SINGLE_COLOR (GL_SEPARATE_SPECULAR_COLOR: pipeline/color_sum.c) */
    fs_material material[2]; /* front, back */
    bool color_material;     /* GL_COLOR_MATERIAL */
    GLenum color_material_face, color_material_mode;
    GLenum shade_model;      /* GL_SMOOTH */
    /* glProvokingVertex (EXT/ARB_provoking_vertex, GL 3.2 2.19): which
     * vertex a flat-shaded line or triangle takes its colour from. */
    GLenum provoking_vertex; /* GL_LAST_VERTEX_CONVENTION */
} fs_lighting_state;

typedef struct fs_current_state {
    float color[4], normal[3];
    float texcoord[FS_MAX_TEXTURE_UNITS][4]; /* per texture unit (2.7) */
    /* GL 1.4's attributes (2.7; pipeline/color_sum.c, pipeline/fog.c): the
     * secondary colour (0, 0, 0, 1), set as r, g, b with alpha 1, and the
     * fog coordinate (0); neither clamped when set. */
    float secondary_color[4], fog_coord;
} fs_current_state;

typedef struct fs_client_array {
    bool enabled;
    GLint size;
    GLenum type;
    GLsizei stride;          /* as given; 0 means tightly packed */
    const void *pointer;
    /* Bytes readable at pointer: SIZE_MAX for an application's memory
     * (GL trusts it), 0 for NULL, the exact length for data that came with
     * a replayed call (driver/dispatch.c), which a draw may not read past. */
    size_t bytes;
    /* The buffer object bound to GL_ARRAY_BUFFER when the pointer was set
     * (GL 1.5 spec 2.9.1), pointer then being an offset into it; 0: none. */
    GLuint buffer;
} fs_client_array;

typedef struct fs_array_state {
    fs_client_array vertex, normal, color;
    /* One texture coordinate array per texture unit, the one
     * glClientActiveTexture selects taking glTexCoordPointer (2.8). */
    fs_client_array texcoord[FS_MAX_TEXTURE_UNITS];
    /* GL 1.4's arrays and the edge flag and colour index arrays (2.8):
     * secondary colour, fog coordinate and edge flag are fetched (polygon
     * mode GL_LINE/GL_POINT reads the edge flag); the index, which an RGBA
     * context ignores, only answers glGet. */
    fs_client_array secondary_color, fog_coord, edge_flag, index;
    /* GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING (2.9),
     * client state as the arrays are (pipeline/buffer_object.c). */
    GLuint array_buffer, element_buffer;
} fs_array_state;

/* The client arrays in one fixed order, for code that treats them alike
 * (replayed array data, buffer offsets, display-list snapshots, capture):
 * vertex, normal, colour, each unit's texture coordinates, secondary
 * colour, fog coordinate, edge flag, index. */
#define FS_CLIENT_ARRAYS (7 + FS_MAX_TEXTURE_UNITS)
static inline fs_client_array *fs_client_array_at(fs_array_state *A, int k)
{
    if (k < 3)
        return k == 0 ? &A->vertex : k == 1 ? &A->normal : &A->color;
    if (k < 3 + FS_MAX_TEXTURE_UNITS)
        return &A->texcoord[k - 3];
    fs_client_array *const s[4] = {&A->secondary_color, &A->fog_coord, &A->edge_flag, &A->index};
    return s[k - 3 - FS_MAX_TEXTURE_UNITS];
}

/* The array a pointer call of fs_pointer_slot's slot (vertex, normal,
 * colour, texture coordinates, secondary colour, fog coordinate, edge
 * flag, index: FS_ARRAY_SLOTS of them) sets, as an index of
 * fs_client_array_at: a texture coordinate pointer is the unit's (2.8). */
#define FS_ARRAY_SLOTS 8
static inline int fs_array_of_slot(int slot, int unit)
{
    return slot < 3 ? slot : slot == 3 ? 3 + unit : slot - 1 + FS_MAX_TEXTURE_UNITS;
}

/* Immediate-mode primitive assembly state; the vertex agent owns its fields. */
typedef struct fs_prim_state {
    bool inside_begin;
    GLenum mode;
    int count;               /* vertices since glBegin */
    /* Nonzero while a display list executes.  Mesa compiles list contents
     * into indexed draws, which split GL_QUADS along the other diagonal
     * than immediate mode does; driver/display_list.c increments it around
     * glCallList so that fragsim splits the same way. */
    int list_depth;
    /* The attributes (FS_ATTR_*) of the vertex format of Mesa's immediate
     * mode (vbo_exec): each one given between Begin and End joins it and
     * stays for the primitives that follow, until a state change or
     * glCallList flushes the vertices and resets the format
     * (fs_vs_format_reset).  Measured on OSMesa (tests/test_constant_attribs.c):
     * glColor before glBegin gives a constant colour, glColor inside
     * (or in an earlier glBegin/glEnd with only vertex commands and queries
     * between) an interpolated one. */
    unsigned vtx_attribs;
    /* Mesa's immediate mode concatenates a glBegin/glEnd onto the one
     * before when nothing flushed its vertices between (the same rule as
     * vtx_attribs), both are GL_QUADS and the first holds whole quads
     * (Mesa src/mesa/vbo: _mesa_End's try_vbo_merge, vbo_merge_draws):
     * llvmpipe then gets one draw, and its draw module takes the pipeline
     * route (primitive.c) for all of its quads when a vertex of any of
     * them lies outside the view volume.  quads_run: the last immediate
     * draw can be continued so; quads_run_pipeline: the run so far took
     * the pipeline route; quads_route: set by fs_prim_draw, the route its
     * quads took.  Measured on OSMesa (tests/test_quad_merge.c). */
    bool quads_run, quads_run_pipeline, quads_force_pipeline, quads_route;
    unsigned quads_run_attribs; /* vtx_attribs at the end of the run's last draw */
    void *impl;              /* private buffers (vertex_internal.h) */
} fs_prim_state;

void fs_vertex_stage_init(fs_context *c);
void fs_vertex_stage_free(fs_context *c);
/* Tests: true shades every vertex of a draw before primitive assembly
 * (the reference), false (the default) lets a triangle draw shade only
 * the vertices of triangles not wholly outside one clip plane
 * (fs_vs_defer_shading, tests/test_vertex_defer.c). */
void fs_vs_set_eager(fs_context *c, bool eager);

/* Derived vertex state (products of matrices, normalised light vectors) is
 * recomputed at each draw, so enables need no hook. */

/* Helpers shared with the driver (glGet, glEnable(GL_COLOR_MATERIAL)). */
const fs_matrix *fs_current_matrix(const fs_context *c, GLenum mode);
/* Mesa analyses the modelview when a command uses the state (a draw, a
 * clear, a pixel rectangle): one built by glLoadMatrix or glMultMatrix is
 * classified by its values then, and later commands add to those flags
 * (pipeline/matrix_inverse.c). */
void fs_modelview_analyse(fs_context *c);
/* The active texture unit (glActiveTexture) and the client one
 * (glClientActiveTexture) as indices 0 .. FS_MAX_TEXTURE_UNITS - 1
 * (pipeline/texture_select.c). */
int fs_active_unit(const fs_context *c);
int fs_client_active_unit(const fs_context *c);
/* Copies the current colour into the material properties that track it
 * (GL 1.5 spec 2.14.3); called on glColor and on enabling GL_COLOR_MATERIAL. */
void fs_color_material_update(fs_context *c);
/* The immediate-mode vertex format (fs_prim_state.vtx_attribs): an
 * attribute given between Begin and End joins it; the driver resets it on
 * every command that flushes Mesa's vertices (a state change, glCallList),
 * queries excepted. */
void fs_vs_attrib_given(fs_context *c, unsigned attribs);
void fs_vs_format_reset(fs_context *c);
/* glMultiDrawElements' arguments (GL 1.4 spec 2.8): false, with the GL
 * error raised, when it draws nothing for a bad one (the driver then runs
 * its draws as glDrawElements calls, driver/dispatch.c). */
bool fs_multidraw_elements_valid(fs_context *c, GLenum mode, const GLsizei *count, GLenum type, GLsizei drawcount);
#endif
