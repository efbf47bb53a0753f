/*
 * Garbage: the content of a virtual garbage can, many small independent
 * objects that move between frames.
 *
 * Workload size: Hüttner 1999, Table 3.1 and sec. 3.1.9: 2,500 independent,
 * potentially moving objects of about 2,100 polygons each, 5,331,146
 * polygons in all (after Zhang et al. [114]).
 *
 * Objects are balls (GL_TRIANGLE_FAN poles, GL_TRIANGLE_STRIP bands), rings
 * (GL_TRIANGLE_STRIP tori), cans (GL_QUAD_STRIP sides, fan caps) and boxes
 * (GL_QUADS grids).  Each shape is compiled twice, at the two per-object
 * budgets floor(T/n) and floor(T/n)+1, and the first T mod n objects take
 * the larger one, so the frame has exactly T triangles.  Inside a shape, a
 * flat label (GL_POLYGON) takes what the tessellation leaves over.
 * Colour and motion are per object, outside the lists.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sg.h"

static int garbage_isqrt(uint64_t v) { return (int)sqrt((double)v); }

/* Emits one shape of exactly 'b' triangles (b >= 40). */
static void garbage_shape(sg *s, int kind, uint64_t b)
{
    uint64_t body = 0;
    int q = garbage_isqrt(b);
    switch (kind) {
    case 0: { /* ball: 2 sl (st - 1) */
        int sl = q < 6 ? 6 : q;
        int st = (int)(b / (2ull * (uint64_t)sl)) + 1;
        if (st > sl) st = sl;
        body = 2ull * (uint64_t)sl * (uint64_t)(st - 1);
        sg_sphere(s, 1.0f, sl, st);
        break;
    }
    case 1: { /* ring: 2 nu nv */
        int nv = q / 2 < 3 ? 3 : q / 2;
        int nu = (int)(b / (2ull * (uint64_t)nv));
        body = 2ull * (uint64_t)nu * (uint64_t)nv;
        sg_torus(s, 0.8f, 0.3f, nu, nv);
        break;
    }
    case 2: { /* can: 2 sl st + 2 sl */
        int sl = q < 6 ? 6 : q;
        int st = (int)((b - 2ull * (uint64_t)sl) / (2ull * (uint64_t)sl));
        if (st < 1) { sl = 6; st = (int)((b - 12) / 12); }
        body = 2ull * (uint64_t)sl * (uint64_t)st + 2ull * (uint64_t)sl;
        G0(s, PushMatrix);
        G(s, Translatef, 0.0f, -0.9f, 0.0f);
        sg_cylinder(s, 0.6f, 1.8f, sl, st, 1);
        G0(s, PopMatrix);
        break;
    }
    default: { /* box: six m x m grids, 12 m^2 */
        int m = garbage_isqrt(b / 12);
        if (m < 1) m = 1;
        body = 12ull * (uint64_t)m * (uint64_t)m;
        const float e = 0.7f;
        const float o[6][3] = {{e, -e, e}, {-e, -e, -e}, {-e, e, -e}, {-e, -e, -e}, {-e, -e, e}, {e, -e, -e}};
        const float u[6][3] = {{0, 0, -2 * e}, {0, 0, 2 * e}, {0, 0, 2 * e}, {2 * e, 0, 0}, {2 * e, 0, 0}, {-2 * e, 0, 0}};
        const float v[6][3] = {{0, 2 * e, 0}, {0, 2 * e, 0}, {2 * e, 0, 0}, {0, 0, 2 * e}, {0, 2 * e, 0}, {0, 2 * e, 0}};
        for (int f = 0; f < 6; f++) sg_grid(s, o[f], u[f], v[f], m, m);
        break;
    }
    }
    /* The label sits just above the shape's top. */
    if (b > body) {
        float top = kind == 0 ? 1.0f : kind == 1 ? 0.3f : kind == 2 ? 0.9f : 0.7f;
        sg_disc(s, 0, top + 0.01f, 0, 0.25f, b - body, 1);
    }
}

int sg_garbage_plan_make(sg_garbage_plan *G, const sg_params *p, char *err, size_t errlen)
{
    uint64_t n;
    if (p->paper) {
        n = 2500; /* Hüttner 1999, Table 3.1 */
    } else {
        n = (uint64_t)(0.5 * sqrt((double)p->target));
        if (n < 4) n = 4;
        if (n > 2500) n = 2500;
    }
    G->n = n;
    G->per = p->target / n;
    G->extra = p->target % n;
    /* The can: a box of side ~ cube root of n, objects ~2 m apart. */
    G->side = 2.2f * (float)cbrt((double)n);
    if (G->per < 40) {
        snprintf(err, errlen, "garbage: %llu triangles per object are too few", (unsigned long long)G->per);
        return -1;
    }
    return 0;
}

void sg_garbage_compile(sg *s, const sg_garbage_plan *G, GLuint base)
{
    for (int k = 0; k < 4; k++)
        for (int big = 0; big < 2; big++) {
            sg_new_list(s, base + (GLuint)(2 * k + big));
            garbage_shape(s, k, G->per + (uint64_t)big);
            sg_end_list(s);
        }
}

void sg_garbage_object(sg_rng *r, const sg_garbage_plan *G, uint64_t i, float t, sg_garbage_obj *o)
{
    float side = G->side;
    int kind = sg_rng_int(r, 4);
    float x = (float)sg_rng_range(r, -0.5, 0.5) * side, y = (float)sg_rng_range(r, -0.5, 0.5) * side;
    float z = (float)sg_rng_range(r, -0.5, 0.5) * side;
    float vx = (float)sg_rng_range(r, -0.3, 0.3), vy = (float)sg_rng_range(r, -0.3, 0.1);
    float vz = (float)sg_rng_range(r, -0.3, 0.3);
    float ax = (float)sg_rng_range(r, -1, 1), ay = (float)sg_rng_range(r, -1, 1);
    float az = (float)sg_rng_range(r, -1, 1);
    float a0 = (float)sg_rng_range(r, 0, 360), spin = (float)sg_rng_range(r, -20, 20);
    o->scale = (float)sg_rng_range(r, 0.6, 1.3);
    o->color[0] = (float)sg_rng_range(r, 0.2, 1);
    o->color[1] = (float)sg_rng_range(r, 0.2, 1);
    o->color[2] = (float)sg_rng_range(r, 0.2, 1);
    o->pos[0] = x + vx * t;
    o->pos[1] = y + vy * t;
    o->pos[2] = z + vz * t;
    o->angle = a0 + spin * t;
    o->axis[0] = ax;
    o->axis[1] = ay;
    o->axis[2] = az + 0.01f;
    o->list = 2 * kind + (i < G->extra ? 1 : 0);
}

void sg_garbage_view(const sg_garbage_plan *G, float t, float eye[3], float at[3])
{
    float ang = 0.4f + 0.15f * t, side = G->side;
    eye[0] = 1.6f * side * sinf(ang);
    eye[1] = 0.9f * side;
    eye[2] = 1.6f * side * cosf(ang);
    at[0] = at[1] = at[2] = 0;
}

void sg_garbage_state(sg *s)
{
    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, ShadeModel, GL_SMOOTH);
    sg_lighting(s, GL_FRONT);
    G(s, Enable, GL_NORMALIZE); /* objects are scaled */
    const float spec[4] = {0.4f, 0.4f, 0.4f, 1};
    G(s, Materialfv, GL_FRONT, GL_SPECULAR, spec);
    G(s, Materialf, GL_FRONT, GL_SHININESS, 24.0f);
}

void sg_garbage_lights(sg *s)
{
    const float l0[4] = {0.3f, 1.0f, 0.5f, 0}, d0[4] = {0.8f, 0.8f, 0.75f, 1}, sp[4] = {1, 1, 1, 1};
    const float l1[4] = {-0.8f, 0.2f, -0.3f, 0}, d1[4] = {0.3f, 0.3f, 0.45f, 1};
    const float l2[4] = {0.0f, -1.0f, 0.2f, 0}, d2[4] = {0.25f, 0.2f, 0.1f, 1};
    sg_light(s, GL_LIGHT0, l0, d0, NULL, sp);
    sg_light(s, GL_LIGHT1, l1, d1, NULL, NULL);
    sg_light(s, GL_LIGHT2, l2, d2, NULL, NULL);
}

int sg_scene_garbage(sg *s, const sg_params *p, char *err, size_t errlen)
{
    sg_garbage_plan Gp;
    if (sg_garbage_plan_make(&Gp, p, err, errlen) != 0) return -1;
    GLuint base = sg_gen_lists(s, 8);
    if (!base) {
        snprintf(err, errlen, "garbage: glGenLists failed");
        return -1;
    }
    sg_garbage_compile(s, &Gp, base);
    sg_garbage_state(s);
    sg_perspective(s, SG_GARBAGE_FOVY, (double)p->width / p->height, SG_GARBAGE_ZNEAR, SG_GARBAGE_ZFAR);

    for (int fr = 0; fr < p->frames; fr++) {
        float t = (float)fr;
        sg_frame_begin(s, 0.15f, 0.15f, 0.15f);
        G0(s, LoadIdentity);
        float eye[3], at[3];
        sg_garbage_view(&Gp, t, eye, at);
        const float up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        sg_garbage_lights(s);
        sg_rng r;
        sg_rng_seed(&r, p->seed * 7919 + 11);
        for (uint64_t i = 0; i < Gp.n; i++) {
            sg_garbage_obj o;
            sg_garbage_object(&r, &Gp, i, t, &o);
            G(s, Color3f, o.color[0], o.color[1], o.color[2]);
            G0(s, PushMatrix);
            G(s, Translatef, o.pos[0], o.pos[1], o.pos[2]);
            G(s, Rotatef, o.angle, o.axis[0], o.axis[1], o.axis[2]);
            G(s, Scalef, o.scale, o.scale, o.scale);
            sg_call_list(s, base + (GLuint)o.list);
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}
