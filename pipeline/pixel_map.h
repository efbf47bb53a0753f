/*
 * Pixel transfer state and operations (GL 1.5 spec 3.6.3, 3.6.5, table
 * 6.24; pipeline/pixel_map.c): glPixelTransfer's scales, biases, index
 * shift and offset and the MAP_COLOR / MAP_STENCIL switches, the ten
 * glPixelMap tables, and the operations that apply them to pixel groups on
 * their way from client memory (glDrawPixels, glTexImage*), to it
 * (glReadPixels, 4.3.2) and between buffers (glCopyPixels, 4.3.3,
 * glCopyTexImage*).
 *
 * Mesa runs these operations on the CPU for llvmpipe; the values below
 * (table sizes, the storing conversions of glPixelMap*, the lookups) are
 * the ones measured through libOSMesa by tests/test_pixel_map.c.
 */
#ifndef FS_PIXEL_MAP_H
#define FS_PIXEL_MAP_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;
struct fs_pixel_layout;

/* GL_MAX_PIXEL_MAP_TABLE as OSMesa reports it. */
#define FS_PIXEL_MAP_MAX 256
/* The maps in the order of their enums (GL_PIXEL_MAP_I_TO_I 0x0C70 ...
 * GL_PIXEL_MAP_A_TO_A 0x0C79). */
enum {
    FS_MAP_I_TO_I, FS_MAP_S_TO_S, FS_MAP_I_TO_R, FS_MAP_I_TO_G, FS_MAP_I_TO_B, FS_MAP_I_TO_A,
    FS_MAP_R_TO_R, FS_MAP_G_TO_G, FS_MAP_B_TO_B, FS_MAP_A_TO_A, FS_PIXEL_MAPS
};

typedef struct fs_pixel_xfer {
    float scale[4], bias[4];     /* GL_RED_SCALE ... GL_ALPHA_BIAS: 1 and 0 */
    float depth_scale, depth_bias; /* 1, 0 */
    GLint index_shift, index_offset; /* 0, 0 */
    bool map_color, map_stencil; /* false */
    GLint size[FS_PIXEL_MAPS];   /* 1 each */
    /* The tables as Mesa keeps them: colour maps clamped to [0, 1],
     * S_TO_S rounded to integers, I_TO_I as given; all 0 initially. */
    float map[FS_PIXEL_MAPS][FS_PIXEL_MAP_MAX];
} fs_pixel_xfer;

/* Elements glPixelMap* reads (mapsize when the call can succeed, else 0)
 * and glGetPixelMap* writes (the map's size; 0 for a bad map), for the
 * command table's counts. */
int fs_pixel_map_count(GLsizei mapsize);
int fs_pixel_map_size(const fs_context *c, GLenum map);

/* Whether colour groups are changed by the transfer (any scale not 1,
 * bias not 0, or MAP_COLOR); depth (scale or bias); stencil (shift,
 * offset or MAP_STENCIL). */
bool fs_pixel_xfer_color(const fs_context *c);
bool fs_pixel_xfer_depth(const fs_context *c);
bool fs_pixel_xfer_stencil(const fs_context *c);

/* Scale and bias, then MAP_COLOR's lookup, on n RGBA groups (3.6.5
 * "Arithmetic on Components", "RGBA to RGBA Lookup"); the results are not
 * clamped (each destination clamps as it converts). */
void fs_pixel_xfer_rgba(const fs_context *c, float *rgba, int64_t n);
/* Colour indices to RGBA: shift and offset, then the I_TO_R/G/B/A maps
 * (3.6.5 "Arithmetic on Indices", "Color Index Lookup"). */
void fs_pixel_xfer_index_to_rgba(const fs_context *c, const uint32_t *index, int64_t n, float *rgba);
/* The I_TO_R/G/B/A lookup alone, without shift and offset (glDrawPixels
 * on llvmpipe, pipeline/pixel_rect.c). */
void fs_pixel_map_index_to_rgba(const fs_context *c, const uint32_t *index, int64_t n, float *rgba);
/* Stencil indices: shift and offset, then S_TO_S when MAP_STENCIL. */
uint32_t fs_pixel_xfer_stencil_index(const fs_context *c, uint32_t index);
/* Depth: d * DEPTH_SCALE + DEPTH_BIAS, clamped to [0, 1] (3.6.5). */
float fs_pixel_xfer_depth_value(const fs_context *c, float d);

/* A float component (clamped to [0, 1] here) as an 8-bit value, rounded
 * to nearest as llvmpipe stores the results of the transfer. */
uint8_t fs_pixel_float_to_8(float f);

/* Groups x0 .. x0+n-1 of row y of image z of a colour or COLOR_INDEX image
 * to RGBA8 through the pixel transfer (3.6.4 unpacking, 3.6.5): the path
 * glTexImage* and glTexSubImage* take.  Without transfer operations this
 * is fs_pixel_unpack_rgba8. */
void fs_pixel_unpack_transfer_rgba8(const fs_context *c, const struct fs_pixel_layout *l, const void *pixels,
                                    int64_t z, int64_t y, int64_t x0, int64_t n, uint8_t *rgba);
/* The same with the final conversion conv(arg, floats, k, out) of each
 * piece of k groups instead of the 8-bit rounding: for the formats
 * llvmpipe stores at other than 8 bits, which it rounds from the floats
 * directly (units/texel_format.c). */
void fs_pixel_unpack_transfer_conv(const fs_context *c, const struct fs_pixel_layout *l, const void *pixels,
                                   int64_t z, int64_t y, int64_t x0, int64_t n, uint8_t *rgba,
                                   void (*conv)(const void *arg, const float *f, size_t k, uint8_t *out),
                                   const void *arg);
#endif
