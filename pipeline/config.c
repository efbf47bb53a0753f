/*
 * Configuration keys from config.def: defaults, INI files (libinih),
 * "section.key=value" overrides, and the listing behind `fragsim config --list`.
 * Checks are done per key with one precise message (the SimpleScalar idea in
 * shared/style-anchors.md).
 */
#include <errno.h>
#include <stddef.h>
#include <ini.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>
#include "config.h"

typedef struct key_info {
    const char *section, *key, *type, *unit, *meaning;
    long def, lo, hi;
    size_t offset;
} key_info;

static const key_info keys[] = {
#define FS_CONFIG(sec, k, type, def, lo, hi, unit, meaning) \
    {#sec, #k, #type, unit, meaning, def, lo, hi, offsetof(fs_config, sec##_##k)},
#include "config.def"
#undef FS_CONFIG
};
#define NKEYS (sizeof keys / sizeof keys[0])

void fs_config_defaults(fs_config *cfg)
{
    for (size_t i = 0; i < NKEYS; i++)
        *(long *)((char *)cfg + keys[i].offset) = keys[i].def;
}

static int set_key(fs_config *cfg, const char *section, const char *key, const char *value,
                   char *err, size_t errlen)
{
    for (size_t i = 0; i < NKEYS; i++) {
        if (strcmp(keys[i].section, section) != 0 || strcmp(keys[i].key, key) != 0)
            continue;
        long v;
        if (strcmp(keys[i].type, "BOOL") == 0) {
            if (!strcmp(value, "true") || !strcmp(value, "1") || !strcmp(value, "yes"))
                v = 1;
            else if (!strcmp(value, "false") || !strcmp(value, "0") || !strcmp(value, "no"))
                v = 0;
            else {
                snprintf(err, errlen, "%s.%s: '%s' is not a boolean (true/false)", section, key, value);
                return -1;
            }
        } else {
            char *end;
            errno = 0;
            v = strtol(value, &end, 0);
            if (errno || end == value || *end != '\0') {
                snprintf(err, errlen, "%s.%s: '%s' is not an integer", section, key, value);
                return -1;
            }
            if (v < keys[i].lo || v > keys[i].hi) {
                snprintf(err, errlen, "%s.%s: %ld is out of range [%ld, %ld] %s", section, key, v,
                         keys[i].lo, keys[i].hi, keys[i].unit);
                return -1;
            }
        }
        *(long *)((char *)cfg + keys[i].offset) = v;
        return 0;
    }
    snprintf(err, errlen, "unknown key %s.%s (see `fragsim config --list`)", section, key);
    return -1;
}

typedef struct load_ctx {
    fs_config *cfg;
    char *err;
    size_t errlen;
    int failed;
} load_ctx;

static int on_ini_value(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *l = user;
    if (l->failed)
        return 0;
    if (set_key(l->cfg, section, name, value, l->err, l->errlen) != 0) {
        l->failed = 1;
        return 0; /* inih then reports this line number */
    }
    return 1;
}

int fs_config_load(fs_config *cfg, const char *path, char *err, size_t errlen)
{
    char msg[256] = "";
    load_ctx l = {cfg, msg, sizeof msg, 0};
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

int fs_config_set(fs_config *cfg, const char *assignment, char *err, size_t errlen)
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
    if (set_key(cfg, section, key, eq + 1, msg, sizeof msg) != 0) {
        snprintf(err, errlen, "--set: %s", msg);
        return -1;
    }
    return 0;
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
    /* A 2x2 quad must stay on one image engine (rtl_model/rasterizer_stage.c). */
    if (cfg->fragment_interleave % 2 != 0) {
        snprintf(err, errlen, "fragment.interleave: %ld is not even", cfg->fragment_interleave);
        return -1;
    }
    /* The texture cache's geometry (rtl_model/texture_cache.h). */
    const struct { const char *name; long v; } pow2[] = {
        {"texture.cache_bytes", cfg->texture_cache_bytes}, {"texture.cache_line_bytes", cfg->texture_cache_line_bytes},
        {"texture.cache_ways", cfg->texture_cache_ways}, {"texture.cache_banks", cfg->texture_cache_banks}};
    for (size_t i = 0; i < sizeof pow2 / sizeof pow2[0]; i++) {
        if (cfg->texture_cache_bytes != 0 && (pow2[i].v & (pow2[i].v - 1)) != 0) {
            snprintf(err, errlen, "%s: %ld is not a power of two", pow2[i].name, pow2[i].v);
            return -1;
        }
    }
    if (cfg->texture_cache_bytes != 0 &&
        cfg->texture_cache_line_bytes * cfg->texture_cache_ways > cfg->texture_cache_bytes) {
        snprintf(err, errlen, "texture.cache_ways: %ld ways of %ld-byte lines do not fit in texture.cache_bytes = %ld",
                 cfg->texture_cache_ways, cfg->texture_cache_line_bytes, cfg->texture_cache_bytes);
        return -1;
    }
    return 0;
}

void fs_config_list(FILE *f)
{
    for (size_t i = 0; i < NKEYS; i++) {
        char name[96];
        snprintf(name, sizeof name, "%s.%s", keys[i].section, keys[i].key);
        fprintf(f, "%-28s %-4s default %-6ld range [%ld, %ld] %-8s %s\n", name, keys[i].type,
                keys[i].def, keys[i].lo, keys[i].hi, keys[i].unit, keys[i].meaning);
    }
}

void fs_config_write_defaults_ini(FILE *f)
{
    fprintf(f, "; Every configuration key with its default (generated by `fragsim config --defaults`\n"
               "; from pipeline/config.def; do not edit: tests/cli_cycle.sh compares).\n");
    const char *section = "";
    for (size_t i = 0; i < NKEYS; i++) {
        if (strcmp(section, keys[i].section) != 0) {
            section = keys[i].section;
            fprintf(f, "\n[%s]\n", section);
        }
        char text[1024];
        snprintf(text, sizeof text, "%s (%s%s%s, range %ld..%ld)", keys[i].meaning, keys[i].type,
                 keys[i].unit[0] ? ", " : "", keys[i].unit, keys[i].lo, keys[i].hi);
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
        if (strcmp(keys[i].type, "BOOL") == 0)
            fprintf(f, "%s = %s\n", keys[i].key, keys[i].def ? "true" : "false");
        else
            fprintf(f, "%s = %ld\n", keys[i].key, keys[i].def);
    }
}

json_t *fs_config_json(const fs_config *cfg)
{
    json_t *o = json_object();
    for (size_t i = 0; o && i < NKEYS; i++) {
        char name[160];
        snprintf(name, sizeof name, "%s.%s", keys[i].section, keys[i].key);
        if (json_object_set_new(o, name, json_integer(*(const long *)((const char *)cfg + keys[i].offset))) != 0) {
            json_decref(o);
            o = NULL;
        }
    }
    return o;
}
