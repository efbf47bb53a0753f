/*
 * The MIPmap pyramid grid (MP-Grid) of Huettner's dissertation (Tuebingen
 * 1999), section 4.1: a large texture split into n x m MIPmap pyramids of
 * power-of-two tiles, all with the same number of levels, addressed by
 * texture coordinates in [0..n] x [0..m].
 *
 * Hardware (4.1.4, Fig. 4.7): a current texture register (CTR) holds, per
 * level lambda, a pointer into a 3-D pointer table indexed by (lambda, i, j).
 * When the interpolated coordinates leave the current pyramid, the entry
 * indexed by the truncated coordinates is loaded into the CTR for that
 * level.  An optional extension size per entry lets the small levels of
 * neighbouring pyramids be stored merged in one block; the border
 * comparators then use the block's extent, so low levels cause no reloads
 * ("pointer thrashing").
 *
 * Residency (4.1.1, Fig. 4.2): per pyramid the finest level needed follows
 * from the projected screen size of the bounding box of the polygons it
 * textures, rounded up to a power of two; an occluded box needs no level;
 * where a level is not resident the best (finest coarser) resident level
 * is used.
 *
 * Files: mpgrid_ctr.c (layout, pointer table, CTR, texel fetch),
 * mpgrid_residency.c (per-frame residency manager), clip_map.c (the
 * Clip-Map memory model compared against in 4.1.2), mpgrid_gl.c (the GL
 * extension GL_FRAGSIM_mp_grid, docs/extensions/mp_grid.txt).
 * No global state: everything lives in the structs below.
 */
#ifndef FS_MPGRID_H
#define FS_MPGRID_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Largest grid accepted (pyramids per side) and largest tile side: the
 * pointer table of the paper's example (100 x 100, 11 levels) fits well. */
#define FS_MPGRID_MAX_PYRAMIDS 4096
#define FS_MPGRID_MAX_TILE 4096
#define FS_MPGRID_MAX_LEVELS 13

/* ---- layout: minimal scaling (4.1.1) ---- */

typedef struct fs_mpgrid_layout {
    int tile_w, tile_h;        /* level-0 size of every pyramid, powers of two */
    int n, m;                  /* pyramids along s and t */
    int levels;                /* levels per pyramid: log2(max side) + 1 */
    int64_t scaled_w, scaled_h; /* n*tile_w, m*tile_h: the size the image is scaled to */
} fs_mpgrid_layout;

/* Chooses the tile for an img_w x img_h image: the tile sides range over the
 * powers of two in [min_tile, max_tile] independently (so a tile may be
 * 1024x512); the tile that scales the image least (smallest n*w x m*h area)
 * wins, ties going to the larger tile (fewer pyramids), then to the wider.
 * Returns 0, or -1 on bad input (non-positive sizes, tiles not powers of two,
 * min > max, more than FS_MPGRID_MAX_PYRAMIDS per side). */
int fs_mpgrid_choose_layout(int64_t img_w, int64_t img_h, int min_tile, int max_tile, fs_mpgrid_layout *out);
/* A layout of n x m pyramids of tile_w x tile_h; 0 or -1 on bad input. */
int fs_mpgrid_make_layout(int n, int m, int tile_w, int tile_h, fs_mpgrid_layout *out);
/* Size of level `level` of one pyramid (GL's max(1, size >> level)). */
int fs_mpgrid_level_w(const fs_mpgrid_layout *L, int level);
int fs_mpgrid_level_h(const fs_mpgrid_layout *L, int level);
/* Bytes of levels first..levels-1 of one pyramid (exact sum of the level
 * sizes); first == levels gives 0. */
uint64_t fs_mpgrid_pyramid_bytes(const fs_mpgrid_layout *L, int first, int bytes_per_texel);
/* Pointer-table bytes (4.1.4): levels * n * m * (pointer + extension). */
uint64_t fs_mpgrid_table_bytes(int levels, int64_t n, int64_t m, int pointer_bytes, int extension_bytes);

/* ---- the grid: pointer table and resident level images ---- */

/* One pointer-table entry (lambda, i, j).  For a merged block the entries of
 * all its pyramids point to the same store; (i0, j0) is the block's first
 * pyramid and (ext_i, ext_j) its extension size in pyramids (1 x 1 when not
 * merged).  texels == NULL: the level is not resident. */
typedef struct fs_mpgrid_entry {
    uint8_t *texels;           /* RGBA8, the block's rows, row 0 at t near 0 */
    int pitch;                 /* texels per row of the block */
    int i0, j0, ext_i, ext_j;
} fs_mpgrid_entry;

typedef struct fs_mpgrid {
    fs_mpgrid_layout L;
    int bytes_per_texel;       /* for memory accounting (the store is RGBA8) */
    /* Levels whose larger side is <= merge_side are stored merged in
     * blocks of merge_block x merge_block pyramids and stay resident
     * (4.1.4: "it can be economical not to remove such low levels");
     * merge_side 0: no merging. */
    int merge_side, merge_block;
    /* The application's images ("on disk", 4.1.1): src[(level*m + j)*n + i],
     * NULL until supplied.  Loading copies them into the resident store. */
    uint8_t **src;
    fs_mpgrid_entry *table;    /* [(level*m + j)*n + i] */
    int *finest;               /* per pyramid: finest resident level (levels: none) */
    uint64_t bytes_resident, levels_loaded, levels_freed;
} fs_mpgrid;

/* Creates an empty grid (no images, nothing resident).  merge_side 0
 * disables merging; merge_block must then be 1 or 0.  Returns 0 or -1. */
int fs_mpgrid_init(fs_mpgrid *g, const fs_mpgrid_layout *L, int bytes_per_texel, int merge_side, int merge_block);
void fs_mpgrid_free(fs_mpgrid *g);
/* Supplies (copies) the RGBA8 image of level `level` of pyramid (i, j),
 * fs_mpgrid_level_w x _h texels.  If that level is resident its store is
 * refreshed.  Returns 0 or -1 (bad indices, no memory). */
int fs_mpgrid_set_image(fs_mpgrid *g, int i, int j, int level, const uint8_t *rgba);
/* True when the level is stored merged. */
bool fs_mpgrid_level_merged(const fs_mpgrid *g, int level);
/* Makes levels finest..levels-1 of pyramid (i, j) resident and frees the
 * finer ones (merged levels are always resident once supplied).  Levels
 * without a supplied image stay absent.  Returns 0 or -1 (no memory). */
int fs_mpgrid_set_finest(fs_mpgrid *g, int i, int j, int finest);
/* Entry (level, i, j), or NULL for indices outside the grid. */
const fs_mpgrid_entry *fs_mpgrid_entry_at(const fs_mpgrid *g, int level, int i, int j);

/* ---- the current texture register ---- */

typedef struct fs_mpgrid_ctr {
    /* Per level (FS_MPGRID_MAX_LEVELS >= FS_TEX_MAX_LEVELS): the pointer
     * into the table (valid == false after reset) and the block loaded
     * before it, for the thrashing count.  The register must be reset when
     * the grid is freed or re-initialised (it points into the table). */
    struct fs_mpgrid_ctr_level {
        bool valid;
        int i, j;                    /* pyramid whose entry was loaded */
        int i0, j0, ext_i, ext_j;    /* the comparators' extent */
        int prev_i, prev_j;          /* the pyramid loaded before, -1: none */
        const fs_mpgrid_entry *entry; /* the pointer-table entry held */
    } lv[FS_MPGRID_MAX_LEVELS];
    uint64_t reloads;       /* entries loaded into the CTR */
    /* Reloads that return to the pyramid the level's CTR held just before
     * (A -> B -> A): the ping-pong the extension size avoids (4.1.4). */
    uint64_t thrashing;
    uint64_t substitutions; /* fetches served by a coarser resident level */
    uint64_t misses;        /* fetches with no resident level at all */
} fs_mpgrid_ctr;

void fs_mpgrid_ctr_reset(fs_mpgrid_ctr *r);
/* Fetches texel (x, y) of level `level`, in texels of that level across
 * the whole grid (x in [0, n*level_w)), through the CTR: the pyramid is
 * x / level_w (the truncated texture coordinate); when it lies outside the
 * CTR's current extent for that level the entry is reloaded.  If the level
 * is not resident the best resident coarser level of that pyramid is read
 * at (x, y) >> (difference) and counted as a substitution.  Coordinates
 * outside the grid are clamped to the edge.  Returns the level read, or -1
 * when the pyramid has no resident level (out is then 0,0,0,0). */
int fs_mpgrid_fetch(const fs_mpgrid *g, fs_mpgrid_ctr *r, int level, int64_t x, int64_t y, uint8_t out[4]);

/* ---- residency (mpgrid_residency.c) ---- */

/* A camera: clip = M * (x, y, z, 1) with M column-major (GL's projection *
 * modelview), and a viewport of vp_w x vp_h pixels. */
typedef struct fs_mpgrid_camera {
    double m[16];
    int vp_w, vp_h;
} fs_mpgrid_camera;

/* Builds M from gluLookAt(eye, center, up) and gluPerspective(fovy, aspect,
 * znear, zfar) (GLU 1.3 sections 4.2 and 6.2).  Returns -1 for non-finite
 * or degenerate input (eye == center, up parallel to the view, fovy
 * outside (0, 180), znear <= 0, zfar <= znear, viewport <= 0). */
int fs_mpgrid_camera_lookat(fs_mpgrid_camera *cam, const double eye[3], const double center[3], const double up[3],
                            double fovy_deg, double znear, double zfar, int vp_w, int vp_h);

/* Screen extent in pixels (max of width and height) of the projection of
 * the axis-aligned box [lo, hi], clipped to the view frustum; 0 when no
 * part is in view, -1 for non-finite input. */
double fs_mpgrid_projected_extent(const fs_mpgrid_camera *cam, const double lo[3], const double hi[3]);
/* The finest level a pyramid needs for a projected extent of `extent`
 * pixels: the extent rounded up to a power of two r, level
 * log2(max side) - log2(r), clamped to 0 (4.1.1, Fig. 4.2).  extent <= 0
 * gives L->levels (no level needed). */
int fs_mpgrid_needed_level(const fs_mpgrid_layout *L, double extent);

/* Per pyramid input to one adaptation. */
typedef struct fs_mpgrid_box {
    double lo[3], hi[3];
    bool occluded;             /* known occluded (e.g. by the Occlusion Unit) */
    bool unbounded;            /* no box known: conservatively needs level 0 */
} fs_mpgrid_box;

typedef struct fs_mpgrid_frame {
    uint64_t bytes_resident, levels_loaded, levels_freed;
    int pyramids_visible;
} fs_mpgrid_frame;

/* Adapts the grid to a camera: for every pyramid the needed level from its
 * box (boxes[j*n + i]), then loads and frees levels.  Levels whose larger
 * side is <= keep_side stay resident everywhere (0: none).  Fills *fr with
 * this adaptation's counts.  Returns 0, or -1 on bad input / no memory
 * (then the grid is unchanged or partially adapted, still consistent). */
int fs_mpgrid_adapt(fs_mpgrid *g, const fs_mpgrid_camera *cam, const fs_mpgrid_box *boxes, int keep_side,
                    fs_mpgrid_frame *fr);
/* Memory the adapted grid would occupy, without loading anything: the sum
 * over pyramids of fs_mpgrid_pyramid_bytes from the needed level (the
 * paper's "amount of memory needed for the adapted MP-Grid"). */
int fs_mpgrid_adapted_bytes(const fs_mpgrid_layout *L, const fs_mpgrid_camera *cam, const fs_mpgrid_box *boxes,
                            int bytes_per_texel, int keep_side, uint64_t *bytes, int *needed_out);

/* ---- Clip-Map memory model (clip_map.c; Tanner et al. 1998, 4.1.2) ---- */

/* Bytes of a Clip-Map of a size x size image (power of two) whose levels
 * larger than clip x clip are clipped to clip x clip: the clipped levels
 * plus the full pyramid below.  0 on bad input. */
uint64_t fs_clip_map_bytes(int64_t size, int64_t clip, int bytes_per_texel);
/* The power-of-two size a w x h image is scaled up to for a Clip-Map
 * (square, 4.1.2); 0 on bad input. */
int64_t fs_clip_map_scaled_size(int64_t w, int64_t h);
#endif
