/*
 * Merged immediate-mode quads (issue 20, xscreensaver's engine): Mesa's
 * immediate mode concatenates a glBegin(GL_QUADS)/glEnd onto the one
 * before when nothing flushed its vertices between and the first holds
 * whole quads (src/mesa/vbo: _mesa_End calls try_vbo_merge, whose
 * vbo_merge_draws appends the second primitive's count to the first's),
 * so llvmpipe sees one draw.  Its draw module picks a route per draw
 * (pipeline/primitive.c): with a vertex of any quad outside the view
 * volume every quad of the draw splits along v1-v3, one fully inside the
 * volume included; drawn alone such a quad splits along v0-v2.  In
 * engine's blended, depth-mask-off boxes that moved 55 to 102 pixels of
 * each frame by 1.
 *
 * Each case draws quad A (a vertex outside the volume, or not) and then
 * quad B (inside, with four distinct colours so that its diagonal shows),
 * with or without something between; model and OSMesa at tolerance 0.
 * The references themselves show the rule: B's pixels differ between
 * case 0 (merged) and case 1 (a glFlush between), so a model that ignores
 * the merge fails case 0 and one that always merges fails case 1.
 *
 * Known difference (KNOWN_REVERSE): A inside, B with a vertex outside.
 * Mesa's one draw takes the pipeline route for A too, but the model has
 * drawn A at its glEnd, before B is known; the check fails when the
 * model draws that case as OSMesa does (then make it a plain case).
 */
#define GL_GLEXT_PROTOTYPES 1
#include "check.h"
#include "osmesa_util.h"

static int CASE;

/* Quad A: its vertex 1 is outside the volume (x = 1.4) unless inside. */
static bool A_PLAIN; /* quad A without colours of its own */
static void quad_a(fs_context *c, bool outside, GLenum mode)
{
    G(Begin, mode);
    if (!A_PLAIN)
        G(Color3f, 0.2f, 0.6f, 0.3f);
    G(Vertex3f, -0.8f, 0.2f, 0);
    if (!A_PLAIN)
        G(Color3f, 0.9f, 0.1f, 0.3f);
    G(Vertex3f, outside ? 1.4f : 0.8f, 0.25f, 0);
    if (!A_PLAIN)
        G(Color3f, 0.1f, 0.2f, 0.9f);
    G(Vertex3f, 0.7f, 0.9f, 0);
    if (!A_PLAIN)
        G(Color3f, 0.8f, 0.9f, 0.7f);
    G(Vertex3f, -0.7f, 0.85f, 0);
    if (mode == GL_TRIANGLES) {
        G(Vertex3f, -0.7f, 0.85f, 0);
        G(Vertex3f, -0.75f, 0.3f, 0);
    }
    G0(End);
}

/* Quad B, inside; with `outside` vertex 2 leaves the volume. */
static void quad_b(fs_context *c, bool outside)
{
    G(Begin, GL_QUADS);
    G(Color3f, 1, 0, 0);
    G(Vertex3f, -0.85f, -0.9f, 0);
    G(Color3f, 0, 1, 0);
    G(Vertex3f, 0.8f, -0.8f, 0);
    G(Color3f, 0, 0, 1);
    G(Vertex3f, outside ? 1.3f : 0.75f, -0.05f, 0);
    G(Color3f, 1, 1, 1);
    G(Vertex3f, -0.7f, -0.1f, 0);
    G0(End);
}

enum { KNOWN_REVERSE = 7, NCASES = 10 };

static void scene(fs_context *c, const void *u, int w, int h)
{
    (void)u;
    G(Viewport, 0, 0, w, h);
    G(ClearColor, 0, 0, 0, 1);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(MatrixMode, GL_PROJECTION);
    G0(LoadIdentity);
    G(MatrixMode, GL_MODELVIEW);
    G0(LoadIdentity);
    switch (CASE) {
    case 0: /* merged: B takes A's pipeline route */
        quad_a(c, true, GL_QUADS);
        quad_b(c, false);
        break;
    case 1: /* a flush between: two draws */
        quad_a(c, true, GL_QUADS);
        G0(Flush);
        quad_b(c, false);
        break;
    case 2: /* A inside: the merged draw keeps the unclipped route */
        quad_a(c, false, GL_QUADS);
        quad_b(c, false);
        break;
    case 3: /* A of another mode: not merged */
        quad_a(c, true, GL_TRIANGLES);
        quad_b(c, false);
        break;
    case 4: /* a state change between */
        quad_a(c, true, GL_QUADS);
        G(LineWidth, 2);
        quad_b(c, false);
        break;
    case 5: /* a colour between (a vertex attribute: no flush) */
        quad_a(c, true, GL_QUADS);
        G(Color3f, 0.5f, 0.5f, 0.5f);
        quad_b(c, false);
        break;
    case 6: /* a query between (no flush) */
        quad_a(c, true, GL_QUADS);
        if (c)
            fsglGetError(c);
        else
            glGetError();
        quad_b(c, false);
        break;
    case KNOWN_REVERSE:
        quad_a(c, false, GL_QUADS);
        quad_b(c, true);
        break;
    case 8: /* a colour between that A's vertex format lacks: Mesa grows
             * the format, which flushes A (vbo_exec_wrap_upgrade_vertex) */
        A_PLAIN = true;
        quad_a(c, true, GL_QUADS);
        A_PLAIN = false;
        G(Color3f, 0.5f, 0.5f, 0.5f);
        quad_b(c, false);
        break;
    case 9: /* an empty glBegin(GL_QUADS)/glEnd between: merged too */
        quad_a(c, true, GL_QUADS);
        G(Begin, GL_QUADS);
        G0(End);
        quad_b(c, false);
        break;
    }
}

static bool render(osm_pair *p, int k)
{
    CASE = k;
    return osm_pair_render(p, 64, 64, NULL, scene, NULL);
}

TEST(merged_quads_vs_osmesa)
{
    for (int k = 0; k < NCASES; k++) {
        osm_pair p;
        REQUIRE(render(&p, k));
        if (k == KNOWN_REVERSE) {
            if (!p.d.differ)
                CHECK_FAIL_("case %d: the known difference is gone: make it a plain case", k);
        } else if (p.d.differ) {
            CHECK_FAIL_("case %d: %ld pixels differ from OSMesa (max %d)", k, p.d.differ, p.d.maxd);
        }
        CHECK_EQ_INT(fsglGetError(p.c), GL_NO_ERROR);
        osm_pair_close(&p);
    }
}

/* OSMesa's images of case 0 and case 1 differ: the merge changes B. */
TEST(merge_changes_the_split_on_osmesa)
{
    osm_pair a, b;
    REQUIRE(render(&a, 0));
    uint8_t *img = malloc(64 * 64 * 4);
    REQUIRE(img != NULL);
    memcpy(img, a.ref.color, 64 * 64 * 4);
    osm_pair_close(&a);
    REQUIRE(render(&b, 1));
    long n = 0;
    for (int i = 0; i < 64 * 64; i++)
        n += memcmp(img + 4 * i, b.ref.color + 4 * i, 4) != 0;
    CHECK(n > 0);
    osm_pair_close(&b);
    free(img);
}

TEST_LIST = {
    TEST_ENTRY(merged_quads_vs_osmesa),
    TEST_ENTRY(merge_changes_the_split_on_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
