/*
 * Terrain: a regular-grid height field flown over at 700 m to 5,000 m.
 *
 * Workload size: Hüttner 1999, sec. 2.1: the USGS Grand-Canyon-East DEM,
 * "120 km x 120 km landscape, regular grid with 1453252 points, 2906504
 * triangles"; the flights of sec. 2.3.5 are "between 700 m and 5000 m" above
 * the terrain.  The papers count two triangles per grid point; we make a
 * grid of T/2 cells (full rows plus one partial row), so the triangle count
 * is exact, over the same 120 km extent at every scale.  Heights are a
 * deterministic value-noise fractal (no DEM is shipped).
 *
 * Each row is one GL_TRIANGLE_STRIP from vertex arrays (positions, normals,
 * colours by height), compiled into display lists of 16 rows, so the trace
 * holds the terrain once and each frame calls the lists.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sg.h"

#define TERRAIN_EXTENT 120000.0 /* metres: Hüttner 1999, sec. 2.1 */
#define TERRAIN_RELIEF 1800.0   /* metres of height variation */
#define TERRAIN_ROWS_PER_LIST 16

typedef struct terrain {
    uint64_t seed;
    int nx;            /* cells per full row */
    int rows;          /* full rows */
    int partial;       /* cells in the last, partial row (0: none) */
    double spacing;
} terrain;

static double terrain_height(const terrain *T, double x, double z)
{
    double h = sg_fractal(T->seed, x / 9000.0, z / 9000.0, 7);
    /* Valleys: fold the noise so that ridges are sharp, canyon-like. */
    return TERRAIN_RELIEF * (0.5 + 0.5 * h) + 300.0 * (1.0 - fabs(sg_fractal(T->seed + 77, x / 20000.0, z / 20000.0, 3)));
}

static void terrain_color(double h, GLubyte *c)
{
    double t = h / (TERRAIN_RELIEF + 300.0);
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    c[0] = (GLubyte)(90 + 120 * t);
    c[1] = (GLubyte)(120 + 60 * t - 40 * t * t);
    c[2] = (GLubyte)(60 + 60 * t);
    c[3] = 255;
}

/* Fills and draws row j (cells cells wide) as one strip. */
static int terrain_row(sg *s, const terrain *T, int j, int cells)
{
    size_t nv = 2 * (size_t)(cells + 1);
    float *pos = sg_buf(s, 0, nv * 3 * sizeof(float));
    float *nrm = sg_buf(s, 1, nv * 3 * sizeof(float));
    GLubyte *col = sg_buf(s, 2, nv * 4);
    if (!pos || !nrm || !col) return -1;
    double d = T->spacing;
    /* Counting needs no heights; skipping them keeps `--list` fast at
     * paper scale (millions of noise evaluations). */
    for (int i = 0; s->c && i <= cells; i++)
        for (int k = 0; k < 2; k++) {
            /* (z_j, z_j+1) pairs with x increasing face up. */
            double x = i * d - TERRAIN_EXTENT / 2, z = (j + k) * d - TERRAIN_EXTENT / 2;
            double h = terrain_height(T, x, z);
            double hx = terrain_height(T, x + d, z) - terrain_height(T, x - d, z);
            double hz = terrain_height(T, x, z + d) - terrain_height(T, x, z - d);
            size_t v = 2 * (size_t)i + (size_t)k;
            pos[3 * v] = (float)x;
            pos[3 * v + 1] = (float)h;
            pos[3 * v + 2] = (float)z;
            double nl = sqrt(hx * hx + 4 * d * d + hz * hz);
            nrm[3 * v] = (float)(-hx / nl);
            nrm[3 * v + 1] = (float)(2 * d / nl);
            nrm[3 * v + 2] = (float)(-hz / nl);
            terrain_color(h, col + 4 * v);
        }
    G(s, VertexPointer, 3, GL_FLOAT, 0, pos);
    G(s, NormalPointer, GL_FLOAT, 0, nrm);
    G(s, ColorPointer, 4, GL_UNSIGNED_BYTE, 0, col);
    sg_draw_arrays(s, GL_TRIANGLE_STRIP, 0, (GLsizei)nv);
    return 0;
}

int sg_scene_terrain(sg *s, const sg_params *p, char *err, size_t errlen)
{
    terrain T;
    memset(&T, 0, sizeof T);
    T.seed = p->seed * 0x5EED + 1;
    uint64_t cells = p->target / 2;
    if (cells < 4) {
        snprintf(err, errlen, "terrain: %llu triangles are too few", (unsigned long long)p->target);
        return -1;
    }
    T.nx = (int)ceil(sqrt((double)cells));
    T.rows = (int)(cells / (uint64_t)T.nx);
    T.partial = (int)(cells % (uint64_t)T.nx);
    T.spacing = TERRAIN_EXTENT / T.nx;
    int all_rows = T.rows + (T.partial ? 1 : 0);
    int lists = (all_rows + TERRAIN_ROWS_PER_LIST - 1) / TERRAIN_ROWS_PER_LIST;

    GLuint base = sg_gen_lists(s, lists + 1);
    if (!base) {
        snprintf(err, errlen, "terrain: glGenLists failed");
        return -1;
    }
    for (int l = 0; l < lists; l++) {
        sg_new_list(s, base + (GLuint)l);
        G(s, EnableClientState, GL_VERTEX_ARRAY);
        G(s, EnableClientState, GL_NORMAL_ARRAY);
        G(s, EnableClientState, GL_COLOR_ARRAY);
        for (int j = l * TERRAIN_ROWS_PER_LIST; j < all_rows && j < (l + 1) * TERRAIN_ROWS_PER_LIST; j++)
            if (terrain_row(s, &T, j, j < T.rows ? T.nx : T.partial) != 0) {
                sg_end_list(s);
                snprintf(err, errlen, "terrain: out of memory");
                return -1;
            }
        G(s, DisableClientState, GL_COLOR_ARRAY);
        G(s, DisableClientState, GL_NORMAL_ARRAY);
        G(s, DisableClientState, GL_VERTEX_ARRAY);
        sg_end_list(s);
    }
    /* An odd target: one more triangle, a marker on the summit of the
     * starting point (GL_TRIANGLES in immediate mode). */
    sg_new_list(s, base + (GLuint)lists);
    if (p->target % 2) {
        double h = terrain_height(&T, 0, 0) + 50.0;
        G(s, Color3f, 1.0f, 0.2f, 0.1f);
        sg_begin(s, GL_TRIANGLES);
        sg_nrm(s, 0, 1, 0);
        sg_vtx(s, 0, (float)h, 0);
        sg_vtx(s, 400, (float)h, 0);
        sg_vtx(s, 0, (float)h, -400);
        sg_end(s);
    }
    sg_end_list(s);

    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, ShadeModel, GL_SMOOTH);
    sg_lighting(s, GL_FRONT);
    /* Hüttner 1999, sec. 2.3.5: a 50 mm lens, i.e. about 40 degrees. */
    sg_perspective(s, 40.0, (double)p->width / p->height, 50.0, 200000.0);

    for (int fr = 0; fr < p->frames; fr++) {
        double t = p->frames > 1 ? (double)fr / (double)(p->frames - 1) : 0.0;
        sg_frame_begin(s, 0.55f, 0.65f, 0.85f);
        G0(s, LoadIdentity);
        /* Fly diagonally; the height above the ground climbs from 700 m
         * to 5,000 m over the flight. */
        double ex = -0.3 * TERRAIN_EXTENT + 0.4 * TERRAIN_EXTENT * t, ez = ex * 0.8;
        double alt = 700.0 + (5000.0 - 700.0) * t;
        double ey = terrain_height(&T, ex, ez) + alt;
        const float eye[3] = {(float)ex, (float)ey, (float)ez};
        const float at[3] = {(float)(ex + 8000.0), (float)(ey - 2500.0 - alt * 0.4), (float)(ez + 6400.0)};
        const float up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        const float sun[4] = {0.6f, 0.7f, -0.4f, 0}, sd[4] = {0.95f, 0.9f, 0.8f, 1}, sa[4] = {0.2f, 0.2f, 0.25f, 1};
        const float sky[4] = {-0.3f, 1.0f, 0.5f, 0}, kd[4] = {0.2f, 0.25f, 0.35f, 1};
        sg_light(s, GL_LIGHT0, sun, sd, sa, NULL);
        sg_light(s, GL_LIGHT1, sky, kd, NULL, NULL);
        for (int l = 0; l <= lists; l++) sg_call_list(s, base + (GLuint)l);
        sg_frame_end(s);
    }
    return 0;
}
