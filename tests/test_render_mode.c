/*
 * Selection and feedback (GL 1.5 spec 5.2, 5.3; pipeline/render_mode.c)
 * against OSMesa: the same calls on both, every glRenderMode return value,
 * every GL error and every word of the selection and feedback buffers
 * compared exactly (floats bit for bit).  Random scenes: primitives of
 * every type partly outside the view volume, random projections, depth
 * ranges, culling, shading, buffer sizes that overflow, name-stack
 * commands including the erroneous ones.  The dissertation's view-frustum
 * culling (issue 21) counts hits and reads their depths: they must be
 * llvmpipe's exactly.
 */
#include <math.h>
#include "check.h"
#include "osmesa_util.h"

#define W 64
#define H 48

/* What one run records: return values, errors, buffer words. */
typedef struct rec { uint32_t v[20000]; int n; } rec;

static void put(rec *r, uint32_t x)
{
    if (r->n < (int)(sizeof r->v / sizeof r->v[0]))
        r->v[r->n++] = x;
}

static void put_err(fs_context *c, rec *r)
{
    put(r, c ? fsglGetError(c) : glGetError());
}

static uint32_t rnd(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static float frand(uint32_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(rnd(s) % 100000u) / 100000.0f;
}

static void random_projection(fs_context *c, uint32_t *s)
{
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    if (rnd(s) & 1)
        G(Frustum, -1.0, 1.0, -0.75, 0.75, 1.0, (double)frand(s, 3.0f, 20.0f));
    else
        G(Ortho, -1.0, 1.0, -1.0, 1.0, (double)frand(s, -3.0f, -0.5f), (double)frand(s, 0.5f, 3.0f));
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    G(Translatef, frand(s, -0.3f, 0.3f), frand(s, -0.3f, 0.3f), frand(s, -4.0f, -1.5f));
    G(Rotatef, frand(s, 0.0f, 360.0f), frand(s, -1.0f, 1.0f), frand(s, -1.0f, 1.0f), 1.0f);
    if (rnd(s) % 3 == 0)
        G(DepthRange, (double)frand(s, 0.0f, 0.5f), (double)frand(s, 0.5f, 1.0f));
    else
        G(DepthRange, 0.0, 1.0);
}

static const GLenum prim_modes[] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                                     GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};

/* A primitive of a random type, its vertices up to 1.6 units from the
 * origin (so some leave the view volume), with colours and texture
 * coordinates. */
static void random_primitive(fs_context *c, uint32_t *s, bool allow_flat)
{
    GLenum mode = prim_modes[rnd(s) % 10];
    int n = 1 + (int)(rnd(s) % 9);
    if (rnd(s) % 4 == 0) {
        G(Enable, GL_CULL_FACE);
        G(CullFace, rnd(s) & 1 ? GL_BACK : GL_FRONT);
    } else {
        G(Disable, GL_CULL_FACE);
    }
    G(ShadeModel, (rnd(s) & 1) && allow_flat ? GL_FLAT : GL_SMOOTH);
    G(Begin, mode);
    float cx = frand(s, -1.0f, 1.0f), cy = frand(s, -1.0f, 1.0f), cz = frand(s, -1.0f, 1.0f);
    for (int i = 0; i < n; i++) {
        G(Color4f, frand(s, 0, 1), frand(s, 0, 1), frand(s, 0, 1), frand(s, 0, 1));
        G(TexCoord4f, frand(s, -2, 2), frand(s, -2, 2), frand(s, -2, 2), frand(s, 0.5f, 2));
        G(Vertex3f, cx + frand(s, -0.6f, 0.6f), cy + frand(s, -0.6f, 0.6f), cz + frand(s, -0.6f, 0.6f));
    }
    G0(End);
}

/* A name-stack command, sometimes one GL refuses (5.2). */
static void random_name_command(fs_context *c, uint32_t *s, rec *r)
{
    switch (rnd(s) % 8) {
    case 0: G0(InitNames); break;
    case 1: case 2: case 3: G(PushName, rnd(s) % 1000u); break;
    case 4: case 5: G0(PopName); break;
    default: G(LoadName, rnd(s) % 1000u); break;
    }
    put_err(c, r);
}

static void put_int(fs_context *c, rec *r, GLenum pname)
{
    GLint v = -12345;
    G(GetIntegerv, pname, &v);
    put(r, (uint32_t)v);
}

static void select_scene(fs_context *c, uint32_t seed, rec *r)
{
    static GLuint buf[512];
    uint32_t s = seed;
    GLsizei size = rnd(&s) % 4 == 0 ? (GLsizei)(1 + rnd(&s) % 40) : 512;
    memset(buf, 0xAB, sizeof buf);
    G(SelectBuffer, size, buf);
    put((rec *)r, (uint32_t)(c ? fsglRenderMode(c, GL_SELECT) : glRenderMode(GL_SELECT)));
    put_err(c, r);
    for (int pass = 0; pass < 2; pass++) {
        G0(InitNames);
        random_projection(c, &s);
        int k = 5 + (int)(rnd(&s) % 30);
        for (int i = 0; i < k; i++) {
            if (rnd(&s) % 3 == 0)
                random_name_command(c, &s, r);
            random_primitive(c, &s, true);
        }
        if (rnd(&s) % 5 == 0)
            for (int i = 0; i < 70; i++)
                G(PushName, (GLuint)i); /* past GL_MAX_NAME_STACK_DEPTH */
        put_err(c, r);
        put_int(c, r, GL_NAME_STACK_DEPTH);
        put_int(c, r, GL_RENDER_MODE);
        /* the second pass is entered from selection itself */
        put((rec *)r, (uint32_t)GR(RenderMode, pass ? GL_RENDER : GL_SELECT));
        put_err(c, r);
        put_int(c, r, GL_NAME_STACK_DEPTH);
        for (GLsizei i = 0; i < 512; i++)
            put(r, buf[i]);
        memset(buf, 0xAB, sizeof buf);
    }
}

static void feedback_scene(fs_context *c, uint32_t seed, rec *r)
{
    /* Not GL_3D_COLOR: OSMesa writes two words of what looks like an
     * address there instead of the colour (0x7f20, 0xfec9a2b0, different
     * from run to run), nothing to compare with. */
    static const GLenum types[] = {GL_2D, GL_3D, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
    static GLfloat buf[4096];
    uint32_t s = seed;
    GLenum type = types[rnd(&s) % 4];
    GLsizei size = rnd(&s) % 4 == 0 ? (GLsizei)(1 + rnd(&s) % 200) : 4096;
    memset(buf, 0xAB, sizeof buf);
    G(FeedbackBuffer, size, type, buf);
    put_err(c, r);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_FEEDBACK));
    random_projection(c, &s);
    int k = 3 + (int)(rnd(&s) % 12);
    for (int i = 0; i < k; i++) {
        if (rnd(&s) % 3 == 0)
            G(PassThrough, frand(&s, -100, 100));
        random_primitive(c, &s, false);
    }
    put_int(c, r, GL_FEEDBACK_BUFFER_SIZE);
    put_int(c, r, GL_FEEDBACK_BUFFER_TYPE);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_RENDER));
    put_err(c, r);
    for (GLsizei i = 0; i < 4096; i++) {
        uint32_t u;
        memcpy(&u, &buf[i], 4);
        put(r, u);
    }
}

static float as_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

typedef void (*scene_fn)(fs_context *c, uint32_t seed, rec *r);

/* Runs scene on OSMesa and on the model; returns the index of the first
 * recorded value that differs, or -1. */
static int compare_scene(scene_fn scene, uint32_t seed, rec *ref, rec *mine)
{
    osm o;
    if (!osm_open(&o, W, H)) {
        osm_close(&o);
        return -2;
    }
    ref->n = mine->n = 0;
    scene(NULL, seed, ref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, W, H);
    if (!c)
        return -2;
    scene(c, seed, mine);
    fs_context_destroy(c);
    if (ref->n != mine->n)
        return ref->n < mine->n ? ref->n : mine->n;
    for (int i = 0; i < ref->n; i++)
        if (ref->v[i] != mine->v[i])
            return i;
    return -1;
}

static uint32_t seeds(void)
{
    const char *e = getenv("FS_TEST_SEEDS");
    return e ? (uint32_t)atoi(e) : 60;
}

static void random_scenes(check_state *check_st_, scene_fn scene, uint32_t seeds)
{
    static rec ref, mine;
    int bad = 0;
    for (uint32_t seed = 1; seed <= seeds; seed++) {
        int at = compare_scene(scene, seed * 2654435761u, &ref, &mine);
        if (at == -2)
            SKIP("no OSMesa context");
        if (at >= 0 && bad++ < 3) {
            CHECK_FAIL_("seed %u: value %d differs: OSMesa %#x, model %#x", seed, at, ref.v[at], mine.v[at]);
            if (getenv("FS_TEST_VERBOSE"))
                for (int i = at - 14 < 0 ? 0 : at - 14; i < at + 14 && i < ref.n; i++)
                    fprintf(stderr, "    [%d] %#10x %.9g | %#10x %.9g\n", i, ref.v[i], (double)as_float(ref.v[i]),
                            mine.v[i], (double)as_float(mine.v[i]));
        }
    }
    CHECK_EQ_INT(bad, 0);
}

TEST(select_random_scenes_vs_osmesa) { random_scenes(check_st_, select_scene, seeds()); }

TEST(feedback_random_scenes_vs_osmesa) { random_scenes(check_st_, feedback_scene, seeds()); }

/* The errors and return values of the commands themselves (5.2, 5.3). */
static void errors_scene(fs_context *c, uint32_t seed, rec *r)
{
    (void)seed;
    static GLuint sb[8];
    static GLfloat fb[8];
    G(PushName, 1u); put_err(c, r);   /* outside GL_SELECT: ignored */
    G0(PopName); put_err(c, r);
    G(LoadName, 1u); put_err(c, r);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_SELECT)); put_err(c, r); /* no buffer */
    put_int(c, r, GL_RENDER_MODE);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_FEEDBACK)); put_err(c, r);
    put_int(c, r, GL_RENDER_MODE);
    put((rec *)r, (uint32_t)GR(RenderMode, 0x1234)); put_err(c, r);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_RENDER)); put_err(c, r);
    G(SelectBuffer, -1, sb); put_err(c, r);
    G(SelectBuffer, 0, sb); put_err(c, r);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_SELECT)); put_err(c, r); /* size 0 */
    put((rec *)r, (uint32_t)GR(RenderMode, GL_RENDER)); put_err(c, r);
    G(FeedbackBuffer, -1, 0x1234, fb); put_err(c, r);
    G(FeedbackBuffer, 3, 0x1234, fb); put_err(c, r);
    G(FeedbackBuffer, 8, GL_2D, NULL); put_err(c, r);
    G(FeedbackBuffer, 8, GL_3D, fb); put_err(c, r);
    G(SelectBuffer, 8, sb); put_err(c, r);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_SELECT)); put_err(c, r);
    G(SelectBuffer, 8, sb); put_err(c, r);          /* in GL_SELECT */
    G0(PopName); put_err(c, r);                     /* empty stack */
    G(LoadName, 3u); put_err(c, r);
    G(FeedbackBuffer, 8, GL_2D, fb); put_err(c, r); /* allowed in GL_SELECT */
    put((rec *)r, (uint32_t)GR(RenderMode, GL_FEEDBACK)); put_err(c, r);
    G(FeedbackBuffer, 8, GL_2D, fb); put_err(c, r); /* in GL_FEEDBACK */
    put_int(c, r, GL_RENDER_MODE);
    G(Begin, GL_POINTS);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_RENDER)); put_err(c, r); /* inside Begin/End */
    G0(End);
    put((rec *)r, (uint32_t)GR(RenderMode, GL_RENDER)); put_err(c, r);
    put_int(c, r, GL_RENDER_MODE);
    put_int(c, r, GL_SELECTION_BUFFER_SIZE);
    put_int(c, r, GL_MAX_NAME_STACK_DEPTH);
    /* glClear makes no pixels outside GL_RENDER */
    G(ClearColor, 1.0f, 0.0f, 0.0f, 1.0f);
    GR(RenderMode, GL_SELECT);
    G(Clear, GL_COLOR_BUFFER_BIT);
    GR(RenderMode, GL_RENDER);
    GLubyte px[4] = {9, 9, 9, 9};
    G(ReadPixels, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    put(r, px[0]);
    put_err(c, r);
}

TEST(errors_and_returns_vs_osmesa)
{
    static rec ref, mine;
    int at = compare_scene(errors_scene, 0, &ref, &mine);
    if (at == -2)
        SKIP("no OSMesa context");
    if (at >= 0)
        CHECK_FAIL_("value %d differs: OSMesa %#x, model %#x", at, ref.v[at], mine.v[at]);
}

TEST_LIST = {TEST_ENTRY(select_random_scenes_vs_osmesa), TEST_ENTRY(feedback_random_scenes_vs_osmesa),
             TEST_ENTRY(errors_and_returns_vs_osmesa), TEST_END};

int main(int argc, char **argv)
{
    setenv("LP_NUM_THREADS", "1", 0);
    return check_main(argc, argv, test_list);
}
