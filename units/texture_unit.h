/*
 * The GL texture unit (GL 1.5 spec 3.8): texture objects, 1D, 2D and 3D
 * images and their MIPmap levels, sampling with the six min filters, and
 * the texture environment.  FS_MAX_TEXTURE_UNITS units
 * (pipeline/rasterizer.h), each with its bindings, enables and environment,
 * applied unit after unit (3.8.13); cube maps (GL 1.3, 3.8.6) sample their
 * six faces as 2D images (texture_sample.c's cube_* functions).  The
 * MP-Grid (GL_FRAGSIM_mp_grid), the footprint filters and the cycle model's
 * texel addresses (fs_tex_level_size, units/texture_reads.h: (level, x, y))
 * are 2D only (units/texture_target.c).
 *
 * Where it sits: the rasterizer interpolates the texture coordinates of all
 * four pixels of a 2x2 quad (covered or not, because lambda needs the
 * quad's derivatives) and calls fs_texture_quad() right before the
 * per-fragment operations; it replaces each covered pixel's colour with the
 * texture environment's result (GL 1.5 spec 3.8.13).
 *
 * The arithmetic follows llvmpipe as OSMesa uses it (Mesa 22.3, gallivm
 * lp_bld_sample*.c; read for the rules, not copied): see texture_sample.c.
 *
 * Files: texture_object.c (objects, images, parameters, environment, GL
 * errors), texture_target.c (targets, their priority, the 1D and 3D image
 * commands), texture_sample.c (lambda, filters, environment arithmetic).
 */
#ifndef FS_TEXTURE_UNIT_H
#define FS_TEXTURE_UNIT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>
#include "../pipeline/rasterizer.h"

typedef struct fs_context fs_context;

/* GL_MAX_TEXTURE_SIZE: levels 0..FS_TEX_MAX_LEVELS-1 (GL 1.5 spec 3.8.1). */
#define FS_TEX_MAX_LOG2 12
#define FS_TEX_MAX_SIZE (1 << FS_TEX_MAX_LOG2)
#define FS_TEX_MAX_LEVELS (FS_TEX_MAX_LOG2 + 1)

/* Allocates c->texture with GL's initial state (GL 1.5 spec table 6.16-6.19).
 * Returns 0, or -1 when out of memory. */
int fs_texture_init(fs_context *c);
void fs_texture_free(fs_context *c);

/* The enable flag of a texture target (GL_TEXTURE_2D) of the active unit,
 * for glEnable and glIsEnabled; NULL for other caps.  After changing it
 * call fs_texture_enables_changed. */
bool *fs_texture_enable_flag(fs_context *c, GLenum cap);
/* Re-derives c->raster.interpolate_tex, tex_mask and tex_units from the
 * enables. */
void fs_texture_enables_changed(fs_context *c);
/* Every unit's target enables as bits (for the enable and texture
 * attribute groups, pipeline/state.c), and setting them back. */
uint64_t fs_texture_enables(const fs_context *c);
void fs_texture_set_enables(fs_context *c, uint64_t bits);
/* The name of the bound 2D texture (glGet, glPushAttrib; pipeline/state.c),
 * and of the texture bound to a target enum of the active unit
 * (GL_TEXTURE_BINDING_1D/2D/3D; 0 for an enum that names none). */
GLuint fs_texture_binding_2d(const fs_context *c);
GLuint fs_texture_binding(const fs_context *c, GLenum target);
/* The texture unit's part of the texture attribute group (GL 1.5 spec
 * 6.1.14, tables 6.16-6.20), for glPushAttrib(GL_TEXTURE_BIT): each
 * unit's binding of each target, the parameters of the objects bound there,
 * its texture environment, and the parameters of each target's default
 * object (texture 0).  (The GL_TEXTURE_1D/2D/3D enables are
 * in the enable group too; pipeline/state.c restores it through
 * fs_texture_enable_flag.) */
typedef struct fs_tex_params {
    GLenum min_filter, mag_filter, wrap_s, wrap_t, wrap_r;
    float border[4], priority;
    int footprint_budget;         /* GL_FRAGSIM_footprint_filter's parameters */
    GLenum footprint_snap;
    int base_level, max_level;    /* GL 1.2-1.4 level of detail (texture_lod.c) */
    float min_lod, max_lod, lod_bias;
    bool generate_mipmap;
    GLenum depth_mode, compare_mode, compare_func; /* GL 1.4 depth textures (texture_depth.c) */
} fs_tex_params;
/* A texture unit's environment (3.8.13, table 6.19): the mode, the
 * constant colour and GL_COMBINE's parameters, [0] for the RGB function,
 * [1] for the alpha one (units/texture_combine.c). */
typedef struct fs_tex_env {
    GLenum mode;
    float color[4];
    GLenum combine[2];          /* GL_COMBINE_RGB, GL_COMBINE_ALPHA */
    GLenum source[2][3];        /* GL_SOURCEn_RGB, GL_SOURCEn_ALPHA */
    GLenum operand[2][3];       /* GL_OPERANDn_RGB, GL_OPERANDn_ALPHA */
    float scale[2];             /* GL_RGB_SCALE, GL_ALPHA_SCALE */
    float lod_bias;             /* GL_TEXTURE_FILTER_CONTROL's bias (1.4, 3.8.8; texture_lod.c) */
} fs_tex_env;
/* The texture targets a unit binds (2D, 1D, 3D, cube map, rectangle: units/texture_priv.h). */
#define FS_TEX_TARGET_COUNT 5
typedef struct fs_texture_attrib {
    struct {
        GLuint binding[FS_TEX_TARGET_COUNT];
        fs_tex_params bound[FS_TEX_TARGET_COUNT];
        fs_tex_env env;
    } unit[FS_MAX_TEXTURE_UNITS];
    fs_tex_params defaults[FS_TEX_TARGET_COUNT];
} fs_texture_attrib;
void fs_texture_attrib_save(const fs_context *c, fs_texture_attrib *a);
/* 6.1.14: unit by unit, the binding is restored first, then the
 * parameters of the object it binds; the default object's are restored whatever is bound,
 * as OSMesa does (measured: test_state_table's push_pop_restores_vs_osmesa,
 * texture 0 changed while another was bound). */
void fs_texture_attrib_restore(fs_context *c, const fs_texture_attrib *a);

/* A texture object as the cycle model lays its texels out in memory
 * (rtl_model/texture_stage.c), without its internals: the object's name;
 * the width and height of a level as stored (0 x 0 for an undefined level
 * or one outside 0..FS_TEX_MAX_LEVELS-1), true when the level is defined
 * and one that sampling may use (up to the complete chain's last level,
 * GL 1.5 spec 3.8.10); and texel (x, y) of a level as the footprint
 * filters read it: wrapped for GL_REPEAT, otherwise clamped to the edge
 * (GL_CLAMP has no border colour there, texture_sample.c). */
struct fs_tex_object;
GLuint fs_tex_object_name(const struct fs_tex_object *t);
bool fs_tex_level_size(const struct fs_tex_object *t, int level, int *width, int *height);
void fs_tex_footprint_texel(const struct fs_tex_object *t, int level, int *x, int *y);

/* The compressed internal formats listed by GL_COMPRESSED_TEXTURE_FORMATS
 * (units/texture_compressed.c): their count, and the formats written to
 * formats when it is not NULL. */
int fs_tex_compressed_formats(GLint *formats);

/* Applies texturing to a quad whose unit[u].tex holds the interpolated
 * (s, t, r, q) of all four pixels for each enabled unit u, unit after unit
 * (3.8.13). */
void fs_texture_quad(fs_context *c, fs_quad *q);

/* Sampling counters for tests: quads textured, and quads passed through
 * untextured because the bound texture is incomplete (GL 1.5 spec 3.8.10). */
uint64_t fs_texture_quads_sampled(const fs_context *c);
uint64_t fs_texture_quads_incomplete(const fs_context *c);

/* Whether sampling keeps to the reference path (generic true) or may take
 * the 8-bit quad path of the common textures (units/texture_sample.c; the
 * same bits either way, tests/test_texture_fast.c), and the count of quads
 * that took the latter. */
void fs_texture_set_generic(fs_context *c, bool generic);
uint64_t fs_texture_quads_fast(const fs_context *c);
/* Threaded rasterization (pipeline/raster_threads.h; units/texture_fork.c):
 * whether the enabled units may be sampled by several threads at once (no
 * MP-Grid, no footprint filter; caches each bound object's completeness
 * first), the size of the unit's state, a thread's copy of it with zeroed
 * counters, and the copy's counters added back. */
struct fs_texture_state;
bool fs_texture_par_safe(fs_context *c);
size_t fs_texture_state_bytes(void);
void fs_texture_fork(const fs_context *c, struct fs_texture_state *dst);
void fs_texture_join(fs_context *c, const struct fs_texture_state *w);
#endif
