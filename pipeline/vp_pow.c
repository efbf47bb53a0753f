/*
 * POW of the fixed-function vertex program, bit for bit as llvmpipe
 * computes it.  The lighting equation's two powers (GL 1.5 spec 2.14.1:
 * the specular factor (n.h)^s_rm and the spot factor (-VP.s_dl)^s_rl)
 * reach llvmpipe as the program's LIT and POW, which Mesa's prog_to_nir
 * turns into NIR's fpow; llvmpipe keeps fpow (it does not ask NIR to lower
 * it, and the exponents are uniforms, so NIR's pow(a, 2) = a a and similar
 * rewrites never fire) and gallivm evaluates it as
 *
 *   pow(x, y) = x == 0 ? 0 : exp2(log2(x) y)
 *
 * with its own polynomial approximations of log2 and exp2, not the C
 * library's powf.  The rules, as read from Mesa 22.3's gallivm (the
 * installed libOSMesa), in this file's words:
 *
 * log2(x): x's exponent field e gives the integer part e - 127 (converted
 *   to float); its mantissa bits with a zero exponent give m in [1, 2);
 *   with t = (m - 1) / (m + 1) (a true division) and z = t^2,
 *   log2(x) = t P(z) + (e - 127), P of degree 4 in z (a minimax fit of
 *   log2((1 + sqrt z) / (1 - sqrt z)) / sqrt z).  Edge cases, by unordered
 *   comparisons (so a NaN x takes each of them in turn and ends NaN):
 *   x >= inf gives inf, x == 0 gives -inf, x < 0 gives NaN.  (A denormal
 *   never gets here: see the end of this comment.)
 * exp2(v): v clamped to [-126.99999, 128] (a NaN stays NaN), split into
 *   floor(v) and the fraction f = v - floor(v); 2^floor(v) is built in the
 *   exponent field ((floor(v) + 127) << 23: 0 for -127, inf for 128) and
 *   multiplied by Q(f), Q of degree 5 with Q(0) = 1 exactly.
 * The polynomials are evaluated as an even and an odd part in the square
 *   of their argument (c0 + u^2 (c2 + u^2 c4 ...) and c1 + u^2 (c3 ...)),
 *   then odd u + even; every step a multiply-add, emitted as LLVM's
 *   fmuladd, which LLVM fuses into one FMA on a CPU that has it (the
 *   x86-64 machine measured has); with separate products and sums about a
 *   third of the specular values differ from OSMesa (measured,
 *   tests/test_lighting_order.c, tests/test_vp_pow.c).  On a CPU without
 *   FMA llvmpipe would round the products; the model fuses regardless.
 *   The coefficients are doubles rounded to float.
 * pow's zero test is an unordered comparison too: a NaN base gives 0.
 * The vertex code runs with denormals read as zero (measured on OSMesa,
 * tests/test_vp_pow.c: pow(1e-40, 0.5) is 0, not 2^-66.4), so a denormal
 * base is a zero one.
 */
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include "vp_pow.h"

static float bits_to_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static uint32_t float_to_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* The multiply-add of gallivm's polynomials (see above: fused). */
static float mad(float a, float b, float c)
{
    return fmaf(a, b, c);
}

/* c[0] + c[1] u + ... + c[n-1] u^(n-1), in the even/odd split above. */
static float polynomial(float u, const double *c, int n)
{
    float u2 = u * u, even = 0.0f, odd = 0.0f;
    bool have_even = false, have_odd = false;
    for (int i = n - 1; i >= 0; i--) {
        float k = (float)c[i];
        if (i % 2 == 0) {
            even = have_even ? mad(u2, even, k) : k;
            have_even = true;
        } else {
            odd = have_odd ? mad(u2, odd, k) : k;
            have_odd = true;
        }
    }
    return have_odd ? mad(odd, u, even) : even;
}

static float log2_approx(float x)
{
    /* The coefficients of the degree 4 fit (gallivm's LOG_POLY_DEGREE). */
    static const double p[5] = {
        2.88539009343309178325, 0.961791550404184197881, 0.577440339438736392009,
        0.403343858251329912514, 0.406718052498846252698,
    };
    uint32_t i = float_to_bits(x);
    float e = (float)((int32_t)((i & 0x7f800000u) >> 23) - 127);
    float m = bits_to_float((i & 0x007fffffu) | 0x3f800000u);
    float t = (m - 1.0f) / (m + 1.0f);
    float z = t * t;
    float r = mad(t, polynomial(z, p, 5), e);
    if (!(x < INFINITY))
        r = INFINITY;
    if (!(x != 0.0f))
        r = -INFINITY;
    if (!(x >= 0.0f))
        r = NAN;
    return r;
}

static float exp2_approx(float v)
{
    static const double q[6] = {
        1.0, 0.693153073200168932794, 0.240153617044375388211, 0.0558263180532956664775,
        0.00898934009049466391101, 0.00187757667519147912699,
    };
    if (isnan(v))
        return v;
    if (v > 128.0f)
        v = 128.0f;
    const float lo = (float)-126.99999;
    if (v < lo)
        v = lo;
    float fl = floorf(v);
    float f = v - fl;
    float scale = bits_to_float((uint32_t)((int32_t)fl + 127) << 23);
    return scale * polynomial(f, q, 6);
}

float fs_vp_pow(float x, float y)
{
    if (!(fabsf(x) >= FLT_MIN))
        return 0.0f; /* zero, denormal or NaN */
    return exp2_approx(log2_approx(x) * y);
}
