/*
 * `fragsim sweep SPEC.ini`: a grid of configuration values x traces, run as
 * independent `fragsim replay` jobs, gathered into one CSV and gnuplot plots.
 *
 * Every job is one line of OUT/jobs.tsv and is run by the same entry point
 * wherever it runs: `fragsim sweep --run-job OUT/jobs.tsv N` (GNU parallel on
 * this machine, the built-in process pool, a Slurm array task or a GNU
 * parallel --sshlogin worker).  It leaves OUT/jobs/N/{stats.json,log.txt,
 * result}; gathering only reads those files, so a sweep run on a cluster is
 * gathered with `fragsim sweep --gather SPEC.ini`.
 *
 * The spec (paths relative to the working directory):
 *   [sweep]   name, mode (functional|cycle|sampled), base_config, out, jobs
 *   [traces]  trace = FILE (repeatable; the CSV names it by its file name
 *             without directory and .trace); scene = NAME[:SCALE] (generated
 *             with scenegen into OUT/traces/ when missing or older than it)
 *   [axis.SECTION.KEY] values = v1, v2, ...   (a key of `fragsim config --list`)
 *   [axis.config]      values = a.ini, b.ini  (the --config file itself)
 *   [output]  stats = totals.NAME, ... (JSON paths in the statistics file;
 *             the column is the last name); ratio.NAME = COLUMN / COLUMN;
 *             cycles = JSON path of the cycle count (default
 *             cycle.totals.cycles, what --mode cycle|sampled writes)
 *   [plot.NAME] x, y (CSV column names), series (optional column), title,
 *             xlabel, ylabel, logx, logy; y is the mean over rows sharing
 *             (series, x)
 */
#include <errno.h>
#include <stdarg.h>
#include <ini.h>
#include <jansson.h>
#include <limits.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>
#include "run_config.h"
#include "cli.h"

#define MAX_AXES 8
#define MAX_VALUES 64
#define MAX_TRACES 32
#define MAX_STATS 32
#define MAX_RATIOS 8
#define MAX_PLOTS 8
#define NAME_LEN 128
#define PATH_LEN 4096
#define CELL_LEN 256 /* a CSV cell; trace labels are shorter */
#define VALUE_LEN 1024 /* longest value in a spec; also the output directory */

typedef struct axis {
    char name[NAME_LEN]; /* "section.key" or "config" */
    char values[MAX_VALUES][NAME_LEN];
    int nvalues;
    int line;
} axis;

typedef struct trace_item {
    char label[CELL_LEN]; /* what the CSV shows: the path as given, or scene:scale */
    char path[PATH_LEN];
    char scene[NAME_LEN], scale[NAME_LEN]; /* scene[0] == 0 for a file */
} trace_item;

typedef struct plot {
    char name[NAME_LEN], x[NAME_LEN], y[NAME_LEN], series[NAME_LEN];
    char title[256], xlabel[256], ylabel[256];
    bool logx, logy;
} plot;

typedef struct spec {
    const char *path;
    char name[NAME_LEN], mode[32], base_config[PATH_LEN], out[PATH_LEN];
    int jobs;
    axis axes[MAX_AXES];
    int naxes;
    trace_item traces[MAX_TRACES];
    int ntraces;
    char stats[MAX_STATS][NAME_LEN];
    int nstats;
    /* ratio columns: name = numerator column / denominator column */
    char ratio_name[MAX_RATIOS][NAME_LEN], ratio_num[MAX_RATIOS][NAME_LEN], ratio_den[MAX_RATIOS][NAME_LEN];
    int nratios;
    char cycles_path[NAME_LEN], fragments_path[NAME_LEN];
    plot plots[MAX_PLOTS];
    int nplots;
    char err[512];
    bool failed;
} spec;

static const char *prog = "fragsim sweep";

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fragsim sweep [options] SPEC.ini\n"
            "\n"
            "Expands SPEC's grid (traces x axis values) into jobs, runs them on this\n"
            "machine (GNU parallel if installed, else a built-in process pool), gathers\n"
            "OUT/results.csv and draws OUT/PLOT.png with gnuplot.  Also writes\n"
            "OUT/jobs.tsv, OUT/slurm.sh (sbatch job array) and OUT/parallel_ssh.sh\n"
            "(GNU parallel --sshlogin) for clusters, without running them.\n"
            "\n"
            "options:\n"
            "  -j N               parallel jobs (default: [sweep] jobs, else 2)\n"
            "  --out DIR          output directory (default: [sweep] out, else out/sweeps/NAME)\n"
            "  --runner R         auto (default), parallel or builtin\n"
            "  --mode M           replay mode of every job, over [sweep] mode:\n"
            "                     functional, cycle or sampled\n"
            "  --no-run           write the job list and cluster scripts only\n"
            "  --gather           gather and plot results already in OUT, run nothing\n"
            "  --run-job JOBS N   run job N of a job list (what every runner calls)\n"
            "\n"
            "SPEC (paths relative to the working directory; see configs/sweeps/*.ini):\n"
            "  [sweep]            name, mode (functional|cycle|sampled), base_config, out, jobs\n"
            "  [traces]           trace = FILE, scene = NAME[:SCALE] (built with scenegen), repeatable\n"
            "  [axis.SEC.KEY]     values = v1, v2, ...  (keys of `fragsim config --list`)\n"
            "  [axis.config]      values = a.ini, b.ini (whole configuration files)\n"
            "  [output]           stats = JSON paths (totals.NAME, cycle.totals.NAME),\n"
            "                     ratio.NAME = COLUMN / COLUMN, cycles = JSON path\n"
            "  [plot.NAME]        x, y, series (CSV columns), title, xlabel, ylabel, logx, logy\n"
            "\n"
            "Exit status 0 when every job succeeded, 1 when a job failed (the others\n"
            "are still gathered), 2 for a usage or spec error.\n");
}

/* ---------- small helpers ---------- */

/* snprintf for paths and names.  The spec's values and the output directory
 * are length-checked on input so that composed paths fit; a truncation is
 * still caught here rather than used. */
__attribute__((format(printf, 3, 4))) static void fmt(char *buf, size_t len, const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    int n = vsnprintf(buf, len, f, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= len) {
        fprintf(stderr, "%s: a path or name is too long: %.60s...\n", prog, buf);
        exit(2);
    }
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int make_dirs(const char *dir)
{
    char buf[PATH_LEN];
    fmt(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

static void trim(char *s)
{
    char *b = s;
    while (*b == ' ' || *b == '\t')
        b++;
    size_t n = strlen(b);
    while (n && (b[n - 1] == ' ' || b[n - 1] == '\t' || b[n - 1] == '\r' || b[n - 1] == '\n'))
        n--;
    memmove(s, b, n);
    s[n] = '\0';
}

/* An absolute form of a path that may not exist yet (jobs run elsewhere). */
static void absolute(const char *path, char *out, size_t len)
{
    if (path[0] == '/') {
        fmt(out, len, "%s", path);
        return;
    }
    char cwd[PATH_LEN];
    if (!getcwd(cwd, sizeof cwd))
        fmt(cwd, sizeof cwd, ".");
    fmt(out, len, "%s/%s", cwd, path[0] == '.' && path[1] == '/' ? path + 2 : path);
}

static int self_path(char *out, size_t len)
{
    ssize_t n = readlink("/proc/self/exe", out, len - 1);
    if (n <= 0)
        return -1;
    out[n] = '\0';
    return 0;
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 == cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (buf)
        buf[n] = '\0';
    return buf;
}

/* ---------- spec ---------- */

/* Splits a comma list into at most max items of NAME_LEN; -1 when too many
 * or an item is empty or too long. */
static int split_list(const char *value, char (*items)[NAME_LEN], int max)
{
    int n = 0;
    const char *p = value;
    for (;;) {
        const char *e = strchr(p, ',');
        size_t l = e ? (size_t)(e - p) : strlen(p);
        if (n == max || l >= NAME_LEN)
            return -1;
        memcpy(items[n], p, l);
        items[n][l] = '\0';
        trim(items[n]);
        if (!items[n][0])
            return -1;
        n++;
        if (!e)
            return n;
        p = e + 1;
    }
}

static bool parse_bool(const char *v, bool *out)
{
    if (!strcmp(v, "1") || !strcmp(v, "true") || !strcmp(v, "yes"))
        *out = true;
    else if (!strcmp(v, "0") || !strcmp(v, "false") || !strcmp(v, "no"))
        *out = false;
    else
        return false;
    return true;
}

/* Records the first error of the spec; a message cut short is still clear. */
__attribute__((format(printf, 2, 3))) static int spec_err(spec *s, const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    vsnprintf(s->err, sizeof s->err, f, ap);
    va_end(ap);
    s->failed = true;
    return 0; /* inih then reports the line */
}
#define SPEC_ERR(...) spec_err(s, __VA_ARGS__)

/* [sweep]: the run as a whole. */
static int spec_sweep_key(spec *s, const char *name, const char *value)
{
    if (!strcmp(name, "name"))
        fmt(s->name, sizeof s->name, "%s", value);
    else if (!strcmp(name, "mode")) {
        if (strcmp(value, "functional") && strcmp(value, "cycle") && strcmp(value, "sampled"))
            return SPEC_ERR("mode '%s': expected functional, cycle or sampled", value);
        fmt(s->mode, sizeof s->mode, "%s", value);
    } else if (!strcmp(name, "base_config"))
        fmt(s->base_config, sizeof s->base_config, "%s", value);
    else if (!strcmp(name, "out"))
        fmt(s->out, sizeof s->out, "%s", value);
    else if (!strcmp(name, "jobs")) {
        char *end;
        long j = strtol(value, &end, 10);
        if (*end || j < 1 || j > 256)
            return SPEC_ERR("jobs '%s': expected 1..256", value);
        s->jobs = (int)j;
    } else
        return SPEC_ERR("unknown key sweep.%s (name, mode, base_config, out, jobs)", name);
    return 1;
}

/* [traces]: one trace file or generated scene per key. */
static int spec_trace_key(spec *s, const char *name, const char *value)
{
    if (s->ntraces == MAX_TRACES)
        return SPEC_ERR("more than %d traces", MAX_TRACES);
    trace_item *t = &s->traces[s->ntraces];
    memset(t, 0, sizeof *t);
    if (strlen(value) >= CELL_LEN - 16)
        return SPEC_ERR("traces.%s: longer than %d characters", name, CELL_LEN - 17);
    if (!strcmp(name, "trace")) {
        /* The CSV names a file trace by its name without directory and
         * ".trace", short enough for tables and plot keys. */
        const char *base = strrchr(value, '/');
        fmt(t->label, sizeof t->label, "%s", base ? base + 1 : value);
        size_t ll = strlen(t->label);
        if (ll > 6 && !strcmp(t->label + ll - 6, ".trace"))
            t->label[ll - 6] = '\0';
        absolute(value, t->path, sizeof t->path);
    } else if (!strcmp(name, "scene")) {
        const char *colon = strchr(value, ':');
        size_t l = colon ? (size_t)(colon - value) : strlen(value);
        if (l == 0 || l >= sizeof t->scene)
            return SPEC_ERR("scene '%s': expected NAME or NAME:SCALE", value);
        memcpy(t->scene, value, l);
        fmt(t->scale, sizeof t->scale, "%s", colon ? colon + 1 : "small");
        for (const char *c = t->scene; *c; c++)
            if (!(*c >= 'a' && *c <= 'z') && !(*c >= '0' && *c <= '9') && *c != '_')
                return SPEC_ERR("scene '%s': a scene name is lower-case letters and digits", value);
        for (const char *c = t->scale; *c; c++)
            if (!(*c >= 'a' && *c <= 'z') && !(*c >= '0' && *c <= '9'))
                return SPEC_ERR("scene '%s': scale is small, paper or a number", value);
        fmt(t->label, sizeof t->label, "%s:%s", t->scene, t->scale);
    } else
        return SPEC_ERR("unknown key traces.%s (trace, scene)", name);
    s->ntraces++;
    return 1;
}

/* [axis.KEY]: the values of one config key (or of whole config files). */
static int spec_axis_key(spec *s, const char *section, const char *name, const char *value)
{
    const char *key = section + 5;
    axis *a = NULL;
    for (int i = 0; i < s->naxes; i++)
        if (!strcmp(s->axes[i].name, key))
            a = &s->axes[i];
    if (a || strcmp(name, "values"))
        return a ? SPEC_ERR("axis %s given twice", key)
                 : SPEC_ERR("unknown key %s in [%s] (only values)", name, section);
    if (s->naxes == MAX_AXES)
        return SPEC_ERR("more than %d axes", MAX_AXES);
    a = &s->axes[s->naxes];
    fmt(a->name, sizeof a->name, "%s", key);
    a->nvalues = split_list(value, a->values, MAX_VALUES);
    if (a->nvalues < 0)
        return SPEC_ERR("[%s] values: expected 1 to %d comma-separated values", section, MAX_VALUES);
    if (strcmp(key, "config") != 0) {
        /* The config parser's own check, so an axis gives the same
         * message for an unknown key or a bad value as an INI file. */
        for (int i = 0; i < a->nvalues; i++) {
            fs_run_config scratch;
            fs_run_config_defaults(&scratch);
            char assign[2 * NAME_LEN + 2], msg[400];
            fmt(assign, sizeof assign, "%s=%s", key, a->values[i]);
            if (fs_run_config_set(&scratch, assign, msg, sizeof msg) != 0) {
                const char *m = strncmp(msg, "--set: ", 7) ? msg : msg + 7;
                return SPEC_ERR("%s", m);
            }
        }
    }
    s->naxes++;
    return 1;
}

/* [output]: the columns of results.csv. */
static int spec_output_key(spec *s, const char *name, const char *value)
{
    if (!strcmp(name, "stats")) {
        s->nstats = split_list(value, s->stats, MAX_STATS);
        if (s->nstats < 0)
            return SPEC_ERR("output.stats: expected 1 to %d comma-separated names", MAX_STATS);
    } else if (!strncmp(name, "ratio.", 6)) {
        if (s->nratios == MAX_RATIOS)
            return SPEC_ERR("more than %d ratio columns", MAX_RATIOS);
        const char *slash = strchr(value, '/');
        size_t ln = slash ? (size_t)(slash - value) : 0;
        int k = s->nratios;
        if (!slash || ln >= NAME_LEN || strlen(slash + 1) >= NAME_LEN || strlen(name + 6) >= NAME_LEN || !name[6])
            return SPEC_ERR("output.%s: expected ratio.NAME = COLUMN / COLUMN", name);
        fmt(s->ratio_name[k], NAME_LEN, "%s", name + 6);
        memcpy(s->ratio_num[k], value, ln);
        s->ratio_num[k][ln] = '\0';
        trim(s->ratio_num[k]);
        fmt(s->ratio_den[k], NAME_LEN, "%s", slash + 1);
        trim(s->ratio_den[k]);
        s->nratios++;
    } else if (!strcmp(name, "cycles"))
        fmt(s->cycles_path, sizeof s->cycles_path, "%s", value);
    else if (!strcmp(name, "fragments"))
        fmt(s->fragments_path, sizeof s->fragments_path, "%s", value);
    else
        return SPEC_ERR("unknown key output.%s (stats, ratio.NAME, cycles, fragments)", name);
    return 1;
}

/* [plot.NAME]: one gnuplot figure. */
static int spec_plot_key(spec *s, const char *section, const char *name, const char *value)
{
    plot *p = NULL;
    for (int i = 0; i < s->nplots; i++)
        if (!strcmp(s->plots[i].name, section + 5))
            p = &s->plots[i];
    if (!p) {
        if (s->nplots == MAX_PLOTS)
            return SPEC_ERR("more than %d plots", MAX_PLOTS);
        p = &s->plots[s->nplots++];
        memset(p, 0, sizeof *p);
        fmt(p->name, sizeof p->name, "%s", section + 5);
        for (const char *c = p->name; *c; c++)
            if (!(*c >= 'a' && *c <= 'z') && !(*c >= '0' && *c <= '9') && *c != '_' && *c != '-')
                return SPEC_ERR("plot name '%s': lower-case letters, digits, _ and -", p->name);
    }
    bool b;
    if (!strcmp(name, "x"))
        fmt(p->x, sizeof p->x, "%s", value);
    else if (!strcmp(name, "y"))
        fmt(p->y, sizeof p->y, "%s", value);
    else if (!strcmp(name, "series"))
        fmt(p->series, sizeof p->series, "%s", value);
    else if (!strcmp(name, "title"))
        fmt(p->title, sizeof p->title, "%s", value);
    else if (!strcmp(name, "xlabel"))
        fmt(p->xlabel, sizeof p->xlabel, "%s", value);
    else if (!strcmp(name, "ylabel"))
        fmt(p->ylabel, sizeof p->ylabel, "%s", value);
    else if (!strcmp(name, "logx") || !strcmp(name, "logy")) {
        if (!parse_bool(value, &b))
            return SPEC_ERR("%s.%s '%s' is not a boolean", section, name, value);
        *(name[3] == 'x' ? &p->logx : &p->logy) = b;
    } else
        return SPEC_ERR("unknown key %s in [%s] (x, y, series, title, xlabel, ylabel, logx, logy)", name, section);
    return 1;
}

static int on_spec_value(void *user, const char *section, const char *name, const char *value)
{
    spec *s = user;
    if (s->failed)
        return 0;
    if (strlen(value) >= VALUE_LEN)
        return SPEC_ERR("%s.%s: value longer than %d characters", section, name, VALUE_LEN - 1);
    if (strchr(value, '\t'))
        return SPEC_ERR("%s.%s: a tab in a value (the job list is tab-separated)", section, name);
    if (!strcmp(section, "sweep"))
        return spec_sweep_key(s, name, value);
    if (!strcmp(section, "traces"))
        return spec_trace_key(s, name, value);
    if (!strncmp(section, "axis.", 5))
        return spec_axis_key(s, section, name, value);
    if (!strcmp(section, "output"))
        return spec_output_key(s, name, value);
    if (!strncmp(section, "plot.", 5))
        return spec_plot_key(s, section, name, value);
    return SPEC_ERR("unknown section [%s] (sweep, traces, axis.SECTION.KEY, axis.config, output, plot.NAME)", section);
}

static int load_spec(spec *s, const char *path)
{
    memset(s, 0, sizeof *s);
    s->path = path;
    fmt(s->mode, sizeof s->mode, "functional");
    fmt(s->cycles_path, sizeof s->cycles_path, "cycle.totals.cycles");
    fmt(s->fragments_path, sizeof s->fragments_path, "totals.fragments_generated");
    int line = ini_parse(path, on_spec_value, s);
    if (line == -1) {
        fprintf(stderr, "%s: %s: cannot open: %s\n", prog, path, strerror(errno));
        return -1;
    }
    if (line != 0) {
        fprintf(stderr, "%s: %s:%d: %s\n", prog, path, line > 0 ? line : 0, s->failed ? s->err : "syntax error");
        return -1;
    }
    if (!s->name[0]) {
        const char *b = strrchr(path, '/');
        fmt(s->name, sizeof s->name, "%s", b ? b + 1 : path);
        char *dot = strrchr(s->name, '.');
        if (dot)
            *dot = '\0';
    }
    if (s->ntraces == 0) {
        fprintf(stderr, "%s: %s: no traces ([traces] trace = FILE or scene = NAME[:SCALE])\n", prog, path);
        return -1;
    }
    for (int i = 0; i < s->nplots; i++) {
        if (!s->plots[i].x[0] || !s->plots[i].y[0]) {
            fprintf(stderr, "%s: %s: [plot.%s] needs x and y\n", prog, path, s->plots[i].name);
            return -1;
        }
    }
    for (int i = 0; i < s->nratios; i++) {
        const char *need[2] = {s->ratio_num[i], s->ratio_den[i]};
        for (int k = 0; k < 2; k++) {
            bool found = !strcmp(need[k], "cycles") || !strcmp(need[k], "fragments") ||
                         !strcmp(need[k], "run_time_s");
            for (int a = 0; a < s->naxes && !found; a++)
                found = !strcmp(need[k], s->axes[a].name);
            for (int a = 0; a < s->nstats && !found; a++) {
                const char *b = strrchr(s->stats[a], '.');
                found = !strcmp(need[k], b ? b + 1 : s->stats[a]);
            }
            for (int a = 0; a < i && !found; a++)
                found = !strcmp(need[k], s->ratio_name[a]);
            if (!found) {
                fprintf(stderr, "%s: %s: [output] ratio.%s: no column '%s' (cycles, fragments, run_time_s, an axis, "
                                "a stat's last name or an earlier ratio)\n", prog, path, s->ratio_name[i], need[k]);
                return -1;
            }
        }
    }
    if (s->base_config[0]) {
        char abs[PATH_LEN];
        absolute(s->base_config, abs, sizeof abs);
        fmt(s->base_config, sizeof s->base_config, "%s", abs);
    }
    return 0;
}

/* ---------- jobs ---------- */

static long job_count(const spec *s)
{
    long n = s->ntraces;
    for (int i = 0; i < s->naxes; i++)
        n *= s->axes[i].nvalues;
    return n;
}

/* Job j: traces outermost, then the axes in spec order, the last fastest. */
static void job_indices(const spec *s, long j, int *trace, int *vals)
{
    for (int i = s->naxes - 1; i >= 0; i--) {
        vals[i] = (int)(j % s->axes[i].nvalues);
        j /= s->axes[i].nvalues;
    }
    *trace = (int)j;
}

static const char *job_config_file(const spec *s, const int *vals, char *buf, size_t len)
{
    const char *cfg = s->base_config[0] ? s->base_config : NULL;
    for (int i = 0; i < s->naxes; i++)
        if (!strcmp(s->axes[i].name, "config")) {
            absolute(s->axes[i].values[vals[i]], buf, len);
            cfg = buf;
        }
    return cfg;
}

/* The job's configuration must pass the same checks replay makes. */
static int check_job_config(const spec *s, long j)
{
    int t, vals[MAX_AXES];
    job_indices(s, j, &t, vals);
    char cfgbuf[PATH_LEN], err[512];
    const char *cfgfile = job_config_file(s, vals, cfgbuf, sizeof cfgbuf);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    if (cfgfile && fs_run_config_load(&cfg, cfgfile, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return -1;
    }
    for (int i = 0; i < s->naxes; i++) {
        if (!strcmp(s->axes[i].name, "config"))
            continue;
        char assign[2 * NAME_LEN + 2];
        fmt(assign, sizeof assign, "%s=%s", s->axes[i].name, s->axes[i].values[vals[i]]);
        if (fs_run_config_set(&cfg, assign, err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s: %s\n", prog, s->path, err);
            return -1;
        }
    }
    if (fs_run_config_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s: job %ld:", prog, s->path, j);
        for (int i = 0; i < s->naxes; i++)
            fprintf(stderr, " %s=%s", s->axes[i].name, s->axes[i].values[vals[i]]);
        fprintf(stderr, ": %s\n", err);
        return -1;
    }
    return 0;
}

/* jobs.tsv: "N<TAB>TRACE<TAB>OUTDIR<TAB>replay arguments..." per line. */
static int write_jobs(const spec *s, const char *out)
{
    char path[PATH_LEN];
    fmt(path, sizeof path, "%s/jobs.tsv", out);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "%s: %s: %s\n", prog, path, strerror(errno));
        return -1;
    }
    long n = job_count(s);
    for (long j = 0; j < n; j++) {
        int t, vals[MAX_AXES];
        job_indices(s, j, &t, vals);
        fprintf(f, "%ld\t%s\t%s/jobs/%ld", j, s->traces[t].path, out, j);
        if (strcmp(s->mode, "functional") != 0)
            fprintf(f, "\t--mode\t%s", s->mode);
        char cfgbuf[PATH_LEN];
        const char *cfg = job_config_file(s, vals, cfgbuf, sizeof cfgbuf);
        if (cfg)
            fprintf(f, "\t--config\t%s", cfg);
        for (int i = 0; i < s->naxes; i++)
            if (strcmp(s->axes[i].name, "config") != 0)
                fprintf(f, "\t--set\t%s=%s", s->axes[i].name, s->axes[i].values[vals[i]]);
        fputc('\n', f);
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* Runs job N of a job list: `fragsim replay` in a child with its output in
 * the job's log; writes "EXIT SECONDS" to the job's result file last, so a
 * result file means the job finished. */
static int run_job(const char *jobs_path, long want)
{
    char *text = read_file(jobs_path);
    if (!text) {
        fprintf(stderr, "%s: %s: %s\n", prog, jobs_path, strerror(errno));
        return 1;
    }
    char *line = NULL;
    for (char *p = text; p && *p;) {
        char *nl = strchr(p, '\n');
        if (nl)
            *nl = '\0';
        if (strtol(p, NULL, 10) == want && strchr(p, '\t')) {
            line = p;
            break;
        }
        p = nl ? nl + 1 : NULL;
    }
    if (!line) {
        fprintf(stderr, "%s: %s: no job %ld\n", prog, jobs_path, want);
        free(text);
        return 1;
    }
    char *fields[80];
    int nf = 0;
    for (char *tok = strtok(line, "\t"); tok && nf < 80; tok = strtok(NULL, "\t"))
        fields[nf++] = tok;
    if (nf < 3) {
        fprintf(stderr, "%s: %s: job %ld: malformed line\n", prog, jobs_path, want);
        free(text);
        return 1;
    }
    const char *trace = fields[1], *dir = fields[2];
    char self[PATH_LEN], stats[PATH_LEN], log[PATH_LEN], result[PATH_LEN], tmp[PATH_LEN];
    fmt(stats, sizeof stats, "%s/stats.json", dir);
    fmt(log, sizeof log, "%s/log.txt", dir);
    fmt(result, sizeof result, "%s/result", dir);
    fmt(tmp, sizeof tmp, "%s/result.tmp", dir);
    if (self_path(self, sizeof self) != 0 || make_dirs(dir) != 0) {
        fprintf(stderr, "%s: job %ld: cannot create %s\n", prog, want, dir);
        free(text);
        return 1;
    }
    unlink(result);
    unlink(stats);
    char *argv[100];
    int na = 0;
    argv[na++] = self;
    argv[na++] = "replay";
    for (int i = 3; i < nf; i++)
        argv[na++] = fields[i];
    argv[na++] = "--out";
    argv[na++] = (char *)dir;
    argv[na++] = "--stats";
    argv[na++] = stats;
    argv[na++] = "--quiet";
    argv[na++] = (char *)trace;
    argv[na] = NULL;
    double t0 = now_seconds();
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execv(self, argv);
        _exit(127);
    }
    int status = 0, rc;
    if (pid < 0)
        rc = 127;
    else if (waitpid(pid, &status, 0) < 0)
        rc = 127;
    else
        rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    double secs = now_seconds() - t0;
    free(text);
    FILE *f = fopen(tmp, "w");
    if (!f || fprintf(f, "%d %.6f\n", rc, secs) < 0 || fclose(f) != 0 || rename(tmp, result) != 0) {
        fprintf(stderr, "%s: job %ld: cannot write %s\n", prog, want, result);
        return 1;
    }
    return rc == 0 ? 0 : 1;
}

/* ---------- runners ---------- */

static bool have_program(const char *name)
{
    const char *path = getenv("PATH");
    if (!path)
        return false;
    char dir[PATH_LEN];
    for (const char *p = path; *p;) {
        const char *e = strchr(p, ':');
        size_t l = e ? (size_t)(e - p) : strlen(p);
        if (l && l < sizeof dir - 64) {
            fmt(dir, sizeof dir, "%.*s/%s", (int)l, p, name);
            if (access(dir, X_OK) == 0)
                return true;
        }
        if (!e)
            break;
        p = e + 1;
    }
    return false;
}

static int wait_child(pid_t pid)
{
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static int run_with_parallel(const char *out, long n, int jobs)
{
    char ids[PATH_LEN], jobs_path[PATH_LEN], self[PATH_LEN], jarg[16];
    fmt(ids, sizeof ids, "%s/job_ids.txt", out);
    fmt(jobs_path, sizeof jobs_path, "%s/jobs.tsv", out);
    fmt(jarg, sizeof jarg, "%d", jobs);
    if (self_path(self, sizeof self) != 0)
        return -1;
    FILE *f = fopen(ids, "w");
    if (!f)
        return -1;
    for (long j = 0; j < n; j++)
        fprintf(f, "%ld\n", j);
    if (fclose(f) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        /* Job output is in each job's log; parallel itself stays quiet. */
        char *argv[] = {"parallel", "--will-cite", "--halt", "never", "-j", jarg, "-a", ids,
                        self, "sweep", "--run-job", jobs_path, "{}", NULL};
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) {
            dup2(fd, 1);
            close(fd);
        }
        execvp("parallel", argv);
        _exit(127);
    }
    if (pid < 0)
        return -1;
    /* parallel's exit status counts failed jobs; results say which. */
    return wait_child(pid) == 127 ? -1 : 0;
}

static int run_builtin(const char *out, long n, int jobs)
{
    char jobs_path[PATH_LEN];
    fmt(jobs_path, sizeof jobs_path, "%s/jobs.tsv", out);
    long next = 0;
    int running = 0;
    while (next < n || running > 0) {
        while (running < jobs && next < n) {
            fflush(NULL);
            pid_t pid = fork();
            if (pid == 0)
                _exit(run_job(jobs_path, next));
            if (pid < 0) {
                fprintf(stderr, "%s: fork: %s\n", prog, strerror(errno));
                break;
            }
            running++;
            next++;
        }
        if (running == 0)
            return -1;
        int status;
        if (waitpid(-1, &status, 0) > 0)
            running--;
        else if (errno != EINTR)
            return -1;
    }
    return 0;
}

/* ---------- cluster scripts ---------- */

static int write_cluster_scripts(const spec *s, const char *out, const char *spec_abs, long n)
{
    char self[PATH_LEN], path[PATH_LEN], cwd[PATH_LEN];
    if (self_path(self, sizeof self) != 0 || !getcwd(cwd, sizeof cwd))
        return -1;
    /* Slurm does not create the directory of --output itself. */
    fmt(path, sizeof path, "%s/jobs", out);
    if (make_dirs(path) != 0)
        return -1;
    fmt(path, sizeof path, "%s/slurm.sh", out);
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f,
            "#!/bin/bash\n"
            "# Slurm job array for sweep '%s' (%ld jobs), written by fragsim sweep.\n"
            "# Submit with: sbatch %s\n"
            "# then gather with: cd %s && %s sweep --gather --out %s %s\n"
            "#SBATCH --job-name=fragsim-%s\n"
            "#SBATCH --array=0-%ld\n"
            "#SBATCH --ntasks=1\n"
            "#SBATCH --cpus-per-task=1\n"
            "#SBATCH --output=%s/jobs/slurm-%%a.log\n"
            "exec %s sweep --run-job %s/jobs.tsv \"$SLURM_ARRAY_TASK_ID\"\n",
            s->name, n, path, cwd, self, out, spec_abs, s->name, n - 1, out, self, out);
    if (fclose(f) != 0)
        return -1;
    chmod(path, 0755);
    fmt(path, sizeof path, "%s/parallel_ssh.sh", out);
    f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f,
            "#!/bin/bash\n"
            "# Sweep '%s' (%ld jobs) on several machines with GNU parallel over ssh.\n"
            "# Every machine needs this directory and %s at the same paths\n"
            "# (a shared file system).  SSHLOGIN: e.g. 8/node1,8/node2 (see man parallel).\n"
            "# Then gather with: %s sweep --gather --out %s %s\n"
            "parallel --will-cite --halt never --sshlogin \"${SSHLOGIN:?set SSHLOGIN=host1,host2}\" \\\n"
            "    --workdir %s -a %s/job_ids.txt \\\n"
            "    %s sweep --run-job %s/jobs.tsv {}\n",
            s->name, n, self, self, out, spec_abs, cwd, out, self, out);
    if (fclose(f) != 0)
        return -1;
    chmod(path, 0755);
    fmt(path, sizeof path, "%s/job_ids.txt", out);
    f = fopen(path, "w");
    if (!f)
        return -1;
    for (long j = 0; j < n; j++)
        fprintf(f, "%ld\n", j);
    return fclose(f) == 0 ? 0 : -1;
}

/* ---------- gathering ---------- */

/* A real as the shortest text that reads back as the same double (what
 * the statistics file printed with a fixed format, less trailing zeros). */
static void real_text(double d, char *out, size_t len)
{
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(out, len, "%.*g", prec, d);
        if (strtod(out, NULL) == d)
            return;
    }
}

/* The value at a dotted path ("totals.cycles") from the top-level object,
 * as text for the CSV: an integer in decimal, a real as real_text, a
 * string as it is, true/false; -1 when absent, an object, an array or null. */
static int json_get(const json_t *root, const char *path, char *out, size_t len)
{
    char comp[NAME_LEN];
    const json_t *v = root;
    while (*path) {
        const char *dot = strchr(path, '.');
        size_t l = dot ? (size_t)(dot - path) : strlen(path);
        if (l >= sizeof comp)
            return -1;
        memcpy(comp, path, l);
        comp[l] = '\0';
        path += l + (dot ? 1 : 0);
        if (!(v = json_object_get(v, comp)))
            return -1;
    }
    int n;
    switch (json_typeof(v)) {
    case JSON_INTEGER:
        n = snprintf(out, len, "%" JSON_INTEGER_FORMAT, json_integer_value(v));
        break;
    case JSON_REAL:
        real_text(json_real_value(v), out, len);
        n = (int)strlen(out);
        break;
    case JSON_STRING:
        n = snprintf(out, len, "%s", json_string_value(v));
        break;
    case JSON_TRUE:
    case JSON_FALSE:
        n = snprintf(out, len, "%s", json_is_true(v) ? "true" : "false");
        break;
    default:
        return -1;
    }
    return n >= 0 && (size_t)n < len ? 0 : -1;
}

/* A job's statistics file, parsed; NULL with the reason in why (the file
 * and, for malformed JSON, line and column) when it cannot be read. */
static json_t *load_stats(const char *path, char *why, size_t len)
{
    json_error_t e;
    json_t *root = json_load_file(path, 0, &e);
    if (root && !json_is_object(root)) {
        snprintf(why, len, "%s: not a JSON object", path);
        json_decref(root);
        return NULL;
    }
    if (!root && e.line > 0)
        snprintf(why, len, "%s:%d:%d: malformed JSON: %s", path, e.line, e.column, e.text);
    else if (!root)
        snprintf(why, len, "%s", e.text);
    return root;
}

/* CSV field: quoted when it holds a comma, quote or newline. */
static void csv_field(FILE *f, const char *v, bool last)
{
    if (strpbrk(v, ",\"\n")) {
        fputc('"', f);
        for (; *v; v++) {
            if (*v == '"')
                fputc('"', f);
            fputc(*v, f);
        }
        fputc('"', f);
    } else
        fputs(v, f);
    fputc(last ? '\n' : ',', f);
}

typedef struct row {
    char cells[MAX_AXES + MAX_STATS + MAX_RATIOS + 8][CELL_LEN];
} row;

/* Gathers every job into OUT/results.csv; rows[] receives the cells for the
 * plots.  Returns the number of failed jobs. */
static long gather(const spec *s, const char *out, row *rows, char (*cols)[NAME_LEN], int *ncols)
{
    long n = job_count(s), failed = 0;
    int nc = 0;
    fmt(cols[nc++], NAME_LEN, "job");
    fmt(cols[nc++], NAME_LEN, "trace");
    for (int i = 0; i < s->naxes; i++)
        fmt(cols[nc++], NAME_LEN, "%s", s->axes[i].name);
    fmt(cols[nc++], NAME_LEN, "status");
    fmt(cols[nc++], NAME_LEN, "cycles");
    fmt(cols[nc++], NAME_LEN, "fragments");
    fmt(cols[nc++], NAME_LEN, "run_time_s");
    for (int i = 0; i < s->nstats; i++) {
        const char *b = strrchr(s->stats[i], '.');
        fmt(cols[nc++], NAME_LEN, "%s", b ? b + 1 : s->stats[i]);
    }
    int rnum[MAX_RATIOS], rden[MAX_RATIOS];
    for (int i = 0; i < s->nratios; i++) {
        /* load_spec checked that both name earlier columns */
        rnum[i] = rden[i] = 0;
        for (int k = 0; k < nc; k++) {
            if (!strcmp(cols[k], s->ratio_num[i]))
                rnum[i] = k;
            if (!strcmp(cols[k], s->ratio_den[i]))
                rden[i] = k;
        }
        fmt(cols[nc++], NAME_LEN, "%s", s->ratio_name[i]);
    }
    *ncols = nc;
    char path[PATH_LEN];
    fmt(path, sizeof path, "%s/results.csv", out);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "%s: %s: %s\n", prog, path, strerror(errno));
        return n;
    }
    for (int c = 0; c < nc; c++)
        csv_field(f, cols[c], c == nc - 1);
    for (long j = 0; j < n; j++) {
        row *r = &rows[j];
        int t, vals[MAX_AXES], c = 0;
        job_indices(s, j, &t, vals);
        fmt(r->cells[c++], sizeof r->cells[0], "%ld", j);
        fmt(r->cells[c++], sizeof r->cells[0], "%s", s->traces[t].label);
        for (int i = 0; i < s->naxes; i++)
            fmt(r->cells[c++], sizeof r->cells[0], "%s", s->axes[i].values[vals[i]]);
        char rpath[PATH_LEN + 32], lpath[PATH_LEN + 32], spath[PATH_LEN + 32];
        fmt(rpath, sizeof rpath, "%s/jobs/%ld/result", out, j);
        fmt(lpath, sizeof lpath, "%s/jobs/%ld/log.txt", out, j);
        fmt(spath, sizeof spath, "%s/jobs/%ld/stats.json", out, j);
        int rc = -1;
        double secs = 0;
        FILE *rf = fopen(rpath, "r");
        if (rf) {
            if (fscanf(rf, "%d %lf", &rc, &secs) != 2)
                rc = -1;
            fclose(rf);
        }
        char why[PATH_LEN + 300] = "";
        json_t *json = rc == 0 ? load_stats(spath, why, sizeof why) : NULL;
        const char *status = rc == 0 && json ? "ok" : rf ? "failed" : "not run";
        if (strcmp(status, "ok") != 0) {
            failed++;
            fprintf(stderr, "%s: job %ld %s", prog, j, status);
            if (rc > 0)
                fprintf(stderr, " (exit %d)", rc);
            if (why[0])
                fprintf(stderr, " (statistics: %s)", why);
            fprintf(stderr, ": trace=%s", s->traces[t].label);
            for (int i = 0; i < s->naxes; i++)
                fprintf(stderr, " %s=%s", s->axes[i].name, s->axes[i].values[vals[i]]);
            fprintf(stderr, "; log: %s\n", lpath);
        }
        fmt(r->cells[c++], sizeof r->cells[0], "%s", status);
        char v[NAME_LEN];
        fmt(r->cells[c++], sizeof r->cells[0], "%s", json && json_get(json, s->cycles_path, v, sizeof v) == 0 ? v : "");
        fmt(r->cells[c++], sizeof r->cells[0], "%s", json && json_get(json, s->fragments_path, v, sizeof v) == 0 ? v : "");
        if (rf && rc >= 0)
            fmt(r->cells[c++], sizeof r->cells[0], "%.3f", secs);
        else
            r->cells[c++][0] = '\0';
        for (int i = 0; i < s->nstats; i++)
            fmt(r->cells[c++], sizeof r->cells[0], "%s", json && json_get(json, s->stats[i], v, sizeof v) == 0 ? v : "");
        for (int i = 0; i < s->nratios; i++) {
            /* empty unless both are numbers and the denominator is not 0;
             * %.4g keeps the CSV short and the same on every run */
            char *e1, *e2;
            const char *a = r->cells[rnum[i]], *b = r->cells[rden[i]];
            double x = strtod(a, &e1), y = strtod(b, &e2);
            if (*a && *b && !*e1 && !*e2 && y != 0)
                fmt(r->cells[c++], sizeof r->cells[0], "%.4g", x / y);
            else
                r->cells[c++][0] = '\0';
        }
        json_decref(json);
        for (int k = 0; k < c; k++)
            csv_field(f, r->cells[k], k == c - 1);
    }
    if (fclose(f) != 0)
        fprintf(stderr, "%s: %s: write error\n", prog, path);
    return failed;
}

/* ---------- plots ---------- */

static int col_index(char (*cols)[NAME_LEN], int ncols, const char *name)
{
    for (int i = 0; i < ncols; i++)
        if (!strcmp(cols[i], name))
            return i;
    return -1;
}

static bool is_number(const char *v, double *out)
{
    char *end;
    if (!*v)
        return false;
    *out = strtod(v, &end);
    return *end == '\0';
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Plot p: one line per series value (first-appearance order), y the mean
 * over the rows sharing (series, x).  Writes OUT/NAME.dat, OUT/NAME.gp and
 * runs gnuplot for OUT/NAME.png. */
/* Distinct series and x values of one plot, on the heap (they are large). */
#define PLOT_MAX (MAX_VALUES * MAX_TRACES)
typedef struct plot_scratch {
    char series[PLOT_MAX][NAME_LEN], xs[PLOT_MAX][NAME_LEN];
    double xv[PLOT_MAX], tmp[PLOT_MAX][2];
    int order[PLOT_MAX];
} plot_scratch;

static int draw_plot_with(plot_scratch *sc, const spec *s, const plot *p, const char *out, row *rows, long n,
                     char (*cols)[NAME_LEN], int ncols)
{
    int cx = col_index(cols, ncols, p->x), cy = col_index(cols, ncols, p->y);
    int cs = p->series[0] ? col_index(cols, ncols, p->series) : -1;
    int cstat = col_index(cols, ncols, "status");
    if (cx < 0 || cy < 0 || (p->series[0] && cs < 0)) {
        fprintf(stderr, "%s: %s: [plot.%s]: no CSV column '%s' (columns: job, trace, axes, status, "
                        "cycles, fragments, run_time_s, output.stats)\n",
                prog, s->path, p->name, cx < 0 ? p->x : cy < 0 ? p->y : p->series);
        return -1;
    }
    /* Distinct series and x values in grid order. */
    char (*series)[NAME_LEN] = sc->series, (*xs)[NAME_LEN] = sc->xs;
    int nseries = 0, nx = 0;
    bool numeric_x = true;
    for (long j = 0; j < n; j++) {
        const char *sv = cs >= 0 ? rows[j].cells[cs] : "", *xv = rows[j].cells[cx];
        int k;
        for (k = 0; k < nseries && strcmp(series[k], sv); k++)
            ;
        if (k == nseries && nseries < PLOT_MAX)
            fmt(series[nseries++], NAME_LEN, "%s", sv);
        for (k = 0; k < nx && strcmp(xs[k], xv); k++)
            ;
        if (k == nx && nx < PLOT_MAX) {
            double d;
            numeric_x &= is_number(xv, &d);
            fmt(xs[nx++], NAME_LEN, "%s", xv);
        }
    }
    char dat[PATH_LEN], gp[PATH_LEN], png[PATH_LEN];
    fmt(dat, sizeof dat, "%s/%s.dat", out, p->name);
    fmt(gp, sizeof gp, "%s/%s.gp", out, p->name);
    fmt(png, sizeof png, "%s/%s.png", out, p->name);
    FILE *f = fopen(dat, "w");
    if (!f)
        return -1;
    int points = 0;
    for (int si = 0; si < nseries; si++) {
        fprintf(f, "# series %s\n", series[si]);
        double *xv = sc->xv;
        int *order = sc->order, m = 0;
        for (int xi = 0; xi < nx; xi++) {
            double d;
            xv[m] = numeric_x && is_number(xs[xi], &d) ? d : xi;
            order[m++] = xi;
        }
        /* sort x positions (numeric x); categorical x keeps grid order */
        if (numeric_x) {
            double (*tmp)[2] = sc->tmp;
            for (int k = 0; k < m; k++) {
                tmp[k][0] = xv[k];
                tmp[k][1] = order[k];
            }
            qsort(tmp, (size_t)m, sizeof tmp[0], cmp_double);
            for (int k = 0; k < m; k++) {
                xv[k] = tmp[k][0];
                order[k] = (int)tmp[k][1];
            }
        }
        for (int k = 0; k < m; k++) {
            double sum = 0;
            int cnt = 0;
            for (long j = 0; j < n; j++) {
                double y;
                if (strcmp(rows[j].cells[cstat], "ok") || strcmp(rows[j].cells[cx], xs[order[k]]) ||
                    (cs >= 0 && strcmp(rows[j].cells[cs], series[si])) || !is_number(rows[j].cells[cy], &y))
                    continue;
                sum += y;
                cnt++;
            }
            if (cnt) {
                fprintf(f, "%.17g %.17g \"%s\"\n", xv[k], sum / cnt, xs[order[k]]);
                points++;
            }
        }
        fprintf(f, "\n\n");
    }
    fclose(f);
    if (points == 0) {
        fprintf(stderr, "%s: plot %s: no numeric '%s' values in successful jobs; no plot\n", prog, p->name, p->y);
        return -1;
    }
    f = fopen(gp, "w");
    if (!f)
        return -1;
    /* noenhanced: names such as occlusion_t16 are text, not subscripts */
    fprintf(f, "set terminal pngcairo size 720,400 font 'sans,10' noenhanced\nset output '%s'\n", png);
    fprintf(f, "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\nset grid\nset key outside right\n",
            p->title[0] ? p->title : p->name, p->xlabel[0] ? p->xlabel : p->x, p->ylabel[0] ? p->ylabel : p->y);
    if (p->logx)
        fprintf(f, "set logscale x 2\n");
    if (p->logy)
        fprintf(f, "set logscale y\n");
    if (!numeric_x)
        fprintf(f, "set xrange [-0.5:%d.5]\n", nx - 1);
    fprintf(f, "plot ");
    for (int si = 0; si < nseries; si++) {
        char label[2 * NAME_LEN + 4];
        if (cs >= 0 && !strcmp(p->series, "trace"))
            fmt(label, sizeof label, "%s", series[si]);
        else if (cs >= 0)
            fmt(label, sizeof label, "%s=%s", p->series, series[si]);
        else
            fmt(label, sizeof label, "%s", p->y);
        for (char *c = label; *c; c++)
            if (*c == '"')
                *c = '\'';
        fprintf(f, "%s'%s' index %d using 1:2%s with linespoints title \"%s\"", si ? ", \\\n     " : "", dat,
                si, numeric_x ? "" : ":xtic(3)", label);
    }
    fprintf(f, "\n");
    fclose(f);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        char *argv[] = {"gnuplot", gp, NULL};
        execvp("gnuplot", argv);
        _exit(127);
    }
    int rc = pid < 0 ? -1 : wait_child(pid);
    if (rc != 0) {
        fprintf(stderr, "%s: gnuplot %s failed (%s)\n", prog, gp, rc == 127 ? "gnuplot not installed; make deps" : "see its message");
        return -1;
    }
    return 0;
}

static int draw_plot(const spec *s, const plot *p, const char *out, row *rows, long n,
                     char (*cols)[NAME_LEN], int ncols)
{
    plot_scratch *sc = malloc(sizeof *sc);
    if (!sc) {
        fprintf(stderr, "%s: plot %s: out of memory\n", prog, p->name);
        return -1;
    }
    int rc = draw_plot_with(sc, s, p, out, rows, n, cols, ncols);
    free(sc);
    return rc;
}

/* ---------- traces ---------- */

/* Generates scene traces that are missing or older than scenegen. */
static int make_scenes(spec *s, const char *out)
{
    char self[PATH_LEN], scenegen[PATH_LEN + 16];
    if (self_path(self, sizeof self) != 0)
        return -1;
    char *slash = strrchr(self, '/');
    if (slash)
        *slash = '\0';
    fmt(scenegen, sizeof scenegen, "%s/scenegen", self);
    for (int i = 0; i < s->ntraces; i++) {
        trace_item *t = &s->traces[i];
        if (!t->scene[0])
            continue;
        char dir[PATH_LEN];
        fmt(dir, sizeof dir, "%s/traces", out);
        fmt(t->path, sizeof t->path, "%s/%s_%s.trace", dir, t->scene, t->scale);
        struct stat st_trace, st_gen;
        if (stat(scenegen, &st_gen) != 0) {
            fprintf(stderr, "%s: %s: scene %s needs %s (make scenes)\n", prog, s->path, t->label, scenegen);
            return -1;
        }
        if (stat(t->path, &st_trace) == 0 && st_trace.st_mtime >= st_gen.st_mtime)
            continue;
        if (make_dirs(dir) != 0)
            return -1;
        fflush(NULL);
        pid_t pid = fork();
        if (pid == 0) {
            char *argv[] = {scenegen, t->scene, "--scale", t->scale, "-o", t->path, NULL};
            int fd = open("/dev/null", O_WRONLY);
            if (fd >= 0) {
                dup2(fd, 1);
                close(fd);
            }
            execv(scenegen, argv);
            _exit(127);
        }
        if (pid < 0 || wait_child(pid) != 0) {
            fprintf(stderr, "%s: %s: generating scene %s failed\n", prog, s->path, t->label);
            unlink(t->path);
            return -1;
        }
    }
    return 0;
}

/* ---------- entry ---------- */

typedef struct sweep_opts {
    const char *spec_path, *out, *runner, *mode;
    int jobs; /* -j; 0: the spec's, or 2 */
    bool no_run, gather_only;
} sweep_opts;

/* The value of -j, --out, --mode or --runner; 0, or -1 (printed). */
static int sweep_opt_value(sweep_opts *o, const char *a, const char *v)
{
    if (a[1] == 'j') {
        char *end;
        long j = strtol(v, &end, 10);
        if (*end || j < 1 || j > 256) {
            fprintf(stderr, "%s: -j '%s': expected 1..256\n", prog, v);
            return -1;
        }
        o->jobs = (int)j;
    } else if (!strcmp(a, "--out")) {
        o->out = v;
    } else if (!strcmp(a, "--mode")) {
        if (strcmp(v, "functional") && strcmp(v, "cycle") && strcmp(v, "sampled")) {
            fprintf(stderr, "%s: --mode '%s': expected functional, cycle or sampled\n", prog, v);
            return -1;
        }
        o->mode = v;
    } else if (strcmp(v, "auto") && strcmp(v, "parallel") && strcmp(v, "builtin")) {
        fprintf(stderr, "%s: --runner '%s': expected auto, parallel or builtin\n", prog, v);
        return -1;
    } else {
        o->runner = v;
    }
    return 0;
}

/* 0: run the sweep; otherwise the exit status (--help: 0 after *done; a
 * --run-job's own status; 2 on a bad option, printed). */
static int parse_sweep_opts(int argc, char **argv, sweep_opts *o, bool *done)
{
    *o = (sweep_opts){NULL, NULL, "auto", NULL, 0, false, false};
    *done = true;
    for (int i = 0; i < argc;) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        i++; /* past the option; past its value too where it takes one */
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--run-job")) {
            char *end;
            long n = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : -1;
            if (!v || n < 0 || *end) {
                fprintf(stderr, "%s: --run-job needs JOBS.tsv and a job number\n", prog);
                return 2;
            }
            return run_job(v, n);
        } else if (!strcmp(a, "-j") || !strcmp(a, "--out") || !strcmp(a, "--runner") || !strcmp(a, "--mode")) {
            if (!v) {
                fprintf(stderr, "%s: %s needs a value\n", prog, a);
                return 2;
            }
            i++;
            if (sweep_opt_value(o, a, v) != 0)
                return 2;
        } else if (!strcmp(a, "--no-run")) {
            o->no_run = true;
        } else if (!strcmp(a, "--gather")) {
            o->gather_only = true;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "%s: unknown option %s (see --help)\n", prog, a);
            return 2;
        } else if (!o->spec_path) {
            o->spec_path = a;
        } else {
            fprintf(stderr, "%s: more than one spec given (%s, %s)\n", prog, o->spec_path, a);
            return 2;
        }
    }
    if (!o->spec_path) {
        fprintf(stderr, "%s: no spec given (see --help)\n", prog);
        return 2;
    }
    *done = false;
    return 0;
}

/* Runs the n jobs of OUT/jobs.tsv; 0, or -1 (printed). */
static int run_jobs(const spec *s, const sweep_opts *o, const char *out, long n)
{
    int j = o->jobs ? o->jobs : s->jobs ? s->jobs : 2;
    bool use_parallel = !strcmp(o->runner, "parallel") || (!strcmp(o->runner, "auto") && have_program("parallel"));
    if (!strcmp(o->runner, "parallel") && !have_program("parallel")) {
        fprintf(stderr, "%s: --runner parallel: GNU parallel is not installed (make deps)\n", prog);
        return -1;
    }
    /* Stale results of an earlier run must not be gathered as this one's. */
    for (long k = 0; k < n; k++) {
        char r[PATH_LEN + 32];
        fmt(r, sizeof r, "%s/jobs/%ld/result", out, k);
        unlink(r);
    }
    double t0 = now_seconds();
    int ran = use_parallel ? run_with_parallel(out, n, j) : run_builtin(out, n, j);
    if (ran != 0) {
        fprintf(stderr, "%s: the %s runner could not start\n", prog, use_parallel ? "GNU parallel" : "built-in");
        return -1;
    }
    printf("%s: ran %ld jobs with %s (-j %d) in %.1f s\n", s->name, n,
           use_parallel ? "GNU parallel" : "the built-in process pool", j, now_seconds() - t0);
    return 0;
}

/* results.csv and the plots from the jobs' results: the exit status. */
static int gather_and_plot(const spec *s, const char *out, long n)
{
    row *rows = calloc((size_t)(n ? n : 1), sizeof *rows);
    if (!rows)
        return 2;
    char cols[MAX_AXES + MAX_STATS + MAX_RATIOS + 8][NAME_LEN];
    int ncols;
    long failed = gather(s, out, rows, cols, &ncols);
    printf("%s: results in %s/results.csv (%ld rows, %ld failed)\n", s->name, out, n, failed);
    int plot_failed = 0;
    for (int i = 0; i < s->nplots; i++) {
        if (draw_plot(s, &s->plots[i], out, rows, n, cols, ncols) == 0)
            printf("%s: plot %s/%s.png\n", s->name, out, s->plots[i].name);
        else
            plot_failed = 1;
    }
    free(rows);
    return failed || plot_failed ? 1 : 0;
}

/* The job list and cluster scripts in OUT, each job's config checked
 * first; 0, or -1 (printed). */
static int prepare_jobs(spec *s, const sweep_opts *o, const char *out, long n)
{
    char spec_abs[PATH_LEN];
    absolute(o->spec_path, spec_abs, sizeof spec_abs);
    if (n > 10000) {
        fprintf(stderr, "%s: %s: %ld jobs; at most 10000\n", prog, o->spec_path, n);
        return -1;
    }
    for (long j = 0; j < n; j++)
        if (check_job_config(s, j) != 0)
            return -1;
    if (make_dirs(out) != 0) {
        fprintf(stderr, "%s: cannot create %s: %s\n", prog, out, strerror(errno));
        return -1;
    }
    if (o->gather_only)
        return 0; /* scene traces live in OUT/traces; labels only need their names */
    if (make_scenes(s, out) != 0 || write_jobs(s, out) != 0 || write_cluster_scripts(s, out, spec_abs, n) != 0) {
        fprintf(stderr, "%s: cannot write the job list or scripts in %s\n", prog, out);
        return -1;
    }
    printf("%s: %ld jobs in %s/jobs.tsv; cluster: %s/slurm.sh (sbatch --array=0-%ld), %s/parallel_ssh.sh\n", s->name,
           n, out, out, n - 1, out);
    return 0;
}

int fs_cli_sweep(int argc, char **argv)
{
    sweep_opts o;
    bool done;
    int rc = parse_sweep_opts(argc, argv, &o, &done);
    if (done)
        return rc;
    spec *s = malloc(sizeof *s);
    if (!s || load_spec(s, o.spec_path) != 0) {
        free(s);
        return 2;
    }
    if (o.mode)
        fmt(s->mode, sizeof s->mode, "%s", o.mode);
    long n = job_count(s);
    char out_rel[PATH_LEN], out[PATH_LEN];
    if (o.out)
        fmt(out_rel, sizeof out_rel, "%s", o.out);
    else if (s->out[0])
        fmt(out_rel, sizeof out_rel, "%s", s->out);
    else
        fmt(out_rel, sizeof out_rel, "out/sweeps/%s", s->name);
    rc = 2;
    if (strlen(out_rel) >= VALUE_LEN) {
        fprintf(stderr, "%s: output directory name longer than %d characters\n", prog, VALUE_LEN - 1);
        free(s);
        return rc;
    }
    absolute(out_rel, out, sizeof out);
    bool ran = prepare_jobs(s, &o, out, n) == 0 && (o.gather_only || o.no_run || run_jobs(s, &o, out, n) == 0);
    if (ran)
        rc = o.no_run ? 0 : gather_and_plot(s, out, n);
    free(s);
    return rc;
}
