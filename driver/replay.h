/*
 * Replaying an apitrace trace: decoded trace calls (trace.h) become fs_call
 * records for the model (and, in `fragsim check`, for OSMesa too), with
 * frames delimited by swap calls or by a chosen frame-end call.
 *
 * The trace is read twice: a first pass validates the whole file, finds the
 * frame boundaries and the window size, so a malformed trace is reported
 * before any image is written.  The first pass keeps the decoded calls
 * (fs_replay_opts.max_record_bytes), and the second replays them from memory.
 */
#ifndef FS_REPLAY_H
#define FS_REPLAY_H
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "gl_call.h"
#include "trace.h"

typedef struct fs_replay_opts {
    const char *frame_end; /* call name that ends a frame, or NULL for automatic */
    int width, height;     /* 0: from the first glViewport */
    /* Pass 1 keeps the decoded calls for pass 2 in blocks of up to this
     * many bytes in all (0: 1 GiB); a longer trace is read from the file
     * twice. */
    size_t max_record_bytes;
    /* Also return the calls the model does not execute (unknown, window
     * system, unsafe draws) as FS_REPLAY_SKIPPED, e.g. to snapshot at them. */
    bool report_skipped;
    /* The trace reader's parser (trace.h); 0, the fast one, by default. */
    fs_trace_parser parser;
} fs_replay_opts;

typedef struct fs_replay_info {
    uint64_t calls;         /* calls in the trace */
    uint64_t frames;        /* frames found (a trailing partial frame counts) */
    int width, height;      /* chosen window size */
    char frame_end[64];     /* the call that ends frames */
    bool uses_queries;      /* the trace begins occlusion queries itself */
    /* The trace swaps buffers (glXSwapBuffers, ...): the captured context
     * was double-buffered; give it to fs_context_set_double_buffered. */
    bool double_buffered;
    char warning[400];      /* e.g. the trace ends inside an event (a killed capture) */
    bool from_record;       /* pass 2 replays pass 1's decoded calls, not the file */
} fs_replay_info;

typedef enum fs_replay_event {
    FS_REPLAY_CALL,      /* *call is ready to execute */
    FS_REPLAY_FRAME_END, /* the frame just ended (after executing its last call) */
    FS_REPLAY_EOF,
    FS_REPLAY_ERROR,     /* fs_replay_error() says what and where */
    FS_REPLAY_SKIPPED    /* a call not executed (only with fs_replay_opts.report_skipped) */
} fs_replay_event;

typedef struct fs_replayer fs_replayer;

/* Opens and validates the trace (first pass).  NULL on error, with one
 * message naming the file and byte offset in err. */
fs_replayer *fs_replay_open(const char *path, const fs_replay_opts *opts, char *err, size_t errlen);
const fs_replay_info *fs_replay_info_get(const fs_replayer *r);
/* Each frame's signatures of work, from pass 1's hash of its calls
 * without executing them (sampled mode's frame clustering,
 * fs_cycle_set_frame_signatures): *kind without floating-point arguments
 * and array contents, *exact of everything.  Returns the frames (0: none,
 * e.g. out of memory); the arrays live until fs_replay_close. */
uint64_t fs_replay_frame_signatures(const fs_replayer *r, const uint64_t **kind, const uint64_t **exact);
/* Next event of the second pass.  A FS_REPLAY_CALL's call stays valid
 * until the next call of this function. */
fs_replay_event fs_replay_next(fs_replayer *r, fs_call *call);
const char *fs_replay_error(const fs_replayer *r);
/* The last FS_REPLAY_CALL or FS_REPLAY_SKIPPED call, which a following
 * FS_REPLAY_FRAME_END belongs to: its number as `apitrace dump` numbers it,
 * its name in the trace (valid until fs_replay_close) and its apitrace call
 * flags (FS_CALL_* of callset.h). */
uint64_t fs_replay_call_no(const fs_replayer *r);
const char *fs_replay_call_name(const fs_replayer *r);
unsigned fs_replay_call_flags(const fs_replayer *r);
/* Calls the replay could not execute, by name (unknown to fragsim, or
 * unsafe: e.g. a draw whose client arrays the trace did not record), and
 * window-system calls that were deliberately ignored. */
struct json_t;
/* As a new JSON object (jansson): {"name": {"count": N, "reason": "..."}, ...};
 * NULL when out of memory. */
struct json_t *fs_replay_skipped_json(const fs_replayer *r);
void fs_replay_print_skipped(const fs_replayer *r, FILE *f);
uint64_t fs_replay_skipped_total(const fs_replayer *r);
void fs_replay_close(fs_replayer *r);
#endif
