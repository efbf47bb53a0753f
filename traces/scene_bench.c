/*
 * Throughput benchmarks: many small random triangles of a fixed area.
 *
 * No paper workload; the 8- and 32-pixel sizes bracket the small triangles
 * of the paper scenes (e.g. 28,500-triangle trees and 2,100-triangle garbage
 * objects a few hundred pixels across), where per-triangle setup rather than
 * per-fragment work dominates.  One frame at 1024x1024: glOrtho in window
 * coordinates, so the area is exact in pixels whatever the size, drawn from
 * vertex arrays with glDrawArrays(GL_TRIANGLES) in chunks, depth test on,
 * smooth per-vertex colours, no lighting and no culling.
 */
#include <math.h>
#include <stdio.h>
#include "sg.h"

#define BENCH_CHUNK 4096

static int bench_run(sg *s, const sg_params *p, double area, char *err, size_t errlen)
{
    float *pos = sg_buf(s, 0, BENCH_CHUNK * 3 * 3 * sizeof(float));
    GLubyte *col = sg_buf(s, 1, BENCH_CHUNK * 3 * 4);
    if (!pos || !col) {
        snprintf(err, errlen, "bench: out of memory");
        return -1;
    }
    G(s, Enable, GL_DEPTH_TEST);
    G(s, DepthFunc, GL_LESS);
    G(s, ShadeModel, GL_SMOOTH);
    G(s, MatrixMode, GL_PROJECTION);
    G0(s, LoadIdentity);
    G(s, Ortho, 0.0, (double)p->width, 0.0, (double)p->height, -1.0, 1.0);
    G(s, MatrixMode, GL_MODELVIEW);
    G0(s, LoadIdentity);
    G(s, EnableClientState, GL_VERTEX_ARRAY);
    G(s, EnableClientState, GL_COLOR_ARRAY);
    G(s, VertexPointer, 3, GL_FLOAT, 0, pos);
    G(s, ColorPointer, 4, GL_UNSIGNED_BYTE, 0, col);

    /* A right isosceles triangle of legs l has area l^2 / 2. */
    float leg = (float)sqrt(2.0 * area);
    for (int fr = 0; fr < p->frames; fr++) {
        sg_rng r;
        sg_rng_seed(&r, p->seed * 104729 + (uint64_t)fr);
        sg_frame_begin(s, 0.0f, 0.0f, 0.0f);
        for (uint64_t done = 0; done < p->target;) {
            uint64_t k = p->target - done < BENCH_CHUNK ? p->target - done : BENCH_CHUNK;
            for (uint64_t i = 0; i < k; i++) {
                float x = (float)sg_rng_range(&r, leg, p->width - leg);
                float y = (float)sg_rng_range(&r, leg, p->height - leg);
                float z = (float)sg_rng_range(&r, -0.99, 0.99);
                float a = (float)sg_rng_range(&r, 0, 6.283185307179586);
                float ux = leg * cosf(a), uy = leg * sinf(a);
                float *v = pos + i * 9;
                v[0] = x; v[1] = y; v[2] = z;
                v[3] = x + ux; v[4] = y + uy; v[5] = z;
                v[6] = x - uy; v[7] = y + ux; v[8] = z;
                for (int j = 0; j < 12; j++) col[i * 12 + (uint64_t)j] = (GLubyte)(j % 4 == 3 ? 255 : sg_rng_int(&r, 256));
            }
            sg_draw_arrays(s, GL_TRIANGLES, 0, (GLsizei)(3 * k));
            done += k;
        }
        sg_frame_end(s);
    }
    G(s, DisableClientState, GL_COLOR_ARRAY);
    G(s, DisableClientState, GL_VERTEX_ARRAY);
    return 0;
}

int sg_scene_bench8(sg *s, const sg_params *p, char *err, size_t errlen)
{
    return bench_run(s, p, 8.0, err, errlen);
}

int sg_scene_bench32(sg *s, const sg_params *p, char *err, size_t errlen)
{
    return bench_run(s, p, 32.0, err, errlen);
}
