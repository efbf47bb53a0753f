/*
 * Textured ground plane: the setting of Huettner 1999, Figs. 4.33-4.41 (a
 * plane seen at a grazing angle, where MIPmapping blurs and anisotropic
 * filtering pays off), here with a 256x256 checkerboard and its MIPmap
 * pyramid, trilinear filtering, GL_REPEAT and GL_MODULATE over vertex
 * colours, plus a NEAREST-filtered box.  The ground is a row-major grid of
 * quads, so any triangle budget is met exactly (one triangle more for an
 * odd budget).  scenegen --filter footprint / footprint-hybrid --budget M
 * draws the ground with the fast-footprint filter instead
 * (GL_FRAGSIM_footprint_filter; the texture-cache study sweeps M).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "sg.h"
#include "../glext/GL_FRAGSIM_footprint_filter.h"

#define TEX 256

/* Level l of the checkerboard: 2x2 box filtering of level l-1 (what
 * gluBuild2DMipmaps does for a power-of-two image). */
static unsigned char *checker_levels(int *nlevels)
{
    size_t total = 0;
    int n = 0;
    for (int s = TEX; s >= 1; s /= 2, n++)
        total += (size_t)s * s * 4;
    unsigned char *all = malloc(total);
    if (!all)
        return NULL;
    unsigned char *p = all;
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            int on = ((x / 16) + (y / 16)) & 1;
            unsigned char *t = p + 4 * ((size_t)y * TEX + (size_t)x);
            t[0] = on ? 235 : 40;
            t[1] = on ? 225 : 60;
            t[2] = on ? 200 : 110;
            t[3] = 255;
        }
    for (int s = TEX / 2; s >= 1; s /= 2) {
        const unsigned char *src = p;
        unsigned char *dst = p + (size_t)(2 * s) * (size_t)(2 * s) * 4;
        for (int y = 0; y < s; y++)
            for (int x = 0; x < s; x++)
                for (int ch = 0; ch < 4; ch++) {
                    int sum = 0;
                    for (int k = 0; k < 4; k++)
                        sum += src[4 * ((size_t)(2 * y + k / 2) * (size_t)(2 * s) + (size_t)(2 * x + k % 2)) + (size_t)ch];
                    dst[4 * ((size_t)y * (size_t)s + (size_t)x) + (size_t)ch] = (unsigned char)((sum + 2) / 4);
                }
        p = dst;
    }
    *nlevels = n;
    return all;
}

int sg_scene_textured(sg *s, const sg_params *p, char *err, size_t errlen)
{
    int nlevels;
    unsigned char *levels = checker_levels(&nlevels);
    if (!levels) {
        snprintf(err, errlen, "textured: out of memory");
        return -1;
    }
    GLuint tex = 1; /* what fragsim hands out first; the count-only run has no context */
    G(s, GenTextures, 1, &tex);
    G(s, BindTexture, GL_TEXTURE_2D, tex);
    const unsigned char *lp = levels;
    for (int l = 0, sz = TEX; l < nlevels; l++, sz /= 2) {
        G(s, TexImage2D, GL_TEXTURE_2D, l, GL_RGBA, sz, sz, 0, GL_RGBA, GL_UNSIGNED_BYTE, lp);
        lp += (size_t)sz * (size_t)sz * 4;
    }
    free(levels);
    const GLint ground = p->filter == SG_FILTER_FOOTPRINT          ? GL_FOOTPRINT_FRAGSIM
                         : p->filter == SG_FILTER_FOOTPRINT_HYBRID ? GL_FOOTPRINT_HYBRID_FRAGSIM
                                                                   : GL_LINEAR_MIPMAP_LINEAR;
    if (p->budget)
        G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_FOOTPRINT_BUDGET_FRAGSIM, p->budget);
    G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    G(s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    G(s, Enable, GL_DEPTH_TEST);
    G(s, Enable, GL_CULL_FACE);
    sg_perspective(s, 50.0, (double)p->width / p->height, 0.5, 400.0);

    /* Ground: quads over [-100, 100]^2, 64 per row, as many as the budget
     * holds; texture coordinates repeat every 4 units. */
    const uint64_t target = p->target > 12 ? p->target - 12 : 2; /* the box takes 12 */
    const uint64_t quads = target / 2;
    const int per_row = 64;
    const uint64_t rows = (quads + (uint64_t)per_row - 1) / (uint64_t)per_row;
    const float cell = 200.0f / (float)per_row, depth = rows ? 200.0f / (float)rows : 200.0f;
    for (int fr = 0; fr < p->frames; fr++) {
        sg_frame_begin(s, 0.55f, 0.7f, 0.9f);
        G0(s, LoadIdentity);
        float t = (float)fr / (float)(p->frames > 1 ? p->frames - 1 : 1);
        const float eye[3] = {-20.0f + 40.0f * t, 2.0f + 6.0f * t, 60.0f}, at[3] = {0, 0, -40.0f},
                    up[3] = {0, 1, 0};
        sg_look_at(s, eye, at, up);
        G(s, Enable, GL_TEXTURE_2D);
        G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, ground);
        sg_begin(s, GL_QUADS);
        for (uint64_t q = 0; q < quads; q++) {
            int i = (int)(q % (uint64_t)per_row);
            uint64_t j = q / (uint64_t)per_row;
            float x0 = -100.0f + cell * (float)i, z0 = 100.0f - depth * (float)j;
            float shade = 0.75f + 0.25f * (float)((i + (int)j) % 3) / 2.0f;
            sg_col(s, shade, shade, shade);
            const float xs[4] = {x0, x0 + cell, x0 + cell, x0}, zs[4] = {z0, z0, z0 - depth, z0 - depth};
            for (int k = 0; k < 4; k++) {
                G(s, TexCoord2f, xs[k] / 4.0f, zs[k] / 4.0f);
                sg_vtx(s, xs[k], 0.0f, zs[k]);
            }
        }
        sg_end(s);
        if (target % 2) {
            sg_begin(s, GL_TRIANGLES);
            G(s, TexCoord2f, 0, 0);
            sg_vtx(s, -100.0f, 0.0f, -110.0f);
            G(s, TexCoord2f, 1, 0);
            sg_vtx(s, -90.0f, 0.0f, -110.0f);
            G(s, TexCoord2f, 0, 1);
            sg_vtx(s, -100.0f, 0.0f, -120.0f);
            sg_end(s);
        }
        /* A box with magnified NEAREST texels: 6 faces, 12 triangles. */
        G(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        G0(s, PushMatrix);
        G(s, Translatef, 0.0f, 3.0f, 20.0f);
        G(s, Rotatef, 30.0f + 20.0f * (float)fr, 0.0f, 1.0f, 0.0f);
        static const float v[8][3] = {{-3, -3, -3}, {3, -3, -3}, {3, 3, -3}, {-3, 3, -3},
                                      {-3, -3, 3},  {3, -3, 3},  {3, 3, 3},  {-3, 3, 3}};
        static const int f[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
        static const float tc[4][2] = {{0, 0}, {0.25f, 0}, {0.25f, 0.25f}, {0, 0.25f}};
        sg_col(s, 1.0f, 1.0f, 1.0f);
        sg_begin(s, GL_QUADS);
        for (int k = 0; k < 6; k++)
            for (int m = 0; m < 4; m++) {
                G(s, TexCoord2f, tc[m][0], tc[m][1]);
                sg_vtxv(s, v[f[k][m]]);
            }
        sg_end(s);
        G0(s, PopMatrix);
        G(s, Disable, GL_TEXTURE_2D);
        sg_frame_end(s);
    }
    return 0;
}
