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

/* The inverse the planes are transformed by, in float as Mesa inverts
 * matrices: the one Mesa-order inversion texgen's eye planes use too
 * (matrix_inverse.c, fs_mat_invert_gl: the method chosen by the matrix's
 * values, Mesa's by its flags; a singular matrix gives the identity).
 * Measured with glGetClipPlane on OSMesa (tests/test_clip_plane.c): exact
 * under translations, scales and rotations.  Known difference: Mesa's
 * flags survive glLoadIdentity, so a matrix it built with a non-uniform
 * scale once may be inverted by another method there. */
static void plane_inverse(float inv[16], const float m[16])
{
    (void)fs_mat_invert_gl(inv, m);
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
    fs_matrix_invert(inv, &c->xf.modelview[c->xf.modelview_top]);
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
