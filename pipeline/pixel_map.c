/*
 * Pixel transfer (GL 1.5 spec 3.6.3, 3.6.5; see pixel_map.h):
 * glPixelTransfer{i,f}, glPixelMap{fv,uiv,usv}, glGetPixelMap{fv,uiv,usv}
 * and the operations on pixel groups.
 *
 * Measured through libOSMesa (tests/test_pixel_map.c), where the spec
 * leaves the value or Mesa differs from it:
 * - glPixelMap*: mapsize outside [1, GL_MAX_PIXEL_MAP_TABLE] is
 *   INVALID_VALUE before the map is looked at, an unknown map then
 *   INVALID_ENUM; the power-of-two rule (3.6.3) holds for S_TO_S and
 *   I_TO_R..I_TO_A but not for I_TO_I.
 * - Stored values: colour maps clamp to [0, 1]; S_TO_S from floats is
 *   rounded half away from zero; integer forms convert colour entries as
 *   c / (2^b - 1) and index entries as plain numbers.
 * - glGetPixelMapuiv gives trunc(v * (2^32 - 1)) modulo 2^32 for every map
 *   but S_TO_S, whose entries come back as the bits of their floats;
 *   glGetPixelMapusv rounds colour entries times 65535 and clamps index
 *   entries to [0, 65535].
 */
#include <math.h>
#include <string.h>
#include "pixel_map.h"
#include "context.h"
#include "pixel_transfer.h"

/* ---- state ---- */

void fs_exec_PixelTransferf(fs_context *c, GLenum pname, GLfloat param)
{
    fs_pixel_xfer *x = &c->px;
    switch (pname) {
    case GL_MAP_COLOR: x->map_color = param != 0.0f; break;
    case GL_MAP_STENCIL: x->map_stencil = param != 0.0f; break;
    /* Integer state takes the float truncated, as Mesa converts it. */
    case GL_INDEX_SHIFT: x->index_shift = (GLint)fmaxf(fminf(param, 2147483520.0f), -2147483648.0f); break;
    case GL_INDEX_OFFSET: x->index_offset = (GLint)fmaxf(fminf(param, 2147483520.0f), -2147483648.0f); break;
    case GL_RED_SCALE: x->scale[0] = param; break;
    case GL_GREEN_SCALE: x->scale[1] = param; break;
    case GL_BLUE_SCALE: x->scale[2] = param; break;
    case GL_ALPHA_SCALE: x->scale[3] = param; break;
    case GL_RED_BIAS: x->bias[0] = param; break;
    case GL_GREEN_BIAS: x->bias[1] = param; break;
    case GL_BLUE_BIAS: x->bias[2] = param; break;
    case GL_ALPHA_BIAS: x->bias[3] = param; break;
    case GL_DEPTH_SCALE: x->depth_scale = param; break;
    case GL_DEPTH_BIAS: x->depth_bias = param; break;
    default: fs_error(c, GL_INVALID_ENUM); return;
    }
    fs_state_mark(c, GL_PIXEL_MODE_BIT);
}

void fs_exec_PixelTransferi(fs_context *c, GLenum pname, GLint param)
{
    fs_exec_PixelTransferf(c, pname, (GLfloat)param); /* as Mesa converts it */
}

/* The index of a map enum, -1 for another enum. */
static int map_index(GLenum map)
{
    return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A ? (int)(map - GL_PIXEL_MAP_I_TO_I) : -1;
}

static bool is_color_map(int m) { return m >= FS_MAP_I_TO_R; }

int fs_pixel_map_count(GLsizei mapsize)
{
    return mapsize >= 1 && mapsize <= FS_PIXEL_MAP_MAX ? mapsize : 0;
}

int fs_pixel_map_size(const fs_context *c, GLenum map)
{
    int m = map_index(map);
    return m < 0 ? 0 : c->px.size[m];
}

/* The checks of glPixelMap* in Mesa's order (see the file comment); the
 * map's index, or -1 with the error set. */
static int map_to_store(fs_context *c, GLenum map, GLsizei mapsize)
{
    if (mapsize < 1 || mapsize > FS_PIXEL_MAP_MAX) {
        fs_error(c, GL_INVALID_VALUE);
        return -1;
    }
    int m = map_index(map);
    if (m < 0) {
        fs_error(c, GL_INVALID_ENUM);
        return -1;
    }
    if (m != FS_MAP_I_TO_I && m <= FS_MAP_I_TO_A && (mapsize & (mapsize - 1)) != 0) {
        fs_error(c, GL_INVALID_VALUE);
        return -1;
    }
    c->px.size[m] = mapsize;
    fs_state_mark(c, GL_PIXEL_MODE_BIT);
    return m;
}

static float clamp01(float f) { return f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f; }

void fs_exec_PixelMapfv(fs_context *c, GLenum map, GLsizei mapsize, const GLfloat *values)
{
    int m = map_to_store(c, map, mapsize);
    if (m < 0 || !values)
        return;
    for (int i = 0; i < mapsize; i++)
        c->px.map[m][i] = is_color_map(m) ? clamp01(values[i]) : m == FS_MAP_S_TO_S ? roundf(values[i]) : values[i];
}

void fs_exec_PixelMapuiv(fs_context *c, GLenum map, GLsizei mapsize, const GLuint *values)
{
    int m = map_to_store(c, map, mapsize);
    if (m < 0 || !values)
        return;
    for (int i = 0; i < mapsize; i++)
        c->px.map[m][i] = is_color_map(m) ? (float)((double)values[i] / 4294967295.0) : (float)values[i];
}

void fs_exec_PixelMapusv(fs_context *c, GLenum map, GLsizei mapsize, const GLushort *values)
{
    int m = map_to_store(c, map, mapsize);
    if (m < 0 || !values)
        return;
    for (int i = 0; i < mapsize; i++)
        c->px.map[m][i] = is_color_map(m) ? (float)values[i] * (1.0f / 65535.0f) : (float)values[i];
}

/* The map glGetPixelMap* reads, NULL with INVALID_ENUM for another enum. */
static const float *map_to_get(fs_context *c, GLenum map, int *m)
{
    *m = map_index(map);
    if (*m < 0) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    return c->px.map[*m];
}

void fs_exec_GetPixelMapfv(fs_context *c, GLenum map, GLfloat *values)
{
    int m;
    const float *t = map_to_get(c, map, &m);
    if (t && values)
        memcpy(values, t, (size_t)c->px.size[m] * sizeof *values);
}

/* v * (2^32 - 1) truncated, modulo 2^32 (the low half of the 64-bit
 * integer; beyond 2^63 and for NaN that integer is x86's 2^63, whose low
 * half is 0). */
static GLuint float_to_uint_bits(float v)
{
    double d = (double)v * 4294967295.0;
    if (!(d > -9223372036854775808.0 && d < 9223372036854775808.0))
        return 0;
    return (GLuint)(uint64_t)(int64_t)d;
}

void fs_exec_GetPixelMapuiv(fs_context *c, GLenum map, GLuint *values)
{
    int m;
    const float *t = map_to_get(c, map, &m);
    if (!t || !values)
        return;
    for (int i = 0; i < c->px.size[m]; i++) {
        if (m == FS_MAP_S_TO_S)
            memcpy(&values[i], &t[i], sizeof values[i]);
        else
            values[i] = float_to_uint_bits(t[i]);
    }
}

void fs_exec_GetPixelMapusv(fs_context *c, GLenum map, GLushort *values)
{
    int m;
    const float *t = map_to_get(c, map, &m);
    if (!t || !values)
        return;
    for (int i = 0; i < c->px.size[m]; i++) {
        float v = t[i];
        if (is_color_map(m))
            values[i] = (GLushort)lrintf(clamp01(v) * 65535.0f); /* ties to even */
        else
            values[i] = (GLushort)(v > 0.0f ? (v < 65535.0f ? v : 65535.0f) : 0.0f);
    }
}

/* ---- the operations (3.6.5) ---- */

bool fs_pixel_xfer_color(const fs_context *c)
{
    const fs_pixel_xfer *x = &c->px;
    for (int k = 0; k < 4; k++)
        if (x->scale[k] != 1.0f || x->bias[k] != 0.0f)
            return true;
    return x->map_color;
}

bool fs_pixel_xfer_depth(const fs_context *c)
{
    return c->px.depth_scale != 1.0f || c->px.depth_bias != 0.0f;
}

bool fs_pixel_xfer_stencil(const fs_context *c)
{
    return c->px.index_shift != 0 || c->px.index_offset != 0 || c->px.map_stencil;
}

/* A lookup in a colour map of component c in [0, 1]: entry
 * round(c * (size - 1)) (3.6.5), a tie rounded to even as llvmpipe's
 * results show. */
static float lookup(const fs_pixel_xfer *x, int m, float v)
{
    int i = (int)lrintf(clamp01(v) * (float)(x->size[m] - 1));
    return x->map[m][i];
}

void fs_pixel_xfer_rgba(const fs_context *c, float *rgba, int64_t n)
{
    const fs_pixel_xfer *x = &c->px;
    for (int64_t i = 0; i < n; i++, rgba += 4)
        for (int k = 0; k < 4; k++) {
            float v = rgba[k] * x->scale[k] + x->bias[k];
            rgba[k] = x->map_color ? lookup(x, FS_MAP_R_TO_R + k, v) : v;
        }
}

/* An index shifted (left for a positive shift) and offset (3.6.5
 * "Arithmetic on Indices"), in 32-bit unsigned arithmetic. */
static uint32_t shift_offset(const fs_pixel_xfer *x, uint32_t i)
{
    int s = x->index_shift;
    if (s > 0)
        i = s < 32 ? i << s : 0;
    else if (s < 0)
        i = s > -32 ? i >> -s : 0;
    return i + (uint32_t)x->index_offset;
}

void fs_pixel_map_index_to_rgba(const fs_context *c, const uint32_t *index, int64_t n, float *rgba)
{
    const fs_pixel_xfer *x = &c->px;
    for (int64_t i = 0; i < n; i++, rgba += 4)
        /* The maps' sizes are powers of two: the index is masked (3.6.5). */
        for (int k = 0; k < 4; k++)
            rgba[k] = x->map[FS_MAP_I_TO_R + k][index[i] & (uint32_t)(x->size[FS_MAP_I_TO_R + k] - 1)];
}

void fs_pixel_xfer_index_to_rgba(const fs_context *c, const uint32_t *index, int64_t n, float *rgba)
{
    for (int64_t i = 0; i < n; i++) {
        uint32_t v = shift_offset(&c->px, index[i]);
        fs_pixel_map_index_to_rgba(c, &v, 1, rgba + 4 * i);
    }
}

uint32_t fs_pixel_xfer_stencil_index(const fs_context *c, uint32_t index)
{
    const fs_pixel_xfer *x = &c->px;
    uint32_t v = shift_offset(x, index);
    if (x->map_stencil)
        v = (uint32_t)(int64_t)x->map[FS_MAP_S_TO_S][v & (uint32_t)(x->size[FS_MAP_S_TO_S] - 1)];
    return v;
}

float fs_pixel_xfer_depth_value(const fs_context *c, float d)
{
    return clamp01(d * c->px.depth_scale + c->px.depth_bias);
}

uint8_t fs_pixel_float_to_8(float f)
{
    return (uint8_t)lrintf(clamp01(f) * 255.0f); /* ties to even */
}

/* Groups x0 .. x0+k-1 (k <= PIECE) as floats after the transfer. */
enum { PIECE = 64 };
static void unpack_transfer_piece(const fs_context *c, const fs_pixel_layout *l, const void *pixels, int64_t z,
                                  int64_t y, int64_t x0, int64_t k, float *f)
{
    if (l->format == GL_COLOR_INDEX) {
        /* Indices become RGBA through the I_TO_* maps only: scale, bias
         * and MAP_COLOR apply to RGBA groups (3.6.5). */
        uint32_t idx[PIECE];
        fs_pixel_unpack_index(l, pixels, z, y, x0, k, idx);
        fs_pixel_xfer_index_to_rgba(c, idx, k, f);
    } else {
        fs_pixel_unpack_rgbaf(l, pixels, z, y, x0, k, f);
        fs_pixel_xfer_rgba(c, f, k);
    }
}

void fs_pixel_unpack_transfer_rgba8(const fs_context *c, const fs_pixel_layout *l, const void *pixels, int64_t z,
                                    int64_t y, int64_t x0, int64_t n, uint8_t *rgba)
{
    if (l->format != GL_COLOR_INDEX && !fs_pixel_xfer_color(c)) {
        fs_pixel_unpack_rgba8(l, pixels, z, y, x0, n, rgba);
        return;
    }
    /* In pieces, so that a row of any width needs no allocation. */
    for (int64_t done = 0; done < n; done += PIECE) {
        int64_t k = n - done < PIECE ? n - done : PIECE;
        float f[PIECE * 4];
        unpack_transfer_piece(c, l, pixels, z, y, x0 + done, k, f);
        for (int64_t i = 0; i < k * 4; i++)
            rgba[done * 4 + i] = fs_pixel_float_to_8(f[i]);
    }
}

void fs_pixel_unpack_transfer_conv(const fs_context *c, const fs_pixel_layout *l, const void *pixels, int64_t z,
                                   int64_t y, int64_t x0, int64_t n, uint8_t *rgba,
                                   void (*conv)(const void *arg, const float *f, size_t k, uint8_t *out),
                                   const void *arg)
{
    for (int64_t done = 0; done < n; done += PIECE) {
        int64_t k = n - done < PIECE ? n - done : PIECE;
        float f[PIECE * 4];
        unpack_transfer_piece(c, l, pixels, z, y, x0 + done, k, f);
        conv(arg, f, (size_t)k, rgba + done * 4);
    }
}
