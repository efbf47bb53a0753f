/*
 * The current raster position (GL 1.5 spec 2.13, table 6.5): set by
 * glRasterPos* through the vertex stage and by glWindowPos* (GL 1.4)
 * directly; moved by glBitmap; read by glBitmap, glDrawPixels and
 * glCopyPixels (pipeline/pixel_rect.c) and glGet.
 */
#ifndef FS_RASTER_POS_H
#define FS_RASTER_POS_H
#include <stdbool.h>
#include "rasterizer.h" /* FS_MAX_TEXTURE_UNITS */

typedef struct fs_raster_pos {
    float win[4];     /* window x, y, z and the clip w (as Mesa answers) */
    bool valid;
    float color[4];   /* lit when lighting is on, clamped */
    float index;      /* colour index: 1 in an RGBA context */
    /* Per texture unit (GL 1.3; 2.13 and table 6.5's "n x"): each unit's
     * current coordinates, generated and transformed by that unit's
     * texture matrix, whether or not the unit is enabled. */
    float tex[FS_MAX_TEXTURE_UNITS][4];
    float distance;   /* eye distance, or the fog coordinate (2.13) */
} fs_raster_pos;
#endif
