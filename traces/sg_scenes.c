/* Scene generators: the scene table and the driver (trace writing and
 * count-only runs). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sg.h"
#include "../pipeline/context.h"
#include "../driver/capture.h"

/* ---- the scene table ---- */
/* Sizes from the seed papers (see traces/README.md and docs/scenes.md):
 * Hüttner 1999, Table 3.1 for city, cathedrals, forest and garbage;
 * Willmott et al. 2001 section 3.1.4 for the Norwich city;
 * Hüttner 1999 section 2.1 (Grand-Canyon-East DEM) for terrain. */
const sg_scene sg_scenes[] = {
    {"city", "grid of houses with furnished interiors, walked at street level",
     "Huettner 1999, Table 3.1: city, 300 buildings, 1,056,280 triangles",
     1056280, 3200, 4, 20, 256, 1024, sg_scene_city},
    {"norwich", "800 small houses with interiors (city generator), walked at street level",
     "Willmott et al. 2001, sec. 3.1.4: 800 houses, 222,912 polygons (counted here as triangles)",
     222912, 3000, 4, 20, 256, 1024, sg_scene_norwich},
    {"cathedrals", "2x2x2 array of a gothic cathedral: nave, columns, arches, vaults",
     "Huettner 1999, Table 3.1: 8 cathedrals x 416,763 = 3,334,104 triangles",
     3334104, 6400, 3, 10, 256, 1024, sg_scene_cathedrals},
    {"forest", "12 dense trees in front of an octagonal castle",
     "Huettner 1999, Table 3.1: 12 trees x 28,500 + castle 110,981 = 452,981 triangles",
     452981, 3500, 3, 10, 256, 1024, sg_scene_forest},
    {"garbage", "2,500 small independent objects (balls, rings, cans, boxes) that move",
     "Huettner 1999, Table 3.1: 2,500 objects, about 2,100 each, 5,331,146 triangles",
     5331146, 3000, 3, 5, 256, 1024, sg_scene_garbage},
    {"terrain", "fractal height field flown over at 700 m to 5,000 m",
     "Huettner 1999, sec. 2.1: Grand-Canyon-East DEM, 2,906,504 triangles; flights at 700-5000 m (sec. 2.3.5)",
     2906504, 3200, 4, 10, 256, 1024, sg_scene_terrain},
    {"demo", "small lit scene: floor, torus, sphere, columns, pyramid; three lights",
     "none (bundled demo for `make run`)", 0, 3000, 3, 3, 256, 256, sg_scene_demo},
    {"textured", "textured ground plane at a grazing angle (trilinear MIPmaps) and a NEAREST box",
     "none (texturing workload; setting of Huettner 1999, Figs. 4.33-4.41)", 0, 3000, 3, 3, 256, 1024,
     sg_scene_textured},
    {"bench8", "100,000 random 8-pixel triangles, vertex arrays, depth test, one frame",
     "none (throughput benchmark)", 0, 2000, 1, 1, 256, 1024, sg_scene_bench8},
    {"bench32", "100,000 random 32-pixel triangles, vertex arrays, depth test, one frame",
     "none (throughput benchmark)", 0, 2000, 1, 1, 256, 1024, sg_scene_bench32},
};
const int sg_scene_count = (int)(sizeof sg_scenes / sizeof sg_scenes[0]);

const sg_scene *sg_find_scene(const char *name)
{
    for (int i = 0; i < sg_scene_count; i++)
        if (strcmp(sg_scenes[i].name, name) == 0) return &sg_scenes[i];
    return NULL;
}

int sg_default_params(const sg_scene *sc, const char *scale, sg_params *p)
{
    memset(p, 0, sizeof *p);
    p->seed = 1;
    if (strcmp(scale, "small") == 0) {
        p->target = sc->small_tris;
        p->frames = sc->small_frames;
        p->width = p->height = sc->small_size;
    } else if (strcmp(scale, "paper") == 0) {
        /* Benchmarks and the demo have no paper; their "paper" scale is the
         * full-size workload of the brief (100,000 triangles). */
        p->paper = 1;
        p->target = sc->paper_tris ? sc->paper_tris : sc->run == sg_scene_demo ? sc->small_tris : 100000;
        p->frames = sc->paper_frames;
        p->width = p->height = sc->paper_size;
    } else {
        char *end;
        unsigned long long n = strtoull(scale, &end, 10);
        if (*end || n < 100 || n > 100000000ull) return -1;
        p->target = n;
        p->frames = sc->small_frames;
        p->width = p->height = 512;
    }
    return 0;
}

static void fill_report(const sg *s, sg_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->tris_total = s->tris;
    rep->frames = s->frames;
    rep->min_frame_tris = s->frames ? s->min_frame_tris : 0;
    rep->max_frame_tris = s->max_frame_tris;
    rep->tris_per_frame = s->frames ? s->tris / (uint64_t)s->frames : 0;
    rep->calls = s->calls;
    rep->pointer_calls = s->pointer_calls;
}

static int run_scene(sg *s, const sg_scene *sc, const sg_params *p, char *err, size_t errlen)
{
    G(s, Viewport, 0, 0, p->width, p->height);
    int rc = sc->run(s, p, err, errlen);
    if (rc == 0 && s->oom) {
        snprintf(err, errlen, "%s: out of memory", sc->name);
        rc = -1;
    }
    if (rc == 0 && (s->misuse || s->in_prim || s->compiling)) {
        snprintf(err, errlen, "%s: unbalanced glBegin/glEnd or glNewList, or glGenLists failed", sc->name);
        rc = -1;
    }
    return rc;
}

int sg_generate(const sg_scene *sc, const sg_params *p, const char *path,
                sg_report *rep, char *err, size_t errlen)
{
    fs_context *c = fs_context_create(NULL, p->width, p->height);
    if (!c) {
        snprintf(err, errlen, "cannot create a %dx%d context", p->width, p->height);
        return -1;
    }
    if (fs_capture_open(c, path, err, errlen) != 0) {
        fs_context_destroy(c);
        return -1;
    }
    sg s;
    sg_init(&s, c);
    int rc = run_scene(&s, sc, p, err, errlen);
    if (fs_capture_close(c) != 0 && rc == 0) {
        snprintf(err, errlen, "%s: writing failed", path);
        rc = -1;
    }
    fill_report(&s, rep);
    sg_free(&s);
    fs_context_destroy(c);
    return rc;
}

int sg_count(const sg_scene *sc, const sg_params *p, sg_report *rep, char *err, size_t errlen)
{
    sg s;
    sg_init(&s, NULL);
    int rc = run_scene(&s, sc, p, err, errlen);
    fill_report(&s, rep);
    sg_free(&s);
    return rc;
}
