/*
 * libFuzzer harness for the GL API itself: the input is read as a sequence
 * of calls (command, then each argument by its kind in driver/gl_commands.def)
 * that go straight to fs_submit, as a trace's decoded calls do.  Where
 * fuzz_trace.c mostly meets the reader's checks, this one reaches the
 * executors with the values the standards call bad input: NaN, infinities,
 * huge and negative sizes, unknown enums, arrays shorter than the command
 * reads, degenerate primitives, calls out of order (inside glBegin/glEnd,
 * while compiling a display list).
 *
 * The contract kept is the trace reader's (driver/replay.c): an array
 * argument's count is the number of elements its buffer really holds,
 * client-array pointers are trace data (is_data = 1), and outputs are NULL
 * (the dispatcher gives them scratch space; an application's own output
 * buffers are trusted, as GL trusts them).  Buffers live until the input ends,
 * because the context keeps vertex-array pointers, as with a replay.
 * The mode (functional, full-cycle or sampled) is fuzz_cycle.h's.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "../../driver/gl_call.h"
#include "../../driver/gl_enums.h"
#include "fuzz_cycle.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint32_t *enums;
static size_t n_enums;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    /* Every enum value the name table knows (GL 1.5 core and fragsim's
     * extensions), so that most enum arguments are ones some command takes. */
    enums = malloc(0x10000 * sizeof *enums);
    for (uint32_t v = 0; enums && v < 0x10000; v++)
        if (fs_gl_enum_name(v))
            enums[n_enums++] = v;
    return 0;
}

typedef struct input {
    const uint8_t *p;
    size_t n;
} input;

static uint64_t take(input *in, int bytes)
{
    uint64_t v = 0;
    for (int i = 0; i < bytes; i++) {
        v = v << 8 | (in->n ? *in->p : 0);
        if (in->n) {
            in->p++;
            in->n--;
        }
    }
    return v;
}

static int64_t an_int(input *in)
{
    static const int64_t pick[] = {0, 1, 2, 3, 4, -1, 7, 8, 16, 64, 256, 1024, 4096, 65536,
                                   INT32_MAX, INT32_MIN, -2, 1 << 20};
    unsigned s = (unsigned)take(in, 1);
    if (s < 2 * (sizeof pick / sizeof *pick))
        return pick[s / 2];
    return (int32_t)take(in, 4);
}

static double a_float(input *in)
{
    static const double pick[] = {0.0, 1.0, -1.0, 0.5, 2.0, 0.25, 10.0, -10.0, 100.0, 1e-30, 1e30,
                                  1e38, FLT_MAX, -FLT_MAX, INFINITY, -INFINITY, NAN, 3e9, -0.0};
    unsigned s = (unsigned)take(in, 1);
    if (s < 4 * (sizeof pick / sizeof *pick))
        return pick[s / 4];
    if (s < 0xf0) { /* a small value with a fraction */
        return ((double)(int16_t)take(in, 2)) / 256.0;
    }
    uint32_t u = (uint32_t)take(in, 4);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static uint32_t an_enum(input *in)
{
    unsigned s = (unsigned)take(in, 1);
    if (s < 0xf0 && n_enums)
        return enums[take(in, 2) % n_enums];
    return (uint32_t)take(in, 4);
}

/* Buffers of one input: freed after the context. */
typedef struct arena {
    void **p;
    size_t n, cap;
} arena;

static void *alloc(arena *a, size_t bytes)
{
    if (a->n == a->cap) {
        size_t cap = a->cap ? 2 * a->cap : 64;
        void **np = realloc(a->p, cap * sizeof *np);
        if (!np)
            return NULL;
        a->p = np;
        a->cap = cap;
    }
    void *b = calloc(1, bytes ? bytes : 1);
    if (b)
        a->p[a->n++] = b;
    return b;
}

static void fill_array(input *in, int kind, void *buf, uint32_t count)
{
    for (uint32_t i = 0; i < count; i++) {
        switch (kind) {
        case FS_K_AF: ((float *)buf)[i] = (float)a_float(in); break;
        case FS_K_AD: ((double *)buf)[i] = a_float(in); break;
        case FS_K_AI: ((int32_t *)buf)[i] = (int32_t)an_int(in); break;
        case FS_K_AU: ((uint32_t *)buf)[i] = (uint32_t)an_int(in); break;
        case FS_K_AUB: case FS_K_ABY: ((uint8_t *)buf)[i] = (uint8_t)take(in, 1); break;
        case FS_K_AS: case FS_K_AUS: ((uint16_t *)buf)[i] = (uint16_t)an_int(in); break;
        default: break;
        }
    }
}

/* One call from the input; false when the command has an argument kind the
 * harness cannot make safely. */
static bool make_call(input *in, arena *ar, fs_call *call)
{
    memset(call, 0, sizeof *call);
    call->cmd = (uint16_t)(take(in, 2) % FS_CMD_COUNT);
    const fs_cmd_info *info = &fs_cmd_table[call->cmd];
    call->nargs = info->nargs;
    for (int k = 0; k < info->nargs; k++) {
        fs_arg *a = &call->a[k];
        int kind = info->kinds[k];
        switch (kind) {
        case FS_K_E: a->i = an_enum(in); break;
        case FS_K_BM: a->i = (uint32_t)take(in, 4); break;
        case FS_K_B: case FS_K_UB: a->i = (uint8_t)take(in, 1); break;
        case FS_K_BY: a->i = (int8_t)take(in, 1); break;
        case FS_K_S: a->i = (int16_t)an_int(in); break;
        case FS_K_US: a->i = (uint16_t)an_int(in); break;
        case FS_K_I: case FS_K_SZ: a->i = (int32_t)an_int(in); break;
        case FS_K_IP: a->i = (int64_t)(int32_t)an_int(in); break; /* GLintptr, GLsizeiptr */
        case FS_K_U: a->i = (uint32_t)an_int(in); break;
        case FS_K_F: case FS_K_CF: a->d = (float)a_float(in); break;
        case FS_K_D: case FS_K_CD: a->d = a_float(in); break;
        case FS_K_AF: case FS_K_AD: case FS_K_AI: case FS_K_AU: case FS_K_AUB: case FS_K_ABY:
        case FS_K_AS: case FS_K_AUS: {
            a->count = (uint32_t)(take(in, 1) % 24);
            void *b = alloc(ar, a->count * fs_kind_elem_size(kind));
            if (!b)
                return false;
            fill_array(in, kind, b, a->count);
            a->p = b;
            break;
        }
        case FS_K_BLOB: case FS_K_CPTR: {
            unsigned s = (unsigned)take(in, 1);
            a->count = s < 0x80 ? s : s < 0xf0 ? (uint32_t)take(in, 2) : (uint32_t)(take(in, 3) % (1u << 20));
            uint8_t *b = alloc(ar, a->count);
            if (!b)
                return false;
            for (uint32_t i = 0; i < a->count && in->n; i++)
                b[i] = (uint8_t)take(in, 1);
            a->p = b;
            a->is_data = 1;
            break;
        }
        case FS_K_OV: case FS_K_OF: case FS_K_OD: case FS_K_OI: case FS_K_OU: case FS_K_OUS: case FS_K_OB: case FS_K_OUB: case FS_K_OP:
            a->out = NULL; /* as from a trace: the dispatcher gives scratch space */
            break;
        case FS_K_STR: {
            static const char *const names[] = {"glBegin", "glOcclusionBuffers", "", "GL_FRAGSIM_mp_grid",
                                                "glScissors"};
            a->p = names[take(in, 1) % (sizeof names / sizeof *names)];
            a->count = (uint32_t)strlen(a->p) + 1;
            break;
        }
        default: return false;
        }
    }
    return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fs_config cfg;
    fs_config_defaults(&cfg);
    fs_context *c = fs_context_create(&cfg, 32, 32);
    if (!c)
        return 0;
    fs_cycle *cy = fuzz_cycle_begin(c, size, 1);
    input in = {data, size};
    arena ar = {0};
    fs_call call;
    for (int n = 0; in.n && n < 4096; n++) {
        if (!make_call(&in, &ar, &call))
            break;
        fuzz_cycle_submit(cy, c, &call);
    }
    fuzz_cycle_frame_end(cy);
    fuzz_cycle_end(cy);
    fs_context_destroy(c);
    for (size_t i = 0; i < ar.n; i++)
        free(ar.p[i]);
    free(ar.p);
    return 0;
}
