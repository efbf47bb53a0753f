/*
 * Fine control of buffer updates (GL 1.5 spec 4.2.2): glColorMask and the
 * masked colour write.  glDepthMask lives in depth_test.c and glStencilMask in
 * stencil_test.c, next to the state they guard.
 */
#include "fragment_stages.h"

void fs_exec_ColorMask(fs_context *c, GLboolean red, GLboolean green, GLboolean blue, GLboolean alpha)
{
    c->frag.color_mask[0] = red != GL_FALSE;
    c->frag.color_mask[1] = green != GL_FALSE;
    c->frag.color_mask[2] = blue != GL_FALSE;
    c->frag.color_mask[3] = alpha != GL_FALSE;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

/* 4.2.2: the colour index write mask; the window has no colour index
 * mode (GL_INDEX_BITS 0), so it only answers glGet (as GLint: all ones
 * reads as -1, as on OSMesa). */
void fs_exec_IndexMask(fs_context *c, GLuint mask)
{
    c->st.index_mask = (GLint)mask;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

void fs_masked_color_write(const fs_context *c, uint8_t *dst, const uint8_t rgba[4])
{
    for (int k = 0; k < 4; k++)
        if (c->frag.color_mask[k])
            dst[k] = rgba[k];
}
