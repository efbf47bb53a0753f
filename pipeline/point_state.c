/*
 * Point parameters (GL 1.4; GL 1.5 spec 3.3) and the point sprite's
 * coordinate origin (GL 2.0 spec 3.3): glPointParameter{f,i}{,v}, and the
 * size a point is drawn with.
 *
 * The size (3.3): without distance attenuation, GL_POINT_SIZE clamped to
 * [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX] (Mesa's state tracker clamps the
 * rasterizer's size so); with it, each vertex's derived size
 * size * sqrt(1 / (a + b*d + c*d^2)) clamped again, computed by the vertex
 * stage (vertex_array.c, fs_point_derived_size).  The fade threshold is
 * stored and queried only: llvmpipe's fixed-function shaders do not fade
 * (measured on OSMesa, tests/test_point_params.c: alpha is the vertex's
 * below the threshold too).
 */
#include "context.h"
#include "vertex_internal.h"

int fs_point_param_count(GLenum pname) { return pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1; }

bool fs_point_attenuated(const fs_raster_state *r)
{
    /* Mesa's _Attenuated: any coefficient but the initial (1, 0, 0). */
    return r->point_atten[0] != 1.0f || r->point_atten[1] != 0.0f || r->point_atten[2] != 0.0f;
}

static float clamp_size(float v, float lo, float hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

float fs_point_size(const fs_raster_state *r)
{
    return clamp_size(r->point_size, r->point_size_min, r->point_size_max);
}

/* The derived size of a vertex at eye-plane distance d = |z_e| (GL 1.5
 * spec 3.3 names the eye distance; Mesa's fixed-function vertex program
 * takes |z_e|, as it does for fog): GL_POINT_SIZE as it is (measured on
 * OSMesa: size 2, minimum 3, attenuation 1/4 draws 4 pixels wide, not 6;
 * size 20, maximum 10, attenuation 4 draws 10, not 5) times the reciprocal
 * square root of |a + d*(b + d*c)| (two multiply-adds for the program's
 * MADs, taken as fused; unfused ones give the same images in
 * tests/test_point_params.c, the size being snapped to 1/256 pixel),
 * clamped by a max then a min to the bounds
 * fs_vs_prepare narrows to the implementation's range. */
float fs_point_derived_size(const fs_vs_setup *s, float d)
{
    float q = fmaf(d, s->point_atten[2], s->point_atten[1]);
    q = fmaf(d, q, s->point_atten[0]);
    float size = (1.0f / sqrtf(fabsf(q))) * s->point_size;
    size = size > s->point_size_min ? size : s->point_size_min;
    return size < s->point_size_max ? size : s->point_size_max;
}

static void point_parameter(fs_context *c, GLenum pname, const float *v)
{
    fs_raster_state *r = &c->raster;
    switch (pname) {
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
        /* 3.3: a negative size or threshold is INVALID_VALUE. */
        if (!(v[0] >= 0.0f)) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        if (pname == GL_POINT_SIZE_MIN)
            r->point_size_min = v[0];
        else if (pname == GL_POINT_SIZE_MAX)
            r->point_size_max = v[0];
        else
            r->point_fade_threshold = v[0];
        break;
    case GL_POINT_DISTANCE_ATTENUATION:
        /* No error case (3.3). */
        r->point_atten[0] = v[0];
        r->point_atten[1] = v[1];
        r->point_atten[2] = v[2];
        break;
    case GL_POINT_SPRITE_COORD_ORIGIN: {
        /* GL 2.0 spec 3.3: GL_LOWER_LEFT or GL_UPPER_LEFT, else
         * INVALID_VALUE (as Mesa answers: the enum is right, its value
         * is not). */
        GLenum e = (GLenum)(GLint)v[0];
        if (e != GL_LOWER_LEFT && e != GL_UPPER_LEFT) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        r->sprite_origin = e;
        break;
    }
    default:
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_state_mark(c, GL_POINT_BIT);
}

/* The scalar forms take the distance attenuation too, as (param, 0, 0):
 * the spec allows only the vector forms for it, but Mesa passes every
 * scalar form on as a vector (measured on OSMesa: no error, and
 * glGetFloatv answers (param, 0, 0)). */
void fs_exec_PointParameterf(fs_context *c, GLenum pname, GLfloat param)
{
    const float v[3] = {param, 0.0f, 0.0f};
    point_parameter(c, pname, v);
}

void fs_exec_PointParameteri(fs_context *c, GLenum pname, GLint param)
{
    const float v[3] = {(float)param, 0.0f, 0.0f};
    point_parameter(c, pname, v);
}

void fs_exec_PointParameterfv(fs_context *c, GLenum pname, const GLfloat *params)
{
    float v[3] = {params[0], 0.0f, 0.0f};
    if (pname == GL_POINT_DISTANCE_ATTENUATION) {
        v[1] = params[1];
        v[2] = params[2];
    }
    point_parameter(c, pname, v);
}

void fs_exec_PointParameteriv(fs_context *c, GLenum pname, const GLint *params)
{
    float v[3] = {(float)params[0], 0.0f, 0.0f};
    if (pname == GL_POINT_DISTANCE_ATTENUATION) {
        v[1] = (float)params[1];
        v[2] = (float)params[2];
    }
    point_parameter(c, pname, v);
}
