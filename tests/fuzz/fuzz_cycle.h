/*
 * The mode both fuzz harnesses run an input in: functional, or with the
 * cycle model attached in full or sampled mode, chosen by the input's
 * length modulo 3 so that an input always takes the same path.
 */
#ifndef FS_FUZZ_CYCLE_H
#define FS_FUZZ_CYCLE_H
#include <stddef.h>
#include <stdint.h>
#include "../../driver/gl_call.h"
#include "../../pipeline/context.h"
#include "../../rtl_model/cycle_model.h"

/* The model with the default configuration; NULL for functional mode (or
 * when the model cannot be made). */
static inline fs_cycle *fuzz_cycle_begin(fs_context *c, size_t size, uint64_t frames)
{
    char err[256];
    int mode = (int)(size % 3) - 1;
    fs_cycle_config cfg;
    fs_config_part defaults = fs_cycle_config_part(&cfg);
    fs_config_part_defaults(&defaults);
    fs_cycle *cy = mode >= 0 ? fs_cycle_create(&cfg, (fs_cycle_mode)mode, err, sizeof err) : NULL;
    if (cy) {
        fs_cycle_set_frames(cy, frames);
        fs_cycle_attach(cy, c);
    }
    return cy;
}

static inline void fuzz_cycle_frame_end(fs_cycle *cy)
{
    fs_cycle_stats st;
    if (cy)
        fs_cycle_frame_end(cy, &st);
}

/* Submits a call, unless sampled mode skips it (a frame it interpolates). */
static inline int fuzz_cycle_submit(const fs_cycle *cy, fs_context *c, fs_call *call)
{
    return cy && fs_cycle_frame_skipped(cy) && fs_cmd_skippable(c, call->cmd) ? 0 : fs_submit(c, call);
}

/* Finishes the run (the interpolation of skipped frames and the totals
 * run too) and frees the model; before fs_context_destroy. */
static inline void fuzz_cycle_end(fs_cycle *cy)
{
    fs_cycle_stats t;
    if (cy) {
        fs_cycle_finish(cy);
        fs_cycle_totals(cy, &t);
    }
    fs_cycle_destroy(cy);
}
#endif
