/*
 * Signals on the command line (docs/signals.md): `fragsim replay --mode
 * cycle --vcd FILE [--vcd-signals LIST] [--vcd-frames A-B]` writes the
 * cycle model's signals as a Value Change Dump, and `--gpio CHIP
 * [--gpio-map SIGNAL=LINE,...]` drives them on GPIO lines while the trace
 * replays, both from one signal writer (rtl_model/cycle_signals.c).  Every
 * mistake in these options is found, with a one-line message and exit
 * status 2, before the trace is opened or anything is written.
 */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "gpio_lines.h"
#include "../rtl_model/cycle_model.h"
#include "../rtl_model/cycle_signals.h"

#define MAX_MAPPED 64

struct fs_cli_signals {
    fs_signals *w;
    FILE *vcd;
    const char *vcd_path;
    fs_gpio *gpio;
    int line_of[FS_SIG_COUNT]; /* index in gpio's lines, -1 */
};

int fs_cli_parse_frames(const char *s, long *a, long *b)
{
    char *end;
    *a = 0;
    *b = -1;
    if (*s == '-') {
        *b = strtol(s + 1, &end, 10);
        return *end || *b < 0 ? -1 : 0;
    }
    *a = strtol(s, &end, 10);
    if (end == s || *a < 0)
        return -1;
    if (*end == '\0') {
        *b = *a;
        return 0;
    }
    if (*end != '-')
        return -1;
    if (end[1] == '\0')
        return 0;
    const char *t = end + 1;
    *b = strtol(t, &end, 10);
    return *end || *b < *a ? -1 : 0;
}


int fs_cli_signals_option(fs_cli_signal_opts *so, const char *a, const char *v)
{
    static const struct { const char *name; size_t off; } opts[] = {
        {"--vcd", offsetof(fs_cli_signal_opts, vcd)},
        {"--vcd-signals", offsetof(fs_cli_signal_opts, vcd_signals)},
        {"--vcd-frames", offsetof(fs_cli_signal_opts, vcd_frames)},
        {"--gpio", offsetof(fs_cli_signal_opts, gpio)},
        {"--gpio-map", offsetof(fs_cli_signal_opts, gpio_map)},
    };
    for (size_t i = 0; i < sizeof opts / sizeof opts[0]; i++) {
        if (strcmp(a, opts[i].name))
            continue;
        const char **field = (const char **)(void *)((char *)so + opts[i].off);
        if (!v) {
            fprintf(stderr, "fragsim: %s needs a value\n", a);
            return -1;
        }
        if (*field) {
            fprintf(stderr, "fragsim: %s given twice ('%s', '%s')\n", a, *field, v);
            return -1;
        }
        *field = v;
        return 1;
    }
    return 0;
}

void fs_cli_signals_usage(FILE *f)
{
    fprintf(f, "  --vcd FILE         with --mode cycle: the model's signals as a Value Change Dump\n"
               "                     (IEEE 1364, one time unit per cycle; GTKWave reads it)\n"
               "  --vcd-signals LIST signals to write, names or patterns (raster_*), comma-separated;\n"
               "                     default all (`fragsim signals --list`, docs/signals.md)\n"
               "  --vcd-frames A-B   only frames A to B (as --frames)\n"
               "  --gpio CHIP        with --mode cycle: drive signals on GPIO lines of CHIP (libgpiod:\n"
               "                     name, number or /dev path) while replaying\n"
               "  --gpio-map S=L,... signal S on line L (default frame_start=0,query_done=1)\n");
}

/* SIGNAL=LINE,...: the signals and offsets; -1 with the message. */
static int parse_map(const char *map, int *sig, unsigned *line, int *n, char *err, size_t errlen)
{
    *n = 0;
    for (const char *p = map; p && *p;) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        char item[160];
        snprintf(item, sizeof item, "%.*s", (int)(len < sizeof item ? len : sizeof item - 1), p);
        char *eq = strchr(item, '='), *end;
        unsigned long off = eq ? strtoul(eq + 1, &end, 10) : 0;
        if (!eq || eq == item || !eq[1] || *end || off > 65535) {
            snprintf(err, errlen, "--gpio-map '%s': expected SIGNAL=LINE, LINE a number", item);
            return -1;
        }
        *eq = '\0';
        int s = fs_signal_find(item);
        if (s < 0) {
            snprintf(err, errlen, "--gpio-map: unknown signal '%s' (see `fragsim signals --list`)", item);
            return -1;
        }
        for (int j = 0; j < *n; j++)
            if (sig[j] == s || line[j] == off) {
                snprintf(err, errlen, "--gpio-map: %s %s mapped twice", sig[j] == s ? "signal" : "line",
                         sig[j] == s ? item : eq + 1);
                return -1;
            }
        if (*n == MAX_MAPPED) {
            snprintf(err, errlen, "--gpio-map: at most %d lines", MAX_MAPPED);
            return -1;
        }
        sig[*n] = s;
        line[(*n)++] = (unsigned)off;
        p = e ? e + 1 : NULL;
    }
    return 0;
}

static void drive(void *user, int sig, bool level)
{
    fs_cli_signals *s = user;
    if (s->line_of[sig] >= 0)
        fs_gpio_set(s->gpio, s->line_of[sig], level);
}

/* The options' own consistency: -1 with the message. */
static int check_opts(const fs_cli_signal_opts *so, int mode, char *err, size_t errlen)
{
    if ((so->vcd_signals || so->vcd_frames) && !so->vcd && !so->gpio) {
        snprintf(err, errlen, "%s needs --vcd or --gpio", so->vcd_signals ? "--vcd-signals" : "--vcd-frames");
        return -1;
    }
    if (so->gpio_map && !so->gpio) {
        snprintf(err, errlen, "--gpio-map needs --gpio");
        return -1;
    }
    if (mode != FS_CYCLE_FULL) {
        /* sampled mode estimates work it does not time: no cycles to show */
        snprintf(err, errlen, "%s needs --mode cycle", so->vcd ? "--vcd" : "--gpio");
        return -1;
    }
    return 0;
}

/* Without --vcd-signals: every signal in the VCD, only the mapped ones for
 * the lines alone; the mapped ones always. */
static void complete_selection(const fs_cli_signals *s, const fs_cli_signal_opts *so, bool sel[FS_SIG_COUNT])
{
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        if (!so->vcd_signals)
            sel[i] = so->vcd != NULL;
        sel[i] |= s->line_of[i] >= 0;
    }
}

static fs_cli_signals *open_fail(fs_cli_signals *s, bool *failed)
{
    *failed = true;
    fs_gpio_close(s->gpio);
    free(s);
    return NULL;
}

fs_cli_signals *fs_cli_signals_open(const fs_cli_signal_opts *so, int mode, const char *trace, const char *config,
                                    bool *failed, char *err, size_t errlen)
{
    *failed = false;
    if (!so->vcd && !so->gpio && !so->vcd_signals && !so->vcd_frames && !so->gpio_map)
        return NULL;
    fs_cli_signals *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        *failed = true;
        return NULL;
    }
    bool sel[FS_SIG_COUNT];
    long first = 0, last = -1;
    int sig[MAX_MAPPED], n = 0;
    unsigned line[MAX_MAPPED];
    bool out[MAX_MAPPED];
    if (check_opts(so, mode, err, errlen) != 0 ||
        (so->vcd_signals && fs_signals_select(so->vcd_signals, sel, err, errlen) != 0))
        return open_fail(s, failed);
    if (so->vcd_frames && fs_cli_parse_frames(so->vcd_frames, &first, &last) != 0) {
        snprintf(err, errlen, "--vcd-frames '%s': expected A-B, A, A- or -B with A <= B", so->vcd_frames);
        return open_fail(s, failed);
    }
    if (so->gpio && parse_map(so->gpio_map ? so->gpio_map : "frame_start=0,query_done=1", sig, line, &n, err,
                              errlen) != 0)
        return open_fail(s, failed);
    for (int i = 0; i < FS_SIG_COUNT; i++)
        s->line_of[i] = -1;
    for (int i = 0; i < n; i++) {
        s->line_of[sig[i]] = i;
        out[i] = true;
    }
    if (so->gpio && !(s->gpio = fs_gpio_open(&fs_gpio_libgpiod, so->gpio, n, line, out, err, errlen)))
        return open_fail(s, failed);
    if (so->vcd && !(s->vcd = fopen(so->vcd, "w"))) {
        snprintf(err, errlen, "cannot write %s", so->vcd);
        return open_fail(s, failed);
    }
    s->vcd_path = so->vcd;
    complete_selection(s, so, sel);
    char comment[600];
    snprintf(comment, sizeof comment, "fragsim replay --mode cycle%s%s %s", config ? " --config " : "",
             config ? config : "", trace ? trace : "");
    s->w = fs_signals_create(sel, first, last, s->vcd, s->gpio ? drive : NULL, s, comment);
    if (!s->w) {
        snprintf(err, errlen, "out of memory");
        if (s->vcd)
            fclose(s->vcd);
        return open_fail(s, failed);
    }
    return s;
}

int fs_cli_signals_attach(fs_cli_signals *s, fs_cli_cycle *cycle, char *err, size_t errlen)
{
    if (fs_cycle_signals_attach(fs_cli_cycle_model(cycle), s->w) != 0) {
        snprintf(err, errlen, "signals: out of memory");
        return -1;
    }
    return 0;
}

int fs_cli_signals_close(fs_cli_signals *s, char *err, size_t errlen)
{
    if (!s)
        return 0;
    uint64_t late = fs_signals_late(s->w);
    if (late)
        fprintf(stderr, "fragsim: warning: %llu signal changes out of order (written at the horizon)\n",
                (unsigned long long)late);
    int rc = fs_signals_close(s->w);
    if (s->vcd && fclose(s->vcd) != 0)
        rc = -1;
    if (rc != 0)
        snprintf(err, errlen, "writing %s failed", s->vcd_path ? s->vcd_path : "the signals");
    fs_gpio_close(s->gpio);
    free(s);
    return rc;
}
