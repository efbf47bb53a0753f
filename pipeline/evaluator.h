/*
 * Evaluators (GL 1.5 spec 5.1): the state glPushAttrib(GL_EVAL_BIT) saves
 * (table 6.26: the maps' enables, GL_AUTO_NORMAL and the grids), which
 * pipeline/state.def names; the maps themselves (order, domain, control
 * points, in no attribute group) are pipeline/evaluator.c's, behind
 * fs_context.eval_maps.
 */
#ifndef FS_EVALUATOR_H
#define FS_EVALUATOR_H
#include <stdbool.h>
#include <GL/gl.h>

/* The nine maps of each dimension in the order of their enums (table 5.1:
 * GL_MAP1_COLOR_4 + k, GL_MAP2_COLOR_4 + k). */
#define FS_EVAL_MAPS 9

typedef struct fs_eval_state {
    bool map1[FS_EVAL_MAPS], map2[FS_EVAL_MAPS]; /* GL_MAP1_x, GL_MAP2_x enabled */
    bool auto_normal;                            /* GL_AUTO_NORMAL */
    GLint grid1_segments;                        /* GL_MAP1_GRID_SEGMENTS */
    float grid1_domain[2];                       /* GL_MAP1_GRID_DOMAIN: u1, u2 */
    GLint grid2_segments[2];                     /* GL_MAP2_GRID_SEGMENTS: un, vn */
    float grid2_domain[4];                       /* GL_MAP2_GRID_DOMAIN: u1, u2, v1, v2 */
} fs_eval_state;

typedef struct fs_context fs_context;

/* Frees the maps' control points (fs_context_destroy). */
void fs_eval_free(fs_context *c);

#endif
