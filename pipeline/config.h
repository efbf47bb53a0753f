/* Configuration: see config.def for every key. */
#ifndef FS_CONFIG_H
#define FS_CONFIG_H
#include <stdio.h>

typedef struct fs_config {
#define FS_CONFIG(sec, key, type, def, lo, hi, unit, meaning) long sec##_##key;
#include "config.def"
#undef FS_CONFIG
} fs_config;

void fs_config_defaults(fs_config *cfg);
/* Loads an INI file over cfg.  On error returns -1 and writes one message
 * naming the file and line into err. */
int fs_config_load(fs_config *cfg, const char *path, char *err, size_t errlen);
/* Applies "section.key=value". */
int fs_config_set(fs_config *cfg, const char *assignment, char *err, size_t errlen);
/* Checks constraints between or within keys that ranges cannot express.
 * Returns 0, or -1 with one message naming the key. */
int fs_config_check(const fs_config *cfg, char *err, size_t errlen);
void fs_config_list(FILE *f);
/* Writes every key with its default and meaning as an INI file
 * (configs/default.ini). */
void fs_config_write_defaults_ini(FILE *f);
/* The keys as a new JSON object (jansson) of "section.key": value, in the
 * table's order; NULL when out of memory. */
struct json_t;
struct json_t *fs_config_json(const fs_config *cfg);
#endif
