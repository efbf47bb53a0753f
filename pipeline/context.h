/*
 * The one context struct passed everywhere.  It holds a whole GL context:
 * state of every stage, the framebuffer, statistics, display lists and the
 * optional capture writer.  There is no global mutable state; two contexts
 * (say a baseline and a proposed pipeline) can live in one process.
 * Each sub-struct is owned by the header of the stage it belongs to.
 */
#ifndef FS_CONTEXT_H
#define FS_CONTEXT_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>
#include "config.h"
#include "stats.h"
#include "framebuffer.h"
#include "rasterizer.h"
#include "fragment_ops.h"
#include "vertex_stage.h"
#include "state.h"
#include "stored_state.h"
#include "raster_pos.h"
#include "observer.h"
#include "render_mode.h"
#include "evaluator.h"
#include "pixel_map.h"
#include "accum.h"
#include "texgen.h"

struct fs_dlist_state;      /* driver/display_list.c */
struct fs_capture;          /* driver/capture.c */
struct fs_occlusion;        /* units/occlusion_gl.c */
struct fs_texture_state;    /* units/texture_object.c */
struct fs_buffer_objects;   /* pipeline/buffer_object.c */

struct fs_context {
    fs_config cfg;
    GLenum error;                 /* sticky GL error flag (GL 1.5 spec 2.5) */
    /* Called by fs_error with every error raised (NULL: nobody listens), so
     * that a replay or the shim can name the call that raised it; it costs
     * nothing while no error is raised. */
    void (*error_hook)(void *user, GLenum err);
    void *error_user;

    fs_transform_state xf;
    fs_lighting_state lighting;
    fs_current_state current;
    /* Texture coordinate generation of each texture unit (GL 1.5 spec
     * 2.11.4; pipeline/texgen.c). */
    fs_texgen_unit texgen[FS_MAX_TEXTURE_UNITS];
    /* The current raster position (GL 1.5 spec 2.13; pipeline/raster_pos.c). */
    fs_raster_pos rpos;
    fs_array_state arrays;
    fs_prim_state prim;
    fs_raster_state raster;
    fs_fragment_state frag;
    fs_framebuffer fb;
    /* glRenderMode's GL_SELECT and GL_FEEDBACK, the name stack and their
     * buffers (GL 1.5 spec 5.2, 5.3; pipeline/render_mode.c). */
    fs_render_mode_state rmode;
    /* Evaluators (GL 1.5 spec 5.1; pipeline/evaluator.c): the enables and
     * grids of GL_EVAL_BIT here, the maps (in no attribute group, table
     * 6.26) behind eval_maps, made at first use. */
    fs_eval_state eval;
    struct fs_eval_maps *eval_maps;
    /* glPixelTransfer and glPixelMap (GL 1.5 spec 3.6.3, table 6.24;
     * pipeline/pixel_map.c). */
    fs_pixel_xfer px;
    /* The accumulation buffer (GL 1.5 spec 4.2.4; pipeline/accum.c). */
    fs_accum_state accum;

    GLint pack_alignment, unpack_alignment, unpack_row_length, pack_row_length;
    /* The rest of the pixel-store state (GL 1.5 spec table 3.1 / 4.5; all
     * 0 initially, swap bytes and LSB first as 0/1), read by
     * pipeline/pixel_transfer.c. */
    GLint unpack_skip_pixels, unpack_skip_rows, unpack_image_height, unpack_skip_images;
    GLint pack_skip_pixels, pack_skip_rows, pack_image_height, pack_skip_images;
    GLint unpack_swap_bytes, unpack_lsb_first, pack_swap_bytes, pack_lsb_first;
    bool unmodelled_caps[48];     /* enables fragsim stores but does not model (driver/gl_state.c) */
    /* The window's buffers (GL 1.5 spec 4.2.1, 4.3.2, table 6.34): one colour
     * buffer serves front and back.  double_buffered is what the captured
     * program's context was (fs_context_set_double_buffered; false, as for
     * OSMesa, unless replay sees swap calls); draw_buffer and read_buffer
     * are the enums glDrawBuffer and glReadBuffer set (pipeline/buffer_select.c). */
    bool double_buffered;
    GLenum draw_buffer, read_buffer;
    /* Hints (GL 1.5 spec 5.6, table 6.27), stored only: llvmpipe ignores them. */
    GLenum hints[7];
    fs_stored_state st;           /* stored for glGet, not modelled yet (stored_state.h) */
    /* The attribute stacks (6.1.14; pipeline/state.c) and the groups whose
     * state changed since the last validation, as glPushAttrib's bits with
     * the client groups in bits 20-21 (pipeline/state.h). */
    GLint attrib_depth, client_attrib_depth;
    struct fs_attrib_stack *attrib_stack;
    uint32_t dirty;

    /* The driver layer's state in the context, opaque here: the display
     * lists (driver/display_list.c) and the calls counted unsupported by
     * command (driver/dispatch.c), each made on first use.  The driver sets
     * driver_free when it makes one; fs_context_destroy calls it first. */
    struct fs_dlist_state *lists;
    /* glListBase (GL 1.5 spec 5.4), here rather than in the driver's list
     * state so that the table's GL_LIST_BIT group saves it. */
    GLuint list_base;
    uint64_t *unsupported_cmds;
    void (*driver_free)(fs_context *c);
    struct fs_capture *capture;   /* non-NULL while recording a trace */

    fs_occlusion_hook_fn occlusion_hook; /* issue 3 attaches here */
    void *occlusion_user;
    /* The Occlusion Unit, its GL state and the query objects; created on
     * first use (units/occlusion_gl.c). */
    struct fs_occlusion *occlusion;
    /* The texture unit's state (units/texture_unit.h). */
    struct fs_texture_state *texture;
    /* The buffer objects (GL 1.5 spec 2.9), created on first use; their
     * bindings are in `arrays` (pipeline/buffer_object.h). */
    struct fs_buffer_objects *buffers;
    /* Whoever watches the work (observer.h); NULL in functional mode,
     * where each report point costs one branch. */
    fs_observer *observer;

    fs_stats stats;               /* counters of the current frame */
    /* Threaded rasterization (raster_threads.h): the worker pool, made on
     * the first draw that may go parallel, and whether the current draw's
     * triangles are being recorded for it. */
    struct fs_raster_par *par;
    bool par_recording;
    /* Unsupported features of implemented calls (e.g. "glPolygonMode(GL_LINE)"),
     * counted by name. */
    struct { char name[64]; uint64_t count; } unsupported_feature[64];
    int unsupported_feature_count;

    void *scratch;                /* output buffer for replayed glGet and glReadPixels */
    size_t scratch_size;
    /* Copies of the array data replayed pointer calls carry, two per array
     * (fs_client_array_at's order: vertex, normal, colour, the texcoord
     * array of each texture unit, secondary colour, fog coordinate, edge
     * flag, index): a call GL rejects must not overwrite the copy the
     * array still points at (driver/dispatch.c). */
    struct { void *buf[2]; size_t cap[2]; } array_copy[FS_CLIENT_ARRAYS];
};

/* Creates a context with a width x height framebuffer (cfg may be NULL for
 * defaults).  Returns NULL when out of memory or when the size is invalid. */
fs_context *fs_context_create(const fs_config *cfg, int width, int height);
void fs_context_destroy(fs_context *c);
/* Resizes the framebuffer (contents cleared to zero). */
int fs_context_resize(fs_context *c, int width, int height);

/* Records a GL error: only the first error since the last glGetError sticks. */
void fs_error(fs_context *c, GLenum err);
/* Counts an unsupported feature of a call by a descriptive name. */
void fs_unsupported(fs_context *c, const char *what);
void *fs_scratch(fs_context *c, size_t bytes);
/* A normalized value as glGetIntegerv returns it (GL 1.5 spec 6.1.2;
 * driver/gl_state.c), for every query of colours. */
GLint fs_norm_to_int(double x);
/* Sets whether the context is double-buffered and the draw and read
 * buffers to its initial GL_BACK or GL_FRONT (GL 1.5 spec 4.2.1, 4.3.2);
 * before any call, as when the context was created. */
void fs_context_set_double_buffered(fs_context *c, bool double_buffered);

/* Most names of one kind of object (display lists, texture objects,
 * queries) held at once.  Each name generated is an object, so a glGen* of
 * 2^31 - 1 names from a bad trace would otherwise allocate for hours. */
#define FS_MAX_NAMES ((size_t)1 << 20)
/* The check every glGen* shares: whether n more names may be generated
 * where `held` are held.  Otherwise sets the error and nothing may be
 * generated: GL_INVALID_VALUE for n < 0 (GL 1.5 spec 2.5 and each command's
 * section), GL_OUT_OF_MEMORY beyond FS_MAX_NAMES (which GL allows for any
 * command). */
bool fs_gen_names_ok(fs_context *c, GLsizei n, size_t held);

/* The observer's tile mask while it is on, else NULL (observer.h). */
static inline const fs_tile_mask *fs_tile_mask_active(const fs_context *c)
{
    return c->observer && c->observer->mask.on ? &c->observer->mask : NULL;
}
/* Reports to the observer, if any: FS_OBSERVE(c, clear, c, mask, w, h). */
#define FS_OBSERVE(c, hook, ...)                                                    \
    do {                                                                            \
        if ((c)->observer)                                                          \
            (c)->observer->ops->hook((c)->observer->user, __VA_ARGS__);            \
    } while (0)
/* Whether the observer skips a draw of n vertices in mode (observer.h). */
static inline bool fs_draw_skipped(fs_context *c, GLenum mode, size_t n)
{
    /* Selection and feedback need every primitive: none is skipped. */
    return c->observer && !fs_render_mode_diverts(&c->rmode) && !c->observer->ops->draw(c->observer->user, c, mode, n);
}
#endif
