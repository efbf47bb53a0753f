/*
 * Memories of the cycle model: framebuffer and texture memory, or O2's one
 * unified memory (configs/o2.ini), each a bandwidth (bytes per cycle) and a
 * read latency.  A transfer occupies the memory for bytes / bandwidth
 * cycles; the remainder of a partly used cycle is kept (time counted in
 * bytes), so many small transfers cost what their sum costs.
 */
#include "cycle_internal.h"

void fs_cyc_mem_init(fs_cyc_mem *m, uint64_t bytes_per_cycle, uint32_t latency)
{
    m->bw = bytes_per_cycle ? bytes_per_cycle : 1;
    m->t = 0;
    m->latency = latency;
    m->shift = -1;
    m->tap = NULL; /* cycle_signal_taps.c sets it when signals are written */
    if (!(m->bw & (m->bw - 1)))
        for (m->shift = 0; (1ull << m->shift) < m->bw; m->shift++)
            ;
}

uint64_t fs_cyc_mem_reserve(fs_cyc_mem *m, uint64_t t, uint64_t bytes)
{
    uint64_t tb = t * m->bw;
    if (m->t < tb)
        m->t = tb;
    if (m->tap)
        fs_sig_memory(m->tap, m->t, m->t + bytes, m->bw);
    m->t += bytes;
    if (m->shift >= 0)
        return (m->t + m->bw - 1) >> m->shift;
    return (m->t + m->bw - 1) / m->bw;
}
