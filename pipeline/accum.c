/*
 * The accumulation buffer (GL 1.5 spec 4.2.4; see accum.h).
 *
 * llvmpipe keeps it as RGBA16_SNORM and Mesa runs glAccum on the CPU, in
 * floats; measured through libOSMesa (tests/test_accum.c):
 * - values are stored as c * 32767 converted to a 16-bit integer toward
 *   zero, and sums wrap around (1.0 + 0.3 reads back as a negative value,
 *   which GL_RETURN clamps to 0) rather than saturating;
 * - GL_LOAD takes the colour buffer's byte c as the float c * (1/255),
 *   times value * 32767, truncated; GL_ADD adds value * 32767 truncated;
 *   GL_MULT truncates the product; GL_ACCUM adds what GL_LOAD would load
 *   (exact for every byte and values up to +-2.5, wrapping included:
 *   accum_conversion_vs_osmesa);
 * - glClear of the buffer stores the clamped clear value v as
 *   (trunc(65535 v) - 1) / 2, Mesa's float-to-short rule, not as
 *   trunc(32767 v): that 1 was GL_ACCUM's difference in 7 of 60 random
 *   sequences (now 0 of 200);
 * - GL_RETURN writes clamp(a * value / 32767) rounded to 8 bits through the
 *   colour mask, bypassing the other fragment operations (4.2.4);
 * - every operation, and glClear of the buffer, covers the scissor box.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fragment_stages.h"
#include "accum.h"

/* The buffer of the window's size, made on first use; NULL when the
 * context has none or it cannot be allocated (GL_OUT_OF_MEMORY set). */
static int16_t *accum_buffer(fs_context *c)
{
    fs_accum_state *a = &c->accum;
    if (a->bits[0] == 0)
        return NULL;
    if (a->buf && a->w == c->fb.width && a->h == c->fb.height)
        return a->buf;
    free(a->buf);
    a->w = c->fb.width;
    a->h = c->fb.height;
    a->buf = calloc((size_t)a->w * (size_t)a->h * 4, sizeof *a->buf);
    if (!a->buf)
        fs_error(c, GL_OUT_OF_MEMORY);
    return a->buf;
}

void fs_accum_free(fs_context *c)
{
    free(c->accum.buf);
    c->accum.buf = NULL;
}

/* A float to the buffer's 16 bits as the CPU converts it: toward zero to
 * 32 bits (out of range: the integer indefinite 2^31, whose low half is
 * 0), of which the low 16 bits are kept. */
static int16_t to_accum(float f)
{
    if (!(f > -2147483648.0f && f < 2147483648.0f))
        return 0;
    return (int16_t)(uint16_t)(uint32_t)(int32_t)f;
}

void fs_accum_clear(fs_context *c, int x0, int y0, int x1, int y1)
{
    int16_t *buf = accum_buffer(c);
    if (!buf)
        return; /* no buffer: nothing to clear, no error (4.2.3) */
    /* The clear value (clamped to [-1, 1] by glClearAccum) is converted
     * as Mesa's signed-short rule does, (trunc(65535 v) - 1) / 2 with the
     * division toward zero, not as the accumulating operations do
     * (trunc(32767 v)): the two differ by 1 for some values. */
    int16_t v[4];
    for (int k = 0; k < 4; k++)
        v[k] = (int16_t)(((int32_t)(c->st.accum_clear[k] * 65535.0f) - 1) / 2);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            memcpy(buf + ((size_t)y * (size_t)c->fb.width + (size_t)x) * 4, v, sizeof v);
}

/* One operation on one pixel's accumulation values a and colour p. */
static void accum_pixel(fs_context *c, GLenum op, float value, int16_t *a, uint8_t *p)
{
    switch (op) {
    case GL_ACCUM:
    case GL_LOAD: {
        float scale = value * 32767.0f;
        for (int k = 0; k < 4; k++) {
            int16_t add = to_accum((float)p[k] * (1.0f / 255.0f) * scale);
            a[k] = op == GL_LOAD ? add : (int16_t)(uint16_t)((uint32_t)(uint16_t)a[k] + (uint16_t)add);
        }
        break;
    }
    case GL_ADD: {
        int16_t add = to_accum(value * 32767.0f);
        for (int k = 0; k < 4; k++)
            a[k] = (int16_t)(uint16_t)((uint32_t)(uint16_t)a[k] + (uint16_t)add);
        break;
    }
    case GL_MULT:
        for (int k = 0; k < 4; k++)
            a[k] = to_accum((float)a[k] * value);
        break;
    default: { /* GL_RETURN */
        float scale = value / 32767.0f;
        uint8_t rgba[4];
        for (int k = 0; k < 4; k++) {
            float f = (float)a[k] * scale;
            rgba[k] = (uint8_t)lrintf((f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f) * 255.0f);
        }
        fs_masked_color_write(c, p, rgba);
        break;
    }
    }
}

void fs_exec_Accum(fs_context *c, GLenum op, GLfloat value)
{
    fs_modelview_analyse(c);
    if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (c->accum.bits[0] == 0) {
        fs_error(c, GL_INVALID_OPERATION); /* 4.2.4: no accumulation buffer */
        return;
    }
    int16_t *buf = accum_buffer(c);
    int x0, y0, x1, y1;
    if (!buf || fs_render_mode_diverts(&c->rmode) || !fs_scissor_rect(c, &x0, &y0, &x1, &y1))
        return;
    /* GL_RETURN writes no colour buffer with glDrawBuffer(GL_NONE) (4.2.1). */
    if (op == GL_RETURN && c->draw_buffer == GL_NONE)
        return;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * (size_t)c->fb.width + (size_t)x;
            accum_pixel(c, op, value, buf + i * 4, c->fb.color + i * 4);
        }
}
