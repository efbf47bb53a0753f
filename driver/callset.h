/*
 * apitrace's call sets (glretrace --snapshot=CALLSET, apitrace dump
 * --calls=CALLSET; lib/trace/trace_callset.cpp, docs/USAGE.markdown) and
 * the call flags they select by (lib/trace/trace_parser_flags.cpp).
 *
 * Grammar: a list of ranges separated by commas or white space; a range is
 *   *            every call
 *   N            call N
 *   A-B, A-      calls A to B, A to the end
 *   R/S          every S-th call of range R, counted from its start
 *   R/FREQ, FREQ the calls of R (or of all) with that flag: frame (calls
 *                that end a frame: swaps), draw or render (draw calls),
 *                fbo or rendertarget (frame ends and framebuffer binds)
 *   @FILE        the ranges written in FILE
 * Calls are numbered as apitrace numbers them (dump's numbers).
 */
#ifndef FS_CALLSET_H
#define FS_CALLSET_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* apitrace's CALL_FLAG_* that call sets select by. */
#define FS_CALL_END_FRAME 0x1u
#define FS_CALL_SWAP_RENDERTARGET 0x2u
#define FS_CALL_RENDER 0x4u

typedef struct fs_callset_range {
    uint64_t start, stop, step;
    unsigned freq; /* FS_CALL_* bits, or FS_CALLSET_ALL */
} fs_callset_range;
#define FS_CALLSET_ALL 0xffffffffu

typedef struct fs_callset {
    fs_callset_range *ranges;
    size_t n, cap;
} fs_callset;

/* Adds the ranges of spec.  Returns 0, or -1 with a message in err (the
 * set may then hold some of the ranges). */
int fs_callset_parse(fs_callset *cs, const char *spec, char *err, size_t errlen);
bool fs_callset_contains(const fs_callset *cs, uint64_t call_no, unsigned call_flags);
void fs_callset_free(fs_callset *cs);
/* The flags apitrace gives a call by its name. */
unsigned fs_call_flags(const char *name);
#endif
