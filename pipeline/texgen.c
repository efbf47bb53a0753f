/*
 * Texture coordinate generation (GL 1.5 spec 2.11.4): glTexGen and
 * glGetTexGen for the s, t, r, q coordinates of the active texture unit,
 * and the generation itself, which the vertex stage runs per vertex
 * before the texture matrix (vertex_array.c's vs_attributes).
 *
 * The arithmetic is that of llvmpipe's fixed-function vertex shader, which
 * Mesa's ffvertex_prog builds: planes as four-component dot products of
 * the object or eye position; SPHERE_MAP and REFLECTION_MAP from the unit
 * eye vector u = e * rsq(e . e) (x, y, z of the eye position, its w left
 * out) and the eye normal n that lighting uses (transformed by the inverse
 * transpose, then normalised or rescaled as GL_NORMALIZE and
 * GL_RESCALE_NORMAL say): r = (-(2 n.u)) n + u, and for the sphere map
 * r / m + 1/2 with 1/m = rsq(r_x^2 + r_y^2 + (r_z + 1)^2) / 2.  Every
 * product and sum is rounded on its own, dot products summed from the
 * last component to the first, the planes and normals transformed by the
 * inverse modelview as Mesa computes it (matrix_inverse.c).  Checked bit
 * for bit against OSMesa's feedback values (tests/test_texgen.c): OBJECT
 * and EYE_LINEAR, REFLECTION_MAP and NORMAL_MAP are exact; the sphere
 * map's 1/m is 1-4 ulps off llvmpipe's in about one vertex in eight (354
 * of 400 exact; neither 1/sqrt in float or double, nor rsqrtss or rcpss
 * with a Newton step, nor another summation order reproduces the rest).
 */
#include <limits.h>
#include <math.h>
#include <string.h>
#include "vertex_internal.h"

int fs_texgen_count(GLenum pname)
{
    switch (pname) {
    case GL_TEXTURE_GEN_MODE: return 1;
    case GL_OBJECT_PLANE: case GL_EYE_PLANE: return 4;
    default: return 0;
    }
}

void fs_texgen_init(fs_context *c)
{
    for (int u = 0; u < FS_MAX_TEXTURE_UNITS; u++) {
        for (int k = 0; k < 4; k++) {
            fs_texgen_coord *g = &c->texgen[u].coord[k];
            memset(g, 0, sizeof *g);
            g->mode = GL_EYE_LINEAR;
            if (k < 2)
                g->object_plane[k] = g->eye_plane[k] = 1.0f;
        }
    }
}

/* The active unit's state of coordinate `coord` (GL_S .. GL_Q), or NULL
 * after GL_INVALID_ENUM. */
static fs_texgen_coord *coord_of(fs_context *c, GLenum coord)
{
    if (coord < GL_S || coord > GL_Q) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    return &c->texgen[fs_active_unit(c)].coord[coord - GL_S];
}

/* Modes a coordinate may take (2.11.4): SPHERE_MAP for s and t only,
 * REFLECTION_MAP and NORMAL_MAP for s, t and r. */
static bool mode_allowed(GLenum coord, GLenum mode)
{
    switch (mode) {
    case GL_OBJECT_LINEAR: case GL_EYE_LINEAR: return true;
    case GL_SPHERE_MAP: return coord == GL_S || coord == GL_T;
    case GL_REFLECTION_MAP: case GL_NORMAL_MAP: return coord != GL_Q;
    default: return false;
    }
}

/* glTexGen*v with the values as floats (the scalar forms give
 * (param, 0, 0, 0): OSMesa sets a plane from them, without an error). */
static void texgen_v(fs_context *c, GLenum coord, GLenum pname, const float p[4])
{
    fs_texgen_coord *g = coord_of(c, coord);
    if (!g)
        return;
    switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
        /* A float mode is truncated (measured: 9217.5 is GL_EYE_LINEAR). */
        GLenum mode = p[0] >= 0.0f && p[0] < 2147483648.0f ? (GLenum)(GLint)p[0] : 0;
        if (!mode_allowed(coord, mode)) {
            fs_error(c, GL_INVALID_ENUM);
            return;
        }
        g->mode = mode;
        break;
    }
    case GL_OBJECT_PLANE:
        memcpy(g->object_plane, p, sizeof g->object_plane);
        break;
    case GL_EYE_PLANE: {
        /* (p1 p2 p3 p4) M^-1 with M the modelview now (2.11.4). */
        float inv[16];
        fs_matrix_invert(inv, &c->xf.modelview[c->xf.modelview_top]);
        for (int i = 0; i < 4; i++)
            g->eye_plane[i] = p[0] * inv[4 * i] + p[1] * inv[4 * i + 1] + p[2] * inv[4 * i + 2] + p[3] * inv[4 * i + 3];
        break;
    }
    default:
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_state_mark(c, GL_TEXTURE_BIT);
}

void fs_exec_TexGenfv(fs_context *c, GLenum coord, GLenum pname, const GLfloat *params)
{
    float p[4] = {0, 0, 0, 0};
    memcpy(p, params, (size_t)fs_texgen_count(pname) * sizeof p[0]);
    texgen_v(c, coord, pname, p);
}

void fs_exec_TexGeniv(fs_context *c, GLenum coord, GLenum pname, const GLint *params)
{
    float p[4] = {0, 0, 0, 0};
    for (int i = 0; i < fs_texgen_count(pname); i++)
        p[i] = (float)params[i];
    texgen_v(c, coord, pname, p);
}

void fs_exec_TexGendv(fs_context *c, GLenum coord, GLenum pname, const GLdouble *params)
{
    float p[4] = {0, 0, 0, 0};
    for (int i = 0; i < fs_texgen_count(pname); i++)
        p[i] = (float)params[i];
    texgen_v(c, coord, pname, p);
}

void fs_exec_TexGenf(fs_context *c, GLenum coord, GLenum pname, GLfloat param)
{
    const float p[4] = {param, 0, 0, 0};
    texgen_v(c, coord, pname, p);
}

void fs_exec_TexGeni(fs_context *c, GLenum coord, GLenum pname, GLint param)
{
    fs_exec_TexGenf(c, coord, pname, (float)param);
}

void fs_exec_TexGend(fs_context *c, GLenum coord, GLenum pname, GLdouble param)
{
    fs_exec_TexGenf(c, coord, pname, (float)param);
}

/* glGetTexGen (6.1.3): the mode (as a float: every mode is exact), or a
 * plane as stored (the eye plane transformed); n values, 0 after
 * GL_INVALID_ENUM. */
static int get_texgen(fs_context *c, GLenum coord, GLenum pname, float v[4])
{
    const fs_texgen_coord *g = coord_of(c, coord);
    if (!g)
        return 0;
    switch (pname) {
    case GL_TEXTURE_GEN_MODE: v[0] = (float)g->mode; return 1;
    case GL_OBJECT_PLANE: memcpy(v, g->object_plane, 4 * sizeof v[0]); return 4;
    case GL_EYE_PLANE: memcpy(v, g->eye_plane, 4 * sizeof v[0]); return 4;
    default: fs_error(c, GL_INVALID_ENUM); return 0;
    }
}

void fs_exec_GetTexGenfv(fs_context *c, GLenum coord, GLenum pname, GLfloat *params)
{
    float v[4];
    int n = get_texgen(c, coord, pname, v);
    memcpy(params, v, (size_t)n * sizeof v[0]);
}

void fs_exec_GetTexGendv(fs_context *c, GLenum coord, GLenum pname, GLdouble *params)
{
    float v[4];
    int n = get_texgen(c, coord, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = (double)v[i];
}

/* A plane's value as an integer: truncated, and INT_MIN where it does not
 * fit (measured on OSMesa: -2.7 gives -2, 1e10 and infinity INT_MIN, the
 * x86 conversion's answer).  Modes convert exactly. */
static GLint plane_int(float f)
{
    return f > -2147483649.0f && f < 2147483648.0f ? (GLint)f : INT_MIN;
}

void fs_exec_GetTexGeniv(fs_context *c, GLenum coord, GLenum pname, GLint *params)
{
    float v[4];
    int n = get_texgen(c, coord, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = plane_int(v[i]);
}

/* ---- the generation (vertex stage) ---- */

/* The inverse transpose of the modelview for the eye normals, and the
 * GL_RESCALE_NORMAL factor: 1 / |third row of the inverse|, 1 for a
 * modelview that preserves lengths (as Mesa's normal scale). */
static void normal_matrix(fs_vs_setup *s)
{
    /* The modelview's inverse as fs_vs_prepare analysed it (Mesa's). */
    memcpy(s->texgen_nmat, s->nmat, sizeof s->texgen_nmat);
    s->texgen_nscale = s->nscale;
}

void fs_texgen_setup(fs_context *c, fs_vs_setup *s)
{
    s->texgen = s->texgen_eye = s->texgen_normal = false;
    for (int u = 0; u < s->ntex; u++) {
        const fs_texgen_unit *t = &c->texgen[u];
        for (int k = 0; k < 4; k++) {
            const fs_texgen_coord *g = &t->coord[k];
            unsigned char m = FS_TG_NONE;
            if (t->enabled[k]) {
                switch (g->mode) {
                case GL_OBJECT_LINEAR: m = FS_TG_OBJECT; break;
                case GL_EYE_LINEAR: m = FS_TG_EYE; break;
                case GL_SPHERE_MAP: m = FS_TG_SPHERE; break;
                case GL_REFLECTION_MAP: m = FS_TG_REFLECTION; break;
                default: m = FS_TG_NORMAL; break;
                }
                memcpy(s->texgen_plane[u][k], m == FS_TG_OBJECT ? g->object_plane : g->eye_plane,
                       sizeof s->texgen_plane[u][k]);
            }
            s->texgen_mode[u][k] = m;
            s->texgen |= m != FS_TG_NONE;
            s->texgen_eye |= m != FS_TG_NONE && m != FS_TG_OBJECT;
            s->texgen_normal |= m >= FS_TG_SPHERE;
        }
    }
    /* Lighting computes the eye position only where it needs it; the
     * generation shares it. */
    s->need_eye |= s->texgen_eye;
    s->normalize = c->xf.normalize;
    s->rescale = c->xf.rescale_normal;
    if (s->texgen_normal)
        normal_matrix(s);
}

/* llvmpipe's dot products: the products summed from the last component
 * to the first (measured: ((w w' + z z') + y y') + x x' matches OSMesa's
 * OBJECT_LINEAR values in 300 of 300 vertices, left to right in 194). */
static float dot4(const float a[4], const float b[4])
{
    float d = a[3] * b[3];
    d = d + a[2] * b[2];
    d = d + a[1] * b[1];
    return d + a[0] * b[0];
}

static float dot3(const float a[3], const float b[3])
{
    float d = a[2] * b[2];
    d = d + a[1] * b[1];
    return d + a[0] * b[0];
}

/* The eye normal as llvmpipe's vertex shader computes it for the
 * generation: each component a dot3 of the normal with a column of the
 * inverse modelview, then normalised or rescaled (fs_vs_eye_normal's
 * rules).  Lighting's normal (fs_vs_eye_normal) sums the other way; it
 * keeps that order so that lit images stay as they were. */
static void texgen_normal(const fs_vs_setup *s, const fs_ivert *v, float n[4])
{
    for (int r = 0; r < 3; r++)
        n[r] = dot3(&s->texgen_nmat[r * 3], v->nrm);
    if (s->rescale && !s->normalize)
        for (int k = 0; k < 3; k++)
            n[k] *= s->texgen_nscale;
    if (s->normalize) {
        const float q = 1.0f / sqrtf(dot3(n, n));
        for (int k = 0; k < 3; k++)
            n[k] *= q;
    }
    n[3] = 0.0f; /* no q: mode_allowed */
}

/* What SPHERE_MAP and REFLECTION_MAP share: the reflection vector r of
 * the unit eye vector about the eye normal, and the sphere map's (s, t). */
typedef struct texgen_vectors {
    bool done;
    float r[4], sphere[4]; /* r[3], sphere[2..3] unused (mode_allowed) */
} texgen_vectors;

static void reflection(texgen_vectors *t, const float eye[4], const float n[3])
{
    const float q = 1.0f / sqrtf(dot3(eye, eye));
    const float u[3] = {eye[0] * q, eye[1] * q, eye[2] * q};
    float d = dot3(n, u);
    d = d + d;
    for (int k = 0; k < 3; k++)
        t->r[k] = -d * n[k] + u[k];
    const float v[3] = {t->r[0], t->r[1], t->r[2] + 1.0f};
    const float inv_m = (1.0f / sqrtf(dot3(v, v))) * 0.5f;
    for (int k = 0; k < 2; k++)
        t->sphere[k] = t->r[k] * inv_m + 0.5f;
    t->done = true;
}

void fs_texgen_vertex(const fs_vs_setup *s, const fs_ivert *v, float eye[4], fs_pvert *o)
{
    if (!s->lighting && s->texgen_eye)
        fs_mat_xform4(eye, s->mv, v->obj); /* else lighting's (need_eye) */
    texgen_vectors t = {.done = false};
    float n[4] = {0, 0, 0, 0};
    if (s->texgen_normal)
        texgen_normal(s, v, n);
    for (int u = 0; u < s->ntex; u++) {
        float tc[4];
        for (int k = 0; k < 4; k++) {
            const unsigned char m = s->texgen_mode[u][k];
            if ((m == FS_TG_SPHERE || m == FS_TG_REFLECTION) && !t.done)
                reflection(&t, eye, n);
            switch (m) {
            case FS_TG_NONE: tc[k] = v->tc[u][k]; break;
            case FS_TG_OBJECT: tc[k] = dot4(v->obj, s->texgen_plane[u][k]); break;
            case FS_TG_EYE: tc[k] = dot4(eye, s->texgen_plane[u][k]); break;
            case FS_TG_SPHERE: tc[k] = t.sphere[k]; break;
            case FS_TG_REFLECTION: tc[k] = t.r[k]; break;
            default: tc[k] = n[k]; break;
            }
        }
        if (s->tex_identity[u])
            memcpy(o->tc[u], tc, sizeof o->tc[u]);
        else
            fs_mat_xform4(o->tc[u], s->tex[u], tc);
    }
}
