/*
 * View-frustum and occlusion tests of the culling study (Huettner 1999,
 * sec. 3.1.6).  The occlusion test sends a node's bounding box with colour
 * and depth writes off and asks how many of its fragments passed the depth
 * test against what has been drawn so far:
 *  - query:   GL 1.5 occlusion queries (GL 1.5 spec 4.1.6A, SAMPLES_PASSED),
 *             the count NOHC of the Occlusion Unit;
 *  - hp:      GL_HP_occlusion_test, one flag (offered by the shim only);
 *  - stencil: the dissertation's "virtual occlusion buffer": the box is
 *             drawn into the stencil buffer (REPLACE on depth pass) and
 *             its screen rectangle read back with glReadPixels;
 *  - brief:   the proposed extension's GL_BRIEF_OCCLUSION render mode
 *             (sec. 3.2.1): the box drawn in that mode, its brief record's
 *             NOHC read from the occlusion buffer (offered by the shim only).
 * and the VFC test in GL selection mode (sec. 3.1.6), as the dissertation
 * does it.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "cull.h"
#include "../../glext/GL_FRAGSIM_occlusion_unit.h"

#ifndef GL_OCCLUSION_TEST_HP
#define GL_OCCLUSION_TEST_HP 0x8165
#define GL_OCCLUSION_TEST_RESULT_HP 0x8166
#endif

/* Planes of clip space, -w <= x, y, z <= w, as a.p >= 0 in world space
 * (rows of the combined matrix: Gribb and Hartmann's extraction). */
void cull_view_planes(cull_view *v)
{
    const float *m = v->mvp;
    for (int i = 0; i < 3; i++)
        for (int sgn = 0; sgn < 2; sgn++) {
            float *p = v->planes[2 * i + sgn];
            float s = sgn ? -1.0f : 1.0f;
            for (int k = 0; k < 4; k++) p[k] = m[4 * k + 3] + s * m[4 * k + i];
        }
}

int cull_frustum_test(const cull_view *v, const cull_box *b)
{
    int inside = 1;
    for (int i = 0; i < 6; i++) {
        const float *p = v->planes[i];
        float far_d = p[3], near_d = p[3]; /* the corner furthest along p, and nearest */
        for (int a = 0; a < 3; a++) {
            far_d += p[a] * (p[a] >= 0 ? b->hi[a] : b->lo[a]);
            near_d += p[a] * (p[a] >= 0 ? b->lo[a] : b->hi[a]);
        }
        if (far_d < 0) return 0;
        if (near_d < 0) inside = 0;
    }
    return inside ? 2 : 1;
}

float cull_box_zmin(const cull_view *v, const cull_box *b)
{
    float z = 0;
    for (int a = 0; a < 3; a++) z += v->dir[a] * ((v->dir[a] >= 0 ? b->lo[a] : b->hi[a]) - v->eye[a]);
    return z;
}

int cull_box_contains(const cull_box *b, const float p[3])
{
    for (int a = 0; a < 3; a++)
        if (p[a] < b->lo[a] || p[a] > b->hi[a]) return 0;
    return 1;
}

/* The box as six quads, counter-clockwise seen from outside. */
static void draw_box(const cull_box *b)
{
    static const unsigned char f[6][4] = {
        {0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3},
    };
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 4; k++) {
            int c = f[i][k];
            glVertex3f(c & 4 ? b->hi[0] : b->lo[0], c & 2 ? b->hi[1] : b->lo[1], c & 1 ? b->hi[2] : b->lo[2]);
        }
    glEnd();
}

/* The window rectangle the box can cover: the projected corners, or the
 * whole window when a corner lies behind the eye (w <= 0). */
static void box_rect(const cull_view *v, const cull_box *b, int r[4])
{
    float x0 = (float)v->width, y0 = (float)v->height, x1 = 0, y1 = 0;
    for (int c = 0; c < 8; c++) {
        float p[3] = {c & 4 ? b->hi[0] : b->lo[0], c & 2 ? b->hi[1] : b->lo[1], c & 1 ? b->hi[2] : b->lo[2]};
        float q[4];
        for (int i = 0; i < 4; i++)
            q[i] = v->mvp[i] * p[0] + v->mvp[4 + i] * p[1] + v->mvp[8 + i] * p[2] + v->mvp[12 + i];
        if (q[3] <= 0) {
            r[0] = r[1] = 0;
            r[2] = v->width;
            r[3] = v->height;
            return;
        }
        float x = (q[0] / q[3] * 0.5f + 0.5f) * (float)v->width, y = (q[1] / q[3] * 0.5f + 0.5f) * (float)v->height;
        if (x < x0) x0 = x;
        if (x > x1) x1 = x;
        if (y < y0) y0 = y;
        if (y > y1) y1 = y;
    }
    /* One pixel of margin: the rasterizer samples pixel centres. */
    r[0] = (int)floorf(x0) - 1;
    r[1] = (int)floorf(y0) - 1;
    r[2] = (int)ceilf(x1) + 1;
    r[3] = (int)ceilf(y1) + 1;
    if (r[0] < 0) r[0] = 0;
    if (r[1] < 0) r[1] = 0;
    if (r[2] > v->width) r[2] = v->width;
    if (r[3] > v->height) r[3] = v->height;
}

static uint64_t stencil_test(const cull_view *v, const cull_box *b, int sampling)
{
    int r[4];
    box_rect(v, b, r);
    int w = r[2] - r[0], h = r[3] - r[1];
    if (w <= 0 || h <= 0) return 0;
    glEnable(GL_SCISSOR_TEST);
    glScissor(r[0], r[1], w, h);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    draw_box(b);
    glDisable(GL_STENCIL_TEST);
    unsigned char *row = malloc((size_t)w);
    uint64_t n = 0;
    if (sampling < 1) sampling = 1;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int y = r[1]; row && y < r[3]; y += sampling) {
        glReadPixels(r[0], y, w, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, row);
        for (int x = 0; x < w; x++) n += row[x] != 0;
    }
    int read = row != NULL;
    free(row);
    glClear(GL_STENCIL_BUFFER_BIT); /* leave the virtual occlusion buffer empty */
    glDisable(GL_SCISSOR_TEST);
    return read ? n : 1; /* out of memory: visible, which is safe */
}

/* GL_BRIEF_OCCLUSION: the box's non-occlusion hits in the one tile (the
 * whole viewport), from the brief record glRenderMode(GL_RENDER) writes. */
static uint64_t brief_test(const cull_box *b)
{
    /* Looked up, not linked: libOSMesa has no such entry point, and the
     * program is built against it too (cull_test_unavailable says so). */
    PFNGLOCCLUSIONBUFFERSPROC occlusion_buffers =
        (PFNGLOCCLUSIONBUFFERSPROC)OSMesaGetProcAddress("glOcclusionBuffers");
    if (!occlusion_buffers) return 1; /* visible, which is safe */
    GLuint rec[GL_OCCLUSION_RECORD_WORDS] = {0};
    GLuint *bufs[1] = {rec};
    const GLsizei sizes[1] = {GL_OCCLUSION_RECORD_WORDS};
    occlusion_buffers(sizes, bufs);
    glRenderMode(GL_BRIEF_OCCLUSION);
    draw_box(b);
    if (glRenderMode(GL_RENDER) < 0) return 1;
    return rec[GL_OCCLUSION_RECORD_NOHC];
}

int cull_select_test(const cull_box *b)
{
    GLuint hits[4] = {0};
    glSelectBuffer(4, hits);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    glDisable(GL_CULL_FACE); /* a face seen from behind still intersects the volume */
    glDisable(GL_LIGHTING);
    draw_box(b);
    glEnable(GL_LIGHTING);
    glEnable(GL_CULL_FACE);
    GLint n = glRenderMode(GL_RENDER);
    return n != 0; /* one hit record, or an overflow (-1): the box reaches into the view volume */
}

uint64_t cull_occlusion_test(int test, const cull_view *v, const cull_box *b, int sampling)
{
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    /* Front faces only: "for the correct computation of occlusion, backface
     * culling must be enabled, since otherwise hits can be counted twice"
     * (Huettner 1999, sec. 3.2).  Still conservative: the eye is outside
     * the box (occlusion_walk draws boxes it is in untested), so the front
     * faces cover the box's projection and lie in front of its back faces. */
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDisable(GL_LIGHTING);
    uint64_t n = 1;
    if (test == CULL_TEST_QUERY) {
        GLuint q, samples = 0;
        glGenQueries(1, &q);
        glBeginQuery(GL_SAMPLES_PASSED, q);
        draw_box(b);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
        glDeleteQueries(1, &q);
        n = samples;
    } else if (test == CULL_TEST_HP) {
        GLboolean hit = GL_TRUE;
        glEnable(GL_OCCLUSION_TEST_HP);
        draw_box(b);
        glDisable(GL_OCCLUSION_TEST_HP);
        glGetBooleanv(GL_OCCLUSION_TEST_RESULT_HP, &hit);
        n = hit ? 1 : 0;
    } else if (test == CULL_TEST_STENCIL) {
        n = stencil_test(v, b, sampling);
    } else if (test == CULL_TEST_BRIEF) {
        n = brief_test(b);
    }
    glEnable(GL_LIGHTING);
    glEnable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return n;
}

const char *cull_test_unavailable(int test)
{
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    if (test == CULL_TEST_BRIEF && (!ext || !strstr(ext, "GL_FRAGSIM_occlusion_unit") ||
                                    !OSMesaGetProcAddress("glOcclusionBuffers")))
        return "this GL does not offer GL_FRAGSIM_occlusion_unit (GL_BRIEF_OCCLUSION; libOSMesa does not, the shim does)";
    if (test == CULL_TEST_HP && (!ext || !strstr(ext, "GL_HP_occlusion_test")))
        return "this GL does not offer GL_HP_occlusion_test (libOSMesa 22.3 does not; the shim does)";
    if (test == CULL_TEST_STENCIL) {
        GLint bits = 0;
        glGetIntegerv(GL_STENCIL_BITS, &bits);
        if (bits < 1) return "--test stencil needs a stencil buffer";
    }
    return NULL;
}
