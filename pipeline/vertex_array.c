/*
 * Client vertex arrays (GL 1.5 spec 2.8): the array pointers (and
 * glGetPointerv, 6.1.11) and ArrayElement, DrawArrays, MultiDrawArrays,
 * DrawElements, DrawRangeElements; and the
 * per-vertex transformation shared with immediate mode (2.10-2.11):
 * clip = (P * M) * obj in float, the order Mesa's fixed-function vertex
 * program uses (measured against OSMesa feedback: a plain multiply-add
 * chain, no fused multiply-add), then x_w = fma(x_c * (1/w_c), scale,
 * translate) as llvmpipe's draw module computes it.
 *
 * A draw is fetched into one batch, transformed in one loop and assembled
 * in primitive.c; buffers grow once and are reused (no per-vertex malloc).
 */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "vertex_internal.h"

int fs_type_size(GLenum type)
{
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: return 2;
    case GL_3_BYTES: return 3;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
    }
}

int64_t fs_index_bytes(GLsizei count, GLenum type)
{
    if (count <= 0)
        return 0;
    if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
        return 0;
    return (int64_t)count * fs_type_size(type);
}

int64_t fs_calllists_bytes(GLsizei n, GLenum type)
{
    if (n <= 0)
        return 0;
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT:
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT:
    case GL_2_BYTES: case GL_3_BYTES: case GL_4_BYTES:
        return (int64_t)n * fs_type_size(type);
    default:
        return 0;
    }
}

/* ---- array specification ---- */
/* GL 1.5 spec 2.9.1: the array takes the buffer bound to GL_ARRAY_BUFFER
 * now, and p is then an offset into it (resolved at each draw, as the
 * store may change: pipeline/buffer_object.c). */
static void set_array(fs_context *c, fs_client_array *a, GLint size, GLenum type, GLsizei stride, const void *p)
{
    a->size = size;
    a->type = type;
    a->stride = stride;
    a->pointer = p;
    a->buffer = c->arrays.array_buffer;
    a->bytes = p || a->buffer ? SIZE_MAX : 0;
}

void fs_exec_VertexPointer(fs_context *c, GLint size, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    if (size < 2 || size > 4 || stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    set_array(c, &c->arrays.vertex, size, type, stride, pointer);
}

void fs_exec_NormalPointer(fs_context *c, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    if (stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (type != GL_BYTE && type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    set_array(c, &c->arrays.normal, 3, type, stride, pointer);
}

/* glColorPointer and glSecondaryColorPointer take the same sizes and types. */
static void color_pointer(fs_context *c, fs_client_array *a, GLint size, GLenum type, GLsizei stride,
                          const GLvoid *pointer)
{
    if (size < 3 || size > 4 || stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (fs_type_size(type) == 0 || type == GL_2_BYTES || type == GL_3_BYTES || type == GL_4_BYTES) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    set_array(c, a, size, type, stride, pointer);
}

void fs_exec_ColorPointer(fs_context *c, GLint size, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    color_pointer(c, &c->arrays.color, size, type, stride, pointer);
}

void fs_exec_TexCoordPointer(fs_context *c, GLint size, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    if (size < 1 || size > 4 || stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    set_array(c, &c->arrays.texcoord[fs_client_active_unit(c)], size, type, stride, pointer);
}

/* GL 1.4's arrays and the edge flag and index arrays, with the errors
 * OSMesa raises (measured by tests/test_color_sum.c): a secondary colour
 * has 3 or 4 components (GL_BGRA is not modelled: GL_INVALID_VALUE) of any
 * glColorPointer type; a fog coordinate is GL_FLOAT or GL_DOUBLE (OSMesa
 * also takes GL_HALF_FLOAT, which fragsim does not fetch:
 * GL_INVALID_ENUM); an index GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT
 * or GL_DOUBLE; a negative stride is GL_INVALID_VALUE. */
void fs_exec_SecondaryColorPointer(fs_context *c, GLint size, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    color_pointer(c, &c->arrays.secondary_color, size, type, stride, pointer);
}

void fs_exec_FogCoordPointer(fs_context *c, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    if (type != GL_FLOAT && type != GL_DOUBLE) { fs_error(c, GL_INVALID_ENUM); return; }
    if (stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    set_array(c, &c->arrays.fog_coord, 1, type, stride, pointer);
}

void fs_exec_EdgeFlagPointer(fs_context *c, GLsizei stride, const GLvoid *pointer)
{
    if (stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    set_array(c, &c->arrays.edge_flag, 1, GL_UNSIGNED_BYTE, stride, pointer);
}

void fs_exec_IndexPointer(fs_context *c, GLenum type, GLsizei stride, const GLvoid *pointer)
{
    if (type != GL_UNSIGNED_BYTE && type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    set_array(c, &c->arrays.index, 1, type, stride, pointer);
}

static fs_client_array *array_of(fs_context *c, GLenum array)
{
    switch (array) {
    case GL_VERTEX_ARRAY: return &c->arrays.vertex;
    case GL_NORMAL_ARRAY: return &c->arrays.normal;
    case GL_COLOR_ARRAY: return &c->arrays.color;
    case GL_TEXTURE_COORD_ARRAY: return &c->arrays.texcoord[fs_client_active_unit(c)];
    case GL_SECONDARY_COLOR_ARRAY: return &c->arrays.secondary_color;
    case GL_FOG_COORDINATE_ARRAY: return &c->arrays.fog_coord;
    case GL_EDGE_FLAG_ARRAY: return &c->arrays.edge_flag;
    case GL_INDEX_ARRAY: return &c->arrays.index;
    default: return NULL;
    }
}

/* GL 1.5 spec 2.8: the six arrays of table 2.4 plus GL 1.4's fog
 * coordinate and secondary colour arrays are valid names. */
static void client_state(fs_context *c, GLenum array, bool on)
{
    fs_client_array *a = array_of(c, array);
    if (!a) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    a->enabled = on;
}

/* GL 1.5 spec 6.1.11: each array's pointer as it was given (an offset when
 * a buffer object was bound), the texture coordinates of the client active
 * unit; the selection and feedback buffers (5.2, 5.3). */
void fs_exec_GetPointerv(fs_context *c, GLenum pname, GLvoid **params)
{
    GLenum array;
    switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: array = GL_VERTEX_ARRAY; break;
    case GL_NORMAL_ARRAY_POINTER: array = GL_NORMAL_ARRAY; break;
    case GL_COLOR_ARRAY_POINTER: array = GL_COLOR_ARRAY; break;
    case GL_TEXTURE_COORD_ARRAY_POINTER: array = GL_TEXTURE_COORD_ARRAY; break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: array = GL_SECONDARY_COLOR_ARRAY; break;
    case GL_FOG_COORDINATE_ARRAY_POINTER: array = GL_FOG_COORDINATE_ARRAY; break;
    case GL_EDGE_FLAG_ARRAY_POINTER: array = GL_EDGE_FLAG_ARRAY; break;
    case GL_INDEX_ARRAY_POINTER: array = GL_INDEX_ARRAY; break;
    case GL_SELECTION_BUFFER_POINTER: *params = c->rmode.select_buf; return;
    case GL_FEEDBACK_BUFFER_POINTER: *params = c->rmode.feedback_buf; return;
    default: fs_error(c, GL_INVALID_ENUM); return;
    }
    *params = (GLvoid *)(uintptr_t)array_of(c, array)->pointer;
}

void fs_exec_EnableClientState(fs_context *c, GLenum array) { client_state(c, array, true); }
void fs_exec_DisableClientState(fs_context *c, GLenum array) { client_state(c, array, false); }

/* ---- glInterleavedArrays (GL 1.5 spec 2.8, table 2.5) ----
 * One row per format: the flags et, ec, en, the sizes st, sc, sv, the
 * colour type tc and the offsets pc, pn, pv and the whole size s, in
 * bytes, with f = sizeof(float) and c = 4 unsigned bytes rounded up to a
 * multiple of f (4 bytes). */
typedef struct interleaved_row {
    GLenum format;
    bool et, ec, en;
    GLint st, sc, sv;
    GLenum tc;
    int pc, pn, pv, s;
} interleaved_row;

#define F_ 4
#define C_ 4
static const interleaved_row interleaved_rows[14] = {
    {GL_V2F, false, false, false, 0, 0, 2, 0, 0, 0, 0, 2 * F_},
    {GL_V3F, false, false, false, 0, 0, 3, 0, 0, 0, 0, 3 * F_},
    {GL_C4UB_V2F, false, true, false, 0, 4, 2, GL_UNSIGNED_BYTE, 0, 0, C_, C_ + 2 * F_},
    {GL_C4UB_V3F, false, true, false, 0, 4, 3, GL_UNSIGNED_BYTE, 0, 0, C_, C_ + 3 * F_},
    {GL_C3F_V3F, false, true, false, 0, 3, 3, GL_FLOAT, 0, 0, 3 * F_, 6 * F_},
    {GL_N3F_V3F, false, false, true, 0, 0, 3, 0, 0, 0, 3 * F_, 6 * F_},
    {GL_C4F_N3F_V3F, false, true, true, 0, 4, 3, GL_FLOAT, 0, 4 * F_, 7 * F_, 10 * F_},
    {GL_T2F_V3F, true, false, false, 2, 0, 3, 0, 0, 0, 2 * F_, 5 * F_},
    {GL_T4F_V4F, true, false, false, 4, 0, 4, 0, 0, 0, 4 * F_, 8 * F_},
    {GL_T2F_C4UB_V3F, true, true, false, 2, 4, 3, GL_UNSIGNED_BYTE, 2 * F_, 0, C_ + 2 * F_, C_ + 5 * F_},
    {GL_T2F_C3F_V3F, true, true, false, 2, 3, 3, GL_FLOAT, 2 * F_, 0, 5 * F_, 8 * F_},
    {GL_T2F_N3F_V3F, true, false, true, 2, 0, 3, 0, 0, 2 * F_, 5 * F_, 8 * F_},
    {GL_T2F_C4F_N3F_V3F, true, true, true, 2, 4, 3, GL_FLOAT, 2 * F_, 6 * F_, 9 * F_, 12 * F_},
    {GL_T4F_C4F_N3F_V4F, true, true, true, 4, 4, 4, GL_FLOAT, 4 * F_, 8 * F_, 11 * F_, 15 * F_},
};
#undef F_
#undef C_

/* The offset o from pointer p: an address, or with a buffer bound an
 * offset into it (2.9.1), either way p + o as an integer. */
static const void *offset_by(const void *p, int o) { return (const void *)((uintptr_t)p + (uintptr_t)o); }

/* The spec's sequence of calls: a zero stride becomes s; the edge flag
 * and index arrays are disabled; the texture coordinate, colour and normal
 * arrays enabled and set or disabled as the format says (the texture
 * coordinates of the client active unit, 2.8: glTexCoordPointer's); the
 * vertex array enabled and set.  Each pointer takes the GL_ARRAY_BUFFER
 * binding, as glXxxPointer does.  GL 1.5's version of the sequence also
 * disables the secondary colour and fog coordinate arrays; OSMesa (the
 * oracle) leaves them as they were, and so does fragsim
 * (tests/test_array_draws.c, interleaved_state_vs_osmesa). */
void fs_exec_InterleavedArrays(fs_context *c, GLenum format, GLsizei stride, const GLvoid *pointer)
{
    const interleaved_row *r = NULL;
    for (int i = 0; i < 14; i++)
        if (interleaved_rows[i].format == format)
            r = &interleaved_rows[i];
    if (stride < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (!r) { fs_error(c, GL_INVALID_ENUM); return; }
    GLsizei str = stride ? stride : r->s;
    fs_client_array *tex = &c->arrays.texcoord[fs_client_active_unit(c)];
    c->arrays.edge_flag.enabled = false;
    c->arrays.index.enabled = false;
    tex->enabled = r->et;
    if (r->et)
        set_array(c, tex, r->st, GL_FLOAT, str, pointer);
    c->arrays.color.enabled = r->ec;
    if (r->ec)
        set_array(c, &c->arrays.color, r->sc, r->tc, str, offset_by(pointer, r->pc));
    c->arrays.normal.enabled = r->en;
    if (r->en)
        set_array(c, &c->arrays.normal, 3, GL_FLOAT, str, offset_by(pointer, r->pn));
    c->arrays.vertex.enabled = true;
    set_array(c, &c->arrays.vertex, r->sv, GL_FLOAT, str, offset_by(pointer, r->pv));
}

/* ---- fetch ---- */
/* How integer components become floats: not at all (positions, texture
 * coordinates), as the colour conversions of table 2.9 (glArrayElement,
 * which OSMesa converts as the immediate commands do), or as llvmpipe's
 * vertex fetch converts the normalized arrays of a draw.  The last differs
 * for the signed types: measured on OSMesa through lit and unlit feedback
 * colours, every GL_BYTE and GL_SHORT normal and colour of a draw is
 * max(v * (1/127), -1) and max(v * (1/32767), -1) (the reciprocal rounded
 * to float first; the GL 1.5 rule (2v + 1) / 255 matches 2 of 256 bytes),
 * GL_INT max(v * (1/(2^31 - 1)), -1). */
enum { FETCH_RAW, FETCH_GL, FETCH_DRAW };

/* The signed normalization of a draw's arrays (FETCH_DRAW). */
static inline float snorm(float v, float inv_max)
{
    float f = v * inv_max;
    return f < -1.0f ? -1.0f : f;
}

/* Reads up to `size` components of element i, converted as `norm` says. */
static void fetch(const fs_client_array *a, size_t i, float out[4], int norm)
{
    int esz = fs_type_size(a->type);
    size_t stride = a->stride ? (size_t)a->stride : (size_t)esz * (size_t)a->size;
    const unsigned char *p = (const unsigned char *)a->pointer + i * stride;
    if (a->type == GL_FLOAT) {
        /* The common case, and a copy of constant size (inlined, unlike a
         * memcpy of 4 * size bytes) instead of a switch per component. */
        switch (a->size) {
        case 4: memcpy(out, p, 16); return;
        case 3: memcpy(out, p, 12); return;
        case 2: memcpy(out, p, 8); return;
        default: memcpy(out, p, 4); return;
        }
    }
    if (a->type == GL_UNSIGNED_BYTE && norm) {
        /* Byte colours (terrain, forest, bench): the expression below for
         * each byte, evaluated by the compiler (a division per component
         * was a tenth of the vertex fetch of a draw restricted to a tile
         * mask). */
#define U1(i) ((float)(i) / 255.0f)
#define U4(i) U1(i), U1((i) + 1), U1((i) + 2), U1((i) + 3)
#define U16(i) U4(i), U4((i) + 4), U4((i) + 8), U4((i) + 12)
#define U64(i) U16(i), U16((i) + 16), U16((i) + 32), U16((i) + 48)
        static const float unorm8[256] = {U64(0), U64(64), U64(128), U64(192)};
#undef U64
#undef U16
#undef U4
#undef U1
        for (int k = 0; k < a->size; k++)
            out[k] = unorm8[p[k]];
        return;
    }
    for (int k = 0; k < a->size; k++) {
        float v;
        switch (a->type) {
        case GL_FLOAT: { float f; memcpy(&f, p + 4 * k, 4); v = f; break; }
        case GL_DOUBLE: { double d; memcpy(&d, p + 8 * k, 8); v = (float)d; break; }
        case GL_UNSIGNED_BYTE: { uint8_t u = p[k]; v = norm ? (float)u / 255.0f : (float)u; break; }
        case GL_BYTE: {
            int8_t s = (int8_t)p[k];
            v = norm == FETCH_DRAW ? snorm(s, 1.0f / 127.0f) : norm ? (2.0f * s + 1.0f) / 255.0f : (float)s;
            break;
        }
        case GL_UNSIGNED_SHORT: { uint16_t u; memcpy(&u, p + 2 * k, 2); v = norm ? (float)u / 65535.0f : (float)u; break; }
        case GL_SHORT: {
            int16_t s;
            memcpy(&s, p + 2 * k, 2);
            v = norm == FETCH_DRAW ? snorm(s, 1.0f / 32767.0f) : norm ? (2.0f * s + 1.0f) / 65535.0f : (float)s;
            break;
        }
        case GL_UNSIGNED_INT: { uint32_t u; memcpy(&u, p + 4 * k, 4); v = norm ? (float)(u / 4294967295.0) : (float)u; break; }
        case GL_INT: {
            int32_t s;
            memcpy(&s, p + 4 * k, 4);
            v = norm == FETCH_DRAW ? snorm((float)s, 1.0f / 2147483647.0f)
                : norm             ? (float)((2.0 * s + 1.0) / 4294967295.0)
                                   : (float)s;
            break;
        }
        default: v = 0.0f; break;
        }
        out[k] = v;
    }
}

/* An input vertex's position from the vertex array. */
static inline void fetch_position(const fs_context *c, size_t i, fs_ivert *o)
{
    o->obj[0] = o->obj[1] = o->obj[2] = 0.0f;
    o->obj[3] = 1.0f;
    fetch(&c->arrays.vertex, i, o->obj, FETCH_RAW);
}

/* Positions of n consecutive elements from `first`: float arrays, the
 * usual case, without fetch's per-element type dispatch (under a tile mask
 * most vertices fetch nothing else). */
static void fetch_positions(const fs_context *c, size_t first, size_t n, fs_ivert *o)
{
    const fs_client_array *a = &c->arrays.vertex;
    if (a->type != GL_FLOAT) {
        for (size_t i = 0; i < n; i++)
            fetch_position(c, first + i, &o[i]);
        return;
    }
    const size_t stride = a->stride ? (size_t)a->stride : 4 * (size_t)a->size;
    const unsigned char *p = (const unsigned char *)a->pointer + first * stride;
    const float fill[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (size_t i = 0; i < n; i++, p += stride) {
        memcpy(o[i].obj, fill, sizeof fill);
        if (a->size == 3) /* constant sizes: copies inlined, not memcpy calls */
            memcpy(o[i].obj, p, 12);
        else if (a->size == 2)
            memcpy(o[i].obj, p, 8);
        else
            memcpy(o[i].obj, p, 16);
    }
}

/* The secondary colour (its alpha is 1 whatever a size-4 array holds) and
 * the fog coordinate from their arrays, else the current values (2.8). */
static void fetch_gl14_attributes(const fs_context *c, size_t i, fs_ivert *o, int norm)
{
    const fs_array_state *A = &c->arrays;
    memcpy(o->col2, c->current.secondary_color, sizeof o->col2);
    if (A->secondary_color.enabled) {
        float s[4];
        fetch(&A->secondary_color, i, s, norm);
        memcpy(o->col2, s, 3 * sizeof(float));
    }
    o->fogc = c->current.fog_coord;
    if (A->fog_coord.enabled) {
        float f[4];
        fetch(&A->fog_coord, i, f, FETCH_RAW);
        o->fogc = f[0];
    }
}

/* Element i's edge flag from the enabled edge flag array (2.8). */
static bool array_edge_flag(const fs_context *c, size_t i)
{
    float e[4];
    fetch(&c->arrays.edge_flag, i, e, FETCH_RAW);
    return e[0] != 0.0f;
}

/* Its other attributes from the enabled arrays, the current values
 * elsewhere; norm: FETCH_DRAW for a draw, FETCH_GL for glArrayElement. */
static void fetch_attributes(const fs_context *c, size_t i, fs_ivert *o, int ntex, int norm)
{
    const fs_array_state *A = &c->arrays;
    if (A->color.enabled) {
        o->col[3] = 1.0f;
        fetch(&A->color, i, o->col, norm);
    } else {
        memcpy(o->col, c->current.color, sizeof o->col);
    }
    if (A->normal.enabled) {
        float n[4];
        fetch(&A->normal, i, n, norm);
        memcpy(o->nrm, n, sizeof o->nrm);
    } else {
        memcpy(o->nrm, c->current.normal, sizeof o->nrm);
    }
    for (int u = 0; u < ntex; u++) {
        if (A->texcoord[u].enabled) {
            o->tc[u][0] = o->tc[u][1] = o->tc[u][2] = 0.0f;
            o->tc[u][3] = 1.0f;
            fetch(&A->texcoord[u], i, o->tc[u], FETCH_RAW);
        } else {
            memcpy(o->tc[u], c->current.texcoord[u], sizeof o->tc[u]);
        }
    }
    fetch_gl14_attributes(c, i, o, norm);
}

static void fetch_vertex(const fs_context *c, size_t i, fs_ivert *o)
{
    fetch_position(c, i, o);
    fetch_attributes(c, i, o, c->raster.tex_units, FETCH_DRAW);
}

/* ---- transformation ---- */
/* Which attributes llvmpipe shades as constants (fs_raster_state.const_attribs).
 * Mesa's fixed-function fragment program takes a colour or texture
 * coordinate input from the vertex stage only when that stage can vary it
 * (its filter of possible inputs, ff_fragment_shader.cpp): the primary
 * colour when it comes per vertex or from lighting (GL 1.5 spec 2.14.1),
 * the secondary when per vertex or from separate specular lighting
 * (2.14.2), unit u's coordinates when per vertex, generated (2.11.4) or
 * through a texture matrix other than the identity (2.11.2).  Otherwise it
 * reads the current value as a constant, without the perspective division
 * (measured: tests/test_constant_attribs.c). */
void fs_vs_constant_attribs(fs_context *c, const fs_vs_setup *s, unsigned varying)
{
    unsigned k = 0;
    if (!(varying & FS_ATTR_COLOR) && !s->lighting)
        k |= FS_ATTR_COLOR;
    if (!(varying & FS_ATTR_COLOR2) && !s->separate_specular)
        k |= FS_ATTR_COLOR2;
    for (int u = 0; u < s->ntex; u++) {
        bool gen = false;
        for (int j = 0; j < 4; j++)
            gen |= s->texgen_mode[u][j] != FS_TG_NONE;
        if (!(varying & FS_ATTR_TEX(u)) && !gen && s->tex_identity[u])
            k |= FS_ATTR_TEX(u);
    }
    c->raster.const_attribs = k;
}

void fs_vs_prepare(fs_context *c, fs_vs_setup *s)
{
    const fs_transform_state *x = &c->xf;
    fs_modelview_analyse(c);
    fs_matrix *mvm = &c->xf.modelview[x->modelview_top];
    const float *mv = mvm->m;
    memcpy(s->mv, mv, sizeof s->mv);
    /* Mesa analyses the modelview at each draw; its inverse (the normal
     * matrix, lighting's object space, texgen) follows the analysis.
     * Draws of one object share a modelview: invert it once (the
     * persistent setup of the context keeps the last one). */
    if (!(s->nmat_valid && s->nmat_flags == mvm->flags && memcmp(s->nmat_of, mv, sizeof s->nmat_of) == 0)) {
        s->mv_rigid = fs_matrix_invert(s->mv_inv, mvm);
        memcpy(s->nmat_of, mv, sizeof s->nmat_of);
        s->nmat_flags = mvm->flags;
        s->nmat_valid = true;
        /* The inverse's rows are the normal matrix; GL_RESCALE_NORMAL's
         * factor is 1 / |third row|, 1 for a length-preserving modelview
         * (Mesa's normal scale). */
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                s->nmat[r * 3 + k] = s->mv_inv[r * 4 + k];
        const float *inv = s->mv_inv;
        float d = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
        s->nscale = s->mv_rigid || d < 1e-12f ? 1.0f : 1.0f / sqrtf(d);
    }
    fs_mat_mul(s->mvp, x->projection[x->projection_top].m, mv);
    float id[16];
    fs_mat_identity(id);
    s->ntex = c->raster.tex_units;
    for (int u = 0; u < s->ntex; u++) {
        memcpy(s->tex[u], x->texture[u][x->texture_top[u]].m, sizeof s->tex[u]);
        s->tex_identity[u] = memcmp(s->tex[u], id, sizeof id) == 0;
    }
    fs_viewport_xform(c, s->vp_scale, s->vp_trans);
    fs_clip_plane_setup(c, s);
    s->has_fma = c->raster.has_fma;
    s->has_avx2 = c->raster.has_avx2;
    s->edge = NULL;
    s->defer = false;
    /* llvmpipe draws OSMesa's buffer y-down: Mesa's state tracker negates the
     * y scale and takes the translation from the framebuffer height. */
    s->yr_scale = -s->vp_scale[1];
    s->yr_trans = (float)c->fb.height - s->vp_trans[1];
    c->raster.use_y_raster = true; /* every fs_rvertex from here carries it */
    s->flat = c->lighting.shade_model == GL_FLAT;
    s->flat_first = s->flat && c->lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
    c->raster.flat_color = s->flat;
    c->raster.const_attribs = 0; /* interpolate all unless the draw says (fs_vs_constant_attribs) */
    s->fog = c->st.fog.enabled;
    s->fog_from_coord = c->st.fog.coord_src == GL_FOG_COORD;
    c->raster.interpolate_fog = s->fog;
    const fs_raster_state *r = &c->raster;
    s->points_attenuated = fs_point_attenuated(r);
    memcpy(s->point_atten, r->point_atten, sizeof s->point_atten);
    s->point_size = s->points_attenuated ? r->point_size : fs_point_size(r);
    /* Mesa's vertex program clamps to the bounds narrowed to the
     * implementation's range, [1, 255] for llvmpipe whichever kind of
     * point (GL_POINT_SIZE_RANGE and GL_ALIASED_POINT_SIZE_RANGE agree):
     * measured on OSMesa, a smooth point attenuated below size 1 is drawn
     * as size 1. */
    s->point_size_min = r->point_size_min > 1.0f ? r->point_size_min : 1.0f;
    s->point_size_max = r->point_size_max < 255.0f ? r->point_size_max : 255.0f;
    fs_color_sum_setup(c, s);
    fs_lighting_setup(c, s);
    fs_texgen_setup(c, s);
    /* Draws of one object share a modelview: invert it once (the
     * persistent setup of the context keeps the last one). */
    if (s->lighting)
        fs_lighting_spaces(s);
}

static float clamp01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

/* Clip and window coordinates of one vertex (GL 1.5 spec 2.10-2.11). */
static inline void vs_position(const fs_vs_setup *s, const fs_ivert *v, fs_pvert *o)
{
    fs_mat_xform4(o->clip, s->mvp, v->obj);
    o->mask = fs_clip_mask(o->clip);
    /* Computed for every vertex: points and lines outside only the x/y
     * planes are drawn unclipped.  w = 0 gives infinities, not a trap. */
    const float iw = 1.0f / o->clip[3];
    o->win[0] = fmaf(o->clip[0] * iw, s->vp_scale[0], s->vp_trans[0]);
    o->win[1] = fmaf(o->clip[1] * iw, s->vp_scale[1], s->vp_trans[1]);
    o->win[2] = fmaf(o->clip[2] * iw, s->vp_scale[2], s->vp_trans[2]);
    o->win[3] = iw;
    o->win[4] = fmaf(o->clip[1] * iw, s->yr_scale, s->yr_trans);
}

/* The fog coordinate (GL 1.5 spec 3.10): of a GL_FOG_COORD source, the
 * vertex's fog coordinate's absolute value (measured on OSMesa: -1 fogs
 * as 1; Mesa 22's vertex shader takes |c| from the array or the current
 * value); of a GL_FRAGMENT_DEPTH source:
 * llvmpipe's fixed-function vertex shader takes the eye-plane distance,
 * |z_e|, with z_e the modelview's third row times the object position in
 * the order and float precision of the position transform (so the same
 * bits as the z of the eye position lighting uses). */
static inline float vs_fog_coord(const fs_vs_setup *s, const fs_ivert *v)
{
    const float *m = s->mv;
    float z = m[2] * v->obj[0];
    z = z + m[6] * v->obj[1];
    z = z + m[10] * v->obj[2];
    z = z + m[14] * v->obj[3];
    return fabsf(z);
}

/* Colours (lighting, GL 1.5 spec 2.14) and texture coordinates (2.10.2). */
static inline void vs_attributes(const fs_vs_setup *s, const fs_ivert *v, fs_pvert *o)
{
    float eye[4] = {0, 0, 0, 1};
    if (s->lighting) {
        float nrm[3];
        fs_vs_eye_normal(s, v, eye, nrm);
        fs_light_vertex(s, eye, nrm, v->col, o->col, o->col2);
    } else {
        for (int k = 0; k < 4; k++)
            o->col[0][k] = clamp01(v->col[k]);
    }
    if (s->texgen) {
        fs_texgen_vertex(s, v, eye, o); /* generation, then the texture matrices */
    } else {
        for (int u = 0; u < s->ntex; u++) {
            if (s->tex_identity[u])
                memcpy(o->tc[u], v->tc[u], sizeof o->tc[u]);
            else
                fs_mat_xform4(o->tc[u], s->tex[u], v->tc[u]);
        }
    }
    if (s->fog)
        o->fog = s->fog_from_coord ? fabsf(v->fogc) : vs_fog_coord(s, v);
    /* The attenuation's eye distance is the fog's |z_e| (point_state.c). */
    o->psize = s->points_attenuated ? fs_point_derived_size(s, vs_fog_coord(s, v)) : s->point_size;
    if (s->color_sum && !s->lighting)
        for (int k = 0; k < 4; k++)
            o->col2[0][k] = clamp01(v->col2[k]);
    else if (s->color_sum && !s->separate_specular)
        memset(o->col2, 0, sizeof o->col2); /* lit: no secondary colour is written */
}

/* A box edge as a pixel within [0, 65536] (compares, not fminf/fmaxf,
 * which are library calls here: this runs for every triangle). */
static inline int box_pixel(float v)
{
    return v > 0.0f ? (v < 65536.0f ? (int)v : 65536) : 0;
}

/* Whether a window-space box touches a tile of the tile mask (one pixel of
 * margin: fragments lie within the vertices' box). */
bool fs_vs_box_masked(const fs_tile_mask *t, float x0, float y0, float x1, float y1)
{
    if (!(x0 <= x1 && y0 <= y1))
        return true; /* NaN: let the rasterizer decide */
    int ix0 = box_pixel(x0 - 1.0f), iy0 = box_pixel(y0 - 1.0f);
    int ix1 = box_pixel(x1 + 1.0f), iy1 = box_pixel(y1 + 1.0f);
    return fs_tile_mask_meets_box(t, ix0, iy0, ix1, iy1);
}

static uint32_t index_at(const void *indices, GLenum type, size_t i);

void fs_vs_attributes(fs_context *c, const fs_vs_setup *s, fs_ivert *iv, fs_pvert *pv, size_t k)
{
    const fs_vs_impl *v = fs_vs(c);
    if (v->deferred)
        fetch_attributes(c, v->src_indices ? index_at(v->src_indices, v->src_type, k) : v->src_first + k, &iv[k], s->ntex,
                         FETCH_DRAW);
    vs_attributes(s, &iv[k], &pv[k]);
    pv[k].lazy = false;
}

/* What the tile mask needs of a batch's positions: the window box and
 * the clip masks or-ed (any vertex outside a plane) and and-ed (all
 * outside one). */
typedef struct vs_bounds {
    float x0, y0, x1, y1;
    unsigned any, all;
} vs_bounds;

/* Compares, not fminf/fmaxf (library calls here): a NaN position leaves
 * the box as they would. */
static inline void box_add(vs_bounds *b, float x, float y)
{
    b->x0 = x < b->x0 ? x : b->x0;
    b->x1 = x > b->x1 ? x : b->x1;
    b->y0 = y < b->y0 ? y : b->y0;
    b->y1 = y > b->y1 ? y : b->y1;
}

static inline void bounds_add(vs_bounds *b, const fs_pvert *o)
{
    b->any |= o->mask;
    b->all &= o->mask;
    box_add(b, o->win[0], o->win[1]);
}

#if FS_VS_HAVE_FMA
/* fs_mat_xform4 and fs_clip_mask lane by lane (products and sums rounded
 * one by one in vs_position's order; ordered compares are false on NaN, as
 * C's). */
__attribute__((target("avx2,fma"))) static inline __m256i xform_mask8(const __m256 m[16], const __m256 v[4], __m256 c[4])
{
    const __m256 zero = _mm256_setzero_ps();
    for (int r = 0; r < 4; r++) { /* fs_mat_xform4 */
        __m256 a = _mm256_mul_ps(m[r], v[0]);
        a = _mm256_add_ps(a, _mm256_mul_ps(m[4 + r], v[1]));
        a = _mm256_add_ps(a, _mm256_mul_ps(m[8 + r], v[2]));
        c[r] = _mm256_add_ps(a, _mm256_mul_ps(m[12 + r], v[3]));
    }
#define BIT(cmp, bit) _mm256_and_si256(_mm256_castps_si256(cmp), _mm256_set1_epi32(bit))
    __m256i mk = _mm256_or_si256(
        _mm256_or_si256(BIT(_mm256_cmp_ps(c[0], c[3], _CMP_GT_OQ), 1),
                        BIT(_mm256_cmp_ps(zero, _mm256_add_ps(c[0], c[3]), _CMP_GT_OQ), 2)),
        _mm256_or_si256(_mm256_or_si256(BIT(_mm256_cmp_ps(c[1], c[3], _CMP_GT_OQ), 4),
                                        BIT(_mm256_cmp_ps(zero, _mm256_add_ps(c[1], c[3]), _CMP_GT_OQ), 8)),
                        _mm256_or_si256(BIT(_mm256_cmp_ps(zero, _mm256_add_ps(c[2], c[3]), _CMP_GT_OQ), 16),
                                        BIT(_mm256_cmp_ps(c[2], c[3], _CMP_GT_OQ), 32))));
    __m256i bad = _mm256_and_si256(_mm256_cmpeq_epi32(mk, _mm256_setzero_si256()),
                                   _mm256_castps_si256(_mm256_cmp_ps(c[3], zero, _CMP_NGT_UQ)));
#undef BIT
    return _mm256_or_si256(mk, _mm256_and_si256(bad, _mm256_set1_epi32(0x3f)));
}

/* vs_position and bounds_add for the first multiple of 8 vertices, 8 at a
 * time; returns how many it did.  Each lane does the operations of
 * vs_position in the same order (products and sums rounded one by one,
 * a true division, fused viewport multiply-adds) and the compares of
 * fs_clip_mask and bounds_add with the same NaN outcome (ordered compares
 * are false on NaN, as C's), so every bit is the same as one at a time.
 * b: the batch's bounds, for the tile mask.  Under a tile mask most
 * batches need only this pass, which was then a third of the run's time. */
__attribute__((target("avx2,fma"), always_inline)) static inline size_t
vs_positions8_core(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out, size_t n, vs_bounds *b, const bool bounds)
{
    enum { STRIDE = sizeof(fs_ivert) / sizeof(float) };
    _Static_assert(sizeof(fs_ivert) % sizeof(float) == 0, "fs_ivert is floats");
    _Static_assert(offsetof(fs_pvert, win) == offsetof(fs_pvert, clip) + 4 * sizeof(float),
                   "clip and win[0..3] are one 8-float store");
    const __m256i gather = _mm256_mullo_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), _mm256_set1_epi32(STRIDE));
    __m256 m[16];
    for (int i = 0; i < 16; i++)
        m[i] = _mm256_set1_ps(s->mvp[i]);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 sx = _mm256_set1_ps(s->vp_scale[0]), tx = _mm256_set1_ps(s->vp_trans[0]);
    const __m256 sy = _mm256_set1_ps(s->vp_scale[1]), ty = _mm256_set1_ps(s->vp_trans[1]);
    const __m256 sz = _mm256_set1_ps(s->vp_scale[2]), tz = _mm256_set1_ps(s->vp_trans[2]);
    const __m256 sr = _mm256_set1_ps(s->yr_scale), tr = _mm256_set1_ps(s->yr_trans);
    __m256 x0 = _mm256_set1_ps(bounds ? b->x0 : 0), x1 = _mm256_set1_ps(bounds ? b->x1 : 0);
    __m256 y0 = _mm256_set1_ps(bounds ? b->y0 : 0), y1 = _mm256_set1_ps(bounds ? b->y1 : 0);
    __m256i any = _mm256_setzero_si256(), all = _mm256_set1_epi32(-1);
    size_t k = 0;
    for (; k + 8 <= n; k += 8) {
        const float *p = in[k].obj;
        const __m256 v[4] = {_mm256_i32gather_ps(p, gather, 4), _mm256_i32gather_ps(p + 1, gather, 4),
                             _mm256_i32gather_ps(p + 2, gather, 4), _mm256_i32gather_ps(p + 3, gather, 4)};
        __m256 c[4];
        const __m256i mk = xform_mask8(m, v, c);
        const __m256 iw = _mm256_div_ps(one, c[3]);
        const __m256 wx = _mm256_fmadd_ps(_mm256_mul_ps(c[0], iw), sx, tx);
        const __m256 wy = _mm256_fmadd_ps(_mm256_mul_ps(c[1], iw), sy, ty);
        const __m256 wz = _mm256_fmadd_ps(_mm256_mul_ps(c[2], iw), sz, tz);
        const __m256 wr = _mm256_fmadd_ps(_mm256_mul_ps(c[1], iw), sr, tr);
        if (bounds) { /* bounds_add, lane by lane */
            any = _mm256_or_si256(any, mk);
            all = _mm256_and_si256(all, mk);
            x0 = _mm256_blendv_ps(x0, wx, _mm256_cmp_ps(wx, x0, _CMP_LT_OQ));
            x1 = _mm256_blendv_ps(x1, wx, _mm256_cmp_ps(wx, x1, _CMP_GT_OQ));
            y0 = _mm256_blendv_ps(y0, wy, _mm256_cmp_ps(wy, y0, _CMP_LT_OQ));
            y1 = _mm256_blendv_ps(y1, wy, _mm256_cmp_ps(wy, y1, _CMP_GT_OQ));
        }
        /* Rows clip[0..3], win[0..3] to one 8-float store per vertex. */
        const __m256 t0 = _mm256_unpacklo_ps(c[0], c[1]), t1 = _mm256_unpackhi_ps(c[0], c[1]);
        const __m256 t2 = _mm256_unpacklo_ps(c[2], c[3]), t3 = _mm256_unpackhi_ps(c[2], c[3]);
        const __m256 t4 = _mm256_unpacklo_ps(wx, wy), t5 = _mm256_unpackhi_ps(wx, wy);
        const __m256 t6 = _mm256_unpacklo_ps(wz, iw), t7 = _mm256_unpackhi_ps(wz, iw);
        const __m256 u[8] = {_mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xEE),
                             _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xEE),
                             _mm256_shuffle_ps(t4, t6, 0x44), _mm256_shuffle_ps(t4, t6, 0xEE),
                             _mm256_shuffle_ps(t5, t7, 0x44), _mm256_shuffle_ps(t5, t7, 0xEE)};
        for (int j = 0; j < 4; j++) {
            _mm256_storeu_ps(out[k + (size_t)j].clip, _mm256_permute2f128_ps(u[j], u[4 + j], 0x20));
            _mm256_storeu_ps(out[k + 4 + (size_t)j].clip, _mm256_permute2f128_ps(u[j], u[4 + j], 0x31));
        }
        float r[8];
        uint32_t mm[8];
        _mm256_storeu_ps(r, wr);
        _mm256_storeu_si256((__m256i *)(void *)mm, mk);
        for (int j = 0; j < 8; j++) {
            out[k + (size_t)j].win[4] = r[j];
            out[k + (size_t)j].mask = mm[j];
        }
    }
    if (!bounds)
        return k;
    float bx0[8], bx1[8], by0[8], by1[8];
    uint32_t ba[8], bl[8];
    _mm256_storeu_ps(bx0, x0);
    _mm256_storeu_ps(bx1, x1);
    _mm256_storeu_ps(by0, y0);
    _mm256_storeu_ps(by1, y1);
    _mm256_storeu_si256((__m256i *)(void *)ba, any);
    _mm256_storeu_si256((__m256i *)(void *)bl, all);
    for (int j = 0; j < 8; j++) {
        b->any |= ba[j];
        b->all &= bl[j];
        /* Lane by lane the same compares as box_add (the order of the
         * vertices changes signed zeros at most, which box_pixel does not
         * tell apart). */
        b->x0 = bx0[j] < b->x0 ? bx0[j] : b->x0;
        b->x1 = bx1[j] > b->x1 ? bx1[j] : b->x1;
        b->y0 = by0[j] < b->y0 ? by0[j] : b->y0;
        b->y1 = by1[j] > b->y1 ? by1[j] : b->y1;
    }
    return k;
}

/* The two instances: with the batch's bounds for a tile mask, and without
 * for the plain functional run, which has no use for them. */
__attribute__((target("avx2,fma"))) static size_t vs_positions8_bounded(const fs_vs_setup *s, const fs_ivert *in,
                                                                        fs_pvert *out, size_t n, vs_bounds *b)
{
    return vs_positions8_core(s, in, out, n, b, true);
}

__attribute__((target("avx2,fma"))) static size_t vs_positions8(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out,
                                                                 size_t n)
{
    return vs_positions8_core(s, in, out, n, NULL, false);
}
#endif

/* Adds the user clip planes' bits to the batch's masks (only called when
 * a plane is enabled); returns the bits every vertex has in its low half
 * and those some vertex has in its high half. */
static unsigned user_plane_masks(const fs_vs_setup *s, fs_pvert *out, size_t n)
{
    unsigned any = 0, all = s->ucp_mask;
    for (size_t i = 0; i < n; i++) {
        unsigned m = fs_clip_user_mask(s, out[i].clip);
        out[i].mask |= m;
        any |= m;
        all &= m;
    }
    return all | any << 16;
}

static inline __attribute__((always_inline)) bool vs_process(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out, size_t n,
                                                             const fs_tile_mask *tiles)
{
    if (!tiles) {
        size_t i = 0;
#if FS_VS_HAVE_FMA
        if (s->has_avx2)
            i = vs_positions8(s, in, out, n);
#endif
        for (; i < n; i++)
            vs_position(s, &in[i], &out[i]);
        if (s->ucp_mask)
            user_plane_masks(s, out, n);
        if (s->defer) {
            /* Shaded by fs_prim_draw when a triangle reads them. */
            for (i = 0; i < n; i++)
                out[i].lazy = true;
            return true;
        }
        for (i = 0; i < n; i++) {
            vs_attributes(s, &in[i], &out[i]);
            out[i].lazy = false;
        }
        return false;
    }
    /* The tile mask: a filled batch wholly inside the view volume whose
     * window box misses every masked tile makes no fragment there,
     * nor does one wholly outside one clip plane, so its lighting, the
     * larger part of the vertex stage, is not needed (colours and texture
     * coordinates are then zero). */
    vs_bounds b = {INFINITY, INFINITY, -INFINITY, -INFINITY, 0, ~0u};
    size_t i = 0;
#if FS_VS_HAVE_FMA
    if (s->has_avx2)
        i = vs_positions8_bounded(s, in, out, n, &b);
#endif
    for (; i < n; i++) {
        vs_position(s, &in[i], &out[i]);
        bounds_add(&b, &out[i]);
    }
    if (s->ucp_mask) {
        /* The user planes' bits are apart from the view volume's, so
         * or-ing and and-ing them in apart gives the same any and all. */
        unsigned all_user = user_plane_masks(s, out, n);
        b.any |= all_user >> 16;
        b.all = (b.all & ((1u << FS_CLIP_USER_BIT) - 1)) | (all_user & 0xffffu);
    }
    bool need = b.all == 0 && (b.any != 0 || fs_vs_box_masked(tiles, b.x0, b.y0, b.x1, b.y1));
    /* A batch that may reach a masked tile is lit per triangle by
     * fs_prim_draw, only where a triangle's box meets one: big batches
     * (whole objects) touch some masked tile almost always. */
    for (size_t i = 0; i < n; i++) {
        /* A lazy vertex is lit before any triangle reads it (fs_prim_draw);
         * the others are read as zeros by triangles dropped or clipped
         * away outside the mask. */
        if (!need) {
            memset(out[i].col, 0, sizeof out[i].col);
            memset(out[i].tc, 0, (size_t)s->ntex * sizeof out[i].tc[0]);
            out[i].fog = 0.0f;
            memset(out[i].col2, 0, sizeof out[i].col2);
        }
        out[i].lazy = need;
    }
    return need;
}

#if FS_VS_HAVE_FMA
__attribute__((target("fma"))) static bool vs_process_fma(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out,
                                                          size_t n, const fs_tile_mask *tiles)
{
    return vs_process(s, in, out, n, tiles);
}
#endif

bool fs_vs_process(const fs_vs_setup *s, const fs_ivert *in, fs_pvert *out, size_t n, const fs_tile_mask *tiles)
{
#if FS_VS_HAVE_FMA
    if (s->has_fma)
        return vs_process_fma(s, in, out, n, tiles);
#endif
    return vs_process(s, in, out, n, tiles);
}

/* The tile mask fs_vs_process may use for a draw in `mode`: filled
 * polygons only (points and wide lines reach beyond their vertices). */
const fs_tile_mask *fs_vs_tile_mask(const fs_context *c, GLenum mode)
{
    if (mode < GL_TRIANGLES || mode > GL_POLYGON)
        return NULL;
    const fs_tile_mask *t = fs_tile_mask_active(c);
    if (!t || fs_render_mode_diverts(&c->rmode) || c->raster.polygon_mode[0] != GL_FILL || c->raster.polygon_mode[1] != GL_FILL)
        return NULL;
    return t;
}

/* Deferred shading (s->defer): a triangle wholly outside one clip plane
 * is rejected before the clipper or the rasterizer reads a colour, a
 * texture coordinate or a fog value of its vertices (GL 1.5 spec 2.12;
 * primitive.c's tri_e), and most vertices of the corpus's programs are
 * only in such triangles (winduprobot: 1.57 M of 2.18 M triangles).  So
 * a triangle draw shades a vertex (vs_attributes, the same function and
 * the same inputs, so the same bits) when the first triangle that is not
 * rejected uses it.  Not for points and lines (fs_clip_line reads every
 * vertex), nor in selection and feedback (2.13, 5.2-5.3: their own
 * route), nor for unfilled polygons, nor when the tile mask's own lazy
 * shading is on, nor for a batch lit with materials changed between its
 * vertices (immediate.c lights each run with its own material). */
bool fs_vs_defer_shading(fs_context *c, GLenum mode)
{
    if (mode < GL_TRIANGLES || mode > GL_POLYGON || fs_vs(c)->eager)
        return false;
    return !fs_render_mode_diverts(&c->rmode) && c->raster.polygon_mode[0] == GL_FILL &&
           c->raster.polygon_mode[1] == GL_FILL && !fs_tile_mask_active(c);
}

void fs_vs_set_eager(fs_context *c, bool eager)
{
    fs_vs(c)->eager = eager;
}

/* ---- drawing ---- */
void fs_exec_ArrayElement(fs_context *c, GLint i)
{
    if (i < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    /* GL 1.5 spec 2.8: the values of the enabled arrays become current, as
     * if the corresponding commands had been called; a disabled array is
     * not read (its pointer may be NULL or stale). */
    fs_ivert v;
    if (c->arrays.vertex.enabled)
        fetch_position(c, (size_t)i, &v);
    fetch_attributes(c, (size_t)i, &v, FS_MAX_TEXTURE_UNITS, FETCH_GL);
    if (c->arrays.color.enabled) fs_exec_Color4fv(c, v.col);
    if (c->arrays.normal.enabled) fs_exec_Normal3fv(c, v.nrm);
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        if (c->arrays.texcoord[u].enabled) {
            memcpy(c->current.texcoord[u], v.tc[u], sizeof v.tc[u]);
            fs_vs_attrib_given(c, FS_ATTR_TEX(u));
        }
    if (c->arrays.secondary_color.enabled) {
        memcpy(c->current.secondary_color, v.col2, sizeof v.col2);
        fs_vs_attrib_given(c, FS_ATTR_COLOR2);
    }
    if (c->arrays.fog_coord.enabled) c->current.fog_coord = v.fogc;
    /* Through glEdgeFlag, so the batch's vertices keep their flags (immediate.c). */
    if (c->arrays.edge_flag.enabled) fs_exec_EdgeFlag(c, array_edge_flag(c, (size_t)i));
    if (c->arrays.vertex.enabled) fs_exec_Vertex4fv(c, v.obj);
}

static void draw_batch(fs_context *c, GLenum mode, size_t n, const uint32_t *idx, size_t count, bool elements)
{
    fs_vs_impl *v = fs_vs(c);
    if (!fs_vs_reserve_pv(c, n)) {
        v->deferred = false;
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    fs_vs_prepare(c, &v->setup);
    unsigned varying = (c->arrays.color.enabled ? FS_ATTR_COLOR : 0u) |
                       (c->arrays.secondary_color.enabled ? FS_ATTR_COLOR2 : 0u);
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        varying |= c->arrays.texcoord[u].enabled ? FS_ATTR_TEX(u) : 0u;
    fs_vs_constant_attribs(c, &v->setup, varying);
    if (c->arrays.edge_flag.enabled) {
        /* The batch vertices' edge flags from the array (GL 1.5 spec 2.6.2,
         * 2.8): batch vertex k is element src_indices[k] or src_first + k
         * (defer_from). */
        if (!fs_vs_reserve_edge(c, n)) {
            v->deferred = false;
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        for (size_t k = 0; k < n; k++)
            v->iv_edge[k] = array_edge_flag(c, v->src_indices ? index_at(v->src_indices, v->src_type, k)
                                                              : v->src_first + k);
        v->setup.edge = v->iv_edge;
    }
    v->setup.defer = fs_vs_defer_shading(c, mode);
    bool lazy = fs_vs_process(&v->setup, v->iv, v->pv, n, fs_vs_tile_mask(c, mode));
    fs_prim_draw(c, &v->setup, mode, v->pv, lazy ? v->iv : NULL, idx, count, elements);
    v->deferred = false;
}

/* Fetches batch vertex k from array element `src`: under the tile mask,
 * its position only (the other attributes wait for fs_vs_attributes, which
 * most vertices outside the mask never reach). */
static inline void fetch_batch(fs_context *c, bool deferred, size_t src, fs_ivert *o)
{
    if (deferred)
        fetch_position(c, src, o);
    else
        fetch_vertex(c, src, o);
}

/* Where a batch's vertices come from, for fs_vs_attributes. */
static bool defer_from(fs_context *c, GLenum mode, size_t first, const void *indices, GLenum type)
{
    fs_vs_impl *v = fs_vs(c);
    v->deferred = fs_vs_tile_mask(c, mode) != NULL;
    v->src_first = first;
    v->src_indices = indices;
    v->src_type = type;
    return v->deferred;
}

void fs_exec_DrawArrays(fs_context *c, GLenum mode, GLint first, GLsizei count)
{
    if (!fs_prim_mode_valid(mode)) { fs_error(c, GL_INVALID_ENUM); return; }
    if (count < 0 || first < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    if (!c->arrays.vertex.enabled || count == 0 || !fs_vs(c))
        return;
    if (fs_draw_skipped(c, mode, (size_t)count)) {
        c->stats.vertices += (uint64_t)count;
        return;
    }
    /* A triangle list is drawn in pieces: its triangles stand alone, so
     * the pieces make the same triangles in the same order, and a piece
     * stays in the cache from fetch to assembly (a whole 12,288-vertex
     * draw of bench8 did not: 8% of the time of a run under a tile mask). */
    const size_t total = (size_t)count, piece = mode == GL_TRIANGLES ? 3 * 128 : total;
    if (!fs_vs_reserve_iv(c, total < piece ? total : piece)) { fs_error(c, GL_OUT_OF_MEMORY); return; }
    c->stats.vertices += (uint64_t)count;
    for (size_t at = 0; at < total;) {
        size_t n = total - at < piece ? total - at : piece;
        fs_vs_impl *v = fs_vs(c);
        bool deferred = defer_from(c, mode, (size_t)first + at, NULL, 0);
        if (deferred)
            fetch_positions(c, (size_t)first + at, n, v->iv);
        else
            for (size_t i = 0; i < n; i++)
                fetch_vertex(c, (size_t)first + at + i, &v->iv[i]);
        draw_batch(c, mode, n, NULL, n, c->prim.list_depth > 0);
        at += n;
    }
}

/* GL 1.5 spec 2.8: the draws of glDrawArrays in order, none when an
 * argument is bad (the errors as OSMesa raises them: a negative drawcount
 * or count, GL_INVALID_VALUE; a bad mode, GL_INVALID_ENUM). */
void fs_exec_MultiDrawArrays(fs_context *c, GLenum mode, const GLint *first, const GLint *count, GLsizei drawcount)
{
    if (!fs_prim_mode_valid(mode)) { fs_error(c, GL_INVALID_ENUM); return; }
    if (drawcount < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    for (GLsizei i = 0; i < drawcount; i++)
        if (count[i] < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    for (GLsizei i = 0; i < drawcount; i++)
        fs_exec_DrawArrays(c, mode, first[i], count[i]);
}

static uint32_t index_at(const void *indices, GLenum type, size_t i)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return ((const uint8_t *)indices)[i];
    case GL_UNSIGNED_SHORT: { uint16_t u; memcpy(&u, (const char *)indices + 2 * i, 2); return u; }
    default: { uint32_t u; memcpy(&u, (const char *)indices + 4 * i, 4); return u; }
    }
}

static void draw_elements(fs_context *c, GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
    if (!c->arrays.vertex.enabled || count == 0 || !indices || !fs_vs(c))
        return;
    size_t n = (size_t)count;
    uint32_t lo = UINT32_MAX, hi = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t k = index_at(indices, type, i);
        lo = k < lo ? k : lo;
        hi = k > hi ? k : hi;
    }
    size_t range = (size_t)(hi - lo) + 1;
    fs_vs_impl *v;
    c->stats.vertices += n;
    if (fs_draw_skipped(c, mode, n))
        return;
    if (range <= 2 * n + 64) {
        /* Dense indices: transform each referenced vertex once. */
        if (!fs_vs_reserve_iv(c, range) || !fs_vs_reserve_idx(c, n)) { fs_error(c, GL_OUT_OF_MEMORY); return; }
        v = fs_vs(c);
        bool deferred = defer_from(c, mode, lo, NULL, 0);
        for (size_t i = 0; i < range; i++)
            fetch_batch(c, deferred, lo + i, &v->iv[i]);
        for (size_t i = 0; i < n; i++)
            v->idx[i] = index_at(indices, type, i) - lo;
        draw_batch(c, mode, range, v->idx, n, true);
    } else {
        /* Sparse indices: fetch in index order, so memory follows count. */
        if (!fs_vs_reserve_iv(c, n)) { fs_error(c, GL_OUT_OF_MEMORY); return; }
        v = fs_vs(c);
        bool deferred = defer_from(c, mode, 0, indices, type);
        for (size_t i = 0; i < n; i++)
            fetch_batch(c, deferred, index_at(indices, type, i), &v->iv[i]);
        draw_batch(c, mode, n, NULL, n, true);
    }
}

static bool index_type_valid(GLenum type)
{
    return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
}

void fs_exec_DrawElements(fs_context *c, GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
    if (!fs_prim_mode_valid(mode) || !index_type_valid(type)) { fs_error(c, GL_INVALID_ENUM); return; }
    if (count < 0) { fs_error(c, GL_INVALID_VALUE); return; }
    draw_elements(c, mode, count, type, indices);
}

/* GL 1.4 spec 2.8: glMultiDrawElements is a glDrawElements per draw, in
 * order.  Its errors as OSMesa raises them, before any draw, in this
 * order: a negative drawcount GL_INVALID_VALUE, a bad mode or type
 * GL_INVALID_ENUM, a negative count GL_INVALID_VALUE
 * (tests/test_array_draws.c, multidraw_elements_errors_vs_osmesa). */
bool fs_multidraw_elements_valid(fs_context *c, GLenum mode, const GLsizei *count, GLenum type, GLsizei drawcount)
{
    GLenum err = GL_NO_ERROR;
    if (drawcount < 0)
        err = GL_INVALID_VALUE;
    else if (!fs_prim_mode_valid(mode) || !index_type_valid(type))
        err = GL_INVALID_ENUM;
    for (GLsizei i = 0; err == GL_NO_ERROR && i < drawcount; i++)
        if (count[i] < 0)
            err = GL_INVALID_VALUE;
    if (err != GL_NO_ERROR)
        fs_error(c, err);
    return err == GL_NO_ERROR;
}

/* The driver runs the draws itself (driver/dispatch.c: each one's indices
 * may be an offset into the element array buffer); this is the call on
 * client memory alone. */
void fs_exec_MultiDrawElements(fs_context *c, GLenum mode, const GLsizei *count, GLenum type,
                               const GLvoid *const *indices, GLsizei drawcount)
{
    if (!fs_multidraw_elements_valid(c, mode, count, type, drawcount))
        return;
    for (GLsizei i = 0; i < drawcount; i++)
        if (!indices[i])
            return; /* as OSMesa: with client indices, one NULL draws nothing */
    for (GLsizei i = 0; i < drawcount; i++)
        draw_elements(c, mode, count[i], type, indices[i]);
}

void fs_exec_DrawRangeElements(fs_context *c, GLenum mode, GLuint start, GLuint end, GLsizei count,
                               GLenum type, const GLvoid *indices)
{
    if (!fs_prim_mode_valid(mode) || !index_type_valid(type)) { fs_error(c, GL_INVALID_ENUM); return; }
    if (count < 0 || end < start) { fs_error(c, GL_INVALID_VALUE); return; }
    /* Indices outside [start, end] are used as they are (GL 1.5 2.8 leaves
     * them implementation-dependent). llvmpipe has no answer to match: by
     * experiment through OSMesa (quad 0,1,2 0,2,3 drawn with [0,1]) it lit 120
     * of 256 pixels first time, 256 after a full draw, and crashed for [2,3]:
     * it trusts the range and reads vertices outside it undefined. */
    draw_elements(c, mode, count, type, indices);
}
