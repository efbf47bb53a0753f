/*
 * Enables and state queries (GL 1.5 spec 2.x "Enable", 5.5-5.6 flush and
 * finish, 5.6 hints, 6.1 querying state, 3.6.1 pixel storage).  The state
 * itself lives in each stage's struct; this file only maps GL names onto it.
 */
#include <math.h>
#include <string.h>
#include "gl_call.h"
#include "../pipeline/context.h"
#include "display_list.h"
#include "../units/occlusion_unit.h"
#include "../units/texture_unit.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

#define FS_GL_VERSION "1.1 fragsim-0.1"

/* Enables come from the state table (pipeline/state.def): a cap marked
 * ENU is one fragsim accepts but does not model yet.  Its state is kept so
 * glIsEnabled answers truthfully, and enabling one is reported as an
 * unsupported feature by name, since the image will differ from GL. */
static void set_cap(fs_context *c, GLenum cap, bool on)
{
    if (cap == GL_OCCLUSION_TEST_HP) {
        if (fs_occlusion_hp_enable(c, on) != 0)
            fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    const fs_state_info *row;
    bool *flag = fs_state_cap_flag(c, cap, false, &row);
    if (!flag && row && row->cap == FS_CAP_CLI) {
        /* Mesa's compatibility profile takes the arrays' names in glEnable
         * and glDisable as glEnableClientState would (measured on OSMesa;
         * GL 1.5 lists them only under 2.8's EnableClientState). */
        if (on)
            fs_exec_EnableClientState(c, cap);
        else
            fs_exec_DisableClientState(c, cap);
        return;
    }
    if (!flag) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    *flag = on;
    fs_state_mark(c, row->groups);
    if (cap == GL_COLOR_MATERIAL && on)
        fs_color_material_update(c); /* GL 1.5 spec 2.14.3: tracks the current colour at once */
    if (fs_texture_enable_flag(c, cap))
        fs_texture_enables_changed(c); /* the rasterizer interpolates texture coordinates */
    if (on && row->cap == FS_CAP_ENU) {
        char what[64];
        snprintf(what, sizeof what, "glEnable(%s)", row->label);
        fs_unsupported(c, what);
    }
}

void fs_exec_Enable(fs_context *c, GLenum cap) { set_cap(c, cap, true); }
void fs_exec_Disable(fs_context *c, GLenum cap) { set_cap(c, cap, false); }

GLboolean fs_exec_IsEnabled(fs_context *c, GLenum cap)
{
    if (cap == GL_OCCLUSION_TEST_HP)
        return fs_occlusion_hp_enabled(c) ? GL_TRUE : GL_FALSE;
    bool *flag = fs_state_cap_flag(c, cap, true, NULL);
    if (!flag) {
        fs_error(c, GL_INVALID_ENUM);
        return GL_FALSE;
    }
    return *flag ? GL_TRUE : GL_FALSE;
}

GLenum fs_exec_GetError(fs_context *c)
{
    GLenum e = c->error;
    c->error = GL_NO_ERROR;
    return e;
}

const GLubyte *fs_exec_GetString(fs_context *c, GLenum name)
{
    switch (name) {
    case GL_VENDOR: return (const GLubyte *)"fragsim";
    case GL_RENDERER: return (const GLubyte *)"fragsim functional model";
    case GL_VERSION: return (const GLubyte *)FS_GL_VERSION;
    /* Only what is implemented: the Occlusion Unit (units/occlusion_gl.c). */
    case GL_EXTENSIONS: return (const GLubyte *)"GL_ARB_occlusion_query GL_ARB_texture_non_power_of_two GL_FRAGSIM_occlusion_unit GL_HP_occlusion_test GL_FRAGSIM_footprint_filter GL_FRAGSIM_mp_grid";
    default:
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
}

/* ---- glGet (GL 1.5 spec 6.1.2) ---- */

typedef fs_get_value get_result;
#define GET_NUM FS_GET_NUM
#define GET_NORM FS_GET_NORM
#define GET_BOOL FS_GET_BOOL
#define GET_ENUM FS_GET_ENUM

static void put(get_result *r, enum fs_get_class cls, int n, const double *v)
{
    r->cls = cls;
    r->n = n;
    memcpy(r->v, v, (size_t)n * sizeof *v);
}

static void put1(get_result *r, enum fs_get_class cls, double v) { put(r, cls, 1, &v); }

static void putf(get_result *r, enum fs_get_class cls, int n, const float *v)
{
    double d[16];
    for (int i = 0; i < n; i++)
        d[i] = v[i];
    put(r, cls, n, d);
}

static const fs_matrix *top_matrix(const fs_context *c, GLenum which)
{
    switch (which) {
    case GL_MODELVIEW_MATRIX: return &c->xf.modelview[c->xf.modelview_top];
    case GL_PROJECTION_MATRIX: return &c->xf.projection[c->xf.projection_top];
    default: { /* the active unit's (GL 1.5 spec 2.10.2) */
        int u = fs_active_unit(c);
        return &c->xf.texture[u][c->xf.texture_top[u]];
    }
    }
}

/* The computed rows of the state table (FS_STATE_GET) and the Occlusion
 * Unit's state; false for an unknown name. */
static bool get_computed(fs_context *c, GLenum pname, get_result *r)
{
    double v[4];
    switch (pname) {
    case GL_VIEWPORT:
        /* Until glViewport is called the viewport is the window (2.11.1). */
        for (int i = 0; i < 4; i++)
            v[i] = c->xf.viewport_set ? c->xf.viewport[i] : i < 2 ? 0 : i == 2 ? c->fb.width : c->fb.height;
        put(r, GET_NUM, 4, v);
        return true;
    case GL_MODELVIEW_MATRIX: case GL_PROJECTION_MATRIX: case GL_TEXTURE_MATRIX:
        putf(r, GET_NORM, 16, top_matrix(c, pname)->m); /* as OSMesa converts them */
        return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX: case GL_TRANSPOSE_PROJECTION_MATRIX: case GL_TRANSPOSE_TEXTURE_MATRIX: {
        const float *m = top_matrix(c, pname - GL_TRANSPOSE_MODELVIEW_MATRIX + GL_MODELVIEW_MATRIX)->m;
        float t[16];
        for (int i = 0; i < 16; i++)
            t[i] = m[(i % 4) * 4 + i / 4];
        putf(r, GET_NORM, 16, t);
        return true;
    }
    case GL_MODELVIEW_STACK_DEPTH: put1(r, GET_NUM, c->xf.modelview_top + 1); return true;
    case GL_PROJECTION_STACK_DEPTH: put1(r, GET_NUM, c->xf.projection_top + 1); return true;
    case GL_TEXTURE_STACK_DEPTH: put1(r, GET_NUM, c->xf.texture_top[fs_active_unit(c)] + 1); return true;
    /* GL 1.5 spec table 6.15 and 6.26 (texture unit, units/texture_object.c). */
    case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D: case GL_TEXTURE_CUBE_MAP: case GL_TEXTURE_RECTANGLE:
        put1(r, GET_BOOL, *fs_texture_enable_flag(c, pname));
        return true;
    case GL_TEXTURE_BINDING_1D: put1(r, GET_NUM, fs_texture_binding(c, GL_TEXTURE_1D)); return true;
    case GL_TEXTURE_BINDING_2D: put1(r, GET_NUM, fs_texture_binding_2d(c)); return true;
    case GL_TEXTURE_BINDING_3D: put1(r, GET_NUM, fs_texture_binding(c, GL_TEXTURE_3D)); return true;
    case GL_TEXTURE_BINDING_CUBE_MAP: put1(r, GET_NUM, fs_texture_binding(c, GL_TEXTURE_CUBE_MAP)); return true;
    case GL_TEXTURE_BINDING_RECTANGLE: put1(r, GET_NUM, fs_texture_binding(c, GL_TEXTURE_RECTANGLE)); return true;
    /* GL 1.5 spec table 6.30 and GL_FRAGSIM_occlusion_unit's New State. */
    /* Table 6.30: the compressed formats the texture unit decodes. */
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: put1(r, GET_NUM, fs_tex_compressed_formats(NULL)); return true;
    case GL_COMPRESSED_TEXTURE_FORMATS: {
        GLint f[8];
        int n = fs_tex_compressed_formats(f);
        for (int i = 0; i < n; i++)
            v[i] = f[i];
        put(r, GET_ENUM, n, v);
        return true;
    }
    case GL_LIST_MODE: case GL_LIST_INDEX: {
        GLenum mode;
        GLuint index;
        fs_dlist_building(c, &mode, &index);
        put1(r, pname == GL_LIST_MODE ? GET_ENUM : GET_NUM, pname == GL_LIST_MODE ? mode : index);
        return true;
    }
    case GL_RENDER_MODE:
        put1(r, GET_ENUM, fs_render_mode_diverts(&c->rmode) ? c->rmode.mode : fs_occlusion_render_mode(c));
        return true;
    case GL_OCCLUSION_TEST_HP: put1(r, GET_BOOL, fs_occlusion_hp_enabled(c)); return true;
    /* Reading the result clears it (GL_HP_occlusion_test). */
    case GL_OCCLUSION_TEST_RESULT_HP: put1(r, GET_BOOL, fs_occlusion_hp_take_result(c)); return true;
    case GL_MAX_OCCLUSION_TILES: put1(r, GET_NUM, (double)c->cfg.occlusion_max_tiles); return true;
    case GL_OCCLUSION_TILE_COUNT: put1(r, GET_NUM, fs_occlusion_tiles_set(c)); return true;
    case GL_OCCLUSION_COUNTER_BITS: put1(r, GET_NUM, (double)c->cfg.occlusion_counter_bits); return true;
    default: return false;
    }
}

/* Fills r with the state named by pname; returns false for an unknown name. */
static bool get_state(fs_context *c, GLenum pname, get_result *r)
{
    return fs_state_get(c, pname, r) || get_computed(c, pname, r);
}

int fs_get_count(GLenum pname) { return fs_state_count(pname); }

static bool fetch(fs_context *c, GLenum pname, get_result *r)
{
    if (!get_state(c, pname, r)) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    return true;
}

void fs_exec_GetDoublev(fs_context *c, GLenum pname, GLdouble *params)
{
    get_result r;
    if (fetch(c, pname, &r))
        for (int i = 0; i < r.n; i++)
            params[i] = r.v[i];
}

void fs_exec_GetFloatv(fs_context *c, GLenum pname, GLfloat *params)
{
    get_result r;
    if (fetch(c, pname, &r))
        for (int i = 0; i < r.n; i++)
            params[i] = (GLfloat)r.v[i];
}

GLint fs_norm_to_int(double x)
{
    /* GL 1.5 spec 6.1.2 maps [-1,1] linearly onto [-2^31, 2^31-1]; llvmpipe
     * (measured on OSMesa) takes x * (2^31 - 1) toward zero, and a value
     * outside the integer range (a current colour or normal beyond 1, or
     * NaN) becomes -2^31, as the x86 conversion gives. */
    double y = x * 2147483647.0;
    if (!(y > -2147483649.0 && y < 2147483648.0))
        return (GLint)-2147483647 - 1;
    return (GLint)y;
}

void fs_exec_GetIntegerv(fs_context *c, GLenum pname, GLint *params)
{
    get_result r;
    if (!fetch(c, pname, &r))
        return;
    for (int i = 0; i < r.n; i++) {
        double x = r.v[i];
        if (r.cls == GET_NORM) {
            params[i] = fs_norm_to_int(x);
        } else {
            /* To the nearest integer, halves away from zero, as OSMesa
             * rounds (measured with the colour index: -2.5 gives -3). */
            x = x < 0.0 ? ceil(x - 0.5) : floor(x + 0.5);
            params[i] = x > 2147483647.0 ? 2147483647 : x < -2147483648.0 ? (GLint)-2147483647 - 1 : (GLint)x;
        }
    }
}

void fs_exec_GetBooleanv(fs_context *c, GLenum pname, GLboolean *params)
{
    get_result r;
    if (fetch(c, pname, &r))
        for (int i = 0; i < r.n; i++)
            params[i] = r.v[i] != 0.0 ? GL_TRUE : GL_FALSE;
}

/* ---- hints, pixel storage, synchronisation ---- */

/* Hints may be ignored (GL 1.5 spec 5.6), and llvmpipe ignores these, so
 * they are only stored for glGet (table 6.27). */
void fs_exec_Hint(fs_context *c, GLenum target, GLenum mode)
{
    /* GL_GENERATE_MIPMAP_HINT is a hint outside the hint group (state.def). */
    GLenum *hint = target == GL_GENERATE_MIPMAP_HINT ? &c->hints[5] : fs_state_field(c, target, GL_HINT_BIT, NULL);
    if (!hint || (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    *hint = mode;
    fs_state_mark(c, GL_HINT_BIT);
}

/* GL 1.5 spec 3.6.1: booleans are FALSE for 0 and TRUE otherwise; the
 * alignments must be 1, 2, 4 or 8 and the other values non-negative
 * (GL_INVALID_VALUE).  The values are only stored here; pixel transfers
 * read them from the context. */
void fs_exec_PixelStorei(fs_context *c, GLenum pname, GLint param)
{
    /* The pixel-store parameters of GL 1.5 spec tables 3.1 and 4.5. */
    const fs_state_info *row;
    GLint *p = fs_state_field(c, pname, FS_CLIENT_PIXEL_STORE, &row);
    if (!p) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_state_mark(c, FS_CLIENT_PIXEL_STORE);
    if (row->cls == FS_GET_BOOL) {
        *p = param != 0;
        return;
    }
    bool alignment = pname == GL_PACK_ALIGNMENT || pname == GL_UNPACK_ALIGNMENT;
    if (alignment ? (param != 1 && param != 2 && param != 4 && param != 8) : param < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    *p = param;
}

/* 3.6.1: a float parameter is rounded to the nearest integer.  As Mesa
 * (measured on OSMesa): exactly, halves away from zero (0.49999997 gives
 * 0), to a 64-bit integer whose low 32 bits are the value (so 3e9 becomes
 * negative and is refused, -3e9 becomes 1294967296), NaN 0; booleans
 * then follow the integer rule (0.4 is FALSE, -0.6 TRUE). */
void fs_exec_PixelStoref(fs_context *c, GLenum pname, GLfloat param)
{
    GLint i = 0;
    if (fabsf(param) < 9.2233715e18f) /* false for NaN */
        i = (GLint)(uint32_t)(uint64_t)(int64_t)roundf(param);
    fs_exec_PixelStorei(c, pname, i);
}

/* The model executes every command to completion when it is issued, so
 * glFlush and glFinish have nothing left to do (GL 1.5 spec 5.5). */
void fs_exec_Flush(fs_context *c) { (void)c; }
void fs_exec_Finish(fs_context *c) { (void)c; }
