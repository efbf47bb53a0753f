/*
 * OSMesa (llvmpipe) as the reference in the tests: one context per image,
 * the same GL calls on OSMesa and on the model, and the comparison of the
 * two colour buffers.  Header-only (static functions), included by the
 * test files that compare against OSMesa.
 *
 *   osm o;  osm_open(&o, w, h);  ... gl calls ...  osm_close(&o);
 *   G(Name, args...)   calls fsglName(c, args...) when the fs_context *c in
 *                      scope is non-NULL, else glName(args...) on OSMesa.
 *   osm_pair p;  osm_pair_render(&p, w, h, create, draw, user);  ... p.d,
 *                      p.c (the model), p.ref.color ...  osm_pair_close(&p);
 */
#ifndef FS_TEST_OSMESA_UTIL_H
#define FS_TEST_OSMESA_UTIL_H
#include <GL/osmesa.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

#define G(name, ...) do { if (c) fsgl##name(c, __VA_ARGS__); else gl##name(__VA_ARGS__); } while (0)
#define G0(name) do { if (c) fsgl##name(c); else gl##name(); } while (0)
#define GR(name, ...) (c ? fsgl##name(c, __VA_ARGS__) : gl##name(__VA_ARGS__))
/* GA(DECL, Name, NARGS, (KIND, name, count)...): G with the arguments of a
 * gl_commands*.def row, each declared first as a local a0, a1, ... by
 * DECL(k, KIND, name, count) (so they are drawn in order) and then passed. */
#define GA_USE_(k, kind, name, cnt) , a##k
#define GA_DROP1_(...) GA_DROP1__(__VA_ARGS__)
#define GA_DROP1__(empty, ...) __VA_ARGS__
#define GA(decl, name, nargs, ...)                                              \
    do {                                                                        \
        FS_MAP(nargs, decl, __VA_ARGS__)                                        \
        if (c)                                                                  \
            fsgl##name(c FS_MAP(nargs, GA_USE_, __VA_ARGS__));                  \
        else                                                                    \
            gl##name(GA_DROP1_(FS_MAP(nargs, GA_USE_, __VA_ARGS__)));           \
    } while (0)

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

/* Pixels of an RGBA8 image of n pixels whose colour is not black (that a
 * comparison drew something at all). */
static inline long img_lit_pixels(const uint8_t *rgba, long n)
{
    long lit = 0;
    for (long i = 0; i < n; i++)
        lit += (rgba[i * 4] | rgba[i * 4 + 1] | rgba[i * 4 + 2]) != 0;
    return lit;
}

/* One sequence of calls and queries on both: fn(NULL, ref, nr) on a new
 * w x h OSMesa context, then fn(c, mine, nm) on a model context; each
 * appends the values it reads to its array.  False when a context cannot
 * be made. */
typedef void (*osm_values_fn)(fs_context *c, double *v, int *n);
static inline bool osm_run_values(osm_values_fn fn, int w, int h, double *ref, int *nr, double *mine, int *nm)
{
    osm o;
    *nr = *nm = 0;
    if (!osm_open(&o, w, h)) {
        osm_close(&o);
        return false;
    }
    fn(NULL, ref, nr);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, w, h);
    if (!c)
        return false;
    fn(c, mine, nm);
    fs_context_destroy(c);
    return true;
}

/* A test's check that fn reads the same values on both (at most cap of
 * them; check.h's macros, expanded in the test). */
#define OSM_CHECK_VALUES(fn, w, h, cap)                                                    \
    do {                                                                                   \
        static double ref_[cap], mine_[cap];                                               \
        int nr_, nm_;                                                                      \
        REQUIRE(osm_run_values(fn, w, h, ref_, &nr_, mine_, &nm_));                        \
        CHECK_EQ_INT(nm_, nr_);                                                            \
        for (int i_ = 0; i_ < nr_ && i_ < nm_; i_++)                                       \
            if (mine_[i_] != ref_[i_])                                                     \
                CHECK_FAIL_("value %d: fragsim %.9g, OSMesa %.9g", i_, mine_[i_], ref_[i_]); \
    } while (0)

/* One drawing on both: draw(NULL, ...) on a new OSMesa context, then
 * draw(c, ...) on a model context from create(w, h) (fs_context_create's
 * defaults when create is NULL), and the colour buffers compared into d.
 * False when a context cannot be made (nothing left to close then). */
typedef struct osm_pair { osm ref; fs_context *c; img_diff d; } osm_pair;

static inline bool osm_pair_render(osm_pair *p, int w, int h, fs_context *(*create)(int w, int h),
                                   void (*draw)(fs_context *c, const void *user, int w, int h), const void *user)
{
    memset(p, 0, sizeof *p);
    if (!osm_open(&p->ref, w, h)) {
        osm_close(&p->ref);
        return false;
    }
    draw(NULL, user, w, h);
    glFinish();
    p->c = create ? create(w, h) : fs_context_create(NULL, w, h);
    if (!p->c) {
        osm_close(&p->ref);
        return false;
    }
    draw(p->c, user, w, h);
    img_compare(p->c->fb.color, p->ref.color, (long)w * h, &p->d);
    return true;
}

static inline void osm_pair_close(osm_pair *p)
{
    fs_context_destroy(p->c);
    osm_close(&p->ref);
    p->c = NULL;
}

/* For looking at a comparison: OSMesa's image, the model's and, when
 * diff_panel, a map of their difference (red: more than 1, green: 1) side
 * by side as a binary PPM, every pixel scale x scale, top row first. */
static inline void img_dump_ppm(const char *fn, const uint8_t *ref, const uint8_t *mine, int w, int h, int scale,
                                bool diff_panel)
{
    FILE *f = fopen(fn, "wb");
    if (!f)
        return;
    int panels = diff_panel ? 3 : 2;
    fprintf(f, "P6 %d %d 255\n", w * panels * scale, h * scale);
    for (int y = h * scale - 1; y >= 0; y--)
        for (int x = 0; x < w * panels * scale; x++) {
            int px = (x / scale) % w, part = x / scale / w;
            long o = ((long)(y / scale) * w + px) * 4;
            uint8_t rgb[3];
            if (part < 2) {
                memcpy(rgb, (part ? mine : ref) + o, 3);
            } else {
                int m = 0;
                for (int k = 0; k < 4; k++) {
                    int e = abs((int)mine[o + k] - (int)ref[o + k]);
                    m = e > m ? e : m;
                }
                rgb[0] = m > 1 ? 255 : 0;
                rgb[1] = m == 1 ? 255 : 0;
                rgb[2] = 0;
            }
            fwrite(rgb, 1, 3, f);
        }
    fclose(f);
}
/* One scene, draw(c, w, h), on OSMesa and on the model (G() in it goes to
 * whichever c says): returns the pixels that differ at all (-1 when a
 * context cannot be made), *errors the model's glGetError; prints one line
 * and, with the environment variable dump_env set, writes both images and
 * their difference to /tmp/<prefix>_<name>.ppm (img_dump_ppm). */
typedef void (*osm_scene_fn)(fs_context *c, int w, int h);

static inline void osm_scene_draw_(fs_context *c, const void *user, int w, int h)
{
    (*(const osm_scene_fn *)user)(c, w, h);
}

static inline long osm_compare_scene(osm_scene_fn scene, int w, int h, const char *name, const char *dump_env,
                                     const char *prefix, GLenum *errors)
{
    osm_pair p;
    if (!osm_pair_render(&p, w, h, NULL, osm_scene_draw_, &scene))
        return -1;
    long d = p.d.differ;
    *errors = fsglGetError(p.c);
    printf("  %-22s %dx%d: %ld pixels differ, max %d\n", name, w, h, d, p.d.maxd);
    if (getenv(dump_env)) {
        char fn[256];
        snprintf(fn, sizeof fn, "/tmp/%s_%s.ppm", prefix, name);
        img_dump_ppm(fn, p.ref.color, p.c->fb.color, w, h, 4, true);
    }
    osm_pair_close(&p);
    return d;
}
/* Values a sequence of calls answers (glGet and the like), on OSMesa and
 * on the model, each in an 8x8 context: run(c, out, &n) appends to out.
 * False when a context cannot be made. */
typedef void (*osm_values_fn)(fs_context *c, double *out, int *n);

static inline bool osm_pair_values(osm_values_fn run, double *ref, int *nref, double *mine, int *nmine)
{
    *nref = *nmine = 0;
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        return false;
    }
    run(NULL, ref, nref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    if (!c)
        return false;
    run(c, mine, nmine);
    fs_context_destroy(c);
    return true;
}

/* A test's check that a scene is drawn alike, without a GL error on the
 * model (check.h's CHECK_EQ_INT, expanded in the test). */
#define OSM_CHECK_SCENE(fn, w, h, name, dump_env, prefix)                              \
    do {                                                                               \
        GLenum err_;                                                                   \
        CHECK_EQ_INT(osm_compare_scene(fn, w, h, name, dump_env, prefix, &err_), 0);   \
        CHECK_EQ_INT(err_, GL_NO_ERROR);                                               \
    } while (0)
/* The set-up many scenes share: the whole window as viewport, cleared
 * to (r, g, b, 1), the projection glFrustum(-1, 1, -1, 1, 1, far) and an
 * identity modelview. */
static inline void osm_frustum_scene(fs_context *c, int w, int h, float r, float g, float b, float far)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, r, g, b, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1, 1, -1, 1, 1, far);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
}
/* The textured-quad tests' view: a w x h viewport cleared to one colour,
 * the texture environment env, a frustum, and the quad's plane 3 units
 * away tilted about x. */
static inline void osm_tilted_view(fs_context *c, int w, int h, GLenum env, float tilt)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.3f, 0.1f, 0.2f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
    G(MatrixMode, GL_PROJECTION);
    G(Frustum, -1.0, 1.0, -(double)h / w, (double)h / w, 2.0, 40.0);
    G(MatrixMode, GL_MODELVIEW);
    G(Translatef, 0, 0, -3);
    G(Rotatef, -tilt, 1, 0, 0);
}

/* Texture level queries for the texture tests: the pnames' values at
 * (target, level), then the error. */
static inline void osm_level_params(fs_context *c, GLenum target, int level, const GLenum *pn, int npn, double *v,
                                    int *n)
{
    for (int i = 0; i < npn; i++) {
        GLint iv = -5;
        G(GetTexLevelParameteriv, target, level, pn[i], &iv);
        v[(*n)++] = iv;
    }
    v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError());
}

/* glGetTexImage of a level into a buffer with guard bytes: the checksum
 * of the whole buffer, then the error. */
static inline void osm_get_image(fs_context *c, GLenum target, int level, GLenum format, GLenum type, double *v,
                                 int *n)
{
    static uint8_t out[40000];
    memset(out, 0xa5, sizeof out);
    G(GetTexImage, target, level, format, type, out);
    uint32_t sum = 0;
    for (size_t i = 0; i < sizeof out; i++)
        sum = sum * 31u + out[i];
    v[(*n)++] = sum;
    v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError());
}

#endif
