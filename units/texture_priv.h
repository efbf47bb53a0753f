/*
 * Private to the texture unit (texture_object.c, texture_sample.c): the
 * texture objects and the unit's state.
 */
#ifndef FS_TEXTURE_PRIV_H
#define FS_TEXTURE_PRIV_H
#include <stddef.h>
#include <stdlib.h>
#include "texture_unit.h"
#include "../pipeline/context.h"

/* One image (a MIPmap level).  Texels are stored as RGBA8 already expanded
 * the way the sampler reads them (llvmpipe's sampler-view swizzle, GL 1.5
 * spec table 3.21): LUMINANCE as (L,L,L,1), ALPHA as (0,0,0,A),
 * INTENSITY as (I,I,I,I), RGB as (R,G,B,1).  The base format is kept for
 * the texture environment, whose functions depend on it (table 3.22). */
typedef struct fs_tex_image {
    int width, height;          /* 0: the level is not defined */
    int depth;                  /* 1 for 1D and 2D images; a 3D image's slices follow each other */
    GLint internal_format;      /* as given (for the completeness rule) */
    GLenum base_format;         /* GL_RGBA, GL_RGB, GL_LUMINANCE, ... */
    uint8_t *texels;            /* width*height*depth*4 bytes, row 0 = t near 0, slice 0 = r near 0 */
    /* A proxy level (3.8.11) has no texels: described tells that its
     * state is set, border is the one given (images keep none). */
    bool described;
    int border;
    /* A level given by glCompressedTexImage (3.8.3): its blocks as given,
     * for glGetCompressedTexImage; NULL otherwise (texture_compressed.c). */
    uint8_t *compressed;
    size_t compressed_size;
    /* A DEPTH_COMPONENT image (base_format GL_DEPTH_COMPONENT) keeps one
     * uint32 depth of depth_bits bits per texel (units/texture_depth.h). */
    int depth_bits;
    /* A format llvmpipe stores at other than 8 bits (RGB10, RGB10_A2, the
     * 12- and 16-bit normalized ones, RGB5, RGBA4, R3_G3_B2 ...;
     * units/texel_format.c fs_texel_float_bits) also keeps each texel as
     * stored: 4 values per texel beside texels[] (same order, same
     * expansion), component k an unsigned value of wide_bits[k] bits, or
     * for wide_bits[k] 0 the constant 0 or 1 of the expansion.  The float
     * sampler reads these as q / (2^n - 1), as gallivm converts them (a
     * format above 8 bits is always filtered in float); texels[] holds the
     * 8-bit values the fixed-point sampler and the other readers use.
     * NULL for the formats stored at 8 bits. */
    uint16_t *wide;
    uint8_t wide_bits[4];
} fs_tex_image;

/* Frees an image's texels (both copies) and blocks, leaving it undefined. */
static inline void fs_tex_image_free(fs_tex_image *img)
{
    free(img->texels);
    free(img->wide);
    free(img->compressed);
    img->texels = NULL;
    img->wide = NULL;
    img->compressed = NULL;
    img->compressed_size = 0;
}
/* Sets the stored values of n texels from texel i on of a wide image
 * (fs_tex_image.wide) from its 8-bit texels (texture_object.c). */
void fs_tex_wide_from_texels(fs_tex_image *img, size_t i, size_t n);

/* The texture targets as indices into a unit's bindings and enables and
 * the default objects (GL 1.5 spec 3.8.12: each target has its own texture
 * 0).  A new target is one more name here and in units/texture_target.c. */
/* FS_TEX_RECT: ARB_texture_rectangle (GL 3.1 core), one level of any size,
 * sampled at unnormalized coordinates (texture_sample.c). */
enum fs_tex_target { FS_TEX_2D, FS_TEX_1D, FS_TEX_3D, FS_TEX_CUBE, FS_TEX_RECT, FS_TEX_TARGETS };
/* A cube map's faces (3.8.6): GL_TEXTURE_CUBE_MAP_POSITIVE_X + face. */
#define FS_TEX_FACES 6
_Static_assert(FS_TEX_TARGETS == FS_TEX_TARGET_COUNT, "texture_unit.h counts the targets");

typedef struct fs_tex_object {
    GLuint name;
    bool bound_once;            /* has been bound: its target is fixed (3.8.12) */
    enum fs_tex_target target;  /* the target of the first bind (texture_target.c) */
    GLenum min_filter, mag_filter, wrap_s, wrap_t;
    GLenum wrap_r;              /* GL 1.2 (3.8.4), sampled for 3D textures only */
    float border[4];
    float priority;
    /* EXT_texture_swizzle: the source of each of R, G, B, A (GL_RED..
     * GL_ALPHA, GL_ZERO, GL_ONE), applied to the filtered texel. */
    GLenum swizzle[4];
    /* GL_FRAGSIM_footprint_filter: the budget M and the corner snapping. */
    int footprint_budget;
    GLenum footprint_snap;
    /* GL 1.4 depth textures (3.8.4, 3.8.14; units/texture_depth.c). */
    GLenum depth_mode, compare_mode, compare_func;
    fs_tex_image level[FS_TEX_MAX_LEVELS];
    /* A cube map's faces 1..5 (NEGATIVE_X..NEGATIVE_Z); face 0
     * (POSITIVE_X) is level[] (fs_tex_levels). */
    fs_tex_image cube_face[FS_TEX_FACES - 1][FS_TEX_MAX_LEVELS];
    /* GL 1.2-1.4 level range, LOD clamps and bias, automatic MIPmaps
     * (3.8.8-3.8.10, table 6.17; units/texture_lod.c). */
    int base_level, max_level;
    float min_lod, max_lod, lod_bias;
    bool generate_mipmap;
    /* Completeness (3.8.10), recomputed when images, filters or the level
     * range change: -1 unknown, 0 incomplete, 1 complete.  first_level and
     * last_level are the lowest and highest levels sampling may use (the
     * base level and q of 3.8.10). */
    int complete;
    int first_level, last_level;
    /* GL_FRAGSIM_mp_grid: non-NULL for an MP-Grid texture, whose texels
     * come through the CTR (units/mpgrid_gl.h). */
    struct fs_mpgrid_tex *mpgrid;
} fs_tex_object;


/* units/texture_combine.c: the initial environment; glTexEnv of a
 * GL_COMBINE parameter (false: pname is none; *error GL_NO_ERROR or the
 * error, which leaves the parameter as it was) and glGetTexEnv of one
 * (false: pname is none). */
void fs_tex_env_init(fs_tex_env *e);
bool fs_tex_combine_set(fs_tex_env *e, GLenum pname, float value, GLenum *error);
bool fs_tex_combine_get(const fs_tex_env *e, GLenum pname, float *value);
/* What GL_COMBINE reads at one pixel: the combining unit, the units with a
 * texel (enabled, complete) and their texels, the fragment's colour before
 * texturing and the previous unit's result. */
typedef struct fs_combine_inputs {
    int unit;
    unsigned valid;
    const float (*texel)[4];
    const float *primary, *previous;
} fs_combine_inputs;
void fs_tex_combine(const fs_tex_env *e, const fs_combine_inputs *in, float out[4]);

/* One texture unit (2.7, 3.8.13): per target its enable and binding, its
 * environment.  Its coordinates and matrix stack are the vertex stage's
 * (pipeline/vertex_stage.h). */
typedef struct fs_tex_unit {
    bool enabled[FS_TEX_TARGETS];    /* glEnable(GL_TEXTURE_2D) on this unit */
    fs_tex_object *bound[FS_TEX_TARGETS];
    fs_tex_env env;
} fs_tex_unit;

struct fs_texture_state {
    fs_tex_object default_obj[FS_TEX_TARGETS]; /* texture object 0 of each target (3.8.12) */
    fs_tex_unit unit[FS_MAX_TEXTURE_UNITS];
    fs_tex_object **objects;    /* named objects, unordered */
    size_t count, cap;
    GLuint next_name;           /* where glGenTextures starts looking */
    uint64_t quads_sampled, quads_incomplete;
    /* Sampling takes the reference path only (fs_texture_set_generic);
     * quads_fast counts the quads that took the 8-bit quad path
     * (texture_sample.c). */
    bool generic;
    uint64_t quads_fast;
    /* The proxy targets' levels (3.8.11), by target: state only, no texels. */
    fs_tex_image proxy[FS_TEX_TARGETS][FS_TEX_MAX_LEVELS];
    /* Footprint filters (units/footprint.h) by M (8, 16, 32, 64), snapping
     * (integer, mid-point) and hybrid, created on first use: each holds
     * its weighting ROMs. */
    struct fs_footprint_filter *footprint[4][2][2];
};

/* The levels of face `face` of a cube map (0 for every other target). */
static inline fs_tex_image *fs_tex_levels(const fs_tex_object *t, int face)
{
    return face ? (fs_tex_image *)t->cube_face[face - 1] : (fs_tex_image *)t->level;
}

/* The active texture unit (glActiveTexture, 2.7), and its 2D texture. */
static inline fs_tex_unit *fs_tex_active(const fs_context *c) { return &c->texture->unit[fs_active_unit(c)]; }
static inline fs_tex_object *fs_tex_bound_2d(const fs_context *c) { return fs_tex_active(c)->bound[FS_TEX_2D]; }

/* ---- texture targets (units/texture_target.c) ---- */
/* What a GL target enum names: the target, whether it is the proxy, and
 * the image dimensions (1, 2, 3); false for an enum that names none. */
typedef struct fs_tex_target_info {
    enum fs_tex_target k;
    bool proxy;
    int dims;
    int face;   /* the cube map face an image target names, 0 otherwise */
} fs_tex_target_info;
/* The targets of glBindTexture, glEnable, glTexParameter (GL_TEXTURE_CUBE_MAP,
 * not its faces) and their proxies. */
bool fs_tex_target_of(GLenum target, fs_tex_target_info *ti);
/* The targets of the image commands and image queries: GL_TEXTURE_CUBE_MAP's
 * six faces instead of GL_TEXTURE_CUBE_MAP itself (3.8.1: it is
 * INVALID_ENUM for glTexImage2D), GL_PROXY_TEXTURE_CUBE_MAP kept. */
bool fs_tex_image_target_of(GLenum target, fs_tex_target_info *ti);
/* log2 of the largest image of a target (GL_MAX_TEXTURE_SIZE,
 * GL_MAX_3D_TEXTURE_SIZE as OSMesa reports them). */
int fs_tex_target_max_log2(enum fs_tex_target k);
int fs_tex_target_dims(enum fs_tex_target k);
/* The target a unit samples (3.8.15: cube map before 3D before 2D before 1D), -1 when no
 * target is enabled. */
int fs_tex_unit_target(const fs_tex_unit *tu);
/* The image commands of every target (texture_object.c): glTexImage*D,
 * glTexSubImage*D, glCopyTexImage*D, glCopyTexSubImage*D with the target
 * enum as given, dims the command's image dimensions; heights and depths
 * a command does not have are 1, offsets 0. */
void fs_tex_image_nd(fs_context *c, int dims, GLenum target, GLint level, GLint internalformat, GLsizei w, GLsizei h,
                     GLsizei d, GLint border, GLenum format, GLenum type, const GLvoid *pixels);
void fs_tex_subimage_nd(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3], GLsizei w,
                        GLsizei h, GLsizei d, GLenum format, GLenum type, const GLvoid *pixels);
void fs_tex_copy_image_nd(fs_context *c, int dims, GLenum target, GLint level, GLenum internalformat, GLint x,
                          GLint y, GLsizei w, GLsizei h, GLint border);
void fs_tex_copy_subimage_nd(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3], GLint x,
                             GLint y, GLsizei w, GLsizei h);

/* ---- compressed images (texture_compressed.c) ---- */
/* Bytes of a 4x4 block of a compressed internal format the model decodes
 * (and its base format in *base when not NULL); 0 for any other. */
int fs_tex_compressed_block_bytes(GLint internalformat, GLenum *base);
/* GL_TEXTURE_COMPRESSED_IMAGE_SIZE of a level (0: not compressed). */
int64_t fs_tex_compressed_image_size(const fs_tex_image *img);
/* Compression at upload (llvmpipe compresses what glTexImage,
 * glCopyTexImage and the sub-image commands store into a compressed
 * format): the block format a generic compressed internal format is
 * stored as on a 2D, cube map or 3D image (0: stored uncompressed); the
 * base format of a compressed format the model can encode (0: none);
 * encoding the blocks covering a box of the level's texels (x, y on the
 * 4x4 grid) and decoding them back into the texels, the blocks allocated
 * on first use (false: out of memory; true doing nothing for a level of
 * another format); whether a sub-image box is on the block grid. */
GLint fs_tex_generic_compressed_format(GLint f);
GLenum fs_tex_compressed_upload_base(GLint f);
bool fs_tex_compress_box(fs_tex_image *img, int x, int y, int z, int w, int h, int d);
bool fs_tex_compressed_box_aligned(const fs_tex_image *img, const GLint off[3], const GLsizei size[3]);
/* glGetTexImage's texels of row y of slice z when they are not the
 * sampler's (a LATC2 level, which Mesa decodes in software): true with
 * row filled (width texels, expanded as stored). */
bool fs_tex_compressed_readback(const fs_tex_image *img, int y, int z, uint8_t *row);
/* texture_encode.c: one RGTC / LATC channel block from v[4 j + i], the
 * nx x ny pixels inside the image. */
void fs_tex_encode_rgtc_channel(uint8_t blk[8], const uint8_t v[16], int nx, int ny);
/* DXT5's alpha block (as RGTC's channel but without its single-value
 * shortcut) and DXT3's; an S3TC colour block of px[4 j + i] (RGBA), the
 * nx x ny pixels inside the image: FS_DXT_RGB1 and FS_DXT_RGBA1 try
 * DXT1's three-colour mode (RGBA1 with punch-through alpha), FS_DXT_FOUR
 * (DXT3, DXT5) four colours only. */
enum { FS_DXT_RGB1, FS_DXT_RGBA1, FS_DXT_FOUR };
void fs_tex_encode_dxt5_alpha(uint8_t blk[8], const uint8_t v[16], int nx, int ny);
void fs_tex_encode_dxt3_alpha(uint8_t blk[8], const uint8_t px[16][4]);
void fs_tex_encode_dxt_colour(uint8_t blk[8], const uint8_t px[16][4], int nx, int ny, int mode);

/* ---- level of detail (texture_lod.c) ---- */
void fs_tex_lod_defaults(fs_tex_object *t);
/* glTexParameter of BASE_LEVEL, MAX_LEVEL, MIN_LOD, MAX_LOD, LOD_BIAS or
 * GENERATE_MIPMAP: 1 when pname is one of them (*err then says whether
 * the value was refused, nothing changed), 0 otherwise. */
int fs_tex_lod_parameter(fs_tex_object *t, GLenum pname, float v, GLenum *err);
/* glTexParameterfv's conversion of the value of pname (before
 * fs_tex_lod_parameter). */
void fs_tex_lod_vector_form(GLenum pname, float *v);
/* Their values for glGetTexParameterfv (v) and iv (iv); 0 for another pname. */
int fs_tex_lod_value(const fs_tex_object *t, GLenum pname, float *v, GLint *iv);
/* The texture unit's LOD bias (GL_TEXTURE_FILTER_CONTROL), behind an
 * accessor so per-unit state can move without touching the sampler; its
 * glTexEnv and glGetTexEnv (false: the error is set). */
float fs_tex_unit_lod_bias(const fs_context *c, int unit);
bool fs_tex_filter_control(fs_context *c, GLenum pname, float v);
bool fs_tex_filter_control_value(fs_context *c, GLenum pname, float *v, GLint *iv);
/* lambda's adjustments as llvmpipe's sampler takes them (3.8.8): the
 * summed bias, the clamps and which of them apply. */
typedef struct fs_tex_lod {
    float bias, min_lod, max_lod;
    bool apply_min, apply_max, fixed;
} fs_tex_lod;
void fs_tex_lod_params(const fs_tex_object *t, float unit_bias, fs_tex_lod *p);
/* After an image of `level` of t was specified or changed: GENERATE_MIPMAP's
 * regeneration of the levels below the base level. */
void fs_tex_image_changed(fs_context *c, fs_tex_object *t, int face, int level);
/* The wraps llvmpipe filters in 8-bit fixed point (gallivm
 * lp_is_simple_wrap_mode); the others take its float path. */
static inline bool fs_tex_simple_wrap(GLenum w) { return w == GL_REPEAT || w == GL_CLAMP_TO_EDGE; }
/* Whether every wrap of the dimensions a texture has is simple (gallivm
 * checks wrap t from 2D up and wrap r for 3D only). */
static inline bool fs_tex_simple_wraps(const fs_tex_object *t)
{
    if (t->target == FS_TEX_CUBE) /* sampled CLAMP_TO_EDGE (fs_tex_wrap_of) */
        return true;
    return fs_tex_simple_wrap(t->wrap_s) && (t->target == FS_TEX_1D || fs_tex_simple_wrap(t->wrap_t)) &&
           (t->target != FS_TEX_3D || fs_tex_simple_wrap(t->wrap_r));
}
/* The wrap a texture's axis (0 s, 1 t, 2 r) is sampled with: a cube map's
 * faces are clamped to their edges whatever the wraps (measured on
 * llvmpipe: REPEAT, CLAMP and MIRRORED_REPEAT give CLAMP_TO_EDGE's
 * texels; GL 1.5 leaves the wrap across a face edge to the wraps). */
static inline GLenum fs_tex_wrap_of(const fs_tex_object *t, int axis)
{
    return t->target == FS_TEX_CUBE ? GL_CLAMP_TO_EDGE : axis == 0 ? t->wrap_s : axis == 1 ? t->wrap_t : t->wrap_r;
}
/* Completeness of an object, cached (3.8.10). */
bool fs_tex_complete(fs_tex_object *t);
/* Whether sampling a quad with this texture depends on the quad sharing
 * llvmpipe's vector with it (fs_quad.tex_pair). */
bool fs_tex_pair_decides(const fs_tex_object *t);

/* The name of the bound 2D texture, for glGet(GL_TEXTURE_BINDING_2D)
 * (driver/gl_state.c). */
GLuint fs_texture_binding_2d(const fs_context *c);

/* For GL_FRAGSIM_mp_grid (units/mpgrid_gl.c): the base format of an
 * internalformat (0 if none), and a client image unpacked as glTexImage2D
 * does into w x h RGBA8 texels of base format `base` (dst NULL: only
 * checks).  Returns GL_NO_ERROR or glTexImage2D's error for format/type. */
GLenum fs_tex_base_format(GLint internalformat);
GLenum fs_tex_unpack_rgba8(fs_context *c, uint8_t *dst, int w, int h, GLenum base, GLenum format, GLenum type,
                           const void *pixels);
#endif
