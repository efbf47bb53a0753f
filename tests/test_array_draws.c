/*
 * Vertex-array entry points against OSMesa (llvmpipe) at tolerance 0:
 * glMultiDrawArrays (GL 1.4, 2.8) and its errors, in display lists too;
 * glGetPointerv (6.1.11) for every array and the selection and feedback
 * buffers; and the signed normalized arrays of a draw (byte, short and int
 * normals and colours), which llvmpipe's vertex fetch converts otherwise
 * than GL 1.5's table 2.9 does.
 */
#define GL_GLEXT_PROTOTYPES
#include "check.h"
#include "osmesa_util.h"

#define COMPARE_SCENE(fn, w, h, name) OSM_CHECK_SCENE(fn, w, h, name, "FS_ARRAY_DRAWS_DUMP", "array_draws")

/* A strip of quads across the window, one colour per vertex. */
static float pos[64][2];
static uint8_t col[64][4];

static void fill_arrays(void)
{
    for (int i = 0; i < 64; i++) {
        pos[i][0] = -0.95f + 0.06f * (float)(i / 2) + 0.013f * (float)(i % 3);
        pos[i][1] = (i & 1) ? 0.8f - 0.01f * (float)i : -0.7f + 0.02f * (float)(i % 5);
        col[i][0] = (uint8_t)(i * 37);
        col[i][1] = (uint8_t)(255 - i * 11);
        col[i][2] = (uint8_t)(i * 91);
        col[i][3] = 255;
    }
}

static void s_multidraw(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.2f, 0.2f, 0.2f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    fill_arrays();
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(VertexPointer, 2, GL_FLOAT, 0, pos);
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, 0, col);
    static const GLint first[4] = {0, 10, 30, 50}, count[4] = {8, 0, 12, 14};
    G(MultiDrawArrays, GL_TRIANGLE_STRIP, first, count, 4);
    static const GLint bad[2] = {3, -1};
    G(MultiDrawArrays, GL_TRIANGLES, first, bad, 2); /* GL_INVALID_VALUE, nothing drawn */
    (void)(c ? fsglGetError(c) : glGetError());
    G(MultiDrawArrays, GL_TRIANGLES, first, count, -1); /* GL_INVALID_VALUE */
    (void)(c ? fsglGetError(c) : glGetError());
    G(MultiDrawArrays, 0x1234, first, count, 1); /* GL_INVALID_ENUM */
    (void)(c ? fsglGetError(c) : glGetError());
    /* In a display list, executed under another colour. */
    GLuint l = GR(GenLists, 1);
    G(NewList, l, GL_COMPILE);
    static const GLint lf[2] = {20, 40}, lc[2] = {6, 5};
    G(MultiDrawArrays, GL_LINE_STRIP, lf, lc, 2);
    G0(EndList);
    G(DisableClientState, GL_COLOR_ARRAY);
    G(Color3f, 1, 1, 0);
    G(CallList, l);
    G(DeleteLists, l, 1);
}

TEST(multidraw_arrays_vs_osmesa)
{
    COMPARE_SCENE(s_multidraw, 80, 64, "multidraw_arrays");
}

/* The errors of the bad calls above, as glGetError answers them. */
static void multidraw_errors(fs_context *c, GLenum out[4])
{
    fill_arrays();
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(VertexPointer, 2, GL_FLOAT, 0, pos);
    static const GLint first[2] = {0, 4}, bad[2] = {3, -1}, good[2] = {3, 3};
    G(MultiDrawArrays, GL_TRIANGLES, first, bad, 2);
    out[0] = c ? fsglGetError(c) : glGetError();
    G(MultiDrawArrays, GL_TRIANGLES, first, good, -1);
    out[1] = c ? fsglGetError(c) : glGetError();
    G(MultiDrawArrays, 0x1234, first, good, 2);
    out[2] = c ? fsglGetError(c) : glGetError();
    G(MultiDrawArrays, GL_TRIANGLES, first, good, 0);
    out[3] = c ? fsglGetError(c) : glGetError();
}

/* glGetPointerv of each array (the texture coordinates of two units) and
 * of the selection and feedback buffers, and a bad name. */
static void pointers(fs_context *c, uintptr_t out[13])
{
    static float f[16];
    static GLuint sel[8];
    static GLfloat fb[8];
    G(VertexPointer, 3, GL_FLOAT, 0, f + 1);
    G(NormalPointer, GL_FLOAT, 0, f + 2);
    G(ColorPointer, 4, GL_FLOAT, 0, f + 3);
    G(TexCoordPointer, 2, GL_FLOAT, 0, f + 4);
    G(ClientActiveTexture, GL_TEXTURE1);
    G(TexCoordPointer, 2, GL_FLOAT, 0, f + 5);
    G(SecondaryColorPointer, 3, GL_FLOAT, 0, f + 6);
    G(FogCoordPointer, GL_FLOAT, 0, f + 7);
    G(EdgeFlagPointer, 0, f + 8);
    G(IndexPointer, GL_FLOAT, 0, f + 9);
    G(SelectBuffer, 8, sel);
    G(FeedbackBuffer, 8, GL_2D, fb);
    static const GLenum names[] = {GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER,
                                   GL_TEXTURE_COORD_ARRAY_POINTER, GL_SECONDARY_COLOR_ARRAY_POINTER,
                                   GL_FOG_COORDINATE_ARRAY_POINTER, GL_EDGE_FLAG_ARRAY_POINTER,
                                   GL_INDEX_ARRAY_POINTER, GL_SELECTION_BUFFER_POINTER, GL_FEEDBACK_BUFFER_POINTER};
    int n = 0;
    for (int i = 0; i < 10; i++) {
        GLvoid *p = NULL;
        G(GetPointerv, names[i], &p);
        out[n++] = (uintptr_t)p;
    }
    G(ClientActiveTexture, GL_TEXTURE0);
    GLvoid *p = NULL;
    G(GetPointerv, GL_TEXTURE_COORD_ARRAY_POINTER, &p);
    out[n++] = (uintptr_t)p;
    G(GetPointerv, GL_VERTEX_ARRAY, &p); /* GL_INVALID_ENUM */
    out[n++] = c ? fsglGetError(c) : glGetError();
    out[n++] = c ? fsglGetError(c) : glGetError();
}

TEST(errors_and_pointers_vs_osmesa)
{
    GLenum eref[4], emine[4];
    uintptr_t pref[13], pmine[13];
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    multidraw_errors(NULL, eref);
    pointers(NULL, pref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    multidraw_errors(c, emine);
    pointers(c, pmine);
    fs_context_destroy(c);
    for (int i = 0; i < 4; i++)
        CHECK_EQ_INT(emine[i], eref[i]);
    for (int i = 0; i < 13; i++)
        if (pmine[i] != pref[i])
            CHECK_FAIL_("value %d: OSMesa %#lx, fragsim %#lx", i, (unsigned long)pref[i], (unsigned long)pmine[i]);
}

/* Lit triangles whose normals come from signed byte, short and int
 * arrays, and unlit ones with signed colours: every value of a byte. */
static void s_signed_arrays(fs_context *c, int w, int h)
{
    osm_frustum_scene(c, w, h, 0, 0, 0, 10);
    static float v[256][3];
    static GLbyte nb[256][3], cb[256][4];
    static GLshort ns[256][3];
    static GLint ni[256][3];
    for (int i = 0; i < 256; i++) {
        int gx = i % 16, gy = i / 16;
        v[i][0] = -1.5f + 0.2f * (float)gx + ((i % 3) ? 0.17f : 0.0f);
        v[i][1] = -1.5f + 0.2f * (float)gy + ((i % 3) == 2 ? 0.19f : 0.0f);
        v[i][2] = -2;
        nb[i][0] = (GLbyte)(i - 128);
        nb[i][1] = (GLbyte)(127 - i);
        nb[i][2] = (GLbyte)((i * 7) % 256 - 128);
        ns[i][0] = (GLshort)((i - 128) * 256 + i);
        ns[i][1] = (GLshort)(32767 - i * 200);
        ns[i][2] = (GLshort)(i * 131 - 16000);
        ni[i][0] = (i - 128) * 16777216;
        ni[i][1] = 2147483647 - i * 8000000 - i;
        ni[i][2] = (i - 128) * 9000000;
        for (int k = 0; k < 4; k++)
            cb[i][k] = (GLbyte)((i * (k + 3)) % 256 - 128);
    }
    static const float white[4] = {1, 1, 1, 1}, dir[4] = {0.3f, 0.5f, 0.8f, 0};
    G(Lightfv, GL_LIGHT0, GL_POSITION, dir);
    G(Lightfv, GL_LIGHT0, GL_DIFFUSE, white);
    G(Enable, GL_LIGHT0);
    G(Enable, GL_LIGHTING);
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_NORMAL_ARRAY);
    G(VertexPointer, 3, GL_FLOAT, 0, v);
    G(NormalPointer, GL_BYTE, 0, nb);
    G(DrawArrays, GL_TRIANGLES, 0, 84);
    G(NormalPointer, GL_SHORT, 0, ns);
    G(DrawArrays, GL_TRIANGLES, 84, 84);
    G(NormalPointer, GL_INT, 0, ni);
    G(DrawArrays, GL_TRIANGLES, 168, 87);
    G(Disable, GL_LIGHTING);
    G(DisableClientState, GL_NORMAL_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(ColorPointer, 4, GL_BYTE, 0, cb);
    G(Translatef, 0.1f, 0.05f, -0.5f);
    G(DrawArrays, GL_TRIANGLES, 0, 255);
}

TEST(signed_normalized_arrays_vs_osmesa)
{
    COMPARE_SCENE(s_signed_arrays, 96, 96, "signed_arrays");
}

TEST_LIST = {
    TEST_ENTRY(multidraw_arrays_vs_osmesa),
    TEST_ENTRY(errors_and_pointers_vs_osmesa),
    TEST_ENTRY(signed_normalized_arrays_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
