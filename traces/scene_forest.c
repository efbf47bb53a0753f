/*
 * Forest: 12 dense leafy trees in front of an octagonal castle.
 *
 * Workload size: Hüttner 1999, Table 3.1 and sec. 3.1.9: 12 "tree with
 * leaves" objects of 28,500 polygons each and a model of Castle del Monte of
 * 110,981 polygons behind the trees (452,981 triangles).  The scattered but
 * dense leaves are what makes this scene hard for occlusion culling.
 *
 * Trees: three variants, each a display list: a trunk (GL_QUAD_STRIP
 * cylinder, immediate mode) and leaves from vertex arrays (glDrawArrays,
 * GL_TRIANGLES, per-vertex colours), drawn with culling off because leaves
 * are seen from both sides.  The castle: an octagon with a courtyard and
 * eight octagonal towers; its wall subdivision and tower stacks take the
 * budget and the courtyard floor (a GL_TRIANGLE_FAN) absorbs the rest.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sg.h"

#define FOREST_PI 3.14159265358979323846f

static uint64_t forest_trunk_tris(int slices, int stacks) { return 2ull * (uint64_t)slices * (uint64_t)stacks; }

static int forest_tree(sg *s, uint64_t seed, uint64_t budget)
{
    sg_rng r;
    sg_rng_seed(&r, seed);
    int slices = budget > 2000 ? 12 : 6, stacks = budget > 2000 ? 6 : 2;
    uint64_t trunk = forest_trunk_tris(slices, stacks);
    if (budget < trunk + 1) return -1;
    uint64_t leaves = budget - trunk;
    float height = (float)sg_rng_range(&r, 5.0, 7.0);
    G(s, Color3f, 0.35f, 0.24f, 0.12f);
    sg_cylinder(s, 0.35f, height + 1.0f, slices, stacks, 0);

    size_t nv = (size_t)leaves * 3;
    float *pos = sg_buf(s, 0, nv * 3 * sizeof(float));
    float *nrm = sg_buf(s, 1, nv * 3 * sizeof(float));
    GLubyte *col = sg_buf(s, 2, nv * 4);
    if (!pos || !nrm || !col) return -1;
    /* Leaves fill an ellipsoidal crown; the leaf size shrinks as their
     * number grows so that the crown stays equally dense. */
    float crown_r = 3.5f, crown_h = 4.5f;
    float leaf = 0.9f * powf(1000.0f / (float)leaves, 0.33f);
    if (leaf > 1.2f) leaf = 1.2f;
    for (uint64_t k = 0; k < leaves; k++) {
        float cx, cy, cz;
        do {
            cx = (float)sg_rng_range(&r, -1, 1);
            cy = (float)sg_rng_range(&r, -1, 1);
            cz = (float)sg_rng_range(&r, -1, 1);
        } while (cx * cx + cy * cy + cz * cz > 1.0f);
        float c[3] = {cx * crown_r, height + cy * crown_h, cz * crown_r};
        float a = (float)sg_rng_range(&r, 0, 2 * FOREST_PI), b = (float)sg_rng_range(&r, -1.2, 1.2);
        float n[3] = {cosf(a) * cosf(b), sinf(b), sinf(a) * cosf(b)};
        /* Two edge directions perpendicular to the normal. */
        float t1[3] = {-sinf(a), 0, cosf(a)};
        float t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
        float g = (float)sg_rng_range(&r, 0.0, 1.0);
        for (int v = 0; v < 3; v++) {
            float ang = 2.0f * FOREST_PI * (float)v / 3.0f + a;
            float *pp = pos + (k * 3 + (uint64_t)v) * 3, *nn = nrm + (k * 3 + (uint64_t)v) * 3;
            GLubyte *cc = col + (k * 3 + (uint64_t)v) * 4;
            for (int i = 0; i < 3; i++) {
                pp[i] = c[i] + leaf * (cosf(ang) * t1[i] + sinf(ang) * t2[i]);
                nn[i] = n[i];
            }
            cc[0] = (GLubyte)(30 + 50 * g);
            cc[1] = (GLubyte)(90 + 100 * g + 20 * v);
            cc[2] = (GLubyte)(20 + 30 * g);
            cc[3] = 255;
        }
    }
    G(s, Disable, GL_CULL_FACE);
    G(s, EnableClientState, GL_VERTEX_ARRAY);
    G(s, EnableClientState, GL_NORMAL_ARRAY);
    G(s, EnableClientState, GL_COLOR_ARRAY);
    G(s, VertexPointer, 3, GL_FLOAT, 0, pos);
    G(s, NormalPointer, GL_FLOAT, 0, nrm);
    G(s, ColorPointer, 4, GL_UNSIGNED_BYTE, 0, col);
    sg_draw_arrays(s, GL_TRIANGLES, 0, (GLsizei)nv);
    G(s, DisableClientState, GL_COLOR_ARRAY);
    G(s, DisableClientState, GL_NORMAL_ARRAY);
    G(s, DisableClientState, GL_VERTEX_ARRAY);
    G(s, Enable, GL_CULL_FACE);
    return 0;
}

typedef sg_forest_plan forest_castle; /* the castle's fields of the plan */

/* The meadow the castle and the trees stand on. */
void sg_forest_ground(sg *s)
{
    G(s, Color3f, 0.55f, 0.6f, 0.45f);
    const float go[3] = {-120, 0, -120}, gu[3] = {0, 0, 240}, gv[3] = {240, 0, 0};
    sg_grid(s, go, gu, gv, 1, 1);
}

/* The castle: outer and courtyard octagon walls, a roof ring, towers (the
 * scene's castle list has the ground first). */
static void forest_castle_walls(sg *s, const forest_castle *C)
{
    const float R = 26.0f, Rc = 13.0f, H = 20.0f;
    G(s, Color3f, 0.82f, 0.74f, 0.6f);
    for (int k = 0; k < 8; k++) {
        float a0 = FOREST_PI / 4 * (float)k + FOREST_PI / 8, a1 = a0 + FOREST_PI / 4;
        /* Corners counter-clockwise seen from above: x = cos, z = -sin. */
        float p0[3] = {R * cosf(a0), 0, -R * sinf(a0)}, p1[3] = {R * cosf(a1), 0, -R * sinf(a1)};
        float q0[3] = {Rc * cosf(a0), 0, -Rc * sinf(a0)}, q1[3] = {Rc * cosf(a1), 0, -Rc * sinf(a1)};
        const float v[3] = {0, H, 0};
        /* Outer wall faces out: from p0 to p1 then up. */
        float ou[3] = {p1[0] - p0[0], 0, p1[2] - p0[2]};
        sg_grid(s, p0, ou, v, C->sub, C->sub);
        /* Courtyard wall faces the courtyard: from q1 to q0. */
        float iu[3] = {q0[0] - q1[0], 0, q0[2] - q1[2]};
        sg_grid(s, q1, iu, v, C->sub, C->sub);
        /* Roof between the two, facing up. */
        sg_begin(s, GL_QUAD_STRIP);
        sg_nrm(s, 0, 1, 0);
        for (int i = 0; i <= C->sub; i++) {
            float t = (float)i / (float)C->sub;
            float pr[3] = {p0[0] + (p1[0] - p0[0]) * t, H, p0[2] + (p1[2] - p0[2]) * t};
            float qr[3] = {q0[0] + (q1[0] - q0[0]) * t, H, q0[2] + (q1[2] - q0[2]) * t};
            sg_vtxv(s, qr);
            sg_vtxv(s, pr);
        }
        sg_end(s);
    }
    G(s, Color3f, 0.78f, 0.7f, 0.56f);
    for (int k = 0; k < 8; k++) {
        float a = FOREST_PI / 4 * (float)k + FOREST_PI / 8;
        G0(s, PushMatrix);
        G(s, Translatef, (R + 1.0f) * cosf(a), 0.0f, -(R + 1.0f) * sinf(a));
        sg_cylinder(s, 4.5f, H + 4.0f, 8, C->stacks, 1);
        G0(s, PopMatrix);
    }
    G(s, Color3f, 0.6f, 0.55f, 0.45f);
    sg_disc(s, 0, 0.05f, 0, Rc - 0.2f, C->court, 0);
}

static void forest_castle_draw(sg *s, const forest_castle *C)
{
    sg_forest_ground(s);
    forest_castle_walls(s, C);
}

static uint64_t forest_castle_tris(const forest_castle *C)
{
    sg m;
    sg_init(&m, NULL);
    forest_castle_draw(&m, C);
    uint64_t t = m.tris;
    sg_free(&m);
    return t;
}

int sg_forest_plan_make(sg_forest_plan *F, const sg_params *p, char *err, size_t errlen)
{
    /* Hüttner 1999, Table 3.1: 12 x 28,500 + 110,981; other targets keep
     * the castle's share of the paper scene. */
    uint64_t tree, castle;
    if (p->paper) {
        tree = 28500;
        castle = 110981;
    } else {
        castle = (uint64_t)((double)p->target * 110981.0 / 452981.0);
        tree = (p->target - castle) / 12;
        castle = p->target - 12 * tree;
    }
    forest_castle C = {1, 1, 1, 0};
    if (forest_castle_tris(&C) > castle) {
        snprintf(err, errlen, "forest: %llu triangles are too few for the castle", (unsigned long long)castle);
        return -1;
    }
    for (;;) {
        forest_castle n = C;
        n.sub++;
        if (forest_castle_tris(&n) > castle) break;
        C = n;
    }
    forest_castle C2 = C;
    C2.stacks = 2;
    uint64_t c1 = forest_castle_tris(&C), per = forest_castle_tris(&C2) - c1;
    C.stacks = 1 + (int)((castle - c1) / per);
    C.court = 1;
    C.court += castle - forest_castle_tris(&C);
    C.tree = tree;
    *F = C;
    return 0;
}

int sg_forest_compile(sg *s, const sg_forest_plan *F, uint64_t seed, GLuint base, int with_ground, char *err,
                      size_t errlen)
{
    for (int v = 0; v < 3; v++) {
        sg_new_list(s, base + (GLuint)v);
        int rc = forest_tree(s, seed * 131 + (uint64_t)v, F->tree);
        sg_end_list(s);
        if (rc != 0) {
            snprintf(err, errlen, "forest: a tree of %llu triangles does not fit (or out of memory)",
                     (unsigned long long)F->tree);
            return -1;
        }
    }
    sg_new_list(s, base + 3);
    if (with_ground)
        forest_castle_draw(s, F);
    else
        forest_castle_walls(s, F);
    sg_end_list(s);
    return 0;
}

void sg_forest_trees(uint64_t seed, float tx[12], float tz[12], int tv[12])
{
    sg_rng r;
    sg_rng_seed(&r, seed * 17 + 3);
    for (int i = 0; i < 12; i++) {
        tx[i] = -27.5f + 10.0f * (float)(i % 6) + (float)sg_rng_range(&r, -2, 2);
        tz[i] = 40.0f + 9.0f * (float)(i / 6) + (float)sg_rng_range(&r, -2, 2);
        tv[i] = sg_rng_int(&r, 3);
    }
}

/* Bounds with 0.25 m of margin: a tree's crown reaches 3.5 m + a leaf's
 * 1.2 m from the trunk and 4.5 m + 1.2 m above its top (at most 7 m,
 * forest_tree); the castle's towers stand at 27 m with radius 4.5 m and
 * are 24 m high with their caps. */
void sg_forest_bounds(int castle, float lo[3], float hi[3])
{
    const float m = 0.25f, r = castle ? 31.5f : 4.7f, h = castle ? 24.0f : 12.7f;
    lo[0] = lo[2] = -r - m;
    hi[0] = hi[2] = r + m;
    lo[1] = -m;
    hi[1] = h + m;
}

void sg_forest_view(float t, float eye[3], float at[3])
{
    /* Strafe along the row of trees looking through them at the castle. */
    eye[0] = -30.0f + 60.0f * t;
    eye[1] = 4.0f;
    eye[2] = 75.0f;
    at[0] = 0.5f * eye[0];
    at[1] = 8.0f;
    at[2] = 0.0f;
}

void sg_forest_state(sg *s)
{
    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, ShadeModel, GL_SMOOTH);
    sg_lighting(s, GL_FRONT_AND_BACK);
}

void sg_forest_lights(sg *s)
{
    const float l0[4] = {0.5f, 1.0f, 0.6f, 0}, d0[4] = {0.9f, 0.85f, 0.7f, 1}, a0[4] = {0.2f, 0.22f, 0.25f, 1};
    const float l1[4] = {-0.7f, 0.3f, -0.4f, 0}, d1[4] = {0.2f, 0.25f, 0.35f, 1};
    sg_light(s, GL_LIGHT0, l0, d0, a0, NULL);
    sg_light(s, GL_LIGHT1, l1, d1, NULL, NULL);
}

int sg_scene_forest(sg *s, const sg_params *p, char *err, size_t errlen)
{
    sg_forest_plan F;
    if (sg_forest_plan_make(&F, p, err, errlen) != 0) return -1;
    GLuint base = sg_gen_lists(s, 4);
    if (!base) {
        snprintf(err, errlen, "forest: glGenLists failed");
        return -1;
    }
    if (sg_forest_compile(s, &F, p->seed, base, 1, err, errlen) != 0) return -1;
    sg_forest_state(s);
    sg_perspective(s, SG_FOREST_FOVY, (double)p->width / p->height, SG_FOREST_ZNEAR, SG_FOREST_ZFAR);

    float tx[12], tz[12];
    int tv[12];
    sg_forest_trees(p->seed, tx, tz, tv);
    for (int fr = 0; fr < p->frames; fr++) {
        float t = p->frames > 1 ? (float)fr / (float)(p->frames - 1) : 0.0f;
        sg_frame_begin(s, 0.6f, 0.75f, 0.95f);
        G0(s, LoadIdentity);
        float eye[3], at[3];
        sg_forest_view(t, eye, at);
        const float up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        sg_forest_lights(s);
        sg_call_list(s, base + 3);
        for (int i = 0; i < 12; i++) {
            G0(s, PushMatrix);
            G(s, Translatef, tx[i], 0.0f, tz[i]);
            sg_call_list(s, base + (GLuint)tv[i]);
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}
