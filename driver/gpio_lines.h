/*
 * GPIO lines for the cycle model's signals (docs/signals.md): a set of
 * lines of one chip, requested with the consumer name "fragsim", driven or
 * read, and released on close, at exit and on SIGINT/SIGTERM.  The chip is
 * reached through a small table of operations: libgpiod 1.6 in use
 * (fs_gpio_libgpiod), a fake chip in the tests (this machine has no GPIO
 * chips and cannot load gpio-sim or gpio-mockup).
 */
#ifndef FS_GPIO_LINES_H
#define FS_GPIO_LINES_H
#include <stdbool.h>
#include <stddef.h>

typedef struct fs_gpio_ops {
    /* A chip by name, number or path; NULL (errno set) when there is none. */
    void *(*chip_open)(const char *name);
    unsigned (*chip_lines)(void *chip);
    /* Whether the line is requested already, and by whom (may be NULL). */
    bool (*line_used)(void *chip, unsigned offset, const char **consumer);
    /* Requests a line as an output (driven low) or an input; NULL, errno set. */
    void *(*line_request)(void *chip, unsigned offset, bool output, const char *consumer);
    int (*line_set)(void *line, int value);
    int (*line_get)(void *line);
    void (*line_release)(void *line);
    void (*chip_close)(void *chip);
} fs_gpio_ops;
extern const fs_gpio_ops fs_gpio_libgpiod;

typedef struct fs_gpio fs_gpio;
/* Requests lines offsets[0..n) of chip (output[i]: driven, else read).
 * NULL with a one-line message in err: no such chip (named), an offset out
 * of range, a line in use, a line given twice, or the request refused. */
fs_gpio *fs_gpio_open(const fs_gpio_ops *ops, const char *chip, int n, const unsigned *offsets, const bool *output,
                      char *err, size_t errlen);
int fs_gpio_set(fs_gpio *g, int i, bool level);
/* 1 high, 0 low, -1 on error. */
int fs_gpio_get(fs_gpio *g, int i);
/* Drives the outputs low and releases every line; g may be NULL. */
void fs_gpio_close(fs_gpio *g);
/* Open sets are released at exit and on SIGINT and SIGTERM too (the
 * signal is then raised again with its default action). */
#endif
