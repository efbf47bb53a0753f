/*
 * The Occlusion Unit (OccU) of Huettner 1999, 3.2-3.3 (after Bartz,
 * Meissner, Huettner, Graphics Hardware 1998): functional and bit-accurate.
 *
 *   per-fragment operations --(x, y, z, depth pass)--> OccU
 *     OccU = engines 0..E-1, tiles assigned round robin (tile t to engine
 *            t mod E), each engine testing a fragment against its tiles
 *            (occlusion_engine.c), and OccU Control serialising the
 *            engines' hit-list writes to memory (like Selection Control).
 *
 * fs_occu is independent of the GL context: occlusion_gl.c attaches it to
 * fs_context.occlusion_hook and implements the GL commands
 * (GL_FRAGSIM_occlusion_unit, GL 1.5 occlusion queries).
 */
#ifndef FS_OCCLUSION_UNIT_H
#define FS_OCCLUSION_UNIT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <GL/gl.h>
#include "occlusion_engine.h"
#include "../pipeline/rasterizer.h"
#include "../pipeline/stats.h"

typedef struct fs_context fs_context;

/* Observation points for a cycle model (a later issue).  All optional; each
 * is called in the unit's deterministic processing order. */
typedef struct fs_occu_hooks {
    void *user;
    /* Engine `engine` processed the fragment at (x, y): it made `tests`
     * tile tests (one cycle each, 3.3.1) and found `hits` hits. */
    void (*engine_fragment)(void *user, int engine, int x, int y, unsigned tests, unsigned hits);
    /* OccU Control granted engine `engine` a memory write: hit (x, y) of
     * tile `tile` into list slot `slot` (stored == false: the list was full,
     * nothing written, the overflow flag set). */
    void (*control_write)(void *user, int engine, int tile, int x, int y, uint32_t slot, bool stored);
} fs_occu_hooks;

typedef struct fs_occu {
    int nengines;
    uint32_t counter_max;     /* 2^counter_bits - 1 */
    int max_tiles;
    fs_occu_engine *engines;
    fs_occu_tile *tiles;      /* max_tiles of them */
    int ntiles;               /* tiles of the current pass */
    bool verbose;             /* store hit lists */
    int *hit_scratch;         /* hit tile indices of one engine step */
    fs_occu_hooks hooks;
} fs_occu;

/* Creates a unit with `engines` engines, counters of `counter_bits` bits
 * (1..32) and room for `max_tiles` tiles.  NULL when out of memory or when
 * an argument is out of range. */
fs_occu *fs_occu_create(int engines, int counter_bits, int max_tiles);
void fs_occu_destroy(fs_occu *u);

/* Starts a pass: n tiles given as x, y, width, height (window pixels, width
 * and height >= 0), and per tile the number of hits its list may hold
 * (ignored unless verbose).  Counters, boxes and lists are reset.  Returns
 * -1 when n is out of range or out of memory. */
int fs_occu_begin(fs_occu *u, int n, const GLint *rects, const uint32_t *list_capacity, bool verbose);

/* The per-fragment input: one quad from the depth test with the mask of
 * pixels that reached it (tested) and the mask that passed it (passed).
 * Pixels are processed in quad order 0..3, engines in index order.  When
 * stats is not NULL the occlusion_* counters are added to it. */
void fs_occu_quad(fs_occu *u, const fs_quad *q, unsigned tested, unsigned passed, fs_stats *stats);

/* Words of tile t's record in a buffer of `size` words (>= 8): the brief
 * record NOHC, PHC, Xmin, Xmax, Ymin, Ymax, Zmin, Zmax, and when verbose the
 * stored hits as x, y pairs followed by 0xFFFFFFFF (-1) if a word is left.
 * Writes into buf (which may be NULL to only count); returns the words used. */
size_t fs_occu_write_record(const fs_occu *u, int t, GLuint *buf, size_t size);

/* Hits a verbose list in a buffer of `size` words can hold. */
uint32_t fs_occu_list_capacity(size_t size);

/* Did tile t overflow: a saturated counter, or (verbose) a hit that found
 * no room in its list? */
bool fs_occu_tile_overflowed(const fs_occu *u, int t);

/* ---- the GL side (occlusion_gl.c) ---- */
/* Frees the unit and the GL occlusion state of a context (fs_context_destroy). */
void fs_occlusion_free(fs_context *c);
/* The render mode (GL_RENDER, GL_BRIEF_OCCLUSION, GL_VERBOSE_OCCLUSION). */
GLenum fs_occlusion_render_mode(const fs_context *c);
/* Tiles set by glScissors (0: the scissor box is the one tile). */
int fs_occlusion_tiles_set(const fs_context *c);
/* GL_HP_occlusion_test: glEnable/glDisable(GL_OCCLUSION_TEST_HP), and
 * GL_OCCLUSION_TEST_RESULT_HP, which reports whether any fragment passed the
 * depth test while the test was enabled since the last read, then clears. */
int fs_occlusion_hp_enable(fs_context *c, bool on);
bool fs_occlusion_hp_enabled(const fs_context *c);
bool fs_occlusion_hp_take_result(fs_context *c);
/* The unit of a context, or NULL before any occlusion command.  Its tiles
 * keep the last pass's results until the next pass starts, also when no
 * client buffers were given (a replayed trace). */
const fs_occu *fs_occlusion_unit(const fs_context *c);
/* The result of query `id` as glEndQuery stored it (GL 1.5 4.1.7; the
 * cycle model's occlusion_result signal); false when there is no such query. */
bool fs_occlusion_query_result(const fs_context *c, GLuint id, uint64_t *result);
/* Installs cycle-model hooks on the context's unit (creating it). */
int fs_occlusion_set_hooks(fs_context *c, const fs_occu_hooks *hooks);
#endif
