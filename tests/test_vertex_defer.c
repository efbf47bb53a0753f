/*
 * Deferred vertex shading (pipeline/vertex_array.c, fs_vs_defer_shading)
 * against the reference it short-cuts: every vertex shaded before
 * primitive assembly (fs_vs_set_eager(c, true)), which the lighting,
 * texgen and fog tests hold to OSMesa.  Random scenes drawn twice on the
 * model must give the same colour and depth bytes and the same
 * statistics: triangles, strips, fans, quads, quad strips and polygons,
 * immediate and from arrays (glDrawArrays, glDrawElements), lit (one or
 * two sided, local viewer, colour material) or not, with texgen, fog, flat
 * shading with either provoking vertex, face culling, and vertices spread
 * so that many triangles are wholly outside one clip plane and many are
 * clipped.  FS_VTX_DEFER_SEED overrides the seed.
 */
#include <stdio.h>
#include "check.h"
#include "osmesa_util.h"
#include "test_rng.h"
#include "../pipeline/context.h"

#define N_SCENES 200
#define MAXV 64

static const GLenum modes[] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
#define N_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void state(fs_context *c, rng *r)
{
    G(Viewport, 0, 0, 48, 40);
    G(ClearColor, 0.25f, 0.5f, 0.75f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(Frustum, -0.6, 0.6, -0.6, 0.6, 1.0, 20.0);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, 0, 0, -3.0f);
    G(Rotatef, rndf(r, 0, 360), 0, 1, 0);
    if (rndi(r, 2)) {
        G(Enable, GL_LIGHTING);
        G(Enable, GL_LIGHT0);
        const float pos[4] = {rndf(r, -2, 2), rndf(r, -2, 2), rndf(r, 0, 2), rndi(r, 2) ? 0.0f : 1.0f};
        G(Lightfv, GL_LIGHT0, GL_POSITION, pos);
        if (rndi(r, 2)) {
            G(Enable, GL_LIGHT1);
            const float d[4] = {rndf(r, 0, 1), rndf(r, 0, 1), rndf(r, 0, 1), 1};
            G(Lightfv, GL_LIGHT1, GL_DIFFUSE, d);
            G(Lightfv, GL_LIGHT1, GL_SPECULAR, d);
        }
        G(Materialf, GL_FRONT_AND_BACK, GL_SHININESS, rndf(r, 0, 100));
        const float sp[4] = {rndf(r, 0, 1), rndf(r, 0, 1), rndf(r, 0, 1), 1};
        G(Materialfv, GL_FRONT_AND_BACK, GL_SPECULAR, sp);
        G(LightModeli, GL_LIGHT_MODEL_TWO_SIDE, rndi(r, 2));
        G(LightModeli, GL_LIGHT_MODEL_LOCAL_VIEWER, rndi(r, 2));
        if (rndi(r, 2))
            G(Enable, GL_COLOR_MATERIAL);
        if (rndi(r, 2))
            G(Enable, GL_NORMALIZE);
    }
    if (rndi(r, 2)) {
        G(TexGeni, GL_S, GL_TEXTURE_GEN_MODE, rndi(r, 2) ? GL_SPHERE_MAP : GL_OBJECT_LINEAR);
        G(TexGeni, GL_T, GL_TEXTURE_GEN_MODE, rndi(r, 2) ? GL_EYE_LINEAR : GL_SPHERE_MAP);
        G(Enable, GL_TEXTURE_GEN_S);
        G(Enable, GL_TEXTURE_GEN_T);
    }
    if (rndi(r, 2)) {
        /* A texture makes the coordinates show in the colours. */
        uint8_t px[4 * 4 * 4];
        for (int i = 0; i < 64; i++)
            px[i] = (uint8_t)rnd(r);
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        G(Enable, GL_TEXTURE_2D);
    }
    if (rndi(r, 3) == 0) {
        G(Enable, GL_FOG);
        G(Fogi, GL_FOG_MODE, GL_LINEAR);
        G(Fogf, GL_FOG_START, 1.0f);
        G(Fogf, GL_FOG_END, 6.0f);
    }
    if (rndi(r, 2))
        G(ShadeModel, GL_FLAT);
    if (rndi(r, 3) == 0)
        fsglProvokingVertex(c, GL_FIRST_VERTEX_CONVENTION); /* the model only: no OSMesa side here */
    if (rndi(r, 2)) {
        G(Enable, GL_CULL_FACE);
        G(CullFace, rndi(r, 2) ? GL_BACK : GL_FRONT);
    }
}

/* Scene `seed` on c: a few draws whose vertices lie up to `spread` from
 * the view's centre, so that some triangles are rejected, some clipped. */
static void draw_scene(fs_context *c, uint64_t seed)
{
    rng r = {seed};
    state(c, &r);
    static float pos[MAXV][3], col[MAXV][4], nrm[MAXV][3], tc[MAXV][2];
    static GLushort idx[MAXV];
    for (int d = 0; d < 4; d++) {
        GLenum mode = modes[rndi(&r, N_OF(modes))];
        int n = 3 + rndi(&r, MAXV - 3);
        float spread = rndf(&r, 0.5f, 6.0f);
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                pos[i][k] = rndf(&r, -spread, spread);
                nrm[i][k] = rndf(&r, -1, 1);
            }
            for (int k = 0; k < 4; k++)
                col[i][k] = rndf(&r, 0, 1);
            tc[i][0] = rndf(&r, 0, 1);
            tc[i][1] = rndf(&r, 0, 1);
            idx[i] = (GLushort)rndi(&r, n);
        }
        int how = rndi(&r, 3);
        if (how == 0) {
            G(Begin, mode);
            for (int i = 0; i < n; i++) {
                G(Color4fv, col[i]);
                G(Normal3fv, nrm[i]);
                G(TexCoord2fv, tc[i]);
                G(Vertex3fv, pos[i]);
            }
            G0(End);
        } else {
            G(VertexPointer, 3, GL_FLOAT, 0, pos);
            G(ColorPointer, 4, GL_FLOAT, 0, col);
            G(NormalPointer, GL_FLOAT, 0, nrm);
            G(TexCoordPointer, 2, GL_FLOAT, 0, tc);
            G(EnableClientState, GL_VERTEX_ARRAY);
            G(EnableClientState, GL_COLOR_ARRAY);
            G(EnableClientState, GL_NORMAL_ARRAY);
            G(EnableClientState, GL_TEXTURE_COORD_ARRAY);
            if (how == 1)
                G(DrawArrays, mode, 0, n);
            else
                G(DrawElements, mode, n, GL_UNSIGNED_SHORT, idx);
        }
    }
}

TEST(deferred_shading_matches_eager)
{
    const char *seed_env = getenv("FS_VTX_DEFER_SEED");
    rng r = {seed_env && strtoull(seed_env, NULL, 0) ? strtoull(seed_env, NULL, 0) : 0xdefe55edull};
    long differ = 0;
    uint64_t rejected = 0, clipped = 0, rasterized = 0;
    for (int i = 0; i < N_SCENES; i++) {
        uint64_t seed = ((uint64_t)rnd(&r) << 32 | rnd(&r)) | 1u;
        fs_context *c[2];
        for (int k = 0; k < 2; k++) {
            c[k] = fs_context_create(NULL, 48, 40);
            REQUIRE(c[k]);
            fs_vs_set_eager(c[k], k == 0);
            draw_scene(c[k], seed);
        }
        size_t n = 48 * 40;
        bool same = memcmp(c[0]->fb.color, c[1]->fb.color, n * 4) == 0 &&
                    memcmp(c[0]->fb.depth, c[1]->fb.depth, n * sizeof c[0]->fb.depth[0]) == 0 &&
                    memcmp(&c[0]->stats, &c[1]->stats, sizeof c[0]->stats) == 0;
        if (!same && differ++ < 10)
            CHECK_FAIL_("scene %d: deferred shading differs from the eager reference", i);
        else if (!same)
            check_st_->failed++;
        rejected += c[1]->stats.triangles_rejected;
        clipped += c[1]->stats.triangles_clipped;
        rasterized += c[1]->stats.triangles_rasterized;
        for (int k = 0; k < 2; k++)
            fs_context_destroy(c[k]);
    }
    printf("  %d scenes: %llu triangles rejected, %llu clipped, %llu rasterized; %ld scenes differ\n", N_SCENES,
           (unsigned long long)rejected, (unsigned long long)clipped, (unsigned long long)rasterized, differ);
    /* The scenes must exercise what the deferral depends on. */
    CHECK(rejected > 1000 && clipped > 1000 && rasterized > 1000);
}

TEST_LIST = {
    TEST_ENTRY(deferred_shading_matches_eager),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
