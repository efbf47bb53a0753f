/*
 * The GL side of the Occlusion Unit: GL_FRAGSIM_occlusion_unit
 * (docs/extensions/occlusion_unit.txt; Huettner 1999, 3.2.1) -- glRenderMode
 * with GL_BRIEF_OCCLUSION / GL_VERBOSE_OCCLUSION, glScissors,
 * glOcclusionBuffers -- and the GL 1.5 occlusion queries (GL 1.5 spec
 * 4.1.7, 6.1.12), which the same unit answers with one unbounded tile whose
 * NOHC is GL_SAMPLES_PASSED.  The unit sees fragments through
 * fs_context.occlusion_hook, installed only while a mode or a query is
 * active, so the pipeline pays one branch per quad otherwise.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "occlusion_unit.h"
#include "../pipeline/context.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

typedef struct fs_query {
    GLuint id;
    bool ever_active; /* glIsQuery is true only once begun (as Mesa) */
    uint32_t result;
} fs_query;

struct fs_occlusion {
    fs_occu *unit;
    GLenum render_mode;
    /* glScissors: ntiles_spec tiles (0: the scissor box is the one tile). */
    int ntiles_spec;
    GLint *tiles_spec;
    /* glOcclusionBuffers: sizes of nbuffers buffers (0: not given) and the
     * client's buffer pointers (NULL when the call came from a trace). */
    int nbuffers;
    GLsizei *sizes;
    GLuint **client;
    /* Tiles of the running pass, latched at glRenderMode. */
    GLint *pass_rects;
    /* Occlusion queries: a whole-window tile counted apart from the pass's
     * tiles so that both may run at once. */
    fs_query *queries;
    int nqueries, queries_cap;
    GLuint max_query_id;   /* largest name ever used: Mesa's next name is +1 */
    GLuint active_query;   /* 0 when none */
    uint32_t query_count;
    bool query_overflow;
    /* GL_HP_occlusion_test: one flag, set when any fragment passes while
     * the test is enabled, cleared when it is read. */
    bool hp_enabled, hp_result;
};

/* Fixed layout of GL state tokens we rely on: GL/glext.h names them. */
#ifndef GL_SAMPLES_PASSED
#define GL_SAMPLES_PASSED 0x8914
#define GL_QUERY_COUNTER_BITS 0x8864
#define GL_CURRENT_QUERY 0x8865
#define GL_QUERY_RESULT 0x8866
#define GL_QUERY_RESULT_AVAILABLE 0x8867
#endif

static struct fs_occlusion *state(fs_context *c)
{
    if (c->occlusion)
        return c->occlusion;
    struct fs_occlusion *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    o->unit = fs_occu_create((int)c->cfg.occlusion_engines, (int)c->cfg.occlusion_counter_bits,
                             (int)c->cfg.occlusion_max_tiles);
    o->pass_rects = calloc((size_t)c->cfg.occlusion_max_tiles * 4, sizeof *o->pass_rects);
    if (!o->unit || !o->pass_rects) {
        fs_occu_destroy(o->unit);
        free(o->pass_rects);
        free(o);
        return NULL;
    }
    o->render_mode = GL_RENDER;
    c->occlusion = o;
    return o;
}

void fs_occlusion_free(fs_context *c)
{
    struct fs_occlusion *o = c->occlusion;
    if (!o)
        return;
    fs_occu_destroy(o->unit);
    free(o->tiles_spec);
    free(o->sizes);
    free(o->client);
    free(o->pass_rects);
    free(o->queries);
    free(o);
    c->occlusion = NULL;
}

GLenum fs_occlusion_render_mode(const fs_context *c)
{
    return c->occlusion ? c->occlusion->render_mode : (GLenum)GL_RENDER;
}

const fs_occu *fs_occlusion_unit(const fs_context *c)
{
    return c->occlusion ? c->occlusion->unit : NULL;
}

int fs_occlusion_set_hooks(fs_context *c, const fs_occu_hooks *hooks)
{
    struct fs_occlusion *o = state(c);
    if (!o)
        return -1;
    o->unit->hooks = *hooks;
    return 0;
}

static bool in_occlusion_mode(const struct fs_occlusion *o)
{
    return o && (o->render_mode == GL_BRIEF_OCCLUSION || o->render_mode == GL_VERBOSE_OCCLUSION);
}

/* ---- GL_HP_occlusion_test ---- */

static void update_hook(fs_context *c);

int fs_occlusion_hp_enable(fs_context *c, bool on)
{
    struct fs_occlusion *o = state(c);
    if (!o)
        return -1;
    /* Enabling does not clear the result; only reading it does (as Mesa's
     * implementation of the extension behaved). */
    o->hp_enabled = on;
    update_hook(c);
    return 0;
}

bool fs_occlusion_hp_enabled(const fs_context *c)
{
    return c->occlusion && c->occlusion->hp_enabled;
}

bool fs_occlusion_hp_take_result(fs_context *c)
{
    struct fs_occlusion *o = c->occlusion;
    if (!o)
        return false;
    bool r = o->hp_result;
    o->hp_result = false;
    return r;
}

int fs_occlusion_tiles_set(const fs_context *c)
{
    return c->occlusion ? c->occlusion->ntiles_spec : 0;
}

int fs_occlusion_tile_count(fs_context *c)
{
    const struct fs_occlusion *o = c->occlusion;
    return o && o->ntiles_spec > 0 ? o->ntiles_spec : 1;
}

/* ---- the hook: the Occlusion Unit's place after the depth test (3.3,
 * Fig. 3.16) ---- */
static void occlusion_hook(fs_context *c, void *user, const fs_quad *q, unsigned tested, unsigned passed)
{
    struct fs_occlusion *o = user;
    if (o->hp_enabled && passed)
        o->hp_result = true;
    if (in_occlusion_mode(o))
        fs_occu_quad(o->unit, q, tested, passed, &c->stats);
    if (o->active_query) {
        /* NOHC of an unbounded tile: every fragment that passed (the window
         * already bounds them), saturating like the tiles' counters. */
        unsigned n = (passed & 1u) + (passed >> 1 & 1u) + (passed >> 2 & 1u) + (passed >> 3 & 1u);
        uint32_t max = o->unit->counter_max;
        if (max - o->query_count < n) {
            o->query_count = max;
            o->query_overflow = true;
        } else {
            o->query_count += n;
        }
        c->stats.query_samples += n;
    }
}

static void update_hook(fs_context *c)
{
    struct fs_occlusion *o = c->occlusion;
    bool on = in_occlusion_mode(o) || (o && (o->active_query || o->hp_enabled));
    c->occlusion_hook = on ? occlusion_hook : NULL;
    c->occlusion_user = on ? o : NULL;
    c->frag.suppress_writes = in_occlusion_mode(o);
    fs_state_mark(c, FS_DIRTY_OCCLUSION_MODE);
}

/* ---- glRenderMode (GL 1.5 spec 5.2-5.3; Huettner 1999, 3.2.1) ---- */

/* Leaves an occlusion mode: writes every tile's record into its client
 * buffer and returns how many tiles overflowed (3.2.1). */
static GLint finish_pass(fs_context *c, struct fs_occlusion *o)
{
    GLint overflowed = 0;
    const fs_occu *u = o->unit;
    for (int t = 0; t < u->ntiles; t++) {
        if (fs_occu_tile_overflowed(u, t))
            overflowed++;
        if (o->client && o->client[t])
            fs_occu_write_record(u, t, o->client[t], (size_t)o->sizes[t]);
    }
    c->stats.occlusion_overflows += (uint64_t)overflowed;
    return overflowed;
}

static int start_pass(fs_context *c, struct fs_occlusion *o, GLenum mode)
{
    int n = fs_occlusion_tile_count(c);
    if (o->ntiles_spec > 0)
        memcpy(o->pass_rects, o->tiles_spec, (size_t)n * 4 * sizeof *o->pass_rects);
    else
        memcpy(o->pass_rects, c->frag.scissor, 4 * sizeof *o->pass_rects);
    uint32_t *cap = malloc((size_t)n * sizeof *cap);
    if (!cap)
        return -1;
    for (int t = 0; t < n; t++)
        cap[t] = fs_occu_list_capacity((size_t)o->sizes[t]);
    int rc = fs_occu_begin(o->unit, n, o->pass_rects, cap, mode == GL_VERBOSE_OCCLUSION);
    free(cap);
    return rc;
}

GLint fs_exec_RenderMode(fs_context *c, GLenum mode)
{
    bool occlusion = mode == GL_BRIEF_OCCLUSION || mode == GL_VERBOSE_OCCLUSION;
    if (!occlusion && mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
        fs_error(c, GL_INVALID_ENUM);
        return 0;
    }
    /* GL_SELECT and GL_FEEDBACK need their buffers (GL 1.5 spec 5.2, 5.3;
     * pipeline/render_mode.c); without one Mesa raises the error and enters
     * the mode all the same (measured: GL_RENDER_MODE is then GL_SELECT). */
    if (!fs_render_mode_may_enter(c, mode))
        fs_error(c, GL_INVALID_OPERATION);
    if (!occlusion && !in_occlusion_mode(c->occlusion) && (mode != GL_RENDER || !c->occlusion)) {
        /* GL_SELECT and GL_FEEDBACK too: leaving them returns the pass's
         * records, so the cycle model drains there as well (the cost of
         * VFC in selection mode, Huettner 1999, 3.1.6). */
        GLint ret = fs_render_mode_switch(c, mode);
        FS_OBSERVE(c, render_mode, c, mode);
        return ret;
    }
    struct fs_occlusion *o = state(c);
    if (!o) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return 0;
    }
    /* Like GL_SELECT before glSelectBuffer (GL 1.5 spec 5.2): an occlusion
     * mode needs one buffer per current tile. */
    if (occlusion && o->nbuffers != fs_occlusion_tile_count(c)) {
        fs_error(c, GL_INVALID_OPERATION);
        return 0;
    }
    GLint ret = in_occlusion_mode(o) ? finish_pass(c, o) : fs_render_mode_switch(c, GL_RENDER);
    o->render_mode = GL_RENDER;
    if (occlusion) {
        if (start_pass(c, o, mode) != 0) {
            fs_error(c, GL_OUT_OF_MEMORY);
        } else {
            o->render_mode = mode;
        }
    } else {
        fs_render_mode_switch(c, mode);
    }
    update_hook(c);
    FS_OBSERVE(c, render_mode, c, mode);
    return ret;
}

/* ---- glScissors, glOcclusionBuffers (3.2.1) ---- */

void fs_exec_Scissors(fs_context *c, GLint numTiles, const GLint *tiles)
{
    struct fs_occlusion *o = c->occlusion;
    if (in_occlusion_mode(o)) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    if (numTiles < 0 || numTiles > c->cfg.occlusion_max_tiles) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    for (GLint t = 0; t < numTiles; t++) {
        if (tiles[4 * t + 2] < 0 || tiles[4 * t + 3] < 0) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
    }
    if (!o && !(o = state(c))) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    GLint *copy = NULL;
    if (numTiles > 0) {
        copy = malloc((size_t)numTiles * 4 * sizeof *copy);
        if (!copy) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        memcpy(copy, tiles, (size_t)numTiles * 4 * sizeof *copy);
    }
    free(o->tiles_spec);
    o->tiles_spec = copy;
    o->ntiles_spec = numTiles;
}

void fs_exec_OcclusionBuffers(fs_context *c, const GLint *sizes, const GLvoid *buffers)
{
    struct fs_occlusion *o = c->occlusion;
    if (in_occlusion_mode(o)) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    int n = fs_occlusion_tile_count(c);
    for (int t = 0; t < n; t++) {
        if (sizes[t] < GL_OCCLUSION_RECORD_WORDS) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
    }
    if (!o && !(o = state(c))) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    GLsizei *ns = malloc((size_t)n * sizeof *ns);
    GLuint **nc = buffers ? malloc((size_t)n * sizeof *nc) : NULL;
    if (!ns || (buffers && !nc)) {
        free(ns);
        free(nc);
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    memcpy(ns, sizes, (size_t)n * sizeof *ns);
    /* The pointer array is read now (it may be a temporary); the buffers
     * themselves are written at glRenderMode, like glSelectBuffer's. */
    if (nc)
        memcpy(nc, buffers, (size_t)n * sizeof *nc);
    free(o->sizes);
    free(o->client);
    o->sizes = ns;
    o->client = nc;
    o->nbuffers = n;
}

/* ---- occlusion queries (GL 1.5 spec 4.1.7, 6.1.12) ---- */

static fs_query *find_query(struct fs_occlusion *o, GLuint id)
{
    if (!o || id == 0)
        return NULL;
    for (int i = 0; i < o->nqueries; i++)
        if (o->queries[i].id == id)
            return &o->queries[i];
    return NULL;
}

bool fs_occlusion_query_result(const fs_context *c, GLuint id, uint64_t *result)
{
    const fs_query *q = find_query(c->occlusion, id);
    if (q)
        *result = (uint64_t)q->result;
    return q != NULL;
}

static fs_query *add_query(struct fs_occlusion *o, GLuint id)
{
    if (o->nqueries == o->queries_cap) {
        int cap = o->queries_cap ? o->queries_cap * 2 : 16;
        fs_query *p = realloc(o->queries, (size_t)cap * sizeof *p);
        if (!p)
            return NULL;
        o->queries = p;
        o->queries_cap = cap;
    }
    fs_query *q = &o->queries[o->nqueries++];
    memset(q, 0, sizeof *q);
    q->id = id;
    if (id > o->max_query_id)
        o->max_query_id = id;
    return q;
}

void fs_exec_GenQueries(fs_context *c, GLsizei n, GLuint *ids)
{
    /* At most FS_MAX_NAMES queries held (fs_gen_names_ok). */
    if (!fs_gen_names_ok(c, n, c->occlusion ? (size_t)c->occlusion->nqueries : 0))
        return;
    struct fs_occlusion *o = state(c);
    if (!o) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    /* Mesa hands out the names after the largest name ever used. */
    GLuint first = o->max_query_id + 1;
    for (GLsizei i = 0; i < n; i++) {
        if (!add_query(o, first + (GLuint)i)) {
            fs_error(c, GL_OUT_OF_MEMORY);
            return;
        }
        ids[i] = first + (GLuint)i;
    }
}

void fs_exec_DeleteQueries(fs_context *c, GLsizei n, const GLuint *ids)
{
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    struct fs_occlusion *o = c->occlusion;
    for (GLsizei i = 0; i < n && o; i++) {
        fs_query *q = find_query(o, ids[i]);
        if (!q)
            continue; /* unused names are silently ignored (4.1.7) */
        if (o->active_query == q->id) {
            /* Deleting the active query ends it (as Mesa does). */
            o->active_query = 0;
            update_hook(c);
        }
        *q = o->queries[--o->nqueries];
    }
}

GLboolean fs_exec_IsQuery(fs_context *c, GLuint id)
{
    fs_query *q = find_query(c->occlusion, id);
    return q && q->ever_active ? GL_TRUE : GL_FALSE;
}

void fs_exec_BeginQuery(fs_context *c, GLenum target, GLuint id)
{
    if (target != GL_SAMPLES_PASSED) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    struct fs_occlusion *o = state(c);
    if (!o) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    if (o->active_query || id == 0) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    fs_query *q = find_query(o, id);
    /* A compatibility context accepts names never generated (as Mesa). */
    if (!q && !(q = add_query(o, id))) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    q->ever_active = true;
    o->active_query = id;
    o->query_count = 0;
    o->query_overflow = false;
    update_hook(c);
    FS_OBSERVE(c, query_begin, c, id);
}

void fs_exec_EndQuery(fs_context *c, GLenum target)
{
    if (target != GL_SAMPLES_PASSED) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    struct fs_occlusion *o = c->occlusion;
    if (!o || !o->active_query) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    fs_query *q = find_query(o, o->active_query);
    if (q)
        q->result = o->query_count;
    o->active_query = 0;
    update_hook(c);
    FS_OBSERVE(c, query_end, c);
}

void fs_exec_GetQueryiv(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    if (target != GL_SAMPLES_PASSED) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    switch (pname) {
    case GL_CURRENT_QUERY:
        *params = c->occlusion ? (GLint)c->occlusion->active_query : 0;
        return;
    case GL_QUERY_COUNTER_BITS:
        *params = (GLint)c->cfg.occlusion_counter_bits;
        return;
    default:
        fs_error(c, GL_INVALID_ENUM);
    }
}

/* Returns the query's result through *v, or false after raising the error. */
static bool query_value(fs_context *c, GLuint id, GLenum pname, uint32_t *v)
{
    struct fs_occlusion *o = c->occlusion;
    fs_query *q = find_query(o, id);
    if (!q || !q->ever_active || o->active_query == id) {
        fs_error(c, GL_INVALID_OPERATION);
        return false;
    }
    switch (pname) {
    case GL_QUERY_RESULT:
        *v = q->result;
        FS_OBSERVE(c, query_wait, c, id);
        return true;
    case GL_QUERY_RESULT_AVAILABLE:
        /* The model finishes every command when it is issued. */
        *v = GL_TRUE;
        return true;
    default:
        fs_error(c, GL_INVALID_ENUM);
        return false;
    }
}

void fs_exec_GetQueryObjectiv(fs_context *c, GLuint id, GLenum pname, GLint *params)
{
    uint32_t v;
    if (query_value(c, id, pname, &v))
        *params = v > INT_MAX ? INT_MAX : (GLint)v; /* clamped, as Mesa does */
}

void fs_exec_GetQueryObjectuiv(fs_context *c, GLuint id, GLenum pname, GLuint *params)
{
    uint32_t v;
    if (query_value(c, id, pname, &v))
        *params = v;
}

/* ---- GL_ARB_occlusion_query entry points: the same commands ---- */
void fs_exec_GenQueriesARB(fs_context *c, GLsizei n, GLuint *ids) { fs_exec_GenQueries(c, n, ids); }
void fs_exec_DeleteQueriesARB(fs_context *c, GLsizei n, const GLuint *ids) { fs_exec_DeleteQueries(c, n, ids); }
GLboolean fs_exec_IsQueryARB(fs_context *c, GLuint id) { return fs_exec_IsQuery(c, id); }
void fs_exec_BeginQueryARB(fs_context *c, GLenum target, GLuint id) { fs_exec_BeginQuery(c, target, id); }
void fs_exec_EndQueryARB(fs_context *c, GLenum target) { fs_exec_EndQuery(c, target); }
void fs_exec_GetQueryivARB(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    fs_exec_GetQueryiv(c, target, pname, params);
}
void fs_exec_GetQueryObjectivARB(fs_context *c, GLuint id, GLenum pname, GLint *params)
{
    fs_exec_GetQueryObjectiv(c, id, pname, params);
}
void fs_exec_GetQueryObjectuivARB(fs_context *c, GLuint id, GLenum pname, GLuint *params)
{
    fs_exec_GetQueryObjectuiv(c, id, pname, params);
}
