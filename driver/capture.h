/*
 * Capture mode: every fs_call submitted to a context is written to an
 * apitrace trace (driver/trace.h), with client-array data written as
 * apitrace does, as "fake" glXxxPointer calls carrying a blob before each
 * draw call that reads them.
 */
#ifndef FS_CAPTURE_H
#define FS_CAPTURE_H
#include <stddef.h>
#include "gl_call.h"

/* Starts recording to path.  Returns 0, or -1 with a message in err. */
int fs_capture_open(fs_context *c, const char *path, char *err, size_t errlen);
/* Writes the call (after it was executed, so return values are known). */
void fs_capture_call(fs_context *c, const fs_call *call);
/* Writes a frame boundary (glXSwapBuffers, as apitrace records it). */
void fs_capture_frame_end(fs_context *c);
/* Finishes the file.  Returns 0, or -1 when writing failed. */
int fs_capture_close(fs_context *c);
#endif
