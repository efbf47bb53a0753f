/*
 * Vertex-array entry points against OSMesa (llvmpipe) at tolerance 0:
 * glMultiDrawArrays (GL 1.4, 2.8) and its errors, in display lists too;
 * glMultiDrawElements (GL 1.4, 2.8) with client indices and with offsets
 * into an element array buffer, compiled into display lists, and its
 * errors; glInterleavedArrays (GL 1.1, 2.8, table 2.5), all 14 formats
 * drawn and the state each leaves (strides, pointers, enables, the client
 * active texture unit, a bound GL_ARRAY_BUFFER), and its errors; both
 * read from a trace as apitrace records them (indices as blobs or as
 * offsets, the interleaved block an offset into a buffer), replayed from
 * the record and from the file on the model and on OSMesa;
 * glGetPointerv (6.1.11) for every array and the selection and feedback
 * buffers; and the signed normalized arrays of a draw (byte, short and int
 * normals and colours), which llvmpipe's vertex fetch converts otherwise
 * than GL 1.5's table 2.9 does.
 */
#define GL_GLEXT_PROTOTYPES
#include <unistd.h>
#include "check.h"
#include "osmesa_util.h"
#include "trace_build.h"
#include "../driver/osmesa_ref.h"
#include "../driver/replay.h"

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

/* ---- glMultiDrawElements ---- */

/* Indices into the strip's 64 vertices of fill_arrays, of each type. */
static GLubyte idx_ub[24];
static GLushort idx_us[24];
static GLuint idx_ui[24];

static void fill_indices(void)
{
    for (int i = 0; i < 24; i++) {
        idx_ub[i] = (GLubyte)((i * 7 + 3) % 64);
        idx_us[i] = (GLushort)((i * 5 + 1) % 64);
        idx_ui[i] = (GLuint)((i * 11 + 2) % 64);
    }
}

static void s_multidraw_elements(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.1f, 0.2f, 0.3f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    fill_arrays();
    fill_indices();
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(VertexPointer, 2, GL_FLOAT, 0, pos);
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, 0, col);
    /* Client indices of each type, a zero count among them. */
    const GLvoid *ub[3] = {idx_ub, idx_ub + 9, idx_ub + 12};
    static const GLsizei cub[3] = {6, 0, 9};
    G(MultiDrawElements, GL_TRIANGLES, cub, GL_UNSIGNED_BYTE, ub, 3);
    const GLvoid *us[2] = {idx_us + 2, idx_us + 10};
    static const GLsizei cus[2] = {7, 8};
    G(MultiDrawElements, GL_LINE_STRIP, cus, GL_UNSIGNED_SHORT, us, 2);
    const GLvoid *ui[2] = {idx_ui, idx_ui + 12};
    static const GLsizei cui[2] = {5, 6};
    G(MultiDrawElements, GL_TRIANGLE_FAN, cui, GL_UNSIGNED_INT, ui, 2);
    /* No draw at all, then bad calls that draw nothing (errors read and
     * compared in multidraw_elements_errors_vs_osmesa). */
    G(MultiDrawElements, GL_TRIANGLES, cub, GL_UNSIGNED_BYTE, ub, 0);
    static const GLsizei cbad[3] = {6, -1, 9};
    G(MultiDrawElements, GL_TRIANGLES, cbad, GL_UNSIGNED_BYTE, ub, 3);
    G(MultiDrawElements, 0x1234, cub, GL_UNSIGNED_BYTE, ub, 3);
    G(MultiDrawElements, GL_TRIANGLES, cub, GL_FLOAT, ub, 3);
    G(MultiDrawElements, GL_TRIANGLES, cub, GL_UNSIGNED_BYTE, ub, -2);
    /* With client indices one NULL pointer draws nothing. */
    const GLvoid *with_null[2] = {idx_ub, NULL};
    static const GLsizei c2[2] = {6, 6};
    G(MultiDrawElements, GL_TRIANGLES, c2, GL_UNSIGNED_BYTE, with_null, 2);
    while ((c ? fsglGetError(c) : glGetError()) != GL_NO_ERROR)
        ;
    /* Offsets into an element array buffer (GL 1.5 spec 2.9.2), NULL the
     * first (offset 0). */
    GLuint b = 0;
    G(GenBuffers, 1, &b);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, b);
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, sizeof idx_us, idx_us, GL_STATIC_DRAW);
    const GLvoid *offs[3] = {NULL, (const GLvoid *)(uintptr_t)(2 * 6), (const GLvoid *)(uintptr_t)(2 * 15)};
    static const GLsizei coff[3] = {6, 0, 9};
    G(Color4f, 1, 1, 1, 1);
    G(DisableClientState, GL_COLOR_ARRAY);
    G(Translatef, 0.02f, -0.03f, 0);
    G(MultiDrawElements, GL_TRIANGLES, coff, GL_UNSIGNED_SHORT, offs, 3);
    G(EnableClientState, GL_COLOR_ARRAY);
    /* Compiled into lists: the indices and the vertices they reach are
     * read at compile time (GL 1.5 spec 5.4), so what changes after
     * (the buffer's indices, the array data) is not drawn. */
    GLuint l = GR(GenLists, 2);
    G(NewList, l, GL_COMPILE);
    G(MultiDrawElements, GL_TRIANGLES, coff, GL_UNSIGNED_SHORT, offs, 3);
    G0(EndList);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, 0);
    G(NewList, l + 1, GL_COMPILE_AND_EXECUTE);
    G(MultiDrawElements, GL_LINE_LOOP, cus, GL_UNSIGNED_SHORT, us, 2);
    G(MultiDrawElements, GL_TRIANGLES, cub, GL_UNSIGNED_BYTE, ub, 0);
    G0(EndList);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, b);
    static const GLushort other[24] = {0};
    G(BufferSubData, GL_ELEMENT_ARRAY_BUFFER, 0, sizeof other, other);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, 0);
    for (int i = 0; i < 64; i++)
        pos[i][1] = -pos[i][1];
    idx_us[3] = 63;
    G0(LoadIdentity);
    G(Translatef, -0.05f, 0.04f, 0);
    G(CallList, l);
    G(Translatef, 0.1f, 0, 0);
    G(CallList, l + 1);
    G(DeleteLists, l, 2);
    G(DeleteBuffers, 1, &b);
}

TEST(multidraw_elements_vs_osmesa)
{
    COMPARE_SCENE(s_multidraw_elements, 96, 80, "multidraw_elements");
}

/* The errors of bad glMultiDrawElements calls, several bad at once (which
 * one wins), between glBegin and glEnd, and compiled into a list (raised
 * when it runs: the draws are compiled). */
static void multidraw_elements_errors(fs_context *c, double *v, int *n)
{
    fill_arrays();
    fill_indices();
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(VertexPointer, 2, GL_FLOAT, 0, pos);
    const GLvoid *ub[2] = {idx_ub, idx_ub + 3};
    static const GLsizei good[2] = {3, 3}, bad[2] = {3, -1}, zero[2] = {0, 0};
    struct { GLenum mode; const GLsizei *count; GLenum type; GLsizei n; } calls[] = {
        {GL_TRIANGLES, good, GL_UNSIGNED_BYTE, 2}, {GL_TRIANGLES, good, GL_UNSIGNED_BYTE, -1},
        {GL_TRIANGLES, bad, GL_UNSIGNED_BYTE, 2},  {0x1234, good, GL_UNSIGNED_BYTE, 2},
        {GL_TRIANGLES, good, GL_BYTE, 2},          {0x1234, bad, GL_UNSIGNED_BYTE, 2},
        {GL_TRIANGLES, bad, GL_FLOAT, 2},          {0x1234, good, GL_FLOAT, 2},
        {0x1234, good, GL_FLOAT, -1},              {0x1234, zero, GL_UNSIGNED_BYTE, 0},
        {GL_TRIANGLES, good, GL_INT, 0},           {GL_QUADS, zero, GL_UNSIGNED_INT, 2},
    };
    for (size_t i = 0; i < sizeof calls / sizeof calls[0]; i++) {
        G(MultiDrawElements, calls[i].mode, calls[i].count, calls[i].type, ub, calls[i].n);
        v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    }
    G(Begin, GL_POINTS);
    G(MultiDrawElements, GL_TRIANGLES, good, GL_UNSIGNED_BYTE, ub, 2);
    G0(End);
    v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(Begin, GL_POINTS);
    G(MultiDrawElements, GL_TRIANGLES, good, GL_UNSIGNED_BYTE, ub, 0);
    G0(End);
    v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    GLuint l = GR(GenLists, 1);
    /* (A bad type compiled is a known difference: known_differences.) */
    for (int k = 0; k < 4; k++) {
        if (k == 1)
            continue;
        G(NewList, l, GL_COMPILE);
        if (k == 0)
            G(MultiDrawElements, 0x1234, good, GL_UNSIGNED_BYTE, ub, 2);
        else if (k == 2)
            G(MultiDrawElements, GL_TRIANGLES, bad, GL_UNSIGNED_BYTE, ub, 2);
        else
            G(MultiDrawElements, GL_TRIANGLES, good, GL_UNSIGNED_BYTE, ub, -1);
        v[(*n)++] = (c ? fsglGetError(c) : glGetError());
        G0(EndList);
        G(CallList, l);
        v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    }
    G(DeleteLists, l, 1);
}

TEST(multidraw_elements_errors_vs_osmesa)
{
    OSM_CHECK_VALUES(multidraw_elements_errors, 8, 8, 64);
}

/* ---- glInterleavedArrays ---- */

/* The 14 formats of table 2.5, as the test lays them out: texture
 * coordinates (0, 2 or 4 floats), colour (0 none, 3 or 4 floats, 5 four
 * unsigned bytes), normal (3 floats or none), vertex (2, 3 or 4 floats). */
typedef struct ilv_format { GLenum format; int t, c, n, v; } ilv_format;
static const ilv_format ilv_formats[14] = {
    {GL_V2F, 0, 0, 0, 2},          {GL_V3F, 0, 0, 0, 3},           {GL_C4UB_V2F, 0, 5, 0, 2},
    {GL_C4UB_V3F, 0, 5, 0, 3},     {GL_C3F_V3F, 0, 3, 0, 3},       {GL_N3F_V3F, 0, 0, 3, 3},
    {GL_C4F_N3F_V3F, 0, 4, 3, 3},  {GL_T2F_V3F, 2, 0, 0, 3},       {GL_T4F_V4F, 4, 0, 0, 4},
    {GL_T2F_C4UB_V3F, 2, 5, 0, 3}, {GL_T2F_C3F_V3F, 2, 3, 0, 3},   {GL_T2F_N3F_V3F, 2, 0, 3, 3},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, 3}, {GL_T4F_C4F_N3F_V4F, 4, 4, 3, 4},
};

/* Bytes of one vertex of the format, tightly packed (table 2.5's s). */
static int ilv_size(const ilv_format *f) { return 4 * (f->t + (f->c == 5 ? 1 : f->c) + f->n + f->v); }

/* The first vertex's green of the unsigned byte colours: 248 in the
 * scenes that must match; 250 makes the pixel of known_differences. */
static int ilv_green0 = 248;

/* nv vertices of format f at `stride` bytes (0: packed) into out: a
 * triangle strip in the cell (x0, y0) of side d, every component varying. */
static void ilv_fill(const ilv_format *f, unsigned char *out, int stride, int nv, float x0, float y0, float d)
{
    int str = stride ? stride : ilv_size(f);
    for (int i = 0; i < nv; i++) {
        unsigned char *p = out + (size_t)i * (size_t)str;
        float fl[4];
        for (int k = 0; k < f->t; k++) {
            fl[k] = k == 0 ? (float)(i / 2) * 0.37f : k == 1 ? (float)(i & 1) * 0.8f + 0.1f
                    : k == 2 ? 0.5f : 1.0f + 0.25f * (float)(i % 3);
            if (k == 3 && f->t == 4) /* q scales s and t (projective) */
                fl[0] *= fl[3], fl[1] *= fl[3];
        }
        memcpy(p, fl, 4 * (size_t)f->t);
        p += 4 * f->t;
        if (f->c == 5) {
            unsigned char ub[4] = {(unsigned char)(40 + i * 29), (unsigned char)(ilv_green0 - i * 17),
                                   (unsigned char)(i * 53), (unsigned char)(255 - i * 9)};
            memcpy(p, ub, 4);
            p += 4;
        } else if (f->c) {
            float cf[4] = {0.2f + 0.07f * (float)i, 0.9f - 0.05f * (float)i, 0.13f * (float)(i % 5), 0.6f};
            memcpy(p, cf, 4 * (size_t)f->c);
            p += 4 * f->c;
        }
        if (f->n) {
            float nf[3] = {0.3f * (float)(i % 3) - 0.3f, 0.2f * (float)(i & 1), 1.0f};
            memcpy(p, nf, 12);
            p += 12;
        }
        float w = f->v == 4 ? 1.0f + 0.5f * (float)(i % 2) : 1.0f;
        float vf[4] = {(x0 + d * (float)(i / 2) / (float)(nv / 2 - 1) + 0.013f * (float)(i % 3)) * w,
                       (y0 + d * (float)(i & 1)) * w, -0.1f * (float)(i % 4) * w, w};
        memcpy(p, vf, 4 * (size_t)f->v);
    }
}

/* Each format in a cell of its own, textured (an 8x8 texture modulated),
 * lit where it has normals (the colour tracking the material's diffuse,
 * GL 1.5 spec 2.14.3): strides 0 and larger than s, one block from an
 * array buffer (the pointer an offset, 2.9.1), the texture coordinates of
 * the client active unit (unit 1) for another. */
static void s_interleaved(fs_context *c, int w, int h)
{
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.25f, 0.1f, 0.1f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    static GLubyte tex[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        tex[4 * i] = (GLubyte)(i * 4);
        tex[4 * i + 1] = (GLubyte)((i % 8) * 32);
        tex[4 * i + 2] = (GLubyte)(255 - i * 3);
        tex[4 * i + 3] = 255;
    }
    GLuint t[2];
    G(GenTextures, 2, t);
    for (int u = 0; u < 2; u++) {
        G(ActiveTexture, GL_TEXTURE0 + u);
        G(BindTexture, GL_TEXTURE_2D, t[u]);
        G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
    G(ActiveTexture, GL_TEXTURE0);
    static const float white[4] = {1, 1, 1, 1}, dir[4] = {0.2f, 0.4f, 0.9f, 0};
    G(Lightfv, GL_LIGHT0, GL_POSITION, dir);
    G(Lightfv, GL_LIGHT0, GL_DIFFUSE, white);
    G(Enable, GL_LIGHT0);
    G(ColorMaterial, GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    G(Enable, GL_COLOR_MATERIAL);
    static unsigned char block[16][12 * 64];
    GLuint buf = 0;
    G(GenBuffers, 1, &buf);
    for (int i = 0; i < 16; i++) {
        const ilv_format *f = &ilv_formats[i % 14];
        int stride = (i % 3 == 1) ? ilv_size(f) + 8 : 0;
        float x0 = -0.95f + 0.48f * (float)(i % 4), y0 = -0.95f + 0.48f * (float)(i / 4);
        ilv_fill(f, block[i], stride, 10, x0, y0, 0.4f);
        bool unit1 = i == 11 || i == 15, from_buffer = i == 9 || i == 14;
        if (unit1)
            G(ClientActiveTexture, GL_TEXTURE1);
        const GLvoid *p = block[i];
        if (from_buffer) {
            G(BindBuffer, GL_ARRAY_BUFFER, buf);
            G(BufferData, GL_ARRAY_BUFFER, 16 + sizeof block[i], NULL, GL_STREAM_DRAW);
            G(BufferSubData, GL_ARRAY_BUFFER, 16, sizeof block[i], block[i]);
            p = (const GLvoid *)(uintptr_t)16;
        }
        G(InterleavedArrays, f->format, stride, p);
        if (from_buffer)
            G(BindBuffer, GL_ARRAY_BUFFER, 0);
        if (unit1)
            G(ClientActiveTexture, GL_TEXTURE0);
        G(ActiveTexture, unit1 ? GL_TEXTURE1 : GL_TEXTURE0);
        if (f->t)
            G(Enable, GL_TEXTURE_2D);
        if (f->n)
            G(Enable, GL_LIGHTING);
        if (!f->c)
            G(Color4f, 0.9f, 0.8f, 0.7f, 1);
        G(DrawArrays, GL_TRIANGLE_STRIP, 0, 10);
        G(Disable, GL_TEXTURE_2D);
        G(Disable, GL_LIGHTING);
        G(ActiveTexture, GL_TEXTURE0);
        if (unit1) { /* unit 0's coordinates stay off for the next cells */
            G(ClientActiveTexture, GL_TEXTURE1);
            G(DisableClientState, GL_TEXTURE_COORD_ARRAY);
            G(ClientActiveTexture, GL_TEXTURE0);
        }
    }
    G(DeleteBuffers, 1, &buf);
    G(DeleteTextures, 2, t);
}

TEST(interleaved_arrays_vs_osmesa)
{
    COMPARE_SCENE(s_interleaved, 128, 128, "interleaved");
}

/* The client state each format leaves, from every array enabled and set
 * before: enables, pointers, sizes, types and strides of each array (the
 * texture coordinates of both units, unit 1 the client active one for the
 * odd formats), a bound GL_ARRAY_BUFFER for formats 4 and 11 (the arrays'
 * buffer bindings then), and the errors (a bad format, a negative stride,
 * both: the state then as it was); compiled into a list, the call is
 * executed at once and not compiled (GL 1.5 spec 5.4). */
static void ilv_read_state(fs_context *c, double *v, int *n)
{
    static const GLenum arrays[] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY,
                                    GL_SECONDARY_COLOR_ARRAY, GL_FOG_COORDINATE_ARRAY, GL_EDGE_FLAG_ARRAY,
                                    GL_INDEX_ARRAY};
    static const GLenum ints[] = {
        GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, GL_NORMAL_ARRAY_TYPE,
        GL_NORMAL_ARRAY_STRIDE, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
        GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
        GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING, GL_COLOR_ARRAY_BUFFER_BINDING,
        GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING};
    static const GLenum ptrs[] = {GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER,
                                  GL_TEXTURE_COORD_ARRAY_POINTER};
    GLint was = 0;
    G(GetIntegerv, GL_CLIENT_ACTIVE_TEXTURE, &was);
    for (int u = 0; u < 2; u++) {
        G(ClientActiveTexture, GL_TEXTURE0 + u);
        for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
            if (u == 0 || arrays[i] == GL_TEXTURE_COORD_ARRAY)
                v[(*n)++] = GR(IsEnabled, arrays[i]);
        for (size_t i = 0; i < sizeof ints / sizeof ints[0]; i++) {
            GLint x = -7;
            G(GetIntegerv, ints[i], &x);
            v[(*n)++] = x;
        }
        for (size_t i = 0; i < sizeof ptrs / sizeof ptrs[0]; i++) {
            GLvoid *p = NULL;
            G(GetPointerv, ptrs[i], &p);
            v[(*n)++] = (double)(uintptr_t)p;
        }
    }
    G(ClientActiveTexture, (GLenum)was);
    v[(*n)++] = (c ? fsglGetError(c) : glGetError());
}

static void ilv_all_on(fs_context *c, const float *junk)
{
    for (int u = 0; u < 2; u++) {
        G(ClientActiveTexture, GL_TEXTURE0 + u);
        G(EnableClientState, GL_TEXTURE_COORD_ARRAY);
        G(TexCoordPointer, 3, GL_SHORT, 6, junk + 1);
    }
    G(ClientActiveTexture, GL_TEXTURE0);
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_NORMAL_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(EnableClientState, GL_SECONDARY_COLOR_ARRAY);
    G(EnableClientState, GL_FOG_COORDINATE_ARRAY);
    G(EnableClientState, GL_EDGE_FLAG_ARRAY);
    G(EnableClientState, GL_INDEX_ARRAY);
    G(VertexPointer, 4, GL_SHORT, 2, junk + 2);
    G(NormalPointer, GL_BYTE, 4, junk + 3);
    G(ColorPointer, 3, GL_UNSIGNED_SHORT, 8, junk + 4);
}

static void interleaved_state(fs_context *c, double *v, int *n)
{
    static float junk[16];
    static unsigned char block[64];
    GLuint buf = 0;
    G(GenBuffers, 1, &buf);
    for (int i = 0; i < 14; i++) {
        ilv_all_on(c, junk);
        if (i % 2)
            G(ClientActiveTexture, GL_TEXTURE1);
        if (i == 4 || i == 11) {
            G(BindBuffer, GL_ARRAY_BUFFER, buf);
            G(InterleavedArrays, ilv_formats[i].format, i == 11 ? 60 : 0, (const GLvoid *)(uintptr_t)(8 * i));
            G(BindBuffer, GL_ARRAY_BUFFER, 0);
        } else {
            G(InterleavedArrays, ilv_formats[i].format, i % 3 == 0 ? 0 : 4 * i, block + i);
        }
        G(ClientActiveTexture, GL_TEXTURE0);
        ilv_read_state(c, v, n);
    }
    ilv_all_on(c, junk);
    G(InterleavedArrays, GL_RGBA, 0, block);           /* GL_INVALID_ENUM */
    ilv_read_state(c, v, n);
    G(InterleavedArrays, GL_T2F_V3F, -4, block);       /* GL_INVALID_VALUE */
    ilv_read_state(c, v, n);
    G(InterleavedArrays, GL_RGBA, -4, block);          /* which wins */
    ilv_read_state(c, v, n);
    GLuint l = GR(GenLists, 1);
    G(NewList, l, GL_COMPILE);
    G(InterleavedArrays, GL_C3F_V3F, 0, block);        /* executed now */
    G0(EndList);
    ilv_read_state(c, v, n);
    ilv_all_on(c, junk);
    G(CallList, l);                                    /* the list holds nothing */
    ilv_read_state(c, v, n);
    G(DeleteLists, l, 1);
    G(DeleteBuffers, 1, &buf);
}

TEST(interleaved_state_vs_osmesa)
{
    OSM_CHECK_VALUES(interleaved_state, 8, 8, 2048);
}

/* ---- known differences: each check fails when the difference goes ----
 *
 * 1. A draw with a bad index type compiled into a display list: Mesa's
 *    list compiler (vbo_save, the glDrawElements it compiles each of
 *    glMultiDrawElements' draws into) records GL_INVALID_VALUE, raised
 *    when the list runs; GL 1.5 spec 2.8 says GL_INVALID_ENUM, which
 *    fragsim raises (its list holds the draw, checked when it runs).
 * 2. One pixel of a triangle strip with unsigned byte colours (the
 *    C4UB_V3F cell of s_interleaved with a first green of 250, drawn
 *    through glColorPointer and glVertexPointer, no glInterleavedArrays):
 *    its green is 1 above llvmpipe's, a rounding of the colour
 *    interpolation not of this file's entry points (the interleaved scene
 *    takes 248, drawn alike). */
static void compiled_bad_type(fs_context *c, double *v, int *n)
{
    fill_arrays();
    fill_indices();
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(VertexPointer, 2, GL_FLOAT, 0, pos);
    const GLvoid *ub[2] = {idx_ub, idx_ub + 3};
    static const GLsizei good[2] = {3, 3};
    GLuint l = GR(GenLists, 1);
    G(NewList, l, GL_COMPILE);
    G(MultiDrawElements, GL_TRIANGLES, good, GL_FLOAT, ub, 2);
    G(DrawElements, GL_TRIANGLES, 3, GL_FLOAT, idx_ub);
    v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G0(EndList);
    G(CallList, l);
    v[(*n)++] = (c ? fsglGetError(c) : glGetError());
    G(DeleteLists, l, 1);
}

static void s_ubyte_colour_pixel(fs_context *c, int w, int h)
{
    static unsigned char block[16 * 10];
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0.25f, 0.1f, 0.1f, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    ilv_green0 = 250;
    ilv_fill(&ilv_formats[3], block, 0, 10, -0.95f + 0.48f * 3, -0.95f, 0.4f);
    ilv_green0 = 248;
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, 16, block);
    G(VertexPointer, 3, GL_FLOAT, 16, block + 4);
    G(DrawArrays, GL_TRIANGLE_STRIP, 0, 10);
}

TEST(known_differences)
{
    double ref[2], mine[2];
    int nr, nm;
    REQUIRE(osm_run_values(compiled_bad_type, 8, 8, ref, &nr, mine, &nm));
    CHECK_EQ_INT(nr, 2);
    CHECK_EQ_INT(nm, 2);
    CHECK_EQ_INT((int)ref[0], GL_NO_ERROR);
    CHECK_EQ_INT((int)mine[0], GL_NO_ERROR);
    CHECK_EQ_INT((int)ref[1], GL_INVALID_VALUE); /* Mesa's list compiler */
    CHECK_EQ_INT((int)mine[1], GL_INVALID_ENUM); /* GL 1.5 spec 2.8 */
    GLenum err;
    CHECK_EQ_INT(osm_compare_scene(s_ubyte_colour_pixel, 128, 128, "ubyte_colour_pixel", "FS_ARRAY_DRAWS_DUMP",
                                   "array_draws", &err), 1);
    CHECK_EQ_INT(err, GL_NO_ERROR);
}

/* ---- from a trace ---- */

static fs_tval tb_array(const fs_tval *elems, size_t n)
{
    fs_tval x;
    memset(&x, 0, sizeof x);
    x.type = FS_TV_ARRAY;
    x.arr.elems = elems;
    x.arr.n = n;
    return x;
}

/* A trace as apitrace writes these calls: glInterleavedArrays with a
 * buffer bound (the pointer an offset), glMultiDrawElements with an
 * element buffer bound (offsets, NULL the first: offset 0) and without
 * (blobs, one of a zero count empty), and with no draw and no counts. */
static int write_multidraw_trace(const char *path)
{
    char err[256];
    fs_trace_writer *w = fs_trace_create(path, err, sizeof err);
    if (!w)
        return -1;
    fs_tval vp[4] = {tb_ival(0), tb_ival(0), tb_ival(48), tb_ival(40)};
    tb_write_call(w, "glViewport", 4, vp, 0);
    /* GL_C3F_V3F: 12 vertices of a colour and a position, 8 bytes in. */
    static float block[2 + 12 * 6];
    for (int i = 0; i < 12; i++) {
        float *v = block + 2 + 6 * i;
        v[0] = 0.1f + 0.07f * (float)i;
        v[1] = 1.0f - 0.06f * (float)i;
        v[2] = (float)(i % 3) * 0.4f;
        v[3] = -0.9f + 0.15f * (float)i + ((i % 3) == 1 ? 0.3f : 0.0f);
        v[4] = (i % 3) == 2 ? 0.8f : -0.7f + 0.05f * (float)i;
        v[5] = 0;
    }
    fs_tval bb[2] = {tb_eval(GL_ARRAY_BUFFER, "GL_ARRAY_BUFFER"), tb_ival(1)};
    tb_write_call(w, "glBindBuffer", 2, bb, 0);
    fs_tval bd[4] = {tb_eval(GL_ARRAY_BUFFER, "GL_ARRAY_BUFFER"), tb_ival(sizeof block), tb_blob(block, sizeof block),
                     tb_eval(GL_STATIC_DRAW, "GL_STATIC_DRAW")};
    tb_write_call(w, "glBufferData", 4, bd, 0);
    fs_tval ia[3] = {tb_eval(GL_C3F_V3F, "GL_C3F_V3F"), tb_ival(0), tb_opaque(8)};
    tb_write_call(w, "glInterleavedArrays", 3, ia, 0);
    bb[1] = tb_ival(0);
    tb_write_call(w, "glBindBuffer", 2, bb, 0);
    static const GLubyte idx[9] = {0, 1, 2, 3, 4, 5, 2, 4, 5};
    fs_tval eb[2] = {tb_eval(GL_ELEMENT_ARRAY_BUFFER, "GL_ELEMENT_ARRAY_BUFFER"), tb_ival(2)};
    tb_write_call(w, "glBindBuffer", 2, eb, 0);
    fs_tval ed[4] = {tb_eval(GL_ELEMENT_ARRAY_BUFFER, "GL_ELEMENT_ARRAY_BUFFER"), tb_ival(sizeof idx),
                     tb_blob(idx, sizeof idx), tb_eval(GL_STATIC_DRAW, "GL_STATIC_DRAW")};
    tb_write_call(w, "glBufferData", 4, ed, 0);
    fs_tval counts[3] = {tb_ival(3), tb_ival(0), tb_ival(3)};
    fs_tval offs[3];
    memset(&offs[0], 0, sizeof offs[0]);
    offs[0].type = FS_TV_NULL;
    offs[1] = tb_opaque(1);
    offs[2] = tb_opaque(3);
    fs_tval md[5] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_array(counts, 3),
                     tb_eval(GL_UNSIGNED_BYTE, "GL_UNSIGNED_BYTE"), tb_array(offs, 3), tb_ival(3)};
    tb_write_call(w, "glMultiDrawElements", 5, md, 0);
    eb[1] = tb_ival(0);
    tb_write_call(w, "glBindBuffer", 2, eb, 0);
    static const GLushort us[2][3] = {{6, 7, 8}, {9, 10, 11}};
    fs_tval blobs[3] = {tb_blob(us[0], sizeof us[0]), tb_blob(us[1], 0), tb_blob(us[1], sizeof us[1])};
    fs_tval md2[5] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_array(counts, 3),
                      tb_eval(GL_UNSIGNED_SHORT, "GL_UNSIGNED_SHORT"), tb_array(blobs, 3), tb_ival(3)};
    tb_write_call(w, "glMultiDrawElements", 5, md2, 0);
    /* No draw, no counts, and more pointers than draws: nothing (a record
     * that sized the indices by counts it has not would read NULL). */
    fs_tval none[5] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(0), tb_eval(GL_UNSIGNED_SHORT, "GL_UNSIGNED_SHORT"),
                       tb_array(blobs, 3), tb_ival(0)};
    none[1].type = FS_TV_NULL;
    tb_write_call(w, "glMultiDrawElements", 5, none, 0);
    fs_tval sw[2] = {tb_ival(0), tb_ival(0)};
    tb_write_call(w, "glXSwapBuffers", 2, sw, 0);
    return fs_trace_finish(w);
}

/* Replays the trace (record_limit 1: from the file, 0: from the record)
 * on the model and on OSMesa; the pixels that differ, -1 on an error;
 * *unsupported the model's calls it could not execute, *digest its image's
 * (FNV-1a). */
static long replay_both(const char *path, size_t record_limit, bool *from_record, uint64_t *unsupported,
                        uint64_t *digest)
{
    char err[512];
    fs_replay_opts o = {NULL, 0, 0, record_limit, false, FS_TRACE_PARSER_FAST};
    fs_replayer *r = fs_replay_open(path, &o, err, sizeof err);
    if (!r)
        return -1;
    int w = fs_replay_info_get(r)->width, h = fs_replay_info_get(r)->height;
    *from_record = fs_replay_info_get(r)->from_record;
    fs_osmesa *ref = fs_osmesa_create(w, h, 24, 8, err, sizeof err);
    fs_context *c = ref ? fs_context_create(NULL, w, h) : NULL;
    long differ = -1;
    fs_call call;
    fs_replay_event ev;
    while (c && (ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR) {
        if (ev != FS_REPLAY_CALL)
            continue;
        fs_call mine = call;
        fs_submit(c, &mine);
        fs_osmesa_dispatch(ref, &call);
    }
    if (c && ev == FS_REPLAY_EOF) {
        const uint8_t *a = fs_osmesa_color(ref), *b = c->fb.color;
        differ = 0;
        for (long i = 0; i < (long)w * h; i++)
            differ += memcmp(a + 4 * i, b + 4 * i, 4) != 0;
        long lit = 0;
        for (long i = 0; i < (long)w * h; i++)
            lit += (b[4 * i] | b[4 * i + 1] | b[4 * i + 2]) != 0;
        printf("  multidraw trace (record limit %zu): %ld pixels differ, %ld lit\n", record_limit, differ, lit);
        if (lit < 40)
            differ = -2; /* the draws must have drawn */
        *digest = 1469598103934665603ull;
        for (long i = 0; i < 4L * w * h; i++)
            *digest = (*digest ^ b[i]) * 1099511628211ull;
        *unsupported = c->stats.unsupported_calls;
        for (int i = 0; i < c->unsupported_feature_count; i++)
            printf("  unsupported: %s\n", c->unsupported_feature[i].name);
        *unsupported += (uint64_t)c->unsupported_feature_count;
    }
    if (c)
        fs_context_destroy(c);
    if (ref)
        fs_osmesa_destroy(ref);
    fs_replay_close(r);
    return differ;
}

TEST(multidraw_and_interleaved_from_a_trace_vs_osmesa)
{
    char path[128];
    snprintf(path, sizeof path, "/tmp/fragsim_test_array_draws_%d.trace", (int)getpid());
    REQUIRE(write_multidraw_trace(path) == 0);
    uint64_t digest[2] = {0, 1};
    for (int pass = 0; pass < 2; pass++) {
        bool from_record = false;
        uint64_t unsupported = 99;
        CHECK_EQ_INT(replay_both(path, pass ? 0 : 1, &from_record, &unsupported, &digest[pass]), 0);
        CHECK_EQ_INT(from_record, pass == 1); /* the record holds the arrays of pointers */
        CHECK_EQ_INT((int)unsupported, 0);
    }
    CHECK(digest[0] == digest[1]); /* the record replays what the file holds */
    unlink(path);
}

TEST_LIST = {
    TEST_ENTRY(multidraw_arrays_vs_osmesa),
    TEST_ENTRY(errors_and_pointers_vs_osmesa),
    TEST_ENTRY(signed_normalized_arrays_vs_osmesa),
    TEST_ENTRY(multidraw_elements_vs_osmesa),
    TEST_ENTRY(multidraw_elements_errors_vs_osmesa),
    TEST_ENTRY(interleaved_arrays_vs_osmesa),
    TEST_ENTRY(interleaved_state_vs_osmesa),
    TEST_ENTRY(known_differences),
    TEST_ENTRY(multidraw_and_interleaved_from_a_trace_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
