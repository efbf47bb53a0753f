/*
 * Lighting (GL 1.5 spec 2.14.1) on random lights against OSMesa, pixel for
 * pixel at tolerance 0: positional and infinite lights, spot lights (also
 * infinite ones, which llvmpipe attenuates by the spot factor of the
 * light's direction: piglit's infinite-spot-light), constant, linear and
 * quadratic attenuation, local viewer, two-sided lighting, seen on a
 * tessellated surface whose both sides face the viewer somewhere.
 */
#include <math.h>
#include "check.h"
#include "osmesa_util.h"

#define W 64
#define H 64

static uint32_t rnd(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static float frand(uint32_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(rnd(s) % 100000u) / 100000.0f;
}

typedef struct lights_case { uint32_t seed; bool infinite_spot_only; } lights_case;

static void random_light(fs_context *c, uint32_t *s, GLenum light, bool infinite_spot)
{
    G(Enable, light);
    bool infinite = infinite_spot || rnd(s) % 3 == 0;
    GLfloat pos[4] = {frand(s, -2, 2), frand(s, -2, 2), frand(s, -1, 3), infinite ? 0.0f : 1.0f};
    G(Lightfv, light, GL_POSITION, pos);
    GLfloat amb[4] = {frand(s, 0, 0.4f), frand(s, 0, 0.4f), frand(s, 0, 0.4f), 1};
    GLfloat dif[4] = {frand(s, 0, 1), frand(s, 0, 1), frand(s, 0, 1), 1};
    GLfloat spe[4] = {frand(s, 0, 1), frand(s, 0, 1), frand(s, 0, 1), 1};
    G(Lightfv, light, GL_AMBIENT, amb);
    G(Lightfv, light, GL_DIFFUSE, dif);
    G(Lightfv, light, GL_SPECULAR, spe);
    if (infinite_spot || rnd(s) % 2 == 0) {
        GLfloat dir[3] = {frand(s, -1, 1), frand(s, -1, 1), frand(s, -1, 1)};
        G(Lightfv, light, GL_SPOT_DIRECTION, dir);
        G(Lightf, light, GL_SPOT_CUTOFF, frand(s, 5, 90));
        G(Lightf, light, GL_SPOT_EXPONENT, rnd(s) % 3 == 0 ? 0.0f : frand(s, 0, 20));
    }
    if (!infinite && rnd(s) % 2 == 0) {
        G(Lightf, light, GL_CONSTANT_ATTENUATION, frand(s, 0.5f, 2));
        G(Lightf, light, GL_LINEAR_ATTENUATION, frand(s, 0, 1));
        G(Lightf, light, GL_QUADRATIC_ATTENUATION, frand(s, 0, 0.5f));
    }
}

static void draw_lit(fs_context *c, const void *user, int w, int h)
{
    const lights_case *lc = user;
    uint32_t s = lc->seed;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.0f, 0.0f, 0.0f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1, 1, -1, 1, 2, 10);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    int n = 1 + (int)(rnd(&s) % 3);
    for (int i = 0; i < n; i++)
        random_light(c, &s, GL_LIGHT0 + (GLenum)i, lc->infinite_spot_only);
    G(LightModeli, GL_LIGHT_MODEL_LOCAL_VIEWER, lc->infinite_spot_only ? 0 : (GLint)(rnd(&s) & 1));
    G(LightModeli, GL_LIGHT_MODEL_TWO_SIDE, lc->infinite_spot_only ? 0 : (GLint)(rnd(&s) & 1));
    GLfloat mf[4] = {frand(&s, 0, 1), frand(&s, 0, 1), frand(&s, 0, 1), 1};
    GLfloat mb[4] = {frand(&s, 0, 1), frand(&s, 0, 1), frand(&s, 0, 1), 1};
    G(Materialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, mf);
    G(Materialfv, GL_BACK, GL_AMBIENT_AND_DIFFUSE, mb);
    GLfloat sp[4] = {1, 1, 1, 1};
    G(Materialfv, GL_FRONT_AND_BACK, GL_SPECULAR, sp);
    G(Materialf, GL_FRONT_AND_BACK, GL_SHININESS, frand(&s, 1, 60));
    G(Enable, GL_LIGHTING);
    G(Translatef, 0, 0, -4);
    G(Rotatef, frand(&s, 0, 360), frand(&s, -1, 1), frand(&s, -1, 1), 1);
    /* a saddle, so that both faces of it show */
    for (int j = 0; j < 8; j++) {
        G(Begin, GL_TRIANGLE_STRIP);
        for (int i = 0; i <= 8; i++)
            for (int k = 0; k < 2; k++) {
                float x = -1.5f + 3.0f * (float)i / 8, y = -1.5f + 3.0f * (float)(j + k) / 8;
                float z = 0.4f * (x * x - y * y);
                float nx = -0.8f * x, ny = 0.8f * y, nz = 1.0f, l = sqrtf(nx * nx + ny * ny + nz * nz);
                G(Normal3f, nx / l, ny / l, nz / l);
                G(Vertex3f, x, y, z);
            }
        G0(End);
    }
}

/* Measured: every scene exact since the lighting follows the vertex
 * program's order and float rounding (pipeline/lighting.c; seeds 34 of the
 * infinite spot lights and 55 of the random ones were one pixel off by one
 * before) and its POW (pipeline/vp_pow.c).  Any difference fails. */
#define KNOWN_OFF_BY_ONE 0

static void lights_vs_osmesa(check_state *check_st_, bool infinite_spot_only, uint32_t seeds)
{
    long bad_seeds = 0, pixels = 0, gt1 = 0;
    for (uint32_t seed = 1; seed <= seeds; seed++) {
        lights_case lc = {seed * 2654435761u, infinite_spot_only};
        osm_pair p;
        if (!osm_pair_render(&p, W, H, NULL, draw_lit, &lc))
            SKIP("no OSMesa context");
        if (p.d.differ) {
            if (bad_seeds < 5)
                printf("  seed %u: %ld pixels differ, max %d\n", seed, p.d.differ, p.d.maxd);
            bad_seeds++;
            pixels += p.d.differ;
            gt1 += p.d.differ_gt1;
        }
        osm_pair_close(&p);
    }
    printf("  %u scenes, %ld differ (%ld pixels)\n", seeds, bad_seeds, pixels);
    CHECK(pixels <= KNOWN_OFF_BY_ONE);
    CHECK_EQ_INT(gt1, 0);
}

TEST(infinite_spot_lights_vs_osmesa) { lights_vs_osmesa(check_st_, true, 40); }

TEST(random_lights_vs_osmesa) { lights_vs_osmesa(check_st_, false, 60); }

TEST_LIST = {TEST_ENTRY(infinite_spot_lights_vs_osmesa), TEST_ENTRY(random_lights_vs_osmesa), TEST_END};

int main(int argc, char **argv)
{
    setenv("LP_NUM_THREADS", "1", 0);
    return check_main(argc, argv, test_list);
}
