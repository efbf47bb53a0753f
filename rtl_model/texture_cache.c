/*
 * Texture cache model (see texture_cache.h).  Sets are arrays of tags with
 * a last-use stamp each; LRU picks the smallest stamp.  Associativity is
 * small in every configuration the studies use (Hakura & Gupta 1997 find
 * 2-way as good as fully associative for blocked textures), so a linear scan
 * over the ways of one set is cheaper than keeping ordered lists.
 */
#include "texture_cache.h"
#include <stdlib.h>
#include <string.h>

#define NO_TAG UINT64_MAX

struct fs_tex_cache {
    fs_tex_cache_config cfg;
    unsigned line_shift, set_mask, sets;
    uint64_t *tags;   /* sets * ways */
    uint64_t *stamps; /* last use of each way; 0 = empty */
    uint64_t clock;
    unsigned miss_cycles;
    fs_tex_cache_stats stats;
};

static int pow2(unsigned v) { return v != 0 && (v & (v - 1)) == 0; }

static unsigned log2u(unsigned v)
{
    unsigned s = 0;
    while ((1u << s) < v)
        s++;
    return s;
}

fs_tex_cache *fs_tex_cache_create(const fs_tex_cache_config *cfg)
{
    if (!cfg || !pow2(cfg->size_bytes) || !pow2(cfg->line_bytes) || !pow2(cfg->ways) ||
        !pow2(cfg->banks) || cfg->bytes_per_cycle == 0)
        return NULL;
    if (cfg->size_bytes > FS_TEX_CACHE_MAX_BYTES || cfg->line_bytes > cfg->size_bytes ||
        cfg->banks > FS_TEX_CACHE_MAX_BANKS || cfg->ways > FS_TEX_CACHE_MAX_WAYS)
        return NULL;
    unsigned lines = cfg->size_bytes / cfg->line_bytes;
    if (cfg->ways > lines)
        return NULL;
    fs_tex_cache *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    c->cfg = *cfg;
    c->line_shift = log2u(cfg->line_bytes);
    c->sets = lines / cfg->ways;
    c->set_mask = c->sets - 1;
    c->tags = malloc((size_t)lines * sizeof *c->tags);
    c->stamps = calloc(lines, sizeof *c->stamps);
    if (!c->tags || !c->stamps) {
        fs_tex_cache_destroy(c);
        return NULL;
    }
    for (unsigned i = 0; i < lines; i++)
        c->tags[i] = NO_TAG;
    /* Igehy et al. 1998: a miss waits for the memory latency, then for the
     * line to stream in at the memory bandwidth. */
    unsigned transfer = (cfg->line_bytes + cfg->bytes_per_cycle - 1) / cfg->bytes_per_cycle;
    c->miss_cycles = cfg->miss_latency + transfer;
    return c;
}

void fs_tex_cache_destroy(fs_tex_cache *c)
{
    if (!c)
        return;
    free(c->tags);
    free(c->stamps);
    free(c);
}

void fs_tex_cache_flush(fs_tex_cache *c)
{
    unsigned lines = c->sets * c->cfg.ways;
    for (unsigned i = 0; i < lines; i++) {
        c->tags[i] = NO_TAG;
        c->stamps[i] = 0;
    }
}

unsigned fs_tex_cache_miss_cycles(const fs_tex_cache *c) { return c->miss_cycles; }

unsigned fs_tex_cache_bank(const fs_tex_cache *c, uint64_t address)
{
    return (unsigned)(address / FS_TEX_CACHE_WORD_BYTES) & (c->cfg.banks - 1);
}

/* Looks one address up, filling on a miss; returns 1 for a hit. */
static int lookup(fs_tex_cache *c, uint64_t address)
{
    uint64_t line = address >> c->line_shift;
    unsigned set = (unsigned)line & c->set_mask;
    uint64_t *tags = c->tags + (size_t)set * c->cfg.ways;
    uint64_t *stamps = c->stamps + (size_t)set * c->cfg.ways;
    uint64_t now = ++c->clock;
    unsigned victim = 0;
    c->stats.accesses++;
    for (unsigned w = 0; w < c->cfg.ways; w++) {
        if (stamps[w] && tags[w] == line) {
            stamps[w] = now;
            c->stats.hits++;
            return 1;
        }
        /* Empty ways have stamp 0, so they are taken before any used way. */
        if (stamps[w] < stamps[victim])
            victim = w;
    }
    tags[victim] = line;
    stamps[victim] = now;
    c->stats.misses++;
    c->stats.bytes_from_memory += c->cfg.line_bytes;
    return 0;
}

unsigned fs_tex_cache_access(fs_tex_cache *c, uint64_t address, unsigned bank_hint)
{
    (void)bank_hint; /* a lone access has no other access to conflict with */
    return lookup(c, address) ? 0 : c->miss_cycles;
}

unsigned fs_tex_cache_access_group(fs_tex_cache *c, const uint64_t *addresses, unsigned n)
{
    if (n == 0)
        return 0;
    unsigned misses = 0;
    for (unsigned i = 0; i < n; i++)
        misses += !lookup(c, addresses[i]);
    unsigned conflicts = 0;
    if (c->cfg.banks > 1 && n > 1) {
        /* A word read by several accesses of the group is read once and
         * broadcast, so it occupies its bank one cycle; the group takes as
         * many cycles as its busiest bank has distinct words.  Groups are a
         * few dozen texels, so the quadratic search for repeats is cheap. */
        unsigned per_bank[FS_TEX_CACHE_MAX_BANKS] = {0}, most = 0;
        for (unsigned i = 0; i < n; i++) {
            uint64_t word = addresses[i] / FS_TEX_CACHE_WORD_BYTES;
            unsigned j = 0;
            while (j < i && addresses[j] / FS_TEX_CACHE_WORD_BYTES != word)
                j++;
            if (j < i)
                continue;
            unsigned b = (unsigned)word & (c->cfg.banks - 1);
            if (++per_bank[b] > most)
                most = per_bank[b];
        }
        conflicts = most - 1;
        c->stats.bank_conflicts += conflicts;
    }
    unsigned cycles = 1 + conflicts;
    if (misses) {
        /* The group's missing lines are requested together: one latency,
         * then each line's transfer at the memory bandwidth. */
        uint64_t bytes = (uint64_t)misses * c->cfg.line_bytes;
        cycles += c->cfg.miss_latency +
                  (unsigned)((bytes + c->cfg.bytes_per_cycle - 1) / c->cfg.bytes_per_cycle);
    }
    return cycles;
}

void fs_tex_cache_get_stats(const fs_tex_cache *c, fs_tex_cache_stats *out) { *out = c->stats; }
