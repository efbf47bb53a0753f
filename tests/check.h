/*
 * A minimal test harness in the libuv style: tests listed once, each run
 * alone by name or all together, assertions print both sides.
 * Each test binary prints "N passed, N failed" (and ", N skipped").
 *
 *   TEST(name) { CHECK_EQ_INT(a, b); ... }
 *   TEST_LIST = { TEST_ENTRY(name), ... , TEST_END };
 *   int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
 */
#ifndef FS_CHECK_H
#define FS_CHECK_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

typedef struct check_state { int failed; int skipped; const char *skip_reason; } check_state;
typedef void (*check_fn)(check_state *);
typedef struct check_test { const char *name; check_fn fn; } check_test;

#define TEST(name) static void test_##name(check_state *check_st_)
#define TEST_ENTRY(name) {#name, test_##name}
#define TEST_END {NULL, NULL}
#define TEST_LIST static const check_test test_list[]

#define CHECK_FAIL_(fmt, ...)                                                  \
    do {                                                                       \
        fprintf(stderr, "  %s:%d: " fmt "\n", __FILE__, __LINE__, __VA_ARGS__); \
        check_st_->failed++;                                                   \
    } while (0)
#define CHECK(cond)                                                            \
    do { if (!(cond)) CHECK_FAIL_("check failed: %s", #cond); } while (0)
#define CHECK_EQ_INT(a, b)                                                     \
    do {                                                                       \
        long long a_ = (long long)(a), b_ = (long long)(b);                   \
        if (a_ != b_) CHECK_FAIL_("%s == %s: %lld != %lld", #a, #b, a_, b_);  \
    } while (0)
#define CHECK_EQ_UINT(a, b)                                                    \
    do {                                                                       \
        unsigned long long a_ = (unsigned long long)(a), b_ = (unsigned long long)(b); \
        if (a_ != b_) CHECK_FAIL_("%s == %s: %llu != %llu", #a, #b, a_, b_);  \
    } while (0)
#define CHECK_NEAR(a, b, tol)                                                  \
    do {                                                                       \
        double a_ = (double)(a), b_ = (double)(b);                             \
        if (!(fabs(a_ - b_) <= (tol)))                                         \
            CHECK_FAIL_("%s ~ %s: %.9g vs %.9g (tol %g)", #a, #b, a_, b_, (double)(tol)); \
    } while (0)
#define CHECK_STR(a, b)                                                        \
    do {                                                                       \
        const char *a_ = (a), *b_ = (b);                                       \
        if (!a_ || !b_ || strcmp(a_, b_) != 0)                                 \
            CHECK_FAIL_("%s == %s: \"%s\" != \"%s\"", #a, #b, a_ ? a_ : "(null)", b_ ? b_ : "(null)"); \
    } while (0)
/* Ends the test as skipped, with a reason that is printed. */
#define SKIP(reason) do { check_st_->skipped = 1; check_st_->skip_reason = (reason); return; } while (0)
/* Returns from the test when a previous check failed (for setup steps). */
#define REQUIRE(cond) do { if (!(cond)) { CHECK_FAIL_("required: %s", #cond); return; } } while (0)

static inline int check_main(int argc, char **argv, const check_test *tests)
{
    int passed = 0, failed = 0, skipped = 0;
    for (const check_test *t = tests; t->name; t++) {
        if (argc > 1) {
            int want = 0;
            for (int i = 1; i < argc; i++) want |= strcmp(argv[i], t->name) == 0;
            if (!want) continue;
        }
        check_state st = {0, 0, NULL};
        t->fn(&st);
        if (st.failed) { failed++; fprintf(stderr, "FAIL %s\n", t->name); }
        else if (st.skipped) { skipped++; printf("SKIP %s: %s\n", t->name, st.skip_reason); }
        else { passed++; printf("ok   %s\n", t->name); }
    }
    printf("%d passed, %d failed, %d skipped\n", passed, failed, skipped);
    return failed ? 1 : 0;
}
#endif
