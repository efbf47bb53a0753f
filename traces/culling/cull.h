/*
 * The culling study (issue 21; Huettner 1999, sec. 3.1): an ordinary OSMesa
 * program, built against libOSMesa (build/cullstudy-osmesa) and against
 * fragsim's shim (build/cullstudy), so the same culling decisions are made
 * on llvmpipe and on the model.
 */
#ifndef CULL_H
#define CULL_H
#include <stdint.h>
#include <GL/gl.h>

/* An axis-aligned box, world coordinates. */
typedef struct cull_box { float lo[3], hi[3]; } cull_box;

/* One object of the scene: the unit of geometry the hierarchies sort
 * (a furnished house of the city).  The dissertation subdivides polygons;
 * here a leaf holds whole objects, so no geometry is split or regrouped and
 * every method draws the very same display-list calls as DR.  Drawn as
 * glTranslatef(pre), glRotatef(angle, axis) if rotate, glTranslatef(post)
 * if nonzero, glScalef(scale) if not 1, glColor3fv(color) if has_color,
 * glCallList(list), between glPushMatrix and glPopMatrix. */
typedef struct cull_obj {
    cull_box box;                 /* world space, this frame */
    uint64_t tris;
    GLuint list;
    float top;                    /* the geometry's highest point, when the scene knows a tighter one than box (or box.hi[1]) */
    float pre[3], angle, axis[3], post[3], scale, color[3];
    int rotate, has_color;
} cull_obj;

/* ---- scenes (cull_scenes.c): Huettner 1999, Table 3.1 ---- */
typedef struct cull_camera { float eye[3], at[3]; double fovy, znear, zfar; } cull_camera;
struct sg;
typedef struct cull_scene {
    struct sg *s;                 /* the emitter the geometry goes through */
    int paper, frames;
    uint64_t seed;
    cull_obj *objs;
    int n_objs;
    uint64_t ground_tris;         /* what ops->ground draws */
    float (*occ)[6];              /* solid occluder boxes lo xyz, hi xyz (the shadow method), or NULL */
    int n_occ;
    void *priv;
} cull_scene;
typedef struct cull_scene_ops {
    const char *name;
    int dynamic;                  /* objects move: frame() places them and their boxes */
    float clear[3];
    int (*setup)(cull_scene *sc, char *err, size_t errlen);   /* lists, objects; 0 or -1 */
    void (*state)(cull_scene *sc);                            /* GL state, once */
    void (*frame)(cull_scene *sc, int frame, cull_camera *cam);
    void (*lights)(cull_scene *sc);                           /* after the view */
    void (*ground)(cull_scene *sc);                           /* drawn first by every method, or NULL */
} cull_scene_ops;
const cull_scene_ops *cull_scene_find(const char *name);
void cull_scene_free(cull_scene *sc);

/* A node of the snSP-tree (sec. 3.1.5): inner nodes only bound their
 * children (boxes of one level may overlap: "sloppy"); leaves hold objects. */
typedef struct cull_node {
    cull_box box;
    uint64_t tris;
    int first_child, n_children;  /* into cull_tree.child */
    int first_obj, n_objs;        /* leaves: into cull_tree.obj_index */
} cull_node;

typedef struct cull_tree {
    cull_node *node;
    int n_nodes, cap_nodes;
    int *child;                   /* child node indices, grouped per node */
    int n_child, cap_child;
    int *obj_index;               /* object indices, grouped per leaf */
    int n_leaves;
} cull_tree;

enum { CULL_DBVS, CULL_PHBVO, CULL_SGI };
/* Builds the hierarchy over objs; leaf_objs: at most that many objects per
 * leaf.  Returns 0, or -1 on out of memory. */
int cull_tree_build(cull_tree *t, int kind, const cull_obj *objs, int n, int leaf_objs);
void cull_tree_free(cull_tree *t);
const char *cull_tree_name(int kind);

/* ---- view frustum (CPU VFC, sec. 3.1.6) ---- */
typedef struct cull_view {
    float mvp[16];                /* projection * modelview, column-major as GL */
    float planes[6][4];
    float eye[3], dir[3];         /* eye position and unit view direction */
    float znear;
    int width, height;
} cull_view;
void cull_view_planes(cull_view *v);
/* 0 outside, 1 intersecting, 2 entirely inside. */
int cull_frustum_test(const cull_view *v, const cull_box *b);
/* Distance from the eye along the view direction to the box's nearest
 * corner (the DepthHeap key, sec. 3.1.8). */
float cull_box_zmin(const cull_view *v, const cull_box *b);
int cull_box_contains(const cull_box *b, const float p[3]);

/* ---- occlusion tests (sec. 3.1.6) ---- */
enum { CULL_TEST_QUERY, CULL_TEST_HP, CULL_TEST_BRIEF, CULL_TEST_STENCIL };
/* Visible samples of the box against the current depth buffer (for hp:
 * 1 or 0), colour, depth and stencil contents left as they were (stencil:
 * the box's rectangle is cleared again).  sampling > 1 reads every
 * sampling-th line of the stencil rectangle only (non-conservative). */
uint64_t cull_occlusion_test(int test, const cull_view *v, const cull_box *b, int sampling);
/* VFC in GL selection mode (sec. 3.1.6): does the box, drawn in GL_SELECT,
 * reach into the view volume?  The caller handles boxes the eye is in or
 * that reach in front of the near plane (they may contain the volume). */
int cull_select_test(const cull_box *b);
/* A reason the test cannot run on this GL, or NULL. */
const char *cull_test_unavailable(int test);

/* ---- occluder shadows (cull_shadow.c; Willmott et al. 2001, sec. 3.2) ---- */
typedef struct cull_shadow {
    float x0, z0, cell, diag;     /* the map's corner, cell edge, a length beyond it */
    int res;                      /* res x res cells */
    float *height;                /* per cell: a lower bound of the shadows' height over it, or -1 */
    unsigned short *raw;          /* the depth read back */
    uint64_t shadows;             /* shadow polygons of the last map */
} cull_shadow;
/* A map over the objects' ground-plane bounds; res even.  0 or -1. */
int cull_shadow_init(cull_shadow *m, const cull_obj *objs, int n, int res);
void cull_shadow_free(cull_shadow *m);
/* Draws and reads back the cull map from eye (GL state left as it was;
 * the depth buffer's first res x res pixels overwritten). */
void cull_shadow_render(cull_shadow *m, const float (*occ)[6], int n_occ, const float eye[3]);
/* 1 when the box is under the map's shadows over all of its footprint. */
int cull_shadow_hidden(const cull_shadow *m, const cull_box *b);

/* ---- output ---- */
int cull_write_png(const char *path, const unsigned char *rgba, int w, int h);
#endif
