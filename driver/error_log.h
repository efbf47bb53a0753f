/*
 * Every GL error a replay (or the shim) raises, with the number and name of
 * the call that raised it: what glretrace prints as
 * "N: warning: glGetError(glName) = GL_INVALID_ENUM", and what the
 * statistics file lists under "errors".  Fed by the context's error hook
 * (fs_context.error_hook, called by fs_error); an error raised while a
 * display list executes belongs to the glCallList that executes it.
 */
#ifndef FS_ERROR_LOG_H
#define FS_ERROR_LOG_H
#include <stdint.h>
#include <stdio.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

#define FS_ERROR_LOG_MAX 10000 /* errors kept with their call; all are counted */

typedef struct fs_error_entry {
    uint64_t call;
    const char *command;
    GLenum error;
} fs_error_entry;

typedef struct fs_error_log {
    uint64_t call;           /* the call being executed: set before each call */
    const char *command;     /* its name; must live as long as the log */
    fs_error_entry *entries;
    size_t n, cap;
    uint64_t total;          /* every error raised, kept or not */
    FILE *print;             /* where to print the first print_max errors as they come, or NULL */
    unsigned print_max;
} fs_error_log;

/* Clears log and makes it receive c's errors. */
void fs_error_log_attach(fs_error_log *log, fs_context *c);
/* Sets two members of the JSON object into (jansson): "errors_total": N
 * and "errors": [{"call": N, "command": "glName", "error": "GL_..."}, ...].
 * 0, or -1 when out of memory. */
struct json_t;
int fs_error_log_json(const fs_error_log *log, struct json_t *into);
/* After a run: "N GL errors" and how many were printed, if any. */
void fs_error_log_summary(const fs_error_log *log, FILE *f, const char *prog);
void fs_error_log_free(fs_error_log *log);
/* GL_INVALID_ENUM, ...; the number in hex for a value GL does not define. */
const char *fs_error_name(GLenum err, char buf[16]);
#endif
