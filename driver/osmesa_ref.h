/*
 * The reference renderer: Mesa's OSMesa (llvmpipe) in this process, fed the
 * same decoded fs_call stream as the model.  CLI and tools only; the library
 * core does not link OSMesa.
 */
#ifndef FS_OSMESA_REF_H
#define FS_OSMESA_REF_H
#include <stdint.h>
#include "gl_call.h"

typedef struct fs_osmesa fs_osmesa;

/* Creates an RGBA8 context with the given depth and stencil bits and makes
 * it current.  NULL with a message in err on failure. */
fs_osmesa *fs_osmesa_create(int width, int height, int depth_bits, int stencil_bits, char *err, size_t errlen);
/* Executes one call with the real gl* entry point.  Returns 0, or -1 when
 * the call's arrays are too short (it is then not executed). */
int fs_osmesa_dispatch(fs_osmesa *o, const fs_call *call);
/* Finishes rendering and returns the colour buffer (rows bottom-up, RGBA8)
 * and the depth buffer as values in [0, 2^depth_bits - 1]. */
const uint8_t *fs_osmesa_color(fs_osmesa *o);
const uint32_t *fs_osmesa_depth(fs_osmesa *o);
/* Counting samples per frame: begin a GL_SAMPLES_PASSED query now, and end
 * it and return its result (fragments that passed the depth and stencil
 * tests since the begin).  Returns -1 when the query failed. */
void fs_osmesa_samples_begin(fs_osmesa *o);
int64_t fs_osmesa_samples_end(fs_osmesa *o);
void fs_osmesa_destroy(fs_osmesa *o);
#endif
