/*
 * Display lists (GL 1.5 spec 5.4).  A list is a sequence of fs_call records
 * with deep copies of their array arguments.  Commands that read client
 * arrays are stored with a snapshot of the array state and of the vertex
 * data they dereference, because GL 1.5 spec 5.4 says client state is
 * dereferenced when the list is compiled, not when it is executed.
 */
#include <stdlib.h>
#include <string.h>
#include "../pipeline/context.h"
#include "../pipeline/pixel_transfer.h"
#include "../pipeline/name_map.h"
#include "display_list.h"

/* GL leaves the nesting limit to the implementation (GL_MAX_LIST_NESTING,
 * at least 64); Mesa uses 64. */
#define FS_MAX_LIST_NESTING 64

typedef struct dl_entry {
    fs_call call;
    fs_array_state *arrays; /* non-NULL for FS_F_DRAW commands: the snapshot */
    /* For commands that unpack an image (glTexImage2D, glTexSubImage2D):
     * the unpack state at compile time, which GL 1.5 spec 5.4 says the
     * list uses ("pixel data are unpacked when the list is compiled"). */
    bool has_unpack;
    fs_pixel_store unpack;
} dl_entry;

typedef struct dl_list {
    GLuint name;
    dl_entry *entries;
    size_t n, cap;
    void **blocks; /* copied argument data and vertex snapshots */
    size_t nblocks, blocks_cap;
} dl_list;

typedef struct fs_dlist_state {
    fs_name_map names; /* the lists held, by name */
    dl_list *building; /* between glNewList and glEndList */
    GLenum mode;
    int depth;
    bool oom; /* out of memory while compiling: EndList raises GL_OUT_OF_MEMORY */
    /* Mesa's list compiler between a compiled glBegin and the first command it
     * cannot keep in its vertex buffer (see vbo_role): `vbo` is set, and the
     * entries from `held` on are vertex attributes given since the last
     * vertex, which that command discards. */
    bool vbo;
    size_t held;
} fs_dlist_state;

static fs_dlist_state *state(fs_context *c)
{
    if (!c->lists && (c->lists = calloc(1, sizeof(fs_dlist_state))) != NULL)
        c->driver_free = fs_driver_state_free;
    return c->lists;
}

static void list_free(dl_list *l)
{
    if (!l)
        return;
    for (size_t i = 0; i < l->nblocks; i++)
        free(l->blocks[i]);
    free(l->blocks);
    free(l->entries);
    free(l);
}

void fs_dlist_free_all(fs_context *c)
{
    fs_dlist_state *s = c->lists;
    if (!s)
        return;
    size_t pos = 0;
    for (dl_list *l; (l = fs_name_map_next(&s->names, &pos, NULL));)
        list_free(l);
    fs_name_map_clear(&s->names);
    list_free(s->building);
    free(s);
    c->lists = NULL;
}

static dl_list *find_list(fs_dlist_state *s, GLuint name)
{
    return fs_name_map_get(&s->names, name);
}

static int insert_list(fs_dlist_state *s, dl_list *l)
{
    return fs_name_map_put(&s->names, l->name, l);
}

static void delete_list(fs_dlist_state *s, GLuint name)
{
    list_free(fs_name_map_remove(&s->names, name));
}

bool fs_dlist_compiling(const fs_context *c)
{
    return c->lists && c->lists->building;
}

static void *keep(fs_dlist_state *s, dl_list *l, const void *src, size_t bytes)
{
    if (l->nblocks == l->blocks_cap) {
        size_t cap = l->blocks_cap ? l->blocks_cap * 2 : 16;
        void **b = realloc(l->blocks, cap * sizeof *b);
        if (!b) {
            s->oom = true;
            return NULL;
        }
        l->blocks = b;
        l->blocks_cap = cap;
    }
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        s->oom = true;
        return NULL;
    }
    if (src && bytes)
        memcpy(p, src, bytes);
    l->blocks[l->nblocks++] = p;
    return p;
}

/* Bytes between consecutive elements of a client array (GL 1.5 spec 2.8:
 * stride 0 means tightly packed). */
static size_t array_stride(const fs_client_array *a, int ncomp)
{
    return a->stride ? (size_t)a->stride : (size_t)fs_type_size(a->type) * (size_t)ncomp;
}

static void snapshot_array(fs_dlist_state *s, dl_list *l, fs_client_array *dst,
                           const fs_client_array *src, int ncomp, int64_t lo, int64_t hi)
{
    *dst = *src;
    if (!src->enabled || !src->pointer)
        return;
    size_t stride = array_stride(src, ncomp);
    size_t elem = (size_t)fs_type_size(src->type) * (size_t)ncomp;
    size_t n = (size_t)(hi - lo + 1);
    size_t bytes = (n - 1) * stride + elem;
    const char *from = (const char *)src->pointer + (size_t)lo * stride;
    char *copy = keep(s, l, from, bytes);
    if (!copy) {
        dst->enabled = false;
        return;
    }
    /* Index i of the snapshot lives at copy + (i - lo) * stride. */
    dst->pointer = copy - (ptrdiff_t)((size_t)lo * stride);
}

static bool append(fs_context *c, const fs_call *call)
{
    fs_dlist_state *s = c->lists;
    dl_list *l = s->building;
    if (l->n == l->cap) {
        size_t cap = l->cap ? l->cap * 2 : 64;
        dl_entry *e = realloc(l->entries, cap * sizeof *e);
        if (!e) {
            s->oom = true;
            return false;
        }
        l->entries = e;
        l->cap = cap;
    }
    dl_entry *e = &l->entries[l->n];
    e->call = *call;
    e->arrays = NULL;
    /* The image blob was sized by the current unpack state
     * (fs_teximage_bytes); keep that state with it. */
    e->has_unpack = call->cmd == FS_CMD_TexImage2D || call->cmd == FS_CMD_TexSubImage2D ||
                    call->cmd == FS_CMD_TexImage1D || call->cmd == FS_CMD_TexSubImage1D ||
                    call->cmd == FS_CMD_TexImage3D || call->cmd == FS_CMD_TexSubImage3D ||
                    call->cmd == FS_CMD_Bitmap || call->cmd == FS_CMD_DrawPixels ||
                    call->cmd == FS_CMD_PolygonStipple;
    e->unpack = fs_pixel_store_unpack(c);
    const fs_cmd_info *info = &fs_cmd_table[call->cmd];
    for (int i = 0; i < info->nargs; i++) {
        size_t es = fs_kind_elem_size(info->kinds[i]);
        if (es && call->a[i].p) {
            e->call.a[i].p = keep(s, l, call->a[i].p, es * call->a[i].count);
            if (!e->call.a[i].p)
                return false;
        }
    }
    if (info->flags & FS_F_DRAW) {
        int64_t lo, hi;
        fs_array_state *snap = keep(s, l, &c->arrays, sizeof c->arrays);
        if (!snap)
            return false;
        if (fs_draw_vertex_range(&e->call, &lo, &hi)) {
            for (int k = 0; k < FS_CLIENT_ARRAYS; k++) {
                const fs_client_array *a = fs_client_array_at(&c->arrays, k);
                snapshot_array(s, l, fs_client_array_at(snap, k), a, k == 1 ? 3 : a->size, lo, hi);
            }
        } else {
            memset(snap, 0, sizeof *snap);
        }
        e->arrays = snap;
    }
    l->n++;
    return true;
}

/* How Mesa's display-list compiler (Mesa 22, vbo save mode) treats a call
 * between glBegin and glEnd: vertex attributes are held until the next
 * vertex; glEvalCoord, glEvalPoint and glCallList(s) make it leave its vertex
 * buffer, and the attributes held at that moment are lost: neither stored
 * in the list nor executed in GL_COMPILE_AND_EXECUTE mode.  After that the
 * primitive's commands are stored one by one and nothing more is lost until
 * glEnd.  Measured through libOSMesa (tests/test_list_state.c
 * begin_attributes_lost_at_fallback_vs_osmesa): colours, normals, texture
 * coordinates and materials are lost, glArrayElement counts as a vertex,
 * and each glBegin of a list starts over.  GL 1.5 spec 5.4 would keep them;
 * piglit's dlist-fdo31590 tests exactly this, and llvmpipe fails it. */
enum vbo_role { VBO_OTHER, VBO_BEGIN, VBO_END, VBO_VERTEX, VBO_ATTRIB, VBO_FALLBACK };

static enum vbo_role vbo_role(unsigned cmd)
{
    const char *n = fs_cmd_table[cmd].name;
    if (!strcmp(n, "glBegin"))
        return VBO_BEGIN;
    if (!(fs_cmd_table[cmd].flags & FS_F_PRIM))
        return VBO_OTHER;
    if (!strcmp(n, "glEnd"))
        return VBO_END;
    if (!strncmp(n, "glVertex", 8) || !strcmp(n, "glArrayElement"))
        return VBO_VERTEX;
    if (!strncmp(n, "glEvalCoord", 11) || !strncmp(n, "glEvalPoint", 11) || !strncmp(n, "glCallList", 10))
        return VBO_FALLBACK;
    return VBO_ATTRIB;
}

int fs_dlist_compile(fs_context *c, fs_call *call, int (*run)(fs_context *, fs_call *))
{
    fs_dlist_state *s = c->lists;
    dl_list *l = s ? s->building : NULL;
    if (!l)
        return 0;
    bool exec = s->mode == GL_COMPILE_AND_EXECUTE;
    enum vbo_role role = vbo_role(call->cmd);
    if (s->vbo && role == VBO_ATTRIB) {
        append(c, call); /* held: run with the next vertex */
        return 0;
    }
    int rc = 0;
    if (s->vbo && role == VBO_FALLBACK) {
        l->n = s->held; /* lost (their copied data stays in l->blocks) */
        s->vbo = false;
    } else if (s->vbo && exec) {
        for (size_t i = s->held; i < l->n && rc == 0; i++) {
            fs_call held = l->entries[i].call;
            rc = run(c, &held);
        }
    }
    if (role == VBO_END)
        s->vbo = false;
    if (!append(c, call))
        return rc;
    if (role == VBO_BEGIN)
        s->vbo = true;
    s->held = l->n;
    if (exec && rc == 0)
        rc = run(c, call);
    return rc;
}

static void execute_list(fs_context *c, GLuint name)
{
    fs_dlist_state *s = state(c);
    dl_list *l = s ? find_list(s, name) : NULL;
    if (!l)
        return; /* GL 1.5 spec 5.4: calling an undefined list has no effect */
    if (s->depth >= FS_MAX_LIST_NESTING)
        return; /* the spec bounds nesting; deeper calls are ignored */
    s->depth++;
    /* Calling a list flushes immediate mode's vertices, and a list's
     * vertices are apart from them (vertex_stage.h, fs_prim_state.vtx_attribs). */
    fs_vs_format_reset(c);
    /* Mesa splits quads from display lists along another diagonal than
     * immediate mode; the vertex stage needs to know (vertex_stage.h). */
    c->prim.list_depth++;
    for (size_t i = 0; i < l->n; i++) {
        dl_entry *e = &l->entries[i];
        if (e->arrays) {
            fs_array_state saved = c->arrays;
            c->arrays = *e->arrays;
            fs_dispatch(c, &e->call);
            c->arrays = saved;
        } else if (e->has_unpack) {
            fs_pixel_store saved = fs_pixel_store_unpack(c);
            fs_pixel_store_set_unpack(c, &e->unpack);
            fs_dispatch(c, &e->call);
            fs_pixel_store_set_unpack(c, &saved);
        } else {
            fs_dispatch(c, &e->call);
        }
    }
    c->prim.list_depth--;
    s->depth--;
    fs_vs_format_reset(c);
}

GLuint fs_exec_GenLists(fs_context *c, GLsizei range)
{
    /* Each reserved name is a list object (as in Mesa): at most
     * FS_MAX_NAMES held at once (fs_gen_names_ok). */
    fs_dlist_state *s = state(c);
    if (!fs_gen_names_ok(c, range, s ? s->names.held : 0))
        return 0;
    if (range == 0)
        return 0;
    if (!s) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return 0;
    }
    /* First fit: the lowest run of `range` unused names, as Mesa hands them out. */
    for (uint64_t first = 1; first + (uint64_t)range - 1 <= 0xffffffffu;) {
        GLsizei k = 0;
        while (k < range && !find_list(s, (GLuint)(first + (uint64_t)k)))
            k++;
        if (k == range) {
            for (GLsizei j = 0; j < range; j++) {
                dl_list *l = calloc(1, sizeof *l);
                if (l)
                    l->name = (GLuint)(first + (uint64_t)j);
                if (!l || insert_list(s, l) != 0) {
                    free(l);
                    fs_error(c, GL_OUT_OF_MEMORY);
                    return 0;
                }
            }
            return (GLuint)first;
        }
        first += (uint64_t)k + 1;
    }
    fs_error(c, GL_OUT_OF_MEMORY);
    return 0;
}

void fs_exec_NewList(fs_context *c, GLuint list, GLenum mode)
{
    fs_dlist_state *s = state(c);
    if (list == 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (!s || s->building) {
        fs_error(c, s ? GL_INVALID_OPERATION : GL_OUT_OF_MEMORY);
        return;
    }
    s->building = calloc(1, sizeof(dl_list));
    if (!s->building) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    s->building->name = list;
    s->mode = mode;
    s->oom = false;
    s->vbo = false;
}

void fs_exec_EndList(fs_context *c)
{
    fs_dlist_state *s = state(c);
    if (!s || !s->building) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    dl_list *l = s->building;
    s->building = NULL;
    s->mode = 0;
    if (s->oom) {
        list_free(l);
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    /* The new definition replaces the old one only now (GL 1.5 spec 5.4). */
    delete_list(s, l->name);
    if (insert_list(s, l) != 0) {
        list_free(l);
        fs_error(c, GL_OUT_OF_MEMORY);
    }
}

void fs_exec_CallList(fs_context *c, GLuint list)
{
    execute_list(c, list);
}

void fs_exec_CallLists(fs_context *c, GLsizei n, GLenum type, const GLvoid *lists)
{
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (fs_calllists_bytes(1, type) <= 0) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    GLuint base = c->list_base;
    const GLubyte *b = lists;
    for (GLsizei i = 0; i < n; i++) {
        GLuint v;
        switch (type) {
        case GL_BYTE: v = (GLuint)(GLint)((const GLbyte *)lists)[i]; break;
        case GL_UNSIGNED_BYTE: v = b[i]; break;
        case GL_SHORT: { GLshort x; memcpy(&x, b + 2 * i, 2); v = (GLuint)(GLint)x; break; }
        case GL_UNSIGNED_SHORT: { GLushort x; memcpy(&x, b + 2 * i, 2); v = x; break; }
        case GL_INT: { GLint x; memcpy(&x, b + 4 * i, 4); v = (GLuint)x; break; }
        case GL_UNSIGNED_INT: { memcpy(&v, b + 4 * i, 4); break; }
        case GL_FLOAT: { GLfloat x; memcpy(&x, b + 4 * i, 4); v = (GLuint)(GLint)x; break; }
        /* GL 1.5 spec 5.4: the n-byte types are big-endian byte sequences. */
        case GL_2_BYTES: v = (GLuint)b[2 * i] << 8 | b[2 * i + 1]; break;
        case GL_3_BYTES: v = (GLuint)b[3 * i] << 16 | (GLuint)b[3 * i + 1] << 8 | b[3 * i + 2]; break;
        default: v = (GLuint)b[4 * i] << 24 | (GLuint)b[4 * i + 1] << 16 | (GLuint)b[4 * i + 2] << 8 | b[4 * i + 3]; break;
        }
        execute_list(c, base + v);
    }
}

void fs_exec_DeleteLists(fs_context *c, GLuint list, GLsizei range)
{
    if (range < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    fs_dlist_state *s = state(c);
    if (!s)
        return;
    /* Names run from list to list + range - 1, and none is above 2^32 - 1. */
    uint64_t end = (uint64_t)list + (uint64_t)range;
    if (end > 0x100000000ull)
        end = 0x100000000ull;
    if ((uint64_t)range > s->names.cap) {
        /* A range wider than the table (glDeleteLists(1, 2147483647) from a
         * bad trace probed 2^31 names for minutes; found by fuzz_gl): visit
         * the lists held instead of the names asked for. */
        size_t pos = 0;
        GLuint name;
        for (dl_list *l; (l = fs_name_map_next(&s->names, &pos, &name));) {
            if (name >= list && name < end) {
                fs_name_map_take(&s->names, pos);
                list_free(l);
            }
        }
        return;
    }
    for (uint64_t n = list; n < end; n++)
        delete_list(s, (GLuint)n);
}

void fs_exec_ListBase(fs_context *c, GLuint base)
{
    c->list_base = base;
    fs_state_mark(c, GL_LIST_BIT);
}

void fs_dlist_building(const fs_context *c, GLenum *mode, GLuint *index)
{
    const fs_dlist_state *s = c->lists;
    bool on = s && s->building;
    *mode = on ? s->mode : 0;
    *index = on ? s->building->name : 0;
}

GLboolean fs_exec_IsList(fs_context *c, GLuint list)
{
    fs_dlist_state *s = state(c);
    return s && find_list(s, list) ? GL_TRUE : GL_FALSE;
}
