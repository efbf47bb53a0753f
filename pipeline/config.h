/*
 * Configuration.  The functional pipeline's keys are config.def; the
 * machinery here reads any table of keys in that row format (its INI files
 * through libinih, "section.key=value" overrides, listings, JSON), so that
 * a layer above keeps its own table and one file sets both
 * (driver/run_config.h).
 */
#ifndef FS_CONFIG_H
#define FS_CONFIG_H
#include <stddef.h>
#include <stdio.h>

/* One key of a table: every value is a long in the table's struct. */
typedef struct fs_config_key {
    const char *section, *key, *type, *unit, *meaning;
    long def, lo, hi;
    size_t offset;
} fs_config_key;
/* A table row from a .def row FS_CONFIG(sec, key, type, def, lo, hi, unit,
 * meaning) of the struct strct, whose member is sec_key. */
#define FS_CONFIG_KEY(strct, sec, k, type, def, lo, hi, unit, meaning) \
    {#sec, #k, #type, unit, meaning, def, lo, hi, offsetof(strct, sec##_##k)}

/* A table bound to the struct its offsets point into (values; NULL when
 * only listed). */
typedef struct fs_config_part {
    const fs_config_key *keys;
    size_t nkeys;
    void *values;
} fs_config_part;

void fs_config_part_defaults(const fs_config_part *p);
/* Loads an INI file into the parts (a key goes to the first part that
 * has it).  On error returns -1 and writes one message naming the file and
 * line into err. */
int fs_config_parts_load(const fs_config_part *p, size_t n, const char *path, char *err, size_t errlen);
/* Applies "section.key=value". */
int fs_config_parts_set(const fs_config_part *p, size_t n, const char *assignment, char *err, size_t errlen);
/* `fragsim config --list`: every key of the parts, in order. */
void fs_config_parts_list(const fs_config_part *p, size_t n, FILE *f);
/* Every key with its default and meaning as the sections of an INI file. */
void fs_config_parts_write_ini(const fs_config_part *p, size_t n, FILE *f);
/* The parts' values as a new JSON object (jansson) of "section.key":
 * value, in order; NULL when out of memory. */
struct json_t;
struct json_t *fs_config_parts_json(const fs_config_part *p, size_t n);

/* The functional pipeline's keys (config.def). */
typedef struct fs_config {
#define FS_CONFIG(sec, key, type, def, lo, hi, unit, meaning) long sec##_##key;
#include "config.def"
#undef FS_CONFIG
} fs_config;

void fs_config_defaults(fs_config *cfg);
/* config.def bound to cfg (NULL: for listings only). */
fs_config_part fs_config_part_of(fs_config *cfg);
/* Checks constraints between or within keys that ranges cannot express.
 * Returns 0, or -1 with one message naming the key. */
int fs_config_check(const fs_config *cfg, char *err, size_t errlen);
#endif
