/*
 * Texture cache model against an independent oracle: a naive simulation
 * that keeps, per set, the resident lines as a recency-ordered list (most
 * recent first) and moves or inserts at the front, dropping the tail.
 * Plus closed forms: a stream that fits in the cache misses once per distinct
 * line; a cyclic stream of ways+1 lines in one set always misses under LRU;
 * a group's bank conflicts are the most distinct words in one bank minus 1.
 */
#include <stdint.h>
#include "check.h"
#include "../rtl_model/texture_cache.h"

/* ---- Oracle: recency lists ---- */
typedef struct oracle {
    unsigned sets, ways, line;
    uint64_t *list; /* sets * ways, most recent first */
    unsigned *len;
    uint64_t hits, misses;
} oracle;

static void oracle_init(oracle *o, unsigned size, unsigned line, unsigned ways)
{
    o->line = line;
    o->ways = ways;
    o->sets = size / line / ways;
    o->list = calloc((size_t)o->sets * ways, sizeof *o->list);
    o->len = calloc(o->sets, sizeof *o->len);
    o->hits = o->misses = 0;
}

static void oracle_free(oracle *o)
{
    free(o->list);
    free(o->len);
}

static int oracle_access(oracle *o, uint64_t addr)
{
    uint64_t ln = addr / o->line;
    unsigned set = (unsigned)(ln % o->sets);
    uint64_t *l = o->list + (size_t)set * o->ways;
    unsigned n = o->len[set], pos = n;
    for (unsigned i = 0; i < n; i++)
        if (l[i] == ln) { pos = i; break; }
    int hit = pos < n;
    if (!hit) {
        pos = n < o->ways ? n : o->ways - 1; /* grow, or overwrite the tail */
        if (n < o->ways) o->len[set]++;
    }
    for (unsigned i = pos; i > 0; i--) l[i] = l[i - 1];
    l[0] = ln;
    if (hit) o->hits++; else o->misses++;
    return hit;
}

static uint64_t rng_next(uint64_t *s)
{
    /* xorshift64*: a fixed seed gives the same stream on every run */
    *s ^= *s >> 12; *s ^= *s << 25; *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

static fs_tex_cache *make(unsigned size, unsigned line, unsigned ways, unsigned banks)
{
    fs_tex_cache_config cfg = {size, line, ways, banks, 20, 8};
    return fs_tex_cache_create(&cfg);
}

/* Compares cache and oracle access by access on one stream. */
static int compare_stream(check_state *check_st_, unsigned size, unsigned line, unsigned ways,
                          const uint64_t *addr, unsigned n)
{
    fs_tex_cache *c = make(size, line, ways, 1);
    if (!c) { CHECK_FAIL_("create %u/%u/%u failed", size, line, ways); return 0; }
    oracle o;
    oracle_init(&o, size, line, ways);
    unsigned miss_cost = fs_tex_cache_miss_cycles(c), bad = 0;
    for (unsigned i = 0; i < n && !bad; i++) {
        int want_hit = oracle_access(&o, addr[i]);
        unsigned got = fs_tex_cache_access(c, addr[i], 0);
        if (got != (want_hit ? 0 : miss_cost)) {
            CHECK_FAIL_("size %u line %u ways %u access %u addr %llu: %u cycles, oracle %s", size,
                        line, ways, i, (unsigned long long)addr[i], got, want_hit ? "hit" : "miss");
            bad = 1;
        }
    }
    fs_tex_cache_stats st;
    fs_tex_cache_get_stats(c, &st);
    CHECK_EQ_UINT(st.accesses, n);
    CHECK_EQ_UINT(st.hits, o.hits);
    CHECK_EQ_UINT(st.misses, o.misses);
    CHECK_EQ_UINT(st.bytes_from_memory, o.misses * line);
    oracle_free(&o);
    fs_tex_cache_destroy(c);
    return !bad;
}

static const unsigned geoms[][3] = {
    {1024, 32, 1}, {1024, 32, 2}, {4096, 64, 4}, {2048, 16, 8}, {512, 64, 8} /* fully assoc. */,
    {16384, 128, 2}, {256, 4, 64},
};

TEST(random_streams_match_oracle)
{
    enum { N = 20000 };
    uint64_t *a = malloc(N * sizeof *a);
    uint64_t s = 0x9E3779B97F4A7C15ull;
    for (size_t g = 0; g < sizeof geoms / sizeof geoms[0]; g++) {
        /* Address range a few times the cache, so hits and misses both occur. */
        uint64_t range = (uint64_t)geoms[g][0] * 3;
        for (unsigned i = 0; i < N; i++) a[i] = rng_next(&s) % range;
        compare_stream(check_st_, geoms[g][0], geoms[g][1], geoms[g][2], a, N);
    }
    free(a);
}

TEST(structured_streams_match_oracle)
{
    /* Texture-like walks: rows of a 256x256 RGBA8 texture stepping by a
     * fractional texel (the 2x2 bilinear neighbourhood per sample), and a
     * column walk that strides a whole row each step. */
    enum { W = 256, N = 16000 };
    uint64_t *a = malloc(N * sizeof *a);
    for (size_t g = 0; g < sizeof geoms / sizeof geoms[0]; g++) {
        unsigned n = 0;
        for (unsigned k = 0; n + 4 <= N / 2; k++) {
            unsigned u = (k * 3 / 4) % (W - 1), v = (k / 300) % (W - 1);
            a[n++] = ((uint64_t)v * W + u) * 4;
            a[n++] = ((uint64_t)v * W + u + 1) * 4;
            a[n++] = ((uint64_t)(v + 1) * W + u) * 4;
            a[n++] = ((uint64_t)(v + 1) * W + u + 1) * 4;
        }
        for (unsigned k = 0; n < N; k++)
            a[n++] = ((uint64_t)(k % W) * W + (k / W) % W) * 4 + 0x100000;
        compare_stream(check_st_, geoms[g][0], geoms[g][1], geoms[g][2], a, N);
    }
    free(a);
}

TEST(fitting_stream_misses_once_per_line)
{
    /* 3 passes over 24 KB in a 32 KB 2-way cache: only cold misses. */
    fs_tex_cache *c = make(32768, 32, 2, 1);
    REQUIRE(c);
    for (int pass = 0; pass < 3; pass++)
        for (uint64_t a = 0x4000; a < 0x4000 + 24576; a += 4)
            fs_tex_cache_access(c, a, 0);
    fs_tex_cache_stats st;
    fs_tex_cache_get_stats(c, &st);
    CHECK_EQ_UINT(st.misses, 24576 / 32);
    CHECK_EQ_UINT(st.hits, 3 * 24576 / 4 - 24576 / 32);
    fs_tex_cache_destroy(c);
}

TEST(cyclic_stream_over_ways_always_misses)
{
    /* ways+1 lines of one set (stride = sets * line) visited cyclically:
     * LRU evicts exactly the line needed next. */
    const unsigned size = 8192, line = 64, ways = 4, sets = size / line / ways;
    fs_tex_cache *c = make(size, line, ways, 1);
    REQUIRE(c);
    unsigned cost = 0;
    for (unsigned i = 0; i < 100 * (ways + 1); i++)
        cost += fs_tex_cache_access(c, (uint64_t)(i % (ways + 1)) * sets * line + 8, 0);
    fs_tex_cache_stats st;
    fs_tex_cache_get_stats(c, &st);
    CHECK_EQ_UINT(st.hits, 0);
    CHECK_EQ_UINT(st.misses, 100 * (ways + 1));
    /* 20 cycles latency + 64 bytes at 8 bytes/cycle, per miss */
    CHECK_EQ_UINT(cost, 100 * (ways + 1) * (20 + 64 / 8));
    /* With ways lines instead, only the first round misses. */
    fs_tex_cache_destroy(c);
    c = make(size, line, ways, 1);
    for (unsigned i = 0; i < 100 * ways; i++)
        fs_tex_cache_access(c, (uint64_t)(i % ways) * sets * line, 0);
    fs_tex_cache_get_stats(c, &st);
    CHECK_EQ_UINT(st.misses, ways);
    fs_tex_cache_destroy(c);
}

TEST(bank_conflicts_closed_form)
{
    uint64_t s = 12345;
    for (unsigned banks = 1; banks <= 16; banks *= 2) {
        fs_tex_cache *c = make(65536, 64, 4, banks);
        REQUIRE(c);
        uint64_t total = 0;
        for (int g = 0; g < 500; g++) {
            uint64_t a[16];
            unsigned n = 1 + (unsigned)(rng_next(&s) % 16);
            for (unsigned i = 0; i < n; i++) a[i] = (rng_next(&s) % 4096) & ~3ull;
            a[n - 1] = a[0] + (rng_next(&s) % 4); /* sometimes the same word, other byte */
            /* Brute force: count distinct words per bank. */
            unsigned most = 0;
            for (unsigned b = 0; b < banks; b++) {
                unsigned cnt = 0;
                for (unsigned i = 0; i < n; i++) {
                    if ((a[i] / 4) % banks != b) continue;
                    int dup = 0;
                    for (unsigned j = 0; j < i; j++) dup |= a[j] / 4 == a[i] / 4;
                    cnt += !dup;
                }
                if (cnt > most) most = cnt;
            }
            unsigned want_conf = banks == 1 ? 0 : most - 1;
            /* Warm the lines so the group's cycles are conflicts only. */
            for (unsigned i = 0; i < n; i++) fs_tex_cache_access(c, a[i], 0);
            CHECK_EQ_UINT(fs_tex_cache_access_group(c, a, n), 1 + want_conf);
            total += want_conf;
        }
        fs_tex_cache_stats st;
        fs_tex_cache_get_stats(c, &st);
        CHECK_EQ_UINT(st.bank_conflicts, total);
        fs_tex_cache_destroy(c);
    }
}

TEST(bilinear_quad_banks)
{
    /* A 2x2 quad of a 4-texel-wide row pitch lands in banks 0,1,0,1 under
     * word interleaving; with an odd pitch of 5 texels it is 0,1,1,2. */
    fs_tex_cache *c = make(4096, 32, 2, 4);
    REQUIRE(c);
    uint64_t even[4] = {0, 4, 16, 20}, odd[4] = {0, 4, 20, 24};
    CHECK_EQ_UINT(fs_tex_cache_bank(c, 20), 1);
    fs_tex_cache_access_group(c, even, 4); /* warm */
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, even, 4), 2);
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, odd, 4), 2);
    uint64_t distinct[4] = {0, 4, 8, 12};
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, distinct, 4), 1);
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, distinct, 0), 0);
    fs_tex_cache_destroy(c);
}

TEST(group_miss_cycles)
{
    /* Two cold lines in one group: 1 + latency 20 + 2 * 32 bytes / 8. */
    fs_tex_cache *c = make(4096, 32, 2, 1);
    REQUIRE(c);
    uint64_t a[3] = {0, 4, 64};
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, a, 3), 1 + 20 + 8);
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, a, 3), 1);
    fs_tex_cache_stats st;
    fs_tex_cache_get_stats(c, &st);
    CHECK_EQ_UINT(st.misses, 2);
    CHECK_EQ_UINT(st.hits, 4);
    CHECK_EQ_UINT(st.bytes_from_memory, 64);
    fs_tex_cache_flush(c);
    CHECK_EQ_UINT(fs_tex_cache_access(c, 0, 0), 20 + 4);
    fs_tex_cache_destroy(c);
}

TEST(bad_configs_rejected)
{
    const fs_tex_cache_config bad[] = {
        {0, 32, 2, 1, 10, 8}, {1000, 32, 2, 1, 10, 8}, {4096, 24, 2, 1, 10, 8},
        {4096, 32, 3, 1, 10, 8}, {4096, 32, 2, 3, 10, 8}, {4096, 32, 2, 1, 10, 0},
        {4096, 8192, 1, 1, 10, 8}, {4096, 32, 256, 1, 10, 8} /* 128 lines */,
        {1u << 31, 32, 2, 1, 10, 8}, {4096, 32, 2, 128, 10, 8},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fs_tex_cache *c = fs_tex_cache_create(&bad[i]);
        if (c) CHECK_FAIL_("config %zu accepted", i);
        fs_tex_cache_destroy(c);
    }
    CHECK(fs_tex_cache_create(NULL) == NULL);
    fs_tex_cache_config ok = {4096, 32, 128, 64, 0, 4096};
    fs_tex_cache *c = fs_tex_cache_create(&ok);
    CHECK(c != NULL);
    /* huge addresses near the top of the 64-bit range are lines like any other */
    if (c) {
        CHECK_EQ_UINT(fs_tex_cache_access(c, UINT64_MAX, 0), 0 + 1);
        CHECK_EQ_UINT(fs_tex_cache_access(c, UINT64_MAX - 1, 0), 0);
    }
    fs_tex_cache_destroy(c);
    /* Bandwidth need not be a power of two: 64-byte line at 12 B/cycle
     * streams in ceil(64 / 12) = 6 cycles after the latency. */
    fs_tex_cache_config odd = {4096, 64, 2, 1, 10, 12};
    c = fs_tex_cache_create(&odd);
    REQUIRE(c);
    CHECK_EQ_UINT(fs_tex_cache_miss_cycles(c), 10 + 6);
    uint64_t two[2] = {0, 64}; /* two lines: ceil(128 / 12) = 11 */
    CHECK_EQ_UINT(fs_tex_cache_access_group(c, two, 2), 1 + 10 + 11);
    fs_tex_cache_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(random_streams_match_oracle),
    TEST_ENTRY(structured_streams_match_oracle),
    TEST_ENTRY(fitting_stream_misses_once_per_line),
    TEST_ENTRY(cyclic_stream_over_ways_always_misses),
    TEST_ENTRY(bank_conflicts_closed_form),
    TEST_ENTRY(bilinear_quad_banks),
    TEST_ENTRY(group_miss_cycles),
    TEST_ENTRY(bad_configs_rejected),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
