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

int sg_scene_garbage(sg *s, const sg_params *p, char *err, size_t errlen)
{
    uint64_t n;
    if (p->paper) {
        n = 2500; /* Hüttner 1999, Table 3.1 */
    } else {
        n = (uint64_t)(0.5 * sqrt((double)p->target));
        if (n < 4) n = 4;
        if (n > 2500) n = 2500;
    }
    uint64_t q = p->target / n, extra = p->target % n;
    if (q < 40) {
        snprintf(err, errlen, "garbage: %llu triangles per object are too few", (unsigned long long)q);
        return -1;
    }
    GLuint base = sg_gen_lists(s, 8);
    if (!base) {
        snprintf(err, errlen, "garbage: glGenLists failed");
        return -1;
    }
    for (int k = 0; k < 4; k++)
        for (int big = 0; big < 2; big++) {
            sg_new_list(s, base + (GLuint)(2 * k + big));
            garbage_shape(s, k, q + (uint64_t)big);
            sg_end_list(s);
        }

    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, ShadeModel, GL_SMOOTH);
    sg_lighting(s, GL_FRONT);
    G(s, Enable, GL_NORMALIZE); /* objects are scaled */
    const float spec[4] = {0.4f, 0.4f, 0.4f, 1};
    G(s, Materialfv, GL_FRONT, GL_SPECULAR, spec);
    G(s, Materialf, GL_FRONT, GL_SHININESS, 24.0f);
    sg_perspective(s, 50.0, (double)p->width / p->height, 1.0, 1000.0);

    /* The can: a box of side ~ cube root of n, objects ~2 m apart. */
    float side = 2.2f * (float)cbrt((double)n);
    for (int fr = 0; fr < p->frames; fr++) {
        float t = (float)fr;
        sg_frame_begin(s, 0.15f, 0.15f, 0.15f);
        G0(s, LoadIdentity);
        float ang = 0.4f + 0.15f * t;
        const float eye[3] = {1.6f * side * sinf(ang), 0.9f * side, 1.6f * side * cosf(ang)};
        const float at[3] = {0, 0, 0}, up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        const float l0[4] = {0.3f, 1.0f, 0.5f, 0}, d0[4] = {0.8f, 0.8f, 0.75f, 1}, sp[4] = {1, 1, 1, 1};
        const float l1[4] = {-0.8f, 0.2f, -0.3f, 0}, d1[4] = {0.3f, 0.3f, 0.45f, 1};
        const float l2[4] = {0.0f, -1.0f, 0.2f, 0}, d2[4] = {0.25f, 0.2f, 0.1f, 1};
        sg_light(s, GL_LIGHT0, l0, d0, NULL, sp);
        sg_light(s, GL_LIGHT1, l1, d1, NULL, NULL);
        sg_light(s, GL_LIGHT2, l2, d2, NULL, NULL);
        sg_rng r;
        sg_rng_seed(&r, p->seed * 7919 + 11);
        for (uint64_t i = 0; i < n; i++) {
            int kind = sg_rng_int(&r, 4);
            float x = (float)sg_rng_range(&r, -0.5, 0.5) * side, y = (float)sg_rng_range(&r, -0.5, 0.5) * side;
            float z = (float)sg_rng_range(&r, -0.5, 0.5) * side;
            float vx = (float)sg_rng_range(&r, -0.3, 0.3), vy = (float)sg_rng_range(&r, -0.3, 0.1);
            float vz = (float)sg_rng_range(&r, -0.3, 0.3);
            float ax = (float)sg_rng_range(&r, -1, 1), ay = (float)sg_rng_range(&r, -1, 1);
            float az = (float)sg_rng_range(&r, -1, 1);
            float a0 = (float)sg_rng_range(&r, 0, 360), spin = (float)sg_rng_range(&r, -20, 20);
            float sc = (float)sg_rng_range(&r, 0.6, 1.3);
            float cr = (float)sg_rng_range(&r, 0.2, 1), cg = (float)sg_rng_range(&r, 0.2, 1);
            float cb = (float)sg_rng_range(&r, 0.2, 1);
            G(s, Color3f, cr, cg, cb);
            G0(s, PushMatrix);
            G(s, Translatef, x + vx * t, y + vy * t, z + vz * t);
            G(s, Rotatef, a0 + spin * t, ax, ay, az + 0.01f);
            G(s, Scalef, sc, sc, sc);
            sg_call_list(s, base + (GLuint)(2 * kind + (i < extra ? 1 : 0)));
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}
