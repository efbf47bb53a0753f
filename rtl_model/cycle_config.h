/*
 * The cycle-level model's configuration: the keys of cycle_config.def in
 * a struct of their own, read through pipeline/config.h's key tables (one
 * INI file sets these and the functional pipeline's keys together,
 * driver/run_config.h).
 */
#ifndef FS_CYCLE_CONFIG_H
#define FS_CYCLE_CONFIG_H
#include <stddef.h>
#include "../pipeline/config.h"

typedef struct fs_cycle_config {
#define FS_CONFIG(sec, key, type, def, lo, hi, unit, meaning) long sec##_##key;
#include "cycle_config.def"
#undef FS_CONFIG
} fs_cycle_config;

/* The key table bound to cfg (NULL: for listings only); its defaults with
 * fs_config_part_defaults. */
fs_config_part fs_cycle_config_part(fs_cycle_config *cfg);
/* Constraints a key's range cannot express (the texture cache's geometry,
 * the framebuffer interleave).  Returns 0, or -1 with one message naming
 * the key. */
int fs_cycle_config_check(const fs_cycle_config *cfg, char *err, size_t errlen);
#endif
