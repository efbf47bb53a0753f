/*
 * Depth textures and ARB_shadow (GL 1.4 spec 3.8.1, 3.8.14), modelled on
 * Mesa 22.3 as OSMesa uses it (main/pack.c _mesa_unpack_depth_span,
 * main/texstore.c, gallivm lp_bld_sample_soa.c and lp_bld_conv.c; read for
 * the rules, not copied; tests/test_texture_depth.c compares with OSMesa):
 *
 * - Storage: DEPTH_COMPONENT16 at 16 bits, DEPTH_COMPONENT24 at 24 (Z24X8),
 *   DEPTH_COMPONENT32 at 32 (Z32_UNORM), ARB_depth_buffer_float's
 *   DEPTH_COMPONENT32F as a float (clamped to [0, 1] on upload, as
 *   measured; its reference not clamped); unsized DEPTH_COMPONENT at the
 *   size that matches the client type (measured: UNSIGNED_SHORT 16,
 *   UNSIGNED_INT 32, others 24).
 * - EXT_packed_depth_stencil's DEPTH_STENCIL and DEPTH24_STENCIL8 are
 *   stored at 24 bits, ARB_depth_buffer_float's DEPTH32F_STENCIL8 as a
 *   float; the stencil is not kept (GL 1.x samples the depth only).
 *   GL_DEPTH_STENCIL client data converts by ds_to_storage.
 * - Upload: a client type equal to the storage (UNSIGNED_SHORT into 16
 *   bits, UNSIGNED_INT into 32) is copied; UNSIGNED_INT into 16 bits keeps
 *   the top 16, UNSIGNED_SHORT into 32 repeats its 16 bits; everything else
 *   becomes a float (table 2.9 in float arithmetic), is scaled and biased
 *   (3.6.5), clamped to [0, 1] and truncated to the storage: f * (2^n - 1)
 *   in float for 16 and 24 bits, in double for 32.
 * - Sampling: llvmpipe never filters depth in its 8-bit path.  A texel
 *   reads as the float n / (2^n - 1) (a float product with the constant
 *   1 / (2^n - 1)) for 16 and 24 bits; a 32-bit one keeps its top 23 bits:
 *   (n >> 9) / 2^23 * (2^23 / (2^23 - 1)).
 * - glCopyTexImage copies a depth buffer of the same width; into 16 bits
 *   from 24 it rounds as llvmpipe's blit does (fs_tex_depth_store_copy).
 * - Comparison (3.8.14): the reference r (divided by q, as the coordinates
 *   are) is clamped to [0, 1], NaN to 0, and compared in float with each
 *   texel before filtering: LINEAR weights the four results (the
 *   "percentage closer" value), the MIPmap levels blend those.  A 1D
 *   texture compares with t, not r (fs_tex_depth_ref_coord).  The
 *   reference is not quantized to the texel format first (gallivm compares
 *   in float).
 * - The result (the depth, or the comparison's) becomes R, G, B, A by
 *   DEPTH_TEXTURE_MODE; the environment takes the mode as the base format.
 */
#include <math.h>
#include <string.h>
#include "texture_depth.h"
#include <GL/glext.h>
#include "texture_priv.h"
#include "../pipeline/context.h"
#include "../pipeline/pixel_map.h"
#include "../pipeline/pixel_transfer.h"

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

bool fs_tex_depth_format(GLint f)
{
    return f == GL_DEPTH_COMPONENT || f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 ||
           f == GL_DEPTH_COMPONENT32 || f == GL_DEPTH_COMPONENT32F || f == GL_DEPTH_STENCIL ||
           f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8;
}

int fs_tex_depth_bits(GLint f, GLenum type)
{
    switch (f) {
    case GL_DEPTH_COMPONENT16: return 16;
    case GL_DEPTH_COMPONENT24: return 24;
    case GL_DEPTH_COMPONENT32: case GL_DEPTH_COMPONENT32F: case GL_DEPTH32F_STENCIL8: return 32;
    /* Z24_UNORM_S8_UINT whatever the client type (measured: TEXTURE_DEPTH_SIZE
     * 24 for unsized DEPTH_STENCIL from FLOAT_32_UNSIGNED_INT_24_8_REV). */
    case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: return 24;
    case GL_DEPTH_COMPONENT: return type == GL_UNSIGNED_SHORT ? 16 : type == GL_UNSIGNED_INT ? 32 : 24;
    default: return 0;
    }
}

static inline float bits_to_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static void put_texel(uint8_t *texel, uint32_t v) { memcpy(texel, &v, 4); }

/* ARB_depth_buffer_float's DEPTH_COMPONENT32F, which llvmpipe offers: the
 * texel is the float itself (Z32_FLOAT). */
static bool float_image(const fs_tex_image *img)
{
    return img->internal_format == GL_DEPTH_COMPONENT32F || img->internal_format == GL_DEPTH32F_STENCIL8;
}

static uint32_t float_bits(float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    return v;
}

static uint32_t get_texel(const uint8_t *texel)
{
    uint32_t v;
    memcpy(&v, texel, 4);
    return v;
}

/* Table 2.9 in Mesa's float arithmetic; signed and float values may fall
 * outside [0, 1] (*clamp set). */
static float elem_to_float(uint32_t raw, GLenum type, bool *clamp)
{
    *clamp = false;
    switch (type) {
    case GL_UNSIGNED_BYTE: return (float)raw / 255.0f;
    case GL_UNSIGNED_SHORT: return (float)raw * (1.0f / 65535.0f);
    case GL_UNSIGNED_INT: return (float)((double)raw * (1.0 / 4294967295.0));
    case GL_BYTE: *clamp = true; return (2.0f * (float)(int8_t)raw + 1.0f) * (1.0f / 255.0f);
    case GL_SHORT: *clamp = true; return (2.0f * (float)(int16_t)raw + 1.0f) * (1.0f / 65535.0f);
    case GL_INT: *clamp = true; return (float)((double)(2.0f * (float)(int32_t)raw + 1.0f) * (1.0 / 4294967294.0));
    default: {
        float f;
        memcpy(&f, &raw, 4);
        *clamp = true;
        return f;
    }
    }
}

/* A float depth in [0, 1] to n-bit storage, truncated as Mesa stores it. */
static uint32_t float_to_storage(float f, int bits)
{
    if (!(f > 0.0f))
        return 0; /* 0 and NaN */
    if (bits == 32) {
        double z = (double)f * 4294967295.0;
        return z >= 4294967295.0 ? 0xffffffffu : (uint32_t)z;
    }
    float z = f * (float)((1u << bits) - 1u);
    return (uint32_t)z;
}

/* One client value to the storage of a bits-wide image (the rules at the
 * top of the file). */
static uint32_t client_to_storage(const fs_context *c, uint32_t raw, GLenum type, int bits, bool is_float)
{
    float scale = c->px.depth_scale, bias = c->px.depth_bias;
    bool identity = scale == 1.0f && bias == 0.0f;
    if (identity && !is_float) {
        if ((type == GL_UNSIGNED_SHORT && bits == 16) || (type == GL_UNSIGNED_INT && bits == 32))
            return raw;
        if (type == GL_UNSIGNED_INT && bits == 16)
            return raw >> 16;
        if (type == GL_UNSIGNED_SHORT && bits == 32)
            return raw | (raw << 16);
    }
    bool clamp;
    float f = elem_to_float(raw, type, &clamp);
    if (!identity) {
        f = f * scale + bias;
        clamp = true;
    }
    if (clamp) /* NaN to 0 (Mesa's CLAMP leaves it, and its conversion is undefined) */
        f = !(f > 0.0f) ? 0.0f : f > 1.0f ? 1.0f : f;
    return is_float ? float_bits(f) : float_to_storage(f, bits);
}

/* One DEPTH_STENCIL group's depth (fs_pixel_unpack_depth_stencil) to
 * the storage of a bits-wide image (measured through glGetTexImage on
 * OSMesa, tests/test_texture_depth.c): 24 bits into 24 bits is copied; a
 * 24-bit depth becomes the float product d * (float)(1 / (2^24 - 1))
 * (the double product is 1 ulp low for some), a float depth is clamped to
 * [0, 1] (NaN to 0), for the float formats too; the float is then stored
 * as an upload stores it (float_to_storage). */
static uint32_t ds_to_storage(uint32_t d, GLenum type, int bits, bool is_float)
{
    if (type == GL_UNSIGNED_INT_24_8 && bits == 24 && !is_float)
        return d;
    float f = type == GL_UNSIGNED_INT_24_8 ? (float)d * (float)(1.0 / 16777215.0) : bits_to_float(d);
    f = !(f > 0.0f) ? 0.0f : f > 1.0f ? 1.0f : f;
    return is_float ? float_bits(f) : float_to_storage(f, bits);
}

void fs_tex_depth_unpack(fs_context *c, fs_tex_image *img, int dims, const int off[3], int w, int h, int d,
                         GLenum format, GLenum type, const void *pixels)
{
    fs_pixel_store ps = fs_pixel_store_unpack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, dims, w, h, d, format, type))
        return;
    bool ds = format == GL_DEPTH_STENCIL;
    if (ds && (c->px.depth_scale != 1.0f || c->px.depth_bias != 0.0f))
        fs_unsupported(c, "glTexImage(GL_DEPTH_STENCIL) with depth scale or bias");
    for (int z = 0; z < d; z++)
        for (int y = 0; y < h; y++) {
            const uint8_t *src = (const uint8_t *)pixels + l.origin + z * l.image_stride + y * l.row_stride;
            uint8_t *dst = img->texels + (((size_t)(off[2] + z) * (size_t)img->height + (size_t)(off[1] + y)) *
                                              (size_t)img->width + (size_t)off[0]) * 4;
            for (int x = 0; x < w; x++, src += l.group_bytes) {
                uint32_t v;
                if (ds) {
                    fs_pixel_unpack_depth_stencil(&l, pixels, z, y, x, 1, &v, NULL);
                    v = ds_to_storage(v, type, img->depth_bits, float_image(img));
                } else {
                    v = client_to_storage(c, fs_pixel_load_elem(src, l.elem_bytes, l.swap_bytes), type,
                                          img->depth_bits, float_image(img));
                }
                put_texel(dst + 4 * x, v);
            }
        }
}

void fs_tex_depth_store_copy(fs_tex_image *img, uint8_t *texel, uint32_t z, int fb_bits)
{
    /* The same width is copied.  Into fewer bits llvmpipe blits: the
     * buffer's depth read as the sampler reads it, written to the narrower
     * format as a depth write rounds (f * (2^n - 1) rounded to even, in
     * float).  Into more bits (24 to 32) the float value stored as an
     * upload stores it (no pixel differs in the tests; not analysed further). */
    bool is_float = float_image(img);
    if (img->depth_bits == fb_bits && !is_float) {
        put_texel(texel, z);
        return;
    }
    fs_tex_image src = {.depth_bits = fb_bits};
    uint8_t raw[4];
    put_texel(raw, z);
    float f = fs_tex_depth_texel(&src, raw);
    if (is_float) /* the sampled float, written as it is */
        put_texel(texel, float_bits(f));
    else if (img->depth_bits < fb_bits)
        put_texel(texel, (uint32_t)nearbyintf(f * (float)((1u << img->depth_bits) - 1u)));
    else
        put_texel(texel, float_to_storage(f, img->depth_bits));
}

/* A stored depth as Mesa's format unpacking reads it for glGetTexImage:
 * n / (2^n - 1) in float for 16 bits, in double for 24 and 32. */
static float texel_for_get(const fs_tex_image *img, uint32_t v)
{
    if (float_image(img))
        return bits_to_float(v);
    if (img->depth_bits == 16)
        return (float)v * (1.0f / 65535.0f);
    return (float)((double)v / (double)((1ull << img->depth_bits) - 1u));
}

void fs_tex_depth_get_image(fs_context *c, const fs_tex_image *img, int dims, GLenum type, void *pixels)
{
    fs_pixel_store ps = fs_pixel_store_pack(c);
    fs_pixel_layout l;
    if (!fs_pixel_layout_init(&l, &ps, dims, img->width, img->height, img->depth, GL_DEPTH_COMPONENT, type))
        return;
    float scale = c->px.depth_scale, bias = c->px.depth_bias;
    bool counted = false;
    for (int z = 0; z < img->depth; z++)
        for (int y = 0; y < img->height; y++) {
            uint8_t *dst = (uint8_t *)pixels + l.origin + z * l.image_stride + y * l.row_stride;
            const uint8_t *src = img->texels + ((size_t)z * (size_t)img->height + (size_t)y) * (size_t)img->width * 4;
            for (int x = 0; x < img->width; x++, dst += l.group_bytes) {
                float f = texel_for_get(img, get_texel(src + 4 * x));
                if (scale != 1.0f || bias != 0.0f)
                    f = f * scale + bias;
                uint32_t v;
                switch (type) {
                case GL_FLOAT: memcpy(&v, &f, 4); break;
                /* The integer types as table 2.9 inverted, rounded; Mesa's
                 * exact rounding of each is not measured. */
                default: {
                    float cf = !(f > 0.0f) ? 0.0f : f > 1.0f ? 1.0f : f; /* NaN to 0 */
                    if (!counted)
                        fs_unsupported(c, "glGetTexImage(GL_DEPTH_COMPONENT) to an integer type (rounding not measured)");
                    counted = true;
                    double m = type == GL_UNSIGNED_BYTE ? 255.0 : type == GL_UNSIGNED_SHORT ? 65535.0
                             : type == GL_UNSIGNED_INT ? 4294967295.0 : type == GL_BYTE ? 127.0
                             : type == GL_SHORT ? 32767.0 : 2147483647.0;
                    v = (uint32_t)(int64_t)((double)cf * m + 0.5);
                    break;
                }
                }
                fs_pixel_store_elem(dst, l.elem_bytes, l.swap_bytes, v);
            }
        }
}


float fs_tex_depth_texel(const fs_tex_image *img, const uint8_t *texel)
{
    uint32_t v = get_texel(texel);
    if (float_image(img))
        return bits_to_float(v);
    if (img->depth_bits == 32) {
        /* More bits than a float's mantissa: the top 23 as a fraction of
         * 2^23 (through the bits of 1 + v / 2^23), scaled to reach 1. */
        float f = bits_to_float((v >> 9) | 0x3f800000u) - 1.0f;
        return f * (float)(8388608.0 / 8388607.0);
    }
    return (float)v * (float)(1.0 / (double)((1u << img->depth_bits) - 1u));
}

float fs_tex_depth_ref(const fs_tex_object *t, float r)
{
    /* A float depth format is not clamped (gallivm clamps the reference
     * for fixed-point formats only). */
    if (float_image(&t->level[t->first_level]))
        return r;
    return r > 0.0f ? (r < 1.0f ? r : 1.0f) : 0.0f;
}

float fs_tex_depth_filtered_value(const fs_tex_object *t, float ref, float d)
{
    if (t->compare_mode != GL_COMPARE_R_TO_TEXTURE)
        return d;
    bool pass;
    switch (t->compare_func) {
    case GL_NEVER: pass = false; break;
    case GL_LESS: pass = ref < d; break;
    case GL_EQUAL: pass = ref == d; break;
    case GL_LEQUAL: pass = ref <= d; break;
    case GL_GREATER: pass = ref > d; break;
    case GL_NOTEQUAL: pass = ref != d; break;
    case GL_GEQUAL: pass = ref >= d; break;
    default: pass = true; break; /* GL_ALWAYS */
    }
    return pass ? 1.0f : 0.0f;
}

void fs_tex_depth_mode_apply(const fs_tex_object *t, float rgba[4])
{
    float v = rgba[0];
    switch (t->depth_mode) {
    case GL_INTENSITY: rgba[0] = rgba[1] = rgba[2] = rgba[3] = v; break;
    case GL_ALPHA: rgba[0] = rgba[1] = rgba[2] = 0.0f; rgba[3] = v; break;
    case GL_RED: rgba[0] = v; rgba[1] = rgba[2] = 0.0f; rgba[3] = 1.0f; break;
    default: rgba[0] = rgba[1] = rgba[2] = v; rgba[3] = 1.0f; break; /* LUMINANCE */
    }
}

GLenum fs_tex_depth_env_base(const fs_tex_object *t)
{
    /* ARB_texture_rg's RED takes the environment of RGB (texture_sample.c). */
    return t->depth_mode == GL_RED ? GL_RGB : t->depth_mode;
}

void fs_tex_depth_defaults(fs_tex_object *t)
{
    t->depth_mode = GL_LUMINANCE;
    t->compare_mode = GL_NONE;
    t->compare_func = GL_LEQUAL;
}

int fs_tex_depth_parameter(fs_tex_object *t, GLenum pname, GLenum e, GLenum *err)
{
    *err = GL_NO_ERROR;
    switch (pname) {
    case GL_DEPTH_TEXTURE_MODE:
        /* LUMINANCE, INTENSITY, ALPHA (3.8.4); Mesa with ARB_texture_rg
         * also takes RED (measured). */
        if (e == GL_LUMINANCE || e == GL_INTENSITY || e == GL_ALPHA || e == GL_RED)
            t->depth_mode = e;
        else
            *err = GL_INVALID_ENUM;
        return 1;
    case GL_TEXTURE_COMPARE_MODE:
        if (e == GL_NONE || e == GL_COMPARE_R_TO_TEXTURE)
            t->compare_mode = e;
        else
            *err = GL_INVALID_ENUM;
        return 1;
    case GL_TEXTURE_COMPARE_FUNC:
        if (e >= GL_NEVER && e <= GL_ALWAYS)
            t->compare_func = e;
        else
            *err = GL_INVALID_ENUM;
        return 1;
    default:
        return 0;
    }
}

int fs_tex_depth_parameter_value(const fs_tex_object *t, GLenum pname, float *v)
{
    switch (pname) {
    case GL_DEPTH_TEXTURE_MODE: *v = (float)t->depth_mode; return 1;
    case GL_TEXTURE_COMPARE_MODE: *v = (float)t->compare_mode; return 1;
    case GL_TEXTURE_COMPARE_FUNC: *v = (float)t->compare_func; return 1;
    default: return 0;
    }
}
