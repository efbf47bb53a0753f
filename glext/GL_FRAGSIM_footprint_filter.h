/*
 * GL_FRAGSIM_footprint_filter: fast footprint filtering (Huettner,
 * dissertation, Tuebingen 1999, section 4.3; Huettner & Strasser, "Fast
 * footprint MIPmapping", Graphics Hardware 1999) as a texture minification
 * filter.  The full specification is docs/extensions/footprint_filter.txt.
 *
 * Token values lie in the private range 0x6F30-0x6F3F (no token of Mesa's
 * GL/gl.h or GL/glext.h, Debian 12, lies in 0x6000-0x6FFF; 0x6F00-0x6F0F
 * belong to GL_FRAGSIM_occlusion_unit).  Khronos never allocated them.
 */
#ifndef GL_FRAGSIM_footprint_filter
#define GL_FRAGSIM_footprint_filter 1

#include <GL/gl.h>

/* Accepted by glTexParameter* as the value of GL_TEXTURE_MIN_FILTER. */
#define GL_FOOTPRINT_FRAGSIM                 0x6F30 /* every pixel through the footprint filter */
#define GL_FOOTPRINT_HYBRID_FRAGSIM          0x6F31 /* MIPmapping for isotropic footprints, the filter for the rest */
/* Accepted by glTexParameter* as pname. */
#define GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM  0x6F32 /* M: 8, 16 (initial), 32 or 64 texels */
#define GL_TEXTURE_FOOTPRINT_SNAP_FRAGSIM    0x6F33 /* corner snapping, one of: */
#define GL_FOOTPRINT_SNAP_INTEGER_FRAGSIM    0x6F34 /* integer grid positions (initial) */
#define GL_FOOTPRINT_SNAP_MIDPOINT_FRAGSIM   0x6F35 /* texel mid-points, ties up and right */

#endif
