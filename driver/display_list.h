/* Display lists (GL 1.5 spec 5.4): compiled fs_call records. */
#ifndef FS_DISPLAY_LIST_H
#define FS_DISPLAY_LIST_H
#include <stdbool.h>
#include "gl_call.h"

bool fs_dlist_compiling(const fs_context *c);
/* True while compiling with GL_COMPILE_AND_EXECUTE. */
bool fs_dlist_execute_too(const fs_context *c);
/* Appends a deep copy of the call to the list being compiled.  Calls that
 * read client arrays are stored with the array data they dereference. */
void fs_dlist_compile(fs_context *c, const fs_call *call);
void fs_dlist_free_all(fs_context *c);
#endif
