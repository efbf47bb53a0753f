/*
 * The shim driver (build/libfragsimGL.so): GL and OSMesa entry points under
 * their real names, so that a program written for OSMesa runs on the model
 * unchanged.  shim_gl.c holds the GL entry points, generated from
 * gl_commands.def; shim_osmesa.c the OSMesa context API, the current context
 * and the rule that keeps the caller's buffer up to date; shim_ext.c the
 * extension entry points with their glext/ prototypes.
 *
 * Internal to the shared library: the library is built with
 * -fvisibility=hidden, so only the GL and OSMesa names are exported.
 */
#ifndef FS_SHIM_H
#define FS_SHIM_H
#include "gl_call.h"

#define FS_SHIM_EXPORT __attribute__((visibility("default")))

/* The model context of the calling thread's current OSMesa context, or NULL
 * when none is current: GL calls without a current context do nothing. */
fs_context *fs_shim_begin(void);
/* Runs after each GL call on the current context: keeps the caller's buffer
 * and the capture's frame boundaries up to date (see shim_osmesa.c). */
void fs_shim_end(enum fs_cmd cmd);
/* The exported GL entry point called name, or NULL (shim_gl.c). */
void (*fs_shim_gl_proc(const char *name))(void);
#endif
