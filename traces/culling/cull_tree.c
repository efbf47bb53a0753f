/*
 * Scene hierarchies of the culling study (Huettner 1999, sec. 3.1.5): the
 * sloppy n-ary space-partitioning tree (snSP-tree) built three ways.
 *  - D-BVS: a node is split n_split times along its largest dimension,
 *    n_split = largest / second largest dimension (eq. 3.1), at least once.
 *  - p-HBVO: binary splits at the barycentre of an element, chosen over all
 *    three axes by the minimum of C_H = S(L)/S(H)|L| + S(R)/S(H)|R|
 *    (eq. 3.2; S the bounding-box surface, |.| the triangles).
 *  - SGI Optimizer-like: eight children per node, each cut placed so the
 *    rendering load (triangles) on both sides is about equal (the text's
 *    reading of the tool: "subdivision planes so that the rendering loads of
 *    the resulting parts are similar").
 * The elements sorted are objects (cull.h), not polygons: nothing is split,
 * and boxes are recomputed from the objects a node holds (sloppy).
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include "cull.h"

typedef struct build {
    cull_tree *t;
    const cull_obj *objs;
    int leaf_objs, kind, oom;
} build;

const char *cull_tree_name(int kind)
{
    return kind == CULL_DBVS ? "D-BVS" : kind == CULL_PHBVO ? "p-HBVO" : "SGI";
}

static float centre(const cull_obj *o, int axis) { return 0.5f * (o->box.lo[axis] + o->box.hi[axis]); }

static void box_empty(cull_box *b)
{
    for (int a = 0; a < 3; a++) { b->lo[a] = FLT_MAX; b->hi[a] = -FLT_MAX; }
}

static void box_add(cull_box *b, const cull_box *o)
{
    for (int a = 0; a < 3; a++) {
        if (o->lo[a] < b->lo[a]) b->lo[a] = o->lo[a];
        if (o->hi[a] > b->hi[a]) b->hi[a] = o->hi[a];
    }
}

static double box_area(const cull_box *b)
{
    double dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

/* qsort has no context argument: the axis and objects of the sort. */
static const cull_obj *sort_objs;
static int sort_axis;
static int by_centre(const void *a, const void *b)
{
    float ca = centre(&sort_objs[*(const int *)a], sort_axis), cb = centre(&sort_objs[*(const int *)b], sort_axis);
    if (ca != cb) return ca < cb ? -1 : 1;
    return *(const int *)a - *(const int *)b; /* deterministic ties */
}

static void sort_by(build *B, int *idx, int n, int axis)
{
    sort_objs = B->objs;
    sort_axis = axis;
    qsort(idx, (size_t)n, sizeof *idx, by_centre);
}

/* Splits cut the range idx[0..n) into groups at ends[0] < ends[1] < ... = n. */
#define MAX_GROUPS 8

/* Eq. 3.1: n_split pieces along the largest dimension. */
static int split_dbvs(build *B, const cull_box *bx, int *idx, int n, int *ends)
{
    float d[3];
    int ax = 0;
    for (int a = 0; a < 3; a++) {
        d[a] = bx->hi[a] - bx->lo[a];
        if (d[a] > d[ax]) ax = a;
    }
    if (d[ax] <= 0) return 1; /* a point: nothing to split */
    float second = 0;
    for (int a = 0; a < 3; a++)
        if (a != ax && d[a] > second) second = d[a];
    int ns = second > 0 ? (int)(d[ax] / second + 0.5f) : MAX_GROUPS;
    if (ns < 2) ns = 2; /* cube-like: split once */
    if (ns > MAX_GROUPS) ns = MAX_GROUPS;
    sort_by(B, idx, n, ax);
    int g = 0, prev = -1;
    for (int i = 0; i < n; i++) { /* sorted, so each piece is one run */
        int k = (int)((centre(&B->objs[idx[i]], ax) - bx->lo[ax]) / d[ax] * (float)ns);
        if (k >= ns) k = ns - 1;
        if (i > 0 && k != prev) ends[g++] = i;
        prev = k;
    }
    ends[g++] = n;
    return g;
}

/* Eq. 3.2 over every barycentre of every axis. */
static int split_phbvo(build *B, const cull_box *bx, int *idx, int n, int *ends)
{
    double best = DBL_MAX, sh = box_area(bx);
    int best_ax = 0, best_k = n / 2;
    double *right = malloc((size_t)n * sizeof *right);
    if (!right || sh <= 0) {
        free(right);
        sort_by(B, idx, n, 0);
        ends[0] = n / 2;
        ends[1] = n;
        return 2;
    }
    for (int ax = 0; ax < 3; ax++) {
        sort_by(B, idx, n, ax);
        cull_box r;
        box_empty(&r);
        uint64_t rt = 0;
        for (int i = n - 1; i > 0; i--) { /* right[i]: cost of idx[i..n) */
            box_add(&r, &B->objs[idx[i]].box);
            rt += B->objs[idx[i]].tris;
            right[i] = box_area(&r) / sh * (double)rt;
        }
        cull_box l;
        box_empty(&l);
        uint64_t lt = 0;
        for (int k = 1; k < n; k++) { /* left idx[0..k), right idx[k..n) */
            box_add(&l, &B->objs[idx[k - 1]].box);
            lt += B->objs[idx[k - 1]].tris;
            double c = box_area(&l) / sh * (double)lt + right[k];
            if (c < best) { best = c; best_ax = ax; best_k = k; }
        }
    }
    free(right);
    sort_by(B, idx, n, best_ax);
    ends[0] = best_k;
    ends[1] = n;
    return 2;
}

/* The load median of idx[0..n) along axis: the first k with half the triangles before it. */
static int load_median(build *B, int *idx, int n, int axis)
{
    sort_by(B, idx, n, axis);
    uint64_t total = 0, acc = 0;
    for (int i = 0; i < n; i++) total += B->objs[idx[i]].tris;
    int k = 0;
    while (k < n - 1 && (acc + B->objs[idx[k]].tris) * 2 <= total) acc += B->objs[idx[k++]].tris;
    return k == 0 ? (n > 1 ? 1 : 0) : k;
}

/* Eight load-balanced octants: x, then y in each half, then z in each quarter. */
static int split_sgi(build *B, int *idx, int n, int *ends)
{
    int cuts[9] = {0, n}, nc = 2;
    for (int axis = 0; axis < 3; axis++) {
        int next[9], nn = 0;
        for (int c = 0; c + 1 < nc; c++) {
            int lo = cuts[c], len = cuts[c + 1] - lo;
            next[nn++] = lo;
            if (len > 1) next[nn++] = lo + load_median(B, idx + lo, len, axis);
        }
        next[nn++] = n;
        memcpy(cuts, next, (size_t)nn * sizeof *cuts);
        nc = nn;
    }
    int g = 0;
    for (int c = 1; c < nc; c++)
        if (cuts[c] > cuts[c - 1]) ends[g++] = cuts[c];
    return g;
}

static int new_node(build *B)
{
    cull_tree *t = B->t;
    if (t->n_nodes == t->cap_nodes) {
        int cap = t->cap_nodes ? 2 * t->cap_nodes : 64;
        cull_node *p = realloc(t->node, (size_t)cap * sizeof *p);
        if (!p) { B->oom = 1; return -1; }
        t->node = p;
        t->cap_nodes = cap;
    }
    memset(&t->node[t->n_nodes], 0, sizeof t->node[0]);
    return t->n_nodes++;
}

static int reserve_children(build *B, int k)
{
    cull_tree *t = B->t;
    if (t->n_child + k > t->cap_child) {
        int cap = t->cap_child ? 2 * t->cap_child : 64;
        while (cap < t->n_child + k) cap *= 2;
        int *p = realloc(t->child, (size_t)cap * sizeof *p);
        if (!p) { B->oom = 1; return -1; }
        t->child = p;
        t->cap_child = cap;
    }
    int first = t->n_child;
    t->n_child += k;
    return first;
}

/* The node over idx[0..n), idx being a slice of t->obj_index. */
static int build_node(build *B, int *idx, int n)
{
    int id = new_node(B);
    if (id < 0) return -1;
    cull_box bx;
    box_empty(&bx);
    uint64_t tris = 0;
    for (int i = 0; i < n; i++) {
        box_add(&bx, &B->objs[idx[i]].box);
        tris += B->objs[idx[i]].tris;
    }
    B->t->node[id].box = bx;
    B->t->node[id].tris = tris;
    int ends[MAX_GROUPS], g = 0;
    if (n > B->leaf_objs) {
        g = B->kind == CULL_DBVS    ? split_dbvs(B, &bx, idx, n, ends)
            : B->kind == CULL_PHBVO ? split_phbvo(B, &bx, idx, n, ends)
                                    : split_sgi(B, idx, n, ends);
    }
    if (g < 2) { /* a leaf: small enough, or nothing to separate */
        B->t->node[id].first_obj = (int)(idx - B->t->obj_index);
        B->t->node[id].n_objs = n;
        B->t->n_leaves++;
        return id;
    }
    int first = reserve_children(B, g);
    if (first < 0) return -1;
    B->t->node[id].first_child = first;
    B->t->node[id].n_children = g;
    for (int k = 0, start = 0; k < g; start = ends[k++]) {
        int c = build_node(B, idx + start, ends[k] - start);
        if (c < 0) return -1;
        B->t->child[first + k] = c;
    }
    return id;
}

int cull_tree_build(cull_tree *t, int kind, const cull_obj *objs, int n, int leaf_objs)
{
    memset(t, 0, sizeof *t);
    build B = {t, objs, leaf_objs < 1 ? 1 : leaf_objs, kind, 0};
    t->obj_index = malloc((size_t)(n > 0 ? n : 1) * sizeof *t->obj_index);
    if (!t->obj_index) return -1;
    for (int i = 0; i < n; i++) t->obj_index[i] = i;
    if (n > 0 && build_node(&B, t->obj_index, n) < 0) {
        cull_tree_free(t);
        return -1;
    }
    return 0;
}

void cull_tree_free(cull_tree *t)
{
    free(t->node);
    free(t->child);
    free(t->obj_index);
    memset(t, 0, sizeof *t);
}
