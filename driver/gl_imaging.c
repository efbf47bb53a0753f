/*
 * The executors of driver/gl_commands_imaging.def, generated: each raises
 * GL_INVALID_OPERATION and does nothing else, as OSMesa (llvmpipe, which
 * does not expose GL_ARB_imaging) answers every call of the imaging subset
 * (measured: tests/test_imaging.c).
 */
#include "gl_call.h"
#include "../pipeline/context.h"

#define FS_IMAGING_UNUSED(k, kind, name, cnt) (void)name;
#define FS_CMD_IMAGING(name, n, ...)                                           \
    void fs_exec_##name(fs_context *c FS_MAP(n, FS_PDECL, __VA_ARGS__))        \
    {                                                                          \
        FS_MAP(n, FS_IMAGING_UNUSED, __VA_ARGS__)                              \
        fs_error(c, GL_INVALID_OPERATION);                                     \
    }
#include "gl_commands_imaging.def"
