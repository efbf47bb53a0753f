/*
 * Pixel rectangle state of GL 1.5 spec 3.6.4 that fragsim stores for glGet
 * and glPushAttrib(GL_PIXEL_MODE_BIT): glPixelZoom.  glDrawPixels and
 * glCopyPixels, which zoom, are not commands of fragsim yet.
 */
#include "context.h"

void fs_exec_PixelZoom(fs_context *c, GLfloat xfactor, GLfloat yfactor)
{
    /* 3.6.4: any factors, negative ones included; no error. */
    c->st.zoom[0] = xfactor;
    c->st.zoom[1] = yfactor;
    fs_state_mark(c, GL_PIXEL_MODE_BIT);
}
