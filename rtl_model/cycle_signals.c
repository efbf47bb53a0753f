/*
 * The signal writer (cycle_signals.h): the table, the ordering of the
 * model's value changes in simulated time, and their one output path to a
 * Value Change Dump (IEEE 1364-2005, clause 18: header, $dumpvars, then
 * "#time" and value changes in increasing time) and to a line driver.
 */
#include <fnmatch.h>
#include <stdlib.h>
#include <string.h>
#include "cycle_signals.h"

const fs_signal_info fs_signal_table[FS_SIG_COUNT] = {
#define FS_SIGNAL(name, kind, width, unit, meaning) {#name, FS_SIGK_##kind, width, unit, meaning},
#include "signals.def"
#undef FS_SIGNAL
#define FS_CUNIT(name, meaning)                                                                          \
    {#name "_busy", FS_SIGK_BITS, 0, "instances", "per instance of the " meaning ": working (UNIT_busy)"}, \
    {#name "_stalled", FS_SIGK_BITS, 0, "instances",                                                      \
     "per instance of the " meaning ": holding finished work, the next FIFO full or memory busy (UNIT_stalled)"}, \
    {#name "_fifo", FS_SIGK_MAX, 16, "entries",                                                           \
     "entries that reached the FIFO feeding the " meaning " and did not start yet, most over its instances"},
#include "cycle_stats.def"
#undef FS_CUNIT
};

static const char *const kind_names[] = {"pulse", "value", "count", "bits", "max"};

void fs_signals_list(FILE *f, bool md)
{
    if (md)
        fprintf(f, "| signal | kind | width | unit | meaning |\n| --- | --- | --- | --- | --- |\n");
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        const fs_signal_info *s = &fs_signal_table[i];
        char width[16];
        snprintf(width, sizeof width, s->width ? "%d" : "instances", s->width);
        if (md)
            fprintf(f, "| `%s` | %s | %s | %s | %s |\n", s->name, kind_names[s->kind], width, s->unit, s->meaning);
        else
            fprintf(f, "%-24s %-6s %-9s %-9s %s\n", s->name, kind_names[s->kind], width, s->unit, s->meaning);
    }
}

int fs_signal_find(const char *name)
{
    for (int i = 0; i < FS_SIG_COUNT; i++)
        if (!strcmp(fs_signal_table[i].name, name))
            return i;
    return -1;
}

int fs_signals_select(const char *list, bool sel[FS_SIG_COUNT], char *err, size_t errlen)
{
    memset(sel, 0, FS_SIG_COUNT * sizeof *sel);
    const char *p = list;
    do {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        char pat[128];
        if (len == 0 || len >= sizeof pat) {
            snprintf(err, errlen, "signal list '%s': empty or too long name", list);
            return -1;
        }
        memcpy(pat, p, len);
        pat[len] = '\0';
        bool any = false;
        for (int i = 0; i < FS_SIG_COUNT; i++)
            if (!strcmp(pat, "all") || fnmatch(pat, fs_signal_table[i].name, 0) == 0)
                any = sel[i] = true;
        if (!any) {
            snprintf(err, errlen, "unknown signal '%s' (see `fragsim signals --list`)", pat);
            return -1;
        }
        p = e ? e + 1 : NULL;
    } while (p);
    return 0;
}

/* ---- the writer ---- */

typedef struct sig_event {
    uint64_t t;
    int64_t v;
    uint16_t sig, inst;
} sig_event;

typedef struct sig_state {
    int n;             /* instances (BITS, MAX); 1 otherwise */
    int width;         /* bits in the VCD */
    int64_t value;     /* PULSE, VALUE, COUNT */
    int64_t *count;    /* per instance (BITS, MAX) */
    char *last;        /* the value last written, as VCD bits */
    bool dirty;
} sig_state;

struct fs_signals {
    bool sel[FS_SIG_COUNT];
    long first, last;
    FILE *vcd;
    fs_signal_drive_fn drive;
    void *drive_user;
    char comment[512];
    sig_state s[FS_SIG_COUNT];
    sig_event *ev, *tmp;
    size_t n, cap;
    uint64_t (*horizon)(const void *model);
    const void *model;
    uint64_t written_to;    /* every change before it is written */
    uint64_t time;          /* the last "#time" written */
    bool time_written;
    bool pulse_pending;     /* pulses set at pulse_t, to clear at pulse_t + 1 */
    uint64_t pulse_t;
    uint64_t frame, frame_t, end_t; /* end_t: the last frame's end */
    bool frame_due, on, started, ended;
    int dirty[FS_SIG_COUNT], ndirty;
    char *text;             /* a value being formatted */
    uint64_t changes, late;
    int failed;
};

fs_signals *fs_signals_create(const bool *selected, long first, long last, FILE *vcd, fs_signal_drive_fn drive,
                              void *drive_user, const char *comment)
{
    fs_signals *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        w->sel[i] = !selected || selected[i];
        w->s[i].n = 1;
        w->s[i].width = fs_signal_table[i].width ? fs_signal_table[i].width : 1;
    }
    w->first = first;
    w->last = last;
    w->vcd = vcd;
    w->drive = drive;
    w->drive_user = drive_user;
    snprintf(w->comment, sizeof w->comment, "%s", comment ? comment : "");
    return w;
}

void fs_signals_set_instances(fs_signals *w, int sig, int n)
{
    w->s[sig].n = n > 0 ? n : 1;
    if (!fs_signal_table[sig].width)
        w->s[sig].width = w->s[sig].n;
}

void fs_signals_set_horizon(fs_signals *w, uint64_t (*fn)(const void *model), const void *model)
{
    w->horizon = fn;
    w->model = model;
}

uint64_t fs_signals_changes(const fs_signals *w) { return w->changes; }
uint64_t fs_signals_late(const fs_signals *w) { return w->late; }

/* The VCD identifier of signal i: printable ASCII '!'..'~', base 94. */
static void vcd_id(int i, char out[4])
{
    int k = 0;
    do {
        out[k++] = (char)('!' + i % 94);
        i /= 94;
    } while (i && k < 3);
    out[k] = '\0';
}

/* Signal i's current value as VCD bits, most significant first, into w->text. */
static const char *value_text(fs_signals *w, int i)
{
    sig_state *s = &w->s[i];
    fs_signal_kind k = fs_signal_table[i].kind;
    char *t = w->text;
    if (k == FS_SIGK_BITS) {
        for (int b = 0; b < s->n; b++)
            t[s->n - 1 - b] = s->count[b] > 0 ? '1' : '0';
        t[s->n] = '\0';
        return t;
    }
    int64_t v = s->value;
    if (k == FS_SIGK_MAX)
        for (int b = 0; b < s->n; b++)
            if (s->count[b] > v || b == 0)
                v = s->count[b];
    uint64_t u = v > 0 ? (uint64_t)v : 0;
    for (int b = 0; b < s->width; b++)
        t[s->width - 1 - b] = b < 64 && (u >> b) & 1 ? '1' : '0';
    t[s->width] = '\0';
    return t;
}

static void vcd_value(fs_signals *w, int i, const char *bits)
{
    char id[4];
    vcd_id(i, id);
    if (w->s[i].width == 1)
        fprintf(w->vcd, "%s%s\n", bits, id);
    else
        fprintf(w->vcd, "b%s %s\n", bits, id);
}

/* The header and the values at the first dumped cycle t. */
static void start_dump(fs_signals *w, uint64_t t)
{
    w->started = true;
    w->time = t;
    w->time_written = true;
    if (w->vcd) {
        fprintf(w->vcd, "$comment\n  %s\n$end\n$version\n  fragsim\n$end\n", w->comment);
        /* A time unit is one cycle of the model's clock: the
         * configurations give no clock frequency, and 1 ns is the unit
         * GTKWave shows without scaling. */
        fprintf(w->vcd, "$timescale 1 ns $end\n$scope module fragsim $end\n");
        for (int i = 0; i < FS_SIG_COUNT; i++) {
            char id[4];
            vcd_id(i, id);
            if (w->sel[i])
                fprintf(w->vcd, "$var wire %d %s %s $end\n", w->s[i].width, id, fs_signal_table[i].name);
        }
        fprintf(w->vcd, "$upscope $end\n$enddefinitions $end\n#%llu\n$dumpvars\n", (unsigned long long)t);
    }
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        if (!w->sel[i])
            continue;
        const char *v = value_text(w, i);
        memcpy(w->s[i].last, v, (size_t)w->s[i].width + 1);
        if (w->vcd)
            vcd_value(w, i, v);
        if (w->drive)
            w->drive(w->drive_user, i, strchr(v, '1') != NULL);
    }
    if (w->vcd)
        fprintf(w->vcd, "$end\n");
}

static void mark(fs_signals *w, int i)
{
    if (!w->s[i].dirty) {
        w->s[i].dirty = true;
        w->dirty[w->ndirty++] = i;
    }
}

/* Writes the changed signals' new values at time t. */
static void output_dirty(fs_signals *w, uint64_t t)
{
    for (int k = 0; k < w->ndirty; k++) {
        int i = w->dirty[k];
        w->s[i].dirty = false;
        const char *v = value_text(w, i);
        if (!strcmp(v, w->s[i].last))
            continue;
        memcpy(w->s[i].last, v, (size_t)w->s[i].width + 1);
        if (w->vcd && (!w->time_written || w->time != t)) {
            fprintf(w->vcd, "#%llu\n", (unsigned long long)t);
            w->time = t;
            w->time_written = true;
        }
        if (w->vcd)
            vcd_value(w, i, v);
        if (w->drive)
            w->drive(w->drive_user, i, strchr(v, '1') != NULL);
        w->changes++;
    }
    w->ndirty = 0;
}

/* Pulses end one cycle after they were set: at T, or on their own before. */
static void settle_pulses(fs_signals *w, uint64_t T)
{
    if (!w->pulse_pending || w->pulse_t + 1 > T)
        return;
    for (int i = 0; i < FS_SIG_COUNT; i++)
        if (fs_signal_table[i].kind == FS_SIGK_PULSE && w->s[i].value) {
            w->s[i].value = 0;
            mark(w, i);
        }
    w->pulse_pending = false;
    if (w->pulse_t + 1 < T)
        output_dirty(w, w->pulse_t + 1);
}

static void apply(fs_signals *w, const sig_event *e)
{
    sig_state *s = &w->s[e->sig];
    switch (fs_signal_table[e->sig].kind) {
    case FS_SIGK_PULSE:
        s->value = 1;
        w->pulse_pending = true;
        w->pulse_t = e->t;
        break;
    case FS_SIGK_VALUE: s->value = e->v; break;
    case FS_SIGK_COUNT: s->value += e->v; break;
    default: s->count[e->inst < s->n ? e->inst : 0] += e->v; break;
    }
    mark(w, e->sig);
}

/* Stable merge sort of the events by time (equal times keep the order they
 * were reported in, which is each stage's own order). */
static void sort_events(sig_event *a, sig_event *tmp, size_t n)
{
    for (size_t width = 1; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            size_t mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
            size_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                tmp[k++] = a[j].t < a[i].t ? a[j++] : a[i++];
            while (i < mid)
                tmp[k++] = a[i++];
            while (j < hi)
                tmp[k++] = a[j++];
        }
        memcpy(a, tmp, n * sizeof *a);
    }
}

/* Writes the events before time h, in time order. */
static void emit_until(fs_signals *w, uint64_t h)
{
    sort_events(w->ev, w->tmp, w->n);
    size_t i = 0;
    while (i < w->n && w->ev[i].t < h) {
        uint64_t T = w->ev[i].t;
        settle_pulses(w, T);
        for (; i < w->n && w->ev[i].t == T; i++)
            apply(w, &w->ev[i]);
        output_dirty(w, T);
    }
    memmove(w->ev, w->ev + i, (w->n - i) * sizeof *w->ev);
    w->n -= i;
    if (h > w->written_to)
        w->written_to = h;
}

static int grow(fs_signals *w)
{
    size_t cap = w->cap ? w->cap * 2 : 4096;
    sig_event *a = realloc(w->ev, cap * sizeof *a);
    if (!a)
        return -1;
    w->ev = a;
    sig_event *b = realloc(w->tmp, cap * sizeof *b);
    if (!b)
        return -1;
    w->tmp = b;
    w->cap = cap;
    return 0;
}

static void queue(fs_signals *w, uint64_t t, int sig, int inst, int64_t v)
{
    if (t < w->written_to) {
        w->late++;
        t = w->written_to;
    }
    if (w->n == w->cap) {
        if (w->horizon && w->n)
            emit_until(w, w->horizon(w->model));
        if (w->n + w->n / 4 >= w->cap && grow(w) != 0) {
            w->failed = 1;
            return;
        }
    }
    w->ev[w->n++] = (sig_event){t, v, (uint16_t)sig, (uint16_t)inst};
}

/* The per-instance counts and written values, now that the instance
 * counts are known, and a buffer for the widest value. */
static int alloc_states(fs_signals *w)
{
    int widest = 1;
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        sig_state *s = &w->s[i];
        s->last = calloc((size_t)s->width + 1, 1);
        s->count = calloc((size_t)s->n, sizeof *s->count);
        if (!s->last || !s->count)
            return -1;
        if (s->width > widest)
            widest = s->width;
    }
    w->text = malloc((size_t)widest + 1);
    return w->text ? 0 : -1;
}

/* The frame's first report (or its end): its pulse, and the dump's start
 * or end at the window's edges (the pipeline is drained here). */
static void open_frame(fs_signals *w)
{
    w->frame_due = false;
    bool in = (long)w->frame >= w->first && (w->last < 0 || (long)w->frame <= w->last);
    if (in && !w->on && !w->ended) {
        if (alloc_states(w) != 0) {
            w->failed = 1;
            w->ended = true;
            return;
        }
        w->s[FS_SIG_frame].value = (int64_t)w->frame;
        start_dump(w, w->frame_t);
        w->written_to = w->frame_t;
        w->on = true;
    }
    if (w->on && w->sel[FS_SIG_frame_start])
        queue(w, w->frame_t, FS_SIG_frame_start, 0, 1);
    if (w->on && w->sel[FS_SIG_frame])
        queue(w, w->frame_t, FS_SIG_frame, 0, (int64_t)w->frame);
}

void fs_signals_put(fs_signals *w, uint64_t t, int sig, int inst, int64_t v)
{
    if (w->frame_due)
        open_frame(w);
    if (!w->on) {
        /* Outside the window only the levels are kept, for the values the
         * dump starts with. */
        if (fs_signal_table[sig].kind == FS_SIGK_VALUE)
            w->s[sig].value = v;
        return;
    }
    if (w->sel[sig])
        queue(w, t, sig, inst, v);
}

void fs_signals_frame_begin(fs_signals *w, uint64_t f, uint64_t t)
{
    w->frame = f;
    w->frame_t = t;
    w->frame_due = true;
}

/* The dump's last time: pulses ended, then t. */
static void end_dump(fs_signals *w, uint64_t t)
{
    emit_until(w, UINT64_MAX);
    settle_pulses(w, UINT64_MAX);
    if (w->pulse_t + 1 > t && w->started)
        t = w->pulse_t + 1;
    if (w->vcd && w->started && (!w->time_written || t > w->time))
        fprintf(w->vcd, "#%llu\n", (unsigned long long)t);
    w->on = false;
    w->ended = true;
}

void fs_signals_frame_end(fs_signals *w, uint64_t t)
{
    w->end_t = t;
    if (w->frame_due)
        open_frame(w);
    if (!w->on)
        return;
    if (w->last >= 0 && (long)w->frame >= w->last)
        end_dump(w, t);
    else
        emit_until(w, t); /* the next frame's first changes can come at t */
}

void fs_signals_drained(fs_signals *w, uint64_t t)
{
    (void)t;
    if (w->on && w->n && w->horizon)
        emit_until(w, w->horizon(w->model));
}

int fs_signals_close(fs_signals *w)
{
    if (!w)
        return 0;
    if (!w->started && !w->ended && !w->failed) {
        /* The window held no frame: an empty dump, valid all the same. */
        w->frame_due = false;
        w->failed |= alloc_states(w) != 0;
        if (!w->failed)
            start_dump(w, 0);
    } else if (w->on) {
        end_dump(w, w->end_t);
    }
    int rc = w->failed || (w->vcd && ferror(w->vcd)) ? -1 : 0;
    for (int i = 0; i < FS_SIG_COUNT; i++) {
        free(w->s[i].count);
        free(w->s[i].last);
    }
    free(w->text);
    free(w->ev);
    free(w->tmp);
    free(w);
    return rc;
}

/* ---- taps of the FIFO engine ---- */

void fs_sig_item(fs_sig_tap *tap, uint64_t start, uint64_t service, uint64_t depart, fs_sig_tap *next)
{
    fs_signals *w = tap->w;
    uint64_t done = start + service;
    if (service) {
        fs_signals_put(w, start, tap->busy, tap->inst, 1);
        fs_signals_put(w, done, tap->busy, tap->inst, -1);
    }
    if (depart > done) {
        fs_signals_put(w, done, tap->stalled, tap->inst, 1);
        fs_signals_put(w, depart, tap->stalled, tap->inst, -1);
    }
    if (next) {
        next->waiting++;
        fs_signals_put(w, depart, next->fifo, next->inst, 1);
    }
}

void fs_sig_take(fs_sig_tap *tap, uint64_t t)
{
    if (!tap->waiting)
        return; /* it came from the host or a clear, through no FIFO */
    tap->waiting--;
    fs_signals_put(tap->w, t, tap->fifo, tap->inst, -1);
}

void fs_sig_memory(fs_sig_tap *tap, uint64_t b0, uint64_t b1, uint64_t bw)
{
    if (b1 <= b0)
        return;
    /* The cycles the transfer touches (a partly used cycle counts). */
    fs_signals_put(tap->w, b0 / bw, tap->busy, tap->inst, 1);
    fs_signals_put(tap->w, (b1 + bw - 1) / bw, tap->busy, tap->inst, -1);
}
