/*
 * The table of fragment variants (pipeline/fragment_ops.c) and the
 * validation step that chooses from it (pipeline/validate.c).
 *
 * The oracle is the general path, fs_fragment_quad_general, which
 * tests/test_fragment_ops.c holds to OSMesa: every variant must give the
 * same colour, depth and stencil bytes, statistics, work record and
 * Occlusion Unit hook calls on random state and random quads.  The table
 * must route some state to every variant, and no state setter may leave
 * the validated key stale.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "../pipeline/context.h"
#include "../pipeline/fragment_stages.h"
#include "../pipeline/validate.h"
#include "../driver/gl_call.h"
#include "../glext/GL_FRAGSIM_occlusion_unit.h"

enum { W = 13, H = 9 }; /* odd, so that quads at the edges are partly outside */

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static GLenum pick(uint32_t *s, const GLenum *v, int n) { return v[rng(s) % (unsigned)n]; }

static const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const GLenum factors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                 GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_DST_COLOR,
                                 GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
                                 GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA};
static const GLenum stencil_ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
#define N_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void set_cap(fs_context *c, GLenum cap, bool on)
{
    if (on)
        fs_exec_Enable(c, cap);
    else
        fs_exec_Disable(c, cap);
}

/* Enters (or leaves) an occlusion render mode, the one way to suppress
 * writes (units/occlusion_gl.c). */
static void set_occlusion_mode(fs_context *c, bool on)
{
    static GLuint buf[64];
    GLsizei size = 64;
    GLuint *bufs[1] = {buf};
    if (on) {
        fsglOcclusionBuffers(c, &size, bufs);
        fsglRenderMode(c, GL_BRIEF_OCCLUSION);
    } else {
        fsglRenderMode(c, GL_RENDER);
    }
}

/* Sets, through the GL commands, a state whose fragment key is `key`
 * (every field of validate.h). */
static void apply_key(fs_context *c, uint32_t key)
{
    fs_exec_DrawBuffer(c, key & FS_FKEY_NO_COLOR ? GL_NONE : GL_FRONT);
    set_occlusion_mode(c, key & FS_FKEY_SUPPRESS);
    set_cap(c, GL_SCISSOR_TEST, key & FS_FKEY_SCISSOR);
    set_cap(c, GL_ALPHA_TEST, key & FS_FKEY_ALPHA);
    set_cap(c, GL_STENCIL_TEST, key & FS_FKEY_STENCIL);
    set_cap(c, GL_DEPTH_TEST, key & FS_FKEY_DEPTH);
    fs_exec_DepthMask(c, (key & FS_FKEY_DEPTH_WRITE) != 0);
    fs_exec_DepthFunc(c, GL_NEVER + (key >> FS_FKEY_DEPTH_FUNC_SHIFT & 7u));
    set_cap(c, GL_BLEND, key & FS_FKEY_BLEND);
    fs_exec_BlendFunc(c, factors[(key >> FS_FKEY_BLEND_SRC_SHIFT & 15u) % 15u],
                      factors[(key >> FS_FKEY_BLEND_DST_SHIFT & 15u) % 15u]);
    fs_exec_BlendEquation(c, key & FS_FKEY_BLEND_EXT ? GL_FUNC_SUBTRACT : GL_FUNC_ADD);
    set_cap(c, GL_COLOR_LOGIC_OP, key & FS_FKEY_LOGIC);
    fs_exec_LogicOp(c, GL_CLEAR + (key >> FS_FKEY_LOGIC_OP_SHIFT & 15u));
    unsigned cm = key >> FS_FKEY_COLOR_MASK_SHIFT;
    fs_exec_ColorMask(c, cm & 1u, cm >> 1 & 1u, cm >> 2 & 1u, cm >> 3 & 1u);
}

/* A random key, half the time one a fast variant serves (all tests off,
 * all channels on, a depth test or blending of the kinds the table has). */
static uint32_t random_key(uint32_t *s, const fs_fragment_variant *v, int nv)
{
    uint32_t key = rng(s) & 0x1fffffffu;
    if (rng(s) % 2) {
        const fs_fragment_variant *e = &v[rng(s) % (unsigned)(nv - 1)];
        key = (key & ~e->mask) | e->value;
    }
    /* a valid blend factor (0..14) in both fields */
    uint32_t src = (key >> FS_FKEY_BLEND_SRC_SHIFT & 15u) % 15u, dst = (key >> FS_FKEY_BLEND_DST_SHIFT & 15u) % 15u;
    if (src == 10 && rng(s) % 2)
        src = 4; /* GL_SRC_ALPHA_SATURATE is a source factor only: keep some */
    if (dst == 10)
        dst = 5;
    key &= ~(FS_FKEY_BLEND_SRC_MASK | FS_FKEY_BLEND_DST_MASK);
    return key | src << FS_FKEY_BLEND_SRC_SHIFT | dst << FS_FKEY_BLEND_DST_SHIFT;
}

/* The rest of the fragment state, which no key field holds. */
static void random_params(fs_context *c, uint32_t *s)
{
    fs_exec_AlphaFunc(c, pick(s, funcs, 8), (float)(rng(s) % 260) / 256.0f);
    fs_exec_StencilFunc(c, pick(s, funcs, 8), (GLint)(rng(s) % 300) - 20, rng(s) % 2 ? 0xffu : rng(s) & 0xffu);
    fs_exec_StencilOp(c, pick(s, stencil_ops, 8), pick(s, stencil_ops, 8), pick(s, stencil_ops, 8));
    fs_exec_StencilMask(c, rng(s) % 2 ? 0xffu : rng(s) & 0xffu);
    fs_exec_Scissor(c, (GLint)(rng(s) % 8) - 2, (GLint)(rng(s) % 6) - 2, (GLsizei)(rng(s) % 14),
                    (GLsizei)(rng(s) % 10));
}

static void random_framebuffer(fs_context *c, uint32_t *s)
{
    for (int i = 0; i < W * H; i++) {
        for (int k = 0; k < 4; k++)
            c->fb.color[i * 4 + k] = (uint8_t)rng(s);
        c->fb.depth[i] = rng(s) % 3 ? rng(s) & 0xffffffu : 0x800000u;
        c->fb.stencil[i] = (uint8_t)(rng(s) % 3 ? rng(s) : 0u);
    }
}

/* Quads anywhere from partly left of / below the window to partly outside
 * its top right; depths often equal to the stored one (ties decide LESS
 * against LEQUAL) or one unit off; colours a little outside [0, 1]. */
static void random_quad(const fs_context *c, fs_quad *q, uint32_t *s)
{
    memset(q, 0, sizeof *q);
    q->x = (int)(rng(s) % (W + 3)) - 2;
    q->y = (int)(rng(s) % (H + 3)) - 2;
    q->mask = rng(s) & 0xfu;
    q->front_facing = rng(s) % 2;
    for (int i = 0; i < 4; i++) {
        int x = q->x + (i & 1), y = q->y + (i >> 1);
        uint32_t stored = x >= 0 && y >= 0 && x < W && y < H ? c->fb.depth[y * W + x] : 0x800000u;
        switch (rng(s) % 4) {
        case 0: q->z[i] = stored; break;
        case 1: q->z[i] = (stored + (rng(s) % 3) - 1) & 0xffffffu; break;
        default: q->z[i] = rng(s) & 0xffffffu; break;
        }
        for (int k = 0; k < 4; k++)
            q->color[i][k] = (float)((int)(rng(s) % 1200) - 100) / 1000.0f;
        if (rng(s) % 8 == 0)
            q->color[i][3] = rng(s) % 2 ? 1.0f : 0.0f;
    }
}

/* What the Occlusion Unit attachment point was given. */
typedef struct hook_log {
    int calls;
    unsigned tested[4], passed[4];
} hook_log;

static void log_hook(fs_context *c, void *user, const fs_quad *q, unsigned tested, unsigned passed)
{
    (void)c;
    (void)q;
    hook_log *l = user;
    if (l->calls < 4) {
        l->tested[l->calls] = tested;
        l->passed[l->calls] = passed;
    }
    l->calls++;
}

/* Everything a quad can change. */
typedef struct outcome {
    uint8_t color[W * H * 4], stencil[W * H];
    uint32_t depth[W * H];
    fs_stats stats;
    fs_quad_work work;
    hook_log hook;
} outcome;

static void save(const fs_context *c, outcome *o)
{
    memcpy(o->color, c->fb.color, sizeof o->color);
    memcpy(o->stencil, c->fb.stencil, sizeof o->stencil);
    memcpy(o->depth, c->fb.depth, sizeof o->depth);
    o->stats = c->stats;
}

static void restore(fs_context *c, const outcome *o)
{
    memcpy(c->fb.color, o->color, sizeof o->color);
    memcpy(c->fb.stencil, o->stencil, sizeof o->stencil);
    memcpy(c->fb.depth, o->depth, sizeof o->depth);
    c->stats = o->stats;
}

/* Runs q through fn from the state in `before` and records the outcome. */
static void run(fs_context *c, const fs_quad *q, fs_fragment_fn fn, const outcome *before, outcome *after)
{
    restore(c, before);
    memset(&after->hook, 0, sizeof after->hook);
    c->occlusion_user = &after->hook; /* for log_hook when it is installed */
    fs_quad copy = *q;
    after->work = fs_fragment_quad_with(c, &copy, fn);
    save(c, after);
}

static bool same(const outcome *a, const outcome *b)
{
    return !memcmp(a->color, b->color, sizeof a->color) && !memcmp(a->stencil, b->stencil, sizeof a->stencil) &&
           !memcmp(a->depth, b->depth, sizeof a->depth) && !memcmp(&a->stats, &b->stats, sizeof a->stats) &&
           a->work.killed_early == b->work.killed_early && a->work.passed == b->work.passed &&
           a->work.written == b->work.written && !memcmp(&a->hook, &b->hook, sizeof a->hook);
}

/* For several seeds: random state, random framebuffer and quads, every
 * table entry that serves the key against the general path. */
TEST(variants_equal_general_on_random_state)
{
    int nv;
    const fs_fragment_variant *v = fs_fragment_variants(&nv);
    long compared[64] = {0}, bad = 0;
    REQUIRE(nv <= 64);
    static outcome before, ref, got;
    for (uint32_t seed = 1; seed <= 6; seed++) {
        fs_context *c = fs_context_create(NULL, W, H);
        REQUIRE(c);
        uint32_t s = seed * 2654435761u;
        for (int round = 0; round < 400; round++) {
            uint32_t key = random_key(&s, v, nv);
            apply_key(c, key);
            random_params(c, &s);
            fs_validate(c);
            CHECK_EQ_UINT(c->frag.key, key);
            bool hook = rng(&s) % 3 == 0;
            fs_occlusion_hook_fn saved_hook = c->occlusion_hook;
            void *saved_user = c->occlusion_user;
            /* the log instead of the Occlusion Unit's own hook (an
             * occlusion mode installs it), whose records are not compared */
            c->occlusion_hook = hook ? log_hook : NULL;
            random_framebuffer(c, &s);
            for (int n = 0; n < 20; n++) {
                fs_quad q;
                random_quad(c, &q, &s);
                save(c, &before);
                run(c, &q, fs_fragment_quad_general, &before, &ref);
                for (int i = 0; i < nv; i++) {
                    if ((key & v[i].mask) != v[i].value)
                        continue;
                    run(c, &q, v[i].fn, &before, &got);
                    compared[i]++;
                    if (!same(&ref, &got) && bad++ < 5)
                        fprintf(stderr, "  variant \"%s\" differs: key %08x, quad (%d,%d) mask %x\n", v[i].name,
                                key, q.x, q.y, q.mask);
                }
                restore(c, &ref); /* the next quad draws over this one's result */
            }
            c->occlusion_hook = saved_hook;
            c->occlusion_user = saved_user;
        }
        fs_context_destroy(c);
    }
    CHECK_EQ_INT(bad, 0);
    for (int i = 0; i < nv; i++) {
        if (compared[i] < 1000)
            fprintf(stderr, "  variant \"%s\": %ld quads\n", v[i].name, compared[i]);
        CHECK(compared[i] >= 1000);
    }
}

/* The validation step chooses every variant for the state its entry
 * describes, so no entry is shadowed by an earlier one and the table
 * cannot route everything to the general path; states no fast variant
 * serves take the general path. */
TEST(every_variant_is_selected)
{
    int nv;
    const fs_fragment_variant *v = fs_fragment_variants(&nv);
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c);
    CHECK(nv >= 6);
    CHECK(v[nv - 1].fn == fs_fragment_quad_general && v[nv - 1].mask == 0);
    for (int i = 0; i < nv - 1; i++) {
        apply_key(c, v[i].value | (15u << FS_FKEY_COLOR_MASK_SHIFT & ~v[i].mask));
        fs_validate(c);
        if (c->frag.quad_fn != v[i].fn)
            fprintf(stderr, "  variant \"%s\" is not selected for its key %08x\n", v[i].name, v[i].value);
        CHECK(c->frag.quad_fn == v[i].fn);
    }
    /* the general path for a test no variant leaves out */
    static const GLenum caps[] = {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP};
    for (int i = 0; i < N_OF(caps); i++) {
        apply_key(c, 15u << FS_FKEY_COLOR_MASK_SHIFT);
        fs_exec_Enable(c, caps[i]);
        fs_validate(c);
        CHECK(c->frag.quad_fn == fs_fragment_quad_general);
    }
    apply_key(c, 7u << FS_FKEY_COLOR_MASK_SHIFT);
    fs_validate(c);
    CHECK(c->frag.quad_fn == fs_fragment_quad_general);
    fs_context_destroy(c);
}

/* One command that changes fragment state, chosen at random. */
static void random_setter(fs_context *c, uint32_t *s)
{
    static const GLenum caps[] = {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND,
                                  GL_COLOR_LOGIC_OP, GL_DITHER};
    static const GLenum equations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    switch (rng(s) % 17) {
    case 0: set_cap(c, pick(s, caps, N_OF(caps)), rng(s) % 2); break;
    case 1: fs_exec_DepthFunc(c, pick(s, funcs, 8)); break;
    case 2: fs_exec_DepthMask(c, rng(s) % 2); break;
    case 3: fs_exec_BlendFunc(c, pick(s, factors, 10), pick(s, factors, 10)); break;
    case 4: fs_exec_LogicOp(c, GL_CLEAR + rng(s) % 16); break;
    case 5: fs_exec_ColorMask(c, rng(s) % 4 != 0, 1, rng(s) % 4 != 0, 1); break;
    case 6: fs_exec_DrawBuffer(c, rng(s) % 3 ? GL_FRONT : GL_NONE); break;
    case 7: random_params(c, s); break;
    case 8: set_occlusion_mode(c, rng(s) % 2); break;
    case 9: fs_exec_PushAttrib(c, rng(s) % 2 ? GL_ALL_ATTRIB_BITS : GL_DEPTH_BUFFER_BIT); break;
    case 10: fs_exec_PopAttrib(c); break;
    case 11: fs_exec_Hint(c, GL_FOG_HINT, GL_NICEST); break;
    case 12: fs_exec_BlendEquation(c, pick(s, equations, 5)); break;
    case 13: fs_exec_BlendFuncSeparate(c, pick(s, factors, 10), pick(s, factors, 10), pick(s, factors, 10),
                                       pick(s, factors, 10)); break;
    case 14: fs_exec_BlendColor(c, 0.25f, 0.5f, 0.75f, (float)(rng(s) % 3) * 0.5f); break;
    default: apply_key(c, rng(s) % 2 ? 15u << FS_FKEY_COLOR_MASK_SHIFT | FS_FKEY_DEPTH | FS_FKEY_DEPTH_WRITE | FS_FKEY_DEPTH_FUNC(GL_LESS)
                                   : rng(s)); break;
    }
}

/* After any one command between two quads, the quad runs on the key of the
 * state as it is then (a setter that forgot its dirty bit leaves the key
 * of the state before). */
TEST(no_stale_key_after_any_setter)
{
    int nv;
    const fs_fragment_variant *v = fs_fragment_variants(&nv);
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c);
    uint32_t s = 99;
    long stale = 0;
    for (int i = 0; i < 20000; i++) {
        random_setter(c, &s);
        fs_quad q;
        random_quad(c, &q, &s);
        fs_fragment_quad(c, &q);
        uint32_t key = fs_fragment_key(c);
        int e = 0;
        while (e < nv - 1 && (key & v[e].mask) != v[e].value)
            e++;
        if ((c->frag.key != key || c->frag.quad_fn != v[e].fn) && stale++ < 5)
            fprintf(stderr, "  step %d: key %08x in use, %08x current\n", i, c->frag.key, key);
    }
    CHECK_EQ_INT(stale, 0);
    fs_context_destroy(c);
}

/* The case of issue 18: glDepthFunc alone between two draws.  The second
 * quad must meet GL_GREATER, as the general path does. */
TEST(depth_func_alone_between_draws)
{
    fs_context *c = fs_context_create(NULL, W, H);
    REQUIRE(c);
    fs_exec_Enable(c, GL_DEPTH_TEST);
    fs_quad q;
    memset(&q, 0, sizeof q);
    q.x = q.y = 2;
    q.mask = 0xf;
    for (int i = 0; i < 4; i++) {
        q.z[i] = 1000;
        q.color[i][0] = q.color[i][3] = 1.0f;
    }
    fs_quad_work w = fs_fragment_quad(c, &q); /* LESS against the cleared 0: fails */
    CHECK_EQ_UINT(w.written, 0);
    fs_exec_DepthFunc(c, GL_GREATER);
    w = fs_fragment_quad(c, &q);
    CHECK_EQ_UINT(w.written, 4);
    CHECK_EQ_UINT(c->fb.depth[2 * W + 2], 1000);
    CHECK_EQ_UINT(c->fb.color[(2 * W + 2) * 4], 255);
    fs_context_destroy(c);
}

TEST_LIST = {
    TEST_ENTRY(variants_equal_general_on_random_state),
    TEST_ENTRY(every_variant_is_selected),
    TEST_ENTRY(no_stale_key_after_any_setter),
    TEST_ENTRY(depth_func_alone_between_draws),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
