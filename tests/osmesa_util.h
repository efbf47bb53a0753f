/*
 * OSMesa (llvmpipe) as the reference in the tests: one context per image,
 * the same GL calls on OSMesa and on the model, and the comparison of the
 * two colour buffers.  Header-only (static functions), included by the
 * test files that compare against OSMesa.
 *
 *   osm o;  osm_open(&o, w, h);  ... gl calls ...  osm_close(&o);
 *   G(Name, args...)   calls fsglName(c, args...) when the fs_context *c in
 *                      scope is non-NULL, else glName(args...) on OSMesa.
 */
#ifndef FS_TEST_OSMESA_UTIL_H
#define FS_TEST_OSMESA_UTIL_H
#include <GL/osmesa.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define G(name, ...) do { if (c) fsgl##name(c, __VA_ARGS__); else gl##name(__VA_ARGS__); } while (0)
#define G0(name) do { if (c) fsgl##name(c); else gl##name(); } while (0)
#define GR(name, ...) (c ? fsgl##name(c, __VA_ARGS__) : gl##name(__VA_ARGS__))

typedef struct osm {
    OSMesaContext ctx;
    uint8_t *color; /* w x h RGBA8, rows bottom-up */
    int w, h;
} osm;

/* An RGBA8 context with 24 depth and 8 stencil bits, made current, its
 * colour buffer zeroed.  False on failure (osm_close still safe). */
static inline bool osm_open(osm *o, int w, int h)
{
    o->w = w;
    o->h = h;
    o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    o->color = calloc((size_t)w * (size_t)h, 4);
    return o->ctx && o->color && OSMesaMakeCurrent(o->ctx, o->color, GL_UNSIGNED_BYTE, w, h);
}

static inline void osm_close(osm *o)
{
    if (o->ctx) {
        glFinish(); /* llvmpipe's threads are done with the buffer */
        OSMesaDestroyContext(o->ctx);
    }
    free(o->color);
    o->ctx = NULL;
    o->color = NULL;
}

/* Per-channel comparison of two RGBA8 images of n pixels: pixels that
 * differ at all, by more than 1, and the largest channel difference. */
typedef struct img_diff { long pixels, differ, differ_gt1; int maxd; } img_diff;

static inline void img_compare(const uint8_t *a, const uint8_t *b, long n, img_diff *d)
{
    for (long i = 0; i < n; i++) {
        int m = 0;
        for (int k = 0; k < 4; k++) {
            int e = abs((int)a[i * 4 + k] - (int)b[i * 4 + k]);
            m = e > m ? e : m;
        }
        d->pixels++;
        d->differ += m != 0;
        d->differ_gt1 += m > 1;
        d->maxd = m > d->maxd ? m : d->maxd;
    }
}
#endif
