/*
 * Evaluators (GL 1.5 spec 5.1): glMap1/glMap2 define Bezier curves and
 * tensor-product surfaces of up to GL_MAX_EVAL_ORDER control points per
 * direction, glEvalCoord evaluates the enabled maps at a domain point and
 * issues the vertex with the evaluated colour, normal and texture
 * coordinates (the current values stay as they were, 5.1), glMapGrid and
 * glEvalPoint/glEvalMesh walk an evenly spaced grid.
 *
 * llvmpipe evaluates on the CPU in Mesa's front end (main/eval.c for the
 * state, vbo's EvalCoord and EvalMesh, math/m_eval.c), in float; the
 * model does the same IEEE operations in the same order, so the vertices
 * are bit for bit those llvmpipe draws (tests/test_evaluator.c):
 *  - a map keeps its control points converted to float (glMap*d too) and
 *    1 / (u2 - u1); a domain value u maps to (u - u1) * that;
 *  - points on curves, and on surfaces without GL_AUTO_NORMAL, come from
 *    Horner's scheme (bezier_curve); a surface is evaluated first along its
 *    lower order's direction (the v direction when the orders are equal),
 *    which gives one curve of control points in the other;
 *  - with GL_AUTO_NORMAL the point and both partial derivatives come from
 *    de Casteljau's algorithm (surface_with_derivatives), the derivatives
 *    unscaled, crossed (dP/du x dP/dv, 5.1) and scaled by 1/sqrtf of the
 *    squared length;
 *  - the grid step is (u2 - u1) / n, and glEvalMesh adds it to
 *    u1 + i1 * step for each next point instead of multiplying;
 *    glEvalPoint computes i * step + u1;
 *  - glEvalMesh2(GL_FILL) draws a triangle strip per row, each column's
 *    point at v before the one at v + step; GL_LINE the rows, then the
 *    columns, as line strips.
 * The index maps are stored and queried, but colour-index evaluation does
 * not exist in an RGBA context (as in llvmpipe).  Surfaces with an order of
 * 1 in a direction and GL_AUTO_NORMAL: Mesa reads past its control points
 * there (its result is not defined); the model takes the derivative in that
 * direction as 0, so the normal is (0, 0, 0).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "vertex_internal.h"
#include "evaluator.h"

/* GL_MAX_EVAL_ORDER as OSMesa reports it (pipeline/state.def). */
#define FS_MAX_EVAL_ORDER 30
/* The most vertices one glEvalMesh issues; a larger grid (from a bad
 * trace: 2^31 x 2^31 points) is GL_OUT_OF_MEMORY, which GL allows for any
 * command (2.5), instead of hours of work. */
#define FS_EVAL_MESH_MAX ((int64_t)1 << 24)

enum { MAP_COLOR4, MAP_INDEX, MAP_NORMAL, MAP_TEX1, MAP_TEX2, MAP_TEX3, MAP_TEX4, MAP_VERTEX3, MAP_VERTEX4 };
/* Components per control point, table 5.1, in the enums' order. */
static const int map_components[FS_EVAL_MAPS] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

typedef struct fs_eval_map {
    GLint order[2];   /* u, v (1 for a MAP1) */
    float domain[4];  /* u1, u2, v1, v2 */
    float inv[2];     /* 1 / (u2 - u1), 1 / (v2 - v1) */
    float *points;    /* order[0] x order[1] points, u-major (i before j, 5.1) */
} fs_eval_map;

struct fs_eval_maps {
    fs_eval_map map[2][FS_EVAL_MAPS];
};

/* The dimension (1 or 2) of the map target names, its index in *idx; 0
 * for an enum that names no map. */
static int map_target(GLenum target, int *idx)
{
    if (target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4) {
        *idx = (int)(target - GL_MAP1_COLOR_4);
        return 1;
    }
    if (target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4) {
        *idx = (int)(target - GL_MAP2_COLOR_4);
        return 2;
    }
    return 0;
}

void fs_eval_free(fs_context *c)
{
    if (!c->eval_maps)
        return;
    for (int d = 0; d < 2; d++)
        for (int k = 0; k < FS_EVAL_MAPS; k++)
            free(c->eval_maps->map[d][k].points);
    free(c->eval_maps);
    c->eval_maps = NULL;
}

/* The maps, made at first use with the initial values of table 6.26:
 * order 1, domain [0, 1], the one control point the current value's
 * initial value (colour and index 1, normal (0, 0, 1), vertex and texture
 * coordinates (0, 0, 0, 1)).  NULL (GL_OUT_OF_MEMORY set) when out of
 * memory. */
static struct fs_eval_maps *eval_maps(fs_context *c)
{
    static const float initial[FS_EVAL_MAPS][4] = {
        {1, 1, 1, 1}, {1}, {0, 0, 1}, {0}, {0, 0}, {0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0, 1}};
    if (c->eval_maps)
        return c->eval_maps;
    struct fs_eval_maps *m = calloc(1, sizeof *m);
    if (!m) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return NULL;
    }
    c->eval_maps = m;
    for (int d = 0; d < 2; d++)
        for (int k = 0; k < FS_EVAL_MAPS; k++) {
            fs_eval_map *e = &m->map[d][k];
            e->order[0] = e->order[1] = 1;
            e->domain[1] = e->domain[3] = 1.0f;
            e->inv[0] = e->inv[1] = 1.0f;
            e->points = malloc(sizeof initial[k]);
            if (!e->points) {
                fs_eval_free(c);
                fs_error(c, GL_OUT_OF_MEMORY);
                return NULL;
            }
            memcpy(e->points, initial[k], sizeof initial[k]);
        }
    return m;
}

/* ---- the elements glMap reads (the command table's counts) ---- */

static int64_t points_read(int dim, GLenum target, const GLint stride[2], const GLint order[2])
{
    int idx;
    if (map_target(target, &idx) != dim)
        return 0;
    int k = map_components[idx];
    int64_t n = k;
    for (int d = 0; d < dim; d++) {
        if (order[d] < 1 || order[d] > FS_MAX_EVAL_ORDER || stride[d] < k)
            return 0;
        n += (int64_t)(order[d] - 1) * stride[d];
    }
    return n;
}

int64_t fs_map1_points(GLenum target, GLint stride, GLint order)
{
    const GLint s[2] = {stride, 0}, o[2] = {order, 1};
    return points_read(1, target, s, o);
}

int64_t fs_map2_points(GLenum target, GLint ustride, GLint uorder, GLint vstride, GLint vorder)
{
    const GLint s[2] = {ustride, vstride}, o[2] = {uorder, vorder};
    return points_read(2, target, s, o);
}

/* ---- glMap1, glMap2 ---- */

/* A map definition's checks in the order llvmpipe makes them (so a call
 * with several faults raises the same error): equal domain ends, then the
 * orders (GL_INVALID_VALUE), no points, an enum that is no map target
 * (GL_INVALID_ENUM), a stride below the components (GL_INVALID_VALUE), a
 * texture unit other than the first active (GL_INVALID_OPERATION, GL 1.5
 * spec 2.7 / F.2.13: evaluators feed unit 0), a target of the other
 * dimension (GL_INVALID_ENUM).  Returns the map's index or -1. */
static int map_check(fs_context *c, int dim, GLenum target, const float dom[4], const GLint stride[2],
                     const GLint order[2], const void *points)
{
    int idx = 0;
    GLenum err = GL_NO_ERROR;
    int tdim = map_target(target, &idx);
    for (int d = 0; d < dim && !err; d++)
        if (dom[2 * d] == dom[2 * d + 1])
            err = GL_INVALID_VALUE;
    for (int d = 0; d < dim && !err; d++)
        if (order[d] < 1 || order[d] > FS_MAX_EVAL_ORDER)
            err = GL_INVALID_VALUE;
    if (!err && !points)
        err = GL_INVALID_VALUE;
    if (!err && !tdim)
        err = GL_INVALID_ENUM;
    for (int d = 0; d < dim && !err; d++)
        if (stride[d] < map_components[idx])
            err = GL_INVALID_VALUE;
    if (!err && fs_active_unit(c) != 0)
        err = GL_INVALID_OPERATION;
    if (!err && tdim != dim)
        err = GL_INVALID_ENUM;
    if (err) {
        fs_error(c, err);
        return -1;
    }
    return idx;
}

/* Defines a map from float or double control points (dbl), copied now:
 * the map, and a display list that holds the call, keep their own. */
static void map_define(fs_context *c, int dim, GLenum target, const float dom[4], const GLint stride[2],
                       const GLint order[2], const void *points, bool dbl)
{
    int idx = map_check(c, dim, target, dom, stride, order, points);
    if (idx < 0)
        return;
    struct fs_eval_maps *m = eval_maps(c);
    if (!m)
        return;
    int k = map_components[idx];
    float *p = malloc((size_t)order[0] * (size_t)order[1] * (size_t)k * sizeof *p);
    if (!p) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    float *o = p;
    for (int64_t i = 0; i < order[0]; i++)
        for (int64_t j = 0; j < order[1]; j++)
            for (int e = 0; e < k; e++) {
                int64_t at = i * stride[0] + j * stride[1] + e;
                *o++ = dbl ? (float)((const GLdouble *)points)[at] : ((const GLfloat *)points)[at];
            }
    fs_eval_map *e = &m->map[dim - 1][idx];
    free(e->points);
    e->points = p;
    for (int d = 0; d < 2; d++) {
        e->order[d] = d < dim ? order[d] : 1;
        e->domain[2 * d] = d < dim ? dom[2 * d] : 0.0f;
        e->domain[2 * d + 1] = d < dim ? dom[2 * d + 1] : 1.0f;
        e->inv[d] = 1.0f / (e->domain[2 * d + 1] - e->domain[2 * d]);
    }
}

static void map1(fs_context *c, GLenum target, float u1, float u2, GLint stride, GLint order, const void *points,
                 bool dbl)
{
    const float dom[4] = {u1, u2, 0.0f, 1.0f};
    const GLint s[2] = {stride, 0}, o[2] = {order, 1};
    map_define(c, 1, target, dom, s, o, points, dbl);
}

static void map2(fs_context *c, GLenum target, const float dom[4], GLint ustride, GLint uorder, GLint vstride,
                 GLint vorder, const void *points, bool dbl)
{
    const GLint s[2] = {ustride, vstride}, o[2] = {uorder, vorder};
    map_define(c, 2, target, dom, s, o, points, dbl);
}

void fs_exec_Map1f(fs_context *c, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                   const GLfloat *points)
{
    map1(c, target, u1, u2, stride, order, points, false);
}

void fs_exec_Map1d(fs_context *c, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                   const GLdouble *points)
{
    map1(c, target, (float)u1, (float)u2, stride, order, points, true);
}

void fs_exec_Map2f(fs_context *c, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1,
                   GLfloat v2, GLint vstride, GLint vorder, const GLfloat *points)
{
    const float dom[4] = {u1, u2, v1, v2};
    map2(c, target, dom, ustride, uorder, vstride, vorder, points, false);
}

void fs_exec_Map2d(fs_context *c, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                   GLdouble v1, GLdouble v2, GLint vstride, GLint vorder, const GLdouble *points)
{
    const float dom[4] = {(float)u1, (float)u2, (float)v1, (float)v2};
    map2(c, target, dom, ustride, uorder, vstride, vorder, points, true);
}

/* ---- glGetMap (6.1.8) ---- */

/* The values glGetMap answers for target and query (GL_COEFF: the control
 * points, i before j; GL_ORDER; GL_DOMAIN), as floats, in *n; tmp holds
 * the short ones.  NULL with the error set for a bad target or query. */
static const float *map_query(fs_context *c, GLenum target, GLenum query, int *n, float tmp[4])
{
    int idx, dim = map_target(target, &idx);
    if (!dim || (query != GL_COEFF && query != GL_ORDER && query != GL_DOMAIN)) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    struct fs_eval_maps *m = eval_maps(c);
    if (!m)
        return NULL;
    const fs_eval_map *e = &m->map[dim - 1][idx];
    if (query == GL_COEFF) {
        *n = e->order[0] * e->order[1] * map_components[idx];
        return e->points;
    }
    *n = query == GL_ORDER ? dim : 2 * dim;
    for (int d = 0; d < *n; d++)
        tmp[d] = query == GL_ORDER ? (float)e->order[d] : e->domain[d];
    return tmp;
}

int fs_getmap_count(fs_context *c, GLenum target, GLenum query)
{
    int idx, dim = map_target(target, &idx);
    if (!dim)
        return 0;
    const fs_eval_map *e = c->eval_maps ? &c->eval_maps->map[dim - 1][idx] : NULL;
    switch (query) {
    case GL_COEFF: return e ? e->order[0] * e->order[1] * map_components[idx] : map_components[idx];
    case GL_ORDER: return dim;
    case GL_DOMAIN: return 2 * dim;
    default: return 0;
    }
}

/* glGetMap into v of GL_FLOAT, GL_DOUBLE or GL_INT values (integers
 * rounded to the nearest, 6.1.2). */
static void get_map(fs_context *c, GLenum target, GLenum query, void *v, GLenum type)
{
    float tmp[4];
    int n = 0;
    const float *x = map_query(c, target, query, &n, tmp);
    for (int i = 0; x && i < n; i++) {
        if (type == GL_FLOAT)
            ((GLfloat *)v)[i] = x[i];
        else if (type == GL_DOUBLE)
            ((GLdouble *)v)[i] = x[i];
        else
            ((GLint *)v)[i] = (GLint)lroundf(x[i]);
    }
}

void fs_exec_GetMapfv(fs_context *c, GLenum target, GLenum query, GLfloat *v) { get_map(c, target, query, v, GL_FLOAT); }
void fs_exec_GetMapdv(fs_context *c, GLenum target, GLenum query, GLdouble *v) { get_map(c, target, query, v, GL_DOUBLE); }
void fs_exec_GetMapiv(fs_context *c, GLenum target, GLenum query, GLint *v) { get_map(c, target, query, v, GL_INT); }

/* ---- glMapGrid (5.1) ---- */

void fs_exec_MapGrid1f(fs_context *c, GLint un, GLfloat u1, GLfloat u2)
{
    if (un < 1) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    c->eval.grid1_segments = un;
    c->eval.grid1_domain[0] = u1;
    c->eval.grid1_domain[1] = u2;
    fs_state_mark(c, GL_EVAL_BIT);
}

void fs_exec_MapGrid1d(fs_context *c, GLint un, GLdouble u1, GLdouble u2)
{
    fs_exec_MapGrid1f(c, un, (float)u1, (float)u2);
}

void fs_exec_MapGrid2f(fs_context *c, GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2)
{
    if (un < 1 || vn < 1) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    const GLint segments[2] = {un, vn};
    const float domain[4] = {u1, u2, v1, v2};
    memcpy(c->eval.grid2_segments, segments, sizeof segments);
    memcpy(c->eval.grid2_domain, domain, sizeof domain);
    fs_state_mark(c, GL_EVAL_BIT);
}

void fs_exec_MapGrid2d(fs_context *c, GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2)
{
    fs_exec_MapGrid2f(c, un, (float)u1, (float)u2, vn, (float)v1, (float)v2);
}

/* ---- evaluation ---- */

/* The Bezier curve of `order` control points of k components, `step`
 * floats apart, at t in [0, 1], by Horner's scheme: with s = 1 - t,
 * c = (...((s b0 + C1 t b1) s + C2 t^2 b2) s + ...) + C(n-1) t^(n-1) b(n-1),
 * the binomial coefficients carried as C(i) = C(i-1) (n - i) * (1/i),
 * 1/i a float (as llvmpipe's front end computes it). */
static void bezier_curve(const float *p, size_t step, int order, int k, float t, float *out)
{
    if (order < 2) {
        for (int e = 0; e < k; e++)
            out[e] = p[e];
        return;
    }
    float s = 1.0f - t, bc = (float)(order - 1), tp = t;
    for (int e = 0; e < k; e++)
        out[e] = s * p[e] + bc * t * p[step + e];
    for (int i = 2; i < order; i++) {
        tp *= t;
        bc *= (float)(order - i);
        bc *= 1.0f / (float)i;
        for (int e = 0; e < k; e++)
            out[e] = s * out[e] + bc * tp * p[(size_t)i * step + e];
    }
}

/* A point of a surface by Horner's scheme, first along the direction of
 * the lower order (v when the orders are equal). */
static void bezier_surface(const fs_eval_map *m, int k, float u, float v, float *out)
{
    float cp[FS_MAX_EVAL_ORDER * 4];
    int uo = m->order[0], vo = m->order[1];
    size_t row = (size_t)vo * (size_t)k;
    if (vo > uo) {
        for (int j = 0; j < vo; j++)
            bezier_curve(m->points + (size_t)j * k, row, uo, k, u, cp + (size_t)j * k);
        bezier_curve(cp, (size_t)k, vo, k, v, out);
    } else {
        for (int i = 0; i < uo; i++)
            bezier_curve(m->points + (size_t)i * row, (size_t)k, vo, k, v, cp + (size_t)i * k);
        bezier_curve(cp, (size_t)k, uo, k, u, out);
    }
}

/* de Casteljau's algorithm on one component's control net g (g[i][j],
 * nu x nv, rows FS_MAX_EVAL_ORDER apart), reduced in place. */
typedef float fs_eval_net[FS_MAX_EVAL_ORDER][FS_MAX_EVAL_ORDER];

static float lerp(float a, float b, float t, float s) { return s * a + t * b; }

/* Bilinear steps (along u, then along v of the results) until the lower
 * order is 2. */
static void net_reduce(fs_eval_net g, int *nu, int *nv, float u, float v)
{
    float us = 1.0f - u, vs = 1.0f - v;
    while (*nu > 2 && *nv > 2) {
        for (int i = 0; i + 1 < *nu; i++) {
            float a = lerp(g[i][0], g[i + 1][0], u, us);
            for (int j = 0; j + 1 < *nv; j++) {
                float b = lerp(g[i][j + 1], g[i + 1][j + 1], u, us);
                g[i][j] = lerp(a, b, v, vs);
                a = b;
            }
        }
        (*nu)--;
        (*nv)--;
    }
}

/* Linear steps on a row of n values down to 2. */
static void row_reduce(float *x, int n, float t)
{
    float s = 1.0f - t;
    for (; n > 2; n--)
        for (int i = 0; i + 1 < n; i++)
            x[i] = lerp(x[i], x[i + 1], t, s);
}

/* One component of the point and of the (unscaled) partial derivatives
 * at (u, v) from a net of orders of at least 2. */
static void net_point(fs_eval_net g, int nu, int nv, float u, float v, float *p, float *du, float *dv)
{
    float us = 1.0f - u, vs = 1.0f - v;
    float diff[FS_MAX_EVAL_ORDER], pt[FS_MAX_EVAL_ORDER];
    net_reduce(g, &nu, &nv, u, v);
    if (nu == 2 && nv == 2) {
        *du = lerp(g[1][0] - g[0][0], g[1][1] - g[0][1], v, vs);
        *dv = lerp(g[0][1] - g[0][0], g[1][1] - g[1][0], u, us);
        *p = lerp(lerp(g[0][0], g[0][1], v, vs), lerp(g[1][0], g[1][1], v, vs), u, us);
    } else if (nu == 2) {
        /* The u difference and the u step, then along v. */
        for (int j = 0; j < nv; j++) {
            diff[j] = g[1][j] - g[0][j];
            pt[j] = lerp(g[0][j], g[1][j], u, us);
        }
        row_reduce(diff, nv, v);
        row_reduce(pt, nv, v);
        *dv = pt[1] - pt[0];
        *du = lerp(diff[0], diff[1], v, vs);
        *p = lerp(pt[0], pt[1], v, vs);
    } else {
        for (int i = 0; i < nu; i++) {
            diff[i] = g[i][1] - g[i][0];
            pt[i] = lerp(g[i][0], g[i][1], v, vs);
        }
        row_reduce(diff, nu, u);
        row_reduce(pt, nu, u);
        *du = pt[1] - pt[0];
        *dv = lerp(diff[0], diff[1], u, us);
        *p = lerp(pt[0], pt[1], u, us);
    }
}

/* A surface point and its partial derivatives, component by component. */
static void surface_with_derivatives(const fs_eval_map *m, int k, float u, float v, float *p, float *du, float *dv)
{
    fs_eval_net g;
    int uo = m->order[0], vo = m->order[1];
    if (uo < 2 || vo < 2) {
        bezier_surface(m, k, u, v, p);
        for (int e = 0; e < k; e++)
            du[e] = dv[e] = 0.0f;
        return;
    }
    for (int e = 0; e < k; e++) {
        for (int i = 0; i < uo; i++)
            for (int j = 0; j < vo; j++)
                g[i][j] = m->points[((size_t)i * vo + j) * k + e];
        net_point(g, uo, vo, u, v, &p[e], &du[e], &dv[e]);
    }
}

/* GL_AUTO_NORMAL's normal (5.1): dP/du x dP/dv, for a rational surface of
 * the derivatives of the homogeneous point's xyz times w minus w's times
 * xyz, normalised unless it is zero. */
static void auto_normal(const float *p, float *du, float *dv, int k, float n[3])
{
    if (k == 4)
        for (int e = 0; e < 3; e++) {
            du[e] = du[e] * p[3] - du[3] * p[e];
            dv[e] = dv[e] * p[3] - dv[3] * p[e];
        }
    n[0] = du[1] * dv[2] - du[2] * dv[1];
    n[1] = du[2] * dv[0] - du[0] * dv[2];
    n[2] = du[0] * dv[1] - du[1] * dv[0];
    float len = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (len != 0.0f) {
        float inv = 1.0f / sqrtf(len);
        for (int e = 0; e < 3; e++)
            n[e] *= inv;
    }
}

/* One map at (u, v) (v unused for a MAP1), into out preset to (0, 0, 0, 1). */
static void map_eval(const fs_eval_map *m, int dim, int k, float u, float v, float out[4])
{
    float uu = (u - m->domain[0]) * m->inv[0];
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    if (dim == 1)
        bezier_curve(m->points, (size_t)k, m->order[0], k, uu, out);
    else
        bezier_surface(m, k, uu, (v - m->domain[2]) * m->inv[1], out);
}

/* The enabled texture-coordinate map of the highest dimension (5.1), or -1. */
static int tex_map(const bool *enabled)
{
    for (int k = MAP_TEX4; k >= MAP_TEX1; k--)
        if (enabled[k])
            return k;
    return -1;
}

/* glEvalCoord: the enabled maps' values become the vertex's colour,
 * normal and unit 0's texture coordinates, and the vertex map's value
 * its position; without a vertex map nothing happens (5.1).  The current
 * values are restored after the vertex. */
static void eval_coord(fs_context *c, int dim, float u, float v)
{
    const bool *on = dim == 1 ? c->eval.map1 : c->eval.map2;
    int vtx = on[MAP_VERTEX4] ? MAP_VERTEX4 : on[MAP_VERTEX3] ? MAP_VERTEX3 : -1;
    if (vtx < 0)
        return;
    struct fs_eval_maps *maps = eval_maps(c);
    if (!maps)
        return;
    const fs_eval_map *m = maps->map[dim - 1];
    fs_current_state saved = c->current;
    float x[4];
    if (on[MAP_COLOR4]) {
        map_eval(&m[MAP_COLOR4], dim, 4, u, v, x);
        memcpy(c->current.color, x, sizeof c->current.color);
        fs_vs_attrib_given(c, FS_ATTR_COLOR); /* a per-vertex colour, as Mesa's evaluator gives it */
    }
    if (on[MAP_NORMAL]) {
        map_eval(&m[MAP_NORMAL], dim, 3, u, v, x);
        memcpy(c->current.normal, x, sizeof c->current.normal);
    }
    int t = tex_map(on);
    if (t >= 0) {
        map_eval(&m[t], dim, map_components[t], u, v, x);
        memcpy(c->current.texcoord[0], x, sizeof c->current.texcoord[0]);
        fs_vs_attrib_given(c, FS_ATTR_TEX(0));
    }
    int k = map_components[vtx];
    if (dim == 2 && c->eval.auto_normal) {
        const fs_eval_map *mv = &m[vtx];
        float du[4], dv[4];
        x[3] = 1.0f;
        surface_with_derivatives(mv, k, (u - mv->domain[0]) * mv->inv[0], (v - mv->domain[2]) * mv->inv[1], x, du,
                                 dv);
        auto_normal(x, du, dv, k, c->current.normal);
    } else {
        map_eval(&m[vtx], dim, k, u, v, x);
    }
    fs_exec_Vertex4fv(c, x);
    c->current = saved;
}

void fs_exec_EvalCoord1f(fs_context *c, GLfloat u) { eval_coord(c, 1, u, 0.0f); }
void fs_exec_EvalCoord1d(fs_context *c, GLdouble u) { eval_coord(c, 1, (float)u, 0.0f); }
void fs_exec_EvalCoord1fv(fs_context *c, const GLfloat *u) { eval_coord(c, 1, u[0], 0.0f); }
void fs_exec_EvalCoord1dv(fs_context *c, const GLdouble *u) { eval_coord(c, 1, (float)u[0], 0.0f); }
void fs_exec_EvalCoord2f(fs_context *c, GLfloat u, GLfloat v) { eval_coord(c, 2, u, v); }
void fs_exec_EvalCoord2d(fs_context *c, GLdouble u, GLdouble v) { eval_coord(c, 2, (float)u, (float)v); }
void fs_exec_EvalCoord2fv(fs_context *c, const GLfloat *u) { eval_coord(c, 2, u[0], u[1]); }
void fs_exec_EvalCoord2dv(fs_context *c, const GLdouble *u) { eval_coord(c, 2, (float)u[0], (float)u[1]); }

/* ---- the grids: glEvalPoint, glEvalMesh (5.1) ---- */

/* The grid step of direction d of the 1D (dim 1) or 2D grid. */
static float grid_step(const fs_context *c, int dim, int d)
{
    const float *dom = dim == 1 ? c->eval.grid1_domain : c->eval.grid2_domain;
    GLint n = dim == 1 ? c->eval.grid1_segments : c->eval.grid2_segments[d];
    return (dom[2 * d + 1] - dom[2 * d]) / (float)n;
}

void fs_exec_EvalPoint1(fs_context *c, GLint i)
{
    eval_coord(c, 1, (float)i * grid_step(c, 1, 0) + c->eval.grid1_domain[0], 0.0f);
}

void fs_exec_EvalPoint2(fs_context *c, GLint i, GLint j)
{
    eval_coord(c, 2, (float)i * grid_step(c, 2, 0) + c->eval.grid2_domain[0],
               (float)j * grid_step(c, 2, 1) + c->eval.grid2_domain[2]);
}

/* Whether a mesh of (n1 + 1) x (n2 + 1) points may be drawn; otherwise
 * GL_OUT_OF_MEMORY (FS_EVAL_MESH_MAX). */
static bool mesh_size_ok(fs_context *c, int64_t n1, int64_t n2)
{
    if (n1 < 0 || n2 < 0)
        return true;
    if (n1 >= FS_EVAL_MESH_MAX || n2 >= FS_EVAL_MESH_MAX || (n1 + 1) * (n2 + 1) * 2 > FS_EVAL_MESH_MAX) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return false;
    }
    return true;
}

void fs_exec_EvalMesh1(fs_context *c, GLenum mode, GLint i1, GLint i2)
{
    if (mode != GL_POINT && mode != GL_LINE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if ((!c->eval.map1[MAP_VERTEX3] && !c->eval.map1[MAP_VERTEX4]) || !mesh_size_ok(c, (int64_t)i2 - i1, 0))
        return;
    float du = grid_step(c, 1, 0);
    float u = c->eval.grid1_domain[0] + (float)i1 * du;
    fs_exec_Begin(c, mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
    for (int64_t i = i1; i <= i2; i++, u += du)
        eval_coord(c, 1, u, 0.0f);
    fs_exec_End(c);
}

/* glEvalMesh2's lines: strips along u for each v (along_u), or along v
 * for each u. */
static void mesh2_lines(fs_context *c, bool along_u, GLint i1, GLint i2, GLint j1, GLint j2, float u1, float v1,
                        float du, float dv)
{
    GLint outer1 = along_u ? j1 : i1, outer2 = along_u ? j2 : i2;
    GLint inner1 = along_u ? i1 : j1, inner2 = along_u ? i2 : j2;
    float o = along_u ? v1 : u1, step_o = along_u ? dv : du;
    for (int64_t a = outer1; a <= outer2; a++, o += step_o) {
        float in = along_u ? u1 : v1, step_in = along_u ? du : dv;
        fs_exec_Begin(c, GL_LINE_STRIP);
        for (int64_t b = inner1; b <= inner2; b++, in += step_in)
            eval_coord(c, 2, along_u ? in : o, along_u ? o : in);
        fs_exec_End(c);
    }
}

void fs_exec_EvalMesh2(fs_context *c, GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2)
{
    if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if ((!c->eval.map2[MAP_VERTEX3] && !c->eval.map2[MAP_VERTEX4]) ||
        !mesh_size_ok(c, (int64_t)i2 - i1, (int64_t)j2 - j1))
        return;
    float du = grid_step(c, 2, 0), dv = grid_step(c, 2, 1);
    float v1 = c->eval.grid2_domain[2] + (float)j1 * dv;
    float u1 = c->eval.grid2_domain[0] + (float)i1 * du;
    float u, v;
    int64_t i, j;
    switch (mode) {
    case GL_POINT:
        fs_exec_Begin(c, GL_POINTS);
        for (v = v1, j = j1; j <= j2; j++, v += dv)
            for (u = u1, i = i1; i <= i2; i++, u += du)
                eval_coord(c, 2, u, v);
        fs_exec_End(c);
        break;
    case GL_LINE:
        mesh2_lines(c, true, i1, i2, j1, j2, u1, v1, du, dv);
        mesh2_lines(c, false, i1, i2, j1, j2, u1, v1, du, dv);
        break;
    default:
        for (v = v1, j = j1; j < j2; j++, v += dv) {
            fs_exec_Begin(c, GL_TRIANGLE_STRIP);
            for (u = u1, i = i1; i <= i2; i++, u += du) {
                eval_coord(c, 2, u, v);
                eval_coord(c, 2, u, v + dv);
            }
            fs_exec_End(c);
        }
        break;
    }
}
