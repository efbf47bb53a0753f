/*
 * Generated plumbing of driver/gl_commands.def: the command table, the public
 * fsgl* entry points, the dispatcher and weak fallback executors.
 */
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include "../pipeline/context.h"
#include "../pipeline/buffer_object.h"
#include "display_list.h"
#include "capture.h"
#include "gl_call_unpack.h"

const char *const fs_kind_names[FS_K_COUNT] = {
#define FS_KIND_NAME(k) #k,
    FS_KINDS(FS_KIND_NAME)
#undef FS_KIND_NAME
};

/* ---- the table ---- */
#define FS_KINDOF(k, kind, name, cnt) FS_K_##kind,
#define FS_NAMEOF(k, kind, name, cnt) #name,
#define FS_CMD(name, rk, flags, n, ...)                                   \
    {"gl" #name, FS_K_##rk, n, (flags),                                   \
     {FS_MAP(n, FS_KINDOF, __VA_ARGS__)}, {FS_MAP(n, FS_NAMEOF, __VA_ARGS__)}},
const fs_cmd_info fs_cmd_table[FS_CMD_COUNT] = {
#include "gl_commands.def"
};
#undef FS_CMD

int fs_cmd_lookup(const char *name)
{
    /* The table is small and lookups happen once per signature in a trace. */
    for (int i = 0; i < FS_CMD_COUNT; i++)
        if (strcmp(fs_cmd_table[i].name, name) == 0)
            return i;
    return -1;
}

size_t fs_kind_elem_size(int kind)
{
    switch (kind) {
    case FS_K_AF: case FS_K_AI: case FS_K_AU: return 4;
    case FS_K_AD: return 8;
    case FS_K_AS: case FS_K_AUS: return 2;
    case FS_K_AUB: case FS_K_ABY: case FS_K_BLOB: return 1;
    default: return 0;
    }
}

static int64_t index_at(const unsigned char *idx, int es, int64_t i)
{
    if (es == 1)
        return idx[i];
    if (es == 2) {
        uint16_t v;
        memcpy(&v, idx + 2 * i, 2);
        return v;
    }
    uint32_t v;
    memcpy(&v, idx + 4 * i, 4);
    return v;
}

bool fs_draw_vertex_range(const fs_call *call, int64_t *lo, int64_t *hi)
{
    switch (call->cmd) {
    case FS_CMD_ArrayElement:
        *lo = *hi = call->a[0].i;
        return *lo >= 0;
    case FS_CMD_DrawArrays:
        *lo = call->a[1].i;
        *hi = call->a[1].i + call->a[2].i - 1;
        return *lo >= 0 && *hi >= *lo;
    case FS_CMD_MultiDrawArrays: {
        /* The union of the draws' ranges (GL 1.4: one glDrawArrays each). */
        const GLint *first = call->a[1].p, *count = call->a[2].p;
        int64_t n = call->a[3].i;
        if (!first || !count || n <= 0 || call->a[1].count < n || call->a[2].count < n)
            return false;
        *lo = INT64_MAX;
        *hi = -1;
        for (int64_t i = 0; i < n; i++) {
            if (first[i] < 0 || count[i] <= 0)
                continue;
            *lo = first[i] < *lo ? first[i] : *lo;
            *hi = (int64_t)first[i] + count[i] - 1 > *hi ? (int64_t)first[i] + count[i] - 1 : *hi;
        }
        return *hi >= *lo;
    }
    case FS_CMD_DrawElements:
    case FS_CMD_DrawRangeElements: {
        int ci = call->cmd == FS_CMD_DrawElements ? 1 : 3;
        int64_t count = call->a[ci].i;
        GLenum type = (GLenum)call->a[ci + 1].i;
        const unsigned char *idx = call->a[ci + 2].p;
        int es = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : type == GL_UNSIGNED_INT ? 4 : 0;
        if (!idx || es == 0 || count <= 0 || (int64_t)call->a[ci + 2].count < count * es)
            return false;
        *lo = INT64_MAX;
        *hi = -1;
        for (int64_t i = 0; i < count; i++) {
            int64_t v = index_at(idx, es, i);
            if (v < *lo) *lo = v;
            if (v > *hi) *hi = v;
        }
        return true;
    }
    default:
        return false;
    }
}

static uint32_t count_u32(int64_t n)
{
    return n < 0 ? 0 : n > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)n;
}

/* ---- packing arguments of the public API into an fs_call ---- */
#define FS_PK_INT(a, v, n) (a).i = (int64_t)(v)
#define FS_PK_FLT(a, v, n) (a).d = (double)(v)
#define FS_PK_ARR(a, v, n) ((a).p = (v), (a).count = count_u32(n))
#define FS_PK_OUT(a, v, n) ((a).out = (v), (a).count = count_u32(n))
#define FS_PK_E FS_PK_INT
#define FS_PK_BM FS_PK_INT
#define FS_PK_B FS_PK_INT
#define FS_PK_I FS_PK_INT
#define FS_PK_U FS_PK_INT
#define FS_PK_SZ FS_PK_INT
#define FS_PK_UB FS_PK_INT
#define FS_PK_BY FS_PK_INT
#define FS_PK_S FS_PK_INT
#define FS_PK_US FS_PK_INT
#define FS_PK_F FS_PK_FLT
#define FS_PK_D FS_PK_FLT
#define FS_PK_CF FS_PK_FLT
#define FS_PK_CD FS_PK_FLT
#define FS_PK_AF FS_PK_ARR
#define FS_PK_AD FS_PK_ARR
#define FS_PK_AI FS_PK_ARR
#define FS_PK_AU FS_PK_ARR
#define FS_PK_AUB FS_PK_ARR
#define FS_PK_ABY FS_PK_ARR
#define FS_PK_AS FS_PK_ARR
#define FS_PK_AUS FS_PK_ARR
#define FS_PK_BLOB FS_PK_ARR
#define FS_PK_CPTR(a, v, n) ((a).p = (v), (a).is_data = 0)
#define FS_PK_OV FS_PK_OUT
#define FS_PK_OF FS_PK_OUT
#define FS_PK_OD FS_PK_OUT
#define FS_PK_OI FS_PK_OUT
#define FS_PK_OU FS_PK_OUT
#define FS_PK_OUS FS_PK_OUT
#define FS_PK_OB FS_PK_OUT
#define FS_PK_OUB FS_PK_OUT
#define FS_PK_IP FS_PK_INT
#define FS_PK_OP FS_PK_OUT
#define FS_PK_AP(a, v, n) ((a).p = (v), (a).count = count_u32(n), (a).is_data = 0)
#define FS_PACK(k, kind, name, cnt) FS_PK_##kind(call.a[k], name, cnt);

#define FS_RETURN_V(r)
#define FS_RETURN_U(r) return (GLuint)(r).i;
#define FS_RETURN_E(r) return (GLenum)(r).i;
#define FS_RETURN_B(r) return (GLboolean)(r).i;
#define FS_RETURN_I(r) return (GLint)(r).i;
#define FS_RETURN_STR(r) return (const GLubyte *)(r).p;
#define FS_RETURN_P(r) return (r).out;

#define FS_CMD(name, rk, flags, n, ...)                                   \
    FS_CT_##rk fsgl##name(fs_context *c FS_MAP(n, FS_PDECL, __VA_ARGS__)) \
    {                                                                      \
        fs_call call;                                                      \
        memset(&call, 0, sizeof call);                                    \
        call.cmd = FS_CMD_##name;                                          \
        call.nargs = n;                                                    \
        FS_MAP(n, FS_PACK, __VA_ARGS__)                                    \
        fs_submit(c, &call);                                               \
        FS_RETURN_##rk(call.ret)                                          \
    }
#include "gl_commands.def"
#undef FS_CMD

/* ---- weak fallback executors: counted as unsupported, by name ---- */
/* The counts by command are driver knowledge (the command table), kept
 * in the context behind an opaque pointer made at the first such call;
 * out of memory, only the total in the statistics counts it. */
static void count_unsupported(fs_context *c, int cmd)
{
    c->stats.unsupported_calls++;
    if (!c->unsupported_cmds) {
        c->unsupported_cmds = calloc(FS_CMD_COUNT, sizeof *c->unsupported_cmds);
        if (!c->unsupported_cmds)
            return;
        c->driver_free = fs_driver_state_free;
    }
    c->unsupported_cmds[cmd]++;
}

bool fs_cmd_skippable(const fs_context *c, int cmd)
{
    if (cmd < 0 || cmd >= FS_CMD_COUNT)
        return false;
    bool draw = (fs_cmd_table[cmd].flags & (FS_F_PRIM | FS_F_DRAW)) || cmd == FS_CMD_Begin ||
                cmd == FS_CMD_Clear || cmd == FS_CMD_ReadPixels;
    return draw && !fs_dlist_compiling(c);
}

uint64_t fs_cmd_unsupported(const fs_context *c, int cmd)
{
    return c->unsupported_cmds && cmd >= 0 && cmd < FS_CMD_COUNT ? c->unsupported_cmds[cmd] : 0;
}

void fs_driver_state_free(fs_context *c)
{
    fs_dlist_free_all(c);
    free(c->unsupported_cmds);
    c->unsupported_cmds = NULL;
}

#define FS_PDECL_UNUSED(k, kind, name, cnt) , FS_CT_##kind name __attribute__((unused))
#define FS_ZERO_V
#define FS_ZERO_U return 0;
#define FS_ZERO_E return 0;
#define FS_ZERO_B return GL_FALSE;
#define FS_ZERO_I return 0;
#define FS_ZERO_STR return NULL;
#define FS_ZERO_P return NULL;
#define FS_CMD(name, rk, flags, n, ...)                                            \
    __attribute__((weak)) FS_CT_##rk fs_exec_##name(                              \
        fs_context *c FS_MAP(n, FS_PDECL_UNUSED, __VA_ARGS__))                     \
    {                                                                               \
        count_unsupported(c, FS_CMD_##name);                                       \
        FS_ZERO_##rk                                                              \
    }
#include "gl_commands.def"
#undef FS_CMD

/* ---- the dispatcher ---- */
/* An array argument must hold at least what the command reads. */
#define FS_CK_NONE(k, name, cnt, esize)
#define FS_CK_ARR(k, name, cnt, esize) \
    if ((int64_t)(cnt) > 0 && (name == NULL || (int64_t)call->a[k].count < (int64_t)(cnt))) \
        return bad_argument(c, call, k);
/* Outputs from a replayed trace have no buffer: give them scratch space.
 * More than FS_SCRATCH_MAX bytes (glGenQueries(1.6e9, ...) from a bad trace
 * asked for 6.5 GB before the command's own bound was reached) is
 * GL_OUT_OF_MEMORY and the command is not executed (GL 1.5 spec 2.5). */
#define FS_SCRATCH_MAX ((int64_t)1 << 30)
_Static_assert(FS_GEN_NAMES_MAX == FS_MAX_NAMES, "FS_GEN_COUNT bounds by the context's name limit");
#define FS_CK_OUT(k, name, cnt, esize) \
    if (name == NULL) {                                                        \
        int64_t need_ = (int64_t)(cnt) > 16 ? (int64_t)(cnt) : 16;             \
        if (need_ > FS_SCRATCH_MAX / (int64_t)(esize)) {                       \
            fs_error(c, GL_OUT_OF_MEMORY);                                     \
            return 0;                                                          \
        }                                                                      \
        name = fs_scratch(c, (size_t)need_ * (esize));                         \
        if (name == NULL) return bad_argument(c, call, k);                     \
    }
#define FS_CK_E FS_CK_NONE
#define FS_CK_BM FS_CK_NONE
#define FS_CK_B FS_CK_NONE
#define FS_CK_I FS_CK_NONE
#define FS_CK_U FS_CK_NONE
#define FS_CK_SZ FS_CK_NONE
#define FS_CK_UB FS_CK_NONE
#define FS_CK_BY FS_CK_NONE
#define FS_CK_S FS_CK_NONE
#define FS_CK_US FS_CK_NONE
#define FS_CK_F FS_CK_NONE
#define FS_CK_D FS_CK_NONE
#define FS_CK_CF FS_CK_NONE
#define FS_CK_CD FS_CK_NONE
#define FS_CK_CPTR FS_CK_NONE
#define FS_CK_AF FS_CK_ARR
#define FS_CK_AD FS_CK_ARR
#define FS_CK_AI FS_CK_ARR
#define FS_CK_AU FS_CK_ARR
#define FS_CK_AUB FS_CK_ARR
#define FS_CK_ABY FS_CK_ARR
#define FS_CK_AS FS_CK_ARR
#define FS_CK_AUS FS_CK_ARR
#define FS_CK_BLOB FS_CK_ARR
#define FS_CK_OV FS_CK_OUT
#define FS_CK_OF FS_CK_OUT
#define FS_CK_OD FS_CK_OUT
#define FS_CK_OI FS_CK_OUT
#define FS_CK_OU FS_CK_OUT
#define FS_CK_OUS FS_CK_OUT
#define FS_CK_OB FS_CK_OUT
#define FS_CK_OUB FS_CK_OUT
#define FS_CK_IP FS_CK_NONE
#define FS_CK_OP FS_CK_OUT
#define FS_CK_AP FS_CK_ARR
#define FS_CHECK(k, kind, name, cnt) FS_CK_##kind(k, name, cnt, FS_ESIZE_##kind)

#define FS_STORE_V(r, e) e
#define FS_STORE_U(r, e) (r).i = (int64_t)(e)
#define FS_STORE_E(r, e) (r).i = (int64_t)(e)
#define FS_STORE_B(r, e) (r).i = (int64_t)(e)
#define FS_STORE_I(r, e) (r).i = (int64_t)(e)
#define FS_STORE_STR(r, e) (r).p = (const void *)(e)
#define FS_STORE_P(r, e) (r).out = (e)

static int bad_argument(fs_context *c, fs_call *call, int k)
{
    (void)c;
    (void)call;
    (void)k;
    return -1;
}

/* ---- client arrays whose data came with the call (a replayed trace) ----
 *
 * GL trusts an application's array pointers; a trace's pointer call instead
 * carries its data, which lives only as long as the call.  The context keeps
 * its own copy, and a draw may read no further than that copy holds. */

/* The arrays that may hold such a copy, as indices of c->array_copy:
 * fs_client_array_at's (vertex, normal, colour, the texture coordinates of
 * each unit, secondary colour, fog coordinate, edge flag, index). */
#define N_COPIED_ARRAYS FS_CLIENT_ARRAYS
_Static_assert(N_COPIED_ARRAYS == sizeof(((fs_context *)0)->array_copy) / sizeof(((fs_context *)0)->array_copy[0]),
               "a copy per array");

static fs_client_array *array_of_copy(fs_context *c, int i) { return fs_client_array_at(&c->arrays, i); }

/* The copy a pointer call of fs_pointer_slot's slot writes: a texture
 * coordinate pointer is the client active unit's (GL 1.5 spec 2.8). */
static int copy_of_slot(const fs_context *c, int slot) { return fs_array_of_slot(slot, fs_client_active_unit(c)); }

int fs_pointer_slot(int cmd, int *pk)
{
    *pk = 3;
    switch (cmd) {
    case FS_CMD_VertexPointer: return 0;
    case FS_CMD_NormalPointer: *pk = 2; return 1; /* no size argument */
    case FS_CMD_ColorPointer: return 2;
    case FS_CMD_TexCoordPointer: return 3;
    case FS_CMD_SecondaryColorPointer: return 4;
    case FS_CMD_FogCoordPointer: *pk = 2; return 5;
    case FS_CMD_EdgeFlagPointer: *pk = 1; return 6;
    case FS_CMD_IndexPointer: *pk = 2; return 7;
    default: return -1;
    }
}

static int dispatch_call(fs_context *c, fs_call *call);

/* Executes a pointer call with data on a copy the context owns.  Of the two
 * copies per array the one the array does not point at is written, so a
 * call GL rejects leaves the array's data as it was. */
static int dispatch_pointer_data(fs_context *c, fs_call *call, int pointer_slot, int pk)
{
    int slot = copy_of_slot(c, pointer_slot);
    fs_client_array *arr = array_of_copy(c, slot);
    size_t n = call->a[pk].count;
    int k = arr->pointer == c->array_copy[slot].buf[0] && arr->pointer ? 1 : 0;
    if (n > c->array_copy[slot].cap[k] || !c->array_copy[slot].buf[k]) {
        void *d = realloc(c->array_copy[slot].buf[k], n ? n : 1);
        if (!d) {
            fs_unsupported(c, "array data (out of memory copying it)");
            return 0;
        }
        c->array_copy[slot].buf[k] = d;
        c->array_copy[slot].cap[k] = n ? n : 1;
    }
    if (n)
        memcpy(c->array_copy[slot].buf[k], call->a[pk].p, n);
    fs_call local = *call;
    local.a[pk].p = c->array_copy[slot].buf[k];
    int rc = dispatch_call(c, &local);
    if (arr->pointer == c->array_copy[slot].buf[k]) {
        arr->bytes = n;
        arr->buffer = 0; /* the data came with the call, whatever is bound */
    }
    return rc;
}

/* Whether enabled array a holds vertex hi (glNormalPointer sets size 3). */
static bool array_covers(const fs_client_array *a, int64_t hi)
{
    int ts = fs_type_size(a->type);
    if (ts <= 0 || a->size < 1 || a->stride < 0)
        return false;
    uint64_t elem = (uint64_t)ts * (uint64_t)a->size;
    uint64_t stride = a->stride ? (uint64_t)a->stride : elem;
    return (uint64_t)hi <= (UINT64_MAX - elem) / stride && (uint64_t)hi * stride + elem <= a->bytes;
}

/* False (and the draw counted by name) when an enabled array's data ends
 * before a vertex the draw reads.  GL leaves such a draw undefined (the
 * application reads past its memory); fragsim refuses it.  Arrays of the
 * application's memory (bytes SIZE_MAX), the usual case, need no index
 * scan. */
static bool draw_reads_in_bounds(fs_context *c, const fs_call *call)
{
    int64_t lo, hi = -1;
    for (int slot = 0; slot < N_COPIED_ARRAYS; slot++) {
        const fs_client_array *a = array_of_copy(c, slot);
        if (!a->enabled || a->bytes == SIZE_MAX)
            continue;
        if (hi < 0 && !fs_draw_vertex_range(call, &lo, &hi))
            return true; /* reads no vertex (or is an error GL reports) */
        if (!array_covers(a, hi)) {
            char what[96];
            snprintf(what, sizeof what, "%s (client array shorter than the draw reads)", fs_cmd_table[call->cmd].name);
            fs_unsupported(c, what);
            return false;
        }
    }
    return true;
}

/* in_bounds: the caller already checked the draw's reads
 * (draw_reads_in_bounds), which scans its indices. */
/* glBegin, glGet*, glIs* and glGetError: measured on OSMesa, they leave
 * Mesa's immediate-mode vertex format as it was (tests/test_constant_attribs.c). */
static bool is_query(int cmd)
{
    if (cmd == FS_CMD_Begin)
        return true;
    const char *n = fs_cmd_table[cmd].name;
    return strncmp(n, "glGet", 5) == 0 || strncmp(n, "glIs", 4) == 0;
}

static int dispatch(fs_context *c, fs_call *call, bool in_bounds)
{
    if (call->cmd >= FS_CMD_COUNT)
        return -1;
    c->stats.calls++;
    if (c->prim.inside_begin && !(fs_cmd_table[call->cmd].flags & FS_F_PRIM)) {
        /* GL 1.5 spec 2.6.3: only vertex attribute, material, array element
         * and call-list commands may appear between Begin and End. */
        fs_error(c, GL_INVALID_OPERATION);
        return 0;
    }
    if ((c->prim.vtx_attribs || c->prim.quads_run) && !(fs_cmd_table[call->cmd].flags & FS_F_PRIM) &&
        !is_query(call->cmd))
        fs_vs_format_reset(c); /* Mesa flushes its immediate vertices (vertex_stage.h) */
    if (!in_bounds && (fs_cmd_table[call->cmd].flags & FS_F_DRAW) && !draw_reads_in_bounds(c, call))
        return 0;
    int pk, slot = fs_pointer_slot(call->cmd, &pk);
    if (slot >= 0 && call->a[pk].is_data == FS_ARG_DATA)
        return dispatch_pointer_data(c, call, slot, pk);
    if (slot >= 0 && call->a[pk].is_data == FS_ARG_ADDR && !c->arrays.array_buffer) {
        /* A recorded address with no buffer bound is the traced program's
         * memory: set, never dereferenced (the array reads nothing). */
        fs_call local = *call;
        local.a[pk].p = NULL;
        local.a[pk].is_data = 0;
        return dispatch_call(c, &local);
    }
    if ((call->cmd == FS_CMD_SelectBuffer || call->cmd == FS_CMD_FeedbackBuffer) &&
        !call->a[call->nargs - 1].out) {
        /* No scratch space for these outputs: GL writes them after the
         * call.  A replayed call's buffer (FS_ARG_ADDR) is the traced
         * program's, so nothing is written and the size is no allocation
         * (a bad trace's 2^31 - 1); a program's NULL is its error. */
        bool replayed = call->a[call->nargs - 1].is_data == FS_ARG_ADDR;
        if (call->cmd == FS_CMD_SelectBuffer)
            fs_render_mode_select_buffer(c, (GLsizei)call->a[0].i, NULL);
        else
            fs_render_mode_feedback_buffer(c, (GLsizei)call->a[0].i, (GLenum)call->a[1].i, NULL, replayed);
        return 0;
    }
    if (call->cmd == FS_CMD_InterleavedArrays && call->a[2].is_data != 0 &&
        (call->a[2].is_data != FS_ARG_ADDR || !c->arrays.array_buffer)) {
        /* As the pointer calls: a recorded address with no buffer bound is
         * the traced program's memory, set as NULL (apitrace writes the
         * arrays' data as pointer calls before each draw).  Data with the
         * call (apitrace writes none) would outlive it in four arrays. */
        if (call->a[2].is_data == FS_ARG_DATA)
            fs_unsupported(c, "glInterleavedArrays (array data with the call)");
        fs_call local = *call;
        local.a[2].p = NULL;
        local.a[2].is_data = 0;
        return dispatch_call(c, &local);
    }
    if (call->cmd == FS_CMD_OcclusionBuffers && call->a[1].is_data != 0) {
        /* glOcclusionBuffers' second argument holds addresses the unit
         * writes to at glRenderMode: data or an address from a trace are no
         * addresses of this process, so the records stay in the unit. */
        fs_call local = *call;
        local.a[1].p = NULL;
        local.a[1].is_data = 0;
        return dispatch_call(c, &local);
    }
    return dispatch_call(c, call);
}

static int submit_call(fs_context *c, fs_call *call);

/* ---- draws sourcing buffer objects (GL 1.5 spec 2.9.1, 2.9.2) ---- */

/* The indices of glDrawElements and glDrawRangeElements while a buffer is
 * bound to GL_ELEMENT_ARRAY_BUFFER are an offset into it: *call then points
 * at the store.  False when the draw cannot run: indices past the store
 * (GL leaves that undefined; Mesa draws nothing and raises no error), or a
 * recorded address with no buffer bound (the traced program's memory). */
static bool resolve_indices(fs_context *c, fs_call *call)
{
    int k = call->cmd == FS_CMD_DrawElements ? 3 : call->cmd == FS_CMD_DrawRangeElements ? 5 : -1;
    if (k < 0)
        return true;
    fs_arg *a = &call->a[k];
    const char *why = "indices not recorded in the trace";
    if (c->arrays.element_buffer) {
        size_t bytes;
        const void *p = fs_buffer_element_data(c, (uint64_t)a->i, &bytes);
        int64_t need = fs_index_bytes((GLsizei)call->a[k - 2].i, (GLenum)call->a[k - 1].i);
        /* exactly the indices: a display list compiling the draw copies them */
        a->p = p;
        a->count = need > 0 && (uint64_t)need <= bytes ? (uint32_t)need : 0;
        a->is_data = 0;
        if (need <= 0 || (uint64_t)need <= bytes)
            return true;
        why = "indices past the element array buffer";
    } else if (a->is_data != FS_ARG_ADDR) {
        return true;
    }
    char what[96];
    snprintf(what, sizeof what, "%s (%s)", fs_cmd_table[call->cmd].name, why);
    fs_unsupported(c, what);
    return false;
}

/* Runs a draw (submit: as fs_submit, else as fs_dispatch) with the arrays
 * that source buffer objects pointing into their stores for its duration,
 * each as long as its store, so that the bounds check of client arrays
 * refuses a read past one (draw_reads_in_bounds). */
static int draw_with_buffers(fs_context *c, const fs_call *call, bool submit)
{
    fs_call local = *call;
    if (!resolve_indices(c, &local))
        return 0;
    fs_array_state saved = c->arrays;
    fs_buffer_resolve_arrays(c, &c->arrays);
    int rc = submit ? submit_call(c, &local) : dispatch(c, &local, false);
    c->arrays = saved;
    return rc;
}

/* glMultiDrawElements as its glDrawElements calls (GL 1.4 spec 2.8), each
 * routed as a draw of its own (submit: fs_submit, else fs_dispatch): its
 * indices an offset into the element array buffer when one is bound, a
 * display list compiling each draw with the vertices it dereferences, a
 * capture writing each.  While a list is compiled, Mesa (the oracle)
 * compiles the draws of a positive count without checking the call, and
 * each draw's errors are raised when the list runs; executed, a bad
 * argument draws nothing. */
static int multi_draw_elements(fs_context *c, const fs_call *call, bool submit)
{
    const GLsizei *count = call->a[1].p;
    const GLvoid *const *indices = call->a[3].p;
    GLsizei n = (GLsizei)call->a[4].i;
    if (n > 0 && (!count || !indices || call->a[1].count < (uint32_t)n || call->a[3].count < (uint32_t)n))
        return -1;
    bool compiling = submit && fs_dlist_compiling(c);
    if (!compiling) {
        if (c->prim.inside_begin) {
            fs_error(c, GL_INVALID_OPERATION); /* GL 1.5 spec 2.6.3 */
            return 0;
        }
        if (!fs_multidraw_elements_valid(c, (GLenum)call->a[0].i, count, (GLenum)call->a[2].i, n))
            return 0;
        /* With client indices, one NULL pointer draws nothing (as OSMesa). */
        for (GLsizei i = 0; i < n && !c->arrays.element_buffer; i++)
            if (!indices[i] && call->a[3].is_data != FS_ARG_ADDR)
                return 0;
    }
    int rc = 0;
    for (GLsizei i = 0; i < n && rc == 0; i++) {
        if (compiling && count[i] <= 0)
            continue;
        fs_call d;
        memset(&d, 0, sizeof d);
        d.cmd = FS_CMD_DrawElements;
        d.nargs = 4;
        d.flags = call->flags;
        d.a[0].i = call->a[0].i;
        d.a[1].i = count[i];
        d.a[2].i = call->a[2].i;
        d.a[3].p = indices[i];
        d.a[3].is_data = call->a[3].is_data == FS_ARG_ADDR ? FS_ARG_ADDR : 0;
        int64_t bytes = fs_index_bytes(count[i], (GLenum)call->a[2].i);
        d.a[3].count = d.a[3].is_data == FS_ARG_ADDR ? 0 : count_u32(bytes);
        rc = submit ? fs_submit(c, &d) : draw_with_buffers(c, &d, false);
    }
    return rc;
}

int fs_dispatch(fs_context *c, fs_call *call)
{
    if (call->cmd == FS_CMD_MultiDrawElements)
        return multi_draw_elements(c, call, false);
    if (call->cmd < FS_CMD_COUNT && (fs_cmd_table[call->cmd].flags & FS_F_DRAW))
        return draw_with_buffers(c, call, false);
    return dispatch(c, call, false);
}

static int dispatch_call(fs_context *c, fs_call *call)
{
    switch ((enum fs_cmd)call->cmd) {
#define FS_CMD(name, rk, flags, n, ...)                                        \
    case FS_CMD_##name: {                                                       \
        FS_MAP(n, FS_LOCAL, __VA_ARGS__)                                        \
        FS_MAP(n, FS_CHECK, __VA_ARGS__)                                        \
        FS_STORE_##rk(call->ret, fs_exec_##name(c FS_MAP(n, FS_ANAME, __VA_ARGS__))); \
        break;                                                                  \
    }
#include "gl_commands.def"
#undef FS_CMD
    case FS_CMD_COUNT:
        return -1;
    }
    return 0;
}

/* Array-length validation alone, for checking a whole trace before any of
 * it executes (replay's first pass).  Returns -1 - k for a short argument k. */
#define FS_VLOCAL(k, kind, name, cnt) FS_CT_##kind name = FS_UP_##kind(FS_CT_##kind, call->a[k]); (void)name;
/* A draw's indices given as a recorded address are checked at the draw,
 * against the element array buffer they are an offset into. */
#define FS_VCK_ARR(k, name, cnt) \
    if (call->a[k].is_data != FS_ARG_ADDR && (int64_t)(cnt) > 0 && \
        (name == NULL || (int64_t)call->a[k].count < (int64_t)(cnt)))         \
        return -1 - (k);
#define FS_VCK_E(k, name, cnt)
#define FS_VCK_BM FS_VCK_E
#define FS_VCK_B FS_VCK_E
#define FS_VCK_I FS_VCK_E
#define FS_VCK_U FS_VCK_E
#define FS_VCK_SZ FS_VCK_E
#define FS_VCK_UB FS_VCK_E
#define FS_VCK_BY FS_VCK_E
#define FS_VCK_S FS_VCK_E
#define FS_VCK_US FS_VCK_E
#define FS_VCK_F FS_VCK_E
#define FS_VCK_D FS_VCK_E
#define FS_VCK_CF FS_VCK_E
#define FS_VCK_CD FS_VCK_E
#define FS_VCK_CPTR FS_VCK_E
#define FS_VCK_OV FS_VCK_E
#define FS_VCK_OF FS_VCK_E
#define FS_VCK_OD FS_VCK_E
#define FS_VCK_OI FS_VCK_E
#define FS_VCK_OU FS_VCK_E
#define FS_VCK_OUS FS_VCK_E
#define FS_VCK_OB FS_VCK_E
#define FS_VCK_OUB FS_VCK_E
#define FS_VCK_IP FS_VCK_E
#define FS_VCK_OP FS_VCK_E
#define FS_VCK_AF FS_VCK_ARR
#define FS_VCK_AD FS_VCK_ARR
#define FS_VCK_AI FS_VCK_ARR
#define FS_VCK_AU FS_VCK_ARR
#define FS_VCK_AUB FS_VCK_ARR
#define FS_VCK_ABY FS_VCK_ARR
#define FS_VCK_AS FS_VCK_ARR
#define FS_VCK_AUS FS_VCK_ARR
#define FS_VCK_BLOB FS_VCK_ARR
/* The pointers themselves are always there, addresses or not. */
#define FS_VCK_AP(k, name, cnt) \
    if ((int64_t)(cnt) > 0 && (name == NULL || (int64_t)call->a[k].count < (int64_t)(cnt))) \
        return -1 - (k);
#define FS_VCHECK(k, kind, name, cnt) FS_VCK_##kind(k, name, cnt)
/* Output counts may need a context; validation never evaluates them. */
#define fs_readpixels_bytes(c, w, h, f, t) 0
#define fs_occlusion_tile_count(c) 0
#define fs_teximage_bytes(c, w, h, f, t) 0
#define fs_getmap_count(c, t, q) 0
#define fs_teximage_nd_bytes(c, n, w, h, d, f, t) 0

int fs_call_validate(const fs_call *call)
{
    switch ((enum fs_cmd)call->cmd) {
#define FS_CMD(name, rk, flags, n, ...)                 \
    case FS_CMD_##name: {                               \
        FS_MAP(n, FS_VLOCAL, __VA_ARGS__)               \
        FS_MAP(n, FS_VCHECK, __VA_ARGS__)               \
        return 0;                                       \
    }
#include "gl_commands.def"
#undef FS_CMD
    case FS_CMD_COUNT:
        break;
    }
    return -1 - FS_MAX_ARGS;
}
#undef fs_readpixels_bytes
#undef fs_occlusion_tile_count
#undef fs_teximage_bytes
#undef fs_getmap_count
#undef fs_teximage_nd_bytes

/* GL_COMPILE_AND_EXECUTE: a call the list compiler says is due now. */
static int run_compiled(fs_context *c, fs_call *call)
{
    return dispatch(c, call, true);
}

/* fs_submit without the capture. */
static int submit_call(fs_context *c, fs_call *call)
{
    uint32_t flags = fs_cmd_table[call->cmd].flags;
    int rc = 0;
    if (fs_dlist_compiling(c) && (flags & FS_F_LIST)) {
        /* Compiling copies the vertices a draw reads (display_list.c). */
        if (!(flags & FS_F_DRAW) || draw_reads_in_bounds(c, call))
            rc = fs_dlist_compile(c, call, run_compiled);
    } else {
        rc = dispatch(c, call, false);
    }
    return rc;
}

int fs_submit(fs_context *c, fs_call *call)
{
    if (call->cmd == FS_CMD_MultiDrawElements)
        return multi_draw_elements(c, call, true); /* each draw captured */
    int rc = (fs_cmd_table[call->cmd].flags & FS_F_DRAW) ? draw_with_buffers(c, call, true) : submit_call(c, call);
    if (c->capture)
        fs_capture_call(c, call);
    return rc;
}
