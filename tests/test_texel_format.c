/*
 * Texel formats (units/texel_format.c) against OSMesa (llvmpipe): for
 * each sized internal format below and above 8 bits per component, the
 * ARB_texture_rg formats, ARB_texture_float's and a few unsized ones, a 256-texel ramp is
 * uploaded, the level's component sizes are read with
 * glGetTexLevelParameteriv, the texels with glGetTexImage, and the texture
 * is drawn (NEAREST, REPLACE) and read back; then a second ramp drawn
 * with glDrawPixels is copied with glCopyTexImage2D and read again.
 * Every value must be equal (tolerance 0).
 */
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

#define W 256
#define H 4

static const GLint formats[] = {
    GL_RGB4, GL_RGB5, GL_R3_G3_B2, GL_RGBA2, GL_RGBA4, GL_RGB5_A1, GL_ALPHA4, GL_LUMINANCE4,
    GL_LUMINANCE4_ALPHA4, GL_LUMINANCE6_ALPHA2, GL_INTENSITY4, GL_RGB10, GL_RGB12, GL_RGB16, GL_RGBA12,
    GL_RGBA16, GL_RGB10_A2, GL_LUMINANCE12, GL_LUMINANCE16, GL_ALPHA12, GL_ALPHA16, GL_INTENSITY12,
    GL_INTENSITY16, GL_LUMINANCE12_ALPHA4, GL_LUMINANCE12_ALPHA12, GL_LUMINANCE16_ALPHA16, GL_RED, GL_RG,
    GL_R8, GL_RG8, GL_R16, GL_RG16, GL_RGBA8, GL_RGB, GL_LUMINANCE_ALPHA, GL_INTENSITY,
    /* ARB_texture_float (kept at 8 bits: 8-bit ramps and copies are exact) */
    GL_RGBA16F, GL_RGB16F, GL_RGBA32F, GL_RGB32F, GL_ALPHA16F_ARB, GL_ALPHA32F_ARB, GL_LUMINANCE16F_ARB,
    GL_LUMINANCE32F_ARB, GL_LUMINANCE_ALPHA16F_ARB, GL_LUMINANCE_ALPHA32F_ARB, GL_INTENSITY16F_ARB,
    GL_INTENSITY32F_ARB, GL_R16F, GL_R32F, GL_RG16F, GL_RG32F,
};
#define NFORMATS ((int)(sizeof formats / sizeof formats[0]))

static void put_err(fs_context *c, double *v, int *n) { v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError()); }

static void draw_quad(fs_context *c)
{
    static const float xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    G(Begin, GL_QUADS);
    for (int k = 0; k < 4; k++) {
        G(TexCoord2f, (xy[k][0] + 1) / 2, (xy[k][1] + 1) / 2);
        G(Vertex2f, xy[k][0], xy[k][1]);
    }
    G0(End);
}

static void read_level(fs_context *c, double *v, int *n)
{
    static const GLenum pn[] = {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                                GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_INTERNAL_FORMAT};
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        GLint iv = -5;
        G(GetTexLevelParameteriv, GL_TEXTURE_2D, 0, pn[i], &iv);
        v[(*n)++] = iv;
    }
    static uint8_t px[W * 4];
    memset(px, 0xEE, sizeof px);
    G(GetTexImage, GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < W * 4; i++)
        v[(*n)++] = px[i];
    /* Drawn with NEAREST and REPLACE: the texels as the sampler reads them. */
    G(Enable, GL_TEXTURE_2D);
    draw_quad(c);
    G(Disable, GL_TEXTURE_2D);
    memset(px, 0xEE, sizeof px);
    G(ReadPixels, 0, 1, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < W * 4; i++)
        v[(*n)++] = px[i];
    put_err(c, v, n);
}

static void formats_sequence(fs_context *c, double *v, int *n)
{
    static uint8_t ramp[W * 4], ramp2[W * 4];
    for (int i = 0; i < W; i++) {
        ramp[4 * i] = (uint8_t)i;
        ramp[4 * i + 1] = (uint8_t)(255 - i);
        ramp[4 * i + 2] = (uint8_t)(i * 7);
        ramp[4 * i + 3] = (uint8_t)(i * 3 + 11);
        ramp2[4 * i] = (uint8_t)(i * 5 + 3);
        ramp2[4 * i + 1] = (uint8_t)i;
        ramp2[4 * i + 2] = (uint8_t)(255 - i);
        ramp2[4 * i + 3] = (uint8_t)(i * 11);
    }
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(PixelStorei, GL_UNPACK_ALIGNMENT, 1);
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    G(Color4f, 0.25f, 0.5f, 0.75f, 0.625f);
    for (int f = 0; f < NFORMATS; f++) {
        G(TexImage2D, GL_TEXTURE_2D, 0, formats[f], W, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
        put_err(c, v, n);
        read_level(c, v, n);
        /* glCopyTexImage2D of a ramp written by glDrawPixels (3.8.2). */
        G(RasterPos2f, -1, -1);
        G(DrawPixels, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, ramp2);
        G(CopyTexImage2D, GL_TEXTURE_2D, 0, (GLenum)formats[f], 0, 0, W, 1, 0);
        put_err(c, v, n);
        read_level(c, v, n);
    }
}

/* The ramp texels' values, per format: 2 x (8 + 2 W 4 + 1) + 2 */
#define PER_FORMAT (2 * (8 + 2 * W * 4 + 1) + 2)

TEST(texel_formats_vs_osmesa)
{
    int cap = NFORMATS * PER_FORMAT + 16;
    double *ref = malloc((size_t)cap * sizeof *ref), *mine = malloc((size_t)cap * sizeof *mine);
    REQUIRE(ref && mine);
    int nr, nm;
    REQUIRE(osm_run_values(formats_sequence, W, H, ref, &nr, mine, &nm));
    CHECK_EQ_INT(nm, nr);
    int bad = 0, bad_formats = 0;
    for (int f = 0; f < NFORMATS; f++) {
        int fb = 0;
        /* (the copy into R3_G3_B2, its second half, is compared too:
         * units/texel_format.c gives its rule) */
        int end = (f + 1) * PER_FORMAT;
        for (int i = f * PER_FORMAT; i < end && i < nr && i < nm; i++)
            if (mine[i] != ref[i] && fb++ < 3)
                CHECK_FAIL_("format 0x%x value %d: fragsim %.9g, OSMesa %.9g", formats[f], i - f * PER_FORMAT,
                            mine[i], ref[i]);
        bad += fb;
        bad_formats += fb > 0;
    }
    printf("  %d formats, %d values, %d differ (%d formats)\n", NFORMATS, nr, bad, bad_formats);
    free(ref);
    free(mine);
}

/* GL_FLOAT images into the formats stored below 8 bits: values on and
 * near the n-bit rounding ties (0.3f * 15 is 4.5 in float), which
 * llvmpipe rounds from the float itself (units/texel_format.c); through
 * 8-bit values first, 1066 of 16,384 such values differed in RGBA4. */
static const GLint float_formats[] = {GL_RGBA4, GL_RGBA2, GL_RGB4, GL_RGB5, GL_RGB5_A1, GL_R3_G3_B2,
                                      GL_LUMINANCE4_ALPHA4};

static void float_sequence(fs_context *c, double *v, int *n)
{
    static float img[W * 4];
    for (int i = 0; i < W * 4; i++) {
        const int k = i % 64;
        /* Ties and their neighbours for 2 to 5 bits, and the texwrap trace's 0.3. */
        const float tie = ((float)(k % 31) + 0.5f) / (float)((1 << (2 + k % 4)) - 1);
        img[i] = k == 0 ? 0.3f : (k & 1) ? tie : nextafterf(tie, (k & 2) ? 2.0f : -1.0f);
        if (img[i] > 1.0f)
            img[i] = (float)(i % 7) / 7.0f;
    }
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    G(PixelStorei, GL_PACK_ALIGNMENT, 1);
    for (size_t f = 0; f < sizeof float_formats / sizeof float_formats[0]; f++) {
        G(TexImage2D, GL_TEXTURE_2D, 0, float_formats[f], W, 1, 0, GL_RGBA, GL_FLOAT, img);
        put_err(c, v, n);
        read_level(c, v, n);
    }
}

TEST(float_uploads_vs_osmesa)
{
    static double ref[16 * (8 + 2 * W * 4 + 2)], mine[16 * (8 + 2 * W * 4 + 2)];
    int nr, nm;
    REQUIRE(osm_run_values(float_sequence, W, H, ref, &nr, mine, &nm));
    CHECK_EQ_INT(nm, nr);
    int bad = 0;
    for (int i = 0; i < nr && i < nm; i++)
        if (mine[i] != ref[i] && bad++ < 5)
            CHECK_FAIL_("value %d: fragsim %.9g, OSMesa %.9g", i, mine[i], ref[i]);
    printf("  %zu formats, %d values, %d differ\n", sizeof float_formats / sizeof float_formats[0], nr, bad);
}

TEST_LIST = {
    TEST_ENTRY(float_uploads_vs_osmesa),
    TEST_ENTRY(texel_formats_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
