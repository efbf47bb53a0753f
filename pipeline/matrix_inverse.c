/*
 * The inverse of a modelview matrix as llvmpipe's GL front end (Mesa's
 * matrix module) computes it, in float, for what glTexGen's eye planes
 * (GL 1.5 spec 2.11.4) and the generation's eye normals are transformed
 * by.  Mesa classifies a matrix (identity; scale and translation only, in
 * 2D or 3D; a 2D or 3D affine map, with its upper 3x3 a rotation, a
 * uniformly scaled rotation or neither; a perspective projection; general)
 * and inverts each class its own way: reciprocals of the diagonal, the
 * transposed rotation, the scaled transpose, the adjugate over the
 * determinant with the translation carried through it, and Gauss-Jordan
 * elimination with partial pivoting otherwise.  The last bits of the
 * inverse, and so of every generated coordinate, depend on which; the
 * class here is taken from the matrix's values, as Mesa does after
 * glLoadMatrix and glMultMatrix (after glTranslate, glRotate and glScale
 * it keeps the operations' classes instead, which agree for the matrices
 * they build, up to the tolerance of 1e-6 below).
 */
#include <math.h>
#include <string.h>
#include "vertex_internal.h"

enum mat_class { M_IDENTITY, M_2D_NO_ROT, M_3D_NO_ROT, M_2D, M_3D, M_PERSPECTIVE, M_GENERAL };

/* Properties of the upper 3x3 (Mesa's matrix flags, the ones inversion
 * reads). */
enum {
    F_TRANSLATION = FS_MATF_TRANSLATION, F_ROTATION = FS_MATF_ROTATION, F_UNIFORM_SCALE = FS_MATF_UNIFORM_SCALE,
    F_GENERAL_SCALE = FS_MATF_GENERAL_SCALE, F_GENERAL_3D = FS_MATF_GENERAL_3D
};

static bool zeros(const float m[16], const int *idx, int n)
{
    for (int i = 0; i < n; i++)
        if (m[idx[i]] != 0.0f)
            return false;
    return true;
}

static float sq(float x) { return x * x; }

/* The 3D classes' flags from the columns' lengths and angles. */
static unsigned affine_flags(const float m[16], bool flat)
{
    const float tol = sq(1e-6f);
    unsigned f = 0;
    if (flat) {
        const float mm = m[0] * m[0] + m[1] * m[1], m4m4 = m[4] * m[4] + m[5] * m[5];
        const float mm4 = m[0] * m[4] + m[1] * m[5];
        if (sq(mm - 1.0f) > tol || sq(m4m4 - 1.0f) > tol)
            f |= F_GENERAL_SCALE;
        f |= sq(mm4) > tol ? F_GENERAL_3D : F_ROTATION;
        return f;
    }
    const float c1 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
    const float c2 = m[4] * m[4] + m[5] * m[5] + m[6] * m[6];
    const float c3 = m[8] * m[8] + m[9] * m[9] + m[10] * m[10];
    const float d1 = m[0] * m[4] + m[1] * m[5] + m[2] * m[6];
    if (sq(c1 - c2) < tol && sq(c1 - c3) < tol) {
        if (sq(c1 - 1.0f) > tol)
            f |= F_UNIFORM_SCALE;
    } else {
        f |= F_GENERAL_SCALE;
    }
    if (sq(d1) < tol) {
        /* The third column the cross product of the first two. */
        const float cp[3] = {m[1] * m[6] - m[2] * m[5] - m[8], m[2] * m[4] - m[0] * m[6] - m[9],
                             m[0] * m[5] - m[1] * m[4] - m[10]};
        f |= cp[0] * cp[0] + cp[1] * cp[1] + cp[2] * cp[2] < tol ? F_ROTATION : F_GENERAL_3D;
    } else {
        f |= F_GENERAL_3D;
    }
    return f;
}

static enum mat_class classify(const float m[16], unsigned *flags)
{
    static const int off_diag[] = {1, 2, 3, 4, 6, 7, 8, 9, 11}, trans[] = {12, 13, 14};
    static const int flat[] = {2, 3, 6, 7, 8, 9, 11, 14}, affine[] = {3, 7, 11};
    static const int persp[] = {1, 2, 3, 4, 6, 7, 12, 13, 15};
    *flags = zeros(m, trans, 3) ? 0 : F_TRANSLATION;
    const bool no_rot = zeros(m, off_diag, 9) && m[15] == 1.0f;
    if (no_rot && m[0] == 1.0f && m[5] == 1.0f && m[10] == 1.0f && !*flags)
        return M_IDENTITY;
    if (no_rot && m[10] == 1.0f && m[14] == 0.0f)
        return M_2D_NO_ROT;
    if (zeros(m, flat, 8) && m[10] == 1.0f && m[15] == 1.0f) {
        *flags |= affine_flags(m, true);
        return M_2D;
    }
    if (no_rot)
        return M_3D_NO_ROT;
    if (zeros(m, affine, 3) && m[15] == 1.0f) {
        *flags |= affine_flags(m, false);
        return M_3D;
    }
    if (zeros(m, persp, 9) && m[11] == -1.0f)
        return M_PERSPECTIVE;
    return M_GENERAL;
}

/* Column-major element (row r, column k). */
#define AT(m, r, k) (m)[(k) * 4 + (r)]

/* The translation column of an affine inverse: -(A^-1 t), the sum over
 * t's components in order. */
static void affine_translation(float out[16], const float in[16])
{
    for (int r = 0; r < 3; r++)
        AT(out, r, 3) = -(AT(in, 0, 3) * AT(out, r, 0) + AT(in, 1, 3) * AT(out, r, 1) + AT(in, 2, 3) * AT(out, r, 2));
}

/* A 3D affine map: the adjugate of the upper 3x3 over its determinant
 * (positive and negative terms summed apart); singular below 1e-25. */
static bool invert_3d_general(float out[16], const float in[16])
{
    static const int t[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}, {1, 0, 2}, {0, 2, 1}};
    float pos = 0.0f, neg = 0.0f;
    for (int i = 0; i < 6; i++) {
        /* Term i: in(r0,0) in(r1,1) in(r2,2) over a permutation, the
         * last three negated first. */
        float a = AT(in, t[i][0], 0);
        float v = (i < 3 ? a : -a) * AT(in, t[i][1], 1) * AT(in, t[i][2], 2);
        if (v >= 0.0f)
            pos += v;
        else
            neg += v;
    }
    float det = pos + neg;
    if (fabsf(det) < 1e-25f)
        return false;
    det = 1.0f / det;
    fs_mat_identity(out);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            /* Cofactor of in(k, r): rows and columns other than k and r, in order. */
            const int r0 = r == 0 ? 1 : 0, r1 = r == 2 ? 1 : 2;
            const int k0 = k == 0 ? 1 : 0, k1 = k == 2 ? 1 : 2;
            const float minor = AT(in, k0, r0) * AT(in, k1, r1) - AT(in, k1, r0) * AT(in, k0, r1);
            AT(out, r, k) = ((r + k) & 1 ? -minor : minor) * det;
        }
    affine_translation(out, in);
    return true;
}

/* A 2D or 3D affine map: transpose (scaled) for a rotation (and uniform
 * scale), the general 3D inverse otherwise. */
static bool invert_3d(float out[16], const float in[16], unsigned flags)
{
    if (flags & (F_GENERAL_SCALE | F_GENERAL_3D))
        return invert_3d_general(out, in);
    fs_mat_identity(out);
    if (flags & (F_UNIFORM_SCALE | F_ROTATION)) {
        float scale = 1.0f;
        if (flags & F_UNIFORM_SCALE) {
            scale = AT(in, 0, 0) * AT(in, 0, 0) + AT(in, 0, 1) * AT(in, 0, 1) + AT(in, 0, 2) * AT(in, 0, 2);
            if (scale == 0.0f)
                return false;
            scale = 1.0f / scale;
        }
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                AT(out, r, k) = flags & F_UNIFORM_SCALE ? scale * AT(in, k, r) : AT(in, k, r);
    } else {
        for (int r = 0; r < 3; r++) /* a translation */
            AT(out, r, 3) = -AT(in, r, 3);
        return true;
    }
    if (flags & F_TRANSLATION)
        affine_translation(out, in);
    return true;
}

/* Scale and translation only: reciprocals of the diagonal (n of them). */
static bool invert_no_rot(float out[16], const float in[16], int n, unsigned flags)
{
    fs_mat_identity(out);
    for (int i = 0; i < n; i++) {
        if (AT(in, i, i) == 0.0f)
            return false;
        AT(out, i, i) = 1.0f / AT(in, i, i);
    }
    if (flags & F_TRANSLATION)
        for (int i = 0; i < n; i++)
            AT(out, i, 3) = -(AT(in, i, 3) * AT(out, i, i));
    return true;
}

/* Gauss-Jordan elimination on [M | I] with partial pivoting: the pivot
 * rows chosen bottom-up by magnitude, elimination below each pivot (an
 * identity half's zero multiplier skipped), then back substitution. */
static bool invert_general(float out[16], const float m[16])
{
    float w[4][8], *r[4] = {w[0], w[1], w[2], w[3]};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 8; k++)
            w[i][k] = k < 4 ? AT(m, i, k) : (k - 4 == i ? 1.0f : 0.0f);
    for (int col = 0; col < 4; col++) {
        for (int i = 3; i > col; i--)
            if (fabsf(r[i][col]) > fabsf(r[i - 1][col])) {
                float *t = r[i];
                r[i] = r[i - 1];
                r[i - 1] = t;
            }
        if (r[col][col] == 0.0f)
            return false;
        if (col == 3)
            break;
        float f[4];
        for (int i = col + 1; i < 4; i++)
            f[i] = r[i][col] / r[col][col];
        for (int k = col + 1; k < 8; k++) {
            const float s = r[col][k];
            if (k >= 4 && s == 0.0f && col < 2)
                continue;
            for (int i = col + 1; i < 4; i++)
                r[i][k] -= f[i] * s;
        }
    }
    float s = 1.0f / r[3][3];
    for (int k = 4; k < 8; k++)
        r[3][k] *= s;
    for (int row = 2; row >= 0; row--) {
        const float mr = r[row][row + 1];
        s = 1.0f / r[row][row];
        for (int k = 4; k < 8; k++)
            r[row][k] = s * (r[row][k] - r[row + 1][k] * mr);
        for (int i = row - 1; i >= 0; i--) {
            const float mi = r[i][row + 1];
            for (int k = 4; k < 8; k++)
                r[i][k] -= r[row + 1][k] * mi;
        }
    }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            AT(out, i, k) = r[i][4 + k];
    return true;
}

/* Inverts m of class cls with flags (a singular matrix gives the
 * identity, as Mesa leaves it). */
static void invert_class(float out[16], const float m[16], enum mat_class cls, unsigned flags)
{
    bool ok;
    switch (cls) {
    case M_IDENTITY: fs_mat_identity(out); return;
    case M_2D_NO_ROT: ok = invert_no_rot(out, m, 2, flags); break;
    case M_3D_NO_ROT: ok = invert_no_rot(out, m, 3, flags); break;
    case M_2D: case M_3D: ok = invert_3d(out, m, flags); break;
    default: ok = invert_general(out, m); break;
    }
    if (!ok)
        fs_mat_identity(out);
}

/* Length preserving: a rotation and translation, nothing else (Mesa's
 * _math_matrix_is_length_preserving, on the flags). */
static bool length_preserving(unsigned flags)
{
    return !(flags & ~(unsigned)(F_ROTATION | F_TRANSLATION));
}

/* The flags of Mesa's analysis from the values (analyse_from_scratch):
 * classify's, with the scale of a matrix without rotation and the
 * perspective and general classes' own. */
static unsigned value_flags(const float m[16], enum mat_class cls, unsigned flags)
{
    const float tol = sq(1e-6f);
    switch (cls) {
    case M_2D_NO_ROT:
        if (m[0] != 1.0f || m[5] != 1.0f)
            flags |= F_GENERAL_SCALE;
        break;
    case M_3D_NO_ROT:
        if (sq(m[0] - m[5]) < tol && sq(m[0] - m[10]) < tol) {
            if (sq(m[0] - 1.0f) > tol)
                flags |= F_UNIFORM_SCALE;
        } else {
            flags |= F_GENERAL_SCALE;
        }
        break;
    case M_PERSPECTIVE:
    case M_GENERAL:
        flags |= FS_MATF_GENERAL;
        break;
    default:
        break;
    }
    return flags;
}

bool fs_mat_invert_gl(float out[16], const float m[16])
{
    unsigned flags;
    const enum mat_class cls = classify(m, &flags);
    invert_class(out, m, cls, flags);
    return length_preserving(value_flags(m, cls, flags));
}

/* Mesa's analysis from the flags (analyse_from_flags): the class the
 * commands that built the matrix imply, the values deciding only between
 * the 2D and 3D forms. */
static enum mat_class flags_class(const float m[16], unsigned flags)
{
    const unsigned geom = flags & (unsigned)(F_TRANSLATION | F_ROTATION | F_UNIFORM_SCALE | F_GENERAL_SCALE |
                                             F_GENERAL_3D | FS_MATF_PERSPECTIVE | FS_MATF_GENERAL);
    if (geom == 0)
        return M_IDENTITY;
    if (!(geom & ~(unsigned)(F_TRANSLATION | F_UNIFORM_SCALE | F_GENERAL_SCALE)))
        return m[10] == 1.0f && m[14] == 0.0f ? M_2D_NO_ROT : M_3D_NO_ROT;
    if (!(geom & ~(unsigned)(F_TRANSLATION | F_ROTATION | F_UNIFORM_SCALE | F_GENERAL_SCALE | F_GENERAL_3D)))
        return m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f && m[10] == 1.0f && m[14] == 0.0f
                   ? M_2D
                   : M_3D;
    return M_GENERAL; /* Mesa's perspective class has its own inversion: not modelled */
}

/* Mesa's analysis of a matrix whose values decide (analyse_from_scratch):
 * its class, and its flags replaced by the values'. */
static enum mat_class analyse(fs_matrix *mx)
{
    unsigned flags;
    const enum mat_class cls = classify(mx->m, &flags);
    mx->flags = value_flags(mx->m, cls, flags);
    return cls;
}

void fs_matrix_analyse(fs_matrix *mx)
{
    if (mx->flags & FS_MATF_DIRTY)
        (void)analyse(mx);
}

void fs_modelview_analyse(fs_context *c)
{
    fs_matrix_analyse(&c->xf.modelview[c->xf.modelview_top]);
}

bool fs_matrix_invert(float out[16], fs_matrix *mx)
{
    const float *m = mx->m;
    if (mx->flags & FS_MATF_DIRTY) {
        const enum mat_class cls = analyse(mx);
        invert_class(out, m, cls, mx->flags);
        return length_preserving(mx->flags);
    }
    if (mx->flags & FS_MATF_IDENTITY) {
        fs_mat_identity(out); /* glLoadIdentity's inverse, whatever the flags */
        return length_preserving(mx->flags);
    }
    unsigned flags = mx->flags;
    invert_class(out, m, flags_class(m, flags), flags);
    return length_preserving(flags);
}
