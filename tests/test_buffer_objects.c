/*
 * Buffer objects (pipeline/buffer_object.c, GL 1.5 spec 2.9) against
 * OSMesa through the same calls: names, data round trips, sub-data,
 * mapping, every error, the bindings' glGet answers and their client
 * attribute push and pop, deleting a bound buffer, and draws whose arrays
 * and indices are offsets into buffers (images at tolerance 0).  Then a
 * trace as apitrace records a VBO program (writes through a mapping as
 * memcpy pseudo-calls, pointers as offsets) replayed on the model.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdint.h>
#include <unistd.h>
#include "check.h"
#include "osmesa_util.h"
#include "trace_build.h"
#include "../driver/capture.h"
#include "../driver/replay.h"
#include "../driver/trace.h"
#include "../pipeline/buffer_object.h"

/* ---- a script of calls whose errors and answers are logged ---- */
typedef struct blog {
    long v[16384];
    int n;
} blog;

static void put(blog *l, long v)
{
    if (l->n < (int)(sizeof l->v / sizeof l->v[0]))
        l->v[l->n++] = v;
}

/* The sticky error after each step, as glGetError gives it. */
static void step(fs_context *c, blog *l)
{
    put(l, (long)(c ? fsglGetError(c) : glGetError()));
}

static void get_int(fs_context *c, blog *l, GLenum pname)
{
    GLint v = -7;
    G(GetIntegerv, pname, &v);
    put(l, v);
}

static void buffer_params(fs_context *c, blog *l, GLenum target)
{
    static const GLenum p[4] = {GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS, GL_BUFFER_MAPPED};
    for (int k = 0; k < 4; k++) {
        GLint v = -7;
        G(GetBufferParameteriv, target, p[k], &v);
        put(l, v);
    }
    step(c, l);
}

/* Names, bindings and the errors of GL 1.5 spec 2.9. */
static void names_and_errors(fs_context *c, blog *l)
{
    GLuint b[3] = {0, 0, 0};
    G(GenBuffers, 3, b);
    step(c, l);
    put(l, b[1] - b[0]);
    put(l, GR(IsBuffer, b[0])); /* a name, not yet an object */
    G(BindBuffer, GL_ARRAY_BUFFER, b[0]);
    put(l, GR(IsBuffer, b[0]));
    buffer_params(c, l, GL_ARRAY_BUFFER); /* the initial state, table 2.6 */
    G(BindBuffer, 0x1234, b[0]);
    step(c, l);
    G(GenBuffers, -1, b + 2);
    step(c, l);
    G(DeleteBuffers, -1, b);
    step(c, l);
    /* buffer 0 bound: no object to operate on */
    G(BindBuffer, GL_ARRAY_BUFFER, 0);
    G(BufferData, GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);
    step(c, l);
    G(BufferSubData, GL_ARRAY_BUFFER, 0, 0, NULL);
    step(c, l);
    GLint v = -7;
    G(GetBufferParameteriv, GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    step(c, l);
    put(l, (long)(intptr_t)GR(MapBuffer, GL_ARRAY_BUFFER, GL_READ_WRITE));
    step(c, l);
    put(l, GR(UnmapBuffer, GL_ARRAY_BUFFER));
    step(c, l);
    void *p = (void *)1;
    G(GetBufferPointerv, GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
    step(c, l);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, b[1]);
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW);
    step(c, l);
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, 4, NULL, 0x1234);
    step(c, l);
    G(BufferData, 0x1234, 4, NULL, GL_STATIC_DRAW);
    step(c, l);
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)1 << 40, NULL, GL_STATIC_DRAW);
    step(c, l);
    /* mapping an empty store */
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, 0, NULL, GL_STREAM_READ);
    put(l, GR(MapBuffer, GL_ELEMENT_ARRAY_BUFFER, GL_READ_WRITE) == NULL);
    step(c, l);
    buffer_params(c, l, GL_ELEMENT_ARRAY_BUFFER);
    get_int(c, l, GL_ARRAY_BUFFER_BINDING);
    get_int(c, l, GL_ELEMENT_ARRAY_BUFFER_BINDING);
    /* inside glBegin/glEnd */
    G(Begin, GL_POINTS);
    G(BindBuffer, GL_ARRAY_BUFFER, b[0]);
    put(l, GR(IsBuffer, b[1]));
    G0(End);
    step(c, l);
    get_int(c, l, GL_ARRAY_BUFFER_BINDING);
    G(DeleteBuffers, 3, b);
    put(l, GR(IsBuffer, b[0]));
    put(l, GR(IsBuffer, 0));
    step(c, l);
}

/* Data in and out, sub-data, mapping and its errors. */
static void data_and_mapping(fs_context *c, blog *l)
{
    unsigned char d[16], g[16];
    for (int i = 0; i < 16; i++)
        d[i] = (unsigned char)(3 * i + 1);
    GLuint b;
    G(GenBuffers, 1, &b);
    G(BindBuffer, GL_ARRAY_BUFFER, b);
    G(BufferData, GL_ARRAY_BUFFER, 16, d, GL_DYNAMIC_COPY);
    step(c, l);
    buffer_params(c, l, GL_ARRAY_BUFFER);
    G(BufferSubData, GL_ARRAY_BUFFER, 12, 4, d); /* the last four bytes */
    step(c, l);
    G(BufferSubData, GL_ARRAY_BUFFER, -1, 4, d);
    step(c, l);
    G(BufferSubData, GL_ARRAY_BUFFER, 0, -1, d);
    step(c, l);
    G(BufferSubData, GL_ARRAY_BUFFER, 13, 4, d);
    step(c, l);
    memset(g, 0, sizeof g);
    G(GetBufferSubData, GL_ARRAY_BUFFER, 0, 16, g);
    step(c, l);
    for (int i = 0; i < 16; i++)
        put(l, g[i]);
    G(GetBufferSubData, GL_ARRAY_BUFFER, 9, 8, g);
    step(c, l);
    put(l, GR(MapBuffer, GL_ARRAY_BUFFER, 0x1234) == NULL);
    step(c, l);
    unsigned char *m = GR(MapBuffer, GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    step(c, l);
    put(l, m != NULL);
    if (m)
        m[5] = 200;
    buffer_params(c, l, GL_ARRAY_BUFFER);
    void *p = NULL;
    G(GetBufferPointerv, GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
    put(l, p == m);
    G(GetBufferPointerv, GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &p);
    step(c, l);
    G(GetBufferParameteriv, GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, (GLint *)g);
    step(c, l);
    put(l, GR(MapBuffer, GL_ARRAY_BUFFER, GL_READ_ONLY) == NULL); /* mapped already */
    step(c, l);
    G(BufferSubData, GL_ARRAY_BUFFER, 0, 4, d);
    step(c, l);
    G(GetBufferSubData, GL_ARRAY_BUFFER, 0, 4, g);
    step(c, l);
    put(l, GR(UnmapBuffer, GL_ARRAY_BUFFER));
    step(c, l);
    put(l, GR(UnmapBuffer, GL_ARRAY_BUFFER)); /* not mapped */
    step(c, l);
    buffer_params(c, l, GL_ARRAY_BUFFER);
    G(GetBufferSubData, GL_ARRAY_BUFFER, 4, 2, g);
    put(l, g[0]);
    put(l, g[1]);
    /* glBufferData on a mapped buffer: a new store, no longer mapped */
    G(MapBuffer, GL_ARRAY_BUFFER, GL_READ_WRITE);
    G(BufferData, GL_ARRAY_BUFFER, 8, d, GL_STREAM_DRAW);
    step(c, l);
    buffer_params(c, l, GL_ARRAY_BUFFER);
    G(DeleteBuffers, 1, &b);
}

/* The bindings as client state: the arrays' bindings taken at pointer
 * time, pushed and popped with GL_CLIENT_VERTEX_ARRAY_BIT, and deleting a
 * bound buffer unbinding it everywhere. */
static void bindings(fs_context *c, blog *l)
{
    GLuint b[3];
    G(GenBuffers, 3, b);
    G(BindBuffer, GL_ARRAY_BUFFER, b[0]);
    G(VertexPointer, 2, GL_FLOAT, 0, (const void *)8);
    G(NormalPointer, GL_FLOAT, 0, (const void *)0);
    G(BindBuffer, GL_ARRAY_BUFFER, b[1]);
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, 0, (const void *)4);
    G(TexCoordPointer, 2, GL_FLOAT, 0, (const void *)0);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, b[2]);
    static const GLenum q[6] = {GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING,
                                GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING,
                                GL_COLOR_ARRAY_BUFFER_BINDING, GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING};
    for (int k = 0; k < 6; k++)
        get_int(c, l, q[k]);
    G(PushClientAttrib, GL_CLIENT_VERTEX_ARRAY_BIT);
    G(BindBuffer, GL_ARRAY_BUFFER, b[2]);
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, 0);
    G(VertexPointer, 2, GL_FLOAT, 0, (const void *)0);
    G0(PopClientAttrib);
    for (int k = 0; k < 6; k++)
        get_int(c, l, q[k]);
    G(PushClientAttrib, GL_CLIENT_PIXEL_STORE_BIT);
    G(BindBuffer, GL_ARRAY_BUFFER, b[2]);
    G0(PopClientAttrib);
    get_int(c, l, GL_ARRAY_BUFFER_BINDING); /* not in the pixel-store group */
    G(BindBuffer, GL_ARRAY_BUFFER, b[0]);
    G(DeleteBuffers, 1, &b[0]);
    step(c, l);
    for (int k = 0; k < 6; k++)
        get_int(c, l, q[k]);
    G(DeleteBuffers, 2, &b[1]);
    for (int k = 0; k < 6; k++)
        get_int(c, l, q[k]);
}

/* ARB_map_buffer_range: every access combination of the six bits at a
 * valid range, and valid and invalid ranges at three accesses (one with
 * an undefined bit), with the errors, the
 * pointer's offset into the store, GL_BUFFER_ACCESS and GL_BUFFER_MAPPED,
 * writes through the range, and glFlushMappedBufferRange's errors. */
static void map_buffer_range(fs_context *c, blog *l)
{
    unsigned char d[64], g[64];
    for (int i = 0; i < 64; i++)
        d[i] = (unsigned char)(5 * i + 2);
    GLuint b;
    G(GenBuffers, 1, &b);
    put(l, GR(MapBufferRange, GL_ARRAY_BUFFER, 0, 4, GL_MAP_WRITE_BIT) == NULL); /* nothing bound */
    step(c, l);
    G(BindBuffer, GL_ARRAY_BUFFER, b);
    G(BufferData, GL_ARRAY_BUFFER, 64, d, GL_STREAM_DRAW);
    put(l, GR(MapBufferRange, GL_TEXTURE_2D, 0, 4, GL_MAP_WRITE_BIT) == NULL);
    step(c, l);
    static const GLintptr ranges[][2] = {{0, 64}, {8, 16}, {-1, 4}, {0, -1}, {60, 8}, {64, 0}, {0, 0}, {63, 1}};
    for (int a = 0; a < 64 + 3 * 8; a++) {
        /* Every access at a valid range, then every range at three. */
        static const GLbitfield some[3] = {GL_MAP_WRITE_BIT, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT, GL_MAP_WRITE_BIT | 0x100};
        GLbitfield access = a < 64 ? (GLbitfield)a : some[(a - 64) / 8];
        const GLintptr *r = ranges[a < 64 ? 1 : (a - 64) % 8];
        put(l, 100000 + a); /* a marker (compare_script) */
        unsigned char *m = GR(MapBufferRange, GL_ARRAY_BUFFER, r[0], r[1], access);
        step(c, l);
        put(l, m == NULL);
        buffer_params(c, l, GL_ARRAY_BUFFER);
        if (!m)
            continue;
        void *p = NULL;
        G(GetBufferPointerv, GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
        put(l, p == m);
        if (access & GL_MAP_WRITE_BIT)
            m[r[1] - 1] = (unsigned char)a;
        put(l, GR(MapBufferRange, GL_ARRAY_BUFFER, 0, 4, GL_MAP_WRITE_BIT) == NULL); /* mapped already */
        step(c, l);
        G(FlushMappedBufferRange, GL_ARRAY_BUFFER, 0, 1);
        step(c, l);
        G(FlushMappedBufferRange, GL_ARRAY_BUFFER, -1, 1);
        step(c, l);
        G(FlushMappedBufferRange, GL_ARRAY_BUFFER, 0, r[1] + 1);
        step(c, l);
        G(FlushMappedBufferRange, GL_ARRAY_BUFFER, r[1], 0);
        step(c, l);
        put(l, GR(UnmapBuffer, GL_ARRAY_BUFFER));
        step(c, l);
        if (!(access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT))) {
            memset(g, 0, sizeof g);
            G(GetBufferSubData, GL_ARRAY_BUFFER, 0, 64, g);
            for (int i = 0; i < 64; i++)
                put(l, g[i]);
        }
    }
    G(FlushMappedBufferRange, GL_ARRAY_BUFFER, 0, 1); /* not mapped */
    step(c, l);
    G(DeleteBuffers, 1, &b);
}

static void compare_script(check_state *check_st_, void (*script)(fs_context *c, blog *l))
{
    osm o;
    REQUIRE(osm_open(&o, 8, 8));
    blog ref = {{0}, 0}, mine = {{0}, 0};
    script(NULL, &ref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    script(c, &mine);
    fs_context_destroy(c);
    CHECK_EQ_INT(mine.n, ref.n);
    for (int i = 0; i < ref.n && i < mine.n; i++)
        if (mine.v[i] != ref.v[i]) {
            /* A script may log markers 100000 + case: name the case. */
            int at = i;
            while (at > 0 && ref.v[at] < 100000)
                at--;
            CHECK_FAIL_("entry %d: model %ld, OSMesa %ld (%ld entries after marker %ld)", i, mine.v[i], ref.v[i],
                        (long)(i - at), ref.v[at]);
        }
}

TEST(names_and_errors_match_osmesa) { compare_script(check_st_, names_and_errors); }
TEST(data_and_mapping_match_osmesa) { compare_script(check_st_, data_and_mapping); }
TEST(bindings_push_pop_and_delete_match_osmesa) { compare_script(check_st_, bindings); }
TEST(map_buffer_range_vs_osmesa) { compare_script(check_st_, map_buffer_range); }

/* A store larger than FS_BUFFER_MAX_BYTES is GL_OUT_OF_MEMORY and leaves
 * the buffer as it was (a bad trace must not allocate without bound). */
TEST(huge_buffer_data_is_out_of_memory)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    GLuint b;
    fsglGenBuffers(c, 1, &b);
    fsglBindBuffer(c, GL_ARRAY_BUFFER, b);
    fsglBufferData(c, GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
    fsglBufferData(c, GL_ARRAY_BUFFER, FS_BUFFER_MAX_BYTES + 1, NULL, GL_DYNAMIC_DRAW);
    CHECK_EQ_INT(fsglGetError(c), GL_OUT_OF_MEMORY);
    GLint v = 0;
    fsglGetBufferParameteriv(c, GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK_EQ_INT(v, 16);
    fsglGetBufferParameteriv(c, GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    CHECK_EQ_INT(v, GL_STATIC_DRAW);
    fs_context_destroy(c);
}

/* ---- draws from buffers ---- */
typedef struct vtx {
    float pos[3];
    unsigned char col[4];
    float nrm[3];
    float tc[2];
} vtx;

static void make_vertices(vtx *v, int n)
{
    for (int i = 0; i < n; i++) {
        float a = (float)i * 0.7f;
        v[i].pos[0] = 0.9f * cosf(a) * (float)(i % 3 + 1) / 3.0f;
        v[i].pos[1] = 0.9f * sinf(a) * (float)(i % 4 + 1) / 4.0f;
        v[i].pos[2] = 0.1f * (float)(i % 5) - 0.2f;
        v[i].col[0] = (unsigned char)(37 * i);
        v[i].col[1] = (unsigned char)(255 - 19 * i);
        v[i].col[2] = (unsigned char)(90 + 11 * i);
        v[i].col[3] = 255;
        v[i].nrm[0] = 0.3f * (float)(i % 2);
        v[i].nrm[1] = 0.2f;
        v[i].nrm[2] = 1.0f;
        v[i].tc[0] = (float)(i % 3) * 0.5f;
        v[i].tc[1] = (float)(i % 2);
    }
}

#define NV 24

/* One interleaved buffer (with a 64-byte header before the vertices, so
 * that every offset is nonzero) and an index buffer that also holds some
 * vertex bytes before its indices: arrays and indices at offsets. */
static void draw_from_buffers(fs_context *c, const void *user, int w, int h)
{
    (void)user;
    (void)w;
    (void)h;
    vtx v[NV];
    make_vertices(v, NV);
    GLuint b[2];
    G(GenBuffers, 2, b);
    G(BindBuffer, GL_ARRAY_BUFFER, b[0]);
    G(BufferData, GL_ARRAY_BUFFER, 64 + sizeof v, NULL, GL_STATIC_DRAW);
    G(BufferSubData, GL_ARRAY_BUFFER, 64, sizeof v, v);
    const char *base = (const char *)64;
    G(VertexPointer, 3, GL_FLOAT, sizeof(vtx), base + offsetof(vtx, pos));
    G(ColorPointer, 4, GL_UNSIGNED_BYTE, sizeof(vtx), base + offsetof(vtx, col));
    G(NormalPointer, GL_FLOAT, sizeof(vtx), base + offsetof(vtx, nrm));
    G(TexCoordPointer, 2, GL_FLOAT, sizeof(vtx), base + offsetof(vtx, tc));
    G(BindBuffer, GL_ARRAY_BUFFER, 0); /* the arrays keep their binding (2.9.1) */
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(EnableClientState, GL_COLOR_ARRAY);
    G(ClearColor, 0.1f, 0.2f, 0.3f, 1.0f);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(DrawArrays, GL_TRIANGLE_STRIP, 2, 9);
    /* indices from the element buffer, after 6 bytes of other data */
    static const GLushort idx[9] = {0, 5, 9, 12, 3, 17, 20, 22, 8};
    G(BindBuffer, GL_ELEMENT_ARRAY_BUFFER, b[1]);
    G(BufferData, GL_ELEMENT_ARRAY_BUFFER, 6 + sizeof idx, NULL, GL_STATIC_DRAW);
    unsigned short *m = GR(MapBuffer, GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY);
    if (m)
        memcpy((char *)m + 6, idx, sizeof idx);
    G(UnmapBuffer, GL_ELEMENT_ARRAY_BUFFER);
    G(DrawElements, GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, (const void *)6);
    /* lit, with normals from the buffer */
    G(Enable, GL_LIGHTING);
    G(Enable, GL_LIGHT0);
    G(EnableClientState, GL_NORMAL_ARRAY);
    G(DisableClientState, GL_COLOR_ARRAY);
    G(Translatef, 0.1f, -0.05f, 0.0f);
    G(DrawRangeElements, GL_TRIANGLES, 0, 22, 6, GL_UNSIGNED_SHORT, (const void *)8);
    G(Disable, GL_LIGHTING);
    /* textured, with texture coordinates from the buffer */
    static const unsigned char tex[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    G(TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    G(Enable, GL_TEXTURE_2D);
    G(EnableClientState, GL_TEXTURE_COORD_ARRAY);
    G(Translatef, -0.2f, 0.1f, 0.0f);
    G(DrawArrays, GL_TRIANGLE_FAN, 10, 7);
    G(DeleteBuffers, 2, b);
}

TEST(draws_from_buffers_match_osmesa)
{
    osm_pair p;
    REQUIRE(osm_pair_render(&p, 64, 48, NULL, draw_from_buffers, NULL));
    CHECK_EQ_INT(p.d.differ, 0);
    long lit = 0;
    for (long i = 0; i < 64 * 48; i++)
        lit += memcmp(p.ref.color + 4 * i, p.ref.color, 4) != 0;
    CHECK(lit > 200); /* the draws drew (the corner is background) */
    CHECK_EQ_INT(fsglGetError(p.c), GL_NO_ERROR);
    osm_pair_close(&p);
}

/* A draw past a buffer's store, or sourcing a deleted buffer, reads
 * nothing (GL leaves it undefined; Mesa draws nothing there either). */
TEST(draws_past_the_store_read_nothing)
{
    fs_context *c = fs_context_create(NULL, 16, 16);
    REQUIRE(c);
    static const float v[6] = {-1, -1, 1, -1, 0, 1};
    GLuint b[2];
    fsglGenBuffers(c, 2, b);
    fsglBindBuffer(c, GL_ARRAY_BUFFER, b[0]);
    fsglBufferData(c, GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
    fsglVertexPointer(c, 2, GL_FLOAT, 0, NULL);
    fsglEnableClientState(c, GL_VERTEX_ARRAY);
    fsglDrawArrays(c, GL_TRIANGLES, 1, 3); /* vertex 3 is past the store */
    fsglVertexPointer(c, 2, GL_FLOAT, 0, (const void *)4096);
    fsglDrawArrays(c, GL_TRIANGLES, 0, 3); /* the offset is past it */
    static const GLubyte idx[3] = {0, 1, 2};
    fsglBindBuffer(c, GL_ELEMENT_ARRAY_BUFFER, b[1]);
    fsglBufferData(c, GL_ELEMENT_ARRAY_BUFFER, 3, idx, GL_STATIC_DRAW);
    fsglVertexPointer(c, 2, GL_FLOAT, 0, NULL);
    fsglDrawElements(c, GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, (const void *)1); /* indices past it */
    fsglDeleteBuffers(c, 1, &b[0]);
    fsglDrawElements(c, GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, NULL); /* the array's buffer is gone */
    CHECK_EQ_INT(c->stats.fragments_written, 0);
    CHECK_EQ_INT(fsglGetError(c), GL_NO_ERROR);
    CHECK(c->stats.unsupported_calls >= 4);
    /* and the same draw with everything in place does draw */
    fsglGenBuffers(c, 1, &b[0]);
    fsglBindBuffer(c, GL_ARRAY_BUFFER, b[0]);
    fsglBufferData(c, GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
    fsglVertexPointer(c, 2, GL_FLOAT, 0, NULL);
    fsglDrawElements(c, GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, NULL);
    CHECK(c->stats.fragments_written > 0);
    fs_context_destroy(c);
}

/* ---- a trace as apitrace records a VBO program ---- */
#define uval tb_opaque
#define bval tb_blob

static void tcall(fs_trace_writer *w, const char *name, int n, const fs_tval *args)
{
    tb_write_call(w, name, n, args, 0);
}

/* glMapBuffer(target, access) = addr, as the traced program saw it. */
static void tmap(fs_trace_writer *w, GLenum target, uint64_t addr)
{
    fs_tval a[2] = {tb_eval(target, target == GL_ARRAY_BUFFER ? "GL_ARRAY_BUFFER" : "GL_ELEMENT_ARRAY_BUFFER"),
                    tb_eval(GL_WRITE_ONLY, "GL_WRITE_ONLY")};
    fs_tval ret = tb_opaque(addr);
    tb_write_call_ret(w, "glMapBuffer", 2, a, 0, &ret);
}

static void tmemcpy(fs_trace_writer *w, uint64_t dest, const void *src, size_t n)
{
    fs_tval a[3] = {uval(dest), bval(src, n), tb_ival((int64_t)n)};
    tb_write_call(w, "memcpy", 3, a, 1 /* fake */);
}

static const float tri_v[4][2] = {{-0.9f, -0.8f}, {0.7f, -0.9f}, {0.1f, 0.85f}, {-0.6f, 0.5f}};
static const GLushort tri_i[6] = {0, 1, 2, 0, 2, 3};

/* Two buffers mapped at once (vertices at 0x7000, indices at 0x9000),
 * written by memcpy at an offset, a draw of the indices by offset, and a
 * memcpy outside every mapping. */
static bool write_vbo_trace(const char *path)
{
    char err[256];
    fs_trace_writer *w = fs_trace_create(path, err, sizeof err);
    if (!w)
        return false;
    fs_tval vp[4] = {tb_ival(0), tb_ival(0), tb_ival(32), tb_ival(32)};
    tcall(w, "glViewport", 4, vp);
    fs_tval gen[2] = {tb_ival(2), tb_ival(0)};
    fs_tval names = {0};
    fs_tval elems[2] = {tb_ival(1), tb_ival(2)};
    names.type = FS_TV_ARRAY;
    names.arr.n = 2;
    names.arr.elems = elems;
    gen[1] = names;
    tcall(w, "glGenBuffers", 2, gen);
    fs_tval bind_a[2] = {tb_eval(GL_ARRAY_BUFFER, "GL_ARRAY_BUFFER"), tb_ival(1)};
    fs_tval bind_e[2] = {tb_eval(GL_ELEMENT_ARRAY_BUFFER, "GL_ELEMENT_ARRAY_BUFFER"), tb_ival(2)};
    tcall(w, "glBindBuffer", 2, bind_a);
    tcall(w, "glBindBuffer", 2, bind_e);
    fs_tval data_a[4] = {bind_a[0], tb_ival(16 + sizeof tri_v), tb_ival(0), tb_eval(GL_STATIC_DRAW, "GL_STATIC_DRAW")};
    data_a[2].type = FS_TV_NULL;
    tcall(w, "glBufferData", 4, data_a);
    fs_tval data_e[4] = {bind_e[0], tb_ival(sizeof tri_i), tb_ival(0), tb_eval(GL_STATIC_DRAW, "GL_STATIC_DRAW")};
    data_e[2].type = FS_TV_NULL;
    tcall(w, "glBufferData", 4, data_e);
    tmap(w, GL_ARRAY_BUFFER, 0x7000);
    tmap(w, GL_ELEMENT_ARRAY_BUFFER, 0x9000);
    tmemcpy(w, 0x9000, tri_i, sizeof tri_i);
    tmemcpy(w, 0x7000 + 16, tri_v, sizeof tri_v);
    tmemcpy(w, 0x5000, tri_v, 8); /* below every mapping */
    fs_tval un_a[1] = {bind_a[0]}, un_e[1] = {bind_e[0]};
    tcall(w, "glUnmapBuffer", 1, un_e);
    tcall(w, "glUnmapBuffer", 1, un_a);
    tmemcpy(w, 0x7000, tri_v, 8); /* after the unmap: outside every mapping */
    fs_tval ptr[4] = {tb_ival(2), tb_eval(GL_FLOAT, "GL_FLOAT"), tb_ival(0), uval(16)};
    tcall(w, "glVertexPointer", 4, ptr);
    fs_tval en = tb_eval(GL_VERTEX_ARRAY, "GL_VERTEX_ARRAY");
    tcall(w, "glEnableClientState", 1, &en);
    fs_tval de[4] = {tb_eval(GL_TRIANGLES, "GL_TRIANGLES"), tb_ival(3), tb_eval(GL_UNSIGNED_SHORT, "GL_UNSIGNED_SHORT"),
                     uval(6)};
    tcall(w, "glDrawElements", 4, de); /* the second triangle, by offset */
    de[1] = tb_ival(3);
    de[3].type = FS_TV_NULL;
    fs_tval col[3] = {tb_fval(0.2), tb_fval(0.9), tb_fval(0.4)};
    tcall(w, "glColor3f", 3, col);
    tcall(w, "glDrawElements", 4, de); /* the first, at offset 0 */
    tcall(w, "glFinish", 0, NULL);
    return fs_trace_finish(w) == 0;
}

static void draw_vbo_reference(void)
{
    glViewport(0, 0, 32, 32);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, tri_v);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, tri_i + 3);
    glColor3f(0.2f, 0.9f, 0.4f);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, tri_i);
}

static uint64_t feature_count(const fs_context *c, const char *name)
{
    for (int i = 0; i < c->unsupported_feature_count; i++)
        if (strcmp(c->unsupported_feature[i].name, name) == 0)
            return c->unsupported_feature[i].count;
    return 0;
}

/* Replays the trace at path on a new w x h model context (NULL when it
 * cannot be opened); *ok is false when a call was malformed. */
static fs_context *replay_on_model(const char *path, size_t max_record, int w, int h, bool *ok)
{
    char err[512];
    fs_replay_opts opts = {NULL, 0, 0, max_record};
    fs_replayer *r = fs_replay_open(path, &opts, err, sizeof err);
    fs_context *c = r ? fs_context_create(NULL, w, h) : NULL;
    *ok = c != NULL;
    fs_call call;
    fs_replay_event ev = FS_REPLAY_EOF;
    while (c && (ev = fs_replay_next(r, &call)) != FS_REPLAY_EOF && ev != FS_REPLAY_ERROR)
        if (ev == FS_REPLAY_CALL && fs_submit(c, &call) != 0)
            *ok = false;
    *ok = *ok && ev == FS_REPLAY_EOF;
    fs_replay_close(r);
    return c;
}

/* Replays path on the model (pass 2 from the file or from pass 1's
 * record) and checks: every call well-formed, no GL error, the image ref.
 * Returns the context (NULL when the trace could not be replayed). */
static fs_context *replay_and_compare(check_state *check_st_, const char *path, int from_file, const uint8_t *ref,
                                      int w, int h)
{
    bool ok;
    fs_context *c = replay_on_model(path, from_file ? 1 : 0, w, h, &ok);
    if (!c)
        return NULL;
    CHECK(ok);
    img_diff d = {0, 0, 0, 0};
    img_compare(c->fb.color, ref, (long)w * h, &d);
    CHECK_EQ_INT(d.differ, 0);
    CHECK_EQ_INT(c->stats.gl_errors, 0);
    return c;
}

TEST(replayed_vbo_trace_with_memcpy_matches_osmesa)
{
    char path[128];
    snprintf(path, sizeof path, "/tmp/fragsim_test_vbo_%d.trace", (int)getpid());
    REQUIRE(write_vbo_trace(path));
    osm o;
    REQUIRE(osm_open(&o, 32, 32));
    draw_vbo_reference();
    glFinish();
    /* Both ways pass 2 replays: from pass 1's record and from the file. */
    for (int from_file = 0; from_file < 2; from_file++) {
        fs_context *c = replay_and_compare(check_st_, path, from_file, o.color, 32, 32);
        REQUIRE(c);
        CHECK(c->stats.fragments_written > 100);
        CHECK_EQ_INT(feature_count(c, "memcpy (outside every mapped buffer)"), 2);
        fs_context_destroy(c);
    }
    osm_close(&o);
    unlink(path);
}

/* A program drawing from buffers, captured (the writes through its
 * mapping as memcpy, its pointers and indices as offsets, no fake pointer
 * calls for them), replays to the same image. */
TEST(captured_vbo_program_replays_the_same)
{
    char path[128], err[256];
    snprintf(path, sizeof path, "/tmp/fragsim_test_vbo_capture_%d.trace", (int)getpid());
    fs_context *c = fs_context_create(NULL, 64, 48);
    REQUIRE(c);
    REQUIRE(fs_capture_open(c, path, err, sizeof err) == 0);
    fsglViewport(c, 0, 0, 64, 48); /* replay takes the window size from it */
    draw_from_buffers(c, NULL, 64, 48);
    fsglFinish(c);
    CHECK_EQ_INT(fs_capture_close(c), 0);
    for (int from_file = 0; from_file < 2; from_file++) {
        fs_context *r = replay_and_compare(check_st_, path, from_file, c->fb.color, 64, 48);
        REQUIRE(r);
        CHECK_EQ_INT(r->stats.unsupported_calls, 0);
        fs_context_destroy(r);
    }
    fs_context_destroy(c);
    unlink(path);
}

TEST_LIST = {
    TEST_ENTRY(names_and_errors_match_osmesa),
    TEST_ENTRY(data_and_mapping_match_osmesa),
    TEST_ENTRY(bindings_push_pop_and_delete_match_osmesa),
    TEST_ENTRY(map_buffer_range_vs_osmesa),
    TEST_ENTRY(huge_buffer_data_is_out_of_memory),
    TEST_ENTRY(draws_from_buffers_match_osmesa),
    TEST_ENTRY(draws_past_the_store_read_nothing),
    TEST_ENTRY(replayed_vbo_trace_with_memcpy_matches_osmesa),
    TEST_ENTRY(captured_vbo_program_replays_the_same),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
