/*
 * GL_PROXY_TEXTURE_2D (GL 1.5 spec 3.8.11; units/texture_object.c) against
 * OSMesa (llvmpipe): glTexImage2D on the proxy target for valid images of
 * every base format, with and without a border, and with bad arguments,
 * each followed by every glGetTexLevelParameteriv of the proxy level and
 * glGetError; the proxy never changes the bound texture.  Sizes above the
 * model's GL_MAX_TEXTURE_SIZE (4096, llvmpipe's is 16384) and
 * non-power-of-two sizes (llvmpipe has ARB_texture_non_power_of_two) are
 * left out: there the two differ by design.
 */
#include <stdlib.h>
#include <stdint.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

static void log_proxy_level(fs_context *c, GLenum target, int level, double *v, int *n)
{
    static const GLenum pn[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER,
                                GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE,
                                GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE};
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        GLint iv = -5;
        G(GetTexLevelParameteriv, target, level, pn[i], &iv);
        v[(*n)++] = iv;
    }
    v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError());
}

static void proxy_sequence(fs_context *c, double *v, int *n)
{
    static const struct { int level, w, h, border; GLint internal; GLenum format; } img[] = {
        {0, 64, 32, 0, GL_RGBA, GL_RGBA},      {1, 128, 16, 0, GL_INTENSITY, GL_LUMINANCE},
        {0, 18, 10, 1, GL_RGB, GL_RGB},        {2, 1, 1, 0, GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA},
        {0, 0, 0, 0, GL_ALPHA, GL_ALPHA},      {3, 512, 128, 0, GL_LUMINANCE8, GL_LUMINANCE},
        {0, 64, 32, 2, GL_RGBA, GL_RGBA},      {0, 64, 32, 0, 77, GL_RGBA},
        {-1, 64, 32, 0, GL_RGBA, GL_RGBA},     {0, -4, 32, 0, GL_RGBA, GL_RGBA},
        {0, 8, 8, 0, GL_RGBA, GL_DEPTH_COMPONENT}, {0, 8, 8, 0, GL_RGBA, 0x1234},
    };
    G(BindTexture, GL_TEXTURE_2D, 4);
    for (size_t i = 0; i < sizeof img / sizeof img[0]; i++) {
        G(TexImage2D, GL_PROXY_TEXTURE_2D, img[i].level, img[i].internal, img[i].w, img[i].h, img[i].border,
          img[i].format, GL_UNSIGNED_BYTE, NULL);
        v[(*n)++] = (double)(c ? fsglGetError(c) : glGetError());
        log_proxy_level(c, GL_PROXY_TEXTURE_2D, img[i].level >= 0 ? img[i].level : 0, v, n);
    }
    /* The bound texture is untouched. */
    log_proxy_level(c, GL_TEXTURE_2D, 0, v, n);
}

TEST(proxy_levels_vs_osmesa)
{
    double ref[512], mine[512];
    int nr, nm;
    REQUIRE(osm_run_values(proxy_sequence, 8, 8, ref, &nr, mine, &nm));
    CHECK_EQ_INT(nm, nr);
    int bad = 0;
    for (int i = 0; i < nr && i < nm; i++)
        if (mine[i] != ref[i] && bad++ < 10)
            CHECK_FAIL_("value %d: fragsim %.9g, OSMesa %.9g", i, mine[i], ref[i]);
    printf("  %d values, %d differ\n", nr, bad);
}

TEST_LIST = {
    TEST_ENTRY(proxy_levels_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
