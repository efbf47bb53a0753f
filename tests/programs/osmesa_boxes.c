/*
 * An ordinary OSMesa program, written for OSMesa and not for fragsim: it
 * includes only OSMesa's and GL's headers.  It draws lit boxes into an
 * OSMesa buffer, counts each box's visible samples with GL 1.5 occlusion
 * queries (GL_SAMPLES_PASSED), tests hidden boxes with colour and depth
 * writes off, as occlusion culling does, and prints the counts and checksums
 * of the colour and depth buffers.
 *
 * tests/cli_shim.sh builds it against -lOSMesa and against fragsim's shim
 * (build/libfragsimGL.so) and expects the same output.
 * Usage: osmesa_boxes [image.ppm]   (writes the final image when given)
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>

#define W 160
#define H 120
#define NBOX 5

static const float box_pos[NBOX][3] = {
    {-1.2f, -0.4f, -6.0f}, {0.9f, 0.3f, -7.0f}, {0.0f, 0.0f, -4.5f},
    {0.0f, 0.0f, -9.0f}, /* behind box 2: hidden */
    {3.5f, 0.5f, -5.0f}, /* partly outside the window */
};
static const float box_col[NBOX][3] = {
    {0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.9f, 0.9f, 0.2f}, {0.8f, 0.4f, 0.9f},
};

/* An axis-aligned box of half-size s, outward normals, counter-clockwise
 * faces (back faces culled). */
static void box(float s)
{
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    static const float v[6][4][3] = {
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
        {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
        {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
        {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
    };
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        glNormal3fv(n[f]);
        for (int k = 0; k < 4; k++)
            glVertex3f(v[f][k][0] * s, v[f][k][1] * s, v[f][k][2] * s);
    }
    glEnd();
}

static unsigned long long fnv1a(const unsigned char *p, size_t n)
{
    unsigned long long h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

static void place(int i, float angle)
{
    glLoadIdentity();
    glTranslatef(box_pos[i][0], box_pos[i][1], box_pos[i][2]);
    glRotatef(angle + 17.0f * (float)i, 0.3f, 1.0f, 0.2f);
}

static void frame(GLuint *queries, float angle, const char *label)
{
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    for (int i = 0; i < NBOX; i++) {
        glColor3fv(box_col[i]);
        place(i, angle);
        glBeginQuery(GL_SAMPLES_PASSED, queries[i]);
        box(i == 2 ? 0.9f : 0.7f);
        glEndQuery(GL_SAMPLES_PASSED);
    }
    /* Occlusion culling's test: the boxes' bounding volumes again, scaled
     * up, without writing colour or depth. */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    for (int i = 0; i < NBOX; i++) {
        place(i, angle);
        glBeginQuery(GL_SAMPLES_PASSED, queries[NBOX + i]);
        box(0.8f);
        glEndQuery(GL_SAMPLES_PASSED);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glFinish();
    for (int i = 0; i < 2 * NBOX; i++) {
        GLuint avail = 0, samples = 0;
        glGetQueryObjectuiv(queries[i], GL_QUERY_RESULT_AVAILABLE, &avail);
        glGetQueryObjectuiv(queries[i], GL_QUERY_RESULT, &samples);
        printf("%s %s %d: samples %u available %u\n", label, i < NBOX ? "box" : "bound", i % NBOX,
               samples, avail);
    }
}

int main(int argc, char **argv)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = calloc(W * H, 4);
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "cannot create an OSMesa context\n");
        return 1;
    }
    /* To stderr: differs between implementations by design. */
    fprintf(stderr, "renderer: %s\n", (const char *)glGetString(GL_RENDERER));

    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1.5, 20.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    const GLfloat light_pos[4] = {2.0f, 3.0f, 4.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);

    GLuint queries[2 * NBOX];
    glGenQueries(2 * NBOX, queries);
    frame(queries, 10.0f, "frame0");
    frame(queries, 40.0f, "frame1");
    glDeleteQueries(2 * NBOX, queries);

    GLint w, h, format, bpv;
    void *color, *depth;
    if (!OSMesaGetColorBuffer(ctx, &w, &h, &format, &color) || color != buf) {
        fprintf(stderr, "OSMesaGetColorBuffer failed\n");
        return 1;
    }
    printf("color %dx%d format 0x%x checksum %016llx\n", w, h, format, fnv1a(buf, (size_t)W * H * 4));
    if (!OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &depth)) {
        fprintf(stderr, "OSMesaGetDepthBuffer failed\n");
        return 1;
    }
    printf("depth %dx%d %d bytes checksum %016llx\n", w, h, bpv, fnv1a(depth, (size_t)w * h * bpv));
    printf("error 0x%x\n", glGetError());

    if (argc > 1) {
        /* PPM, top row first; OSMesa's rows are bottom-up (OSMESA_Y_UP). */
        FILE *f = fopen(argv[1], "wb");
        if (!f)
            return 1;
        fprintf(f, "P6\n%d %d\n255\n", W, H);
        for (int y = H - 1; y >= 0; y--)
            for (int x = 0; x < W; x++)
                fwrite(buf + ((size_t)y * W + x) * 4, 1, 3, f);
        fclose(f);
    }
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
