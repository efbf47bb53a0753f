/*
 * pipeline/name_map.c against a brute-force model: a plain array of the
 * names held.  Random puts, removes, gets and visits over a small name
 * space (so names collide, are deleted and come back, and probing runs
 * over deleted slots), and the wide visit-and-take that glDeleteLists
 * uses for huge ranges.
 */
#include <stdint.h>
#include "check.h"
#include "../pipeline/name_map.h"

enum { SPACE = 3000 };

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Every name's object equals the model's, and a visit sees each held
 * object once. */
static int agrees(const fs_name_map *m, void *const *model)
{
    int bad = 0, held = 0;
    for (GLuint n = 0; n < SPACE; n++) {
        bad += fs_name_map_get(m, n) != model[n];
        held += model[n] != NULL;
    }
    int seen = 0;
    size_t pos = 0;
    GLuint name;
    for (void *o; (o = fs_name_map_next(m, &pos, &name));) {
        bad += name >= SPACE || model[name] != o;
        seen++;
    }
    return bad + (seen != held) + ((size_t)held != m->held);
}

TEST(random_operations_match_an_array)
{
    static void *model[SPACE];
    static char objs[SPACE];
    memset(model, 0, sizeof model);
    fs_name_map m = {0};
    uint32_t s = 12345;
    int bad = 0;
    for (int step = 0; step < 200000; step++) {
        GLuint n = rng(&s) % SPACE;
        if (rng(&s) % 3) {
            if (!model[n]) {
                CHECK_EQ_INT(fs_name_map_put(&m, n, &objs[n]), 0);
                model[n] = &objs[n];
            }
        } else {
            bad += fs_name_map_remove(&m, n) != model[n];
            model[n] = NULL;
        }
        if (step % 5000 == 0)
            bad += agrees(&m, model);
    }
    bad += agrees(&m, model);
    CHECK_EQ_INT(bad, 0);
    /* Deleted slots do not pile up: the table stays within twice the
     * largest count held (at most SPACE) and at most half full. */
    CHECK(m.cap <= 4 * SPACE);
    CHECK(m.used * 2 <= m.cap);
    fs_name_map_clear(&m);
    CHECK_EQ_INT(m.cap, 0);
    CHECK(fs_name_map_get(&m, 1) == NULL);
}

TEST(visit_and_take_removes_a_range)
{
    static void *model[SPACE];
    static char objs[SPACE];
    fs_name_map m = {0};
    for (GLuint n = 0; n < SPACE; n++) {
        model[n] = &objs[n];
        CHECK_EQ_INT(fs_name_map_put(&m, n, model[n]), 0);
    }
    size_t pos = 0;
    GLuint name;
    for (void *o; (o = fs_name_map_next(&m, &pos, &name));) {
        if (name >= 1000 && name < 2500) {
            CHECK(o == model[name]);
            fs_name_map_take(&m, pos);
            model[name] = NULL;
        }
    }
    CHECK_EQ_INT(agrees(&m, model), 0);
    CHECK_EQ_INT(m.held, SPACE - 1500);
    fs_name_map_clear(&m);
}

TEST_LIST = {
    TEST_ENTRY(random_operations_match_an_array),
    TEST_ENTRY(visit_and_take_removes_a_range),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
