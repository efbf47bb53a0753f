/*
 * The GL_COMBINE texture environment (GL 1.5 spec 3.8.13, tables 3.20 and
 * 3.21; ARB_texture_env_combine, _crossbar and _dot3, now core), and the
 * combiner functions of ATI_texture_env_combine3 (GL_ZERO and GL_ONE
 * sources, MODULATE_ADD, MODULATE_SIGNED_ADD, MODULATE_SUBTRACT), which
 * OSMesa also accepts: the parameters glTexEnv sets and glGetTexEnv
 * returns, and the arithmetic.
 *
 * The arithmetic is llvmpipe's: Mesa 22 builds a fragment shader from the
 * environment (main/ff_fragment_shader.cpp; read for the rules, not
 * copied), which llvmpipe runs in 32-bit float on the texel c/255 and the
 * interpolated colour, without fused multiply-adds:
 *   - the RGB and the alpha function each take their arguments with their
 *     operands (1 - x for ONE_MINUS_*, the alpha smeared for *_ALPHA);
 *   - the shader compiler reassociates and folds (measured, 256 texel
 *     values per case): INTERPOLATE is a0 a2 + a1 (1 - a2), where
 *     1 - a2 of a ONE_MINUS_* operand is the source value itself;
 *     ADD_SIGNED is (a0 + -0.5) + a1, MODULATE_SIGNED_ADD a0 a2 + (a1 +
 *     -0.5); DOT3 is (2 a0 - 1) . (2 a1 - 1) over RGB as x x' + (y y' +
 *     z z'), DOT3_RGBA gives alpha the same;
 *   - the result is clamped to [0, 1] once, after the scale (the shader
 *     clamps only the functions whose result can leave [0, 1], which
 *     gives the same);
 *   - a TEXTUREn source names unit n's texel, (0, 0, 0, 0) when unit n is
 *     disabled or its texture incomplete; PRIMARY_COLOR is the fragment's
 *     colour before texturing, PREVIOUS the previous enabled unit's
 *     result (the fragment colour for the first).
 * Measured against OSMesa: tests/test_multitexture.c, combine_vs_osmesa.
 */
#include <string.h>
#include "texture_priv.h"

#ifndef GL_MODULATE_ADD_ATI
#define GL_MODULATE_ADD_ATI 0x8744
#define GL_MODULATE_SIGNED_ADD_ATI 0x8745
#define GL_MODULATE_SUBTRACT_ATI 0x8746
#endif

void fs_tex_env_init(fs_tex_env *e)
{
    /* GL 1.5 spec table 6.19. */
    static const GLenum sources[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
    memset(e, 0, sizeof *e);
    e->mode = GL_MODULATE;
    for (int a = 0; a < 2; a++) {
        e->combine[a] = GL_MODULATE;
        e->scale[a] = 1.0f;
        for (int i = 0; i < 3; i++) {
            e->source[a][i] = sources[i];
            e->operand[a][i] = a == 0 && i < 2 ? GL_SRC_COLOR : GL_SRC_ALPHA;
        }
    }
}

static bool rgb_function(GLenum f)
{
    switch (f) {
    case GL_REPLACE: case GL_MODULATE: case GL_ADD: case GL_ADD_SIGNED: case GL_INTERPOLATE: case GL_SUBTRACT:
    case GL_MODULATE_ADD_ATI: case GL_MODULATE_SIGNED_ADD_ATI: case GL_MODULATE_SUBTRACT_ATI:
        return true;
    default:
        return false;
    }
}

static bool valid_source(GLenum s)
{
    switch (s) {
    case GL_TEXTURE: case GL_CONSTANT: case GL_PRIMARY_COLOR: case GL_PREVIOUS: case GL_ZERO: case GL_ONE:
        return true;
    default: /* the crossbar: another unit's texture */
        return s >= GL_TEXTURE0 && s < GL_TEXTURE0 + FS_MAX_TEXTURE_UNITS;
    }
}

/* Where a parameter lives: *a 0 for RGB, 1 for alpha, *i the argument. */
static GLenum *combine_field(fs_tex_env *e, GLenum pname, int *a, int *i)
{
    switch (pname) {
    case GL_COMBINE_RGB: *a = 0; return &e->combine[0];
    case GL_COMBINE_ALPHA: *a = 1; return &e->combine[1];
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB:
        *a = 0;
        *i = (int)(pname - GL_SOURCE0_RGB);
        return &e->source[0][*i];
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA:
        *a = 1;
        *i = (int)(pname - GL_SOURCE0_ALPHA);
        return &e->source[1][*i];
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
        *a = 0;
        *i = (int)(pname - GL_OPERAND0_RGB);
        return &e->operand[0][*i];
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
        *a = 1;
        *i = (int)(pname - GL_OPERAND0_ALPHA);
        return &e->operand[1][*i];
    default:
        return NULL;
    }
}

bool fs_tex_combine_set(fs_tex_env *e, GLenum pname, float value, GLenum *error)
{
    *error = GL_NO_ERROR;
    if (pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE) {
        /* 3.8.13: 1.0, 2.0 or 4.0, else INVALID_VALUE. */
        if (value != 1.0f && value != 2.0f && value != 4.0f)
            *error = GL_INVALID_VALUE;
        else
            e->scale[pname == GL_ALPHA_SCALE] = value;
        return true;
    }
    int a = 0, i = 0;
    GLenum *field = combine_field(e, pname, &a, &i);
    if (!field)
        return false;
    GLenum v = (GLenum)value;
    bool ok;
    if (pname == GL_COMBINE_RGB || pname == GL_COMBINE_ALPHA)
        ok = rgb_function(v) || (a == 0 && (v == GL_DOT3_RGB || v == GL_DOT3_RGBA));
    else if (field == &e->source[a][i])
        ok = valid_source(v);
    else /* operands: the alpha function takes alpha values only */
        ok = v == GL_SRC_ALPHA || v == GL_ONE_MINUS_SRC_ALPHA ||
             (a == 0 && (v == GL_SRC_COLOR || v == GL_ONE_MINUS_SRC_COLOR));
    if (!ok || (float)v != value)
        *error = GL_INVALID_ENUM;
    else
        *field = v;
    return true;
}

bool fs_tex_combine_get(const fs_tex_env *e, GLenum pname, float *value)
{
    if (pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE) {
        *value = e->scale[pname == GL_ALPHA_SCALE];
        return true;
    }
    int a = 0, i = 0;
    const GLenum *field = combine_field((fs_tex_env *)e, pname, &a, &i);
    if (!field)
        return false;
    *value = (float)*field;
    return true;
}

/* ---- arithmetic ---- */

static inline float sat(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }

/* Argument k of function a (0 RGB, 1 alpha) for channel ch; *complement
 * (if not NULL) gets 1 - the argument as the shader has it: the source
 * value itself for a ONE_MINUS_* operand (1 - (1 - x) folds to x). */
static float argument_c(const fs_tex_env *e, const fs_combine_inputs *in, int a, int k, int ch, float *complement)
{
    GLenum s = e->source[a][k];
    const float *v;
    static const float zero[4] = {0, 0, 0, 0}, one[4] = {1, 1, 1, 1};
    switch (s) {
    case GL_TEXTURE: v = in->texel[in->unit]; break;
    case GL_CONSTANT: v = e->color; break;
    case GL_PRIMARY_COLOR: v = in->primary; break;
    case GL_PREVIOUS: v = in->previous; break;
    case GL_ZERO: v = zero; break;
    case GL_ONE: v = one; break;
    default: { /* GL_TEXTUREn: only an enabled, complete unit has a texel */
        int n = (int)(s - GL_TEXTURE0);
        v = (in->valid >> n) & 1u ? in->texel[n] : zero;
        break;
    }
    }
    GLenum op = e->operand[a][k];
    float x = op == GL_SRC_ALPHA || op == GL_ONE_MINUS_SRC_ALPHA ? v[3] : v[ch];
    bool minus = op == GL_ONE_MINUS_SRC_COLOR || op == GL_ONE_MINUS_SRC_ALPHA;
    if (complement)
        *complement = minus ? x : 1.0f - x;
    return minus ? 1.0f - x : x;
}

static float argument(const fs_tex_env *e, const fs_combine_inputs *in, int a, int k, int ch)
{
    return argument_c(e, in, a, k, ch, NULL);
}

/* Argument k (value ak) + -0.5 as the compiler folds it: (1 - x) + -0.5
 * becomes 0.5 - x. */
static float signed_half(const fs_tex_env *e, const fs_combine_inputs *in, int a, int k, int ch, float ak)
{
    float x;
    argument_c(e, in, a, k, ch, &x);
    GLenum op = e->operand[a][k];
    return op == GL_ONE_MINUS_SRC_COLOR || op == GL_ONE_MINUS_SRC_ALPHA ? 0.5f - x : ak + -0.5f;
}

/* Function f of the arguments of function a for channel ch (DOT3: of RGB). */
static float combine_value(const fs_tex_env *e, const fs_combine_inputs *in, int a, GLenum f, int ch)
{
    float a0 = argument(e, in, a, 0, ch);
    switch (f) {
    case GL_REPLACE: return a0;
    case GL_DOT3_RGB: case GL_DOT3_RGBA: {
        float x[3], y[3];
        for (int k = 0; k < 3; k++) {
            x[k] = argument(e, in, a, 0, k) * 2.0f + -1.0f;
            y[k] = argument(e, in, a, 1, k) * 2.0f + -1.0f;
        }
        return x[0] * y[0] + (x[1] * y[1] + x[2] * y[2]);
    }
    default: break;
    }
    float a1 = argument(e, in, a, 1, ch);
    switch (f) {
    case GL_MODULATE: return a0 * a1;
    case GL_ADD: return a0 + a1;
    case GL_ADD_SIGNED: return signed_half(e, in, a, 0, ch, a0) + a1;
    case GL_SUBTRACT: return a0 - a1;
    default: break;
    }
    float om2;
    float a2 = argument_c(e, in, a, 2, ch, &om2);
    switch (f) {
    case GL_INTERPOLATE: return a0 * a2 + a1 * om2;
    case GL_MODULATE_ADD_ATI: return a0 * a2 + a1;
    case GL_MODULATE_SIGNED_ADD_ATI: return a0 * a2 + signed_half(e, in, a, 1, ch, a1);
    default: return a0 * a2 - a1; /* GL_MODULATE_SUBTRACT_ATI */
    }
}

void fs_tex_combine(const fs_tex_env *e, const fs_combine_inputs *in, float out[4])
{
    GLenum frgb = e->combine[0];
    if (frgb == GL_DOT3_RGB || frgb == GL_DOT3_RGBA) {
        float d = combine_value(e, in, 0, frgb, 0);
        out[0] = out[1] = out[2] = d;
        out[3] = frgb == GL_DOT3_RGBA ? d : combine_value(e, in, 1, e->combine[1], 3);
    } else {
        for (int ch = 0; ch < 3; ch++)
            out[ch] = combine_value(e, in, 0, frgb, ch);
        out[3] = combine_value(e, in, 1, e->combine[1], 3);
    }
    /* One clamp after the scale (a product by 1 is exact, and clamping
     * leaves the results of REPLACE, MODULATE and INTERPOLATE, which
     * cannot leave [0, 1], as they are). */
    for (int ch = 0; ch < 4; ch++)
        out[ch] = sat(out[ch] * e->scale[ch == 3]);
}
