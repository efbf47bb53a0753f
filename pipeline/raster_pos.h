/*
 * The current raster position (GL 1.5 spec 2.13, table 6.5): set by
 * glRasterPos* through the vertex stage and by glWindowPos* (GL 1.4)
 * directly; moved by glBitmap; read by glBitmap, glDrawPixels and
 * glCopyPixels (pipeline/pixel_rect.c) and glGet.
 */
#ifndef FS_RASTER_POS_H
#define FS_RASTER_POS_H
#include <stdbool.h>

typedef struct fs_raster_pos {
    float win[4];     /* window x, y, z and the clip w (as Mesa answers) */
    bool valid;
    float color[4];   /* lit when lighting is on, clamped */
    float index;      /* colour index: 1 in an RGBA context */
    float tex[4];     /* transformed by the texture matrix */
    float distance;   /* eye distance, or the fog coordinate (2.13) */
} fs_raster_pos;
#endif
