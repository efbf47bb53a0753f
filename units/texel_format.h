/*
 * Texel formats: the precision llvmpipe gives each internal format
 * (units/texel_format.c).  The model keeps every texel as RGBA8
 * (texture_priv.h); a format stored at fewer bits is requantized to them.
 */
#ifndef FS_TEXEL_FORMAT_H
#define FS_TEXEL_FORMAT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>

/* Components of the stored format, as glGetTexLevelParameter reports
 * them (table 6.18). */
enum fs_texel_comp { FS_TC_RED, FS_TC_GREEN, FS_TC_BLUE, FS_TC_ALPHA, FS_TC_LUMINANCE, FS_TC_INTENSITY, FS_TC_COUNT };

/* Bits of component k in the format llvmpipe stores internalformat in
 * (base is its base internal format); 0 for a component it has not. */
int fs_texel_bits(GLint internalformat, GLenum base, enum fs_texel_comp k);

/* Rounds n RGBA8 texels (expanded as texture_priv.h says) to the
 * precision of internalformat and back to 8 bits; nothing for a format
 * stored at 8 bits or more.  copy: the texels come from glCopyTexImage,
 * which llvmpipe converts differently for some formats. */
void fs_texel_quantize(GLint internalformat, uint8_t *rgba, size_t n, bool copy);

/* For a format llvmpipe stores at other than 8 bits in some component:
 * true, with the bits of R, G, B, A (0: none) for fs_texel_from_float. */
bool fs_texel_float_bits(GLint internalformat, int bits[4]);
/* n RGBA float texels (after unpacking and transfer) rounded to the bits
 * (an int[4] from fs_texel_float_bits) as llvmpipe rounds them at upload,
 * kept as RGBA8 (texture_priv.h). */
void fs_texel_from_float(const void *bits, const float *f, size_t n, uint8_t *out);

/* For a format llvmpipe stores above 8 bits and filters in float (RGB10,
 * RGB10_A2, the 12- and 16-bit normalized formats): true, with the bits it
 * keeps of R, G, B, A (of the RGBA group, before the base format's
 * expansion).  False for the others. */
bool fs_texel_wide_bits(GLint internalformat, int bits[4]);
/* n RGBA float groups (after unpacking and transfer) as the values such a
 * format stores (bits from fs_texel_wide_bits), RGBA per group; bytes: the
 * groups came from GL_UNSIGNED_BYTE data without transfer operations. */
void fs_texel_wide_from_float(const int bits[4], const float *f, size_t n, bool bytes, uint16_t *out);
/* An 8-bit value v as an n-bit one as llvmpipe stores a byte (see there). */
unsigned fs_texel_wide_from8(unsigned v, int n);
/* A stored value q of n bits as the sampler's float (n 0: q is the
 * constant itself), as gallivm converts a normalized channel: q times
 * 1 / (2^n - 1) in float. */
static inline float fs_texel_wide_float(unsigned q, int n)
{
    return n ? (float)q * (1.0f / (float)((1u << n) - 1u)) : (float)q;
}
#endif
