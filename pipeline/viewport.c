/*
 * Viewport and depth range (GL 1.5 spec 2.11.1).  The window transform is
 * kept as scale and translate in float, as Mesa hands it to the draw
 * module: x_w = x_ndc * (w/2) + (x + w/2), z_w = z_ndc * (f-n)/2 + (n+f)/2.
 */
#include "vertex_internal.h"

/* Mesa's limits for llvmpipe: GL_MAX_VIEWPORT_DIMS and the viewport bounds. */
#define FS_MAX_VIEWPORT 16384
#define FS_VIEWPORT_BOUND 32768

void fs_exec_Viewport(fs_context *c, GLint x, GLint y, GLsizei width, GLsizei height)
{
    if (width < 0 || height < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (width > FS_MAX_VIEWPORT) width = FS_MAX_VIEWPORT;
    if (height > FS_MAX_VIEWPORT) height = FS_MAX_VIEWPORT;
    if (x < -FS_VIEWPORT_BOUND) x = -FS_VIEWPORT_BOUND;
    if (x > FS_VIEWPORT_BOUND - 1) x = FS_VIEWPORT_BOUND - 1;
    if (y < -FS_VIEWPORT_BOUND) y = -FS_VIEWPORT_BOUND;
    if (y > FS_VIEWPORT_BOUND - 1) y = FS_VIEWPORT_BOUND - 1;
    c->xf.viewport_set = true;
    c->xf.viewport[0] = x;
    c->xf.viewport[1] = y;
    c->xf.viewport[2] = width;
    c->xf.viewport[3] = height;
}

static double clamp01(double v)
{
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; /* NaN becomes 0 */
}

void fs_exec_DepthRange(fs_context *c, GLclampd zNear, GLclampd zFar)
{
    c->xf.depth_range[0] = clamp01(zNear);
    c->xf.depth_range[1] = clamp01(zFar);
}

void fs_viewport_xform(fs_context *c, float scale[3], float trans[3])
{
    if (!c->xf.viewport_set) {
        c->xf.viewport[0] = c->xf.viewport[1] = 0;
        c->xf.viewport[2] = c->fb.width;
        c->xf.viewport[3] = c->fb.height;
    }
    const GLint *v = c->xf.viewport;
    const float hw = (float)v[2] * 0.5f, hh = (float)v[3] * 0.5f;
    scale[0] = hw;
    trans[0] = hw + (float)v[0];
    scale[1] = hh;
    trans[1] = hh + (float)v[1];
    const double n = c->xf.depth_range[0], f = c->xf.depth_range[1];
    scale[2] = (float)((f - n) / 2.0);
    trans[2] = (float)((n + f) / 2.0);
}
