/*
 * Compressed texture images (GL 1.5 spec 3.8.3, 6.1.4;
 * EXT_texture_compression_s3tc): glCompressedTexImage1D/2D/3D,
 * glCompressedTexSubImage1D/2D/3D and glGetCompressedTexImage.
 *
 * The four S3TC formats and RGTC1/RGTC2/LATC1/LATC2 are decoded at
 * upload into the level's RGBA8 texels (units/texture_priv.h), which the
 * sampler reads as it reads any other image; the blocks are kept as
 * given, for glGetCompressedTexImage and for sub-image updates.  The RGTC
 * and LATC formats are also what llvmpipe stores the generic
 * GL_COMPRESSED_RED, _RG, _LUMINANCE, _LUMINANCE_ALPHA as on 2D, cube map
 * and 3D images: the uncompressed upload paths (texture_object.c) store
 * the texels, then fs_tex_compress_box encodes the blocks as Mesa does
 * (texture_encode.c) and decodes them back into the texels.
 *
 * The decoding is llvmpipe's, which is what OSMesa samples (Mesa 22.3,
 * gallivm lp_bld_format_s3tc.c, read for its rules; measured through
 * OSMesa, tests/test_compressed_tex.c).  The S3TC spec leaves the
 * rounding of the interpolated colours open, and llvmpipe does not divide
 * by 3: with the 565 endpoints expanded to 8 bits by repeating their top
 * bits (c0, c1), colour 2 is c0 + floor(85 (c1 - c0) / 256) and colour 3
 * c0 + floor(170 (c1 - c0) / 256), per channel; DXT1's three-colour mode
 * (color0 <= color1 as 16-bit numbers) takes the average rounded up,
 * (c0 + c1 + 1) / 2, and code 3 is black, transparent for RGBA_DXT1 and
 * opaque for RGB_DXT1 (the spec's punch-through rule).  DXT3 alpha is a
 * 4-bit value a expanded to a * 17.  DXT5 alpha interpolates with
 * weights w = floor(k * 2331 / 64) (a0 > a1, k = code - 1 of 1..6) or
 * floor(k * 3264 / 64) (a0 <= a1, k of 1..4): a0 + floor((a1 - a0) w /
 * 256); codes 6 and 7 of the second mode are 0 and 255.
 *
 * Formats: OSMesa lists twelve (GL_COMPRESSED_TEXTURE_FORMATS: FXT1 RGB
 * and RGBA, S3TC DXT1/DXT3/DXT5, ETC2 and EAC).  The model decodes the
 * S3TC ones only; the others are refused with GL_INVALID_ENUM, as an
 * implementation that does not support a format must (3.8.3: "If
 * internalformat is not a supported compressed format"), and are not
 * listed: FXT1 and ETC2/EAC would each need their decoder matched bit for
 * bit against llvmpipe's, which is not done.  Like Mesa, the list leaves
 * out GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, whose punch-through makes it no
 * general-purpose format (ARB_texture_compression: the list holds the
 * formats "suitable for general-purpose usage"), though it is accepted.
 *
 * S3TC images are two-dimensional: glCompressedTexImage1D and 3D refuse
 * them (GL_INVALID_ENUM, as OSMesa: EXT_texture_compression_s3tc names
 * CompressedTexImage2D only).
 *
 * The S3TC formats named in glTexImage2D / glCopyTexImage2D, and the
 * generic GL_COMPRESSED_RGB / _RGBA (stored as DXT1 / DXT5 on 2D, cube
 * map and 3D images), are encoded as Mesa's S3TC encoder does
 * (texture_encode.c) and decoded back, as are sub-image updates of them.
 * Not modelled: GL_GENERATE_MIPMAP of a compressed level, counted as
 * unsupported (texture_lod.c).
 * docs/compressed_textures.md sums this up.
 */
#include <stdlib.h>
#include <string.h>
#include "texture_priv.h"
#include "../pipeline/context.h"
#include <GL/glext.h>

/* ---- formats ---- */

/* The bytes of one 4x4 block of a supported compressed internal format and
 * its base internal format; 0 for any other format. */
int fs_tex_compressed_block_bytes(GLint internalformat, GLenum *base)
{
    GLenum b;
    int n;
    switch (internalformat) {
    case GL_COMPRESSED_RGB_S3TC_DXT1_EXT: b = GL_RGB, n = 8; break;
    case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT: b = GL_RGBA, n = 8; break;
    case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT: b = GL_RGBA, n = 16; break;
    case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT: b = GL_RGBA, n = 16; break;
    /* RGTC (ARB_texture_compression_rgtc) and LATC
     * (EXT_texture_compression_latc): one (two) 8-byte channel blocks,
     * each coded as DXT5's alpha; what Mesa stores the generic
     * GL_COMPRESSED_RED, _RG, _LUMINANCE, _LUMINANCE_ALPHA as. */
    case GL_COMPRESSED_RED_RGTC1: b = GL_RED, n = 8; break;
    case GL_COMPRESSED_RG_RGTC2: b = GL_RG, n = 16; break;
    case GL_COMPRESSED_LUMINANCE_LATC1_EXT: b = GL_LUMINANCE, n = 8; break;
    case GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT: b = GL_LUMINANCE_ALPHA, n = 16; break;
    default: return 0;
    }
    if (base)
        *base = b;
    return n;
}

int fs_tex_compressed_formats(GLint *formats)
{
    /* GL_COMPRESSED_TEXTURE_FORMATS (table 6.30), as Mesa orders them
     * (RGBA_DXT1 left out, see the top of this file). */
    static const GLint list[] = {GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
                                 GL_COMPRESSED_RGBA_S3TC_DXT5_EXT};
    int n = (int)(sizeof list / sizeof list[0]);
    if (formats)
        memcpy(formats, list, sizeof list);
    return n;
}

/* Bytes of a w x h image of 4x4 blocks of `bytes` each (a partial block at
 * an edge is a whole block, EXT_texture_compression_s3tc). */
static int64_t blocks_size(int64_t w, int64_t h, int bytes) { return ((w + 3) / 4) * ((h + 3) / 4) * bytes; }

int64_t fs_tex_compressed_image_size(const fs_tex_image *img)
{
    int bytes = fs_tex_compressed_block_bytes(img->internal_format, NULL);
    if (!bytes || !(img->texels || img->described))
        return 0;
    return blocks_size(img->width, img->height, bytes) * (img->depth > 0 ? img->depth : 1);
}

/* ---- decoding (see the top of the file for the rules) ---- */

static void expand565(unsigned v, int rgb[3])
{
    unsigned r = (v >> 11) & 31, g = (v >> 5) & 63, b = v & 31;
    rgb[0] = (int)((r << 3) | (r >> 2));
    rgb[1] = (int)((g << 2) | (g >> 4));
    rgb[2] = (int)((b << 3) | (b >> 2));
}

/* floor(a / 256) for any sign (the arithmetic shift of gallivm's 16-bit
 * lanes, whose results are taken modulo 256 and stay in 0..255 here). */
static int floor256(int a) { return a >= 0 ? a / 256 : -((-a + 255) / 256); }

/* The four colours of a colour block (8 bytes); dxt1: DXT1's two modes
 * apply (DXT3 and DXT5 always use four colours). */
static void colour_table(const uint8_t *blk, bool dxt1, bool rgba_dxt1, uint8_t col[4][4])
{
    unsigned c0 = blk[0] | (unsigned)blk[1] << 8, c1 = blk[2] | (unsigned)blk[3] << 8;
    int e0[3], e1[3];
    expand565(c0, e0);
    expand565(c1, e1);
    bool four = !dxt1 || c0 > c1;
    for (int k = 0; k < 3; k++) {
        int d = e1[k] - e0[k];
        col[0][k] = (uint8_t)e0[k];
        col[1][k] = (uint8_t)e1[k];
        if (four) {
            col[2][k] = (uint8_t)(e0[k] + floor256(85 * d));
            col[3][k] = (uint8_t)(e0[k] + floor256(170 * d));
        } else {
            col[2][k] = (uint8_t)((e0[k] + e1[k] + 1) / 2);
            col[3][k] = 0;
        }
    }
    for (int i = 0; i < 4; i++)
        col[i][3] = 255;
    if (!four && rgba_dxt1)
        col[3][3] = 0;
}

/* The eight alpha values of a DXT5 alpha block (8 bytes). */
static void alpha_table(const uint8_t *blk, uint8_t a[8])
{
    int a0 = blk[0], a1 = blk[1];
    bool eight = a0 > a1;
    a[0] = (uint8_t)a0;
    a[1] = (uint8_t)a1;
    for (int code = 2; code < 8; code++) {
        int k = code - 1;
        int w = eight ? k * (255 * 64 / 7) / 64 : k * (255 * 64 / 5) / 64;
        a[code] = (uint8_t)(a0 + floor256((a1 - a0) * w));
    }
    if (!eight) {
        a[6] = 0;
        a[7] = 255;
    }
}

/* The sixteen values of a channel block (8 bytes: two endpoints, 3-bit
 * codes from bit 16): DXT5's alpha and each RGTC / LATC channel, which
 * llvmpipe decodes alike (gallivm lp_bld_format_s3tc.c decodes RGTC
 * through its DXT5 alpha channel). */
static void channel_values(const uint8_t *blk, uint8_t out[16])
{
    uint8_t a[8];
    alpha_table(blk, a);
    uint64_t bits = 0;
    for (int i = 7; i >= 2; i--)
        bits = bits << 8 | blk[i];
    for (int p = 0; p < 16; p++)
        out[p] = a[(bits >> (3 * p)) & 7];
}

/* Decodes one block of `fmt` into the texels of img at (x0, y0) of slice
 * z, the part of it inside the image, expanded as the sampler reads the
 * base format (fs_tex_image): RED (R,0,0,1), RG (R,G,0,1), LUMINANCE
 * (L,L,L,1), LUMINANCE_ALPHA (L,L,L,A). */
static void decode_block(GLint fmt, const uint8_t *blk, fs_tex_image *img, int x0, int y0, int z)
{
    uint8_t px[16][4], ch0[16], ch1[16];
    bool dxt1 = fmt == GL_COMPRESSED_RGB_S3TC_DXT1_EXT || fmt == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
    bool s3tc = dxt1 || fmt == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT || fmt == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    if (s3tc) {
        const uint8_t *cb = dxt1 ? blk : blk + 8;
        uint8_t col[4][4];
        colour_table(cb, dxt1, fmt == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, col);
        uint32_t codes = cb[4] | (uint32_t)cb[5] << 8 | (uint32_t)cb[6] << 16 | (uint32_t)cb[7] << 24;
        uint64_t abits = 0;
        for (int i = 7; i >= 0; i--)
            abits = abits << 8 | blk[i];
        if (fmt == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
            channel_values(blk, ch0);
        for (int p = 0; p < 16; p++) {
            memcpy(px[p], col[(codes >> (2 * p)) & 3], 4);
            if (fmt == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT)
                px[p][3] = (uint8_t)(((abits >> (4 * p)) & 15) * 17);
            else if (fmt == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
                px[p][3] = ch0[p];
        }
    } else {
        bool two = fs_tex_compressed_block_bytes(fmt, NULL) == 16;
        bool lum = fmt == GL_COMPRESSED_LUMINANCE_LATC1_EXT || fmt == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
        channel_values(blk, ch0);
        if (two)
            channel_values(blk + 8, ch1);
        for (int p = 0; p < 16; p++) {
            px[p][0] = ch0[p];
            px[p][1] = lum ? ch0[p] : two ? ch1[p] : 0;
            px[p][2] = lum ? ch0[p] : 0;
            px[p][3] = lum && two ? ch1[p] : 255;
        }
    }
    for (int j = 0; j < 4 && y0 + j < img->height; j++)
        for (int i = 0; i < 4 && x0 + i < img->width; i++) {
            uint8_t *t = img->texels +
                         (((size_t)z * (size_t)img->height + (size_t)(y0 + j)) * (size_t)img->width + (size_t)(x0 + i)) * 4;
            memcpy(t, px[4 * j + i], 4);
        }
}

/* Writes a w x h x d box of blocks at (x, y, z) (x and y multiples of 4)
 * into the level's stored blocks and decodes it into its texels. */
static void store_blocks(fs_tex_image *img, int x, int y, int z, int w, int h, int d, const uint8_t *data)
{
    int bytes = fs_tex_compressed_block_bytes(img->internal_format, NULL);
    int64_t bw = (img->width + 3) / 4, bh = (img->height + 3) / 4;
    int nx = (w + 3) / 4, ny = (h + 3) / 4;
    for (int k = 0; k < d; k++)
        for (int by = 0; by < ny; by++)
            for (int bx = 0; bx < nx; bx++) {
                const uint8_t *src = data + (((size_t)k * (size_t)ny + (size_t)by) * (size_t)nx + (size_t)bx) * (size_t)bytes;
                int64_t dst_block = ((int64_t)(z + k) * bh + y / 4 + by) * bw + x / 4 + bx;
                uint8_t *dst = img->compressed + dst_block * bytes;
                if (dst != src) /* a NULL image decodes the zeroed blocks in place */
                    memcpy(dst, src, (size_t)bytes);
                decode_block(img->internal_format, src, img, x + 4 * bx, y + 4 * by, z + k);
            }
}

/* ---- compression at upload (the encoders: texture_encode.c) ---- */

GLint fs_tex_generic_compressed_format(GLint f)
{
    /* What llvmpipe stores a generic compressed format (table 3.17) as on
     * a 2D, cube map or 3D image (measured through OSMesa:
     * GL_TEXTURE_INTERNAL_FORMAT and glGetCompressedTexImage). */
    switch (f) {
    case GL_COMPRESSED_RED: return GL_COMPRESSED_RED_RGTC1;
    case GL_COMPRESSED_RG: return GL_COMPRESSED_RG_RGTC2;
    case GL_COMPRESSED_LUMINANCE: return GL_COMPRESSED_LUMINANCE_LATC1_EXT;
    case GL_COMPRESSED_LUMINANCE_ALPHA: return GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
    case GL_COMPRESSED_RGB: return GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
    case GL_COMPRESSED_RGBA: return GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    default: return 0;
    }
}

GLenum fs_tex_compressed_upload_base(GLint f)
{
    GLenum base = 0;
    switch (f) {
    case GL_COMPRESSED_RED_RGTC1: case GL_COMPRESSED_RG_RGTC2: case GL_COMPRESSED_LUMINANCE_LATC1_EXT:
    case GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT:
    case GL_COMPRESSED_RGB_S3TC_DXT1_EXT: case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT:
    case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT: case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT:
        fs_tex_compressed_block_bytes(f, &base);
        return base;
    default:
        return 0;
    }
}

/* One block's channel c of the texels at (x0, y0) of slice z: component
 * `comp` of each texel inside the image, into v[4 j + i]. */
static void gather_channel(const fs_tex_image *img, int x0, int y0, int z, int nx, int ny, int comp, uint8_t v[16])
{
    memset(v, 0, 16);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            v[4 * j + i] = img->texels[(((size_t)z * (size_t)img->height + (size_t)(y0 + j)) * (size_t)img->width +
                                        (size_t)(x0 + i)) * 4 + (size_t)comp];
}

/* One S3TC block of the texels at (x0, y0) of slice z (encoded by Mesa's
 * rules, texture_encode.c) and decoded back; false for another format. */
static bool encode_s3tc(fs_tex_image *img, uint8_t *blk, int x0, int y0, int z, int nx, int ny)
{
    GLint f = img->internal_format;
    int mode = f == GL_COMPRESSED_RGB_S3TC_DXT1_EXT    ? FS_DXT_RGB1
               : f == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT ? FS_DXT_RGBA1
               : f == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT || f == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT ? FS_DXT_FOUR
                                                                                                 : -1;
    if (mode < 0)
        return false;
    uint8_t px[16][4], a[16];
    memset(px, 0, sizeof px);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            memcpy(px[4 * j + i],
                   img->texels + (((size_t)z * (size_t)img->height + (size_t)(y0 + j)) * (size_t)img->width +
                                  (size_t)(x0 + i)) * 4,
                   4);
    for (int p = 0; p < 16; p++)
        a[p] = px[p][3];
    if (f == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
        fs_tex_encode_dxt5_alpha(blk, a, nx, ny);
    else if (f == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT)
        fs_tex_encode_dxt3_alpha(blk, (const uint8_t(*)[4])px);
    fs_tex_encode_dxt_colour(mode == FS_DXT_FOUR ? blk + 8 : blk, (const uint8_t(*)[4])px, nx, ny, mode);
    decode_block(f, blk, img, x0, y0, z);
    return true;
}

bool fs_tex_compress_box(fs_tex_image *img, int x, int y, int z, int w, int h, int d)
{
    int bytes = fs_tex_compressed_block_bytes(img->internal_format, NULL);
    if (!bytes || !fs_tex_compressed_upload_base(img->internal_format) || !img->texels)
        return true;
    int64_t bw = (img->width + 3) / 4, bh = (img->height + 3) / 4;
    if (!img->compressed) {
        img->compressed_size = (size_t)(bw * bh * bytes * img->depth);
        img->compressed = calloc(img->compressed_size, 1);
        if (!img->compressed) {
            img->compressed_size = 0;
            return false;
        }
    }
    /* The second channel: G of RG, A of LUMINANCE_ALPHA (the texels hold
     * L in R, G and B). */
    int second = img->internal_format == GL_COMPRESSED_RG_RGTC2 ? 1 : 3;
    for (int k = z; k < z + d; k++)
        for (int y0 = y; y0 < y + h; y0 += 4)
            for (int x0 = x; x0 < x + w; x0 += 4) {
                int nx = img->width - x0 < 4 ? img->width - x0 : 4, ny = img->height - y0 < 4 ? img->height - y0 : 4;
                uint8_t *blk = img->compressed + ((k * bh + y0 / 4) * bw + x0 / 4) * bytes;
                uint8_t v[16];
                if (encode_s3tc(img, blk, x0, y0, k, nx, ny))
                    continue;
                gather_channel(img, x0, y0, k, nx, ny, 0, v);
                fs_tex_encode_rgtc_channel(blk, v, nx, ny);
                if (bytes == 16) {
                    gather_channel(img, x0, y0, k, nx, ny, second, v);
                    fs_tex_encode_rgtc_channel(blk + 8, v, nx, ny);
                }
                decode_block(img->internal_format, blk, img, x0, y0, k);
            }
    return true;
}

/* One channel value as Mesa's CPU decoder gives it (util_format's RGTC
 * fetch, src/util/texcompress_rgtc_tmp.h): the interpolations divided by
 * 7 and 5, truncated, instead of the sampler's weights. */
static uint8_t cpu_channel(const uint8_t *blk, int p)
{
    int a0 = blk[0], a1 = blk[1];
    uint64_t bits = 0;
    for (int i = 7; i >= 2; i--)
        bits = bits << 8 | blk[i];
    int code = (int)((bits >> (3 * p)) & 7);
    if (code < 2)
        return (uint8_t)(code ? a1 : a0);
    if (a0 > a1)
        return (uint8_t)((a0 * (8 - code) + a1 * (code - 1)) / 7);
    if (code < 6)
        return (uint8_t)((a0 * (6 - code) + a1 * (code - 1)) / 5);
    return code == 6 ? 0 : 255;
}

bool fs_tex_compressed_readback(const fs_tex_image *img, int y, int z, uint8_t *row)
{
    /* Measured through OSMesa: glGetTexImage of a LATC2 level gives the
     * CPU decoder's values (luminance 111 where sampling, and every other
     * format's readback, gives 112), so Mesa reads it back by decoding in
     * software rather than by its sampler. */
    if (img->internal_format != GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT || !img->compressed)
        return false;
    int64_t bw = (img->width + 3) / 4, bh = (img->height + 3) / 4;
    for (int x = 0; x < img->width; x++) {
        const uint8_t *blk = img->compressed + ((z * bh + y / 4) * bw + x / 4) * 16;
        int p = 4 * (y % 4) + x % 4;
        row[4 * x] = row[4 * x + 1] = row[4 * x + 2] = cpu_channel(blk, p);
        row[4 * x + 3] = cpu_channel(blk + 8, p);
    }
    return true;
}

bool fs_tex_compressed_box_aligned(const fs_tex_image *img, const GLint off[3], const GLsizei size[3])
{
    /* Mesa's rule for every sub-image command into a compressed level
     * (measured through OSMesa: glTexSubImage2D and glCopyTexSubImage2D
     * at x 2, or 3 wide short of the edge, are INVALID_OPERATION): the
     * box starts on the 4x4 grid and ends on it or at the image's edge. */
    const int dim[2] = {img->width, img->height};
    for (int i = 0; i < 2; i++)
        if (off[i] % 4 != 0 || (size[i] % 4 != 0 && off[i] + size[i] != dim[i]))
            return false;
    return true;
}

/* ---- the commands ---- */

/* A level holding blocks: given by glCompressedTexImage and not replaced
 * since (a level GL_GENERATE_MIPMAP rewrote from an uncompressed base
 * keeps its old blocks but has the base's internal format). */
static bool holds_blocks(const fs_tex_image *img)
{
    return img->compressed && img->texels && fs_tex_compressed_block_bytes(img->internal_format, NULL);
}

/* glCompressedTexImage's checks, in the order Mesa makes them (so that a
 * call with several faults gets the same error, measured through OSMesa):
 * the target (done by the caller), the format, the border, imageSize
 * against the size, the level, then the size.  Returns the error; *size_only when only the size is
 * refused (a proxy then takes zeros, 3.8.11). */
static GLenum check_image(const fs_tex_target_info *ti, GLint level, GLenum internalformat, const GLsizei size[3],
                          GLint border, GLsizei imageSize, bool *size_only)
{
    *size_only = false;
    GLenum base;
    int bytes = fs_tex_compressed_block_bytes((GLint)internalformat, &base);
    /* S3TC is two-dimensional (EXT_texture_compression_s3tc); Mesa checks
     * the target against the format first, with INVALID_ENUM. */
    if (!bytes || ti->dims != 2)
        return GL_INVALID_ENUM;
    /* 3.8.3: no compressed format has a border; OSMesa answers
     * INVALID_OPERATION (measured), before imageSize. */
    if (border != 0)
        return GL_INVALID_OPERATION;
    if (size[0] >= 0 && size[1] >= 0 && imageSize != blocks_size(size[0], size[1], bytes))
        return GL_INVALID_VALUE;
    int max_log2 = fs_tex_target_max_log2(ti->k);
    if (level < 0 || level > max_log2 || size[0] < 0 || size[1] < 0)
        return GL_INVALID_VALUE;
    /* The sizes glTexImage2D takes (texture_object.c): any, with
     * ARB_texture_non_power_of_two, up to the largest >> level; a size
     * that is no multiple of 4 has partial blocks at the edge. */
    for (int i = 0; i < 2; i++)
        if (size[i] > ((1 << max_log2) >> level)) {
            *size_only = true;
            return GL_INVALID_VALUE;
        }
    return GL_NO_ERROR;
}

static void compressed_image(fs_context *c, int dims, GLenum target, GLint level, GLenum internalformat,
                             GLsizei w, GLsizei h, GLsizei d, GLint border, GLsizei imageSize, const GLvoid *data)
{
    fs_tex_target_info ti;
    if (!fs_tex_image_target_of(target, &ti) || ti.dims != dims) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    const GLsizei size[3] = {w, h, d};
    bool size_only;
    GLenum err = check_image(&ti, level, internalformat, size, border, imageSize, &size_only);
    GLenum base = 0;
    fs_tex_compressed_block_bytes((GLint)internalformat, &base);
    if (ti.proxy && (err == GL_NO_ERROR || size_only)) {
        /* 3.8.11: a proxy level takes the image's state, or zeros when
         * only its size is refused. */
        fs_tex_image *p = &c->texture->proxy[ti.k][level];
        memset(p, 0, sizeof *p);
        if (err == GL_NO_ERROR) {
            *p = (fs_tex_image){.width = w, .height = h, .depth = 1, .internal_format = (GLint)internalformat,
                                .base_format = base, .described = true};
        }
        return;
    }
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    fs_tex_object *t = fs_tex_active(c)->bound[ti.k];
    fs_tex_image *img = &fs_tex_levels(t, ti.face)[level];
    uint8_t *texels = NULL, *blocks = NULL;
    if (w > 0 && h > 0) {
        texels = calloc((size_t)w * (size_t)h, 4);
        blocks = calloc((size_t)imageSize, 1);
        if (!texels || !blocks) {
            free(texels);
            free(blocks);
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
    }
    fs_tex_image_free(img);
    *img = (fs_tex_image){.width = texels ? w : 0, .height = texels ? h : 0, .depth = texels ? 1 : 0,
                          .internal_format = (GLint)internalformat, .base_format = base, .texels = texels,
                          .compressed = blocks, .compressed_size = blocks ? (size_t)imageSize : 0};
    t->complete = -1;
    /* A NULL image leaves the contents undefined (3.8.3 as 3.8.1): zero
     * blocks here. */
    if (texels)
        store_blocks(img, 0, 0, 0, w, h, 1, data ? data : blocks);
    fs_tex_image_changed(c, t, ti.face, level);
}

void fs_exec_CompressedTexImage1D(fs_context *c, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLint border, GLsizei imageSize, const GLvoid *data)
{
    compressed_image(c, 1, target, level, internalformat, width, 1, 1, border, imageSize, data);
}

void fs_exec_CompressedTexImage2D(fs_context *c, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLsizei height, GLint border, GLsizei imageSize, const GLvoid *data)
{
    compressed_image(c, 2, target, level, internalformat, width, height, 1, border, imageSize, data);
}

void fs_exec_CompressedTexImage3D(fs_context *c, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLsizei height, GLsizei depth, GLint border, GLsizei imageSize,
                                  const GLvoid *data)
{
    compressed_image(c, 3, target, level, internalformat, width, height, depth, border, imageSize, data);
}

/* glCompressedTexSubImage (3.8.3), checked in the order OSMesa answers
 * (measured, tests/test_compressed_tex.c): the target (a 1D one
 * INVALID_ENUM and a 3D one INVALID_OPERATION whatever else is wrong, as
 * neither can hold an S3TC image), the level's range, a format that is
 * no compressed one (INVALID_OPERATION: it cannot be the level's),
 * imageSize against the box in `format`, the level defined and of that
 * format, the box inside the level, and the box on 4x4 block boundaries
 * (EXT_texture_compression_s3tc: INVALID_OPERATION unless an edge that is
 * not on one is the image's edge). */
static GLenum check_subimage(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3],
                             const GLsizei size[3], GLenum format, GLsizei imageSize, fs_tex_image **out)
{
    fs_tex_target_info ti;
    if (!fs_tex_image_target_of(target, &ti) || ti.dims != dims || ti.proxy || dims == 1)
        return GL_INVALID_ENUM;
    if (dims == 3)
        return GL_INVALID_OPERATION;
    if (level < 0 || level > fs_tex_target_max_log2(ti.k))
        return GL_INVALID_VALUE;
    int bytes = fs_tex_compressed_block_bytes((GLint)format, NULL);
    if (!bytes)
        return GL_INVALID_OPERATION;
    if (size[0] < 0 || size[1] < 0 || imageSize != blocks_size(size[0], size[1], bytes))
        return GL_INVALID_VALUE;
    fs_tex_image *img = &fs_tex_levels(fs_tex_active(c)->bound[ti.k], ti.face)[level];
    if (!holds_blocks(img) || img->internal_format != (GLint)format)
        return GL_INVALID_OPERATION;
    const int dim[2] = {img->width, img->height};
    for (int i = 0; i < 2; i++)
        if (off[i] < 0 || (int64_t)off[i] + size[i] > dim[i])
            return GL_INVALID_VALUE;
    if (!fs_tex_compressed_box_aligned(img, off, size))
        return GL_INVALID_OPERATION;
    *out = img;
    return GL_NO_ERROR;
}

static void compressed_subimage(fs_context *c, int dims, GLenum target, GLint level, const GLint off[3], GLsizei w,
                                GLsizei h, GLsizei d, GLenum format, GLsizei imageSize, const GLvoid *data)
{
    const GLsizei size[3] = {w, h, d};
    fs_tex_image *img = NULL;
    GLenum err = check_subimage(c, dims, target, level, off, size, format, imageSize, &img);
    if (err != GL_NO_ERROR) {
        fs_error(c, err);
        return;
    }
    fs_tex_target_info ti;
    fs_tex_image_target_of(target, &ti);
    if (w > 0 && h > 0 && d > 0 && data)
        store_blocks(img, off[0], off[1], off[2], w, h, d, data);
    fs_tex_image_changed(c, fs_tex_active(c)->bound[ti.k], ti.face, level);
}

void fs_exec_CompressedTexSubImage1D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLsizei width,
                                     GLenum format, GLsizei imageSize, const GLvoid *data)
{
    const GLint off[3] = {xoffset, 0, 0};
    compressed_subimage(c, 1, target, level, off, width, 1, 1, format, imageSize, data);
}

void fs_exec_CompressedTexSubImage2D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLsizei width, GLsizei height, GLenum format, GLsizei imageSize,
                                     const GLvoid *data)
{
    const GLint off[3] = {xoffset, yoffset, 0};
    compressed_subimage(c, 2, target, level, off, width, height, 1, format, imageSize, data);
}

void fs_exec_CompressedTexSubImage3D(fs_context *c, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format,
                                     GLsizei imageSize, const GLvoid *data)
{
    const GLint off[3] = {xoffset, yoffset, zoffset};
    compressed_subimage(c, 3, target, level, off, width, height, depth, format, imageSize, data);
}

/* The level glGetCompressedTexImage reads (6.1.4): NULL with the error
 * set for a bad target or level, an undefined level (INVALID_VALUE, as
 * OSMesa answers, except for a 3D one, which it lets pass writing
 * nothing), or a level that is not compressed. */
static const fs_tex_image *get_level(fs_context *c, GLenum target, GLint level, bool set_error)
{
    fs_tex_target_info ti;
    GLenum err = GL_NO_ERROR;
    const fs_tex_image *img = NULL;
    if (!fs_tex_image_target_of(target, &ti) || ti.proxy)
        err = GL_INVALID_ENUM;
    else if (level < 0 || level > fs_tex_target_max_log2(ti.k))
        err = GL_INVALID_VALUE;
    else {
        img = &fs_tex_levels(fs_tex_active(c)->bound[ti.k], ti.face)[level];
        if (!img->texels)
            err = ti.k == FS_TEX_3D ? GL_NO_ERROR : GL_INVALID_VALUE;
        else if (!holds_blocks(img))
            err = GL_INVALID_OPERATION;
        if (!holds_blocks(img))
            img = NULL;
    }
    if (err != GL_NO_ERROR && set_error)
        fs_error(c, err);
    return img;
}

int64_t fs_getcompressed_bytes(fs_context *c, GLenum target, GLint level)
{
    const fs_tex_image *img = get_level(c, target, level, false);
    return img ? (int64_t)img->compressed_size : 0;
}

void fs_exec_GetCompressedTexImage(fs_context *c, GLenum target, GLint level, GLvoid *img)
{
    const fs_tex_image *l = get_level(c, target, level, true);
    if (l && img)
        memcpy(img, l->compressed, l->compressed_size);
}
