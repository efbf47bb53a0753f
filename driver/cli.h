/*
 * Entry points of the fragsim subcommands that live outside cli_main.c
 * (one file each: driver/cli_NAME.c).  Each takes the arguments after the
 * command name (argv[0] is the first of them) and returns the exit status:
 * 0 success, 1 bad input or failure, 2 usage error.  cli_main.c lists them
 * in its command table.
 */
#ifndef FS_CLI_H
#define FS_CLI_H
/* fragsim sweep SPEC.ini: parameter grids run as jobs (driver/cli_sweep.c) */
int fs_cli_sweep(int argc, char **argv);
/* fragsim study-filters: texture filter quality/cost study (driver/cli_study_filters.c) */
int fs_cli_study_filters(int argc, char **argv);
/* fragsim mpgrid: the MP-Grid memory example of Huettner 1999, 4.1.2 (driver/cli_mpgrid.c) */
int fs_cli_mpgrid(int argc, char **argv);
/* fragsim rom: Table 4.3 of Huettner 1999 next to fragsim's weighting ROMs (driver/cli_rom.c) */
int fs_cli_rom(int argc, char **argv);

/* driver/cli_cycle.c: the cycle-level model behind `fragsim replay --mode`. */
#include <stdio.h>
#include "../pipeline/context.h"
#include "../rtl_model/cycle_model.h"
typedef struct fs_cli_cycle fs_cli_cycle;
/* "functional" -> -1, "cycle", "sampled" -> an fs_cycle_mode; returns -1 for
 * an unknown name. */
int fs_cli_cycle_mode(const char *name, int *mode);
fs_cli_cycle *fs_cli_cycle_begin(int mode, const fs_cycle_config *cfg, fs_context *c, const char *csv_path,
                                 uint64_t trace_frames, bool draw_stats, char *err, size_t errlen);
/* Sampled mode: true for a call the replay skips (fs_cycle_frame_skipped, fs_cmd_skippable). */
bool fs_cli_cycle_skip(const fs_cli_cycle *h, const fs_context *c, int cmd);
void fs_cli_cycle_frame(fs_cli_cycle *h, long frame);
/* Sets the "cycle" member of the statistics file's JSON object (jansson);
 * 0, or -1 when out of memory. */
struct json_t;
int fs_cli_cycle_json(fs_cli_cycle *h, struct json_t *into);
/* Finishes the model's work; its totals in *t; returns the error estimate. */
double fs_cli_cycle_totals(fs_cli_cycle *h, fs_cycle_stats *t);
void fs_cli_cycle_summary(fs_cli_cycle *h, FILE *f, double seconds);
void fs_cli_cycle_end(fs_cli_cycle *h);
#endif
