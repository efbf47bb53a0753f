/* The cycle-level model's key table (cycle_config.def) and its checks. */
#include <stdio.h>
#include "cycle_config.h"

static const fs_config_key keys[] = {
#define FS_CONFIG(sec, k, type, def, lo, hi, unit, meaning) \
    FS_CONFIG_KEY(fs_cycle_config, sec, k, type, def, lo, hi, unit, meaning),
#include "cycle_config.def"
#undef FS_CONFIG
};

fs_config_part fs_cycle_config_part(fs_cycle_config *cfg)
{
    return (fs_config_part){keys, sizeof keys / sizeof keys[0], cfg};
}

int fs_cycle_config_check(const fs_cycle_config *cfg, char *err, size_t errlen)
{
    /* A 2x2 quad must stay on one image engine (rasterizer_stage.c). */
    if (cfg->fragment_interleave % 2 != 0) {
        snprintf(err, errlen, "fragment.interleave: %ld is not even", cfg->fragment_interleave);
        return -1;
    }
    /* The texture cache's geometry (texture_cache.h). */
    const struct { const char *name; long v; } pow2[] = {
        {"texture.cache_bytes", cfg->texture_cache_bytes}, {"texture.cache_line_bytes", cfg->texture_cache_line_bytes},
        {"texture.cache_ways", cfg->texture_cache_ways}, {"texture.cache_banks", cfg->texture_cache_banks}};
    for (size_t i = 0; i < sizeof pow2 / sizeof pow2[0]; i++) {
        if (cfg->texture_cache_bytes != 0 && (pow2[i].v & (pow2[i].v - 1)) != 0) {
            snprintf(err, errlen, "%s: %ld is not a power of two", pow2[i].name, pow2[i].v);
            return -1;
        }
    }
    if (cfg->readback_ps_per_byte != 0 && cfg->clock_khz == 0) {
        snprintf(err, errlen, "readback.ps_per_byte: a time per byte needs clock.khz to become cycles");
        return -1;
    }
    if (cfg->texture_cache_bytes != 0 &&
        cfg->texture_cache_line_bytes * cfg->texture_cache_ways > cfg->texture_cache_bytes) {
        snprintf(err, errlen, "texture.cache_ways: %ld ways of %ld-byte lines do not fit in texture.cache_bytes = %ld",
                 cfg->texture_cache_ways, cfg->texture_cache_line_bytes, cfg->texture_cache_bytes);
        return -1;
    }
    return 0;
}
