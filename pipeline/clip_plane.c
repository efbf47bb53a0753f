/*
 * User clip planes (GL 1.5 spec 2.11): glClipPlane, glGetClipPlane and the
 * per-draw setup that turns the enabled planes into clip-space planes for
 * the clipper (clip.c).
 *
 * glClipPlane transforms the plane by the inverse of the modelview current
 * at specification time, (p1 p2 p3 p4) M^-1, in float, and keeps the
 * eye-space result, which glGetClipPlane returns.  llvmpipe clips in clip
 * space: Mesa's state tracker hands the draw module the eye-space planes
 * transformed once more by the inverse projection (for fixed-function
 * vertex processing; a vertex shader would get them in eye space), and the
 * draw module tests each vertex's clip position against them and clips
 * against them after the six view-volume planes.  So a vertex is inside
 * plane i when dot(P_c, x_c) >= 0, with P_c = P_e P^-1; the two agree with
 * the spec's dot(P_e, x_e) >= 0 up to rounding, and the rounding is
 * llvmpipe's.
 */
#include <math.h>
#include <string.h>
#include "vertex_internal.h"

/* v M^-1 for a row vector v, as Mesa's _mesa_transform_vector computes it
 * (each output a plain sum of four products, left to right). */
static void row_times(float out[4], const float v[4], const float m[16])
{
    float r[4];
    for (int k = 0; k < 4; k++)
        r[k] = v[0] * m[4 * k] + v[1] * m[4 * k + 1] + v[2] * m[4 * k + 2] + v[3] * m[4 * k + 3];
    memcpy(out, r, sizeof r);
}

/* Gauss-Jordan elimination with partial pivoting in float, row by row on
 * the matrix beside the identity, the order of operations Mesa's general
 * inversion has (Jacques Leroy's, now util_invert_mat4x4): pivots chosen by
 * comparing each row with the one above from the bottom up, each lower row
 * reduced by r_j -= (r_j[col] / r_col[col]) r_col, then back substitution
 * from the last row, r_i = (1 / r_i[i]) (r_i - r_{i+1} r_i[i+1]) with the
 * rows above losing r_{i+1}'s share afterwards.  False when singular. */
static bool gauss_invert(float inv[16], const float m[16])
{
    float w[4][8];
    float *r[4] = {w[0], w[1], w[2], w[3]};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) {
            w[i][k] = m[4 * k + i]; /* row i of the column-major m */
            w[i][4 + k] = i == k ? 1.0f : 0.0f;
        }
    for (int col = 0; col < 3; col++) {
        for (int i = 3; i > col; i--)
            if (fabsf(r[i][col]) > fabsf(r[i - 1][col])) {
                float *t = r[i];
                r[i] = r[i - 1];
                r[i - 1] = t;
            }
        if (r[col][col] == 0.0f)
            return false;
        for (int j = col + 1; j < 4; j++) {
            const float f = r[j][col] / r[col][col];
            for (int k = col + 1; k < 8; k++)
                r[j][k] -= f * r[col][k];
        }
    }
    if (r[3][3] == 0.0f)
        return false;
    const float s3 = 1.0f / r[3][3];
    for (int k = 4; k < 8; k++)
        r[3][k] *= s3;
    for (int i = 2; i >= 0; i--) {
        const float f = r[i][i + 1], s = 1.0f / r[i][i];
        for (int k = 4; k < 8; k++)
            r[i][k] = s * (r[i][k] - r[i + 1][k] * f);
        for (int j = 0; j < i; j++) {
            const float g = r[j][i + 1];
            for (int k = 4; k < 8; k++)
                r[j][k] -= r[i + 1][k] * g;
        }
    }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            inv[4 * k + i] = r[i][4 + k];
    return true;
}

/* Whether m is affine with an angle-preserving upper 3x3 (a rotation,
 * perhaps uniformly scaled): orthogonal columns of one length. */
static bool angle_preserving(const float *m, float *len2)
{
    if (m[3] != 0.0f || m[7] != 0.0f || m[11] != 0.0f || m[15] != 1.0f)
        return false;
    float l[3], d[3];
    for (int k = 0; k < 3; k++) {
        const float *a = m + 4 * k, *b = m + 4 * ((k + 1) % 3);
        l[k] = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        d[k] = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    const float eps = 1e-5f * l[0];
    for (int k = 0; k < 3; k++)
        if (!(fabsf(l[k] - l[0]) <= eps && fabsf(d[k]) <= eps))
            return false;
    /* Mesa scales by the first row's squared length. */
    *len2 = m[0] * m[0] + m[4] * m[4] + m[8] * m[8];
    return *len2 > 0.0f;
}

/* A rotation's inverse as Mesa takes it: the transpose of the upper 3x3
 * (scaled by 1 / len2 unless that is 1, for a uniform scale), and the
 * translation negated through it, -(t_x out_r0 + t_y out_r1 + t_z out_r2)
 * for row r. */
static void rotation_inverse(float inv[16], const float m[16], float len2)
{
    const bool unit = fabsf(len2 - 1.0f) <= 1e-6f;
    const float scale = unit ? 1.0f : 1.0f / len2;
    fs_mat_identity(inv);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++)
            inv[4 * k + r] = unit ? m[4 * r + k] : scale * m[4 * r + k];
    for (int r = 0; r < 3; r++)
        inv[12 + r] = -(m[12] * inv[r] + m[13] * inv[4 + r] + m[14] * inv[8 + r]);
}

/* The inverse the planes are transformed by, in float as Mesa inverts
 * matrices.  Mesa chooses the method by the commands that built the matrix
 * (its matrix flags), fragsim by the matrix's values: the identity is its
 * own inverse; an affine matrix with an angle-preserving 3x3 (what glRotate,
 * glTranslate and a uniform glScale build) is transposed (rotation_inverse);
 * any other (glFrustum, glOrtho, glLoadMatrix, non-uniform scales) goes
 * through gauss_invert, which for a scale with a translation gives the same
 * bits as Mesa's 1/s and -(t (1/s)).  Measured with glGetClipPlane on
 * OSMesa (tests/test_clip_plane.c): exact under translations, scales and
 * rotations.  Known difference: Mesa's flags survive glLoadIdentity, so a
 * rotation on a stack that once held a non-uniform scale is inverted by
 * cofactors instead (measured: 18 of 32 coefficients 1-3 ulps apart).  A
 * singular matrix gives the identity, as in Mesa. */
static void plane_inverse(float inv[16], const float m[16])
{
    float id[16];
    fs_mat_identity(id);
    float len2;
    if (memcmp(m, id, sizeof id) == 0)
        memcpy(inv, id, sizeof id);
    else if (angle_preserving(m, &len2))
        rotation_inverse(inv, m, len2);
    else if (!gauss_invert(inv, m))
        memcpy(inv, id, sizeof id);
}

static int plane_index(fs_context *c, GLenum plane)
{
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + FS_MAX_CLIP_PLANES) {
        fs_error(c, GL_INVALID_ENUM);
        return -1;
    }
    return (int)(plane - GL_CLIP_PLANE0);
}

void fs_exec_ClipPlane(fs_context *c, GLenum plane, const GLdouble *equation)
{
    int i = plane_index(c, plane);
    if (i < 0)
        return;
    /* The double coefficients become floats first (Mesa keeps the planes
     * in float). */
    const float p[4] = {(float)equation[0], (float)equation[1], (float)equation[2], (float)equation[3]};
    float inv[16];
    plane_inverse(inv, c->xf.modelview[c->xf.modelview_top].m);
    row_times(c->xf.clip_plane[i], p, inv);
    fs_state_mark(c, GL_TRANSFORM_BIT);
}

void fs_exec_GetClipPlane(fs_context *c, GLenum plane, GLdouble *equation)
{
    int i = plane_index(c, plane);
    if (i < 0)
        return;
    for (int k = 0; k < 4; k++)
        equation[k] = c->xf.clip_plane[i][k];
}

void fs_clip_plane_setup(const fs_context *c, fs_vs_setup *s)
{
    s->ucp_mask = 0;
    for (int i = 0; i < FS_MAX_CLIP_PLANES; i++)
        if (c->xf.clip_enabled[i])
            s->ucp_mask |= 1u << (FS_CLIP_USER_BIT + i);
    if (!s->ucp_mask)
        return; /* no user plane: nothing more per draw, nothing per vertex */
    float inv[16];
    plane_inverse(inv, c->xf.projection[c->xf.projection_top].m);
    for (int i = 0; i < FS_MAX_CLIP_PLANES; i++)
        if (c->xf.clip_enabled[i])
            row_times(s->ucp[i], c->xf.clip_plane[i], inv);
}

unsigned fs_clip_user_mask(const fs_vs_setup *s, const float clip[4])
{
    unsigned m = 0;
    for (unsigned bits = s->ucp_mask; bits; bits &= bits - 1) {
        int b = __builtin_ctz(bits);
        const float *p = s->ucp[b - FS_CLIP_USER_BIT];
        /* The draw module's test: outside when 0 > the distance (NaN is
         * inside here and is dropped by the clipper). */
        float d = p[0] * clip[0] + p[1] * clip[1] + p[2] * clip[2] + p[3] * clip[3];
        if (0.0f > d)
            m |= 1u << b;
    }
    return m;
}
