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
struct fs_replayer;
/* r: the trace's replayer, for its frame count and frame signatures */
fs_cli_cycle *fs_cli_cycle_begin(int mode, const fs_cycle_config *cfg, fs_context *c, const char *csv_path,
                                 const struct fs_replayer *r, bool draw_stats, char *err, size_t errlen);
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
/* The run's model, to attach signals to. */
fs_cycle *fs_cli_cycle_model(fs_cli_cycle *h);
/* sampling.max_error (--max-error): the passes of a run, each with the
 * sampling keys it ran with and the estimate it reported. */
enum { FS_CLI_MAX_PASSES = 32 };
typedef struct fs_cli_passes {
    int n;
    struct { long frames, frame_tiles, tiles, every; double estimate, part[FS_CYCLE_ERR_PARTS]; } p[FS_CLI_MAX_PASSES];
} fs_cli_passes;
/* After a pass that ran with cfg: records it in *passes (which h's JSON
 * and summary report from then on) and returns true with cfg changed to
 * the next, denser pass when the estimate exceeds sampling.max_error and
 * more can be sampled. */
bool fs_cli_cycle_resample(fs_cli_cycle *h, fs_cycle_config *cfg, fs_cli_passes *passes);
/* --max-error P (percent) as a --set assignment into buf; -1 if malformed. */
int fs_cli_max_error_set(const char *percent, char *buf, size_t len);
/* --frames A-B, A, A-, -B (first frame 0; b -1: to the end); -1 if malformed. */
int fs_cli_parse_frames(const char *s, long *a, long *b);

/* driver/cli_signals.c: `fragsim replay --vcd`, `--gpio` (docs/signals.md). */
typedef struct fs_cli_signal_opts {
    const char *vcd, *vcd_signals, *vcd_frames, *gpio, *gpio_map;
} fs_cli_signal_opts;
/* Option a with value v: 0 not a signal option, 1 taken (with its value),
 * -1 a usage error (printed). */
int fs_cli_signals_option(fs_cli_signal_opts *so, const char *a, const char *v);
/* The options' help lines, generated from the signal table. */
void fs_cli_signals_usage(FILE *f);
typedef struct fs_cli_signals fs_cli_signals;
/* Checks the options against the mode, opens the GPIO lines and the VCD
 * file: NULL with *failed false when no option was given; NULL with
 * *failed true and a one-line message in err otherwise (exit status 2,
 * nothing written). */
fs_cli_signals *fs_cli_signals_open(const fs_cli_signal_opts *so, int mode, const char *trace, const char *config,
                                    bool *failed, char *err, size_t errlen);
/* Connects them to the run's model; -1 with a message. */
int fs_cli_signals_attach(fs_cli_signals *s, fs_cli_cycle *cycle, char *err, size_t errlen);
/* Writes what is left, releases the lines; -1 with a message when the
 * VCD could not be written.  s may be NULL. */
int fs_cli_signals_close(fs_cli_signals *s, char *err, size_t errlen);
#endif
