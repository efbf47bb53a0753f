/*
 * Pixel pack and unpack (GL 1.5 spec 3.6, 4.3.2, 6.1.4): the one place that
 * knows client pixel memory.  It converts between an image in client memory
 * (a format, a type and the pixel-store state) and the model's own values:
 * RGBA8 colours (the framebuffer and the texture unit store 8 bits a
 * component), depth in buffer units and stencil indices.
 *
 * Every pixel path calls it: glTexImage2D/glTexSubImage2D and
 * GL_FRAGSIM_mp_grid's image upload (unpack), glReadPixels and
 * glGetTexImage (pack), and the byte counts the command table gives the
 * trace reader and writer (fs_pixel_image_bytes).  A later glTexImage1D/3D
 * or glDrawPixels makes an fs_pixel_layout for its image (dims 1, 2 or 3)
 * and unpacks it row by row; nothing else needs to know the layout.
 *
 * Use:
 *   fs_pixel_store ps = fs_pixel_store_unpack(c);
 *   GLenum e = fs_pixel_check(format, type);              // 3.6.4 errors
 *   fs_pixel_layout l;
 *   fs_pixel_layout_init(&l, &ps, 2, w, h, 1, format, type);
 *   for (y...) fs_pixel_unpack_rgba8(&l, pixels, 0, y, 0, w, row);
 *
 * Conversions are llvmpipe's (Mesa 22.3's format conversion, measured
 * through libOSMesa by tests/test_pixel_transfer.c): see pixel_transfer.c.
 */
#ifndef FS_PIXEL_TRANSFER_H
#define FS_PIXEL_TRANSFER_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

/* The pixel-store state of one direction (tables 3.1 and 4.5). */
typedef struct fs_pixel_store {
    GLint alignment;            /* 1, 2, 4 or 8 */
    GLint row_length;           /* 0: the image's width */
    GLint image_height;         /* 0: the image's height (3D images only) */
    GLint skip_pixels, skip_rows, skip_images;
    bool swap_bytes, lsb_first;
} fs_pixel_store;

/* The context's unpack (glTexImage*, glDrawPixels) and pack (glReadPixels,
 * glGetTexImage) state; fs_pixel_store_set_unpack puts one back (display
 * lists replay an image with the unpack state it was compiled with). */
fs_pixel_store fs_pixel_store_unpack(const fs_context *c);
fs_pixel_store fs_pixel_store_pack(const fs_context *c);
void fs_pixel_store_set_unpack(fs_context *c, const fs_pixel_store *ps);

/* What a format holds (table 3.6); 0 when the enum is not a format. */
enum { FS_PIXEL_COLOR = 1, FS_PIXEL_COLOR_INDEX = 2, FS_PIXEL_STENCIL = 4, FS_PIXEL_DEPTH = 8,
       FS_PIXEL_DEPTH_STENCIL = 16 /* EXT_packed_depth_stencil's GL_DEPTH_STENCIL */ };
int fs_pixel_format_kind(GLenum format);
/* Elements per group of a format (table 3.6), 0 if not a format. */
int fs_pixel_components(GLenum format);
/* The errors of a format/type pair by 3.6.4: GL_INVALID_ENUM for an enum
 * that is no format or no type, or GL_BITMAP with a format other than
 * COLOR_INDEX and STENCIL_INDEX; GL_INVALID_OPERATION for a packed type
 * (table 3.8) with a format of the wrong component count (the _3_3_2 and
 * _5_6_5 types take RGB, the others RGBA or BGRA).  Commands add their own
 * (which kinds of format they take, 3.8.1, 4.3.2, 6.1.4). */
GLenum fs_pixel_check(GLenum format, GLenum type);
/* Bytes per group (pixel) of a valid pair; 0 for GL_BITMAP or an invalid pair. */
int fs_pixel_group_bytes(GLenum format, GLenum type);

/* Where the groups of a client image are (3.6.4 "Unpacking", 4.3.2): one
 * image of width x height x depth groups, dims 1, 2 or 3 (skip images and
 * image height apply to 3D images only; skip rows also to 1D ones, as in
 * Mesa).  For GL_BITMAP offsets count bits. */
typedef struct fs_pixel_layout {
    GLenum format, type;
    int comps;                  /* elements per group */
    int elem_bytes;             /* bytes of one element (packed: of the group); 0 for BITMAP */
    int64_t group_bytes;        /* bytes per group; 0 for BITMAP */
    int64_t row_stride, image_stride; /* bytes */
    int64_t origin;             /* bytes (BITMAP: bits) to group (0, 0, 0) */
    int64_t width, height, depth;
    bool swap_bytes, lsb_first;
} fs_pixel_layout;

/* False (and *l zeroed) when the pair is invalid (fs_pixel_check), a size
 * is negative, or the image would span more than 2^60 bytes (then nothing
 * may be read or written). */
bool fs_pixel_layout_init(fs_pixel_layout *l, const fs_pixel_store *ps, int dims, int64_t width, int64_t height,
                          int64_t depth, GLenum format, GLenum type);
/* Bytes from the image pointer to one past the last byte of the image (skips
 * included): what a command reads or writes.  0 for an empty image or an
 * invalid pair. */
int64_t fs_pixel_layout_bytes(const fs_pixel_layout *l);
int64_t fs_pixel_image_bytes(const fs_pixel_store *ps, int dims, int64_t width, int64_t height, int64_t depth,
                             GLenum format, GLenum type);

/* ---- unpacking (3.6.4) ----
 * Groups x0 .. x0+n-1 of row y of image z of a colour format to RGBA8:
 * missing colour components are 0, a missing alpha is 255, luminance goes
 * to R, G and B (3.6.4 "Conversion to RGB").  Each element converts to 8
 * bits as llvmpipe's texture upload does: unsigned normalized integers
 * rounded to nearest (packed ones replicate their top bits), signed ones
 * clamped at 0 and their magnitude taken as an unsigned value one bit
 * narrower, floats clamped to [0, 1] and rounded to nearest even. */
void fs_pixel_unpack_rgba8(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, uint8_t *rgba);

/* The same groups as floats, unclamped, for the pixel transfer operations
 * (pipeline/pixel_map.h): unsigned normalized elements c / (2^b - 1),
 * signed ones c / (2^(b-1) - 1) but at least -1, floats as they are. */
void fs_pixel_unpack_rgbaf(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, float *rgba);

/* Groups of a STENCIL_INDEX or COLOR_INDEX image as indices (3.6.4): the
 * integer types as integers (signed ones sign-extended), FLOAT truncated
 * toward zero modulo 2^32 (a negative index wraps, as in llvmpipe's
 * COLOR_INDEX texture uploads), BITMAP one bit each (bit 7 of
 * a byte first unless LSB first).  Groups of a DEPTH_COMPONENT image as
 * floats in [0, 1] by table 2.9 (unsigned c / (2^b - 1), signed
 * (2c + 1) / (2^b - 1), floats clamped).  For glDrawPixels; not yet
 * compared with llvmpipe (no command of the model unpacks them yet). */
void fs_pixel_unpack_index(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, uint32_t *index);
void fs_pixel_unpack_depth(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                           int64_t n, float *depth);

/* Groups of a DEPTH_STENCIL image (EXT_packed_depth_stencil,
 * ARB_depth_buffer_float): depth[i] the 24-bit depth of an
 * UNSIGNED_INT_24_8 group, or the bits of the float depth of a
 * FLOAT_32_UNSIGNED_INT_24_8_REV one (unconverted: how it is stored
 * depends on the destination); stencil[i] (if stencil is not NULL) the
 * stencil index, the low 8 bits. */
void fs_pixel_unpack_depth_stencil(const fs_pixel_layout *l, const void *pixels, int64_t z, int64_t y, int64_t x0,
                                   int64_t n, uint32_t *depth, uint8_t *stencil);

/* ---- packing (4.3.2, 6.1.4) ----
 * RGBA8 values to groups x0 .. x0+n-1 of row y of a colour format.
 * FS_PACK_LUMINANCE_SUM: luminance is R + G + B clamped (glReadPixels,
 * 4.3.2), else R (glGetTexImage, table 6.1 / 6.1.4).
 * FS_PACK_ROUND_PACKED: packed types wider than 8 bits round to nearest
 * (Mesa converts through float for textures whose base format is not RGBA)
 * instead of replicating the top bits.
 * FS_PACK_LUMINANCE_UINT_FLOAT: LUMINANCE and LUMINANCE_ALPHA as
 * GL_UNSIGNED_INT go through float (24 bits; 1.0 wraps to 0), as Mesa's
 * glGetTexImage converts them, instead of x * 0x01010101. */
enum { FS_PACK_LUMINANCE_SUM = 1, FS_PACK_ROUND_PACKED = 2, FS_PACK_LUMINANCE_UINT_FLOAT = 4 };
/* Reads one element of `bytes` bytes (1, 2 or 4) at p, the bytes swapped
 * with swap (GL_UNPACK_SWAP_BYTES). */
uint32_t fs_pixel_load_elem(const uint8_t *p, int bytes, bool swap);
/* Writes one element of `bytes` bytes (1, 2 or 4) holding v at p, the
 * bytes swapped with swap (GL_PACK_SWAP_BYTES). */
void fs_pixel_store_elem(uint8_t *p, int bytes, bool swap, uint32_t v);
void fs_pixel_pack_rgba8(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                         const uint8_t *rgba, unsigned flags);
/* Depth values of `bits` bits (buffer units, max 2^bits - 1) to a
 * DEPTH_COMPONENT image, and stencil indices to a STENCIL_INDEX image. */
void fs_pixel_pack_depth(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                         const uint32_t *depth, int bits);
void fs_pixel_pack_stencil(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                           const uint8_t *stencil);
/* Depth values of `bits` bits (buffer units) and stencil indices to a
 * DEPTH_STENCIL image (glReadPixels): UNSIGNED_INT_24_8 as depth << 8 |
 * stencil, FLOAT_32_UNSIGNED_INT_24_8_REV as the float depth and a word
 * holding the stencil index. */
void fs_pixel_pack_depth_stencil(const fs_pixel_layout *l, void *pixels, int64_t y, int64_t x0, int64_t n,
                                 const uint32_t *depth, int bits, const uint8_t *stencil);
#endif
