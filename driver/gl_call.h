/*
 * A GL call as data.  The public fsgl* entry points, the trace reader, the trace
 * writer and display lists all speak fs_call, so one dispatcher executes calls
 * from every source (the TinyGL idea of one command table, see
 * shared/style-anchors.md).  Everything here is generated from
 * driver/gl_commands.def.
 */
#ifndef FS_GL_CALL_H
#define FS_GL_CALL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

/* Argument kinds.  Scalars are held in fs_arg.i (integers, enums) or fs_arg.d
 * (floating point); arrays, blobs and outputs in fs_arg.p with fs_arg.count
 * elements (bytes for BLOB and OV). */
#define FS_KINDS(X) \
    X(V)   X(E)   X(BM)  X(B)   X(I)   X(U)   X(SZ)  X(UB)  X(BY)  X(S)  X(US) \
    X(F)   X(D)   X(CF)  X(CD)  \
    X(AF)  X(AD)  X(AI)  X(AU)  X(AUB) X(ABY) X(AS)  X(AUS) \
    X(BLOB) X(CPTR) X(OV) X(OF) X(OD) X(OI) X(OU) X(OUS) X(OB) X(OUB) X(STR) \
    X(IP) X(OP) X(P) X(AP)

enum fs_kind {
#define FS_KIND_ENUM(k) FS_K_##k,
    FS_KINDS(FS_KIND_ENUM)
#undef FS_KIND_ENUM
    FS_K_COUNT
};

/* C types of each kind, used by the generated prototypes. */
#define FS_CT_V void
#define FS_CT_E GLenum
#define FS_CT_BM GLbitfield
#define FS_CT_B GLboolean
#define FS_CT_I GLint
#define FS_CT_U GLuint
#define FS_CT_SZ GLsizei
#define FS_CT_UB GLubyte
#define FS_CT_BY GLbyte
#define FS_CT_S GLshort
#define FS_CT_US GLushort
#define FS_CT_F GLfloat
#define FS_CT_D GLdouble
#define FS_CT_CF GLclampf
#define FS_CT_CD GLclampd
#define FS_CT_AF const GLfloat *
#define FS_CT_AD const GLdouble *
#define FS_CT_AI const GLint *
#define FS_CT_AU const GLuint *
#define FS_CT_AUB const GLubyte *
#define FS_CT_ABY const GLbyte *
#define FS_CT_AS const GLshort *
#define FS_CT_AUS const GLushort *
#define FS_CT_BLOB const GLvoid *
#define FS_CT_CPTR const GLvoid *
#define FS_CT_OV GLvoid *
#define FS_CT_OF GLfloat *
#define FS_CT_OD GLdouble *
#define FS_CT_OI GLint *
#define FS_CT_OU GLuint *
#define FS_CT_OUS GLushort * /* glGetPixelMapusv */
#define FS_CT_OB GLboolean *
/* glGetPolygonStipple's mask: bytes like OV (apitrace records an opaque
 * pointer), typed as the GL prototype. */
#define FS_CT_OUB GLubyte *
#define FS_CT_STR const GLubyte *
/* GL 1.5's GLintptr and GLsizeiptr (the same C type), glGetBufferPointerv's
 * output and glMapBuffer's result. */
#define FS_CT_IP GLintptr
#define FS_CT_OP GLvoid **
#define FS_CT_P GLvoid *
/* glMultiDrawElements' indices: one pointer per draw, each an address of
 * the caller's memory or, with an element array buffer bound, an offset
 * into it (GL 1.5 spec 2.9.2).  fs_arg.p holds the array of count
 * pointers; is_data is FS_ARG_ADDR when they are addresses a trace
 * recorded (offsets, or the traced program's memory), else 0 (pointers to
 * indices, or offsets given by the program).  A trace's blobs are checked
 * against what each draw reads when the call is read (driver/replay.c). */
#define FS_CT_AP const GLvoid *const *

/* Command flags. */
#define FS_F_LIST 0x1u   /* compiled into display lists */
#define FS_F_NOLIST 0x2u /* executed immediately even while compiling (GL 1.5 spec 5.4) */
#define FS_F_DRAW 0x4u   /* reads client vertex arrays */
#define FS_F_FRAME 0x8u  /* may mark the end of a frame (glFinish/glFlush) */
#define FS_F_PRIM 0x10u  /* allowed between glBegin and glEnd (GL 1.5 spec 2.6.3) */
/* A command of one of fragsim's own extensions (glext/): OSMesa has no such
 * entry point, so the reference dispatcher (osmesa_ref.c) skips it.  Such
 * rows are written FS_CMD_EXT in gl_commands.def (see there). */
#define FS_F_EXT 0x20u
/* A trace pseudo-call (apitrace's memcpy), no GL entry point: the shim does
 * not export it (rows written FS_CMD_TRACE). */
#define FS_F_TRACE 0x40u
/* The elements glGen{Textures,Buffers,Queries} write: n, but no more than
 * one past the most names a context holds (FS_MAX_NAMES, pipeline/
 * context.h), since beyond it the command is GL_OUT_OF_MEMORY with nothing
 * written.  A bad trace's n = 2^28 so costs no gigabyte of output space
 * before the command refuses it (make fuzz found 3.5 s units). */
#define FS_GEN_NAMES_MAX 1048576
#define FS_GEN_COUNT(n) ((int64_t)(n) > FS_GEN_NAMES_MAX ? (int64_t)FS_GEN_NAMES_MAX + 1 : (int64_t)(n))
#define LIST FS_F_LIST
#define NOLIST FS_F_NOLIST

#define FS_MAX_ARGS 11 /* glTexSubImage3D */

typedef struct fs_arg {
    union {
        int64_t i;
        double d;
        const void *p;
        void *out;
    };
    uint32_t count; /* elements for arrays/outputs, bytes for BLOB/OV */
    /* For CPTR: FS_ARG_DATA when p is trace-provided data (a blob), 0 when p
     * is an address in the caller's memory or a buffer offset.  For CPTR and
     * a draw's BLOB: FS_ARG_ADDR when p is an address a trace recorded (an
     * offset into a bound buffer object, or the traced program's memory,
     * which is never dereferenced). */
    uint32_t is_data;
} fs_arg;
#define FS_ARG_DATA 1u
#define FS_ARG_ADDR 2u

typedef struct fs_call {
    uint16_t cmd;   /* enum fs_cmd */
    uint16_t nargs;
    uint32_t flags; /* FS_CALL_* */
    fs_arg a[FS_MAX_ARGS];
    fs_arg ret;
} fs_call;

#define FS_CALL_FAKE 0x1u /* apitrace "fake" call: client array data before a draw */

/* ---- generated from the table ---- */
enum fs_cmd {
#define FS_CMD(name, rk, flags, n, ...) FS_CMD_##name,
#include "gl_commands.def"
#undef FS_CMD
    FS_CMD_COUNT
};

typedef struct fs_cmd_info {
    const char *name;           /* GL name, with the "gl" prefix */
    uint8_t ret;                /* enum fs_kind */
    uint8_t nargs;
    uint32_t flags;
    uint8_t kinds[FS_MAX_ARGS];  /* enum fs_kind per argument */
    const char *argnames[FS_MAX_ARGS];
} fs_cmd_info;

extern const fs_cmd_info fs_cmd_table[FS_CMD_COUNT];
extern const char *const fs_kind_names[FS_K_COUNT];

/* Looks a GL call name ("glVertex3f") up; returns -1 when fragsim has no such
 * command. */
int fs_cmd_lookup(const char *name);

/* Argument-list plumbing for the X-macros: each argument is a tuple
 * (KIND, name, count); FS_MAPn applies m(index, KIND, name, count). */
#define FS_EXP(x) x
#define FS_APPLY(m, k, t) FS_EXP(m FS_APPLY_I(k, FS_UNPACK t))
#define FS_UNPACK(...) __VA_ARGS__
#define FS_APPLY_I(k, ...) (k, __VA_ARGS__)
#define FS_MAP0(m, ...)
#define FS_MAP1(m, a) FS_APPLY(m, 0, a)
#define FS_MAP2(m, a, b) FS_MAP1(m, a) FS_APPLY(m, 1, b)
#define FS_MAP3(m, a, b, c) FS_MAP2(m, a, b) FS_APPLY(m, 2, c)
#define FS_MAP4(m, a, b, c, d) FS_MAP3(m, a, b, c) FS_APPLY(m, 3, d)
#define FS_MAP5(m, a, b, c, d, e) FS_MAP4(m, a, b, c, d) FS_APPLY(m, 4, e)
#define FS_MAP6(m, a, b, c, d, e, f) FS_MAP5(m, a, b, c, d, e) FS_APPLY(m, 5, f)
#define FS_MAP7(m, a, b, c, d, e, f, g) FS_MAP6(m, a, b, c, d, e, f) FS_APPLY(m, 6, g)
#define FS_MAP8(m, a, b, c, d, e, f, g, h) FS_MAP7(m, a, b, c, d, e, f, g) FS_APPLY(m, 7, h)
#define FS_MAP9(m, a, b, c, d, e, f, g, h, i) FS_MAP8(m, a, b, c, d, e, f, g, h) FS_APPLY(m, 8, i)
#define FS_MAP10(m, a, b, c, d, e, f, g, h, i, j) FS_MAP9(m, a, b, c, d, e, f, g, h, i) FS_APPLY(m, 9, j)
#define FS_MAP11(m, a, b, c, d, e, f, g, h, i, j, k) FS_MAP10(m, a, b, c, d, e, f, g, h, i, j) FS_APPLY(m, 10, k)
#define FS_MAP(n, m, ...) FS_MAP##n(m, __VA_ARGS__)

#define FS_PDECL(k, kind, name, cnt) , FS_CT_##kind name

/* Public API: fsglName(ctx, args...) behaves like glName on context ctx
 * (records it when capturing, compiles it when inside glNewList, executes it). */
#define FS_CMD(name, rk, flags, n, ...) \
    FS_CT_##rk fsgl##name(fs_context *c FS_MAP(n, FS_PDECL, __VA_ARGS__));
#include "gl_commands.def"
#undef FS_CMD

/* Executors: the implementation of each command, one per command, defined in
 * the pipeline file that owns the GL spec section.  A command whose executor
 * is not written yet falls back to a weak stub that counts it as unsupported. */
#define FS_CMD(name, rk, flags, n, ...) \
    FS_CT_##rk fs_exec_##name(fs_context *c FS_MAP(n, FS_PDECL, __VA_ARGS__));
#include "gl_commands.def"
#undef FS_CMD

/* Routes a call as a GL implementation receives it: compiles it while a
 * display list is being defined, executes it, records it when capturing
 * (driver/dispatch.c).  Returns fs_dispatch's result. */
int fs_submit(fs_context *c, fs_call *call);
/* Executes a call now (no capture, no compilation).  Returns 0, or -1 when
 * an array argument is shorter than the command reads (malformed input). */
int fs_dispatch(fs_context *c, fs_call *call);

/* Whether sampled mode may leave the call out of a frame it interpolates
 * (fs_cycle_frame_skipped): a draw, what is allowed between glBegin and
 * glEnd, glBegin itself, a clear or a read-back; never while a display list
 * is compiled (the call goes into the list). */
bool fs_cmd_skippable(const fs_context *c, int cmd);
/* How many calls of cmd were counted unsupported (a command without an
 * executor); 0 for every command while none was. */
uint64_t fs_cmd_unsupported(const fs_context *c, int cmd);
/* Frees what the driver keeps in the context (display lists, the counts by
 * command); the driver sets it as c->driver_free (pipeline/context.h). */
void fs_driver_state_free(fs_context *c);

/* Checks array arguments against what the command reads, without a
 * context.  Returns 0, or -1 - k when argument k is too short. */
int fs_call_validate(const fs_call *call);

/* Size helpers used by the count expressions in the table (driver/gl_sizes.c). */
int64_t fs_index_bytes(GLsizei count, GLenum type);
int64_t fs_calllists_bytes(GLsizei n, GLenum type);
int fs_light_param_count(GLenum pname);
int fs_lightmodel_param_count(GLenum pname);
int fs_fog_param_count(GLenum pname);
int fs_material_param_count(GLenum pname);
int fs_get_count(GLenum pname);
int64_t fs_readpixels_bytes(fs_context *c, GLsizei w, GLsizei h, GLenum format, GLenum type);
/* Elements glPixelMap* reads and glGetPixelMap* writes (pipeline/pixel_map.h). */
int fs_pixel_map_count(GLsizei mapsize);
int fs_pixel_map_size(const fs_context *c, GLenum map);
int fs_type_size(GLenum type); /* bytes of GL_FLOAT, GL_UNSIGNED_BYTE, ...; 0 if unknown */
/* Bytes per element of an array kind (BLOB: 1); 0 for kinds that are not arrays. */
size_t fs_kind_elem_size(int kind);
/* The vertices a draw call (FS_F_DRAW) reads from client arrays: indices
 * *lo..*hi.  False when it reads none: no vertex, a negative first index, an
 * unknown index type, or an index blob shorter than the count. */
bool fs_draw_vertex_range(const fs_call *call, int64_t *lo, int64_t *hi);
/* For glVertexPointer, glNormalPointer, glColorPointer and glTexCoordPointer:
 * the client array they set (0 vertex, 1 normal, 2 colour, 3 texcoord) and
 * in *pk the index of their pointer argument; -1 for other commands. */
int fs_pointer_slot(int cmd, int *pk);
/* Occlusion tiles glOcclusionBuffers expects a size for (units/occlusion_gl.c). */
int fs_occlusion_tile_count(fs_context *c);
/* Texture unit (units/texture_object.c): bytes a glTexImage2D image reads
 * under the current unpack state, values of glTexParameter*v/glTexEnv*v. */
int64_t fs_teximage_bytes(fs_context *c, GLsizei w, GLsizei h, GLenum format, GLenum type);
/* The same for an image of dims 1, 2 or 3 (glTexImage1D/3D, glTexSubImage1D/3D). */
int64_t fs_teximage_nd_bytes(fs_context *c, int dims, GLsizei w, GLsizei h, GLsizei d, GLenum format, GLenum type);
int fs_texparam_count(GLenum pname);
/* Evaluators (pipeline/evaluator.c): the elements glMap1 and glMap2 read
 * (0 for arguments they refuse), the values glGetMap writes. */
int64_t fs_map1_points(GLenum target, GLint stride, GLint order);
int64_t fs_map2_points(GLenum target, GLint ustride, GLint uorder, GLint vstride, GLint vorder);
int fs_getmap_count(fs_context *c, GLenum target, GLenum query);
int fs_texenv_count(GLenum pname);
int fs_point_param_count(GLenum pname); /* values of glPointParameter*v (pipeline/point_state.c) */
int fs_texgen_count(GLenum pname); /* values of glTexGen*v, glGetTexGen*v (pipeline/texgen.c) */
/* Bytes glGetTexImage writes under the current pack state (0 when it
 * writes nothing: an error or an undefined level). */
int64_t fs_gettexImage_bytes(fs_context *c, GLenum target, GLint level, GLenum format, GLenum type);
/* Bytes glGetCompressedTexImage writes (units/texture_compressed.c; 0 when
 * it writes nothing: an error or a level that is not compressed). */
int64_t fs_getcompressed_bytes(fs_context *c, GLenum target, GLint level);

#endif
