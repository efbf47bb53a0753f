/*
 * Depth textures and ARB_shadow (GL 1.4 spec 3.8.1, 3.8.4, 3.8.13, 3.8.14;
 * units/texture_depth.c): the DEPTH_COMPONENT internal formats, their
 * texels, the texture comparison and the depth texture mode.  Private to
 * the texture unit (texture_object.c, texture_sample.c).
 *
 * A depth image keeps one 32-bit value per texel in the 4 bytes an RGBA8
 * texel takes (fs_tex_image.texels), the depth in units of the format
 * llvmpipe stores it in (fs_tex_image.depth_bits: 16, 24 or 32 bits).
 */
#ifndef FS_TEXTURE_DEPTH_H
#define FS_TEXTURE_DEPTH_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;
struct fs_tex_image;
struct fs_tex_object;

/* Whether an internalformat is DEPTH_COMPONENT or a sized one (table 3.16;
 * and ARB_depth_buffer_float's DEPTH_COMPONENT32F, which llvmpipe offers). */
bool fs_tex_depth_format(GLint internalformat);
/* Bits llvmpipe stores a depth internalformat at: the sized formats at
 * their size; DEPTH_COMPONENT at the size matching the client type
 * (UNSIGNED_SHORT 16, UNSIGNED_INT 32, others 24; type 0: a copy from the
 * depth buffer or a proxy, 24).  Measured through OSMesa (TEXTURE_DEPTH_SIZE). */
int fs_tex_depth_bits(GLint internalformat, GLenum type);

/* Unpacks a w x h x d DEPTH_COMPONENT (or DEPTH_STENCIL: its depth)
 * client image into img at off, as glTexImage and glTexSubImage take it
 * (3.8.1: as glDrawPixels, depth scale and bias applied). */
void fs_tex_depth_unpack(fs_context *c, struct fs_tex_image *img, int dims, const int off[3], int w, int h, int d,
                         GLenum format, GLenum type, const void *pixels);
/* Stores a depth buffer value (fb_bits bits) as texel (x, y) of img, as
 * glCopyTexImage does. */
void fs_tex_depth_store_copy(struct fs_tex_image *img, uint8_t *texel, uint32_t z, int fb_bits);

/* glGetTexImage(DEPTH_COMPONENT) of a depth image into pixels by the pack
 * state (6.1.4): each texel as Mesa unpacks it to float, depth scale and
 * bias applied, then packed as glReadPixels packs depth. */
void fs_tex_depth_get_image(fs_context *c, const struct fs_tex_image *img, int dims, GLenum type, void *pixels);

/* The texel as the sampler reads it: the stored depth converted to float
 * (gallivm's unsigned-normalized conversion for the format's width). */
float fs_tex_depth_texel(const struct fs_tex_image *img, const uint8_t *texel);
/* What the filter takes of a depth texel d (or the border's depth) for a
 * fragment whose reference is ref (already clamped, fs_tex_depth_ref):
 * with COMPARE_R_TO_TEXTURE 1 or 0 by the compare function (3.8.14),
 * else d. */
float fs_tex_depth_filtered_value(const struct fs_tex_object *t, float ref, float d);
/* The reference r/q of texture t clamped to [0, 1] (NaN to 0), as
 * llvmpipe clamps it for a fixed-point depth format. */
float fs_tex_depth_ref(const struct fs_tex_object *t, float r);
/* The coordinate the reference is: r (GL 1.4 3.8.14) for 2D textures, but
 * t for 1D ones, as Mesa's fixed-function fragment program takes the
 * comparator from the component after the texture's coordinates
 * (measured: a 1D depth texture compares with t/q on OSMesa). */
static inline int fs_tex_depth_ref_coord(int dims) { return dims < 2 ? 1 : 2; }
/* The filtered value v as R, G, B, A by DEPTH_TEXTURE_MODE (3.8.14,
 * table 3.21: LUMINANCE (v, v, v, 1), INTENSITY (v, v, v, v), ALPHA
 * (0, 0, 0, v), RED (v, 0, 0, 1)). */
void fs_tex_depth_mode_apply(const struct fs_tex_object *t, float rgba[4]);
/* The base format the texture environment takes for a depth texture:
 * its DEPTH_TEXTURE_MODE (3.8.13). */
GLenum fs_tex_depth_env_base(const struct fs_tex_object *t);

/* The initial DEPTH_TEXTURE_MODE, COMPARE_MODE and COMPARE_FUNC (table 6.17). */
void fs_tex_depth_defaults(struct fs_tex_object *t);
/* glTexParameter of DEPTH_TEXTURE_MODE, TEXTURE_COMPARE_MODE or
 * TEXTURE_COMPARE_FUNC: 1 when pname is one of them (*err GL_NO_ERROR, or
 * INVALID_ENUM for a value it does not take, nothing changed), 0 otherwise. */
int fs_tex_depth_parameter(struct fs_tex_object *t, GLenum pname, GLenum value, GLenum *err);
/* Their values for glGetTexParameter; 0 for another pname. */
int fs_tex_depth_parameter_value(const struct fs_tex_object *t, GLenum pname, float *v);
#endif
