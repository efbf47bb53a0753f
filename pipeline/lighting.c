/*
 * Lighting (GL 1.5 spec 2.14): Light, LightModel, Material, ColorMaterial,
 * ShadeModel, and the lighting equation of 2.14.1 evaluated per vertex in
 * float (Mesa runs it as a float vertex program), results clamped to
 * [0,1] (2.14.6).  Light positions and spot directions are transformed by
 * the modelview matrix when they are specified (2.14.2).
 */
#include <math.h>
#include <string.h>
#include "vertex_internal.h"
#include "vp_pow.h"

int fs_light_param_count(GLenum pname)
{
    switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
    }
}

int fs_lightmodel_param_count(GLenum pname)
{
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: return 4;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: case GL_LIGHT_MODEL_TWO_SIDE: case GL_LIGHT_MODEL_COLOR_CONTROL: return 1;
    default: return 0;
    }
}

int fs_material_param_count(GLenum pname)
{
    switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE: return 4;
    case GL_SHININESS: return 1;
    case GL_COLOR_INDEXES: return 3;
    default: return 0;
    }
}

/* Integer colours map to [-1,1] (GL 1.5 spec table 2.9); other integer
 * parameters convert directly. */
static float int_color(GLint i)
{
    return (float)((2.0 * i + 1.0) / 4294967295.0);
}

static bool is_color_pname(GLenum p)
{
    return p == GL_AMBIENT || p == GL_DIFFUSE || p == GL_SPECULAR || p == GL_EMISSION ||
           p == GL_AMBIENT_AND_DIFFUSE || p == GL_LIGHT_MODEL_AMBIENT;
}

static void light_v(fs_context *c, GLenum light, GLenum pname, const float *p)
{
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + FS_MAX_LIGHTS) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    fs_light *l = &c->lighting.light[light - GL_LIGHT0];
    const float *mv = c->xf.modelview[c->xf.modelview_top].m;
    switch (pname) {
    case GL_AMBIENT: memcpy(l->ambient, p, 4 * sizeof(float)); break;
    case GL_DIFFUSE: memcpy(l->diffuse, p, 4 * sizeof(float)); break;
    case GL_SPECULAR: memcpy(l->specular, p, 4 * sizeof(float)); break;
    case GL_POSITION: fs_mat_xform4(l->position, mv, p); break;
    case GL_SPOT_DIRECTION:
        for (int r = 0; r < 3; r++)
            l->spot_direction[r] = mv[r] * p[0] + mv[4 + r] * p[1] + mv[8 + r] * p[2];
        break;
    case GL_SPOT_EXPONENT:
        if (!(p[0] >= 0.0f && p[0] <= 128.0f)) { fs_error(c, GL_INVALID_VALUE); return; }
        l->spot_exponent = p[0];
        break;
    case GL_SPOT_CUTOFF:
        if (!((p[0] >= 0.0f && p[0] <= 90.0f) || p[0] == 180.0f)) { fs_error(c, GL_INVALID_VALUE); return; }
        l->spot_cutoff = p[0];
        break;
    case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION:
        if (!(p[0] >= 0.0f)) { fs_error(c, GL_INVALID_VALUE); return; }
        l->attenuation[pname - GL_CONSTANT_ATTENUATION] = p[0];
        break;
    default:
        fs_error(c, GL_INVALID_ENUM);
    }
}

void fs_exec_Lightfv(fs_context *c, GLenum light, GLenum pname, const GLfloat *params)
{
    light_v(c, light, pname, params);
}

/* The integer forms of Light and Material (GL 1.5 2.14.2): colours map
 * [-2^31, 2^31-1] linearly to [-1, 1], other values convert directly. */
static void int_params(float f[4], GLenum pname, int n, const GLint *params)
{
    for (int i = 0; i < 4; i++)
        f[i] = i >= n ? 0.0f : is_color_pname(pname) ? int_color(params[i]) : (float)params[i];
}

void fs_exec_Lightiv(fs_context *c, GLenum light, GLenum pname, const GLint *params)
{
    float f[4];
    int_params(f, pname, fs_light_param_count(pname), params);
    light_v(c, light, pname, f);
}

void fs_exec_Lightf(fs_context *c, GLenum light, GLenum pname, GLfloat param)
{
    if (fs_light_param_count(pname) != 1) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    light_v(c, light, pname, &param);
}

void fs_exec_Lighti(fs_context *c, GLenum light, GLenum pname, GLint param)
{
    fs_exec_Lightf(c, light, pname, (float)param);
}

static void lightmodel_v(fs_context *c, GLenum pname, const float *p)
{
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: memcpy(c->lighting.model_ambient, p, 4 * sizeof(float)); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: c->lighting.local_viewer = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: c->lighting.two_side = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        if (p[0] == (float)GL_SINGLE_COLOR) {
            c->lighting.color_control = GL_SINGLE_COLOR;
            break;
        }
        if (p[0] == (float)GL_SEPARATE_SPECULAR_COLOR) {
            c->lighting.color_control = GL_SEPARATE_SPECULAR_COLOR;
            break;
        }
        fs_error(c, GL_INVALID_ENUM);
        break;
    default:
        fs_error(c, GL_INVALID_ENUM);
    }
}

void fs_exec_LightModelfv(fs_context *c, GLenum pname, const GLfloat *params)
{
    lightmodel_v(c, pname, params);
}

void fs_exec_LightModeliv(fs_context *c, GLenum pname, const GLint *params)
{
    float f[4] = {0};
    int n = fs_lightmodel_param_count(pname);
    for (int i = 0; i < n; i++)
        f[i] = pname == GL_LIGHT_MODEL_AMBIENT ? int_color(params[i]) : (float)params[i];
    lightmodel_v(c, pname, f);
}

void fs_exec_LightModelf(fs_context *c, GLenum pname, GLfloat param)
{
    if (fs_lightmodel_param_count(pname) != 1) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    lightmodel_v(c, pname, &param);
}

void fs_exec_LightModeli(fs_context *c, GLenum pname, GLint param)
{
    fs_exec_LightModelf(c, pname, (float)param);
}

/* Whether GL_COLOR_MATERIAL tracks colour property prop (GL_AMBIENT,
 * GL_DIFFUSE, GL_SPECULAR or GL_EMISSION) of face f (0 front, 1 back):
 * it is enabled, and glColorMaterial named the face and the property
 * (GL 1.5 spec 2.14.3). */
static bool color_material_tracks(const fs_context *c, int f, GLenum prop)
{
    const fs_lighting_state *L = &c->lighting;
    if (!L->color_material || L->color_material_face == (f ? GL_FRONT : GL_BACK))
        return false;
    GLenum mode = L->color_material_mode;
    return mode == prop || (mode == GL_AMBIENT_AND_DIFFUSE && (prop == GL_AMBIENT || prop == GL_DIFFUSE));
}

/* glMaterial of a property GL_COLOR_MATERIAL tracks has no effect on
 * llvmpipe: Mesa's glMaterial leaves out the tracked properties, which
 * follow the current colour (measured on OSMesa: with GL_FRONT, GL_DIFFUSE
 * tracked, glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE) changes only the
 * back diffuse). */
static void set_untracked(const fs_context *c, int f, GLenum prop, float dst[4], const float *p)
{
    if (!color_material_tracks(c, f, prop))
        memcpy(dst, p, 16);
}

static void material_v(fs_context *c, GLenum face, GLenum pname, const float *p)
{
    int mask;
    switch (face) {
    case GL_FRONT: mask = 1; break;
    case GL_BACK: mask = 2; break;
    case GL_FRONT_AND_BACK: mask = 3; break;
    default: fs_error(c, GL_INVALID_ENUM); return;
    }
    if (pname == GL_SHININESS && !(p[0] >= 0.0f && p[0] <= 128.0f)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    fs_material before[2];
    memcpy(before, c->lighting.material, sizeof before);
    for (int f = 0; f < 2; f++) {
        if (!(mask & (1 << f)))
            continue;
        fs_material *m = &c->lighting.material[f];
        switch (pname) {
        case GL_AMBIENT: set_untracked(c, f, GL_AMBIENT, m->ambient, p); break;
        case GL_DIFFUSE: set_untracked(c, f, GL_DIFFUSE, m->diffuse, p); break;
        case GL_SPECULAR: set_untracked(c, f, GL_SPECULAR, m->specular, p); break;
        case GL_EMISSION: set_untracked(c, f, GL_EMISSION, m->emission, p); break;
        case GL_AMBIENT_AND_DIFFUSE:
            set_untracked(c, f, GL_AMBIENT, m->ambient, p);
            set_untracked(c, f, GL_DIFFUSE, m->diffuse, p);
            break;
        case GL_SHININESS: m->shininess = p[0]; break;
        case GL_COLOR_INDEXES: break; /* colour-index mode only */
        default: fs_error(c, GL_INVALID_ENUM); return;
        }
    }
    /* GL 1.5 spec 2.6.3: Material is allowed between Begin and End and
     * applies to the vertices that follow. */
    if (c->prim.inside_begin)
        fs_vs_material_changed(c, before);
}

void fs_exec_Materialfv(fs_context *c, GLenum face, GLenum pname, const GLfloat *params)
{
    material_v(c, face, pname, params);
}

void fs_exec_Materialiv(fs_context *c, GLenum face, GLenum pname, const GLint *params)
{
    float f[4];
    int_params(f, pname, fs_material_param_count(pname), params);
    material_v(c, face, pname, f);
}

void fs_exec_Materialf(fs_context *c, GLenum face, GLenum pname, GLfloat param)
{
    if (pname != GL_SHININESS) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    material_v(c, face, pname, &param);
}

void fs_exec_Materiali(fs_context *c, GLenum face, GLenum pname, GLint param)
{
    fs_exec_Materialf(c, face, pname, (float)param);
}

/* ---- glGetLight and glGetMaterial (GL 1.5 spec 6.1.3) ---- */

/* The stored values of a light parameter (positions and directions in eye
 * coordinates, 2.14.2) and their number, or NULL after the error. */
static const float *light_param(fs_context *c, GLenum light, GLenum pname, int *n)
{
    *n = fs_light_param_count(pname);
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + FS_MAX_LIGHTS || *n == 0) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    const fs_light *l = &c->lighting.light[light - GL_LIGHT0];
    switch (pname) {
    case GL_AMBIENT: return l->ambient;
    case GL_DIFFUSE: return l->diffuse;
    case GL_SPECULAR: return l->specular;
    case GL_POSITION: return l->position;
    case GL_SPOT_DIRECTION: return l->spot_direction;
    case GL_SPOT_EXPONENT: return &l->spot_exponent;
    case GL_SPOT_CUTOFF: return &l->spot_cutoff;
    default: return &l->attenuation[pname - GL_CONSTANT_ATTENUATION];
    }
}

/* The same for a material of one face (GL_FRONT or GL_BACK only). */
static const float *material_param(fs_context *c, GLenum face, GLenum pname, int *n)
{
    static const float no_indexes[3];
    *n = pname == GL_AMBIENT_AND_DIFFUSE ? 0 : fs_material_param_count(pname);
    if ((face != GL_FRONT && face != GL_BACK) || *n == 0) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    const fs_material *m = &c->lighting.material[face == GL_BACK];
    switch (pname) {
    case GL_AMBIENT: return m->ambient;
    case GL_DIFFUSE: return m->diffuse;
    case GL_SPECULAR: return m->specular;
    case GL_EMISSION: return m->emission;
    case GL_SHININESS: return &m->shininess;
    default: return no_indexes; /* colour-index mode only */
    }
}

/* Writes the n values v of a query (none after an error, v NULL) as
 * floats, or as integers: colours as glGetIntegerv converts them (6.1.2),
 * other values as OSMesa answers (measured): light parameters toward zero,
 * the shininess to the nearest integer. */
static void put_params(GLenum pname, const float *v, int n, GLfloat *fv, GLint *iv)
{
    for (int i = 0; v && i < n; i++) {
        if (fv)
            fv[i] = v[i];
        else if (is_color_pname(pname))
            iv[i] = fs_norm_to_int(v[i]);
        else
            iv[i] = pname == GL_SHININESS ? (GLint)lroundf(v[i]) : (GLint)v[i];
    }
}

static void get_light(fs_context *c, GLenum light, GLenum pname, GLfloat *fv, GLint *iv)
{
    int n;
    const float *v = light_param(c, light, pname, &n);
    put_params(pname, v, n, fv, iv);
}

static void get_material(fs_context *c, GLenum face, GLenum pname, GLfloat *fv, GLint *iv)
{
    int n;
    const float *v = material_param(c, face, pname, &n);
    put_params(pname, v, n, fv, iv);
}

void fs_exec_GetLightfv(fs_context *c, GLenum l, GLenum pname, GLfloat *params) { get_light(c, l, pname, params, NULL); }
void fs_exec_GetLightiv(fs_context *c, GLenum l, GLenum pname, GLint *params) { get_light(c, l, pname, NULL, params); }
void fs_exec_GetMaterialfv(fs_context *c, GLenum face, GLenum pname, GLfloat *params)
{
    get_material(c, face, pname, params, NULL);
}
void fs_exec_GetMaterialiv(fs_context *c, GLenum face, GLenum pname, GLint *params)
{
    get_material(c, face, pname, NULL, params);
}

void fs_exec_ColorMaterial(fs_context *c, GLenum face, GLenum mode)
{
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
        mode != GL_AMBIENT_AND_DIFFUSE) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->lighting.color_material_face = face;
    c->lighting.color_material_mode = mode;
    fs_color_material_update(c);
}

void fs_exec_ShadeModel(fs_context *c, GLenum mode)
{
    if (mode != GL_FLAT && mode != GL_SMOOTH) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->lighting.shade_model = mode;
}

void fs_exec_ProvokingVertex(fs_context *c, GLenum mode)
{
    /* ARB_provoking_vertex: any other mode is INVALID_ENUM. */
    if (mode != GL_FIRST_VERTEX_CONVENTION && mode != GL_LAST_VERTEX_CONVENTION) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->lighting.provoking_vertex = mode;
}

static void apply_color_material(fs_material *m, GLenum mode, const float col[4])
{
    switch (mode) {
    case GL_EMISSION: memcpy(m->emission, col, 16); break;
    case GL_AMBIENT: memcpy(m->ambient, col, 16); break;
    case GL_DIFFUSE: memcpy(m->diffuse, col, 16); break;
    case GL_SPECULAR: memcpy(m->specular, col, 16); break;
    default: memcpy(m->ambient, col, 16); memcpy(m->diffuse, col, 16); break;
    }
}

void fs_color_material_update(fs_context *c)
{
    if (!c->lighting.color_material)
        return;
    GLenum face = c->lighting.color_material_face;
    if (face != GL_BACK)
        apply_color_material(&c->lighting.material[0], c->lighting.color_material_mode, c->current.color);
    if (face != GL_FRONT)
        apply_color_material(&c->lighting.material[1], c->lighting.color_material_mode, c->current.color);
}

/* Mesa's NORMALIZE_3FV, on the CPU for the light state: the squares
 * summed left to right, 1/sqrt, a zero vector left alone. */
static void normalize3(float v[3])
{
    float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (len2 > 0.0f) {
        float inv = 1.0f / sqrtf(len2);
        v[0] *= inv; v[1] *= inv; v[2] *= inv;
    }
}

void fs_lighting_setup(fs_context *c, fs_vs_setup *s)
{
    const fs_lighting_state *L = &c->lighting;
    s->lighting = L->enabled;
    s->two_side = L->enabled && L->two_side;
    s->local_viewer = L->local_viewer;
    s->need_eye = L->local_viewer;
    s->normalize = c->xf.normalize;
    s->rescale = c->xf.rescale_normal;
    s->light_object_space = false;
    memcpy(s->model_ambient, L->model_ambient, sizeof s->model_ambient);
    s->mat[0] = L->material[0];
    s->mat[1] = L->material[1];
    s->cm_face_mask = 0;
    if (L->color_material) {
        s->cm_face_mask = L->color_material_face == GL_FRONT ? 1 : L->color_material_face == GL_BACK ? 2 : 3;
        s->cm_mode = L->color_material_mode;
    }
    s->nlights = 0;
    if (!s->lighting)
        return;
    for (int i = 0; i < FS_MAX_LIGHTS; i++) {
        const fs_light *l = &L->light[i];
        if (!l->enabled)
            continue;
        fs_light_setup *o = &s->light[s->nlights++];
        memcpy(o->amb, l->ambient, 16);
        memcpy(o->dif, l->diffuse, 16);
        memcpy(o->spe, l->specular, 16);
        memcpy(o->pos, l->position, 16);
        memcpy(o->att, l->attenuation, sizeof o->att);
        o->attenuated = o->att[0] != 1.0f || o->att[1] != 0.0f || o->att[2] != 0.0f;
        o->positional = l->position[3] != 0.0f;
        /* Infinite lights are spot lights too in llvmpipe (measured: piglit's
         * infinite-spot-light reads half the ambient red, its spot factor,
         * where the spec's attenuation would leave all of it). */
        o->spot = l->spot_cutoff != 180.0f;
        o->spot_exp = l->spot_exponent;
        /* The cutoff's cosine in float, the direction normalised once. */
        o->cos_cutoff = cosf(l->spot_cutoff * (float)(FS_PI / 180.0));
        memcpy(o->spot_dir, l->spot_direction, sizeof o->spot_dir);
        normalize3(o->spot_dir);
        if (o->positional) {
            /* Mesa's _Position: the eye position divided by w. */
            float iw = 1.0f / o->pos[3];
            o->pos[0] *= iw; o->pos[1] *= iw; o->pos[2] *= iw;
            s->need_eye = true;
        }
    }
}

/* Mesa's vertex program lights in eye space when a light is positional
 * or a spot light, with a local viewer or separate specular colour, when
 * texture generation reads eye coordinates, or when the modelview does not
 * preserve lengths; otherwise in object space (light.c
 * _mesa_update_tnl_spaces): then the normal is the object's and a
 * directional light's direction is brought back by the inverse modelview,
 * with the eye's z axis (the half vector's) by the modelview itself.  The
 * directional vectors are Mesa's state values, computed on the CPU. */
void fs_lighting_spaces(fs_vs_setup *s)
{
    bool eye = s->need_eye || s->separate_specular || s->texgen_eye || !s->mv_rigid;
    for (int i = 0; i < s->nlights; i++)
        eye |= s->light[i].positional || s->light[i].spot;
    s->light_object_space = !eye;
    float zdir[3] = {0.0f, 0.0f, 1.0f};
    if (!eye) {
        zdir[0] = s->mv[2];
        zdir[1] = s->mv[6];
        zdir[2] = s->mv[10];
    }
    for (int i = 0; i < s->nlights; i++) {
        fs_light_setup *o = &s->light[i];
        if (o->positional)
            continue;
        float p[4];
        if (eye)
            memcpy(p, o->pos, sizeof p);
        else
            fs_mat_xform4(p, s->mv_inv, o->pos);
        memcpy(o->vp_inf, p, sizeof o->vp_inf);
        normalize3(o->vp_inf);
        o->h_inf[0] = o->vp_inf[0] + zdir[0];
        o->h_inf[1] = o->vp_inf[1] + zdir[1];
        o->h_inf[2] = o->vp_inf[2] + zdir[2];
        normalize3(o->h_inf);
    }
}

static float clamp01f(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* NaN becomes 0 */
}

/* The vertex program's POW: gallivm's exp2(log2(x) y), 0 for a zero base
 * (pipeline/vp_pow.c). */
static float vp_pow(float x, float y)
{
    return fs_vp_pow(x, y);
}

/* One side of the lighting equation (GL 1.5 spec 2.14.1) in the
 * operations, order and float rounding of Mesa's fixed-function vertex
 * program (ffvertex_prog.c, compiled by gallivm with every multiply-add
 * a product and a sum): the scene colour (emission + model ambient times
 * ambient) collects per light the ambient product, then the diffuse
 * product times max(n.VP, 0), then the specular product times the
 * specular factor; a light with attenuation (distance or spot) scales the
 * three factors of LIT first.  sign is -1 for the back face, which takes
 * the negated dot products. */
static void light_side(const fs_vs_setup *s, const fs_material *m, const float eye[4], const float n[3],
                       float sign, float shin, bool shin_zero, float out[4], float *spec_out)
{
    float col[3], col1[3] = {0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 3; k++)
        col[k] = s->model_ambient[k] * m->ambient[k] + m->emission[k];
    float *cs = spec_out ? col1 : col; /* where the specular term goes */
    for (int i = 0; i < s->nlights; i++) {
        const fs_light_setup *l = &s->light[i];
        float vp[3], dist = 0.0f, d2 = 0.0f;
        if (l->positional) {
            vp[0] = l->pos[0] - eye[0];
            vp[1] = l->pos[1] - eye[1];
            vp[2] = l->pos[2] - eye[2];
            d2 = fs_vs_dot3(vp, vp);
            dist = 1.0f / sqrtf(d2); /* RSQ */
            vp[0] *= dist; vp[1] *= dist; vp[2] *= dist;
        } else {
            memcpy(vp, l->vp_inf, sizeof vp);
        }
        bool has_att = false;
        float att = 1.0f;
        if (l->spot) {
            const float nvp[3] = {-vp[0], -vp[1], -vp[2]};
            float sp = fs_vs_dot3(nvp, l->spot_dir);
            float slt = l->cos_cutoff < sp ? 1.0f : 0.0f;
            att = slt * vp_pow(fabsf(sp), l->spot_exp);
            has_att = true;
        }
        if (l->attenuated && l->positional) {
            /* The program's (r (1/r), 1/r, (1/r)^2) from r = RSQ(d^2),
             * dotted with the three factors, then its reciprocal; NIR's
             * algebraic rules make 1/r a square root of d^2 and its
             * square d^2 itself (measured on OSMesa,
             * tests/test_lighting_order.c). */
            float d = sqrtf(d2);
            const float dv[3] = {dist * d, d, d2};
            float q = 1.0f / fs_vs_dot3(l->att, dv);
            att = has_att ? q * att : q;
            has_att = true;
        }
        float half[3];
        if (!shin_zero) {
            if (s->local_viewer) {
                float eh[3] = {eye[0], eye[1], eye[2]};
                fs_vs_normalize3(eh);
                half[0] = vp[0] - eh[0]; half[1] = vp[1] - eh[1]; half[2] = vp[2] - eh[2];
                fs_vs_normalize3(half);
            } else if (!l->positional) {
                memcpy(half, l->h_inf, sizeof half);
            } else {
                half[0] = vp[0]; half[1] = vp[1]; half[2] = vp[2] + 1.0f;
                fs_vs_normalize3(half);
            }
        }
        float nvp = sign * fs_vs_dot3(n, vp);
        /* Without a shininess the program's dot products are all n.VP. */
        float nh = shin_zero ? nvp : sign * fs_vs_dot3(n, half);
        float expo = shin_zero ? nvp : shin;
        /* LIT: (1, max(n.VP, 0), n.VP > 0 ? pow(max(n.H, 0), e) : 0), the
         * exponent clamped to [-128, 128], then scaled by the attenuation;
         * without either, the program's degenerate LIT: (1, max(n.VP, 0),
         * n.VP > 0). */
        float ly = nvp > 0.0f ? nvp : 0.0f, lz;
        if (has_att || !shin_zero) {
            float e = expo < -128.0f ? -128.0f : expo > 128.0f ? 128.0f : expo;
            lz = nvp > 0.0f ? vp_pow(nh > 0.0f ? nh : 0.0f, e) : 0.0f;
        } else {
            lz = 0.0f < nvp ? 1.0f : 0.0f;
        }
        if (has_att) {
            ly *= att;
            lz *= att;
        }
        for (int k = 0; k < 3; k++) {
            float amb = l->amb[k] * m->ambient[k], dif = l->dif[k] * m->diffuse[k];
            float spe = l->spe[k] * m->specular[k];
            col[k] = (has_att ? att * amb : amb) + col[k]; /* LIT's x is 1: x * att is att */
            col[k] = ly * dif + col[k];
            cs[k] = lz * spe + cs[k];
        }
    }
    if (spec_out) {
        /* GL_SEPARATE_SPECULAR_COLOR: the secondary colour, alpha 1. */
        spec_out[0] = clamp01f(col1[0]);
        spec_out[1] = clamp01f(col1[1]);
        spec_out[2] = clamp01f(col1[2]);
        spec_out[3] = 1.0f;
    }
    out[0] = clamp01f(col[0]);
    out[1] = clamp01f(col[1]);
    out[2] = clamp01f(col[2]);
    out[3] = clamp01f(m->diffuse[3]);
}

void fs_light_vertex(const fs_vs_setup *s, const float eye[4], const float n[3],
                     const float col[4], float out[2][4], float spec[2][4])
{
    fs_material m[2];
    const fs_material *mp[2] = {&s->mat[0], &s->mat[1]};
    if (s->cm_face_mask) {
        for (int f = 0; f < 2; f++) {
            if (s->cm_face_mask & (1 << f)) {
                m[f] = s->mat[f];
                apply_color_material(&m[f], s->cm_mode, col);
                mp[f] = &m[f];
            }
        }
    }
    bool apart = s->separate_specular;
    /* The program has no specular factor when no shininess is set (front,
     * or back with two sides: ffvertex_prog.c's material_shininess_is_zero). */
    bool shin_zero = mp[0]->shininess == 0.0f && !(s->two_side && mp[1]->shininess != 0.0f);
    light_side(s, mp[0], eye, n, 1.0f, mp[0]->shininess, shin_zero, out[0], apart ? spec[0] : NULL);
    if (s->two_side)
        light_side(s, mp[1], eye, n, -1.0f, mp[1]->shininess, shin_zero, out[1], apart ? spec[1] : NULL);
}
