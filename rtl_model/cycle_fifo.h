/*
 * The FIFO engine of the cycle-level model: stages connected by bounded
 * FIFOs and memories, evaluated work item by work item (the recurrence of
 * docs/cycle_model.md).  It knows nothing of GL or of the pipeline: the
 * observer (cycle_observer.c) and the sampling estimator
 * (cycle_sampling.c) drive it.  The recurrence is inline here because the
 * observer steps it per quad; cycle_fifo.c creates and frees stages,
 * memory.c keeps the memories.
 */
#ifndef FS_CYCLE_FIFO_H
#define FS_CYCLE_FIFO_H
#include <stdbool.h>
#include <stdint.h>
#include "cycle_signals.h"

/* The FIFO in front of a stage: the start times of the last `depth` items
 * the stage took from it (a ring), which is all the recurrence needs: item
 * i may enter once item i - depth has left. */
typedef struct fs_cyc_fifo {
    uint64_t *ring;
    uint32_t depth;
    uint64_t count;     /* items taken so far */
    uint32_t widx;      /* count % depth, kept so that no step divides */
    uint64_t sptr;      /* first item not known to have started (occupancy) */
    uint32_t sidx;      /* sptr % depth */
    uint64_t hwm;       /* most items ever waiting, since the last reset */
    fs_sig_tap *tap;    /* the stage's signals (cycle_signals.h), NULL when none are written */
} fs_cyc_fifo;

/* A memory: bandwidth in bytes per cycle, read latency.  `t` is the time the
 * memory is busy until, in bytes (cycles * bandwidth), so fractional
 * bandwidth use carries over exactly. */
typedef struct fs_cyc_mem {
    uint64_t bw, t;
    uint32_t latency;
    int shift;   /* log2 bw when bw is a power of two (a shift, not a division), else -1 */
    fs_sig_tap *tap;   /* its memory_busy signal, NULL when none are written */
} fs_cyc_mem;

typedef struct fs_cyc_stage {
    uint64_t free;          /* earliest start of the next item */
    uint64_t busy, stalled;
    uint32_t latency;
    fs_cyc_fifo in;
    fs_cyc_mem *mem;
} fs_cyc_stage;

/* ---- memory.c ---- */
void fs_cyc_mem_init(fs_cyc_mem *m, uint64_t bytes_per_cycle, uint32_t latency);
/* Reserves `bytes` of bandwidth from cycle t on; returns the cycle the
 * transfer ends (latency not included). */
uint64_t fs_cyc_mem_reserve(fs_cyc_mem *m, uint64_t t, uint64_t bytes);

int fs_cyc_stage_init(fs_cyc_stage *st, uint32_t latency, uint32_t fifo_depth);
void fs_cyc_stage_free(fs_cyc_stage *st);

/* The per-item steps stay inline in the observer's per-quad code, as
 * before the signal taps: their call to the (cold) tap made gcc keep
 * fs_cyc_step_n out of line, 3.5% more instructions on bench32 without any
 * signal (callgrind). */
#define FS_CYC_STEP_INLINE static inline __attribute__((always_inline))

/* Records that the stage owning fifo started its next item at time t. */
FS_CYC_STEP_INLINE void fs_cyc_fifo_push(fs_cyc_fifo *f, uint64_t t)
{
    f->ring[f->widx] = t;
    if (++f->widx == f->depth)
        f->widx = 0;
    f->count++;
    if (__builtin_expect(f->tap != NULL, 0))
        fs_sig_take(f->tap, t);
}

/* The same for m quads taken one after another over `service` cycles (a
 * train, sampled mode's spread items): the FIFOs count quads, so a train
 * holds m places, as its quads would, not one. */
static inline void fs_cyc_fifo_push_n(fs_cyc_fifo *f, uint64_t t, uint64_t service, uint64_t m)
{
    uint64_t k = m < f->depth ? m : f->depth;
    uint32_t idx = m > f->depth ? (uint32_t)((f->widx + m) % f->depth) : f->widx;
    double per = (double)service / (double)m;
    for (uint64_t i = m - k; i < m; i++) {
        /* i * per < service: the signed conversion is exact and cheaper */
        f->ring[idx] = t + (uint64_t)(int64_t)((double)(int64_t)i * per);
        if (++idx == f->depth)
            idx = 0;
    }
    f->widx = idx; /* k places on from where the loop began: (count + m) % depth */
    f->count += m;
}

/* The recurrence for an item of m quads (m = 1: one quad or triangle) that
 * keeps the stage `occupy` >= `service` cycles (a train: the sum over its
 * quads of each one's service or memory time, whichever is longer). */
FS_CYC_STEP_INLINE uint64_t fs_cyc_step_n(fs_cyc_stage *st, uint64_t arr, uint64_t service, uint64_t occupy, uint64_t bytes,
                            bool reads, fs_cyc_stage *next, uint64_t m)
{
    uint64_t start = arr > st->free ? arr : st->free;
    if (m == 1)
        fs_cyc_fifo_push(&st->in, start);
    else
        fs_cyc_fifo_push_n(&st->in, start, service, m);
    uint64_t finish = start + occupy, lat = st->latency;
    if (bytes && st->mem) {
        uint64_t mem_done = fs_cyc_mem_reserve(st->mem, start, bytes);
        if (mem_done > finish)
            finish = mem_done;
        if (reads)
            lat += st->mem->latency;
    }
    uint64_t depart = finish;
    if (next) {
        fs_cyc_fifo *nf = &next->in;
        uint32_t d = nf->depth;
        /* Room (for the train's last quad, or its d-th) when the quad
         * `depth` places ahead has left the FIFO. */
        uint64_t last = (m < d ? m : d) - 1;
        if (nf->count + last >= d) {
            uint64_t at = nf->widx + last; /* (count + last) % d, last < d */
            uint64_t slot = nf->ring[at >= d ? at - d : at];
            if (slot > depart)
                depart = slot;
        }
        /* Occupancy on entry: earlier items not yet started.  Starts are in
         * order, so a pointer that only moves forward finds them. */
        uint64_t lo = nf->count > d ? nf->count - d : 0;
        if (nf->sptr < lo) {
            nf->sptr = lo;
            nf->sidx = lo ? nf->widx : 0; /* lo % d: lo is 0 or count - d */
        }
        while (nf->sptr < nf->count && nf->ring[nf->sidx] <= depart) {
            nf->sptr++;
            if (++nf->sidx == d)
                nf->sidx = 0;
        }
        uint64_t occ = nf->count - nf->sptr + 1 + last;
        if (occ > nf->hwm)
            nf->hwm = occ;
    }
    st->busy += service;
    st->stalled += depart - start - service;
    st->free = depart;
    if (__builtin_expect(st->in.tap != NULL, 0))
        fs_sig_item(st->in.tap, start, service, depart, next ? next->in.tap : NULL);
    return depart + lat;
}
/* Passes one item through stage st: it arrives at `arr`, takes `service`
 * cycles and `bytes` of st's memory bandwidth, and leaves when `next`'s
 * FIFO has room (next NULL: no FIFO after it).  Returns its arrival at the
 * next stage (departure + latency, + memory latency when it read memory). */
FS_CYC_STEP_INLINE uint64_t fs_cyc_step(fs_cyc_stage *st, uint64_t arr, uint64_t service, uint64_t bytes, bool reads,
                                   fs_cyc_stage *next)
{
    return fs_cyc_step_n(st, arr, service, service, bytes, reads, next, 1);
}
#endif
