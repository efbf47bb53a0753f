/*
 * `fragsim mpgrid`: the memory example of Huettner 1999, 4.1.2 (flat
 * terrain, viewer at (0, 0, 1000) looking at (2500, 2500, 0), 1024x1024
 * screen, 45 degree field of view, a 5120x5120 8-bit grey texture as a 5x5
 * MP-Grid) computed from the camera by the residency manager, next to the
 * paper's numbers, plus the pointer-table size example of 4.1.4.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "../units/mpgrid.h"

/* The paper's numbers (4.1.2 and 4.1.4), for the side-by-side table only. */
#define PAPER_ADAPTED 6198605ull
#define PAPER_FULL 34952550ull
#define PAPER_CLIP 13981013ull
#define PAPER_TABLE 880000ull

static void usage(FILE *f)
{
    fprintf(f, "usage: fragsim mpgrid [--markdown] [--fov DEG] [--near Z] [--far Z] [--keep-side N]\n"
               "  Computes the MP-Grid / MIPmap / Clip-Map memory example of Huettner 1999, 4.1.2\n"
               "  from the camera and prints it next to the paper's numbers.\n"
               "  --fov DEG      vertical field of view (default 45)\n"
               "  --near, --far  clip planes (default 1 and 10000 m; the terrain lies within)\n"
               "  --keep-side N  keep levels of at most N x N texels in every pyramid (default 0)\n"
               "  --markdown     print Markdown tables (docs/mp_grid.md)\n");
}

static int parse_double(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

/* Splits of `rem` bytes into at most `left` whole pyramids whose sizes are
 * size[k..]: counts them and the fewest and most pyramids a split uses. */
static void count_splits(const uint64_t *size, int k, int nsize, uint64_t rem, int left, int used, long *count,
                         int *fewest, int *most)
{
    if (rem == 0) {
        (*count)++;
        *fewest = used < *fewest ? used : *fewest;
        *most = used > *most ? used : *most;
        return;
    }
    if (k == nsize || left == 0)
        return;
    for (int c = 0; c <= left && (uint64_t)c * size[k] <= rem; c++)
        count_splits(size, k + 1, nsize, rem - (uint64_t)c * size[k], left - c, used + c, count, fewest, most);
}

static void row(bool md, const char *what, uint64_t paper, uint64_t ours)
{
    double dev = paper ? 100.0 * ((double)ours - (double)paper) / (double)paper : 0.0;
    if (md)
        printf("| %s | %llu | %llu | %+.3f %% |\n", what, (unsigned long long)paper, (unsigned long long)ours, dev);
    else
        printf("%-44s %14llu %14llu %+9.3f %%\n", what, (unsigned long long)paper, (unsigned long long)ours, dev);
}

int fs_cli_mpgrid(int argc, char **argv)
{
    bool md = false;
    double fov = 45.0, znear = 1.0, zfar = 10000.0, keep = 0.0;
    for (int a = 0; a < argc; a++) {
        double *dst = NULL;
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(argv[a], "--markdown")) {
            md = true;
            continue;
        } else if (!strcmp(argv[a], "--fov")) {
            dst = &fov;
        } else if (!strcmp(argv[a], "--near")) {
            dst = &znear;
        } else if (!strcmp(argv[a], "--far")) {
            dst = &zfar;
        } else if (!strcmp(argv[a], "--keep-side")) {
            dst = &keep;
        } else {
            fprintf(stderr, "fragsim mpgrid: unknown option '%s'\n", argv[a]);
            usage(stderr);
            return 2;
        }
        if (a + 1 >= argc || parse_double(argv[a + 1], dst) < 0) {
            fprintf(stderr, "fragsim mpgrid: %s needs a finite number\n", argv[a]);
            return 2;
        }
        a++;
    }
    if (!(keep >= 0 && keep <= FS_MPGRID_MAX_TILE)) {
        fprintf(stderr, "fragsim mpgrid: --keep-side must be in [0, %d]\n", FS_MPGRID_MAX_TILE);
        return 2;
    }
    /* 4.1.2: terrain 5000 m x 5000 m, texture 5120 x 5120, tiles up to 1024. */
    const double terrain = 5000.0;
    const int64_t img = 5120;
    fs_mpgrid_layout L;
    if (fs_mpgrid_choose_layout(img, img, 512, 1024, &L) < 0) {
        fprintf(stderr, "fragsim mpgrid: no layout\n");
        return 1;
    }
    fs_mpgrid_camera cam;
    const double eye[3] = {0, 0, 1000}, center[3] = {2500, 2500, 0}, up[3] = {0, 0, 1};
    if (fs_mpgrid_camera_lookat(&cam, eye, center, up, fov, znear, zfar, 1024, 1024) < 0) {
        fprintf(stderr, "fragsim mpgrid: bad camera (fov in (0, 180), 0 < near < far)\n");
        return 1;
    }
    fs_mpgrid_box *boxes = calloc((size_t)L.n * L.m, sizeof *boxes);
    int *needed = calloc((size_t)L.n * L.m, sizeof *needed);
    double *extent = calloc((size_t)L.n * L.m, sizeof *extent);
    if (!boxes || !needed || !extent) {
        free(boxes);
        free(needed);
        free(extent);
        return 1;
    }
    /* The scaled texture covers the terrain; pyramid (i, j) textures the
     * square it maps to (flat terrain: a box of zero height). */
    double cw = terrain / L.n, ch = terrain / L.m;
    for (int j = 0; j < L.m; j++)
        for (int i = 0; i < L.n; i++) {
            fs_mpgrid_box *b = &boxes[j * L.n + i];
            b->lo[0] = i * cw;
            b->hi[0] = (i + 1) * cw;
            b->lo[1] = j * ch;
            b->hi[1] = (j + 1) * ch;
            extent[j * L.n + i] = fs_mpgrid_projected_extent(&cam, b->lo, b->hi);
        }
    uint64_t adapted = 0;
    int rc = fs_mpgrid_adapted_bytes(&L, &cam, boxes, 1, (int)keep, &adapted, needed);
    if (rc < 0) {
        fprintf(stderr, "fragsim mpgrid: adaptation failed\n");
        free(boxes);
        free(needed);
        free(extent);
        return 1;
    }
    uint64_t full_exact = (uint64_t)L.n * L.m * fs_mpgrid_pyramid_bytes(&L, 0, 1);
    /* The convention that gives the paper's 34,952,550: every pyramid
     * counted as ceil(4/3 * 1024^2) bytes (the geometric series' limit). */
    uint64_t tile = (uint64_t)L.tile_w * L.tile_h;
    uint64_t full_43 = (uint64_t)L.n * L.m * ((4 * tile + 2) / 3);
    int64_t cs = fs_clip_map_scaled_size(img, img);
    uint64_t clip = fs_clip_map_bytes(cs, 2048, 1);
    uint64_t table = fs_mpgrid_table_bytes(11, 100, 100, 4, 4);

    if (md) {
        printf("| quantity | paper | fragsim | difference |\n|---|---:|---:|---:|\n");
    } else {
        printf("MP-Grid memory example (Huettner 1999, 4.1.2): %lldx%lld texels as %dx%d pyramids of %dx%d,\n"
               "viewer (0,0,1000) -> (2500,2500,0), fovy %g, 1024x1024, near %g, far %g, 8-bit grey\n\n",
               (long long)img, (long long)img, L.n, L.m, L.tile_w, L.tile_h, fov, znear, zfar);
        printf("%-44s %14s %14s %10s\n", "quantity (bytes)", "paper", "fragsim", "diff");
    }
    row(md, "adapted MP-Grid", PAPER_ADAPTED, adapted);
    row(md, "full MIPmap, 25 x ceil(4/3 x 1024^2)", PAPER_FULL, full_43);
    row(md, "full MIPmap, exact level sums", PAPER_FULL, full_exact);
    char what[80];
    snprintf(what, sizeof what, "Clip-Map %lld^2, clip size 2048", (long long)cs);
    row(md, what, PAPER_CLIP, clip);
    row(md, "pointer table 11 x 100 x 100 x (4 + 4)", PAPER_TABLE, table);

    /* Which per-pyramid sizes can make up the paper's adapted number:
     * every split into at most n*m exact pyramid sizes. */
    uint64_t sizes[FS_MPGRID_MAX_LEVELS];
    for (int l = 0; l < L.levels; l++)
        sizes[l] = fs_mpgrid_pyramid_bytes(&L, l, 1);
    long splits = 0;
    int fewest = L.n * L.m + 1, most = 0;
    count_splits(sizes, 0, L.levels, PAPER_ADAPTED, L.n * L.m, 0, &splits, &fewest, &most);
    printf(md ? "\nSplits of the paper's %llu bytes into at most %d whole pyramids (sizes %dx%d down to 1x1): "
                "%ld, using %d to %d non-empty pyramids.\n"
              : "\nsplits of the paper's %llu bytes into <= %d whole pyramids (from %dx%d down): %ld, "
                "using %d to %d non-empty pyramids\n",
           (unsigned long long)PAPER_ADAPTED, L.n * L.m, L.tile_w, L.tile_h, splits, fewest, most);

    /* Fig. 4.5: the needed resolution per pyramid (row j = m-1 first). */
    printf(md ? "\nNeeded level-0 resolution per pyramid (projected extent in pixels), far row first:\n\n"
              : "\nneeded resolution per pyramid (projected extent px), far row first:\n");
    if (md) {
        printf("| j \\ i |");
        for (int i = 0; i < L.n; i++)
            printf(" %d |", i);
        printf("\n|---|");
        for (int i = 0; i < L.n; i++)
            printf("---:|");
        printf("\n");
    }
    for (int j = L.m - 1; j >= 0; j--) {
        printf(md ? "| %d |" : "  j=%d", j);
        for (int i = 0; i < L.n; i++) {
            int p = j * L.n + i;
            int res = needed[p] >= L.levels ? 0 : fs_mpgrid_level_w(&L, needed[p]);
            printf(md ? " %d (%.1f) |" : "  %5d (%6.1f)", res, extent[p]);
        }
        printf("\n");
    }
    free(boxes);
    free(needed);
    free(extent);
    return 0;
}
