/*
 * Generated from the state table (pipeline/state.def, GL 1.5 spec 6.2):
 * initial values, glGet of stored and constant variables, enable caps,
 * the server and client attribute stacks (6.1.14) and dirty bits.
 */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "context.h"
#include "state.h"
#include "../units/texture_unit.h"

#define FS_UNPAREN(...) __VA_ARGS__

/* Storage type and glGet class of each table type. */
#define FS_CTYPE_B bool
#define FS_CTYPE_BI GLint
#define FS_CTYPE_I GLint
#define FS_CTYPE_U GLuint
#define FS_CTYPE_E GLenum
#define FS_CTYPE_F float
#define FS_CTYPE_FN float
#define FS_CTYPE_DN double
#define FS_CLS_B FS_GET_BOOL
#define FS_CLS_BI FS_GET_BOOL
#define FS_CLS_I FS_GET_NUM
#define FS_CLS_U FS_GET_NUM
#define FS_CLS_E FS_GET_ENUM
#define FS_CLS_F FS_GET_NUM
#define FS_CLS_FN FS_GET_NORM
#define FS_CLS_DN FS_GET_NORM
enum store_type { T_B, T_BI, T_I, T_U, T_E, T_F, T_FN, T_DN, T_NONE };

#define MEMBER_SIZE(member) sizeof(((fs_context *)0)->member)

/* The rows' public part, in the table's order. */
static const fs_state_info rows[] = {
#define FS_STATE(name, groups, type, count, member, init, cap) \
    {name, #name, groups, FS_CLS_##type, count, FS_STATE_FIELD, FS_CAP_##cap},
#define FS_STATE_RT(name, groups, type, count, member, cap) \
    {name, #name, groups, FS_CLS_##type, count, FS_STATE_FIELD, FS_CAP_##cap},
#define FS_STATE_GET(name, groups, type, count) \
    {name, #name, groups, FS_CLS_##type, count, FS_STATE_COMPUTED, FS_CAP_NO},
#define FS_STATE_CONST(name, type, count, values) \
    {name, #name, 0, FS_CLS_##type, count, FS_STATE_CONSTANT, FS_CAP_NO},
#define FS_STATE_PUSH(groups, member) {0, #member, groups, FS_GET_NUM, 0, FS_STATE_PUSH_ONLY, FS_CAP_NO},
#define FS_STATE_TU(name, groups, type, count, array, elem, init, cap, unit) \
    {name, #name, groups, FS_CLS_##type, count, FS_STATE_FIELD, FS_CAP_##cap},
#define FS_STATE_PUSH_TU(groups, array, elem) {0, #array #elem, groups, FS_GET_NUM, 0, FS_STATE_PUSH_ONLY, FS_CAP_NO},
#include "state.def"
};
#define N_ROWS ((int)(sizeof rows / sizeof rows[0]))

/* Where each row lives in fs_context (size 0: not stored there).  A
 * per-unit row (FS_STATE_TU) lives at offset + u * stride for each texture
 * unit u; unit says which unit glGet answers for (0: not per unit). */
enum unit_sel { U_NONE, U_ACTIVE, U_CLIENT };
static const struct store {
    enum store_type type;
    size_t offset, size, stride;
    enum unit_sel unit;
} store[] = {
#define FS_STATE(name, groups, type, count, member, init, cap) \
    {T_##type, offsetof(fs_context, member), MEMBER_SIZE(member), 0, U_NONE},
#define FS_STATE_RT(name, groups, type, count, member, cap) \
    {T_##type, offsetof(fs_context, member), MEMBER_SIZE(member), 0, U_NONE},
#define FS_STATE_GET(name, groups, type, count) {T_NONE, 0, 0, 0, U_NONE},
#define FS_STATE_CONST(name, type, count, values) {T_NONE, 0, 0, 0, U_NONE},
#define FS_STATE_PUSH(groups, member) {T_NONE, offsetof(fs_context, member), MEMBER_SIZE(member), 0, U_NONE},
#define FS_STATE_TU(name, groups, type, count, array, elem, init, cap, unit) \
    {T_##type, offsetof(fs_context, array[0] elem), MEMBER_SIZE(array[0] elem), MEMBER_SIZE(array[0]), U_##unit},
#define FS_STATE_PUSH_TU(groups, array, elem) \
    {T_NONE, offsetof(fs_context, array[0] elem), MEMBER_SIZE(array[0] elem), MEMBER_SIZE(array[0]), U_ACTIVE},
#include "state.def"
};

/* Each stored row's field holds exactly `count` values of its type. */
#define FS_STATE(name, groups, type, count, member, init, cap) \
    _Static_assert(MEMBER_SIZE(member) == (count) * sizeof(FS_CTYPE_##type), #name " size");
#define FS_STATE_RT(name, groups, type, count, member, cap) \
    _Static_assert(MEMBER_SIZE(member) == (count) * sizeof(FS_CTYPE_##type), #name " size");
#define FS_STATE_TU(name, groups, type, count, array, elem, init, cap, unit) \
    _Static_assert(MEMBER_SIZE(array[0] elem) == (count) * sizeof(FS_CTYPE_##type), #name " size"); \
    _Static_assert(MEMBER_SIZE(array) == FS_MAX_TEXTURE_UNITS * MEMBER_SIZE(array[0]), #name " units");
#include "state.def"

const fs_state_info *fs_state_rows(int *count)
{
    *count = N_ROWS;
    return rows;
}

void fs_state_init(fs_context *c)
{
#define FS_STATE(name, groups, type, count, member, init, cap)                         \
    {                                                                                \
        static const FS_CTYPE_##type v[count] = {FS_UNPAREN init};                     \
        memcpy(&c->member, v, sizeof v);                                             \
    }
#define FS_STATE_TU(name, groups, type, count, array, elem, init, cap, unit)           \
    {                                                                                \
        static const FS_CTYPE_##type v[count] = {FS_UNPAREN init};                     \
        for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++)                               \
            memcpy(&c->array[u] elem, v, sizeof v);                                  \
    }
#include "state.def"
    /* Nothing is derived yet: the first validation derives everything. */
    c->dirty = ~(uint32_t)0;
}

static int find_row(GLenum pname)
{
    for (int i = 0; i < N_ROWS; i++)
        if (rows[i].name == pname && rows[i].kind != FS_STATE_PUSH_ONLY)
            return i;
    return -1;
}

int fs_state_count(GLenum pname)
{
    int i = find_row(pname);
    return i < 0 ? 1 : rows[i].count;
}

/* Where row's value lives now: a per-unit row's for the unit it follows. */
static size_t field_offset(const fs_context *c, int row)
{
    const struct store *s = &store[row];
    switch (s->unit) {
    case U_ACTIVE: return s->offset + (size_t)fs_active_unit(c) * s->stride;
    case U_CLIENT: return s->offset + (size_t)fs_client_active_unit(c) * s->stride;
    default: return s->offset;
    }
}

static double load(const fs_context *c, int row, int k)
{
    const char *p = (const char *)c + field_offset(c, row);
    switch (store[row].type) {
    case T_B: return ((const bool *)(const void *)p)[k];
    case T_BI: case T_I: return ((const GLint *)(const void *)p)[k];
    case T_U: return ((const GLuint *)(const void *)p)[k];
    case T_E: return ((const GLenum *)(const void *)p)[k];
    case T_F: case T_FN: return ((const float *)(const void *)p)[k];
    case T_DN: return ((const double *)(const void *)p)[k];
    default: return 0.0;
    }
}

/* The values of a constant row. */
static bool get_constant(GLenum pname, double *v)
{
    switch (pname) {
#define FS_STATE_CONST(name, type, count, values)                                     \
    case name: {                                                                     \
        static const double k[count] = {FS_UNPAREN values};                            \
        memcpy(v, k, sizeof k);                                                      \
        return true;                                                                 \
    }
#include "state.def"
    default: return false;
    }
}

bool fs_state_get(fs_context *c, GLenum pname, fs_get_value *r)
{
    int i = find_row(pname);
    if (i < 0 || rows[i].kind == FS_STATE_COMPUTED)
        return false;
    r->n = rows[i].count;
    r->cls = rows[i].cls;
    if (rows[i].kind == FS_STATE_CONSTANT)
        return get_constant(pname, r->v);
    for (int k = 0; k < r->n; k++)
        r->v[k] = load(c, i, k);
    return true;
}

bool *fs_state_cap_flag(fs_context *c, GLenum cap, bool client_too, const fs_state_info **row)
{
    int i = find_row(cap);
    if (row)
        *row = i < 0 ? NULL : &rows[i];
    bool *tex = fs_texture_enable_flag(c, cap); /* GL_TEXTURE_1D..CUBE_MAP: the texture unit's own flag */
    if (tex)
        return tex;
    if (i < 0 || rows[i].cap == FS_CAP_NO || (rows[i].cap == FS_CAP_CLI && !client_too))
        return NULL;
    return (bool *)(void *)((char *)c + field_offset(c, i));
}

void *fs_state_field(fs_context *c, GLenum pname, uint32_t groups, const fs_state_info **row)
{
    int i = find_row(pname);
    if (i < 0 || !(rows[i].groups & groups) || !store[i].size)
        return NULL;
    if (row)
        *row = &rows[i];
    return (char *)c + field_offset(c, i);
}

void fs_state_mark(fs_context *c, uint32_t groups) { c->dirty |= groups; }

/* ---- attribute stacks (GL 1.5 spec 6.1.14) ---- */

/* One glPushAttrib or glPushClientAttrib: the groups pushed and the bytes
 * of every stored row in one of them, in the table's order. */
typedef struct attrib_record {
    uint32_t mask;
    unsigned char *data;
    /* GL_TEXTURE_BIT / GL_ENABLE_BIT state the texture unit keeps: the
     * enables of every unit's targets, the rest of the texture group. */
    uint64_t texture_enables;
    fs_texture_attrib texture;
} attrib_record;

_Static_assert(FS_ATTRIB_STACK_DEPTH == FS_CLIENT_ATTRIB_STACK_DEPTH, "one depth check for both stacks");
struct fs_attrib_stack {
    attrib_record server[FS_ATTRIB_STACK_DEPTH];
    attrib_record client[FS_CLIENT_ATTRIB_STACK_DEPTH];
};

static bool saved(int i, uint32_t mask) { return (rows[i].groups & mask) && store[i].size; }

/* The bytes a push saves of row i: every texture unit's for a per-unit row. */
static size_t saved_size(int i) { return store[i].size * (store[i].stride ? FS_MAX_TEXTURE_UNITS : 1); }

/* Copies the rows of the groups in mask from the context into rec (save)
 * or back (restore). */
static void copy_rows(fs_context *c, attrib_record *rec, bool save)
{
    size_t at = 0;
    for (int i = 0; i < N_ROWS; i++) {
        if (!saved(i, rec->mask))
            continue;
        for (int u = 0; u < (store[i].stride ? FS_MAX_TEXTURE_UNITS : 1); u++) {
            char *field = (char *)c + store[i].offset + (size_t)u * store[i].stride;
            if (save)
                memcpy(rec->data + at, field, store[i].size);
            else
                memcpy(field, rec->data + at, store[i].size);
            at += store[i].size;
        }
    }
}

static bool push(fs_context *c, attrib_record *rec, uint32_t mask)
{
    size_t bytes = 0;
    for (int i = 0; i < N_ROWS; i++)
        if (saved(i, mask))
            bytes += saved_size(i);
    rec->data = malloc(bytes ? bytes : 1);
    if (!rec->data) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return false;
    }
    rec->mask = mask;
    copy_rows(c, rec, true);
    rec->texture_enables = fs_texture_enables(c);
    if (mask & GL_TEXTURE_BIT)
        fs_texture_attrib_save(c, &rec->texture);
    return true;
}

static void pop(fs_context *c, attrib_record *rec)
{
    copy_rows(c, rec, false);
    if (rec->mask & GL_TEXTURE_BIT)
        fs_texture_attrib_restore(c, &rec->texture);
    if (rec->mask & (GL_TEXTURE_BIT | GL_ENABLE_BIT))
        fs_texture_set_enables(c, rec->texture_enables); /* and what the rasterizer interpolates */
    fs_state_mark(c, rec->mask);
    free(rec->data);
    rec->data = NULL;
}

/* The server or the client stack and its depth, created on first use
 * (NULL after GL_OUT_OF_MEMORY). */
static attrib_record *stack_of(fs_context *c, bool client, GLint **depth)
{
    *depth = client ? &c->client_attrib_depth : &c->attrib_depth;
    if (!c->attrib_stack)
        c->attrib_stack = calloc(1, sizeof *c->attrib_stack);
    if (!c->attrib_stack) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return NULL;
    }
    return client ? c->attrib_stack->client : c->attrib_stack->server;
}

/* GL 1.5 spec 6.1.14: pushing onto a full stack is GL_STACK_OVERFLOW,
 * popping an empty one GL_STACK_UNDERFLOW, and neither changes state.
 * Between Begin and End they are GL_INVALID_OPERATION (driver/dispatch.c;
 * OSMesa raises it for the client stack too).  Both stacks are 16 deep. */
static void push_groups(fs_context *c, bool client, uint32_t groups)
{
    GLint *depth;
    attrib_record *stack = stack_of(c, client, &depth);
    if (stack && *depth >= FS_ATTRIB_STACK_DEPTH)
        fs_error(c, GL_STACK_OVERFLOW);
    else if (stack && push(c, &stack[*depth], groups))
        ++*depth;
}

static void pop_groups(fs_context *c, bool client)
{
    GLint *depth;
    attrib_record *stack = stack_of(c, client, &depth);
    if (stack && *depth == 0)
        fs_error(c, GL_STACK_UNDERFLOW);
    else if (stack)
        pop(c, &stack[--*depth]);
}

void fs_exec_PushAttrib(fs_context *c, GLbitfield mask) { push_groups(c, false, mask & ~FS_CLIENT_GROUPS); }
void fs_exec_PopAttrib(fs_context *c) { pop_groups(c, false); }

void fs_exec_PushClientAttrib(fs_context *c, GLbitfield mask)
{
    push_groups(c, true, (mask & GL_CLIENT_PIXEL_STORE_BIT ? FS_CLIENT_PIXEL_STORE : 0) |
                             (mask & GL_CLIENT_VERTEX_ARRAY_BIT ? FS_CLIENT_VERTEX_ARRAY : 0));
}

void fs_exec_PopClientAttrib(fs_context *c) { pop_groups(c, true); }

void fs_state_free(fs_context *c)
{
    if (!c->attrib_stack)
        return;
    for (int i = 0; i < c->attrib_depth; i++)
        free(c->attrib_stack->server[i].data);
    for (int i = 0; i < c->client_attrib_depth; i++)
        free(c->attrib_stack->client[i].data);
    free(c->attrib_stack);
    c->attrib_stack = NULL;
}
