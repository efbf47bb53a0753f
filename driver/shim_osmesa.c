/*
 * The shim's OSMesa context API: OSMesaCreateContext[Ext|Attribs],
 * OSMesaMakeCurrent, OSMesaGetCurrentContext, OSMesaGetColorBuffer,
 * OSMesaGetDepthBuffer, OSMesaGetProcAddress, OSMesaDestroyContext,
 * OSMesaPixelStore, OSMesaGetIntegerv, on the model's contexts.
 *
 * The caller's buffer.  The model renders into its own framebuffer
 * (fs_framebuffer: RGBA8, bottom row first), not into the buffer given to
 * OSMesaMakeCurrent.  The colour buffer is copied into the caller's buffer,
 * converted to the context's format, row length and OSMESA_Y_UP:
 *   - after glFinish, glFlush and glReadPixels,
 *   - in OSMesaGetColorBuffer,
 *   - when OSMesaMakeCurrent makes another context or buffer current, or
 *     releases the context (the buffer losing the context gets its pixels).
 * Between those points the caller's buffer holds the pixels of the last one,
 * which is what OSMesa (Mesa 22, gallium) does too: it renders into its own
 * texture and copies into the caller's buffer when flushing; pixels the
 * caller had in the buffer before are not read (OSMesa overwrites them).
 *
 * Capture.  With FRAGSIM_TRACE=path in the environment, a context records
 * every call from its first OSMesaMakeCurrent on, as an apitrace trace
 * (driver/capture.c).  The first recorded call is glViewport(0, 0, width,
 * height): OSMesa sets that viewport at the first OSMesaMakeCurrent, and
 * `fragsim replay` takes the window size from the first glViewport.  Every
 * glFinish ends a frame; the trace is finished when the context is destroyed
 * or, for a context still current, when the program exits.
 *
 * Statistics.  With FRAGSIM_STATS=path, the context's counters, summed over
 * its whole life, are written as JSON ({"totals": {...}}, the block `fragsim
 * replay` writes under the same name) when it is destroyed or, still
 * current, when the program exits; so a capture's replay can be checked
 * against the run that made it.  Beside them, "errors_total" and "errors"
 * list every GL error as `fragsim replay` does, numbered by the shim's own
 * count of the program's GL calls on the context (from 0; a capture's
 * numbers differ by its initial glViewport and fake array calls).
 *
 * The only mutable state outside the contexts is GL's current context, one
 * per thread.
 */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>
#include "../pipeline/context.h"
#include "capture.h"
#include "error_log.h"
#include "gpio_lines.h"
#include "shim.h"
#include "run_config.h"

/* llvmpipe's largest 2D texture, which Mesa's OSMesa reports as
 * OSMESA_MAX_WIDTH and OSMESA_MAX_HEIGHT. */
#define SHIM_MAX_SIZE 16384

struct osmesa_context {
    fs_context *fs;            /* created at the first OSMesaMakeCurrent, which gives the size */
    fs_run_config cfg;         /* FRAGSIM_CONFIG, read as replay reads --config; the model takes cfg.gl */
    GLenum format;             /* OSMESA_RGBA, ... */
    int has_depth;             /* 0 when created with depthBits 0 (see make_config) */
    void *buffer;              /* the caller's buffer, NULL before the first bind */
    GLenum type;
    GLsizei width, height;
    GLint row_length;          /* OSMESA_ROW_LENGTH in pixels, 0: the width */
    GLboolean y_up;            /* OSMESA_Y_UP */
    void *depth_copy;          /* what OSMesaGetDepthBuffer hands out */
    int frame_open;            /* calls recorded since the last frame boundary */
    fs_gpio *gate;             /* FRAGSIM_TRACE_GPIO's input line, NULL without one */
    int gate_waiting;          /* capture waits for the gate line to go high */
    /* The GL errors of the context's calls (FRAGSIM_STATS), numbered by the
     * shim's own count of the program's GL calls on it, from 0; the
     * command is named when the call returns (fs_shim_end). */
    fs_error_log errs;
    size_t errs_named;
};

static _Thread_local struct osmesa_context *current;

static void shim_message(const char *what, const char *detail)
{
    fprintf(stderr, "libfragsimGL: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
}

/* ---- the caller's buffer ---- */

static int bytes_per_pixel(GLenum format)
{
    return format == OSMESA_RGB || format == OSMESA_BGR ? 3 : 4;
}

static void copy_out(struct osmesa_context *o)
{
    if (!o->fs || !o->buffer)
        return;
    const fs_framebuffer *fb = &o->fs->fb;
    int bpp = bytes_per_pixel(o->format);
    size_t stride = (size_t)(o->row_length > 0 ? o->row_length : o->width) * (size_t)bpp;
    for (int y = 0; y < fb->height; y++) {
        const uint8_t *s = fb->color + (size_t)y * (size_t)fb->width * 4;
        uint8_t *d = (uint8_t *)o->buffer + (size_t)(o->y_up ? y : fb->height - 1 - y) * stride;
        if (o->format == OSMESA_RGBA) {
            memcpy(d, s, (size_t)fb->width * 4);
            continue;
        }
        for (int x = 0; x < fb->width; x++, s += 4, d += bpp) {
            switch (o->format) {
            case OSMESA_BGRA: d[0] = s[2]; d[1] = s[1]; d[2] = s[0]; d[3] = s[3]; break;
            case OSMESA_ARGB: d[0] = s[3]; d[1] = s[0]; d[2] = s[1]; d[3] = s[2]; break;
            case OSMESA_RGB: d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; break;
            default: /* OSMESA_BGR */ d[0] = s[2]; d[1] = s[1]; d[2] = s[0]; break;
            }
        }
    }
}

/* ---- capture ---- */

static void capture_begin(struct osmesa_context *o, const char *path)
{
    char err[512];
    if (fs_capture_open(o->fs, path, err, sizeof err) != 0) {
        shim_message("FRAGSIM_TRACE: not capturing", err);
        return;
    }
    fsglViewport(o->fs, 0, 0, o->width, o->height);
    o->frame_open = 0;
}

/* FRAGSIM_TRACE_GPIO=CHIP:LINE: the input line that gates the capture
 * (docs/signals.md); 0 when there is none or it opened, -1 (printed) when
 * it cannot be read: then nothing is captured. */
static int gate_open(struct osmesa_context *o)
{
    const char *spec = getenv("FRAGSIM_TRACE_GPIO");
    if (!spec || !*spec || o->gate)
        return 0;
    char chip[256], err[512], *end;
    const char *colon = strrchr(spec, ':');
    unsigned long line = colon ? strtoul(colon + 1, &end, 10) : 0;
    if (!colon || colon == spec || !colon[1] || *end || (size_t)(colon - spec) >= sizeof chip) {
        shim_message("FRAGSIM_TRACE_GPIO: expected CHIP:LINE, not capturing", spec);
        return -1;
    }
    snprintf(chip, sizeof chip, "%.*s", (int)(colon - spec), spec);
    unsigned off = (unsigned)line;
    bool out = false;
    o->gate = fs_gpio_open(&fs_gpio_libgpiod, chip, 1, &off, &out, err, sizeof err);
    if (!o->gate) {
        shim_message("FRAGSIM_TRACE_GPIO: not capturing", err);
        return -1;
    }
    return 0;
}

/* The capture starts at the first OSMesaMakeCurrent or, with a gate line,
 * at the first of it and the glFinish calls at which the line is high. */
static void capture_start(struct osmesa_context *o)
{
    const char *path = getenv("FRAGSIM_TRACE");
    if (!path || !*path || gate_open(o) != 0)
        return;
    o->gate_waiting = o->gate && fs_gpio_get(o->gate, 0) != 1;
    if (!o->gate_waiting)
        capture_begin(o, path);
}

static void capture_finish(struct osmesa_context *o)
{
    if (!o->fs || !o->fs->capture)
        return;
    /* The calls after the last glFinish form a last frame, so that replay
     * shows what a program ending without glFinish drew. */
    if (o->frame_open)
        fs_capture_frame_end(o->fs);
    if (fs_capture_close(o->fs) != 0)
        shim_message("FRAGSIM_TRACE: writing the trace failed", getenv("FRAGSIM_TRACE"));
}

static void write_stats(struct osmesa_context *o)
{
    const char *path = getenv("FRAGSIM_STATS");
    if (!o->fs || !path || !*path)
        return;
    /* the "totals" and "errors" of fragsim replay's statistics file */
    json_t *doc = json_pack("{s:o}", "totals", fs_stats_json(&o->fs->stats));
    if (!doc || fs_error_log_json(&o->errs, doc) != 0 || json_dump_file(doc, path, JSON_INDENT(2)) != 0)
        shim_message("FRAGSIM_STATS: cannot write", path);
    json_decref(doc);
}

/* A context still current when the program exits (OSMesa programs rarely
 * destroy theirs) would leave an unfinished trace: finish it. */
__attribute__((destructor)) static void shim_at_exit(void)
{
    if (current) {
        capture_finish(current);
        write_stats(current);
    }
}

/* ---- hooks of the GL entry points (shim.h) ---- */

fs_context *fs_shim_begin(void)
{
    return current ? current->fs : NULL;
}

void fs_shim_end(enum fs_cmd cmd)
{
    struct osmesa_context *o = current;
    o->frame_open = 1;
    /* errors raised by this call (or by the lists a glCallList executes) */
    for (size_t i = o->errs_named; i < o->errs.n; i++)
        o->errs.entries[i].command = fs_cmd_table[cmd].name;
    o->errs_named = o->errs.n;
    o->errs.call++;
    switch (cmd) {
    case FS_CMD_Finish:
        copy_out(o);
        if (o->fs->capture) {
            fs_capture_frame_end(o->fs);
            o->frame_open = 0;
        } else if (o->gate_waiting) {
            capture_start(o);
        }
        break;
    case FS_CMD_Flush:
    case FS_CMD_ReadPixels:
        copy_out(o);
        break;
    default:
        break;
    }
}

/* ---- contexts ---- */

/* The model's framebuffer for OSMesa's depth and stencil requests, as
 * Mesa 22.3.6 chooses them (measured): a stencil buffer brings a 24-bit
 * depth buffer; up to 16 depth bits give 16, more give 24; stencil is 8 bits
 * or none.  The model always has a depth buffer: with depthBits 0 it keeps a
 * 24-bit one, so the depth test still tests where OSMesa's would pass (see
 * README: programs that enable GL_DEPTH_TEST without a depth buffer differ). */
static int make_config(struct osmesa_context *o, GLint depth, GLint stencil, GLint accum)
{
    fs_run_config_defaults(&o->cfg);
    const char *ini = getenv("FRAGSIM_CONFIG");
    char err[512];
    if (ini && *ini && fs_run_config_load(&o->cfg, ini, err, sizeof err) != 0) {
        shim_message("FRAGSIM_CONFIG", err);
        return -1;
    }
    /* FRAGSIM_THREADS=N: the context's raster.threads (0: the online CPUs;
     * pipeline/raster_threads.h); unset, the library's default of 1. */
    const char *th = getenv("FRAGSIM_THREADS");
    if (th && *th) {
        char *end;
        long n = strtol(th, &end, 10);
        if (*end || n < 0 || n > 8) {
            shim_message("FRAGSIM_THREADS", "expected 0 (the online CPUs) to 8");
            return -1;
        }
        o->cfg.gl.raster_threads = n;
    }
    o->has_depth = depth > 0;
    o->cfg.gl.framebuffer_depth_bits = depth <= 0 || stencil > 0 || depth > 16 ? 24 : 16;
    o->cfg.gl.framebuffer_stencil_bits = stencil > 0 ? 8 : 0;
    /* llvmpipe gives 16 bits a component for any accumBits above 0. */
    o->cfg.gl.framebuffer_accum_bits = accum > 0 ? 16 : 0;
    if (fs_run_config_check(&o->cfg, err, sizeof err) != 0) {
        shim_message("FRAGSIM_CONFIG", err);
        return -1;
    }
    return 0;
}

OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                GLint accumBits, OSMesaContext sharelist)
{
    /* No display lists shared between contexts: sharelist is ignored. */
    (void)sharelist;
    /* OSMESA_RGB_565 and OSMESA_COLOR_INDEX are not modelled. */
    if (format != OSMESA_RGBA && format != OSMESA_BGRA && format != OSMESA_ARGB &&
        format != OSMESA_RGB && format != OSMESA_BGR)
        return NULL;
    struct osmesa_context *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    if (make_config(o, depthBits, stencilBits, accumBits) != 0) {
        free(o);
        return NULL;
    }
    o->format = format;
    o->y_up = GL_TRUE;
    return o;
}

OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist)
{
    /* Mesa's OSMesaCreateContext asks for 24 depth and 8 stencil bits. */
    return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int *attribList, OSMesaContext sharelist)
{
    /* Mesa's defaults: RGBA, no depth, stencil or accumulation buffer. */
    GLenum format = OSMESA_RGBA;
    GLint depth = 0, stencil = 0, accum = 0;
    for (int i = 0; attribList && attribList[i]; i += 2) {
        switch (attribList[i]) {
        case OSMESA_FORMAT: format = (GLenum)attribList[i + 1]; break;
        case OSMESA_DEPTH_BITS: depth = attribList[i + 1]; break;
        case OSMESA_STENCIL_BITS: stencil = attribList[i + 1]; break;
        case OSMESA_ACCUM_BITS: accum = attribList[i + 1]; break;
        case OSMESA_PROFILE:
            /* The model is a GL 1.x compatibility context. */
            if (attribList[i + 1] == OSMESA_CORE_PROFILE)
                return NULL;
            break;
        case OSMESA_CONTEXT_MAJOR_VERSION:
        case OSMESA_CONTEXT_MINOR_VERSION:
            break;
        default:
            return NULL;
        }
    }
    return OSMesaCreateContextExt(format, depth, stencil, accum, sharelist);
}

GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext o, void *buffer, GLenum type, GLsizei width,
                                       GLsizei height)
{
    if (!o) {
        /* Releasing the current context: its buffer gets its pixels. */
        if (current)
            copy_out(current);
        current = NULL;
        return GL_TRUE;
    }
    if (!buffer || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 || width > SHIM_MAX_SIZE ||
        height > SHIM_MAX_SIZE)
        return GL_FALSE;
    if (current)
        copy_out(current);
    if (!o->fs) {
        o->fs = fs_context_create(&o->cfg.gl, width, height);
        if (!o->fs)
            return GL_FALSE;
        o->width = width;
        o->height = height;
        fs_error_log_attach(&o->errs, o->fs);
        o->errs_named = 0;
        capture_start(o);
    } else if (width != o->width || height != o->height) {
        /* A new size: the model's buffers start again (cleared), like a
         * resized OSMesa buffer whose contents are undefined.  A trace has
         * one window size, so a capture replays at the first size. */
        if (fs_context_resize(o->fs, width, height) != 0)
            return GL_FALSE;
        o->width = width;
        o->height = height;
    }
    o->buffer = buffer;
    o->type = type;
    current = o;
    return GL_TRUE;
}

OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void)
{
    return current;
}

void GLAPIENTRY OSMesaDestroyContext(OSMesaContext o)
{
    if (!o)
        return;
    if (o == current)
        current = NULL;
    capture_finish(o);
    write_stats(o);
    fs_gpio_close(o->gate);
    fs_context_destroy(o->fs);
    fs_error_log_free(&o->errs);
    free(o->depth_copy);
    free(o);
}

/* An error of an OSMesa function: listed under that function's name, with
 * the number the next GL call will have. */
static void osmesa_error(struct osmesa_context *o, GLenum err, const char *fn)
{
    fs_error(o->fs, err);
    for (size_t i = o->errs_named; i < o->errs.n; i++)
        o->errs.entries[i].command = fn;
    o->errs_named = o->errs.n;
}

void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value)
{
    struct osmesa_context *o = current;
    if (!o)
        return;
    switch (pname) {
    case OSMESA_ROW_LENGTH:
        if (value < 0) {
            osmesa_error(o, GL_INVALID_VALUE, "OSMesaPixelStore");
            return;
        }
        o->row_length = value;
        break;
    case OSMESA_Y_UP:
        o->y_up = value ? GL_TRUE : GL_FALSE;
        break;
    default:
        osmesa_error(o, GL_INVALID_ENUM, "OSMesaPixelStore");
        break;
    }
}

void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint *value)
{
    struct osmesa_context *o = current;
    switch (pname) {
    case OSMESA_WIDTH: *value = o ? o->width : 0; break;
    case OSMESA_HEIGHT: *value = o ? o->height : 0; break;
    case OSMESA_FORMAT: *value = o ? (GLint)o->format : 0; break;
    case OSMESA_TYPE: *value = o ? (GLint)o->type : 0; break;
    case OSMESA_ROW_LENGTH: *value = o ? o->row_length : 0; break;
    case OSMESA_Y_UP: *value = o ? o->y_up : 0; break;
    case OSMESA_MAX_WIDTH:
    case OSMESA_MAX_HEIGHT: *value = SHIM_MAX_SIZE; break;
    default:
        if (o)
            osmesa_error(o, GL_INVALID_ENUM, "OSMesaGetIntegerv");
        break;
    }
}

GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext o, GLint *width, GLint *height,
                                          GLint *format, void **buffer)
{
    if (!o || !o->buffer) {
        *width = *height = *format = 0;
        *buffer = NULL;
        return GL_FALSE;
    }
    copy_out(o);
    *width = o->width;
    *height = o->height;
    *format = (GLint)o->format;
    *buffer = o->buffer;
    return GL_TRUE;
}

/* Depth values as OSMesa (Mesa 22.3.6, llvmpipe) hands them out, measured:
 * bottom row first; 2 bytes per value for a 16-bit depth buffer without
 * stencil, otherwise 4 bytes with the depth in the low 24 bits and the
 * stencil value in the high 8.  The values are a copy taken now: unlike
 * OSMesa's pointer, it does not follow later rendering. */
GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext o, GLint *width, GLint *height,
                                          GLint *bytesPerValue, void **buffer)
{
    *width = *height = *bytesPerValue = 0;
    *buffer = NULL;
    if (!o || !o->fs || !o->has_depth)
        return GL_FALSE;
    const fs_framebuffer *fb = &o->fs->fb;
    size_t n = (size_t)fb->width * (size_t)fb->height;
    int bpv = fb->depth_bits == 16 && fb->stencil_bits == 0 ? 2 : 4;
    void *copy = realloc(o->depth_copy, n * (size_t)bpv);
    if (!copy)
        return GL_FALSE;
    o->depth_copy = copy;
    for (size_t i = 0; i < n; i++) {
        if (bpv == 2)
            ((uint16_t *)copy)[i] = (uint16_t)fb->depth[i];
        else
            ((uint32_t *)copy)[i] = fb->depth[i] | (fb->stencil_bits ? (uint32_t)fb->stencil[i] << 24 : 0);
    }
    *width = fb->width;
    *height = fb->height;
    *bytesPerValue = bpv;
    *buffer = copy;
    return GL_TRUE;
}

/* Accepted for source compatibility: the model always clamps colours, as
 * fixed-function GL 1.x does, and has no post-processing filters. */
void GLAPIENTRY OSMesaColorClamp(GLboolean enable)
{
    (void)enable;
}

void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char *filter, unsigned enable_value)
{
    (void)osmesa;
    (void)filter;
    (void)enable_value;
}

OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char *funcName)
{
    /* GL names come from the command table (shim_gl.c); OSMesa's own
     * functions are listed here, as Mesa's OSMesaGetProcAddress lists them. */
    /* Through void (*)(void), the type that converts to any function
     * pointer type without -Wcast-function-type complaining. */
#define OWN(f) (OSMESAproc)(void (*)(void))(f)
    static const struct {
        const char *name;
        OSMESAproc proc;
    } own[] = {
        {"OSMesaCreateContext", OWN(OSMesaCreateContext)},
        {"OSMesaCreateContextExt", OWN(OSMesaCreateContextExt)},
        {"OSMesaCreateContextAttribs", OWN(OSMesaCreateContextAttribs)},
        {"OSMesaDestroyContext", OWN(OSMesaDestroyContext)},
        {"OSMesaMakeCurrent", OWN(OSMesaMakeCurrent)},
        {"OSMesaGetCurrentContext", OWN(OSMesaGetCurrentContext)},
        {"OSMesaPixelStore", OWN(OSMesaPixelStore)},
        {"OSMesaGetIntegerv", OWN(OSMesaGetIntegerv)},
        {"OSMesaGetDepthBuffer", OWN(OSMesaGetDepthBuffer)},
        {"OSMesaGetColorBuffer", OWN(OSMesaGetColorBuffer)},
        {"OSMesaGetProcAddress", OWN(OSMesaGetProcAddress)},
        {"OSMesaColorClamp", OWN(OSMesaColorClamp)},
        {"OSMesaPostprocess", OWN(OSMesaPostprocess)},
    };
#undef OWN
    if (!funcName)
        return NULL;
    for (size_t i = 0; i < sizeof own / sizeof own[0]; i++)
        if (strcmp(own[i].name, funcName) == 0)
            return own[i].proc;
    return (OSMESAproc)fs_shim_gl_proc(funcName);
}
