/*
 * Configuration key tables: defaults, INI files (libinih), "section.key=value"
 * overrides, the listing behind `fragsim config --list`, the INI file of
 * defaults and the JSON of the effective values; the functional pipeline's
 * table (config.def) and its checks.  Checks are done per key with one
 * precise message (the SimpleScalar idea in shared/style-anchors.md).
 */
#include <errno.h>
#include <stddef.h>
#include <ini.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>
#include "config.h"

static long *value_of(const fs_config_part *p, size_t i) { return (long *)((char *)p->values + p->keys[i].offset); }

void fs_config_part_defaults(const fs_config_part *p)
{
    for (size_t i = 0; i < p->nkeys; i++)
        *value_of(p, i) = p->keys[i].def;
}

/* A key's value from its text, or -1 with the message. */
static int parse_value(const fs_config_key *k, const char *value, long *v, char *err, size_t errlen)
{
    if (strcmp(k->type, "BOOL") == 0) {
        if (!strcmp(value, "true") || !strcmp(value, "1") || !strcmp(value, "yes"))
            *v = 1;
        else if (!strcmp(value, "false") || !strcmp(value, "0") || !strcmp(value, "no"))
            *v = 0;
        else {
            snprintf(err, errlen, "%s.%s: '%s' is not a boolean (true/false)", k->section, k->key, value);
            return -1;
        }
        return 0;
    }
    char *end;
    errno = 0;
    *v = strtol(value, &end, 0);
    if (errno || end == value || *end != '\0') {
        snprintf(err, errlen, "%s.%s: '%s' is not an integer", k->section, k->key, value);
        return -1;
    }
    if (*v < k->lo || *v > k->hi) {
        snprintf(err, errlen, "%s.%s: %ld is out of range [%ld, %ld] %s", k->section, k->key, *v, k->lo, k->hi,
                 k->unit);
        return -1;
    }
    return 0;
}

static int set_key(const fs_config_part *p, size_t n, const char *section, const char *key, const char *value,
                   char *err, size_t errlen)
{
    for (size_t t = 0; t < n; t++)
        for (size_t i = 0; i < p[t].nkeys; i++) {
            const fs_config_key *k = &p[t].keys[i];
            if (strcmp(k->section, section) != 0 || strcmp(k->key, key) != 0)
                continue;
            long v;
            if (parse_value(k, value, &v, err, errlen) != 0)
                return -1;
            *value_of(&p[t], i) = v;
            return 0;
        }
    snprintf(err, errlen, "unknown key %s.%s (see `fragsim config --list`)", section, key);
    return -1;
}

typedef struct load_ctx {
    const fs_config_part *parts;
    size_t nparts;
    char *err;
    size_t errlen;
    int failed;
} load_ctx;

static int on_ini_value(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *l = user;
    if (l->failed)
        return 0;
    if (set_key(l->parts, l->nparts, section, name, value, l->err, l->errlen) != 0) {
        l->failed = 1;
        return 0; /* inih then reports this line number */
    }
    return 1;
}

int fs_config_parts_load(const fs_config_part *p, size_t n, const char *path, char *err, size_t errlen)
{
    char msg[256] = "";
    load_ctx l = {p, n, msg, sizeof msg, 0};
    int line = ini_parse(path, on_ini_value, &l);
    if (line == -1) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (line == -2) {
        snprintf(err, errlen, "%s: out of memory while parsing", path);
        return -1;
    }
    if (line > 0) {
        snprintf(err, errlen, "%s:%d: %s", path, line, msg[0] ? msg : "syntax error");
        return -1;
    }
    return 0;
}

int fs_config_parts_set(const fs_config_part *p, size_t n, const char *assignment, char *err, size_t errlen)
{
    const char *dot = strchr(assignment, '.');
    const char *eq = strchr(assignment, '=');
    if (!dot || !eq || dot > eq) {
        snprintf(err, errlen, "--set '%s': expected section.key=value", assignment);
        return -1;
    }
    char section[64], key[64];
    size_t ls = (size_t)(dot - assignment), lk = (size_t)(eq - dot - 1);
    if (ls >= sizeof section || lk >= sizeof key) {
        snprintf(err, errlen, "--set '%s': name too long", assignment);
        return -1;
    }
    memcpy(section, assignment, ls);
    section[ls] = '\0';
    memcpy(key, dot + 1, lk);
    key[lk] = '\0';
    char msg[256];
    if (set_key(p, n, section, key, eq + 1, msg, sizeof msg) != 0) {
        snprintf(err, errlen, "--set: %s", msg);
        return -1;
    }
    return 0;
}

void fs_config_parts_list(const fs_config_part *p, size_t n, FILE *f)
{
    for (size_t t = 0; t < n; t++)
        for (size_t i = 0; i < p[t].nkeys; i++) {
            const fs_config_key *k = &p[t].keys[i];
            char name[96];
            snprintf(name, sizeof name, "%s.%s", k->section, k->key);
            fprintf(f, "%-28s %-4s default %-6ld range [%ld, %ld] %-8s %s\n", name, k->type, k->def, k->lo, k->hi,
                    k->unit, k->meaning);
        }
}

/* One key of the INI file of defaults: its meaning as comment lines, then
 * the key. */
static void write_ini_key(const fs_config_key *k, FILE *f)
{
    char text[1024];
    snprintf(text, sizeof text, "%s (%s%s%s, range %ld..%ld)", k->meaning, k->type, k->unit[0] ? ", " : "",
             k->unit, k->lo, k->hi);
    /* Comment lines wrapped at 76 columns: libinih reads lines of up to
     * 200 characters. */
    for (const char *p = text; *p;) {
        size_t n = strlen(p);
        if (n > 74) {
            n = 74;
            while (n > 20 && p[n] != ' ')
                n--;
        }
        fprintf(f, "; %.*s\n", (int)n, p);
        p += n;
        while (*p == ' ')
            p++;
    }
    if (strcmp(k->type, "BOOL") == 0)
        fprintf(f, "%s = %s\n", k->key, k->def ? "true" : "false");
    else
        fprintf(f, "%s = %ld\n", k->key, k->def);
}

void fs_config_parts_write_ini(const fs_config_part *p, size_t n, FILE *f)
{
    const char *section = "";
    for (size_t t = 0; t < n; t++)
        for (size_t i = 0; i < p[t].nkeys; i++) {
            const fs_config_key *k = &p[t].keys[i];
            if (strcmp(section, k->section) != 0) {
                section = k->section;
                fprintf(f, "\n[%s]\n", section);
            }
            write_ini_key(k, f);
        }
}

json_t *fs_config_parts_json(const fs_config_part *p, size_t n)
{
    json_t *o = json_object();
    for (size_t t = 0; o && t < n; t++)
        for (size_t i = 0; o && i < p[t].nkeys; i++) {
            char name[160];
            snprintf(name, sizeof name, "%s.%s", p[t].keys[i].section, p[t].keys[i].key);
            if (json_object_set_new(o, name, json_integer(*value_of(&p[t], i))) != 0) {
                json_decref(o);
                o = NULL;
            }
        }
    return o;
}

/* ---- the functional pipeline's keys ---- */

static const fs_config_key keys[] = {
#define FS_CONFIG(sec, k, type, def, lo, hi, unit, meaning) \
    FS_CONFIG_KEY(fs_config, sec, k, type, def, lo, hi, unit, meaning),
#include "config.def"
#undef FS_CONFIG
};

fs_config_part fs_config_part_of(fs_config *cfg) { return (fs_config_part){keys, sizeof keys / sizeof keys[0], cfg}; }

void fs_config_defaults(fs_config *cfg)
{
    fs_config_part p = fs_config_part_of(cfg);
    fs_config_part_defaults(&p);
}

int fs_config_check(const fs_config *cfg, char *err, size_t errlen)
{
    /* Constraints a range cannot say, one message each. */
    if (cfg->framebuffer_depth_bits != 16 && cfg->framebuffer_depth_bits != 24) {
        snprintf(err, errlen, "framebuffer.depth_bits: %ld is not supported (16 or 24)", cfg->framebuffer_depth_bits);
        return -1;
    }
    if (cfg->framebuffer_stencil_bits != 0 && cfg->framebuffer_stencil_bits != 8) {
        snprintf(err, errlen, "framebuffer.stencil_bits: %ld is not supported (0 or 8)", cfg->framebuffer_stencil_bits);
        return -1;
    }
    return 0;
}
