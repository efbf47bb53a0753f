/*
 * The 8-bit quad path of texture sampling (units/texture_sample.c,
 * sample_quad8) against the reference path it short-cuts (sample_pixel per
 * pixel, which tests/test_texture*.c hold to OSMesa at tolerance 0): random
 * textured scenes drawn twice on the model, once with
 * fs_texture_set_generic(c, true), must give the same colour and depth
 * bytes and the same statistics.
 *
 * The scenes: windows of 5..70 pixels (odd heights move llvmpipe's quads,
 * triangles leave partial quads), one or two units with 1D or 2D textures
 * of every 8-bit base format, sizes 1..64 per side, powers of two or not,
 * full or clipped MIPmap chains (BASE_LEVEL, MAX_LEVEL, MIN/MAX_LOD, LOD
 * bias), every min and mag filter, REPEAT and CLAMP_TO_EDGE (the wraps the
 * path takes) and now and then GL_CLAMP (which must leave it), coordinates
 * far outside [0, 1] (beyond 2^31 texels too) with q != 1, every
 * environment mode.  At least half of
 * the textured quads must take the quad path, or the test proves nothing.
 * FS_TEX_FAST_SEED overrides the seed, FS_TEX_FAST_ONLY=n draws scene n.
 */
#include <stdio.h>
#include "check.h"
#include "osmesa_util.h"
#include "test_rng.h"
#include "../pipeline/context.h"
#include "../units/texture_unit.h"

#define N_SCENES 300

static const struct { GLint internal; GLenum format; int comps; } formats[] = {
    {GL_RGBA, GL_RGBA, 4}, {GL_RGB, GL_RGB, 3}, {GL_LUMINANCE, GL_LUMINANCE, 1},
    {GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, 2}, {GL_ALPHA, GL_ALPHA, 1}, {GL_INTENSITY, GL_LUMINANCE, 1},
};
static const GLenum min_filters[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                     GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
static const GLenum envs[] = {GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND, GL_ADD, GL_COMBINE};
#define N_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* A size of 1..64: a power of two or any. */
static int tex_size(rng *r) { return rndi(r, 2) ? 1 << rndi(r, 7) : 1 + rndi(r, 64); }

static GLenum pick_wrap(rng *r) { return rndi(r, 10) == 0 ? GL_CLAMP : rndi(r, 2) ? GL_REPEAT : GL_CLAMP_TO_EDGE; }

/* One unit's texture and state, from the scene's generator. */
static void setup_unit(fs_context *c, rng *r, int u)
{
    G(ActiveTexture, GL_TEXTURE0 + u);
    GLenum target = rndi(r, 5) ? GL_TEXTURE_2D : GL_TEXTURE_1D;
    int f = rndi(r, N_OF(formats));
    int w = tex_size(r), h = target == GL_TEXTURE_2D ? tex_size(r) : 1;
    G(BindTexture, target, (GLuint)(u + 1));
    uint8_t *px = malloc((size_t)w * (size_t)h * 4);
    if (!px)
        return;
    for (int lvl = 0, lw = w, lh = h;; lvl++) {
        for (int i = 0; i < lw * lh * formats[f].comps; i++)
            px[i] = (uint8_t)rnd(r);
        if (target == GL_TEXTURE_2D)
            G(TexImage2D, target, lvl, formats[f].internal, lw, lh, 0, formats[f].format, GL_UNSIGNED_BYTE, px);
        else
            G(TexImage1D, target, lvl, formats[f].internal, lw, 0, formats[f].format, GL_UNSIGNED_BYTE, px);
        if (lw == 1 && lh == 1)
            break;
        lw = lw > 1 ? lw / 2 : 1;
        lh = lh > 1 ? lh / 2 : 1;
    }
    free(px);
    G(TexParameteri, target, GL_TEXTURE_MIN_FILTER, (GLint)min_filters[rndi(r, N_OF(min_filters))]);
    G(TexParameteri, target, GL_TEXTURE_MAG_FILTER, rndi(r, 2) ? GL_LINEAR : GL_NEAREST);
    G(TexParameteri, target, GL_TEXTURE_WRAP_S, (GLint)pick_wrap(r));
    G(TexParameteri, target, GL_TEXTURE_WRAP_T, (GLint)pick_wrap(r));
    if (rndi(r, 4) == 0) {
        G(TexParameteri, target, GL_TEXTURE_BASE_LEVEL, rndi(r, 3));
        G(TexParameteri, target, GL_TEXTURE_MAX_LEVEL, 1 + rndi(r, 5));
    }
    if (rndi(r, 4) == 0) {
        G(TexParameterf, target, GL_TEXTURE_MIN_LOD, rndf(r, -1, 2));
        G(TexParameterf, target, GL_TEXTURE_MAX_LOD, rndf(r, 0, 6));
    }
    if (rndi(r, 4) == 0)
        G(TexParameterf, target, GL_TEXTURE_LOD_BIAS, rndf(r, -2, 2));
    if (rndi(r, 6) == 0)
        G(TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, rndf(r, -2, 2));
    GLenum env = envs[rndi(r, N_OF(envs))];
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
    if (env == GL_COMBINE) {
        G(TexEnvi, GL_TEXTURE_ENV, GL_COMBINE_RGB, rndi(r, 2) ? GL_MODULATE : GL_INTERPOLATE);
        G(TexEnvi, GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE);
    }
    const float col[4] = {rndf(r, 0, 1), rndf(r, 0, 1), rndf(r, 0, 1), rndf(r, 0, 1)};
    G(TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, col);
    G(Enable, target);
}

/* Scene `seed` on c: its textures, then triangles and quads under a
 * perspective projection, each vertex with its own coordinates and q. */
static void draw_scene(fs_context *c, uint64_t seed, int w, int h)
{
    rng r = {seed};
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.25f, 0.5f, 0.75f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -0.6, 0.6, -0.6, 0.6, 1.0, 20.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -3.0f);
    G(Rotatef, rndf(&r, -70, 70), 1, 0, 0);
    G(Rotatef, rndf(&r, 0, 360), 0, 0, 1);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    int units = 1 + rndi(&r, 2);
    for (int u = 0; u < units; u++)
        setup_unit(c, &r, u);
    /* Coordinates far out exercise the wraps, beyond 2^31 texels the
     * conversions' out-of-range results. */
    int far = rndi(&r, 8);
    float range = far > 2 ? 2.0f : far ? 40.0f : 3e9f;
    for (int prim = 0; prim < 3; prim++) {
        bool quad = rndi(&r, 2);
        G(Begin, quad ? GL_QUADS : GL_TRIANGLES);
        float base[2] = {rndf(&r, -1.5f, 1.5f), rndf(&r, -1.5f, 1.5f)};
        const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int i = 0; i < (quad ? 4 : 3); i++) {
            G(Color4f, rndf(&r, 0, 1), rndf(&r, 0, 1), rndf(&r, 0, 1), rndf(&r, 0, 1));
            for (int u = 0; u < units; u++) {
                float q = rndi(&r, 2) ? 1.0f : rndf(&r, 0.25f, 3.0f);
                G(MultiTexCoord4f, GL_TEXTURE0 + u, rndf(&r, -range, range) * q, rndf(&r, -range, range) * q,
                  0.0f, q);
            }
            G(Vertex3f, base[0] + corner[i][0] * rndf(&r, 0.2f, 1.2f), base[1] + corner[i][1] * rndf(&r, 0.2f, 1.2f),
              rndf(&r, -0.5f, 0.5f));
        }
        G0(End);
    }
}

TEST(fast_path_matches_reference)
{
    const char *seed_env = getenv("FS_TEX_FAST_SEED"), *only = getenv("FS_TEX_FAST_ONLY");
    rng r = {seed_env && strtoull(seed_env, NULL, 0) ? strtoull(seed_env, NULL, 0) : 0xfa57e8b17ull};
    uint64_t sampled = 0, fast = 0;
    long differ_scenes = 0;
    for (int i = 0; i < N_SCENES; i++) {
        int w = 5 + rndi(&r, 66), h = 5 + rndi(&r, 66);
        uint64_t seed = ((uint64_t)rnd(&r) << 32 | rnd(&r)) | 1u;
        if (only && atoi(only) != i)
            continue;
        fs_context *c[2];
        for (int k = 0; k < 2; k++) {
            c[k] = fs_context_create(NULL, w, h);
            REQUIRE(c[k]);
            fs_texture_set_generic(c[k], k == 0);
            draw_scene(c[k], seed, w, h);
        }
        CHECK_EQ_UINT(fs_texture_quads_fast(c[0]), 0);
        sampled += fs_texture_quads_sampled(c[1]);
        fast += fs_texture_quads_fast(c[1]);
        size_t n = (size_t)w * (size_t)h;
        bool same = memcmp(c[0]->fb.color, c[1]->fb.color, n * 4) == 0 &&
                    memcmp(c[0]->fb.depth, c[1]->fb.depth, n * sizeof c[0]->fb.depth[0]) == 0 &&
                    memcmp(&c[0]->stats, &c[1]->stats, sizeof c[0]->stats) == 0 &&
                    fs_texture_quads_sampled(c[0]) == fs_texture_quads_sampled(c[1]) &&
                    fs_texture_quads_incomplete(c[0]) == fs_texture_quads_incomplete(c[1]);
        if (!same) {
            long px = 0;
            for (size_t p = 0; p < n; p++)
                px += memcmp(c[0]->fb.color + 4 * p, c[1]->fb.color + 4 * p, 4) != 0;
            if (differ_scenes++ < 10)
                CHECK_FAIL_("scene %d (%dx%d): %ld pixels differ between the reference and the quad path", i, w, h,
                            px);
            else
                check_st_->failed++;
        }
        for (int k = 0; k < 2; k++)
            fs_context_destroy(c[k]);
    }
    printf("  %d scenes, %llu textured quads, %llu of them on the quad path, %ld scenes differ\n", N_SCENES,
           (unsigned long long)sampled, (unsigned long long)fast, differ_scenes);
    if (!only)
        CHECK(fast * 2 > sampled);
}

TEST_LIST = {
    TEST_ENTRY(fast_path_matches_reference),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
