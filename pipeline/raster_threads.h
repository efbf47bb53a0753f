/*
 * Threaded functional rasterization (issue 23): a draw's filled triangles
 * are recorded after the vertex stage and rasterized by N threads at once,
 * thread k doing only the quads whose GL rows lie in its bands (bands of
 * 2^FS_PAR_BAND_SHIFT rows, dealt round robin).  Every thread walks all the
 * recorded triangles in their order, so each pixel sees the same fragments
 * in the same order as on one thread: images are bit-identical.  Each
 * thread counts into its own copy of the context's statistics and of the
 * texture unit's counters; they are summed at the join in thread order.
 *
 * Only draws that cannot touch shared mutable state go parallel
 * (fs_par_draw_begin): no observer (observer.h: its hooks are not
 * called from several threads), no Occlusion Unit hook
 * (occlusion modes, queries), GL_RENDER mode, triangle modes filled on both
 * faces, the incremental rasterizer, and no MP-Grid or footprint-filtered
 * texture.  raster.threads = 1 records nothing: today's path exactly.
 */
#ifndef FS_RASTER_THREADS_H
#define FS_RASTER_THREADS_H
#include <stdbool.h>
#include <stddef.h>
#include <GL/gl.h>
#include "rasterizer.h"

typedef struct fs_context fs_context;
struct fs_raster_par;

/* Rows per band: 2^4 = 16 (even, so a quad never straddles two bands). */
#define FS_PAR_BAND_SHIFT 4
/* Most triangles recorded before the batch is rasterized mid-draw. */
#define FS_PAR_BATCH 4096
/* A batch whose triangles' boxes (clamped to the window) cover fewer
 * pixels than this is rasterized on the calling thread alone: the
 * fork/join would cost more than it saves (docs/architecture.md). */
#define FS_PAR_MIN_PIXELS 8192

/* The worker count a raster.threads value means: 0 is the online CPUs,
 * at most 8. */
int fs_par_resolve_threads(long cfg_threads);
/* At the start of fs_prim_draw: whether this draw's triangles are
 * recorded (route: the draw takes the draw module's route). */
void fs_par_draw_begin(fs_context *c, GLenum mode, bool route, bool tri_hook);
/* At its end, and before any other rasterizer entry: rasterizes what was
 * recorded and stops recording. */
void fs_par_draw_end(fs_context *c);
/* Records one triangle (only while recording). */
void fs_par_record(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2);
void fs_par_free(fs_context *c);
/* The triangle path without recording (rasterizer.c), which the threads run. */
void fs_raster_triangle_now(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2);
/* The statistics of the last draws: batches run in parallel, and serially
 * for being below FS_PAR_MIN_PIXELS (for tests). */
void fs_par_counts(const fs_context *c, unsigned long *parallel, unsigned long *serial);
#endif
