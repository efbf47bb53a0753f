/*
 * Tests of the signal writer (rtl_model/cycle_signals.c) and the GPIO lines
 * (driver/gpio_lines.c).  This machine's kernel has no GPIO chips and
 * cannot load gpio-sim or gpio-mockup, so the lines are tested behind the
 * operations table with a fake chip (8 lines, line 3 held by another
 * consumer) whose state lives in shared memory, so that a child process's
 * release at exit or on SIGTERM can be seen; libgpiod itself is only
 * asked for a chip that does not exist.
 */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include <signal.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>
#include "check.h"
#include "../driver/gpio_lines.h"
#include "../rtl_model/cycle_signals.h"

/* ---- the writer ---- */

/* The VCD text a writer made, from a memory stream. */
typedef struct memvcd {
    char *buf;
    size_t len;
    FILE *f;
} memvcd;

static fs_signals *writer(memvcd *m, const bool *sel, long first, long last)
{
    m->buf = NULL;
    m->f = open_memstream(&m->buf, &m->len);
    return fs_signals_create(sel, first, last, m->f, NULL, NULL, "test");
}

static char *finish(memvcd *m, fs_signals *w)
{
    fs_signals_close(w);
    fclose(m->f);
    return m->buf;
}

/* The times of the "#t" lines after $enddefinitions, in order, until 0. */
static int times(const char *vcd, unsigned long long *t, int max)
{
    int n = 0;
    const char *p = strstr(vcd, "$enddefinitions");
    while (p && (p = strstr(p, "\n#")) && n < max) {
        t[n++] = strtoull(p + 2, NULL, 10);
        p += 2;
    }
    return n;
}

static uint64_t fixed_horizon;
static uint64_t get_horizon(const void *model)
{
    (void)model;
    return fixed_horizon;
}

/* Changes reported out of time order (as the stages report them) come out
 * sorted, each time once, with busy bits and a pulse of one cycle. */
TEST(writer_orders_changes_in_time)
{
    memvcd m;
    bool sel[FS_SIG_COUNT] = {0};
    sel[FS_SIG_fragment_busy] = sel[FS_SIG_draw_start] = true;
    fs_signals *w = writer(&m, sel, 0, -1);
    REQUIRE(w);
    fs_signals_set_instances(w, FS_SIG_fragment_busy, 2);
    fs_signals_frame_begin(w, 0, 0);
    fixed_horizon = 0;
    fs_signals_set_horizon(w, get_horizon, NULL);
    fs_signals_put(w, 50, FS_SIG_fragment_busy, 1, 1);
    fs_signals_put(w, 60, FS_SIG_fragment_busy, 1, -1);
    fs_signals_put(w, 10, FS_SIG_draw_start, 0, 1);
    fs_signals_put(w, 20, FS_SIG_fragment_busy, 0, 1);
    fs_signals_put(w, 55, FS_SIG_fragment_busy, 0, -1);
    fs_signals_drained(w, 0); /* horizon 0: nothing can be written yet */
    fs_signals_frame_end(w, 60);
    fs_signals_frame_begin(w, 1, 60);
    char *v = finish(&m, w);
    unsigned long long t[16];
    int n = times(v, t, 16);
    unsigned long long want[] = {0, 10, 11, 20, 50, 55, 60};
    CHECK_EQ_INT(n, 7);
    for (int i = 0; i < n && i < 7; i++)
        CHECK_EQ_UINT(t[i], want[i]);
    CHECK(strstr(v, "#10\n1#\n#11\n0#\n")); /* draw_start (id #): one cycle high */
    CHECK(strstr(v, "#50\nb11 ")); /* both engines busy */
    CHECK(strstr(v, "#55\nb10 "));
    CHECK(strstr(v, "$var wire 2 "));
    free(v);
}

/* Only frames first..last are dumped; the dump ends at the last one's end. */
TEST(writer_frame_window)
{
    memvcd m;
    fs_signals *w = writer(&m, NULL, 1, 1);
    REQUIRE(w);
    for (uint64_t f = 0; f < 3; f++) {
        fs_signals_frame_begin(w, f, f * 100);
        fs_signals_put(w, f * 100 + 5, FS_SIG_draw_start, 0, 1);
        fs_signals_frame_end(w, f * 100 + 90);
    }
    char *v = finish(&m, w);
    unsigned long long t[16];
    int n = times(v, t, 16);
    unsigned long long want[] = {100, 101, 105, 106, 190}; /* $dumpvars at frame 1's start, its pulse */
    CHECK_EQ_INT(n, 5);
    for (int i = 0; i < n && i < 5; i++)
        CHECK_EQ_UINT(t[i], want[i]);
    CHECK(strstr(v, "01 \"\n")); /* frame = 1 */
    CHECK(!strstr(v, "#205"));
    free(v);
}

TEST(select_names_and_patterns)
{
    bool sel[FS_SIG_COUNT];
    char err[256];
    CHECK_EQ_INT(fs_signals_select("frame_start,raster_*", sel, err, sizeof err), 0);
    CHECK(sel[FS_SIG_frame_start] && sel[FS_SIG_raster_busy] && sel[FS_SIG_raster_stalled] && sel[FS_SIG_raster_fifo]);
    CHECK(!sel[FS_SIG_fragment_busy]);
    CHECK_EQ_INT(fs_signals_select("frame_start,no_such", sel, err, sizeof err), -1);
    CHECK(strstr(err, "unknown signal 'no_such'"));
    CHECK_EQ_INT(fs_signal_find("occlusion_result"), FS_SIG_occlusion_result);
    CHECK_EQ_INT(fs_signal_find("nope"), -1);
}

/* The line driver gets every selected signal's level changes in time order. */
static char drive_log[256];
static void log_drive(void *user, int sig, bool level)
{
    (void)user;
    size_t n = strlen(drive_log);
    snprintf(drive_log + n, sizeof drive_log - n, "%s=%d ", fs_signal_table[sig].name, level);
}

TEST(writer_drives_lines_in_time_order)
{
    bool sel[FS_SIG_COUNT] = {0};
    sel[FS_SIG_frame_start] = sel[FS_SIG_query_done] = true;
    drive_log[0] = '\0';
    fs_signals *w = fs_signals_create(sel, 0, -1, NULL, log_drive, NULL, NULL);
    REQUIRE(w);
    fs_signals_frame_begin(w, 0, 0);
    fs_signals_put(w, 40, FS_SIG_query_done, 0, 1);
    fs_signals_frame_end(w, 50);
    fs_signals_frame_begin(w, 1, 50);
    fs_signals_frame_end(w, 80);
    fs_signals_close(w);
    CHECK_STR(drive_log, "frame_start=0 query_done=0 frame_start=1 frame_start=0 query_done=1 query_done=0 "
                         "frame_start=1 frame_start=0 ");
}

/* ---- GPIO lines through a fake chip ---- */

#define FAKE_LINES 8
typedef struct fake_chip {
    int requested[FAKE_LINES]; /* 1 output, 2 input, 0 free */
    int value[FAKE_LINES];
    int released[FAKE_LINES];
    int closed;
} fake_chip;
static fake_chip *fake; /* in shared memory, seen by a parent after its child ended */

static void *f_open(const char *name) { return strcmp(name, "fake0") ? NULL : fake; }
static unsigned f_lines(void *chip)
{
    (void)chip;
    return FAKE_LINES;
}
static bool f_used(void *chip, unsigned off, const char **by)
{
    (void)chip;
    *by = "other";
    return off == 3;
}
static int lines_ids[FAKE_LINES];
static void *f_request(void *chip, unsigned off, bool output, const char *consumer)
{
    (void)chip;
    if (strcmp(consumer, "fragsim"))
        return NULL;
    fake->requested[off] = output ? 1 : 2;
    fake->value[off] = output ? 0 : fake->value[off];
    lines_ids[off] = (int)off;
    return &lines_ids[off];
}
static int f_set(void *line, int v)
{
    fake->value[*(int *)line] = v;
    return 0;
}
static int f_get(void *line) { return fake->value[*(int *)line]; }
static void f_release(void *line)
{
    fake->requested[*(int *)line] = 0;
    fake->released[*(int *)line]++;
}
static void f_close(void *chip)
{
    (void)chip;
    fake->closed++;
}
static const fs_gpio_ops fake_ops = {f_open, f_lines, f_used, f_request, f_set, f_get, f_release, f_close};

/* The fake chip's state in a file mapped shared, so that a child process
 * (run as this binary again) sees and changes the same state. */
#define FAKE_ENV "FRAGSIM_TEST_FAKE_GPIO"
static char fake_path[64];
static int map_fake(const char *path)
{
    int fd = open(path, O_RDWR);
    if (fd < 0 || ftruncate(fd, sizeof *fake) != 0)
        return -1;
    fake = mmap(NULL, sizeof *fake, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    close(fd);
    return fake == MAP_FAILED ? (fake = NULL, -1) : 0;
}

static void fake_reset_shared(void)
{
    const char *p = getenv(FAKE_ENV);
    if (!p || map_fake(p) != 0)
        exit(13);
}

static void fake_reset(void)
{
    if (!fake) {
        snprintf(fake_path, sizeof fake_path, "/tmp/fragsim_fake_gpio_XXXXXX");
        int fd = mkstemp(fake_path);
        if (fd < 0 || (close(fd), map_fake(fake_path)) != 0)
            abort();
        setenv(FAKE_ENV, fake_path, 1);
    }
    memset(fake, 0, sizeof *fake);
}

TEST(gpio_missing_chip_is_named)
{
    char err[256] = "";
    unsigned off = 0;
    bool out = true;
    CHECK(!fs_gpio_open(&fs_gpio_libgpiod, "fragsim-no-such-chip", 1, &off, &out, err, sizeof err));
    CHECK(strstr(err, "no GPIO chip 'fragsim-no-such-chip'"));
    fake_reset();
    CHECK(!fs_gpio_open(&fake_ops, "fake1", 1, &off, &out, err, sizeof err));
    CHECK(strstr(err, "'fake1'"));
}

TEST(gpio_bad_lines_refused_and_released)
{
    fake_reset();
    char err[256] = "";
    bool out[2] = {true, true};
    unsigned range[2] = {0, 8}, used[2] = {1, 3}, twice[2] = {2, 2};
    CHECK(!fs_gpio_open(&fake_ops, "fake0", 2, range, out, err, sizeof err));
    CHECK(strstr(err, "GPIO line 8 out of range: chip 'fake0' has lines 0-7"));
    CHECK(!fs_gpio_open(&fake_ops, "fake0", 2, used, out, err, sizeof err));
    CHECK(strstr(err, "GPIO line 3 of chip 'fake0' is in use (by 'other')"));
    CHECK(!fs_gpio_open(&fake_ops, "fake0", 2, twice, out, err, sizeof err));
    CHECK(strstr(err, "given twice"));
    /* The lines requested before the bad one were released, the chip closed. */
    CHECK_EQ_INT(fake->requested[0] + fake->requested[1] + fake->requested[2], 0);
    CHECK_EQ_INT(fake->released[0], 1);
    CHECK_EQ_INT(fake->released[1], 1);
    CHECK_EQ_INT(fake->closed, 3);
}

TEST(gpio_drive_read_and_close)
{
    fake_reset();
    char err[256] = "";
    unsigned off[2] = {5, 6};
    bool out[2] = {true, false};
    fs_gpio *g = fs_gpio_open(&fake_ops, "fake0", 2, off, out, err, sizeof err);
    REQUIRE(g);
    CHECK_EQ_INT(fake->requested[5], 1);
    CHECK_EQ_INT(fake->requested[6], 2);
    fs_gpio_set(g, 0, true);
    CHECK_EQ_INT(fake->value[5], 1);
    fake->value[6] = 1;
    CHECK_EQ_INT(fs_gpio_get(g, 1), 1);
    fs_gpio_close(g);
    CHECK_EQ_INT(fake->value[5], 0); /* driven low before the release */
    CHECK_EQ_INT(fake->requested[5] + fake->requested[6], 0);
    CHECK_EQ_INT(fake->closed, 1);
}

/* A child process opens lines, drives one high and ends by `how` (0:
 * exit without closing; else raises that signal): the lines are released
 * (and the output low) once it is gone.  The child is this binary run
 * again (`test_signals --child HOW`): a forked copy of a process with the
 * libraries' threads can hang in their exit handlers. */
static int child_main(int how)
{
    char err[256];
    unsigned off = 4;
    bool out = true;
    fs_gpio *g = fs_gpio_open(&fake_ops, "fake0", 1, &off, &out, err, sizeof err);
    if (!g)
        return 10;
    fs_gpio_set(g, 0, true);
    if (fake->value[4] != 1)
        return 11;
    if (how)
        raise(how);
    exit(3); /* without fs_gpio_close */
}

static int child_ends(int how)
{
    fake_reset();
    char arg[16];
    snprintf(arg, sizeof arg, "%d", how);
    pid_t pid = fork();
    if (pid == 0) {
        execl("/proc/self/exe", "test_signals", "--child", arg, (char *)NULL);
        _exit(12);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return st;
}

TEST(gpio_released_at_exit)
{
    int st = child_ends(0);
    CHECK(WIFEXITED(st) && WEXITSTATUS(st) == 3);
    CHECK_EQ_INT(fake->released[4], 1);
    CHECK_EQ_INT(fake->value[4], 0);
}

TEST(gpio_released_on_sigterm_and_sigint)
{
    int sigs[2] = {SIGTERM, SIGINT};
    for (int i = 0; i < 2; i++) {
        int st = child_ends(sigs[i]);
        CHECK(WIFSIGNALED(st) && WTERMSIG(st) == sigs[i]);
        CHECK_EQ_INT(fake->released[4], 1);
        CHECK_EQ_INT(fake->value[4], 0);
    }
}

TEST_LIST = {
    TEST_ENTRY(writer_orders_changes_in_time),
    TEST_ENTRY(writer_frame_window),
    TEST_ENTRY(select_names_and_patterns),
    TEST_ENTRY(writer_drives_lines_in_time_order),
    TEST_ENTRY(gpio_missing_chip_is_named),
    TEST_ENTRY(gpio_bad_lines_refused_and_released),
    TEST_ENTRY(gpio_drive_read_and_close),
    TEST_ENTRY(gpio_released_at_exit),
    TEST_ENTRY(gpio_released_on_sigterm_and_sigint),
    TEST_END,
};

int main(int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "--child")) {
        fake_reset_shared();
        return child_main(atoi(argv[2]));
    }
    int rc = check_main(argc, argv, test_list);
    if (fake_path[0])
        unlink(fake_path);
    return rc;
}
