/* Debug probe (outside the build): replays a trace on the model and on
 * OSMesa with the same decoded calls; the call numbered CALL runs in
 * GL_FEEDBACK mode (GL_3D_COLOR) on both, and the vertices of the
 * primitives covering pixel (X, Y) (GL window coordinates) are printed from
 * both, with every vertex whose feedback differs.
 *   lsb_probe TRACE CALL X Y
 * With CALL "first": the first call (of those that render) after which
 * the two colour buffers (RGBA, as fragsim check) differ, and its
 * differing pixels (up to 10); frame ends are compared too.
 * Build (the archives whole, else the weak fallback executors of
 * driver/dispatch.c win and the model draws nothing):
 *   gcc -O1 -g -Wall -o /tmp/probe tests/wip/lsb_probe.c build/driver/osmesa_ref.o \
 *     -Wl,--whole-archive build/libfragsim.a -Wl,--no-whole-archive \
 *     $(pkg-config --libs osmesa snappy zlib inih jansson libgpiod) -lm -lstdc++
 * Experiments (environment):
 *   PROBE_FRAMES=1       "first" compares at frame ends only (llvmpipe's
 *                        result may depend on where it is flushed: the
 *                        probe's glFinish after each draw ends Mesa's
 *                        merging of glBegin/glEnd draws, issue 20)
 *   PROBE_FLUSH_O=A-B    glFinish on OSMesa after each render call in A..B
 *   PROBE_FLUSH_M=1      fsglFinish on the model after each render call
 *   PROBE_SKIP=A-B[,C-D] leave those calls out on both
 *   PROBE_PIXEL=X,Y      print the model's pixel after each call changing it
 *   PROBE_SAMPLES=1      run OSMesa's GL_SAMPLES_PASSED query as check does
 *   PROBE_NOALPHA=1      feedback: compare positions and RGB only
 *   PROBE_ALPHA_ONE=1    glMaterialfv's alpha set to 1 on both */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../../pipeline/context.h"
#include "../../driver/gl_call.h"
#include "../../driver/replay.h"
#include "../../driver/osmesa_ref.h"

#define FB 4000000
static float fb_m[FB], fb_o[FB];

static int inside(const float *v, int n, float px, float py)
{
    /* any triangle of the fan */
    for (int k = 1; k + 1 < n; k++) {
        const float *a = v, *b = v + 7 * k, *c = v + 7 * (k + 1);
        float d1 = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
        float d2 = (c[0] - b[0]) * (py - b[1]) - (c[1] - b[1]) * (px - b[0]);
        float d3 = (a[0] - c[0]) * (py - c[1]) - (a[1] - c[1]) * (px - c[0]);
        if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0))
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: lsb_probe TRACE CALL X Y\n");
        return 2;
    }
    bool first = !strcmp(argv[2], "first");
    char *dash = NULL;
    uint64_t start = first ? UINT64_MAX : strtoull(argv[2], &dash, 10);
    uint64_t target = dash && *dash == '-' ? strtoull(dash + 1, NULL, 10) : start;
    float px = (float)atof(argv[3]) + 0.5f, py = (float)atof(argv[4]) + 0.5f;
    char err[512];
    fs_config cfg;
    fs_config_defaults(&cfg); /* the window size fragsim check uses */
    fs_replay_opts ro = {NULL, (int)cfg.framebuffer_width, (int)cfg.framebuffer_height};
    fs_replayer *r = fs_replay_open(argv[1], &ro, err, sizeof err);
    if (!r) { fprintf(stderr, "%s\n", err); return 1; }
    const fs_replay_info *info = fs_replay_info_get(r);
    fs_context *c = fs_context_create(&cfg, info->width, info->height);
    fs_context_set_double_buffered(c, info->double_buffered); /* as fragsim check does */
    fs_osmesa *o = fs_osmesa_create(info->width, info->height, 24, 8, err, sizeof err);
    if (!c || !o) { fprintf(stderr, "create: %s\n", err); return 1; }
    if (getenv("PROBE_SAMPLES"))
        fs_osmesa_samples_begin(o); /* as fragsim check does */
    fs_call call;
    for (;;) {
        fs_replay_event ev = fs_replay_next(r, &call);
        if (ev == FS_REPLAY_EOF || ev == FS_REPLAY_ERROR) break;
        if (ev != FS_REPLAY_CALL && ev != FS_REPLAY_FRAME_END) continue;
        bool frame_end = ev == FS_REPLAY_FRAME_END;
        uint64_t no = fs_replay_call_no(r);
        if (no == start) {
            fsglFeedbackBuffer(c, FB, GL_3D_COLOR, fb_m);
            fsglRenderMode(c, GL_FEEDBACK);
            glFeedbackBuffer(FB, GL_3D_COLOR, fb_o);
            glRenderMode(GL_FEEDBACK);
        }
        bool skip_call = false;
        if (getenv("PROBE_SKIP")) { /* experiments: leave out calls A-B on both */
            const char *sp = getenv("PROBE_SKIP"); /* A-B[,C-D...] */
            while (sp && *sp) {
                unsigned long long sa = 0, sb = 0;
                if (sscanf(sp, "%llu-%llu", &sa, &sb) == 2 && no >= sa && no <= sb)
                    skip_call = true;
                sp = strchr(sp, ',');
                sp = sp ? sp + 1 : NULL;
            }
        }
        if (!frame_end && call.cmd == FS_CMD_Materialfv && getenv("PROBE_ALPHA_ONE")) {
            /* experiment: material alphas of 1 instead of the trace's */
            static float pm[4];
            const float *q = call.a[2].p;
            if (q && call.a[2].count >= 4) {
                memcpy(pm, q, sizeof pm);
                pm[3] = 1.0f;
                call.a[2].p = pm;
            }
        }
        if (!frame_end && !skip_call) {
            fs_submit(c, &call);
            fs_osmesa_dispatch(o, &call);
            /* experiments: flush one side after each render call */
            if ((fs_replay_call_flags(r) & 0x4u) && getenv("PROBE_FLUSH_O")) {
                unsigned long long fa = 0, fb = ~0ull;
                sscanf(getenv("PROBE_FLUSH_O"), "%llu-%llu", &fa, &fb);
                if (no >= fa && no <= fb)
                    glFinish();
            }
            if ((fs_replay_call_flags(r) & 0x4u) && getenv("PROBE_FLUSH_M"))
                fsglFinish(c);
            if ((fs_replay_call_flags(r) & 0x4u) && getenv("PROBE_PIXEL")) {
                /* the model's pixel after each render call that changes it */
                static uint8_t last[4];
                int qx = 0, qy = 0;
                sscanf(getenv("PROBE_PIXEL"), "%d,%d", &qx, &qy);
                fsglFinish(c);
                const uint8_t *q = c->fb.color + 4 * ((size_t)qy * info->width + qx);
                if (memcmp(q, last, 4))
                    printf("call %llu %s: model pixel (%d, %d) = %d %d %d %d\n", (unsigned long long)no,
                           fs_replay_call_name(r), qx, qy, q[0], q[1], q[2], q[3]);
                memcpy(last, q, 4);
            }
        }
        if (first && (frame_end || (!getenv("PROBE_FRAMES") && (fs_replay_call_flags(r) & 0x4u)))) {
            fsglFinish(c);
            const uint8_t *a = c->fb.color, *b = fs_osmesa_color(o);
            long n = (long)info->width * info->height, nd = 0;
            for (long i = 0; i < n; i++)
                if (memcmp(a + 4 * i, b + 4 * i, 4)) { /* alpha too, as fragsim check */
                    if (nd < 10)
                        printf("call %llu %s: pixel (%ld, %ld) model %d %d %d %d osmesa %d %d %d %d\n",
                               (unsigned long long)no, frame_end ? "frame end" : fs_replay_call_name(r), i % info->width, i / info->width,
                               a[4 * i], a[4 * i + 1], a[4 * i + 2], a[4 * i + 3], b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]);
                    nd++;
                }
            if (nd) {
                long nz = 0;
                for (long i = 0; i < n; i++) nz += a[4 * i] || a[4 * i + 1] || a[4 * i + 2];
                printf("model: %ld non-black pixels, %llu fragments generated, %llu written, %llu killed depth, draw 0x%x, error 0x%x\n", nz,
                       (unsigned long long)c->stats.fragments_generated, (unsigned long long)c->stats.fragments_written, (unsigned long long)c->stats.killed_depth, (unsigned)c->draw_buffer, (unsigned)c->error);
                printf("clears %llu depth[0] %u\n", (unsigned long long)c->stats.clears, (unsigned)c->fb.depth[0]);
                printf("%ld pixels differ after call %llu\n", nd, (unsigned long long)no);
                return 0;
            }
        }
        if (no == target) {
            int nm = fsglRenderMode(c, GL_RENDER), no_ = glRenderMode(GL_RENDER);
            printf("feedback values: model %d, osmesa %d\n", nm, no_);
            int i = 0, j = 0, prim = 0, ndiff = 0;
            while (i < nm && j < no_) {
                if (fb_m[i] != fb_o[j] || (fb_m[i] != GL_POLYGON_TOKEN && fb_m[i] != GL_POINT_TOKEN)) {
                    printf("token %g / %g at prim %d\n", fb_m[i], fb_o[j], prim);
                    break;
                }
                int pt = fb_m[i] == GL_POINT_TOKEN;
                int n = pt ? 1 : (int)fb_m[i + 1], n2 = pt ? 1 : (int)fb_o[j + 1];
                const float *vm = fb_m + i + 2 - pt, *vo = fb_o + j + 2 - pt;
                int hit = n == n2 && inside(vo, n, px, py);
                for (int k = 0; k < n && k < n2; k++) {
                    int d = memcmp(vm + 7 * k, vo + 7 * k, (getenv("PROBE_NOALPHA") ? 6 : 7) * sizeof(float)) != 0;
                    ndiff += d;
                    if (hit || (d && ndiff < 20)) {
                        printf("prim %d v%d %s\n  model ", prim, k, hit ? "COVERS" : "");
                        for (int q = 0; q < 7; q++) printf(" %a", vm[7 * k + q]);
                        printf("\n  osmesa");
                        for (int q = 0; q < 7; q++) printf(" %a", vo[7 * k + q]);
                        printf("\n");
                    }
                }
                i += 2 - pt + 7 * n;
                j += 2 - pt + 7 * n2;
                prim++;
            }
            printf("%d primitives, %d vertices differ\n", prim, ndiff);
            break;
        }
    }
    if (first)
        printf("no render call leaves the colour buffers different\n");
    return 0;
}
