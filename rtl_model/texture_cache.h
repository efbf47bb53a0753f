/*
 * Texture cache model for the cycle-level texture unit, after Hakura and
 * Gupta, "The design and analysis of a cache architecture for texture
 * mapping" (ISCA 1997) and Igehy, Eldridge, Proudfoot, "Prefetching in a
 * texture cache architecture" (Graphics Hardware 1998).
 *
 * Set-associative, LRU, lines interleaved across banks.  A hit costs nothing
 * beyond the texture unit's own pipeline; a miss costs the memory latency
 * plus the line's transfer time at the configured bandwidth; accesses of one
 * group that fall into the same bank serialise (one extra cycle each).
 */
#ifndef FS_TEXTURE_CACHE_H
#define FS_TEXTURE_CACHE_H
#include <stdint.h>

typedef struct fs_tex_cache_config {
    unsigned size_bytes;      /* total capacity */
    unsigned line_bytes;      /* bytes per line */
    unsigned ways;            /* associativity; ways == lines is fully associative */
    unsigned banks;           /* texel-address interleaving; 1 = no banking */
    unsigned miss_latency;    /* cycles from request to first byte */
    unsigned bytes_per_cycle; /* memory bandwidth */
} fs_tex_cache_config;

typedef struct fs_tex_cache fs_tex_cache;

/* NULL on a bad config: size, line, ways or banks zero or not a power of
 * two, bytes_per_cycle zero (any other value is fine, latency may be 0),
 * line larger than the cache, ways more than lines
 * or than FS_TEX_CACHE_MAX_WAYS, banks more than FS_TEX_CACHE_MAX_BANKS, or a
 * cache larger than FS_TEX_CACHE_MAX_BYTES. */
#define FS_TEX_CACHE_MAX_BYTES (64u << 20)
#define FS_TEX_CACHE_MAX_WAYS 4096u
#define FS_TEX_CACHE_MAX_BANKS 64u
/* Banks interleave 4-byte texel words: bank = (address / 4) mod banks, so
 * neighbouring texels of a row go to different banks (the
 * texel interleaving of Igehy et al. 1998).  With row-major texels a 2x2
 * bilinear quad meets itself in a bank when the row pitch is a multiple of
 * banks words; a caller that stores textures in 2x2 blocks makes each quad
 * four consecutive words, conflict-free with 4 banks. */
#define FS_TEX_CACHE_WORD_BYTES 4u
fs_tex_cache *fs_tex_cache_create(const fs_tex_cache_config *cfg);
void fs_tex_cache_destroy(fs_tex_cache *c);

/* One texel access: returns the extra cycles it costs beyond a hit (0 for a
 * hit, fs_tex_cache_miss_cycles for a miss).  bank_hint unused if banks==1;
 * a lone access never conflicts, so it is unused otherwise too (kept for
 * callers that model a busy bank). */
unsigned fs_tex_cache_access(fs_tex_cache *c, uint64_t address, unsigned bank_hint);

/* Accesses of one texel group (e.g. the 8 texels of a trilinear sample or
 * the M texels of a footprint) issued in the same cycle: returns cycles the
 * group takes (bank conflicts serialise).  Cycles = 1 + conflicts + (if any
 * access missed) miss_latency + ceil(misses * line_bytes / bytes_per_cycle).
 * conflicts = (most distinct texel words in one bank) - 1: a word read by
 * several accesses of the group is read once and broadcast.  Accesses are
 * looked up in order, so a line missed by one is a hit for the next.
 * n == 0 takes 0 cycles. */
unsigned fs_tex_cache_access_group(fs_tex_cache *c, const uint64_t *addresses, unsigned n);

typedef struct fs_tex_cache_stats {
    uint64_t accesses, hits, misses, bank_conflicts, bytes_from_memory;
} fs_tex_cache_stats;
void fs_tex_cache_get_stats(const fs_tex_cache *c, fs_tex_cache_stats *out);
/* Invalidates every line (texture image changed); statistics are kept. */
void fs_tex_cache_flush(fs_tex_cache *c);

/* Bank of an address (see FS_TEX_CACHE_WORD_BYTES). */
unsigned fs_tex_cache_bank(const fs_tex_cache *c, uint64_t address);
/* Extra cycles of one miss: latency + line_bytes / bytes_per_cycle (rounded up). */
unsigned fs_tex_cache_miss_cycles(const fs_tex_cache *c);
#endif
