/*
 * Point parameters (GL 1.4, GL 1.5 spec 3.3) and point sprites (GL 2.0
 * spec 3.3) drawn by fragsim and by OSMesa (llvmpipe) with the same calls,
 * compared pixel for pixel at tolerance 0: random points with distance
 * attenuation and size bounds, the fade threshold, point sprites with a
 * small texture and GL_COORD_REPLACE on either origin; and the commands'
 * errors, glGet answers and glPushAttrib/glPopAttrib against OSMesa's.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "seeded_scenes.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

typedef struct pscene {
    unsigned seed;
    bool perspective;
    bool attenuate; /* random distance attenuation */
    bool bounds;    /* random GL_POINT_SIZE_MIN and _MAX */
    bool fade;      /* a fade threshold above the sizes, blending on */
    bool sprite;    /* GL_POINT_SPRITE with a texture */
    int units;      /* sprites: textured units (1 or 2) */
    bool smooth;    /* GL_POINT_SMOOTH on (sprites turn it off) */
    bool polygons;  /* GL_POINT polygons instead of point primitives */
} pscene;

/* A w x h RGBA texture of random texels on the active unit. */
static void random_texture(fs_context *c, rng *r, int w, int h, bool linear)
{
    static GLubyte px[16 * 16 * 4];
    for (int i = 0; i < w * h * 4; i++)
        px[i] = (GLubyte)(rnd(r) & 0xff);
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    GLint f = linear ? GL_LINEAR : GL_NEAREST;
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
    G(Enable, GL_TEXTURE_2D);
}

static void draw_points(fs_context *c, const void *user, int w, int h)
{
    const pscene *sc = user;
    rng r = {sc->seed * 2654435761u + 17};
    scene_view(c, w, h, sc->perspective);
    if (rnd(&r) & 1)
        G(Disable, GL_DEPTH_TEST);
    if (sc->fade || rnd(&r) % 4 == 0) {
        G(Enable, GL_BLEND);
        G(BlendFunc, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    if (sc->sprite) {
        G(Enable, GL_POINT_SPRITE);
        for (int u = 0; u < sc->units; u++) {
            G(ActiveTexture, GL_TEXTURE0 + u);
            random_texture(c, &r, 4 << (rnd(&r) % 2), 4 << (rnd(&r) % 2), rnd(&r) & 1);
            G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, u ? GL_ADD : GL_MODULATE);
            /* Unit 1 replaces only in some scenes: the other keeps its
             * constant coordinate across the sprite. */
            bool replace = u == 0 || (rnd(&r) & 1);
            G(TexEnvi, GL_POINT_SPRITE, GL_COORD_REPLACE, replace ? GL_TRUE : GL_FALSE);
        }
        G(ActiveTexture, GL_TEXTURE0);
        G(PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, rnd(&r) & 1 ? GL_LOWER_LEFT : GL_UPPER_LEFT);
        /* A texture matrix transforms the vertex's coordinates, not the
         * replaced ones. */
        if (rnd(&r) & 1) {
            G(MatrixMode, GL_TEXTURE);
            G(Scalef, 2.0f, 0.5f, 1.0f);
            G(MatrixMode, GL_MODELVIEW);
        }
    }
    if (sc->attenuate) {
        GLfloat att[3] = {rnd_in(&r, 0.05f, 1.5f), rnd_in(&r, 0.0f, 0.6f), rnd_in(&r, 0.0f, 0.4f)};
        if (rnd(&r) % 4 == 0)
            att[1] = att[2] = 0.0f; /* a constant factor alone */
        G(PointParameterfv, GL_POINT_DISTANCE_ATTENUATION, att);
    }
    if (sc->bounds) {
        float lo = rnd_in(&r, 0.0f, 6.0f), hi = lo + rnd_in(&r, 0.0f, 20.0f);
        G(PointParameterf, GL_POINT_SIZE_MIN, lo);
        G(PointParameterf, GL_POINT_SIZE_MAX, hi);
    }
    if (sc->fade)
        G(PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, rnd_in(&r, 4.0f, 40.0f));
    if (sc->smooth)
        G(Enable, GL_POINT_SMOOTH);
    if (sc->polygons)
        G(PolygonMode, GL_FRONT_AND_BACK, GL_POINT);
    for (int draw = 0; draw < 6; draw++) {
        float size = rnd_in(&r, 0.5f, sc->sprite ? 24.0f : 16.0f);
        if (rnd(&r) % 3 == 0)
            size = (float)(int)size + 0.5f * (float)(rnd(&r) & 1);
        G(PointSize, size);
        G(ShadeModel, rnd(&r) & 1 ? GL_FLAT : GL_SMOOTH);
        G(Begin, sc->polygons ? GL_TRIANGLES : GL_POINTS);
        for (int i = 0; i < (sc->polygons ? 9 : 8); i++) {
            G(Color4f, rndf(&r), rndf(&r), rndf(&r), rnd_in(&r, 0.3f, 1.0f));
            if (sc->sprite)
                G(MultiTexCoord2f, GL_TEXTURE1, rndf(&r), rndf(&r));
            G(Vertex3f, rnd_in(&r, -0.98f, 0.98f), rnd_in(&r, -0.98f, 0.98f), rnd_in(&r, -0.9f, 0.9f));
        }
        G0(End);
    }
    G0(Finish);
}

static void check_points(check_state *check_st_, pscene sc, const char *name, unsigned first, unsigned count)
{
    seeded_run r = {draw_points, &sc, &sc.seed, 61, 47, 6, 6, name};
    check_seeded_runs(check_st_, &r, first, count);
}

TEST(attenuation_vs_osmesa) { check_points(check_st_, (pscene){0, true, true, false, false, false, 0}, "atten", 1, 30); }

TEST(attenuation_bounds_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, true, false, false, 0}, "atten_bounds", 100, 30);
}

TEST(size_bounds_vs_osmesa) { check_points(check_st_, (pscene){0, false, false, true, false, false, 0}, "bounds", 200, 30); }

/* The fade threshold is above most derived sizes: the points stay as
 * large and as opaque as without it (point_state.c). */
TEST(fade_threshold_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, true, true, false, 0}, "fade", 300, 30);
}

TEST(sprites_vs_osmesa) { check_points(check_st_, (pscene){0, false, false, false, false, true, 1}, "sprites", 400, 30); }

TEST(sprites_perspective_attenuated_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, true, false, true, 1}, "sprites_persp", 500, 30);
}

TEST(sprites_two_units_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, false, false, false, true, 2}, "sprites_units", 600, 30);
}

/* Smooth points take the derived size too (Mesa's draw module reads the
 * vertex's size); a sprite is never smooth (Mesa's state tracker). */
TEST(smooth_attenuated_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, true, false, false, 0, true, false}, "smooth_atten", 700, 30);
}

TEST(smooth_sprites_vs_osmesa)
{
    check_points(check_st_, (pscene){0, false, false, false, false, true, 1, true, false}, "smooth_sprites", 800, 20);
}

/* GL_POINT polygons (3.5.4): their vertices' points, attenuated. */
TEST(polygon_points_attenuated_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, true, false, false, 0, false, true}, "poly_atten", 900, 30);
}

/* Sprites as the vertices of GL_POINT polygons, attenuated. */
TEST(polygon_sprites_vs_osmesa)
{
    check_points(check_st_, (pscene){0, true, true, false, false, true, 2, false, true}, "poly_sprites", 1000, 20);
}

/* ---- errors, glGet and the attribute stack ---- */

static void add(double *v, int *n, double x) { v[(*n)++] = x; }

static void add_err(fs_context *c, double *v, int *n) { add(v, n, (double)(c ? fsglGetError(c) : glGetError())); }

static void add_floats(fs_context *c, double *v, int *n, GLenum pname, int count)
{
    GLfloat f[4] = {-7, -7, -7, -7};
    G(GetFloatv, pname, f);
    for (int k = 0; k < count; k++)
        add(v, n, f[k]);
    add_err(c, v, n);
}

static void add_point_state(fs_context *c, double *v, int *n)
{
    add_floats(c, v, n, GL_POINT_SIZE, 1);
    add_floats(c, v, n, GL_POINT_SIZE_MIN, 1);
    add_floats(c, v, n, GL_POINT_SIZE_MAX, 1);
    add_floats(c, v, n, GL_POINT_FADE_THRESHOLD_SIZE, 1);
    add_floats(c, v, n, GL_POINT_DISTANCE_ATTENUATION, 3);
    GLint i = -7;
    G(GetIntegerv, GL_POINT_SPRITE_COORD_ORIGIN, &i);
    add(v, n, i);
    add(v, n, GR(IsEnabled, GL_POINT_SPRITE));
    add_err(c, v, n);
    for (int u = 0; u < 3; u++) {
        G(ActiveTexture, GL_TEXTURE0 + u);
        GLint b = -7;
        G(GetTexEnviv, GL_POINT_SPRITE, GL_COORD_REPLACE, &b);
        add(v, n, b);
        GLfloat f = -7;
        G(GetTexEnvfv, GL_POINT_SPRITE, GL_COORD_REPLACE, &f);
        add(v, n, f);
    }
    G(ActiveTexture, GL_TEXTURE0);
    add_err(c, v, n);
}

static void errors_run(fs_context *c, double *v, int *n)
{
    add_point_state(c, v, n); /* the initial values */
    /* 3.3: negative sizes and thresholds are INVALID_VALUE and change
     * nothing; zero is allowed. */
    G(PointParameterf, GL_POINT_SIZE_MIN, -1.0f);
    add_err(c, v, n);
    G(PointParameteri, GL_POINT_SIZE_MAX, -3);
    add_err(c, v, n);
    GLfloat neg = -0.5f;
    G(PointParameterfv, GL_POINT_FADE_THRESHOLD_SIZE, &neg);
    add_err(c, v, n);
    GLint negi = -2;
    G(PointParameteriv, GL_POINT_SIZE_MIN, &negi);
    add_err(c, v, n);
    G(PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, 0.0f);
    add_err(c, v, n);
    /* Names that are no point parameter: INVALID_ENUM. */
    G(PointParameterf, GL_POINT_SIZE, 2.0f);
    add_err(c, v, n);
    G(PointParameteri, GL_POINT_SPRITE, 1);
    add_err(c, v, n);
    GLfloat three[3] = {1, 2, 3};
    G(PointParameterfv, GL_LINE_WIDTH, three);
    add_err(c, v, n);
    /* The origin takes only its two values: INVALID_VALUE otherwise. */
    G(PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, GL_LEFT);
    add_err(c, v, n);
    G(PointParameterf, GL_POINT_SPRITE_COORD_ORIGIN, 0.0f);
    add_err(c, v, n);
    /* The scalar form with the attenuation (param, 0, 0). */
    G(PointParameterf, GL_POINT_DISTANCE_ATTENUATION, 2.5f);
    add_err(c, v, n);
    add_floats(c, v, n, GL_POINT_DISTANCE_ATTENUATION, 3);
    /* glTexEnv on GL_POINT_SPRITE: GL_COORD_REPLACE only, GL_TRUE or GL_FALSE. */
    G(TexEnvi, GL_POINT_SPRITE, GL_COORD_REPLACE, 2);
    add_err(c, v, n);
    G(TexEnvi, GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    add_err(c, v, n);
    GLint b;
    G(GetTexEnviv, GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &b);
    add_err(c, v, n);
    G(TexEnvf, GL_POINT_SPRITE, GL_COORD_REPLACE, 1.0f);
    add_err(c, v, n);
    /* Between Begin and End: INVALID_OPERATION (2.6.3), nothing set. */
    G(Begin, GL_POINTS);
    G(PointParameterf, GL_POINT_SIZE_MIN, 4.0f);
    G0(End);
    add_err(c, v, n);
    add_point_state(c, v, n);
}

TEST(errors_vs_osmesa) { OSM_CHECK_VALUES(errors_run, 8, 8, 256); }

static void set_points(fs_context *c, float base, bool sprite, GLenum origin, unsigned replace)
{
    G(PointSize, base + 1.0f);
    G(PointParameterf, GL_POINT_SIZE_MIN, base * 0.5f);
    G(PointParameteri, GL_POINT_SIZE_MAX, (GLint)base + 30);
    G(PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, base + 0.25f);
    GLint att[3] = {2, (GLint)base, 1};
    G(PointParameteriv, GL_POINT_DISTANCE_ATTENUATION, att);
    GLfloat o = (GLfloat)origin;
    G(PointParameterfv, GL_POINT_SPRITE_COORD_ORIGIN, &o);
    if (sprite)
        G(Enable, GL_POINT_SPRITE);
    else
        G(Disable, GL_POINT_SPRITE);
    for (int u = 0; u < 3; u++) {
        G(ActiveTexture, GL_TEXTURE0 + u);
        GLfloat f = (replace >> u) & 1 ? 1.0f : 0.0f;
        G(TexEnvfv, GL_POINT_SPRITE, GL_COORD_REPLACE, &f);
    }
    G(ActiveTexture, GL_TEXTURE0);
}

/* Round trips and the groups: GL_POINT_BIT saves all of it, GL_ENABLE_BIT
 * the sprite enable, GL_TEXTURE_BIT none of it (GL 2.0 table 6.12). */
static void push_pop_run(fs_context *c, double *v, int *n)
{
    set_points(c, 3.0f, true, GL_LOWER_LEFT, 5);
    add_point_state(c, v, n);
    static const GLbitfield groups[] = {GL_POINT_BIT, GL_ENABLE_BIT, GL_TEXTURE_BIT, GL_ALL_ATTRIB_BITS};
    for (int g = 0; g < 4; g++) {
        G(PushAttrib, groups[g]);
        set_points(c, 7.0f + (float)g, g & 1, GL_UPPER_LEFT, 2);
        add_point_state(c, v, n);
        G0(PopAttrib);
        add_point_state(c, v, n);
    }
}

TEST(glget_push_pop_vs_osmesa) { OSM_CHECK_VALUES(push_pop_run, 8, 8, 1024); }

/* Display lists carry the new commands (compiled, then executed). */
static void draw_listed(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    scene_view(c, w, h, true);
    GLuint list = GR(GenLists, 1);
    G(NewList, list, GL_COMPILE);
    GLfloat att[3] = {0.2f, 0.3f, 0.1f};
    G(PointParameterfv, GL_POINT_DISTANCE_ATTENUATION, att);
    G(PointParameterf, GL_POINT_SIZE_MIN, 2.0f);
    GLint mx = 14;
    G(PointParameteriv, GL_POINT_SIZE_MAX, &mx);
    G(PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    G0(EndList);
    G(PointSize, 9.0f);
    G(CallList, list);
    rng r = {99};
    G(Begin, GL_POINTS);
    for (int i = 0; i < 20; i++) {
        G(Color3f, rndf(&r), rndf(&r), rndf(&r));
        G(Vertex3f, rnd_in(&r, -0.9f, 0.9f), rnd_in(&r, -0.9f, 0.9f), rnd_in(&r, -0.9f, 0.9f));
    }
    G0(End);
    G0(Finish);
}

TEST(display_list_vs_osmesa)
{
    osm_pair p;
    REQUIRE(osm_pair_render(&p, 64, 48, NULL, draw_listed, NULL));
    CHECK_EQ_INT(p.d.differ, 0);
    CHECK(img_lit_pixels(p.ref.color, 64 * 48) > 100);
    CHECK_EQ_INT(fsglGetError(p.c), GL_NO_ERROR);
    osm_pair_close(&p);
}

TEST_LIST = {
    TEST_ENTRY(attenuation_vs_osmesa),
    TEST_ENTRY(attenuation_bounds_vs_osmesa),
    TEST_ENTRY(size_bounds_vs_osmesa),
    TEST_ENTRY(fade_threshold_vs_osmesa),
    TEST_ENTRY(sprites_vs_osmesa),
    TEST_ENTRY(sprites_perspective_attenuated_vs_osmesa),
    TEST_ENTRY(sprites_two_units_vs_osmesa),
    TEST_ENTRY(smooth_attenuated_vs_osmesa),
    TEST_ENTRY(smooth_sprites_vs_osmesa),
    TEST_ENTRY(polygon_points_attenuated_vs_osmesa),
    TEST_ENTRY(polygon_sprites_vs_osmesa),
    TEST_ENTRY(errors_vs_osmesa),
    TEST_ENTRY(glget_push_pop_vs_osmesa),
    TEST_ENTRY(display_list_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
