/*
 * cullstudy: the culling experiments of Huettner 1999, sec. 3.1, as an
 * ordinary OSMesa program (OSMesaCreateContextExt, OSMesaMakeCurrent and
 * plain gl* calls).  The Makefile builds it against libOSMesa
 * (build/cullstudy-osmesa) and against fragsim's shim (build/cullstudy).
 *
 *   cullstudy [--scene city] [--scale small|paper] [--method dr|vfc|vo|ac|cac]
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

enum { M_DR, M_VFC, M_VO, M_AC, M_CAC };

typedef struct opts {
    const char *scene, *scale, *out;
    int method, test, hierarchy, frames, width, height, leaf_objs, sampling;
    double ac_threshold;   /* eq. 3.3 threshold, in pixels of a 650x650 view plane */
    double p_graphics;     /* eq. 3.4 */
    double test_cost;      /* one occlusion test, in triangles rendered (eq. 3.4's unit here) */
    uint64_t seed;
} opts;

typedef struct frame_stats {
    uint64_t vfc_tests, occ_tests, vfc_culled, occ_culled, objects, tris;
} frame_stats;

typedef struct study {
    opts o;
    sg s;
    sg_city_plan plan;
    cull_obj *objs;
    int n_objs;
    cull_tree tree;
    cull_view view;
    uint64_t ground_tris;
    double prev_render;    /* eq. 3.4's T_render: triangles of the previous frame */
    frame_stats st;
} study;

static int usage(const char *msg)
{
    if (msg) fprintf(stderr, "cullstudy: %s\n", msg);
    fprintf(stderr, "usage: cullstudy [--scene city] [--scale small|paper] [--method dr|vfc|vo|ac|cac]\n"
                    "  [--test query|hp|brief|stencil] [--hierarchy phbvo|dbvs|sgi] [--frames N]\n"
                    "  [--size WxH] [--out DIR] [--leaf N] [--sampling N] [--ac-threshold PIXELS]\n"
                    "  [--test-cost TRIANGLES] [--vfc-select]\n");
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
    static const char *const methods[] = {"dr", "vfc", "vo", "ac", "cac"};
    static const char *const tests[] = {"query", "hp", "brief", "stencil"};
    static const char *const trees[] = {"dbvs", "phbvo", "sgi"};
    char *end;
    if (!strcmp(k, "--scene")) o->scene = v;
    else if (!strcmp(k, "--scale")) o->scale = v;
    else if (!strcmp(k, "--out")) o->out = v;
    else if (!strcmp(k, "--method")) return (o->method = pick(v, methods, 5)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--test")) return (o->test = pick(v, tests, 4)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--hierarchy")) return (o->hierarchy = pick(v, trees, 3)) < 0 ? -1 : 0;
    else if (!strcmp(k, "--frames")) return parse_int(v, 1, 100000, &o->frames);
    else if (!strcmp(k, "--leaf")) return parse_int(v, 1, 1 << 20, &o->leaf_objs);
    else if (!strcmp(k, "--sampling")) return parse_int(v, 1, 1 << 12, &o->sampling);
    else if (!strcmp(k, "--size")) {
        if (sscanf(v, "%dx%d", &o->width, &o->height) != 2 || o->width < 1 || o->height < 1 ||
            o->width > 4096 || o->height > 4096)
            return -1;
    } else if (!strcmp(k, "--ac-threshold")) {
        o->ac_threshold = strtod(v, &end);
        return *end || o->ac_threshold < 0 ? -1 : 0;
    } else if (!strcmp(k, "--test-cost")) {
        o->test_cost = strtod(v, &end);
        return *end || o->test_cost < 0 ? -1 : 0;
    } else return -2;
    return 0;
}

static int parse_args(opts *o, int argc, char **argv)
{
    *o = (opts){"city", "small", "out/cullstudy", M_VO, CULL_TEST_QUERY, CULL_PHBVO, 100, 650, 650, 1, 1,
                100.0, 1.0 / 3.0, 100.0, 1};
    for (int i = 1; i < argc; i += 2) {
        if (!strcmp(argv[i], "--vfc-select")) {
            /* TODO(issue 21, item 3): VFC through GL selection mode, as the
             * dissertation does it (sec. 3.1.6), once GL_SELECT is in the
             * model (GL 1.5 issue 19). */
            fprintf(stderr, "cullstudy: --vfc-select (VFC in GL selection mode): not yet; "
                            "--method vfc culls on the CPU\n");
            return 2;
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
    if (strcmp(o->scene, "city") != 0) {
        fprintf(stderr, "cullstudy: --scene %s: only city so far (cathedrals, forest, garbage: not yet)\n",
                o->scene);
        return 2;
    }
    if (strcmp(o->scale, "small") != 0 && strcmp(o->scale, "paper") != 0)
        return usage("--scale is small or paper");
    return 0;
}

/* ---- the city (Huettner 1999, Table 3.1: 300 houses, 1,056,280 triangles) ---- */

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

static int city_setup(study *S, char *err, size_t errlen)
{
    int paper = !strcmp(S->o.scale, "paper");
    uint64_t houses = paper ? 300 : 36;
    uint64_t target = paper ? 1056280 : 36 * 700;
    if (sg_city_plan_make(&S->plan, houses, target, 3, "city", err, errlen) != 0) return -1;
    GLuint base = sg_gen_lists(&S->s, S->plan.variants + 1);
    if (!base || sg_city_compile(&S->s, &S->plan, S->o.seed, base, "city", err, errlen) != 0) return -1;
    S->n_objs = (int)houses;
    S->objs = calloc(houses, sizeof *S->objs);
    if (!S->objs) return -1;
    sg_rng lots;
    sg_rng_seed(&lots, sg_city_lots_seed(S->o.seed));
    for (uint64_t i = 0; i < houses; i++) {
        int v, turn;
        sg_city_lot(&lots, &S->plan, i, &v, &turn);
        cull_obj *o = &S->objs[i];
        o->box = lot_box(&S->plan, i);
        o->list = base + (GLuint)v;
        o->tris = sg_list_tris(&S->s, o->list);
        o->lot = i;
        o->turn = turn;
    }
    S->ground_tris = 2ull * (uint64_t)(S->plan.cols + 2) * (uint64_t)(S->plan.rows + 2);
    return 0;
}

/* ---- camera: a walk down the middle street, as scenegen's city ---- */

static void mat_mul(const float a[16], const float b[16], float r[16])
{
    for (int c = 0; c < 4; c++)
        for (int i = 0; i < 4; i++) {
            float x = 0;
            for (int k = 0; k < 4; k++) x += a[4 * k + i] * b[4 * c + k];
            r[4 * c + i] = x;
        }
}

/* gluPerspective's and gluLookAt's matrices (GLU 1.3, 4.1 and 4.2). */
static void camera(study *S, int frame, float proj[16], float mv[16])
{
    const sg_city_plan *pl = &S->plan;
    float t = S->o.frames > 1 ? (float)frame / (float)(S->o.frames - 1) : 0.0f;
    float street_x = (float)(pl->cols / 2) * SG_CITY_LOT, z_end = (float)pl->rows * SG_CITY_LOT * 0.9f;
    float yaw = 0.35f * sinf(6.2831853f * t * 1.5f);
    float eye[3] = {street_x + 1.5f * sinf(3.0f * t), 1.7f, -4.0f + t * (z_end + 4.0f)};
    float f[3] = {sinf(yaw), -0.1f, cosf(yaw)}, up[3] = {0, 1, 0};
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
    float zn = 0.5f, zf = 3000.0f, cot = 1.0f / tanf(30.0f * 3.14159265f / 180.0f);
    float aspect = (float)S->o.width / (float)S->o.height;
    float p[16] = {cot / aspect, 0, 0, 0, 0, cot, 0, 0, 0, 0, (zf + zn) / (zn - zf), -1, 0, 0, 2 * zf * zn / (zn - zf), 0};
    memcpy(proj, p, sizeof p);
    cull_view *v = &S->view;
    mat_mul(p, m, v->mvp);
    cull_view_planes(v);
    memcpy(v->eye, eye, sizeof eye);
    memcpy(v->dir, f, sizeof f);
    v->znear = zn;
    v->width = S->o.width;
    v->height = S->o.height;
}

/* ---- drawing ---- */

static void draw_obj(study *S, const cull_obj *o)
{
    glPushMatrix();
    sg_city_lot_transform(&S->s, &S->plan, o->lot, o->turn);
    sg_call_list(&S->s, o->list);
    glPopMatrix();
    S->st.objects++;
    S->st.tris += o->tris;
}

static void draw_leaf(study *S, const cull_node *n)
{
    for (int k = 0; k < n->n_objs; k++) draw_obj(S, &S->objs[S->tree.obj_index[n->first_obj + k]]);
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

static void draw_frame(study *S, int frame)
{
    float proj[16], mv[16];
    camera(S, frame, proj, mv);
    memset(&S->st, 0, sizeof S->st);
    glClearColor(0.55f, 0.7f, 0.9f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(mv);
    /* Lights after the view so that they stay fixed in the world. */
    const float sun[4] = {0.4f, 1.0f, 0.3f, 0.0f}, sund[4] = {0.85f, 0.8f, 0.7f, 1};
    const float suna[4] = {0.25f, 0.25f, 0.3f, 1};
    const float sky[4] = {-0.5f, 0.6f, -0.7f, 0.0f}, skyd[4] = {0.25f, 0.3f, 0.4f, 1};
    sg_light(&S->s, GL_LIGHT0, sun, sund, suna, NULL);
    sg_light(&S->s, GL_LIGHT1, sky, skyd, NULL, NULL);
    /* The ground: drawn by every method, first, and the first occluder. */
    glColor3f(0.42f, 0.42f, 0.4f);
    const sg_city_plan *pl = &S->plan;
    const float go[3] = {-SG_CITY_LOT, 0, -SG_CITY_LOT}, gu[3] = {0, 0, (float)(pl->rows + 2) * SG_CITY_LOT},
                gv[3] = {(float)(pl->cols + 2) * SG_CITY_LOT, 0, 0};
    sg_grid(&S->s, go, gu, gv, pl->rows + 2, pl->cols + 2);
    S->st.tris += S->ground_tris;
    if (S->o.method == M_DR)
        for (int i = 0; i < S->n_objs; i++) draw_obj(S, &S->objs[i]);
    else if (S->o.method == M_VFC)
        vfc_walk(S, 0, 0);
    else
        occlusion_walk(S);
    glFinish();
    S->prev_render = (double)S->st.tris;
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

static void gl_setup(study *S)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glShadeModel(GL_FLAT);
    sg_lighting(&S->s, GL_FRONT);
    glEnable(GL_NORMALIZE);
}

static int run(study *S, unsigned char *buf, FILE *csv)
{
    static const char *const mnames[] = {"dr", "vfc", "vo", "ac", "cac"};
    static const char *const tnames[] = {"query", "hp", "brief", "stencil"};
    S->prev_render = 0;
    for (int i = 0; i < S->n_objs; i++) S->prev_render += (double)S->objs[i].tris; /* frame -1: DR */
    /* cycles: the shim runs the functional model only; cycles come from
     * replaying a FRAGSIM_TRACE capture with fragsim replay --mode cycle. */
    fprintf(csv, "frame,method,test,vfc_tests,vfc_culled,occ_tests,occ_culled,objects_rendered,"
                 "objects_culled,triangles_rendered,cycles\n");
    for (int f = 0; f < S->o.frames; f++) {
        draw_frame(S, f);
        fprintf(csv, "%d,%s,%s,%llu,%llu,%llu,%llu,%llu,%llu,%llu,\n", f, mnames[S->o.method],
                S->o.method >= M_VO ? tnames[S->o.test] : "", (unsigned long long)S->st.vfc_tests,
                (unsigned long long)S->st.vfc_culled, (unsigned long long)S->st.occ_tests,
                (unsigned long long)S->st.occ_culled, (unsigned long long)S->st.objects,
                (unsigned long long)(S->n_objs - S->st.objects), (unsigned long long)S->st.tris);
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
    const char *why = S.o.method >= M_VO ? cull_test_unavailable(S.o.test) : NULL;
    if (why) {
        fprintf(stderr, "cullstudy: %s\n", why);
        return 2;
    }
    /* The emitter's context pointer only says "send" here (sg.h, SG_DIRECT_GL). */
    static char live;
    sg_init(&S.s, (fs_context *)(void *)&live);
    char err[256] = "";
    gl_setup(&S);
    if (city_setup(&S, err, sizeof err) != 0 ||
        cull_tree_build(&S.tree, S.o.hierarchy, S.objs, S.n_objs, S.o.leaf_objs) != 0) {
        fprintf(stderr, "cullstudy: %s\n", err[0] ? err : "out of memory");
        return 1;
    }
    printf("hierarchy %s: %d nodes, %d leaves, %d objects\n", cull_tree_name(S.o.hierarchy), S.tree.n_nodes,
           S.tree.n_leaves, S.n_objs);
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
    free(S.objs);
    sg_free(&S.s);
    OSMesaDestroyContext(ctx);
    free(buf);
    return rc;
}
