/*
 * Signals of the cycle-level model (signals.def, docs/signals.md): the
 * writer that orders the model's value changes in simulated time and hands
 * them to a Value Change Dump (IEEE 1364-2005, clause 18) and to a line
 * driver (driver/gpio_lines.c), in that one path.
 *
 * The model evaluates work item by item, not cycle by cycle, so its
 * stages report changes out of time order (the front end runs ahead of the
 * fragment stage).  The writer keeps them until no stage can report an
 * earlier one (the horizon: every stage's next item starts at or after the
 * later of its last departure and the host's command time), sorts them and
 * writes those before the horizon.  At a frame's end the pipeline is
 * drained and everything is written.
 */
#ifndef FS_CYCLE_SIGNALS_H
#define FS_CYCLE_SIGNALS_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef enum fs_signal_kind { FS_SIGK_PULSE, FS_SIGK_VALUE, FS_SIGK_COUNT, FS_SIGK_BITS, FS_SIGK_MAX } fs_signal_kind;

enum {
#define FS_SIGNAL(name, kind, width, unit, meaning) FS_SIG_##name,
#include "signals.def"
#undef FS_SIGNAL
#define FS_CUNIT(name, meaning) FS_SIG_##name##_busy, FS_SIG_##name##_stalled, FS_SIG_##name##_fifo,
#include "cycle_stats.def"
#undef FS_CUNIT
    FS_SIG_COUNT
};

typedef struct fs_signal_info {
    const char *name;
    fs_signal_kind kind;
    int width;            /* 0: one bit per instance */
    const char *unit, *meaning;
} fs_signal_info;
extern const fs_signal_info fs_signal_table[FS_SIG_COUNT];
/* The table as text: name, kind, width, unit, meaning; markdown when md. */
void fs_signals_list(FILE *f, bool md);
/* The signal of that name, or -1. */
int fs_signal_find(const char *name);
/* Selects the signals a comma-separated LIST names (names or shell
 * patterns, e.g. raster_*; "all").  -1 with a message on a name that
 * matches none. */
int fs_signals_select(const char *list, bool sel[FS_SIG_COUNT], char *err, size_t errlen);

/* A line driver: called with a selected signal's new level (any bit set)
 * when it changes, in simulated-time order, while the run goes on. */
typedef void (*fs_signal_drive_fn)(void *user, int sig, bool level);

typedef struct fs_signals fs_signals;
/* A writer of the selected signals (NULL: all) of frames [first, last]
 * (last < 0: to the end), to vcd (NULL: none; the writer does not close
 * it) and to drive (NULL: none).  `comment` goes into the VCD header. */
fs_signals *fs_signals_create(const bool *selected, long first, long last, FILE *vcd, fs_signal_drive_fn drive,
                              void *drive_user, const char *comment);
/* Writes what is left, the VCD's last time; 0, or -1 when a write failed.
 * Then frees it. */
int fs_signals_close(fs_signals *w);
/* Counts: value changes written, and changes reported before the horizon
 * (a bug of the model's ordering if not 0; they are written at the
 * horizon instead). */
uint64_t fs_signals_changes(const fs_signals *w);
uint64_t fs_signals_late(const fs_signals *w);

/* ---- for the model (rtl_model/) ---- */
/* Instances of a BITS or MAX signal (before the first frame). */
void fs_signals_set_instances(fs_signals *w, int sig, int n);
/* The earliest time the model can still report a change at (NULL: only
 * frame ends and drains flush). */
void fs_signals_set_horizon(fs_signals *w, uint64_t (*fn)(const void *model), const void *model);
/* One change: a PULSE at t; a VALUE set to v; a COUNT or an instance of a
 * BITS or MAX signal changed by v. */
void fs_signals_put(fs_signals *w, uint64_t t, int sig, int inst, int64_t v);
/* Frame f begins at cycle t (its frame_start pulse, once it has work or
 * ends); frame f ended at cycle t, drained. */
void fs_signals_frame_begin(fs_signals *w, uint64_t f, uint64_t t);
void fs_signals_frame_end(fs_signals *w, uint64_t t);
/* Writes the changes before the horizon now (the pipeline drained at t). */
void fs_signals_drained(fs_signals *w, uint64_t t);

/* A stage's or FIFO's signals: its busy and stalled BITS signals and the
 * MAX signal of the FIFO in front of it, its instance, and the items that
 * entered the FIFO but did not start yet (cycle_fifo.h). */
typedef struct fs_sig_tap {
    fs_signals *w;
    int busy, stalled, fifo, inst;
    uint64_t waiting;
} fs_sig_tap;
/* An item started at `start`, worked `service` cycles and left at `depart`
 * (stalled in between); `next` (may be NULL) is the tap of the FIFO it
 * entered at `depart`. */
void fs_sig_item(fs_sig_tap *tap, uint64_t start, uint64_t service, uint64_t depart, fs_sig_tap *next);
/* The stage took the item from its FIFO at t. */
void fs_sig_take(fs_sig_tap *tap, uint64_t t);
/* A memory transfer occupied byte-times [b0, b1) of a memory of bw bytes
 * per cycle (memory.c). */
void fs_sig_memory(fs_sig_tap *tap, uint64_t b0, uint64_t b1, uint64_t bw);
#endif
