/*
 * Display-list state (GL 1.5 spec 5.4, table 6.32): GL_LIST_BASE,
 * GL_LIST_MODE, GL_LIST_INDEX and glListBase in the list attribute group
 * (GL_LIST_BIT, 6.1.14), against OSMesa: the same calls on both, every
 * glGet and error compared.  And what Mesa's list compiler loses between
 * glBegin and glEnd (driver/display_list.c, vbo_role): images and current
 * attributes after calling lists of attribute / vertex / evaluator / list
 * calls, compiled with GL_COMPILE and GL_COMPILE_AND_EXECUTE.
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

enum { FB_W = 64, FB_H = 64, FB_CASES = 10, FB_VALUES = 11 };

/* One list body between glNewList and glEndList.  Points at window
 * (16, 32), (48, 32) from glEvalCoord1f(0.25 / 0.75) and (16, 48) from
 * glVertex2f / glArrayElement, so each lands on one pixel. */
static void fallback_body(fs_context *c, int k)
{
    static const GLfloat va[2] = {-0.5f + 1.0f / 64, 0.5f + 1.0f / 64};
    G(Begin, GL_POINTS);
    switch (k) {
    case 0: /* piglit dlist-fdo31590's case: the colour is lost */
        G(Color3f, 1, 1, 0); G(EvalCoord1f, 0.25f); break;
    case 1: /* a vertex keeps what came before it; what follows is lost */
        G(Color3f, 1, 1, 0); G(Vertex2fv, va); G(Color3f, 0, 1, 1); G(EvalCoord1f, 0.25f); break;
    case 2: /* after the first evaluator call nothing more is lost */
        G(Color3f, 1, 1, 0); G(EvalCoord1f, 0.25f); G(Color3f, 0, 1, 1); G(EvalCoord1f, 0.75f); break;
    case 3: /* glEvalPoint1 does the same */
        G(Color3f, 1, 1, 0); G(EvalPoint1, 16); break;
    case 4: /* so does glCallList */
        G(Color3f, 1, 1, 0); G(CallList, 2u); break;
    case 5: /* normals, texture coordinates and materials too */
        G(Normal3f, 0, 0, -1); G(TexCoord2f, 0.5f, 0.25f); G(Materialf, GL_FRONT, GL_SHININESS, 7.0f);
        G(Color3f, 1, 0, 0); G(EvalCoord1f, 0.25f); break;
    case 6: /* glArrayElement is a vertex */
        G(Color3f, 1, 1, 0); G(ArrayElement, 0); G(Color3f, 0, 1, 1); G(EvalCoord1f, 0.75f); break;
    case 7: /* no evaluator: nothing lost.  (Attributes held at glEnd
             * after a vertex leave garbage as llvmpipe's current colour,
             * read from memory it never wrote: not compared.) */
        G(Color3f, 1, 1, 0); G(Vertex2fv, va); break;
    case 8: /* each glBegin starts over */
        G(Color3f, 1, 1, 0); G(EvalCoord1f, 0.25f); G0(End); G(Begin, GL_POINTS);
        G(Color3f, 0, 1, 1); G(EvalCoord1f, 0.75f); break;
    case 9: /* a colour before glBegin is not held */
        G0(End); G(Color3f, 1, 1, 0); G(Begin, GL_POINTS); G(EvalCoord1f, 0.25f); break;
    }
    G0(End);
}

/* Compiles case k in `mode`, clears, calls it and records the current
 * colour, normal, texture coordinate and front shininess into v. */
static void fallback_case(fs_context *c, int k, GLenum mode, GLfloat v[FB_VALUES])
{
    static const GLfloat pts[6] = {-1 + 1.0f / 64, 1.0f / 64, 0, 1 + 1.0f / 64, 1.0f / 64, 0};
    static const GLfloat va[2] = {-0.5f + 1.0f / 64, 0.5f + 1.0f / 64};
    G(Map1f, GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, pts);
    G(Enable, GL_MAP1_VERTEX_3);
    G(MapGrid1f, 64, 0.0f, 1.0f);
    G(VertexPointer, 2, GL_FLOAT, 0, va);
    G(EnableClientState, GL_VERTEX_ARRAY);
    G(NewList, 2u, GL_COMPILE);
    G(Vertex2fv, va);
    G0(EndList);
    G(Color3f, 1, 1, 1);
    G(Normal3f, 0, 0, 1);
    G(TexCoord2f, 0, 0);
    G(Materialf, GL_FRONT, GL_SHININESS, 0.0f);
    G(NewList, 1u, mode);
    fallback_body(c, k);
    G0(EndList);
    G(Clear, GL_COLOR_BUFFER_BIT);
    G(Color3f, 1, 1, 1);
    G(CallList, 1u);
    G(GetFloatv, GL_CURRENT_COLOR, v);
    G(GetFloatv, GL_CURRENT_NORMAL, v + 4);
    G(GetFloatv, GL_CURRENT_TEXTURE_COORDS, v + 7);
    G(GetMaterialfv, GL_FRONT, GL_SHININESS, v + 10);
    if (!c)
        glFinish();
}

TEST(begin_attributes_lost_at_fallback_vs_osmesa)
{
    int lost = 0;
    for (int m = 0; m < 2; m++) {
        GLenum mode = m ? GL_COMPILE_AND_EXECUTE : GL_COMPILE;
        for (int k = 0; k < FB_CASES; k++) {
            osm o;
            if (!osm_open(&o, FB_W, FB_H)) {
                osm_close(&o);
                SKIP("no OSMesa context");
            }
            GLfloat ref[FB_VALUES], mine[FB_VALUES];
            fallback_case(NULL, k, mode, ref);
            fs_context *c = fs_context_create(NULL, FB_W, FB_H);
            REQUIRE(c);
            fallback_case(c, k, mode, mine);
            img_diff d = {0};
            img_compare(c->fb.color, o.color, (long)FB_W * FB_H, &d);
            if (d.differ)
                CHECK_FAIL_("%s case %d: %ld pixels differ", m ? "COMPILE_AND_EXECUTE" : "COMPILE", k, d.differ);
            for (int i = 0; i < FB_VALUES; i++)
                if (memcmp(&ref[i], &mine[i], sizeof ref[i]))
                    CHECK_FAIL_("%s case %d value %d: OSMesa %g, model %g", m ? "COMPILE_AND_EXECUTE" : "COMPILE",
                                k, i, ref[i], mine[i]);
            /* The losing cases must really lose something on OSMesa, or
             * the comparison shows nothing about the rule. */
            lost += k == 0 && ref[2] == 1.0f;
            fs_context_destroy(c);
            osm_close(&o);
        }
    }
    CHECK_EQ_INT(lost, 2);
}

TEST_LIST = {TEST_ENTRY(list_state_vs_osmesa), TEST_ENTRY(begin_attributes_lost_at_fallback_vs_osmesa), TEST_END};

int main(int argc, char **argv)
{
    setenv("LP_NUM_THREADS", "1", 0);
    return check_main(argc, argv, test_list);
}
