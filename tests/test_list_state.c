/*
 * Display-list state (GL 1.5 spec 5.4, table 6.32): GL_LIST_BASE,
 * GL_LIST_MODE, GL_LIST_INDEX and glListBase in the list attribute group
 * (GL_LIST_BIT, 6.1.14), against OSMesa: the same calls on both, every
 * glGet and error compared.
 */
#include "check.h"
#include "osmesa_util.h"

static void get_list_state(fs_context *c, GLint out[4])
{
    GLenum names[3] = {GL_LIST_BASE, GL_LIST_MODE, GL_LIST_INDEX};
    for (int i = 0; i < 3; i++) {
        out[i] = -12345;
        G(GetIntegerv, names[i], &out[i]);
    }
    out[3] = (GLint)(c ? fsglGetError(c) : glGetError());
}

/* Records 4 values per step into out; returns the count. */
static int list_steps(fs_context *c, GLint *out)
{
    int n = 0;
    get_list_state(c, out + n), n += 4;
    G(ListBase, 7u);
    get_list_state(c, out + n), n += 4;
    G(NewList, 5u, GL_COMPILE);
    get_list_state(c, out + n), n += 4;     /* glGet runs at once while compiling */
    G(ListBase, 9u);                        /* compiled, not executed */
    G0(EndList);
    get_list_state(c, out + n), n += 4;
    G(NewList, 6u, GL_COMPILE_AND_EXECUTE);
    get_list_state(c, out + n), n += 4;
    G0(EndList);
    G(PushAttrib, GL_LIST_BIT);
    G(ListBase, 11u);
    get_list_state(c, out + n), n += 4;
    G0(PopAttrib);
    get_list_state(c, out + n), n += 4;     /* restored to 7 */
    G(PushAttrib, GL_ALL_ATTRIB_BITS);
    G(CallList, 5u);                        /* sets 9 */
    get_list_state(c, out + n), n += 4;
    G0(PopAttrib);
    get_list_state(c, out + n), n += 4;
    G(NewList, 0u, GL_COMPILE);             /* GL_INVALID_VALUE, nothing compiled */
    get_list_state(c, out + n), n += 4;
    return n;
}

TEST(list_state_vs_osmesa)
{
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    GLint ref[64], mine[64];
    int n = list_steps(NULL, ref);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    CHECK_EQ_INT(list_steps(c, mine), n);
    for (int i = 0; i < n; i++)
        if (ref[i] != mine[i])
            CHECK_FAIL_("step %d value %d: OSMesa %d, model %d", i / 4, i % 4, ref[i], mine[i]);
    fs_context_destroy(c);
}

TEST_LIST = {TEST_ENTRY(list_state_vs_osmesa), TEST_END};

int main(int argc, char **argv)
{
    setenv("LP_NUM_THREADS", "1", 0);
    return check_main(argc, argv, test_list);
}
