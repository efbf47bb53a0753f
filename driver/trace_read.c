/*
 * Reading apitrace traces (apitrace docs/FORMAT.markdown, versions 0-6).
 *
 * Input is untrusted: every length, count and id is checked against fixed
 * limits and against how much data can still follow, values nest at most
 * MAX_DEPTH deep, and buffers for long items grow as their bytes actually
 * arrive, so a malformed file ends in one error message, never in a crash,
 * a hang or a huge allocation.  The bound on remaining data uses Snappy's
 * largest expansion: a 3-byte copy tag yields at most 64 bytes, so a
 * compressed byte stands for fewer than EXPANSION decompressed bytes.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <errno.h>
#include <sys/stat.h>
#include <snappy-c.h>
#include <zlib.h>
#include "trace.h"


#define CHUNK_MAX (1u << 20)          /* a chunk decompresses to at most 1 MiB */
#define EXPANSION 22u
/* Deflate's largest expansion: a match of 258 bytes costs at least 2 bits
 * (a 1-bit length code and a 1-bit distance code), so 1032 bytes per
 * compressed byte, plus one match inflate may hold back. */
#define GZ_EXPANSION 1032u
#define GZ_HELD 258u
#define GZ_IN (64u << 10)             /* compressed bytes read at a time */
#define MAX_ITEM (1ull << 30)         /* longest string, blob or array: 1 GiB */
#define MAX_SIG_STRING (1u << 20)     /* names in signatures and properties */
#define MAX_SIG_ID (1u << 20)         /* ids of function/enum/bitmask/struct signatures */
#define MAX_FRAME_ID (1u << 26)       /* ids of backtrace frames (a bitmap) */
#define MAX_SIG_ARGS 4096u            /* arguments of a function, members of a struct */
#define MAX_SIG_VALUES (1u << 20)     /* values of an enum or bitmask signature */
#define MAX_CALL_BYTES (3ull << 30)   /* memory for one call's values */
#define MAX_DEPTH 64
#define MAX_ABANDONED 256
#define TRACE_VERSION 6

enum { EV_ENTER = 0, EV_LEAVE = 1 };
enum { CD_END = 0, CD_ARG, CD_RET, CD_THREAD, CD_BACKTRACE, CD_FLAGS };
enum { FLAG_FAKE = 1 };

/* ---- arenas: a call's values live in one, freed or reused as a whole ---- */
typedef struct block {
    struct block *next;
    size_t size, used;
    _Alignas(16) unsigned char data[];
} block;

typedef struct arena {
    block *head;
    uint64_t total;
} arena;

#define ALIGN16(n) (((n) + 15) & ~(size_t)15)

static void arena_release(arena *a)
{
    for (block *b = a->head, *n; b; b = n) {
        n = b->next;
        free(b);
    }
    a->head = NULL;
    a->total = 0;
}

/* Keeps one ordinary block, so a reused arena does not malloc per call. */
static __attribute__((noinline)) void arena_reset_blocks(arena *a)
{
    block *keep = NULL;
    for (block *b = a->head, *n; b; b = n) {
        n = b->next;
        if (!keep && b->size == 65536) {
            keep = b;
            keep->used = 0;
            keep->next = NULL;
        } else {
            free(b);
        }
    }
    a->head = keep;
    a->total = keep ? keep->size : 0;
}

/* Inline for the usual arena of a small call: one ordinary block. */
static inline void arena_reset(arena *a)
{
    block *b = a->head;
    if (b && !b->next && b->size == 65536) {
        b->used = 0;
        a->total = b->size;
    } else {
        arena_reset_blocks(a);
    }
}

static __attribute__((noinline)) void *arena_alloc_block(arena *a, size_t n)
{
    size_t size = n > 16384 ? n : 65536;
    block *b = malloc(sizeof *b + size);
    if (!b)
        return NULL;
    b->size = size;
    b->used = n;
    a->total += size;
    if (a->head && n > 16384) {
        /* A big item gets its own block behind the current one, which may
         * still have room for small items. */
        b->next = a->head->next;
        a->head->next = b;
    } else {
        b->next = a->head;
        a->head = b;
    }
    return b->data;
}

static inline void *arena_alloc(arena *a, size_t n)
{
    n = ALIGN16(n ? n : 1);
    if (__builtin_expect(a->head && a->head->size - a->head->used >= n, 1)) {
        void *p = a->head->data + a->head->used;
        a->head->used += n;
        return p;
    }
    return arena_alloc_block(a, n);
}

static void *arena_zalloc(arena *a, size_t n)
{
    void *p = arena_alloc(a, n);
    if (p)
        memset(p, 0, n);
    return p;
}

/* A growable buffer that becomes an arena block when complete. */
typedef struct growbuf { block *b; } growbuf;

/* The block size grow_reserve picks for `need` bytes, from `size`. */
static size_t grow_size(size_t size, size_t need)
{
    if (size < 256)
        size = 256;
    while (size < need)
        size *= 2;
    return size;
}

static int grow_reserve(growbuf *g, size_t need)
{
    if (g->b && g->b->size >= need)
        return 0;
    size_t size = grow_size(g->b ? g->b->size : 0, need);
    block *nb = realloc(g->b, sizeof *nb + size);
    if (!nb)
        return -1;
    if (!g->b)
        nb->used = 0;
    nb->size = size;
    g->b = nb;
    return 0;
}

static void *grow_adopt(growbuf *g, arena *a)
{
    block *b = g->b;
    g->b = NULL;
    a->total += b->size;
    if (a->head) {
        b->next = a->head->next;
        a->head->next = b;
    } else {
        b->next = NULL;
        a->head = b;
    }
    return b->data;
}

/* ---- signatures ---- */
typedef struct fsig {
    const char *name;
    unsigned nargs;
    const char **arg_names;
} fsig;

typedef struct pending {
    arena a;
    arena elems;  /* the fast path's arrays (see fast_value_any), outside a's count */
    fs_tcall call;
    fs_tval *args;
    const fsig *sig;
    int complete;
    struct pending *next_free;
} pending;

struct fs_trace_reader {
    FILE *f;
    char *path;
    uint64_t file_size;
    uint64_t file_pos;       /* file offset of the next chunk */
    uint64_t chunk_off;      /* file offset of the current chunk's length */
    /* The zlib container (old apitrace; lib/trace/trace_file_zlib.cpp reads
     * it with gzread): the whole file is one gzip stream, or gzip members
     * one after another, of the same event stream the Snappy chunks carry. */
    z_stream *gz;            /* NULL for the Snappy container */
    int gz_file_eof;         /* every byte of the file was handed to inflate */
    int gz_member_end;       /* inflate reached a member's end mark */
    int gz_cut;              /* the file ended inside a member (lenient mode) */
    char *cbuf;
    size_t cbuf_cap;
    unsigned char *buf;      /* current decompressed chunk */
    size_t len, pos;
    uint64_t stream_base;    /* stream offset of buf[0] */
    int eof;                 /* no more events */
    int failed;
    int cut_in_event;      /* the data ended cleanly at a chunk boundary inside an event */
    int strict_end;        /* treat that as an error too (fs_trace_set_strict_end) */
    int general_only;      /* FS_TRACE_PARSER_GENERAL: no fast paths (fs_trace_set_parser) */
    char warning[400];     /* set when the trace ended inside an event */
    char err[512];
    unsigned version, semantic;

    arena sigs;
    fsig **funcs;
    size_t nfuncs;
    fs_tsig **enums, **bitmasks, **structs;
    size_t nenums, nbitmasks, nstructs;
    unsigned char *frames;   /* bitmap of defined backtrace frame ids */
    size_t frames_bytes;

    pending **q;             /* ring of calls waiting to be returned, in call order */
    size_t qhead, qcount, qcap; /* qcap: 0 or a power of two, so indices wrap with a mask */
    pending *returned;
    pending *free_list;
    uint64_t next_call_no;
    uint64_t abandoned[MAX_ABANDONED];
    size_t nabandoned;
    const char *hint;        /* context added to the next error message */
};

static uint64_t stream_off(const fs_trace_reader *r)
{
    return r->stream_base + r->pos;
}

static int rfail_at(fs_trace_reader *r, uint64_t off, const char *fmt, ...)
{
    if (!r->failed) {
        char msg[320];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        if (r->gz)
            snprintf(r->err, sizeof r->err,
                     "%s: %s%s%s at stream offset %llu (gzip container, before file offset %llu)",
                     r->path, msg, r->hint ? " " : "", r->hint ? r->hint : "",
                     (unsigned long long)off, (unsigned long long)r->file_pos);
        else
            snprintf(r->err, sizeof r->err,
                     "%s: %s%s%s at stream offset %llu (in the chunk at file offset %llu)",
                     r->path, msg, r->hint ? " " : "", r->hint ? r->hint : "",
                     (unsigned long long)off, (unsigned long long)r->chunk_off);
    }
    r->failed = 1;
    return -1;
}

#define rfail(r, ...) rfail_at((r), stream_off(r), __VA_ARGS__)

/*
 * The zlib container's load_chunk: inflates up to 1 MiB of the stream into
 * buf.  A member's end mark followed by more bytes starts the next member (as
 * gzread reads concatenated members); anything after the end mark that is no
 * gzip member is an error, as is corrupt data.  A stream cut before its end
 * mark (apitrace's old writer flushed without finishing the stream when the
 * program was killed) is an error in strict mode; otherwise what was
 * decompressed is read and the warning says where it stopped.
 */
static __attribute__((noinline)) int load_gz(fs_trace_reader *r)
{
    z_stream *z = r->gz;
    r->stream_base += r->len;
    r->len = r->pos = 0;
    z->next_out = r->buf;
    z->avail_out = CHUNK_MAX;
    while (z->avail_out) {
        if (z->avail_in == 0 && !r->gz_file_eof) {
            size_t got = fread(r->cbuf, 1, GZ_IN, r->f);
            if (got == 0 && ferror(r->f))
                return rfail(r, "read error: %s", strerror(errno));
            r->file_pos += got;
            r->gz_file_eof = got < GZ_IN;
            z->next_in = (unsigned char *)r->cbuf;
            z->avail_in = (unsigned)got;
        }
        if (r->gz_member_end) {
            if (z->avail_in == 0)
                break;           /* the clean end of the file */
            if (inflateReset(z) != Z_OK)
                return rfail(r, "zlib: cannot start the next gzip member");
            r->gz_member_end = 0;
        }
        if (z->avail_in == 0) {  /* the file ends inside a member */
            if (r->strict_end)
                return rfail(r, "truncated gzip stream (the file ends before the stream's end mark)");
            snprintf(r->warning, sizeof r->warning,
                     "%s: the gzip stream ends without its end mark (truncated file?); read up to stream offset %llu",
                     r->path, (unsigned long long)(r->stream_base + (CHUNK_MAX - z->avail_out)));
            r->gz_member_end = r->gz_cut = 1;
            break;
        }
        int zr = inflate(z, Z_NO_FLUSH);
        if (zr == Z_STREAM_END)
            r->gz_member_end = 1;
        else if (zr == Z_MEM_ERROR)
            return rfail(r, "out of memory");
        else if (zr != Z_OK && zr != Z_BUF_ERROR)
            return rfail(r, "bad gzip data (zlib: %s)", z->msg ? z->msg : "inflate failed");
    }
    r->len = CHUNK_MAX - z->avail_out;
    return r->len > 0;
}

/* Loads the next chunk.  Returns 1, 0 at the end of the file, -1 on error. */
static int load_chunk(fs_trace_reader *r)
{
    if (r->gz)
        return load_gz(r);
    for (;;) {
        r->stream_base += r->len;
        r->len = r->pos = 0;
        r->chunk_off = r->file_pos;
        unsigned char h[4];
        size_t got = fread(h, 1, 4, r->f);
        if (got == 0 && !ferror(r->f))
            return 0;
        if (got < 4) {
            if (ferror(r->f))
                return rfail(r, "read error: %s", strerror(errno));
            return rfail(r, "truncated chunk header (%zu of 4 length bytes)", got);
        }
        uint64_t clen = (uint64_t)h[0] | (uint64_t)h[1] << 8 | (uint64_t)h[2] << 16 |
                        (uint64_t)h[3] << 24;
        uint64_t left = r->file_size - r->file_pos - 4;
        if (clen == 0)
            return rfail(r, "empty chunk (compressed length 0)");
        if (clen > snappy_max_compressed_length(CHUNK_MAX))
            return rfail(r, "chunk compressed length %llu exceeds the %zu bytes a 1 MiB chunk can take",
                         (unsigned long long)clen, snappy_max_compressed_length(CHUNK_MAX));
        if (clen > left)
            return rfail(r, "truncated chunk: length %llu but only %llu bytes left in the file",
                         (unsigned long long)clen, (unsigned long long)left);
        if (clen > r->cbuf_cap) {
            char *nb = realloc(r->cbuf, clen);
            if (!nb)
                return rfail(r, "out of memory");
            r->cbuf = nb;
            r->cbuf_cap = clen;
        }
        if (fread(r->cbuf, 1, clen, r->f) != clen)
            return rfail(r, "truncated chunk: file shorter than its length %llu",
                         (unsigned long long)clen);
        r->file_pos += 4 + clen;
        size_t ulen;
        if (snappy_uncompressed_length(r->cbuf, clen, &ulen) != SNAPPY_OK)
            return rfail(r, "bad Snappy data (unreadable uncompressed length)");
        if (ulen > CHUNK_MAX)
            return rfail(r, "bad Snappy data: chunk claims %zu decompressed bytes, over the 1 MiB limit", ulen);
        size_t out = CHUNK_MAX;
        if (snappy_uncompress(r->cbuf, clen, (char *)r->buf, &out) != SNAPPY_OK || out != ulen)
            return rfail(r, "bad Snappy data (decompression failed)");
        r->len = out;
        if (out)
            return 1;
    }
}

/* 1 when a byte is available, 0 at the end of the data, -1 on error. */
static int have_data(fs_trace_reader *r)
{
    if (r->pos < r->len)
        return 1;
    if (r->failed)
        return -1;
    return load_chunk(r);
}

/* The byte reader's slow half: the chunk is used up. */
static __attribute__((noinline)) int rd_byte_next_chunk(fs_trace_reader *r, unsigned *b)
{
    int rc = have_data(r);
    if (rc <= 0) {
        *b = 0;
        if (rc == 0) {
            r->cut_in_event = 1;
            rfail(r, "unexpected end of the trace inside an event (truncated file?)");
        }
        return -1;
    }
    *b = r->buf[r->pos++];
    return 0;
}

static inline int rd_byte(fs_trace_reader *r, unsigned *b)
{
    if (__builtin_expect(r->pos >= r->len, 0))
        return rd_byte_next_chunk(r, b);
    *b = r->buf[r->pos++];
    return 0;
}

static __attribute__((noinline)) int rd_bytes_across(fs_trace_reader *r, unsigned char *d, size_t n)
{
    while (n) {
        if (r->pos >= r->len) {
            int rc = have_data(r);
            if (rc <= 0) {
                r->cut_in_event = rc == 0;
                return rc < 0 ? -1 : rfail(r, "unexpected end of the trace inside an event (truncated file?)");
            }
        }
        size_t k = r->len - r->pos < n ? r->len - r->pos : n;
        if (d) {
            memcpy(d, r->buf + r->pos, k);
            d += k;
        }
        r->pos += k;
        n -= k;
    }
    return 0;
}

/* Inline so that the fixed-size reads (floats, doubles) become plain loads. */
static inline int rd_bytes(fs_trace_reader *r, void *dst, size_t n)
{
    if (__builtin_expect(r->len - r->pos < n, 0))
        return rd_bytes_across(r, dst, n);
    if (dst)
        memcpy(dst, r->buf + r->pos, n);
    r->pos += n;
    return 0;
}

/*
 * A whole, well-formed varint in [*pp, end): 1 with *pp moved past it, else
 * 0 with *pp unchanged.  The fast paths use it and leave anything else
 * (a varint cut by the chunk's end, an over-long one) to the byte-by-byte
 * reader, which owns the error messages.
 */
static inline int cur_uint(const unsigned char **pp, const unsigned char *end, uint64_t *v)
{
    const unsigned char *p = *pp;
    if (__builtin_expect(p < end && *p < 0x80, 1)) {
        *v = *p;
        *pp = p + 1;
        return 1;
    }
    uint64_t x = 0;
    for (unsigned i = 0; i < 10 && p < end; i++, p++) {
        unsigned b = *p;
        if (i == 9 && (b & 0x7e))
            return 0;
        x |= (uint64_t)(b & 0x7f) << (7 * i);
        if (!(b & 0x80)) {
            *v = x;
            *pp = p + 1;
            return 1;
        }
    }
    return 0;
}

/* "uint": 7 bits per byte, least significant first; at most 10 bytes. */
static __attribute__((noinline)) int rd_uint_slow(fs_trace_reader *r, uint64_t *v)
{
    uint64_t off = stream_off(r), x = 0;
    for (unsigned i = 0; i < 10; i++) {
        unsigned b;
        if (rd_byte(r, &b))
            return -1;
        if (i == 9 && (b & 0x7e))
            return rfail_at(r, off, "bad varint (over 64 bits)");
        x |= (uint64_t)(b & 0x7f) << (7 * i);
        if (!(b & 0x80)) {
            *v = x;
            return 0;
        }
    }
    return rfail_at(r, off, "bad varint (more than 10 bytes)");
}

static inline int rd_uint(fs_trace_reader *r, uint64_t *v)
{
    const unsigned char *p = r->buf + r->pos;
    if (__builtin_expect(cur_uint(&p, r->buf + r->len, v), 1)) {
        r->pos = (size_t)(p - r->buf);
        return 0;
    }
    return rd_uint_slow(r, v);
}

/* Upper bound of the decompressed bytes still to come. */
static uint64_t remaining_bound(const fs_trace_reader *r)
{
    if (r->gz)
        return (uint64_t)(r->len - r->pos) + GZ_HELD +
               ((uint64_t)r->gz->avail_in + (r->file_size - r->file_pos)) * GZ_EXPANSION;
    return (uint64_t)(r->len - r->pos) + (r->file_size - r->file_pos) * EXPANSION;
}

/* Checks a count of items each taking at least min_bytes of stream. */
static int check_count(fs_trace_reader *r, uint64_t off, uint64_t n, uint64_t limit,
                       unsigned min_bytes, const char *what)
{
    if (n > limit)
        return rfail_at(r, off, "absurd %s %llu (limit %llu)", what, (unsigned long long)n,
                        (unsigned long long)limit);
    if (n > remaining_bound(r) / min_bytes) {
        /* A gzip stream cut before its end mark, all of it inflated: the
         * bound is the data left exactly, so the trace ends inside this
         * event, as a killed capture's does. */
        if (r->gz_cut || (r->gz && r->gz_file_eof && r->gz->avail_in == 0 && !r->gz_member_end))
            r->cut_in_event = 1;
        return rfail_at(r, off, "%s %llu is beyond the remaining data", what, (unsigned long long)n);
    }
    return 0;
}

/* Reads a length-prefixed byte string into a, NUL-terminated. */
static int rd_string(fs_trace_reader *r, arena *a, uint64_t limit, const char **s, size_t *lenp)
{
    uint64_t off = stream_off(r), n;
    if (rd_uint(r, &n) || check_count(r, off, n, limit, 1, "string length"))
        return -1;
    if (a->total + n > MAX_CALL_BYTES)
        return rfail_at(r, off, "call too large (over %llu bytes of values)",
                        (unsigned long long)MAX_CALL_BYTES);
    char *p;
    if (n <= 16384) {
        p = arena_alloc(a, (size_t)n + 1);
        if (!p)
            return rfail_at(r, off, "out of memory");
        if (rd_bytes(r, p, (size_t)n))
            return -1;
    } else {
        /* Grow as bytes arrive: a lying length fails at the end of the data,
         * having allocated about twice what the file really holds. */
        growbuf g = {NULL};
        size_t got = 0;
        while (got < n) {
            size_t want = (size_t)n - got;
            if (want > CHUNK_MAX)
                want = CHUNK_MAX;
            if (grow_reserve(&g, got + want + 1)) {
                free(g.b);
                return rfail_at(r, off, "out of memory");
            }
            if (rd_bytes(r, g.b->data + got, want)) {
                free(g.b);
                return -1;
            }
            got += want;
        }
        g.b->used = g.b->size;
        p = grow_adopt(&g, a);
    }
    p[n] = '\0';
    *s = p;
    if (lenp)
        *lenp = (size_t)n;
    return 0;
}

static int skip_string(fs_trace_reader *r)
{
    uint64_t off = stream_off(r), n;
    if (rd_uint(r, &n) || check_count(r, off, n, MAX_ITEM, 1, "string length"))
        return -1;
    return rd_bytes(r, NULL, (size_t)n);
}

/* The value of a SINT, which apitrace writes as the magnitude of a
 * negative number: false when it is beyond INT64_MIN. */
static inline bool sint_value(uint64_t magnitude, int64_t *v)
{
    if (magnitude > (uint64_t)INT64_MAX + 1)
        return false;
    *v = magnitude == (uint64_t)INT64_MAX + 1 ? INT64_MIN : -(int64_t)magnitude;
    return true;
}

/* A signed integer written as a value: tag 0x03 (negative) or 0x04. */
static int rd_sint(fs_trace_reader *r, int64_t *v)
{
    uint64_t off = stream_off(r), u;
    unsigned tag;
    if (rd_byte(r, &tag))
        return -1;
    if (tag != FS_TV_SINT && tag != FS_TV_UINT)
        return rfail_at(r, off, "expected an integer value tag (0x03 or 0x04), found 0x%02x", tag);
    if (rd_uint(r, &u))
        return -1;
    if (tag == FS_TV_SINT) {
        if (!sint_value(u, v))
            return rfail_at(r, off, "negative integer out of range");
    } else {
        *v = (int64_t)u;
    }
    return 0;
}

/* Makes room for id in a table of signatures indexed by id. */
static int sig_slot(fs_trace_reader *r, uint64_t off, void ***table, size_t *n, uint64_t id,
                    const char *what)
{
    if (id >= MAX_SIG_ID)
        return rfail_at(r, off, "absurd %s signature id %llu (limit %u)", what,
                        (unsigned long long)id, MAX_SIG_ID);
    if (id >= *n) {
        size_t nn = *n ? *n : 64;
        while (nn <= id)
            nn *= 2;
        if (nn > MAX_SIG_ID)
            nn = MAX_SIG_ID;
        void **nt = realloc(*table, nn * sizeof *nt);
        if (!nt)
            return rfail_at(r, off, "out of memory");
        memset(nt + *n, 0, (nn - *n) * sizeof *nt);
        *table = nt;
        *n = nn;
    }
    return 0;
}

/* call_sig = id function_name count arg_name* | id */
static const fsig *parse_function_sig(fs_trace_reader *r, int *follow_on, uint64_t *idp)
{
    uint64_t off = stream_off(r), id;
    if (rd_uint(r, &id) || sig_slot(r, off, (void ***)&r->funcs, &r->nfuncs, id, "function"))
        return NULL;
    *idp = id;
    if (r->funcs[id]) {
        *follow_on = 1;
        return r->funcs[id];
    }
    *follow_on = 0;
    fsig *s = arena_zalloc(&r->sigs, sizeof *s);
    uint64_t n, noff;
    if (!s) {
        rfail_at(r, off, "out of memory");
        return NULL;
    }
    if (rd_string(r, &r->sigs, MAX_SIG_STRING, &s->name, NULL))
        return NULL;
    noff = stream_off(r);
    if (rd_uint(r, &n) || check_count(r, noff, n, MAX_SIG_ARGS, 1, "argument count"))
        return NULL;
    s->nargs = (unsigned)n;
    s->arg_names = arena_zalloc(&r->sigs, (size_t)n * sizeof *s->arg_names);
    if (!s->arg_names) {
        rfail_at(r, off, "out of memory");
        return NULL;
    }
    for (unsigned i = 0; i < s->nargs; i++)
        if (rd_string(r, &r->sigs, MAX_SIG_STRING, &s->arg_names[i], NULL))
            return NULL;
    r->funcs[id] = s;
    return s;
}

/* enum_sig = id count (name value)+ | id      (version >= 3)
 * bitmask_sig = id count (name uint)+ | id
 * old enum_sig = id name value | id           (version < 3, per apitrace's parser) */
static const fs_tsig *parse_flag_sig(fs_trace_reader *r, int bitmask, int *follow_on)
{
    uint64_t off = stream_off(r), id, n;
    fs_tsig ***table = bitmask ? &r->bitmasks : &r->enums;
    size_t *count = bitmask ? &r->nbitmasks : &r->nenums;
    const char *what = bitmask ? "bitmask" : "enum";
    if (rd_uint(r, &id) || sig_slot(r, off, (void ***)table, count, id, what))
        return NULL;
    if ((*table)[id]) {
        *follow_on = 1;
        return (*table)[id];
    }
    *follow_on = 0;
    int old_enum = !bitmask && r->version < 3;
    uint64_t noff = stream_off(r);
    if (old_enum)
        n = 1;
    else if (rd_uint(r, &n) || check_count(r, noff, n, MAX_SIG_VALUES, 2, "signature value count"))
        return NULL;
    fs_tsig *s = arena_zalloc(&r->sigs, sizeof *s);
    const char **names = arena_zalloc(&r->sigs, (size_t)n * sizeof *names);
    int64_t *values = arena_zalloc(&r->sigs, (size_t)n * sizeof *values);
    if (!s || !names || !values) {
        rfail_at(r, off, "out of memory");
        return NULL;
    }
    for (uint64_t i = 0; i < n; i++) {
        if (rd_string(r, &r->sigs, MAX_SIG_STRING, &names[i], NULL))
            return NULL;
        if (bitmask) {
            uint64_t u;
            if (rd_uint(r, &u))
                return NULL;
            values[i] = (int64_t)u;
        } else if (rd_sint(r, &values[i])) {
            return NULL;
        }
    }
    s->n = (unsigned)n;
    s->names = names;
    s->values = values;
    (*table)[id] = s;
    return s;
}

/* struct_sig = id struct_name count member_name* | id */
static const fs_tsig *parse_struct_sig(fs_trace_reader *r)
{
    uint64_t off = stream_off(r), id, n;
    if (rd_uint(r, &id) || sig_slot(r, off, (void ***)&r->structs, &r->nstructs, id, "struct"))
        return NULL;
    if (r->structs[id])
        return r->structs[id];
    fs_tsig *s = arena_zalloc(&r->sigs, sizeof *s);
    if (!s) {
        rfail_at(r, off, "out of memory");
        return NULL;
    }
    if (rd_string(r, &r->sigs, MAX_SIG_STRING, &s->name, NULL))
        return NULL;
    uint64_t noff = stream_off(r);
    if (rd_uint(r, &n) || check_count(r, noff, n, MAX_SIG_ARGS, 1, "struct member count"))
        return NULL;
    const char **names = arena_zalloc(&r->sigs, (size_t)n * sizeof *names);
    if (!names) {
        rfail_at(r, off, "out of memory");
        return NULL;
    }
    for (uint64_t i = 0; i < n; i++)
        if (rd_string(r, &r->sigs, MAX_SIG_STRING, &names[i], NULL))
            return NULL;
    s->n = (unsigned)n;
    s->names = names;
    r->structs[id] = s;
    return s;
}

static int parse_value(fs_trace_reader *r, arena *a, fs_tval *v, int depth);

/* Reads n values (or, for WSTRING, n raw uints) into a new element array. */
static int parse_elems(fs_trace_reader *r, arena *a, uint64_t off, uint64_t n, int wide,
                       const fs_tval **elems, int depth)
{
    if (a->total + n * sizeof(fs_tval) > MAX_CALL_BYTES)
        return rfail_at(r, off, "call too large (over %llu bytes of values)",
                        (unsigned long long)MAX_CALL_BYTES);
    /* Grown as elements parse, so memory follows the data actually present. */
    growbuf g = {NULL};
    size_t cap = 0;
    for (uint64_t i = 0; i < n; i++) {
        if (i == cap) {
            cap = cap ? cap * 2 : 64;
            if (cap > n)
                cap = (size_t)n;
            if (grow_reserve(&g, cap * sizeof(fs_tval))) {
                free(g.b);
                return rfail_at(r, off, "out of memory");
            }
        }
        fs_tval *e = (fs_tval *)g.b->data + i;
        memset(e, 0, sizeof *e);
        int rc;
        if (wide) {
            e->type = FS_TV_UINT;
            rc = rd_uint(r, &e->u);
        } else {
            rc = parse_value(r, a, e, depth + 1);
        }
        if (rc) {
            free(g.b);
            return -1;
        }
    }
    if (!g.b) {
        *elems = NULL;
        return 0;
    }
    g.b->used = g.b->size;
    *elems = grow_adopt(&g, a);
    return 0;
}

static int parse_value(fs_trace_reader *r, arena *a, fs_tval *v, int depth)
{
    uint64_t off = stream_off(r), n;
    unsigned tag;
    int follow_on;
    memset(v, 0, sizeof *v);
    if (depth > MAX_DEPTH)
        return rfail_at(r, off, "values nested deeper than %d", MAX_DEPTH);
    if (rd_byte(r, &tag))
        return -1;
    v->type = (fs_tv_type)tag;
    switch (tag) {
    case FS_TV_NULL:
    case FS_TV_FALSE:
    case FS_TV_TRUE:
        return 0;
    case FS_TV_SINT:
        if (rd_uint(r, &n))
            return -1;
        if (!sint_value(n, &v->i))
            return rfail_at(r, off, "negative integer out of range");
        return 0;
    case FS_TV_UINT:
    case FS_TV_OPAQUE:
        return rd_uint(r, &v->u);
    case FS_TV_FLOAT: {
        /* Stored in the writer's byte order; apitrace only runs on
         * little-endian machines, like this one. */
        float f;
        if (rd_bytes(r, &f, 4))
            return -1;
        v->d = f;
        return 0;
    }
    case FS_TV_DOUBLE:
        return rd_bytes(r, &v->d, 8);
    case FS_TV_STRING:
    case FS_TV_BLOB:
        return rd_string(r, a, MAX_ITEM, &v->str.ptr, &v->str.len);
    case FS_TV_ENUM: {
        const fs_tsig *s = parse_flag_sig(r, 0, &follow_on);
        if (!s)
            return -1;
        if (r->version < 3) {
            v->i = s->values[0];
        } else {
            if (follow_on)
                r->hint = "(after a known enum signature id: was the signature described twice?)";
            int rc = rd_sint(r, &v->i);
            r->hint = NULL;
            if (rc)
                return -1;
        }
        v->sig = s;
        for (unsigned k = 0; k < s->n; k++)
            if (s->values[k] == v->i) {
                v->enum_name = s->names[k];
                break;
            }
        return 0;
    }
    case FS_TV_BITMASK:
        if (!(v->sig = parse_flag_sig(r, 1, &follow_on)))
            return -1;
        return rd_uint(r, &v->u);
    case FS_TV_ARRAY:
    case FS_TV_WSTRING: {
        uint64_t noff = stream_off(r);
        if (rd_uint(r, &n) || check_count(r, noff, n, MAX_ITEM, 1,
                                          tag == FS_TV_ARRAY ? "array length" : "wide string length"))
            return -1;
        v->arr.n = (size_t)n;
        return parse_elems(r, a, off, n, tag == FS_TV_WSTRING, &v->arr.elems, depth);
    }
    case FS_TV_STRUCT:
        if (!(v->sig = parse_struct_sig(r)))
            return -1;
        v->arr.n = v->sig->n;
        return parse_elems(r, a, off, v->sig->n, 0, &v->arr.elems, depth);
    case FS_TV_REPR:
        v->arr.n = 2;
        return parse_elems(r, a, off, 2, 0, &v->arr.elems, depth);
    default:
        return rfail_at(r, off, "unknown value tag 0x%02x", tag);
    }
}

/* frame = id frame_detail+ | id  (frames are read and dropped) */
static int parse_backtrace(fs_trace_reader *r)
{
    uint64_t off = stream_off(r), n;
    if (rd_uint(r, &n) || check_count(r, off, n, MAX_ITEM, 1, "backtrace frame count"))
        return -1;
    for (uint64_t i = 0; i < n; i++) {
        uint64_t foff = stream_off(r), id;
        if (rd_uint(r, &id))
            return -1;
        if (id >= MAX_FRAME_ID)
            return rfail_at(r, foff, "absurd backtrace frame id %llu", (unsigned long long)id);
        if (id / 8 >= r->frames_bytes) {
            size_t nb = r->frames_bytes ? r->frames_bytes : 64;
            while (nb <= id / 8)
                nb *= 2;
            unsigned char *nf = realloc(r->frames, nb);
            if (!nf)
                return rfail_at(r, foff, "out of memory");
            memset(nf + r->frames_bytes, 0, nb - r->frames_bytes);
            r->frames = nf;
            r->frames_bytes = nb;
        }
        if (r->frames[id / 8] >> (id % 8) & 1)
            continue;
        for (;;) {
            uint64_t doff = stream_off(r), u;
            unsigned d;
            if (rd_byte(r, &d))
                return -1;
            if (d == 0)
                break;
            if (d >= 1 && d <= 3) {        /* module, function, file name */
                if (skip_string(r))
                    return -1;
            } else if (d == 4 || d == 5) { /* line number, offset */
                if (rd_uint(r, &u))
                    return -1;
            } else {
                return rfail_at(r, doff, "unknown backtrace frame detail 0x%02x", d);
            }
        }
        r->frames[id / 8] |= (unsigned char)(1u << (id % 8));
    }
    return 0;
}

/* Argument u came with the leave event (an output) or the enter. */
static inline void mark_arg(pending *p, uint64_t u, int leave)
{
    if (u < 64) {
        if (leave)
            p->call.out_args |= 1ull << u;
        else
            p->call.out_args &= ~(1ull << u);
    }
}

static int parse_details(fs_trace_reader *r, pending *p, int leave, int follow_on_sig, uint64_t sig_id)
{
    char hint[160];
    for (;;) {
        uint64_t off = stream_off(r), u;
        unsigned d;
        if (rd_byte(r, &d))
            return -1;
        switch (d) {
        case CD_END:
            return 0;
        case CD_ARG: {
            if (rd_uint(r, &u))
                return -1;
            if (u >= p->call.nargs)
                return rfail_at(r, off, "argument index %llu but %s has %u arguments",
                                (unsigned long long)u, p->call.name, p->call.nargs);
            if (parse_value(r, &p->a, &p->args[u], 0))
                return -1;
            mark_arg(p, u, leave);
            break;
        }
        case CD_RET:
            if (parse_value(r, &p->a, &p->call.ret, 0))
                return -1;
            p->call.has_ret = 1;
            break;
        case CD_THREAD:
            if (rd_uint(r, &u))
                return -1;
            if (u > UINT32_MAX)
                return rfail_at(r, off, "absurd thread number %llu", (unsigned long long)u);
            p->call.thread = (uint32_t)u;
            break;
        case CD_BACKTRACE:
            if (parse_backtrace(r))
                return -1;
            break;
        case CD_FLAGS:
            if (rd_uint(r, &u))
                return -1;
            if (u & FLAG_FAKE)
                p->call.flags |= FS_TCALL_FAKE;
            break;
        default:
            if (follow_on_sig && !leave) {
                /* In the enter of a signature id seen before, garbage most
                 * likely means the id was given a second description, which
                 * this reader (like apitrace's) does not expect. */
                snprintf(hint, sizeof hint,
                         "(the call's function signature id %llu was already defined as %s: "
                         "signature id reused inconsistently?)",
                         (unsigned long long)sig_id, p->call.name);
                r->hint = hint;
            }
            rfail_at(r, off, "unknown call detail 0x%02x in %s of call %llu (%s)", d,
                     leave ? "leave" : "enter", (unsigned long long)p->call.no, p->call.name);
            r->hint = NULL;
            return -1;
        }
    }
}

/* ---- pending calls ---- */
static inline pending *pending_new(fs_trace_reader *r)
{
    pending *p = r->free_list;
    if (!p)
        return calloc(1, sizeof *p);
    r->free_list = p->next_free;
    /* Member by member, keeping the arena: gcc turns a memset of the whole
     * struct (or of the whole fs_tcall) into rep stos, whose start-up cost
     * was a tenth of decoding a small call. */
    _Static_assert(offsetof(fs_tcall, out_args) + sizeof(uint64_t) == sizeof(fs_tcall),
                   "pending_new() zeroes every member of fs_tcall");
    p->call.no = 0;
    p->call.thread = 0;
    p->call.name = NULL;
    p->call.nargs = 0;
    p->call.arg_names = NULL;
    p->call.args = NULL;
    p->call.ret = (fs_tval){0};
    p->call.has_ret = 0;
    p->call.flags = 0;
    p->call.offset = 0;
    p->call.out_args = 0;
    p->args = NULL;
    p->sig = NULL;
    p->complete = 0;
    p->next_free = NULL;
    return p;
}

static inline void pending_free(fs_trace_reader *r, pending *p)
{
    arena_reset(&p->a);
    if (p->elems.head)
        arena_reset(&p->elems);
    p->next_free = r->free_list;
    r->free_list = p;
}

static __attribute__((noinline)) int queue_grow(fs_trace_reader *r)
{
    size_t ncap = r->qcap ? r->qcap * 2 : 16;
    pending **nq = malloc(ncap * sizeof *nq);
    if (!nq)
        return -1;
    for (size_t i = 0; i < r->qcount; i++)
        nq[i] = r->q[(r->qhead + i) & (r->qcap - 1)];
    free(r->q);
    r->q = nq;
    r->qcap = ncap;
    r->qhead = 0;
    return 0;
}

static inline int queue_push(fs_trace_reader *r, pending *p)
{
    if (r->qcount == r->qcap && queue_grow(r))
        return -1;
    r->q[(r->qhead + r->qcount) & (r->qcap - 1)] = p;
    r->qcount++;
    return 0;
}

/* The queued call numbered no, newest first (a leave event usually
 * closes the call entered last), or NULL. */
static pending *queue_find(const fs_trace_reader *r, uint64_t no)
{
    for (size_t i = r->qcount; i-- > 0;) {
        pending *q = r->q[(r->qhead + i) & (r->qcap - 1)];
        if (q->call.no == no)
            return q;
    }
    return NULL;
}

static pending *queue_pop(fs_trace_reader *r)
{
    pending *p = r->q[r->qhead];
    r->qhead = (r->qhead + 1) & (r->qcap - 1);
    r->qcount--;
    return p;
}

static int parse_enter(fs_trace_reader *r, uint64_t off)
{
    uint64_t thread = 0, sig_id = 0;
    if (r->version >= 4 && rd_uint(r, &thread))
        return -1;
    if (thread > UINT32_MAX)
        return rfail_at(r, off, "absurd thread number %llu", (unsigned long long)thread);
    int follow_on = 0;
    const fsig *s = parse_function_sig(r, &follow_on, &sig_id);
    if (!s)
        return -1;
    pending *p = pending_new(r);
    if (!p)
        return rfail_at(r, off, "out of memory");
    p->sig = s;
    p->call.no = r->next_call_no++;
    p->call.thread = (uint32_t)thread;
    p->call.name = s->name;
    p->call.nargs = s->nargs;
    p->call.arg_names = s->arg_names;
    p->call.offset = off;
    p->args = arena_zalloc(&p->a, s->nargs * sizeof *p->args);
    p->call.args = p->args;
    if (!p->args || queue_push(r, p)) {
        pending_free(r, p);
        return rfail_at(r, off, "out of memory");
    }
    /* Queued before its details so that close() frees it on error. */
    return parse_details(r, p, 0, follow_on, sig_id);
}

static int parse_leave(fs_trace_reader *r, uint64_t off)
{
    uint64_t no;
    if (rd_uint(r, &no))
        return -1;
    pending *p = queue_find(r, no);
    if (p && p->complete)
        return rfail_at(r, off, "second leave event for call %llu (%s)", (unsigned long long)no,
                        p->call.name);
    if (!p) {
        size_t k;
        for (k = 0; k < r->nabandoned; k++)
            if (r->abandoned[k] == no)
                break;
        if (k == r->nabandoned)
            return rfail_at(r, off, "leave event for call %llu, which %s", (unsigned long long)no,
                            no >= r->next_call_no ? "was never entered"
                                                  : "is not waiting for a leave (left already?)");
        /* A late leave of a call returned early: read and drop it. */
        r->abandoned[k] = r->abandoned[--r->nabandoned];
        pending *tmp = pending_new(r);
        if (!tmp)
            return rfail_at(r, off, "out of memory");
        tmp->call.no = no;
        tmp->call.name = "(call returned early)";
        tmp->call.nargs = MAX_SIG_ARGS;
        tmp->args = arena_zalloc(&tmp->a, MAX_SIG_ARGS * sizeof *tmp->args);
        int rc = tmp->args ? parse_details(r, tmp, 1, 0, 0) : rfail_at(r, off, "out of memory");
        pending_free(r, tmp);
        return rc;
    }
    if (parse_details(r, p, 1, 0, 0))
        return -1;
    p->complete = 1;
    return 0;
}

/*
 * Fast paths for the events that make up nearly all of a trace: a call of
 * a known function signature whose values are scalars, enums and bitmasks
 * of known signatures, short strings/blobs and short arrays of scalars,
 * with every byte inside the current chunk.  They read from a local cursor
 * without the per-byte end-of-chunk test and the error bookkeeping of the
 * general parser.  On anything else (a chunk boundary, a new signature,
 * any malformed or unusual input) they give up, and the general parser
 * reads the event again from its first byte: it alone reports errors, so
 * messages, offsets and limits are those of the general parser.
 *
 * Giving up leaves no trace: an enter's call is discarded before it is
 * queued, and what a leave wrote into its call before giving up the general
 * parser writes again, identically, from the same bytes (a leave's fast
 * path allocates nothing, so it leaves no memory behind either).
 *
 * The call's arena sees the very allocations of the general parser, so
 * its memory count (a->total, held to MAX_CALL_BYTES) and blocks stay what
 * they would be there; see fast_value_any for arrays.
 */
enum { FAST_MAX_ELEMS = 32 };
enum { FAST_ALLOC = 1, FAST_ARRAY = 2 }; /* what fast_value may read: strings, arrays */

static __attribute__((noinline)) int fast_value_any(fs_trace_reader *r, pending *p, arena *a,
                                                    fs_tval *v, const unsigned char **pp,
                                                    const unsigned char *end, unsigned allow);

/* Floats are most of the values of immediate-mode traces: read inline. */
static inline int fast_value(fs_trace_reader *r, pending *p, arena *a, fs_tval *v,
                             const unsigned char **pp, const unsigned char *end, unsigned allow)
{
    const unsigned char *q = *pp;
    if (__builtin_expect(end - q >= 5 && *q == FS_TV_FLOAT, 1)) {
        float f;
        memcpy(&f, q + 1, 4);
        memset(v, 0, sizeof *v);
        v->type = FS_TV_FLOAT;
        v->d = f;
        *pp = q + 5;
        return 1;
    }
    return fast_value_any(r, p, a, v, pp, end, allow);
}

/* An enum value: its signature id (defined before) and, from version 3
 * on, the value as a SINT or UINT; its name from the signature. */
static inline int fast_enum(const fs_trace_reader *r, fs_tval *v, const unsigned char **pp, const unsigned char *end)
{
    const unsigned char *q = *pp;
    const fs_tsig *s;
    uint64_t n;
    if (!cur_uint(&q, end, &n) || n >= r->nenums || !(s = r->enums[n]))
        return 0;
    if (r->version < 3) {
        v->i = s->values[0];
    } else {
        if (q >= end || (*q != FS_TV_SINT && *q != FS_TV_UINT))
            return 0;
        unsigned itag = *q++;
        if (!cur_uint(&q, end, &n))
            return 0;
        if (itag == FS_TV_UINT)
            v->i = (int64_t)n;
        else if (!sint_value(n, &v->i))
            return 0;
    }
    v->sig = s;
    for (unsigned k = 0; k < s->n; k++)
        if (s->values[k] == v->i) {
            v->enum_name = s->names[k];
            break;
        }
    *pp = q;
    return 1;
}

static int fast_value_any(fs_trace_reader *r, pending *p, arena *a, fs_tval *v,
                          const unsigned char **pp, const unsigned char *end, unsigned allow)
{
    const unsigned char *q = *pp;
    uint64_t n;
    if (q >= end)
        return 0;
    unsigned tag = *q++;
    memset(v, 0, sizeof *v);
    v->type = (fs_tv_type)tag;
    switch (tag) {
    case FS_TV_NULL:
    case FS_TV_FALSE:
    case FS_TV_TRUE:
        break;
    case FS_TV_SINT:
        if (!cur_uint(&q, end, &n) || !sint_value(n, &v->i))
            return 0;
        break;
    case FS_TV_UINT:
    case FS_TV_OPAQUE:
        if (!cur_uint(&q, end, &v->u))
            return 0;
        break;
    case FS_TV_FLOAT: {
        float f;
        if (end - q < 4)
            return 0;
        memcpy(&f, q, 4);
        q += 4;
        v->d = f;
        break;
    }
    case FS_TV_DOUBLE:
        if (end - q < 8)
            return 0;
        memcpy(&v->d, q, 8);
        q += 8;
        break;
    case FS_TV_ENUM:
        if (!fast_enum(r, v, &q, end))
            return 0;
        break;
    case FS_TV_BITMASK:
        if (!cur_uint(&q, end, &n) || n >= r->nbitmasks || !r->bitmasks[n])
            return 0;
        v->sig = r->bitmasks[n];
        if (!cur_uint(&q, end, &v->u))
            return 0;
        break;
    case FS_TV_STRING:
    case FS_TV_BLOB: {
        /* Only lengths the general reader would also take from the arena
         * (n <= 16384), and wholly in this chunk, which also passes its
         * bound on the remaining data. */
        char *str;
        if (!(allow & FAST_ALLOC) || !cur_uint(&q, end, &n) || n > 16384 ||
            n > (uint64_t)(end - q) || a->total + n > MAX_CALL_BYTES ||
            !(str = arena_alloc(a, (size_t)n + 1)))
            return 0;
        memcpy(str, q, (size_t)n);
        str[n] = '\0';
        q += n;
        v->str.ptr = str;
        v->str.len = (size_t)n;
        break;
    }
    case FS_TV_ARRAY: {
        /* Each element takes a byte at least, so a length within the chunk
         * passes the general reader's bound on the remaining data.  The
         * general parser gives an array a malloc'd block of its own and
         * counts its size; here the elements go to the call's second arena
         * (no malloc per array) and the count grows by that same size. */
        fs_tval *e;
        if (!(allow & FAST_ARRAY) || !cur_uint(&q, end, &n) || n > FAST_MAX_ELEMS ||
            n > (uint64_t)(end - q) || a->total + n * sizeof(fs_tval) > MAX_CALL_BYTES)
            return 0;
        v->arr.n = (size_t)n;
        if (n) {
            if (!(e = arena_alloc(&p->elems, (size_t)n * sizeof *e)))
                return 0;
            for (size_t i = 0; i < n; i++)
                if (!fast_value(r, p, a, &e[i], &q, end, FAST_ALLOC))
                    return 0;
            v->arr.elems = e;
            a->total += grow_size(0, (size_t)n * sizeof(fs_tval));
        }
        break;
    }
    default:
        return 0;
    }
    *pp = q;
    return 1;
}

static inline __attribute__((always_inline)) int fast_details(fs_trace_reader *r, pending *p,
                                                              int leave, const unsigned char **pp,
                                                              const unsigned char *end)
{
    const unsigned char *q = *pp;
    for (;;) {
        uint64_t u;
        if (q >= end)
            return 0;
        switch (*q++) {
        case CD_END:
            *pp = q;
            return 1;
        case CD_ARG:
            if (!cur_uint(&q, end, &u) || u >= p->call.nargs ||
                !fast_value(r, p, &p->a, &p->args[u], &q, end, leave ? 0 : FAST_ALLOC | FAST_ARRAY))
                return 0;
            mark_arg(p, u, leave);
            break;
        case CD_RET:
            if (!fast_value(r, p, &p->a, &p->call.ret, &q, end, leave ? 0 : FAST_ALLOC | FAST_ARRAY))
                return 0;
            p->call.has_ret = 1;
            break;
        case CD_THREAD:
            if (!cur_uint(&q, end, &u) || u > UINT32_MAX)
                return 0;
            p->call.thread = (uint32_t)u;
            break;
        case CD_FLAGS:
            if (!cur_uint(&q, end, &u))
                return 0;
            if (u & FLAG_FAKE)
                p->call.flags |= FS_TCALL_FAKE;
            break;
        default:
            return 0;
        }
    }
}

/* The enter event at r->pos, of a known signature.  1 when read and queued;
 * 2 when its leave followed and the call is in *call, as fs_trace_next
 * returns it; 0 when the general parser must read it (nothing changed). */
static int fast_enter(fs_trace_reader *r, fs_tcall *call)
{
    const unsigned char *q = r->buf + r->pos + 1, *end = r->buf + r->len;
    uint64_t thread = 0, id;
    if (r->version >= 4 && (!cur_uint(&q, end, &thread) || thread > UINT32_MAX))
        return 0;
    if (!cur_uint(&q, end, &id) || id >= r->nfuncs || !r->funcs[id])
        return 0;
    const fsig *s = r->funcs[id];
    pending *p = pending_new(r);
    if (!p)
        return 0;
    p->sig = s;
    p->call.no = r->next_call_no;
    p->call.thread = (uint32_t)thread;
    p->call.name = s->name;
    p->call.nargs = s->nargs;
    p->call.arg_names = s->arg_names;
    p->call.offset = stream_off(r);
    /* Zeroed value by value: small fixed-size memsets become vector stores,
     * where one of variable size is a libc call. */
    p->args = arena_alloc(&p->a, s->nargs * sizeof *p->args);
    if (p->args)
        for (unsigned i = 0; i < s->nargs; i++)
            memset(&p->args[i], 0, sizeof p->args[i]);
    p->call.args = p->args;
    if (!p->args || !fast_details(r, p, 0, &q, end)) {
        pending_free(r, p);
        return 0;
    }
    /* The usual case, no other call waiting and the leave right behind:
     * the call is complete and first in call order, so it is returned
     * without a trip through the queue.  If the leave has to be left to
     * the general parser after all, what this wrote into the call it
     * writes again (see above). */
    if (r->qcount == 0 && q < end && *q == EV_LEAVE) {
        const unsigned char *lq = q + 1;
        uint64_t no;
        if (cur_uint(&lq, end, &no) && no == p->call.no && fast_details(r, p, 1, &lq, end)) {
            r->next_call_no++;
            r->pos = (size_t)(lq - r->buf);
            p->complete = 1;
            r->returned = p;
            *call = p->call;
            return 2;
        }
    }
    if (queue_push(r, p)) {
        pending_free(r, p);
        return 0;
    }
    r->next_call_no++;
    r->pos = (size_t)(q - r->buf);
    return 1;
}

/* The leave event at r->pos of a call waiting for it; 1 or 0 as fast_enter. */
static int fast_leave(fs_trace_reader *r)
{
    const unsigned char *q = r->buf + r->pos + 1, *end = r->buf + r->len;
    uint64_t no;
    if (!cur_uint(&q, end, &no))
        return 0;
    pending *p = queue_find(r, no);
    if (!p || p->complete || !fast_details(r, p, 1, &q, end))
        return 0;
    p->complete = 1;
    r->pos = (size_t)(q - r->buf);
    return 1;
}

void fs_trace_set_strict_end(fs_trace_reader *r, int strict) { r->strict_end = strict; }

void fs_trace_set_parser(fs_trace_reader *r, fs_trace_parser parser)
{
    r->general_only = parser == FS_TRACE_PARSER_GENERAL;
}

const char *fs_trace_warning(const fs_trace_reader *r) { return r->warning[0] ? r->warning : NULL; }

int fs_trace_next(fs_trace_reader *r, fs_tcall *call)
{
    if (r->returned) {
        pending_free(r, r->returned);
        r->returned = NULL;
    }
    if (r->failed)
        return -1;
    for (;;) {
        if (r->qcount) {
            pending *p = r->q[r->qhead];
            int early = !p->complete && !r->eof && r->qcount > FS_TRACE_MAX_PENDING;
            if (p->complete || r->eof || early) {
                queue_pop(r);
                if (!p->complete)
                    p->call.flags |= FS_TCALL_INCOMPLETE;
                if (early) {
                    if (r->nabandoned == MAX_ABANDONED)
                        return rfail(r, "more than %d calls waiting for their leave event", MAX_ABANDONED);
                    r->abandoned[r->nabandoned++] = p->call.no;
                }
                r->returned = p;
                *call = p->call;
                return 1;
            }
        } else if (r->eof) {
            return 0;
        }
        int rc = have_data(r);
        if (rc < 0)
            return -1;
        if (rc == 0) {
            r->eof = 1;
            continue;
        }
        unsigned ev = r->buf[r->pos];
        if (r->general_only) {
            /* the reference: every event through the general parser */
        } else if (ev == EV_ENTER) {
            int fast = fast_enter(r, call);
            if (fast == 2)
                return 1;
            if (fast)
                continue;
        } else if (ev == EV_LEAVE && fast_leave(r)) {
            continue;
        }
        uint64_t off = stream_off(r);
        r->pos++;
        size_t queued = r->qcount;
        if (ev == EV_ENTER)
            rc = parse_enter(r, off);
        else if (ev == EV_LEAVE)
            rc = parse_leave(r, off);
        else
            rc = rfail_at(r, off, "unknown event 0x%02x", ev);
        if (rc && r->cut_in_event && r->strict_end)
            return -1;
        if (rc && r->cut_in_event) {
            /* Every chunk is whole but the stream stops inside this event:
             * what apitrace leaves when the traced program is killed (it
             * flushes whole chunks on SIGTERM).  The partial event is
             * dropped; calls before it are returned as usual. */
            if (ev == EV_ENTER && r->qcount > queued) {
                pending *last = r->q[(r->qhead + r->qcount - 1) & (r->qcap - 1)];
                r->qcount--;
                pending_free(r, last);
            }
            snprintf(r->warning, sizeof r->warning,
                     "%s: the trace ends inside an event at stream offset %llu; that partial call was dropped",
                     r->path, (unsigned long long)off);
            r->failed = 0;
            r->cut_in_event = 0;
            r->eof = 1;
            continue;
        }
        if (rc)
            return -1;
    }
}

fs_trace_reader *fs_trace_open(const char *path, char *err, size_t errlen)
{
    fs_trace_reader *r = calloc(1, sizeof *r);
    if (!r || !(r->path = strdup(path)) || !(r->buf = malloc(CHUNK_MAX))) {
        if (err && errlen)
            snprintf(err, errlen, "%s: out of memory", path);
        if (r) {
            free(r->path);
            free(r);
        }
        return NULL;
    }
    r->f = fopen(path, "rb");
    struct stat st;
    if (!r->f || fstat(fileno(r->f), &st) != 0) {
        if (err && errlen)
            snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        fs_trace_close(r);
        return NULL;
    }
    r->file_size = (uint64_t)st.st_size;
    unsigned char magic[2] = {0, 0};
    size_t got = fread(magic, 1, 2, r->f);
    const char *bad = NULL;
    if (got < 2)
        bad = "file too short to be a trace";
    else if (magic[0] == 0x1f && magic[1] == 0x8b) {
        /* apitrace's zlib container (lib/trace/trace_file_read.cpp picks it
         * by gzip's magic bytes); inflate from the file's first byte, with
         * gzip framing (windowBits 16 + 15). */
        r->gz = calloc(1, sizeof *r->gz);
        r->cbuf = malloc(GZ_IN);
        if (!r->gz || !r->cbuf || inflateInit2(r->gz, 16 + MAX_WBITS) != Z_OK) {
            free(r->gz);
            r->gz = NULL;
            bad = "out of memory (zlib)";
        } else {
            r->cbuf_cap = GZ_IN;
            rewind(r->f);
            r->file_pos = 0;
        }
    } else if (magic[0] != 'a' || magic[1] != 't')
        bad = "not an apitrace trace (the file does not start with 'at' (Snappy) or gzip's mark)";
    if (bad) {
        if (err && errlen)
            snprintf(err, errlen, "%s: %s", path, bad);
        fs_trace_close(r);
        return NULL;
    }
    if (!r->gz)
        r->file_pos = 2;

    /* header = version_no semantic_version_no properties (version >= 6) | version_no */
    uint64_t v = 0, sv = 0;
    if (rd_uint(r, &v) == 0) {
        if (v > TRACE_VERSION)
            rfail_at(r, 0, "unsupported trace format version %llu (this reader knows up to %d)",
                     (unsigned long long)v, TRACE_VERSION);
        r->version = r->semantic = (unsigned)v;
    }
    if (!r->failed && r->version >= 6 && rd_uint(r, &sv) == 0) {
        if (sv > v)
            rfail(r, "semantic version %llu above the format version %llu",
                  (unsigned long long)sv, (unsigned long long)v);
        r->semantic = (unsigned)sv;
        /* properties = (name value)* empty_string; kept in a scratch arena */
        arena props = {NULL, 0};
        for (unsigned k = 0; !r->failed; k++) {
            const char *name;
            size_t len;
            if (rd_string(r, &props, MAX_SIG_STRING, &name, &len) || len == 0)
                break;
            if (rd_string(r, &props, MAX_SIG_STRING, &name, &len))
                break;
            if (k > 100000) {
                rfail(r, "absurd number of properties");
                break;
            }
        }
        arena_release(&props);
    }
    if (r->failed) {
        if (err && errlen)
            snprintf(err, errlen, "%s", r->err);
        fs_trace_close(r);
        return NULL;
    }
    return r;
}

const char *fs_trace_error(const fs_trace_reader *r)
{
    return r->failed ? r->err : NULL;
}

unsigned fs_trace_version(const fs_trace_reader *r)
{
    return r->version;
}

void fs_trace_close(fs_trace_reader *r)
{
    if (!r)
        return;
    if (r->f)
        fclose(r->f);
    if (r->gz) {
        inflateEnd(r->gz);
        free(r->gz);
    }
    if (r->returned)
        pending_free(r, r->returned);
    while (r->qcount)
        pending_free(r, queue_pop(r));
    for (pending *p = r->free_list, *n; p; p = n) {
        n = p->next_free;
        arena_release(&p->a);
        arena_release(&p->elems);
        free(p);
    }
    arena_release(&r->sigs);
    free(r->funcs);
    free(r->enums);
    free(r->bitmasks);
    free(r->structs);
    free(r->frames);
    free(r->q);
    free(r->cbuf);
    free(r->buf);
    free(r->path);
    free(r);
}
