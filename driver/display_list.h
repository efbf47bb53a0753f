/* Display lists (GL 1.5 spec 5.4): compiled fs_call records. */
#ifndef FS_DISPLAY_LIST_H
#define FS_DISPLAY_LIST_H
#include <stdbool.h>
#include "gl_call.h"

bool fs_dlist_compiling(const fs_context *c);
/* Appends a deep copy of the call to the list being compiled.  Calls that
 * read client arrays are stored with the array data they dereference.  In
 * GL_COMPILE_AND_EXECUTE mode it executes through `run` what is due now:
 * usually the call, but vertex attributes between glBegin and glEnd are
 * held until the next vertex, as Mesa's compiler holds them (display_list.c,
 * vbo_role).  Returns run's first nonzero result, else 0. */
int fs_dlist_compile(fs_context *c, fs_call *call, int (*run)(fs_context *, fs_call *));
void fs_dlist_free_all(fs_context *c);
/* GL_LIST_MODE and GL_LIST_INDEX (table 6.32): the list being compiled
 * and its mode, both 0 outside glNewList/glEndList. */
void fs_dlist_building(const fs_context *c, GLenum *mode, GLuint *index);
#endif
