/*
 * Matrix stacks and matrix commands (GL 1.5 spec 2.11.2): MatrixMode,
 * Load/Mult, Translate, Rotate, Scale, Frustum, Ortho, Push/PopMatrix.
 *
 * Arithmetic is in float in the order Mesa uses (m_matrix.c), because the
 * reference rasterizes from positions transformed by these float matrices
 * and a one-ulp difference can move an edge across a pixel centre:
 * double-precision entry points convert their arguments to float first,
 * products accumulate row-by-column left to right, glRotate special-cases
 * rotations about a coordinate axis.
 */
#include <math.h>
#include <stdbool.h>
#include <string.h>
#include "vertex_internal.h"

void fs_mat_identity(float m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
}

void fs_mat_mul(float r[16], const float a[16], const float b[16])
{
    float t[16];
    for (int i = 0; i < 4; i++) {
        const float ai0 = a[i], ai1 = a[4 + i], ai2 = a[8 + i], ai3 = a[12 + i];
        for (int j = 0; j < 4; j++)
            t[j * 4 + i] = ai0 * b[j * 4] + ai1 * b[j * 4 + 1] + ai2 * b[j * 4 + 2] + ai3 * b[j * 4 + 3];
    }
    memcpy(r, t, sizeof t);
}

bool fs_mat_invert(float r[16], const float m[16])
{
    /* Cofactor expansion in double: only lighting normals use the inverse,
     * and there a last-bit difference is far below one colour step. */
    double inv[16], d[16];
    for (int i = 0; i < 16; i++)
        d[i] = m[i];
    inv[0] = d[5] * d[10] * d[15] - d[5] * d[11] * d[14] - d[9] * d[6] * d[15] + d[9] * d[7] * d[14] + d[13] * d[6] * d[11] - d[13] * d[7] * d[10];
    inv[4] = -d[4] * d[10] * d[15] + d[4] * d[11] * d[14] + d[8] * d[6] * d[15] - d[8] * d[7] * d[14] - d[12] * d[6] * d[11] + d[12] * d[7] * d[10];
    inv[8] = d[4] * d[9] * d[15] - d[4] * d[11] * d[13] - d[8] * d[5] * d[15] + d[8] * d[7] * d[13] + d[12] * d[5] * d[11] - d[12] * d[7] * d[9];
    inv[12] = -d[4] * d[9] * d[14] + d[4] * d[10] * d[13] + d[8] * d[5] * d[14] - d[8] * d[6] * d[13] - d[12] * d[5] * d[10] + d[12] * d[6] * d[9];
    inv[1] = -d[1] * d[10] * d[15] + d[1] * d[11] * d[14] + d[9] * d[2] * d[15] - d[9] * d[3] * d[14] - d[13] * d[2] * d[11] + d[13] * d[3] * d[10];
    inv[5] = d[0] * d[10] * d[15] - d[0] * d[11] * d[14] - d[8] * d[2] * d[15] + d[8] * d[3] * d[14] + d[12] * d[2] * d[11] - d[12] * d[3] * d[10];
    inv[9] = -d[0] * d[9] * d[15] + d[0] * d[11] * d[13] + d[8] * d[1] * d[15] - d[8] * d[3] * d[13] - d[12] * d[1] * d[11] + d[12] * d[3] * d[9];
    inv[13] = d[0] * d[9] * d[14] - d[0] * d[10] * d[13] - d[8] * d[1] * d[14] + d[8] * d[2] * d[13] + d[12] * d[1] * d[10] - d[12] * d[2] * d[9];
    inv[2] = d[1] * d[6] * d[15] - d[1] * d[7] * d[14] - d[5] * d[2] * d[15] + d[5] * d[3] * d[14] + d[13] * d[2] * d[7] - d[13] * d[3] * d[6];
    inv[6] = -d[0] * d[6] * d[15] + d[0] * d[7] * d[14] + d[4] * d[2] * d[15] - d[4] * d[3] * d[14] - d[12] * d[2] * d[7] + d[12] * d[3] * d[6];
    inv[10] = d[0] * d[5] * d[15] - d[0] * d[7] * d[13] - d[4] * d[1] * d[15] + d[4] * d[3] * d[13] + d[12] * d[1] * d[7] - d[12] * d[3] * d[5];
    inv[14] = -d[0] * d[5] * d[14] + d[0] * d[6] * d[13] + d[4] * d[1] * d[14] - d[4] * d[2] * d[13] - d[12] * d[1] * d[6] + d[12] * d[2] * d[5];
    inv[3] = -d[1] * d[6] * d[11] + d[1] * d[7] * d[10] + d[5] * d[2] * d[11] - d[5] * d[3] * d[10] - d[9] * d[2] * d[7] + d[9] * d[3] * d[6];
    inv[7] = d[0] * d[6] * d[11] - d[0] * d[7] * d[10] - d[4] * d[2] * d[11] + d[4] * d[3] * d[10] + d[8] * d[2] * d[7] - d[8] * d[3] * d[6];
    inv[11] = -d[0] * d[5] * d[11] + d[0] * d[7] * d[9] + d[4] * d[1] * d[11] - d[4] * d[3] * d[9] - d[8] * d[1] * d[7] + d[8] * d[3] * d[5];
    inv[15] = d[0] * d[5] * d[10] - d[0] * d[6] * d[9] - d[4] * d[1] * d[10] + d[4] * d[2] * d[9] + d[8] * d[1] * d[6] - d[8] * d[2] * d[5];
    double det = d[0] * inv[0] + d[1] * inv[4] + d[2] * inv[8] + d[3] * inv[12];
    if (det == 0.0 || !isfinite(det)) {
        fs_mat_identity(r);
        return false;
    }
    for (int i = 0; i < 16; i++)
        r[i] = (float)(inv[i] / det);
    return true;
}

static fs_matrix *top(fs_context *c)
{
    fs_transform_state *x = &c->xf;
    switch (x->matrix_mode) {
    case GL_PROJECTION: return &x->projection[x->projection_top];
    case GL_TEXTURE: {
        int u = fs_active_unit(c); /* the active unit's stack (2.10.2) */
        return &x->texture[u][x->texture_top[u]];
    }
    default: return &x->modelview[x->modelview_top];
    }
}

const fs_matrix *fs_current_matrix(const fs_context *c, GLenum mode)
{
    const fs_transform_state *x = &c->xf;
    switch (mode) {
    case GL_PROJECTION: return &x->projection[x->projection_top];
    case GL_TEXTURE: {
        int u = fs_active_unit(c);
        return &x->texture[u][x->texture_top[u]];
    }
    default: return &x->modelview[x->modelview_top];
    }
}

/* Multiplies the current matrix by m, adding Mesa's flags for it
 * (matrix_multf; glMultMatrix marks the matrix for analysis from its
 * values). */
static void mult(fs_context *c, const float m[16], unsigned flags)
{
    fs_matrix *t = top(c);
    fs_mat_mul(t->m, t->m, m);
    t->flags = (t->flags | flags) & ~(unsigned)FS_MATF_IDENTITY;
}

/* Mesa skips a glMultMatrix by the identity altogether (matrix.c
 * matrix_mult), leaving the flags as they were; the test compares values,
 * so -0 passes for 0 (measured: sierpinski3d multiplies by such a matrix,
 * and llvmpipe's lighting then follows the flags of the commands around
 * it, tests/test_lighting_order.c). */
static void mult_matrix(fs_context *c, const float m[16])
{
    float id[16];
    fs_mat_identity(id);
    bool same = true;
    for (int i = 0; i < 16; i++)
        same &= m[i] == id[i];
    if (same)
        return;
    mult(c, m, FS_MATF_GENERAL | FS_MATF_DIRTY);
}

/* glLoadMatrix: Mesa changes nothing when the matrix is the same, else
 * analyses the new one from its values. */
static void load_matrix(fs_context *c, const float m[16])
{
    fs_matrix *t = top(c);
    if (memcmp(t->m, m, sizeof t->m) == 0)
        return;
    memcpy(t->m, m, sizeof t->m);
    t->flags = FS_MATF_GENERAL | FS_MATF_DIRTY;
}

void fs_exec_MatrixMode(fs_context *c, GLenum mode)
{
    if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->xf.matrix_mode = mode;
}

void fs_exec_LoadIdentity(fs_context *c)
{
    fs_matrix *t = top(c);
    fs_mat_identity(t->m);
    /* Mesa's _math_matrix_set_identity clears the dirty bits only. */
    t->flags = (t->flags & ~(unsigned)FS_MATF_DIRTY) | FS_MATF_IDENTITY;
}

void fs_exec_LoadMatrixf(fs_context *c, const GLfloat *m)
{
    float f[16];
    memcpy(f, m, sizeof f);
    load_matrix(c, f);
}

/* The double forms convert each element to float first (GL 1.5 2.11.2:
 * the GL computes in float; Mesa converts the same way). */
static void mat_from_double(float f[16], const GLdouble *m)
{
    for (int i = 0; i < 16; i++)
        f[i] = (float)m[i];
}

void fs_exec_LoadMatrixd(fs_context *c, const GLdouble *m)
{
    float f[16];
    mat_from_double(f, m);
    load_matrix(c, f);
}

void fs_exec_MultMatrixf(fs_context *c, const GLfloat *m)
{
    float f[16];
    memcpy(f, m, sizeof f);
    mult_matrix(c, f);
}

void fs_exec_MultMatrixd(fs_context *c, const GLdouble *m)
{
    float f[16];
    mat_from_double(f, m);
    mult_matrix(c, f);
}

/* GL 1.3's transposed forms (2.11.2): LoadTransposeMatrix(m) is
 * LoadMatrix(m^T) and MultTransposeMatrix(m) is MultMatrix(m^T), m given
 * row by row; the double forms convert each element to float as
 * glLoadMatrixd does. */
static void transposed(fs_context *c, const GLfloat *mf, const GLdouble *md, bool load)
{
    float t[16];
    for (int i = 0; i < 16; i++) {
        int k = (i % 4) * 4 + i / 4;
        t[i] = mf ? mf[k] : (float)md[k];
    }
    if (load)
        load_matrix(c, t);
    else
        mult_matrix(c, t);
}

void fs_exec_LoadTransposeMatrixf(fs_context *c, const GLfloat *m) { transposed(c, m, NULL, true); }
void fs_exec_LoadTransposeMatrixd(fs_context *c, const GLdouble *m) { transposed(c, NULL, m, true); }
void fs_exec_MultTransposeMatrixf(fs_context *c, const GLfloat *m) { transposed(c, m, NULL, false); }
void fs_exec_MultTransposeMatrixd(fs_context *c, const GLdouble *m) { transposed(c, NULL, m, false); }

void fs_exec_Translatef(fs_context *c, GLfloat x, GLfloat y, GLfloat z)
{
    /* Only the last column changes; the other products with the identity
     * columns are exact, so updating it alone equals the full product. */
    float *m = top(c)->m;
    m[12] = m[0] * x + m[4] * y + m[8] * z + m[12];
    m[13] = m[1] * x + m[5] * y + m[9] * z + m[13];
    m[14] = m[2] * x + m[6] * y + m[10] * z + m[14];
    m[15] = m[3] * x + m[7] * y + m[11] * z + m[15];
    top(c)->flags = (top(c)->flags | FS_MATF_TRANSLATION) & ~(unsigned)FS_MATF_IDENTITY;
}

void fs_exec_Translated(fs_context *c, GLdouble x, GLdouble y, GLdouble z)
{
    fs_exec_Translatef(c, (float)x, (float)y, (float)z);
}

void fs_exec_Scalef(fs_context *c, GLfloat x, GLfloat y, GLfloat z)
{
    float *m = top(c)->m;
    m[0] *= x; m[4] *= y; m[8] *= z;
    m[1] *= x; m[5] *= y; m[9] *= z;
    m[2] *= x; m[6] *= y; m[10] *= z;
    m[3] *= x; m[7] *= y; m[11] *= z;
    /* Mesa: uniform when the factors agree within 1e-8. */
    bool uniform = fabsf(x - y) < 1e-8f && fabsf(x - z) < 1e-8f;
    top(c)->flags = (top(c)->flags | (uniform ? FS_MATF_UNIFORM_SCALE : FS_MATF_GENERAL_SCALE)) &
                    ~(unsigned)FS_MATF_IDENTITY;
}

void fs_exec_Scaled(fs_context *c, GLdouble x, GLdouble y, GLdouble z)
{
    fs_exec_Scalef(c, (float)x, (float)y, (float)z);
}

void fs_exec_Rotatef(fs_context *c, GLfloat angle, GLfloat x, GLfloat y, GLfloat z)
{
    if (angle == 0.0f)
        return;
    /* The angle converts to radians in double, as Mesa does, before sinf. */
    const float s = sinf((float)(angle * FS_PI / 180.0));
    const float co = cosf((float)(angle * FS_PI / 180.0));
    float m[16];
    fs_mat_identity(m);
#define M_(row, col) m[(col) * 4 + (row)]
    bool axis = false;
    if (x == 0.0f && y == 0.0f && z != 0.0f) {
        axis = true;
        M_(0, 0) = co; M_(1, 1) = co;
        M_(0, 1) = z < 0.0f ? s : -s;
        M_(1, 0) = z < 0.0f ? -s : s;
    } else if (x == 0.0f && z == 0.0f && y != 0.0f) {
        axis = true;
        M_(0, 0) = co; M_(2, 2) = co;
        M_(0, 2) = y < 0.0f ? -s : s;
        M_(2, 0) = y < 0.0f ? s : -s;
    } else if (y == 0.0f && z == 0.0f && x != 0.0f) {
        axis = true;
        M_(1, 1) = co; M_(2, 2) = co;
        M_(1, 2) = x < 0.0f ? s : -s;
        M_(2, 1) = x < 0.0f ? -s : s;
    }
    if (!axis) {
        const float mag = sqrtf(x * x + y * y + z * z);
        if (!(mag > 1.0e-4f)) /* a null axis leaves the matrix unchanged (NaN too) */
            return;
        x /= mag; y /= mag; z /= mag;
        const float xx = x * x, yy = y * y, zz = z * z;
        const float xy = x * y, yz = y * z, zx = z * x;
        const float xs = x * s, ys = y * s, zs = z * s;
        const float one_c = 1.0f - co;
        M_(0, 0) = (one_c * xx) + co;
        M_(0, 1) = (one_c * xy) - zs;
        M_(0, 2) = (one_c * zx) + ys;
        M_(1, 0) = (one_c * xy) + zs;
        M_(1, 1) = (one_c * yy) + co;
        M_(1, 2) = (one_c * yz) - xs;
        M_(2, 0) = (one_c * zx) - ys;
        M_(2, 1) = (one_c * yz) + xs;
        M_(2, 2) = (one_c * zz) + co;
    }
#undef M_
    mult(c, m, FS_MATF_ROTATION);
}

void fs_exec_Rotated(fs_context *c, GLdouble angle, GLdouble x, GLdouble y, GLdouble z)
{
    fs_exec_Rotatef(c, (float)angle, (float)x, (float)y, (float)z);
}

void fs_exec_PushMatrix(fs_context *c)
{
    fs_transform_state *x = &c->xf;
    int *t, depth;
    fs_matrix *stack;
    switch (x->matrix_mode) {
    case GL_PROJECTION: t = &x->projection_top; depth = FS_PROJECTION_STACK_DEPTH; stack = x->projection; break;
    case GL_TEXTURE: {
        int u = fs_active_unit(c);
        t = &x->texture_top[u];
        depth = FS_TEXTURE_STACK_DEPTH;
        stack = x->texture[u];
        break;
    }
    default: t = &x->modelview_top; depth = FS_MODELVIEW_STACK_DEPTH; stack = x->modelview; break;
    }
    if (*t + 1 >= depth) {
        fs_error(c, GL_STACK_OVERFLOW);
        return;
    }
    /* Mesa analyses a dirty matrix before pushing its copy (matrix.c
     * _math_matrix_push_copy, so that an unchanged glPopMatrix is a no-op):
     * a glMultMatrix before the push is classified without what the copy
     * adds later.  Measured: boxed's camera (glMultMatrixf of a rotation),
     * pushed, then glScalef(3, 3, 3), gets the scaled transpose as its
     * inverse on llvmpipe, not the adjugate (tests/test_lighting_order.c
     * C_PUSH). */
    fs_matrix_analyse(&stack[*t]);
    stack[*t + 1] = stack[*t];
    (*t)++;
}

void fs_exec_PopMatrix(fs_context *c)
{
    fs_transform_state *x = &c->xf;
    int *t = x->matrix_mode == GL_PROJECTION ? &x->projection_top
           : x->matrix_mode == GL_TEXTURE ? &x->texture_top[fs_active_unit(c)] : &x->modelview_top;
    if (*t == 0) {
        fs_error(c, GL_STACK_UNDERFLOW);
        return;
    }
    (*t)--;
}

void fs_exec_Frustum(fs_context *c, GLdouble left, GLdouble right, GLdouble bottom, GLdouble top_,
                     GLdouble zNear, GLdouble zFar)
{
    const float l = (float)left, r = (float)right, b = (float)bottom, t = (float)top_;
    const float n = (float)zNear, f = (float)zFar;
    if (n <= 0.0f || f <= 0.0f || n == f || l == r || b == t) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    float m[16] = {0};
    m[0] = (2.0f * n) / (r - l);
    m[5] = (2.0f * n) / (t - b);
    m[8] = (r + l) / (r - l);
    m[9] = (t + b) / (t - b);
    m[10] = -(f + n) / (f - n);
    m[11] = -1.0f;
    m[14] = -(2.0f * f * n) / (f - n);
    mult(c, m, FS_MATF_PERSPECTIVE);
}

void fs_exec_Ortho(fs_context *c, GLdouble left, GLdouble right, GLdouble bottom, GLdouble top_,
                   GLdouble zNear, GLdouble zFar)
{
    const float l = (float)left, r = (float)right, b = (float)bottom, t = (float)top_;
    const float n = (float)zNear, f = (float)zFar;
    if (l == r || b == t || n == f) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    float m[16] = {0};
    m[0] = 2.0f / (r - l);
    m[12] = -(r + l) / (r - l);
    m[5] = 2.0f / (t - b);
    m[13] = -(t + b) / (t - b);
    m[10] = -2.0f / (f - n);
    m[14] = -(f + n) / (f - n);
    m[15] = 1.0f;
    mult(c, m, FS_MATF_GENERAL_SCALE | FS_MATF_TRANSLATION);
}
