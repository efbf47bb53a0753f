/*
 * Workload of the occlusion studies (docs/studies/occlusion.md and
 * query_cost.md): occlusion-driven rendering as Huettner 1999, 3.2 uses the
 * Occlusion Unit.  A wall hides part of a grid of object groups; per frame
 * the wall is drawn, then each group's bounding box is tested and the
 * group's boxes are drawn only when the test reports visible pixels.
 *
 *   --test brief   the box in GL_BRIEF_OCCLUSION with T tiles set by
 *                  glScissors (a t x t grid over the window, T = t*t); the
 *                  glRenderMode(GL_RENDER) that returns the counts drains
 *                  the pipeline (3.2.1)
 *   --test query   a GL 1.5 occlusion query per box (GL_SAMPLES_PASSED),
 *                  its result read at once
 *
 * Built and run by scripts/sweep_study.sh (it links build/libfragsim.a and
 * captures a trace through driver/capture.h); not part of the library.
 *
 *   occlusion_workload [--test brief|query] [--tiles T] [--groups G]
 *                      [--frames F] [--size N] -o OUT.trace
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../../pipeline/context.h"
#include "../../glext/GL_FRAGSIM_occlusion_unit.h"
#include "../../driver/capture.h"

static void box(fs_context *c, float x0, float y0, float z0, float x1, float y1, float z1)
{
    static const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    float v[8][3];
    for (int i = 0; i < 8; i++) {
        v[i][0] = i & 4 ? x1 : x0;
        v[i][1] = i & 2 ? y1 : y0;
        v[i][2] = i & 1 ? z1 : z0;
    }
    fsglBegin(c, GL_QUADS);
    for (int f = 0; f < 6; f++)
        for (int k = 0; k < 4; k++)
            fsglVertex3fv(c, v[faces[f][k]]);
    fsglEnd(c);
}

int main(int argc, char **argv)
{
    const char *out = NULL, *test = "brief";
    int tiles = 1, groups = 64, frames = 2, size = 256;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v) {
            fprintf(stderr, "occlusion_workload: %s needs a value\n", a);
            return 2;
        }
        i++;
        if (!strcmp(a, "-o"))
            out = v;
        else if (!strcmp(a, "--test"))
            test = v;
        else if (!strcmp(a, "--tiles"))
            tiles = atoi(v);
        else if (!strcmp(a, "--groups"))
            groups = atoi(v);
        else if (!strcmp(a, "--frames"))
            frames = atoi(v);
        else if (!strcmp(a, "--size"))
            size = atoi(v);
        else {
            fprintf(stderr, "occlusion_workload: unknown option %s\n", a);
            return 2;
        }
    }
    int t = (int)lround(sqrt((double)tiles));
    bool brief = !strcmp(test, "brief");
    if (!out || (!brief && strcmp(test, "query")) || t < 1 || t * t != tiles || tiles > 4096 || groups < 1 ||
        groups > 4096 || frames < 1 || frames > 1000 || size < 16 || size > 4096) {
        fprintf(stderr, "usage: occlusion_workload [--test brief|query] [--tiles T (a square)] [--groups G] "
                        "[--frames F] [--size N] -o OUT.trace\n");
        return 2;
    }
    fs_context *c = fs_context_create(NULL, size, size);
    char err[256];
    if (!c || fs_capture_open(c, out, err, sizeof err) != 0) {
        fprintf(stderr, "occlusion_workload: %s\n", c ? err : "cannot create a context");
        return 1;
    }
    fsglViewport(c, 0, 0, size, size);
    fsglEnable(c, GL_DEPTH_TEST);
    fsglEnable(c, GL_CULL_FACE);
    GLint *rects = malloc(sizeof *rects * 4 * (size_t)tiles);
    GLuint *records = malloc(sizeof *records * GL_OCCLUSION_RECORD_WORDS * (size_t)tiles);
    GLuint **bufs = malloc(sizeof *bufs * (size_t)tiles);
    GLsizei *sizes = malloc(sizeof *sizes * (size_t)tiles);
    if (!rects || !records || !bufs || !sizes)
        return 1;
    for (int k = 0; k < tiles; k++) {
        int tx = k % t, ty = k / t;
        rects[4 * k] = tx * size / t;
        rects[4 * k + 1] = ty * size / t;
        rects[4 * k + 2] = (tx + 1) * size / t - rects[4 * k];
        rects[4 * k + 3] = (ty + 1) * size / t - rects[4 * k + 1];
        bufs[k] = records + (size_t)k * GL_OCCLUSION_RECORD_WORDS;
        sizes[k] = GL_OCCLUSION_RECORD_WORDS;
    }
    GLuint query = 0;
    if (brief)
        fsglScissors(c, tiles, rects);
    else
        fsglGenQueries(c, 1, &query);
    int side = (int)ceil(sqrt((double)groups));
    for (int f = 0; f < frames; f++) {
        fsglClear(c, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        fsglMatrixMode(c, GL_PROJECTION);
        fsglLoadIdentity(c);
        fsglFrustum(c, -1, 1, -1, 1, 1, 100);
        fsglMatrixMode(c, GL_MODELVIEW);
        fsglLoadIdentity(c);
        fsglTranslatef(c, 0, -0.5f, -4);
        fsglRotatef(c, 20, 1, 0, 0);
        fsglRotatef(c, (float)(10 * f - 10), 0, 1, 0);
        /* The occluder: a wall over the left half, in front of the grid. */
        fsglColor3f(c, 0.6f, 0.6f, 0.6f);
        box(c, -3.0f, -1.0f, -0.6f, 0.2f, 2.5f, -0.4f);
        for (int g = 0; g < groups; g++) {
            float gx = -3.0f + 6.0f * (float)(g % side) / (float)side;
            float gz = -1.0f - 6.0f * (float)(g / side) / (float)side;
            float w = 5.0f / (float)side;
            GLuint visible = 0;
            if (brief) {
                fsglOcclusionBuffers(c, sizes, (const GLvoid *)bufs);
                fsglRenderMode(c, GL_BRIEF_OCCLUSION);
                box(c, gx, -1.0f, gz - w, gx + w, 0.2f, gz);
                fsglRenderMode(c, GL_RENDER);
                for (int k = 0; k < tiles; k++)
                    visible += records[(size_t)k * GL_OCCLUSION_RECORD_WORDS + GL_OCCLUSION_RECORD_NOHC];
            } else {
                fsglColorMask(c, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
                fsglDepthMask(c, GL_FALSE);
                fsglBeginQuery(c, GL_SAMPLES_PASSED, query);
                box(c, gx, -1.0f, gz - w, gx + w, 0.2f, gz);
                fsglEndQuery(c, GL_SAMPLES_PASSED);
                fsglGetQueryObjectuiv(c, query, GL_QUERY_RESULT, &visible);
                fsglColorMask(c, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                fsglDepthMask(c, GL_TRUE);
            }
            if (visible == 0)
                continue;
            /* The group: a few boxes inside its bounding box. */
            fsglColor3f(c, 0.2f + 0.6f * (float)(g % 3) / 2, 0.5f, 0.8f - 0.6f * (float)(g % 5) / 4);
            for (int b = 0; b < 4; b++) {
                float bx = gx + w * (float)(b % 2) / 2, bz = gz - w * (float)(b / 2) / 2;
                box(c, bx, -1.0f, bz - w / 2.5f, bx + w / 2.5f, -1.0f + 0.3f * (float)(1 + (g + b) % 4), bz);
            }
        }
        fs_capture_frame_end(c);
    }
    int rc = fs_capture_close(c) == 0 ? 0 : 1;
    fs_context_destroy(c);
    free(rects);
    free(records);
    free(bufs);
    free(sizes);
    return rc;
}
