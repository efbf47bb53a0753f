/*
 * City: a grid of houses with furnished interiors, walked at street level.
 *
 * Workload sizes:
 *   city     Hüttner 1999, Table 3.1: 300 buildings, 1,056,280 triangles
 *            (3,521 per building), "each building contains some interior
 *            furniture" (sec. 3.1.9, Fig. 3.10), walked near the ground.
 *   norwich  Willmott et al. 2001, sec. 3.1.4: 800 houses, 222,912 polygons.
 *            The paper says polygons; we count them as triangles.
 *
 * Houses are instanced, as in both papers: a few variants are compiled into
 * display lists once (immediate mode inside the list) and each lot calls one,
 * so a 1M-triangle frame costs a few hundred calls in the trace and memory
 * stays bounded.  Exact paper totals: every regular house has the same
 * budget and one landmark house takes the remainder; inside a house, after
 * the walls and floors, furniture boxes (10 triangles) and a GL_POLYGON rug
 * (0..9 triangles) fill the budget exactly.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "sg.h"

#define CITY_LOT SG_CITY_LOT
#define CITY_FLOOR_H SG_CITY_FLOOR_H

typedef struct city_layout {
    float w, d;        /* footprint */
    int floors, rx, rz;
    int tiles;         /* floor subdivision per room (Hüttner 3.1.5 subdivides floors) */
    float wall[3], roof[3];
    uint64_t seed;
} city_layout;

/* One quad of a wall given in the wall's (u, v) parameters, inside GL_QUADS. */
static void city_rect(sg *s, const float o[3], const float u[3], const float v[3],
                      float a0, float a1, float b0, float b1)
{
    const float ab[4][2] = {{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
    for (int k = 0; k < 4; k++)
        sg_vtx(s, o[0] + u[0] * ab[k][0] + v[0] * ab[k][1], o[1] + u[1] * ab[k][0] + v[1] * ab[k][1],
               o[2] + u[2] * ab[k][0] + v[2] * ab[k][1]);
}

/* An outside wall with a window in every bay and a door on the ground floor
 * of the street side, so that interiors are seen from the street. */
static void city_facade(sg *s, const city_layout *L, const float o[3], const float u[3],
                        float len, int door)
{
    float H = L->floors * CITY_FLOOR_H;
    float v[3] = {0, H, 0};
    float n[3] = {-u[2] * H, 0, u[0] * H}; /* u x v */
    float nl = sqrtf(n[0] * n[0] + n[2] * n[2]);
    int bays = (int)(len / 2.6f);
    if (bays < 1) bays = 1;
    sg_begin(s, GL_QUADS);
    sg_nrm(s, n[0] / nl, 0, n[2] / nl);
    for (int f = 0; f < L->floors; f++) {
        float b0 = (float)f / L->floors, b1 = (float)(f + 1) / L->floors, bh = b1 - b0;
        for (int i = 0; i < bays; i++) {
            float a0 = (float)i / bays, a1 = (float)(i + 1) / bays, aw = a1 - a0;
            if (door && f == 0 && i == bays / 2) {
                city_rect(s, o, u, v, a0, a0 + aw * 0.3f, b0, b1);
                city_rect(s, o, u, v, a0 + aw * 0.7f, a1, b0, b1);
                city_rect(s, o, u, v, a0 + aw * 0.3f, a0 + aw * 0.7f, b0 + bh * 0.75f, b1);
            } else {
                city_rect(s, o, u, v, a0, a1, b0, b0 + bh * 0.3f);
                city_rect(s, o, u, v, a0, a1, b0 + bh * 0.75f, b1);
                city_rect(s, o, u, v, a0, a0 + aw * 0.25f, b0 + bh * 0.3f, b0 + bh * 0.75f);
                city_rect(s, o, u, v, a0 + aw * 0.75f, a1, b0 + bh * 0.3f, b0 + bh * 0.75f);
            }
        }
    }
    sg_end(s);
}

/* Shell, rooms and roof: everything but the furniture. */
static void city_structure(sg *s, const city_layout *L)
{
    float w = L->w, d = L->d, H = L->floors * CITY_FLOOR_H;
    G(s, Color3fv, L->wall);
    const float fo[3] = {0, 0, d}, fu[3] = {w, 0, 0};
    const float ro[3] = {w, 0, d}, ru[3] = {0, 0, -d};
    const float bo[3] = {w, 0, 0}, bu[3] = {-w, 0, 0};
    const float lo[3] = {0, 0, 0}, lu[3] = {0, 0, d};
    city_facade(s, L, fo, fu, w, 1);
    city_facade(s, L, ro, ru, d, 0);
    city_facade(s, L, bo, bu, w, 0);
    city_facade(s, L, lo, lu, d, 0);

    /* Rooms: inward-facing walls inset from the shell so that faces of
     * neighbouring rooms and the shell never coincide. */
    const float e = 0.12f;
    for (int f = 0; f < L->floors; f++) {
        float y0 = f * CITY_FLOOR_H + 0.02f, h = CITY_FLOOR_H - 0.1f;
        for (int ix = 0; ix < L->rx; ix++)
            for (int iz = 0; iz < L->rz; iz++) {
                float x0 = w * ix / L->rx + e, x1 = w * (ix + 1) / L->rx - e;
                float z0 = d * iz / L->rz + e, z1 = d * (iz + 1) / L->rz - e;
                float dx = x1 - x0, dz = z1 - z0;
                G(s, Color3f, 0.55f + 0.1f * (float)((ix + iz + f) % 3), 0.45f, 0.35f);
                const float flo[3] = {x0, y0, z0}, fu2[3] = {0, 0, dz}, fv2[3] = {dx, 0, 0};
                sg_grid(s, flo, fu2, fv2, L->tiles, L->tiles);
                G(s, Color3f, 0.85f, 0.83f, 0.78f);
                const float co[3] = {x0, y0 + h, z0}, cu[3] = {dx, 0, 0}, cv[3] = {0, 0, dz};
                sg_grid(s, co, cu, cv, 1, 1);
                const float up[3] = {0, h, 0};
                const float w1o[3] = {x1, y0, z1}, w1u[3] = {-dx, 0, 0};
                const float w2o[3] = {x0, y0, z0}, w2u[3] = {dx, 0, 0};
                const float w3o[3] = {x1, y0, z0}, w3u[3] = {0, 0, dz};
                const float w4o[3] = {x0, y0, z1}, w4u[3] = {0, 0, -dz};
                G(s, Color3f, 0.75f, 0.72f, 0.6f + 0.05f * (float)(ix % 2));
                sg_grid(s, w1o, w1u, up, 1, 1);
                sg_grid(s, w2o, w2u, up, 1, 1);
                sg_grid(s, w3o, w3u, up, 1, 1);
                sg_grid(s, w4o, w4u, up, 1, 1);
            }
    }

    /* Gable roof: two slopes (GL_QUADS) and two gables (GL_TRIANGLES). */
    float rh = 0.45f * d;
    G(s, Color3fv, L->roof);
    sg_begin(s, GL_QUADS);
    sg_nrm(s, 0, 0.5f * w * d, w * rh);
    sg_vtx(s, 0, H, d);
    sg_vtx(s, w, H, d);
    sg_vtx(s, w, H + rh, d / 2);
    sg_vtx(s, 0, H + rh, d / 2);
    sg_nrm(s, 0, 0.5f * w * d, -w * rh);
    sg_vtx(s, w, H, 0);
    sg_vtx(s, 0, H, 0);
    sg_vtx(s, 0, H + rh, d / 2);
    sg_vtx(s, w, H + rh, d / 2);
    sg_end(s);
    G(s, Color3fv, L->wall);
    sg_begin(s, GL_TRIANGLES);
    sg_nrm(s, -1, 0, 0);
    sg_vtx(s, 0, H, 0);
    sg_vtx(s, 0, H, d);
    sg_vtx(s, 0, H + rh, d / 2);
    sg_nrm(s, 1, 0, 0);
    sg_vtx(s, w, H, d);
    sg_vtx(s, w, H, 0);
    sg_vtx(s, w, H + rh, d / 2);
    sg_end(s);
}

static uint64_t city_structure_tris(const city_layout *L)
{
    sg m;
    sg_init(&m, NULL);
    city_structure(&m, L);
    uint64_t t = m.tris;
    sg_free(&m);
    return t;
}

/* A house's layout for 'budget' triangles, drawn from r; -1 when even the
 * smallest house does not fit. */
static int city_layout_make(city_layout *L_out, sg_rng *r_in, uint64_t seed, uint64_t budget, int max_floors)
{
    sg_rng *r = r_in;
    city_layout L;
    memset(&L, 0, sizeof L);
    L.seed = seed;
    L.w = (float)sg_rng_range(r, 8.0, 13.0);
    L.d = (float)sg_rng_range(r, 7.0, 10.0);
    L.floors = 1 + sg_rng_int(r, max_floors);
    L.rx = 2;
    L.rz = 2;
    L.tiles = 1;
    float shade = (float)sg_rng_range(r, 0.0, 0.25);
    L.wall[0] = 0.75f + shade; L.wall[1] = 0.68f + shade * 0.8f; L.wall[2] = 0.55f;
    L.roof[0] = 0.55f + shade; L.roof[1] = 0.22f; L.roof[2] = 0.15f;

    /* Shrink until the shell fits, then grow floor tiles while the
     * structure stays under ~70% of the budget (the rest is furniture). */
    while (city_structure_tris(&L) > budget) {
        if (L.floors > 1) L.floors--;
        else if (L.rx > 1) L.rx--;
        else if (L.rz > 1) L.rz--;
        else return -1;
    }
    for (;;) {
        city_layout n = L;
        n.tiles++;
        if (n.tiles > 64 || city_structure_tris(&n) * 10 > budget * 7) break;
        L = n;
    }
    *L_out = L;
    return 0;
}

/* Emits one house of exactly 'budget' triangles.  Returns -1 when even the
 * smallest house does not fit. */
static int city_house(sg *s, uint64_t seed, uint64_t budget, int max_floors)
{
    sg_rng r;
    sg_rng_seed(&r, seed);
    city_layout L;
    if (city_layout_make(&L, &r, seed, budget, max_floors) != 0) return -1;
    uint64_t left = budget - city_structure_tris(&L);
    city_structure(s, &L);

    /* Furniture: boxes in random rooms, standing on the floor. */
    uint64_t boxes = left / 10, rug = left % 10;
    int rooms = L.floors * L.rx * L.rz;
    for (uint64_t i = 0; i < boxes; i++) {
        int room = sg_rng_int(&r, rooms);
        int f = room / (L.rx * L.rz), ix = (room / L.rz) % L.rx, iz = room % L.rz;
        float rw = L.w / L.rx, rd = L.d / L.rz;
        float bw = (float)sg_rng_range(&r, 0.3, 0.3 * rw), bd = (float)sg_rng_range(&r, 0.3, 0.3 * rd);
        float bh = (float)sg_rng_range(&r, 0.3, 2.2);
        float x0 = ix * rw + 0.2f + (float)sg_rng_unit(&r) * (rw - bw - 0.4f);
        float z0 = iz * rd + 0.2f + (float)sg_rng_unit(&r) * (rd - bd - 0.4f);
        float y0 = f * CITY_FLOOR_H + 0.03f;
        /* One draw per statement: the order in which C evaluates function
         * arguments is unspecified (gcc and clang differ). */
        float cr = (float)sg_rng_range(&r, 0.2, 0.9);
        float cg = (float)sg_rng_range(&r, 0.2, 0.7);
        float cb = (float)sg_rng_range(&r, 0.1, 0.5);
        G(s, Color3f, cr, cg, cb);
        sg_box(s, x0, y0, z0, x0 + bw, y0 + bh, z0 + bd, 0);
    }
    if (rug) {
        G(s, Color3f, 0.6f, 0.1f, 0.15f);
        sg_disc(s, 0.25f * L.w, 0.04f, 0.25f * L.d, 0.8f, rug, 1);
    }
    return 0;
}

int sg_city_plan_make(sg_city_plan *pl, uint64_t n, uint64_t target, int max_floors,
                      const char *name, char *err, size_t errlen)
{
    memset(pl, 0, sizeof *pl);
    int cols = (int)ceil(sqrt((double)n)), rows = (int)((n + (uint64_t)cols - 1) / (uint64_t)cols);
    uint64_t ground = 2ull * (uint64_t)(cols + 2) * (uint64_t)(rows + 2);
    if (target < ground + n * 100) {
        snprintf(err, errlen, "%s: %llu triangles are too few for %llu houses", name,
                 (unsigned long long)target, (unsigned long long)n);
        return -1;
    }
    uint64_t houses = target - ground, q = houses / n;
    pl->houses = n;
    pl->cols = cols;
    pl->rows = rows;
    pl->budget = q;
    pl->landmark_budget = houses - (n - 1) * q;
    pl->landmark = n / 2;
    pl->variants = n - 1 < 8 ? (int)(n - 1) : 8;
    pl->max_floors = max_floors;
    return 0;
}

int sg_city_compile(sg *s, const sg_city_plan *pl, uint64_t seed, GLuint base, const char *name,
                    char *err, size_t errlen)
{
    for (int v = 0; v <= pl->variants; v++) {
        sg_new_list(s, base + (GLuint)v);
        int rc = v < pl->variants ? city_house(s, seed * 977 + (uint64_t)v, pl->budget, pl->max_floors)
                                  : city_house(s, seed * 977 + 1000, pl->landmark_budget, pl->max_floors + 2);
        sg_end_list(s);
        if (rc != 0) {
            snprintf(err, errlen, "%s: a house budget of %llu triangles is too small", name,
                     (unsigned long long)pl->budget);
            return -1;
        }
    }
    return 0;
}

int sg_city_ground_rooms(const sg_city_plan *pl, uint64_t seed, int v, float rect[][4], int max, float *top)
{
    sg_rng r;
    uint64_t hs = v < pl->variants ? seed * 977 + (uint64_t)v : seed * 977 + 1000; /* sg_city_compile's seeds */
    sg_rng_seed(&r, hs);
    city_layout L;
    if (city_layout_make(&L, &r, hs, v < pl->variants ? pl->budget : pl->landmark_budget,
                         v < pl->variants ? pl->max_floors : pl->max_floors + 2) != 0)
        return -1;
    int n = 0;
    const float e = 0.12f; /* city_structure's inset */
    *top = (float)L.floors * CITY_FLOOR_H + 0.45f * L.d; /* city_structure's roof ridge */
    for (int ix = 0; ix < L.rx; ix++)
        for (int iz = 0; iz < L.rz && n < max; iz++, n++) {
            rect[n][0] = L.w * ix / L.rx + e;
            rect[n][1] = L.d * iz / L.rz + e;
            rect[n][2] = L.w * (ix + 1) / L.rx - e;
            rect[n][3] = L.d * (iz + 1) / L.rz - e;
        }
    return n;
}

uint64_t sg_city_lots_seed(uint64_t seed) { return seed * 31 + 7; }

void sg_city_lot(sg_rng *lots, const sg_city_plan *pl, uint64_t i, int *variant, int *turn)
{
    /* Two draws per lot, in this order, whether or not the lot is drawn. */
    *variant = i == pl->landmark ? pl->variants : sg_rng_int(lots, pl->variants);
    *turn = sg_rng_int(lots, 4);
}

void sg_city_lot_transform(sg *s, const sg_city_plan *pl, uint64_t i, int turn)
{
    int cx = (int)(i % (uint64_t)pl->cols), cz = (int)(i / (uint64_t)pl->cols);
    G(s, Translatef, (cx + 0.5f) * CITY_LOT, 0.0f, (cz + 0.5f) * CITY_LOT);
    G(s, Rotatef, 90.0f * (float)turn, 0.0f, 1.0f, 0.0f);
    G(s, Translatef, -6.0f, 0.0f, -5.0f);
}

static int city_run(sg *s, const sg_params *p, int paper_houses, double paper_density,
                    int max_floors, const char *name, char *err, size_t errlen)
{
    uint64_t n;
    if (p->paper) {
        n = (uint64_t)paper_houses;
    } else {
        n = (uint64_t)((double)p->target / paper_density);
        if (n < 4) n = p->target / 700 < 4 ? (p->target / 700 ? p->target / 700 : 1) : 4;
    }
    sg_city_plan pl;
    if (sg_city_plan_make(&pl, n, p->target, max_floors, name, err, errlen) != 0) return -1;
    int cols = pl.cols, rows = pl.rows;

    GLuint base = sg_gen_lists(s, pl.variants + 1);
    if (!base) {
        snprintf(err, errlen, "%s: glGenLists failed", name);
        return -1;
    }
    if (sg_city_compile(s, &pl, p->seed, base, name, err, errlen) != 0) return -1;

    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    G(s, CullFace, GL_BACK);
    G(s, ShadeModel, GL_FLAT);
    sg_lighting(s, GL_FRONT);
    G(s, Enable, GL_NORMALIZE);
    sg_perspective(s, 60.0, (double)p->width / p->height, 0.5, 3000.0);

    float street_x = (float)(cols / 2) * CITY_LOT;
    float z_end = rows * CITY_LOT * 0.9f;
    for (int fr = 0; fr < p->frames; fr++) {
        sg_frame_begin(s, 0.55f, 0.7f, 0.9f);
        G0(s, LoadIdentity);
        float t = p->frames > 1 ? (float)fr / (float)(p->frames - 1) : 0.0f;
        float yaw = 0.35f * sinf(6.2831853f * t * 1.5f);
        const float eye[3] = {street_x + 1.5f * sinf(3.0f * t), 1.7f, -4.0f + t * (z_end + 4.0f)};
        const float at[3] = {eye[0] + sinf(yaw), 1.6f, eye[2] + cosf(yaw)};
        const float up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        /* Lights after the view so that they stay fixed in the world. */
        const float sun[4] = {0.4f, 1.0f, 0.3f, 0.0f}, sund[4] = {0.85f, 0.8f, 0.7f, 1};
        const float suna[4] = {0.25f, 0.25f, 0.3f, 1};
        const float sky[4] = {-0.5f, 0.6f, -0.7f, 0.0f}, skyd[4] = {0.25f, 0.3f, 0.4f, 1};
        sg_light(s, GL_LIGHT0, sun, sund, suna, NULL);
        sg_light(s, GL_LIGHT1, sky, skyd, NULL, NULL);

        /* Ground, drawn in immediate mode every frame. */
        G(s, Color3f, 0.42f, 0.42f, 0.4f);
        const float go[3] = {-CITY_LOT, 0, -CITY_LOT}, gu[3] = {0, 0, (rows + 2) * CITY_LOT},
                    gv[3] = {(cols + 2) * CITY_LOT, 0, 0};
        sg_grid(s, go, gu, gv, rows + 2, cols + 2);

        sg_rng lots;
        sg_rng_seed(&lots, sg_city_lots_seed(p->seed));
        for (uint64_t i = 0; i < n; i++) {
            int v, turn;
            sg_city_lot(&lots, &pl, i, &v, &turn);
            G0(s, PushMatrix);
            sg_city_lot_transform(s, &pl, i, turn);
            sg_call_list(s, base + (GLuint)v);
            G0(s, PopMatrix);
        }
        sg_frame_end(s);
    }
    return 0;
}

int sg_scene_city(sg *s, const sg_params *p, char *err, size_t errlen)
{
    /* Hüttner 1999, Table 3.1: 300 buildings, 3,521 triangles per building. */
    return city_run(s, p, 300, 1056280.0 / 300.0, 3, "city", err, errlen);
}

int sg_scene_norwich(sg *s, const sg_params *p, char *err, size_t errlen)
{
    /* Willmott et al. 2001, sec. 3.1.4: 800 houses, 222,912 polygons. */
    return city_run(s, p, 800, 222912.0 / 800.0, 2, "norwich", err, errlen);
}
