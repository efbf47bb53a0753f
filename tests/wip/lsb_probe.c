/* Debug probe (outside the build): replays a trace on the model and on
 * OSMesa with the same decoded calls; the call numbered CALL runs in
 * GL_FEEDBACK mode (GL_3D_COLOR) on both, and the vertices of the
 * primitives covering pixel (X, Y) (GL window coordinates) are printed from
 * both, with every vertex whose feedback differs.
 *   lsb_probe TRACE CALL X Y */
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
    uint64_t target = strtoull(argv[2], NULL, 10);
    float px = (float)atof(argv[3]) + 0.5f, py = (float)atof(argv[4]) + 0.5f;
    char err[512];
    fs_replay_opts ro = {0};
    fs_replayer *r = fs_replay_open(argv[1], &ro, err, sizeof err);
    if (!r) { fprintf(stderr, "%s\n", err); return 1; }
    const fs_replay_info *info = fs_replay_info_get(r);
    fs_context *c = fs_context_create(NULL, info->width, info->height);
    fs_context_set_double_buffered(c, info->double_buffered);
    fs_osmesa *o = fs_osmesa_create(info->width, info->height, 24, 8, err, sizeof err);
    if (!c || !o) { fprintf(stderr, "create: %s\n", err); return 1; }
    fs_call call;
    for (;;) {
        fs_replay_event ev = fs_replay_next(r, &call);
        if (ev == FS_REPLAY_EOF || ev == FS_REPLAY_ERROR) break;
        if (ev != FS_REPLAY_CALL) continue;
        uint64_t no = fs_replay_call_no(r);
        if (no == target) {
            fsglFeedbackBuffer(c, FB, GL_3D_COLOR, fb_m);
            fsglRenderMode(c, GL_FEEDBACK);
            glFeedbackBuffer(FB, GL_3D_COLOR, fb_o);
            glRenderMode(GL_FEEDBACK);
        }
        fs_submit(c, &call);
        fs_osmesa_dispatch(o, &call);
        if (no == target) {
            int nm = fsglRenderMode(c, GL_RENDER), no_ = glRenderMode(GL_RENDER);
            printf("feedback values: model %d, osmesa %d\n", nm, no_);
            int i = 0, j = 0, prim = 0, ndiff = 0;
            while (i < nm && j < no_) {
                if (fb_m[i] != GL_POLYGON_TOKEN || fb_o[j] != GL_POLYGON_TOKEN) {
                    printf("token %g / %g at prim %d\n", fb_m[i], fb_o[j], prim);
                    break;
                }
                int n = (int)fb_m[i + 1], n2 = (int)fb_o[j + 1];
                const float *vm = fb_m + i + 2, *vo = fb_o + j + 2;
                int hit = n == n2 && inside(vo, n, px, py);
                for (int k = 0; k < n && k < n2; k++) {
                    int d = memcmp(vm + 7 * k, vo + 7 * k, 7 * sizeof(float)) != 0;
                    ndiff += d;
                    if (hit || (d && ndiff < 20)) {
                        printf("prim %d v%d %s\n  model ", prim, k, hit ? "COVERS" : "");
                        for (int q = 0; q < 7; q++) printf(" %a", vm[7 * k + q]);
                        printf("\n  osmesa");
                        for (int q = 0; q < 7; q++) printf(" %a", vo[7 * k + q]);
                        printf("\n");
                    }
                }
                i += 2 + 7 * n;
                j += 2 + 7 * n2;
                prim++;
            }
            printf("%d primitives, %d vertices differ\n", prim, ndiff);
            break;
        }
    }
    return 0;
}
