/*
 * GL_FRAGSIM_mp_grid: the MIPmap pyramid grid (MP-Grid) of Huettner's
 * dissertation (Tuebingen 1999), section 4.1, as an OpenGL extension: a
 * texture object made of n x m MIPmap pyramids, sampled through the
 * current texture register and pointer table of 4.1.4, with a residency
 * manager that loads and frees pyramid levels for a viewer (4.1.1).  The
 * full specification is docs/extensions/mp_grid.txt.
 *
 * Token values lie in the private range 0x6F20-0x6F2F and at 0x6F30, chosen
 * as those of GL_FRAGSIM_occlusion_unit (0x6F00-0x6F0F): no token of Mesa's
 * GL/gl.h or GL/glext.h (Debian 12) lies in 0x6000-0x6FFF.  0x6F30-0x6F3F
 * belongs to GL_FRAGSIM_footprint_filter.  Not registered.
 */
#ifndef GL_FRAGSIM_mp_grid
#define GL_FRAGSIM_mp_grid 1

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* glGetMPGridiv: the layout */
#define GL_MPGRID_PYRAMIDS_S          0x6F20 /* n */
#define GL_MPGRID_PYRAMIDS_T          0x6F21 /* m */
#define GL_MPGRID_TILE_WIDTH          0x6F22
#define GL_MPGRID_TILE_HEIGHT         0x6F23
#define GL_MPGRID_LEVELS              0x6F24
/* glGetMPGridiv: memory accounting and CTR counters since glMPGridTexture */
#define GL_MPGRID_BYTES_RESIDENT      0x6F25
#define GL_MPGRID_LEVELS_LOADED       0x6F26
#define GL_MPGRID_LEVELS_FREED        0x6F27
#define GL_MPGRID_SUBSTITUTIONS       0x6F28
#define GL_MPGRID_CTR_RELOADS         0x6F29
#define GL_MPGRID_POINTER_THRASHING   0x6F2A
#define GL_MPGRID_IMAGES_MISSING      0x6F2B
/* glMPGridParameteri and glGetMPGridiv */
#define GL_MPGRID_KEEP_SIDE           0x6F2C /* levels of at most this side stay resident (0) */
#define GL_MPGRID_MERGE_SIDE          0x6F2D /* levels of at most this side are stored merged (0: off) */
#define GL_MPGRID_MERGE_BLOCK         0x6F2E /* pyramids per side of a merged block (4) */
#define GL_MAX_MPGRID_PYRAMIDS        0x6F2F /* glGetMPGridiv: largest n and m */
#define GL_MPGRID_AUTO_ADAPT          0x6F40 /* adapt when the camera changed, before texturing (FALSE) */

typedef void (APIENTRYP PFNGLMPGRIDTEXTUREPROC)(GLenum target, GLsizei n, GLsizei m, GLsizei tileWidth,
                                                GLsizei tileHeight, GLint internalformat);
typedef void (APIENTRYP PFNGLMPGRIDIMAGEPROC)(GLenum target, GLint i, GLint j, GLint level, GLsizei width,
                                              GLsizei height, GLenum format, GLenum type, const GLvoid *pixels);
typedef void (APIENTRYP PFNGLMPGRIDPARAMETERIPROC)(GLenum target, GLenum pname, GLint param);
typedef void (APIENTRYP PFNGLMPGRIDBOUNDINGBOXPROC)(GLenum target, GLint i, GLint j, const GLfloat *box,
                                                    GLboolean occluded);
typedef void (APIENTRYP PFNGLMPGRIDADAPTPROC)(GLenum target);
typedef void (APIENTRYP PFNGLGETMPGRIDIVPROC)(GLenum target, GLenum pname, GLint *params);

#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glMPGridTexture(GLenum target, GLsizei n, GLsizei m, GLsizei tileWidth, GLsizei tileHeight,
                                    GLint internalformat);
GLAPI void APIENTRY glMPGridImage(GLenum target, GLint i, GLint j, GLint level, GLsizei width, GLsizei height,
                                  GLenum format, GLenum type, const GLvoid *pixels);
GLAPI void APIENTRY glMPGridParameteri(GLenum target, GLenum pname, GLint param);
GLAPI void APIENTRY glMPGridBoundingBox(GLenum target, GLint i, GLint j, const GLfloat *box, GLboolean occluded);
GLAPI void APIENTRY glMPGridAdapt(GLenum target);
GLAPI void APIENTRY glGetMPGridiv(GLenum target, GLenum pname, GLint *params);
#endif

#ifdef __cplusplus
}
#endif
#endif
