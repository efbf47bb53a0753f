/*
 * Fog (GL 1.5 spec 3.10): glFog's parameters, stored for glGet and
 * glPushAttrib(GL_FOG_BIT), and fog applied to fragments as llvmpipe
 * (Mesa 22.3) applies it.  Where and how, from Mesa's fixed-function
 * programs (ffvertex_prog.c, ff_fragment_shader.cpp, prog_statevars.c,
 * gallivm's lp_build_exp2; read for the method, not copied) and measured
 * against OSMesa by tests/test_fog.c:
 * - per vertex, the fog coordinate c is |z_e|, the eye-space z's absolute
 *   value (GL_FRAGMENT_DEPTH; GL's "eye plane absolute" distance), or the
 *   vertex's fog coordinate (GL_FOG_COORD);
 * - it is interpolated perspective-correctly like a colour (fs_quad.fog);
 * - per fragment, after texturing (3.8) and before the per-fragment
 *   operations (chapter 4): f from c in float with precomputed constants
 *   (fs_fog_validate), clamped to [0, 1], and the colour's r, g, b
 *   replaced by C_f (1 - f) + C_r f; alpha is left alone.
 */
#include <math.h>
#include "fragment_stages.h"

static float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

/* An enum passed as a float (0, no enum, when out of range or NaN). */
static GLenum as_enum(float v) { return v >= 0.0f && v < 65536.0f ? (GLenum)v : 0; }

/* Values glFog*v reads for pname (GL_FOG_COLOR 4, the others 1), 0 for a
 * name glFog does not take. */
int fs_fog_param_count(GLenum pname)
{
    switch (pname) {
    case GL_FOG_COLOR: return 4;
    case GL_FOG_MODE: case GL_FOG_DENSITY: case GL_FOG_START: case GL_FOG_END: case GL_FOG_INDEX:
    case GL_FOG_COORD_SRC: return 1;
    default: return 0;
    }
}

/* 3.10: GL_FOG_MODE is GL_LINEAR, GL_EXP or GL_EXP2 and GL_FOG_COORD_SRC
 * GL_FOG_COORD or GL_FRAGMENT_DEPTH (else GL_INVALID_ENUM); a negative
 * density is GL_INVALID_VALUE; the colour is clamped to [0, 1]. */
static void fog_v(fs_context *c, GLenum pname, const float *p)
{
    fs_fog_state *f = &c->st.fog;
    GLenum e;
    switch (pname) {
    case GL_FOG_MODE:
        e = as_enum(p[0]);
        if (e != GL_LINEAR && e != GL_EXP && e != GL_EXP2)
            goto bad_enum;
        f->mode = e;
        break;
    case GL_FOG_COORD_SRC:
        e = as_enum(p[0]);
        if (e != GL_FOG_COORD && e != GL_FRAGMENT_DEPTH)
            goto bad_enum;
        f->coord_src = e;
        break;
    case GL_FOG_DENSITY:
        if (p[0] < 0.0f) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        f->density = p[0];
        break;
    case GL_FOG_START: f->start = p[0]; break;
    case GL_FOG_END: f->end = p[0]; break;
    case GL_FOG_INDEX: f->index = p[0]; break;
    case GL_FOG_COLOR:
        for (int k = 0; k < 4; k++)
            f->color[k] = clamp01(p[k]);
        break;
    default: goto bad_enum;
    }
    fs_state_mark(c, GL_FOG_BIT);
    return;
bad_enum:
    fs_error(c, GL_INVALID_ENUM);
}

void fs_exec_Fogfv(fs_context *c, GLenum pname, const GLfloat *params) { fog_v(c, pname, params); }

/* Integer colours map [-2^31, 2^31 - 1] onto [-1, 1] (2.14, table 2.9);
 * the other values convert directly. */
void fs_exec_Fogiv(fs_context *c, GLenum pname, const GLint *params)
{
    float f[4] = {0};
    int n = fs_fog_param_count(pname);
    for (int i = 0; i < n; i++)
        f[i] = pname == GL_FOG_COLOR ? (float)((2.0 * params[i] + 1.0) / 4294967295.0) : (float)params[i];
    fog_v(c, pname, f);
}

/* The scalar forms: the spec lists GL_FOG_COLOR for the vector forms only,
 * but OSMesa takes it there too, as (param, 0, 0, 0), without an error
 * (measured by tests/test_state_table.c); so does the model. */
void fs_exec_Fogf(fs_context *c, GLenum pname, GLfloat param)
{
    const float v[4] = {param, 0, 0, 0};
    fog_v(c, pname, v);
}

void fs_exec_Fogi(fs_context *c, GLenum pname, GLint param)
{
    const GLint v[4] = {param, 0, 0, 0};
    fs_exec_Fogiv(c, pname, v);
}

/* The constants of llvmpipe's fog (Mesa's "optimized" fog parameters),
 * rounded to float as Mesa rounds them: LINEAR as one multiply-add
 * c (-1/(e - s)) + e/(e - s), 1 when e == s; EXP and EXP2 as 2^-x with
 * the density divided by ln 2, respectively sqrt(ln 2), in double. */
void fs_fog_validate(fs_context *c)
{
    fs_fog_state *f = &c->st.fog;
    float v = f->end == f->start ? 1.0f : -1.0f / (f->end - f->start);
    f->params[0] = v;
    f->params[1] = f->end * -v;
    f->params[2] = (float)((double)f->density * 1.44269504088896340736);  /* 1 / ln 2 */
    f->params[3] = (float)((double)f->density * 1.201122408786449815);    /* 1 / sqrt(ln 2) */
}

/* 2^x as llvmpipe's shaders compute it (gallivm's lp_build_exp2): x
 * clamped to [-126.99999, 128], 2^floor(x) made in the exponent bits and
 * 2^fraction from a degree-5 minimax polynomial, its even and odd terms
 * summed apart in fused multiply-adds; an approximation, so not exp2f. */
static float lp_exp2(float x)
{
    static const float k[6] = {1.0f, 0.693153073200168932794f, 0.240153617044375388211f,
                               0.0558263180532956664775f, 0.00898934009049466391101f,
                               0.00187757667519147912699f};
    if (!(x < 128.0f))
        x = x == x ? 128.0f : x;
    if (!(x > -126.99999f))
        x = -126.99999f; /* NaN too: nothing defines fog of a NaN coordinate */
    float ip = floorf(x);
    float fp = x - ip;
    float x2 = fp * fp;
    float odd = fmaf(x2, fmaf(x2, k[5], k[3]), k[1]);
    float even = fmaf(x2, fmaf(x2, k[4], k[2]), k[0]);
    float poly = fmaf(odd, fp, even);
    union { uint32_t u; float f; } e = {(uint32_t)((int32_t)ip + 127) << 23};
    return e.f * poly;
}

/* The fog factor f of coordinate z (3.10 eqs. 3.27-3.29), clamped. */
static float fog_factor(const fs_fog_state *f, float z)
{
    float t;
    switch (f->mode) {
    case GL_LINEAR: t = z * f->params[0] + f->params[1]; break;
    case GL_EXP: t = lp_exp2(-(z * f->params[2])); break;
    default: {
        float d = z * f->params[3];
        t = lp_exp2(-(d * d));
        break;
    }
    }
    return t > 0.0f ? (t < 1.0f ? t : 1.0f) : 0.0f;
}

void fs_fog_quad(fs_context *c, fs_quad *q, unsigned mask)
{
    const fs_fog_state *f = &c->st.fog;
    if (!c->raster.interpolate_fog)
        return; /* a quad from no vertex stage carries no fog coordinate */
    for (int i = 0; i < 4; i++) {
        if (!(mask >> i & 1u))
            continue;
        float t = fog_factor(f, q->fog[i]);
        float u = 1.0f - t;
        for (int k = 0; k < 3; k++)
            q->color[i][k] = f->color[k] * u + q->color[i][k] * t;
    }
}

/* glFogCoord (2.7): the current fog coordinate, not clamped. */
void fs_exec_FogCoordf(fs_context *c, GLfloat coord) { c->current.fog_coord = coord; }
void fs_exec_FogCoordd(fs_context *c, GLdouble coord) { c->current.fog_coord = (float)coord; }
void fs_exec_FogCoordfv(fs_context *c, const GLfloat *coord) { c->current.fog_coord = coord[0]; }
void fs_exec_FogCoorddv(fs_context *c, const GLdouble *coord) { c->current.fog_coord = (float)coord[0]; }
