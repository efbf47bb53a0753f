/*
 * The accumulation buffer (pipeline/accum.c; GL 1.5 spec 4.2.4) against
 * OSMesa (llvmpipe) with 16 accumulation bits at tolerance 0: random
 * sequences of glAccum (every op: ACCUM, LOAD, ADD, MULT, RETURN, values
 * beyond [-1, 1] included, so that sums wrap), glClearAccum with glClear
 * under the scissor box and the colour mask; each colour byte through
 * GL_ACCUM and GL_LOAD seen directly; the errors; a context without the
 * buffer.
 */
#include "check.h"
#include "osmesa_util.h"

#define W 32
#define H 32

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static float rndf(uint32_t *s, float lo, float hi) { return lo + (hi - lo) * (float)(rng(s) >> 8) / 16777216.0f; }

static GLenum get_error(fs_context *c) { return c ? fsglGetError(c) : glGetError(); }

typedef struct both { OSMesaContext ctx; uint8_t *color; fs_context *c; } both;

static bool both_open(both *b)
{
    memset(b, 0, sizeof *b);
    b->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    b->color = calloc(W * H, 4);
    if (!b->ctx || !b->color || !OSMesaMakeCurrent(b->ctx, b->color, GL_UNSIGNED_BYTE, W, H))
        return false;
    fs_config cfg;
    fs_config_defaults(&cfg);
    cfg.framebuffer_accum_bits = 16;
    b->c = fs_context_create(&cfg, W, H);
    return b->c != NULL;
}

static void both_close(both *b)
{
    fs_context_destroy(b->c);
    if (b->ctx) {
        glFinish();
        OSMesaDestroyContext(b->ctx);
    }
    free(b->color);
}

/* Random colours in the colour buffer: a glDrawPixels image. */
static void draw_random(fs_context *c, uint32_t seed)
{
    static uint8_t img[W * H * 4];
    uint32_t s = seed | 1u;
    for (int i = 0; i < W * H * 4; i++)
        img[i] = (uint8_t)rng(&s);
    G(RasterPos2f, -1.0f, -1.0f); /* window (0, 0) under the identity matrices */
    G(DrawPixels, W, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
}

TEST(accum_sequences_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context with an accumulation buffer");
    }
    GLint bits[2];
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
    fsglGetIntegerv(b.c, GL_ACCUM_RED_BITS, &bits[1]);
    CHECK_EQ_INT(bits[1], bits[0]);
    static const GLenum ops[] = {GL_LOAD, GL_ADD, GL_MULT, GL_RETURN, GL_ACCUM, GL_ACCUM};
    uint32_t s = 99;
    int bad = 0;
    for (int seq = 0; seq < 200; seq++) {
        uint32_t r = rng(&s);
        float clear[4] = {rndf(&s, -1.2f, 1.2f), rndf(&s, -1.2f, 1.2f), rndf(&s, -1.2f, 1.2f), rndf(&s, -1.2f, 1.2f)};
        int sx = (int)(rng(&s) % 8), sy = (int)(rng(&s) % 8);
        bool scissor = r & 1, mask = (r >> 1) & 1;
        GLenum op[6];
        float val[6];
        for (int k = 0; k < 6; k++) {
            op[k] = ops[rng(&s) % 6];
            val[k] = (rng(&s) & 3) == 0 ? rndf(&s, -2.5f, 2.5f) : rndf(&s, -1.0f, 1.0f);
        }
        op[5] = GL_RETURN;
        GLenum err[2];
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            draw_random(c, (uint32_t)seq * 3 + 1);
            G(ClearAccum, clear[0], clear[1], clear[2], clear[3]);
            if (scissor) {
                G(Enable, GL_SCISSOR_TEST);
                G(Scissor, sx, sy, 20, 17);
            }
            G(Clear, GL_ACCUM_BUFFER_BIT);
            for (int k = 0; k < 6; k++) {
                if (k == 3)
                    draw_random(c, (uint32_t)seq * 3 + 2);
                if (k == 5 && mask)
                    G(ColorMask, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
                G(Accum, op[k], val[k]);
            }
            G(ColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            G(Disable, GL_SCISSOR_TEST);
            err[side] = get_error(c);
            if (!c)
                glFinish();
        }
        long d = 0;
        int first = -1;
        for (int i = 0; i < W * H * 4; i++)
            if (b.c->fb.color[i] != b.color[i] && d++ == 0)
                first = i;
        if ((d || err[0] != err[1]) && bad++ < 8)
            fprintf(stderr, "  sequence %d (ops %#x %#x %#x %#x %#x, values %g %g %g %g %g %g): %ld bytes differ"
                    " (first %d: osmesa %u fragsim %u), errors %#x/%#x\n", seq, op[0], op[1], op[2], op[3], op[4],
                    val[0], val[1], val[2], val[3], val[4], val[5], d, first, first >= 0 ? b.color[first] : 0,
                    first >= 0 ? b.c->fb.color[first] : 0, err[0], err[1]);
    }
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

/* Each byte value p once per channel (W * H = 1024 pixels, 4 channels):
 * the colour buffer to GL_ACCUM or GL_LOAD. */
static void draw_ramp(fs_context *c)
{
    static uint8_t img[W * H * 4];
    for (int i = 0; i < W * H * 4; i++)
        img[i] = (uint8_t)(i / 4 % 256);
    G(RasterPos2f, -1.0f, -1.0f);
    G(DrawPixels, W, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
}

/* The value GL_ACCUM and GL_LOAD add for each colour byte, seen
 * directly: with |value| small the sum a stays within 255, and GL_RETURN
 * of +-32767/255 writes a itself. */
TEST(accum_conversion_vs_osmesa)
{
    both b;
    if (!both_open(&b)) {
        both_close(&b);
        SKIP("no OSMesa context with an accumulation buffer");
    }
    uint32_t s = 7;
    int bad = 0;
    for (int t = 0; t < 400; t++) {
        bool big = t >= 200;
        float v = big ? rndf(&s, 0.9f, 2.5f) : rndf(&s, 0.0f, 0.0078f);
        GLenum op = t & 1 ? GL_ACCUM : GL_LOAD;
        bool neg = t & 2;
        for (int side = 0; side < 2; side++) {
            fs_context *c = side ? b.c : NULL;
            draw_ramp(c);
            G(ClearAccum, 0.0f, 0.0f, 0.0f, 0.0f);
            G(Clear, GL_ACCUM_BUFFER_BIT);
            G(Accum, op, neg ? -v : v);
            if (op == GL_ACCUM)
                G(Accum, op, neg ? -v * 0.5f : v * 0.5f);
            G(Accum, GL_RETURN, big ? (neg ? -1.0f : 1.0f) : (neg ? -32767.0f : 32767.0f) / 255.0f);
            if (!c)
                glFinish();
        }
        for (int i = 0; i < W * H * 4; i++)
            if (b.c->fb.color[i] != b.color[i] && bad++ < 8)
                fprintf(stderr, "  %s %.9g: colour %d: osmesa %u fragsim %u\n", op == GL_ACCUM ? "ACCUM" : "LOAD",
                        neg ? -v : v, i / 4 % 256, b.color[i], b.c->fb.color[i]);
    }
    CHECK_EQ_INT(bad, 0);
    both_close(&b);
}

/* A bad op is INVALID_ENUM; without an accumulation buffer (the default
 * configuration, as the conformance contexts) glAccum is
 * INVALID_OPERATION and glClear of the buffer does nothing, as on an
 * OSMesa context made with accumBits 0. */
TEST(errors_and_no_buffer_vs_osmesa)
{
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    fs_context *m = fs_context_create(NULL, 8, 8);
    REQUIRE(m);
    GLenum err[2][3];
    GLint bits[2];
    for (int side = 0; side < 2; side++) {
        fs_context *c = side ? m : NULL;
        G(Accum, GL_TEXTURE_2D, 1.0f);
        err[side][0] = get_error(c);
        G(Accum, GL_LOAD, 1.0f);
        err[side][1] = get_error(c);
        G(Clear, GL_ACCUM_BUFFER_BIT);
        err[side][2] = get_error(c);
        G(GetIntegerv, GL_ACCUM_ALPHA_BITS, &bits[side]);
    }
    for (int k = 0; k < 3; k++)
        CHECK_EQ_INT(err[1][k], err[0][k]);
    CHECK_EQ_INT(bits[1], bits[0]);
    fs_context_destroy(m);
    osm_close(&o);
}

TEST_LIST = {
    TEST_ENTRY(accum_sequences_vs_osmesa),
    TEST_ENTRY(accum_conversion_vs_osmesa),
    TEST_ENTRY(errors_and_no_buffer_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
