/*
 * Immediate mode (GL 1.5 spec 2.6-2.7): Begin/End and the current vertex
 * attributes, and the vertex stage's lifetime (defaults from the GL 1.5
 * state tables 6.5-6.11).  Vertices between Begin and End are buffered and
 * transformed as one batch at End, as Mesa's vbo module does; the result is
 * the same as per-vertex processing but keeps the transform loop tight.
 * Colour conversions follow table 2.9: unsigned c/(2^b-1), signed
 * (2c+1)/(2^b-1).
 */
#include <stdlib.h>
#include <string.h>
#include "vertex_internal.h"

void fs_vertex_stage_init(fs_context *c)
{
    fs_transform_state *x = &c->xf;
    memset(x, 0, sizeof *x);
    x->matrix_mode = GL_MODELVIEW;
    fs_mat_identity(x->modelview[0].m);
    fs_mat_identity(x->projection[0].m);
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        fs_mat_identity(x->texture[u][0].m);
    /* The viewport becomes the framebuffer size at the first draw unless
     * glViewport comes first (viewport.c). */
    x->depth_range[0] = 0.0;
    x->depth_range[1] = 1.0;

    fs_lighting_state *L = &c->lighting;
    memset(L, 0, sizeof *L);
    for (int i = 0; i < FS_MAX_LIGHTS; i++) {
        fs_light *l = &L->light[i];
        l->ambient[3] = 1.0f;
        l->diffuse[3] = l->specular[3] = 1.0f;
        if (i == 0) {
            l->diffuse[0] = l->diffuse[1] = l->diffuse[2] = 1.0f;
            l->specular[0] = l->specular[1] = l->specular[2] = 1.0f;
        }
        l->position[2] = 1.0f;
        l->spot_direction[2] = -1.0f;
        l->spot_cutoff = 180.0f;
        l->attenuation[0] = 1.0f;
    }
    L->model_ambient[0] = L->model_ambient[1] = L->model_ambient[2] = 0.2f;
    L->model_ambient[3] = 1.0f;
    for (int f = 0; f < 2; f++) {
        fs_material *m = &L->material[f];
        m->ambient[0] = m->ambient[1] = m->ambient[2] = 0.2f;
        m->ambient[3] = 1.0f;
        m->diffuse[0] = m->diffuse[1] = m->diffuse[2] = 0.8f;
        m->diffuse[3] = 1.0f;
        m->specular[3] = 1.0f;
        m->emission[3] = 1.0f;
    }
    L->color_material_face = GL_FRONT_AND_BACK;
    L->color_material_mode = GL_AMBIENT_AND_DIFFUSE;
    L->shade_model = GL_SMOOTH;

    memset(&c->current, 0, sizeof c->current);
    c->current.color[0] = c->current.color[1] = c->current.color[2] = c->current.color[3] = 1.0f;
    c->current.normal[2] = 1.0f;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        c->current.texcoord[u][3] = 1.0f;
    c->current.secondary_color[3] = 1.0f;

    /* Tables 6.6-6.8: sizes and types in fs_pointer_slot's order (the edge
     * flag's bytes have no GL type of their own). */
    static const struct { GLint size; GLenum type; } array_init[FS_ARRAY_SLOTS] = {
        {4, GL_FLOAT}, {3, GL_FLOAT}, {4, GL_FLOAT}, {4, GL_FLOAT},
        {3, GL_FLOAT}, {1, GL_FLOAT}, {1, GL_UNSIGNED_BYTE}, {1, GL_FLOAT}};
    memset(&c->arrays, 0, sizeof c->arrays);
    for (int k = 0; k < FS_CLIENT_ARRAYS; k++) {
        int slot = k < 3 ? k : k < 3 + FS_MAX_TEXTURE_UNITS ? 3 : k + 1 - FS_MAX_TEXTURE_UNITS;
        fs_client_array_at(&c->arrays, k)->size = array_init[slot].size;
        fs_client_array_at(&c->arrays, k)->type = array_init[slot].type;
    }

    free(c->prim.impl);
    memset(&c->prim, 0, sizeof c->prim);
    c->prim.impl = calloc(1, sizeof(fs_vs_impl));
}

void fs_vertex_stage_free(fs_context *c)
{
    fs_vs_impl *v = fs_vs(c);
    if (v) {
        free(v->iv);
        free(v->iv_edge);
        free(v->pv);
        free(v->idx);
        free(v->mat_seg);
        free(v);
    }
    c->prim.impl = NULL;
}

static bool grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return true;
    size_t n = *cap ? *cap : 256;
    while (n < need) {
        if (n > SIZE_MAX / 2 / elem)
            return false;
        n *= 2;
    }
    void *q = realloc(*p, n * elem);
    if (!q)
        return false;
    *p = q;
    *cap = n;
    return true;
}

bool fs_vs_reserve_iv(fs_context *c, size_t n)
{
    fs_vs_impl *v = fs_vs(c);
    return v && grow((void **)&v->iv, &v->iv_cap, n, sizeof *v->iv);
}

bool fs_vs_reserve_pv(fs_context *c, size_t n)
{
    fs_vs_impl *v = fs_vs(c);
    return v && grow((void **)&v->pv, &v->pv_cap, n, sizeof *v->pv);
}

bool fs_vs_reserve_idx(fs_context *c, size_t n)
{
    fs_vs_impl *v = fs_vs(c);
    return v && grow((void **)&v->idx, &v->idx_cap, n, sizeof *v->idx);
}

bool fs_vs_reserve_edge(fs_context *c, size_t n)
{
    fs_vs_impl *v = fs_vs(c);
    return v && grow((void **)&v->iv_edge, &v->iv_edge_cap, n ? n : 1, 1);
}

void fs_exec_Begin(fs_context *c, GLenum mode)
{
    if (c->prim.inside_begin) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (!fs_prim_mode_valid(mode)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->prim.inside_begin = true;
    c->prim.mode = mode;
    c->prim.count = 0;
    if (fs_vs(c)) {
        fs_vs(c)->iv_n = 0;
        fs_vs(c)->mat_seg_n = 0;
        fs_vs(c)->iv_edge_used = false;
    }
}

static bool push_mat_seg(fs_context *c, size_t start, const fs_material mat[2])
{
    fs_vs_impl *v = fs_vs(c);
    if (!grow((void **)&v->mat_seg, &v->mat_seg_cap, v->mat_seg_n + 1, sizeof *v->mat_seg)) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return false;
    }
    v->mat_seg[v->mat_seg_n].start = start;
    memcpy(v->mat_seg[v->mat_seg_n].mat, mat, sizeof v->mat_seg[0].mat);
    v->mat_seg_n++;
    return true;
}

/* The vertices so far keep the material they were given with (`before`,
 * the one current at Begin or after the previous change); those that
 * follow get the new one, as llvmpipe's per-vertex material attributes
 * do. */
void fs_vs_material_changed(fs_context *c, const fs_material before[2])
{
    fs_vs_impl *v = fs_vs(c);
    if (!v)
        return;
    if (v->mat_seg_n == 0 && !push_mat_seg(c, 0, before))
        return;
    fs_mat_seg *last = &v->mat_seg[v->mat_seg_n - 1];
    if (last->start == v->iv_n)
        memcpy(last->mat, c->lighting.material, sizeof last->mat);
    else
        push_mat_seg(c, v->iv_n, c->lighting.material);
}

void fs_vs_attrib_given(fs_context *c, unsigned attribs)
{
    if (c->prim.inside_begin)
        c->prim.vtx_attribs |= attribs;
    else if (attribs & ~c->prim.vtx_attribs)
        c->prim.quads_run = false; /* Mesa grows its vertex format, which flushes (vertex_stage.h) */
}

void fs_vs_format_reset(fs_context *c)
{
    if (!c->prim.inside_begin) { /* glCallList between Begin and End continues the primitive */
        c->prim.vtx_attribs = 0;
        c->prim.quads_run = false; /* the flush draws the run (vertex_stage.h) */
    }
}

void fs_exec_End(fs_context *c)
{
    if (!c->prim.inside_begin) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    c->prim.inside_begin = false;
    fs_vs_impl *v = fs_vs(c);
    if (!v || v->iv_n == 0) {
        /* Mesa merges an empty primitive of the same mode into the run. */
        c->prim.quads_run &= c->prim.mode == GL_QUADS;
        return;
    }
    size_t n = v->iv_n;
    v->iv_n = 0;
    if (fs_draw_skipped(c, c->prim.mode, n))
        return;
    c->stats.vertices += n;
    if (!fs_vs_reserve_pv(c, n)) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    fs_vs_prepare(c, &v->setup);
    fs_vs_constant_attribs(c, &v->setup, c->prim.vtx_attribs);
    if (v->iv_edge_used)
        v->setup.edge = v->iv_edge;
    v->iv_edge_used = false;
    bool lazy = false;
    if (v->mat_seg_n) {
        /* Materials changed within the primitive: each run of vertices is
         * lit with its own (none lazily, which would light with one). */
        for (size_t k = 0; k < v->mat_seg_n; k++) {
            size_t a = v->mat_seg[k].start, b = k + 1 < v->mat_seg_n ? v->mat_seg[k + 1].start : n;
            memcpy(v->setup.mat, v->mat_seg[k].mat, sizeof v->setup.mat);
            if (a < b)
                fs_vs_process(&v->setup, v->iv + a, v->pv + a, b - a, NULL);
        }
        v->mat_seg_n = 0;
        /* Lit in full, none lazy; under a tile mask the inputs still go
         * along, since fs_prim_draw reads a draw without them as one that
         * reaches no masked tile (every triangle of rubik, a corpus
         * program that sets materials between vertices, was dropped). */
        lazy = fs_vs_tile_mask(c, c->prim.mode) != NULL;
    } else {
        v->setup.defer = fs_vs_defer_shading(c, c->prim.mode);
        lazy = fs_vs_process(&v->setup, v->iv, v->pv, n, fs_vs_tile_mask(c, c->prim.mode));
    }
    /* A GL_QUADS draw concatenated onto the run before it (vertex_stage.h)
     * takes the run's route; an attribute new to the vertex format makes
     * Mesa flush the run first (its vertex format grows). */
    bool quads = c->prim.mode == GL_QUADS && c->prim.list_depth == 0;
    bool merged = quads && c->prim.quads_run && !(c->prim.vtx_attribs & ~c->prim.quads_run_attribs);
    c->prim.quads_force_pipeline = merged && c->prim.quads_run_pipeline;
    c->prim.quads_route = false;
    fs_prim_draw(c, &v->setup, c->prim.mode, v->pv, lazy ? v->iv : NULL, NULL, n, c->prim.list_depth > 0);
    c->prim.quads_force_pipeline = false;
    c->prim.quads_run = quads && n % 4 == 0;
    c->prim.quads_run_pipeline = c->prim.quads_route;
    c->prim.quads_run_attribs = c->prim.vtx_attribs;
}

/* The batch's vertices get edge flags of their own (GL 1.5 spec 2.6.2),
 * those so far true.  False when out of memory. */
static bool vertex_edge_flags_start(fs_vs_impl *v)
{
    if (!grow((void **)&v->iv_edge, &v->iv_edge_cap, v->iv_n + 1, 1))
        return false;
    memset(v->iv_edge, 1, v->iv_n);
    v->iv_edge_used = true;
    return true;
}

/* Records the edge flag of the batch's next vertex: nothing while the
 * batch has none of its own and the current flag is true.  False only
 * when out of memory. */
static bool vertex_edge_flag(fs_context *c, fs_vs_impl *v)
{
    if (!v->iv_edge_used) {
        if (c->st.edge_flag)
            return true;
        if (!vertex_edge_flags_start(v))
            return false;
    }
    if (!grow((void **)&v->iv_edge, &v->iv_edge_cap, v->iv_n + 1, 1))
        return false;
    v->iv_edge[v->iv_n] = c->st.edge_flag;
    return true;
}

/* Appends a vertex with the current attributes (GL 1.5 spec 2.7).  Outside
 * Begin/End a vertex has no effect. */
static void vertex4(fs_context *c, float x, float y, float z, float w)
{
    if (!c->prim.inside_begin)
        return;
    fs_vs_impl *v = fs_vs(c);
    if (!v || !fs_vs_reserve_iv(c, v->iv_n + 1)) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    if (!vertex_edge_flag(c, v)) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    fs_ivert *o = &v->iv[v->iv_n++];
    o->obj[0] = x; o->obj[1] = y; o->obj[2] = z; o->obj[3] = w;
    memcpy(o->col, c->current.color, sizeof o->col);
    memcpy(o->nrm, c->current.normal, sizeof o->nrm);
    /* The units the draw reads (fs_raster_state.tex_units; enables do not
     * change between Begin and End, 2.6.3). */
    memcpy(o->tc, c->current.texcoord, (size_t)c->raster.tex_units * sizeof o->tc[0]);
    memcpy(o->col2, c->current.secondary_color, sizeof o->col2);
    o->fogc = c->current.fog_coord;
    c->prim.count++;
}

void fs_exec_Vertex2f(fs_context *c, GLfloat x, GLfloat y) { vertex4(c, x, y, 0.0f, 1.0f); }
void fs_exec_Vertex2d(fs_context *c, GLdouble x, GLdouble y) { vertex4(c, (float)x, (float)y, 0.0f, 1.0f); }
void fs_exec_Vertex2i(fs_context *c, GLint x, GLint y) { vertex4(c, (float)x, (float)y, 0.0f, 1.0f); }
void fs_exec_Vertex2s(fs_context *c, GLshort x, GLshort y) { vertex4(c, x, y, 0.0f, 1.0f); }
void fs_exec_Vertex3f(fs_context *c, GLfloat x, GLfloat y, GLfloat z) { vertex4(c, x, y, z, 1.0f); }
void fs_exec_Vertex3d(fs_context *c, GLdouble x, GLdouble y, GLdouble z) { vertex4(c, (float)x, (float)y, (float)z, 1.0f); }
void fs_exec_Vertex3i(fs_context *c, GLint x, GLint y, GLint z) { vertex4(c, (float)x, (float)y, (float)z, 1.0f); }
void fs_exec_Vertex3s(fs_context *c, GLshort x, GLshort y, GLshort z) { vertex4(c, x, y, z, 1.0f); }
void fs_exec_Vertex4f(fs_context *c, GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex4(c, x, y, z, w); }
void fs_exec_Vertex4d(fs_context *c, GLdouble x, GLdouble y, GLdouble z, GLdouble w) { vertex4(c, (float)x, (float)y, (float)z, (float)w); }
void fs_exec_Vertex4i(fs_context *c, GLint x, GLint y, GLint z, GLint w) { vertex4(c, (float)x, (float)y, (float)z, (float)w); }
void fs_exec_Vertex4s(fs_context *c, GLshort x, GLshort y, GLshort z, GLshort w) { vertex4(c, x, y, z, w); }
void fs_exec_Vertex2fv(fs_context *c, const GLfloat *v) { vertex4(c, v[0], v[1], 0.0f, 1.0f); }
void fs_exec_Vertex2dv(fs_context *c, const GLdouble *v) { vertex4(c, (float)v[0], (float)v[1], 0.0f, 1.0f); }
void fs_exec_Vertex2iv(fs_context *c, const GLint *v) { vertex4(c, (float)v[0], (float)v[1], 0.0f, 1.0f); }
void fs_exec_Vertex2sv(fs_context *c, const GLshort *v) { vertex4(c, v[0], v[1], 0.0f, 1.0f); }
void fs_exec_Vertex3fv(fs_context *c, const GLfloat *v) { vertex4(c, v[0], v[1], v[2], 1.0f); }
void fs_exec_Vertex3dv(fs_context *c, const GLdouble *v) { vertex4(c, (float)v[0], (float)v[1], (float)v[2], 1.0f); }
void fs_exec_Vertex3iv(fs_context *c, const GLint *v) { vertex4(c, (float)v[0], (float)v[1], (float)v[2], 1.0f); }
void fs_exec_Vertex3sv(fs_context *c, const GLshort *v) { vertex4(c, v[0], v[1], v[2], 1.0f); }
void fs_exec_Vertex4fv(fs_context *c, const GLfloat *v) { vertex4(c, v[0], v[1], v[2], v[3]); }
void fs_exec_Vertex4dv(fs_context *c, const GLdouble *v) { vertex4(c, (float)v[0], (float)v[1], (float)v[2], (float)v[3]); }
void fs_exec_Vertex4iv(fs_context *c, const GLint *v) { vertex4(c, (float)v[0], (float)v[1], (float)v[2], (float)v[3]); }
void fs_exec_Vertex4sv(fs_context *c, const GLshort *v) { vertex4(c, v[0], v[1], v[2], v[3]); }

/* ---- colours (table 2.9) ---- */

static void color4(fs_context *c, float r, float g, float b, float a)
{
    fs_vs_attrib_given(c, FS_ATTR_COLOR);
    c->current.color[0] = r;
    c->current.color[1] = g;
    c->current.color[2] = b;
    c->current.color[3] = a;
    /* Outside Begin/End the tracked material follows at once (2.14.3);
     * inside, each vertex carries its colour to the lighting step. */
    if (c->lighting.color_material && !c->prim.inside_begin)
        fs_color_material_update(c);
}

void fs_exec_Color3f(fs_context *c, GLfloat r, GLfloat g, GLfloat b) { color4(c, r, g, b, 1.0f); }
void fs_exec_Color3d(fs_context *c, GLdouble r, GLdouble g, GLdouble b) { color4(c, (float)r, (float)g, (float)b, 1.0f); }
void fs_exec_Color3ub(fs_context *c, GLubyte r, GLubyte g, GLubyte b) { color4(c, UB2F(r), UB2F(g), UB2F(b), 1.0f); }
void fs_exec_Color3b(fs_context *c, GLbyte r, GLbyte g, GLbyte b) { color4(c, B2F(r), B2F(g), B2F(b), 1.0f); }
void fs_exec_Color3i(fs_context *c, GLint r, GLint g, GLint b) { color4(c, I2F(r), I2F(g), I2F(b), 1.0f); }
void fs_exec_Color3ui(fs_context *c, GLuint r, GLuint g, GLuint b) { color4(c, UI2F(r), UI2F(g), UI2F(b), 1.0f); }
void fs_exec_Color3s(fs_context *c, GLshort r, GLshort g, GLshort b) { color4(c, S2F(r), S2F(g), S2F(b), 1.0f); }
void fs_exec_Color3us(fs_context *c, GLushort r, GLushort g, GLushort b) { color4(c, US2F(r), US2F(g), US2F(b), 1.0f); }
void fs_exec_Color4f(fs_context *c, GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color4(c, r, g, b, a); }
void fs_exec_Color4d(fs_context *c, GLdouble r, GLdouble g, GLdouble b, GLdouble a) { color4(c, (float)r, (float)g, (float)b, (float)a); }
void fs_exec_Color4ub(fs_context *c, GLubyte r, GLubyte g, GLubyte b, GLubyte a) { color4(c, UB2F(r), UB2F(g), UB2F(b), UB2F(a)); }
void fs_exec_Color4b(fs_context *c, GLbyte r, GLbyte g, GLbyte b, GLbyte a) { color4(c, B2F(r), B2F(g), B2F(b), B2F(a)); }
void fs_exec_Color4i(fs_context *c, GLint r, GLint g, GLint b, GLint a) { color4(c, I2F(r), I2F(g), I2F(b), I2F(a)); }
void fs_exec_Color4ui(fs_context *c, GLuint r, GLuint g, GLuint b, GLuint a) { color4(c, UI2F(r), UI2F(g), UI2F(b), UI2F(a)); }
void fs_exec_Color4s(fs_context *c, GLshort r, GLshort g, GLshort b, GLshort a) { color4(c, S2F(r), S2F(g), S2F(b), S2F(a)); }
void fs_exec_Color4us(fs_context *c, GLushort r, GLushort g, GLushort b, GLushort a) { color4(c, US2F(r), US2F(g), US2F(b), US2F(a)); }
void fs_exec_Color3fv(fs_context *c, const GLfloat *v) { color4(c, v[0], v[1], v[2], 1.0f); }
void fs_exec_Color3dv(fs_context *c, const GLdouble *v) { color4(c, (float)v[0], (float)v[1], (float)v[2], 1.0f); }
void fs_exec_Color3ubv(fs_context *c, const GLubyte *v) { color4(c, UB2F(v[0]), UB2F(v[1]), UB2F(v[2]), 1.0f); }
void fs_exec_Color4fv(fs_context *c, const GLfloat *v) { color4(c, v[0], v[1], v[2], v[3]); }
void fs_exec_Color4dv(fs_context *c, const GLdouble *v) { color4(c, (float)v[0], (float)v[1], (float)v[2], (float)v[3]); }
void fs_exec_Color4ubv(fs_context *c, const GLubyte *v) { color4(c, UB2F(v[0]), UB2F(v[1]), UB2F(v[2]), UB2F(v[3])); }

/* ---- normals (signed conversions of table 2.9) ---- */
static void normal3(fs_context *c, float x, float y, float z)
{
    c->current.normal[0] = x;
    c->current.normal[1] = y;
    c->current.normal[2] = z;
}

void fs_exec_Normal3f(fs_context *c, GLfloat x, GLfloat y, GLfloat z) { normal3(c, x, y, z); }
void fs_exec_Normal3d(fs_context *c, GLdouble x, GLdouble y, GLdouble z) { normal3(c, (float)x, (float)y, (float)z); }
void fs_exec_Normal3b(fs_context *c, GLbyte x, GLbyte y, GLbyte z) { normal3(c, B2F(x), B2F(y), B2F(z)); }
void fs_exec_Normal3i(fs_context *c, GLint x, GLint y, GLint z) { normal3(c, I2F(x), I2F(y), I2F(z)); }
void fs_exec_Normal3s(fs_context *c, GLshort x, GLshort y, GLshort z) { normal3(c, S2F(x), S2F(y), S2F(z)); }
void fs_exec_Normal3fv(fs_context *c, const GLfloat *v) { normal3(c, v[0], v[1], v[2]); }
void fs_exec_Normal3dv(fs_context *c, const GLdouble *v) { normal3(c, (float)v[0], (float)v[1], (float)v[2]); }

/* ---- the edge flag (2.6.2): each vertex carries the current one; it
 * decides the edges drawn in the GL_LINE and GL_POINT polygon modes ---- */
static void edge_flag(fs_context *c, bool flag)
{
    c->st.edge_flag = flag;
    /* Given between Begin and End, the flag is per-vertex data of the
     * batch (Mesa's vbo makes it a vertex attribute), whatever its values. */
    if (c->prim.inside_begin && fs_vs(c) && !fs_vs(c)->iv_edge_used)
        vertex_edge_flags_start(fs_vs(c));
}

void fs_exec_EdgeFlag(fs_context *c, GLboolean flag) { edge_flag(c, flag != GL_FALSE); }
void fs_exec_EdgeFlagv(fs_context *c, const GLubyte *flag) { edge_flag(c, flag[0] != GL_FALSE); }

/* ---- texture coordinates (2.7): glTexCoord sets unit 0's, glMultiTexCoord
 * (texture_coords.c) those of any unit ---- */
void fs_current_texcoord(fs_context *c, int unit, float s, float t, float r, float q)
{
    fs_vs_attrib_given(c, FS_ATTR_TEX(unit));
    float *v = c->current.texcoord[unit];
    v[0] = s;
    v[1] = t;
    v[2] = r;
    v[3] = q;
}

static void texcoord4(fs_context *c, float s, float t, float r, float q) { fs_current_texcoord(c, 0, s, t, r, q); }

void fs_exec_TexCoord1f(fs_context *c, GLfloat s) { texcoord4(c, s, 0.0f, 0.0f, 1.0f); }
void fs_exec_TexCoord2f(fs_context *c, GLfloat s, GLfloat t) { texcoord4(c, s, t, 0.0f, 1.0f); }
void fs_exec_TexCoord3f(fs_context *c, GLfloat s, GLfloat t, GLfloat r) { texcoord4(c, s, t, r, 1.0f); }
void fs_exec_TexCoord4f(fs_context *c, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { texcoord4(c, s, t, r, q); }
void fs_exec_TexCoord2d(fs_context *c, GLdouble s, GLdouble t) { texcoord4(c, (float)s, (float)t, 0.0f, 1.0f); }
void fs_exec_TexCoord2i(fs_context *c, GLint s, GLint t) { texcoord4(c, (float)s, (float)t, 0.0f, 1.0f); }
void fs_exec_TexCoord2fv(fs_context *c, const GLfloat *v) { texcoord4(c, v[0], v[1], 0.0f, 1.0f); }
void fs_exec_TexCoord2dv(fs_context *c, const GLdouble *v) { texcoord4(c, (float)v[0], (float)v[1], 0.0f, 1.0f); }

/* ---- the colour index (2.7): stored for glGet, the window being RGBA ---- */
void fs_exec_Indexf(fs_context *c, GLfloat c_) { c->st.current_index = c_; }

/* ---- rectangles (2.10) ----
 * glRect(x1, y1, x2, y2) is exactly the sequence Begin(POLYGON),
 * Vertex2(x1, y1), Vertex2(x2, y1), Vertex2(x2, y2), Vertex2(x1, y2),
 * End(), so it takes the immediate-mode path (and gets its errors). */
void fs_exec_Rectf(fs_context *c, GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2)
{
    fs_exec_Begin(c, GL_POLYGON);
    vertex4(c, x1, y1, 0.0f, 1.0f);
    vertex4(c, x2, y1, 0.0f, 1.0f);
    vertex4(c, x2, y2, 0.0f, 1.0f);
    vertex4(c, x1, y2, 0.0f, 1.0f);
    fs_exec_End(c);
}
