/*
 * GPIO lines (gpio_lines.h) through libgpiod 1.6's context-less line API,
 * behind the operations table so that the tests can put a fake chip there.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gpiod.h>
#include "gpio_lines.h"

#define FS_GPIO_CONSUMER "fragsim"
#define FS_GPIO_MAX_LINES 64

struct fs_gpio {
    const fs_gpio_ops *ops;
    void *chip;
    int n;
    void *line[FS_GPIO_MAX_LINES];
    bool output[FS_GPIO_MAX_LINES];
};

/* ---- libgpiod ---- */

static void *lg_open(const char *name) { return gpiod_chip_open_lookup(name); }
static unsigned lg_lines(void *chip) { return gpiod_chip_num_lines(chip); }

static bool lg_used(void *chip, unsigned offset, const char **consumer)
{
    struct gpiod_line *l = gpiod_chip_get_line(chip, offset);
    if (!l || !gpiod_line_is_used(l))
        return false;
    if (consumer)
        *consumer = gpiod_line_consumer(l);
    return true;
}

static void *lg_request(void *chip, unsigned offset, bool output, const char *consumer)
{
    struct gpiod_line *l = gpiod_chip_get_line(chip, offset);
    if (!l)
        return NULL;
    int rc = output ? gpiod_line_request_output(l, consumer, 0) : gpiod_line_request_input(l, consumer);
    return rc == 0 ? l : NULL;
}

static int lg_set(void *line, int v) { return gpiod_line_set_value(line, v); }
static int lg_get(void *line) { return gpiod_line_get_value(line); }
static void lg_release(void *line) { gpiod_line_release(line); }
static void lg_close(void *chip) { gpiod_chip_close(chip); }

const fs_gpio_ops fs_gpio_libgpiod = {lg_open, lg_lines, lg_used, lg_request, lg_set, lg_get, lg_release, lg_close};

/* ---- release at exit and on signals ----
 * A signal handler can only reach the open sets through a global: this
 * list is the one piece of process state here, set and cleared by
 * fs_gpio_open and fs_gpio_close. */
#define FS_GPIO_MAX_SETS 8
static fs_gpio *volatile open_sets[FS_GPIO_MAX_SETS];
static bool handlers_installed;

static void release(fs_gpio *g)
{
    for (int i = 0; i < g->n; i++)
        if (g->line[i]) {
            if (g->output[i])
                g->ops->line_set(g->line[i], 0);
            g->ops->line_release(g->line[i]);
            g->line[i] = NULL;
        }
}

static void release_all(void)
{
    for (int k = 0; k < FS_GPIO_MAX_SETS; k++) {
        fs_gpio *g = open_sets[k];
        open_sets[k] = NULL;
        if (g)
            release(g);
    }
}

static void on_signal(int sig)
{
    release_all();
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_handlers(void)
{
    if (handlers_installed)
        return;
    handlers_installed = true;
    atexit(release_all);
    /* Only where the program has no handler of its own (the shim runs
     * inside somebody else's program). */
    static const int sigs[] = {SIGINT, SIGTERM};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction old, sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_DFL)
            sigaction(sigs[i], &sa, NULL);
    }
}

/* ---- sets of lines ---- */

/* Checks and requests line i; 0, or -1 with the message. */
static int request_line(fs_gpio *g, const char *chip, unsigned nlines, int i, const unsigned *offsets, char *err,
                        size_t errlen)
{
    unsigned off = offsets[i];
    if (off >= nlines) {
        snprintf(err, errlen, "GPIO line %u out of range: chip '%s' has lines 0-%u", off, chip,
                 nlines ? nlines - 1 : 0);
        return -1;
    }
    for (int j = 0; j < i; j++)
        if (offsets[j] == off) {
            snprintf(err, errlen, "GPIO line %u of chip '%s' given twice", off, chip);
            return -1;
        }
    const char *by = NULL;
    if (g->ops->line_used(g->chip, off, &by)) {
        snprintf(err, errlen, "GPIO line %u of chip '%s' is in use (by '%s')", off, chip, by ? by : "unknown");
        return -1;
    }
    g->line[i] = g->ops->line_request(g->chip, off, g->output[i], FS_GPIO_CONSUMER);
    if (!g->line[i]) {
        snprintf(err, errlen, "GPIO line %u of chip '%s': %s", off, chip,
                 errno == EBUSY ? "in use" : strerror(errno));
        return -1;
    }
    return 0;
}

fs_gpio *fs_gpio_open(const fs_gpio_ops *ops, const char *chip, int n, const unsigned *offsets, const bool *output,
                      char *err, size_t errlen)
{
    if (n < 0 || n > FS_GPIO_MAX_LINES) {
        snprintf(err, errlen, "at most %d GPIO lines", FS_GPIO_MAX_LINES);
        return NULL;
    }
    int slot = 0;
    while (slot < FS_GPIO_MAX_SETS && open_sets[slot])
        slot++;
    fs_gpio *g = slot < FS_GPIO_MAX_SETS ? calloc(1, sizeof *g) : NULL;
    if (!g) {
        snprintf(err, errlen, "GPIO: out of memory or too many line sets");
        return NULL;
    }
    g->ops = ops;
    g->n = n;
    errno = 0;
    g->chip = ops->chip_open(chip);
    if (!g->chip) {
        snprintf(err, errlen, "no GPIO chip '%s' (%s)", chip, errno ? strerror(errno) : "not found");
        free(g);
        return NULL;
    }
    unsigned nlines = ops->chip_lines(g->chip);
    for (int i = 0; i < n; i++)
        g->output[i] = output[i];
    install_handlers();
    open_sets[slot] = g;
    for (int i = 0; i < n; i++)
        if (request_line(g, chip, nlines, i, offsets, err, errlen) != 0) {
            fs_gpio_close(g);
            return NULL;
        }
    return g;
}

int fs_gpio_set(fs_gpio *g, int i, bool level)
{
    return i >= 0 && i < g->n && g->line[i] ? g->ops->line_set(g->line[i], level) : -1;
}

int fs_gpio_get(fs_gpio *g, int i)
{
    return i >= 0 && i < g->n && g->line[i] ? g->ops->line_get(g->line[i]) : -1;
}

void fs_gpio_close(fs_gpio *g)
{
    if (!g)
        return;
    for (int k = 0; k < FS_GPIO_MAX_SETS; k++)
        if (open_sets[k] == g)
            open_sets[k] = NULL;
    release(g);
    g->ops->chip_close(g->chip);
    free(g);
}
