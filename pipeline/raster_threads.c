/*
 * Threaded functional rasterization: the recorder, the persistent worker
 * pool and the join (raster_threads.h has the design and the rule that
 * keeps it deterministic).
 */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "context.h"
#include "raster_threads.h"
#include "render_mode.h"
#include "validate.h"
#include "../units/texture_unit.h"

#define MAX_THREADS 8

typedef struct worker {
    struct fs_raster_par *par;
    int index;
    pthread_t thread;
    fs_context *ctx;            /* this thread's copy of the context */
    struct fs_texture_state *tex; /* ... and of the texture unit's state */
} worker;

struct fs_raster_par {
    int n;                      /* threads, the calling one included */
    fs_rvertex *tri;            /* 3 per recorded triangle */
    size_t count;
    double pixels;              /* the recorded boxes' area, clamped to the window */
    pthread_mutex_t lock;
    pthread_cond_t start, done;
    unsigned long generation;   /* bumped per batch handed out */
    int busy;                   /* workers still running the batch */
    bool quit;
    worker w[MAX_THREADS];      /* w[0] is the calling thread */
    unsigned long batches_parallel, batches_serial;
};

int fs_par_resolve_threads(long cfg_threads)
{
    long n = cfg_threads;
    if (n <= 0) {
        n = sysconf(_SC_NPROCESSORS_ONLN);
        if (n < 1)
            n = 1;
    }
    return (int)(n > MAX_THREADS ? MAX_THREADS : n);
}

/* The bands of rows of a thread: thread i of n owns GL rows y with
 * (y >> FS_PAR_BAND_SHIFT) mod n == i. */
static void run_batch(const struct fs_raster_par *p, fs_context *c)
{
    for (size_t t = 0; t < p->count; t++) {
        const fs_rvertex *v = &p->tri[3 * t];
        fs_raster_triangle_now(c, &v[0], &v[1], &v[2]);
    }
}

static void *worker_main(void *arg)
{
    worker *w = arg;
    struct fs_raster_par *p = w->par;
    unsigned long seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (!p->quit && p->generation == seen)
            pthread_cond_wait(&p->start, &p->lock);
        if (p->quit)
            break;
        seen = p->generation;
        pthread_mutex_unlock(&p->lock);
        run_batch(p, w->ctx);
        pthread_mutex_lock(&p->lock);
        if (--p->busy == 0)
            pthread_cond_signal(&p->done);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static void pool_stop(struct fs_raster_par *p, int started)
{
    pthread_mutex_lock(&p->lock);
    p->quit = true;
    pthread_cond_broadcast(&p->start);
    pthread_mutex_unlock(&p->lock);
    for (int i = 1; i < started; i++) {
        pthread_join(p->w[i].thread, NULL);
        free(p->w[i].ctx);
        free(p->w[i].tex);
    }
}

/* Made on the first draw that may go parallel; NULL (and the draw serial)
 * when out of memory or threads. */
static struct fs_raster_par *pool_get(fs_context *c, int n)
{
    struct fs_raster_par *p = c->par;
    if (p && p->n == n)
        return p;
    fs_par_free(c);
    p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    p->tri = malloc(sizeof *p->tri * 3 * FS_PAR_BATCH);
    if (!p->tri) {
        free(p);
        return NULL;
    }
    p->n = n;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->start, NULL);
    pthread_cond_init(&p->done, NULL);
    int i;
    for (i = 1; i < n; i++) {
        worker *w = &p->w[i];
        w->par = p;
        w->index = i;
        w->ctx = malloc(sizeof *w->ctx);
        w->tex = malloc(fs_texture_state_bytes());
        if (!w->ctx || !w->tex || pthread_create(&w->thread, NULL, worker_main, w) != 0) {
            free(w->ctx);
            free(w->tex);
            break;
        }
    }
    if (i < n) {
        pool_stop(p, i);
        free(p->tri);
        free(p);
        return NULL;
    }
    c->par = p;
    return p;
}

void fs_par_free(fs_context *c)
{
    struct fs_raster_par *p = c->par;
    if (!p)
        return;
    pool_stop(p, p->n);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->start);
    pthread_cond_destroy(&p->done);
    free(p->tri);
    free(p);
    c->par = NULL;
}

void fs_par_draw_begin(fs_context *c, GLenum mode, bool route, bool tri_hook)
{
    if (c->cfg.raster_threads == 1 && !c->par)
        return;
    int n = fs_par_resolve_threads(c->cfg.raster_threads);
    bool tri_mode = mode == GL_TRIANGLES || mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN ||
                    mode == GL_QUADS || mode == GL_QUAD_STRIP || mode == GL_POLYGON;
    /* Everything the fragment path could share between threads keeps the
     * draw on one thread (raster_threads.h). */
    if (n < 2 || !tri_mode || route || tri_hook || c->observer || c->occlusion_hook ||
        fs_render_mode_diverts(&c->rmode) || c->raster.reference_path || !fs_texture_par_safe(c))
        return;
    struct fs_raster_par *p = pool_get(c, n);
    if (!p)
        return;
    c->par_recording = true;
    p->count = 0;
    p->pixels = 0.0;
}

static void add_stats(fs_stats *to, const fs_stats *from, bool per_triangle)
{
#define FS_STAT(name, unit, meaning) to->name += from->name;
#include "stats.def"
#undef FS_STAT
    if (!per_triangle) {
        /* Every thread snaps and counts every triangle (culled, or handed
         * to the rasterizer); thread 0's count stands for all. */
        to->triangles_culled -= from->triangles_culled;
        to->triangles_rasterized -= from->triangles_rasterized;
    }
}

/* Rasterizes the recorded triangles: on this thread alone when they are
 * too few pixels, else on all. */
static void flush(fs_context *c)
{
    struct fs_raster_par *p = c->par;
    if (!p->count)
        return;
    if (p->pixels < FS_PAR_MIN_PIXELS) {
        p->batches_serial++;
        c->par_recording = false;
        run_batch(p, c);
        c->par_recording = true;
        p->count = 0;
        p->pixels = 0.0;
        return;
    }
    p->batches_parallel++;
    /* What the fragment path would derive lazily is derived now, before
     * the copies: the fragment key and path (validate.c). */
    if (c->dirty)
        fs_validate(c);
    c->par_recording = false;
    c->raster.band_n = p->n;
    for (int i = 1; i < p->n; i++) {
        worker *w = &p->w[i];
        memcpy(w->ctx, c, sizeof *c);
        memset(&w->ctx->stats, 0, sizeof w->ctx->stats);
        w->ctx->raster.band_i = i;
        w->ctx->par = NULL;
        if (c->texture) {
            fs_texture_fork(c, w->tex);
            w->ctx->texture = w->tex;
        }
    }
    c->raster.band_i = 0;
    pthread_mutex_lock(&p->lock);
    p->busy = p->n - 1;
    p->generation++;
    pthread_cond_broadcast(&p->start);
    pthread_mutex_unlock(&p->lock);
    run_batch(p, c);
    pthread_mutex_lock(&p->lock);
    while (p->busy)
        pthread_cond_wait(&p->done, &p->lock);
    pthread_mutex_unlock(&p->lock);
    /* The join, in thread order. */
    for (int i = 1; i < p->n; i++) {
        add_stats(&c->stats, &p->w[i].ctx->stats, false);
        if (c->texture)
            fs_texture_join(c, p->w[i].tex);
    }
    c->raster.band_n = 0;
    c->par_recording = true;
    p->count = 0;
    p->pixels = 0.0;
}

void fs_par_draw_end(fs_context *c)
{
    struct fs_raster_par *p = c->par;
    if (!p || !c->par_recording)
        return;
    flush(c);
    c->par_recording = false;
}

void fs_par_record(fs_context *c, const fs_rvertex *v0, const fs_rvertex *v1, const fs_rvertex *v2)
{
    struct fs_raster_par *p = c->par;
    fs_rvertex *t = &p->tri[3 * p->count++];
    t[0] = *v0;
    t[1] = *v1;
    t[2] = *v2;
    /* The box decides only whether the batch goes parallel, never a pixel. */
    float x0 = fs_lo3(v0->x, v1->x, v2->x), x1 = fs_hi3(v0->x, v1->x, v2->x);
    float y0 = fs_lo3(v0->y, v1->y, v2->y), y1 = fs_hi3(v0->y, v1->y, v2->y);
    x0 = x0 > 0.0f ? x0 : 0.0f;
    y0 = y0 > 0.0f ? y0 : 0.0f;
    x1 = x1 < (float)c->fb.width ? x1 : (float)c->fb.width;
    y1 = y1 < (float)c->fb.height ? y1 : (float)c->fb.height;
    if (x1 > x0 && y1 > y0)
        p->pixels += (double)(x1 - x0) * (double)(y1 - y0);
    if (p->count == FS_PAR_BATCH)
        flush(c);
}

void fs_par_counts(const fs_context *c, unsigned long *parallel, unsigned long *serial)
{
    *parallel = c->par ? c->par->batches_parallel : 0;
    *serial = c->par ? c->par->batches_serial : 0;
}
