/*
 * The OSMesa context API as a program sees it, written for OSMesa (only
 * OSMesa's and GL's headers): buffer formats, OSMESA_ROW_LENGTH and
 * OSMESA_Y_UP, when the caller's buffer receives the pixels, depth buffer
 * values, OSMesaGetProcAddress, calls without a current context, switching
 * contexts.  tests/cli_shim.sh runs it on OSMesa and on fragsim's shim and
 * expects the same output.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 8
#define H 6

static void px(const char *what, const unsigned char *p, int n)
{
    printf("%s:", what);
    for (int i = 0; i < n; i++)
        printf(" %u", p[i]);
    printf("\n");
}

/* A quad over the bottom half of the window (GL's y up). */
static void bottom_half(float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 0);
    glVertex2f(-1, 0);
    glEnd();
}

int main(void)
{
    /* No current context: calls do nothing. */
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    printf("no context: current %d error 0x%x\n", OSMesaGetCurrentContext() != NULL, glGetError());

    /* RGBA, default Y_UP: row 0 of the buffer is the bottom row. */
    unsigned char *a = calloc(W * H, 4);
    OSMesaContext ca = OSMesaCreateContext(OSMESA_RGBA, NULL);
    printf("make current: %d\n", OSMesaMakeCurrent(ca, a, GL_UNSIGNED_BYTE, W, H));
    printf("current is ca: %d\n", OSMesaGetCurrentContext() == ca);
    GLint v;
    OSMesaGetIntegerv(OSMESA_WIDTH, &v);
    printf("width %d", v);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
    printf(" height %d", v);
    OSMesaGetIntegerv(OSMESA_Y_UP, &v);
    printf(" y_up %d\n", v);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    bottom_half(1, 0, 0);
    glFlush();
    px("rgba y_up bottom row", a, 4);
    px("rgba y_up top row", a + (H - 1) * W * 4, 4);
    unsigned char rp[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rp);
    px("glReadPixels(0,0)", rp, 4);

    /* Through OSMesaGetProcAddress. */
    void (*clear_color)(GLclampf, GLclampf, GLclampf, GLclampf) =
        (void (*)(GLclampf, GLclampf, GLclampf, GLclampf))OSMesaGetProcAddress("glClearColor");
    printf("procs: %d %d %d\n", clear_color != NULL, OSMesaGetProcAddress("glGenQueries") != NULL,
           OSMesaGetProcAddress("OSMesaGetDepthBuffer") != NULL);
    clear_color(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    px("after glFinish", a, 4);

    /* OSMESA_Y_UP 0: row 0 of the buffer is the top row. */
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    bottom_half(1, 1, 0);
    glFinish();
    px("y_down first row", a, 4);
    px("y_down last row", a + (H - 1) * W * 4, 4);
    OSMesaPixelStore(OSMESA_Y_UP, 1);

    /* OSMesaGetColorBuffer gives the caller's buffer.  OSMesa 22 does not
     * flush first (the buffer still shows the last glFinish); fragsim's shim
     * does: the line starting "unflushed" differs by design. */
    glClearColor(0.5f, 0.25f, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    GLint w, h, f;
    void *cb;
    printf("color buffer: %d", OSMesaGetColorBuffer(ca, &w, &h, &f, &cb));
    printf(" %dx%d format 0x%x is caller's %d\n", w, h, f, cb == (void *)a);
    px("unflushed color buffer pixel", a, 4);

    /* Depth: 24 bits with 8 stencil bits above them. */
    glClearDepth(0.5);
    glClearStencil(0x5a);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    GLint bpv;
    void *db;
    printf("depth buffer: %d", OSMesaGetDepthBuffer(ca, &w, &h, &bpv, &db));
    printf(" %dx%d bpv %d value 0x%08x\n", w, h, bpv, ((unsigned *)db)[0]);

    /* Another context with BGRA, a row length and 16 depth bits; making it
     * current hands the first buffer its pixels. */
    glClearColor(1, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char *b = calloc((W + 3) * H, 4);
    OSMesaContext cb2 = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, NULL);
    OSMesaMakeCurrent(cb2, b, GL_UNSIGNED_BYTE, W, H);
    px("first buffer after switch", a, 4);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, W + 3);
    glClearColor(1, 0.5f, 0, 1);
    glClearDepth(0.25);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFinish();
    px("bgra row 0", b, 4);
    px("bgra row 1 (row length)", b + (W + 3) * 4, 4);
    px("bgra row 0 padding", b + W * 4, 4);
    printf("depth buffer: %d", OSMesaGetDepthBuffer(cb2, &w, &h, &bpv, &db));
    printf(" %dx%d bpv %d value 0x%04x\n", w, h, bpv, ((unsigned short *)db)[0]);

    /* RGB, 3 bytes per pixel. */
    unsigned char *c = calloc(W * H, 3);
    OSMesaContext cc = OSMesaCreateContextExt(OSMESA_RGB, 0, 0, 0, NULL);
    OSMesaMakeCurrent(cc, c, GL_UNSIGNED_BYTE, W, H);
    glClearColor(0.2f, 0.4f, 0.6f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    px("rgb", c, 6);
    printf("no depth buffer: %d\n", OSMesaGetDepthBuffer(cc, &w, &h, &bpv, &db));

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    printf("released: %d\n", OSMesaGetCurrentContext() == NULL);
    OSMesaDestroyContext(cc);
    OSMesaDestroyContext(cb2);
    OSMesaDestroyContext(ca);
    free(a);
    free(b);
    free(c);
    return 0;
}
