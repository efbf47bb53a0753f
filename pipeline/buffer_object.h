/*
 * Buffer objects (GL 1.5 spec 2.9): named arrays of bytes in the model's
 * memory, bound to GL_ARRAY_BUFFER or GL_ELEMENT_ARRAY_BUFFER, filled by
 * glBufferData/glBufferSubData or through a mapping, and the source of
 * vertex arrays and of glDrawElements' indices given as offsets into them
 * (2.9.1, 2.9.2).  The bindings are client state (fs_array_state), the
 * objects live in c->buffers, created on first use.
 */
#ifndef FS_BUFFER_OBJECT_H
#define FS_BUFFER_OBJECT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "context.h"

/* Largest store one buffer object may have: a bigger glBufferData (a bad
 * trace asking for 2^40 bytes) is GL_OUT_OF_MEMORY, which GL allows for any
 * command (2.5), instead of an unbounded allocation. */
#define FS_BUFFER_MAX_BYTES ((int64_t)1 << 30)

void fs_buffer_objects_free(fs_context *c);

/* The array state for one draw (*out, which may be &c->arrays): every
 * array that sources a buffer object as plain memory, pointing into the
 * store with `bytes` what is left of it after the offset (0 when the
 * offset lies beyond it or the buffer is gone), so that the dispatcher's
 * bounds check refuses any read past the store; and no element array
 * buffer, its indices being resolved already.  A display list compiled
 * from it keeps its own copies, which sources no buffer. */
void fs_buffer_resolve_arrays(const fs_context *c, fs_array_state *out);
/* The element array buffer's store from byte `offset` on, for the indices
 * of glDrawElements while a buffer is bound to GL_ELEMENT_ARRAY_BUFFER
 * (2.9.2), with *bytes what is left of it; NULL (and *bytes 0) when the
 * offset lies beyond the store or the store is empty. */
const void *fs_buffer_element_data(const fs_context *c, uint64_t offset, size_t *bytes);

/* The mapped range of the buffer bound on target, with its size; NULL when
 * the buffer bound there is not mapped (for capture, which records the
 * writes through a mapping as apitrace does). */
const void *fs_buffer_mapping(const fs_context *c, GLenum target, int64_t *size);

#endif
