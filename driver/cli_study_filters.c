/*
 * fragsim study-filters: the texture filter quality/cost study (issue 4,
 * item 5), after the dissertation's 4.3.6 (Figures 4.33-4.44).
 *
 * A ground plane at a grazing angle, 600x600, textured with a 1024^2
 * checkerboard and a 2048^2 procedural map; every filter renders every
 * visible pixel from the pixel's exact footprint (texture_reference.c's
 * scene); the ground truth is the stratified supersampled box average.
 * Output (DIR, default out/study-filters): one PNG per texture and filter,
 * a side-by-side composite, crops, MIPmap-level data for gnuplot, the
 * hybrid's pixel classes, results.csv and results.md.  --figures DIR also
 * writes the small figures the documentation shows.
 *
 * Rows render in parallel (--threads, rows interleaved); each pixel depends
 * only on its footprint, so the output does not depend on the thread count.
 */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include "cli.h"
#include "image.h"
#include "../units/texture_reference.h"

#include "../units/footprint.h"

#define PI 3.14159265358979323846
#define MAX_FILTERS 24

/* ---- procedural textures (deterministic) --------------------------------- */

static uint32_t hash2(uint32_t x, uint32_t y) { return fs_hash32(x * 0x8da6b343u ^ y * 0xd8163841u); }

static void put(uint8_t *img, int w, int x, int y, int r, int g, int b)
{
    uint8_t *p = img + ((size_t)y * w + x) * 4;
    p[0] = (uint8_t)r, p[1] = (uint8_t)g, p[2] = (uint8_t)b, p[3] = 255;
}

static uint8_t *make_checker(int n, int check)
{
    uint8_t *img = malloc((size_t)n * n * 4);
    if (!img)
        return NULL;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int c = ((x / check) + (y / check)) & 1 ? 235 : 25;
            put(img, n, x, y, c, c, c);
        }
    return img;
}

/* Periodic value noise on a lattice of `cell` texels (period n). */
static double vnoise(int x, int y, int cell, int n, uint32_t seed)
{
    int cx = x / cell, cy = y / cell, m = n / cell;
    double fx = (double)(x % cell) / cell, fy = (double)(y % cell) / cell;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    double v[4];
    for (int k = 0; k < 4; k++)
        v[k] = (hash2((uint32_t)((cx + (k & 1)) % m) + seed, (uint32_t)((cy + (k >> 1)) % m)) >> 8) /
               16777216.0;
    return (v[0] * (1 - fx) + v[1] * fx) * (1 - fy) + (v[2] * (1 - fx) + v[3] * fx) * fy;
}

/* A map: fields and parks (noise), a street grid with blocks of buildings,
 * main roads with centre lines, two meandering rivers, and text-like
 * labels of 1-texel strokes; every feature has period n so REPEAT tiles
 * seamlessly. */
static uint8_t *make_map(int n)
{
    uint8_t *img = malloc((size_t)n * n * 4);
    if (!img)
        return NULL;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            double a = 0.6 * vnoise(x, y, 256, n, 1) + 0.3 * vnoise(x, y, 64, n, 2) + 0.1 * vnoise(x, y, 8, n, 3);
            int city = vnoise(x, y, 512, n, 4) > 0.45;
            int r = (int)(150 + 60 * a), g = (int)(175 + 50 * a), b = (int)(120 + 30 * a);
            if (city) {
                int bx = x % 64, by = y % 64;
                uint32_t hb = hash2((uint32_t)(x / 64), (uint32_t)(y / 64));
                if (bx >= 3 && by >= 3) {
                    /* a block: plots of buildings with their own tone */
                    int px = (bx - 3) / 15, py = (by - 3) / 20;
                    uint32_t hp = hash2(hb + (uint32_t)px, (uint32_t)py * 7 + 1);
                    int inset = (bx - 3) % 15 >= 2 && (by - 3) % 20 >= 2;
                    int tone = 170 + (int)(hp % 60);
                    if (inset)
                        r = tone + 20, g = tone - 10, b = tone - 30;
                    else
                        r = g = b = 215;
                } else
                    r = g = b = 245;    /* street */
            }
            /* main roads every 256 texels */
            int rx = x % 256, ry = y % 256;
            if (rx < 7 || ry < 7) {
                r = 250, g = 200, b = 90;
                if ((rx == 3 && (y / 6) % 2) || (ry == 3 && (x / 6) % 2))
                    r = g = b = 255;
                if (rx == 0 || rx == 6 || ry == 0 || ry == 6)
                    r = 120, g = 100, b = 60;
            }
            put(img, n, x, y, r, g, b);
        }
    /* rivers: periodic meanders, painted over everything but labels */
    for (int x = 0; x < n; x++) {
        double t = 2 * PI * x / n;
        double c = 0.35 * n + 0.06 * n * sin(3 * t) + 0.02 * n * sin(7 * t + 1);
        for (int d = -12; d <= 12; d++) {
            int y = ((int)floor(c) + d + n) % n;
            int bank = abs(d) >= 11;
            put(img, n, x, y, bank ? 60 : 70, bank ? 90 : 120, bank ? 140 : 210);
        }
    }
    for (int y = 0; y < n; y++) {
        double t = 2 * PI * y / n;
        double c = 0.7 * n + 0.05 * n * sin(2 * t + 0.5);
        for (int d = -7; d <= 7; d++) {
            int x = ((int)floor(c) + d + n) % n;
            put(img, n, x, y, 70, 120, 210);
        }
    }
    /* labels: rows of 5x7 glyphs of random strokes */
    for (int l = 0; l < 400; l++) {
        uint32_t h = hash2((uint32_t)l, 99);
        int x0 = (int)(h % (uint32_t)n), y0 = (int)((h >> 12) % (uint32_t)n);
        int glyphs = 4 + (int)(h >> 28) % 8;
        for (int g = 0; g < glyphs; g++) {
            uint32_t bits = hash2((uint32_t)l, (uint32_t)g + 1000);
            for (int gy = 0; gy < 7; gy++)
                for (int gx = 0; gx < 5; gx++) {
                    int on = (bits >> ((gy * 5 + gx) % 32)) & 1;
                    if (gy == 0 || gy == 6)
                        on &= gx > 0 && gx < 4;
                    if (on)
                        put(img, n, (x0 + g * 6 + gx) % n, (y0 + gy) % n, 20, 20, 30);
                }
        }
    }
    return img;
}

/* ---- filters of the study ------------------------------------------------- */

/* Trilinear MIPmapping with GL's isotropic level (eq. 4.10-4.11). */
static void filter_trilinear(const fs_mip_view *m, const fs_footprint *fp, const void *params, fs_filter_out *out)
{
    (void)params;
    memset(out, 0, sizeof *out);
    double l = fs_footprint_lambda_iso(fp);
    fs_footprint c = *fp;
    if (!isfinite(c.u))
        c.u = 0;
    if (!isfinite(c.v))
        c.v = 0;
    out->texels = fs_mip_trilinear(m, l, c.u, c.v, out->rgba);
    double top = m->levels - 1;
    out->level = (float)(!(l > 0) ? 0 : l > top ? top : l);
}

typedef struct study_filter {
    char name[32], label[64];
    fs_filter_fn *fn;
    const void *params;
    int ffp_m, ffp_hybrid;   /* fast footprint rows: M and hybrid flag, else 0 */
    int ffp_midpoint;        /* fast footprint rows: mid-point snapping */
} study_filter;

/* ---- rendering ------------------------------------------------------------ */

typedef struct render_job {
    const fs_mip_view *m;
    const fs_footprint *fps;
    const uint8_t *mask;
    int w, h, threads, index;
    const study_filter *f;
    float *rgba, *level;
    int *cls, *texels;
} render_job;

static void *render_rows(void *arg)
{
    render_job *j = arg;
    for (int y = j->index; y < j->h; y += j->threads)
        for (int x = 0; x < j->w; x++) {
            size_t i = (size_t)y * j->w + x;
            if (!j->mask[i])
                continue;
            fs_filter_out o;
            j->f->fn(j->m, &j->fps[i], j->f->params, &o);
            memcpy(&j->rgba[4 * i], o.rgba, sizeof o.rgba);
            j->level[i] = o.level;
            j->cls[i] = o.cls;
            j->texels[i] = o.texels;
        }
    return NULL;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

typedef struct result {
    float *rgba, *level;
    int *cls, *texels;
    double seconds, psnr, psnr_mag, psnr_min, texels_mean;
    int texels_max;
} result;

static int render(const fs_mip_view *m, const fs_footprint *fps, const uint8_t *mask, int w, int h, int threads,
                  const study_filter *f, result *r)
{
    size_t n = (size_t)w * h;
    r->rgba = calloc(n * 4, sizeof(float));
    r->level = calloc(n, sizeof(float));
    r->cls = calloc(n, sizeof(int));
    r->texels = calloc(n, sizeof(int));
    if (!r->rgba || !r->level || !r->cls || !r->texels)
        return -1;
    render_job jobs[16];
    pthread_t tid[16];
    int started[16] = {0};
    double t0 = now_s();
    for (int t = 0; t < threads; t++) {
        jobs[t] = (render_job){m, fps, mask, w, h, threads, t, f, r->rgba, r->level, r->cls, r->texels};
        if (t > 0)
            started[t] = pthread_create(&tid[t], NULL, render_rows, &jobs[t]) == 0;
    }
    /* Rows of a thread that could not start are rendered here. */
    for (int t = 0; t < threads; t++)
        if (!started[t])
            render_rows(&jobs[t]);
    for (int t = 1; t < threads; t++)
        if (started[t])
            pthread_join(tid[t], NULL);
    r->seconds = now_s() - t0;
    long long sum = 0, cnt = 0;
    r->texels_max = 0;
    for (size_t i = 0; i < n; i++)
        if (mask[i]) {
            sum += r->texels[i];
            cnt++;
            if (r->texels[i] > r->texels_max)
                r->texels_max = r->texels[i];
        }
    r->texels_mean = cnt ? (double)sum / cnt : 0;
    return 0;
}

static void result_free(result *r)
{
    free(r->rgba);
    free(r->level);
    free(r->cls);
    free(r->texels);
    memset(r, 0, sizeof *r);
}

/* ---- images ---------------------------------------------------------------- */

static const uint8_t sky[3] = {168, 196, 232};

static void to_rgba8(const float *rgba, const uint8_t *mask, size_t n, uint8_t *out)
{
    for (size_t i = 0; i < n; i++)
        for (int ch = 0; ch < 4; ch++) {
            double v = mask[i] ? rgba[4 * i + ch] : ch < 3 ? sky[ch] / 255.0 : 1.0;
            v = v < 0 ? 0 : v > 1 ? 1 : v;
            out[4 * i + ch] = (uint8_t)lrint(v * 255);
        }
}

/* Copies the rectangle (sx, sy, cw, ch) of a bottom-up image into a canvas at
 * (dx, dy), optionally halving it by 2x2 box averaging. */
static void blit(const uint8_t *src, int sw, int sx, int sy, int cw, int chh, uint8_t *dst, int dw, int dx, int dy,
                 int half)
{
    int f = half ? 2 : 1;
    for (int y = 0; y < chh / f; y++)
        for (int x = 0; x < cw / f; x++)
            for (int c = 0; c < 4; c++) {
                int s = 0;
                for (int k = 0; k < f * f; k++)
                    s += src[((size_t)(sy + y * f + k / f) * sw + sx + x * f + k % f) * 4 + c];
                dst[((size_t)(dy + y) * dw + dx + x) * 4 + c] = (uint8_t)((s + f * f / 2) / (f * f));
            }
}

static int write_png(const char *path, const uint8_t *img, int w, int h)
{
    char err[512];
    if (fs_image_write_png(path, img, w, h, err, sizeof err) != 0) {
        fprintf(stderr, "fragsim study-filters: %s\n", err);
        return -1;
    }
    return 0;
}

/* A strip of the chosen filters' images side by side (gap of 4 white
 * pixels): full size, or a crop, halved when `half`. */
static int write_strip(const char *path, uint8_t *const *imgs, int count, int w, int sx, int sy, int cw, int chh,
                       int half)
{
    int f = half ? 2 : 1, gap = 4;
    int ow = cw / f, oh = chh / f, tw = count * ow + (count - 1) * gap;
    uint8_t *canvas = malloc((size_t)tw * oh * 4);
    if (!canvas)
        return -1;
    memset(canvas, 255, (size_t)tw * oh * 4);
    for (int i = 0; i < count; i++)
        blit(imgs[i], w, sx, sy, cw, chh, canvas, tw, i * (ow + gap), 0, half);
    int rc = write_png(path, canvas, tw, oh);
    free(canvas);
    return rc;
}

/* ---- the study ------------------------------------------------------------- */

/* A PSNR for the table: "-" when no pixel was compared. */
static const char *db(char buf[24], double v)
{
    if (isnan(v))
        return "-";
    snprintf(buf, 24, "%.2f", v);
    return buf;
}

typedef struct texture_case {
    const char *name, *title;
    int size;
    double texels_per_unit;
} texture_case;

static int mkdir_p(const char *dir)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char *p = tmp + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            if (mkdir(tmp, 0777) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    return mkdir(tmp, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: fragsim study-filters [--out DIR] [--figures DIR] [--threads N] [--size N]\n"
               "                             [--truth-max N] [--rotate DEG] [--iso R]\n"
               "  --out DIR       results (PNGs, results.csv, results.md, level data); default out/study-filters\n"
               "  --figures DIR   also write the small figures for docs/texture_filtering.md\n"
               "  --threads N     render threads (1..16, default 2); output does not depend on it\n"
               "  --size N        image N x N (default 600, as in the dissertation)\n"
               "  --truth-max N   ground truth: at most N x N samples per pixel (16..256, default 64)\n"
               "  --rotate DEG    texture rotation on the plane (default 20)\n"
               "  --iso R         hybrid fast footprint: MIPmap footprints with axis ratio <= R (>= 1,\n"
               "                  default FS_FP_ISO_LIMIT = 2)\n");
}

static int parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*s == 0 || *end || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

int fs_cli_study_filters(int argc, char **argv)
{
    const char *out = "out/study-filters", *figs = NULL;
    int threads = 2, size = 600, truth_max = 64;
    double rotate = 20, iso = FS_FP_ISO_LIMIT;
    /* Every option takes a value: step over both. */
    for (int i = 0; i < argc; i += 2) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        }
        static const char *const known[] = {"--out", "--figures", "--threads", "--size", "--truth-max", "--rotate", "--iso"};
        int is_known = 0;
        for (size_t k = 0; k < sizeof known / sizeof known[0]; k++)
            is_known |= !strcmp(a, known[k]);
        if (!is_known || !v) {
            fprintf(stderr, "fragsim study-filters: %s '%s'\n", is_known ? "missing value after" : "unknown option", a);
            usage(stderr);
            return 2;
        }
        int bad = 0;
        if (!strcmp(a, "--out"))
            out = v;
        else if (!strcmp(a, "--figures"))
            figs = v;
        else if (!strcmp(a, "--threads"))
            bad = parse_int(v, 1, 16, &threads);
        else if (!strcmp(a, "--size"))
            bad = parse_int(v, 16, 4096, &size);
        else if (!strcmp(a, "--truth-max"))
            bad = parse_int(v, 16, 256, &truth_max);
        else if (!strcmp(a, "--rotate")) {
            char *end;
            rotate = strtod(v, &end);
            bad = *end || !isfinite(rotate);
        } else if (!strcmp(a, "--iso")) {
            char *end;
            iso = strtod(v, &end);
            bad = *end || !(iso >= 1.0) || !isfinite(iso);
        }
        if (bad) {
            fprintf(stderr, "fragsim study-filters: bad value '%s' for %s\n", v, a);
            usage(stderr);
            return 2;
        }
    }
    if (strlen(out) > 1000 || (figs && strlen(figs) > 1000)) {
        fprintf(stderr, "fragsim study-filters: directory name too long\n");
        return 2;
    }
    const char *bad_dir = mkdir_p(out) != 0 ? out : figs && mkdir_p(figs) != 0 ? figs : NULL;
    if (bad_dir) {
        fprintf(stderr, "fragsim study-filters: cannot create %s: %s\n", bad_dir, strerror(errno));
        return 1;
    }

    /* The filters.  Parameters: see docs/texture_filtering.md. */
    static const fs_fa_params fa = {16};
    static const fs_aniso_params an[4] = {{2}, {4}, {8}, {16}};
    static const fs_ewa_params ewa = {0.4, 2.0, 0.3, 1.0, 16.0, 4096};
    fs_truth_params truth = {16, truth_max, 0.5, 1};
    study_filter filters[MAX_FILTERS];
    int nf = 0;
    filters[nf++] = (study_filter){"trilinear", "trilinear MIPmapping", filter_trilinear, NULL, 0, 0};
    filters[nf++] = (study_filter){"assembly", "footprint assembly (N <= 16)", fs_filter_footprint_assembly, &fa, 0, 0};
    for (int k = 0; k < 4; k++) {
        study_filter f = {"", "", fs_filter_aniso, &an[k], 0, 0};
        snprintf(f.name, sizeof f.name, "aniso%d", (int)an[k].max_aniso);
        snprintf(f.label, sizeof f.label, "N-probe, max anisotropy %d", (int)an[k].max_aniso);
        filters[nf++] = f;
    }
    filters[nf++] = (study_filter){"ewa", "EWA, Gaussian", fs_filter_ewa, &ewa, 0, 0};
    /* Fast footprint filtering (4.3.6) with integer-position snapping ("I"),
     * hybrid and pure, for M = 8, 16, 32; and with mid-point snapping
     * ("MS"), hybrid and pure, for M = 16 and 32: the comparison behind
     * the choice of snapping. */
    static const struct { int M; bool mid, hyb; } ffp_rows[] = {
        {8, false, true}, {16, false, true}, {32, false, true}, {8, false, false}, {16, false, false},
        {32, false, false}, {16, true, true}, {32, true, true}, {16, true, false}, {32, true, false},
    };
    enum { NFFP = sizeof ffp_rows / sizeof ffp_rows[0] };
    fs_footprint_filter *ffp_objs[NFFP] = {0};
    int nffp = 0;
    for (int k = 0; k < NFFP; k++) {
        fs_footprint_filter *ff = fs_footprint_filter_create(ffp_rows[k].M, ffp_rows[k].mid, ffp_rows[k].hyb);
        if (!ff) {
            fprintf(stderr, "fragsim study-filters: cannot create the M = %d footprint filter\n", ffp_rows[k].M);
            for (int j = 0; j < nffp; j++)
                fs_footprint_filter_destroy(ffp_objs[j]);
            return 1;
        }
        fs_footprint_filter_set_iso_limit(ff, iso);
        ffp_objs[nffp++] = ff;
        study_filter f = {"", "", fs_filter_footprint, ff, ffp_rows[k].M, ffp_rows[k].hyb, ffp_rows[k].mid};
        snprintf(f.name, sizeof f.name, "ffp%d%s%s", ffp_rows[k].M, ffp_rows[k].hyb ? "h" : "",
                 ffp_rows[k].mid ? "ms" : "");
        snprintf(f.label, sizeof f.label, "fast footprint M = %d%s%s", ffp_rows[k].M,
                 ffp_rows[k].hyb ? ", hybrid" : "", ffp_rows[k].mid ? ", mid-point snapping" : "");
        filters[nf++] = f;
    }
    filters[nf++] = (study_filter){"truth", "ground truth", fs_filter_truth, &truth, 0, 0};
    const int truth_index = nf - 1;

    static const texture_case cases[2] = {
        {"checker", "1024x1024 checkerboard", 1024, 200.0},
        {"map", "2048x2048 map", 2048, 320.0},
    };
    char path[1200];
    snprintf(path, sizeof path, "%s/results.csv", out);
    FILE *csv = fopen(path, "w");
    snprintf(path, sizeof path, "%s/results.md", out);
    FILE *md = fopen(path, "w");
    if (!csv || !md) {
        fprintf(stderr, "fragsim study-filters: cannot write in %s\n", out);
        return 1;
    }
    fprintf(csv, "texture,filter,psnr_db,texels_mean,texels_max,seconds,ns_per_pixel,pixels,psnr_magnified_db,"
                 "psnr_minified_db,label\n");
    int rc = 0;
    for (int c = 0; c < 2 && rc == 0; c++) {
        const texture_case *tc = &cases[c];
        uint8_t *img = c == 0 ? make_checker(tc->size, 64) : make_map(tc->size);
        fs_mip_owned tex;
        if (!img || fs_mip_build_box(&tex, img, tc->size, tc->size, GL_REPEAT) != 0) {
            free(img);
            rc = 1;
            break;
        }
        free(img);
        /* Camera: 1 unit above the plane, pitched 20 degrees down, 60 degree
         * field of view; the plane is shown up to 40 units ahead, so its far
         * edge is 1.4 degrees below the horizon (grazing). */
        fs_ground_scene sc = {size, size, 1.0, 20.0, 60.0, tc->texels_per_unit, rotate, 0.0, 0.0, 40.0};
        char err[256];
        if (fs_ground_scene_check(&sc, err, sizeof err) != 0) {
            fprintf(stderr, "fragsim study-filters: %s\n", err);
            rc = 1;
            break;
        }
        size_t n = (size_t)size * size;
        fs_footprint *fps = calloc(n, sizeof *fps);
        uint8_t *mask = calloc(n, 1), *mask_mag = calloc(n, 1), *mask_min = calloc(n, 1);
        result res[MAX_FILTERS];
        memset(res, 0, sizeof res);
        uint8_t *imgs[MAX_FILTERS] = {0};
        long long visible = 0, magnified = 0;
        if (!fps || !mask || !mask_mag || !mask_min) {
            fprintf(stderr, "fragsim study-filters: out of memory\n");
            free(fps);
            free(mask);
            free(mask_mag);
            free(mask_min);
            fs_mip_free(&tex);
            rc = 1;
            break;
        }
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++) {
                size_t i = (size_t)y * size + x;
                mask[i] = fs_ground_footprint(&sc, x, y, &fps[i]);
                visible += mask[i];
                /* Split for the diagnosis: magnified (GL's lambda <= 0, the
                 * texture is interpolated) and minified pixels. */
                mask_mag[i] = mask[i] && fs_footprint_lambda_iso(&fps[i]) <= 0;
                mask_min[i] = mask[i] && !mask_mag[i];
                magnified += mask_mag[i];
            }
        /* Ground truth first: everything is compared with it. */
        int order[MAX_FILTERS], no = 0;
        order[no++] = truth_index;
        for (int f = 0; f < nf; f++)
            if (f != truth_index)
                order[no++] = f;
        for (int k = 0; k < no && rc == 0; k++) {
            int f = order[k];
            if (render(&tex.view, fps, mask, size, size, threads, &filters[f], &res[f]) != 0) {
                fprintf(stderr, "fragsim study-filters: out of memory\n");
                rc = 1;
                break;
            }
            res[f].psnr = fs_psnr_rgb(res[f].rgba, res[truth_index].rgba, mask, n);
            res[f].psnr_mag = fs_psnr_rgb(res[f].rgba, res[truth_index].rgba, mask_mag, n);
            res[f].psnr_min = fs_psnr_rgb(res[f].rgba, res[truth_index].rgba, mask_min, n);
            imgs[f] = malloc(n * 4);
            if (!imgs[f]) {
                rc = 1;
                break;
            }
            to_rgba8(res[f].rgba, mask, n, imgs[f]);
            snprintf(path, sizeof path, "%s/%s_%s.png", out, tc->name, filters[f].name);
            if (write_png(path, imgs[f], size, size) != 0)
                rc = 1;
            fprintf(stderr, "  %-8s %-10s %7.2f dB  %7.1f texels  %6.2f s\n", tc->name, filters[f].name,
                    res[f].psnr, res[f].texels_mean, res[f].seconds);
        }
        if (rc == 0) {
            /* Table. */
            fprintf(md, "\n### %s (%lld visible pixels of %dx%d: %lld magnified, %lld minified)\n\n", tc->title,
                    visible, size, size, magnified, visible - magnified);
            fprintf(md, "| filter | PSNR vs ground truth (dB) | PSNR, magnified pixels | PSNR, minified pixels | texels per pixel (mean) | texels (max) | time (s, %d thread%s) | ns per pixel |\n",
                    threads, threads > 1 ? "s" : "");
            fprintf(md, "|---|---|---|---|---|---|---|---|\n");
            for (int f = 0; f < nf; f++) {
                const result *r = &res[f];
                double ns = r->seconds * 1e9 * threads / (double)visible;
                /* The label goes last: it may contain commas. */
                bool t = f == truth_index;
                fprintf(csv, "%s,%s,%.3f,%.2f,%d,%.3f,%.1f,%lld,%.3f,%.3f,\"%s\"\n", tc->name, filters[f].name,
                        t ? INFINITY : r->psnr, r->texels_mean, r->texels_max, r->seconds, ns, visible,
                        t ? INFINITY : r->psnr_mag, t ? INFINITY : r->psnr_min, filters[f].label);
                if (t)
                    fprintf(md, "| %s (%s) | reference | | | %.0f (reads) | %d | %.2f | %.0f |\n", filters[f].label,
                            filters[f].name, r->texels_mean, r->texels_max, r->seconds, ns);
                else {
                    char b0[24], b1[24], b2[24];
                    fprintf(md, "| %s (%s) | %s | %s | %s | %.1f | %d | %.2f | %.0f |\n", filters[f].label,
                            filters[f].name, db(b0, r->psnr), db(b1, r->psnr_mag), db(b2, r->psnr_min),
                            r->texels_mean, r->texels_max, r->seconds, ns);
                }
            }
            /* The fast footprint filter's pixel classes, as it reports them
             * (paper: Figure 4.35, checkerboard, M = 16, hybrid); the pure
             * filter's rows show where it still falls back to MIPmapping. */
            int any = 0;
            for (int f = 0; f < nf; f++) {
                if (!filters[f].ffp_m)
                    continue;
                long long cnt[4] = {0, 0, 0, 0};
                for (size_t i = 0; i < n; i++)
                    if (mask[i] && res[f].cls[i] >= 0 && res[f].cls[i] < 4)
                        cnt[res[f].cls[i]]++;
                if (!any++) {
                    fprintf(md, "\nFast footprint filtering, pixel classes as the filter reports them (%s):\n\n",
                            tc->title);
                    fprintf(md, "| | pixels filtered | MIPmapped (bilinear level 0 + trilinear) | footprint-filtered | of these with T between M and 2M |\n");
                    fprintf(md, "|---|---|---|---|---|\n");
                    if (c == 0)
                        fprintf(md, "| dissertation, Fig. 4.35 (M = 16, hybrid) | 275,334 | 246,678 | 28,656 | 8,836 |\n");
                }
                fprintf(md, "| fragsim, M = %d, %s | %lld | %lld (%lld + %lld) | %lld | %lld |\n", filters[f].ffp_m,
                        filters[f].ffp_hybrid ? (filters[f].ffp_midpoint ? "hybrid, mid-point" : "hybrid")
                                              : (filters[f].ffp_midpoint ? "pure, mid-point" : "pure"),
                        visible,
                        cnt[FS_FP_CLASS_BILINEAR0] + cnt[FS_FP_CLASS_TRILINEAR], cnt[FS_FP_CLASS_BILINEAR0],
                        cnt[FS_FP_CLASS_TRILINEAR], cnt[FS_FP_CLASS_FOOTPRINT] + cnt[FS_FP_CLASS_FOOTPRINT_2M],
                        cnt[FS_FP_CLASS_FOOTPRINT_2M]);
            }
            /* MIPmap levels along the scan order (top row first, as the
             * dissertation's ray tracer), every 4th visible pixel. */
            snprintf(path, sizeof path, "%s/%s_levels.dat", out, tc->name);
            FILE *lv = fopen(path, "w");
            if (lv) {
                fprintf(lv, "# pixel_index");
                for (int f = 0; f < nf; f++)
                    if (f != truth_index)
                        fprintf(lv, " %s", filters[f].name);
                fprintf(lv, "\n");
                long long idx = 0;
                for (int y = size - 1; y >= 0; y--)
                    for (int x = 0; x < size; x++) {
                        size_t i = (size_t)y * size + x;
                        if (!mask[i])
                            continue;
                        if (idx++ % 4)
                            continue;
                        fprintf(lv, "%lld", idx - 1);
                        for (int f = 0; f < nf; f++)
                            if (f != truth_index)
                                fprintf(lv, " %.3f", res[f].level[i]);
                        fprintf(lv, "\n");
                    }
                fclose(lv);
            }
            /* Composite of the main filters and crops of the far field. */
            const char *pick[] = {"trilinear", "assembly", "aniso16", "ewa", "ffp16h", "ffp32h", "truth"};
            uint8_t *sel[8];
            int ns = 0;
            char names[256] = "";
            for (int p = 0; p < 7; p++)
                for (int f = 0; f < nf; f++)
                    if (!strcmp(filters[f].name, pick[p])) {
                        sel[ns++] = imgs[f];
                        strncat(names, pick[p], sizeof names - strlen(names) - 2);
                        strcat(names, " ");
                    }
            snprintf(path, sizeof path, "%s/%s_composite.png", out, tc->name);
            if (write_strip(path, sel, ns, size, 0, 0, size, size, 0) != 0)
                rc = 1;
            /* The far field just below the plane's far edge (which is at
             * ~79% of the height). */
            int cw = size * 3 / 10, chh = size * 4 / 25, cx = size * 2 / 5, cy = size * 31 / 50;
            snprintf(path, sizeof path, "%s/%s_crop.png", out, tc->name);
            if (write_strip(path, sel, ns, size, cx, cy, cw, chh, 0) != 0)
                rc = 1;
            if (figs) {
                /* Small figures for the documentation (kept small: they are
                 * committed): a crop with four filters; for the checkerboard
                 * also the whole plane, halved, with three. */
                const char *fig_crop[] = {"trilinear", "aniso16", "ffp16h", "truth"};
                const char *fig_all[] = {"trilinear", "ffp16h", "truth"};
                uint8_t *use[6];
                int nu = 0;
                for (int p = 0; p < 4; p++)
                    for (int f = 0; f < nf; f++)
                        if (!strcmp(filters[f].name, fig_crop[p]))
                            use[nu++] = imgs[f];
                snprintf(path, sizeof path, "%s/%s_crop.png", figs, tc->name);
                if (write_strip(path, use, nu, size, cx, cy, cw, chh, 0) != 0)
                    rc = 1;
                if (c == 0) {
                    nu = 0;
                    for (int p = 0; p < 3; p++)
                        for (int f = 0; f < nf; f++)
                            if (!strcmp(filters[f].name, fig_all[p]))
                                use[nu++] = imgs[f];
                    snprintf(path, sizeof path, "%s/%s_overview.png", figs, tc->name);
                    if (write_strip(path, use, nu, size, 0, 0, size, size * 4 / 5, 1) != 0)
                        rc = 1;
                }
            }
            fprintf(md, "\n%s/%s_composite.png and %s_crop.png, left to right: %s\n", out, tc->name, tc->name, names);
        }
        for (int f = 0; f < nf; f++) {
            result_free(&res[f]);
            free(imgs[f]);
        }
        free(fps);
        free(mask);
        free(mask_mag);
        free(mask_min);
        fs_mip_free(&tex);
    }
    fclose(csv);
    fclose(md);
    for (int k = 0; k < nffp; k++)
        fs_footprint_filter_destroy(ffp_objs[k]);
    if (rc == 0)
        printf("wrote %s/results.csv, %s/results.md and the images in %s\n", out, out, out);
    return rc;
}
