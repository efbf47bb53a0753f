/*
 * The current raster position (GL 1.5 spec 2.13): glRasterPos{234}{sifd}[v]
 * and glWindowPos{23}{sifd}[v] (GL 1.4).
 *
 * glRasterPos treats its coordinates as a vertex: it goes through the same
 * transformation, lighting and texture-matrix code as a point would
 * (fs_vs_prepare/fs_vs_process), and is valid when the vertex is inside
 * the view volume (2.13: clipped as a point).  Measured on OSMesa: the
 * fourth component is the clip w, the distance is the length of the eye
 * position's x, y, z (w not divided out), and an invalid position keeps
 * every other value.  glWindowPos sets window x and y as given, z clamped
 * to [0,1] and mapped into the depth range, the current colour and texture
 * coordinates untransformed, distance 0 (the fog coordinate when it is the
 * fog source, which fragsim does not store yet), and is always valid.
 */
#include <math.h>
#include <string.h>
#include "vertex_internal.h"

static void raster_pos(fs_context *c, float x, float y, float z, float w)
{
    fs_vs_setup s;
    memset(&s, 0, sizeof s);
    fs_vs_prepare(c, &s);
    /* Every unit's raster texture coordinates are kept (2.13), not only
     * those of the units a draw reads (fs_vs_prepare's ntex): on OSMesa each
     * unit's come from its own current coordinates, texture generation
     * and texture matrix, enabled or not (tests/test_pixel_rect.c). */
    float id[16];
    fs_mat_identity(id);
    for (int u = s.ntex; u < FS_MAX_TEXTURE_UNITS; u++) {
        const fs_transform_state *xf = &c->xf;
        memcpy(s.tex[u], xf->texture[u][xf->texture_top[u]].m, sizeof s.tex[u]);
        s.tex_identity[u] = memcmp(s.tex[u], id, sizeof id) == 0;
    }
    s.ntex = FS_MAX_TEXTURE_UNITS;
    fs_texgen_setup(c, &s);
    fs_ivert iv;
    memset(&iv, 0, sizeof iv);
    iv.obj[0] = x;
    iv.obj[1] = y;
    iv.obj[2] = z;
    iv.obj[3] = w;
    memcpy(iv.col, c->current.color, sizeof iv.col);
    memcpy(iv.nrm, c->current.normal, sizeof iv.nrm);
    memcpy(iv.tc, c->current.texcoord, sizeof iv.tc);
    fs_pvert pv;
    fs_vs_process(&s, &iv, &pv, 1, NULL);
    fs_raster_pos *r = &c->rpos;
    /* Inside the view volume by the six comparisons alone: unlike a
     * vertex of a primitive, a NaN coordinate (every comparison false)
     * leaves the position valid, as on OSMesa. */
    float eye0[4], v[4];
    fs_mat_xform4(eye0, s.mv, iv.obj);
    fs_mat_xform4(v, c->xf.projection[c->xf.projection_top].m, eye0);
    r->valid = !(v[0] > v[3] || 0.0f > v[0] + v[3] || v[1] > v[3] || 0.0f > v[1] + v[3] || 0.0f > v[2] + v[3] ||
                 v[2] > v[3]);
    if (!r->valid)
        return;
    /* The draw module's viewport transform, product and sum rounded
     * apart; Mesa's state tracker takes y in its y-down frame and flips
     * it back (height - y). */
    const float iw = 1.0f / v[3];
    volatile float t;
    t = v[0] * iw * s.vp_scale[0];
    r->win[0] = t + s.vp_trans[0];
    t = v[1] * iw * s.vp_scale[1];
    r->win[1] = t + s.vp_trans[1];
    t = v[2] * iw * s.vp_scale[2];
    r->win[2] = t + s.vp_trans[2];
    r->win[3] = v[3];
    /* Not clamped (OSMesa answers the current colour as given, and a lit
     * colour above 1); fs_vs_process clamps lit colours, so those
     * saturate here (a known difference). */
    memcpy(r->color, s.lighting ? pv.col[0] : c->current.color, sizeof r->color);
    memcpy(r->tex, pv.tc, sizeof r->tex);
    float eye[4];
    fs_mat_xform4(eye, s.mv, iv.obj);
    r->distance = sqrtf(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    /* 2.13: the fog coordinate when it is the fog source; fragsim keeps no
     * current fog coordinate yet, whose initial value is 0. */
    if (c->st.fog.coord_src == GL_FOG_COORD)
        r->distance = 0.0f;
}

static float clamp01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

static void window_pos(fs_context *c, float x, float y, float z)
{
    fs_raster_pos *r = &c->rpos;
    float n = (float)c->xf.depth_range[0], f = (float)c->xf.depth_range[1];
    r->win[0] = x;
    r->win[1] = y;
    r->win[2] = n + clamp01(z) * (f - n);
    r->win[3] = 1.0f;
    r->valid = true;
    for (int k = 0; k < 4; k++)
        r->color[k] = clamp01(c->current.color[k]); /* clamped, unlike glRasterPos's */
    memcpy(r->tex, c->current.texcoord, sizeof r->tex); /* every unit's, untransformed */
    r->distance = 0.0f;
}

/* The 40 entry points: each converts its arguments to float, as Mesa does. */
#define RP_SCALAR(sfx, T)                                                                                  \
    void fs_exec_RasterPos2##sfx(fs_context *c, T x, T y) { raster_pos(c, (float)x, (float)y, 0.0f, 1.0f); } \
    void fs_exec_RasterPos3##sfx(fs_context *c, T x, T y, T z)                                             \
    {                                                                                                      \
        raster_pos(c, (float)x, (float)y, (float)z, 1.0f);                                                 \
    }                                                                                                      \
    void fs_exec_RasterPos4##sfx(fs_context *c, T x, T y, T z, T w)                                        \
    {                                                                                                      \
        raster_pos(c, (float)x, (float)y, (float)z, (float)w);                                             \
    }                                                                                                      \
    void fs_exec_RasterPos2##sfx##v(fs_context *c, const T *v) { raster_pos(c, (float)v[0], (float)v[1], 0.0f, 1.0f); } \
    void fs_exec_RasterPos3##sfx##v(fs_context *c, const T *v)                                             \
    {                                                                                                      \
        raster_pos(c, (float)v[0], (float)v[1], (float)v[2], 1.0f);                                        \
    }                                                                                                      \
    void fs_exec_RasterPos4##sfx##v(fs_context *c, const T *v)                                             \
    {                                                                                                      \
        raster_pos(c, (float)v[0], (float)v[1], (float)v[2], (float)v[3]);                                 \
    }                                                                                                      \
    void fs_exec_WindowPos2##sfx(fs_context *c, T x, T y) { window_pos(c, (float)x, (float)y, 0.0f); }      \
    void fs_exec_WindowPos3##sfx(fs_context *c, T x, T y, T z) { window_pos(c, (float)x, (float)y, (float)z); } \
    void fs_exec_WindowPos2##sfx##v(fs_context *c, const T *v) { window_pos(c, (float)v[0], (float)v[1], 0.0f); } \
    void fs_exec_WindowPos3##sfx##v(fs_context *c, const T *v)                                             \
    {                                                                                                      \
        window_pos(c, (float)v[0], (float)v[1], (float)v[2]);                                              \
    }
RP_SCALAR(s, GLshort)
RP_SCALAR(i, GLint)
RP_SCALAR(f, GLfloat)
RP_SCALAR(d, GLdouble)
