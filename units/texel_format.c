/*
 * The precision llvmpipe stores each internal format at.  GL 1.5 spec
 * 3.8.1: the GL may choose any internal resolution for a sized internal
 * format; the reference is Mesa llvmpipe, whose choices were measured
 * through OSMesa (glGetTexLevelParameter sizes, glGetTexImage of an
 * uploaded ramp; tests/test_texel_format.c checks them):
 *
 *   RGB4 4/4/4, RGB5 5/5/5, R3_G3_B2 3/3/2, RGBA2 and RGBA4 4/4/4/4,
 *   RGB5_A1 5/5/5/1, LUMINANCE4_ALPHA4 4/4; ALPHA4, LUMINANCE4,
 *   INTENSITY4, LUMINANCE6_ALPHA2 at 8 bits; RGB10 and RGB10_A2 at
 *   10 (and 2); the 12- and 16-bit formats at 16.
 *
 * Upload rounds an 8-bit value to the nearest n-bit one (q = round(v (2^n
 * - 1) / 255), no ties occur for n < 8), integer data of other types
 * through 8 bits first, float data from its floats (fs_texel_from_float);
 * readback and the fixed-point sampler expand q by repeating its bits
 * (5 bits: 3 -> 24, 4 -> 33, as measured; not round(q 255 / 31), which
 * gives 25 and 33); the float sampler reads q / (2^n - 1) (texture_priv.h
 * fs_tex_image.wide).
 */
#include "texel_format.h"
#include <math.h>
#include <stdbool.h>
#include <GL/glext.h>

/* Bits of R, G, B, A (the colour formats) or of L and A (the luminance
 * formats) for the formats llvmpipe stores below 8 bits; false for the
 * others. */
static bool low_bits(GLint f, int rgba[4])
{
    int r = 0, g = 0, b = 0, a = 0;
    switch (f) {
    case GL_RGB4: r = g = b = 4; break;
    case GL_RGB5: r = g = b = 5; break;
    case GL_R3_G3_B2: r = g = 3; b = 2; break;
    case GL_RGBA2: case GL_RGBA4: r = g = b = a = 4; break;
    case GL_RGB5_A1: r = g = b = 5; a = 1; break;
    case GL_LUMINANCE4_ALPHA4: r = g = b = a = 4; break; /* L is stored in R, G, B */
    case GL_RGB10_A2: r = g = b = 8; a = 2; break;     /* 10 bits keep an 8-bit value exactly */
    default: return false;
    }
    rgba[0] = r;
    rgba[1] = g;
    rgba[2] = b;
    rgba[3] = a;
    return true;
}

/* Bits of every component of the formats stored above 8 bits, 8 for the
 * others. */
/* The normalized formats among them: 10 or 16 bits; 8 for the others. */
static int unorm_wide_bits(GLint f)
{
    switch (f) {
    case GL_RGB10: case GL_RGB10_A2: return 10;
    case GL_RGB12: case GL_RGB16: case GL_RGBA12: case GL_RGBA16: case GL_ALPHA12: case GL_ALPHA16:
    case GL_LUMINANCE12: case GL_LUMINANCE16: case GL_INTENSITY12: case GL_INTENSITY16:
    case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12: case GL_LUMINANCE16_ALPHA16: case GL_R16:
    case GL_RG16:
        return 16;
    default: return 8;
    }
}

static int wide_bits(GLint f)
{
    if (unorm_wide_bits(f) != 8)
        return unorm_wide_bits(f);
    switch (f) {
    /* ARB_texture_float's sizes (GL_TEXTURE_*_SIZE; the model keeps 8 bits). */
    case GL_ALPHA16F_ARB: case GL_LUMINANCE16F_ARB: case GL_LUMINANCE_ALPHA16F_ARB: case GL_INTENSITY16F_ARB:
    case GL_R16F: case GL_RG16F: case GL_RGB16F: case GL_RGBA16F:
        return 16;
    case GL_ALPHA32F_ARB: case GL_LUMINANCE32F_ARB: case GL_LUMINANCE_ALPHA32F_ARB: case GL_INTENSITY32F_ARB:
    case GL_R32F: case GL_RG32F: case GL_RGB32F: case GL_RGBA32F:
        return 32;
    default: return 8;
    }
}

int fs_texel_bits(GLint f, GLenum base, enum fs_texel_comp k)
{
    bool rgb = base == GL_RGB || base == GL_RGBA;
    bool has;
    switch (k) {
    case FS_TC_RED: has = rgb || base == GL_RED || base == GL_RG; break;
    case FS_TC_GREEN: has = rgb || base == GL_RG; break;
    case FS_TC_BLUE: has = rgb; break;
    case FS_TC_ALPHA: has = base == GL_ALPHA || base == GL_LUMINANCE_ALPHA || base == GL_RGBA; break;
    case FS_TC_LUMINANCE: has = base == GL_LUMINANCE || base == GL_LUMINANCE_ALPHA; break;
    case FS_TC_INTENSITY: has = base == GL_INTENSITY; break;
    default: has = false; break;
    }
    if (!has)
        return 0;
    /* The S3TC formats (units/texture_compressed.c) report 4 bits for each
     * component they have (measured through OSMesa; their texels are kept
     * decoded at 8 bits). */
    if (f >= GL_COMPRESSED_RGB_S3TC_DXT1_EXT && f <= GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
        return 4;
    int lb[4];
    if (f != GL_RGB10_A2 && low_bits(f, lb)) {
        if (k == FS_TC_ALPHA)
            return lb[3];
        return lb[k == FS_TC_LUMINANCE ? 0 : (int)k];
    }
    /* RGB10_A2 keeps 2 bits of alpha (GL_UNSIGNED_INT_2_10_10_10_REV). */
    if (f == GL_RGB10_A2 && k == FS_TC_ALPHA)
        return 2;
    return wide_bits(f);
}

/* An n-bit value (n < 8) as 8 bits by repeating its bits. */
static uint8_t expand_bits(unsigned q, int n)
{
    unsigned out = 0;
    for (int shift = 8 - n; shift > -n; shift -= n)
        out |= shift >= 0 ? q << shift : q >> -shift;
    return (uint8_t)out;
}

/* v (8 bits) to the nearest n-bit value (or its top n bits: truncate)
 * and back by repeating its bits. */
static uint8_t requantize(uint8_t v, int n, bool truncate)
{
    unsigned max = (1u << n) - 1;
    return expand_bits(truncate ? (unsigned)v >> (8 - n) : ((unsigned)v * max + 127) / 255, n);
}

bool fs_texel_float_bits(GLint f, int bits[4])
{
    int lb[4];
    const int w = unorm_wide_bits(f); /* the float formats are kept at 8 bits */
    if (low_bits(f, lb)) {
        for (int k = 0; k < 4; k++) /* RGB10_A2: 10 bits of colour from floats */
            bits[k] = lb[k] == 8 && w > 8 ? w : lb[k];
        return true;
    }
    for (int k = 0; k < 4; k++)
        bits[k] = w;
    return w != 8;
}

/* llvmpipe rounds a float to n bits as floor(f (2^n - 1) + 1/2), the
 * product in float: 0.3f * 15 is 4.5 there and gives 5, 0.3f * 65535
 * gives 19661 (measured through OSMesa on 16,384 random and near-tie
 * values per format, RGBA4, RGBA2, RGB5, RGB10, RGBA16: 0 differ; the
 * product in double differs in 110-2972, ties to even in 222-3091).  A
 * value above 8 bits is kept as the nearest 8-bit one (no ties occur for
 * 10 and 16 bits), which is what sampling and readback give of it. */
void fs_texel_from_float(const void *bits_arg, const float *f, size_t n, uint8_t *out)
{
    const int *bits = bits_arg;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 4; k++) {
            const float v = f[4 * i + k] > 0.0f ? (f[4 * i + k] < 1.0f ? f[4 * i + k] : 1.0f) : 0.0f; /* NaN: 0 */
            const int nb = bits[k];
            uint8_t *o = &out[4 * i + k];
            if (nb <= 0 || nb == 8) {
                *o = (uint8_t)lrintf(v * 255.0f); /* ties to even, as the 8-bit formats */
                continue;
            }
            const unsigned max = (1u << nb) - 1;
            const unsigned q = (unsigned)floorf(v * (float)max + 0.5f);
            *o = nb < 8 ? expand_bits(q, nb) : (uint8_t)((q * 510u + max) / (2u * max));
        }
}

void fs_texel_quantize(GLint f, uint8_t *rgba, size_t n, bool copy)
{
    int bits[4];
    if (!low_bits(f, bits))
        return;
    /* glCopyTexImage into the 5-, 3- and 2-bit formats keeps the top bits
     * of the framebuffer's 8 (measured: 13 -> 8 in RGB5, 23 -> 0 in
     * R3_G3_B2); into the 4-bit ones it rounds as an upload does.
     * R3_G3_B2 follows neither rule: a copy rounds as an upload does, but
     * from the values with their low bits cleared, red and green to 5 bits
     * and blue to 6 (measured through OSMesa: glCopyTexImage2D of 4096
     * pixels of every value, glGetTexImage; 0 of 12288 values differ, 2496
     * with truncation, 832 with plain rounding). */
    bool r332 = copy && f == GL_R3_G3_B2;
    bool truncate = copy && (f == GL_RGB5 || f == GL_RGB5_A1);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 4; k++)
            if (bits[k] > 0 && bits[k] < 8) {
                uint8_t v = rgba[4 * i + k];
                if (r332)
                    v = (uint8_t)(v & (k == 2 ? 0xfc : 0xf8));
                rgba[4 * i + k] = requantize(v, bits[k], truncate);
            }
}

bool fs_texel_wide_bits(GLint f, int bits[4])
{
    const int w = unorm_wide_bits(f);
    for (int k = 0; k < 4; k++)
        bits[k] = w;
    if (f == GL_RGB10_A2) /* GL_UNSIGNED_INT_2_10_10_10_REV's 2 alpha bits */
        bits[3] = 2;
    return w != 8;
}

/* A byte into 10 or 16 bits repeats its bits (measured through OSMesa,
 * glGetTexImage as GL_FLOAT of RGB10 after GL_UNSIGNED_BYTE data: 0 of 768
 * values differ; rounding v (2^n - 1) / 255 differs in 101: Mesa widens
 * the 8-bit values, it does not go through float); into fewer bits
 * (RGB10_A2's alpha) it rounds (0 of 256 differ). */
unsigned fs_texel_wide_from8(unsigned v, int n)
{
    if (n < 8)
        return (v * ((1u << n) - 1u) + 127u) / 255u;
    unsigned q = v << (n - 8);
    return q | (v >> (16 - n));
}

/* The floats round as into the other formats not stored at 8 bits,
 * floor(f (2^n - 1) + 1/2) in float (fs_texel_from_float; measured through
 * OSMesa glGetTexImage as GL_FLOAT, which gives q / (2^n - 1) exactly, for
 * each of the 15 formats: 0 of 1024 values differ, GL_FLOAT and
 * GL_UNSIGNED_SHORT data; tests/test_texture_wide.c samples them). */
void fs_texel_wide_from_float(const int bits[4], const float *f, size_t n, bool bytes, uint16_t *out)
{
    for (size_t i = 0; i < 4 * n; i++) {
        const float v = f[i] > 0.0f ? (f[i] < 1.0f ? f[i] : 1.0f) : 0.0f; /* NaN: 0 */
        const int nb = bits[i % 4];
        out[i] = (uint16_t)(bytes ? fs_texel_wide_from8((unsigned)lrintf(v * 255.0f), nb)
                                  : (unsigned)floorf(v * (float)((1u << nb) - 1u) + 0.5f));
    }
}
