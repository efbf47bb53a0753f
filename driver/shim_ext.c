/*
 * The shim's entry points of GL_FRAGSIM_occlusion_unit, with the prototypes
 * of glext/GL_FRAGSIM_occlusion_unit.h (declared here, so the compiler checks
 * them).  They override the weak ones shim_gl.c generates from the table's
 * kinds; see there.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "../glext/GL_FRAGSIM_occlusion_unit.h"
#include "shim.h"

FS_SHIM_EXPORT void APIENTRY glScissors(GLint numTiles, const GLint *tiles)
{
    fs_context *c = fs_shim_begin();
    if (!c)
        return;
    fsglScissors(c, numTiles, tiles);
    fs_shim_end(FS_CMD_Scissors);
}

FS_SHIM_EXPORT void APIENTRY glOcclusionBuffers(const GLsizei *sizes, GLuint **buffers)
{
    fs_context *c = fs_shim_begin();
    if (!c)
        return;
    /* The table passes the pointer array as an opaque pointer: the unit
     * writes through it at glRenderMode(GL_RENDER) (units/occlusion_gl.c). */
    fsglOcclusionBuffers(c, sizes, (const GLvoid *)buffers);
    fs_shim_end(FS_CMD_OcclusionBuffers);
}
