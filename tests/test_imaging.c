/*
 * The imaging subset (ARB_imaging, GL 1.5 spec 3.6.2-3.6.3, 6.1.7-6.1.9;
 * driver/gl_commands_imaging.def) against OSMesa (llvmpipe), which does not
 * list GL_ARB_imaging: every entry point with two sets of arguments, then
 * while a display list is compiled, then between glBegin and glEnd, raises
 * the same error as on OSMesa (GL_INVALID_OPERATION, at once), writes none
 * of its outputs and changes nothing drawn; the subset's enables are
 * GL_INVALID_ENUM on both.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"

typedef struct rec { GLenum err[512]; const char *what[512]; int n; int outputs_written; } rec;

static unsigned char in_bytes[4096];
static GLint in_ints[16];
static GLfloat in_floats[16];
static unsigned char out_bytes[3][4096];
static GLint out_ints[16];
static GLfloat out_floats[16];

static void fill_outputs(void)
{
    memset(out_bytes, 0xab, sizeof out_bytes);
    memset(out_ints, 0xab, sizeof out_ints);
    memset(out_floats, 0xab, sizeof out_floats);
}

static int outputs_written(void)
{
    int n = 0;
    for (size_t i = 0; i < sizeof out_bytes; i++)
        n += ((unsigned char *)out_bytes)[i] != 0xab;
    for (size_t i = 0; i < sizeof out_ints; i++)
        n += ((unsigned char *)out_ints)[i] != 0xab;
    for (size_t i = 0; i < sizeof out_floats; i++)
        n += ((unsigned char *)out_floats)[i] != 0xab;
    return n;
}

/* Arguments of each kind the subset's commands take; every enum is the
 * same value (a target, a format or a parameter name alike). */
static GLenum arg_enum;
static int out_next;
#define IMG_V_E arg_enum
#define IMG_V_SZ 4
#define IMG_V_I 0
#define IMG_V_B GL_FALSE
#define IMG_V_F 1.0f
#define IMG_V_BLOB ((const GLvoid *)in_bytes)
#define IMG_V_AI in_ints
#define IMG_V_AF in_floats
#define IMG_V_OV ((GLvoid *)out_bytes[out_next++ % 3])
#define IMG_V_OI out_ints
#define IMG_V_OF out_floats
#define IMG_DECL(k, kind, name, cnt) FS_CT_##kind a##k = IMG_V_##kind;
#define FS_CMD_IMAGING(name, nargs, ...)                                       \
    {                                                                          \
        GA(IMG_DECL, name, nargs, __VA_ARGS__);                                \
        if (r->n < 512) {                                                      \
            r->what[r->n] = "gl" #name;                                        \
            r->err[r->n++] = c ? fsglGetError(c) : glGetError();               \
        }                                                                      \
    }

static void all_commands(fs_context *c, rec *r)
{
    out_next = 0;
#include "../driver/gl_commands_imaging.def"
}

static GLenum error_of(fs_context *c) { return c ? fsglGetError(c) : glGetError(); }

static void sequence(fs_context *c, rec *r)
{
    static const GLenum enums[] = {GL_RGBA, GL_HISTOGRAM, GL_COLOR_TABLE, GL_CONVOLUTION_2D, GL_MINMAX};
    static const GLenum caps[] = {GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE,
                                  GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D, GL_HISTOGRAM, GL_MINMAX};
    r->n = 0;
    fill_outputs();
    for (int i = 0; i < 2; i++) {
        arg_enum = enums[i];
        all_commands(c, r);
    }
    /* Executed at once while a list is compiled: the error is raised. */
    arg_enum = GL_COLOR_TABLE;
    G(NewList, 1, GL_COMPILE);
    all_commands(c, r);
    G0(EndList);
    G(CallList, 1);
    r->what[r->n] = "glCallList";
    r->err[r->n++] = error_of(c);
    /* Between glBegin and glEnd: GL_INVALID_OPERATION, seen after glEnd. */
    G(Begin, GL_TRIANGLES);
    G(Histogram, GL_HISTOGRAM, 16, GL_RGBA, GL_FALSE);
    G0(End);
    r->what[r->n] = "glHistogram in glBegin/glEnd";
    r->err[r->n++] = error_of(c);
    for (int i = 0; i < 8; i++) {
        G(Enable, caps[i]);
        r->what[r->n] = "glEnable";
        r->err[r->n++] = error_of(c);
        r->what[r->n] = "glIsEnabled";
        r->err[r->n++] = GR(IsEnabled, caps[i]);
        r->what[r->n] = "glIsEnabled's error";
        r->err[r->n++] = error_of(c);
    }
    for (int i = 2; i < 5; i++) {
        GLint v = -7;
        G(GetIntegerv, enums[i], &v);
        r->what[r->n] = "glGetIntegerv";
        r->err[r->n++] = error_of(c);
        r->what[r->n] = "its value";
        r->err[r->n++] = (GLenum)v;
    }
    r->outputs_written = outputs_written();
}

TEST(imaging_subset_vs_osmesa)
{
    static rec ref, mine;
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    fs_context *c = NULL;
    sequence(c, &ref);
    c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    sequence(c, &mine);
    CHECK_EQ_INT(mine.n, ref.n);
    for (int i = 0; i < mine.n && i < ref.n; i++)
        if (mine.err[i] != ref.err[i])
            CHECK_FAIL_("%d, %s: 0x%x (model) != 0x%x (OSMesa)", i, ref.what[i], mine.err[i], ref.err[i]);
    CHECK_EQ_INT(ref.err[0], GL_INVALID_OPERATION);
    CHECK_EQ_INT(mine.outputs_written, 0);
    CHECK_EQ_INT(ref.outputs_written, 0);
    /* Nothing unsupported was counted: each command has its executor. */
    CHECK_EQ_UINT(c->stats.unsupported_calls, 0);
    fs_context_destroy(c);
    osm_close(&o);
}

TEST_LIST = {
    TEST_ENTRY(imaging_subset_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
