/*
 * Cathedrals: a 2 x 2 x 2 array of one gothic cathedral interior.
 *
 * Workload size: Hüttner 1999, Table 3.1 and sec. 3.1.9 ("eight gothic
 * cathedrals are aligned on a 2 x 2 x 2 grid, where each cathedral consists
 * of 416,763 polygons"; 3,334,104 triangles), walked through its interior
 * for about 100 frames (Fig. 3.8).
 *
 * Structure: floor, double-sided walls, a barrel vault over the nave, flat
 * aisle ceilings, two rows of columns joined by arches, and a rose window
 * on each end wall.  One column is a display list (base and capital in
 * immediate mode, shaft from vertex arrays with glDrawElements) called from
 * the cathedral's list: nested lists, as an instancing modeller would emit.
 * The columns' stack count takes most of the budget; the two rose windows
 * (GL_TRIANGLE_FAN) absorb the rest so that a copy has exactly its budget.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sg.h"

#define CATH_PI 3.14159265358979323846f
#define CATH_LEN 64.0f      /* nave length (z) */
#define CATH_HALF 12.0f     /* half width including aisles (x) */
#define CATH_NAVE 6.0f      /* half width of the nave: column rows at x = +-6 */
#define CATH_COL_H 12.0f
#define CATH_H 13.0f        /* wall and vault springing height */

typedef sg_cath_params cath_params;

/* A strip of quads between two rows of points, wound so that its first
 * quad faces along the first given normal whatever order the rows were given
 * in (the normals are the intended outside). */
static void cath_band(sg *s, const float (*a)[3], const float (*b)[3], const float (*n)[3], int count)
{
    const float *want = n[0];
    float e1[3] = {b[0][0] - a[0][0], b[0][1] - a[0][1], b[0][2] - a[0][2]};
    float e2[3] = {a[1][0] - a[0][0], a[1][1] - a[0][1], a[1][2] - a[0][2]};
    float c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    int swap = c[0] * want[0] + c[1] * want[1] + c[2] * want[2] < 0.0f;
    sg_begin(s, GL_QUAD_STRIP);
    for (int i = 0; i < count; i++) {
        sg_nrm(s, n[i][0], n[i][1], n[i][2]);
        sg_vtxv(s, swap ? b[i] : a[i]);
        sg_vtxv(s, swap ? a[i] : b[i]);
    }
    sg_end(s);
}

/* A wall seen from both sides (two grids back to back, 0.3 m apart). */
static void cath_wall(sg *s, const float o[3], const float u[3], const float v[3], const float out[3], int sub)
{
    float inner[3] = {o[0] + u[0], o[1] + u[1], o[2] + u[2]};
    float nu[3] = {-u[0], -u[1], -u[2]};
    float o2[3] = {o[0] + 0.3f * out[0], o[1] + 0.3f * out[1], o[2] + 0.3f * out[2]};
    /* u x v faces 'out' for the caller's orientation; the reversed grid
     * faces into the building. */
    sg_grid(s, o2, u, v, sub, sub);
    sg_grid(s, inner, nu, v, sub, sub);
}

static int cath_column(sg *s, const cath_params *P)
{
    int sl = P->slices, st = P->stacks;
    const float r = 0.7f;
    G(s, Color3f, 0.78f, 0.76f, 0.7f);
    sg_cylinder(s, r * 1.35f, 0.6f, sl, 1, 1);
    /* Shaft: (sl+1) x (st+1) vertices, one strip per stack. */
    size_t nv = (size_t)(sl + 1) * (size_t)(st + 1);
    float *vb = sg_buf(s, 0, nv * 6 * sizeof(float));
    GLuint *ib = sg_buf(s, 1, (size_t)(sl + 1) * 2 * sizeof(GLuint));
    if (!vb || !ib) return -1;
    for (int j = 0; j <= st; j++)
        for (int i = 0; i <= sl; i++) {
            float t = 2.0f * CATH_PI * (float)(i % sl) / (float)sl;
            float *q = vb + ((size_t)j * (size_t)(sl + 1) + (size_t)i) * 6;
            q[0] = cosf(t);
            q[1] = 0.0f;
            q[2] = sinf(t);
            q[3] = r * q[0];
            q[4] = 0.6f + (CATH_COL_H - 1.4f) * (float)j / (float)st;
            q[5] = r * q[2];
        }
    /* Pointers are re-based for each stack so that each draw reads only its
     * own two rings (a capture writes what a draw can read from the base). */
    for (int i = 0; i <= sl; i++) {
        ib[2 * i] = (GLuint)i;
        ib[2 * i + 1] = (GLuint)(sl + 1 + i);
    }
    G(s, EnableClientState, GL_VERTEX_ARRAY);
    G(s, EnableClientState, GL_NORMAL_ARRAY);
    for (int j = 0; j < st; j++) {
        const float *ring = vb + (size_t)j * (size_t)(sl + 1) * 6;
        G(s, NormalPointer, GL_FLOAT, 6 * sizeof(float), ring);
        G(s, VertexPointer, 3, GL_FLOAT, 6 * sizeof(float), ring + 3);
        sg_draw_elements(s, GL_TRIANGLE_STRIP, 2 * (sl + 1), GL_UNSIGNED_INT, ib);
    }
    G(s, DisableClientState, GL_NORMAL_ARRAY);
    G(s, DisableClientState, GL_VERTEX_ARRAY);
    G0(s, PushMatrix);
    G(s, Translatef, 0.0f, CATH_COL_H - 0.8f, 0.0f);
    sg_cylinder(s, r * 1.5f, 0.8f, sl, 1, 1);
    G0(s, PopMatrix);
    return 0;
}

/* One semicircular arch of rectangular section between z0 and z1 at x. */
static void cath_arch(sg *s, float x, float z0, float z1, int seg)
{
    enum { MAXSEG = 65 };
    float in[MAXSEG][3], out[MAXSEG][3], inl[MAXSEG][3], outl[MAXSEG][3], nr[MAXSEG][3], nx[MAXSEG][3];
    float zm = 0.5f * (z0 + z1), R = 0.5f * (z1 - z0), yb = CATH_COL_H;
    float ri = R - 0.35f, ro = R + 0.45f;
    if (seg > MAXSEG - 1) seg = MAXSEG - 1;
    for (int k = 0; k <= seg; k++) {
        float a = CATH_PI * (float)k / (float)seg, ca = cosf(a), sa = sinf(a);
        in[k][0] = x + 0.5f; in[k][1] = yb + ri * sa; in[k][2] = zm + ri * ca;
        out[k][0] = x + 0.5f; out[k][1] = yb + ro * sa; out[k][2] = zm + ro * ca;
        inl[k][0] = x - 0.5f; inl[k][1] = in[k][1]; inl[k][2] = in[k][2];
        outl[k][0] = x - 0.5f; outl[k][1] = out[k][1]; outl[k][2] = out[k][2];
        nr[k][0] = 0; nr[k][1] = sa; nr[k][2] = ca;
        nx[k][0] = 1; nx[k][1] = 0; nx[k][2] = 0;
    }
    float ndown[MAXSEG][3], nmx[MAXSEG][3];
    for (int k = 0; k <= seg; k++) {
        ndown[k][0] = 0; ndown[k][1] = -nr[k][1]; ndown[k][2] = -nr[k][2];
        nmx[k][0] = -1; nmx[k][1] = 0; nmx[k][2] = 0;
    }
    /* The intrados faces the arch's centre, the extrados away from it. */
    cath_band(s, (const float (*)[3])in, (const float (*)[3])inl, (const float (*)[3])ndown, seg + 1);
    cath_band(s, (const float (*)[3])out, (const float (*)[3])outl, (const float (*)[3])nr, seg + 1);
    cath_band(s, (const float (*)[3])in, (const float (*)[3])out, (const float (*)[3])nx, seg + 1);
    cath_band(s, (const float (*)[3])inl, (const float (*)[3])outl, (const float (*)[3])nmx, seg + 1);
}

/* A half-cylinder over the nave from z = 0 to CATH_LEN; inside faces down. */
static void cath_vault(sg *s, float radius, int seg, int nz, int inside)
{
    enum { MAXV = 129 };
    float a[MAXV][3], b[MAXV][3], n[MAXV][3];
    if (seg > MAXV - 1) seg = MAXV - 1;
    for (int j = 0; j < nz; j++) {
        float z0 = CATH_LEN * (float)j / (float)nz, z1 = CATH_LEN * (float)(j + 1) / (float)nz;
        for (int k = 0; k <= seg; k++) {
            float t = CATH_PI * (float)k / (float)seg, ct = cosf(t), st = sinf(t);
            a[k][0] = b[k][0] = radius * ct;
            a[k][1] = b[k][1] = CATH_H + radius * st;
            a[k][2] = z0;
            b[k][2] = z1;
            n[k][0] = inside ? -ct : ct;
            n[k][1] = inside ? -st : st;
            n[k][2] = 0;
        }
        cath_band(s, (const float (*)[3])a, (const float (*)[3])b, (const float (*)[3])n, seg + 1);
    }
}

static void cath_end_wall(sg *s, float z, float out_z, const cath_params *P, uint64_t rose)
{
    const float o[3] = {out_z > 0 ? -CATH_HALF : CATH_HALF, 0, z};
    const float u[3] = {out_z > 0 ? 2 * CATH_HALF : -2 * CATH_HALF, 0, 0}, v[3] = {0, CATH_H, 0};
    const float out[3] = {0, 0, out_z};
    cath_wall(s, o, u, v, out, P->wall_sub);
    /* Gable closing the vault: the rose window, a fan facing inwards. */
    G(s, Color3f, 0.45f, 0.3f, 0.6f);
    G0(s, PushMatrix);
    G(s, Translatef, 0.0f, CATH_H, z - 0.05f * out_z);
    G(s, Rotatef, out_z > 0 ? -90.0f : 90.0f, 1.0f, 0.0f, 0.0f); /* +y to inwards */
    sg_disc(s, 0, 0, 0, CATH_NAVE - 0.2f, rose, 0);
    G0(s, PopMatrix);
    G(s, Color3f, 0.72f, 0.7f, 0.65f);
}

/* The shell: floor, walls, end walls with their rose windows, aisle
 * ceilings and roofs, the vault.  It sets its own colours, so it can be
 * drawn in any order with the bays (the culling program does). */
void sg_cath_shell(sg *s, const cath_params *P)
{
    G(s, Color3f, 0.6f, 0.58f, 0.55f);
    const float fo[3] = {-CATH_HALF, 0, 0}, fu[3] = {0, 0, CATH_LEN}, fv[3] = {2 * CATH_HALF, 0, 0};
    sg_grid(s, fo, fu, fv, P->floor_sub, P->floor_sub);
    G(s, Color3f, 0.72f, 0.7f, 0.65f);
    /* Side walls: u x v must face outwards. */
    const float lo[3] = {-CATH_HALF, 0, 0}, lu[3] = {0, 0, CATH_LEN}, v[3] = {0, CATH_H, 0};
    const float ro[3] = {CATH_HALF, 0, CATH_LEN}, ru[3] = {0, 0, -CATH_LEN};
    const float mx[3] = {-1, 0, 0}, px[3] = {1, 0, 0};
    cath_wall(s, lo, lu, v, mx, P->wall_sub);
    cath_wall(s, ro, ru, v, px, P->wall_sub);
    cath_end_wall(s, 0.0f, -1.0f, P, P->rose[0]);
    cath_end_wall(s, CATH_LEN, 1.0f, P, P->rose[1]);
    /* Aisle ceilings (facing down) and roofs (facing up). */
    for (int side = -1; side <= 1; side += 2) {
        float x0 = side < 0 ? -CATH_HALF : CATH_NAVE;
        const float co[3] = {x0, CATH_H, 0}, cu[3] = {CATH_HALF - CATH_NAVE, 0, 0}, cv[3] = {0, 0, CATH_LEN};
        const float ro2[3] = {x0, CATH_H + 0.3f, 0}, ru2[3] = {0, 0, CATH_LEN}, rv2[3] = {CATH_HALF - CATH_NAVE, 0, 0};
        sg_grid(s, co, cu, cv, 1, P->vault_len);
        G(s, Color3f, 0.4f, 0.35f, 0.32f);
        sg_grid(s, ro2, ru2, rv2, P->vault_len, 1);
        G(s, Color3f, 0.72f, 0.7f, 0.65f);
    }
    cath_vault(s, CATH_NAVE, P->vault_seg, P->vault_len, 1);
    G(s, Color3f, 0.4f, 0.35f, 0.32f);
    cath_vault(s, CATH_NAVE + 0.3f, P->vault_seg, P->vault_len, 0);
}

/* Bay i of the column row on 'side' (-1 or 1): the column and the arch to
 * the next column.  The column list sets the colour the arch is drawn in. */
void sg_cath_bay(sg *s, const cath_params *P, GLuint column_list, int side, int i)
{
    float step = CATH_LEN / (float)(P->cols + 1);
    G0(s, PushMatrix);
    G(s, Translatef, side * CATH_NAVE, 0.0f, step * (float)(i + 1));
    sg_call_list(s, column_list);
    G0(s, PopMatrix);
    if (i + 1 < P->cols) cath_arch(s, side * CATH_NAVE, step * (float)(i + 1), step * (float)(i + 2), P->arch_seg);
}

/* Bounds with 0.25 m of margin, so that the geometry lies strictly inside
 * (the culling program's boxes): the shell reaches 0.3 m beyond the walls
 * (cath_wall) and CATH_NAVE + 0.3 above the springing (the outer vault); a
 * bay spans the column's capital (radius 1.05) and the arch (R + 0.45). */
void sg_cath_bounds(const cath_params *P, int bay, float lo[3], float hi[3])
{
    const float m = 0.25f;
    if (bay < 0) {
        const float l[3] = {-CATH_HALF - 0.3f - m, -m, -0.3f - m};
        const float h[3] = {CATH_HALF + 0.3f + m, CATH_H + CATH_NAVE + 0.3f + m, CATH_LEN + 0.3f + m};
        memcpy(lo, l, sizeof l);
        memcpy(hi, h, sizeof h);
        return;
    }
    int side = bay < P->cols ? -1 : 1, i = bay % P->cols;
    float step = CATH_LEN / (float)(P->cols + 1), z0 = step * (float)(i + 1);
    float z1 = i + 1 < P->cols ? step * (float)(i + 2) + 0.45f : z0 + 1.05f;
    lo[0] = side * CATH_NAVE - 1.05f - m;
    hi[0] = side * CATH_NAVE + 1.05f + m;
    lo[1] = -m;
    hi[1] = CATH_COL_H + (i + 1 < P->cols ? 0.5f * step + 0.45f : 0.0f) + m;
    lo[2] = z0 - 1.05f - m;
    hi[2] = z1 + m;
}

static int cath_model(sg *s, const cath_params *P, GLuint column_list)
{
    sg_cath_shell(s, P);
    /* Columns and arches. */
    G(s, Color3f, 0.7f, 0.68f, 0.62f);
    for (int side = -1; side <= 1; side += 2)
        for (int i = 0; i < P->cols; i++) sg_cath_bay(s, P, column_list, side, i);
    return 0;
}

static uint64_t cath_count(const cath_params *P)
{
    sg m;
    sg_init(&m, NULL);
    GLuint col = sg_gen_lists(&m, 1);
    sg_new_list(&m, col);
    int rc = cath_column(&m, P);
    sg_end_list(&m);
    if (rc == 0) cath_model(&m, P, col);
    uint64_t t = rc == 0 && !m.oom ? m.tris : UINT64_MAX;
    sg_free(&m);
    return t;
}

static int cath_isqrt(uint64_t v)
{
    return (int)sqrt((double)v);
}

static int cath_clamp(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

int sg_cath_plan(cath_params *P, uint64_t per, char *err, size_t errlen)
{
    int q = cath_isqrt(per);
    memset(P, 0, sizeof *P);
    P->cols = cath_clamp(q / 40, 3, 16);
    P->slices = cath_clamp(q / 12, 6, 48);
    P->arch_seg = cath_clamp(P->slices / 2, 3, 32);
    P->vault_seg = cath_clamp(P->slices, 6, 64);
    P->vault_len = cath_clamp(P->cols + 1, 2, 64);
    P->wall_sub = cath_clamp(q / 60, 1, 12);
    P->floor_sub = cath_clamp(q / 30, 1, 24);
    P->stacks = 1;
    uint64_t c1 = cath_count(P);
    P->stacks = 2;
    uint64_t c2 = cath_count(P);
    if (c1 == UINT64_MAX || c2 == UINT64_MAX || c1 + 2 > per) {
        snprintf(err, errlen, "cathedrals: %llu triangles per copy are too few (need %llu)",
                 (unsigned long long)per, (unsigned long long)(c1 + 2));
        return -1;
    }
    /* Keep at least two rose-window triangles. */
    P->stacks = 1 + (int)((per - 2 - c1) / (c2 - c1));
    uint64_t rest = per - cath_count(P);
    P->rose[0] = rest / 2;
    P->rose[1] = rest - rest / 2;
    return 0;
}

int sg_cath_compile_column(sg *s, const cath_params *P, GLuint list, char *err, size_t errlen)
{
    sg_new_list(s, list);
    int rc = cath_column(s, P);
    sg_end_list(s);
    if (rc != 0) snprintf(err, errlen, "cathedrals: out of memory");
    return rc;
}

void sg_cath_copy_offset(int k, float t[3])
{
    t[0] = (k & 1) ? 40.0f : 0.0f;
    t[1] = (k & 4) ? 30.0f : 0.0f;
    t[2] = (k & 2) ? 90.0f : 0.0f;
}

void sg_cath_view(float t, float eye[3], float at[3])
{
    /* Walk up the nave of the first cathedral, looking ahead and a little
     * sideways toward the columns. */
    float yaw = 0.6f * sinf(5.0f * t);
    eye[0] = 1.0f * sinf(2.0f * t);
    eye[1] = 1.7f;
    eye[2] = 4.0f + t * (CATH_LEN - 12.0f);
    at[0] = eye[0] + sinf(yaw);
    at[1] = 3.0f;
    at[2] = eye[2] + cosf(yaw);
}

void sg_cath_lights(sg *s)
{
    const float l0[4] = {0.3f, 1.0f, 0.2f, 0}, d0[4] = {0.6f, 0.58f, 0.5f, 1};
    const float l1[4] = {-0.6f, 0.4f, -0.5f, 0}, d1[4] = {0.25f, 0.28f, 0.4f, 1};
    const float l2[4] = {0.0f, 10.0f, CATH_LEN * 0.5f, 1}, d2[4] = {0.9f, 0.75f, 0.5f, 1};
    sg_light(s, GL_LIGHT0, l0, d0, NULL, NULL);
    sg_light(s, GL_LIGHT1, l1, d1, NULL, NULL);
    sg_light(s, GL_LIGHT2, l2, d2, NULL, NULL);
    G(s, Lightf, GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.02f);
}

void sg_cath_state(sg *s)
{
    G(s, Enable, GL_DEPTH_TEST);
    G(s, DepthFunc, GL_LEQUAL);
    G(s, Enable, GL_CULL_FACE);
    G(s, ShadeModel, GL_SMOOTH);
    sg_lighting(s, GL_FRONT);
    const float amb[4] = {0.15f, 0.15f, 0.18f, 1};
    G(s, LightModelfv, GL_LIGHT_MODEL_AMBIENT, amb);
}

int sg_scene_cathedrals(sg *s, const sg_params *p, char *err, size_t errlen)
{
    /* Hüttner 1999, Table 3.1: 8 copies; the per-copy budget is exact when
     * the target divides by 8 (416,763 at paper scale). */
    cath_params P;
    if (sg_cath_plan(&P, p->target / 8, err, errlen) != 0) return -1;
    GLuint col = sg_gen_lists(s, 2);
    if (!col) {
        snprintf(err, errlen, "cathedrals: glGenLists failed");
        return -1;
    }
    if (sg_cath_compile_column(s, &P, col, err, errlen) != 0) return -1;
    sg_new_list(s, col + 1);
    cath_model(s, &P, col);
    sg_end_list(s);

    sg_cath_state(s);
    sg_perspective(s, SG_CATH_FOVY, (double)p->width / p->height, SG_CATH_ZNEAR, SG_CATH_ZFAR);

    for (int fr = 0; fr < p->frames; fr++) {
        float t = p->frames > 1 ? (float)fr / (float)(p->frames - 1) : 0.0f;
        sg_frame_begin(s, 0.1f, 0.1f, 0.14f);
        G0(s, LoadIdentity);
        float eye[3], at[3];
        sg_cath_view(t, eye, at);
        const float up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        sg_cath_lights(s);
        for (int k = 0; k < 8; k++) {
            float o[3];
            sg_cath_copy_offset(k, o);
            G0(s, PushMatrix);
            G(s, Translatef, o[0], o[1], o[2]);
            sg_call_list(s, col + 1);
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}
