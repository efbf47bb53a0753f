/*
 * Pixel pack and unpack (GL 1.5 spec 3.6.4, 4.3.2, 6.1.4); see
 * pixel_transfer.h.  The conversions are the ones llvmpipe (Mesa 22.3)
 * applies, established through libOSMesa by tests/test_pixel_transfer.c:
 * integers between normalized widths convert in integers (narrowing
 * rounds to nearest, widening replicates the top bits), which for the
 * signed types is the GL 4.2 rule (negative values clamp to 0) rather than
 * table 2.9's (2c + 1) / (2^b - 1); floats round to nearest even.
 */
#include <math.h>
#include <string.h>
#include "pixel_transfer.h"
#include "context.h"

fs_pixel_store fs_pixel_store_unpack(const fs_context *c)
{
    return (fs_pixel_store){
        .alignment = c->unpack_alignment,
        .row_length = c->unpack_row_length,
        .image_height = c->unpack_image_height,
        .skip_pixels = c->unpack_skip_pixels,
        .skip_rows = c->unpack_skip_rows,
        .skip_images = c->unpack_skip_images,
        .swap_bytes = c->unpack_swap_bytes != 0,
        .lsb_first = c->unpack_lsb_first != 0,
    };
}

fs_pixel_store fs_pixel_store_pack(const fs_context *c)
{
    return (fs_pixel_store){
        .alignment = c->pack_alignment,
        .row_length = c->pack_row_length,
        .image_height = c->pack_image_height,
        .skip_pixels = c->pack_skip_pixels,
        .skip_rows = c->pack_skip_rows,
        .skip_images = c->pack_skip_images,
        .swap_bytes = c->pack_swap_bytes != 0,
        .lsb_first = c->pack_lsb_first != 0,
    };
}

void fs_pixel_store_set_unpack(fs_context *c, const fs_pixel_store *ps)
{
    c->unpack_alignment = ps->alignment;
    c->unpack_row_length = ps->row_length;
    c->unpack_image_height = ps->image_height;
    c->unpack_skip_pixels = ps->skip_pixels;
    c->unpack_skip_rows = ps->skip_rows;
    c->unpack_skip_images = ps->skip_images;
    c->unpack_swap_bytes = ps->swap_bytes;
    c->unpack_lsb_first = ps->lsb_first;
}

/* ---- formats and types (tables 3.5, 3.6, 3.8) ---- */

int fs_pixel_format_kind(GLenum format)
{
    switch (format) {
    case GL_COLOR_INDEX: return FS_PIXEL_COLOR_INDEX;
    case GL_STENCIL_INDEX: return FS_PIXEL_STENCIL;
    case GL_DEPTH_COMPONENT: return FS_PIXEL_DEPTH;
    case GL_DEPTH_STENCIL: return FS_PIXEL_DEPTH_STENCIL;
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA:
    case GL_RGB: case GL_BGR: case GL_RGBA: case GL_BGRA:
        return FS_PIXEL_COLOR;
    default: return 0;
    }
}

int fs_pixel_components(GLenum format)
{
    switch (format) {
    case GL_COLOR_INDEX: case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT:
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE:
        return 1;
    case GL_LUMINANCE_ALPHA: case GL_DEPTH_STENCIL: return 2;
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    default: return 0;
    }
}

/* A packed type's layout (table 3.8): its bytes, its components and their
 * bits in the order of the format's elements.  The first element sits in
 * the most significant bits, or for the _REV types in the least. */
typedef struct packed_type { int bytes, n, bits[4]; bool rev; } packed_type;

static packed_type packed_of(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: return (packed_type){1, 3, {3, 3, 2, 0}, false};
    case GL_UNSIGNED_BYTE_2_3_3_REV: return (packed_type){1, 3, {3, 3, 2, 0}, true};
    case GL_UNSIGNED_SHORT_5_6_5: return (packed_type){2, 3, {5, 6, 5, 0}, false};
    case GL_UNSIGNED_SHORT_5_6_5_REV: return (packed_type){2, 3, {5, 6, 5, 0}, true};
    case GL_UNSIGNED_SHORT_4_4_4_4: return (packed_type){2, 4, {4, 4, 4, 4}, false};
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return (packed_type){2, 4, {4, 4, 4, 4}, true};
    case GL_UNSIGNED_SHORT_5_5_5_1: return (packed_type){2, 4, {5, 5, 5, 1}, false};
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return (packed_type){2, 4, {5, 5, 5, 1}, true};
    case GL_UNSIGNED_INT_8_8_8_8: return (packed_type){4, 4, {8, 8, 8, 8}, false};
    case GL_UNSIGNED_INT_8_8_8_8_REV: return (packed_type){4, 4, {8, 8, 8, 8}, true};
    case GL_UNSIGNED_INT_10_10_10_2: return (packed_type){4, 4, {10, 10, 10, 2}, false};
    case GL_UNSIGNED_INT_2_10_10_10_REV: return (packed_type){4, 4, {10, 10, 10, 2}, true};
    /* EXT_packed_depth_stencil and ARB_depth_buffer_float (GL_DEPTH_STENCIL
     * only): depth in the top 24 bits, stencil in the low 8; or a float
     * depth word followed by a word with stencil in its low 8 bits. */
    case GL_UNSIGNED_INT_24_8: return (packed_type){4, 2, {24, 8, 0, 0}, false};
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: return (packed_type){8, 2, {32, 8, 0, 0}, true};
    default: return (packed_type){0, 0, {0, 0, 0, 0}, false};
    }
}

/* Bytes of one element of an unpacked type (table 3.5), 0 otherwise. */
static int elem_bytes(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
    }
}

GLenum fs_pixel_check(GLenum format, GLenum type)
{
    packed_type p = packed_of(type);
    if (fs_pixel_format_kind(format) == 0 || (p.bytes == 0 && elem_bytes(type) == 0 && type != GL_BITMAP))
        return GL_INVALID_ENUM;
    /* GL_DEPTH_STENCIL takes its two packed types only; any other type is
     * INVALID_ENUM (measured on OSMesa: UNSIGNED_INT, BYTE, BITMAP, 5_6_5),
     * and those types with another format INVALID_OPERATION. */
    if (format == GL_DEPTH_STENCIL && p.n != 2)
        return GL_INVALID_ENUM;
    if (type == GL_BITMAP)
        return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
    if (p.bytes) {
        bool ok = p.n == 2 ? format == GL_DEPTH_STENCIL
                : p.n == 3 ? format == GL_RGB : format == GL_RGBA || format == GL_BGRA;
        return ok ? GL_NO_ERROR : GL_INVALID_OPERATION;
    }
    return GL_NO_ERROR;
}

int fs_pixel_group_bytes(GLenum format, GLenum type)
{
    if (fs_pixel_check(format, type) != GL_NO_ERROR || type == GL_BITMAP)
        return 0;
    packed_type p = packed_of(type);
    return p.bytes ? p.bytes : fs_pixel_components(format) * elem_bytes(type);
}

/* ---- layout (3.6.4 "Unpacking", 4.3.2 "Placement in client memory") ---- */

bool fs_pixel_layout_init(fs_pixel_layout *l, const fs_pixel_store *ps, int dims, int64_t width, int64_t height,
                          int64_t depth, GLenum format, GLenum type)
{
    memset(l, 0, sizeof *l);
    if (fs_pixel_check(format, type) != GL_NO_ERROR || width < 0 || height < 0 || depth < 0)
        return false;
    int64_t a = ps->alignment == 1 || ps->alignment == 2 || ps->alignment == 8 ? ps->alignment : 4;
    /* Row length, skips and image height are never negative once
     * glPixelStore accepted them; a negative value is taken as 0. */
    int64_t len = ps->row_length > 0 ? ps->row_length : width;
    int64_t rows = dims == 3 && ps->image_height > 0 ? ps->image_height : height;
    int64_t sp = ps->skip_pixels > 0 ? ps->skip_pixels : 0, sr = ps->skip_rows > 0 ? ps->skip_rows : 0;
    int64_t si = dims == 3 && ps->skip_images > 0 ? ps->skip_images : 0;
    packed_type p = packed_of(type);
    l->format = format;
    l->type = type;
    l->comps = fs_pixel_components(format);
    l->width = width;
    l->height = height;
    l->depth = depth;
    l->lsb_first = ps->lsb_first;
    if (type == GL_BITMAP) {
        /* A row is ceil(len / 8) bytes padded to the alignment; skip pixels
         * count bits (3.6.4, "Unpacking of bitmaps"). */
        l->row_stride = ((len + 7) / 8 + a - 1) / a * a;
    } else {
        /* FLOAT_32_UNSIGNED_INT_24_8_REV is two 4-byte words (swapped as such). */
        l->elem_bytes = p.bytes ? (p.bytes > 4 ? 4 : p.bytes) : elem_bytes(type);
        l->group_bytes = p.bytes ? p.bytes : (int64_t)l->comps * l->elem_bytes;
        /* Swapping applies to elements of more than one byte (3.6.4 table 3.7). */
        l->swap_bytes = ps->swap_bytes && l->elem_bytes > 1;
        /* k = a/s * ceil(s n l / a) elements when s < a, else n l: in bytes
         * the row is padded to a multiple of the alignment either way (a
         * and s are powers of two). */
        l->row_stride = (len * l->group_bytes + a - 1) / a * a;
    }
    /* An image that would span more than 2^60 bytes (skips and row lengths
     * near 2^31 from a bad trace) is refused before any product can
     * overflow: nothing is read or written, and its byte count is 0. */
    double extent = ((double)si + (double)depth) * (double)rows * (double)l->row_stride +
                    ((double)sr + (double)height) * (double)l->row_stride +
                    ((double)sp + (double)width) * (double)(l->group_bytes ? l->group_bytes : 1);
    if (extent > 1152921504606846976.0) {
        memset(l, 0, sizeof *l);
        return false;
    }
    l->image_stride = l->row_stride * rows;
    if (type == GL_BITMAP)
        l->origin = (si * l->image_stride + sr * l->row_stride) * 8 + sp;
    else
        l->origin = si * l->image_stride + sr * l->row_stride + sp * l->group_bytes;
    return true;
}

int64_t fs_pixel_layout_bytes(const fs_pixel_layout *l)
{
    if (l->width <= 0 || l->height <= 0 || l->depth <= 0 || l->comps == 0)
        return 0;
    int64_t last_row = (l->depth - 1) * l->image_stride + (l->height - 1) * l->row_stride;
    if (l->type == GL_BITMAP)
        return (l->origin + last_row * 8 + l->width + 7) / 8;
    return l->origin + last_row + l->width * l->group_bytes;
}

int64_t fs_pixel_image_bytes(const fs_pixel_store *ps, int dims, int64_t width, int64_t height, int64_t depth,
                             GLenum format, GLenum type)
{
    fs_pixel_layout l;
    return fs_pixel_layout_init(&l, ps, dims, width, height, depth, format, type) ? fs_pixel_layout_bytes(&l) : 0;
}

static const uint8_t *group_at(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x)
{
    return (const uint8_t *)pixels + l->origin + z * l->image_stride + y * l->row_stride + x * l->group_bytes;
}

/* ---- element access ---- */

uint32_t fs_pixel_load_elem(const uint8_t *p, int bytes, bool swap)
{
    uint8_t b[4];
    memcpy(b, p, (size_t)bytes);
    if (swap)
        for (int i = 0; i < bytes / 2; i++) {
            uint8_t t = b[i];
            b[i] = b[bytes - 1 - i];
            b[bytes - 1 - i] = t;
        }
    if (bytes == 1)
        return b[0];
    if (bytes == 2) {
        uint16_t v;
        memcpy(&v, b, 2);
        return v;
    }
    uint32_t v;
    memcpy(&v, b, 4);
    return v;
}

void fs_pixel_store_elem(uint8_t *p, int bytes, bool swap, uint32_t v)
{
    uint8_t b[4];
    if (bytes == 1) {
        b[0] = (uint8_t)v;
    } else if (bytes == 2) {
        uint16_t h = (uint16_t)v;
        memcpy(b, &h, 2);
    } else {
        memcpy(b, &v, 4);
    }
    if (swap)
        for (int i = 0; i < bytes / 2; i++) {
            uint8_t t = b[i];
            b[i] = b[bytes - 1 - i];
            b[bytes - 1 - i] = t;
        }
    memcpy(p, b, (size_t)bytes);
}

/* ---- conversions between normalized widths ---- */

static uint32_t max_of(int bits) { return bits >= 32 ? 0xffffffffu : (1u << bits) - 1u; }

/* An unsigned normalized b-bit value as an 8-bit one: narrowing rounds to
 * nearest (x * 255 + half) / (2^b - 1); widening (the packed types) repeats
 * the top bits, which is the nearest value too. */
static uint8_t unorm_to_8(uint32_t x, int b)
{
    if (b == 8)
        return (uint8_t)x;
    if (b > 8)
        return (uint8_t)(((uint64_t)x * 255u + (max_of(b) >> 1)) / max_of(b));
    uint32_t v = x * (255u / max_of(b));
    if (8 % b)
        v += x >> (b - 8 % b);
    return (uint8_t)v;
}

/* An 8-bit unsigned normalized value as a b-bit one (2.14.9 eq. 2.3's
 * c = f * (2^b - 1) in integers): narrowing rounds to nearest; widening
 * multiplies by floor((2^b - 1) / 255) and fills the low bits with x's top
 * bits, which is exact for multiples of 8 and is how Mesa converts unorm8
 * storage, so 255 gives the largest value.  `round` asks for rounding to
 * nearest also when widening (up to 16 bits): Mesa goes through float for
 * textures whose base format is not RGBA, which differs for 10 bits. */
static uint32_t unorm8_to_bits(uint32_t x, int b, bool round)
{
    if (b <= 8 || (round && b <= 16))
        return (x * max_of(b) + 127u) / 255u;
    uint32_t v = x * (max_of(b) / 255u);
    if (b % 8)
        v += x >> (8 - b % 8);
    return v;
}

/* One element of an unpacked type to 8 bits (see the file comment). */
static uint8_t elem_to_8(uint32_t raw, GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return (uint8_t)raw;
    case GL_BYTE: return (int8_t)raw <= 0 ? 0 : unorm_to_8(raw, 7);
    case GL_UNSIGNED_SHORT: return unorm_to_8(raw, 16);
    case GL_SHORT: return (int16_t)raw <= 0 ? 0 : unorm_to_8(raw, 15);
    case GL_UNSIGNED_INT: return unorm_to_8(raw, 32);
    case GL_INT: return (int32_t)raw <= 0 ? 0 : unorm_to_8(raw, 31);
    default: {
        float f;
        memcpy(&f, &raw, 4);
        /* Clamped to [0, 1] (NaN to 0), then round to nearest even. */
        f = f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;
        return (uint8_t)lrintf(f * 255.0f);
    }
    }
}

/* An 8-bit value as one element of an unpacked type (4.3.2 "Final
 * conversion", table 4.7 as Mesa computes it).  Floats are x times the
 * float 1/255. */
static uint32_t elem_from_8(uint8_t x, GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return x;
    case GL_BYTE: return unorm8_to_bits(x, 7, false);
    case GL_UNSIGNED_SHORT: return unorm8_to_bits(x, 16, false);
    case GL_SHORT: return unorm8_to_bits(x, 15, false);
    case GL_UNSIGNED_INT: return unorm8_to_bits(x, 32, false);
    case GL_INT: return unorm8_to_bits(x, 31, false);
    default: {
        float f = (float)x * (1.0f / 255.0f);
        uint32_t v;
        memcpy(&v, &f, 4);
        return v;
    }
    }
}

/* A float in [0, 1] as one element of an unpacked type, as Mesa converts
 * floats: f * (2^b - 1) computed in float and rounded to nearest even,
 * the 32-bit types wrapping where that product reaches 2^32 (or 2^31),
 * so 1.0 reads as 0 (as INT_MIN for GL_INT). */
static uint32_t elem_from_float(float f, GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return (uint32_t)lrintf(f * 255.0f);
    case GL_BYTE: return (uint32_t)lrintf(f * 127.0f);
    case GL_UNSIGNED_SHORT: return (uint32_t)lrintf(f * 65535.0f);
    case GL_SHORT: return (uint32_t)lrintf(f * 32767.0f);
    case GL_UNSIGNED_INT: return (uint32_t)(uint64_t)llrintf(f * 4294967295.0f);
    case GL_INT: return (uint32_t)(uint64_t)llrintf(f * 2147483647.0f);
    default: {
        uint32_t v;
        memcpy(&v, &f, 4);
        return v;
    }
    }
}

/* The RGBA index of each element of a colour format, in order; L is R. */
static int format_order(GLenum format, int idx[4])
{
    switch (format) {
    case GL_RED: case GL_LUMINANCE: idx[0] = 0; return 1;
    case GL_GREEN: idx[0] = 1; return 1;
    case GL_BLUE: idx[0] = 2; return 1;
    case GL_ALPHA: idx[0] = 3; return 1;
    case GL_LUMINANCE_ALPHA: idx[0] = 0; idx[1] = 3; return 2;
    case GL_RGB: idx[0] = 0; idx[1] = 1; idx[2] = 2; return 3;
    case GL_BGR: idx[0] = 2; idx[1] = 1; idx[2] = 0; return 3;
    case GL_RGBA: idx[0] = 0; idx[1] = 1; idx[2] = 2; idx[3] = 3; return 4;
    case GL_BGRA: idx[0] = 2; idx[1] = 1; idx[2] = 0; idx[3] = 3; return 4;
    default: return 0;
    }
}

/* ---- unpacking ---- */

/* The elements of one group at src as raw values with their widths: a
 * packed type's components (bits[k] their bits), else the format's
 * elements of the type (bits[k] 0). */
static void decode_group(const fs_pixel_layout *l, const packed_type *p, int nc, const uint8_t *src, uint32_t raw[4],
                         int bits[4])
{
    if (p->bytes) {
        uint32_t w = fs_pixel_load_elem(src, p->bytes, l->swap_bytes);
        int shift = p->rev ? 0 : p->bytes * 8;
        for (int k = 0; k < p->n; k++) {
            int b = p->bits[k];
            if (!p->rev)
                shift -= b;
            raw[k] = (w >> shift) & max_of(b);
            bits[k] = b;
            if (p->rev)
                shift += b;
        }
        return;
    }
    for (int k = 0; k < nc; k++) {
        raw[k] = fs_pixel_load_elem(src + k * l->elem_bytes, l->elem_bytes, l->swap_bytes);
        bits[k] = 0;
    }
}

/* Walks the n groups of a colour image from group x0 of row y of image z,
 * calling put for each with the group's raw elements (see decode_group)
 * and the RGBA index of each element.  False for a format that is not a
 * colour format. */
typedef void (*put_group_fn)(const fs_pixel_layout *l, const uint32_t raw[4], const int bits[4], const int idx[4],
                             int nc, void *out, int64_t i);

static bool each_group(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0, int64_t n,
                       put_group_fn put, void *out)
{
    int idx[4];
    int nc = format_order(l->format, idx);
    if (nc == 0 || n <= 0)
        return false;
    const uint8_t *src = group_at(l, pixels, z, y, x0);
    packed_type p = packed_of(l->type);
    for (int64_t i = 0; i < n; i++, src += l->group_bytes) {
        uint32_t raw[4];
        int bits[4];
        decode_group(l, &p, nc, src, raw, bits);
        put(l, raw, bits, idx, nc, out, i);
    }
    return true;
}

static void put_rgba8(const fs_pixel_layout *l, const uint32_t raw[4], const int bits[4], const int idx[4], int nc,
                      void *out, int64_t i)
{
    uint8_t *rgba = (uint8_t *)out + 4 * i;
    rgba[0] = rgba[1] = rgba[2] = 0;
    rgba[3] = 255;
    for (int k = 0; k < nc; k++)
        rgba[idx[k]] = bits[k] ? unorm_to_8(raw[k], bits[k]) : elem_to_8(raw[k], l->type);
    if (l->format == GL_LUMINANCE || l->format == GL_LUMINANCE_ALPHA)
        rgba[1] = rgba[2] = rgba[0];
}

void fs_pixel_unpack_rgba8(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, uint8_t *rgba)
{
    if (l->format == GL_RGBA && l->type == GL_UNSIGNED_BYTE && n > 0) {
        memcpy(rgba, group_at(l, pixels, z, y, x0), (size_t)n * 4);
        return;
    }
    each_group(l, pixels, z, y, x0, n, put_rgba8, rgba);
}

/* One element of an unpacked type as a float: c times the float
 * 1 / (2^b - 1) for the unsigned types (table 2.9 as Mesa computes it;
 * measured: c / 255 differs from llvmpipe near ties), the signed ones c
 * times 1 / (2^(b-1) - 1) but at least -1 (GL 4.2's rule, which Mesa
 * applies); floats as they are. */
static float unorm_to_float(uint32_t raw, int b) { return (float)raw * (1.0f / (float)max_of(b)); }

static float snorm_to_float(int32_t raw, int b)
{
    float f = (float)raw * (1.0f / (float)max_of(b - 1));
    return f < -1.0f ? -1.0f : f;
}

static float elem_to_float(uint32_t raw, GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return unorm_to_float(raw, 8);
    case GL_BYTE: return snorm_to_float((int8_t)raw, 8);
    case GL_UNSIGNED_SHORT: return unorm_to_float(raw, 16);
    case GL_SHORT: return snorm_to_float((int16_t)raw, 16);
    case GL_UNSIGNED_INT: return unorm_to_float(raw, 32);
    case GL_INT: return snorm_to_float((int32_t)raw, 32);
    default: {
        float f;
        memcpy(&f, &raw, 4);
        return f;
    }
    }
}

static void put_rgbaf(const fs_pixel_layout *l, const uint32_t raw[4], const int bits[4], const int idx[4], int nc,
                      void *out, int64_t i)
{
    float *rgba = (float *)out + 4 * i;
    rgba[0] = rgba[1] = rgba[2] = 0.0f;
    rgba[3] = 1.0f;
    for (int k = 0; k < nc; k++)
        rgba[idx[k]] = bits[k] ? unorm_to_float(raw[k], bits[k]) : elem_to_float(raw[k], l->type);
    if (l->format == GL_LUMINANCE || l->format == GL_LUMINANCE_ALPHA)
        rgba[1] = rgba[2] = rgba[0];
}

void fs_pixel_unpack_rgbaf(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0, int64_t n,
                           float *rgba)
{
    each_group(l, pixels, z, y, x0, n, put_rgbaf, rgba);
}

void fs_pixel_unpack_index(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, uint32_t *index)
{
    if ((l->format != GL_STENCIL_INDEX && l->format != GL_COLOR_INDEX) || n <= 0)
        return;
    if (l->type == GL_BITMAP) {
        const uint8_t *base = pixels;
        int64_t bit = l->origin + (z * l->image_stride + y * l->row_stride) * 8 + x0;
        for (int64_t i = 0; i < n; i++, bit++) {
            int shift = l->lsb_first ? (int)(bit & 7) : 7 - (int)(bit & 7);
            index[i] = (base[bit >> 3] >> shift) & 1u;
        }
        return;
    }
    const uint8_t *src = group_at(l, pixels, z, y, x0);
    for (int64_t i = 0; i < n; i++, src += l->group_bytes) {
        uint32_t raw = fs_pixel_load_elem(src, l->elem_bytes, l->swap_bytes);
        switch (l->type) {
        case GL_BYTE: index[i] = (uint32_t)(int32_t)(int8_t)raw; break;
        case GL_SHORT: index[i] = (uint32_t)(int32_t)(int16_t)raw; break;
        case GL_FLOAT: {
            float f;
            memcpy(&f, &raw, 4);
            /* Truncated toward zero and taken modulo 2^32, so that a
             * negative index wraps (measured with COLOR_INDEX textures);
             * beyond 2^63 (and NaN) 0. */
            index[i] = f > -9.2e18f && f < 9.2e18f ? (uint32_t)(uint64_t)(int64_t)f : 0u;
            break;
        }
        default: index[i] = raw; break;
        }
    }
}

void fs_pixel_unpack_depth(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, float *depth)
{
    if (l->format != GL_DEPTH_COMPONENT || n <= 0)
        return;
    const uint8_t *src = group_at(l, pixels, z, y, x0);
    for (int64_t i = 0; i < n; i++, src += l->group_bytes) {
        uint32_t raw = fs_pixel_load_elem(src, l->elem_bytes, l->swap_bytes);
        double d;
        switch (l->type) {
        case GL_UNSIGNED_BYTE: d = raw / 255.0; break;
        case GL_UNSIGNED_SHORT: d = raw / 65535.0; break;
        case GL_UNSIGNED_INT: d = raw / 4294967295.0; break;
        case GL_BYTE: d = (2.0 * (int8_t)raw + 1.0) / 255.0; break;
        case GL_SHORT: d = (2.0 * (int16_t)raw + 1.0) / 65535.0; break;
        case GL_INT: d = (2.0 * (int32_t)raw + 1.0) / 4294967295.0; break;
        default: {
            float f;
            memcpy(&f, &raw, 4);
            d = f;
            break;
        }
        }
        depth[i] = d > 0.0 ? (d < 1.0 ? (float)d : 1.0f) : 0.0f; /* NaN to 0 */
    }
}

void fs_pixel_unpack_depth_stencil(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                                   int64_t n, uint32_t *depth, uint8_t *stencil)
{
    if (l->format != GL_DEPTH_STENCIL || n <= 0)
        return;
    const uint8_t *src = group_at(l, pixels, z, y, x0);
    bool f32 = l->type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
    for (int64_t i = 0; i < n; i++, src += l->group_bytes) {
        uint32_t w0 = fs_pixel_load_elem(src, 4, l->swap_bytes);
        uint32_t s = f32 ? fs_pixel_load_elem(src + 4, 4, l->swap_bytes) : w0;
        depth[i] = f32 ? w0 : w0 >> 8;
        if (stencil)
            stencil[i] = (uint8_t)s;
    }
}

/* ---- packing ---- */

static uint8_t *group_out(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x)
{
    return (uint8_t *)pixels + l->origin + y * l->row_stride + x * l->group_bytes;
}

void fs_pixel_pack_rgba8(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                         const uint8_t *rgba, unsigned flags)
{
    int idx[4];
    int nc = format_order(l->format, idx);
    if (nc == 0 || n <= 0)
        return;
    uint8_t *out = group_out(l, pixels, y, x0);
    if (l->format == GL_RGBA && l->type == GL_UNSIGNED_BYTE) {
        memcpy(out, rgba, (size_t)n * 4); /* the common case: no conversion */
        return;
    }
    packed_type p = packed_of(l->type);
    bool lum = l->format == GL_LUMINANCE || l->format == GL_LUMINANCE_ALPHA;
    bool lum_sum = (flags & FS_PACK_LUMINANCE_SUM) && lum;
    bool lum_float = (flags & FS_PACK_LUMINANCE_UINT_FLOAT) && lum && !lum_sum && l->type == GL_UNSIGNED_INT;
    bool round = (flags & FS_PACK_ROUND_PACKED) != 0;
    for (int64_t i = 0; i < n; i++, out += l->group_bytes, rgba += 4) {
        uint8_t px[4] = {rgba[0], rgba[1], rgba[2], rgba[3]};
        if (lum_sum) {
            /* L = R + G + B clamped to [0, 1] (4.3.2), summed in float as
             * Mesa does, and every element converted from float. */
            float f[2] = {px[0] * (1.0f / 255.0f) + px[1] * (1.0f / 255.0f) + px[2] * (1.0f / 255.0f),
                          px[3] * (1.0f / 255.0f)};
            f[0] = f[0] < 1.0f ? f[0] : 1.0f;
            for (int k = 0; k < nc; k++)
                fs_pixel_store_elem(out + k * l->elem_bytes, l->elem_bytes, l->swap_bytes, elem_from_float(f[k], l->type));
            continue;
        }
        if (lum_float) {
            float f[2] = {px[0] * (1.0f / 255.0f), px[3] * (1.0f / 255.0f)};
            for (int k = 0; k < nc; k++)
                fs_pixel_store_elem(out + k * l->elem_bytes, l->elem_bytes, l->swap_bytes, elem_from_float(f[k], l->type));
            continue;
        }
        if (p.bytes) {
            uint32_t w = 0;
            int shift = p.rev ? 0 : p.bytes * 8;
            for (int k = 0; k < p.n; k++) {
                int b = p.bits[k];
                if (!p.rev)
                    shift -= b;
                w |= unorm8_to_bits(px[idx[k]], b, round) << shift;
                if (p.rev)
                    shift += b;
            }
            fs_pixel_store_elem(out, p.bytes, l->swap_bytes, w);
            continue;
        }
        for (int k = 0; k < nc; k++)
            fs_pixel_store_elem(out + k * l->elem_bytes, l->elem_bytes, l->swap_bytes, elem_from_8(px[idx[k]], l->type));
    }
}

/* Depth in buffer units to GL_UNSIGNED_INT: Mesa replicates the top bits into
 * the low bits, so the largest value maps to 0xffffffff. */
static uint32_t depth_to_uint(uint32_t z, int bits)
{
    if (bits >= 32)
        return z;
    uint32_t v = z << (32 - bits);
    for (int b = bits; b < 32; b += bits)
        v |= (z << (32 - bits)) >> b;
    return v;
}

void fs_pixel_pack_depth(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                         const uint32_t *depth, int bits)
{
    if (l->format != GL_DEPTH_COMPONENT || n <= 0)
        return;
    uint8_t *out = group_out(l, pixels, y, x0);
    double dmax = (double)max_of(bits);
    for (int64_t i = 0; i < n; i++, out += l->group_bytes) {
        float f = (float)((double)depth[i] / dmax);
        uint32_t v;
        switch (l->type) {
        /* Mesa's exact path, which swapped bytes skip: that case goes
         * through the float value, truncated in double. */
        case GL_UNSIGNED_INT:
            v = l->swap_bytes ? (uint32_t)(4294967295.0 * (double)f) : depth_to_uint(depth[i], bits);
            break;
        /* The other types go through the float value, scaled and rounded
         * in float as Mesa packs them: the float rounding of f * 65535 can
         * reach a .5 tie that exact arithmetic would not. */
        case GL_UNSIGNED_SHORT: v = (uint32_t)lrintf(f * 65535.0f); break;
        /* The byte, short and int types truncate, and the signed ones
         * map 2c + 1 = f (2^b - 1) (table 2.9 inverted), as Mesa packs depth. */
        case GL_UNSIGNED_BYTE: v = (uint32_t)(int32_t)(f * 255.0f); break;
        case GL_BYTE: v = (uint32_t)(((int32_t)(255.0f * f) - 1) / 2); break;
        case GL_SHORT: v = (uint32_t)(((int32_t)(65535.0f * f) - 1) / 2); break;
        case GL_INT: v = (uint32_t)(int32_t)(2147483647.0 * (double)f); break;
        default: memcpy(&v, &f, 4); break;
        }
        fs_pixel_store_elem(out, l->elem_bytes, l->swap_bytes, v);
    }
}

void fs_pixel_pack_stencil(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                           const uint8_t *stencil)
{
    if (l->format != GL_STENCIL_INDEX || n <= 0)
        return;
    if (l->type == GL_BITMAP) {
        /* One bit per index, its least significant bit (4.3.2); bit 7 of a
         * byte first unless LSB first. */
        uint8_t *base = pixels;
        int64_t bit = l->origin + y * l->row_stride * 8 + x0;
        for (int64_t i = 0; i < n; i++, bit++) {
            uint8_t m = (uint8_t)(l->lsb_first ? 1u << (bit & 7) : 0x80u >> (bit & 7));
            if (stencil[i] & 1)
                base[bit >> 3] |= m;
            else
                base[bit >> 3] &= (uint8_t)~m;
        }
        return;
    }
    uint8_t *out = group_out(l, pixels, y, x0);
    for (int64_t i = 0; i < n; i++, out += l->group_bytes) {
        uint32_t v = stencil[i];
        /* Indices are written as integers (4.3.2); GL_BYTE keeps 7 bits,
         * as Mesa writes them. */
        if (l->type == GL_BYTE)
            v &= 0x7f;
        if (l->type == GL_FLOAT) {
            float f = (float)stencil[i];
            memcpy(&v, &f, 4);
        }
        fs_pixel_store_elem(out, l->elem_bytes, l->swap_bytes, v);
    }
}

void fs_pixel_pack_depth_stencil(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                                 const uint32_t *depth, int bits, const uint8_t *stencil)
{
    if (l->format != GL_DEPTH_STENCIL || n <= 0)
        return;
    uint8_t *out = group_out(l, pixels, y, x0);
    bool f32 = l->type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
    double dmax = (double)max_of(bits);
    for (int64_t i = 0; i < n; i++, out += l->group_bytes) {
        if (f32) {
            /* The depth as glReadPixels(GL_FLOAT) gives it; the second
             * word is the stencil index, its top 24 bits 0 (measured). */
            float f = (float)((double)depth[i] / dmax);
            uint32_t v;
            memcpy(&v, &f, 4);
            fs_pixel_store_elem(out, 4, l->swap_bytes, v);
            fs_pixel_store_elem(out + 4, 4, l->swap_bytes, stencil[i]);
            continue;
        }
        /* A 24-bit buffer's depth as it is; another width scaled to 24
         * bits by its top bits (depth_to_uint). */
        uint32_t d24 = bits == 24 ? depth[i] : depth_to_uint(depth[i], bits) >> 8;
        fs_pixel_store_elem(out, 4, l->swap_bytes, d24 << 8 | stencil[i]);
    }
}
