/*
 * The tests' deterministic random numbers: xorshift64*, small, a fixed
 * sequence for a seed, no libc state (so a run is reproducible).
 */
#ifndef FS_TEST_RNG_H
#define FS_TEST_RNG_H
#include <stdint.h>

typedef struct rng { uint64_t s; } rng;

static inline uint32_t rnd(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (uint32_t)((r->s * 2685821657736338717ull) >> 32);
}

static inline float rndf(rng *r, float lo, float hi) { return lo + (hi - lo) * (float)(rnd(r) >> 8) / 16777216.0f; }
static inline int rndi(rng *r, int n) { return (int)(rnd(r) % (uint32_t)n); }
#endif
