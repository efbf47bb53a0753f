/*
 * Buffer objects (GL 1.5 spec 2.9).  Where the spec leaves a choice,
 * fragsim answers as OSMesa (Mesa 22, llvmpipe) does, measured by
 * tests/test_buffer_objects.c: a name from glGenBuffers becomes an object
 * (glIsBuffer true) only when first bound; mapping an empty buffer is
 * GL_INVALID_OPERATION; glBufferData on a mapped buffer unmaps it; an
 * unmapped buffer's GL_BUFFER_ACCESS is GL_READ_WRITE again; a draw may
 * source a mapped buffer without an error.
 */
#include <stdlib.h>
#include <string.h>
#include "buffer_object.h"
#include "name_map.h"

typedef struct fs_buffer_obj {
    GLuint name;
    bool object;             /* bound at least once: a buffer object (glIsBuffer) */
    unsigned char *data;
    int64_t size;            /* GL_BUFFER_SIZE */
    GLenum usage, access;    /* GL_BUFFER_USAGE, GL_BUFFER_ACCESS (table 2.6) */
    bool mapped;             /* GL_BUFFER_MAPPED */
    /* The mapped range (the whole store for glMapBuffer) and, for
     * glMapBufferRange, its access bits (ARB_map_buffer_range). */
    int64_t map_offset, map_length;
    GLbitfield map_flags;
} fs_buffer_obj;

struct fs_buffer_objects {
    fs_name_map names;
    GLuint next_name; /* names are handed out upwards from here */
};

static fs_buffer_obj *lookup(const fs_context *c, GLuint name)
{
    if (!c->buffers || name == 0)
        return NULL;
    return fs_name_map_get(&c->buffers->names, name);
}

/* A new entry for an unused name; NULL when out of memory. */
static fs_buffer_obj *insert(fs_context *c, GLuint name)
{
    if (!c->buffers && !(c->buffers = calloc(1, sizeof *c->buffers)))
        return NULL;
    struct fs_buffer_objects *b = c->buffers;
    fs_buffer_obj *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    o->name = name;
    o->usage = GL_STATIC_DRAW; /* table 2.6 */
    o->access = GL_READ_WRITE;
    if (fs_name_map_put(&b->names, name, o) != 0) {
        free(o);
        return NULL;
    }
    if (name >= b->next_name)
        b->next_name = name == UINT32_MAX ? UINT32_MAX : name + 1;
    return o;
}

static void obj_free(fs_buffer_obj *o)
{
    free(o->data);
    free(o);
}

static void remove_name(fs_context *c, fs_buffer_obj *o)
{
    fs_name_map_remove(&c->buffers->names, o->name);
    obj_free(o);
}

void fs_buffer_objects_free(fs_context *c)
{
    struct fs_buffer_objects *b = c->buffers;
    if (!b)
        return;
    size_t pos = 0;
    for (fs_buffer_obj *o; (o = fs_name_map_next(&b->names, &pos, NULL));)
        obj_free(o);
    fs_name_map_clear(&b->names);
    free(b);
    c->buffers = NULL;
}

/* ---- names (2.9) ---- */
void fs_exec_GenBuffers(fs_context *c, GLsizei n, GLuint *buffers)
{
    if (!fs_gen_names_ok(c, n, c->buffers ? c->buffers->names.held : 0))
        return;
    for (GLsizei i = 0; i < n; i++) {
        GLuint name = c->buffers && c->buffers->next_name ? c->buffers->next_name : 1;
        while (name != 0 && lookup(c, name))
            name++;
        fs_buffer_obj *o = name ? insert(c, name) : NULL;
        if (!o) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        buffers[i] = name;
    }
}

/* The bindings a deleted buffer leaves (2.9: "the binding reverts to 0"):
 * the targets and every array that sources it.  An array keeps its offset
 * as pointer but may read nothing (bytes 0), as no client memory is there. */
static void unbind_everywhere(fs_context *c, GLuint name)
{
    fs_array_state *A = &c->arrays;
    if (A->array_buffer == name)
        A->array_buffer = 0;
    if (A->element_buffer == name)
        A->element_buffer = 0;
    for (int k = 0; k < FS_CLIENT_ARRAYS; k++) {
        fs_client_array *a = fs_client_array_at(A, k);
        if (a->buffer == name) {
            a->buffer = 0;
            a->bytes = 0;
        }
    }
}

void fs_exec_DeleteBuffers(fs_context *c, GLsizei n, const GLuint *buffers)
{
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    for (GLsizei i = 0; i < n; i++) {
        fs_buffer_obj *o = lookup(c, buffers[i]);
        if (!o)
            continue; /* 0 and unused names are silently ignored */
        unbind_everywhere(c, o->name);
        remove_name(c, o);
    }
}

GLboolean fs_exec_IsBuffer(fs_context *c, GLuint buffer)
{
    const fs_buffer_obj *o = lookup(c, buffer);
    return o && o->object ? GL_TRUE : GL_FALSE;
}

static GLuint *binding_of(fs_context *c, GLenum target)
{
    switch (target) {
    case GL_ARRAY_BUFFER: return &c->arrays.array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER: return &c->arrays.element_buffer;
    default: return NULL;
    }
}

void fs_exec_BindBuffer(fs_context *c, GLenum target, GLuint buffer)
{
    GLuint *binding = binding_of(c, target);
    if (!binding) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (buffer != 0) {
        /* Binding an unused name creates the object (2.9). */
        fs_buffer_obj *o = lookup(c, buffer);
        if (!o && !(o = insert(c, buffer))) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        o->object = true;
    }
    *binding = buffer;
}

/* The buffer bound to target, or NULL with the error: GL_INVALID_ENUM for
 * a target that is none, GL_INVALID_OPERATION when 0 is bound. */
static fs_buffer_obj *bound_buffer(fs_context *c, GLenum target)
{
    GLuint *binding = binding_of(c, target);
    if (!binding) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    fs_buffer_obj *o = lookup(c, *binding);
    if (!o)
        fs_error(c, GL_INVALID_OPERATION);
    return o;
}

/* ---- data (2.9) ---- */
static bool usage_valid(GLenum usage)
{
    switch (usage) {
    case GL_STREAM_DRAW: case GL_STREAM_READ: case GL_STREAM_COPY:
    case GL_STATIC_DRAW: case GL_STATIC_READ: case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW: case GL_DYNAMIC_READ: case GL_DYNAMIC_COPY:
        return true;
    default:
        return false;
    }
}

void fs_exec_BufferData(fs_context *c, GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return;
    if (size < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (!usage_valid(usage)) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    unsigned char *store = NULL;
    if (size > FS_BUFFER_MAX_BYTES || (size > 0 && !(store = malloc((size_t)size)))) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    /* Without data the contents are undefined; zero, so that replays are
     * deterministic. */
    if (size > 0) {
        if (data)
            memcpy(store, data, (size_t)size);
        else
            memset(store, 0, (size_t)size);
    }
    free(o->data);
    o->data = store;
    o->size = size;
    o->usage = usage;
    o->mapped = false; /* a new store: the old mapping is gone (as Mesa) */
    o->access = GL_READ_WRITE;
}

/* The range [offset, offset + size) of o, or false with GL_INVALID_VALUE
 * (negative, or beyond the store) or GL_INVALID_OPERATION (mapped). */
static bool range_ok(fs_context *c, const fs_buffer_obj *o, GLintptr offset, GLsizeiptr size)
{
    if (offset < 0 || size < 0 || offset > o->size || size > o->size - offset) {
        fs_error(c, GL_INVALID_VALUE);
        return false;
    }
    if (o->mapped) {
        fs_error(c, GL_INVALID_OPERATION);
        return false;
    }
    return true;
}

void fs_exec_BufferSubData(fs_context *c, GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid *data)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (o && range_ok(c, o, offset, size) && size > 0 && data)
        memcpy(o->data + offset, data, (size_t)size);
}

void fs_exec_GetBufferSubData(fs_context *c, GLenum target, GLintptr offset, GLsizeiptr size, GLvoid *data)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (o && range_ok(c, o, offset, size) && size > 0 && data)
        memcpy(data, o->data + offset, (size_t)size);
}

/* ---- mapping (2.9) ---- */
GLvoid *fs_exec_MapBuffer(fs_context *c, GLenum target, GLenum access)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return NULL;
    if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    if (o->mapped || o->size == 0) {
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    o->mapped = true;
    o->access = access;
    o->map_offset = 0;
    o->map_length = o->size;
    o->map_flags = 0;
    return o->data;
}

/* ARB_map_buffer_range (GL 3.0 spec 2.9.3): a range of the store mapped
 * with access bits, with the extension's errors (their order measured on
 * OSMesa, tests/test_buffer_objects.c map_buffer_range_vs_osmesa).  The
 * model has no GPU to synchronise with and keeps the store's contents on
 * an invalidation (they become undefined in GL: any contents are right). */
GLvoid *fs_exec_MapBufferRange(fs_context *c, GLenum target, GLintptr offset, GLsizeiptr length,
                               GLbitfield access)
{
    const GLbitfield all = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT |
                           GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
    if (!binding_of(c, target)) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    if (offset < 0 || length < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return NULL;
    }
    if (length == 0) { /* INVALID_OPERATION on llvmpipe, before the bits (measured) */
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    if (access & ~all) {
        fs_error(c, GL_INVALID_VALUE);
        return NULL;
    }
    if (!(access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT)) ||
        ((access & GL_MAP_READ_BIT) &&
         (access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT))) ||
        ((access & GL_MAP_FLUSH_EXPLICIT_BIT) && !(access & GL_MAP_WRITE_BIT))) {
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return NULL;
    if (o->mapped) {
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    if (offset > o->size || length > o->size - offset) {
        fs_error(c, GL_INVALID_VALUE);
        return NULL;
    }
    o->mapped = true;
    o->access = (access & GL_MAP_READ_BIT) && (access & GL_MAP_WRITE_BIT) ? GL_READ_WRITE
              : (access & GL_MAP_WRITE_BIT) ? GL_WRITE_ONLY : GL_READ_ONLY;
    o->map_offset = offset;
    o->map_length = length;
    o->map_flags = access;
    return o->data + offset;
}

/* Writes to a FLUSH_EXPLICIT mapping become visible at the flush; the
 * model's store is the mapping, so only the errors remain. */
void fs_exec_FlushMappedBufferRange(fs_context *c, GLenum target, GLintptr offset, GLsizeiptr length)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return;
    if (offset < 0 || length < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (!o->mapped || !(o->map_flags & GL_MAP_FLUSH_EXPLICIT_BIT)) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (offset > o->map_length || length > o->map_length - offset)
        fs_error(c, GL_INVALID_VALUE);
}

GLboolean fs_exec_UnmapBuffer(fs_context *c, GLenum target)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return GL_FALSE;
    if (!o->mapped) {
        fs_error(c, GL_INVALID_OPERATION);
        return GL_FALSE;
    }
    o->mapped = false;
    o->access = GL_READ_WRITE; /* as OSMesa answers after an unmap */
    return GL_TRUE; /* the store is never lost here */
}

void fs_exec_GetBufferParameteriv(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return;
    switch (pname) {
    case GL_BUFFER_SIZE: *params = (GLint)o->size; break;
    case GL_BUFFER_USAGE: *params = (GLint)o->usage; break;
    case GL_BUFFER_ACCESS: *params = (GLint)o->access; break;
    case GL_BUFFER_MAPPED: *params = o->mapped; break;
    default: fs_error(c, GL_INVALID_ENUM); break;
    }
}

void fs_exec_GetBufferPointerv(fs_context *c, GLenum target, GLenum pname, GLvoid **params)
{
    fs_buffer_obj *o = bound_buffer(c, target);
    if (!o)
        return;
    if (pname != GL_BUFFER_MAP_POINTER) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    *params = o->mapped ? o->data + o->map_offset : NULL; /* the range's start */
}

/* A write through a mapping as a trace records it (apitrace's memcpy
 * pseudo-call, which the replayer turns into buffer, offset and bytes):
 * outside the mapped store it is counted, by name, and not done. */
void fs_exec_TraceMemcpy(fs_context *c, GLuint buffer, GLintptr offset, GLsizeiptr size, const GLvoid *data)
{
    /* The offset counts from the start of the mapping. */
    fs_buffer_obj *o = lookup(c, buffer);
    if (!o || !o->mapped || offset < 0 || size < 0 || offset > o->map_length || size > o->map_length - offset ||
        !data) {
        fs_unsupported(c, "memcpy (outside every mapped buffer)");
        return;
    }
    if (size > 0)
        memcpy(o->data + o->map_offset + offset, data, (size_t)size);
}

/* ---- sourcing arrays and indices (2.9.1, 2.9.2) ---- */
/* The array as plain memory: its store from the offset on, no buffer. */
static void resolve_array(const fs_context *c, fs_client_array *a)
{
    const fs_buffer_obj *o = lookup(c, a->buffer);
    uint64_t offset = (uint64_t)(uintptr_t)a->pointer;
    a->buffer = 0;
    if (!o || !o->data || offset > (uint64_t)o->size) {
        a->pointer = NULL;
        a->bytes = 0;
        return;
    }
    a->pointer = o->data + offset;
    a->bytes = (size_t)((uint64_t)o->size - offset);
}

void fs_buffer_resolve_arrays(const fs_context *c, fs_array_state *out)
{
    *out = c->arrays;
    out->element_buffer = 0; /* the indices were resolved before */
    for (int k = 0; k < FS_CLIENT_ARRAYS; k++)
        if (fs_client_array_at(out, k)->buffer)
            resolve_array(c, fs_client_array_at(out, k));
}

const void *fs_buffer_element_data(const fs_context *c, uint64_t offset, size_t *bytes)
{
    const fs_buffer_obj *o = lookup(c, c->arrays.element_buffer);
    *bytes = 0;
    if (!o || !o->data || offset > (uint64_t)o->size)
        return NULL;
    *bytes = (size_t)((uint64_t)o->size - offset);
    return o->data + offset;
}

const void *fs_buffer_mapping(const fs_context *c, GLenum target, int64_t *size)
{
    GLuint name = target == GL_ARRAY_BUFFER ? c->arrays.array_buffer
                  : target == GL_ELEMENT_ARRAY_BUFFER ? c->arrays.element_buffer : 0;
    const fs_buffer_obj *o = lookup(c, name);
    *size = o && o->mapped ? o->map_length : 0;
    return o && o->mapped ? o->data + o->map_offset : NULL;
}
