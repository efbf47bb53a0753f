/*
 * What one run is configured with: the functional pipeline's keys
 * (pipeline/config.def) and the cycle-level model's (rtl_model/
 * cycle_config.def), set together from one INI file (--config,
 * FRAGSIM_CONFIG) and "section.key=value" overrides (--set, sweep axes),
 * listed together, in that order, by `fragsim config --list|--defaults`
 * and in the statistics file.  A key unknown to both tables is an error.
 */
#ifndef FS_RUN_CONFIG_H
#define FS_RUN_CONFIG_H
#include <stdio.h>
#include "../pipeline/config.h"
#include "../rtl_model/cycle_config.h"

typedef struct fs_run_config {
    fs_config gl;           /* the context's (fs_context_create) */
    fs_cycle_config cycle;  /* the cycle model's (fs_cycle_create) */
} fs_run_config;

void fs_run_config_defaults(fs_run_config *cfg);
/* Loads an INI file over cfg.  On error returns -1 and writes one message
 * naming the file and line into err. */
int fs_run_config_load(fs_run_config *cfg, const char *path, char *err, size_t errlen);
/* Applies "section.key=value". */
int fs_run_config_set(fs_run_config *cfg, const char *assignment, char *err, size_t errlen);
/* Checks the constraints ranges cannot express: the pipeline's, then the
 * cycle model's.  Returns 0, or -1 with one message naming the key. */
int fs_run_config_check(const fs_run_config *cfg, char *err, size_t errlen);
void fs_run_config_list(FILE *f);
/* Writes every key with its default and meaning as an INI file
 * (configs/default.ini). */
void fs_run_config_write_defaults_ini(FILE *f);
/* The keys as a new JSON object (jansson) of "section.key": value, in the
 * tables' order; NULL when out of memory. */
struct json_t;
struct json_t *fs_run_config_json(const fs_run_config *cfg);
#endif
