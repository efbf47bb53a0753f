/*
 * fs_vp_pow (pipeline/vp_pow.c) against llvmpipe's own POW, value by
 * value.  Oracle: an ARB vertex program on OSMesa (prog_to_nir turns its
 * POW into NIR's fpow, as it does the fixed-function program's, and
 * gallivm evaluates it) that writes POW(s, t) of its texture coordinate to
 * its output texture coordinate, read back in GL_FEEDBACK mode
 * (GL_4D_COLOR_TEXTURE, unclamped floats).  The bases sweep (0, 2] and
 * the edge values (0, -0, negative, denormal, inf, NaN), the exponents the
 * lighting's range and beyond.  Compared bit for bit (any NaN equals any
 * NaN).
 */
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/vp_pow.h"

#define NPAIRS 6000

static float base_of(int i, uint32_t *rng)
{
    static const float edge[] = {0.0f, -0.0f, 1.0f, -1.0f, -0.5f, 2.0f, 0.5f, 1e-30f, 1e-38f, 1e-40f, 1e-45f,
                                 INFINITY, -INFINITY, NAN, 1.0000001f, 0.99999994f, 3.0e38f, 65536.0f};
    const int ne = (int)(sizeof edge / sizeof edge[0]);
    if (i < ne)
        return edge[i];
    *rng = *rng * 1664525u + 1013904223u;
    float u = (float)(*rng >> 8) / 16777216.0f;
    if (i % 4 == 0)
        return u * 2.0f;          /* (0, 2) */
    if (i % 4 == 1)
        return 1.0f - u * 0.05f;  /* near 1: the specular factor's n.H */
    if (i % 4 == 2)
        return powf(2.0f, -u * 40.0f); /* small */
    return u;                     /* (0, 1): spot cosines */
}

static float expo_of(int i)
{
    static const float e[] = {0.0f, 0.5f, 1.0f, 2.0f, 3.0f, 5.0f, 7.3f, 10.0f, 20.0f, 37.3f, 64.0f, 128.0f,
                              -1.0f, -2.5f, -128.0f, 200.0f, 0.1f, 1e-3f};
    return e[i % (int)(sizeof e / sizeof e[0])];
}

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

static bool same(float a, float b)
{
    uint32_t x, y;
    memcpy(&x, &a, 4);
    memcpy(&y, &b, 4);
    return x == y || (isnan(a) && isnan(b));
}

/* Runs the program on OSMesa over the pairs; false without the extension. */
static bool osmesa_pow(const float *xs, const float *ys, float *out, int n)
{
    static const char prog[] = "!!ARBvp1.0\n"
                               "MOV result.position, vertex.position;\n"
                               "MOV result.color, vertex.color;\n"
                               "POW result.texcoord[0].x, vertex.texcoord[0].x, vertex.texcoord[0].y;\n"
                               "MOV result.texcoord[0].yzw, vertex.texcoord[0];\n"
                               "END\n";
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    if (!ext || !strstr(ext, "GL_ARB_vertex_program"))
        return false;
    PFNGLGENPROGRAMSARBPROC gen = (PFNGLGENPROGRAMSARBPROC)OSMesaGetProcAddress("glGenProgramsARB");
    PFNGLBINDPROGRAMARBPROC bind = (PFNGLBINDPROGRAMARBPROC)OSMesaGetProcAddress("glBindProgramARB");
    PFNGLPROGRAMSTRINGARBPROC str = (PFNGLPROGRAMSTRINGARBPROC)OSMesaGetProcAddress("glProgramStringARB");
    if (!gen || !bind || !str)
        return false;
    GLuint id;
    gen(1, &id);
    bind(GL_VERTEX_PROGRAM_ARB, id);
    str(GL_VERTEX_PROGRAM_ARB, GL_PROGRAM_FORMAT_ASCII_ARB, (GLsizei)strlen(prog), prog);
    if (glGetError() != GL_NO_ERROR)
        return false;
    glEnable(GL_VERTEX_PROGRAM_ARB);
    static float fb[NPAIRS * 16];
    glFeedbackBuffer(NPAIRS * 16, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    for (int i = 0; i < n; i++) {
        glTexCoord2f(xs[i], ys[i]);
        glVertex3f(0.0f, 0.0f, 0.0f);
    }
    glEnd();
    int m = glRenderMode(GL_RENDER);
    int k = 0;
    for (int i = 0; i + 13 <= m && k < n; i += 13) /* token, then 12 floats */
        out[k++] = fb[i + 9];
    return k == n;
}

TEST(pow_vs_osmesa_vertex_program)
{
    static float xs[NPAIRS], ys[NPAIRS], ref[NPAIRS];
    uint32_t rng = 99u;
    for (int i = 0; i < NPAIRS; i++) {
        xs[i] = base_of(i / 18 < 18 ? i / 18 : i, &rng);
        ys[i] = expo_of(i);
    }
    osm o;
    if (!osm_open(&o, 16, 16)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    bool ok = osmesa_pow(xs, ys, ref, NPAIRS);
    osm_close(&o);
    if (!ok)
        SKIP("no GL_ARB_vertex_program on OSMesa");
    int differ = 0;
    for (int i = 0; i < NPAIRS; i++) {
        float mine = fs_vp_pow(xs[i], ys[i]);
        if (!same(mine, ref[i])) {
            if (differ < 10)
                CHECK_FAIL_("pow(%.9g, %.9g): fragsim %.9g (0x%08x), OSMesa %.9g", (double)xs[i], (double)ys[i],
                            (double)mine, (unsigned)bits_of(mine), (double)ref[i]);
            differ++;
        }
    }
    printf("    %d pairs, %d differ\n", NPAIRS, differ);
}

TEST_LIST = {
    TEST_ENTRY(pow_vs_osmesa_vertex_program),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
