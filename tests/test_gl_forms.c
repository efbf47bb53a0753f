/*
 * The generated forms of glColor, glNormal, glTexCoord, glIndex and glRect
 * (driver/gl_commands_forms.def, GL 1.5 spec 2.7, 2.10) and the colour
 * index against OSMesa (llvmpipe), at tolerance 0: every form with random
 * arguments, immediately and compiled into a display list, leaves the same
 * current values (glGetFloatv and glGetIntegerv of GL_CURRENT_COLOR,
 * _NORMAL, _TEXTURE_COORDS and _INDEX) and errors as on OSMesa; glRect of
 * every type draws the same pixels, also from a list, and is an error
 * between glBegin and glEnd.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

#define MAXV 20000
typedef struct rec {
    double v[MAXV];
    const char *what[MAXV];
    int n;
} rec;

static void put(rec *r, const char *what, double v)
{
    if (r->n < MAXV) {
        r->what[r->n] = what;
        r->v[r->n++] = v;
    }
}

/* The current values as both glGet commands give them, and the error. */
static void dump_current(fs_context *c, rec *r, const char *what)
{
    static const GLenum names[] = {GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_CURRENT_TEXTURE_COORDS, GL_CURRENT_INDEX};
    static const int counts[] = {4, 3, 4, 1};
    for (int i = 0; i < 4; i++) {
        GLfloat fv[4];
        GLint iv[4];
        G(GetFloatv, names[i], fv);
        G(GetIntegerv, names[i], iv);
        for (int k = 0; k < counts[i]; k++) {
            put(r, what, fv[k]);
            put(r, what, iv[k]);
        }
    }
    put(r, what, c ? fsglGetError(c) : glGetError());
}

/* Random arguments: all bits of the integer types; floats in [-3, 3] with
 * 24 random bits, and colour indices, which glGetIntegerv rounds, small
 * enough to fit the integer range. */
static uint32_t rnd(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s ^ (*s >> 15);
}
static double rnd_real(uint32_t *s) { return ((double)(rnd(s) >> 8) / 16777216.0) * 6.0 - 3.0; }
#define RND_BY(s) ((GLbyte)rnd(s))
#define RND_UB(s) ((GLubyte)rnd(s))
#define RND_S(s) ((GLshort)rnd(s))
#define RND_US(s) ((GLushort)rnd(s))
#define RND_I(s) ((GLint)rnd(s))
#define RND_U(s) ((GLuint)rnd(s))
#define RND_F(s) ((GLfloat)rnd_real(s))
#define RND_D(s) (rnd_real(s))
#define RND_ABY RND_BY
#define RND_AUB RND_UB
#define RND_AS RND_S
#define RND_AUS RND_US
#define RND_AI RND_I
#define RND_AU RND_U
#define RND_AF RND_F
#define RND_AD RND_D
#define ELEM_ABY GLbyte
#define ELEM_AUB GLubyte
#define ELEM_AS GLshort
#define ELEM_AUS GLushort
#define ELEM_AI GLint
#define ELEM_AU GLuint
#define ELEM_AF GLfloat
#define ELEM_AD GLdouble

/* One call of every generated current-value form (glRect is drawn below),
 * each followed by the dump, with the same random arguments on both. */
#define FS_FORM_V(name, to, ak, n)                                             \
    {                                                                          \
        ELEM_##ak v[4];                                                        \
        for (int k = 0; k < 4; k++)                                            \
            v[k] = RND_##ak(s);                                                \
        G(name, v);                                                            \
        if (r)                                                                 \
            dump_current(c, r, "gl" #name);                                    \
    }
/* Arguments drawn in order into locals (GA, osmesa_util.h). */
#define FORM_DECL(k, kind, name, cnt) FS_CT_##kind a##k = RND_##kind(s);
#define FORM_CALL_(name, n, ...)                                               \
    {                                                                          \
        GA(FORM_DECL, name, n, __VA_ARGS__);                                   \
        if (r)                                                                 \
            dump_current(c, r, "gl" #name);                                    \
    }
#define FORM_CALL(name, ...) FORM_CALL_(name, __VA_ARGS__)
/* glRect's rows draw: rect_vs_osmesa has them. */
#define FS_FORM_F(name, to, k, n, names) FORM_IF_##names(FORM_CALL(name, FS_FORM_ARGS_##names##_##n(k)))
#define FORM_IF_TC(x) x
#define FORM_IF_IX(x) x
#define FORM_IF_RECT(x)
#define FS_FORM_RV(name, to, ak)
#define FS_CMD(...)

/* The forms once; when r is NULL the calls are being compiled (no dump). */
static void all_forms(fs_context *c, rec *r, uint32_t seed)
{
    uint32_t st = seed, *s = &st;
#include "../driver/gl_commands_forms.def"
}

static void compare(check_state *check_st_, const rec *m, const rec *ref)
{
    CHECK_EQ_INT(m->n, ref->n);
    int bad = 0;
    for (int i = 0; i < m->n && i < ref->n; i++) {
        /* Bitwise equal (NaN matches NaN). */
        if (memcmp(&m->v[i], &ref->v[i], sizeof(double)) != 0 && bad++ < 10)
            CHECK_FAIL_("value %d after %s: %.9g (model) != %.9g (OSMesa)", i, ref->what[i], m->v[i], ref->v[i]);
    }
    CHECK_EQ_INT(bad, 0);
}

/* Runs seq on OSMesa, then on a model context, and compares what each
 * read.  False when there is no OSMesa context. */
static bool both(check_state *check_st_, void (*seq)(fs_context *c, rec *r, uint32_t seed), uint32_t seed)
{
    static rec ref, mine;
    osm o;
    if (!osm_open(&o, 16, 16)) {
        osm_close(&o);
        return false;
    }
    ref.n = mine.n = 0;
    seq(NULL, &ref, seed);
    fs_context *c = fs_context_create(NULL, 16, 16);
    if (c) {
        seq(c, &mine, seed);
        compare(check_st_, &mine, &ref);
    }
    CHECK(c != NULL);
    fs_context_destroy(c);
    osm_close(&o);
    return true;
}

/* Every form, immediately, for several seeds. */
TEST(current_value_forms_vs_osmesa)
{
    for (uint32_t seed = 1; seed <= 8; seed++)
        if (!both(check_st_, all_forms, seed))
            SKIP("no OSMesa context");
}

/* Compiled into a list (GL_COMPILE: nothing changes), then called: the
 * last form's values stand, as on OSMesa. */
static void forms_in_lists(fs_context *c, rec *r, uint32_t seed)
{
    G(NewList, 5, GL_COMPILE);
    all_forms(c, NULL, seed);
    G0(EndList);
    dump_current(c, r, "after compiling");
    G(CallList, 5);
    dump_current(c, r, "after glCallList");
    G(NewList, 6, GL_COMPILE_AND_EXECUTE);
    all_forms(c, NULL, seed + 1);
    G0(EndList);
    dump_current(c, r, "after GL_COMPILE_AND_EXECUTE");
    /* Between glBegin and glEnd the current values may be given. */
    G(Begin, GL_POINTS);
    all_forms(c, NULL, seed + 2);
    G0(End);
    dump_current(c, r, "after glBegin ... glEnd");
}

TEST(current_value_forms_in_display_lists_vs_osmesa)
{
    if (!both(check_st_, forms_in_lists, 77))
        SKIP("no OSMesa context");
}

/* glPushAttrib(GL_CURRENT_BIT) saves the colour index (table 6.5). */
static void index_push_pop(fs_context *c, rec *r, uint32_t seed)
{
    (void)seed;
    static const float values[] = {7.0f, 2.5f, -2.5f, 0.49f, -3.6f, 1000.75f, -65536.5f};
    dump_current(c, r, "initial");
    for (size_t i = 0; i < sizeof values / sizeof values[0]; i++) {
        G(Indexf, values[i]);
        dump_current(c, r, "glIndexf");
        G(PushAttrib, GL_CURRENT_BIT);
        G(Indexi, 12345);
        G0(PopAttrib);
        dump_current(c, r, "glPopAttrib");
    }
}

TEST(current_index_push_pop_vs_osmesa)
{
    if (!both(check_st_, index_push_pop, 0))
        SKIP("no OSMesa context");
}

/* glRect of every type and form, in colours, corners in any order (2.10:
 * the winding follows them, so culling tells), compiled into a list too. */
static void draw_rects(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    G(Viewport, 0, 0, w, h);
    G0(LoadIdentity);
    G(Ortho, 0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    G(ClearColor, 0.0f, 0.0f, 0.0f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT);
    /* Not between glBegin and glEnd: an error, and nothing drawn. */
    G(Begin, GL_TRIANGLES);
    G(Rectf, 0.0f, 0.0f, 64.0f, 64.0f);
    G0(End);
    G(Color3f, 1.0f, 0.25f, 0.5f);
    G(Rectf, 1.5f, 2.25f, 20.75f, 9.5f);
    G(Color3f, 0.0f, 1.0f, 0.5f);
    G(Rectd, 40.2, 30.7, 22.1, 12.9);
    G(Color3f, 0.2f, 0.4f, 1.0f);
    G(Recti, 3, 60, 30, 40);
    G(Color3f, 0.9f, 0.9f, 0.1f);
    G(Rects, 60, 2, 33, 20);
    GLfloat f1[2] = {42.5f, 44.25f}, f2[2] = {62.0f, 61.5f};
    GLdouble d1[2] = {5.5, 20.0}, d2[2] = {18.5, 27.25};
    GLint i1[2] = {33, 22}, i2[2] = {40, 38};
    GLshort s1[2] = {50, 30}, s2[2] = {58, 40};
    G(Color3f, 0.5f, 0.1f, 0.9f);
    G(Rectfv, f1, f2);
    G(Rectdv, d1, d2);
    G(NewList, 3, GL_COMPILE);
    G(Color3f, 0.3f, 0.8f, 0.8f);
    G(Rectiv, i1, i2);
    G(Rectsv, s1, s2);
    G0(EndList);
    G(Translatef, 2.0f, -3.0f, 0.0f);
    G(CallList, 3);
    /* Clockwise corners are back faces. */
    G(Enable, GL_CULL_FACE);
    G(Color3f, 1.0f, 1.0f, 1.0f);
    G(Rectf, 10.0f, 50.0f, 2.0f, 63.0f);
    G(Rectf, 20.0f, 50.0f, 28.0f, 63.0f);
    G(Disable, GL_CULL_FACE);
}

TEST(rect_forms_vs_osmesa)
{
    osm_pair p;
    if (!osm_pair_render(&p, 64, 64, NULL, draw_rects, NULL))
        SKIP("no OSMesa context");
    CHECK_EQ_INT(p.d.differ, 0);
    fs_context *c = p.c;
    GLenum mine = fsglGetError(c);
    c = NULL;
    GLenum ref = glGetError();
    CHECK_EQ_INT(mine, ref);
    CHECK_EQ_INT(ref, GL_INVALID_OPERATION);
    CHECK(img_lit_pixels(p.ref.color, 64L * 64) > 500);
    osm_pair_close(&p);
}

TEST_LIST = {
    TEST_ENTRY(current_value_forms_vs_osmesa),
    TEST_ENTRY(current_value_forms_in_display_lists_vs_osmesa),
    TEST_ENTRY(current_index_push_pop_vs_osmesa),
    TEST_ENTRY(rect_forms_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
