/*
 * Randomized texturing against OSMesa (llvmpipe): 200 scenes, each one
 * textured triangle or quad under a random perspective projection in a
 * window of random (also odd) size, with a random texture (size 1..128 per
 * side, non-square allowed, full MIPmap chain), base format (RGBA, RGB,
 * LUMINANCE, LUMINANCE_ALPHA, ALPHA, INTENSITY), client type
 * (GL_UNSIGNED_BYTE or GL_FLOAT, the types the unit takes), min filter (all
 * six), mag filter (both), wrap modes per axis (REPEAT, CLAMP,
 * CLAMP_TO_EDGE) and environment (MODULATE, DECAL, REPLACE, BLEND, ADD).
 *
 * Required (issue 4): every channel within 1 of OSMesa, and exact when the
 * filters are NEAREST/NEAREST_MIPMAP_NEAREST with mag NEAREST.  Scenes with
 * GL_CLAMP and min and mag image filters that differ are counted apart:
 * there llvmpipe samples a quad's NEAREST pixels through its LINEAR code
 * when the quad sharing its SIMD vector uses LINEAR (fs_tex_pair_decides),
 * which the model reproduces.  The totals
 * (pixels compared, differing, largest difference) are printed; the seed is
 * fixed so runs are reproducible (FS_TEX_RANDOM_SEED overrides it;
 * FS_TEX_RANDOM_ONLY=n draws scene n alone, FS_TEX_DUMP=1 writes images of
 * failing scenes).
 */
#include <math.h>
#include <stdio.h>
#include "check.h"
#include "osmesa_util.h"
#include "test_rng.h"
#include "../pipeline/context.h"

#define N_SCENES 200


typedef struct scene {
    int w, h;                    /* window */
    int tw, th;                  /* level-0 size */
    GLint internal;
    GLenum format, type;
    GLenum min, mag, wrap_s, wrap_t, env;
    float env_color[4], border[4];
    int quad;                    /* 0 triangle, 1 quad */
    float v[4][3], tc[4][2], col[4][4];
    float frustum_r, near_z, dist, rx, ry, rz;
    uint32_t tex_seed;
    int content;                 /* 0 random texels, 1 checkerboard */
    int fmt;                     /* index into formats[] */
} scene;

static const struct { GLint internal; GLenum format; const char *name; } formats[] = {
    {GL_RGBA, GL_RGBA, "rgba"}, {GL_RGB, GL_RGB, "rgb"}, {GL_LUMINANCE, GL_LUMINANCE, "lum"},
    {GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, "lum_alpha"}, {GL_ALPHA, GL_ALPHA, "alpha"},
    {GL_INTENSITY, GL_LUMINANCE, "intensity"},
};
static const GLenum min_filters[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                     GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE};
static const GLenum envs[] = {GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND, GL_ADD};

static void make_scene(rng *r, scene *s)
{
    memset(s, 0, sizeof *s);
    s->w = 24 + rndi(r, 73);
    s->h = 24 + rndi(r, 73);
    s->tw = 1 << rndi(r, 8);
    s->th = rndi(r, 3) ? s->tw : 1 << rndi(r, 8);
    int f = rndi(r, 6);
    s->fmt = f;
    s->internal = formats[f].internal;
    s->format = formats[f].format;
    s->type = rndi(r, 4) ? GL_UNSIGNED_BYTE : GL_FLOAT;
    s->min = min_filters[rndi(r, 6)];
    s->mag = rndi(r, 2) ? GL_LINEAR : GL_NEAREST;
    s->wrap_s = wraps[rndi(r, 3)];
    s->wrap_t = wraps[rndi(r, 3)];
    s->env = envs[rndi(r, 5)];
    for (int k = 0; k < 4; k++) {
        s->env_color[k] = rndf(r, 0, 1);
        s->border[k] = rndf(r, 0, 1);
    }
    s->quad = rndi(r, 2);
    for (int i = 0; i < 4; i++) {
        s->v[i][0] = rndf(r, -1.6f, 1.6f);
        s->v[i][1] = rndf(r, -1.6f, 1.6f);
        s->v[i][2] = rndf(r, -0.4f, 0.4f);
        s->tc[i][0] = rndf(r, -1.5f, 2.5f);
        s->tc[i][1] = rndf(r, -1.5f, 2.5f);
        for (int k = 0; k < 4; k++)
            s->col[i][k] = rndf(r, 0, 1);
    }
    if (s->quad) {
        /* A convex quad: the four points sorted by angle about their mean. */
        float cx = 0, cy = 0;
        for (int i = 0; i < 4; i++) { cx += s->v[i][0] / 4; cy += s->v[i][1] / 4; }
        for (int i = 1; i < 4; i++)
            for (int j = i; j > 0 && atan2f(s->v[j][1] - cy, s->v[j][0] - cx) < atan2f(s->v[j - 1][1] - cy, s->v[j - 1][0] - cx); j--) {
                float t[3];
                memcpy(t, s->v[j], sizeof t);
                memcpy(s->v[j], s->v[j - 1], sizeof t);
                memcpy(s->v[j - 1], t, sizeof t);
            }
    }
    s->frustum_r = rndf(r, 0.3f, 1.0f);
    s->near_z = rndf(r, 1.0f, 2.0f);
    s->dist = rndf(r, 2.5f, 6.0f);
    s->rx = rndf(r, -80, 80);
    s->ry = rndf(r, -50, 50);
    s->rz = rndf(r, 0, 360);
    s->tex_seed = rnd(r);
    s->content = rndi(r, 3) == 0;
}

static int comps_of(GLenum f)
{
    return f == GL_RGBA ? 4 : f == GL_RGB ? 3 : f == GL_LUMINANCE_ALPHA ? 2 : 1;
}

/* Level `lvl` (w x h) of the scene's texture in its client format/type. */
static void make_level(const scene *s, int lvl, int w, int h, void *px)
{
    rng r = {0x9E3779B97F4A7C15ull ^ ((uint64_t)s->tex_seed << 8) ^ (uint64_t)lvl};
    int n = comps_of(s->format);
    for (int i = 0; i < w * h * n; i++) {
        int x = (i / n) % w, y = (i / n) / w;
        float v = s->content ? (((x >> (lvl ? 0 : 1)) ^ (y >> (lvl ? 0 : 1))) & 1 ? 0.9f : 0.15f) + 0.02f * (float)(i % n)
                             : rndf(&r, 0, 1);
        if (s->type == GL_FLOAT)
            ((float *)px)[i] = s->content ? v : rndf(&r, -0.1f, 1.1f); /* clamped when unpacked */
        else
            ((uint8_t *)px)[i] = (uint8_t)(v * 255.0f);
    }
}

static void draw_scene(fs_context *c, const void *user, int w, int h)
{
    const scene *s = user;
    (void)w;
    (void)h;
    G(Viewport, 0, 0, s->w, s->h);
    G(ClearColor, 0.25f, 0.5f, 0.75f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    double r = s->frustum_r, a = (double)s->h / s->w;
    G(Frustum, -r, r, -r * a, r * a, s->near_z, 60.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -s->dist);
    G(Rotatef, s->rx, 1, 0, 0);
    G(Rotatef, s->ry, 0, 1, 0);
    G(Rotatef, s->rz, 0, 0, 1);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(BindTexture, GL_TEXTURE_2D, 3);
    void *px = malloc((size_t)s->tw * (size_t)s->th * 4 * sizeof(float));
    if (!px)
        return;
    for (int lvl = 0, lw = s->tw, lh = s->th;; lvl++) {
        make_level(s, lvl, lw, lh, px);
        G(TexImage2D, GL_TEXTURE_2D, lvl, s->internal, lw, lh, 0, s->format, s->type, px);
        if (lw == 1 && lh == 1)
            break;
        lw = lw > 1 ? lw / 2 : 1;
        lh = lh > 1 ? lh / 2 : 1;
    }
    free(px);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)s->min);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)s->mag);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)s->wrap_s);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)s->wrap_t);
    G(TexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, s->border);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)s->env);
    G(TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, s->env_color);
    G(Enable, GL_TEXTURE_2D);
    G(Begin, s->quad ? GL_QUADS : GL_TRIANGLES);
    for (int i = 0; i < (s->quad ? 4 : 3); i++) {
        G(Color4fv, s->col[i]);
        G(TexCoord2fv, s->tc[i]);
        G(Vertex3fv, s->v[i]);
    }
    G0(End);
}

/* The vector-shared sampling above applies to this scene. */
static bool grouped_filter_choice(const scene *s)
{
    bool min_linear = s->min == GL_LINEAR || s->min == GL_LINEAR_MIPMAP_NEAREST || s->min == GL_LINEAR_MIPMAP_LINEAR;
    return (s->wrap_s == GL_CLAMP || s->wrap_t == GL_CLAMP) && (min_linear ? GL_LINEAR : GL_NEAREST) != s->mag;
}

static const char *enum_name(GLenum e)
{
    switch (e) {
    case GL_NEAREST: return "NEAREST";
    case GL_LINEAR: return "LINEAR";
    case GL_NEAREST_MIPMAP_NEAREST: return "NMN";
    case GL_LINEAR_MIPMAP_NEAREST: return "LMN";
    case GL_NEAREST_MIPMAP_LINEAR: return "NML";
    case GL_LINEAR_MIPMAP_LINEAR: return "LML";
    case GL_REPEAT: return "REPEAT";
    case GL_CLAMP: return "CLAMP";
    case GL_CLAMP_TO_EDGE: return "EDGE";
    case GL_MODULATE: return "MODULATE";
    case GL_DECAL: return "DECAL";
    case GL_REPLACE: return "REPLACE";
    case GL_BLEND: return "BLEND";
    case GL_ADD: return "ADD";
    default: return "?";
    }
}

TEST(random_textured_scenes)
{
    const char *seed_env = getenv("FS_TEX_RANDOM_SEED");
    rng r = {seed_env && strtoull(seed_env, NULL, 0) ? strtoull(seed_env, NULL, 0) : 0x5eed7e57ull};
    img_diff all = {0, 0, 0, 0}, nearest = {0, 0, 0, 0}, known = {0, 0, 0, 0};
    int known_scenes = 0;
    long fragments = 0;
    int failed_scenes = 0;
    for (int i = 0; i < N_SCENES; i++) {
        scene s;
        make_scene(&r, &s);
        /* FS_TEX_RANDOM_ONLY=n: draw scene n alone (for debugging). */
        if (getenv("FS_TEX_RANDOM_ONLY") && atoi(getenv("FS_TEX_RANDOM_ONLY")) != i)
            continue;
        osm_pair p;
        REQUIRE(osm_pair_render(&p, s.w, s.h, NULL, draw_scene, &s));
        const osm o = p.ref;
        const fs_context *c = p.c;
        img_diff d = p.d;
        fragments += (long)c->stats.fragments_generated;
        bool exact = (s.min == GL_NEAREST || s.min == GL_NEAREST_MIPMAP_NEAREST) && s.mag == GL_NEAREST;
        img_compare(o.color, c->fb.color, exact ? (long)s.w * s.h : 0, &nearest);
        all.pixels += d.pixels;
        all.differ += d.differ;
        all.differ_gt1 += d.differ_gt1;
        all.maxd = d.maxd > all.maxd ? d.maxd : all.maxd;
        if (grouped_filter_choice(&s)) {
            known_scenes++;
            img_compare(o.color, c->fb.color, (long)s.w * s.h, &known);
        }
        if (d.differ_gt1 || (exact && d.differ)) {
            failed_scenes++;
            CHECK_FAIL_("scene %d (%dx%d, tex %dx%d %s/%s, min %s mag %s, wrap %s/%s, %s, %s): %ld pixels differ "
                        "(%ld by more than 1), max %d",
                        i, s.w, s.h, s.tw, s.th, formats[s.fmt].name, s.type == GL_FLOAT ? "float" : "ubyte",
                        enum_name(s.min), enum_name(s.mag), enum_name(s.wrap_s), enum_name(s.wrap_t),
                        enum_name(s.env), s.quad ? "quad" : "triangle", d.differ, d.differ_gt1, d.maxd);
        }
        if (getenv("FS_TEX_DUMP") && (d.differ_gt1 || (exact && d.differ))) {
            printf("  scene %d (%s): %ld pixels differ, max %d\n", i,
                   grouped_filter_choice(&s) ? "vector-shared filter" : "other", d.differ, d.maxd);
            char fn[64];
            snprintf(fn, sizeof fn, "/tmp/texrand_%d.ppm", i);
            img_dump_ppm(fn, o.color, c->fb.color, s.w, s.h, 4, true);
            for (long p = 0; p < (long)s.w * s.h; p++)
                for (int k = 0; k < 4; k++)
                    if (abs(o.color[p * 4 + k] - c->fb.color[p * 4 + k]) > 1) {
                        printf("    (%ld,%ld) ch%d OSMesa %d model %d\n", p % s.w, p / s.w, k, o.color[p * 4 + k], c->fb.color[p * 4 + k]);
                        break;
                    }
        }
        osm_pair_close(&p);
    }
    printf("  %d scenes: %ld pixels compared (%ld textured fragments), %ld differ (%ld by more than 1), max %d; "
           "NEAREST scenes: %ld pixels, %ld differ\n",
           N_SCENES, all.pixels, fragments, all.differ, all.differ_gt1, all.maxd, nearest.pixels, nearest.differ);
    printf("  of these, %d scenes with GL_CLAMP and different min/mag image filters (vector-shared filter): "
           "%ld pixels, %ld differ, max %d\n", known_scenes, known.pixels, known.differ, known.maxd);
    CHECK(fragments > 0);
    CHECK_EQ_INT(failed_scenes, 0);
}

TEST_LIST = {
    TEST_ENTRY(random_textured_scenes),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
