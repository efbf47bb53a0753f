/* The per-call GL error log (error_log.h). */
#include <stdlib.h>
#include <string.h>
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

static void json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; s && *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(f, "\\u%04x", *s);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

void fs_error_log_write_json(const fs_error_log *log, FILE *f, const char *indent)
{
    fprintf(f, "%s\"errors_total\": %llu,\n%s\"errors\": [", indent, (unsigned long long)log->total,
            indent);
    for (size_t i = 0; i < log->n; i++) {
        char b[16];
        fprintf(f, "%s\n%s  {\"call\": %llu, \"command\": ", i ? "," : "", indent,
                (unsigned long long)log->entries[i].call);
        json_str(f, log->entries[i].command);
        fprintf(f, ", \"error\": \"%s\"}", fs_error_name(log->entries[i].error, b));
    }
    fprintf(f, "%s%s]", log->n ? "\n" : "", log->n ? indent : "");
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
