/*
 * cullstudy: the culling experiments of Huettner 1999, sec. 3.1, as an
 * ordinary OSMesa program (OSMesaCreateContextExt, OSMesaMakeCurrent and
 * plain gl* calls).  The Makefile builds it against libOSMesa
 * (build/cullstudy-osmesa) and against fragsim's shim (build/cullstudy).
 *
 *   cullstudy [--scene city] [--scale small|paper] [--method dr|vfc|vo|ac|cac|pvs|shadow]
 *             [--test query|hp|brief|stencil] [--hierarchy phbvo|dbvs|sgi]
 *             [--frames N] [--size WxH] [--out DIR] [...]
 *
 * Writes DIR/frame_NNNN.png and DIR/culling.csv (one row per frame) and
 * prints the hierarchy's node and leaf counts.  Geometry comes from the
 * scene generators (traces/scene_city.c through traces/sg.c, compiled with
 * SG_DIRECT_GL), so the houses are the ones scenegen's city trace draws.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cull.h"
#include "../sg.h"

enum { M_DR, M_VFC, M_VO, M_AC, M_CAC, M_PVS, M_SHADOW };
/* --pvs-samples: which views of a view cell its PVS is counted from. */
enum { PVS_BOTH, PVS_PATH, PVS_CELL };

typedef struct opts {
    const char *scene, *scale, *out;
    int method, test, hierarchy, frames, width, height, leaf_objs, sampling;
    int leaf_only;         /* occlusion tests at leaves only (sec. 3.1.9, moving objects) */
    int vfc_select;        /* VFC in GL selection mode (sec. 3.1.6) instead of on the CPU */
    double ac_threshold;   /* eq. 3.3 threshold, in pixels of a 650x650 view plane */
    double p_graphics;     /* eq. 3.4 */
    double test_cost;      /* one occlusion test, in triangles rendered (eq. 3.4's unit here) */
    double cell;           /* pvs: view-cell edge, metres */
    int pvs_samples;
    int cull_map;          /* shadow: cells per side of the cull map (even) */
    uint64_t seed;
} opts;

typedef struct frame_stats {
    uint64_t vfc_tests, occ_tests, vfc_culled, occ_culled, objects, tris;
} frame_stats;

/* View-cell PVS (seed 003): a grid of square cells over the ground plane;
 * vis[c * n_objs + i] says object i was seen from a sample view of cell c. */
typedef struct pvs_grid {
    float x0, z0;
    int nx, nz;
    unsigned char *vis, *sampled;
    uint64_t views, queries, cells;
} pvs_grid;

typedef struct study {
    opts o;
    sg s;
    const cull_scene_ops *ops;
    cull_scene sc;
    cull_tree tree;
    cull_view view;
    double prev_render;    /* eq. 3.4's T_render: triangles of the previous frame */
    frame_stats st;
    pvs_grid pvs;
    cull_shadow shadow;
} study;

static int usage(const char *msg)
{
    if (msg) fprintf(stderr, "cullstudy: %s\n", msg);
    fprintf(stderr, "usage: cullstudy [--scene city|norwich|cathedrals|forest|garbage] [--scale small|paper]\n"
                    "  [--method dr|vfc|vo|ac|cac|pvs|shadow] [--cell METRES] [--pvs-samples both|path|cell]\n  [--cull-map N] [--test query|hp|brief|stencil] [--hierarchy phbvo|dbvs|sgi]\n"
                    "  [--frames N] [--size WxH] [--out DIR] [--leaf N] [--leaf-only] [--sampling N]\n"
                    "  [--ac-threshold PIXELS] [--test-cost TRIANGLES] [--vfc-select]\n");
    return 2;
}

static int pick(const char *v, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(v, names[i]) == 0) return i;
    return -1;
}

static int parse_int(const char *v, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long x = strtol(v, &end, 10);
    if (errno || *end || x < lo || x > hi) return -1;
    *out = (int)x;
    return 0;
}

static int parse_opt(opts *o, const char *k, const char *v)
{
    static const char *const methods[] = {"dr", "vfc", "vo", "ac", "cac", "pvs", "shadow"};
    static const char *const samples[] = {"both", "path", "cell"};
    static const char *const tests[] = {"query", "hp", "brief", "stencil"};
    static const char *const trees[] = {"dbvs", "phbvo", "sgi"};
    char *end;
    if (!strcmp(k, "--scene")) o->scene = v;
    else if (!strcmp(k, "--scale")) o->scale = v;
    else if (!strcmp(k, "--out")) o->out = v;
    else if (!strcmp(k, "--method")) return (o->method = pick(v, methods, 7)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--pvs-samples")) return (o->pvs_samples = pick(v, samples, 3)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--test")) return (o->test = pick(v, tests, 4)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--hierarchy")) return (o->hierarchy = pick(v, trees, 3)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--frames")) return parse_int(v, 1, 100000, &o->frames);
    else if (!strcmp(k, "--leaf")) return parse_int(v, 1, 1 << 20, &o->leaf_objs);
    else if (!strcmp(k, "--sampling")) return parse_int(v, 1, 1 << 12, &o->sampling);
    else if (!strcmp(k, "--cull-map")) return parse_int(v, 2, 4096, &o->cull_map) || o->cull_map % 2 ? -1 : 0;
    else if (!strcmp(k, "--size")) {
        if (sscanf(v, "%dx%d", &o->width, &o->height) != 2 || o->width < 1 || o->height < 1 ||
            o->width > 4096 || o->height > 4096)
            return -1;
    } else if (!strcmp(k, "--ac-threshold")) {
        o->ac_threshold = strtod(v, &end);
        return *end || o->ac_threshold < 0 ? -1 : 0;
    } else if (!strcmp(k, "--cell")) {
        o->cell = strtod(v, &end);
        return *end || !(o->cell >= 0.5 && o->cell <= 1e5) ? -1 : 0;
    } else if (!strcmp(k, "--test-cost")) {
        o->test_cost = strtod(v, &end);
        return *end || o->test_cost < 0 ? -1 : 0;
    } else return -2;
    return 0;
}

static int parse_args(opts *o, int argc, char **argv)
{
    /* Designated: the positional list this was gave vfc_select 100.0,
     * ac_threshold 1/3, p_graphics 100, test_cost 1 and seed 0. */
    *o = (opts){.scene = "city", .scale = "small", .out = "out/cullstudy", .method = M_VO, .test = CULL_TEST_QUERY,
                .hierarchy = CULL_PHBVO, .frames = 100, .width = 650, .height = 650, .leaf_objs = 1, .sampling = 1,
                .leaf_only = -1, .ac_threshold = 100.0, .p_graphics = 1.0 / 3.0, .test_cost = 100.0, .seed = 1,
                .cell = SG_CITY_LOT, .pvs_samples = PVS_BOTH, .cull_map = 256};
    for (int i = 1; i < argc; i += 2) {
        if (!strcmp(argv[i], "--leaf-only")) {
            o->leaf_only = 1;
            i--;
            continue;
        }
        if (!strcmp(argv[i], "--vfc-select")) {
            o->vfc_select = 1;
            i--;
            continue;
        }
        if (i + 1 >= argc) return usage("an option without its value");
        int rc = parse_opt(o, argv[i], argv[i + 1]);
        if (rc == -2) {
            fprintf(stderr, "cullstudy: unknown option %s\n", argv[i]);
            return usage(NULL);
        }
        if (rc != 0) {
            fprintf(stderr, "cullstudy: bad value for %s: %s\n", argv[i], argv[i + 1]);
            return usage(NULL);
        }
    }
    if (!cull_scene_find(o->scene)) {
        fprintf(stderr, "cullstudy: --scene %s: the scenes are city, norwich, cathedrals, forest and garbage\n", o->scene);
        return 2;
    }
    if (strcmp(o->scale, "small") != 0 && strcmp(o->scale, "paper") != 0)
        return usage("--scale is small or paper");
    return 0;
}

/* ---- camera ---- */

static void mat_mul(const float a[16], const float b[16], float r[16])
{
    for (int c = 0; c < 4; c++)
        for (int i = 0; i < 4; i++) {
            float x = 0;
            for (int k = 0; k < 4; k++) x += a[4 * k + i] * b[4 * c + k];
            r[4 * c + i] = x;
        }
}

/* gluPerspective's and gluLookAt's matrices (GLU 1.3, 4.1 and 4.2) of the
 * scene's camera, and the view VFC tests against. */
static void camera(study *S, const cull_camera *cam, float proj[16], float mv[16])
{
    const float *eye = cam->eye, up[3] = {0, 1, 0};
    float f[3] = {cam->at[0] - eye[0], cam->at[1] - eye[1], cam->at[2] - eye[2]};
    float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int a = 0; a < 3; a++) f[a] /= fl;
    float s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
    float sl = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int a = 0; a < 3; a++) s[a] /= sl;
    float u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    float m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1};
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    memcpy(mv, m, sizeof m);
    float zn = (float)cam->znear, zf = (float)cam->zfar;
    float cot = 1.0f / tanf((float)cam->fovy * 0.5f * 3.14159265f / 180.0f);
    float aspect = (float)S->o.width / (float)S->o.height;
    float p[16] = {cot / aspect, 0, 0, 0, 0, cot, 0, 0, 0, 0, (zf + zn) / (zn - zf), -1, 0, 0, 2 * zf * zn / (zn - zf), 0};
    memcpy(proj, p, sizeof p);
    cull_view *v = &S->view;
    mat_mul(p, m, v->mvp);
    cull_view_planes(v);
    memcpy(v->eye, eye, sizeof v->eye);
    memcpy(v->dir, f, sizeof f);
    v->znear = zn;
    v->width = S->o.width;
    v->height = S->o.height;
}

/* ---- drawing ---- */

static void draw_obj(study *S, const cull_obj *o)
{
    glPushMatrix();
    glTranslatef(o->pre[0], o->pre[1], o->pre[2]);
    if (o->rotate) glRotatef(o->angle, o->axis[0], o->axis[1], o->axis[2]);
    if (o->post[0] != 0 || o->post[1] != 0 || o->post[2] != 0) glTranslatef(o->post[0], o->post[1], o->post[2]);
    if (o->scale != 1.0f) glScalef(o->scale, o->scale, o->scale);
    if (o->has_color) glColor3fv(o->color);
    sg_call_list(&S->s, o->list);
    glPopMatrix();
    S->st.objects++;
    S->st.tris += o->tris;
}

static void draw_leaf(study *S, const cull_node *n)
{
    for (int k = 0; k < n->n_objs; k++) draw_obj(S, &S->sc.objs[S->tree.obj_index[n->first_obj + k]]);
}

static int is_leaf(const cull_node *n) { return n->n_children == 0; }

/* VFC only (sec. 3.1.6): depth-first; a node entirely inside passes its
 * subtree without further tests. */
/* The VFC test of a node (counted), skipped below a node entirely inside:
 * 0 culled, 1 intersecting, 2 inside. */
static int node_vfc(study *S, const cull_node *n, int parent_inside)
{
    if (parent_inside) return 2;
    S->st.vfc_tests++;
    int r = cull_frustum_test(&S->view, &n->box);
    /* In selection mode GL decides "intersects"; "entirely inside" (which
     * passes the subtree untested) stays the CPU's corner test.  A box the
     * eye is in or reaching in front of the near plane may contain the
     * whole volume and then has no face in it (sec. 3.1.6): not asked. */
    if (S->o.vfc_select && r == 1 && cull_box_zmin(&S->view, &n->box) > S->view.znear &&
        !cull_box_contains(&n->box, S->view.eye))
        r = cull_select_test(&n->box);
    if (r == 0) S->st.vfc_culled++;
    return r;
}

static void vfc_walk(study *S, int id, int inside)
{
    const cull_node *n = &S->tree.node[id];
    int r = node_vfc(S, n, inside);
    if (r == 0) return;
    if (is_leaf(n)) draw_leaf(S, n);
    for (int k = 0; k < n->n_children; k++) vfc_walk(S, S->tree.child[n->first_child + k], r == 2);
}

/* The DepthHeap (sec. 3.1.8): nodes that passed VFC, nearest z_min first. */
typedef struct heap_item { float key; int node, inside; } heap_item;
typedef struct heap { heap_item *a; int n; } heap;

static void heap_push(heap *h, heap_item it)
{
    int i = h->n++;
    while (i > 0 && h->a[(i - 1) / 2].key > it.key) {
        h->a[i] = h->a[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->a[i] = it;
}

static heap_item heap_pop(heap *h)
{
    heap_item top = h->a[0], last = h->a[--h->n];
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->a[c + 1].key < h->a[c].key) c++;
        if (h->a[c].key >= last.key) break;
        h->a[i] = h->a[c];
        i = c;
    }
    if (h->n > 0) h->a[i] = last;
    return top;
}

/* Adds a node after its VFC test. */
static void heap_offer(study *S, heap *h, int id, int parent_inside)
{
    const cull_node *n = &S->tree.node[id];
    int r = node_vfc(S, n, parent_inside);
    if (r == 0) return;
    heap_push(h, (heap_item){cull_box_zmin(&S->view, &n->box), id, r == 2});
}

/* Eq. 3.3 with SizeOf2DBoundingBox the node's visible samples, Dist(Eye)
 * the near-plane distance and Dist(Obj) the box's distance beyond it; the
 * threshold is given for the dissertation's 650 x 650 view plane (footnote 4:
 * 100) and scaled to this one. */
static int adaptive_culls(const study *S, uint64_t samples, float zmin)
{
    double plane = (double)S->o.width * S->o.height;
    double de = S->view.znear, dobj = zmin > de ? zmin - de : 0;
    double adap = (double)samples / plane * (de + dobj) / de;
    return adap < S->o.ac_threshold / (650.0 * 650.0);
}

/* V+O, AC and CAC (sec. 3.1.8's refined algorithm): VFC and occlusion tests
 * interleaved over the DepthHeap, every node (leaves too) tested before its
 * contents are drawn.  A box the eye is in, or that reaches in front of the
 * near plane, is taken as visible untested (sec. 3.1.6: its faces could be
 * clipped away). */
static void occlusion_walk(study *S)
{
    heap h = {malloc((size_t)S->tree.n_nodes * sizeof(heap_item)), 0};
    if (!h.a) return;
    double budget = S->o.method == M_CAC ? S->prev_render * S->o.p_graphics : -1, used = 0;
    heap_offer(S, &h, 0, 0);
    while (h.n > 0) {
        heap_item it = heap_pop(&h);
        const cull_node *n = &S->tree.node[it.node];
        int testable = it.key > S->view.znear && !cull_box_contains(&n->box, S->view.eye);
        if (S->o.leaf_only && !is_leaf(n)) testable = 0; /* sec. 3.1.9: inner nodes bound moving objects loosely */
        if (budget >= 0 && used >= budget) testable = 0; /* eq. 3.4: budget spent, VFC only */
        if (testable) {
            S->st.occ_tests++;
            used += S->o.test_cost;
            uint64_t samples = cull_occlusion_test(S->o.test, &S->view, &n->box, S->o.sampling);
            if (samples == 0 || (S->o.method == M_AC && adaptive_culls(S, samples, it.key))) {
                S->st.occ_culled++;
                continue;
            }
        }
        if (is_leaf(n)) draw_leaf(S, n);
        for (int k = 0; k < n->n_children; k++) heap_offer(S, &h, S->tree.child[n->first_child + k], it.inside);
    }
    free(h.a);
}

/* Clears and sets up the view of cam: matrices, lights, the ground. */
static void begin_view(study *S, const cull_camera *cam)
{
    float proj[16], mv[16];
    camera(S, cam, proj, mv);
    glClearColor(S->ops->clear[0], S->ops->clear[1], S->ops->clear[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(mv);
    S->ops->lights(&S->sc); /* after the view, so that they stay fixed in the world */
    if (S->ops->ground) {
        S->ops->ground(&S->sc);
        S->st.tris += S->sc.ground_tris;
    }
}

/* ---- view-cell PVS (seed 003: per-object pixel counts from sample views
 * of a cell; counted with NOHC, GL_SAMPLES_PASSED, not an item buffer) ---- */

static int pvs_cell_of(const pvs_grid *g, double cell, const float eye[3])
{
    int cx = (int)floor((eye[0] - g->x0) / cell), cz = (int)floor((eye[2] - g->z0) / cell);
    cx = cx < 0 ? 0 : cx >= g->nx ? g->nx - 1 : cx; /* the border cells reach out to infinity */
    cz = cz < 0 ? 0 : cz >= g->nz ? g->nz - 1 : cz;
    return cz * g->nx + cx;
}

/* One sample view: the whole scene as DR draws it, then each object not yet
 * in the cell's PVS again with GL_EQUAL inside a GL_SAMPLES_PASSED query.
 * Redrawing the same geometry with the same state gives the same depths
 * (GL 1.5 Appendix A, rule 1: invariance), so the count is the object's
 * pixels in the final depth buffer, ties included.  An object with none
 * covers no pixel of DR's image of this view: every pixel's colour comes
 * from the first object in draw order reaching the pixel's final depth
 * (GL_LESS), and that object counts there. */
static void pvs_sample(study *S, const cull_camera *cam, unsigned char *vis, GLuint q)
{
    begin_view(S, cam);
    for (int i = 0; i < S->sc.n_objs; i++) draw_obj(S, &S->sc.objs[i]);
    glPushAttrib(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_EQUAL);
    for (int i = 0; i < S->sc.n_objs; i++) {
        if (vis[i]) continue;
        GLuint samples = 0;
        glBeginQuery(GL_SAMPLES_PASSED, q);
        draw_obj(S, &S->sc.objs[i]);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
        vis[i] = samples > 0;
        S->pvs.queries++;
    }
    glPopAttrib();
    S->pvs.views++;
}

/* Cell c's panorama views: from its four corners and centre at eye height
 * y, four quarter turns of fovy 90 (with the view's aspect >= 1 they cover
 * the full circle and +-45 degrees, the walk's 60-degree view included). */
static void pvs_sample_cell(study *S, int c, float y, const cull_camera *like, GLuint q)
{
    pvs_grid *g = &S->pvs;
    float cell = (float)S->o.cell, x = g->x0 + (float)(c % g->nx) * cell, z = g->z0 + (float)(c / g->nx) * cell;
    static const float px[5] = {0, 1, 0, 1, 0.5f}, pz[5] = {0, 0, 1, 1, 0.5f};
    for (int p = 0; p < 5; p++)
        for (int d = 0; d < 4; d++) {
            cull_camera cam = *like;
            float yaw = 1.5707963f * (float)d;
            cam.eye[0] = x + px[p] * cell;
            cam.eye[1] = y;
            cam.eye[2] = z + pz[p] * cell;
            cam.at[0] = cam.eye[0] + sinf(yaw);
            cam.at[1] = y;
            cam.at[2] = cam.eye[2] + cosf(yaw);
            cam.fovy = 90.0;
            pvs_sample(S, &cam, g->vis + (size_t)c * (size_t)S->sc.n_objs, q);
        }
}

/* Precomputes the PVS of every cell the path's eye enters (static scenes).
 * The samples: the path's own views in the cell (--pvs-samples path: then
 * the culled images equal DR's by construction, the above), the cell's
 * panoramas (cell: a from-region PVS in the seed's sense, which can miss
 * what only points between the samples see), or both (the default). */
static int pvs_build(study *S)
{
    pvs_grid *g = &S->pvs;
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    for (int i = 0; i < S->sc.n_objs; i++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fminf(lo[a], S->sc.objs[i].box.lo[2 * a]);
            hi[a] = fmaxf(hi[a], S->sc.objs[i].box.hi[2 * a]);
        }
    g->x0 = lo[0];
    g->z0 = lo[1];
    g->nx = (int)ceil((hi[0] - lo[0]) / S->o.cell);
    g->nz = (int)ceil((hi[1] - lo[1]) / S->o.cell);
    g->nx = g->nx < 1 ? 1 : g->nx;
    g->nz = g->nz < 1 ? 1 : g->nz;
    size_t cells = (size_t)g->nx * (size_t)g->nz;
    g->vis = calloc(cells * (size_t)S->sc.n_objs + 1, 1);
    g->sampled = calloc(cells, 1);
    if (!g->vis || !g->sampled) return -1;
    GLuint q;
    glGenQueries(1, &q);
    for (int f = 0; f < S->o.frames; f++) {
        cull_camera cam;
        S->ops->frame(&S->sc, f, &cam);
        int c = pvs_cell_of(g, S->o.cell, cam.eye);
        if (S->o.pvs_samples != PVS_CELL) pvs_sample(S, &cam, g->vis + (size_t)c * (size_t)S->sc.n_objs, q);
        if (!g->sampled[c]) {
            g->sampled[c] = 1;
            g->cells++;
            if (S->o.pvs_samples != PVS_PATH) pvs_sample_cell(S, c, cam.eye[1], &cam, q);
        }
    }
    glDeleteQueries(1, &q);
    glFinish(); /* the precomputation is a frame of its own in a capture (the study's frame -1) */
    uint64_t in_pvs = 0;
    for (size_t c = 0; c < cells; c++)
        for (int i = 0; g->sampled[c] && i < S->sc.n_objs; i++) in_pvs += g->vis[c * (size_t)S->sc.n_objs + i];
    printf("pvs: %d x %d cells of %.1f m, %llu sampled, %llu sample views, %llu queries, %.1f objects per PVS\n",
           g->nx, g->nz, S->o.cell, (unsigned long long)g->cells, (unsigned long long)g->views,
           (unsigned long long)g->queries, g->cells ? (double)in_pvs / (double)g->cells : 0.0);
    return 0;
}

/* The PVS of the eye's cell, then VFC on the CPU for the objects in it. */
static void pvs_draw(study *S)
{
    const unsigned char *vis = S->pvs.vis + (size_t)pvs_cell_of(&S->pvs, S->o.cell, S->view.eye) * (size_t)S->sc.n_objs;
    for (int i = 0; i < S->sc.n_objs; i++) {
        if (!vis[i]) {
            S->st.occ_culled++;
            continue;
        }
        S->st.vfc_tests++;
        if (cull_frustum_test(&S->view, &S->sc.objs[i].box) == 0) {
            S->st.vfc_culled++;
            continue;
        }
        draw_obj(S, &S->sc.objs[i]);
    }
}

/* Occluder shadows (cull_shadow.c): the cull map from this frame's eye,
 * then per object VFC and the map's test. */
static void shadow_draw(study *S)
{
    for (int i = 0; i < S->sc.n_objs; i++) {
        const cull_box *b = &S->sc.objs[i].box;
        S->st.vfc_tests++;
        if (cull_frustum_test(&S->view, b) == 0) {
            S->st.vfc_culled++;
            continue;
        }
        S->st.occ_tests++;
        cull_box tight = *b; /* the house's own height, not the tallest house's (lot_box) */
        tight.hi[1] = S->sc.objs[i].top;
        if (!cull_box_contains(b, S->view.eye) && cull_shadow_hidden(&S->shadow, &tight)) {
            S->st.occ_culled++;
            continue;
        }
        draw_obj(S, &S->sc.objs[i]);
    }
}

static int draw_frame(study *S, int frame)
{
    cull_camera cam;
    S->ops->frame(&S->sc, frame, &cam);
    if (S->ops->dynamic && S->o.method != M_DR) { /* the objects moved: a new hierarchy over them */
        cull_tree_free(&S->tree);
        if (cull_tree_build(&S->tree, S->o.hierarchy, S->sc.objs, S->sc.n_objs, S->o.leaf_objs) != 0) return -1;
    }
    memset(&S->st, 0, sizeof S->st);
    if (S->o.method == M_SHADOW) /* before the frame's clear: it draws into the same buffer */
        cull_shadow_render(&S->shadow, (const float (*)[6])S->sc.occ, S->sc.n_occ, cam.eye);
    begin_view(S, &cam);
    if (S->o.method == M_DR)
        for (int i = 0; i < S->sc.n_objs; i++) draw_obj(S, &S->sc.objs[i]);
    else if (S->o.method == M_VFC)
        vfc_walk(S, 0, 0);
    else if (S->o.method == M_PVS)
        pvs_draw(S);
    else if (S->o.method == M_SHADOW)
        shadow_draw(S);
    else
        occlusion_walk(S);
    glFinish();
    S->prev_render = (double)S->st.tris;
    return 0;
}

static int write_frame(const study *S, const unsigned char *buf, int frame)
{
    int w = S->o.width, h = S->o.height;
    unsigned char *top = malloc((size_t)w * h * 4);
    if (!top) return -1;
    for (int y = 0; y < h; y++) /* OSMesa's buffer: bottom row first */
        memcpy(top + (size_t)y * w * 4, buf + (size_t)(h - 1 - y) * w * 4, (size_t)w * 4);
    char path[4096];
    snprintf(path, sizeof path, "%s/frame_%04d.png", S->o.out, frame);
    int rc = cull_write_png(path, top, w, h);
    free(top);
    if (rc) fprintf(stderr, "cullstudy: cannot write %s\n", path);
    return rc;
}

/* mkdir -p: each prefix of the path, then the path. */
static void make_dirs(const char *path)
{
    char p[4096];
    snprintf(p, sizeof p, "%s", path);
    for (char *q = p + 1; *q; q++)
        if (*q == '/') {
            *q = 0;
            mkdir(p, 0777);
            *q = '/';
        }
    mkdir(p, 0777);
}

static int run(study *S, unsigned char *buf, FILE *csv)
{
    static const char *const mnames[] = {"dr", "vfc", "vo", "ac", "cac", "pvs", "shadow"};
    static const char *const tnames[] = {"query", "hp", "brief", "stencil"};
    S->prev_render = 0;
    for (int i = 0; i < S->sc.n_objs; i++) S->prev_render += (double)S->sc.objs[i].tris; /* frame -1: DR */
    /* cycles: the shim runs the functional model only; cycles come from
     * replaying a FRAGSIM_TRACE capture with fragsim replay --mode cycle. */
    fprintf(csv, "frame,method,test,vfc_tests,vfc_culled,occ_tests,occ_culled,objects_rendered,"
                 "objects_culled,triangles_rendered,cycles\n");
    for (int f = 0; f < S->o.frames; f++) {
        if (draw_frame(S, f) != 0) {
            fprintf(stderr, "cullstudy: out of memory\n");
            return 1;
        }
        fprintf(csv, "%d,%s,%s,%llu,%llu,%llu,%llu,%llu,%llu,%llu,\n", f, mnames[S->o.method],
                S->o.method >= M_VO && S->o.method <= M_CAC ? tnames[S->o.test]
                : S->o.method == M_PVS                      ? "query"
                : S->o.method == M_SHADOW                   ? "cullmap"
                                                            : "", (unsigned long long)S->st.vfc_tests,
                (unsigned long long)S->st.vfc_culled, (unsigned long long)S->st.occ_tests,
                (unsigned long long)S->st.occ_culled, (unsigned long long)S->st.objects,
                (unsigned long long)((uint64_t)S->sc.n_objs - S->st.objects), (unsigned long long)S->st.tris);
        if (write_frame(S, buf, f)) return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    study S;
    memset(&S, 0, sizeof S);
    int rc = parse_args(&S.o, argc, argv);
    if (rc) return rc;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc((size_t)S.o.width * S.o.height * 4);
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, S.o.width, S.o.height)) {
        fprintf(stderr, "cullstudy: no OSMesa context\n");
        return 1;
    }
    const char *why = S.o.method >= M_VO && S.o.method != M_SHADOW
                          ? cull_test_unavailable(S.o.method == M_PVS ? CULL_TEST_QUERY : S.o.test)
                          : NULL;
    if (why) {
        fprintf(stderr, "cullstudy: %s\n", why);
        return 2;
    }
    /* The emitter's context pointer only says "send" here (sg.h, SG_DIRECT_GL). */
    static char live;
    sg_init(&S.s, (fs_context *)(void *)&live);
    char err[256] = "";
    S.ops = cull_scene_find(S.o.scene);
    S.sc.s = &S.s;
    S.sc.paper = !strcmp(S.o.scale, "paper");
    S.sc.frames = S.o.frames;
    S.sc.seed = S.o.seed;
    if (S.o.leaf_only < 0) S.o.leaf_only = S.ops->dynamic;
    S.ops->state(&S.sc);
    if (S.ops->setup(&S.sc, err, sizeof err) != 0) {
        fprintf(stderr, "cullstudy: %s\n", err[0] ? err : "out of memory");
        return 1;
    }
    if (S.ops->dynamic) { /* the hierarchy of frame 0's placement (rebuilt every frame) */
        cull_camera cam;
        S.ops->frame(&S.sc, 0, &cam);
    }
    if (cull_tree_build(&S.tree, S.o.hierarchy, S.sc.objs, S.sc.n_objs, S.o.leaf_objs) != 0) {
        fprintf(stderr, "cullstudy: out of memory\n");
        return 1;
    }
    if (S.o.method == M_PVS) {
        if (S.ops->dynamic) {
            fprintf(stderr, "cullstudy: --method pvs needs a static scene (%s moves)\n", S.o.scene);
            return 2;
        }
        if (pvs_build(&S) != 0) {
            fprintf(stderr, "cullstudy: out of memory\n");
            return 1;
        }
    }
    if (S.o.method == M_SHADOW) {
        int res = S.o.cull_map;
        if (!S.sc.occ || S.sc.n_occ == 0) {
            fprintf(stderr, "cullstudy: --method shadow: %s has no occluders (city and norwich do)\n", S.o.scene);
            return 2;
        }
        if (res > S.o.width || res > S.o.height) {
            fprintf(stderr, "cullstudy: --cull-map %d is larger than the %dx%d buffer it is drawn in\n", res,
                    S.o.width, S.o.height);
            return 2;
        }
        if (cull_shadow_init(&S.shadow, S.sc.objs, S.sc.n_objs, res) != 0) {
            fprintf(stderr, "cullstudy: out of memory\n");
            return 1;
        }
        printf("shadow: %d x %d cull map of %.2f m cells, %d occluders\n", res, res, S.shadow.cell, S.sc.n_occ);
    }
    printf("scene %s (%s): hierarchy %s: %d nodes, %d leaves, %d objects%s\n", S.o.scene, S.o.scale,
           cull_tree_name(S.o.hierarchy), S.tree.n_nodes, S.tree.n_leaves, S.sc.n_objs,
           S.o.leaf_only ? "; occlusion tests at leaves only" : "");
    make_dirs(S.o.out);
    char path[4096];
    snprintf(path, sizeof path, "%s/culling.csv", S.o.out);
    FILE *csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "cullstudy: cannot write %s\n", path);
        return 1;
    }
    rc = run(&S, buf, csv);
    if (fclose(csv) != 0) rc = 1;
    cull_tree_free(&S.tree);
    free(S.pvs.vis);
    free(S.pvs.sampled);
    cull_shadow_free(&S.shadow);
    cull_scene_free(&S.sc);
    sg_free(&S.s);
    OSMesaDestroyContext(ctx);
    free(buf);
    return rc;
}
