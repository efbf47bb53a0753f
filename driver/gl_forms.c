/*
 * The executors of driver/gl_commands_forms.def: every other type and
 * vector form of glColor, glNormal, glTexCoord, glIndex and glRect (GL 1.5
 * spec 2.7, 2.10) converts its arguments and calls the executor of the form
 * the model implements, so all forms take one path.  Generated from the
 * rows; nothing here is written per command.
 */
#include "gl_call.h"

/* FS_FORM_V: the elements of the array as arguments. */
#define FS_FORM_VEC_1(v) v[0]
#define FS_FORM_VEC_2(v) v[0], v[1]
#define FS_FORM_VEC_3(v) v[0], v[1], v[2]
#define FS_FORM_VEC_4(v) v[0], v[1], v[2], v[3]
#define FS_FORM_V(name, to, ak, n) \
    void fs_exec_##name(fs_context *c, FS_CT_##ak v) { fs_exec_##to(c, FS_FORM_VEC_##n(v)); }

/* FS_FORM_F: each argument converted to float, as the float form takes it. */
#define FS_FORM_TOF(k, kind, name, cnt) , (GLfloat)name
#define FS_FORM_EXEC_F__(name, to, n, ...)                                                   \
    void fs_exec_##name(fs_context *c FS_MAP(n, FS_PDECL, __VA_ARGS__))                    \
    {                                                                                        \
        fs_exec_##to(c FS_MAP(n, FS_FORM_TOF, __VA_ARGS__));                                 \
    }
#define FS_FORM_EXEC_F_(name, to, ...) FS_FORM_EXEC_F__(name, to, __VA_ARGS__)
#define FS_FORM_F(name, to, k, n, names) FS_FORM_EXEC_F_(name, to, FS_FORM_ARGS_##names##_##n(k))

/* FS_FORM_RV: glRect's two corners. */
#define FS_FORM_RV(name, to, ak) \
    void fs_exec_##name(fs_context *c, FS_CT_##ak v1, FS_CT_##ak v2) { fs_exec_##to(c, v1[0], v1[1], v2[0], v2[1]); }

#define FS_CMD(...)
#include "gl_commands_forms.def"
#undef FS_CMD
