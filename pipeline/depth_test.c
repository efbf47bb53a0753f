/*
 * Depth buffer test (GL 1.5 spec 4.1.6), glDepthFunc and glDepthMask, and the
 * combined stencil/depth step: the stencil update (4.1.5) depends on the
 * depth result, so both run per pixel here.  Depth values are compared as
 * unsigned integers in the depth buffer's fixed-point units, as llvmpipe does.
 */
#include "fragment_stages.h"

void fs_exec_DepthFunc(fs_context *c, GLenum func)
{
    if (func < GL_NEVER || func > GL_ALWAYS) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.depth_func = func;
    fs_state_mark(c, GL_DEPTH_BUFFER_BIT);
}

void fs_exec_DepthMask(fs_context *c, GLboolean flag)
{
    c->frag.depth_write = flag != GL_FALSE;
    fs_state_mark(c, GL_DEPTH_BUFFER_BIT);
}

bool fs_depth_test(GLenum func, uint32_t z, uint32_t stored)
{
    switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return z < stored;
    case GL_EQUAL: return z == stored;
    case GL_LEQUAL: return z <= stored;
    case GL_GREATER: return z > stored;
    case GL_NOTEQUAL: return z != stored;
    case GL_GEQUAL: return z >= stored;
    default: return true;
    }
}

unsigned fs_stencil_depth_quad(fs_context *c, const fs_quad *q, unsigned mask,
                               const size_t idx[4], unsigned *tested)
{
    const fs_fragment_state *f = &c->frag;
    fs_framebuffer *fb = &c->fb;
    /* Without a stencil buffer the stencil test always passes and nothing is
     * written (4.1.5). */
    bool stencil = f->stencil_enabled && fb->stencil_bits > 0;
    bool depth = f->depth_enabled;
    /* Occlusion modes run both tests but write neither buffer. */
    bool stencil_write = stencil && !f->suppress_writes;
    bool depth_write = depth && f->depth_write && !f->suppress_writes;
    unsigned reached = 0, passed = 0;
    for (int i = 0; i < 4; i++) {
        if (!(mask >> i & 1u))
            continue;
        size_t k = idx[i];
        if (stencil && !fs_stencil_test(c, fb->stencil[k])) {
            if (stencil_write)
                fb->stencil[k] = fs_stencil_apply(c, f->stencil_fail, fb->stencil[k]);
            c->stats.killed_stencil++;
            continue;
        }
        reached |= 1u << i;
        /* A disabled depth test always passes and never writes (4.1.6). */
        if (depth && !fs_depth_test(f->depth_func, q->z[i], fb->depth[k])) {
            if (stencil_write)
                fb->stencil[k] = fs_stencil_apply(c, f->stencil_zfail, fb->stencil[k]);
            c->stats.killed_depth++;
            continue;
        }
        if (stencil_write)
            fb->stencil[k] = fs_stencil_apply(c, f->stencil_zpass, fb->stencil[k]);
        if (depth_write)
            fb->depth[k] = q->z[i];
        passed |= 1u << i;
    }
    *tested = reached;
    return passed;
}
