/*
 * The GL 1.2-1.4 level-of-detail state of a texture object: the level
 * range (TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, GL 1.5 spec 3.8.9-3.8.10),
 * the LOD clamps and bias (TEXTURE_MIN_LOD, TEXTURE_MAX_LOD,
 * TEXTURE_LOD_BIAS of the object and of the unit, 3.8.8) and automatic
 * MIPmap generation (GENERATE_MIPMAP, 3.8.8 "Automatic Mipmap
 * Generation").  How lambda uses them is in texture_sample.c (select_lod).
 *
 * Conversions and the generation filter were measured on OSMesa (llvmpipe,
 * Mesa 22.3; tests/test_texture_lod.c holds them):
 * - glTexParameterf of a level or GENERATE_MIPMAP rounds the float to the
 *   nearest integer (halves away from zero, saturated): 2.5 sets level 3,
 *   -0.7 is INVALID_VALUE, GENERATE_MIPMAP 0.3 is FALSE; glTexParameterfv
 *   truncates instead (-0.7 sets level 0, 1e10 is INVALID_VALUE).
 * - glGetTexParameteriv rounds MIN_LOD, MAX_LOD and LOD_BIAS the same way;
 *   glGetTexEnviv truncates the unit's bias (out of range: INT_MIN).
 * - A generated level is the previous level filtered 2x2 by two 8-bit
 *   lerps with weight 1/2 (rounded, along x first, then y): Mesa makes the
 *   levels by a blit that samples the previous level bilinearly half-way
 *   between texels, which llvmpipe's fixed-point path computes so
 *   (texture_sample.c, lerp8).  Each level comes from the one above it.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "texture_priv.h"
#include "../pipeline/context.h"

/* A float as an integer state value: nearest, halves away from zero,
 * saturated at the int range; NaN gives 0. */
static GLint round_saturate(float v)
{
    if (!(v == v))
        return 0;
    if (v >= 2147483647.0f)
        return INT_MAX;
    if (v <= -2147483648.0f)
        return INT_MIN;
    return (GLint)lroundf(v);
}

void fs_tex_lod_defaults(fs_tex_object *t)
{
    /* Table 6.17. */
    t->base_level = 0;
    t->max_level = 1000;
    t->min_lod = -1000.0f;
    t->max_lod = 1000.0f;
    t->lod_bias = 0.0f;
    t->generate_mipmap = false;
}

int fs_tex_lod_parameter(fs_tex_object *t, GLenum pname, float v, GLenum *err)
{
    *err = GL_NO_ERROR;
    switch (pname) {
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL: {
        /* 3.8.4: a negative level is INVALID_VALUE. */
        GLint l = round_saturate(v);
        if (l < 0) {
            *err = GL_INVALID_VALUE;
            return 1;
        }
        *(pname == GL_TEXTURE_BASE_LEVEL ? &t->base_level : &t->max_level) = l;
        t->complete = -1; /* the levels sampled change (3.8.10) */
        return 1;
    }
    case GL_TEXTURE_MIN_LOD: t->min_lod = v; return 1;
    case GL_TEXTURE_MAX_LOD: t->max_lod = v; return 1;
    case GL_TEXTURE_LOD_BIAS: t->lod_bias = v; return 1;
    case GL_GENERATE_MIPMAP: t->generate_mipmap = round_saturate(v) != 0; return 1;
    default: return 0;
    }
}

void fs_tex_lod_vector_form(GLenum pname, float *v)
{
    /* glTexParameterfv takes a level or GENERATE_MIPMAP truncated, as
     * cvttss2si (INT_MIN out of range: a negative level), where
     * glTexParameterf rounds (measured on OSMesa). */
    if (pname != GL_TEXTURE_BASE_LEVEL && pname != GL_TEXTURE_MAX_LEVEL && pname != GL_GENERATE_MIPMAP)
        return;
    *v = *v > -2147483649.0f && *v < 2147483648.0f ? truncf(*v) : -2147483648.0f;
}

int fs_tex_lod_value(const fs_tex_object *t, GLenum pname, float *v, GLint *iv)
{
    switch (pname) {
    case GL_TEXTURE_MIN_LOD: *v = t->min_lod; break;
    case GL_TEXTURE_MAX_LOD: *v = t->max_lod; break;
    case GL_TEXTURE_LOD_BIAS: *v = t->lod_bias; break;
    case GL_TEXTURE_BASE_LEVEL: *v = (float)t->base_level; *iv = t->base_level; return 1;
    case GL_TEXTURE_MAX_LEVEL: *v = (float)t->max_level; *iv = t->max_level; return 1;
    case GL_GENERATE_MIPMAP: *v = t->generate_mipmap ? 1.0f : 0.0f; *iv = t->generate_mipmap; return 1;
    default: return 0;
    }
    *iv = round_saturate(*v);
    return 1;
}

/* ---- the unit's bias (GL_TEXTURE_FILTER_CONTROL, 3.8.13) ---- */

float fs_tex_unit_lod_bias(const fs_context *c, int unit) { return c->texture->unit[unit].env.lod_bias; }

bool fs_tex_filter_control(fs_context *c, GLenum pname, float v)
{
    if (pname != GL_TEXTURE_LOD_BIAS) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    fs_tex_active(c)->env.lod_bias = v;
    return true;
}

bool fs_tex_filter_control_value(fs_context *c, GLenum pname, float *v, GLint *iv)
{
    if (pname != GL_TEXTURE_LOD_BIAS) {
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
    *v = fs_tex_active(c)->env.lod_bias;
    /* Truncated as cvttss2si does: INT_MIN out of range. */
    *iv = *v > -2147483649.0f && *v < 2147483648.0f ? (GLint)*v : INT_MIN;
    return true;
}

/* Mesa keeps a sampler's bias as a multiple of 1/256 in [-16, 16]
 * (GL_MAX_TEXTURE_LOD_BIAS), each of the object's and the unit's apart,
 * and llvmpipe adds their sum to lambda. */
static float quantize_bias(float b)
{
    if (!(b == b))
        return 0.0f;
    b = b < -16.0f ? -16.0f : b > 16.0f ? 16.0f : b;
    return roundf(b * 256.0f) / 256.0f;
}

void fs_tex_lod_params(const fs_tex_object *t, float unit_bias, fs_tex_lod *p)
{
    p->bias = quantize_bias(t->lod_bias) + quantize_bias(unit_bias);
    /* Mesa's sampler: MIN_LOD below 0 is 0 (lambda below 0 selects the
     * base level anyway). */
    float lo = t->min_lod > 0.0f ? t->min_lod : 0.0f, hi = t->max_lod;
    p->min_lod = lo;
    p->max_lod = hi;
    /* llvmpipe applies a limit only where it can matter: MIN_LOD above 0,
     * MAX_LOD below its 16 levels' last; equal limits fix lambda. */
    p->apply_min = lo > 0.0f;
    p->apply_max = hi < 15.0f;
    p->fixed = lo == hi;
}

/* ---- automatic MIPmap generation (3.8.8) ---- */

static inline int half8(int a, int b) { return (a + ((128 * (b - a) + 128) >> 8)) & 0xff; }

/* Level dst (w x h) from src (sw x sh), every texel the 2x2 (or 2x1 where
 * one side is 1) block above it. */
static void downsample(const fs_tex_image *src, fs_tex_image *dst)
{
    int sw = src->width, sh = src->height;
    for (int y = 0; y < dst->height; y++) {
        int y0 = 2 * y < sh ? 2 * y : sh - 1, y1 = 2 * y + 1 < sh ? 2 * y + 1 : sh - 1;
        for (int x = 0; x < dst->width; x++) {
            int x0 = 2 * x < sw ? 2 * x : sw - 1, x1 = 2 * x + 1 < sw ? 2 * x + 1 : sw - 1;
            const uint8_t *a = src->texels + ((size_t)y0 * (size_t)sw + (size_t)x0) * 4;
            const uint8_t *b = src->texels + ((size_t)y0 * (size_t)sw + (size_t)x1) * 4;
            const uint8_t *cc = src->texels + ((size_t)y1 * (size_t)sw + (size_t)x0) * 4;
            const uint8_t *d = src->texels + ((size_t)y1 * (size_t)sw + (size_t)x1) * 4;
            uint8_t *o = dst->texels + ((size_t)y * (size_t)dst->width + (size_t)x) * 4;
            for (int k = 0; k < 4; k++)
                o[k] = (uint8_t)half8(half8(a[k], b[k]), half8(cc[k], d[k]));
        }
    }
}

/* Whether Mesa can place the base image into a texture holding the whole
 * pyramid, without which it generates nothing (measured on OSMesa: a base
 * level above 0 whose image is one texel wide or high gets no levels;
 * Mesa guesses level 0's size from a level above 0 only when neither side
 * is 1, so another such level must be defined).  Not modelled: the other
 * cases where its storage decides (e.g. a level 0 defined before
 * GENERATE_MIPMAP was set does not help there). */
static bool base_fits_pyramid(const fs_tex_image *levels, int base)
{
    const fs_tex_image *b = &levels[base];
    if (base == 0 || (b->width > 1 && b->height > 1))
        return true;
    for (int l = 1; l < FS_TEX_MAX_LEVELS; l++)
        if (l != base && levels[l].texels && levels[l].width > 1 && levels[l].height > 1)
            return true;
    return false;
}

void fs_tex_image_changed(fs_context *c, fs_tex_object *t, int face, int level)
{
    /* Generation follows a change of the base level's image only, and
     * fills the levels up to MAX_LEVEL or 1x1 (as Mesa: none when the base
     * level is MAX_LEVEL). */
    if (!t->generate_mipmap || t->mpgrid || level != t->base_level || level >= t->max_level)
        return;
    /* A cube map face regenerates its own levels (3.8.8). */
    fs_tex_image *levels = fs_tex_levels(t, face);
    const fs_tex_image *b = &levels[level];
    if (!b->texels || !base_fits_pyramid(levels, level))
        return;
    if (b->depth > 1) {
        fs_unsupported(c, "GL_GENERATE_MIPMAP on a 3D texture");
        return;
    }
    if (fs_tex_compressed_block_bytes(b->internal_format, NULL)) {
        /* llvmpipe decodes, filters and compresses each level again
         * (units/texture_compressed.c); not modelled. */
        fs_unsupported(c, "GL_GENERATE_MIPMAP of a compressed texture (llvmpipe recompresses the levels)");
        return;
    }
    if (b->base_format == GL_DEPTH_COMPONENT) {
        /* Depth texels are not RGBA8 (units/texture_depth.h). */
        fs_unsupported(c, "GL_GENERATE_MIPMAP on a depth texture");
        return;
    }
    /* The generated levels keep 8-bit texels only (no fs_tex_image.wide,
     * as before it existed); above 8 bits that is visibly not llvmpipe's. */
    if (b->wide && (b->wide_bits[0] > 8 || b->wide_bits[3] > 8))
        fs_unsupported(c, "GL_GENERATE_MIPMAP on a texture stored above 8 bits");
    int w = b->width, h = b->height;
    for (int l = level + 1; l < FS_TEX_MAX_LEVELS && l <= t->max_level && (w > 1 || h > 1); l++) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        fs_tex_image *img = &levels[l];
        uint8_t *texels = calloc((size_t)w * (size_t)h, 4);
        if (!texels) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        fs_tex_image_free(img);
        img->texels = texels;
        img->width = w;
        img->height = h;
        img->depth = 1;
        img->internal_format = b->internal_format;
        img->base_format = b->base_format;
        downsample(&levels[l - 1], img);
    }
    t->complete = -1;
}
