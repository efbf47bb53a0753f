/*
 * The four scenes of Huettner 1999, Table 3.1, as the culling program sees
 * them: objects (a display list, its placement and a world-space box), a
 * camera path, the GL state and lights, and what every method draws first.
 * The geometry is the scene generators' own (traces/scene_*.c through
 * their shared parts in traces/sg.h), compiled into display lists here.
 *
 * Objects are the unit a leaf holds (cull.h): city houses; cathedral shells
 * and bays (column and arch), so that the cathedral the walk is in can be
 * culled in part too; forest trees and the castle; garbage objects, which
 * move, so their boxes are recomputed every frame (cull_scene.dynamic).
 * Small scale (the tests' size): city 36 houses of about 700 triangles,
 * cathedrals 8 x 3,200, forest 14,000, garbage 12,000 triangles.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cull.h"
#include "../sg.h"

static float path_t(const cull_scene *sc, int frame)
{
    return sc->frames > 1 ? (float)frame / (float)(sc->frames - 1) : 0.0f;
}

static int alloc_objs(cull_scene *sc, int n)
{
    sc->objs = calloc((size_t)n, sizeof *sc->objs);
    sc->n_objs = n;
    return sc->objs ? 0 : -1;
}

/* An object at translation t of a list whose model-space bound is lo..hi. */
static void place(cull_scene *sc, cull_obj *o, GLuint list, const float t[3], const float lo[3], const float hi[3])
{
    memset(o, 0, sizeof *o);
    o->list = list;
    o->tris = sg_list_tris(sc->s, list);
    o->scale = 1.0f;
    for (int a = 0; a < 3; a++) {
        o->pre[a] = t[a];
        o->box.lo[a] = lo[a] + t[a];
        o->box.hi[a] = hi[a] + t[a];
    }
}

static void set_camera(cull_camera *cam, const float eye[3], const float at[3], double fovy, double zn, double zf)
{
    memcpy(cam->eye, eye, sizeof cam->eye);
    memcpy(cam->at, at, sizeof cam->at);
    cam->fovy = fovy;
    cam->znear = zn;
    cam->zfar = zf;
}

/* ---- city: 300 furnished houses (1,056,280 triangles) ---- */

typedef struct city_scene { sg_city_plan plan; } city_scene;

/* A house's bound, from scene_city.c's layout: footprint at most 13 x 10 m
 * placed at (-6, -5) and turned by quarter turns, so within 7 m of the lot's
 * centre; at most max_floors + 2 floors of 3 m and a roof of 0.45 x 10 m.
 * The margin keeps geometry strictly inside, so the box's front faces lie in
 * front of it (conservative tests, and VFC's float planes). */
static cull_box lot_box(const sg_city_plan *pl, uint64_t i)
{
    const float m = 0.25f;
    float cx = ((float)(i % (uint64_t)pl->cols) + 0.5f) * SG_CITY_LOT;
    float cz = ((float)(i / (uint64_t)pl->cols) + 0.5f) * SG_CITY_LOT;
    float top = (float)(pl->max_floors + 2) * SG_CITY_FLOOR_H + 4.5f;
    cull_box b = {{cx - 7 - m, -m, cz - 7 - m}, {cx + 7 + m, top + m, cz + 7 + m}};
    return b;
}

/* The house's ground-floor rooms as world boxes (the occluder shadows'
 * occluders, cull_shadow.c): sg_city_lot_transform's translate, quarter
 * turn about y (x' = x cos + z sin, z' = z cos - x sin) and translate,
 * shrunk by 1 mm for the float matrices' rounding. */
static void city_occluders(cull_scene *sc, cull_obj *obj, const sg_city_plan *pl, int v, int turn, const float at[3])
{
    float r[4][4], top = 0;
    int n = sg_city_ground_rooms(pl, sc->seed, v, r, 4, &top);
    obj->top = n > 0 ? top + 0.25f : obj->box.hi[1]; /* lot_box's margin */
    static const float cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const float c = cs[turn & 3][0], s = cs[turn & 3][1];
    for (int k = 0; k < n; k++) {
        float *o = sc->occ[sc->n_occ++];
        float x[2] = {r[k][0] - 6.0f, r[k][2] - 6.0f}, z[2] = {r[k][1] - 5.0f, r[k][3] - 5.0f};
        o[0] = o[2] = 1e30f;
        o[3] = o[5] = -1e30f;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) {
                float wx = x[i] * c + z[j] * s + at[0], wz = z[j] * c - x[i] * s + at[2];
                o[0] = fminf(o[0], wx + 1e-3f), o[3] = fmaxf(o[3], wx - 1e-3f);
                o[2] = fminf(o[2], wz + 1e-3f), o[5] = fmaxf(o[5], wz - 1e-3f);
            }
        o[1] = SG_CITY_ROOM_Y0;
        o[4] = SG_CITY_ROOM_Y1 - 1e-3f;
    }
}

/* The houses of a city plan as objects: scene_city.c's city_run layout. */
static int city_like_setup(cull_scene *sc, uint64_t houses, uint64_t target, int max_floors, const char *name,
                           char *err, size_t errlen)
{
    city_scene *C = calloc(1, sizeof *C);
    if (!(sc->priv = C)) return -1;
    if (sg_city_plan_make(&C->plan, houses, target, max_floors, name, err, errlen) != 0) return -1;
    GLuint base = sg_gen_lists(sc->s, C->plan.variants + 1);
    if (!base || sg_city_compile(sc->s, &C->plan, sc->seed, base, name, err, errlen) != 0) return -1;
    if (alloc_objs(sc, (int)houses) != 0) return -1;
    sc->occ = calloc((size_t)houses * 4, sizeof *sc->occ);
    if (!sc->occ) return -1;
    sg_rng lots;
    sg_rng_seed(&lots, sg_city_lots_seed(sc->seed));
    for (uint64_t i = 0; i < houses; i++) {
        int v, turn;
        sg_city_lot(&lots, &C->plan, i, &v, &turn);
        cull_obj *o = &sc->objs[i];
        o->box = lot_box(&C->plan, i);
        o->list = base + (GLuint)v;
        o->tris = sg_list_tris(sc->s, o->list);
        o->scale = 1.0f;
        /* sg_city_lot_transform's three calls. */
        o->pre[0] = ((float)(i % (uint64_t)C->plan.cols) + 0.5f) * SG_CITY_LOT;
        o->pre[2] = ((float)(i / (uint64_t)C->plan.cols) + 0.5f) * SG_CITY_LOT;
        o->rotate = 1;
        o->angle = 90.0f * (float)turn;
        o->axis[1] = 1.0f;
        o->post[0] = -6.0f;
        o->post[2] = -5.0f;
        city_occluders(sc, o, &C->plan, v, turn, o->pre);
    }
    sc->ground_tris = 2ull * (uint64_t)(C->plan.cols + 2) * (uint64_t)(C->plan.rows + 2);
    return 0;
}

static int city_setup(cull_scene *sc, char *err, size_t errlen)
{
    /* Huettner 1999, Table 3.1: 300 buildings, 1,056,280 triangles. */
    return sc->paper ? city_like_setup(sc, 300, 1056280, 3, "city", err, errlen)
                     : city_like_setup(sc, 36, 36 * 700, 3, "city", err, errlen);
}

/* norwich (scene_city.c): Willmott et al. 2001, sec. 3.1.4, 800 houses of
 * 222,912 polygons, at most 2 floors; the seeds' city (occluder shadows,
 * view-cell PVS).  Small: 64 houses of about 280 triangles. */
static int norwich_setup(cull_scene *sc, char *err, size_t errlen)
{
    return sc->paper ? city_like_setup(sc, 800, 222912, 2, "norwich", err, errlen)
                     : city_like_setup(sc, 64, 64 * 279, 2, "norwich", err, errlen);
}

static void city_state(cull_scene *sc)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glShadeModel(GL_FLAT);
    sg_lighting(sc->s, GL_FRONT);
    glEnable(GL_NORMALIZE);
}

/* A walk down the middle street at eye height, swaying a little. */
static void city_frame(cull_scene *sc, int frame, cull_camera *cam)
{
    const sg_city_plan *pl = &((city_scene *)sc->priv)->plan;
    float t = path_t(sc, frame);
    float street_x = (float)(pl->cols / 2) * SG_CITY_LOT, z_end = (float)pl->rows * SG_CITY_LOT * 0.9f;
    float yaw = 0.35f * sinf(6.2831853f * t * 1.5f);
    float eye[3] = {street_x + 1.5f * sinf(3.0f * t), 1.7f, -4.0f + t * (z_end + 4.0f)};
    float at[3] = {eye[0] + sinf(yaw), eye[1] - 0.1f, eye[2] + cosf(yaw)};
    set_camera(cam, eye, at, 60.0, 0.5, 3000.0);
}

static void city_lights(cull_scene *sc)
{
    const float sun[4] = {0.4f, 1.0f, 0.3f, 0.0f}, sund[4] = {0.85f, 0.8f, 0.7f, 1};
    const float suna[4] = {0.25f, 0.25f, 0.3f, 1};
    const float sky[4] = {-0.5f, 0.6f, -0.7f, 0.0f}, skyd[4] = {0.25f, 0.3f, 0.4f, 1};
    sg_light(sc->s, GL_LIGHT0, sun, sund, suna, NULL);
    sg_light(sc->s, GL_LIGHT1, sky, skyd, NULL, NULL);
}

/* The ground: drawn by every method, first, and the first occluder. */
static void city_ground(cull_scene *sc)
{
    const sg_city_plan *pl = &((city_scene *)sc->priv)->plan;
    glColor3f(0.42f, 0.42f, 0.4f);
    const float go[3] = {-SG_CITY_LOT, 0, -SG_CITY_LOT}, gu[3] = {0, 0, (float)(pl->rows + 2) * SG_CITY_LOT},
                gv[3] = {(float)(pl->cols + 2) * SG_CITY_LOT, 0, 0};
    sg_grid(sc->s, go, gu, gv, pl->rows + 2, pl->cols + 2);
}

/* ---- cathedrals: 2 x 2 x 2 copies of 416,763 triangles ---- */

static int cath_setup(cull_scene *sc, char *err, size_t errlen)
{
    sg_cath_params P;
    if (sg_cath_plan(&P, sc->paper ? 416763 : 3200, err, errlen) != 0) return -1;
    int parts = 1 + 2 * P.cols; /* the shell, then the bays */
    GLuint base = sg_gen_lists(sc->s, (GLsizei)(1 + parts));
    if (!base || sg_cath_compile_column(sc->s, &P, base, err, errlen) != 0) return -1;
    sg_new_list(sc->s, base + 1);
    sg_cath_shell(sc->s, &P);
    sg_end_list(sc->s);
    for (int b = 0; b < 2 * P.cols; b++) {
        sg_new_list(sc->s, base + 2 + (GLuint)b);
        sg_cath_bay(sc->s, &P, base, b < P.cols ? -1 : 1, b % P.cols);
        sg_end_list(sc->s);
    }
    if (alloc_objs(sc, 8 * parts) != 0) return -1;
    for (int k = 0; k < 8; k++) {
        float t[3], lo[3], hi[3];
        sg_cath_copy_offset(k, t);
        for (int part = 0; part < parts; part++) {
            sg_cath_bounds(&P, part - 1, lo, hi);
            place(sc, &sc->objs[k * parts + part], base + 1 + (GLuint)part, t, lo, hi);
        }
    }
    return 0;
}

/* The adapters of a static scene whose generator exports sg_P_state,
 * sg_P_view(t, eye, at), sg_P_lights and SG_PP_FOVY/ZNEAR/ZFAR. */
#define PATH_SCENE(p, P)                                                    \
    static void p##_state(cull_scene *sc) { sg_##p##_state(sc->s); }      \
    static void p##_lights(cull_scene *sc) { sg_##p##_lights(sc->s); }    \
    static void p##_frame(cull_scene *sc, int frame, cull_camera *cam)    \
    {                                                                       \
        float eye[3], at[3];                                                \
        sg_##p##_view(path_t(sc, frame), eye, at);                          \
        set_camera(cam, eye, at, SG_##P##_FOVY, SG_##P##_ZNEAR, SG_##P##_ZFAR); \
    }
PATH_SCENE(cath, CATH)

/* ---- forest: 12 trees of 28,500 triangles before a castle of 110,981 ---- */

static int forest_setup(cull_scene *sc, char *err, size_t errlen)
{
    sg_params p;
    memset(&p, 0, sizeof p);
    p.paper = sc->paper;
    p.target = sc->paper ? 452981 : 14000;
    sg_forest_plan F;
    if (sg_forest_plan_make(&F, &p, err, errlen) != 0) return -1;
    GLuint base = sg_gen_lists(sc->s, 4);
    if (!base || sg_forest_compile(sc->s, &F, sc->seed, base, 0, err, errlen) != 0) return -1;
    float tx[12], tz[12], lo[3], hi[3];
    int tv[12];
    sg_forest_trees(sc->seed, tx, tz, tv);
    if (alloc_objs(sc, 13) != 0) return -1;
    for (int i = 0; i < 12; i++) {
        const float t[3] = {tx[i], 0.0f, tz[i]};
        sg_forest_bounds(0, lo, hi);
        place(sc, &sc->objs[i], base + (GLuint)tv[i], t, lo, hi);
    }
    const float zero[3] = {0, 0, 0};
    sg_forest_bounds(1, lo, hi);
    place(sc, &sc->objs[12], base + 3, zero, lo, hi);
    sc->ground_tris = 2;
    return 0;
}

PATH_SCENE(forest, FOREST)
static void forest_ground(cull_scene *sc) { sg_forest_ground(sc->s); }

/* ---- garbage: 2,500 moving objects, 5,331,146 triangles ---- */

typedef struct garbage_scene { sg_garbage_plan plan; GLuint base; } garbage_scene;

static int garbage_setup(cull_scene *sc, char *err, size_t errlen)
{
    garbage_scene *G = calloc(1, sizeof *G);
    if (!(sc->priv = G)) return -1;
    sg_params p;
    memset(&p, 0, sizeof p);
    p.paper = sc->paper;
    p.target = sc->paper ? 5331146 : 12000;
    if (sg_garbage_plan_make(&G->plan, &p, err, errlen) != 0) return -1;
    G->base = sg_gen_lists(sc->s, 8);
    if (!G->base) return -1;
    sg_garbage_compile(sc->s, &G->plan, G->base);
    return alloc_objs(sc, (int)G->plan.n);
}

static void garbage_state(cull_scene *sc) { sg_garbage_state(sc->s); }

/* The orbit of scenegen's garbage scene (t in frames), and every object's
 * placement this frame: the boxes bound each object's sphere. */
static void garbage_frame(cull_scene *sc, int frame, cull_camera *cam)
{
    garbage_scene *G = sc->priv;
    float eye[3], at[3], t = (float)frame;
    sg_garbage_view(&G->plan, t, eye, at);
    set_camera(cam, eye, at, SG_GARBAGE_FOVY, SG_GARBAGE_ZNEAR, SG_GARBAGE_ZFAR);
    sg_rng r;
    sg_rng_seed(&r, sc->seed * 7919 + 11);
    for (int i = 0; i < sc->n_objs; i++) {
        sg_garbage_obj g;
        sg_garbage_object(&r, &G->plan, (uint64_t)i, t, &g);
        cull_obj *o = &sc->objs[i];
        memset(o, 0, sizeof *o);
        o->list = G->base + (GLuint)g.list;
        o->tris = sg_list_tris(sc->s, o->list);
        memcpy(o->pre, g.pos, sizeof o->pre);
        o->rotate = 1;
        o->angle = g.angle;
        memcpy(o->axis, g.axis, sizeof o->axis);
        o->scale = g.scale;
        o->has_color = 1;
        memcpy(o->color, g.color, sizeof o->color);
        float r0 = SG_GARBAGE_RADIUS * g.scale + 0.05f;
        for (int a = 0; a < 3; a++) {
            o->box.lo[a] = g.pos[a] - r0;
            o->box.hi[a] = g.pos[a] + r0;
        }
    }
}

static void garbage_lights(cull_scene *sc) { sg_garbage_lights(sc->s); }

static const cull_scene_ops scenes[] = {
    {"city", 0, {0.55f, 0.7f, 0.9f}, city_setup, city_state, city_frame, city_lights, city_ground},
    {"norwich", 0, {0.55f, 0.7f, 0.9f}, norwich_setup, city_state, city_frame, city_lights, city_ground},
    {"cathedrals", 0, {0.1f, 0.1f, 0.14f}, cath_setup, cath_state, cath_frame, cath_lights, NULL},
    {"forest", 0, {0.6f, 0.75f, 0.95f}, forest_setup, forest_state, forest_frame, forest_lights, forest_ground},
    {"garbage", 1, {0.15f, 0.15f, 0.15f}, garbage_setup, garbage_state, garbage_frame, garbage_lights, NULL},
};

const cull_scene_ops *cull_scene_find(const char *name)
{
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        if (strcmp(scenes[i].name, name) == 0) return &scenes[i];
    return NULL;
}

void cull_scene_free(cull_scene *sc)
{
    free(sc->objs);
    free(sc->occ);
    free(sc->priv);
    sc->objs = NULL;
    sc->occ = NULL;
    sc->priv = NULL;
}
