/*
 * GL_FRAGSIM_occlusion_unit: the OpenGL interface of the Occlusion Unit
 * proposed by Bartz, Meissner and Huettner (Graphics Hardware 1998) and in
 * Huettner's dissertation (Tuebingen 1999), section 3.2.1.  The full
 * specification is docs/extensions/occlusion_unit.txt.
 *
 * Token values lie in the private range 0x6F00-0x6F0F.  Khronos never
 * allocated them to this extension; the range was chosen because no token of
 * Mesa's GL/gl.h or GL/glext.h (Debian 12) lies anywhere in 0x6000-0x6FFF.
 * A registered version of the extension would receive values from Khronos.
 *
 * The command and token names are the dissertation's, without a vendor
 * suffix, so that its examples read unchanged (see the spec's Issues).
 */
#ifndef GL_FRAGSIM_occlusion_unit
#define GL_FRAGSIM_occlusion_unit 1

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Accepted by glRenderMode (Huettner 1999, 3.2.1). */
#define GL_BRIEF_OCCLUSION          0x6F00
#define GL_VERBOSE_OCCLUSION        0x6F01
/* Accepted by glGetIntegerv and the other glGet commands. */
#define GL_MAX_OCCLUSION_TILES      0x6F02
#define GL_OCCLUSION_TILE_COUNT     0x6F03 /* tiles set by glScissors; 0: the scissor box is the tile */
#define GL_OCCLUSION_COUNTER_BITS   0x6F04 /* width of NOHC and PHC */

/* Layout of the brief record at the start of every occlusion buffer (words). */
#define GL_OCCLUSION_RECORD_NOHC    0
#define GL_OCCLUSION_RECORD_PHC     1
#define GL_OCCLUSION_RECORD_XMIN    2
#define GL_OCCLUSION_RECORD_XMAX    3
#define GL_OCCLUSION_RECORD_YMIN    4
#define GL_OCCLUSION_RECORD_YMAX    5
#define GL_OCCLUSION_RECORD_ZMIN    6
#define GL_OCCLUSION_RECORD_ZMAX    7
#define GL_OCCLUSION_RECORD_WORDS   8 /* also the smallest buffer glOcclusionBuffers accepts */
#define GL_OCCLUSION_LIST_END       0xFFFFFFFFu /* the -1 ending a verbose hit list */

typedef void (APIENTRYP PFNGLSCISSORSPROC)(GLint numTiles, const GLint *tiles);
typedef void (APIENTRYP PFNGLOCCLUSIONBUFFERSPROC)(const GLsizei *sizes, GLuint **buffers);

#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glScissors(GLint numTiles, const GLint *tiles);
GLAPI void APIENTRY glOcclusionBuffers(const GLsizei *sizes, GLuint **buffers);
#endif

#ifdef __cplusplus
}
#endif
#endif
