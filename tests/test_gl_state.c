/*
 * GL state that real programs query and set (issue 17), each answered by
 * fragsim as by OSMesa (llvmpipe) through the same calls: the window's
 * buffers (GL 1.5 spec table 6.34) and glDrawBuffer/glReadBuffer (4.2.1,
 * 4.3.2), the pixel-store parameters (3.6.1), the client-state enables of
 * the GL 1.4 arrays (2.8), and the bound on names every glGen* shares.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/replay.h"
#include "../driver/trace.h"

/* A sequence of calls run on OSMesa (c NULL) or the model, recording the
 * values it reads (errors and query results) in rec. */
typedef struct rec { long v[4096]; int n; } rec;
static void put(rec *r, long v)
{
    if (r->n < (int)(sizeof r->v / sizeof r->v[0]))
        r->v[r->n++] = v;
}
typedef void (*seq_fn)(fs_context *c, rec *r);

/* Runs seq on a fresh OSMesa context and on a fresh model context and
 * compares what both read; prints the first difference. */
static int same_on_both(seq_fn seq, const char *name)
{
    static rec a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    osm o;
    if (!osm_open(&o, 16, 16)) {
        osm_close(&o);
        return -1;
    }
    seq(NULL, &a);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 16, 16);
    if (!c)
        return -1;
    seq(c, &b);
    fs_context_destroy(c);
    if (a.n != b.n) {
        printf("  %s: %d values on OSMesa, %d on the model\n", name, a.n, b.n);
        return 1;
    }
    for (int i = 0; i < a.n; i++)
        if (a.v[i] != b.v[i]) {
            printf("  %s: value %d: OSMesa %#lx, model %#lx\n", name, i, a.v[i], b.v[i]);
            return 1;
        }
    printf("  %s: %d values equal\n", name, a.n);
    return 0;
}

#define GR0(name) (c ? fsgl##name(c) : gl##name())
#define ERR() put(r, (long)GR0(GetError))

/* Every way to ask: integer, boolean and float. */
static void query(fs_context *c, rec *r, GLenum pname)
{
    GLint i = -77;
    GLboolean b = 77;
    GLfloat f = -77;
    G(GetIntegerv, pname, &i);
    ERR();
    G(GetBooleanv, pname, &b);
    ERR();
    G(GetFloatv, pname, &f);
    ERR();
    put(r, i);
    put(r, b);
    put(r, (long)(f * 16));
}

/* ---- the window's buffers ---- */

static void seq_framebuffer(fs_context *c, rec *r)
{
    static const GLenum names[] = {GL_DOUBLEBUFFER, GL_STEREO, GL_AUX_BUFFERS, GL_RGBA_MODE, GL_INDEX_MODE,
                                   GL_INDEX_BITS, GL_RED_BITS, GL_GREEN_BITS, GL_BLUE_BITS, GL_ALPHA_BITS,
                                   GL_DEPTH_BITS, GL_STENCIL_BITS, GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS,
                                   GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS, GL_DRAW_BUFFER, GL_READ_BUFFER};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        query(c, r, names[k]);
}

TEST(framebuffer_queries_vs_osmesa)
{
    CHECK_EQ_INT(same_on_both(seq_framebuffer, "framebuffer"), 0);
}

/* glDrawBuffer and glReadBuffer of every name (OSMesa's single-buffered
 * context takes the back buffer too), each followed by its error and the
 * query; also between Begin and End. */
static void seq_buffers(fs_context *c, rec *r)
{
    static const GLenum bufs[] = {GL_NONE, GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT,
                                  GL_BACK, GL_LEFT, GL_RIGHT, GL_FRONT_AND_BACK, GL_AUX0, GL_AUX1, GL_AUX2,
                                  GL_AUX3, GL_AUX3 + 1, 0x3ff, GL_COLOR_ATTACHMENT0, 0x8cff, 0x8d00,
                                  GL_TEXTURE_2D, GL_COLOR, GL_DEPTH};
    for (size_t k = 0; k < sizeof bufs / sizeof bufs[0]; k++) {
        G(DrawBuffer, GL_FRONT);
        G(DrawBuffer, bufs[k]);
        ERR();
        query(c, r, GL_DRAW_BUFFER);
        G(ReadBuffer, GL_FRONT);
        G(ReadBuffer, bufs[k]);
        ERR();
        query(c, r, GL_READ_BUFFER);
    }
    /* With no read buffer, colour cannot be read; depth and stencil can. */
    GLubyte px[4];
    GLuint z;
    G(ReadBuffer, GL_NONE);
    G(ReadPixels, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    ERR();
    G(ReadPixels, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
    ERR();
    G(ReadPixels, 0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, px);
    ERR();
    G(ReadBuffer, GL_BACK);
    G(ReadPixels, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    ERR();
    G(Begin, GL_TRIANGLES);
    G(DrawBuffer, GL_BACK);
    G(ReadBuffer, GL_BACK);
    G0(End);
    ERR();
    query(c, r, GL_DRAW_BUFFER);
}

TEST(draw_and_read_buffer_vs_osmesa)
{
    CHECK_EQ_INT(same_on_both(seq_buffers, "buffers"), 0);
}

/* GL_NONE as the draw buffer writes no colour, neither by glClear nor by
 * drawing, while depth is still written (4.2.1); GL_BACK writes again. */
static void scene_draw_none(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.2f, 0.3f, 0.4f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    G(Enable, GL_DEPTH_TEST);
    G(DrawBuffer, GL_NONE);
    G(ClearColor, 1, 0, 0, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(Color3f, 1, 1, 0);
    G(Begin, GL_TRIANGLES);
    G(Vertex3f, -1, -1, -0.5f);
    G(Vertex3f, 0.8f, -1, -0.5f);
    G(Vertex3f, -1, 0.8f, -0.5f);
    G0(End);
    G(Enable, GL_BLEND);
    G(BlendFunc, GL_ONE, GL_ONE);
    G(Begin, GL_TRIANGLES);
    G(Vertex3f, 1, 1, -0.9f);
    G(Vertex3f, -0.5f, 1, -0.9f);
    G(Vertex3f, 1, -0.5f, -0.9f);
    G0(End);
    G(Disable, GL_BLEND);
    G(DrawBuffer, GL_BACK);
    G(Color3f, 0, 1, 1);
    G(Begin, GL_QUADS); /* hidden where the first triangle wrote depth */
    G(Vertex3f, -1, -1, 0);
    G(Vertex3f, 1, -1, 0);
    G(Vertex3f, 1, 1, 0);
    G(Vertex3f, -1, 1, 0);
    G0(End);
}

TEST(draw_buffer_none_writes_no_colour_vs_osmesa)
{
    osm_pair p;
    REQUIRE(osm_pair_render(&p, 32, 32, NULL, scene_draw_none, NULL));
    printf("  draw_none 32x32: %ld pixels differ, max %d\n", p.d.differ, p.d.maxd);
    CHECK_EQ_INT(p.d.differ, 0);
    CHECK_EQ_INT(fsglGetError(p.c), GL_NO_ERROR);
    osm_pair_close(&p);
}

/* A double-buffered context (a captured program that swaps) starts with
 * the back buffer for drawing and reading (4.2.1, 4.3.2). */
TEST(double_buffered_context_answers)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    GLboolean b = 7;
    GLint i = 0;
    fsglGetBooleanv(c, GL_DOUBLEBUFFER, &b);
    CHECK_EQ_INT(b, GL_FALSE); /* OSMesa's default */
    fs_context_set_double_buffered(c, true);
    fsglGetBooleanv(c, GL_DOUBLEBUFFER, &b);
    CHECK_EQ_INT(b, GL_TRUE);
    fsglGetIntegerv(c, GL_DRAW_BUFFER, &i);
    CHECK_EQ_INT(i, GL_BACK);
    fsglGetIntegerv(c, GL_READ_BUFFER, &i);
    CHECK_EQ_INT(i, GL_BACK);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fs_context_destroy(c);
}

/* Replay marks a trace with swap calls double-buffered, one without
 * single-buffered. */
static int write_trace(const char *path, bool swap)
{
    char e[256];
    fs_trace_writer *w = fs_trace_create(path, e, sizeof e);
    if (!w)
        return -1;
    static const char *const an[4] = {"x", "y", "width", "height"};
    fs_tval a[4];
    memset(a, 0, sizeof a);
    for (int k = 0; k < 4; k++) {
        a[k].type = FS_TV_SINT;
        a[k].i = k < 2 ? 0 : 8;
    }
    fs_tcall call;
    memset(&call, 0, sizeof call);
    call.name = "glViewport";
    call.nargs = 4;
    call.arg_names = an;
    call.args = a;
    fs_trace_write(w, &call);
    memset(&call, 0, sizeof call);
    call.name = swap ? "glXSwapBuffers" : "glFinish";
    fs_trace_write(w, &call);
    return fs_trace_finish(w);
}

TEST(replay_swapping_trace_is_double_buffered)
{
    for (int swap = 0; swap < 2; swap++) {
        char path[256], e[512];
        snprintf(path, sizeof path, "/tmp/fragsim_test_gl_state_%d_%d.trace", (int)getpid(), swap);
        REQUIRE(write_trace(path, swap) == 0);
        fs_replayer *r = fs_replay_open(path, NULL, e, sizeof e);
        REQUIRE(r);
        CHECK_EQ_INT(fs_replay_info_get(r)->double_buffered, swap);
        fs_replay_close(r);
        unlink(path);
    }
}

/* ---- pixel storage ---- */

static void seq_pixel_store(fs_context *c, rec *r)
{
    static const GLenum p[] = {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH,
                               GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
                               GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT, GL_PACK_SWAP_BYTES,
                               GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_ROWS,
                               GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT};
    static const GLint iv[] = {-1, 3, 0, 8, 2, 1, 7, 4};
    static const GLfloat fv[] = {NAN, 2.5f, 0.4f, -0.4f, -0.6f, 1.5f, 0.49999997f, 3e9f, -3e9f, 16.0f, 1.0f, 4.0f};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) {
        query(c, r, p[k]); /* the initial value */
        for (size_t j = 0; j < sizeof iv / sizeof iv[0]; j++) {
            G(PixelStorei, p[k], iv[j]);
            ERR();
            query(c, r, p[k]);
        }
        for (size_t j = 0; j < sizeof fv / sizeof fv[0]; j++) {
            G(PixelStoref, p[k], fv[j]);
            ERR();
            query(c, r, p[k]);
        }
    }
    G(PixelStorei, 0x1234, 1);
    ERR();
    G(PixelStoref, GL_TEXTURE_2D, 1);
    ERR();
}

TEST(pixel_store_vs_osmesa)
{
    CHECK_EQ_INT(same_on_both(seq_pixel_store, "pixel store"), 0);
}

/* ---- client-state enables ---- */

static void seq_client_state(fs_context *c, rec *r)
{
    static const GLenum a[] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY,
                               GL_EDGE_FLAG_ARRAY, GL_INDEX_ARRAY, GL_FOG_COORDINATE_ARRAY,
                               GL_SECONDARY_COLOR_ARRAY, 0x1234};
    /* via: 0 glEnableClientState, 1 glEnable, which Mesa's compatibility
     * profile also takes for the arrays (measured on OSMesa). */
    for (int via = 0; via < 2; via++)
    for (int on = 1; on >= 0; on--)
        for (size_t k = 0; k < sizeof a / sizeof a[0]; k++) {
            if (on && via)
                G(Enable, a[k]);
            else if (via)
                G(Disable, a[k]);
            else if (on)
                G(EnableClientState, a[k]);
            else
                G(DisableClientState, a[k]);
            ERR();
            put(r, GR(IsEnabled, a[k]));
            ERR();
            query(c, r, a[k]);
        }
}

TEST(client_state_arrays_vs_osmesa)
{
    CHECK_EQ_INT(same_on_both(seq_client_state, "client state"), 0);
}

/* ---- names ---- */

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec / 1e9;
}

/* Every glGen* of 2^31 - 1 names is GL_OUT_OF_MEMORY at once (FS_MAX_NAMES
 * held at most) and generates nothing; a negative count is
 * GL_INVALID_VALUE. */
TEST(gen_names_huge_count_is_out_of_memory)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    GLuint ids[4] = {0};
    double t0 = seconds();
    fsglGenTextures(c, 2147483647, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    fsglGenQueries(c, 2147483647, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    fsglGenQueriesARB(c, 2147483647, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    CHECK_EQ_UINT(fsglGenLists(c, 2147483647), 0);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    double dt = seconds() - t0;
    printf("  four glGen* of 2^31 - 1 names: %.3f ms\n", dt * 1e3);
    CHECK(dt < 1.0);
    fsglGenTextures(c, -1, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglGenQueries(c, -1, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    fsglGenQueriesARB(c, -1, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_INVALID_VALUE);
    /* Nothing was generated: the first names are still free. */
    fsglGenTextures(c, 2, ids);
    CHECK_EQ_UINT(ids[0], 1);
    CHECK_EQ_UINT(ids[1], 2);
    fsglGenQueries(c, 1, ids);
    CHECK_EQ_UINT(ids[0], 1);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    /* The allowance is shared by nothing but counted per kind: queries
     * up to 2^20 held, then no more. */
    GLuint *many = malloc(sizeof(GLuint) << 20);
    REQUIRE(many);
    fsglGenQueries(c, (1 << 20) - 1, many);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    fsglGenQueries(c, 1, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    fsglDeleteQueries(c, 1, many);
    fsglGenQueriesARB(c, 1, ids);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    free(many);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(framebuffer_queries_vs_osmesa),
    TEST_ENTRY(draw_and_read_buffer_vs_osmesa),
    TEST_ENTRY(draw_buffer_none_writes_no_colour_vs_osmesa),
    TEST_ENTRY(double_buffered_context_answers),
    TEST_ENTRY(replay_swapping_trace_is_double_buffered),
    TEST_ENTRY(pixel_store_vs_osmesa),
    TEST_ENTRY(client_state_arrays_vs_osmesa),
    TEST_ENTRY(gen_names_huge_count_is_out_of_memory),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
