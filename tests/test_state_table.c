/*
 * The GL state table (pipeline/state.def) against OSMesa (llvmpipe), at
 * tolerance 0: every state variable of the table answers glGet{Integer,
 * Float,Double,Boolean}v as on OSMesa, initially and after random state;
 * glPushAttrib/glPopAttrib (each group and GL_ALL_ATTRIB_BITS) and
 * glPushClientAttrib/glPopClientAttrib restore it as OSMesa does, for
 * several seeds; the stacks' depths and errors (GL 1.5 spec 6.1.14) are
 * OSMesa's.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "osmesa_util.h"
#include "../pipeline/context.h"
#include "../driver/gl_call.h"
#include "../pipeline/state.h"
#include "../driver/gl_enums.h"

/* What a sequence read: every query result and error, in order, with a
 * label per value for the message on a difference. */
typedef struct rec {
    double v[60000];
    const char *what[60000];
    int n;
} rec;

static void put(rec *r, const char *what, double v)
{
    if (r->n < (int)(sizeof r->v / sizeof r->v[0])) {
        r->what[r->n] = what;
        r->v[r->n++] = v;
    }
}

static void put_error(fs_context *c, rec *r, const char *what)
{
    put(r, what, c ? fsglGetError(c) : glGetError());
}

/* The rows OSMesa is asked about: every named row of the table, except
 * the known differences: GL_MAX_TEXTURE_SIZE and GL_MAX_CUBE_MAP_TEXTURE_SIZE
 * are 16384 on llvmpipe and 4096 in the model, whose texture unit holds no
 * larger image (units/texture_unit.h); the model lists the 3 S3TC
 * formats it decodes (llvmpipe 12; tests/test_compressed_tex.c's
 * known_differences checks both lists). */
static bool queried(const fs_state_info *row)
{
    static const GLenum differ[] = {GL_MAX_TEXTURE_SIZE, GL_MAX_CUBE_MAP_TEXTURE_SIZE,
                                    GL_NUM_COMPRESSED_TEXTURE_FORMATS, GL_COMPRESSED_TEXTURE_FORMATS};
    for (size_t i = 0; i < sizeof differ / sizeof differ[0]; i++)
        if (row->name == differ[i])
            return false;
    return row->kind != FS_STATE_PUSH_ONLY;
}

/* Every variable of the table through the four glGet commands, and the
 * error each raised. */
static void dump(fs_context *c, rec *r)
{
    int n;
    const fs_state_info *rows = fs_state_rows(&n);
    for (int i = 0; i < n; i++) {
        if (!queried(&rows[i]))
            continue;
        GLenum pname = rows[i].name;
        int count = rows[i].count;
        GLint iv[16];
        GLfloat fv[16];
        GLdouble dv[16];
        GLboolean bv[16];
        G(GetIntegerv, pname, iv);
        G(GetFloatv, pname, fv);
        G(GetDoublev, pname, dv);
        G(GetBooleanv, pname, bv);
        for (int k = 0; k < count; k++) {
            put(r, rows[i].label, iv[k]);
            put(r, rows[i].label, fv[k]);
            put(r, rows[i].label, dv[k]);
            put(r, rows[i].label, bv[k]);
        }
        put_error(c, r, rows[i].label);
    }
}

static const GLenum light_pnames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                      GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                      GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION};
static const GLenum material_pnames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS};

static void dump_materials(fs_context *c, rec *r);

/* The lights and materials (GL_LIGHTING_BIT state without a glGet name),
 * through glGetLight{f,i}v and glGetMaterial{f,i}v. */
static void dump_lighting(fs_context *c, rec *r)
{
    GLfloat fv[4];
    GLint iv[4];
    for (int l = 0; l < 8; l++)
        for (int p = 0; p < 10; p++) {
            int n = fs_light_param_count(light_pnames[p]);
            G(GetLightfv, GL_LIGHT0 + l, light_pnames[p], fv);
            G(GetLightiv, GL_LIGHT0 + l, light_pnames[p], iv);
            for (int k = 0; k < n; k++) {
                put(r, "glGetLightfv", fv[k]);
                put(r, "glGetLightiv", iv[k]);
            }
        }
    dump_materials(c, r);
    put_error(c, r, "glGetLight/glGetMaterial");
}

/* Both faces' materials through glGetMaterial{f,i}v. */
static void dump_materials(fs_context *c, rec *r)
{
    GLfloat fv[4];
    GLint iv[4];
    for (int f = 0; f < 2; f++)
        for (int p = 0; p < 5; p++) {
            int n = fs_material_param_count(material_pnames[p]);
            G(GetMaterialfv, f ? GL_BACK : GL_FRONT, material_pnames[p], fv);
            G(GetMaterialiv, f ? GL_BACK : GL_FRONT, material_pnames[p], iv);
            static const char *names[2][5] = {
                {"front GL_AMBIENT", "front GL_DIFFUSE", "front GL_SPECULAR", "front GL_EMISSION", "front GL_SHININESS"},
                {"back GL_AMBIENT", "back GL_DIFFUSE", "back GL_SPECULAR", "back GL_EMISSION", "back GL_SHININESS"}};
            for (int k = 0; k < n; k++) {
                put(r, names[f][p], fv[k]);
                put(r, names[f][p], iv[k]);
            }
        }
}

/* ---- random valid state ---- */

static unsigned rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (*s >> 8) & 0xffffffu;
}
static int pick(unsigned *s, int n) { return (int)(rnd(s) % (unsigned)n); }
/* A float in [lo, hi) with 24 random bits. */
static float rndf(unsigned *s, float lo, float hi) { return lo + (hi - lo) * ((float)rnd(s) / 16777216.0f); }

static const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const GLenum stencil_ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT};
static const GLenum blend_factors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                       GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA};
static const GLenum faces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
static const GLenum hints[] = {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
                               GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT,
                               GL_TEXTURE_COMPRESSION_HINT};
static const GLenum hint_modes[] = {GL_FASTEST, GL_NICEST, GL_DONT_CARE};
static const GLenum pixel_store[] = {
    GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
    GL_UNPACK_ALIGNMENT, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST,
    GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_ALIGNMENT, GL_PACK_IMAGE_HEIGHT,
    GL_PACK_SKIP_IMAGES};
#define N(a) ((int)(sizeof a / sizeof a[0]))

/* The enables of the table (glEnable caps and client arrays). */
static void random_enables(fs_context *c, unsigned *s)
{
    int n;
    const fs_state_info *rows = fs_state_rows(&n);
    for (int i = 0; i < n; i++) {
        /* GL_COLOR_MATERIAL stays off: with it on, llvmpipe ignores
         * glMaterial of the tracked properties and updates them from the
         * current colour only when vertices are flushed, where the model
         * stores glMaterial and tracks glColor at once (a known difference
         * of the lighting stage, not of the state table). */
        if ((rows[i].cap == FS_CAP_NO && rows[i].name != GL_TEXTURE_2D) )
            continue;
        if (pick(s, 3) != 0)
            continue;
        bool on = pick(s, 2);
        if (rows[i].cap == FS_CAP_CLI && on)
            G(EnableClientState, rows[i].name);
        else if (rows[i].cap == FS_CAP_CLI)
            G(DisableClientState, rows[i].name);
        else if (on)
            G(Enable, rows[i].name);
        else
            G(Disable, rows[i].name);
    }
}

static void random_colour(unsigned *s, float *v, float lo, float hi)
{
    for (int k = 0; k < 4; k++)
        v[k] = rndf(s, lo, hi);
}

/* A few lights, and materials unless scramble (the modelview matrix stays
 * the identity, so positions and directions are stored as given).
 * Materials set between a push and its pop are a known difference of
 * Mesa's immediate-mode buffer, not of the state table (measured,
 * deferred_material_known_difference): glMaterial outside Begin/End is a
 * vertex attribute of Mesa's vbo module, copied into the lighting state
 * only when the vbo flushes.  A state call after a flush of the current
 * values (glPushAttrib(GL_LIGHTING_BIT) is one) empties it; a glMaterial
 * after that stays pending through glPopAttrib, which restores the pushed
 * materials, and lands on them at the next flush.  So glLight, glMaterial,
 * glPopAttrib leaves the material as set, while glMaterial, glLight,
 * glPopAttrib restores it.  The model restores it always. */
static void random_lights(fs_context *c, unsigned *s, bool scramble)
{
    float v[4];
    for (int i = 0; i < 6; i++) {
        GLenum light = GL_LIGHT0 + pick(s, 8), p = light_pnames[pick(s, 10)];
        random_colour(s, v, -2, 2);
        if (p == GL_SPOT_EXPONENT)
            v[0] = rndf(s, 0, 128);
        else if (p == GL_SPOT_CUTOFF)
            v[0] = pick(s, 4) ? rndf(s, 0, 90) : 180.0f;
        else if (p >= GL_CONSTANT_ATTENUATION && p <= GL_QUADRATIC_ATTENUATION)
            v[0] = rndf(s, 0, 3);
        G(Lightfv, light, p, v);
    }
    for (int i = 0; i < (scramble ? 0 : 4); i++) {
        GLenum p = material_pnames[pick(s, 5)];
        random_colour(s, v, -2, 2);
        if (p == GL_SHININESS)
            v[0] = rndf(s, 0, 128);
        G(Materialfv, faces[pick(s, 3)], p, v);
    }
}

/* Current values, transformation and lighting state; glColorMaterial only
 * when color_material is set.  The tests leave it unset: glColorMaterial
 * between a push and a glMaterial empties Mesa's vbo as glLight does, and
 * the material then stays pending through the pop (random_lights). */
static void random_vertex_state(fs_context *c, unsigned *s, bool color_material)
{
    float v[4];
    random_colour(s, v, -1.5f, 1.5f);
    G(Color4f, v[0], v[1], v[2], v[3]);
    G(Normal3f, rndf(s, -2, 2), rndf(s, -2, 2), rndf(s, -2, 2));
    G(TexCoord4f, rndf(s, -9, 9), rndf(s, -9, 9), rndf(s, -9, 9), rndf(s, -9, 9));
    static const GLenum modes[] = {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE};
    G(Viewport, pick(s, 20) - 10, pick(s, 20) - 10, pick(s, 64), pick(s, 64));
    G(DepthRange, rndf(s, 0, 1), rndf(s, 0, 1));
    G(ShadeModel, pick(s, 2) ? GL_FLAT : GL_SMOOTH);
    random_colour(s, v, -1, 1);
    G(MatrixMode, modes[pick(s, 3)]);
    G(LightModelfv, GL_LIGHT_MODEL_AMBIENT, v);
    G(LightModeli, GL_LIGHT_MODEL_LOCAL_VIEWER, pick(s, 2));
    G(LightModeli, GL_LIGHT_MODEL_TWO_SIDE, pick(s, 2));
    G(LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, pick(s, 2) ? GL_SINGLE_COLOR : GL_SEPARATE_SPECULAR_COLOR);
    G(EdgeFlag, (GLboolean)pick(s, 2));
    /* A texture matrix, for GL_TRANSPOSE_TEXTURE_MATRIX. */
    float m[16];
    for (int k = 0; k < 16; k++)
        m[k] = rndf(s, -2, 2);
    G(MatrixMode, GL_TEXTURE);
    G(LoadMatrixf, m);
    static const GLenum cm[] = {GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE};
    if (color_material)
        G(ColorMaterial, faces[pick(s, 3)], cm[pick(s, 5)]);
    /* The raster position (2.13): glWindowPos, as glRasterPos under this
     * state would meet texture coordinate generation, which the vertex
     * stage does not do yet (tests/test_pixel_rect.c covers glRasterPos). */
    G(WindowPos3f, rndf(s, -9, 70), rndf(s, -9, 70), rndf(s, -0.5f, 1.5f));
}

static void random_raster_state(fs_context *c, unsigned *s)
{
    G(PointSize, rndf(s, 0.5f, 8));
    G(LineWidth, rndf(s, 0.5f, 8));
    G(CullFace, faces[pick(s, 3)]);
    G(FrontFace, pick(s, 2) ? GL_CW : GL_CCW);
    static const GLenum pm[] = {GL_POINT, GL_LINE, GL_FILL};
    G(PolygonMode, faces[pick(s, 3)], pm[pick(s, 3)]);
    G(PolygonOffset, rndf(s, -4, 4), rndf(s, -4, 4));
    G(LineStipple, pick(s, 300) - 20, (GLushort)rnd(s));
    G(SampleCoverage, rndf(s, -0.5f, 1.5f), (GLboolean)pick(s, 2));
}

/* Fog (3.10), through each of the four glFog commands. */
static void random_fog_state(fs_context *c, unsigned *s)
{
    static const GLenum fog_modes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
    float v[4];
    random_colour(s, v, -0.5f, 1.5f);
    if (pick(s, 2))
        G(Fogfv, GL_FOG_COLOR, v);
    else
        G(Fogiv, GL_FOG_COLOR, ((GLint[4]){(GLint)(rnd(s) << 8), (GLint)(rnd(s) << 8), -(GLint)rnd(s), 7}));
    G(Fogi, GL_FOG_MODE, (GLint)fog_modes[pick(s, 3)]);
    G(Fogf, GL_FOG_DENSITY, rndf(s, 0, 4));
    G(Fogf, GL_FOG_START, rndf(s, -9, 9));
    float end = rndf(s, -9, 9);
    G(Fogfv, GL_FOG_END, &end);
    G(Fogi, GL_FOG_INDEX, pick(s, 100));
    GLint src = pick(s, 2) ? GL_FOG_COORD : GL_FRAGMENT_DEPTH;
    G(Fogiv, GL_FOG_COORD_SRC, &src);
}

static void random_fragment_state(fs_context *c, unsigned *s)
{
    G(Scissor, pick(s, 20) - 10, pick(s, 20) - 10, pick(s, 64), pick(s, 64));
    G(AlphaFunc, funcs[pick(s, 8)], rndf(s, -0.5f, 1.5f));
    G(StencilFunc, funcs[pick(s, 8)], pick(s, 600) - 200, rnd(s) | (rnd(s) << 24));
    G(StencilOp, stencil_ops[pick(s, 6)], stencil_ops[pick(s, 6)], stencil_ops[pick(s, 6)]);
    G(StencilMask, rnd(s) | (rnd(s) << 24));
    G(DepthFunc, funcs[pick(s, 8)]);
    G(DepthMask, (GLboolean)pick(s, 2));
    G(BlendFunc, blend_factors[pick(s, N(blend_factors))], blend_factors[pick(s, 6)]);
    if (pick(s, 2))
        G(BlendFuncSeparate, blend_factors[pick(s, N(blend_factors))], blend_factors[pick(s, 6)],
          blend_factors[pick(s, N(blend_factors))], blend_factors[pick(s, 6)]);
    static const GLenum equations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    G(BlendEquation, equations[pick(s, N(equations))]);
    G(LogicOp, GL_CLEAR + pick(s, 16));
    G(ColorMask, (GLboolean)pick(s, 2), (GLboolean)pick(s, 2), (GLboolean)pick(s, 2), (GLboolean)pick(s, 2));
    float v[4];
    random_colour(s, v, -0.5f, 1.5f);
    G(ClearColor, v[0], v[1], v[2], v[3]);
    random_colour(s, v, -0.5f, 1.5f);
    G(BlendColor, v[0], v[1], v[2], v[3]);
    G(ClearDepth, rndf(s, -0.5f, 1.5f));
    G(ClearStencil, pick(s, 1000) - 300);
    random_colour(s, v, -1.5f, 1.5f);
    G(ClearAccum, v[0], v[1], v[2], v[3]);
    G(ClearIndex, rndf(s, -5, 300));
    G(IndexMask, rnd(s) | (rnd(s) << 24));
    G(PixelZoom, rndf(s, -4, 4), rndf(s, -4, 4));
    G(ActiveTexture, GL_TEXTURE0);
    static const GLenum bufs[] = {GL_FRONT, GL_FRONT_LEFT, GL_FRONT_AND_BACK, GL_LEFT, GL_NONE};
    G(DrawBuffer, bufs[pick(s, N(bufs))]);
    G(ReadBuffer, bufs[pick(s, 2)]);
    G(Hint, hints[pick(s, N(hints))], hint_modes[pick(s, 3)]);
}

static void random_client_state(fs_context *c, unsigned *s)
{
    static const GLint align[] = {1, 2, 4, 8};
    for (int i = 0; i < N(pixel_store); i++) {
        GLenum p = pixel_store[i];
        if (pick(s, 2))
            G(PixelStorei, p, p == GL_PACK_ALIGNMENT || p == GL_UNPACK_ALIGNMENT ? align[pick(s, 4)] : pick(s, 40));
    }
    static const float data[64];
    static const GLenum types[] = {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
    G(VertexPointer, 2 + pick(s, 3), types[pick(s, 4)], pick(s, 5) * 4, data);
    G(NormalPointer, types[pick(s, 4)], pick(s, 5) * 4, data);
    G(ColorPointer, 3 + pick(s, 2), types[pick(s, 4)], pick(s, 5) * 4, data);
    G(TexCoordPointer, 1 + pick(s, 4), types[pick(s, 4)], pick(s, 5) * 4, data);
    G(ClientActiveTexture, GL_TEXTURE0);
}

static const GLenum min_filters[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                     GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE};
static const GLenum env_modes[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD};

/* The texture group's state (GL 1.5 spec tables 6.16-6.20): the
 * parameters of some of texture objects 0-3 (each bound to set them) and
 * the texture environment; random_state binds one of them after. */
static void random_texture_state(fs_context *c, unsigned *s)
{
    for (GLuint name = 0; name < 4; name++) {
        if (pick(s, 2))
            continue;
        G(BindTexture, GL_TEXTURE_2D, name);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min_filters[pick(s, N(min_filters))]);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, pick(s, 2) ? GL_LINEAR : GL_NEAREST);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wraps[pick(s, N(wraps))]);
        G(TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wraps[pick(s, N(wraps))]);
        GLfloat border[4];
        random_colour(s, border, 0.0f, 1.0f);
        G(TexParameterfv, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        G(TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, rndf(s, 0.0f, 1.0f));
    }
    G(TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env_modes[pick(s, N(env_modes))]);
    GLfloat colour[4];
    random_colour(s, colour, 0.0f, 1.0f);
    G(TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, colour);
}

/* scramble: the state changed between a push and its pop. */
static void random_state(fs_context *c, unsigned *s, rec *r, bool scramble)
{
    random_enables(c, s);
    put_error(c, r, "enables");
    random_vertex_state(c, s, false);
    put_error(c, r, "vertex state");
    random_lights(c, s, scramble);
    put_error(c, r, "lights and materials");
    random_raster_state(c, s);
    put_error(c, r, "raster state");
    random_fog_state(c, s);
    put_error(c, r, "fog state");
    random_fragment_state(c, s);
    put_error(c, r, "fragment state");
    random_client_state(c, s);
    put_error(c, r, "client state");
    random_texture_state(c, s);
    put_error(c, r, "texture state");
    G(BindTexture, GL_TEXTURE_2D, (GLuint)pick(s, 4));
    put_error(c, r, "texture binding");
}

static const struct { GLenum pname; const char *label; int n; } tex_params[] = {
    {GL_TEXTURE_MIN_FILTER, "GL_TEXTURE_MIN_FILTER", 1}, {GL_TEXTURE_MAG_FILTER, "GL_TEXTURE_MAG_FILTER", 1},
    {GL_TEXTURE_WRAP_S, "GL_TEXTURE_WRAP_S", 1}, {GL_TEXTURE_WRAP_T, "GL_TEXTURE_WRAP_T", 1},
    {GL_TEXTURE_BORDER_COLOR, "GL_TEXTURE_BORDER_COLOR", 4}, {GL_TEXTURE_PRIORITY, "GL_TEXTURE_PRIORITY", 1},
    {GL_TEXTURE_MIN_LOD, "GL_TEXTURE_MIN_LOD", 1}, {GL_TEXTURE_MAX_LOD, "GL_TEXTURE_MAX_LOD", 1},
    {GL_TEXTURE_BASE_LEVEL, "GL_TEXTURE_BASE_LEVEL", 1}, {GL_TEXTURE_MAX_LEVEL, "GL_TEXTURE_MAX_LEVEL", 1}};

/* glGetTexParameter{i,f}v of every parameter of the bound texture and of
 * textures 0-3 (bound in turn, the binding put back after), and
 * glGetTexEnv{i,f}v of the environment. */
static void dump_textures(fs_context *c, rec *r)
{
    GLint bound = 0;
    G(GetIntegerv, GL_TEXTURE_BINDING_2D, &bound);
    for (int name = -1; name < 4; name++) {
        if (name >= 0)
            G(BindTexture, GL_TEXTURE_2D, (GLuint)name);
        put(r, "texture (-1: the bound one)", name);
        for (int i = 0; i < N(tex_params); i++) {
            GLint iv[4] = {0};
            GLfloat fv[4] = {0};
            G(GetTexParameteriv, GL_TEXTURE_2D, tex_params[i].pname, iv);
            G(GetTexParameterfv, GL_TEXTURE_2D, tex_params[i].pname, fv);
            for (int k = 0; k < tex_params[i].n; k++) {
                put(r, tex_params[i].label, iv[k]);
                put(r, tex_params[i].label, fv[k]);
            }
        }
        put_error(c, r, "glGetTexParameter");
    }
    G(BindTexture, GL_TEXTURE_2D, (GLuint)bound);
    GLint mode = 0, icolour[4] = {0};
    GLfloat fmode = 0, fcolour[4] = {0};
    G(GetTexEnviv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode);
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &fmode);
    G(GetTexEnviv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, icolour);
    G(GetTexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, fcolour);
    put(r, "GL_TEXTURE_ENV_MODE", mode);
    put(r, "GL_TEXTURE_ENV_MODE", fmode);
    for (int k = 0; k < 4; k++) {
        put(r, "GL_TEXTURE_ENV_COLOR", icolour[k]);
        put(r, "GL_TEXTURE_ENV_COLOR", fcolour[k]);
    }
    put_error(c, r, "glGetTexEnv");
}

/* Every value a sequence ends with: the table, lights and materials, and
 * the texture objects and environment. */
static void dump_all(fs_context *c, rec *r)
{
    dump(c, r);
    dump_lighting(c, r);
    dump_textures(c, r);
}

/* Runs seq on OSMesa and on the model and compares every value read. */
typedef void (*seq_fn)(fs_context *c, rec *r, unsigned seed);

static int compare(seq_fn seq, unsigned seed, int *values)
{
    static rec a, b;
    a.n = b.n = 0;
    osm o;
    if (!osm_open(&o, 32, 32)) {
        osm_close(&o);
        return -1;
    }
    seq(NULL, &a, seed);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 32, 32);
    if (!c)
        return -1;
    seq(c, &b, seed);
    fs_context_destroy(c);
    *values = a.n;
    if (a.n != b.n) {
        printf("  seed %u: %d values on OSMesa, %d on the model\n", seed, a.n, b.n);
        return 1;
    }
    int bad = 0;
    for (int i = 0; i < a.n; i++) {
        /* Exact: NaN never occurs, and -0 equals 0 as glGet may give either. */
        if (a.v[i] != b.v[i] && bad++ < 12)
            printf("  seed %u: value %d (%s): OSMesa %.9g, model %.9g\n", seed, i, a.what[i], a.v[i], b.v[i]);
    }
    return bad != 0;
}

/* compare for a sequence without a seed, with the count printed. */
static int compare_once(seq_fn seq)
{
    int values = 0;
    int rc = compare(seq, 0, &values);
    printf("  %d values and errors compared\n", values);
    return rc;
}

/* ---- tests ---- */

/* A test of one sequence without a seed (skipped without OSMesa). */
#define CHECK_ONCE_VS_OSMESA(seq)                                                                          \
    do {                                                                                                   \
        int rc_ = compare_once(seq);                                                                       \
        if (rc_ < 0)                                                                                       \
            SKIP("no OSMesa context");                                                                     \
        CHECK_EQ_INT(rc_, 0);                                                                              \
    } while (0)

static void seq_initial(fs_context *c, rec *r, unsigned seed)
{
    (void)seed;
    dump_all(c, r);
}

/* Every variable of the table answers the four glGet commands on both
 * without error, with the same initial values. */
TEST(every_variable_answers_glget_vs_osmesa)
{
    CHECK_ONCE_VS_OSMESA(seq_initial);
}

static void seq_random(fs_context *c, rec *r, unsigned seed)
{
    unsigned s = seed;
    random_state(c, &s, r, false);
    dump_all(c, r);
}

TEST(random_state_glget_vs_osmesa)
{
    for (unsigned seed = 1; seed <= 8; seed++) {
        int values = 0;
        int rc = compare(seq_random, seed, &values);
        if (rc < 0)
            SKIP("no OSMesa context");
        CHECK_EQ_INT(rc, 0);
        if (seed == 8)
            printf("  8 seeds, %d values each\n", values);
    }
}

/* The server groups one at a time, then random unions and GL_ALL_ATTRIB_BITS. */
static const GLbitfield groups[] = {
    GL_CURRENT_BIT, GL_POINT_BIT, GL_LINE_BIT, GL_POLYGON_BIT, GL_POLYGON_STIPPLE_BIT, GL_PIXEL_MODE_BIT,
    GL_LIGHTING_BIT, GL_FOG_BIT, GL_DEPTH_BUFFER_BIT, GL_ACCUM_BUFFER_BIT, GL_STENCIL_BUFFER_BIT,
    GL_VIEWPORT_BIT, GL_TRANSFORM_BIT, GL_ENABLE_BIT, GL_COLOR_BUFFER_BIT, GL_HINT_BIT, GL_EVAL_BIT,
    GL_LIST_BIT, GL_TEXTURE_BIT, GL_SCISSOR_BIT, GL_MULTISAMPLE_BIT};

static GLbitfield server_mask(unsigned seed)
{
    unsigned k = seed % (N(groups) + 4);
    if (k < (unsigned)N(groups))
        return groups[k];
    if (k == (unsigned)N(groups))
        return GL_ALL_ATTRIB_BITS;
    return (GLbitfield)(seed * 2654435761u) & 0x200fffffu;
}

static void seq_push_pop(fs_context *c, rec *r, unsigned seed)
{
    unsigned s = seed;
    random_state(c, &s, r, false);
    G(PushAttrib, server_mask(seed));
    G(PushClientAttrib, seed % 4 == 3 ? GL_CLIENT_ALL_ATTRIB_BITS : seed % 3);
    put_error(c, r, "push");
    random_state(c, &s, r, true);
    G0(PopAttrib);
    G0(PopClientAttrib);
    put_error(c, r, "pop");
    dump_all(c, r);
}

TEST(push_pop_restores_vs_osmesa)
{
    int total = 0;
    for (unsigned seed = 1; seed <= 2 * (N(groups) + 4); seed++) {
        int values = 0;
        int rc = compare(seq_push_pop, seed, &values);
        if (rc < 0)
            SKIP("no OSMesa context");
        if (rc)
            printf("  seed %u: server mask %#x\n", seed, server_mask(seed));
        CHECK_EQ_INT(rc, 0);
        total += values;
    }
    printf("  %d seeds, %d values\n", 2 * (N(groups) + 4), total);
}

/* Depth, overflow and underflow, Begin/End, and display lists: PushAttrib
 * is compiled, PushClientAttrib executes at once (GL 1.5 spec 5.4). */
static void seq_stack_errors(fs_context *c, rec *r, unsigned seed)
{
    (void)seed;
    GLint v;
    for (int i = 0; i < 18; i++) {
        G(PushAttrib, GL_ALL_ATTRIB_BITS);
        put_error(c, r, "PushAttrib");
        G(PushClientAttrib, GL_CLIENT_ALL_ATTRIB_BITS);
        put_error(c, r, "PushClientAttrib");
    }
    G(GetIntegerv, GL_ATTRIB_STACK_DEPTH, &v);
    put(r, "GL_ATTRIB_STACK_DEPTH", v);
    for (int i = 0; i < 18; i++) {
        G0(PopAttrib);
        put_error(c, r, "PopAttrib");
        G0(PopClientAttrib);
        put_error(c, r, "PopClientAttrib");
    }
    G(Begin, GL_POINTS);
    G(PushAttrib, GL_CURRENT_BIT);
    put_error(c, r, "PushAttrib in Begin");
    G(PushClientAttrib, GL_CLIENT_PIXEL_STORE_BIT);
    put_error(c, r, "PushClientAttrib in Begin");
    G0(End);
    G(NewList, 1, GL_COMPILE);
    G(PushAttrib, GL_ENABLE_BIT);
    G(PushClientAttrib, GL_CLIENT_PIXEL_STORE_BIT);
    G(Enable, GL_BLEND);
    G0(PopAttrib);
    G0(EndList);
    put_error(c, r, "list");
    G(GetIntegerv, GL_ATTRIB_STACK_DEPTH, &v);
    put(r, "GL_ATTRIB_STACK_DEPTH after compile", v);
    G(GetIntegerv, GL_CLIENT_ATTRIB_STACK_DEPTH, &v);
    put(r, "GL_CLIENT_ATTRIB_STACK_DEPTH after compile", v);
    G(CallList, 1);
    put_error(c, r, "CallList");
    put(r, "GL_BLEND after the list", GR(IsEnabled, GL_BLEND));
    G(GetIntegerv, GL_ATTRIB_STACK_DEPTH, &v);
    put(r, "GL_ATTRIB_STACK_DEPTH after CallList", v);
}

TEST(stack_depths_and_errors_vs_osmesa)
{
    CHECK_ONCE_VS_OSMESA(seq_stack_errors);
}

/* glMaterial under GL_COLOR_MATERIAL, for every face and mode of
 * glColorMaterial and every face and property of glMaterial: llvmpipe
 * leaves the tracked properties alone (pipeline/lighting.c
 * set_untracked), the others take the value. */
static void seq_color_material_tracking(fs_context *c, rec *r, unsigned seed)
{
    (void)seed;
    static const GLenum faces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
    static const GLenum modes[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
    static const GLenum props[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
    float v = 0.0f;
    for (int cf = 0; cf < 3; cf++)
        for (int m = 0; m < 5; m++)
            for (int mf = 0; mf < 3; mf++)
                for (int p = 0; p < 5; p++) {
                    G(Color4f, 0.25f, 0.5f, 0.75f, 1.0f);
                    G(ColorMaterial, faces[cf], modes[m]);
                    G(PushAttrib, GL_ENABLE_BIT);
                    G(Enable, GL_COLOR_MATERIAL);
                    v += 0.001f;
                    const float val[4] = {v, -v, 2 * v, 1.0f};
                    G(Materialfv, faces[mf], props[p], val);
                    G0(PopAttrib);
                    dump_materials(c, r);
                    put_error(c, r, "glMaterial under GL_COLOR_MATERIAL");
                }
}

TEST(color_material_tracking_vs_osmesa)
{
    CHECK_ONCE_VS_OSMESA(seq_color_material_tracking);
}

/* The known difference of random_lights: glLightf, glMaterialfv,
 * glPopAttrib leaves OSMesa's material as set (0.9), the model restores
 * it (0.1); glMaterialfv, glLightf, glPopAttrib restores it on both.
 * Fails when either library changes its answer. */
static void seq_deferred_material(fs_context *c, rec *r, unsigned seed)
{
    (void)seed;
    const float a[4] = {0.1f, 0, 0, 1}, b[4] = {0.9f, 0, 0, 1};
    for (int order = 0; order < 2; order++) {
        G(Materialfv, GL_FRONT, GL_AMBIENT, a);
        G(PushAttrib, GL_LIGHTING_BIT);
        if (order == 0)
            G(Lightf, GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f + (float)order);
        G(Materialfv, GL_FRONT, GL_AMBIENT, b);
        if (order == 1)
            G(Lightf, GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f + (float)order);
        G0(PopAttrib);
        float v[4];
        G(GetMaterialfv, GL_FRONT, GL_AMBIENT, v);
        put(r, "front GL_AMBIENT after the pop", v[0]);
    }
}

TEST(deferred_material_known_difference)
{
    static rec a, b;
    a.n = b.n = 0;
    osm o;
    if (!osm_open(&o, 32, 32)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    seq_deferred_material(NULL, &a, 0);
    osm_close(&o);
    fs_context *c = fs_context_create(NULL, 32, 32);
    CHECK(c != NULL);
    seq_deferred_material(c, &b, 0);
    fs_context_destroy(c);
    CHECK_EQ_INT(a.n, 2);
    CHECK_EQ_INT(b.n, 2);
    CHECK(a.v[0] == 0.9f && a.v[1] == 0.1f); /* OSMesa: pending, then restored */
    CHECK(b.v[0] == 0.1f && b.v[1] == 0.1f); /* the model: restored both times */
}

/* The errors of the setters of stored-only state (GL 1.5 spec 2.5: the
 * call has no other effect), Begin/End, and what display lists compile. */
static void seq_setter_errors(fs_context *c, rec *r, unsigned seed)
{
    (void)seed;
    static const char *what[] = {"glFogi(GL_FOG_MODE, bad)", "glFogf(GL_FOG_DENSITY, -1)", "glFogf(GL_FOG_COLOR)",
                                 "glFogf(bad pname)", "glFogiv(GL_FOG_COORD_SRC, bad)", "glFogfv(GL_FOG_MODE, NaN)",
                                 "glActiveTexture(GL_TEXTURE_2D)", "glClientActiveTexture(GL_TEXTURE0 - 1)",
                                 "glLineStipple(0)", "glLineStipple(1000)", "glSampleCoverage(2)"};
    GLint bad = GL_TEXTURE_2D;
    float nan = __builtin_nanf("");
    for (int i = 0; i < N(what); i++) {
        switch (i) {
        case 0: G(Fogi, GL_FOG_MODE, GL_TEXTURE_2D); break;
        case 1: G(Fogf, GL_FOG_DENSITY, -1.0f); break;
        case 2: G(Fogf, GL_FOG_COLOR, 0.5f); break;
        case 3: G(Fogf, GL_FOG_HINT, 0.5f); break;
        case 4: G(Fogiv, GL_FOG_COORD_SRC, &bad); break;
        case 5: G(Fogfv, GL_FOG_MODE, &nan); break;
        case 6: G(ActiveTexture, GL_TEXTURE_2D); break; /* units beyond 0 are a known difference */
        case 7: G(ClientActiveTexture, GL_TEXTURE0 - 1); break;
        case 8: G(LineStipple, 0, 0x1234); break;
        case 9: G(LineStipple, 1000, 0x4321); break;
        default: G(SampleCoverage, 2.0f, GL_TRUE); break;
        }
        put_error(c, r, what[i]);
        dump(c, r);
    }
    G(Begin, GL_POINTS);
    G(Fogf, GL_FOG_START, 3.0f);
    G(EdgeFlag, GL_FALSE); /* allowed between Begin and End (2.6.3) */
    G0(End);
    put_error(c, r, "glFog between Begin and End");
    G(NewList, 1, GL_COMPILE);
    G(Fogf, GL_FOG_END, 7.0f);
    G(PixelZoom, 2.0f, 3.0f);
    G(ClientActiveTexture, GL_TEXTURE0);
    G(ClearAccum, 0.25f, 0.5f, -0.75f, 1.0f);
    G0(EndList);
    dump(c, r);
    G(CallList, 1);
    put_error(c, r, "CallList");
    dump(c, r);
}

TEST(setter_errors_vs_osmesa)
{
    CHECK_ONCE_VS_OSMESA(seq_setter_errors);
}

/* Popping marks the popped groups dirty, for the validation step. */
TEST(pop_marks_groups_dirty)
{
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    fsglPushAttrib(c, GL_SCISSOR_BIT | GL_FOG_BIT);
    fsglPushClientAttrib(c, GL_CLIENT_PIXEL_STORE_BIT);
    c->dirty = 0;
    fsglPopAttrib(c);
    CHECK_EQ_UINT(c->dirty, GL_SCISSOR_BIT | GL_FOG_BIT);
    fsglPopClientAttrib(c);
    CHECK_EQ_UINT(c->dirty, GL_SCISSOR_BIT | GL_FOG_BIT | FS_CLIENT_PIXEL_STORE);
    c->dirty = 0;
    fsglEnable(c, GL_BLEND);
    CHECK_EQ_UINT(c->dirty, GL_COLOR_BUFFER_BIT | GL_ENABLE_BIT);
    fs_context_destroy(c);
}

/* Not yet in the table. */
#define PENDING_STATE

/* GL 1.0-1.5 names OSMesa answers in glGetIntegerv that the table does not
 * have yet (issue 18): none since GL_TEXTURE_BINDING_CUBE_MAP came with the
 * cube maps; GL_NONE stands for the empty list (C has no empty array), and
 * is never a name OSMesa answers. */
static const GLenum pending[] = {
    PENDING_STATE GL_NONE
};

static bool is_pending(GLenum e)
{
    for (int i = 0; i < N(pending); i++)
        if (pending[i] == e && e != GL_NONE)
            return true;
    return false;
}

/* Every GL 1.0-1.5 enum (driver/gl_enums.c, from gl.h and glext.h) that
 * OSMesa answers in glGetIntegerv without an error is a row of the table
 * (glGet answers it without an error), unless listed as pending; and
 * nothing pending is answered yet, so the list shrinks with the table. */
TEST(every_glget_name_of_osmesa_is_in_the_table)
{
    osm o;
    if (!osm_open(&o, 8, 8)) {
        osm_close(&o);
        SKIP("no OSMesa context");
    }
    fs_context *c = fs_context_create(NULL, 8, 8);
    REQUIRE(c);
    int answered = 0, missing = 0;
    for (uint32_t e = 0; e < 0x10000; e++) {
        const char *name = fs_gl_enum_name(e);
        if (!name || strstr(name, "_BIT"))
            continue; /* masks (GL_COLOR_BUFFER_BIT = GL_LIGHT0's value is a name of GL_LIGHT0) */
        GLint v[64];
        while (glGetError() != GL_NO_ERROR)
            ;
        glGetIntegerv(e, v);
        if (glGetError() != GL_NO_ERROR)
            continue;
        answered++;
        fsglGetIntegerv(c, e, v);
        bool model = fsglGetError(c) == GL_NO_ERROR;
        if (model == is_pending(e) && missing++ < 20)
            printf("  %s (%#x): %s\n", name, e, model ? "answered but listed as pending" : "not in the table");
    }
    printf("  %d names answered by OSMesa, %d pending\n", answered, N(pending) - 1);
    CHECK_EQ_INT(missing, 0);
    fs_context_destroy(c);
    osm_close(&o);
}

TEST_LIST = {
    TEST_ENTRY(every_glget_name_of_osmesa_is_in_the_table),
    TEST_ENTRY(every_variable_answers_glget_vs_osmesa),
    TEST_ENTRY(random_state_glget_vs_osmesa),
    TEST_ENTRY(push_pop_restores_vs_osmesa),
    TEST_ENTRY(stack_depths_and_errors_vs_osmesa),
    TEST_ENTRY(setter_errors_vs_osmesa),
    TEST_ENTRY(color_material_tracking_vs_osmesa),
    TEST_ENTRY(deferred_material_known_difference),
    TEST_ENTRY(pop_marks_groups_dirty),
    TEST_END,
};

/* Program mode, `test_state_table --print`: the sequences above as an
 * ordinary OSMesa program, every call through whatever library provides
 * gl* and OSMesa* (libOSMesa, or build/libfragsimGL.so preloaded), each
 * value and error printed.  tests/cli_shim.sh runs it both ways and
 * requires the same output: the whole GL 1.5 state set, pushed,
 * scrambled, popped and queried through the shim as on libOSMesa. */
static int print_sequences(void)
{
    static const struct { seq_fn fn; const char *name; unsigned seeds; } seqs[] = {
        {seq_initial, "initial", 1}, {seq_random, "random", 4}, {seq_push_pop, "push-pop", 2 * N(groups) + 8},
        {seq_stack_errors, "stack-errors", 1}, {seq_setter_errors, "setter-errors", 1},
        {seq_color_material_tracking, "color-material", 1},
    };
    static rec a;
    long values = 0;
    for (size_t q = 0; q < N(seqs); q++)
        for (unsigned seed = 1; seed <= seqs[q].seeds; seed++) {
            osm o;
            if (!osm_open(&o, 32, 32)) {
                osm_close(&o);
                fprintf(stderr, "test_state_table: no OSMesa context\n");
                return 1;
            }
            if (q == 0)
                fprintf(stderr, "test_state_table: renderer %s\n", (const char *)glGetString(GL_RENDERER));
            a.n = 0;
            seqs[q].fn(NULL, &a, seed);
            osm_close(&o);
            for (int i = 0; i < a.n; i++)
                printf("%s %u %d %s %.9g\n", seqs[q].name, seed, i, a.what[i], a.v[i]);
            values += a.n;
        }
    fprintf(stderr, "test_state_table: %ld values and errors printed\n", values);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--print"))
        return print_sequences();
    return check_main(argc, argv, test_list);
}
