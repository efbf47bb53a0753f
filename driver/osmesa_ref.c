/* The OSMesa reference dispatcher: see osmesa_ref.h.  Generated from the
 * same command table as the model's dispatcher. */
/* The GL 1.5 query entry points are declared by GL/glext.h only with
 * prototypes requested, before GL/gl.h is first included. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "osmesa_ref.h"
#include "gl_call_unpack.h"
#include "../pipeline/pixel_transfer.h"

struct fs_osmesa {
    OSMesaContext ctx;
    int width, height, depth_bits;
    uint8_t *color;
    uint32_t *depth;
    void *scratch;
    size_t scratch_size;
    GLuint query; /* per-frame GL_SAMPLES_PASSED query of `fragsim check` */
    bool query_active;
};

fs_osmesa *fs_osmesa_create(int width, int height, int depth_bits, int stencil_bits, char *err, size_t errlen)
{
    fs_osmesa *o = calloc(1, sizeof *o);
    if (!o || width <= 0 || height <= 0) {
        snprintf(err, errlen, "osmesa: bad size %dx%d or out of memory", width, height);
        free(o);
        return NULL;
    }
    o->width = width;
    o->height = height;
    o->depth_bits = depth_bits;
    o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth_bits, stencil_bits, 0, NULL);
    o->color = calloc((size_t)width * (size_t)height, 4);
    o->depth = calloc((size_t)width * (size_t)height, sizeof *o->depth);
    if (!o->ctx || !o->color || !o->depth ||
        !OSMesaMakeCurrent(o->ctx, o->color, GL_UNSIGNED_BYTE, width, height)) {
        snprintf(err, errlen, "osmesa: cannot create a %dx%d context", width, height);
        fs_osmesa_destroy(o);
        return NULL;
    }
    return o;
}

static void *scratch(fs_osmesa *o, size_t bytes)
{
    if (bytes > o->scratch_size) {
        void *p = realloc(o->scratch, bytes);
        if (!p)
            return NULL;
        o->scratch = p;
        o->scratch_size = bytes;
    }
    return o->scratch;
}

/* OSMesa's own pixel-store state of one direction (unpack: pack = false),
 * which the same call stream sets. */
static fs_pixel_store osm_pixel_store(bool pack)
{
    static const GLenum names[2][8] = {
        {GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS,
         GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES},
        {GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_ROWS, GL_PACK_SWAP_BYTES,
         GL_PACK_LSB_FIRST, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES},
    };
    GLint v[8] = {4, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 8; k++)
        glGetIntegerv(names[pack][k], &v[k]);
    return (fs_pixel_store){.alignment = v[0], .row_length = v[1], .skip_pixels = v[2], .skip_rows = v[3],
                            .swap_bytes = v[4] != 0, .lsb_first = v[5] != 0, .image_height = v[6],
                            .skip_images = v[7]};
}

/* glReadPixels, glTexImage2D and glGetTexImage read or write by OSMesa's
 * own pixel-store state: ask it, and size the image as the model does
 * (pipeline/pixel_transfer.h).  A pair GL 1.5 does not have (Mesa takes
 * more, e.g. half floats) is sized as the largest group, RGBA floats, so
 * that OSMesa never reads or writes past the buffer. */
static int64_t osm_image_nd_bytes(bool pack, int dims, GLsizei w, GLsizei h, GLsizei d, GLenum format, GLenum type)
{
    fs_pixel_store ps = osm_pixel_store(pack);
    int64_t n = fs_pixel_image_bytes(&ps, dims, w, h, d, format, type);
    return n || w <= 0 || h <= 0 || d <= 0 ? n : fs_pixel_image_bytes(&ps, dims, w, h, d, GL_RGBA, GL_FLOAT);
}

static int64_t osm_image_bytes(bool pack, GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    return osm_image_nd_bytes(pack, 2, w, h, 1, format, type);
}

static int64_t osm_readpixels_bytes(GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    return osm_image_bytes(true, w, h, format, type);
}

static int64_t osm_teximage_bytes(GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    return osm_image_bytes(false, w, h, format, type);
}

/* The size OSMesa has for a pixel map (glGetPixelMap* writes that many). */
static int osm_pixel_map_size(GLenum map)
{
    GLint n = 0;
    if (map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A)
        glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE + (map - GL_PIXEL_MAP_I_TO_I), &n);
    return n;
}

static int64_t osm_gettex_bytes(GLenum target, GLint level, GLenum format, GLenum type)
{
    GLint w = 0, h = 0, d = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_DEPTH, &d);
    return osm_image_nd_bytes(true, target == GL_TEXTURE_3D ? 3 : target == GL_TEXTURE_1D ? 1 : 2, w, h, d, format,
                              type);
}

/* The bytes OSMesa's glGetCompressedTexImage writes: its level's
 * compressed size (0 for a level that is not compressed; the query's
 * error is not the trace's). */
static int64_t osm_getcompressed_bytes(GLenum target, GLint level)
{
    GLint compressed = 0, size = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_COMPRESSED, &compressed);
    if (compressed)
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
    while (glGetError() != GL_NO_ERROR)
        ;
    return compressed ? size : 0;
}

/* The values OSMesa's glGetMap writes: GL_COEFF's count from its own
 * orders (evaluator targets are GL_MAP1_* and GL_MAP2_*, table 5.1). */
static int osm_getmap_count(GLenum target, GLenum query)
{
    static const int comps[9] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
    bool map2 = target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4;
    if (!map2 && !(target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4))
        return 0;
    if (query == GL_ORDER || query == GL_DOMAIN)
        return (map2 ? 2 : 1) * (query == GL_DOMAIN ? 2 : 1);
    if (query != GL_COEFF)
        return 0;
    GLint order[2] = {1, 1};
    glGetMapiv(target, GL_ORDER, order);
    return order[0] * (map2 ? order[1] : 1) * comps[target - (map2 ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4)];
}

/* A recorded address (FS_ARG_ADDR) reaching here is an offset into a
 * buffer OSMesa has bound (osm_addresses). */
#define FS_OCK_ARR(k, name, cnt) \
    if (call->a[k].is_data != FS_ARG_ADDR && (int64_t)(cnt) > 0 && \
        (name == NULL || (int64_t)call->a[k].count < (int64_t)(cnt))) return -1;
#define FS_OCK_OUT(k, name, cnt, esize) \
    if (name == NULL) {                                                       \
        int64_t need_ = (int64_t)(cnt) > 16 ? (int64_t)(cnt) : 16;            \
        name = scratch(o, (size_t)need_ * (esize));                            \
        if (name == NULL) return -1;                                           \
    }
#define FS_OCK_NONE(k, name, cnt)
#define FS_OCK_E FS_OCK_NONE
#define FS_OCK_BM FS_OCK_NONE
#define FS_OCK_B FS_OCK_NONE
#define FS_OCK_I FS_OCK_NONE
#define FS_OCK_U FS_OCK_NONE
#define FS_OCK_SZ FS_OCK_NONE
#define FS_OCK_UB FS_OCK_NONE
#define FS_OCK_BY FS_OCK_NONE
#define FS_OCK_S FS_OCK_NONE
#define FS_OCK_US FS_OCK_NONE
#define FS_OCK_F FS_OCK_NONE
#define FS_OCK_D FS_OCK_NONE
#define FS_OCK_CF FS_OCK_NONE
#define FS_OCK_CD FS_OCK_NONE
#define FS_OCK_CPTR FS_OCK_NONE
#define FS_OCK_IP FS_OCK_NONE
#define FS_OCK_AF FS_OCK_ARR
#define FS_OCK_AD FS_OCK_ARR
#define FS_OCK_AI FS_OCK_ARR
#define FS_OCK_AU FS_OCK_ARR
#define FS_OCK_AUB FS_OCK_ARR
#define FS_OCK_ABY FS_OCK_ARR
#define FS_OCK_AS FS_OCK_ARR
#define FS_OCK_AUS FS_OCK_ARR
#define FS_OCK_BLOB FS_OCK_ARR
#define FS_OCK_AP(k, name, cnt) \
    if ((int64_t)(cnt) > 0 && (name == NULL || (int64_t)call->a[k].count < (int64_t)(cnt))) return -1;
#define FS_OCK_OV(k, name, cnt) FS_OCK_OUT(k, name, cnt, 1)
#define FS_OCK_OF(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLfloat))
#define FS_OCK_OD(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLdouble))
#define FS_OCK_OI(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLint))
#define FS_OCK_OU(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLuint))
#define FS_OCK_OUS(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLushort))
#define FS_OCK_OB(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLboolean))
#define FS_OCK_OUB(k, name, cnt) FS_OCK_OUT(k, name, cnt, 1)
#define FS_OCK_OP(k, name, cnt) FS_OCK_OUT(k, name, cnt, sizeof(GLvoid *))
#define FS_OCHECK(k, kind, name, cnt) FS_OCK_##kind(k, name, cnt)
#define fs_readpixels_bytes(c, w, h, f, t) osm_readpixels_bytes(w, h, f, t)
#define fs_teximage_bytes(c, w, h, f, t) osm_teximage_bytes(w, h, f, t)
#define fs_teximage_nd_bytes(c, n, w, h, d, f, t) osm_image_nd_bytes(false, n, w, h, d, f, t)
#define fs_gettexImage_bytes(c, tg, l, f, t) osm_gettex_bytes(tg, l, f, t)
#define fs_getcompressed_bytes(c, tg, l) osm_getcompressed_bytes(tg, l)
#define fs_getmap_count(c, tg, q) osm_getmap_count(tg, q)
#define fs_pixel_map_size(c, map) osm_pixel_map_size(map)
#define FS_OCALL_V(e) e
#define FS_OCALL_U(e) (void)(e)
#define FS_OCALL_E(e) (void)(e)
#define FS_OCALL_B(e) (void)(e)
#define FS_OCALL_I(e) (void)(e)
#define FS_OCALL_STR(e) (void)(e)
#define FS_OCALL_P(e) (void)(e)

/* glTraceMemcpy (a write through a mapping, from a trace): into OSMesa's
 * own mapping of the buffer, found by binding it to GL_ARRAY_BUFFER for
 * the query; outside it nothing is written, as in the model. */
static int osm_TraceMemcpy(const fs_call *call)
{
    GLint was = 0, size = 0;
    void *p = NULL;
    int64_t off = call->a[1].i, n = call->a[2].i;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &was);
    glBindBuffer(GL_ARRAY_BUFFER, (GLuint)call->a[0].i);
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
    glBindBuffer(GL_ARRAY_BUFFER, (GLuint)was);
    while (glGetError() != GL_NO_ERROR)
        ; /* buffer 0 or no buffer: the queries' errors are not the trace's */
    if (!p || off < 0 || n < 0 || off > size || n > size - off || (uint64_t)n > call->a[3].count)
        return -1;
    memcpy((char *)p + off, call->a[3].p, (size_t)n);
    return 0;
}

/* Addresses a trace recorded: offsets into the buffer OSMesa has bound to
 * the target (GL 1.5 spec 2.9.1, 2.9.2), else the traced program's memory,
 * which is never passed on: a pointer becomes NULL, a draw with such
 * indices is not executed (false). */
static bool osm_addresses(const fs_call *call, fs_call *local)
{
    int pk, slot = fs_pointer_slot(call->cmd, &pk);
    int k = call->cmd == FS_CMD_DrawElements ? 3 : call->cmd == FS_CMD_DrawRangeElements ? 5 : -1;
    if (call->cmd == FS_CMD_MultiDrawElements || call->cmd == FS_CMD_InterleavedArrays)
        k = call->cmd == FS_CMD_MultiDrawElements ? 3 : 2; /* every draw's indices; the block */
    if (slot >= 0)
        k = pk;
    if (k < 0 || call->a[k].is_data != FS_ARG_ADDR)
        return true;
    GLint bound = 0;
    glGetIntegerv(slot >= 0 || call->cmd == FS_CMD_InterleavedArrays ? GL_ARRAY_BUFFER_BINDING : GL_ELEMENT_ARRAY_BUFFER_BINDING, &bound);
    if (bound)
        return true;
    if (slot < 0 && call->cmd != FS_CMD_InterleavedArrays)
        return false;
    *local = *call;
    local->a[k].p = NULL;
    local->a[k].is_data = 0;
    return true;
}

int fs_osmesa_dispatch(fs_osmesa *o, const fs_call *in)
{
    fs_call fixed;
    const fs_call *call = in;
    fixed.cmd = FS_CMD_COUNT;
    if (!osm_addresses(in, &fixed))
        return -1;
    if (fixed.cmd != FS_CMD_COUNT)
        call = &fixed;
    switch ((enum fs_cmd)call->cmd) {
#define FS_CMD(name, rk, flags, n, ...)                                        \
    case FS_CMD_##name: {                                                       \
        FS_MAP(n, FS_LOCAL, __VA_ARGS__)                                        \
        FS_MAP(n, FS_OCHECK, __VA_ARGS__)                                       \
        FS_OCALL_##rk(gl##name(FS_CALL_ARGS(0 FS_MAP(n, FS_ANAME, __VA_ARGS__)))); \
        return 0;                                                               \
    }
/* fragsim's own extension commands do not exist in OSMesa: not executed. */
#define FS_CMD_EXT(name, rk, flags, n, ...) \
    case FS_CMD_##name:                     \
        return -1;
#define FS_CMD_TRACE(name, rk, flags, n, ...) \
    case FS_CMD_##name:                       \
        return osm_##name(call);
#include "gl_commands.def"
#undef FS_CMD_TRACE
#undef FS_CMD_EXT
#undef FS_CMD
    case FS_CMD_COUNT:
        break;
    }
    return -1;
}
#undef fs_readpixels_bytes
#undef fs_teximage_bytes
#undef fs_teximage_nd_bytes
#undef fs_gettexImage_bytes
#undef fs_getmap_count
#undef fs_pixel_map_size

const uint8_t *fs_osmesa_color(fs_osmesa *o)
{
    glFinish();
    return o->color;
}

const uint32_t *fs_osmesa_depth(fs_osmesa *o)
{
    GLint w, h, bpv;
    void *buf;
    glFinish();
    if (!OSMesaGetDepthBuffer(o->ctx, &w, &h, &bpv, &buf) || w != o->width || h != o->height)
        return NULL;
    size_t n = (size_t)w * (size_t)h;
    uint32_t mask = o->depth_bits >= 32 ? 0xffffffffu : (1u << o->depth_bits) - 1;
    for (size_t i = 0; i < n; i++) {
        /* The notes measured 4 bytes per value with the depth in the low bits. */
        uint32_t v;
        if (bpv == 2) {
            uint16_t s;
            memcpy(&s, (const char *)buf + 2 * i, 2);
            v = s;
        } else {
            memcpy(&v, (const char *)buf + 4 * i, 4);
        }
        o->depth[i] = v & mask;
    }
    return o->depth;
}

void fs_osmesa_samples_begin(fs_osmesa *o)
{
    if (!o->query)
        glGenQueries(1, &o->query);
    glBeginQuery(GL_SAMPLES_PASSED, o->query);
    o->query_active = true;
}

int64_t fs_osmesa_samples_end(fs_osmesa *o)
{
    GLuint n = 0; /* libOSMesa exports the GL 1.5 query, not the 64-bit one */
    glEndQuery(GL_SAMPLES_PASSED);
    o->query_active = false;
    glGetQueryObjectuiv(o->query, GL_QUERY_RESULT, &n);
    return glGetError() == GL_NO_ERROR ? (int64_t)n : -1;
}

void fs_osmesa_destroy(fs_osmesa *o)
{
    if (!o)
        return;
    if (o->ctx && o->query) {
        /* llvmpipe's rasterizer threads still write to an active query:
         * end it and wait for them before the context frees it. */
        if (o->query_active)
            glEndQuery(GL_SAMPLES_PASSED);
        glFinish();
        glDeleteQueries(1, &o->query);
    }
    if (o->ctx)
        OSMesaDestroyContext(o->ctx);
    free(o->color);
    free(o->depth);
    free(o->scratch);
    free(o);
}
