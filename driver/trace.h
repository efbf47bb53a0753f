/*
 * apitrace trace files: reading and writing.
 *
 * Format (apitrace docs/FORMAT.markdown, lib/trace/trace_format.hpp): the
 * bytes 'a' 't', then chunks [uint32 LE compressed length][raw Snappy block],
 * each decompressing to at most 1 MiB.  The decompressed stream is a header
 * (version, and for version >= 6 a semantic version and properties) followed
 * by events: call enter (thread, function signature, call details) and call
 * leave (call number, call details).  Signatures carry an id, and their full
 * description only the first time the id appears.
 *
 * The writer writes version 6 (what apitrace 11 writes and reads).  The
 * reader accepts versions 0-6 in the Snappy container and in the old zlib
 * container (the whole file one gzip stream of the same events, as
 * apitrace's lib/trace/trace_file_zlib.cpp reads it with gzread).
 */
#ifndef FS_TRACE_H
#define FS_TRACE_H
#include <stddef.h>
#include <stdint.h>

/* Value tags, in the order of the format's value tags 0x00-0x0f. */
typedef enum {
    FS_TV_NULL, FS_TV_FALSE, FS_TV_TRUE, FS_TV_SINT, FS_TV_UINT, FS_TV_FLOAT,
    FS_TV_DOUBLE, FS_TV_STRING, FS_TV_BLOB, FS_TV_ENUM, FS_TV_BITMASK,
    FS_TV_ARRAY, FS_TV_STRUCT, FS_TV_OPAQUE, FS_TV_REPR, FS_TV_WSTRING
} fs_tv_type;

/* A signature of an enum, a bitmask or a struct.  ENUM and BITMASK: n
 * (name, value) pairs.  STRUCT: name is the struct's name, names the n
 * member names, values unused (NULL). */
typedef struct fs_tsig {
    const char *name;
    unsigned n;
    const char *const *names;
    const int64_t *values;
} fs_tsig;

/*
 * One value.  Where each type keeps its data:
 *   SINT: i.  UINT, OPAQUE (address), BITMASK: u.  ENUM: i.
 *   FLOAT (stored as float in the file), DOUBLE: d.
 *   STRING, BLOB: str (STRING need not be NUL-terminated; the reader adds one).
 *   ARRAY: arr.  STRUCT: arr holds the members, sig the struct signature.
 *   REPR: arr holds 2 values (human, machine).
 *   WSTRING: arr holds the characters as UINT values.
 *   ENUM: enum_name is the name of the value in its signature (NULL if the
 *   signature has none); sig is the whole signature (reader), or, when
 *   writing, an optional signature to write instead of the one-pair
 *   signature {enum_name: i} made from enum_name.
 *   BITMASK: sig holds the flags (needed for `apitrace dump` to print names).
 * A non-negative SINT is written with the "positive integer" tag (as apitrace
 * does: 0x03 means negative), so it reads back as UINT.
 */
typedef struct fs_tval {
    fs_tv_type type;
    union {
        int64_t i;
        uint64_t u;
        double d;
        struct { const char *ptr; size_t len; } str;
        struct { const struct fs_tval *elems; size_t n; } arr;
    };
    const char *enum_name;
    const fs_tsig *sig;
} fs_tval;

#define FS_TCALL_FAKE 0x1u       /* apitrace "fake" call (call detail flags, FLAG_FAKE) */
#define FS_TCALL_INCOMPLETE 0x2u /* the trace has no leave event for it */

typedef struct fs_tcall {
    uint64_t no;              /* call number (reader); ignored by the writer, which numbers calls itself */
    uint32_t thread;
    const char *name;
    unsigned nargs;           /* from the function signature */
    const char *const *arg_names;
    const fs_tval *args;      /* nargs values; an argument the trace omits is NULL */
    fs_tval ret;
    int has_ret;
    uint32_t flags;           /* FS_TCALL_* */
    uint64_t offset;          /* byte offset in the decompressed stream where the enter event begins */
    /* Bit i: argument i is an output, carried by the leave event (reader:
     * its value came from the leave; writer: write it in the leave). */
    uint64_t out_args;
} fs_tcall;

/* ---- reading ---- */
typedef struct fs_trace_reader fs_trace_reader;

/* Opens a trace and reads its header.  Returns NULL with a message in err
 * when the file cannot be opened or its header is invalid. */
fs_trace_reader *fs_trace_open(const char *path, char *err, size_t errlen);
/*
 * Reads the next call, in call-number order.  Returns 1 with *call filled,
 * 0 at the clean end of the trace, -1 on malformed input (then
 * fs_trace_error names the problem with its stream offset and the file
 * offset of the chunk holding it; later calls return -1 again).
 * A call is complete at its leave event.  Calls that have no leave event
 * when the trace ends (a trace cut short, or a call still blocked in another
 * thread) are returned at the end, in order, flagged FS_TCALL_INCOMPLETE, as
 * apitrace does.  A call still waiting for its leave while
 * FS_TRACE_MAX_PENDING later calls completed is returned early, flagged
 * incomplete, to bound memory; its late leave event is then skipped.
 * What *call points to stays valid until the next fs_trace_next or
 * fs_trace_close.
 */
int fs_trace_next(fs_trace_reader *r, fs_tcall *call);
const char *fs_trace_error(const fs_trace_reader *r);
/* A capture whose program was killed (apitrace flushes whole chunks on
 * SIGTERM) ends inside an event although every chunk is whole.  By default
 * that partial event is dropped and the trace ends cleanly, with a warning
 * here; strict mode makes it an error like any other truncation.  A
 * truncated chunk is always an error. */
const char *fs_trace_warning(const fs_trace_reader *r);
void fs_trace_set_strict_end(fs_trace_reader *r, int strict);
/* Which parser reads the events.  FAST (the default): fast paths for the
 * events that make up nearly all of a trace (a known signature, scalar
 * values, everything inside the current chunk), which give anything else
 * to the general parser.  GENERAL: the general parser alone, the reference
 * the fast paths must equal call for call (tests/test_trace_parsers.c
 * holds them equal on every test trace).  It may change between calls:
 * the fast paths keep no state of their own. */
typedef enum fs_trace_parser { FS_TRACE_PARSER_FAST, FS_TRACE_PARSER_GENERAL } fs_trace_parser;
void fs_trace_set_parser(fs_trace_reader *r, fs_trace_parser parser);
/* The trace's format version (header version_no). */
unsigned fs_trace_version(const fs_trace_reader *r);
void fs_trace_close(fs_trace_reader *r);

#define FS_TRACE_MAX_PENDING 4096

/* ---- writing ---- */
typedef struct fs_trace_writer fs_trace_writer;

fs_trace_writer *fs_trace_create(const char *path, char *err, size_t errlen);
/* Writes the call's enter and leave events.  Returns 0, or -1 (the writer
 * then refuses further calls; fs_trace_writer_error says why). */
int fs_trace_write(fs_trace_writer *w, const fs_tcall *call);
const char *fs_trace_writer_error(const fs_trace_writer *w);
/* Flushes, closes and frees the writer; returns 0, or -1 when any write failed. */
int fs_trace_finish(fs_trace_writer *w);

#endif
