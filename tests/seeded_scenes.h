/*
 * Random scenes drawn by OSMesa and by fragsim and compared at tolerance 0
 * (osmesa_util.h), one seed per scene: the seeded generator and the loop
 * over seeds shared by the rasterization tests (test_polygon_mode.c,
 * test_lines_points.c).  FS_SCENE_DUMP=1 writes each differing scene as
 * /tmp/<name>_<seed>.ppm (img_dump_ppm).
 */
#ifndef FS_TEST_SEEDED_SCENES_H
#define FS_TEST_SEEDED_SCENES_H
#include "check.h"
#include "osmesa_util.h"

typedef struct rng { uint64_t s; } rng;
static inline uint32_t rnd(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(r->s >> 33);
}
static inline float rndf(rng *r) { return (float)(rnd(r) & 0xffffff) / 16777216.0f; }
static inline float rnd_in(rng *r, float lo, float hi) { return lo + (hi - lo) * rndf(r); }

/* The scenes' common start: the whole window, cleared to (0.05, 0.1, 0.15)
 * with its depth, the depth test on, and either identity matrices or a
 * frustum (near 1.5, far 6) looking at the unit cube 3 units away. */
static inline void scene_view(fs_context *c, int w, int h, bool perspective)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.05f, 0.1f, 0.15f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    if (perspective)
        G(Frustum, -1, 1, -1, 1, 1.5, 6);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    if (perspective)
        G(Translatef, 0, 0, -3);
    G(Enable, GL_DEPTH_TEST);
}

/* Scene k of a run is drawn by draw(c, scene, w, h) with *seed = first + k
 * at (w0 + (k % 3) * dw) x (h0 + (k % 2) * dh) pixels. */
typedef struct seeded_run {
    void (*draw)(fs_context *c, const void *scene, int w, int h);
    const void *scene;
    unsigned *seed;
    int w0, h0, dw, dh;
    const char *name;
} seeded_run;

/* The number of scenes that differ (-1 when a context cannot be made);
 * *lit counts the reference's pixels unlike the clear colour's red and
 * blue, 13 and 38 (ClearColor 0.05, *, 0.15). */
static inline int seeded_runs(const seeded_run *r, unsigned first, unsigned count, long *lit)
{
    int bad = 0;
    for (unsigned k = 0; k < count; k++) {
        *r->seed = first + k;
        osm_pair p;
        if (!osm_pair_render(&p, r->w0 + (int)(k % 3) * r->dw, r->h0 + (int)(k % 2) * r->dh, NULL, r->draw,
                             r->scene))
            return -1;
        if (p.d.differ) {
            bad++;
            printf("  %s seed %u: %ld pixels differ (max %d)\n", r->name, first + k, p.d.differ, p.d.maxd);
            if (getenv("FS_SCENE_DUMP")) {
                char fn[160];
                snprintf(fn, sizeof fn, "/tmp/%s_%u.ppm", r->name, first + k);
                img_dump_ppm(fn, p.ref.color, p.c->fb.color, p.ref.w, p.ref.h, 4, true);
            }
        }
        for (long i = 0; i < (long)p.ref.w * p.ref.h; i++)
            *lit += p.ref.color[i * 4] != 13 || p.ref.color[i * 4 + 2] != 38;
        osm_pair_close(&p);
    }
    return bad;
}

/* Every scene of the run equal to OSMesa's, and something drawn. */
static inline void check_seeded_runs(check_state *check_st_, const seeded_run *r, unsigned first, unsigned count)
{
    long lit = 0;
    int bad = seeded_runs(r, first, count, &lit);
    REQUIRE(bad >= 0);
    CHECK_EQ_INT(bad, 0);
    CHECK(lit > 0);
}
#endif
