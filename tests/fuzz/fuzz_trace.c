/*
 * libFuzzer harness for the path a captured trace takes: the apitrace
 * reader (driver/trace_read.c), the replayer's validation pass and the GL
 * dispatch into the model on a small window, in the mode fuzz_cycle.h
 * picks.
 *
 * The input is the *decompressed* event stream (the fuzzer mutates calls,
 * not Snappy blocks); the harness wraps it in the Snappy container in a
 * temporary file.  An input that starts with the container's mark "at" is
 * written unchanged instead, so the container parser is fuzzed too.
 *
 * Built and run by `make fuzz` (clang, ASan + UBSan); tests/fuzz/README.md.
 * A trace that crashes or hangs here must instead be refused with a message
 * or replayed by GL's rules: the property is "returns", checked by the
 * sanitizers and libFuzzer's timeout.
 */
#include <snappy-c.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "../../driver/gl_call.h"
#include "../../driver/replay.h"
#include "fuzz_cycle.h"

/* The writer's chunk size (driver/trace_write.c): apitrace's limit too. */
#define CHUNK (1u << 20)

static char path[64];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    snprintf(path, sizeof path, "/tmp/fragsim-fuzz-%ld.trace", (long)getpid());
    return 0;
}

static int write_input(const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    int rc = 0;
    if (size >= 2 && data[0] == 'a' && data[1] == 't') {
        rc = fwrite(data, 1, size, f) == size ? 0 : -1;
    } else {
        rc = fwrite("at", 1, 2, f) == 2 ? 0 : -1;
        char *cbuf = malloc(snappy_max_compressed_length(CHUNK));
        for (size_t off = 0; rc == 0 && cbuf && off < size; off += CHUNK) {
            size_t n = size - off < CHUNK ? size - off : CHUNK;
            size_t clen = snappy_max_compressed_length(CHUNK);
            if (snappy_compress((const char *)data + off, n, cbuf, &clen) != SNAPPY_OK) {
                rc = -1;
                break;
            }
            unsigned char len[4] = {(unsigned char)clen, (unsigned char)(clen >> 8), (unsigned char)(clen >> 16),
                                    (unsigned char)(clen >> 24)};
            if (fwrite(len, 1, 4, f) != 4 || fwrite(cbuf, 1, clen, f) != clen)
                rc = -1;
        }
        if (!cbuf)
            rc = -1;
        free(cbuf);
    }
    if (fclose(f) != 0)
        rc = -1;
    return rc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (write_input(data, size) != 0)
        return 0;
    char err[512];
    /* A fixed small window: a trace's glViewport may ask for any size, and
     * the fuzzer should spend its time on calls, not on clearing pixels. */
    fs_replay_opts ro = {.width = 32, .height = 32}; /* the rest as by default */
    fs_replayer *r = fs_replay_open(path, &ro, err, sizeof err);
    if (!r)
        return 0;
    const fs_replay_info *info = fs_replay_info_get(r);
    fs_config cfg;
    fs_config_defaults(&cfg);
    fs_context *c = fs_context_create(&cfg, info->width, info->height);
    if (c) {
        fs_cycle *cy = fuzz_cycle_begin(c, size, info->frames);
        fs_call call;
        fs_replay_event ev;
        while ((ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR) {
            if (ev == FS_REPLAY_FRAME_END)
                fuzz_cycle_frame_end(cy);
            else if (ev == FS_REPLAY_CALL && fuzz_cycle_submit(cy, c, &call) != 0)
                break;
        }
        fuzz_cycle_end(cy);
        fs_context_destroy(c);
    }
    fs_replay_close(r);
    return 0;
}
