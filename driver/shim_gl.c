/*
 * The shim's GL entry points, generated from driver/gl_commands.def:
 * glName(args) calls fsglName(current context, args), so a call from a
 * program takes the same path (display lists, capture, executors) as a call
 * from a trace.  Without a current context a call does nothing and returns
 * zero, as GL leaves the behaviour undefined and OSMesa does nothing.
 */
/* The GL 1.5 entry points (glGenQueries, ...) are declared by GL/glext.h
 * only with prototypes requested.  Declared, every definition below is
 * checked against Mesa's prototype, so a table row with a wrong argument
 * type fails to compile instead of exporting a wrong ABI. */
#define GL_GLEXT_PROTOTYPES 1
#include <string.h>
#include "shim.h"

/* gl.h declares glLoadTransposeMatrix{f,d} and glMultTransposeMatrix{f,d}
 * with an array parameter (const GLfloat m[16]); the generated definitions
 * take the pointer, the same type (C11 6.7.6.3), which gcc 11 and later
 * warn about. */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11
#pragma GCC diagnostic ignored "-Warray-parameter"
#endif

/* Parameter lists: FS_PDECL gives ", T a, T b"; the leading comma is
 * dropped, and a command without arguments gets (void). */
#define FS_SHIM_DROP1(...) FS_SHIM_DROP1_(__VA_ARGS__)
#define FS_SHIM_DROP1_(empty, ...) __VA_ARGS__
#define FS_SHIM_PARAMS(n, ...) FS_SHIM_PARAMS_##n(__VA_ARGS__)
#define FS_SHIM_PARAMS_0(...) void
#define FS_SHIM_PARAMS_1(...) FS_SHIM_DROP1(FS_MAP1(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_2(...) FS_SHIM_DROP1(FS_MAP2(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_3(...) FS_SHIM_DROP1(FS_MAP3(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_4(...) FS_SHIM_DROP1(FS_MAP4(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_5(...) FS_SHIM_DROP1(FS_MAP5(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_6(...) FS_SHIM_DROP1(FS_MAP6(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_7(...) FS_SHIM_DROP1(FS_MAP7(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_8(...) FS_SHIM_DROP1(FS_MAP8(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_9(...) FS_SHIM_DROP1(FS_MAP9(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_10(...) FS_SHIM_DROP1(FS_MAP10(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_PARAMS_11(...) FS_SHIM_DROP1(FS_MAP11(FS_PDECL, __VA_ARGS__))
#define FS_SHIM_ARG(k, kind, name, cnt) , name

/* Result handling per return kind. */
#define FS_SHIM_NONE_V return;
#define FS_SHIM_NONE_U return 0;
#define FS_SHIM_NONE_E return 0;
#define FS_SHIM_NONE_B return GL_FALSE;
#define FS_SHIM_NONE_I return 0;
#define FS_SHIM_NONE_STR return NULL;
#define FS_SHIM_NONE_P return NULL;
#define FS_SHIM_KEEP_V
#define FS_SHIM_KEEP_U r_ =
#define FS_SHIM_KEEP_E r_ =
#define FS_SHIM_KEEP_B r_ =
#define FS_SHIM_KEEP_I r_ =
#define FS_SHIM_KEEP_STR r_ =
#define FS_SHIM_KEEP_P r_ =
#define FS_SHIM_DECL_V
#define FS_SHIM_DECL_U GLuint r_;
#define FS_SHIM_DECL_E GLenum r_;
#define FS_SHIM_DECL_B GLboolean r_;
#define FS_SHIM_DECL_I GLint r_;
#define FS_SHIM_DECL_STR const GLubyte *r_;
#define FS_SHIM_DECL_P GLvoid *r_;
#define FS_SHIM_RET_V
#define FS_SHIM_RET_U return r_;
#define FS_SHIM_RET_E return r_;
#define FS_SHIM_RET_B return r_;
#define FS_SHIM_RET_I return r_;
#define FS_SHIM_RET_STR return r_;
#define FS_SHIM_RET_P return r_;

#define FS_SHIM_BODY(name, rk, n, ...)                                        \
    {                                                                          \
        FS_SHIM_DECL_##rk                                                      \
        fs_context *c = fs_shim_begin();                                       \
        if (!c)                                                                \
            FS_SHIM_NONE_##rk                                                  \
        FS_SHIM_KEEP_##rk fsgl##name(c FS_MAP(n, FS_SHIM_ARG, __VA_ARGS__));   \
        fs_shim_end(FS_CMD_##name);                                            \
        FS_SHIM_RET_##rk                                                       \
    }

#define FS_CMD(name, rk, flags, n, ...)                                        \
    FS_SHIM_EXPORT FS_CT_##rk gl##name(FS_SHIM_PARAMS(n, __VA_ARGS__))         \
    FS_SHIM_BODY(name, rk, n, __VA_ARGS__)
/* Commands of fragsim's own extensions are declared by their glext/ header
 * with types the table's kinds do not always spell (glOcclusionBuffers takes
 * GLuint **, the table an opaque pointer).  They are generated weak, with the
 * table's types, and shim_ext.c defines each one again with its header's
 * prototype; a row added without a definition there is still exported. */
#define FS_CMD_EXT(name, rk, flags, n, ...)                                    \
    __attribute__((weak)) FS_SHIM_EXPORT FS_CT_##rk gl##name(                  \
        FS_SHIM_PARAMS(n, __VA_ARGS__))                                        \
    FS_SHIM_BODY(name, rk, n, __VA_ARGS__)
/* Trace pseudo-calls are no GL entry points: not exported. */
#define FS_CMD_TRACE(name, rk, flags, n, ...)
#include "gl_commands.def"
#undef FS_CMD
#undef FS_CMD_EXT
#undef FS_CMD_TRACE

/* For OSMesaGetProcAddress: every entry point by command id. */
typedef void (*fs_shim_proc)(void);
static const fs_shim_proc procs[FS_CMD_COUNT] = {
#define FS_CMD(name, rk, flags, n, ...) (fs_shim_proc)gl##name,
#define FS_CMD_TRACE(name, rk, flags, n, ...) NULL,
#include "gl_commands.def"
#undef FS_CMD
#undef FS_CMD_TRACE
};

fs_shim_proc fs_shim_gl_proc(const char *name)
{
    int cmd = fs_cmd_lookup(name);
    return cmd < 0 ? NULL : procs[cmd];
}
