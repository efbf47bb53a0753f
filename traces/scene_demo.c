/*
 * Demo: a small, lit scene for the bundled trace of `make run`.
 *
 * No paper workload: it exists to show every primitive type and both
 * shading models in one picture cheaply.  Everything is immediate mode,
 * redrawn each frame (the other scenes use lists and arrays).
 */
#include <math.h>
#include "sg.h"

int sg_scene_demo(sg *s, const sg_params *p, char *err, size_t errlen)
{
    (void)err;
    (void)errlen;
    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, CullFace, GL_BACK);
    G(s, FrontFace, GL_CCW);
    sg_lighting(s, GL_FRONT);
    const float spec[4] = {0.8f, 0.8f, 0.8f, 1};
    G(s, Materialfv, GL_FRONT, GL_SPECULAR, spec);
    G(s, Materialf, GL_FRONT, GL_SHININESS, 40.0f);
    const float amb[4] = {0.12f, 0.12f, 0.14f, 1};
    G(s, LightModelfv, GL_LIGHT_MODEL_AMBIENT, amb);
    sg_perspective(s, 45.0, (double)p->width / p->height, 1.0, 100.0);

    for (int fr = 0; fr < p->frames; fr++) {
        float ang = 0.5f + 0.25f * (float)fr;
        sg_frame_begin(s, 0.08f, 0.09f, 0.12f);
        G0(s, LoadIdentity);
        const float eye[3] = {12.0f * sinf(ang), 6.5f, 12.0f * cosf(ang)}, at[3] = {0, 1.0f, 0}, up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        /* A white key light, and a red and a blue point light. */
        const float l0[4] = {0.4f, 1.0f, 0.6f, 0}, d0[4] = {0.8f, 0.8f, 0.75f, 1}, s0[4] = {1, 1, 1, 1};
        const float l1[4] = {-4.0f, 3.0f, 2.0f, 1}, d1[4] = {0.9f, 0.2f, 0.15f, 1};
        const float l2[4] = {4.0f, 2.0f, -3.0f, 1}, d2[4] = {0.15f, 0.3f, 0.95f, 1};
        sg_light(s, GL_LIGHT0, l0, d0, NULL, s0);
        sg_light(s, GL_LIGHT1, l1, d1, NULL, s0);
        sg_light(s, GL_LIGHT2, l2, d2, NULL, s0);
        G(s, Lightf, GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.02f);
        G(s, Lightf, GL_LIGHT2, GL_QUADRATIC_ATTENUATION, 0.02f);

        /* Checkerboard floor: flat-shaded GL_QUADS. */
        G(s, ShadeModel, GL_FLAT);
        sg_begin(s, GL_QUADS);
        sg_nrm(s, 0, 1, 0);
        for (int j = 0; j < 16; j++)
            for (int i = 0; i < 16; i++) {
                float x0 = -8.0f + (float)i, z0 = -8.0f + (float)j;
                float c = ((i + j) & 1) ? 0.85f : 0.35f;
                sg_col(s, c, c, c * 0.95f);
                sg_vtx(s, x0, 0, z0);
                sg_vtx(s, x0, 0, z0 + 1);
                sg_vtx(s, x0 + 1, 0, z0 + 1);
                sg_vtx(s, x0 + 1, 0, z0);
            }
        sg_end(s);

        /* A pyramid: GL_TRIANGLES sides on a GL_POLYGON base (flat). */
        G0(s, PushMatrix);
        G(s, Translatef, 3.5f, 0.0f, 2.5f);
        sg_col(s, 0.95f, 0.75f, 0.2f);
        const float apex[3] = {0, 2.2f, 0};
        const float base[4][3] = {{-1, 0.01f, 1}, {1, 0.01f, 1}, {1, 0.01f, -1}, {-1, 0.01f, -1}};
        sg_begin(s, GL_TRIANGLES);
        for (int k = 0; k < 4; k++) {
            const float *a = base[k], *b = base[(k + 1) % 4];
            float mx = 0.5f * (a[0] + b[0]), mz = 0.5f * (a[2] + b[2]);
            sg_nrm(s, mx * 2.2f, 1.0f, mz * 2.2f);
            sg_vtxv(s, a);
            sg_vtxv(s, b);
            sg_vtxv(s, apex);
        }
        sg_end(s);
        sg_begin(s, GL_POLYGON);
        sg_nrm(s, 0, -1, 0);
        for (int k = 3; k >= 0; k--) sg_vtxv(s, base[k]);
        sg_end(s);
        G0(s, PopMatrix);

        /* Smooth-shaded curved objects. */
        G(s, ShadeModel, GL_SMOOTH);
        G0(s, PushMatrix);
        G(s, Translatef, 0.0f, 1.6f, 0.0f);
        G(s, Rotatef, 20.0f + 15.0f * (float)fr, 1.0f, 0.0f, 0.3f);
        sg_col(s, 0.85f, 0.25f, 0.3f);
        sg_torus(s, 1.5f, 0.5f, 32, 16);
        G0(s, PopMatrix);

        G0(s, PushMatrix);
        G(s, Translatef, -3.0f, 1.3f, 2.5f);
        sg_col(s, 0.3f, 0.8f, 0.4f);
        sg_sphere(s, 1.3f, 28, 14);
        G0(s, PopMatrix);

        for (int k = 0; k < 2; k++) {
            G0(s, PushMatrix);
            G(s, Translatef, k ? 3.5f : -3.5f, 0.0f, -3.0f);
            sg_col(s, 0.7f, 0.7f, 0.75f);
            sg_cylinder(s, 0.5f, 3.0f, 20, 4, 1);
            /* A fan disc on top of each column. */
            sg_col(s, 0.95f, 0.95f, 0.5f);
            sg_disc(s, 0, 3.01f, 0, 0.8f, 24, 0);
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}
