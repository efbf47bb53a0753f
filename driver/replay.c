/*
 * Trace replay: apitrace calls -> fs_call.  See replay.h for the two passes.
 *
 * Client arrays: apitrace records glXxxPointer with the program's address
 * (an opaque pointer, useless here) and, before each draw, a "fake"
 * glXxxPointer call whose pointer argument is a blob with the vertex data
 * the draw reads.  The replayer skips (and counts) a draw whose enabled
 * arrays it does not see backed by recorded data covering every vertex it
 * reads.  That is a report, not the safety: the dispatcher copies each
 * blob GL accepts into the context and refuses any draw that would read
 * past it (dispatch.c), so a trace can never make the model read foreign
 * memory, even where GL rejects a pointer call the replayer counted.
 */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "replay.h"
#include "trace.h"
#include "callset.h"
#include "json_text.h"
#include "../pipeline/rasterizer.h"
#include "../pipeline/vertex_stage.h" /* FS_CLIENT_ARRAYS, fs_array_of_slot */

enum skip_kind { SKIP_UNKNOWN, SKIP_UNSAFE, SKIP_WINSYS };

typedef struct skip_entry {
    char *name;
    uint64_t count;
    enum skip_kind kind;
} skip_entry;

typedef struct arena_chunk {
    struct arena_chunk *next;
    size_t size, used;
    _Alignas(16) unsigned char data[];
} arena_chunk;

/* What the replayer knows of one client array, to check draws. */
typedef struct array_track {
    bool enabled, has_data;
    GLint size;
    GLenum type;
    GLsizei stride;
    size_t bytes; /* of the last pointer call's data */
} array_track;

/* In fs_client_array_at's order: fs_pointer_slot's, with one texture
 * coordinate array per unit (GL 1.5 spec 2.8: glClientActiveTexture selects
 * the one the pointer and client-state calls name). */
enum {
    ARR_VERTEX, ARR_NORMAL, ARR_COLOR, ARR_TEXCOORD,
    ARR_SECONDARY = ARR_TEXCOORD + FS_MAX_TEXTURE_UNITS, ARR_FOG, ARR_EDGE, ARR_INDEX, ARR_COUNT
};
_Static_assert(ARR_COUNT == FS_CLIENT_ARRAYS, "one tracked array per client array");

/* What the replayer knows of buffer objects (GL 1.5 spec 2.9), to turn
 * apitrace's memcpy(dest, src, n) pseudo-calls (writes through a mapping,
 * dest an address the traced program had) into glTraceMemcpy(buffer,
 * offset, ...): the buffers bound to the two targets, and the mappings the
 * trace's glMapBuffer results made. */
#define MAX_MAPS 16
typedef struct buffer_track {
    GLuint bound[2]; /* GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER */
    struct { uint64_t addr; GLuint buffer; } map[MAX_MAPS];
    int nmap;
} buffer_track;

struct fs_replayer {
    char *path;
    fs_trace_reader *tr;
    fs_replay_info info;
    bool frame_end_is_swap; /* any of the swap calls ends a frame */
    int frame_end_cmd;      /* -1, or an fs_cmd that ends frames */
    bool pending_frame_end;
    uint64_t calls_since_frame;
    uint64_t frames_done;
    uint64_t p1_swaps, p1_finishes, p1_named; /* pass 1 counts */
    /* Pass 1's signatures of each frame's work (fs_replay_frame_signatures),
     * for each way of ending frames (swap, the named call, glFinish): the
     * open frame's and the ended frames'. */
    struct frame_sigs {
        uint64_t kind, exact;    /* the open frame's */
        uint64_t *k, *e;         /* per ended frame */
        size_t n, cap;
        bool failed;             /* out of memory: none */
    } sigs[3];
    int sig_end;                 /* the sigs[] of the frame end chosen */
    const char *user_frame_end;
    char err[512];
    skip_entry *skips;
    size_t nskips, skips_cap;
    arena_chunk *arena;
    array_track arr[ARR_COUNT];
    int client_unit; /* glClientActiveTexture's unit */
    buffer_track buf;
    /* name -> command id, open addressing */
    struct { const char *name; int cmd; } *names;
    size_t nnames;
    /* Per call name of this pass, what next_call asks of it (name_info). */
    struct name_info *seen;
    size_t nseen, seen_cap;
    /* Pass 1's decoded calls, replayed by pass 2 instead of decoding the
     * file again (see "the decoded trace" below). */
    fs_trace_reader *rec_tr; /* pass 1's reader, kept for its name strings */
    fs_trace_parser parser;  /* fs_replay_opts.parser, for every pass */
    struct rec_block *rec, *rec_last, *rec_at;
    size_t rec_pos, rec_bytes, rec_max;
    bool rec_on;   /* pass 1 is recording; info.from_record: pass 2 reads the record */
    struct name_info *cmd_info; /* pass 2 from the record: name_info per command */
    /* Pass 2's last call: its number as apitrace numbers calls (the order
     * of enter events, which is the order the reader returns them in), its
     * name in the trace and its apitrace call flags (callset.h). */
    uint64_t call_no, p2_calls;
    const char *call_name;
    unsigned call_flags;
    bool report_skipped;  /* fs_replay_opts.report_skipped */
};

static const char *const swap_calls[] = {
    "glXSwapBuffers", "glXSwapBuffersMscOML", "eglSwapBuffers", "eglSwapBuffersWithDamageEXT",
    "eglSwapBuffersWithDamageKHR", "wglSwapBuffers", "wglSwapLayerBuffers", "SwapBuffers",
    "CGLFlushDrawable",
};

static bool is_swap(const char *name)
{
    for (size_t i = 0; i < sizeof swap_calls / sizeof swap_calls[0]; i++)
        if (strcmp(name, swap_calls[i]) == 0)
            return true;
    return false;
}

static bool is_winsys(const char *name)
{
    return !strncmp(name, "glX", 3) || !strncmp(name, "egl", 3) || !strncmp(name, "wgl", 3) ||
           !strncmp(name, "CGL", 3) || !strncmp(name, "OSMesa", 6);
}

/* ---- name lookup ---- */

static uint64_t hash_str(const char *s)
{
    uint64_t h = 1469598103934665603ull; /* FNV-1a */
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211ull;
    return h;
}

static int build_names(fs_replayer *r)
{
    r->nnames = 1024; /* > 2x the command count */
    r->names = calloc(r->nnames, sizeof *r->names);
    if (!r->names)
        return -1;
    for (int i = 0; i < FS_CMD_COUNT; i++) {
        size_t j = hash_str(fs_cmd_table[i].name) & (r->nnames - 1);
        while (r->names[j].name)
            j = (j + 1) & (r->nnames - 1);
        r->names[j].name = fs_cmd_table[i].name;
        r->names[j].cmd = i;
    }
    /* apitrace's memcpy pseudo-call (see buffer_track). */
    size_t j = hash_str("memcpy") & (r->nnames - 1);
    while (r->names[j].name)
        j = (j + 1) & (r->nnames - 1);
    r->names[j].name = "memcpy";
    r->names[j].cmd = FS_CMD_TraceMemcpy;
    return 0;
}

static int lookup(const fs_replayer *r, const char *name)
{
    for (size_t j = hash_str(name) & (r->nnames - 1);; j = (j + 1) & (r->nnames - 1)) {
        if (!r->names[j].name)
            return -1;
        if (strcmp(r->names[j].name, name) == 0)
            return r->names[j].cmd;
    }
}

/* The reader hands out one name string per function signature for the
 * whole pass, so its address identifies the name: the string compares and
 * hashing of lookup(), is_swap() and the frame-end test run once per name
 * instead of once per call (they were a fifth of decoding). */
typedef struct name_info {
    const char *name; /* the reader's string; NULL: empty slot */
    int cmd;
    bool swap, winsys, user_end, frame_end;
    unsigned flags; /* apitrace's call flags (fs_call_flags) */
} name_info;

/* The slot of `name` in a table of cap (a power of two) entries: its own
 * or the empty one where it would go (linear probing). */
static size_t seen_slot(const name_info *t, size_t cap, const char *name)
{
    uint64_t h = (uint64_t)(uintptr_t)name * 0x9e3779b97f4a7c15ull;
    size_t j = (size_t)(h >> 32) & (cap - 1);
    while (t[j].name && t[j].name != name)
        j = (j + 1) & (cap - 1);
    return j;
}

static void name_info_fill(const fs_replayer *r, name_info *ni, const char *name, int cmd)
{
    ni->name = name;
    ni->cmd = cmd;
    ni->swap = is_swap(name);
    ni->winsys = is_winsys(name);
    ni->user_end = r->user_frame_end && !strcmp(name, r->user_frame_end);
    ni->frame_end = !strcmp(name, r->info.frame_end);
    ni->flags = fs_call_flags(name);
}

static const name_info *name_info_of(fs_replayer *r, const char *name)
{
    if (r->seen_cap) {
        const name_info *ni = &r->seen[seen_slot(r->seen, r->seen_cap, name)];
        if (ni->name)
            return ni;
    }
    if (2 * (r->nseen + 1) > r->seen_cap) {
        size_t cap = r->seen_cap ? 2 * r->seen_cap : 256;
        name_info *t = calloc(cap, sizeof *t);
        if (!t)
            return NULL;
        for (size_t i = 0; i < r->seen_cap; i++)
            if (r->seen[i].name)
                t[seen_slot(t, cap, r->seen[i].name)] = r->seen[i];
        free(r->seen);
        r->seen = t;
        r->seen_cap = cap;
    }
    name_info *ni = &r->seen[seen_slot(r->seen, r->seen_cap, name)];
    name_info_fill(r, ni, name, lookup(r, name));
    r->nseen++;
    return ni;
}

static void forget_names(fs_replayer *r)
{
    free(r->seen);
    r->seen = NULL;
    r->nseen = r->seen_cap = 0;
}

/* ---- bookkeeping ---- */

static void count_skip(fs_replayer *r, const char *name, enum skip_kind kind)
{
    for (size_t i = 0; i < r->nskips; i++) {
        if (r->skips[i].kind == kind && strcmp(r->skips[i].name, name) == 0) {
            r->skips[i].count++;
            return;
        }
    }
    if (r->nskips == r->skips_cap) {
        size_t cap = r->skips_cap ? r->skips_cap * 2 : 16;
        skip_entry *s = realloc(r->skips, cap * sizeof *s);
        if (!s)
            return;
        r->skips = s;
        r->skips_cap = cap;
    }
    char *copy = strdup(name);
    if (!copy)
        return;
    r->skips[r->nskips++] = (skip_entry){copy, 1, kind};
}

static void *arena_alloc(fs_replayer *r, size_t bytes)
{
    bytes = (bytes + 15) & ~(size_t)15;
    arena_chunk *c = r->arena;
    if (!c || c->size - c->used < bytes) {
        size_t size = bytes > (1u << 20) ? bytes : (1u << 20);
        c = malloc(sizeof *c + size);
        if (!c)
            return NULL;
        c->next = r->arena;
        c->size = size;
        c->used = 0;
        r->arena = c;
    }
    void *p = c->data + c->used;
    c->used += bytes;
    return p;
}

static void arena_reset(fs_replayer *r)
{
    /* Keep the newest chunk (the largest working set), free the rest. */
    arena_chunk *c = r->arena;
    if (!c)
        return;
    arena_chunk *rest = c->next;
    c->next = NULL;
    c->used = 0;
    while (rest) {
        arena_chunk *n = rest->next;
        free(rest);
        rest = n;
    }
}

static int fail(fs_replayer *r, const fs_tcall *tc, const char *fmt, const char *detail)
{
    char what[256];
    snprintf(what, sizeof what, fmt, detail);
    snprintf(r->err, sizeof r->err, "%s: call %llu (%s) at stream offset %llu: %s", r->path,
             (unsigned long long)tc->no, tc->name, (unsigned long long)tc->offset, what);
    return -1;
}

/* ---- value conversion ---- */

static bool tv_int(const fs_tval *v, int64_t *out)
{
    switch (v->type) {
    case FS_TV_NULL: case FS_TV_FALSE: *out = 0; return true;
    case FS_TV_TRUE: *out = 1; return true;
    case FS_TV_SINT: case FS_TV_ENUM: *out = v->i; return true;
    case FS_TV_UINT: case FS_TV_BITMASK: case FS_TV_OPAQUE: *out = (int64_t)v->u; return true;
    case FS_TV_FLOAT: case FS_TV_DOUBLE:
        if (!(v->d >= -9.2e18 && v->d <= 9.2e18))
            return false;
        *out = (int64_t)v->d;
        return true;
    default: return false;
    }
}

static bool tv_double(const fs_tval *v, double *out)
{
    switch (v->type) {
    case FS_TV_FLOAT: case FS_TV_DOUBLE: *out = v->d; return true;
    case FS_TV_SINT: case FS_TV_ENUM: *out = (double)v->i; return true;
    case FS_TV_UINT: *out = (double)v->u; return true;
    case FS_TV_FALSE: case FS_TV_NULL: *out = 0; return true;
    case FS_TV_TRUE: *out = 1; return true;
    default: return false;
    }
}

/* Converts an array value into a typed C array in the arena. */
static int to_array(fs_replayer *r, const fs_tcall *tc, int kind, const fs_tval *v, fs_arg *a)
{
    size_t es = fs_kind_elem_size(kind); /* only array kinds come here */
    if (v->type == FS_TV_NULL) {
        a->p = NULL;
        a->count = 0;
        return 0;
    }
    if (v->type == FS_TV_BLOB || v->type == FS_TV_STRING) {
        /* Raw bytes in the machine's representation (apitrace writes arrays
         * it cannot type as blobs). */
        if (v->str.len / es > UINT32_MAX)
            return fail(r, tc, "%s array too long", fs_kind_names[kind]);
        a->p = v->str.ptr;
        a->count = (uint32_t)(v->str.len / es);
        return 0;
    }
    if (v->type != FS_TV_ARRAY)
        return fail(r, tc, "expected an array for a %s argument", fs_kind_names[kind]);
    if (v->arr.n > UINT32_MAX)
        return fail(r, tc, "%s array too long", fs_kind_names[kind]);
    void *buf = arena_alloc(r, v->arr.n * es + 1);
    if (!buf)
        return fail(r, tc, "%s", "out of memory");
    for (size_t i = 0; i < v->arr.n; i++) {
        const fs_tval *e = &v->arr.elems[i];
        double d;
        int64_t n;
        if (kind == FS_K_AF || kind == FS_K_AD) {
            if (!tv_double(e, &d))
                return fail(r, tc, "non-numeric element in a %s array", fs_kind_names[kind]);
            if (kind == FS_K_AF)
                ((GLfloat *)buf)[i] = (GLfloat)d;
            else
                ((GLdouble *)buf)[i] = d;
            continue;
        }
        if (!tv_int(e, &n))
            return fail(r, tc, "non-integer element in a %s array", fs_kind_names[kind]);
        switch (kind) {
        case FS_K_AI: ((GLint *)buf)[i] = (GLint)n; break;
        case FS_K_AU: ((GLuint *)buf)[i] = (GLuint)n; break;
        case FS_K_AS: ((GLshort *)buf)[i] = (GLshort)n; break;
        case FS_K_AUS: ((GLushort *)buf)[i] = (GLushort)n; break;
        case FS_K_ABY: ((GLbyte *)buf)[i] = (GLbyte)n; break;
        default: ((GLubyte *)buf)[i] = (GLubyte)n; break; /* AUB, BLOB given as an array */
        }
    }
    a->p = buf;
    a->count = (uint32_t)v->arr.n;
    return 0;
}

/* glMultiDrawElements' indices (kind AP, gl_call.h): apitrace records one
 * value per draw, a blob of its indices or, while an element array buffer
 * is bound, a pointer value (an offset, GL 1.5 spec 2.9.2; NULL is offset
 * 0).  Into the arena as an array of pointers; each blob must hold what
 * its draw reads (count[i] indices of the call's type, arguments k - 2 and
 * k - 1, already converted); blobs and addresses do not mix. */
static int to_pointers(fs_replayer *r, const fs_tcall *tc, fs_call *call, int k, const fs_tval *v)
{
    fs_arg *a = &call->a[k];
    if (v->type == FS_TV_NULL) {
        a->p = NULL;
        a->count = 0;
        return 0;
    }
    if (v->type != FS_TV_ARRAY)
        return fail(r, tc, "%s", "expected an array of pointers");
    if (v->arr.n > UINT32_MAX / sizeof(void *))
        return fail(r, tc, "%s", "array of pointers too long");
    const void **ptrs = arena_alloc(r, v->arr.n * sizeof *ptrs + 1);
    if (!ptrs)
        return fail(r, tc, "%s", "out of memory");
    const GLint *count = call->a[k - 2].p;
    GLenum type = (GLenum)call->a[k - 1].i;
    bool blobs = false, addrs = false;
    for (size_t i = 0; i < v->arr.n; i++) {
        const fs_tval *e = &v->arr.elems[i];
        int64_t addr;
        if (e->type == FS_TV_BLOB || e->type == FS_TV_STRING) {
            int64_t need = count && i < call->a[k - 2].count ? fs_index_bytes(count[i], type) : 0;
            if ((int64_t)e->str.len < need)
                return fail(r, tc, "%s", "indices blob shorter than its draw reads");
            ptrs[i] = e->str.ptr;
            blobs = true;
        } else if (e->type == FS_TV_NULL) {
            ptrs[i] = NULL;
        } else if (tv_int(e, &addr)) {
            ptrs[i] = (const void *)(uintptr_t)addr;
            addrs = true;
        } else {
            return fail(r, tc, "%s", "non-pointer element in an array of pointers");
        }
    }
    if (blobs && addrs)
        return fail(r, tc, "%s", "indices mix blobs and addresses");
    a->p = ptrs;
    a->count = (uint32_t)v->arr.n;
    a->is_data = addrs ? FS_ARG_ADDR : 0;
    return 0;
}

/* *call with every argument zero: what convert() and rec_next() fill in. */
static void call_start(fs_call *call, int cmd, unsigned nargs, uint32_t flags)
{
    /* All of *call zeroed, but not by one memset: gcc expands that into rep
     * stos, whose start-up cost was a fifth of next_call; per argument it
     * becomes a few vector stores. */
    _Static_assert(offsetof(fs_call, a) == 8 && sizeof(fs_call) == offsetof(fs_call, ret) + sizeof(fs_arg),
                   "call_start() zeroes fs_call member by member");
    for (int k = 0; k < FS_MAX_ARGS; k++)
        memset(&call->a[k], 0, sizeof call->a[k]);
    memset(&call->ret, 0, sizeof call->ret);
    call->cmd = (uint16_t)cmd;
    call->nargs = (uint16_t)nargs;
    call->flags = flags;
}

static int convert(fs_replayer *r, const fs_tcall *tc, int cmd, fs_call *call)
{
    const fs_cmd_info *info = &fs_cmd_table[cmd];
    call_start(call, cmd, info->nargs, tc->flags);
    if (tc->nargs < info->nargs) {
        char n[32];
        snprintf(n, sizeof n, "%u of %u", tc->nargs, (unsigned)info->nargs);
        return fail(r, tc, "too few arguments (%s)", n);
    }
    for (int k = 0; k < info->nargs; k++) {
        const fs_tval *v = &tc->args[k];
        fs_arg *a = &call->a[k];
        int kind = info->kinds[k];
        switch (kind) {
        case FS_K_E: case FS_K_BM: case FS_K_B: case FS_K_I: case FS_K_U: case FS_K_SZ:
        case FS_K_UB: case FS_K_BY: case FS_K_S: case FS_K_US: case FS_K_IP:
            if (!tv_int(v, &a->i))
                return fail(r, tc, "argument '%s' is not an integer", info->argnames[k]);
            break;
        case FS_K_F: case FS_K_D: case FS_K_CF: case FS_K_CD:
            if (v->type == FS_TV_FLOAT || v->type == FS_TV_DOUBLE) /* nearly always */
                a->d = v->d;
            else if (!tv_double(v, &a->d))
                return fail(r, tc, "argument '%s' is not a number", info->argnames[k]);
            break;
        case FS_K_CPTR:
            if (v->type == FS_TV_BLOB) {
                a->p = v->str.ptr;
                a->count = v->str.len > UINT32_MAX ? UINT32_MAX : (uint32_t)v->str.len;
                a->is_data = 1;
            } else {
                if (!tv_int(v, &a->i))
                    return fail(r, tc, "argument '%s' is not a pointer", info->argnames[k]);
                /* An address in the traced program or an offset into a
                 * bound buffer object: the dispatcher decides, and never
                 * dereferences the former. */
                a->is_data = FS_ARG_ADDR;
            }
            break;
        case FS_K_BLOB:
            /* A draw's indices given as a pointer value: an offset into the
             * element array buffer (GL 1.5 spec 2.9.2), as apitrace records
             * them while one is bound. */
            if ((info->flags & FS_F_DRAW) && v->type != FS_TV_BLOB && v->type != FS_TV_STRING &&
                v->type != FS_TV_ARRAY) {
                if (!tv_int(v, &a->i))
                    return fail(r, tc, "argument '%s' is not a pointer", info->argnames[k]);
                a->is_data = FS_ARG_ADDR;
            } else if (to_array(r, tc, kind, v, a) != 0) {
                return -1;
            }
            break;
        case FS_K_AP:
            if (to_pointers(r, tc, call, k, v) != 0)
                return -1;
            break;
        case FS_K_OV: case FS_K_OF: case FS_K_OD: case FS_K_OI: case FS_K_OU: case FS_K_OUS: case FS_K_OB: case FS_K_OUB: case FS_K_OP:
            a->out = NULL; /* the dispatcher provides scratch space */
            /* ... except to the selection and feedback buffers, written
             * after the call: the traced program's, never ours. */
            if (info == &fs_cmd_table[FS_CMD_SelectBuffer] || info == &fs_cmd_table[FS_CMD_FeedbackBuffer])
                a->is_data = FS_ARG_ADDR;
            break;
        default:
            if (to_array(r, tc, kind, v, a) != 0)
                return -1;
            break;
        }
    }
    int bad = fs_call_validate(call);
    if (bad < 0) {
        int k = -1 - bad;
        return fail(r, tc, "argument '%s' holds fewer elements than the call reads",
                    k < info->nargs ? info->argnames[k] : "?");
    }
    return 0;
}

/* ---- buffer objects and writes through mappings ---- */

static int target_slot(GLenum target)
{
    return target == GL_ARRAY_BUFFER ? 0 : target == GL_ELEMENT_ARRAY_BUFFER ? 1 : -1;
}

static void forget_maps_of(buffer_track *b, GLuint buffer)
{
    int n = 0;
    for (int i = 0; i < b->nmap; i++)
        if (b->map[i].buffer != buffer)
            b->map[n++] = b->map[i];
    b->nmap = n;
}

/* Follows the bindings and mappings of the trace (not of the model: a call
 * the model rejects changes nothing there, and the memcpy that follows is
 * then reported by the model as outside every mapping). */
static void track_buffers(fs_replayer *r, const fs_tcall *tc, const fs_call *call)
{
    buffer_track *b = &r->buf;
    int t = call->nargs > 0 ? target_slot((GLenum)call->a[0].i) : -1;
    int64_t addr;
    switch (call->cmd) {
    case FS_CMD_BindBuffer:
        if (t >= 0)
            b->bound[t] = (GLuint)call->a[1].i;
        break;
    case FS_CMD_MapBuffer: case FS_CMD_MapBufferRange: /* the address is the range's start */
        if (t < 0 || !b->bound[t] || !tc->has_ret || !tv_int(&tc->ret, &addr) || addr == 0)
            break;
        forget_maps_of(b, b->bound[t]);
        if (b->nmap == MAX_MAPS) /* the oldest mapping makes room */
            memmove(&b->map[0], &b->map[1], (MAX_MAPS - 1) * sizeof b->map[0]);
        else
            b->nmap++;
        b->map[b->nmap - 1].addr = (uint64_t)addr;
        b->map[b->nmap - 1].buffer = b->bound[t];
        break;
    case FS_CMD_UnmapBuffer: case FS_CMD_BufferData:
        if (t >= 0 && b->bound[t])
            forget_maps_of(b, b->bound[t]);
        break;
    case FS_CMD_DeleteBuffers:
        for (uint32_t i = 0; call->a[1].p && i < call->a[1].count; i++) {
            GLuint name = ((const GLuint *)call->a[1].p)[i];
            forget_maps_of(b, name);
            for (int k = 0; k < 2; k++)
                if (b->bound[k] == name)
                    b->bound[k] = 0;
        }
        break;
    default:
        break;
    }
}

/* memcpy(dest, src, n) as glTraceMemcpy(buffer, offset, n, src): the
 * mapping that begins closest below dest (buffer 0 when none does, which
 * the model reports as a write outside every mapping). */
static int convert_memcpy(fs_replayer *r, const fs_tcall *tc, fs_call *call)
{
    const fs_cmd_info *info = &fs_cmd_table[FS_CMD_TraceMemcpy];
    call_start(call, FS_CMD_TraceMemcpy, info->nargs, tc->flags);
    int64_t dest, n;
    if (tc->nargs < 3 || !tv_int(&tc->args[0], &dest) || !tv_int(&tc->args[2], &n))
        return fail(r, tc, "%s", "memcpy without a destination address and a size");
    if (tc->args[1].type != FS_TV_BLOB)
        return fail(r, tc, "%s", "memcpy without its data");
    const buffer_track *b = &r->buf;
    int best = -1;
    for (int i = 0; i < b->nmap; i++)
        if (b->map[i].addr <= (uint64_t)dest && (best < 0 || b->map[i].addr > b->map[best].addr))
            best = i;
    call->a[0].i = best < 0 ? 0 : b->map[best].buffer;
    call->a[1].i = best < 0 ? 0 : (int64_t)((uint64_t)dest - b->map[best].addr);
    call->a[2].i = n;
    call->a[3].p = tc->args[1].str.ptr;
    call->a[3].count = tc->args[1].str.len > UINT32_MAX ? UINT32_MAX : (uint32_t)tc->args[1].str.len;
    if (fs_call_validate(call) < 0)
        return fail(r, tc, "%s", "memcpy's data holds fewer bytes than its size");
    return 0;
}

/* ---- client-array safety ---- */

static int client_state_slot(const fs_replayer *r, GLenum array)
{
    switch (array) {
    case GL_VERTEX_ARRAY: return ARR_VERTEX;
    case GL_NORMAL_ARRAY: return ARR_NORMAL;
    case GL_COLOR_ARRAY: return ARR_COLOR;
    case GL_TEXTURE_COORD_ARRAY: return ARR_TEXCOORD + r->client_unit;
    case GL_SECONDARY_COLOR_ARRAY: return ARR_SECONDARY;
    case GL_FOG_COORDINATE_ARRAY: return ARR_FOG;
    case GL_EDGE_FLAG_ARRAY: return ARR_EDGE;
    case GL_INDEX_ARRAY: return ARR_INDEX;
    default: return -1;
    }
}

/* Notes what a pointer call says of its array.  The data stays where the
 * call has it: the dispatcher copies it into the context (dispatch.c). */
static void track_pointer(fs_replayer *r, const fs_call *call, int slot, int pk)
{
    int k = fs_array_of_slot(slot, r->client_unit);
    array_track *t = &r->arr[k];
    const fs_arg *p = &call->a[pk];
    /* Normals have 3 components, fog coordinates, edge flags (bytes, no
     * type argument) and indices 1; the others give their size first. */
    t->size = k == ARR_NORMAL ? 3 : k >= ARR_FOG ? 1 : (GLint)call->a[0].i;
    t->type = k == ARR_EDGE ? GL_UNSIGNED_BYTE : (GLenum)call->a[pk - 2].i;
    t->stride = (GLsizei)call->a[pk - 1].i;
    /* An offset into a bound buffer: the dispatcher checks the draw's reads
     * against the store. */
    t->has_data = p->is_data == FS_ARG_DATA || (p->is_data == FS_ARG_ADDR && r->buf.bound[0] != 0);
    t->bytes = p->is_data == FS_ARG_DATA ? p->count : t->has_data ? SIZE_MAX : 0;
}

/* True when every enabled array holds recorded data for the draw's vertices. */
static bool draw_is_safe(fs_replayer *r, const fs_call *call)
{
    int64_t lo, hi;
    if (!fs_draw_vertex_range(call, &lo, &hi))
        return true; /* reads no vertex (or the GL call itself is an error) */
    for (int s = 0; s < ARR_COUNT; s++) {
        const array_track *t = &r->arr[s];
        if (!t->enabled)
            continue;
        int ts = fs_type_size(t->type);
        if (!t->has_data || ts <= 0 || t->size < 1 || t->size > 4 || t->stride < 0)
            return false;
        uint64_t elem = (uint64_t)ts * (uint64_t)t->size;
        uint64_t stride = t->stride ? (uint64_t)t->stride : elem;
        if ((uint64_t)hi * stride + elem > t->bytes)
            return false;
    }
    return true;
}

/* ---- the decoded trace, kept from pass 1 ----
 *
 * Pass 1 decodes every call anyway (to validate the trace and count its
 * frames), so it keeps what pass 2 needs: per call its name and, for a GL
 * command, the converted fs_call with copies of the data its pointers reach.
 * Pass 2 then replays that record instead of decompressing and parsing the
 * file a second time, which was as long as executing a small trace in
 * sampled mode (docs/performance.md).  A record whose blocks would outgrow
 * rec_max bytes is dropped, and pass 2 reads the file as before. */

typedef struct rec_block {
    struct rec_block *next;
    size_t used, size;
    _Alignas(16) unsigned char data[];
} rec_block;

/* One call, then 8 bytes per argument: the scalar (fs_arg's union), or for
 * an argument with data its count and is_data, the data following the
 * arguments.  Compact because pass 2 is bound by reading it from memory. */
typedef struct rec_head {
    const char *name; /* the pass-1 reader's string for the call's name */
    uint32_t size;    /* of the whole entry, a multiple of 8 */
    uint32_t flags;
    uint16_t cmd;    /* REC_NOT_CMD: a name fragsim cannot execute */
    uint16_t data;   /* bit k: argument k has data */
    uint8_t nargs;
    uint8_t unsafe;  /* a draw pass 2 skips: its client arrays are not in the trace */
    uint16_t addr;   /* bit k: argument k is a recorded address (FS_ARG_ADDR) */
} rec_head;
_Static_assert(FS_MAX_ARGS <= 16, "rec_head.data has a bit per argument");
_Static_assert(sizeof(rec_head) % 8 == 0 && sizeof(fs_arg) == 16, "record layout");

#define REC_ALIGN(n) (((n) + 7) & ~(size_t)7)
#define REC_NOT_CMD 0xffffu
_Static_assert(FS_CMD_COUNT < REC_NOT_CMD, "rec_head.cmd holds every command");
#define REC_BLOCK (4u << 20)
#define REC_MAX_DEFAULT ((size_t)1 << 30)

static void rec_free(fs_replayer *r)
{
    while (r->rec) {
        rec_block *n = r->rec->next;
        free(r->rec);
        r->rec = n;
    }
    r->rec_last = r->rec_at = NULL;
    r->rec_pos = r->rec_bytes = 0;
    r->rec_on = r->info.from_record = false;
}

/* Bytes of the data argument k of `call` points to, or -1 when it points
 * at none (a scalar, an output, an address in the traced program). */
static int64_t rec_payload(const fs_call *call, int k);
_Static_assert(sizeof(void *) == 8, "a recorded pointer takes 8 bytes");

/* An array of index pointers (AP, glMultiDrawElements) in the record: a
 * table of 8 bytes per draw, then each draw's indices.  The table holds
 * recorded addresses as they are, else for each draw the offset of its
 * indices from the table's start (0: NULL), which rec_next turns back into
 * pointers.  ptrs: the pointers, or the table of offsets (either way
 * nonzero for the same draws). */
/* Bytes of draw i's indices (as to_pointers checked them): none without
 * a count for it. */
static size_t rec_ap_draw_bytes(const fs_call *call, int k, uint32_t i)
{
    const GLint *count = call->a[k - 2].p;
    if (!count || i >= call->a[k - 2].count)
        return 0;
    return (size_t)fs_index_bytes(count[i], (GLenum)call->a[k - 1].i);
}

static int64_t rec_ap_payload(const fs_call *call, int k)
{
    const fs_arg *a = &call->a[k];
    int64_t n = 8 * (int64_t)a->count;
    if (a->is_data == FS_ARG_ADDR)
        return n;
    for (uint32_t i = 0; i < a->count; i++) {
        uint64_t v;
        memcpy(&v, (const unsigned char *)a->p + 8 * (size_t)i, 8);
        if (v)
            n += (int64_t)REC_ALIGN(rec_ap_draw_bytes(call, k, i));
    }
    return n;
}

static void rec_ap_write(const fs_call *call, int k, unsigned char *out)
{
    const fs_arg *a = &call->a[k];
    if (a->is_data == FS_ARG_ADDR) {
        memcpy(out, a->p, 8 * (size_t)a->count);
        return;
    }
    const void *const *ptrs = a->p;
    size_t at = 8 * (size_t)a->count;
    for (uint32_t i = 0; i < a->count; i++) {
        uint64_t off = ptrs[i] ? at : 0;
        memcpy(out + 8 * (size_t)i, &off, 8);
        if (!ptrs[i])
            continue;
        size_t n = rec_ap_draw_bytes(call, k, i);
        memcpy(out + at, ptrs[i], n);
        at += REC_ALIGN(n);
    }
}

static int64_t rec_payload(const fs_call *call, int k)
{
    const fs_arg *a = &call->a[k];
    int kind = fs_cmd_table[call->cmd].kinds[k];
    if (kind == FS_K_AP)
        return a->p ? rec_ap_payload(call, k) : -1;
    if (!a->p || a->is_data == FS_ARG_ADDR)
        return -1;
    if (kind == FS_K_CPTR)
        return a->is_data == FS_ARG_DATA ? (int64_t)a->count : -1;
    size_t es = fs_kind_elem_size(kind);
    return es ? (int64_t)(es * a->count) : -1;
}

/* ---- signatures of frames (sampled mode's frame clustering) ---- */

static uint64_t sig_mix(uint64_t h, uint64_t v)
{
    /* splitmix64's finaliser over the running value and the next word */
    h ^= v + 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

static uint64_t sig_bytes(uint64_t h, const unsigned char *p, size_t n)
{
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        uint64_t v;
        memcpy(&v, p + i, 8);
        h = sig_mix(h, v);
    }
    uint64_t v = 0;
    memcpy(&v, p + i, n - i);
    return sig_mix(h, v ^ (uint64_t)n << 56);
}

/* A call's two signatures: `kind`, of the command and its integer
 * arguments (counts, modes, enums, names) and its arrays' lengths but not
 * their contents nor floating-point arguments, so that the frames of a
 * camera path or an animation are of one kind; `exact`, of everything the
 * record holds (array and blob contents included). */
static void call_signature(const fs_call *call, uint64_t *kind, uint64_t *exact)
{
    uint64_t k = sig_mix(0, call->cmd), e = k;
    for (int i = 0; i < call->nargs; i++) {
        const fs_arg *a = &call->a[i];
        int kd = fs_cmd_table[call->cmd].kinds[i];
        int64_t n = rec_payload(call, i);
        uint64_t v;
        memcpy(&v, &a->i, 8);
        if (n < 0) {
            e = sig_mix(e, v);
            if (kd != FS_K_F && kd != FS_K_D && kd != FS_K_CF && kd != FS_K_CD && a->is_data != FS_ARG_ADDR)
                k = sig_mix(k, v);
            continue;
        }
        k = sig_mix(k, a->count);
        e = sig_mix(e, a->count);
        /* an array of index pointers (glMultiDrawElements): its counts only */
        if (kd != FS_K_AP)
            e = sig_bytes(e, a->p, (size_t)n);
    }
    *kind = k;
    *exact = e;
}

/* Pass 1: a call (NULL: a name that is no command) into the open frames
 * of each way of ending frames, and the frames it ends. */
static void sig_call(fs_replayer *r, const fs_call *call, const name_info *ni)
{
    uint64_t k = 0, e = 0;
    if (call)
        call_signature(call, &k, &e);
    bool ends[3] = {ni->swap, ni->user_end, call && call->cmd == FS_CMD_Finish};
    for (int m = 0; m < 3; m++) {
        struct frame_sigs *g = &r->sigs[m];
        if (call) {
            g->kind = sig_mix(g->kind, k);
            g->exact = sig_mix(g->exact, e);
        }
        if (!ends[m] || g->failed)
            continue;
        if (g->n == g->cap) {
            size_t cap = g->cap ? 2 * g->cap : 64;
            uint64_t *nk = realloc(g->k, cap * sizeof *nk);
            if (nk)
                g->k = nk;
            uint64_t *ne = nk ? realloc(g->e, cap * sizeof *ne) : NULL;
            if (ne)
                g->e = ne;
            if (!ne) {
                g->failed = true;
                continue;
            }
            g->cap = cap;
        }
        g->k[g->n] = g->kind;
        g->e[g->n++] = g->exact;
        g->kind = g->exact = 0;
    }
}

/* Appends a call (call NULL: a name fragsim cannot execute).  Out of
 * memory, over rec_max, or given a call it cannot hold exactly, the record
 * is dropped (pass 2 reads the file), not the replay. */
static void rec_add(fs_replayer *r, const char *name, const fs_call *call, bool unsafe)
{
    int nargs = call && !unsafe ? call->nargs : 0;
    size_t size = sizeof(rec_head) + 8 * (size_t)nargs;
    for (int k = 0; k < nargs; k++) {
        int64_t n = rec_payload(call, k);
        if (n >= 0)
            size += REC_ALIGN((size_t)n + 1); /* +1: a NUL, as the reader leaves after strings */
        else if (call->a[k].count || (call->a[k].is_data && call->a[k].is_data != FS_ARG_ADDR))
            goto drop; /* not a plain scalar: would not round-trip through 8 bytes */
    }
    if (size > UINT32_MAX)
        goto drop;
    rec_block *b = r->rec_last;
    if (!b || b->size - b->used < size) {
        /* The limit counts whole blocks, the tail a block leaves unused too. */
        size_t bs = size > REC_BLOCK ? size : REC_BLOCK;
        if (bs > r->rec_max || r->rec_bytes > r->rec_max - bs)
            goto drop;
        b = malloc(sizeof *b + bs);
        if (!b)
            goto drop;
        b->next = NULL;
        b->used = 0;
        b->size = bs;
        r->rec_bytes += bs;
        if (r->rec_last)
            r->rec_last->next = b;
        else
            r->rec = b;
        r->rec_last = b;
    }
    unsigned char *at = b->data + b->used;
    rec_head *h = (rec_head *)at;
    *h = (rec_head){name, (uint32_t)size, call ? call->flags : 0, call ? call->cmd : REC_NOT_CMD, 0, (uint8_t)nargs, unsafe, 0};
    unsigned char *slot = at + sizeof *h, *data = slot + 8 * (size_t)nargs;
    for (int k = 0; k < nargs; k++, slot += 8) {
        const fs_arg *a = &call->a[k];
        int64_t n = rec_payload(call, k);
        if (n < 0) {
            memcpy(slot, &a->i, 8);
            if (a->is_data == FS_ARG_ADDR)
                h->addr |= (uint16_t)(1u << k);
            continue;
        }
        h->data |= (uint16_t)(1u << k);
        memcpy(slot, &a->count, 4);
        memcpy(slot + 4, &a->is_data, 4);
        if (fs_cmd_table[call->cmd].kinds[k] == FS_K_AP)
            rec_ap_write(call, k, data);
        else
            memcpy(data, a->p, (size_t)n);
        data[n] = 0;
        data += REC_ALIGN((size_t)n + 1);
    }
    b->used += size;
    return;
drop:
    rec_free(r);
}

/* Pass 2 from the record: 1 with *ni, *unsafe and (for a command) *call
 * set, 0 at the end. */
static int rec_next(fs_replayer *r, fs_call *call, const struct name_info **ni, bool *unsafe)
{
    while (r->rec_at && r->rec_pos >= r->rec_at->used) {
        r->rec_at = r->rec_at->next;
        r->rec_pos = 0;
    }
    if (!r->rec_at)
        return 0;
    const unsigned char *at = r->rec_at->data + r->rec_pos;
    const rec_head *h = (const rec_head *)at;
    r->rec_pos += h->size;
    /* A command's name_info from its number: no hash lookup per call. */
    if (h->cmd != REC_NOT_CMD)
        *ni = &r->cmd_info[h->cmd];
    else if (!(*ni = name_info_of(r, h->name))) {
        snprintf(r->err, sizeof r->err, "%s: out of memory", r->path);
        return -1;
    }
    *unsafe = h->unsafe;
    r->call_name = h->name;
    if ((*ni)->cmd < 0 || h->unsafe)
        return 1;
    call_start(call, h->cmd, h->nargs, h->flags);
    const unsigned char *slot = at + sizeof *h, *data = slot + 8 * (size_t)h->nargs;
    for (int k = 0; k < h->nargs; k++, slot += 8) {
        fs_arg *a = &call->a[k];
        if (!(h->data >> k & 1)) {
            memcpy(&a->i, slot, 8);
            if (h->addr >> k & 1)
                a->is_data = FS_ARG_ADDR;
            continue;
        }
        memcpy(&a->count, slot, 4);
        memcpy(&a->is_data, slot + 4, 4);
        a->p = data;
        if (fs_cmd_table[h->cmd].kinds[k] == FS_K_AP && a->is_data != FS_ARG_ADDR) {
            /* the table's offsets back into pointers (rec_ap_write) */
            arena_reset(r);
            const void **ptrs = arena_alloc(r, 8 * (size_t)a->count + 1);
            if (!ptrs) {
                snprintf(r->err, sizeof r->err, "%s: out of memory", r->path);
                return -1;
            }
            for (uint32_t i = 0; i < a->count; i++) {
                uint64_t off;
                memcpy(&off, data + 8 * (size_t)i, 8);
                ptrs[i] = off ? data + off : NULL;
            }
            a->p = ptrs;
        }
        data += REC_ALIGN((size_t)rec_payload(call, k) + 1);
    }
    return 1;
}

/* Decodes the next call from the file: 1 with *nip, *unsafe and, for a
 * command, *call set; 0 at the end; -1 on error. */
static int decode_next(fs_replayer *r, fs_call *call, bool pass1, const name_info **nip, bool *unsafe)
{
    fs_tcall tc;
    arena_reset(r);
    int got = fs_trace_next(r->tr, &tc);
    if (got < 0) {
        snprintf(r->err, sizeof r->err, "%s", fs_trace_error(r->tr));
        return -1;
    }
    if (got == 0)
        return 0;
    const name_info *ni = name_info_of(r, tc.name);
    if (!ni) {
        snprintf(r->err, sizeof r->err, "%s: out of memory", r->path);
        return -1;
    }
    *nip = ni;
    *unsafe = false;
    r->call_name = tc.name;
    if (pass1) {
        r->info.calls++;
        r->p1_swaps += ni->swap;
        r->p1_named += ni->user_end;
    }
    int cmd = ni->cmd;
    if (cmd < 0) {
        if (r->rec_on)
            rec_add(r, tc.name, NULL, false);
        if (pass1)
            sig_call(r, NULL, ni);
        return 1;
    }
    if (pass1 && cmd == FS_CMD_Finish)
        r->p1_finishes++;
    if (pass1 && (cmd == FS_CMD_BeginQuery || cmd == FS_CMD_BeginQueryARB))
        r->info.uses_queries = true;
    if ((cmd == FS_CMD_TraceMemcpy && strcmp(tc.name, "memcpy") == 0 ? convert_memcpy(r, &tc, call)
                                                                      : convert(r, &tc, cmd, call)) != 0)
        return -1;
    track_buffers(r, &tc, call);
    if (pass1 && cmd == FS_CMD_Viewport && r->info.width == 0) {
        int64_t w = call->a[0].i + call->a[2].i, h = call->a[1].i + call->a[3].i;
        if (w > 0 && h > 0 && w <= 16384 && h <= 16384) {
            r->info.width = (int)w;
            r->info.height = (int)h;
        }
    }
    int pk, slot = fs_pointer_slot(cmd, &pk);
    if (slot >= 0)
        track_pointer(r, call, slot, pk);
    if (cmd == FS_CMD_ClientActiveTexture && call->a[0].i >= GL_TEXTURE0 &&
        call->a[0].i < GL_TEXTURE0 + FS_MAX_TEXTURE_UNITS)
        r->client_unit = (int)(call->a[0].i - GL_TEXTURE0); /* another unit is an error, no change */
    if (cmd == FS_CMD_EnableClientState || cmd == FS_CMD_DisableClientState) {
        int s = client_state_slot(r, (GLenum)call->a[0].i);
        if (s >= 0)
            r->arr[s].enabled = cmd == FS_CMD_EnableClientState;
    }
    *unsafe = (fs_cmd_table[cmd].flags & FS_F_DRAW) && !draw_is_safe(r, call);
    if (r->rec_on)
        rec_add(r, tc.name, call, *unsafe);
    if (pass1)
        sig_call(r, call, ni);
    return 1;
}

/* Reads the next call the model can execute (skipping and counting the
 * rest).  Returns 1 with *call set, 2 for a frame-end call that is not a GL
 * command, 0 at the end, -1 on error. */
static int next_call(fs_replayer *r, fs_call *call, bool pass1)
{
    for (;;) {
        const name_info *ni;
        bool unsafe;
        int got = r->info.from_record ? rec_next(r, call, &ni, &unsafe) : decode_next(r, call, pass1, &ni, &unsafe);
        if (got <= 0)
            return got;
        if (!pass1) {
            r->call_no = r->p2_calls++;
            r->call_flags = ni->flags;
        }
        bool ends_frame = !pass1 && (r->frame_end_is_swap ? ni->swap : ni->frame_end);
        if (ni->cmd < 0) {
            if (!pass1)
                count_skip(r, ni->name, ni->winsys ? SKIP_WINSYS : SKIP_UNKNOWN);
            if (!pass1 && r->report_skipped) {
                r->pending_frame_end = ends_frame;
                return 3;
            }
            if (ends_frame)
                return 2;
            continue;
        }
        if (unsafe) {
            if (!pass1) {
                char what[96];
                snprintf(what, sizeof what, "%s (client arrays not recorded in the trace)", ni->name);
                count_skip(r, what, SKIP_UNSAFE);
            }
            if (!pass1 && r->report_skipped)
                return 3;
            continue;
        }
        /* Fake calls are executed too: apitrace adds them for what a replay
         * needs, e.g. the viewport and scissor a new window gets at
         * glXMakeCurrent, and the array data before a draw. */
        r->pending_frame_end = ends_frame;
        return 1;
    }
}

/* Opens the trace for one pass; on failure frees the replayer. */
static fs_replayer *start_pass(fs_replayer *r, char *err, size_t errlen)
{
    forget_names(r); /* the names of the last pass were the old reader's */
    r->tr = fs_trace_open(r->path, err, errlen);
    if (!r->tr) {
        fs_replay_close(r);
        return NULL;
    }
    fs_trace_set_parser(r->tr, r->parser);
    return r;
}

fs_replayer *fs_replay_open(const char *path, const fs_replay_opts *opts, char *err, size_t errlen)
{
    fs_replayer *r = calloc(1, sizeof *r);
    if (!r || !(r->path = strdup(path)) || build_names(r) != 0) {
        snprintf(err, errlen, "%s: out of memory", path);
        fs_replay_close(r);
        return NULL;
    }
    r->parser = opts ? opts->parser : FS_TRACE_PARSER_FAST;
    if (!start_pass(r, err, errlen))
        return NULL;
    /* Pass 1: validate everything, count frame ends, find the window size,
     * and keep the decoded calls for pass 2. */
    r->user_frame_end = opts ? opts->frame_end : NULL;
    r->report_skipped = opts && opts->report_skipped;
    r->rec_max = opts && opts->max_record_bytes ? opts->max_record_bytes : REC_MAX_DEFAULT;
    r->rec_on = true;
    fs_call call;
    int got;
    while ((got = next_call(r, &call, true)) > 0)
        ;
    if (got < 0) {
        snprintf(err, errlen, "%s", r->err);
        fs_replay_close(r);
        return NULL;
    }
    if (fs_trace_warning(r->tr))
        snprintf(r->info.warning, sizeof r->info.warning, "%s", fs_trace_warning(r->tr));
    if (r->rec_on) {
        r->rec_on = false;
        r->info.from_record = true;
        r->rec_at = r->rec;
        r->rec_pos = 0;
        r->rec_tr = r->tr; /* the record points at its name strings */
    } else {
        fs_trace_close(r->tr);
    }
    r->tr = NULL;
    memset(r->arr, 0, sizeof r->arr);
    memset(&r->buf, 0, sizeof r->buf);
    r->pending_frame_end = false;
    r->info.double_buffered = r->p1_swaps > 0;
    if (r->user_frame_end) {
        r->frame_end_is_swap = false;
        snprintf(r->info.frame_end, sizeof r->info.frame_end, "%s", r->user_frame_end);
        r->info.frames = r->p1_named;
        r->sig_end = 1;
    } else if (r->p1_swaps > 0) {
        r->frame_end_is_swap = true;
        snprintf(r->info.frame_end, sizeof r->info.frame_end, "swap buffers");
        r->info.frames = r->p1_swaps;
        r->sig_end = 0;
    } else {
        r->sig_end = 2;
        /* Captures of programs that swap through EGL have no swap calls; each
         * of their frames ends with glFinish (shared/reference-notes.md). */
        snprintf(r->info.frame_end, sizeof r->info.frame_end, "glFinish");
        r->info.frames = r->p1_finishes;
    }
    if (r->info.frames == 0)
        r->info.frames = 1; /* the whole trace is one frame */
    if (opts && opts->width > 0 && opts->height > 0) {
        r->info.width = opts->width;
        r->info.height = opts->height;
    }
    if (r->info.width <= 0 || r->info.height <= 0) {
        snprintf(err, errlen, "%s: no glViewport in the trace to take the window size from; give --size WxH", path);
        fs_replay_close(r);
        return NULL;
    }
    if (r->info.from_record) {
        forget_names(r); /* frame_end of each name is known only now */
        if (!(r->cmd_info = calloc(FS_CMD_COUNT, sizeof *r->cmd_info))) {
            snprintf(err, errlen, "%s: out of memory", path);
            fs_replay_close(r);
            return NULL;
        }
        for (int i = 0; i < FS_CMD_COUNT; i++)
            name_info_fill(r, &r->cmd_info[i], fs_cmd_table[i].name, i);
        return r;
    }
    return start_pass(r, err, errlen);
}

const fs_replay_info *fs_replay_info_get(const fs_replayer *r) { return &r->info; }

uint64_t fs_replay_frame_signatures(const fs_replayer *r, const uint64_t **kind, const uint64_t **exact)
{
    const struct frame_sigs *g = &r->sigs[r->sig_end];
    *kind = g->k;
    *exact = g->e;
    return g->failed ? 0 : g->n;
}
uint64_t fs_replay_call_no(const fs_replayer *r) { return r->call_no; }
const char *fs_replay_call_name(const fs_replayer *r) { return r->call_name; }
unsigned fs_replay_call_flags(const fs_replayer *r) { return r->call_flags; }
const char *fs_replay_error(const fs_replayer *r) { return r->err; }

fs_replay_event fs_replay_next(fs_replayer *r, fs_call *call)
{
    if (r->pending_frame_end) {
        r->pending_frame_end = false;
        r->frames_done++;
        r->calls_since_frame = 0;
        return FS_REPLAY_FRAME_END;
    }
    int got = next_call(r, call, false);
    if (got < 0)
        return FS_REPLAY_ERROR;
    if (got == 3)
        return FS_REPLAY_SKIPPED;
    if (got == 2) {
        r->frames_done++;
        r->calls_since_frame = 0;
        return FS_REPLAY_FRAME_END;
    }
    if (got == 0) {
        /* Only a trace with no frame boundary at all is one frame: trailing
         * calls after the last boundary are an unfinished frame. */
        if (r->frames_done == 0 && r->calls_since_frame > 0) {
            r->frames_done++;
            r->calls_since_frame = 0;
            return FS_REPLAY_FRAME_END;
        }
        return FS_REPLAY_EOF;
    }
    r->calls_since_frame++;
    return FS_REPLAY_CALL;
}

static const char *kind_name(enum skip_kind k)
{
    return k == SKIP_WINSYS ? "window_system" : k == SKIP_UNSAFE ? "unsafe" : "unknown";
}

json_t *fs_replay_skipped_json(const fs_replayer *r)
{
    json_t *o = json_object();
    for (size_t i = 0; o && i < r->nskips; i++) {
        /* the name is the trace's: any bytes (json_text.h) */
        json_t *name = fs_json_text(r->skips[i].name);
        if (!name || json_object_set_new(o, json_string_value(name),
                                         json_pack("{s:I, s:s}", "count", (json_int_t)r->skips[i].count, "reason",
                                                   kind_name(r->skips[i].kind))) != 0) {
            json_decref(o);
            o = NULL;
        }
        json_decref(name);
    }
    return o;
}

uint64_t fs_replay_skipped_total(const fs_replayer *r)
{
    uint64_t n = 0;
    for (size_t i = 0; i < r->nskips; i++)
        if (r->skips[i].kind != SKIP_WINSYS)
            n += r->skips[i].count;
    return n;
}

void fs_replay_print_skipped(const fs_replayer *r, FILE *f)
{
    for (size_t i = 0; i < r->nskips; i++)
        if (r->skips[i].kind != SKIP_WINSYS)
            fprintf(f, "  %-48s %10llu  (%s)\n", r->skips[i].name,
                    (unsigned long long)r->skips[i].count,
                    r->skips[i].kind == SKIP_UNSAFE ? "skipped" : "not implemented");
}

void fs_replay_close(fs_replayer *r)
{
    if (!r)
        return;
    if (r->tr)
        fs_trace_close(r->tr);
    rec_free(r);
    free(r->cmd_info);
    if (r->rec_tr)
        fs_trace_close(r->rec_tr);
    for (size_t i = 0; i < r->nskips; i++)
        free(r->skips[i].name);
    free(r->skips);
    while (r->arena) {
        arena_chunk *n = r->arena->next;
        free(r->arena);
        r->arena = n;
    }
    free(r->names);
    forget_names(r);
    for (int m = 0; m < 3; m++) {
        free(r->sigs[m].k);
        free(r->sigs[m].e);
    }
    free(r->path);
    free(r);
}
