/*
 * Occluder shadows (Willmott et al. 2001, sec. 3.2, after Wonka and
 * Schmalstieg): per frame, the shadow every occluder casts away from the
 * eye is drawn from above into a cull map, a top view of the ground whose
 * depth is height (cleared to 0, GL_GREATER, so a cell keeps the highest
 * shadow over it), read back as unsigned shorts (their sec. 3.2.7), and an
 * object is culled when the map's height over its whole footprint is above
 * its top.
 *
 * Occluders here are the city houses' ground-floor rooms (scene_city.c):
 * each is closed by inward-facing walls, floor and ceiling, so with back
 * faces culled any ray through its inside is stopped by the face where it
 * leaves.  The occluder lines are the room's footprint edges whose wall the
 * eye sees from inside the room's plane (its far walls); the facades are
 * no occluders, they have a window in every bay.  A point behind such an
 * edge and under the plane through the eye and the edge's top is hidden,
 * as long as the ray passes above the room's floor at 2 cm (true for
 * geometry above 2 cm or closer behind than 1.2% of its distance at the
 * walk's 1.7 m eye height; the images are checked against DR).
 *
 * Conservative where the paper is not (it shrinks occluders by half a cell
 * and tests the building's centre): each shadow polygon is shrunk by half a
 * cell's diagonal, so a cell whose centre it covers lies inside it, and its
 * plane is lowered by the most it falls over half a cell; the map value is
 * rounded down by one unit of the read; every cell under the box is tested.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <GL/gl.h>
#include "cull.h"

#define SHADOW_TOP 4096.0f /* metres at depth 1; the 16-bit read's unit is 6 cm */

/* Line a x + b z = c through p and q, offset by r towards 'inside'. */
static void offset_line(const float p[2], const float q[2], const float inside[2], float r, float l[3])
{
    float a = q[1] - p[1], b = p[0] - q[0], n = sqrtf(a * a + b * b);
    a /= n;
    b /= n;
    float c = a * p[0] + b * p[1];
    if (a * inside[0] + b * inside[1] < c) { a = -a, b = -b, c = -c; }
    l[0] = a;
    l[1] = b;
    l[2] = c + r;
}

/* Shrinks the convex quad v (in order) by r; 0 when nothing is left. */
static int shrink_quad(float v[4][2], float r)
{
    float mid[2] = {0, 0}, l[4][3], out[4][2];
    for (int k = 0; k < 4; k++) {
        mid[0] += v[k][0] / 4;
        mid[1] += v[k][1] / 4;
    }
    for (int k = 0; k < 4; k++) offset_line(v[k], v[(k + 1) % 4], mid, r, l[k]);
    for (int k = 0; k < 4; k++) { /* corner k: lines k-1 and k */
        const float *p = l[(k + 3) % 4], *q = l[k];
        float det = p[0] * q[1] - p[1] * q[0];
        if (fabsf(det) < 1e-9f) return 0;
        out[k][0] = (p[2] * q[1] - p[1] * q[2]) / det;
        out[k][1] = (p[0] * q[2] - p[2] * q[0]) / det;
    }
    /* Still the same orientation and every corner inside every line: else
     * the offset turned the quad inside out. */
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 4; j++)
            if (l[j][0] * out[k][0] + l[j][1] * out[k][1] < l[j][2] - 1e-3f) return 0;
    memcpy(v, out, sizeof out);
    return 1;
}

/* The shadow of the wall over the edge a-b at height h, from eye e. */
static void draw_shadow(const cull_shadow *m, const float e[3], const float a[2], const float b[2], float h)
{
    float q[4][2], far_k[2];
    const float *ends[2] = {a, b};
    for (int i = 0; i < 2; i++) {
        float dx = ends[i][0] - e[0], dz = ends[i][1] - e[2], d = sqrtf(dx * dx + dz * dz);
        far_k[i] = 1.0f + 4.0f * m->diag / (d > 1e-3f ? d : 1e-3f); /* beyond the map (their Fig. 8) */
    }
    q[0][0] = a[0], q[0][1] = a[1];
    q[1][0] = b[0], q[1][1] = b[1];
    q[2][0] = e[0] + far_k[1] * (b[0] - e[0]), q[2][1] = e[2] + far_k[1] * (b[1] - e[2]);
    q[3][0] = e[0] + far_k[0] * (a[0] - e[0]), q[3][1] = e[2] + far_k[0] * (a[1] - e[2]);
    /* The plane y = gx x + gz z + y0 through the eye and the edge's top. */
    float ux = b[0] - a[0], uz = b[1] - a[1], wx = a[0] - e[0], wz = a[1] - e[2], wy = h - e[1];
    float nx = -uz * wy, ny = uz * wx - ux * wz, nz = ux * wy; /* (u, 0) x (w) */
    if (fabsf(ny) < 1e-6f) return;                              /* edge seen end-on */
    float gx = -nx / ny, gz = -nz / ny;
    if (!shrink_quad(q, m->cell * 0.70711f)) return;
    float drop = (fabsf(gx) + fabsf(gz)) * m->cell * 0.5f + 1e-3f;
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        float y = e[1] + gx * (q[k][0] - e[0]) + gz * (q[k][1] - e[2]) - drop;
        glVertex3f(q[k][0], y, q[k][1]);
    }
    glEnd();
}

int cull_shadow_init(cull_shadow *m, const cull_obj *objs, int n, int res)
{
    memset(m, 0, sizeof *m);
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fminf(lo[a], objs[i].box.lo[2 * a]);
            hi[a] = fmaxf(hi[a], objs[i].box.hi[2 * a]);
        }
    float ext = fmaxf(hi[0] - lo[0], hi[1] - lo[1]);
    m->res = res;
    m->x0 = lo[0];
    m->z0 = lo[1];
    m->cell = ext / (float)res;
    m->diag = ext * 1.5f;
    m->height = malloc((size_t)res * (size_t)res * sizeof *m->height);
    m->raw = malloc((size_t)res * (size_t)res * sizeof *m->raw);
    return m->height && m->raw ? 0 : -1;
}

void cull_shadow_free(cull_shadow *m)
{
    free(m->height);
    free(m->raw);
    m->height = NULL;
    m->raw = NULL;
}

void cull_shadow_render(cull_shadow *m, const float (*occ)[6], int n_occ, const float eye[3])
{
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    /* Window x, y = world x, z over the map; depth = y / SHADOW_TOP
     * (near 0, far -SHADOW_TOP with eye z = world y). */
    glOrtho(m->x0, m->x0 + m->cell * (float)m->res, m->z0, m->z0 + m->cell * (float)m->res, 0.0, -SHADOW_TOP);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    const float swap_yz[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    glLoadMatrixf(swap_yz);
    glViewport(0, 0, m->res, m->res);
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE); /* their sec. 3.2.6: orientation is irrelevant */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_GREATER);
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    m->shadows = 0;
    for (int i = 0; i < n_occ; i++) {
        const float *o = occ[i];
        if (eye[0] > o[0] && eye[0] < o[3] && eye[2] > o[2] && eye[2] < o[5]) continue; /* inside: no far walls */
        const float c[4][2] = {{o[0], o[2]}, {o[3], o[2]}, {o[3], o[5]}, {o[0], o[5]}};
        for (int k = 0; k < 4; k++) {
            const float *a = c[k], *b = c[(k + 1) % 4];
            /* A far wall: the eye is on the room's side of its plane. */
            float nx = b[1] - a[1], nz = a[0] - b[0]; /* outward for this counter-clockwise order */
            if (nx * (eye[0] - a[0]) + nz * (eye[2] - a[1]) >= 0) continue;
            draw_shadow(m, eye, a, b, o[4]);
            m->shadows++;
        }
    }
    glReadPixels(0, 0, m->res, m->res, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, m->raw);
    for (int k = 0; k < m->res * m->res; k++) /* one unit down: the read rounds */
        m->height[k] = m->raw[k] ? ((float)m->raw[k] - 1.0f) / 65535.0f * SHADOW_TOP : -1.0f;
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopAttrib();
}

int cull_shadow_hidden(const cull_shadow *m, const cull_box *b)
{
    int i0 = (int)floorf((b->lo[0] - m->x0) / m->cell), i1 = (int)floorf((b->hi[0] - m->x0) / m->cell);
    int j0 = (int)floorf((b->lo[2] - m->z0) / m->cell), j1 = (int)floorf((b->hi[2] - m->z0) / m->cell);
    if (i0 < 0 || j0 < 0 || i1 >= m->res || j1 >= m->res) return 0;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++)
            if (!(m->height[j * m->res + i] > b->hi[1])) return 0;
    return 1;
}
