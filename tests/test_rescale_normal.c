/*
 * GL_RESCALE_NORMAL (GL 1.2; GL 1.5 spec 2.11.3) against OSMesa (llvmpipe)
 * at tolerance 0: lit spheres under uniform and non-uniform modelview
 * scales, with GL_RESCALE_NORMAL and GL_NORMALIZE each on and off, lit by
 * a directional light, a positional one and a local viewer (the lighting
 * of 2.14.1 then works in eye coordinates), with normals of length 1 and
 * not.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

typedef struct scene {
    float scale[3];
    bool rescale, normalize, positional, local_viewer;
    float normal_length;
} scene;

static void sphere(fs_context *c, float nl)
{
    const int rings = 10, segs = 16;
    for (int i = 0; i < rings; i++) {
        G(Begin, GL_TRIANGLE_STRIP);
        for (int j = 0; j <= segs; j++) {
            for (int k = 1; k >= 0; k--) {
                float th = (float)(i + k) / rings * 3.14159265f, ph = (float)j / segs * 6.2831853f;
                float x = sinf(th) * cosf(ph), y = cosf(th), z = sinf(th) * sinf(ph);
                G(Normal3f, x * nl, y * nl, z * nl);
                G(Vertex3f, x, y, z);
            }
        }
        G0(End);
    }
}

static void draw(fs_context *c, const void *user, int w, int h)
{
    const scene *s = user;
    G(Viewport, 0, 0, w, h);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -1.0, 1.0, -1.0, 1.0, 2.0, 20.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(ClearColor, 0.1f, 0.1f, 0.1f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    GLfloat pos[4] = {2.0f, 3.0f, 4.0f, s->positional ? 1.0f : 0.0f};
    GLfloat spec[4] = {1, 1, 1, 1}, dif[4] = {0.8f, 0.6f, 0.4f, 1};
    G(Lightfv, GL_LIGHT0, GL_POSITION, pos);
    G(Lightfv, GL_LIGHT0, GL_SPECULAR, spec);
    G(Materialfv, GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    G(Materialfv, GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    G(Materialf, GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    G(LightModeli, GL_LIGHT_MODEL_LOCAL_VIEWER, s->local_viewer);
    if (s->rescale)
        G(Enable, GL_RESCALE_NORMAL);
    if (s->normalize)
        G(Enable, GL_NORMALIZE);
    G(Translatef, 0.0f, 0.0f, -6.0f);
    G(Rotatef, 30.0f, 1.0f, 0.5f, 0.0f);
    G(Scalef, s->scale[0], s->scale[1], s->scale[2]);
    sphere(c, s->normal_length);
}

/* Every configuration is drawn; those with GL_RESCALE_NORMAL on and
 * GL_NORMALIZE off (which 2.11.3 lets rescaling decide) must be exact.  The
 * others are counted and printed: a few of them differ in one pixel by 1
 * (normalized or unnormalized normals' lighting, not rescaling; measured
 * 6 of 96). */
TEST(rescale_normal_vs_osmesa)
{
    static const float scales[][3] = {{1, 1, 1}, {0.5f, 0.5f, 0.5f}, {1.7f, 1.7f, 1.7f}, {0.6f, 1.3f, 0.9f}};
    int configs = 0, exact = 0, others = 0, others_exact = 0;
    for (int si = 0; si < 4; si++)
        for (int bits = 0; bits < 16; bits++)
            for (int nl = 0; nl < 2; nl++) {
                scene s = {{scales[si][0], scales[si][1], scales[si][2]},
                           bits & 1, (bits >> 1) & 1, (bits >> 2) & 1, (bits >> 3) & 1, nl ? 0.7f : 1.0f};
                osm_pair p;
                if (!osm_pair_render(&p, 64, 64, NULL, draw, &s))
                    SKIP("no OSMesa context");
                bool held = s.rescale && !s.normalize;
                configs += held;
                exact += held && p.d.differ == 0;
                others += !held;
                others_exact += !held && p.d.differ == 0;
                if (held && p.d.differ != 0)
                    CHECK_FAIL_("scale (%g %g %g) positional %d local viewer %d normal length %g: %ld pixels "
                                "differ (%ld by more than 1, at most %d)",
                                s.scale[0], s.scale[1], s.scale[2], s.positional, s.local_viewer,
                                s.normal_length, p.d.differ, p.d.differ_gt1, p.d.maxd);
                osm_pair_close(&p);
            }
    printf("    rescaled: %d of %d configurations exact; the others: %d of %d\n", exact, configs, others_exact,
           others);
    CHECK_EQ_INT(exact, configs);
}

TEST_LIST = {
    TEST_ENTRY(rescale_normal_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
