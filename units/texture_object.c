/*
 * Texture objects (GL 1.5 spec 3.8.12), texture images (3.8.1-3.8.3),
 * texture parameters (3.8.4), completeness (3.8.10) and the texture
 * environment (3.8.13).  Every command checks its arguments first: a call
 * that sets a GL error changes nothing (2.5).
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "texture_priv.h"
#include "texel_format.h"
#include "texture_depth.h"
#include "mpgrid_gl.h"
#include "footprint.h"
#include "../pipeline/context.h"
#include "../pipeline/pixel_transfer.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"

static void object_defaults(fs_tex_object *t, GLuint name)
{
    /* Initial state: GL 1.5 spec table 6.17. */
    memset(t, 0, sizeof *t);
    t->name = name;
    t->min_filter = GL_NEAREST_MIPMAP_LINEAR;
    t->mag_filter = GL_LINEAR;
    t->wrap_s = t->wrap_t = t->wrap_r = GL_REPEAT;
    t->priority = 1.0f;
    t->swizzle[0] = GL_RED, t->swizzle[1] = GL_GREEN, t->swizzle[2] = GL_BLUE, t->swizzle[3] = GL_ALPHA;
    t->footprint_budget = 16;
    t->footprint_snap = GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM;
    fs_tex_lod_defaults(t);
    fs_tex_depth_defaults(t);
    t->complete = -1;
}

/* ARB_texture_rectangle, New State: a rectangle texture starts with
 * CLAMP_TO_EDGE wraps and a LINEAR min filter (it has no MIPmaps). */
static void rect_defaults(fs_tex_object *t)
{
    t->min_filter = GL_LINEAR;
    t->wrap_s = t->wrap_t = t->wrap_r = GL_CLAMP_TO_EDGE;
}

static void object_release(fs_tex_object *t)
{
    fs_mpgrid_gl_release(t);
    for (int f = 0; f < FS_TEX_FACES; f++)
        for (int i = 0; i < FS_TEX_MAX_LEVELS; i++)
            fs_tex_image_free(&fs_tex_levels(t, f)[i]);
}

int fs_texture_init(fs_context *c)
{
    struct fs_texture_state *s = calloc(1, sizeof *s);
    if (!s)
        return -1;
    for (int t = 0; t < FS_TEX_TARGETS; t++) {
        object_defaults(&s->default_obj[t], 0);
        s->default_obj[t].target = (enum fs_tex_target)t;
        if (t == FS_TEX_RECT)
            rect_defaults(&s->default_obj[t]);
    }
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        for (int t = 0; t < FS_TEX_TARGETS; t++)
            s->unit[u].bound[t] = &s->default_obj[t];
        fs_tex_env_init(&s->unit[u].env); /* table 6.19 */
    }
    s->next_name = 1;
    c->texture = s;
    return 0;
}

void fs_texture_free(fs_context *c)
{
    struct fs_texture_state *s = c->texture;
    if (!s)
        return;
    for (int t = 0; t < FS_TEX_TARGETS; t++)
        object_release(&s->default_obj[t]);
    for (size_t i = 0; i < s->count; i++) {
        object_release(s->objects[i]);
        free(s->objects[i]);
    }
    free(s->objects);
    for (int m = 0; m < 4; m++)
        for (int k = 0; k < 4; k++)
            fs_footprint_filter_destroy(s->footprint[m][k / 2][k % 2]);
    free(s);
    c->texture = NULL;
}

bool *fs_texture_enable_flag(fs_context *c, GLenum cap)
{
    fs_tex_target_info ti;
    if (!fs_tex_target_of(cap, &ti) || ti.proxy)
        return NULL;
    return &fs_tex_active(c)->enabled[ti.k];
}

void fs_texture_enables_changed(fs_context *c)
{
    /* The rasterizer interpolates texture coordinates only of the units
     * that read them (rasterizer.h), and those of the quad sharing
     * llvmpipe's vector only while some bound texture's sampling depends
     * on it. */
    unsigned mask = 0;
    bool pair = false;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        const fs_tex_unit *tu = &c->texture->unit[u];
        int k = fs_tex_unit_target(tu);
        if (k < 0)
            continue;
        mask |= 1u << u;
        pair = pair || fs_tex_pair_decides(tu->bound[k]);
    }
    c->raster.tex_mask = mask;
    c->raster.tex_units = mask ? 32 - __builtin_clz(mask) : 1;
    c->raster.interpolate_tex = mask != 0;
    c->raster.tex_pair_lod = pair;
}

uint64_t fs_texture_enables(const fs_context *c)
{
    uint64_t bits = 0;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        for (int t = 0; t < FS_TEX_TARGETS; t++)
            bits |= (uint64_t)c->texture->unit[u].enabled[t] << (u * FS_TEX_TARGETS + t);
    return bits;
}

void fs_texture_set_enables(fs_context *c, uint64_t bits)
{
    _Static_assert(FS_MAX_TEXTURE_UNITS * FS_TEX_TARGETS <= 64, "the enables fit the bits");
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
        for (int t = 0; t < FS_TEX_TARGETS; t++)
            c->texture->unit[u].enabled[t] = (bits >> (u * FS_TEX_TARGETS + t)) & 1u;
    fs_texture_enables_changed(c);
}

bool fs_tex_pair_decides(const fs_tex_object *t)
{
    /* llvmpipe's float path (a wrap other than REPEAT and CLAMP_TO_EDGE
     * on an axis) with min and mag image
     * filters that differ samples the NEAREST pixels of a vector (8
     * pixels, two quads) through its LINEAR code whenever any pixel of the
     * vector needs LINEAR (gallivm lp_bld_sample_soa.c,
     * lp_build_sample_mipmap_both). */
    GLenum mf = t->min_filter;
    bool min_linear = mf == GL_LINEAR || mf == GL_LINEAR_MIPMAP_NEAREST || mf == GL_LINEAR_MIPMAP_LINEAR;
    return !fs_tex_simple_wraps(t) && (GLenum)(min_linear ? GL_LINEAR : GL_NEAREST) != t->mag_filter;
}

uint64_t fs_texture_quads_sampled(const fs_context *c) { return c->texture->quads_sampled; }
uint64_t fs_texture_quads_incomplete(const fs_context *c) { return c->texture->quads_incomplete; }

/* ---- objects (3.8.12) ---- */

static fs_tex_object *lookup(struct fs_texture_state *s, GLuint name, size_t *index)
{
    /* Linear: lookups happen at bind and delete time only, never per
     * fragment (the bound object is held as a pointer). */
    for (size_t i = 0; i < s->count; i++) {
        if (s->objects[i]->name == name) {
            if (index)
                *index = i;
            return s->objects[i];
        }
    }
    return NULL;
}

static fs_tex_object *create_object(struct fs_texture_state *s, GLuint name)
{
    if (s->count == s->cap) {
        size_t ncap = s->cap ? s->cap * 2 : 16;
        fs_tex_object **p = realloc(s->objects, ncap * sizeof *p);
        if (!p)
            return NULL;
        s->objects = p;
        s->cap = ncap;
    }
    fs_tex_object *t = malloc(sizeof *t);
    if (!t)
        return NULL;
    object_defaults(t, name);
    s->objects[s->count++] = t;
    return t;
}

void fs_exec_GenTextures(fs_context *c, GLsizei n, GLuint *textures)
{
    struct fs_texture_state *s = c->texture;
    /* At most FS_MAX_NAMES objects held: n = 2^31 - 1 from a bad trace
     * is GL_OUT_OF_MEMORY at once, with nothing generated. */
    if (!fs_gen_names_ok(c, n, s->count))
        return;
    /* Names are reserved by being returned; GL 1.5 creates the object on
     * first bind.  fragsim creates it at once (unbound, default state),
     * which glIsTexture cannot tell apart only because it also reports
     * bound_once (see fs_exec_IsTexture). */
    /* Names above the largest held cannot be taken: no lookup for them
     * (one per name would make a large n quadratic). */
    GLuint max_held = 0;
    for (size_t k = 0; k < s->count; k++)
        if (s->objects[k]->name > max_held)
            max_held = s->objects[k]->name;
    for (GLsizei i = 0; i < n; i++) {
        GLuint name = s->next_name;
        while (name == 0 || (name <= max_held && lookup(s, name, NULL)))
            name++;
        s->next_name = name + 1;
        if (!create_object(s, name)) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        textures[i] = name;
    }
}

void fs_exec_DeleteTextures(fs_context *c, GLsizei n, const GLuint *textures)
{
    struct fs_texture_state *s = c->texture;
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    for (GLsizei i = 0; i < n; i++) {
        size_t idx;
        fs_tex_object *t = textures[i] ? lookup(s, textures[i], &idx) : NULL;
        if (!t)
            continue; /* 0 and unused names are silently ignored */
        /* A bound texture that is deleted reverts to texture 0, on every
         * unit it is bound to (3.8.12). */
        for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)
            for (int k = 0; k < FS_TEX_TARGETS; k++)
                if (s->unit[u].bound[k] == t) {
                    s->unit[u].bound[k] = &s->default_obj[k];
                    fs_texture_enables_changed(c); /* the rasterizer's tex_pair_lod */
                }
        object_release(t);
        free(t);
        s->objects[idx] = s->objects[--s->count];
    }
}

/* Binds texture (0: the default object) to target k of unit u.  A texture
 * bound before to another target is GL_INVALID_OPERATION (3.8.12: its
 * target is fixed by its first bind). */
static void bind(fs_context *c, int u, enum fs_tex_target k, GLuint texture)
{
    struct fs_texture_state *s = c->texture;
    fs_tex_object *t = &s->default_obj[k];
    if (texture != 0) {
        t = lookup(s, texture, NULL);
        if (t && t->bound_once && t->target != k) {
            fs_error(c, GL_INVALID_OPERATION);
            return;
        }
        if (!t)
            t = create_object(s, texture);
        if (!t) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        if (!t->bound_once && k == FS_TEX_RECT)
            rect_defaults(t);
        t->bound_once = true;
        t->target = k;
    }
    fs_state_mark(c, GL_TEXTURE_BIT);
    s->unit[u].bound[k] = t;
    fs_texture_enables_changed(c); /* the rasterizer's tex_pair_lod */
}

void fs_exec_BindTexture(fs_context *c, GLenum target, GLuint texture)
{
    fs_tex_target_info ti;
    if (!fs_tex_target_of(target, &ti) || ti.proxy) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    bind(c, fs_active_unit(c), ti.k, texture);
}

GLboolean fs_exec_IsTexture(fs_context *c, GLuint texture)
{
    /* GL 1.5 spec 3.8.12: a name returned by GenTextures but not yet bound
     * is not a texture. */
    fs_tex_object *t = texture ? lookup(c->texture, texture, NULL) : NULL;
    return t && t->bound_once ? GL_TRUE : GL_FALSE;
}

/* ---- pixel formats (3.6.4, 3.8.1; pipeline/pixel_transfer.h) ---- */

/* The format/type errors of glTexImage2D and glTexSubImage2D: those of
 * 3.6.4 (fs_pixel_check), and INVALID_OPERATION for the depth and stencil
 * formats: the model has no depth textures, and 3.8.1 makes DEPTH_COMPONENT
 * with a colour internal format INVALID_OPERATION (Mesa answers the same
 * for STENCIL_INDEX).  COLOR_INDEX is valid; fragsim has no colour tables
 * to convert it with. */
static GLenum tex_format_error(GLenum format, GLenum type)
{
    GLenum err = fs_pixel_check(format, type);
    if (err == GL_NO_ERROR && (fs_pixel_format_kind(format) & (FS_PIXEL_STENCIL | FS_PIXEL_DEPTH | FS_PIXEL_DEPTH_STENCIL)))
        return GL_INVALID_OPERATION;
    return err;
}

/* Whether a client format holds depth: DEPTH_COMPONENT, or
 * EXT_packed_depth_stencil's DEPTH_STENCIL, which llvmpipe takes into
 * every depth internal format and DEPTH_COMPONENT into the depth-stencil
 * ones (measured on OSMesa). */
static bool depth_data(GLenum format) { return format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL; }

/* The same for the image commands, which take depth data (GL 1.4
 * 3.8.1: with a depth internal format only, which the caller checks with
 * depth_mismatch once the image's other arguments passed). */
static GLenum image_format_error(GLenum format, GLenum type)
{
    return depth_data(format) ? fs_pixel_check(format, type) : tex_format_error(format, type);
}

/* 3.8.1: depth data with a colour internal format, or other
 * data with a depth one, is INVALID_OPERATION. */
static bool depth_mismatch(bool depth_image, GLenum format)
{
    return depth_image != depth_data(format);
}

/* Bytes glTexImage2D/glTexSubImage2D read (GL 1.5 spec 3.6.4, unpacking by
 * the whole unpack state).  0 for invalid formats and types (the command
 * then fails with an error and reads nothing). */
int64_t fs_teximage_bytes(fs_context *c, GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    return fs_pixel_image_bytes(&ps, 2, w, h, 1, format, type);
}

int64_t fs_teximage_nd_bytes(fs_context *c, int dims, GLsizei w, GLsizei h, GLsizei d, GLenum format, GLenum type)
{
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    return fs_pixel_image_bytes(&ps, dims, w, h, d, format, type);
}

int fs_texparam_count(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1; }
int fs_texenv_count(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }

/* Base internal format of an internalformat argument (tables 3.15 and
 * 3.16); 0 when it is not one. */
static GLenum base_format(GLint f)
{
    switch (f) {
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12: case GL_LUMINANCE16:
        return GL_LUMINANCE;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
        return GL_LUMINANCE_ALPHA;
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
        return GL_ALPHA;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12: case GL_INTENSITY16:
        return GL_INTENSITY;
    case 3: case GL_RGB: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_RGB10:
    case GL_RGB12: case GL_RGB16:
        return GL_RGB;
    case 4: case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8: case GL_RGB10_A2:
    case GL_RGBA12: case GL_RGBA16:
        return GL_RGBA;
    /* ARB_texture_rg, which llvmpipe exposes in a compatibility context
     * (measured through OSMesa: accepted by glTexImage and
     * glCopyTexImage, sizes R8 / R8 G8, R16 / R16 G16). */
    case GL_RED: case GL_R8: case GL_R16:
        return GL_RED;
    case GL_RG: case GL_RG8: case GL_RG16:
        return GL_RG;
    /* ARB_texture_float (and ARB_texture_rg's float formats), which
     * llvmpipe accepts in a compatibility context (measured); the model
     * keeps their texels at 8 bits (float_format). */
    case GL_ALPHA16F_ARB: case GL_ALPHA32F_ARB: return GL_ALPHA;
    case GL_LUMINANCE16F_ARB: case GL_LUMINANCE32F_ARB: return GL_LUMINANCE;
    case GL_LUMINANCE_ALPHA16F_ARB: case GL_LUMINANCE_ALPHA32F_ARB: return GL_LUMINANCE_ALPHA;
    case GL_INTENSITY16F_ARB: case GL_INTENSITY32F_ARB: return GL_INTENSITY;
    case GL_R16F: case GL_R32F: return GL_RED;
    case GL_RG16F: case GL_RG32F: return GL_RG;
    case GL_RGB16F: case GL_RGB32F: return GL_RGB;
    case GL_RGBA16F: case GL_RGBA32F: return GL_RGBA;
    /* GL 1.4 depth textures (units/texture_depth.c). */
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    /* EXT_packed_depth_stencil and ARB_depth_buffer_float: depth textures
     * whose sampling reads the depth (GL 3.0 3.8.14), stencil not kept. */
    case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: case GL_DEPTH32F_STENCIL8:
        return GL_DEPTH_COMPONENT;
    default:
        /* the compressed formats the model encodes (texture_compressed.c) */
        return fs_tex_compressed_upload_base(f);
    }
}

/* Whether an internal format is a float one (ARB_texture_float,
 * ARB_texture_rg): llvmpipe keeps floats, unclamped, and samples them in
 * its float path; the model keeps 8 bits.  A copy from the 8-bit colour
 * buffer keeps every value (a half float holds v / 255 to better than half
 * a step of 1/255; the float snapshots of gl12-copyteximage_3d are exact),
 * but data outside [0, 1] or between the 8-bit steps does not: a
 * glTexImage or glTexSubImage with data into one is counted as
 * unsupported.  (Filtering copied texels in llvmpipe's float path is not
 * compared yet.) */
static bool float_format(GLint f)
{
    switch (f) {
    case GL_ALPHA16F_ARB: case GL_ALPHA32F_ARB: case GL_LUMINANCE16F_ARB: case GL_LUMINANCE32F_ARB:
    case GL_LUMINANCE_ALPHA16F_ARB: case GL_LUMINANCE_ALPHA32F_ARB: case GL_INTENSITY16F_ARB:
    case GL_INTENSITY32F_ARB: case GL_R16F: case GL_R32F: case GL_RG16F: case GL_RG32F: case GL_RGB16F:
    case GL_RGB32F: case GL_RGBA16F: case GL_RGBA32F:
        return true;
    default:
        return false;
    }
}

/* The source of component k of a stored texel of base format `base`
 * (table 3.15's components, expanded as the sampler reads them, see
 * fs_tex_image): a component 0-3 of the RGBA group or a constant. */
enum { SRC_ZERO = 4, SRC_ONE = 5 };
static int texel_source(GLenum base, int k)
{
    switch (base) {
    case GL_LUMINANCE: return k < 3 ? 0 : SRC_ONE;
    case GL_LUMINANCE_ALPHA: return k < 3 ? 0 : 3;
    case GL_ALPHA: return k < 3 ? SRC_ZERO : 3;
    case GL_INTENSITY: return 0;
    case GL_RGB: return k < 3 ? k : SRC_ONE;
    /* ARB_texture_rg: the missing components read as G = B = 0, A = 1. */
    case GL_RED: return k == 0 ? 0 : k < 3 ? SRC_ZERO : SRC_ONE;
    case GL_RG: return k < 2 ? k : k == 2 ? SRC_ZERO : SRC_ONE;
    default: return k;
    }
}

static void store_texel(uint8_t *dst, const uint8_t rgba[4], GLenum base)
{
    uint8_t in[4];
    memcpy(in, rgba, 4);
    for (int k = 0; k < 4; k++) {
        int src = texel_source(base, k);
        dst[k] = src == SRC_ZERO ? 0 : src == SRC_ONE ? 255 : in[src];
    }
}

/* The same for the stored values of a wide image (fs_tex_image.wide). */
static void store_wide(uint16_t *dst, const uint16_t rgba[4], GLenum base)
{
    uint16_t in[4];
    memcpy(in, rgba, sizeof in);
    for (int k = 0; k < 4; k++) {
        int src = texel_source(base, k);
        dst[k] = src == SRC_ZERO ? 0 : src == SRC_ONE ? 1 : in[src];
    }
}

void fs_tex_wide_from_texels(fs_tex_image *img, size_t i, size_t n)
{
    /* A component of the expansion is 0 or 255 in texels[]. */
    for (size_t j = 4 * i; j < 4 * (i + n); j++) {
        int nb = img->wide_bits[j % 4];
        img->wide[j] = (uint16_t)(nb ? fs_texel_wide_from8(img->texels[j], nb) : img->texels[j] == 255);
    }
}

/* The bits of each stored component of a format not stored at 8 bits
 * (fs_tex_image.wide), 0 for the constants of the expansion; false for
 * another format. */
static bool wide_layout(GLint internalformat, GLenum base, uint8_t out[4])
{
    int bits[4];
    if (!fs_texel_float_bits(internalformat, bits))
        return false;
    for (int k = 0; k < 4; k++) {
        int src = texel_source(base, k);
        out[k] = (uint8_t)(src >= SRC_ZERO ? 0 : bits[src]);
    }
    return true;
}

/* The final conversion of a row of a wide image's upload: the 8-bit
 * texels (fs_texel_from_float) and the stored values, unexpanded. */
typedef struct wide_conv {
    int bits[4];        /* fs_texel_float_bits */
    int wbits[4];       /* fs_texel_wide_bits */
    bool bytes;         /* GL_UNSIGNED_BYTE data without transfer */
    const uint8_t *row; /* the row's first 8-bit texel */
    uint16_t *wide;     /* its first stored value */
} wide_conv;

static void wide_from_float(const void *arg, const float *f, size_t n, uint8_t *out)
{
    const wide_conv *w = arg;
    fs_texel_from_float(w->bits, f, n, out);
    fs_texel_wide_from_float(w->wbits, f, n, w->bytes, w->wide + (out - w->row));
}

/* Texel (x, y, z) of an image (slices of 3D images follow each other). */
static uint8_t *texel_addr(const fs_tex_image *img, int x, int y, int z)
{
    return img->texels + (((size_t)z * (size_t)img->height + (size_t)y) * (size_t)img->width + (size_t)x) * 4;
}

/* Unpacks a client image of w x h x d (dims 1, 2 or 3) into img at off
 * (3.6.4 to RGBA, then table 3.15's components of the base format). */
static void unpack_image(fs_context *c, fs_tex_image *img, int dims, const int off[3], int w, int h, int d,
                         GLenum format, GLenum type, const uint8_t *pixels)
{
    if (img->base_format == GL_DEPTH_COMPONENT) {
        fs_tex_depth_unpack(c, img, dims, off, w, h, d, format, type, pixels);
        return;
    }
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, dims, w, h, d, format, type))
        return;
    /* A format stored at other than 8 bits is rounded from the floats, not
     * from 8-bit values (units/texel_format.c). */
    wide_conv wc;
    /* Above 8 bits the stored values come from the floats; below, from the
     * 8-bit texels, which keep them exactly (texel_format.c). */
    const bool above8 = img->wide && fs_texel_wide_bits(img->internal_format, wc.wbits);
    const bool no_xfer = format != GL_COLOR_INDEX && !fs_pixel_xfer_color(c);
    wc.bytes = type == GL_UNSIGNED_BYTE && no_xfer;
    /* Below 8 bits llvmpipe rounds integer data to 8 bits first, then to
     * n bits (measured through OSMesa, GL_UNSIGNED_SHORT into RGB5,
     * RGB5_A1, R3_G3_B2: 0 of 16,384 values differ per component; from
     * the 16-bit value directly 497 differ in RGB5); float data and data
     * through transfer operations from its floats. */
    const bool float_data = type == GL_FLOAT || type == GL_HALF_FLOAT || !no_xfer;
    const bool from_float = fs_texel_float_bits(img->internal_format, wc.bits) && (above8 || float_data);
    for (int z = 0; z < d; z++)
        for (int y = 0; y < h; y++) {
            uint8_t *dst = texel_addr(img, off[0], off[1] + y, off[2] + z);
            uint16_t *wdst = above8 ? img->wide + (dst - img->texels) : NULL;
            /* The pixel transfer operations of 3.6.5 (3.8.1: the image is
             * taken as by glDrawPixels up to the final conversion). */
            if (wdst) {
                wc.row = dst;
                wc.wide = wdst;
                fs_pixel_unpack_transfer_conv(c, &l, pixels, z, y, 0, w, dst, wide_from_float, &wc);
            } else if (from_float) {
                fs_pixel_unpack_transfer_conv(c, &l, pixels, z, y, 0, w, dst, fs_texel_from_float, wc.bits);
            } else {
                fs_pixel_unpack_transfer_rgba8(c, &l, pixels, z, y, 0, w, dst);
            }
            if (img->base_format != GL_RGBA)
                for (int x = 0; x < w; x++) {
                    store_texel(dst + 4 * x, dst + 4 * x, img->base_format);
                    if (wdst)
                        store_wide(wdst + 4 * x, wdst + 4 * x, img->base_format);
                }
            /* llvmpipe's precision for the format (units/texel_format.c). */
            if (!from_float)
                fs_texel_quantize(img->internal_format, dst, (size_t)w, false);
            if (img->wide && !above8)
                fs_tex_wide_from_texels(img, (size_t)(dst - img->texels) / 4, (size_t)w);
        }
}

static const int no_offset[3] = {0, 0, 0};

/* Unpacks a client image of size[0..dims-1] into img, which is that image
 * without `border` texels on each side of each of its dimensions. */
static void unpack_inner(fs_context *c, fs_tex_image *img, int dims, int border, const GLsizei size[3],
                         GLenum format, GLenum type, const uint8_t *pixels)
{
    int w = size[0], h = dims > 1 ? size[1] : 1, d = dims > 2 ? size[2] : 1;
    if (!border) {
        unpack_image(c, img, dims, no_offset, w, h, d, format, type, pixels);
        return;
    }
    fs_tex_image whole = {.width = w, .height = h, .depth = d, .base_format = img->base_format,
                          .internal_format = img->internal_format, .depth_bits = img->depth_bits};
    memcpy(whole.wide_bits, img->wide_bits, sizeof whole.wide_bits);
    const size_t n = (size_t)w * (size_t)h * (size_t)d * 4;
    whole.texels = malloc(n);
    whole.wide = img->wide ? malloc(n * sizeof *whole.wide) : NULL;
    if (!whole.texels || (img->wide && !whole.wide)) {
        fs_tex_image_free(&whole);
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    unpack_image(c, &whole, dims, no_offset, w, h, d, format, type, pixels);
    int by = dims > 1 ? border : 0, bz = dims > 2 ? border : 0;
    for (int z = 0; z < img->depth; z++)
        for (int y = 0; y < img->height; y++) {
            uint8_t *to = texel_addr(img, 0, y, z);
            const uint8_t *from = texel_addr(&whole, border, y + by, z + bz);
            memcpy(to, from, (size_t)img->width * 4);
            if (img->wide)
                memcpy(img->wide + (to - img->texels), whole.wide + (from - whole.texels),
                       (size_t)img->width * 4 * sizeof *img->wide);
        }
    fs_tex_image_free(&whole);
}

GLenum fs_tex_base_format(GLint internalformat)
{
    /* GL_FRAGSIM_mp_grid keeps colour textures only. */
    return fs_tex_depth_format(internalformat) ? 0 : base_format(internalformat);
}

GLenum fs_tex_unpack_rgba8(fs_context *c, uint8_t *dst, int w, int h, GLenum base, GLenum format, GLenum type,
                           const void *pixels)
{
    /* GL_FRAGSIM_mp_grid takes the formats and types glTexImage2D takes,
     * with its errors, and refuses COLOR_INDEX, which it cannot convert,
     * with INVALID_ENUM (docs/extensions/mp_grid.txt). */
    GLenum err = tex_format_error(format, type);
    if (err == GL_NO_ERROR && format == GL_COLOR_INDEX)
        err = GL_INVALID_ENUM;
    if (err != GL_NO_ERROR)
        return err;
    if (dst && pixels && w > 0 && h > 0) {
        fs_tex_image img = {.width = w, .height = h, .depth = 1, .base_format = base, .texels = dst};
        unpack_image(c, &img, 2, no_offset, w, h, 1, format, type, pixels);
    }
    return GL_NO_ERROR;
}

/* Whether llvmpipe would store this image at more than 8 bits: for an
 * unsized internal format Mesa picks the storage that matches the client
 * data when one exists (RGBA, LUMINANCE, LUMINANCE_ALPHA or ALPHA as
 * UNSIGNED_SHORT, the 10-bit packed types; measured through OSMesa with
 * LINEAR filtering and MODULATE).  The model keeps 8 bits: NEAREST with
 * REPLACE is exact (tests/test_pixel_transfer.c), filtering and the
 * texture environment can differ, so it is counted. */
static bool keeps_wide_texels(GLint internalformat, GLenum format, GLenum type)
{
    bool unsized = (internalformat >= 1 && internalformat <= 4) || internalformat == GL_ALPHA ||
                   internalformat == GL_LUMINANCE || internalformat == GL_LUMINANCE_ALPHA ||
                   internalformat == GL_INTENSITY || internalformat == GL_RGB || internalformat == GL_RGBA;
    bool wide = (type == GL_UNSIGNED_SHORT && (format == GL_RGBA || format == GL_LUMINANCE ||
                                               format == GL_LUMINANCE_ALPHA || format == GL_ALPHA)) ||
                type == GL_UNSIGNED_INT_10_10_10_2 || type == GL_UNSIGNED_INT_2_10_10_10_REV;
    return unsized && wide;
}

/* One size of an image of level `level` of a target whose largest image is
 * 2^max_log2 (3.8.1): any size from 0 (a valid, empty image) plus 2 border
 * (ARB_texture_non_power_of_two, core in GL 2.0, which Mesa exposes on
 * every context and captured programs use), at most the largest size >>
 * level. */
static bool size_ok(GLsizei v, GLint border, int max_log2, GLint level)
{
    if (v < 0 || v > (1 << max_log2) + 2 * border)
        return false;
    GLsizei inner = v - 2 * border;
    if (v > 0 && inner < 0)
        return false;
    return inner <= ((1 << max_log2) >> level);
}

/* Checks shared by glTexImage and glCopyTexImage of every target (3.8.1):
 * returns the GL error or GL_NO_ERROR.  Border 1 images are valid GL; the
 * model keeps their inner image, as Mesa does for gallium
 * (fs_tex_image_nd). */
static GLenum check_image_args(const fs_tex_target_info *ti, GLint level, GLint internalformat,
                               const GLsizei size[3], GLint border)
{
    int max_log2 = fs_tex_target_max_log2(ti->k);
    if (level < 0 || level > max_log2)
        return GL_INVALID_VALUE;
    if (!base_format(internalformat))
        return GL_INVALID_VALUE;
    if (border != 0 && border != 1)
        return GL_INVALID_VALUE;
    for (int i = 0; i < ti->dims; i++)
        if (!size_ok(size[i], border, max_log2, level))
            return GL_INVALID_VALUE;
    /* 3.8.1: a cube map face is square. */
    if (ti->k == FS_TEX_CUBE && size[0] != size[1])
        return GL_INVALID_VALUE;
    /* ARB_texture_rectangle: level 0 only, no border. */
    if (ti->k == FS_TEX_RECT && (level != 0 || border != 0))
        return GL_INVALID_VALUE;
    return GL_NO_ERROR;
}

/* The size an image keeps without its border; 1 in the dimensions its
 * target does not have. */
static void inner_size(int dims, const GLsizei size[3], GLint border, int inner[3])
{
    for (int i = 0; i < 3; i++)
        inner[i] = i < dims ? size[i] - 2 * border : 1;
}

/* Replaces level `level` of t with an allocated, undefined image of
 * size[0] x size[1] x size[2].  Returns it, or NULL (GL_OUT_OF_MEMORY set). */
static fs_tex_image *define_level(fs_context *c, fs_tex_object *t, int face, GLint level, GLint internalformat,
                                  const int size[3])
{
    fs_tex_image *img = &fs_tex_levels(t, face)[level];
    uint8_t *texels = NULL;
    uint16_t *wide = NULL;
    uint8_t wide_bits[4];
    const bool is_wide = wide_layout(internalformat, base_format(internalformat), wide_bits);
    if (size[0] > 0 && size[1] > 0 && size[2] > 0) {
        const size_t n = (size_t)size[0] * (size_t)size[1] * (size_t)size[2];
        texels = calloc(n, 4);
        wide = is_wide ? calloc(n, 4 * sizeof *wide) : NULL;
        if (!texels || (is_wide && !wide)) {
            free(texels);
            free(wide);
            fs_error(c, GL_OUT_OF_MEMORY);
            return NULL;
        }
    }
    fs_tex_image_free(img); /* an uncompressed image replaces a compressed one */
    img->texels = texels;
    img->wide = wide;
    if (wide)
        memcpy(img->wide_bits, wide_bits, sizeof wide_bits);
    img->width = texels ? size[0] : 0;
    img->height = texels ? size[1] : 0;
    img->depth = texels ? size[2] : 0;
    img->internal_format = internalformat;
    img->base_format = base_format(internalformat);
    img->depth_bits = fs_tex_depth_bits(internalformat, 0);
    t->complete = -1;
    return img;
}

/* glTexImage on a proxy target (3.8.11): the level's state as the image
 * would set it (its border kept, as Mesa keeps it for a proxy), or all
 * zero when only the size is refused (too large, not 2^n + 2 border),
 * which raises no error.  err is the image's error; false when it is an
 * error to raise (a bad level, format, border or negative size). */
static bool proxy_image(fs_context *c, const fs_tex_target_info *ti, GLenum err, GLint level, GLint internalformat,
                        const GLsizei size[3], GLint border)
{
    bool sizes = size[0] >= 0 && (ti->dims < 2 || size[1] >= 0) && (ti->dims < 3 || size[2] >= 0);
    bool size_only = level >= 0 && level <= fs_tex_target_max_log2(ti->k) && base_format(internalformat) &&
                     (border == 0 || border == 1) && sizes;
    if (err != GL_NO_ERROR && !(err == GL_INVALID_VALUE && size_only))
        return false;
    fs_tex_image *img = &c->texture->proxy[ti->k][level];
    memset(img, 0, sizeof *img);
    if (err != GL_NO_ERROR)
        return true;
    img->width = size[0];
    img->height = ti->dims > 1 ? size[1] : 1;
    img->depth = ti->dims > 2 ? size[2] : 1;
    img->border = border;
    img->internal_format = internalformat;
    img->base_format = base_format(internalformat);
    img->depth_bits = fs_tex_depth_bits(internalformat, 0);
    img->described = true;
    return true;
}

/* The target of an image command taking dims-dimensional images: false
 * (GL_INVALID_ENUM set) for another target, or a proxy where none is
 * allowed. */
static bool image_target(fs_context *c, GLenum target, int dims, bool proxy_ok, fs_tex_target_info *ti)
{
    if (fs_tex_image_target_of(target, ti) && ti->dims == dims && (proxy_ok || !ti->proxy))
        return true;
    fs_error(c, GL_INVALID_ENUM);
    return false;
}

/* GL 1.5 3.8.1 lets the GL store a generic compressed internal format
 * (table 3.17) uncompressed.  llvmpipe does so (measured through OSMesa:
 * GL_TEXTURE_COMPRESSED 0, TEXTURE_INTERNAL_FORMAT, sizes and glGetTexImage
 * as for the base format) for GL_COMPRESSED_ALPHA and _INTENSITY on every
 * target and for every generic one on a 1D target, whose images no block
 * format of Mesa's takes.  Returns the format the image is stored as:
 * the other generic formats on 2D, cube map and 3D images Mesa compresses
 * (RGTC, LATC, DXT1, DXT5: fs_tex_generic_compressed_format, encoded at
 * upload; docs/compressed_textures.md). */
static GLint generic_compressed_storage(GLint f, int dims)
{
    switch (f) {
    case GL_COMPRESSED_ALPHA: return GL_ALPHA;
    case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
    default: break;
    }
    if (dims != 1)
        return fs_tex_generic_compressed_format(f) ? fs_tex_generic_compressed_format(f) : f;
    switch (f) {
    case GL_COMPRESSED_RED: return GL_RED;
    case GL_COMPRESSED_RG: return GL_RG;
    case GL_COMPRESSED_LUMINANCE: return GL_LUMINANCE;
    case GL_COMPRESSED_LUMINANCE_ALPHA: return GL_LUMINANCE_ALPHA;
    case GL_COMPRESSED_RGB: return GL_RGB;
    case GL_COMPRESSED_RGBA: return GL_RGBA;
    default: return f;
    }
}

/* A level of a compressed format just stored: its blocks as llvmpipe
 * encodes the texels, and the texels as they decode (texture_compressed.c;
 * nothing for another format).  False with GL_OUT_OF_MEMORY set. */
static bool compress_box(fs_context *c, fs_tex_image *img, const GLint off[3], const GLsizei size[3])
{
    if (fs_tex_compress_box(img, off[0], off[1], off[2], size[0], size[1], size[2]))
        return true;
    fs_error(c, GL_OUT_OF_MEMORY);
    return false;
}

static bool compress_all(fs_context *c, fs_tex_image *img)
{
    const GLsizei all[3] = {img->width, img->height, img->depth};
    return compress_box(c, img, no_offset, all);
}

/* A sub-image command into a compressed level: the box on the block grid
 * (else GL_INVALID_OPERATION, as OSMesa), and the level one the model
 * encodes (else the blocks are not updated: counted as unsupported). */
static bool compressed_box_ok(fs_context *c, const fs_tex_image *img, const GLint off[3], const GLsizei size[3],
                              const char *what)
{
    if (!fs_tex_compressed_block_bytes(img->internal_format, NULL))
        return true;
    if (!fs_tex_compressed_box_aligned(img, off, size)) {
        fs_error(c, GL_INVALID_OPERATION);
        return false;
    }
    if (!fs_tex_compressed_upload_base(img->internal_format))
        fs_unsupported(c, what);
    return true;
}

/* The S3TC, RGTC and LATC block formats named explicitly are for 2D and
 * cube map images only (Mesa's check of the target a compressed format
 * can take: measured through OSMesa, glTexImage1D/3D and
 * glCopyTexImage1D with one are INVALID_ENUM; the generic formats are
 * stored otherwise, generic_compressed_storage). */
static bool block_format_refused(GLint f, int dims)
{
    return dims != 2 && fs_tex_compressed_block_bytes(f, NULL);
}

void fs_tex_image_nd(fs_context *c, int dims, GLenum target, GLint level, GLint internalformat, GLsizei w, GLsizei h,
                     GLsizei d, GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    fs_tex_target_info ti;
    if (!image_target(c, target, dims, true, &ti))
        return;
    GLint asked = internalformat;
    internalformat = generic_compressed_storage(internalformat, dims);
    const GLsizei size[3] = {w, h, d};
    GLenum err = image_format_error(format, type);
    if (err == GL_NO_ERROR)
        err = check_image_args(&ti, level, internalformat, size, border);
    /* GL 1.4 3.8.1: depth textures are one- and two-dimensional (Mesa
     * answers INVALID_OPERATION for 3D, proxy included; measured). */
    bool depth = fs_tex_depth_format(internalformat);
    if (err == GL_NO_ERROR && (depth_mismatch(depth, format) || (depth && dims == 3)))
        err = GL_INVALID_OPERATION;
    if (err == GL_NO_ERROR && block_format_refused(asked, dims))
        err = GL_INVALID_ENUM;
    if (ti.proxy && proxy_image(c, &ti, err, level, internalformat, size, border))
        return;
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    /* A border (3.8.1) is dropped, as Mesa does for gallium, which has no
     * texture borders: the level is the inner image (measured on OSMesa:
     * TEXTURE_WIDTH w - 2, TEXTURE_BORDER 0, sampling never reads it). */
    int inner[3];
    inner_size(dims, size, border, inner);
    fs_tex_object *t = fs_tex_active(c)->bound[ti.k];
    fs_tex_image *img = define_level(c, t, ti.face, level, internalformat, inner);
    if (img)
        img->depth_bits = fs_tex_depth_bits(internalformat, type);
    if (img && keeps_wide_texels(internalformat, format, type))
        fs_unsupported(c, "16/10-bit texels, unsized internal format (stored at 8 bits)");
    if (img && pixels && float_format(internalformat))
        fs_unsupported(c, "glTexImage data into a float internal format (stored at 8 bits)");
    if (img && img->texels && pixels)
        unpack_inner(c, img, dims, border, size, format, type, pixels);
    if (img && !compress_all(c, img))
        return;
    if (img)
        fs_tex_image_changed(c, t, ti.face, level);
}

void fs_exec_TexImage2D(fs_context *c, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLsizei height, GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    fs_tex_image_nd(c, 2, target, level, internalformat, width, height, 1, border, format, type, pixels);
}

/* The level a TexSubImage or CopyTexSubImage writes into, after the
 * checks they share (3.8.2): level and size in range, the level defined by
 * TexImage, the box inside it.  NULL when one fails; the error is set. */
static fs_tex_image *subimage_target(fs_context *c, const fs_tex_target_info *ti, GLint level, const GLint off[3],
                                     const GLsizei size[3])
{
    if (level < 0 || level > fs_tex_target_max_log2(ti->k) || size[0] < 0 || size[1] < 0 || size[2] < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return NULL;
    }
    fs_tex_image *img = &fs_tex_levels(fs_tex_active(c)->bound[ti->k], ti->face)[level];
    if (!img->texels) {
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    const int dim[3] = {img->width, img->height, img->depth};
    for (int i = 0; i < 3; i++)
        if (off[i] < 0 || (int64_t)off[i] + size[i] > dim[i]) {
            fs_error(c, GL_INVALID_VALUE);
            return NULL;
        }
    return img;
}

void fs_tex_subimage_nd(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3], GLsizei w,
                        GLsizei h, GLsizei d, GLenum format, GLenum type, const GLvoid *pixels)
{
    fs_tex_target_info ti;
    if (!image_target(c, target, dims, false, &ti))
        return;
    GLenum err = image_format_error(format, type);
    if (err == GL_INVALID_ENUM) {
        fs_error(c, err);
        return;
    }
    const GLsizei size[3] = {w, h, d};
    fs_tex_image *img = subimage_target(c, &ti, level, off, size);
    if (!img)
        return;
    if (err == GL_NO_ERROR && depth_mismatch(img->base_format == GL_DEPTH_COMPONENT, format))
        err = GL_INVALID_OPERATION;
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    /* llvmpipe compresses the box into the level's blocks */
    if (!compressed_box_ok(c, img, off, size, "glTexSubImage into a compressed level (units/texture_compressed.c)"))
        return;
    if (pixels && float_format(img->internal_format))
        fs_unsupported(c, "glTexImage data into a float internal format (stored at 8 bits)");
    if (w > 0 && h > 0 && d > 0 && pixels) {
        unpack_image(c, img, dims, off, w, h, d, format, type, pixels);
        if (!compress_box(c, img, off, size))
            return;
    }
    fs_tex_image_changed(c, fs_tex_active(c)->bound[ti.k], ti.face, level);
}

void fs_exec_TexSubImage2D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                           GLsizei width, GLsizei height, GLenum format, GLenum type, const GLvoid *pixels)
{
    const GLint off[3] = {xoffset, yoffset, 0};
    fs_tex_subimage_nd(c, 2, target, level, off, width, height, 1, format, type, pixels);
}

/* Copies a framebuffer rectangle into slice dz of img at (dx, dy) (3.8.2:
 * the pixels are taken as by ReadPixels of RGBA; pixels outside the window
 * are undefined, fragsim leaves them as they were). */
static void copy_from_framebuffer(fs_context *c, fs_tex_image *img, const int dst[3], GLint x, GLint y, GLsizei w,
                                  GLsizei h)
{
    const fs_framebuffer *fb = &c->fb;
    bool depth = img->base_format == GL_DEPTH_COMPONENT;
    for (int j = 0; j < h; j++) {
        int64_t sy = (int64_t)y + j;
        if (sy < 0 || sy >= fb->height)
            continue;
        for (int i = 0; i < w; i++) {
            int64_t sx = (int64_t)x + i;
            if (sx < 0 || sx >= fb->width)
                continue;
            if (depth) {
                /* A depth texture copies the depth buffer (GL 1.4 3.8.2). */
                fs_tex_depth_store_copy(img, texel_addr(img, dst[0] + i, dst[1] + j, dst[2]),
                                        fb->depth[(size_t)sy * (size_t)fb->width + (size_t)sx], fb->depth_bits);
                continue;
            }
            const uint8_t *src = fb->color + ((size_t)sy * (size_t)fb->width + (size_t)sx) * 4;
            uint8_t *t = texel_addr(img, dst[0] + i, dst[1] + j, dst[2]);
            store_texel(t, src, img->base_format);
            fs_texel_quantize(img->internal_format, t, 1, true);
            /* A wide format's stored values as from a byte upload (not
             * measured for copies). */
            if (img->wide)
                fs_tex_wide_from_texels(img, (size_t)(t - img->texels) / 4, 1);
        }
    }
}

void fs_tex_copy_image_nd(fs_context *c, int dims, GLenum target, GLint level, GLenum internalformat, GLint x,
                          GLint y, GLsizei w, GLsizei h, GLint border)
{
    fs_tex_target_info ti;
    if (!image_target(c, target, dims, false, &ti))
        return;
    GLint asked = (GLint)internalformat;
    internalformat = (GLenum)generic_compressed_storage((GLint)internalformat, dims);
    const GLsizei size[3] = {w, h, 1};
    /* Table 3.16: the internal formats 1-4 are not accepted here. */
    GLenum err = internalformat >= 1 && internalformat <= 4
                     ? GL_INVALID_VALUE
                     : check_image_args(&ti, level, (GLint)internalformat, size, border);
    if (err == GL_NO_ERROR && block_format_refused(asked, dims))
        err = GL_INVALID_ENUM;
    /* A depth texture needs a depth buffer to copy from (GL 1.4 3.8.2). */
    if (err == GL_NO_ERROR && fs_tex_depth_format((GLint)internalformat) && (c->fb.depth_bits == 0 || dims == 3))
        err = GL_INVALID_OPERATION;
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    /* The border is dropped as by glTexImage: the inner rectangle is
     * copied. */
    int inner[3];
    inner_size(dims, size, border, inner);
    fs_tex_object *t = fs_tex_active(c)->bound[ti.k];
    fs_tex_image *img = define_level(c, t, ti.face, level, (GLint)internalformat, inner);
    /* (at x or y = INT_MAX everything read is outside the window anyway) */
    GLint bx = x < INT_MAX ? x + border : x, by = dims > 1 && y < INT_MAX ? y + border : y;
    if (img && img->texels)
        copy_from_framebuffer(c, img, no_offset, bx, by, img->width, img->height);
    if (img && !compress_all(c, img))
        return;
    if (img)
        fs_tex_image_changed(c, t, ti.face, level);
}

void fs_exec_CopyTexImage2D(fs_context *c, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                            GLsizei width, GLsizei height, GLint border)
{
    fs_tex_copy_image_nd(c, 2, target, level, internalformat, x, y, width, height, border);
}

void fs_tex_copy_subimage_nd(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3], GLint x,
                             GLint y, GLsizei w, GLsizei h)
{
    fs_tex_target_info ti;
    if (!image_target(c, target, dims, false, &ti))
        return;
    const GLsizei size[3] = {w, h, 1};
    fs_tex_image *img = subimage_target(c, &ti, level, off, size);
    if (!img)
        return;
    if (!compressed_box_ok(c, img, off, size, "glCopyTexSubImage into a compressed level (units/texture_compressed.c)"))
        return;
    if (img->base_format == GL_DEPTH_COMPONENT && c->fb.depth_bits == 0) {
        fs_error(c, GL_INVALID_OPERATION); /* no depth buffer to copy (GL 1.4 3.8.2) */
        return;
    }
    copy_from_framebuffer(c, img, off, x, y, w, h);
    if (!compress_box(c, img, off, size))
        return;
    fs_tex_image_changed(c, fs_tex_active(c)->bound[ti.k], ti.face, level);
}

void fs_exec_CopyTexSubImage2D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                               GLint y, GLsizei width, GLsizei height)
{
    const GLint off[3] = {xoffset, yoffset, 0};
    fs_tex_copy_subimage_nd(c, 2, target, level, off, x, y, width, height);
}

/* ---- parameters (3.8.4) ---- */

static bool is_min_filter(GLenum f)
{
    switch (f) {
    case GL_NEAREST: case GL_LINEAR: case GL_NEAREST_MIPMAP_NEAREST: case GL_LINEAR_MIPMAP_NEAREST:
    case GL_NEAREST_MIPMAP_LINEAR: case GL_LINEAR_MIPMAP_LINEAR:
    case GL_FOOTPRINT_FRAGSIM: case GL_FOOTPRINT_HYBRID_FRAGSIM:
        return true;
    default:
        return false;
    }
}

static bool is_wrap(GLenum w)
{
    return w == GL_REPEAT || w == GL_CLAMP || w == GL_CLAMP_TO_EDGE || w == GL_CLAMP_TO_BORDER ||
           w == GL_MIRRORED_REPEAT || w == GL_MIRROR_CLAMP_EXT || w == GL_MIRROR_CLAMP_TO_EDGE_EXT ||
           w == GL_MIRROR_CLAMP_TO_BORDER_EXT; /* EXT_texture_mirror_clamp, which llvmpipe offers */
}

static bool is_swizzle(GLenum e)
{
    return e == GL_RED || e == GL_GREEN || e == GL_BLUE || e == GL_ALPHA || e == GL_ZERO || e == GL_ONE;
}

/* An enum passed through glTexParameterf or glTexEnvf is truncated to an
 * integer, as Mesa does (so OSMesa and fragsim agree on 9728.5); a value
 * outside GLenum's range (NaN, infinite, negative) names no enum, and
 * converting it would be undefined behaviour in C, so it becomes 0, which
 * every caller rejects with INVALID_ENUM. */
static GLenum float_to_enum(float v)
{
    if (!(v >= 0.0f && v < 2147483648.0f))
        return 0;
    return (GLenum)(GLint)v;
}

/* Clamps to [0, 1]; NaN, which no comparison orders, becomes 0. */
static float clamp01_param(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

/* One texture parameter; vals holds 1 or 4 values already as floats (the
 * integer forms convert colours as 2.14.9 says, enums exactly). */
static void tex_parameter(fs_context *c, GLenum target, GLenum pname, const float *vals, bool vector)
{
    fs_tex_target_info ti;
    if (!fs_tex_target_of(target, &ti) || ti.proxy) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_state_mark(c, GL_TEXTURE_BIT);
    fs_tex_object *t = fs_tex_active(c)->bound[ti.k];
    GLenum e = float_to_enum(vals[0]);
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
        /* The footprint filters are defined for 2D textures only
         * (docs/extensions/footprint_filter.txt). */
        if (!is_min_filter(e) || ((e == GL_FOOTPRINT_FRAGSIM || e == GL_FOOTPRINT_HYBRID_FRAGSIM) && ti.k != FS_TEX_2D))
            break;
        /* ARB_texture_rectangle: NEAREST or LINEAR only (INVALID_ENUM). */
        if (ti.k == FS_TEX_RECT && e != GL_NEAREST && e != GL_LINEAR)
            break;
        t->min_filter = e;
        t->complete = -1;
        return;
    case GL_TEXTURE_MAG_FILTER:
        if (e != GL_NEAREST && e != GL_LINEAR)
            break;
        t->mag_filter = e;
        return;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R: /* GL 1.2; Mesa takes it for every target */
        if (!is_wrap(e))
            break;
        /* ARB_texture_rectangle: no REPEAT or MIRRORED_REPEAT (INVALID_ENUM). */
        if (ti.k == FS_TEX_RECT && (e == GL_REPEAT || e == GL_MIRRORED_REPEAT))
            break;
        *(pname == GL_TEXTURE_WRAP_S ? &t->wrap_s : pname == GL_TEXTURE_WRAP_T ? &t->wrap_t : &t->wrap_r) = e;
        return;
    case GL_TEXTURE_SWIZZLE_R:
    case GL_TEXTURE_SWIZZLE_G:
    case GL_TEXTURE_SWIZZLE_B:
    case GL_TEXTURE_SWIZZLE_A:
        /* EXT_texture_swizzle: one of six sources, else INVALID_ENUM. */
        if (!is_swizzle(e))
            break;
        t->swizzle[pname - GL_TEXTURE_SWIZZLE_R] = e;
        return;
    case GL_TEXTURE_SWIZZLE_RGBA: {
        /* Vector forms only; all four are checked before any is set. */
        if (!vector)
            break;
        GLenum sw[4];
        for (int k = 0; k < 4; k++)
            if (!is_swizzle(sw[k] = float_to_enum(vals[k])))
                goto bad_enum;
        memcpy(t->swizzle, sw, sizeof sw);
        return;
    }
    case GL_TEXTURE_BORDER_COLOR:
        if (!vector)
            break;
        for (int k = 0; k < 4; k++)
            t->border[k] = clamp01_param(vals[k]);
        return;
    case GL_TEXTURE_PRIORITY:
        t->priority = clamp01_param(vals[0]);
        return;
    case GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM:
        /* GL_FRAGSIM_footprint_filter: ROMs exist for these M only. */
        if (vals[0] != 8.0f && vals[0] != 16.0f && vals[0] != 32.0f && vals[0] != 64.0f) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        t->footprint_budget = (int)vals[0];
        return;
    case GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM:
        if (e != GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM && e != GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM)
            break;
        t->footprint_snap = e;
        return;
    default: {
        GLenum lod_err;
        if (fs_tex_depth_parameter(t, pname, e, &lod_err)) {
            if (lod_err != GL_NO_ERROR)
                fs_error(c, lod_err);
            return;
        }
        if (!fs_tex_lod_parameter(t, pname, vals[0], &lod_err))
            break;
        if (lod_err != GL_NO_ERROR)
            fs_error(c, lod_err);
        return;
    }
    }
bad_enum:
    fs_error(c, GL_INVALID_ENUM);
}

/* Integer colour components map to [-1, 1] linearly (2.14.9 table 2.9). */
static float int_to_float_color(GLint v) { return (float)((2.0 * v + 1.0) / 4294967295.0); }

/* The vector forms of glTexParameter and glTexEnv carry four values for a
 * colour parameter and one for any other. */
static void vector_from_iv(float v[4], const GLint *params, bool colour)
{
    v[0] = v[1] = v[2] = v[3] = 0.0f;
    if (colour)
        for (int k = 0; k < 4; k++)
            v[k] = int_to_float_color(params[k]);
    else
        v[0] = (float)params[0];
}

static void vector_from_fv(float v[4], const GLfloat *params, bool colour)
{
    v[0] = params[0];
    v[1] = v[2] = v[3] = 0.0f;
    if (colour)
        memcpy(v, params, 4 * sizeof *v);
}

void fs_exec_TexParameteri(fs_context *c, GLenum target, GLenum pname, GLint param)
{
    float v = (float)param;
    tex_parameter(c, target, pname, &v, false);
    fs_texture_enables_changed(c); /* filters and wraps decide tex_pair_lod */
}

void fs_exec_TexParameterf(fs_context *c, GLenum target, GLenum pname, GLfloat param)
{
    tex_parameter(c, target, pname, &param, false);
    fs_texture_enables_changed(c); /* filters and wraps decide tex_pair_lod */
}

void fs_exec_TexParameteriv(fs_context *c, GLenum target, GLenum pname, const GLint *params)
{
    float v[4];
    vector_from_iv(v, params, pname == GL_TEXTURE_BORDER_COLOR);
    if (pname == GL_TEXTURE_SWIZZLE_RGBA) /* four enums, not a colour */
        for (int k = 0; k < 4; k++)
            v[k] = (float)params[k];
    tex_parameter(c, target, pname, v, true);
    fs_texture_enables_changed(c);
}

void fs_exec_TexParameterfv(fs_context *c, GLenum target, GLenum pname, const GLfloat *params)
{
    float v[4];
    vector_from_fv(v, params, pname == GL_TEXTURE_BORDER_COLOR || pname == GL_TEXTURE_SWIZZLE_RGBA);
    fs_tex_lod_vector_form(pname, v);
    tex_parameter(c, target, pname, v, true);
    fs_texture_enables_changed(c);
}

/* ---- completeness (3.8.10) ---- */

/* Whether levels (one face's) hold the chain sampling needs (3.8.10): the
 * base level's image of size w x h x d and internal format fmt, and with
 * a MIPmap filter the levels from the base to q = min(p, MAX_LEVEL), each
 * half the previous size (at least 1), all of fmt; *last is q. */
static bool chain_ok(const fs_tex_object *t, const fs_tex_image *levels, const fs_tex_image *b, bool mip, int *last)
{
    int base = t->base_level;
    const fs_tex_image *l0 = base < FS_TEX_MAX_LEVELS ? &levels[base] : NULL;
    bool ok = l0 && l0->texels && l0->width == b->width && l0->height == b->height && l0->depth == b->depth &&
              l0->internal_format == b->internal_format;
    *last = base;
    if (ok && mip) {
        ok = t->max_level >= base;
        int w = b->width, h = b->height, d = b->depth;
        while (ok && (w > 1 || h > 1 || d > 1) && *last < t->max_level) {
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
            d = d > 1 ? d / 2 : 1;
            ++*last;
            const fs_tex_image *l = *last < FS_TEX_MAX_LEVELS ? &levels[*last] : NULL;
            ok = l && l->texels && l->width == w && l->height == h && l->depth == d &&
                 l->internal_format == b->internal_format;
        }
    }
    return ok;
}

bool fs_tex_complete(fs_tex_object *t)
{
    if (t->mpgrid) {
        t->first_level = 0;
        return fs_mpgrid_gl_complete(t);
    }
    if (t->complete >= 0)
        return t->complete != 0;
    /* 3.8.10: the image of the base level must exist (a base level past
     * the last level leaves none); a MIPmap filter also needs the levels
     * from the base to q (chain_ok), and MAX_LEVEL not below the base
     * (Mesa; measured: white, i.e. untextured, on OSMesa).  A cube map is
     * cube complete when every face's chain is that of face 0
     * (POSITIVE_X): the same square sizes and internal format. */
    int base = t->base_level;
    const fs_tex_image *b = base < FS_TEX_MAX_LEVELS ? &t->level[base] : NULL;
    bool mip = t->min_filter != GL_NEAREST && t->min_filter != GL_LINEAR;
    int last = base;
    bool ok = b && chain_ok(t, t->level, b, mip, &last);
    for (int f = 1; ok && t->target == FS_TEX_CUBE && f < FS_TEX_FACES; f++)
        ok = chain_ok(t, fs_tex_levels(t, f), b, mip, &last);
    t->first_level = ok ? base : 0;
    t->last_level = ok ? last : 0;
    t->complete = ok ? 1 : 0;
    return ok;
}

/* ---- texture environment (3.8.13) ---- */

/* GL 2.0 spec 3.3: glTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE, b) sets
 * the active unit's coordinate replacement (point state, kept with the
 * rasterizer's: GL_POINT_BIT saves it, table 6.12); a value other than
 * GL_TRUE or GL_FALSE is INVALID_VALUE, as Mesa answers, after truncating
 * a float to an integer. */
static void point_sprite_env(fs_context *c, GLenum pname, float v)
{
    if (pname != GL_COORD_REPLACE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    GLint b = (GLint)v;
    if (b != GL_TRUE && b != GL_FALSE) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    unsigned bit = 1u << fs_active_unit(c);
    c->raster.coord_replace = b ? c->raster.coord_replace | bit : c->raster.coord_replace & ~bit;
    fs_state_mark(c, GL_POINT_BIT);
}

static void tex_env(fs_context *c, GLenum target, GLenum pname, const float *vals, bool vector)
{
    fs_tex_env *s = &fs_tex_active(c)->env;
    if (target == GL_TEXTURE_FILTER_CONTROL) {
        /* GL 1.4's unit LOD bias (3.8.13; texture_lod.c). */
        if (fs_tex_filter_control(c, pname, vals[0]))
            fs_state_mark(c, GL_TEXTURE_BIT);
        return;
    }
    if (target == GL_POINT_SPRITE) {
        point_sprite_env(c, pname, vals[0]);
        return;
    }
    if (target != GL_TEXTURE_ENV) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_state_mark(c, GL_TEXTURE_BIT);
    if (pname == GL_TEXTURE_ENV_MODE) {
        GLenum m = float_to_enum(vals[0]);
        switch (m) {
        case GL_MODULATE: case GL_DECAL: case GL_BLEND: case GL_REPLACE: case GL_ADD: case GL_COMBINE:
            s->mode = m;
            return;
        default:
            fs_error(c, GL_INVALID_ENUM);
            return;
        }
    }
    if (pname == GL_TEXTURE_ENV_COLOR && vector) {
        for (int k = 0; k < 4; k++)
            s->color[k] = clamp01_param(vals[k]);
        return;
    }
    GLenum err;
    if (!fs_tex_combine_set(s, pname, vals[0], &err))
        err = GL_INVALID_ENUM;
    if (err != GL_NO_ERROR)
        fs_error(c, err);
}

void fs_exec_TexEnvi(fs_context *c, GLenum target, GLenum pname, GLint param)
{
    float v = (float)param;
    tex_env(c, target, pname, &v, false);
}

void fs_exec_TexEnvf(fs_context *c, GLenum target, GLenum pname, GLfloat param)
{
    tex_env(c, target, pname, &param, false);
}

void fs_exec_TexEnviv(fs_context *c, GLenum target, GLenum pname, const GLint *params)
{
    float v[4];
    vector_from_iv(v, params, pname == GL_TEXTURE_ENV_COLOR);
    tex_env(c, target, pname, v, true);
}

void fs_exec_TexEnvfv(fs_context *c, GLenum target, GLenum pname, const GLfloat *params)
{
    float v[4];
    vector_from_fv(v, params, pname == GL_TEXTURE_ENV_COLOR);
    tex_env(c, target, pname, v, true);
}

/* ---- the texture attribute group (6.1.14) ---- */

/* The scalar fields fs_tex_params shares with fs_tex_object, by name. */
#define FS_TEX_PARAM_FIELDS(X) \
    X(min_filter) X(mag_filter) X(wrap_s) X(wrap_t) X(wrap_r) X(priority) X(footprint_budget) X(footprint_snap) \
    X(base_level) X(max_level) X(min_lod) X(max_lod) X(lod_bias) X(generate_mipmap) \
    X(depth_mode) X(compare_mode) X(compare_func)

static void params_save(const fs_tex_object *t, fs_tex_params *p)
{
#define FS_SAVE(f) p->f = t->f;
    FS_TEX_PARAM_FIELDS(FS_SAVE)
#undef FS_SAVE
    memcpy(p->border, t->border, sizeof p->border);
}

/* Stored as they were saved, without glTexParameter's checks and counting
 * (they passed them when set). */
static void params_restore(fs_tex_object *t, const fs_tex_params *p)
{
#define FS_RESTORE(f) t->f = p->f;
    FS_TEX_PARAM_FIELDS(FS_RESTORE)
#undef FS_RESTORE
    memcpy(t->border, p->border, sizeof t->border);
    t->complete = -1; /* completeness depends on the min filter (3.8.10) */
}

void fs_texture_attrib_save(const fs_context *c, fs_texture_attrib *a)
{
    const struct fs_texture_state *s = c->texture;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        const fs_tex_unit *tu = &s->unit[u];
        for (int k = 0; k < FS_TEX_TARGETS; k++) {
            a->unit[u].binding[k] = tu->bound[k]->name;
            params_save(tu->bound[k], &a->unit[u].bound[k]);
        }
        a->unit[u].env = tu->env;
    }
    for (int k = 0; k < FS_TEX_TARGETS; k++)
        params_save(&s->default_obj[k], &a->defaults[k]);
}

void fs_texture_attrib_restore(fs_context *c, const fs_texture_attrib *a)
{
    struct fs_texture_state *s = c->texture;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        fs_tex_unit *tu = &s->unit[u];
        for (int k = 0; k < FS_TEX_TARGETS; k++) {
            bind(c, u, (enum fs_tex_target)k, a->unit[u].binding[k]);
            if (tu->bound[k] != &s->default_obj[k])
                params_restore(tu->bound[k], &a->unit[u].bound[k]);
        }
        tu->env = a->unit[u].env;
    }
    for (int k = 0; k < FS_TEX_TARGETS; k++)
        params_restore(&s->default_obj[k], &a->defaults[k]);
    fs_texture_enables_changed(c); /* the restored parameters decide tex_pair_lod */
}

/* ---- queries (GL 1.5 spec 6.1.3 texture queries, 6.1.4 GetTexImage) ----
 * Colours and the priority come out of the integer forms as normalized
 * integers (6.1.2), as Mesa returns them. */

GLuint fs_texture_binding_2d(const fs_context *c) { return fs_tex_bound_2d(c)->name; }

GLuint fs_texture_binding(const fs_context *c, GLenum target)
{
    fs_tex_target_info ti;
    return fs_tex_target_of(target, &ti) && !ti.proxy ? fs_tex_active(c)->bound[ti.k]->name : 0;
}

GLuint fs_tex_object_name(const fs_tex_object *t) { return t->name; }

bool fs_tex_level_size(const fs_tex_object *t, int level, int *width, int *height)
{
    bool stored = level >= 0 && level < FS_TEX_MAX_LEVELS;
    *width = stored ? t->level[level].width : 0;
    *height = stored ? t->level[level].height : 0;
    return stored && level >= t->first_level && level <= t->last_level && *width > 0 && *height > 0;
}

/* A texture target the queries accept (a proxy only where proxy_ok); sets
 * GL_INVALID_ENUM and returns false otherwise. */
static bool query_target_ok(fs_context *c, GLenum target, bool proxy_ok, bool image, fs_tex_target_info *ti)
{
    /* image: the image queries, which name a cube map's faces (3.8.6). */
    if ((image ? fs_tex_image_target_of(target, ti) : fs_tex_target_of(target, ti)) && (proxy_ok || !ti->proxy))
        return true;
    fs_error(c, GL_INVALID_ENUM);
    return false;
}

/* One texture parameter as the queries return it: up to 4 values, whether
 * they are normalized (colours, the priority), and for the level-of-detail
 * values their integer form, which is not a truncation (texture_lod.c). */
typedef struct tex_param_value {
    float v[4];
    bool norm, has_int;
    GLint i;
} tex_param_value;

/* Returns how many values (1 or 4) were written, 0 for an unknown name. */
static int tex_parameter_value(const fs_tex_object *t, GLenum pname, tex_param_value *p)
{
    float *v = p->v;
    p->norm = p->has_int = false;
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER: v[0] = (float)t->min_filter; return 1;
    case GL_TEXTURE_MAG_FILTER: v[0] = (float)t->mag_filter; return 1;
    case GL_TEXTURE_WRAP_S: v[0] = (float)t->wrap_s; return 1;
    case GL_TEXTURE_WRAP_T: v[0] = (float)t->wrap_t; return 1;
    case GL_TEXTURE_WRAP_R: v[0] = (float)t->wrap_r; return 1;
    case GL_TEXTURE_BORDER_COLOR: memcpy(v, t->border, 4 * sizeof *v); p->norm = true; return 4;
    case GL_TEXTURE_PRIORITY: v[0] = t->priority; p->norm = true; return 1;
    case GL_TEXTURE_SWIZZLE_R: case GL_TEXTURE_SWIZZLE_G: case GL_TEXTURE_SWIZZLE_B: case GL_TEXTURE_SWIZZLE_A:
        v[0] = (float)t->swizzle[pname - GL_TEXTURE_SWIZZLE_R];
        return 1;
    case GL_TEXTURE_SWIZZLE_RGBA:
        for (int k = 0; k < 4; k++)
            v[k] = (float)t->swizzle[k];
        return 4;
    /* 3.8.12: a texture of the model is always resident. */
    case GL_TEXTURE_RESIDENT: v[0] = 1.0f; return 1;
    /* GL_FRAGSIM_footprint_filter */
    case GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM: v[0] = (float)t->footprint_budget; return 1;
    case GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM: v[0] = (float)t->footprint_snap; return 1;
    default:
        if (fs_tex_depth_parameter_value(t, pname, v))
            return 1;
        p->has_int = fs_tex_lod_value(t, pname, v, &p->i) != 0;
        return p->has_int ? 1 : 0;
    }
}

static int get_tex_parameter(fs_context *c, GLenum target, GLenum pname, tex_param_value *p)
{
    fs_tex_target_info ti;
    if (!query_target_ok(c, target, false, false, &ti))
        return 0;
    int n = tex_parameter_value(fs_tex_active(c)->bound[ti.k], pname, p);
    if (n == 0)
        fs_error(c, GL_INVALID_ENUM);
    return n;
}

void fs_exec_GetTexParameterfv(fs_context *c, GLenum target, GLenum pname, GLfloat *params)
{
    tex_param_value p;
    int n = get_tex_parameter(c, target, pname, &p);
    memcpy(params, p.v, (size_t)n * sizeof *p.v);
}

void fs_exec_GetTexParameteriv(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    tex_param_value p;
    int n = get_tex_parameter(c, target, pname, &p);
    for (int k = 0; k < n; k++)
        params[k] = p.has_int ? p.i : p.norm ? fs_norm_to_int(p.v[k]) : (GLint)p.v[k];
}

/* Bits of a component pname of an image: those of the format llvmpipe
 * stores its internal format in (table 6.18, units/texel_format.c), -1
 * for a name that is not a component size. */
static int component_bits(const fs_tex_image *img, GLenum pname)
{
    enum fs_texel_comp k;
    switch (pname) {
    case GL_TEXTURE_RED_SIZE: k = FS_TC_RED; break;
    case GL_TEXTURE_GREEN_SIZE: k = FS_TC_GREEN; break;
    case GL_TEXTURE_BLUE_SIZE: k = FS_TC_BLUE; break;
    case GL_TEXTURE_ALPHA_SIZE: k = FS_TC_ALPHA; break;
    case GL_TEXTURE_LUMINANCE_SIZE: k = FS_TC_LUMINANCE; break;
    case GL_TEXTURE_INTENSITY_SIZE: k = FS_TC_INTENSITY; break;
    case GL_TEXTURE_DEPTH_SIZE: return img->texels || img->described ? img->depth_bits : 0;
    default: return -1;
    }
    return img->texels || img->described ? fs_texel_bits(img->internal_format, img->base_format, k) : 0;
}

/* One level parameter (table 6.18); false for an unknown name.  An
 * undefined level reads as zero size with Mesa's internal format RGBA. */
static bool tex_level_value(const fs_tex_image *img, GLenum pname, GLint *v)
{
    bool defined = img && (img->texels || img->described);
    switch (pname) {
    case GL_TEXTURE_WIDTH: *v = defined ? img->width : 0; return true;
    case GL_TEXTURE_HEIGHT: *v = defined ? img->height : 0; return true;
    case GL_TEXTURE_DEPTH: *v = defined ? img->depth : 0; return true;
    case GL_TEXTURE_INTERNAL_FORMAT: *v = defined ? img->internal_format : GL_RGBA; return true;
    case GL_TEXTURE_BORDER: *v = defined ? img->border : 0; return true;
    case GL_TEXTURE_COMPRESSED: *v = defined && fs_tex_compressed_block_bytes(img->internal_format, NULL); return true;
    default: break;
    }
    static const fs_tex_image undefined;
    int bits = component_bits(defined ? img : &undefined, pname);
    if (bits < 0)
        return false;
    *v = bits;
    return true;
}

static bool get_tex_level(fs_context *c, GLenum target, GLint level, GLenum pname, GLint *v)
{
    fs_tex_target_info ti;
    if (!query_target_ok(c, target, true, true, &ti))
        return false;
    if (level < 0 || level > fs_tex_target_max_log2(ti.k)) {
        fs_error(c, GL_INVALID_VALUE);
        return false;
    }
    const fs_tex_image *img =
        ti.proxy ? &c->texture->proxy[ti.k][level] : &fs_tex_levels(fs_tex_active(c)->bound[ti.k], ti.face)[level];
    /* Table 6.18; INVALID_OPERATION for a level that is not compressed
     * and for a proxy (as OSMesa; GL 1.5 leaves it undefined). */
    if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE) {
        *v = ti.proxy ? 0 : (GLint)fs_tex_compressed_image_size(img);
        if (*v == 0)
            fs_error(c, GL_INVALID_OPERATION);
        return *v != 0;
    }
    if (!tex_level_value(img, pname, v)) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    return true;
}

void fs_exec_GetTexLevelParameteriv(fs_context *c, GLenum target, GLint level, GLenum pname, GLint *params)
{
    GLint v;
    if (get_tex_level(c, target, level, pname, &v))
        params[0] = v;
}

void fs_exec_GetTexLevelParameterfv(fs_context *c, GLenum target, GLint level, GLenum pname, GLfloat *params)
{
    GLint v;
    if (get_tex_level(c, target, level, pname, &v))
        params[0] = (GLfloat)v;
}

static int get_tex_env(fs_context *c, GLenum target, GLenum pname, float v[4])
{
    const fs_tex_env *s = &fs_tex_active(c)->env;
    if (target == GL_POINT_SPRITE) {
        if (pname != GL_COORD_REPLACE) {
            fs_error(c, GL_INVALID_ENUM);
            return 0;
        }
        v[0] = (c->raster.coord_replace >> fs_active_unit(c)) & 1u ? 1.0f : 0.0f;
        return 1;
    }
    if (target != GL_TEXTURE_ENV) {
        fs_error(c, GL_INVALID_ENUM);
        return 0;
    }
    if (pname == GL_TEXTURE_ENV_MODE) {
        v[0] = (float)s->mode;
        return 1;
    }
    if (pname == GL_TEXTURE_ENV_COLOR) {
        memcpy(v, s->color, 4 * sizeof *v);
        return 4;
    }
    if (fs_tex_combine_get(s, pname, v))
        return 1;
    fs_error(c, GL_INVALID_ENUM);
    return 0;
}

void fs_exec_GetTexEnvfv(fs_context *c, GLenum target, GLenum pname, GLfloat *params)
{
    float v[4];
    GLint iv;
    if (target == GL_TEXTURE_FILTER_CONTROL) {
        if (fs_tex_filter_control_value(c, pname, v, &iv))
            params[0] = v[0];
        return;
    }
    int n = get_tex_env(c, target, pname, v);
    memcpy(params, v, (size_t)n * sizeof *v);
}

void fs_exec_GetTexEnviv(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    float v[4];
    GLint iv;
    if (target == GL_TEXTURE_FILTER_CONTROL) {
        if (fs_tex_filter_control_value(c, pname, v, &iv))
            params[0] = iv;
        return;
    }
    int n = get_tex_env(c, target, pname, v);
    for (int k = 0; k < n; k++)
        params[k] = n == 4 ? fs_norm_to_int(v[k]) : (GLint)v[k];
}

GLboolean fs_exec_AreTexturesResident(fs_context *c, GLsizei n, const GLuint *textures, GLboolean *residences)
{
    /* 3.8.12: every texture is resident, so the answer is TRUE and
     * residences is left as it was; zero or unused names are an error. */
    (void)residences;
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return GL_FALSE;
    }
    for (GLsizei i = 0; i < n; i++) {
        if (textures[i] == 0 || !lookup(c->texture, textures[i], NULL)) {
            fs_error(c, GL_INVALID_VALUE);
            return GL_FALSE;
        }
    }
    return GL_TRUE;
}

void fs_exec_PrioritizeTextures(fs_context *c, GLsizei n, const GLuint *textures, const GLclampf *priorities)
{
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    /* 3.8.12: zero and unused names are ignored; priorities clamp to [0, 1]. */
    for (GLsizei i = 0; i < n; i++) {
        fs_tex_object *t = textures[i] ? lookup(c->texture, textures[i], NULL) : NULL;
        if (t)
            t->priority = priorities[i] < 0.0f ? 0.0f : priorities[i] > 1.0f ? 1.0f : priorities[i];
    }
}

/* The GL error of a GetTexImage format/type pair (6.1.4 with 3.6.4's rules
 * for packed types), GL_NO_ERROR when the pair is valid: colour formats only. */
static GLenum get_image_format_error(GLenum format, GLenum type)
{
    /* The pair first (3.6.4); then DEPTH_COMPONENT of a colour texture is
     * INVALID_OPERATION (6.1.4), and so is STENCIL_INDEX, as in Mesa.
     * COLOR_INDEX is INVALID_ENUM (Mesa 22 reports an internal error). */
    GLenum err = fs_pixel_check(format, type);
    if (err == GL_NO_ERROR && format == GL_COLOR_INDEX)
        err = GL_INVALID_ENUM;
    else if (err == GL_NO_ERROR && fs_pixel_format_kind(format) != FS_PIXEL_COLOR)
        err = GL_INVALID_OPERATION;
    return err;
}

/* The defined level glGetTexImage reads, NULL when there is none. */
static const fs_tex_image *get_image_level(fs_context *c, const fs_tex_target_info *ti, GLint level)
{
    if (ti->proxy || level < 0 || level >= FS_TEX_MAX_LEVELS)
        return NULL;
    const fs_tex_image *img = &fs_tex_levels(fs_tex_active(c)->bound[ti->k], ti->face)[level];
    return img->texels ? img : NULL;
}

int64_t fs_gettexImage_bytes(fs_context *c, GLenum target, GLint level, GLenum format, GLenum type)
{
    fs_tex_target_info ti;
    bool depth_ok = depth_data(format) && fs_pixel_check(format, type) == GL_NO_ERROR;
    if (!fs_tex_image_target_of(target, &ti) || (!depth_ok && get_image_format_error(format, type) != GL_NO_ERROR))
        return 0;
    const fs_tex_image *img = get_image_level(c, &ti, level);
    if (!img)
        return 0;
    /* The pack layout is glReadPixels' (4.3.2, 6.1.4), with the image
     * height and skipped images for a 3D image. */
    fs_pixel_store ps = fs_pixel_store_pack(c);
    return fs_pixel_image_bytes(&ps, ti.dims, img->width, img->height, img->depth, format, type);
}

/* A texel as GetTexImage sees it: table 6.1 assigns the base format's
 * components to R, G, B, A (luminance and intensity to R alone, a missing
 * alpha to 1), undoing the sampler's expansion of the stored texel. */
static void texel_for_get(const uint8_t *t, GLenum base, uint8_t out[4])
{
    out[0] = t[0];
    out[1] = t[1];
    out[2] = t[2];
    out[3] = t[3];
    switch (base) {
    case GL_LUMINANCE: case GL_INTENSITY: out[1] = out[2] = 0; out[3] = 255; break;
    case GL_LUMINANCE_ALPHA: out[1] = out[2] = 0; break;
    default: break;
    }
}

void fs_exec_GetTexImage(fs_context *c, GLenum target, GLint level, GLenum format, GLenum type, GLvoid *pixels)
{
    fs_tex_target_info ti;
    if (!query_target_ok(c, target, false, true, &ti))
        return;
    if (level < 0 || level > fs_tex_target_max_log2(ti.k)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    /* GL 1.4 6.1.4: DEPTH_COMPONENT reads a depth texture, and only a
     * depth texture is read as depth (INVALID_OPERATION otherwise). */
    const fs_tex_image *img = get_image_level(c, &ti, level);
    bool depth_image = img && img->base_format == GL_DEPTH_COMPONENT;
    GLenum err = depth_data(format) ? fs_pixel_check(format, type) : get_image_format_error(format, type);
    if (err == GL_NO_ERROR && img && depth_mismatch(depth_image, format))
        err = GL_INVALID_OPERATION;
    if (err == GL_NO_ERROR && !img && depth_data(format))
        err = GL_INVALID_OPERATION; /* no depth texture to read */
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    if (!img || !pixels)
        return; /* an undefined level writes nothing */
    if (depth_image && format == GL_DEPTH_STENCIL) { /* accepted by llvmpipe; the model keeps no stencil */
        fs_unsupported(c, "glGetTexImage(GL_DEPTH_STENCIL)");
        return;
    }
    if (depth_image) {
        fs_tex_depth_get_image(c, img, ti.dims, type, pixels);
        return;
    }
    fs_pixel_store ps = fs_pixel_store_pack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, ti.dims, img->width, img->height, img->depth, format, type))
        return; /* an image too large to address: nothing written */
    /* Luminance is R (6.1.4); Mesa packs a texture whose base format is
     * not RGBA through float, and luminance as GL_UNSIGNED_INT
     * (pixel_transfer.h). */
    unsigned flags = FS_PACK_LUMINANCE_UINT_FLOAT | (img->base_format != GL_RGBA ? FS_PACK_ROUND_PACKED : 0);
    uint8_t *row = malloc((size_t)img->width * 4);
    if (!row) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    /* Slice z of a 3D image is packed image_stride bytes after slice 0. */
    for (int z = 0; z < img->depth; z++)
        for (int y = 0; y < img->height; y++) {
            const uint8_t *src = texel_addr(img, 0, y, z);
            if (fs_tex_compressed_readback(img, y, z, row))
                src = row; /* texel_for_get converts in place */
            for (int x = 0; x < img->width; x++)
                texel_for_get(src + 4 * x, img->base_format, row + 4 * x);
            fs_pixel_pack_rgba8(&l, (uint8_t *)pixels + (size_t)z * (size_t)l.image_stride, y, 0, img->width, row,
                                flags);
        }
    free(row);
}
