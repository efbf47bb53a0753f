/*
 * glFog (GL 1.5 spec 3.10): the fog parameters, stored for glGet and
 * glPushAttrib(GL_FOG_BIT).  Fog itself is not modelled: enabling GL_FOG
 * is counted as unsupported (pipeline/state.def, ENU).
 */
#include "context.h"

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
