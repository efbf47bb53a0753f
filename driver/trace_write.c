/*
 * Writing apitrace traces (format version 6, apitrace docs/FORMAT.markdown).
 *
 * The stream is buffered in 1 MiB pieces, each written as one chunk
 * [uint32 LE compressed length][raw Snappy block], like apitrace's own
 * writer, so apitrace's reader never sees a chunk over its 1 MiB cache.
 * Signatures (function, enum, bitmask, struct) get ids in order of first
 * use; their description is written only with the first occurrence of the
 * id ("first occurrence" / "follow-on occurrences" in the grammar).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <errno.h>
#include <snappy-c.h>
#include "trace.h"


#define CHUNK_SIZE (1u << 20)
#define MAX_DEPTH 64
#define TRACE_VERSION 6

/* Event, call detail and value tags (FORMAT.markdown "Calls", "Values"). */
enum { EV_ENTER = 0, EV_LEAVE = 1 };
enum { CD_END = 0, CD_ARG = 1, CD_RET = 2, CD_FLAGS = 5 };
enum { FLAG_FAKE = 1 };

/* A set of byte strings -> ids, for deduplicating signatures by content. */
typedef struct sig_entry { char *key; size_t len; uint64_t hash; uint32_t id; } sig_entry;
typedef struct sig_set { sig_entry *slots; size_t cap, count; uint32_t next_id; } sig_set;

struct fs_trace_writer {
    FILE *f;
    char *path;
    unsigned char *buf;  /* uncompressed stream, CHUNK_SIZE bytes */
    size_t used;
    char *cbuf;          /* compressed chunk */
    size_t cbuf_size;
    int failed;
    char err[256];
    uint64_t call_no;
    sig_set funcs, enums, bitmasks, structs;
    /* scratch for building signature keys */
    char *key;
    size_t key_len, key_cap;
};

static int fail(fs_trace_writer *w, const char *fmt, ...)
{
    if (!w->failed) {
        va_list ap;
        va_start(ap, fmt);
        int n = snprintf(w->err, sizeof w->err, "%s: ", w->path);
        if (n < 0 || (size_t)n >= sizeof w->err)
            n = 0;
        vsnprintf(w->err + n, sizeof w->err - (size_t)n, fmt, ap);
        va_end(ap);
    }
    w->failed = 1;
    return -1;
}

static int flush_chunk(fs_trace_writer *w)
{
    if (w->used == 0 || w->failed)
        return w->failed ? -1 : 0;
    size_t clen = w->cbuf_size;
    if (snappy_compress((const char *)w->buf, w->used, w->cbuf, &clen) != SNAPPY_OK)
        return fail(w, "snappy compression failed");
    unsigned char len[4] = {(unsigned char)clen, (unsigned char)(clen >> 8),
                            (unsigned char)(clen >> 16), (unsigned char)(clen >> 24)};
    if (fwrite(len, 1, 4, w->f) != 4 || fwrite(w->cbuf, 1, clen, w->f) != clen)
        return fail(w, "write error");
    w->used = 0;
    return 0;
}

static void put(fs_trace_writer *w, const void *data, size_t n)
{
    const unsigned char *p = data;
    while (n > 0 && !w->failed) {
        size_t room = CHUNK_SIZE - w->used;
        size_t k = n < room ? n : room;
        memcpy(w->buf + w->used, p, k);
        w->used += k;
        p += k;
        n -= k;
        if (w->used == CHUNK_SIZE)
            flush_chunk(w);
    }
}

static void put_byte(fs_trace_writer *w, unsigned b)
{
    unsigned char c = (unsigned char)b;
    put(w, &c, 1);
}

/* "uint": 7 bits per byte, least significant first, high bit = more. */
static void put_uint(fs_trace_writer *w, uint64_t v)
{
    unsigned char b[10];
    size_t n = 0;
    do {
        b[n++] = (unsigned char)((v & 0x7f) | 0x80);
        v >>= 7;
    } while (v);
    b[n - 1] &= 0x7f;
    put(w, b, n);
}

static void put_string(fs_trace_writer *w, const char *s, size_t len)
{
    put_uint(w, len);
    put(w, s, len);
}

static void put_cstr(fs_trace_writer *w, const char *s)
{
    put_string(w, s ? s : "", s ? strlen(s) : 0);
}

/* A signed integer as a value: tag 0x03 with the magnitude when negative,
 * else 0x04 (as apitrace's writeSInt). */
static void put_sint_value(fs_trace_writer *w, int64_t v)
{
    if (v < 0) {
        put_byte(w, FS_TV_SINT);
        put_uint(w, (uint64_t)0 - (uint64_t)v);
    } else {
        put_byte(w, FS_TV_UINT);
        put_uint(w, (uint64_t)v);
    }
}

/* ---- signature sets ---- */
static uint64_t hash_bytes(const char *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)p[i]) * 1099511628211ull;
    return h;
}

/* Returns the id of key, adding it when new (*is_new = 1); -1 when out of memory. */
static int64_t sig_lookup(sig_set *s, const char *key, size_t len, int *is_new)
{
    if (s->count * 2 >= s->cap) {
        size_t ncap = s->cap ? s->cap * 2 : 64;
        sig_entry *ns = calloc(ncap, sizeof *ns);
        if (!ns)
            return -1;
        for (size_t i = 0; i < s->cap; i++)
            if (s->slots[i].key) {
                size_t j = s->slots[i].hash & (ncap - 1);
                while (ns[j].key)
                    j = (j + 1) & (ncap - 1);
                ns[j] = s->slots[i];
            }
        free(s->slots);
        s->slots = ns;
        s->cap = ncap;
    }
    uint64_t h = hash_bytes(key, len);
    size_t j = h & (s->cap - 1);
    while (s->slots[j].key) {
        sig_entry *e = &s->slots[j];
        if (e->hash == h && e->len == len && memcmp(e->key, key, len) == 0) {
            *is_new = 0;
            return e->id;
        }
        j = (j + 1) & (s->cap - 1);
    }
    char *copy = malloc(len ? len : 1);
    if (!copy)
        return -1;
    memcpy(copy, key, len);
    s->slots[j] = (sig_entry){copy, len, h, s->next_id};
    s->count++;
    *is_new = 1;
    return s->next_id++;
}

static void sig_free(sig_set *s)
{
    for (size_t i = 0; i < s->cap; i++)
        free(s->slots[i].key);
    free(s->slots);
}

static int key_add(fs_trace_writer *w, const void *p, size_t n)
{
    if (w->key_len + n > w->key_cap) {
        size_t ncap = w->key_cap ? w->key_cap : 256;
        while (ncap < w->key_len + n)
            ncap *= 2;
        char *nk = realloc(w->key, ncap);
        if (!nk)
            return fail(w, "out of memory");
        w->key = nk;
        w->key_cap = ncap;
    }
    memcpy(w->key + w->key_len, p, n);
    w->key_len += n;
    return 0;
}

/* Keys are the strings with their terminating NULs and the values' bytes,
 * which separates different contents unambiguously. */
static int key_str(fs_trace_writer *w, const char *s)
{
    return key_add(w, s ? s : "", (s ? strlen(s) : 0) + 1);
}

/* Writes the id of a signature, and its description the first time. */
static int64_t sig_id(fs_trace_writer *w, sig_set *set, int *is_new)
{
    int64_t id = sig_lookup(set, w->key, w->key_len, is_new);
    if (id < 0)
        return fail(w, "out of memory");
    return id;
}

/* ---- values ---- */
static const char *type_name(int t)
{
    static const char *const names[] = {"NULL", "FALSE", "TRUE", "SINT", "UINT", "FLOAT",
                                        "DOUBLE", "STRING", "BLOB", "ENUM", "BITMASK",
                                        "ARRAY", "STRUCT", "OPAQUE", "REPR", "WSTRING"};
    return t >= 0 && t < 16 ? names[t] : "?";
}

static int put_value(fs_trace_writer *w, const fs_tval *v, int depth);

/* enum_sig = id count (name value)+ on first occurrence. */
static int put_enum(fs_trace_writer *w, const fs_tval *v)
{
    const fs_tsig *s = v->sig;
    w->key_len = 0;
    if (s) {
        for (unsigned k = 0; k < s->n; k++)
            if (key_str(w, s->names[k]) || key_add(w, &s->values[k], 8))
                return -1;
    } else if (v->enum_name) {
        if (key_str(w, v->enum_name) || key_add(w, &v->i, 8))
            return -1;
    }
    int is_new;
    int64_t id = sig_id(w, &w->enums, &is_new);
    if (id < 0)
        return -1;
    put_byte(w, FS_TV_ENUM);
    put_uint(w, (uint64_t)id);
    if (is_new) {
        if (s) {
            put_uint(w, s->n);
            for (unsigned k = 0; k < s->n; k++) {
                put_cstr(w, s->names[k]);
                put_sint_value(w, s->values[k]);
            }
        } else if (v->enum_name) {
            put_uint(w, 1);
            put_cstr(w, v->enum_name);
            put_sint_value(w, v->i);
        } else {
            put_uint(w, 0);
        }
    }
    put_sint_value(w, v->i);
    return 0;
}

/* bitmask_sig = id count (name uint)+ on first occurrence. */
static int put_bitmask(fs_trace_writer *w, const fs_tval *v)
{
    const fs_tsig *s = v->sig;
    w->key_len = 0;
    if (s)
        for (unsigned k = 0; k < s->n; k++)
            if (key_str(w, s->names[k]) || key_add(w, &s->values[k], 8))
                return -1;
    int is_new;
    int64_t id = sig_id(w, &w->bitmasks, &is_new);
    if (id < 0)
        return -1;
    put_byte(w, FS_TV_BITMASK);
    put_uint(w, (uint64_t)id);
    if (is_new) {
        put_uint(w, s ? s->n : 0);
        for (unsigned k = 0; s && k < s->n; k++) {
            put_cstr(w, s->names[k]);
            put_uint(w, (uint64_t)s->values[k]);
        }
    }
    put_uint(w, v->u);
    return 0;
}

/* An array of values, or a wide string (its characters as UINTs). */
static int put_array(fs_trace_writer *w, const fs_tval *v, int depth)
{
    if (!v->arr.elems && v->arr.n)
        return fail(w, "%s value with no elements", type_name(v->type));
    put_byte(w, v->type);
    put_uint(w, v->arr.n);
    for (size_t k = 0; k < v->arr.n; k++) {
        const fs_tval *e = &v->arr.elems[k];
        if (v->type == FS_TV_WSTRING) {
            if (e->type != FS_TV_UINT)
                return fail(w, "WSTRING character %zu is not a UINT", k);
            put_uint(w, e->u);
        } else if (put_value(w, e, depth + 1)) {
            return -1;
        }
    }
    return 0;
}

/* struct_sig = id struct_name count member_name* on first occurrence. */
static int put_struct(fs_trace_writer *w, const fs_tval *v, int depth)
{
    const fs_tsig *s = v->sig;
    if (!s || s->n != v->arr.n || (s->n && (!s->names || !v->arr.elems)))
        return fail(w, "STRUCT value whose signature does not match its members");
    w->key_len = 0;
    if (key_str(w, s->name))
        return -1;
    for (unsigned k = 0; k < s->n; k++)
        if (key_str(w, s->names[k]))
            return -1;
    int is_new;
    int64_t id = sig_id(w, &w->structs, &is_new);
    if (id < 0)
        return -1;
    put_byte(w, FS_TV_STRUCT);
    put_uint(w, (uint64_t)id);
    if (is_new) {
        put_cstr(w, s->name);
        put_uint(w, s->n);
        for (unsigned k = 0; k < s->n; k++)
            put_cstr(w, s->names[k]);
    }
    for (unsigned k = 0; k < s->n; k++)
        if (put_value(w, &v->arr.elems[k], depth + 1))
            return -1;
    return 0;
}

static int put_value(fs_trace_writer *w, const fs_tval *v, int depth)
{
    if (depth > MAX_DEPTH)
        return fail(w, "values nested deeper than %d", MAX_DEPTH);
    int rc = 0;
    switch (v->type) {
    case FS_TV_NULL:
    case FS_TV_FALSE:
    case FS_TV_TRUE:
        put_byte(w, v->type);
        break;
    case FS_TV_SINT:
        put_sint_value(w, v->i);
        break;
    case FS_TV_UINT:
    case FS_TV_OPAQUE:
        put_byte(w, v->type);
        put_uint(w, v->u);
        break;
    case FS_TV_FLOAT: {
        /* 32-bit IEEE float in host byte order, which on the little-endian
         * machines apitrace runs on is the file's byte order. */
        float f = (float)v->d;
        put_byte(w, FS_TV_FLOAT);
        put(w, &f, 4);
        break;
    }
    case FS_TV_DOUBLE:
        put_byte(w, FS_TV_DOUBLE);
        put(w, &v->d, 8);
        break;
    case FS_TV_STRING:
    case FS_TV_BLOB:
        if (!v->str.ptr && v->str.len)
            return fail(w, "%s value with no data", type_name(v->type));
        put_byte(w, v->type);
        put_string(w, v->str.ptr, v->str.len);
        break;
    case FS_TV_ENUM:
        rc = put_enum(w, v);
        break;
    case FS_TV_BITMASK:
        rc = put_bitmask(w, v);
        break;
    case FS_TV_ARRAY:
    case FS_TV_WSTRING:
        rc = put_array(w, v, depth);
        break;
    case FS_TV_STRUCT:
        rc = put_struct(w, v, depth);
        break;
    case FS_TV_REPR:
        if (v->arr.n != 2 || !v->arr.elems)
            return fail(w, "REPR value needs exactly 2 elements");
        put_byte(w, FS_TV_REPR);
        if (put_value(w, &v->arr.elems[0], depth + 1) || put_value(w, &v->arr.elems[1], depth + 1))
            return -1;
        break;
    default:
        return fail(w, "unknown value type %d", (int)v->type);
    }
    return rc || w->failed ? -1 : 0;
}

/* ---- public ---- */
fs_trace_writer *fs_trace_create(const char *path, char *err, size_t errlen)
{
    fs_trace_writer *w = calloc(1, sizeof *w);
    if (w) {
        w->path = strdup(path);
        w->buf = malloc(CHUNK_SIZE);
        w->cbuf_size = snappy_max_compressed_length(CHUNK_SIZE);
        w->cbuf = malloc(w->cbuf_size);
    }
    if (!w || !w->path || !w->buf || !w->cbuf) {
        if (err && errlen)
            snprintf(err, errlen, "%s: out of memory", path);
        if (w) {
            free(w->path);
            free(w->buf);
            free(w->cbuf);
            free(w);
        }
        return NULL;
    }
    w->f = fopen(path, "wb");
    if (!w->f) {
        if (err && errlen)
            snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
        free(w->path);
        free(w->buf);
        free(w->cbuf);
        free(w);
        return NULL;
    }
    /* Snappy container header, then the trace header: version_no,
     * semantic_version_no and an empty property list (just the empty-string
     * terminator). */
    if (fwrite("at", 1, 2, w->f) != 2)
        fail(w, "write error");
    put_uint(w, TRACE_VERSION);
    put_uint(w, TRACE_VERSION);
    put_uint(w, 0);
    return w;
}

int fs_trace_write(fs_trace_writer *w, const fs_tcall *call)
{
    if (w->failed)
        return -1;
    if (!call->name)
        return fail(w, "call without a name");
    if (call->nargs && !call->args)
        return fail(w, "%s: no argument values", call->name);
    if (call->nargs > 64 && call->out_args)
        return fail(w, "%s: out_args covers only 64 arguments", call->name);

    /* call_sig = id function_name count arg_name* on first occurrence. */
    char tmp[24];
    w->key_len = 0;
    if (key_str(w, call->name) || key_add(w, &call->nargs, sizeof call->nargs))
        return -1;
    for (unsigned k = 0; k < call->nargs; k++) {
        const char *an = call->arg_names ? call->arg_names[k] : NULL;
        if (!an) {
            snprintf(tmp, sizeof tmp, "arg%u", k);
            an = tmp;
        }
        if (key_str(w, an))
            return -1;
    }
    int is_new;
    int64_t id = sig_id(w, &w->funcs, &is_new);
    if (id < 0)
        return -1;

    put_byte(w, EV_ENTER);
    put_uint(w, call->thread);
    put_uint(w, (uint64_t)id);
    if (is_new) {
        put_cstr(w, call->name);
        put_uint(w, call->nargs);
        for (unsigned k = 0; k < call->nargs; k++) {
            const char *an = call->arg_names ? call->arg_names[k] : NULL;
            if (!an) {
                snprintf(tmp, sizeof tmp, "arg%u", k);
                an = tmp;
            }
            put_cstr(w, an);
        }
    }
    /* apitrace writes the flags detail right after the signature. */
    if (call->flags & FS_TCALL_FAKE) {
        put_byte(w, CD_FLAGS);
        put_uint(w, FLAG_FAKE);
    }
    for (unsigned k = 0; k < call->nargs; k++) {
        if (k < 64 && (call->out_args >> k & 1))
            continue;
        put_byte(w, CD_ARG);
        put_uint(w, k);
        if (put_value(w, &call->args[k], 0))
            return -1;
    }
    put_byte(w, CD_END);

    put_byte(w, EV_LEAVE);
    put_uint(w, w->call_no);
    for (unsigned k = 0; k < call->nargs && k < 64; k++) {
        if (!(call->out_args >> k & 1))
            continue;
        put_byte(w, CD_ARG);
        put_uint(w, k);
        if (put_value(w, &call->args[k], 0))
            return -1;
    }
    if (call->has_ret) {
        put_byte(w, CD_RET);
        if (put_value(w, &call->ret, 0))
            return -1;
    }
    put_byte(w, CD_END);
    w->call_no++;
    return w->failed ? -1 : 0;
}

const char *fs_trace_writer_error(const fs_trace_writer *w)
{
    return w->failed ? w->err : NULL;
}

int fs_trace_finish(fs_trace_writer *w)
{
    if (!w)
        return -1;
    flush_chunk(w);
    if (fflush(w->f) != 0)
        fail(w, "write error");
    if (fclose(w->f) != 0)
        fail(w, "write error on close");
    int rc = w->failed ? -1 : 0;
    sig_free(&w->funcs);
    sig_free(&w->enums);
    sig_free(&w->bitmasks);
    sig_free(&w->structs);
    free(w->key);
    free(w->buf);
    free(w->cbuf);
    free(w->path);
    free(w);
    return rc;
}
