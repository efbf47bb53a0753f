/*
 * Capture mode: the calls submitted to a context, written as an apitrace
 * trace that `apitrace dump` prints like one apitrace made and that
 * fs_trace_next reads back.
 *
 * Values are written the way apitrace's GL tracer writes each parameter
 * type (specs/glapi.py, wrappers/gltrace.py): GLenum as an enum with its
 * name, GLboolean as an enum {GL_FALSE, GL_TRUE}, glClear's mask as a
 * bitmask, signed integers as SINT, unsigned as UINT, pointers to input
 * arrays as arrays, index and list blobs as blobs, outputs in the leave event.
 *
 * Client arrays in user memory: apitrace does not record gl*Pointer calls on
 * them; before
 * each draw it writes, per enabled array, a fake gl*Pointer call (call detail
 * flags = FLAG_FAKE) whose pointer is a blob covering the vertices the draw
 * reads (wrappers/gltrace.py _trace_user_arrays, in its order: texture
 * coordinates, colour, normal, vertex).  Capture does the same.  Like
 * apitrace, glArrayElement gets no array data (apitrace warns "user arrays
 * with glArrayElement not supported").  Arrays and indices in buffer
 * objects (GL 1.5 spec 2.9) are recorded as apitrace records them: the
 * pointer calls with their offsets, no fake calls, and the writes through a
 * mapping as a fake memcpy(dest, src, n) of the whole mapping before its
 * glUnmapBuffer (apitrace's _glUnmapBuffer_flush: dest is the address
 * glMapBuffer returned).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../pipeline/context.h"
#include "../pipeline/buffer_object.h"
#include "capture.h"
#include "trace.h"
#include "gl_enums.h"

struct fs_capture {
    fs_trace_writer *w;
    int failed;
    fs_tval *scratch;      /* elements of array arguments of the call being written */
    size_t scratch_cap;
    /* The mappings of GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER, written
     * out at their glUnmapBuffer. */
    struct { const void *p; int64_t size; } map[2];
};

static const char *const bool_names[] = {"GL_FALSE", "GL_TRUE"};
static const int64_t bool_values[] = {GL_FALSE, GL_TRUE};
static const fs_tsig bool_sig = {"GLboolean", 2, bool_names, bool_values};

/* glClear's mask bits (GL 1.5 spec 4.2.3). */
static const char *const clear_names[] = {"GL_DEPTH_BUFFER_BIT", "GL_ACCUM_BUFFER_BIT",
                                          "GL_STENCIL_BUFFER_BIT", "GL_COLOR_BUFFER_BIT"};
static const int64_t clear_values[] = {GL_DEPTH_BUFFER_BIT, GL_ACCUM_BUFFER_BIT,
                                       GL_STENCIL_BUFFER_BIT, GL_COLOR_BUFFER_BIT};
static const fs_tsig clear_sig = {"GLbitfield", 4, clear_names, clear_values};

static void write_call(fs_context *c, const fs_tcall *tc)
{
    struct fs_capture *cap = c->capture;
    if (!cap->failed && fs_trace_write(cap->w, tc) != 0)
        cap->failed = 1;
}

/* A call fragsim makes up (a frame end, a mapping's memcpy). */
static void write_args(fs_context *c, const char *name, unsigned n, const char *const *names, const fs_tval *args,
                       uint32_t flags)
{
    fs_tcall tc;
    memset(&tc, 0, sizeof tc);
    tc.name = name;
    tc.nargs = n;
    tc.arg_names = names;
    tc.args = args;
    tc.flags = flags;
    write_call(c, &tc);
}

int fs_capture_open(fs_context *c, const char *path, char *err, size_t errlen)
{
    if (c->capture) {
        if (err && errlen)
            snprintf(err, errlen, "%s: the context is already capturing", path);
        return -1;
    }
    struct fs_capture *cap = calloc(1, sizeof *cap);
    if (!cap) {
        if (err && errlen)
            snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    cap->w = fs_trace_create(path, err, errlen);
    if (!cap->w) {
        free(cap);
        return -1;
    }
    c->capture = cap;
    return 0;
}

static fs_tval enum_val(const char *cmd, const char *arg, int64_t v)
{
    fs_tval t;
    memset(&t, 0, sizeof t);
    t.type = FS_TV_ENUM;
    t.i = v;
    t.enum_name = fs_gl_enum_name_for(cmd, arg, (uint32_t)v);
    return t;
}

static fs_tval bool_val(int64_t v)
{
    fs_tval t;
    memset(&t, 0, sizeof t);
    t.type = FS_TV_ENUM;
    t.i = v;
    t.sig = &bool_sig;
    t.enum_name = v == GL_FALSE ? "GL_FALSE" : v == GL_TRUE ? "GL_TRUE" : NULL;
    return t;
}

/* Vertices a draw reads from the arrays, as apitrace's _glDraw_count
 * (wrappers/gltrace_arrays.cpp) computes them. */
static uint64_t draw_vertex_count(const fs_call *call)
{
    switch (call->cmd) {
    case FS_CMD_DrawArrays:
        return call->a[2].i > 0 ? (uint64_t)(uint32_t)call->a[1].i + (uint64_t)call->a[2].i : 0;
    case FS_CMD_DrawRangeElements: {
        uint32_t start = (uint32_t)call->a[1].i, end = (uint32_t)call->a[2].i;
        if (end < start || call->a[3].i <= 0)
            return 0;
        return (uint64_t)end + 1;
    }
    case FS_CMD_DrawElements:
    case FS_CMD_MultiDrawArrays: {
        int64_t lo, hi; /* apitrace: the highest index + 1 */
        return fs_draw_vertex_range(call, &lo, &hi) ? (uint64_t)hi + 1 : 0;
    }
    default:
        return 0;
    }
}

static void write_fake_pointer(fs_context *c, int cmd, const fs_client_array *a, uint64_t count)
{
    const fs_cmd_info *info = &fs_cmd_table[cmd];
    fs_tval args[4];
    unsigned n = 0;
    memset(args, 0, sizeof args);
    int esize = fs_type_size(a->type) * (cmd == FS_CMD_NormalPointer ? 3 : a->size);
    uint64_t stride = a->stride ? (uint64_t)(uint32_t)a->stride : (uint64_t)esize;
    if (cmd != FS_CMD_NormalPointer) {
        args[n].type = FS_TV_SINT;
        args[n++].i = a->size;
    }
    args[n++] = enum_val(info->name, "type", a->type);
    args[n].type = FS_TV_SINT;
    args[n++].i = a->stride;
    /* glsize.hpp _glArrayPointer_size: stride * (count - 1) + element size. */
    uint64_t bytes = count ? stride * (count - 1) + (uint64_t)esize : 0;
    if (a->pointer) {
        args[n].type = FS_TV_BLOB;
        args[n].str.ptr = a->pointer;
        args[n].str.len = (size_t)bytes;
    } else {
        args[n].type = FS_TV_NULL;
    }
    n++;
    fs_tcall tc;
    memset(&tc, 0, sizeof tc);
    tc.name = info->name;
    tc.nargs = n;
    tc.arg_names = info->argnames;
    tc.args = args;
    tc.flags = FS_TCALL_FAKE;
    write_call(c, &tc);
}

/* glClientActiveTexture(texture) as a fake call, around the texture
 * coordinate pointers of units other than the client active one. */
static void write_fake_client_unit(fs_context *c, int unit)
{
    const fs_cmd_info *info = &fs_cmd_table[FS_CMD_ClientActiveTexture];
    fs_tval arg = enum_val(info->name, "texture", GL_TEXTURE0 + unit);
    fs_tcall tc;
    memset(&tc, 0, sizeof tc);
    tc.name = info->name;
    tc.nargs = 1;
    tc.arg_names = info->argnames;
    tc.args = &arg;
    tc.flags = FS_TCALL_FAKE;
    write_call(c, &tc);
}

/* The fake pointer calls of every unit's enabled texture coordinate array
 * of client memory (GL 1.5 spec 2.8: each unit's, selected by
 * glClientActiveTexture, which is set back after). */
static void write_fake_texcoords(fs_context *c, uint64_t n)
{
    int active = fs_client_active_unit(c), selected = active;
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        const fs_client_array *a = &c->arrays.texcoord[u];
        if (!a->enabled || a->buffer)
            continue;
        if (u != selected)
            write_fake_client_unit(c, selected = u);
        write_fake_pointer(c, FS_CMD_TexCoordPointer, a, n);
    }
    if (selected != active)
        write_fake_client_unit(c, active);
}

/* memcpy(dest, src, n) of a mapping, as apitrace writes it (a fake call). */
static void write_memcpy(fs_context *c, const void *p, int64_t n)
{
    static const char *const names[3] = {"dest", "src", "n"};
    fs_tval args[3];
    memset(args, 0, sizeof args);
    args[0].type = FS_TV_OPAQUE;
    args[0].u = (uint64_t)(uintptr_t)p;
    args[1].type = FS_TV_BLOB;
    args[1].str.ptr = p;
    args[1].str.len = (size_t)n;
    args[2].type = FS_TV_UINT;
    args[2].u = (uint64_t)n;
    write_args(c, "memcpy", 3, names, args, FS_TCALL_FAKE);
}

/* What capture does about buffer objects before writing `call`; false when
 * the call is not written now (a pointer call on user memory). */
static bool buffer_calls(fs_context *c, const fs_call *call)
{
    struct fs_capture *cap = c->capture;
    int t = call->nargs > 0 && call->a[0].i == GL_ELEMENT_ARRAY_BUFFER ? 1 : 0;
    int pk, slot = fs_pointer_slot(call->cmd, &pk);
    if (slot >= 0) {
        int k = fs_array_of_slot(slot, fs_client_active_unit(c)); /* texcoords: the client unit's (2.8) */
        return fs_client_array_at(&c->arrays, k)->buffer != 0; /* else written as fake calls before the draws */
    }
    switch (call->cmd) {
    case FS_CMD_MapBuffer: case FS_CMD_MapBufferRange:
        cap->map[t].p = fs_buffer_mapping(c, (GLenum)call->a[0].i, &cap->map[t].size);
        break;
    case FS_CMD_UnmapBuffer:
        if (cap->map[t].p && call->ret.i == GL_TRUE)
            write_memcpy(c, cap->map[t].p, cap->map[t].size);
        cap->map[t].p = NULL;
        break;
    case FS_CMD_BufferData: case FS_CMD_DeleteBuffers:
        cap->map[0].p = cap->map[1].p = NULL; /* a store a mapping pointed at may be gone */
        break;
    default:
        break;
    }
    return true;
}

/* The indices of glDrawElements/glDrawRangeElements at an offset into the
 * element array buffer: *local then points at them, for the vertex count
 * of the fake calls; false when there is none such. */
static bool element_indices(const fs_context *c, const fs_call *call, fs_call *local)
{
    int k = call->cmd == FS_CMD_DrawElements ? 3 : call->cmd == FS_CMD_DrawRangeElements ? 5 : -1;
    if (k < 0 || !c->arrays.element_buffer)
        return false;
    size_t bytes;
    *local = *call;
    local->a[k].p = fs_buffer_element_data(c, (uint64_t)(uintptr_t)call->a[k].p, &bytes);
    local->a[k].count = bytes > UINT32_MAX ? UINT32_MAX : (uint32_t)bytes;
    return true;
}

static int is_array_kind(int k)
{
    return k == FS_K_AF || k == FS_K_AD || k == FS_K_AI || k == FS_K_AU || k == FS_K_AUB ||
           k == FS_K_ABY || k == FS_K_AS || k == FS_K_AUS || k == FS_K_OF || k == FS_K_OD ||
           k == FS_K_OI || k == FS_K_OU || k == FS_K_OUS || k == FS_K_OB;
}

/* One array element of kind k at index i of p. */
static fs_tval array_elem(int k, const void *p, size_t i)
{
    fs_tval t;
    memset(&t, 0, sizeof t);
    switch (k) {
    case FS_K_AF: case FS_K_OF:
        t.type = FS_TV_FLOAT; t.d = ((const GLfloat *)p)[i]; break;
    case FS_K_AD: case FS_K_OD:
        t.type = FS_TV_DOUBLE; t.d = ((const GLdouble *)p)[i]; break;
    case FS_K_AI: case FS_K_OI:
        t.type = FS_TV_SINT; t.i = ((const GLint *)p)[i]; break;
    case FS_K_AU: case FS_K_OU:
        t.type = FS_TV_UINT; t.u = ((const GLuint *)p)[i]; break;
    case FS_K_AUB:
        t.type = FS_TV_UINT; t.u = ((const GLubyte *)p)[i]; break;
    case FS_K_ABY:
        t.type = FS_TV_SINT; t.i = ((const GLbyte *)p)[i]; break;
    case FS_K_AS:
        t.type = FS_TV_SINT; t.i = ((const GLshort *)p)[i]; break;
    case FS_K_AUS: case FS_K_OUS:
        t.type = FS_TV_UINT; t.u = ((const GLushort *)p)[i]; break;
    case FS_K_OB:
        t = bool_val(((const GLboolean *)p)[i]); break;
    default:
        t.type = FS_TV_NULL; break;
    }
    return t;
}

static fs_tval scalar_val(const fs_cmd_info *info, int k, const char *argname, const fs_arg *a)
{
    fs_tval t;
    memset(&t, 0, sizeof t);
    switch (k) {
    case FS_K_E:
        return enum_val(info->name, argname, a->i);
    case FS_K_B:
        return bool_val(a->i);
    case FS_K_BM:
        t.type = FS_TV_BITMASK;
        t.u = (uint64_t)(uint32_t)a->i;
        t.sig = &clear_sig;
        return t;
    case FS_K_I: case FS_K_SZ: case FS_K_BY: case FS_K_S: case FS_K_IP:
        t.type = FS_TV_SINT;
        t.i = a->i;
        return t;
    case FS_K_U: case FS_K_UB: case FS_K_US:
        t.type = FS_TV_UINT;
        t.u = (uint64_t)a->i;
        return t;
    case FS_K_F: case FS_K_CF:
        t.type = FS_TV_FLOAT;
        t.d = a->d;
        return t;
    case FS_K_D: case FS_K_CD:
        t.type = FS_TV_DOUBLE;
        t.d = a->d;
        return t;
    case FS_K_BLOB:
        if (!a->p)
            break;
        t.type = FS_TV_BLOB;
        t.str.ptr = a->p;
        t.str.len = a->count;
        return t;
    case FS_K_CPTR:
        if (a->is_data == FS_ARG_DATA && a->p) {
            t.type = FS_TV_BLOB;
            t.str.ptr = a->p;
            t.str.len = a->count;
            return t;
        }
        if (!a->p)
            break;
        t.type = FS_TV_OPAQUE;
        t.u = (uint64_t)(uintptr_t)a->p;
        return t;
    case FS_K_OV: case FS_K_OUB: case FS_K_P:
        /* apitrace writes glReadPixels' pixels (Out(GLpointer)) as an opaque
         * pointer, and glMapBuffer's result. */
        if (!a->out)
            break;
        t.type = FS_TV_OPAQUE;
        t.u = (uint64_t)(uintptr_t)a->out;
        return t;
    case FS_K_STR:
        if (!a->p)
            break;
        t.type = FS_TV_STRING;
        t.str.ptr = a->p;
        t.str.len = strlen(a->p);
        return t;
    default:
        break;
    }
    t.type = FS_TV_NULL;
    return t;
}

void fs_capture_call(fs_context *c, const fs_call *call)
{
    struct fs_capture *cap = c->capture;
    if (!cap || cap->failed || call->cmd >= FS_CMD_COUNT)
        return;
    const fs_cmd_info *info = &fs_cmd_table[call->cmd];

    if (!buffer_calls(c, call))
        return;
    fs_call resolved;
    bool offset_indices = element_indices(c, call, &resolved);
    if ((info->flags & FS_F_DRAW) && call->cmd != FS_CMD_ArrayElement) {
        uint64_t n = draw_vertex_count(offset_indices ? &resolved : call);
        const fs_array_state *ar = &c->arrays;
        write_fake_texcoords(c, n);
        if (ar->color.enabled && !ar->color.buffer)
            write_fake_pointer(c, FS_CMD_ColorPointer, &ar->color, n);
        if (ar->normal.enabled && !ar->normal.buffer)
            write_fake_pointer(c, FS_CMD_NormalPointer, &ar->normal, n);
        if (ar->vertex.enabled && !ar->vertex.buffer)
            write_fake_pointer(c, FS_CMD_VertexPointer, &ar->vertex, n);
    }

    size_t need = 0;
    for (unsigned i = 0; i < info->nargs; i++)
        if (is_array_kind(info->kinds[i]) && call->a[i].p)
            need += call->a[i].count;
    if (need > cap->scratch_cap) {
        fs_tval *ns = realloc(cap->scratch, need * sizeof *ns);
        if (!ns) {
            cap->failed = 1;
            return;
        }
        cap->scratch = ns;
        cap->scratch_cap = need;
    }

    fs_tval args[FS_MAX_ARGS];
    fs_tcall tc;
    memset(&tc, 0, sizeof tc);
    size_t used = 0;
    for (unsigned i = 0; i < info->nargs; i++) {
        int k = info->kinds[i];
        const fs_arg *a = &call->a[i];
        if (k == FS_K_OV || k == FS_K_OF || k == FS_K_OD || k == FS_K_OI || k == FS_K_OU || k == FS_K_OUS || k == FS_K_OB ||
            k == FS_K_OUB)
            tc.out_args |= 1ull << i;
        if (is_array_kind(k)) {
            memset(&args[i], 0, sizeof args[i]);
            if (!a->p) {
                args[i].type = FS_TV_NULL;
                continue;
            }
            args[i].type = FS_TV_ARRAY;
            args[i].arr.elems = cap->scratch + used;
            args[i].arr.n = a->count;
            for (uint32_t e = 0; e < a->count; e++)
                cap->scratch[used++] = array_elem(k, a->p, e);
        } else if (k == FS_K_BLOB && offset_indices) {
            /* an offset into the element array buffer: a pointer value */
            fs_arg addr = *a;
            addr.is_data = 0;
            args[i] = scalar_val(info, FS_K_CPTR, info->argnames[i], &addr);
        } else {
            args[i] = scalar_val(info, k, info->argnames[i], a);
        }
    }
    tc.name = info->name;
    tc.nargs = info->nargs;
    tc.arg_names = info->argnames;
    tc.args = args;
    tc.flags = (call->flags & FS_CALL_FAKE) ? FS_TCALL_FAKE : 0;
    if (info->ret != FS_K_V) {
        tc.has_ret = 1;
        if (info->ret == FS_K_E)
            tc.ret = enum_val(info->name, NULL, call->ret.i);
        else
            tc.ret = scalar_val(info, info->ret, NULL, &call->ret);
    }
    write_call(c, &tc);
}

void fs_capture_frame_end(fs_context *c)
{
    if (!c->capture)
        return;
    /* glXSwapBuffers(dpy, drawable): fragsim has no X display or drawable,
     * so both are written as zero (apitrace writes a null pointer as NULL). */
    static const char *const names[] = {"dpy", "drawable"};
    fs_tval args[2];
    memset(args, 0, sizeof args);
    args[0].type = FS_TV_NULL;
    args[1].type = FS_TV_UINT;
    write_args(c, "glXSwapBuffers", 2, names, args, 0);
}

int fs_capture_close(fs_context *c)
{
    struct fs_capture *cap = c->capture;
    if (!cap)
        return -1;
    int rc = fs_trace_finish(cap->w) == 0 && !cap->failed ? 0 : -1;
    free(cap->scratch);
    free(cap);
    c->capture = NULL;
    return rc;
}
