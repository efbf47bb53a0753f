/*
 * One Occlusion Engine (Huettner 1999, 3.3, Fig. 3.17) and the occlusion
 * tile state it updates.  Private to the Occlusion Unit (occlusion_unit.c);
 * a cycle model may read these structs but only the unit changes them.
 */
#ifndef FS_OCCLUSION_ENGINE_H
#define FS_OCCLUSION_ENGINE_H
#include <stdbool.h>
#include <stdint.h>

/* An occlusion tile and its registers.  Coordinates are window pixels; the
 * rectangle is half-open, [x0,x1) x [y0,y1), like the scissor box (GL 1.5
 * spec 4.1.2). */
typedef struct fs_occu_tile {
    int64_t x0, y0, x1, y1;
    /* Hit counters, saturating at the unit's counter maximum (3.2: NOHC
     * counts fragments inside the tile that passed the depth test, PHC all
     * fragments inside the tile that reached the depth test). */
    uint32_t nohc, phc;
    bool nohc_overflow, phc_overflow;
    /* Screen bounding box and depth range of the hits (3.2.1), inclusive,
     * depth in the depth buffer's fixed-point units.  With no hit the min
     * registers hold all ones and the max registers zero. */
    uint32_t xmin, xmax, ymin, ymax, zmin, zmax;
    /* Verbose hit list as OccU Control stored it: x,y pairs in arrival
     * order, at most list_capacity pairs; list_overflow once a hit found no
     * room (3.2.1). */
    uint32_t *list;
    uint32_t list_count, list_capacity, list_alloc;
    bool list_overflow;
} fs_occu_tile;

/* Per-engine work counters: what a cycle model needs to charge one cycle
 * per tile test (3.3.1: an engine with several tiles spends one more cycle
 * for each further tile). */
typedef struct fs_occu_engine {
    int index;
    int ntiles;            /* tiles assigned to it round robin */
    uint64_t fragments;    /* fragments it received */
    uint64_t tile_tests;   /* fragment-against-tile tests */
    uint64_t projection_hits; /* PHC increments it made (before saturation) */
    uint64_t hits;         /* NOHC increments it made (before saturation) */
} fs_occu_engine;

/* Clears a tile's registers (counters, box, list) for a new occlusion pass. */
void fs_occe_tile_reset(fs_occu_tile *t);

/* Tests one fragment against one tile and updates its registers exactly as
 * Fig. 3.17 describes: inside -> PHC; inside AND depth passed -> NOHC, box
 * and z range.  Returns true for a non-occlusion hit (the caller hands the
 * hit to OccU Control).  cmax is the counter maximum. */
static inline bool fs_occe_tile_fragment(fs_occu_tile *t, uint32_t cmax, int x, int y, uint32_t z, bool passed,
                                         uint64_t *projection_hits)
{
    if (x < t->x0 || x >= t->x1 || y < t->y0 || y >= t->y1)
        return false;
    (*projection_hits)++;
    if (t->phc < cmax)
        t->phc++;
    else
        t->phc_overflow = true;
    if (!passed)
        return false;
    if (t->nohc < cmax)
        t->nohc++;
    else
        t->nohc_overflow = true;
    uint32_t ux = (uint32_t)x, uy = (uint32_t)y;
    if (ux < t->xmin) t->xmin = ux;
    if (ux > t->xmax) t->xmax = ux;
    if (uy < t->ymin) t->ymin = uy;
    if (uy > t->ymax) t->ymax = uy;
    if (z < t->zmin) t->zmin = z;
    if (z > t->zmax) t->zmax = z;
    return true;
}

/* One engine processes one fragment: it tests the fragment against every
 * tile it owns, tiles e, e + stride, e + 2*stride, ... of tiles[0..ntiles)
 * (round-robin assignment, 3.3), in that order.  The indices of the tiles
 * that recorded a hit are written to hit_tiles (room for every owned tile);
 * returns how many, and the fragment's PHC increments in *projection_hits
 * (the engine's own totals count them too). */
unsigned fs_occe_fragment(fs_occu_engine *e, fs_occu_tile *tiles, int ntiles, int stride,
                          uint32_t cmax, int x, int y, uint32_t z, bool passed, int *hit_tiles,
                          uint64_t *projection_hits);
#endif
