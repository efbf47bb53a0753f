/*
 * Constant attributes (issue 19, the "constant-colour rule"): llvmpipe's
 * fixed-function fragment program reads a colour, secondary colour or
 * texture coordinate the vertex stage does not vary as the current value,
 * without the rounding of the perspective division (a/w)/(1/w) (Mesa's
 * ff_fragment_shader.cpp filters its inputs by the vertex program's
 * varying inputs).  Which draws that is was measured here on OSMesa:
 * glColor before glBegin, glDrawArrays without a colour array, the same in
 * display lists: constant; glColor between Begin and End (or in an earlier
 * Begin/End with only vertex commands, glBegin and queries between: Mesa's
 * immediate vertex format keeps it), lighting, a texture matrix:
 * interpolated.  Each case at tolerance 0, and each case's reference shows
 * whether it was constant (one red value) or not, so a model that always
 * interpolates (or never does) fails.  Then random draws of every kind.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "check.h"
#include <math.h>
#include "osmesa_util.h"

static int CASE;
static const float tri[9] = {-0.9f,-0.8f,-1.5f, 0.9f,-0.7f,-4.0f, 0.1f,0.9f,-2.2f};
static void scene(fs_context *c, const void *u, int w, int h)
{
    (void)u;
    osm_frustum_scene(c, w, h, 0, 0, 0, 10);
    float col[12]; for (int i=0;i<3;i++){col[i*4]=0.3f;col[i*4+1]=0.55f;col[i*4+2]=0.7f;col[i*4+3]=1;}
    switch (CASE) {
    case 0: G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 1: G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++){G(Color3f,0.3f,0.55f,0.7f); G(Vertex3fv,tri+3*i);} G0(End); break;
    case 2: G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 3: /* previous prim had colour, this one not, no state change */
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 4: G(Color3f,0.3f,0.55f,0.7f); G(EnableClientState,GL_VERTEX_ARRAY); G(VertexPointer,3,GL_FLOAT,0,tri); G(DrawArrays,GL_TRIANGLES,0,3); break;
    case 5: G(EnableClientState,GL_VERTEX_ARRAY); G(EnableClientState,GL_COLOR_ARRAY); G(ColorPointer,4,GL_FLOAT,0,col); G(VertexPointer,3,GL_FLOAT,0,tri); G(DrawArrays,GL_TRIANGLES,0,3); break;
    case 6: { GLuint l = GR(GenLists,1); G(NewList,l,GL_COMPILE); G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); G0(EndList); G(CallList,l);} break;
    case 7: { GLuint l = GR(GenLists,1); G(NewList,l,GL_COMPILE); G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); G0(EndList); G(CallList,l);} break;
    case 8: { float a[4]={0.3f,0.3f,0.3f,1}, z[4]={0,0,0,1}, d[4]={0.4f,0.5f,0.6f,1};
        G(Enable,GL_LIGHTING); G(Enable,GL_LIGHT0); G(Lightfv,GL_LIGHT0,GL_DIFFUSE,d); G(LightModelfv,GL_LIGHT_MODEL_AMBIENT,a); G(Lightfv,GL_LIGHT0,GL_SPECULAR,z);
        G(Normal3f,0,0,1); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End);} break;
    case 9: /* lines, current colour */
        G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_LINES); G(Vertex3f,-0.9f,-0.5f,-1.2f); G(Vertex3f,0.9f,0.6f,-5); G0(End); break;
    case 10: G(Begin,GL_LINES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,-0.9f,-0.5f,-1.2f); G(Vertex3f,0.9f,0.6f,-5); G0(End); break;
    case 11: /* colour inside first prim, then state change, then prim without */
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(Enable,GL_CULL_FACE); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 12: /* DrawElements current colour, quads */
        G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_QUADS); G(Vertex3f,-0.9f,-0.9f,-1.2f);G(Vertex3f,0.9f,-0.9f,-5);G(Vertex3f,0.9f,0.9f,-5);G(Vertex3f,-0.9f,0.9f,-1.2f); G0(End); break;
    case 13: /* secondary colour via color sum, current */
        G(Color3f,0,0,0); G(Enable,GL_COLOR_SUM); G(SecondaryColor3f,0.3f,0.55f,0.7f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 14: G(Color3f,0,0,0); G(Enable,GL_COLOR_SUM); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++){ G(SecondaryColor3f,0.3f,0.55f,0.7f); G(Vertex3fv,tri+3*i);} G0(End); break;
    case 15: /* glColor after Begin but set identically before, then DrawArrays later */
        G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End);
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End); break;
    case 16: case 17: case 18: case 19: case 20: { static uint8_t tx[256*4]; for(int i=0;i<256;i++){int v=(i&1)?255:0; tx[i*4]=tx[i*4+1]=tx[i*4+2]=(uint8_t)v; tx[i*4+3]=255;}
        G(TexImage1D,GL_TEXTURE_1D,0,GL_RGBA,256,0,GL_RGBA,GL_UNSIGNED_BYTE,tx);
        G(TexParameteri,GL_TEXTURE_1D,GL_TEXTURE_MIN_FILTER,GL_NEAREST); G(TexParameteri,GL_TEXTURE_1D,GL_TEXTURE_MAG_FILTER,GL_NEAREST);
        G(Enable,GL_TEXTURE_1D); G(TexEnvi,GL_TEXTURE_ENV,GL_TEXTURE_ENV_MODE,GL_REPLACE);
        float s0 = 77.0f/256.0f;
        if (CASE == 16) { G(TexCoord1f,s0); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); }
        if (CASE == 17) { G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++){ G(TexCoord1f,s0); G(Vertex3fv,tri+3*i);} G0(End); }
        if (CASE == 18) { G(TexCoord1f,s0); G(MatrixMode,GL_TEXTURE); G(Translatef,0,0,0.25f); G(MatrixMode,GL_MODELVIEW); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); }
        if (CASE == 19) { G(TexCoord1f,s0); G(EnableClientState,GL_VERTEX_ARRAY); G(VertexPointer,3,GL_FLOAT,0,tri); G(DrawArrays,GL_TRIANGLES,0,3); }
        if (CASE == 20) { G(TexCoord1f,s0); G(Enable,GL_FOG); G(Fogi,GL_FOG_MODE,GL_LINEAR); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); }
        } break;
    case 21: { float a[4]={0.3f,0.3f,0.3f,1}, z[4]={0,0,0,1}, d[4]={0.4f,0.5f,0.6f,1}, dir[4]={0.3f,0.4f,0.8f,0};
        G(Enable,GL_LIGHTING); G(Enable,GL_LIGHT0); G(Lightfv,GL_LIGHT0,GL_DIFFUSE,d); G(Lightfv,GL_LIGHT0,GL_POSITION,dir); G(LightModelfv,GL_LIGHT_MODEL_AMBIENT,a); G(Lightfv,GL_LIGHT0,GL_SPECULAR,z);
        G(Normal3f,0,0,1); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End);} break;
    case 22: /* current colour, then a texture matrix with colour sum off: point */
        G(Color3f,0.3f,0.55f,0.7f); G(PointSize,5); G(Begin,GL_POINTS); G(Vertex3f,0.1f,0.1f,-3); G0(End); break;
    case 23: G(Begin,GL_TRIANGLES); G(Color3f,0.9f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(Color3f,0.3f,0.55f,0.7f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 24: G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(Normal3f,0,1,0); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 25: /* glGetError between */ G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        if (c) fsglGetError(c); else glGetError(); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); break;
    case 26: /* glGetFloatv between */ { float f[4]; G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(GetFloatv,GL_CURRENT_COLOR,f); G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End);} break;
    case 27: /* list: prim with colour then prim without (same list) */ { GLuint l = GR(GenLists,1); G(NewList,l,GL_COMPILE);
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); G0(EndList); G(CallList,l);} break;
    case 28: /* list: prim without colour then prim with */ { GLuint l = GR(GenLists,1); G(NewList,l,GL_COMPILE); G(Color3f,0.3f,0.55f,0.7f);
        G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End);
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End); G0(EndList); G(CallList,l);} break;
    case 29: /* immediate: prim with colour (offscreen) then CallList of a list with current colour prim */ { GLuint l = GR(GenLists,1); G(NewList,l,GL_COMPILE); G(Color3f,0.3f,0.55f,0.7f);
        G(Begin,GL_TRIANGLES); for(int i=0;i<3;i++) G(Vertex3fv,tri+3*i); G0(End); G0(EndList);
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End); G(CallList,l);} break;
    case 30: /* immediate: with colour prim, then DrawArrays without colour array */
        G(Begin,GL_TRIANGLES); G(Color3f,0.3f,0.55f,0.7f); G(Vertex3f,5,5,-2);G(Vertex3f,6,5,-2);G(Vertex3f,5,6,-2); G0(End);
        G(EnableClientState,GL_VERTEX_ARRAY); G(VertexPointer,3,GL_FLOAT,0,tri); G(DrawArrays,GL_TRIANGLES,0,3); break;
    }
}
/* Whether OSMesa's image of a case is constant (1) or interpolated (0):
 * -1 for cases that show neither (lighting, nothing visible). */
static const int constant_case[31] = {
    1, 0, 0, 0, 1, 0, 1, 0, -1, 1, 1, 1, 1, 1, 0, 1,
    1, 0, 0, 1, -1, -1, -1, 0, 0, 0, 0, 0, 1, 1, 1,
};

TEST(measured_cases_vs_osmesa)
{
    for (CASE = 0; CASE <= 30; CASE++) {
        osm_pair p;
        REQUIRE(osm_pair_render(&p, 64, 64, NULL, scene, NULL));
        /* The red channel, or the texel colour for the texture cases. */
        int hist[256] = {0}, values = 0;
        for (int i = 0; i < 64 * 64; i++)
            hist[p.ref.color[i * 4]]++;
        for (int v = 1; v < 255; v++)
            values += hist[v] != 0;
        bool tex = CASE >= 16 && CASE <= 20;
        int lit = 0;
        for (int i = 0; i < 64 * 64; i++)
            lit += p.ref.color[i * 4] == 255;
        int is_const = tex ? (lit == 280 ? 1 : lit ? 0 : -1) : (values == 1 ? 1 : values > 1 ? 0 : -1);
        if (constant_case[CASE] >= 0 && is_const != constant_case[CASE])
            CHECK_FAIL_("case %d: OSMesa's image is %s, the case expects %s", CASE,
                        is_const == 1 ? "constant" : is_const == 0 ? "interpolated" : "empty",
                        constant_case[CASE] ? "constant" : "interpolated");
        if (p.d.differ)
            CHECK_FAIL_("case %d: %ld pixels differ from OSMesa (max %d)", CASE, p.d.differ, p.d.maxd);
        CHECK_EQ_INT(fsglGetError(p.c), GL_NO_ERROR);
        osm_pair_close(&p);
    }
}

/* Random draws: a random colour (and secondary colour under GL_COLOR_SUM),
 * perspective triangles, quads or lines, the colour given before glBegin,
 * inside it, by an array or not, in a display list or not, two
 * primitives with or without a state change between. */
static unsigned rnd_state;
static unsigned rnd(void) { rnd_state = rnd_state * 1103515245u + 12345u; return rnd_state >> 8; }
static float rndf(float a, float b) { return a + (b - a) * (float)(rnd() & 0xffff) / 65535.0f; }
typedef struct rcase { unsigned seed; } rcase;

static void random_scene(fs_context *c, const void *u, int w, int h)
{
    rnd_state = ((const rcase *)u)->seed;
    osm_frustum_scene(c, w, h, 0, 0, 0, 10);
    static const GLenum prims[3] = {GL_TRIANGLES, GL_QUADS, GL_LINES};
    int nprim = 1 + (int)(rnd() % 2);
    bool list = rnd() % 3 == 0;
    GLuint l = 0;
    if (list) {
        l = GR(GenLists, 1);
        G(NewList, l, GL_COMPILE);
    }
    if (rnd() % 2)
        G(Enable, GL_COLOR_SUM);
    static float verts[8][3], cols[8][4];
    for (int p = 0; p < nprim; p++) {
        GLenum mode = prims[rnd() % 3];
        int n = mode == GL_TRIANGLES ? 3 : mode == GL_QUADS ? 4 : 2;
        float r = rndf(0, 1), g = rndf(0, 1), b = rndf(0, 1), s2 = rndf(0, 0.5f);
        /* Quads planar and convex (a square around a centre, z a plane in
         * x and y), so that only the colour rule is tested. */
        float cx = rndf(-1, 1), cy = rndf(-1, 1), rad = rndf(0.3f, 1.5f), ang = rndf(0, 6.28f);
        float z0 = rndf(-6, -2), zx = rndf(-1, 1), zy = rndf(-1, 1);
        for (int i = 0; i < n; i++) {
            if (mode == GL_QUADS) {
                verts[i][0] = cx + rad * cosf(ang + 1.5708f * (float)i);
                verts[i][1] = cy + rad * sinf(ang + 1.5708f * (float)i);
                verts[i][2] = z0 + zx * verts[i][0] + zy * verts[i][1];
            } else {
                verts[i][0] = rndf(-1.5f, 1.5f);
                verts[i][1] = rndf(-1.5f, 1.5f);
                verts[i][2] = rndf(-9, -1.1f);
            }
            cols[i][0] = r, cols[i][1] = g, cols[i][2] = b, cols[i][3] = 1;
        }
        int how = (int)(rnd() % 5);
        if (p > 0 && rnd() % 2)
            G(Disable, GL_ALPHA_TEST); /* a state change between the primitives */
        if (how == 0 || how == 3) {
            G(Color3f, r, g, b);
            G(SecondaryColor3f, s2, s2, s2);
        }
        if (how <= 2) {
            G(Begin, mode);
            for (int i = 0; i < n; i++) {
                if (how == 1 || (how == 2 && i == 0)) {
                    G(Color3f, r, g, b);
                    G(SecondaryColor3f, s2, s2, s2);
                }
                G(Vertex3fv, verts[i]);
            }
            G0(End);
        } else {
            G(EnableClientState, GL_VERTEX_ARRAY);
            G(VertexPointer, 3, GL_FLOAT, 0, verts);
            if (how == 4) {
                G(EnableClientState, GL_COLOR_ARRAY);
                G(ColorPointer, 4, GL_FLOAT, 0, cols);
            }
            G(DrawArrays, mode, 0, n);
            G(DisableClientState, GL_COLOR_ARRAY);
            G(DisableClientState, GL_VERTEX_ARRAY);
        }
    }
    if (list) {
        G0(EndList);
        G(CallList, l);
    }
}

TEST(random_draws_vs_osmesa)
{
    long differ = 0, lit = 0;
    int bad = 0;
    for (unsigned k = 0; k < 200; k++) {
        rcase rc = {0x9e3779b9u * (k + 1)};
        osm_pair p;
        REQUIRE(osm_pair_render(&p, 64, 64, NULL, random_scene, &rc));
        differ += p.d.differ;
        lit += img_lit_pixels(p.ref.color, 64 * 64);
        if (p.d.differ && bad++ < 5)
            CHECK_FAIL_("random case %u: %ld pixels differ (max %d)", k, p.d.differ, p.d.maxd);
        osm_pair_close(&p);
    }
    printf("  200 random scenes, %ld lit pixels, %ld differ\n", lit, differ);
    CHECK(lit > 0);
}

TEST_LIST = {
    TEST_ENTRY(measured_cases_vs_osmesa),
    TEST_ENTRY(random_draws_vs_osmesa),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
