/*
 * The GL state table (pipeline/state.def; GL 1.5 spec section 6.2) and
 * what is generated from it (pipeline/state.c): initial values, glGet of
 * the stored variables (6.1.2), the enable caps, the attribute stacks
 * (6.1.14, glPushAttrib/glPopAttrib, glPushClientAttrib/glPopClientAttrib)
 * and the dirty bits.
 */
#ifndef FS_STATE_H
#define FS_STATE_H
#include <stdbool.h>
#include <stdint.h>
#include <GL/gl.h>

typedef struct fs_context fs_context;

/* Stack depths: the spec's minimum, and what OSMesa (Mesa 22) reports for
 * GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH. */
#define FS_ATTRIB_STACK_DEPTH 16
#define FS_CLIENT_ATTRIB_STACK_DEPTH 16

/* The groups of a state variable and the dirty bits are glPushAttrib's
 * bits (GL 1.5 uses bits 0-19 and 29), with the two client groups in bits
 * 20 and 21, which GL leaves unused. */
#define FS_CLIENT_PIXEL_STORE (1u << 20)
#define FS_CLIENT_VERTEX_ARRAY (1u << 21)
#define FS_CLIENT_GROUPS (FS_CLIENT_PIXEL_STORE | FS_CLIENT_VERTEX_ARRAY)
/* A dirty bit that is no group: the occlusion render modes' suppression
 * of writes (units/occlusion_gl.c; Huettner 1999, 3.2.1), which no
 * glPushAttrib saves. */
#define FS_DIRTY_OCCLUSION_MODE (1u << 22)

/* GL 1.5 spec 2.11: the clip planes beyond the six gl.h names are
 * GL_CLIP_PLANE0 + i (llvmpipe has 8). */
#ifndef GL_CLIP_PLANE6
#define GL_CLIP_PLANE6 (GL_CLIP_PLANE0 + 6)
#define GL_CLIP_PLANE7 (GL_CLIP_PLANE0 + 7)
#endif

/* How a value converts for glGet (GL 1.5 spec 6.1.2): NUM rounds to the
 * nearest integer, NORM (colours, normals, depth values) maps [-1,1]
 * linearly onto the integer range, BOOL and ENUM convert as numbers. */
enum fs_get_class { FS_GET_NUM, FS_GET_NORM, FS_GET_BOOL, FS_GET_ENUM };

typedef struct fs_get_value {
    int n;
    enum fs_get_class cls;
    double v[16];
} fs_get_value;

/* One row of the table. */
enum fs_state_kind { FS_STATE_FIELD, FS_STATE_COMPUTED, FS_STATE_CONSTANT, FS_STATE_PUSH_ONLY };
enum fs_state_cap { FS_CAP_NO, FS_CAP_EN, FS_CAP_ENU, FS_CAP_CLI };
typedef struct fs_state_info {
    GLenum name;          /* 0 for push-only rows */
    const char *label;    /* "GL_..." */
    uint32_t groups;
    enum fs_get_class cls;
    int count;
    enum fs_state_kind kind;
    enum fs_state_cap cap;
} fs_state_info;

/* Every row, in the table's order. */
const fs_state_info *fs_state_rows(int *count);

/* Sets every variable with an initial value in the table. */
void fs_state_init(fs_context *c);
/* glGet of a stored or constant variable: false when pname is not one
 * (computed rows are the driver's, driver/gl_state.c). */
bool fs_state_get(fs_context *c, GLenum pname, fs_get_value *r);
/* The number of values glGet returns for pname (1 for names not in the table). */
int fs_state_count(GLenum pname);
/* The flag of an enable cap of the given kind (FS_CAP_EN and FS_CAP_ENU
 * for glEnable, also FS_CAP_CLI for glIsEnabled), or NULL; *row its row. */
bool *fs_state_cap_flag(fs_context *c, GLenum cap, bool client_too, const fs_state_info **row);
/* The field of a stored variable in one of the groups, or NULL; *row
 * (if row is not NULL) its row. */
void *fs_state_field(fs_context *c, GLenum pname, uint32_t groups, const fs_state_info **row);
/* Marks groups dirty (fs_context.dirty), for the validation step. */
void fs_state_mark(fs_context *c, uint32_t groups);
/* Frees the attribute stacks. */
void fs_state_free(fs_context *c);
#endif
