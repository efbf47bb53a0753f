/* The per-call GL error log (error_log.h). */
#include <stdlib.h>
#include <string.h>
#include "json_text.h"
#include "error_log.h"
#include "../pipeline/context.h"

const char *fs_error_name(GLenum err, char buf[16])
{
    switch (err) { /* GL 1.5 spec table 2.3 */
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_TABLE_TOO_LARGE: return "GL_TABLE_TOO_LARGE";
    default:
        snprintf(buf, 16, "0x%04x", (unsigned)err);
        return buf;
    }
}

static void on_error(void *user, GLenum err)
{
    fs_error_log *log = user;
    log->total++;
    if (log->print && log->total <= log->print_max) {
        char b[16];
        /* glretrace's warning (retrace/glretrace_main.cpp checkGlError) */
        fprintf(log->print, "%llu: warning: glGetError(%s) = %s\n", (unsigned long long)log->call,
                log->command ? log->command : "?", fs_error_name(err, b));
    }
    if (log->n >= FS_ERROR_LOG_MAX)
        return;
    if (log->n == log->cap) {
        size_t cap = log->cap ? log->cap * 2 : 64;
        fs_error_entry *e = realloc(log->entries, cap * sizeof *e);
        if (!e)
            return; /* counted in total, not listed */
        log->entries = e;
        log->cap = cap;
    }
    log->entries[log->n++] = (fs_error_entry){log->call, log->command, err};
}

void fs_error_log_attach(fs_error_log *log, fs_context *c)
{
    FILE *print = log->print;
    unsigned print_max = log->print_max;
    free(log->entries);
    memset(log, 0, sizeof *log);
    log->print = print;
    log->print_max = print_max;
    c->error_hook = on_error;
    c->error_user = log;
}

int fs_error_log_json(const fs_error_log *log, json_t *into)
{
    json_t *list = json_array();
    int rc = json_object_set_new(into, "errors_total", json_integer((json_int_t)log->total)) |
             json_object_set_new(into, "errors", list);
    for (size_t i = 0; list && i < log->n; i++) {
        char b[16];
        rc |= json_array_append_new(list, json_pack("{s:I, s:o, s:s}", "call", (json_int_t)log->entries[i].call,
                                                     "command", fs_json_text(log->entries[i].command), "error",
                                                     fs_error_name(log->entries[i].error, b)));
    }
    return rc ? -1 : 0;
}

void fs_error_log_summary(const fs_error_log *log, FILE *f, const char *prog)
{
    if (!log->total)
        return;
    fprintf(f, "%s: %llu GL error%s raised", prog, (unsigned long long)log->total,
            log->total == 1 ? "" : "s");
    if (log->print && log->total > log->print_max)
        fprintf(f, " (the first %u printed above)", log->print_max);
    fprintf(f, "; %s in the statistics file's \"errors\"%s\n",
            log->total > FS_ERROR_LOG_MAX ? "the first 10000" : "each",
            log->total > FS_ERROR_LOG_MAX ? ", with errors_total" : "");
}

void fs_error_log_free(fs_error_log *log)
{
    free(log->entries);
    log->entries = NULL;
    log->n = log->cap = 0;
}
