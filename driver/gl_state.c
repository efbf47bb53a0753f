/*
 * Enables and state queries (GL 1.5 spec 2.x "Enable", 5.5-5.6 flush and
 * finish, 5.6 hints, 6.1 querying state, 3.6.1 pixel storage).  The state
 * itself lives in each stage's struct; this file only maps GL names onto it.
 */
#include <math.h>
#include <string.h>
#include "../pipeline/context.h"
#include "../units/occlusion_unit.h"
#include "../units/texture_priv.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

#define FS_GL_VERSION "1.1 fragsim-0.1"

/* Capabilities fragsim accepts but does not model yet.  Their state is kept
 * so glIsEnabled answers truthfully, and enabling one is reported as an
 * unsupported feature by name, since the image will differ from GL. */
static const struct { GLenum cap; const char *name; } unmodelled_caps[] = {
    {GL_FOG, "GL_FOG"},
    {GL_TEXTURE_1D, "GL_TEXTURE_1D"},
    {GL_TEXTURE_GEN_S, "GL_TEXTURE_GEN_S"},
    {GL_TEXTURE_GEN_T, "GL_TEXTURE_GEN_T"},
    {GL_TEXTURE_GEN_R, "GL_TEXTURE_GEN_R"},
    {GL_TEXTURE_GEN_Q, "GL_TEXTURE_GEN_Q"},
    {GL_POINT_SMOOTH, "GL_POINT_SMOOTH"},
    {GL_LINE_SMOOTH, "GL_LINE_SMOOTH"},
    {GL_POLYGON_SMOOTH, "GL_POLYGON_SMOOTH"},
    {GL_LINE_STIPPLE, "GL_LINE_STIPPLE"},
    {GL_POLYGON_STIPPLE, "GL_POLYGON_STIPPLE"},
    {GL_POLYGON_OFFSET_LINE, "GL_POLYGON_OFFSET_LINE"},
    {GL_POLYGON_OFFSET_POINT, "GL_POLYGON_OFFSET_POINT"},
    {GL_CLIP_PLANE0, "GL_CLIP_PLANE0"},
    {GL_CLIP_PLANE1, "GL_CLIP_PLANE1"},
    {GL_CLIP_PLANE2, "GL_CLIP_PLANE2"},
    {GL_CLIP_PLANE3, "GL_CLIP_PLANE3"},
    {GL_CLIP_PLANE4, "GL_CLIP_PLANE4"},
    {GL_CLIP_PLANE5, "GL_CLIP_PLANE5"},
    {GL_AUTO_NORMAL, "GL_AUTO_NORMAL"},
    {GL_MAP1_VERTEX_3, "GL_MAP1_VERTEX_3"},
    {GL_MAP2_VERTEX_3, "GL_MAP2_VERTEX_3"},
    {GL_INDEX_LOGIC_OP, "GL_INDEX_LOGIC_OP"},
};
#define N_UNMODELLED (sizeof unmodelled_caps / sizeof unmodelled_caps[0])

/* Enables that have no visible effect on an RGBA8 framebuffer in llvmpipe
 * either, so they are modelled by storing them. */
static bool *cap_flag(fs_context *c, GLenum cap)
{
    switch (cap) {
    case GL_LIGHTING: return &c->lighting.enabled;
    case GL_COLOR_MATERIAL: return &c->lighting.color_material;
    case GL_NORMALIZE: return &c->xf.normalize;
    case GL_RESCALE_NORMAL: return &c->xf.rescale_normal;
    case GL_CULL_FACE: return &c->raster.cull_enabled;
    case GL_POLYGON_OFFSET_FILL: return &c->raster.offset_fill;
    case GL_SCISSOR_TEST: return &c->frag.scissor_enabled;
    case GL_ALPHA_TEST: return &c->frag.alpha_enabled;
    case GL_STENCIL_TEST: return &c->frag.stencil_enabled;
    case GL_DEPTH_TEST: return &c->frag.depth_enabled;
    case GL_BLEND: return &c->frag.blend_enabled;
    case GL_DITHER: return &c->frag.dither_enabled;
    case GL_COLOR_LOGIC_OP: return &c->frag.logic_op_enabled;
    case GL_TEXTURE_2D: return fs_texture_enable_flag(c, cap);
    default: break;
    }
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + FS_MAX_LIGHTS)
        return &c->lighting.light[cap - GL_LIGHT0].enabled;
    for (size_t i = 0; i < N_UNMODELLED; i++)
        if (unmodelled_caps[i].cap == cap)
            return &c->unmodelled_caps[i];
    return NULL;
}

static void set_cap(fs_context *c, GLenum cap, bool on)
{
    if (cap == GL_OCCLUSION_TEST_HP) {
        if (fs_occlusion_hp_enable(c, on) != 0)
            fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    bool *flag = cap_flag(c, cap);
    if (!flag) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    *flag = on;
    if (cap == GL_COLOR_MATERIAL && on)
        fs_color_material_update(c); /* GL 1.5 spec 2.14.3: tracks the current colour at once */
    if (cap == GL_TEXTURE_2D)
        fs_texture_enables_changed(c); /* the rasterizer interpolates texture coordinates */
    if (!on)
        return;
    for (size_t i = 0; i < N_UNMODELLED; i++) {
        if (unmodelled_caps[i].cap == cap) {
            char what[64];
            snprintf(what, sizeof what, "glEnable(%s)", unmodelled_caps[i].name);
            fs_unsupported(c, what);
        }
    }
}

void fs_exec_Enable(fs_context *c, GLenum cap) { set_cap(c, cap, true); }
void fs_exec_Disable(fs_context *c, GLenum cap) { set_cap(c, cap, false); }

GLboolean fs_exec_IsEnabled(fs_context *c, GLenum cap)
{
    fs_client_array *arr = NULL;
    switch (cap) {
    case GL_VERTEX_ARRAY: arr = &c->arrays.vertex; break;
    case GL_NORMAL_ARRAY: arr = &c->arrays.normal; break;
    case GL_COLOR_ARRAY: arr = &c->arrays.color; break;
    case GL_TEXTURE_COORD_ARRAY: arr = &c->arrays.texcoord; break;
    default: break;
    }
    if (arr)
        return arr->enabled ? GL_TRUE : GL_FALSE;
    bool *client = fs_client_state_flag(c, cap);
    if (client)
        return *client ? GL_TRUE : GL_FALSE;
    if (cap == GL_OCCLUSION_TEST_HP)
        return fs_occlusion_hp_enabled(c) ? GL_TRUE : GL_FALSE;
    bool *flag = cap_flag(c, cap);
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
    case GL_EXTENSIONS: return (const GLubyte *)"GL_ARB_occlusion_query GL_FRAGSIM_occlusion_unit GL_HP_occlusion_test GL_FRAGSIM_footprint_filter GL_FRAGSIM_mp_grid";
    default:
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
}

/* ---- glGet ---- */

/* How a value converts to integers (GL 1.5 spec 6.1.2): colours and
 * normals map [-1,1] linearly onto the integer range, other values round. */
enum get_class { GET_NUM, GET_NORM, GET_BOOL, GET_ENUM };

typedef struct get_result {
    int n;
    enum get_class cls;
    double v[16];
} get_result;

static void put(get_result *r, enum get_class cls, int n, const double *v)
{
    r->cls = cls;
    r->n = n;
    memcpy(r->v, v, (size_t)n * sizeof *v);
}

static void put1(get_result *r, enum get_class cls, double v) { put(r, cls, 1, &v); }

static void putf(get_result *r, enum get_class cls, int n, const float *v)
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
    default: return &c->xf.texture[c->xf.texture_top];
    }
}

static const fs_client_array *array_of(const fs_context *c, GLenum pname)
{
    switch (pname) {
    case GL_VERTEX_ARRAY_SIZE: case GL_VERTEX_ARRAY_TYPE: case GL_VERTEX_ARRAY_STRIDE:
        return &c->arrays.vertex;
    case GL_NORMAL_ARRAY_TYPE: case GL_NORMAL_ARRAY_STRIDE:
        return &c->arrays.normal;
    case GL_COLOR_ARRAY_SIZE: case GL_COLOR_ARRAY_TYPE: case GL_COLOR_ARRAY_STRIDE:
        return &c->arrays.color;
    case GL_TEXTURE_COORD_ARRAY_SIZE: case GL_TEXTURE_COORD_ARRAY_TYPE: case GL_TEXTURE_COORD_ARRAY_STRIDE:
        return &c->arrays.texcoord;
    default: return NULL;
    }
}

static GLint *pixel_store(fs_context *c, GLenum pname, bool *boolean);

/* Fills r with the state named by pname; returns false for an unknown name. */
static bool get_state(fs_context *c, GLenum pname, get_result *r)
{
    const fs_fragment_state *f = &c->frag;
    double v[4];
    switch (pname) {
    case GL_VIEWPORT:
        /* Until glViewport is called the viewport is the window (2.11.1). */
        for (int i = 0; i < 4; i++)
            v[i] = c->xf.viewport_set ? c->xf.viewport[i] : i < 2 ? 0 : i == 2 ? c->fb.width : c->fb.height;
        put(r, GET_NUM, 4, v);
        return true;
    case GL_MAX_VIEWPORT_DIMS:
        v[0] = v[1] = 16384;
        put(r, GET_NUM, 2, v);
        return true;
    case GL_DEPTH_RANGE:
        put(r, GET_NORM, 2, c->xf.depth_range);
        return true;
    case GL_MODELVIEW_MATRIX: case GL_PROJECTION_MATRIX: case GL_TEXTURE_MATRIX:
        putf(r, GET_NUM, 16, top_matrix(c, pname)->m);
        return true;
    case GL_MATRIX_MODE: put1(r, GET_ENUM, c->xf.matrix_mode); return true;
    case GL_MODELVIEW_STACK_DEPTH: put1(r, GET_NUM, c->xf.modelview_top + 1); return true;
    case GL_PROJECTION_STACK_DEPTH: put1(r, GET_NUM, c->xf.projection_top + 1); return true;
    case GL_TEXTURE_STACK_DEPTH: put1(r, GET_NUM, c->xf.texture_top + 1); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: put1(r, GET_NUM, FS_MODELVIEW_STACK_DEPTH); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: put1(r, GET_NUM, FS_PROJECTION_STACK_DEPTH); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: put1(r, GET_NUM, FS_TEXTURE_STACK_DEPTH); return true;
    case GL_MAX_LIGHTS: put1(r, GET_NUM, FS_MAX_LIGHTS); return true;
    case GL_MAX_LIST_NESTING: put1(r, GET_NUM, 64); return true;
    case GL_CURRENT_COLOR: putf(r, GET_NORM, 4, c->current.color); return true;
    case GL_CURRENT_NORMAL: putf(r, GET_NORM, 3, c->current.normal); return true;
    case GL_CURRENT_TEXTURE_COORDS: putf(r, GET_NUM, 4, c->current.texcoord); return true;
    case GL_SHADE_MODEL: put1(r, GET_ENUM, c->lighting.shade_model); return true;
    case GL_LIGHT_MODEL_AMBIENT: putf(r, GET_NORM, 4, c->lighting.model_ambient); return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: put1(r, GET_BOOL, c->lighting.local_viewer); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: put1(r, GET_BOOL, c->lighting.two_side); return true;
    case GL_COLOR_MATERIAL_FACE: put1(r, GET_ENUM, c->lighting.color_material_face); return true;
    case GL_COLOR_MATERIAL_PARAMETER: put1(r, GET_ENUM, c->lighting.color_material_mode); return true;
    case GL_CULL_FACE_MODE: put1(r, GET_ENUM, c->raster.cull_mode); return true;
    case GL_FRONT_FACE: put1(r, GET_ENUM, c->raster.front_face); return true;
    case GL_POLYGON_OFFSET_FACTOR: put1(r, GET_NUM, c->raster.offset_factor); return true;
    case GL_POLYGON_OFFSET_UNITS: put1(r, GET_NUM, c->raster.offset_units); return true;
    case GL_POLYGON_MODE:
        v[0] = c->raster.polygon_mode[0];
        v[1] = c->raster.polygon_mode[1];
        put(r, GET_ENUM, 2, v);
        return true;
    case GL_POINT_SIZE: put1(r, GET_NUM, c->raster.point_size); return true;
    case GL_LINE_WIDTH: put1(r, GET_NUM, c->raster.line_width); return true;
    case GL_SUBPIXEL_BITS: put1(r, GET_NUM, c->raster.subpixel_bits); return true;
    case GL_SCISSOR_BOX:
        for (int i = 0; i < 4; i++) v[i] = f->scissor[i];
        put(r, GET_NUM, 4, v);
        return true;
    case GL_ALPHA_TEST_FUNC: put1(r, GET_ENUM, f->alpha_func); return true;
    case GL_ALPHA_TEST_REF: put1(r, GET_NORM, f->alpha_ref); return true;
    case GL_STENCIL_FUNC: put1(r, GET_ENUM, f->stencil_func); return true;
    case GL_STENCIL_REF: put1(r, GET_NUM, f->stencil_ref); return true;
    case GL_STENCIL_VALUE_MASK: put1(r, GET_NUM, f->stencil_value_mask); return true;
    case GL_STENCIL_WRITEMASK: put1(r, GET_NUM, f->stencil_write_mask); return true;
    case GL_STENCIL_FAIL: put1(r, GET_ENUM, f->stencil_fail); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: put1(r, GET_ENUM, f->stencil_zfail); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: put1(r, GET_ENUM, f->stencil_zpass); return true;
    case GL_DEPTH_FUNC: put1(r, GET_ENUM, f->depth_func); return true;
    case GL_DEPTH_WRITEMASK: put1(r, GET_BOOL, f->depth_write); return true;
    case GL_BLEND_SRC: put1(r, GET_ENUM, f->blend_src); return true;
    case GL_BLEND_DST: put1(r, GET_ENUM, f->blend_dst); return true;
    case GL_LOGIC_OP_MODE: put1(r, GET_ENUM, f->logic_op); return true;
    case GL_COLOR_WRITEMASK:
        for (int i = 0; i < 4; i++) v[i] = f->color_mask[i];
        put(r, GET_BOOL, 4, v);
        return true;
    case GL_COLOR_CLEAR_VALUE: putf(r, GET_NORM, 4, f->clear_color); return true;
    case GL_DEPTH_CLEAR_VALUE: put1(r, GET_NORM, f->clear_depth); return true;
    case GL_STENCIL_CLEAR_VALUE: put1(r, GET_NUM, f->clear_stencil); return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS:
        put1(r, GET_NUM, 8);
        return true;
    case GL_DEPTH_BITS: put1(r, GET_NUM, c->fb.depth_bits); return true;
    case GL_STENCIL_BITS: put1(r, GET_NUM, c->fb.stencil_bits); return true;
    /* Table 6.34: the window's buffers (pipeline/buffer_select.c); no
     * colour index mode and no accumulation buffer. */
    case GL_DOUBLEBUFFER: put1(r, GET_BOOL, c->double_buffered); return true;
    case GL_STEREO: put1(r, GET_BOOL, 0); return true;
    case GL_RGBA_MODE: put1(r, GET_BOOL, 1); return true;
    case GL_INDEX_MODE: put1(r, GET_BOOL, 0); return true;
    case GL_AUX_BUFFERS: case GL_INDEX_BITS:
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
        put1(r, GET_NUM, 0);
        return true;
    case GL_DRAW_BUFFER: put1(r, GET_ENUM, c->draw_buffer); return true;
    case GL_READ_BUFFER: put1(r, GET_ENUM, c->read_buffer); return true;
    case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST: case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: {
        bool boolean;
        put1(r, GET_BOOL, *pixel_store(c, pname, &boolean));
        return true;
    }
    case GL_UNPACK_ROW_LENGTH: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_ROWS: case GL_UNPACK_SKIP_PIXELS:
    case GL_UNPACK_SKIP_IMAGES: case GL_UNPACK_ALIGNMENT: case GL_PACK_ROW_LENGTH: case GL_PACK_IMAGE_HEIGHT:
    case GL_PACK_SKIP_ROWS: case GL_PACK_SKIP_PIXELS: case GL_PACK_SKIP_IMAGES: case GL_PACK_ALIGNMENT: {
        bool boolean;
        put1(r, GET_NUM, *pixel_store(c, pname, &boolean));
        return true;
    }
    /* GL 1.5 spec table 6.15 and 6.26 (texture unit, units/texture_object.c). */
    case GL_TEXTURE_BINDING_2D: put1(r, GET_NUM, fs_texture_binding_2d(c)); return true;
    case GL_MAX_TEXTURE_SIZE: put1(r, GET_NUM, FS_TEX_MAX_SIZE); return true;
    case GL_VERTEX_ARRAY: case GL_NORMAL_ARRAY: case GL_COLOR_ARRAY: case GL_TEXTURE_COORD_ARRAY:
    case GL_EDGE_FLAG_ARRAY: case GL_INDEX_ARRAY: case GL_FOG_COORDINATE_ARRAY: case GL_SECONDARY_COLOR_ARRAY:
        put1(r, GET_BOOL, fs_exec_IsEnabled(c, pname));
        return true;
    /* GL 1.5 spec table 6.30 and GL_FRAGSIM_occlusion_unit's New State. */
    case GL_RENDER_MODE: put1(r, GET_ENUM, fs_occlusion_render_mode(c)); return true;
    case GL_OCCLUSION_TEST_HP: put1(r, GET_BOOL, fs_occlusion_hp_enabled(c)); return true;
    /* Reading the result clears it (GL_HP_occlusion_test). */
    case GL_OCCLUSION_TEST_RESULT_HP: put1(r, GET_BOOL, fs_occlusion_hp_take_result(c)); return true;
    case GL_MAX_OCCLUSION_TILES: put1(r, GET_NUM, (double)c->cfg.occlusion_max_tiles); return true;
    case GL_OCCLUSION_TILE_COUNT: put1(r, GET_NUM, fs_occlusion_tiles_set(c)); return true;
    case GL_OCCLUSION_COUNTER_BITS: put1(r, GET_NUM, (double)c->cfg.occlusion_counter_bits); return true;
    default:
        break;
    }
    const fs_client_array *a = array_of(c, pname);
    if (a) {
        switch (pname) {
        case GL_VERTEX_ARRAY_TYPE: case GL_NORMAL_ARRAY_TYPE: case GL_COLOR_ARRAY_TYPE:
        case GL_TEXTURE_COORD_ARRAY_TYPE:
            put1(r, GET_ENUM, a->type);
            return true;
        case GL_VERTEX_ARRAY_STRIDE: case GL_NORMAL_ARRAY_STRIDE: case GL_COLOR_ARRAY_STRIDE:
        case GL_TEXTURE_COORD_ARRAY_STRIDE:
            put1(r, GET_NUM, a->stride);
            return true;
        default:
            put1(r, GET_NUM, a->size);
            return true;
        }
    }
    /* Every enable is also a glGet name (GL 1.5 spec 6.1.1). */
    bool *flag = cap_flag(c, pname);
    if (flag) {
        put1(r, GET_BOOL, *flag);
        return true;
    }
    return false;
}

int fs_get_count(GLenum pname)
{
    switch (pname) {
    case GL_MODELVIEW_MATRIX: case GL_PROJECTION_MATRIX: case GL_TEXTURE_MATRIX: return 16;
    case GL_VIEWPORT: case GL_SCISSOR_BOX: case GL_COLOR_WRITEMASK: case GL_COLOR_CLEAR_VALUE:
    case GL_CURRENT_COLOR: case GL_CURRENT_TEXTURE_COORDS: case GL_LIGHT_MODEL_AMBIENT:
        return 4;
    case GL_CURRENT_NORMAL: return 3;
    case GL_MAX_VIEWPORT_DIMS: case GL_DEPTH_RANGE: case GL_POLYGON_MODE: return 2;
    default: return 1;
    }
}

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
    /* GL 1.5 spec 6.1.2: [-1,1] maps linearly onto [-2^31, 2^31-1]. */
    double y = ((x * 4294967295.0) - 1.0) / 2.0;
    y = y > 2147483647.0 ? 2147483647.0 : y < -2147483648.0 ? -2147483648.0 : y;
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
            x = floor(x + 0.5);
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

void fs_exec_Hint(fs_context *c, GLenum target, GLenum mode)
{
    switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: case GL_POINT_SMOOTH_HINT: case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT: case GL_FOG_HINT:
        break;
    default:
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)
        fs_error(c, GL_INVALID_ENUM);
    /* Hints may be ignored (GL 1.5 spec 5.6); llvmpipe ignores these too. */
}

/* The pixel-store parameter pname names (GL 1.5 spec tables 3.1 and 4.5),
 * or NULL; *boolean for the two booleans of each. */
static GLint *pixel_store(fs_context *c, GLenum pname, bool *boolean)
{
    *boolean = false;
    switch (pname) {
    case GL_UNPACK_SWAP_BYTES: *boolean = true; return &c->unpack_swap_bytes;
    case GL_UNPACK_LSB_FIRST: *boolean = true; return &c->unpack_lsb_first;
    case GL_UNPACK_ROW_LENGTH: return &c->unpack_row_length;
    case GL_UNPACK_IMAGE_HEIGHT: return &c->unpack_image_height;
    case GL_UNPACK_SKIP_ROWS: return &c->unpack_skip_rows;
    case GL_UNPACK_SKIP_PIXELS: return &c->unpack_skip_pixels;
    case GL_UNPACK_SKIP_IMAGES: return &c->unpack_skip_images;
    case GL_UNPACK_ALIGNMENT: return &c->unpack_alignment;
    case GL_PACK_SWAP_BYTES: *boolean = true; return &c->pack_swap_bytes;
    case GL_PACK_LSB_FIRST: *boolean = true; return &c->pack_lsb_first;
    case GL_PACK_ROW_LENGTH: return &c->pack_row_length;
    case GL_PACK_IMAGE_HEIGHT: return &c->pack_image_height;
    case GL_PACK_SKIP_ROWS: return &c->pack_skip_rows;
    case GL_PACK_SKIP_PIXELS: return &c->pack_skip_pixels;
    case GL_PACK_SKIP_IMAGES: return &c->pack_skip_images;
    case GL_PACK_ALIGNMENT: return &c->pack_alignment;
    default: return NULL;
    }
}

/* GL 1.5 spec 3.6.1: booleans are FALSE for 0 and TRUE otherwise; the
 * alignments must be 1, 2, 4 or 8 and the other values non-negative
 * (GL_INVALID_VALUE).  The values are only stored here; pixel transfers
 * read them from the context. */
void fs_exec_PixelStorei(fs_context *c, GLenum pname, GLint param)
{
    bool boolean;
    GLint *p = pixel_store(c, pname, &boolean);
    if (!p) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (boolean) {
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
