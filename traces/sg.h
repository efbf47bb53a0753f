/*
 * Scene generators: shared emitter.
 *
 * Every scene draws through an sg emitter rather than calling fsgl* directly,
 * so that the triangles a scene submits are counted by code that does not
 * depend on fragsim's pipeline statistics, and so that a scene can be run
 * in "count only" mode (no context at all) to report its size at paper
 * scale in milliseconds instead of rendering millions of triangles.
 *
 * Counting rule (GL 1.5 spec 2.6.1): triangles a primitive decomposes into;
 * display lists count when called (nested calls expanded), not when compiled.
 */
#ifndef FS_SG_H
#define FS_SG_H
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>
#include "../driver/gl_call.h"

typedef struct sg_rng { uint64_t s; } sg_rng;

void sg_rng_seed(sg_rng *r, uint64_t seed);
uint64_t sg_rng_u64(sg_rng *r);
double sg_rng_unit(sg_rng *r);                 /* [0, 1) */
double sg_rng_range(sg_rng *r, double lo, double hi);
int sg_rng_int(sg_rng *r, int n);              /* [0, n) */

typedef struct sg {
    fs_context *c;        /* NULL in count-only mode: nothing is sent */
    uint64_t calls;       /* fsgl calls issued (what a trace reader sees, minus frame ends) */
    uint64_t pointer_calls; /* of which gl*Pointer */
    uint64_t tris;        /* triangles executed, all frames */
    uint64_t frame_tris;  /* triangles executed in the current frame */
    uint64_t max_frame_tris, min_frame_tris;
    int frames;

    GLenum prim_mode;     /* current glBegin mode */
    int in_prim;
    uint64_t prim_verts;

    uint64_t *list_tris;  /* triangles per display-list name */
    uint32_t list_cap;
    GLuint next_list;     /* names handed out in count-only mode */
    GLuint compiling;     /* 0 when not compiling */
    uint64_t compile_tris;

    int misuse;           /* a scene broke a GL rule the counter relies on */
    int oom;

    void *scratch[4];     /* reusable client-array buffers (see sg_buf) */
    size_t scratch_size[4];
} sg;

/* Client-array pointer calls: a capture records their data as apitrace's
 * "fake" calls before each draw, so a trace reader sees them differently. */
#define SG_IS_POINTER(id) \
    ((id) == FS_CMD_VertexPointer || (id) == FS_CMD_NormalPointer || \
     (id) == FS_CMD_ColorPointer || (id) == FS_CMD_TexCoordPointer)
/* One GL call.  scenegen sends fsgl<Name> to its fragsim context; the
 * culling program (traces/culling/, built with SG_DIRECT_GL) sends gl<Name>
 * to the current context of whichever GL library it is linked with, so the
 * same geometry runs on libOSMesa and on the shim.  There, c is only a
 * "live" marker (sg_init's c is never dereferenced). */
#ifdef SG_DIRECT_GL
#define SG_SEND(s, Name, ...) gl##Name(__VA_ARGS__)
#define SG_SEND0(s, Name) gl##Name()
#else
#define SG_SEND(s, Name, ...) fsgl##Name((s)->c, __VA_ARGS__)
#define SG_SEND0(s, Name) fsgl##Name((s)->c)
#endif
/* Sends <Name> when there is a context; counts it either way. */
#define G(s, Name, ...) \
    do { \
        (s)->calls++; \
        if (SG_IS_POINTER(FS_CMD_##Name)) (s)->pointer_calls++; \
        if ((s)->c) SG_SEND(s, Name, __VA_ARGS__); \
    } while (0)
#define G0(s, Name) \
    do { (s)->calls++; if ((s)->c) SG_SEND0(s, Name); } while (0)

void sg_init(sg *s, fs_context *c);
void sg_free(sg *s);
/* Triangles a primitive of n vertices makes (GL 1.5 spec 2.6.1). */
uint64_t sg_prim_tris(GLenum mode, uint64_t n);

void sg_begin(sg *s, GLenum mode);
void sg_end(sg *s);
void sg_vtx(sg *s, float x, float y, float z);
void sg_vtxv(sg *s, const float *v);
void sg_nrm(sg *s, float x, float y, float z);
void sg_col(sg *s, float r, float g, float b);

void sg_draw_arrays(sg *s, GLenum mode, GLint first, GLsizei count);
void sg_draw_elements(sg *s, GLenum mode, GLsizei count, GLenum type, const void *idx);

GLuint sg_gen_lists(sg *s, GLsizei n);
void sg_new_list(sg *s, GLuint list);
void sg_end_list(sg *s);
void sg_call_list(sg *s, GLuint list);
/* Triangles a compiled list makes when called. */
uint64_t sg_list_tris(const sg *s, GLuint list);

/* Clears colour and depth. */
void sg_frame_begin(sg *s, float r, float g, float b);
/* glFlush, then the frame boundary in the trace. */
void sg_frame_end(sg *s);

/* A growable client-array buffer; slot 0..3.  NULL on out of memory. */
void *sg_buf(sg *s, int slot, size_t bytes);

/* ---- camera helpers (no GLU in the command table) ---- */
/* The projection matrix of gluPerspective; leaves GL_MODELVIEW current. */
void sg_perspective(sg *s, double fovy_deg, double aspect, double znear, double zfar);
/* Lighting on, with glColor driving the ambient and diffuse material of face. */
void sg_lighting(sg *s, GLenum face);
void sg_look_at(sg *s, const float eye[3], const float at[3], const float up[3]);
void sg_light(sg *s, GLenum light, const float pos[4], const float diffuse[4],
              const float ambient[4], const float specular[4]);

/* ---- geometry: each opens and closes its own primitives ---- */
/* A quad grid of nu x nv cells over origin o and edges u, v, facing u x v. */
void sg_grid(sg *s, const float o[3], const float u[3], const float v[3], int nu, int nv);
/* An axis-aligned box, flat faces, one GL_QUADS; 'bottom' adds the -y face:
 * 10 or 12 triangles. */
void sg_box(sg *s, float x0, float y0, float z0, float x1, float y1, float z1, int bottom);
/* A cylinder on the y axis from y=0 to y=h, smooth sides as one
 * GL_QUAD_STRIP per stack, caps as GL_TRIANGLE_FANs: 2*sl*st (+sl per cap). */
void sg_cylinder(sg *s, float r, float h, int slices, int stacks, int caps);
/* A sphere: GL_TRIANGLE_FAN poles, GL_TRIANGLE_STRIP bands: 2*sl*(st-1). */
void sg_sphere(sg *s, float r, int slices, int stacks);
/* A torus around y: one GL_TRIANGLE_STRIP per minor band: 2*nu*nv. */
void sg_torus(sg *s, float R, float r, int nu, int nv);
/* A flat disc of exactly n triangles (n >= 1) in the plane through c with
 * normal +y, as a GL_TRIANGLE_FAN (or GL_POLYGON when polygon is set): lets a
 * scene hit an exact triangle budget with a rug, a rose window or a label. */
void sg_disc(sg *s, float cx, float cy, float cz, float radius, uint64_t n, int polygon);

/* Deterministic 2D value-noise fractal in [-1, 1] (octaves of lattice noise). */
double sg_fractal(uint64_t seed, double x, double y, int octaves);

/* ---- scenes ---- */
typedef struct sg_params {
    uint64_t target;   /* triangles per frame to aim for */
    int paper;         /* 1 at paper scale (selects the paper's object counts) */
    int frames;
    int width, height;
    uint64_t seed;
    /* The textured scene's ground filter (scenegen --filter, --budget):
     * SG_FILTER_* and the footprint filter's M (0: the GL default, 16). */
    int filter;
    int budget;
} sg_params;
enum { SG_FILTER_TRILINEAR, SG_FILTER_FOOTPRINT, SG_FILTER_FOOTPRINT_HYBRID };

typedef struct sg_scene {
    const char *name;
    const char *summary;
    const char *paper;       /* source and the workload size it reports */
    uint64_t paper_tris;     /* the paper's triangle count (0: none) */
    uint64_t small_tris;
    int small_frames, paper_frames;
    int small_size, paper_size;
    /* Draws every frame; returns 0, or -1 (with err) on failure. */
    int (*run)(sg *s, const sg_params *p, char *err, size_t errlen);
} sg_scene;

extern const sg_scene sg_scenes[];
extern const int sg_scene_count;
const sg_scene *sg_find_scene(const char *name);

typedef struct sg_report {
    uint64_t tris_total;
    uint64_t tris_per_frame;   /* of the first frame (all frames equal unless noted) */
    uint64_t min_frame_tris, max_frame_tris;
    uint64_t calls;            /* fsgl calls, excluding frame ends */
    uint64_t pointer_calls;    /* of which gl*Pointer */
    int frames;
} sg_report;

/* Fills p with the scene's defaults for scale "small", "paper" or a number
 * (triangles per frame).  Returns -1 on a bad scale. */
int sg_default_params(const sg_scene *sc, const char *scale, sg_params *p);
/* Writes the trace: a width x height context in capture mode. */
int sg_generate(const sg_scene *sc, const sg_params *p, const char *path,
                sg_report *rep, char *err, size_t errlen);
/* Runs the scene without a context and reports what it would submit. */
int sg_count(const sg_scene *sc, const sg_params *p, sg_report *rep, char *err, size_t errlen);

/* The city generator's parts (scene_city.c), shared with the culling
 * program: the lot grid and house budgets, the house variants compiled into
 * display lists base..base+variants, and each lot's variant and turn. */
typedef struct sg_city_plan {
    uint64_t houses;           /* lots */
    int cols, rows, variants;  /* variants regular houses + 1 landmark */
    uint64_t budget, landmark_budget, landmark;
    int max_floors;            /* regular houses; the landmark has 2 more */
} sg_city_plan;
#define SG_CITY_LOT 22.0f      /* metres per lot: house plus half a street each side */
#define SG_CITY_FLOOR_H 3.0f
int sg_city_plan_make(sg_city_plan *pl, uint64_t houses, uint64_t target, int max_floors,
                      const char *name, char *err, size_t errlen);
/* Compiles the variants into lists base..base+variants; 0 or -1 (err). */
int sg_city_compile(sg *s, const sg_city_plan *pl, uint64_t seed, GLuint base, const char *name,
                    char *err, size_t errlen);
/* Lot i's variant and turn (quarter turns about y), drawn from 'lots'
 * (seeded with sg_city_lots_seed) in lot order. */
uint64_t sg_city_lots_seed(uint64_t seed);
/* Variant v's ground-floor rooms as house-model rectangles x0, z0, x1, z1
 * (at most max); each is closed by inward-facing walls, floor and ceiling
 * from y = SG_CITY_ROOM_Y0 to SG_CITY_ROOM_Y1; top: the house's highest
 * point (the roof's ridge).  The count, or -1. */
int sg_city_ground_rooms(const sg_city_plan *pl, uint64_t seed, int v, float rect[][4], int max, float *top);
#define SG_CITY_ROOM_Y0 0.02f
#define SG_CITY_ROOM_Y1 2.92f
void sg_city_lot(sg_rng *lots, const sg_city_plan *pl, uint64_t i, int *variant, int *turn);
/* The lot's model transform, as glTranslate/glRotate calls. */
void sg_city_lot_transform(sg *s, const sg_city_plan *pl, uint64_t i, int turn);

/* The cathedrals generator's parts (scene_cathedral.c), shared with the
 * culling program: one cathedral is a shell and 2 x cols bays (a column and
 * its arch), each setting its own colours. */
typedef struct sg_cath_params {
    int cols;       /* columns per row */
    int slices, stacks;
    int arch_seg, vault_seg, vault_len, wall_sub, floor_sub;
    uint64_t rose[2];
} sg_cath_params;
#define SG_CATH_FOVY 65.0
#define SG_CATH_ZNEAR 0.3
#define SG_CATH_ZFAR 800.0
/* The tessellation giving one copy exactly 'per' triangles; 0 or -1 (err). */
int sg_cath_plan(sg_cath_params *P, uint64_t per, char *err, size_t errlen);
/* Compiles the column into 'list'; 0 or -1 (err). */
int sg_cath_compile_column(sg *s, const sg_cath_params *P, GLuint list, char *err, size_t errlen);
void sg_cath_shell(sg *s, const sg_cath_params *P);
void sg_cath_bay(sg *s, const sg_cath_params *P, GLuint column_list, int side, int i);
/* Model-space bounds of the shell (bay -1) or of bay 0..2 cols-1 (side -1
 * first), with a margin. */
void sg_cath_bounds(const sg_cath_params *P, int bay, float lo[3], float hi[3]);
void sg_cath_copy_offset(int k, float t[3]);   /* copy k of 8 */
void sg_cath_view(float t, float eye[3], float at[3]);   /* path position t in [0, 1] */
void sg_cath_state(sg *s);
void sg_cath_lights(sg *s);

/* The forest generator's parts (scene_forest.c), shared with the culling
 * program: three tree variants in lists base..base+2, the castle in base+3
 * (with the ground, as the scene draws it, or without: then
 * sg_forest_ground draws it), 12 trees placed on the meadow. */
typedef struct sg_forest_plan {
    int sub, stacks;      /* the castle's wall subdivision and tower stacks */
    uint64_t court;       /* the courtyard fan's triangles */
    uint64_t tree;        /* triangles per tree */
} sg_forest_plan;
#define SG_FOREST_FOVY 55.0
#define SG_FOREST_ZNEAR 0.5
#define SG_FOREST_ZFAR 1000.0
int sg_forest_plan_make(sg_forest_plan *F, const sg_params *p, char *err, size_t errlen);
int sg_forest_compile(sg *s, const sg_forest_plan *F, uint64_t seed, GLuint base, int with_ground, char *err,
                      size_t errlen);
void sg_forest_ground(sg *s);
void sg_forest_trees(uint64_t seed, float tx[12], float tz[12], int tv[12]);
/* Model-space bounds of a tree (castle 0) or of the castle, with a margin. */
void sg_forest_bounds(int castle, float lo[3], float hi[3]);
void sg_forest_view(float t, float eye[3], float at[3]);
void sg_forest_state(sg *s);
void sg_forest_lights(sg *s);

/* The garbage generator's parts (scene_garbage.c), shared with the culling
 * program: n objects of four shapes (lists base..base+7), each frame placed
 * by drawing sg_garbage_object for i = 0..n-1 from one generator seeded with
 * seed * 7919 + 11; t is the frame number. */
typedef struct sg_garbage_plan {
    uint64_t n, per, extra;  /* objects; triangles per object; objects with one more */
    float side;              /* the can's side */
} sg_garbage_plan;
typedef struct sg_garbage_obj {
    float pos[3], angle, axis[3], scale, color[3];
    int list;                /* offset from the lists' base */
} sg_garbage_obj;
#define SG_GARBAGE_FOVY 50.0
#define SG_GARBAGE_ZNEAR 1.0
#define SG_GARBAGE_ZFAR 1000.0
/* Every shape lies within this radius of its origin (the box's corner,
 * sqrt(3) x 0.7 m, is the farthest point), before the object's scale. */
#define SG_GARBAGE_RADIUS 1.25f
int sg_garbage_plan_make(sg_garbage_plan *G, const sg_params *p, char *err, size_t errlen);
void sg_garbage_compile(sg *s, const sg_garbage_plan *G, GLuint base);
void sg_garbage_object(sg_rng *r, const sg_garbage_plan *G, uint64_t i, float t, sg_garbage_obj *o);
void sg_garbage_view(const sg_garbage_plan *G, float t, float eye[3], float at[3]);
void sg_garbage_state(sg *s);
void sg_garbage_lights(sg *s);

/* Scene entry points (traces/scene_*.c). */
int sg_scene_city(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_norwich(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_cathedrals(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_forest(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_garbage(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_terrain(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_demo(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_textured(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_bench8(sg *s, const sg_params *p, char *err, size_t errlen);
int sg_scene_bench32(sg *s, const sg_params *p, char *err, size_t errlen);
#endif
