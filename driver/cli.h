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
/* fragsim rom: Table 4.3 of Huettner 1999 next to fragsim's weighting ROMs (driver/cli_rom.c) */
int fs_cli_rom(int argc, char **argv);
/* fragsim study-filters: texture filter quality/cost study (driver/cli_study_filters.c) */
int fs_cli_study_filters(int argc, char **argv);
/* fragsim mpgrid: the MP-Grid memory example of Huettner 1999, 4.1.2 (driver/cli_mpgrid.c) */
int fs_cli_mpgrid(int argc, char **argv);
#endif
