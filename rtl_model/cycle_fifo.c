/*
 * The FIFO engine (cycle_fifo.h): a stage's creation and release.
 */
#include <stdlib.h>
#include <string.h>
#include "cycle_fifo.h"

int fs_cyc_stage_init(fs_cyc_stage *st, uint32_t latency, uint32_t fifo_depth)
{
    memset(st, 0, sizeof *st);
    st->latency = latency;
    st->in.depth = fifo_depth ? fifo_depth : 1;
    st->in.ring = calloc(st->in.depth, sizeof *st->in.ring);
    return st->in.ring ? 0 : -1;
}

void fs_cyc_stage_free(fs_cyc_stage *st) { free(st->in.ring); }
