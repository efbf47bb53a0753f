/*
 * GL enum values and their names, for writing enum arguments the way
 * `apitrace dump` prints them (an apitrace enum value carries its name in an
 * enum signature, docs/FORMAT.markdown "Values") and for reading names back.
 * The table covers the GL 1.0-1.5 core enums (gl.h and the GL_VERSION_1_4/1_5
 * sections of glext.h), which include every enum fragsim's commands take,
 * plus the tokens of fragsim's extensions (GL_FRAGSIM_occlusion_unit,
 * GL_FRAGSIM_mp_grid, GL_FRAGSIM_footprint_filter) and GL_HP_occlusion_test.
 */
#ifndef FS_GL_ENUMS_H
#define FS_GL_ENUMS_H
#include <stdint.h>

/* The usual name of a GL enum value, or NULL when the table has none.
 * Several names share some values; 0 and 1 give GL_ZERO and GL_ONE (use
 * fs_gl_prim_name for primitive modes and the GL_NO_ERROR special case
 * below for glGetError). */
const char *fs_gl_enum_name(uint32_t value);
/* Name of a primitive mode (GL_POINTS ... GL_POLYGON), or NULL. */
const char *fs_gl_prim_name(uint32_t value);
/* The name to print for argument argname of GL command cmdname ("glBegin",
 * "mode") with the given value: primitive names for the mode of glBegin and
 * the draw calls, GL_NO_ERROR for glGetError's return (argname NULL). */
const char *fs_gl_enum_name_for(const char *cmdname, const char *argname, uint32_t value);
/* Value of a GL enum name (any alias); returns 0 and sets *value, or -1. */
int fs_gl_enum_value(const char *name, uint32_t *value);
#endif
