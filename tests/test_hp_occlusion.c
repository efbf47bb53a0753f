/*
 * GL_HP_occlusion_test on the Occlusion Unit: the result is TRUE when any
 * fragment passed the depth test while the test was enabled, and reading it
 * clears it.  Mesa no longer implements the extension, so the oracle is
 * OSMesa's GL_SAMPLES_PASSED for the same draws: HP's result must equal
 * "samples > 0".
 */
#define GL_GLEXT_PROTOTYPES 1 /* the GL 1.5 query prototypes */
#include <GL/osmesa.h>
#include <stdlib.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

#define W 64
#define H 64

/* A square at depth z (eye space, ortho), half size h, centred at (x, y). */
static void fs_square(fs_context *c, float x, float y, float h, float z)
{
    fsglBegin(c, GL_QUADS);
    fsglVertex3f(c, x - h, y - h, z);
    fsglVertex3f(c, x + h, y - h, z);
    fsglVertex3f(c, x + h, y + h, z);
    fsglVertex3f(c, x - h, y + h, z);
    fsglEnd(c);
}

static void gl_square(float x, float y, float h, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x - h, y - h, z);
    glVertex3f(x + h, y - h, z);
    glVertex3f(x + h, y + h, z);
    glVertex3f(x - h, y + h, z);
    glEnd();
}

typedef struct probe { float x, y, h, z; } probe;

/* A wall at z = 0 over the left half of the window, with identity matrices:
 * window depth grows with z, so a probe with z < 0 is in front of the wall
 * and one with z > 0 is behind it. */
static const probe probes[] = {
    {-0.5f, 0.0f, 0.2f, 0.5f},  /* behind the wall: hidden */
    {-0.5f, 0.0f, 0.2f, -0.5f}, /* in front of the wall: visible */
    {0.5f, 0.0f, 0.2f, 0.5f},   /* beside the wall: visible */
    {-0.5f, 0.4f, 0.1f, 0.9f},  /* behind, near the top: hidden */
    {3.0f, 3.0f, 0.2f, 0.0f},   /* outside the window: nothing */
};
#define NPROBES (int)(sizeof probes / sizeof probes[0])

TEST(hp_result_equals_osmesa_samples)
{
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c != NULL);
    static uint8_t buf[W * H * 4];
    OSMesaContext o = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    REQUIRE(o && OSMesaMakeCurrent(o, buf, GL_UNSIGNED_BYTE, W, H));
    CHECK(strstr((const char *)fsglGetString(c, GL_EXTENSIONS), "GL_HP_occlusion_test") != NULL);

    fsglEnable(c, GL_DEPTH_TEST);
    glEnable(GL_DEPTH_TEST);
    fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fs_square(c, -0.5f, 0.0f, 0.5f, 0.0f);
    gl_square(-0.5f, 0.0f, 0.5f, 0.0f);

    GLuint q;
    glGenQueries(1, &q);
    fsglEnable(c, GL_OCCLUSION_TEST_HP);
    CHECK_EQ_INT(fsglIsEnabled(c, GL_OCCLUSION_TEST_HP), GL_TRUE);
    GLboolean r;
    fsglGetBooleanv(c, GL_OCCLUSION_TEST_RESULT_HP, &r); /* the wall was drawn before enabling */
    CHECK_EQ_INT(r, GL_FALSE);
    for (int i = 0; i < NPROBES; i++) {
        const probe *p = &probes[i];
        fsglDepthMask(c, GL_FALSE); /* probes test without changing depth */
        glDepthMask(GL_FALSE);
        fs_square(c, p->x, p->y, p->h, p->z);
        glBeginQuery(GL_SAMPLES_PASSED, q);
        gl_square(p->x, p->y, p->h, p->z);
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint samples = 0;
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
        fsglGetBooleanv(c, GL_OCCLUSION_TEST_RESULT_HP, &r);
        printf("    probe %d: HP %s, OSMesa samples %u\n", i, r ? "TRUE" : "FALSE", samples);
        CHECK_EQ_INT(r, samples > 0 ? GL_TRUE : GL_FALSE);
        fsglGetBooleanv(c, GL_OCCLUSION_TEST_RESULT_HP, &r); /* read again: cleared */
        CHECK_EQ_INT(r, GL_FALSE);
    }
    /* Disabled: visible fragments leave the result alone; enabling again
     * does not clear a result set before. */
    fsglDisable(c, GL_OCCLUSION_TEST_HP);
    fs_square(c, 0.5f, 0.0f, 0.2f, -0.5f);
    fsglGetBooleanv(c, GL_OCCLUSION_TEST_RESULT_HP, &r);
    CHECK_EQ_INT(r, GL_FALSE);
    fsglEnable(c, GL_OCCLUSION_TEST_HP);
    fs_square(c, 0.5f, 0.0f, 0.2f, -0.5f);
    fsglDisable(c, GL_OCCLUSION_TEST_HP);
    fsglEnable(c, GL_OCCLUSION_TEST_HP);
    GLint ri = -1;
    fsglGetIntegerv(c, GL_OCCLUSION_TEST_RESULT_HP, &ri);
    CHECK_EQ_INT(ri, 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    glDeleteQueries(1, &q);
    glFinish();
    OSMesaDestroyContext(o);
    fs_context_destroy(c);
}

/* The GL_ARB_occlusion_query names run the same queries: counts equal
 * OSMesa's through its ARB entry points. */
TEST(arb_query_names_match_osmesa)
{
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c != NULL);
    static uint8_t buf[W * H * 4];
    OSMesaContext o = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    REQUIRE(o && OSMesaMakeCurrent(o, buf, GL_UNSIGNED_BYTE, W, H));
    CHECK(strstr((const char *)fsglGetString(c, GL_EXTENSIONS), "GL_ARB_occlusion_query") != NULL);
    fsglEnable(c, GL_DEPTH_TEST);
    glEnable(GL_DEPTH_TEST);
    fsglClear(c, GL_DEPTH_BUFFER_BIT);
    glClear(GL_DEPTH_BUFFER_BIT);
    fs_square(c, -0.5f, 0.0f, 0.5f, 0.0f);
    gl_square(-0.5f, 0.0f, 0.5f, 0.0f);
    GLuint fq = 0, oq = 0;
    fsglGenQueriesARB(c, 1, &fq);
    glGenQueriesARB(1, &oq);
    CHECK(fq != 0);
    for (int i = 0; i < NPROBES; i++) {
        const probe *p = &probes[i];
        fsglBeginQueryARB(c, GL_SAMPLES_PASSED, fq);
        fs_square(c, p->x, p->y, p->h, p->z);
        fsglEndQueryARB(c, GL_SAMPLES_PASSED);
        glBeginQueryARB(GL_SAMPLES_PASSED, oq);
        gl_square(p->x, p->y, p->h, p->z);
        glEndQueryARB(GL_SAMPLES_PASSED);
        GLuint a = 1234, b = 5678, avail = 0;
        fsglGetQueryObjectuivARB(c, fq, GL_QUERY_RESULT_AVAILABLE, &avail);
        fsglGetQueryObjectuivARB(c, fq, GL_QUERY_RESULT, &a);
        glGetQueryObjectuivARB(oq, GL_QUERY_RESULT, &b);
        CHECK_EQ_UINT(avail, GL_TRUE);
        CHECK_EQ_UINT(a, b);
    }
    CHECK_EQ_INT(fsglIsQueryARB(c, fq), GL_TRUE);
    fsglDeleteQueriesARB(c, 1, &fq);
    CHECK_EQ_INT(fsglIsQueryARB(c, fq), GL_FALSE);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    glDeleteQueriesARB(1, &oq);
    glFinish();
    OSMesaDestroyContext(o);
    fs_context_destroy(c);
}

TEST_LIST = {TEST_ENTRY(hp_result_equals_osmesa_samples), TEST_ENTRY(arb_query_names_match_osmesa), TEST_END};

int main(int argc, char **argv)
{
    setenv("LP_NUM_THREADS", "1", 0);
    return check_main(argc, argv, test_list);
}
