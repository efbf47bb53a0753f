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

void fs_exec_Lightiv(fs_context *c, GLenum light, GLenum pname, const GLint *params)
{
    float f[4] = {0};
    int n = fs_light_param_count(pname);
    for (int i = 0; i < n; i++)
        f[i] = is_color_pname(pname) ? int_color(params[i]) : (float)params[i];
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
        case GL_AMBIENT: memcpy(m->ambient, p, 16); break;
        case GL_DIFFUSE: memcpy(m->diffuse, p, 16); break;
        case GL_SPECULAR: memcpy(m->specular, p, 16); break;
        case GL_EMISSION: memcpy(m->emission, p, 16); break;
        case GL_AMBIENT_AND_DIFFUSE: memcpy(m->ambient, p, 16); memcpy(m->diffuse, p, 16); break;
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
    float f[4] = {0};
    int n = fs_material_param_count(pname);
    for (int i = 0; i < n; i++)
        f[i] = is_color_pname(pname) ? int_color(params[i]) : (float)params[i];
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
        o->positional = l->position[3] != 0.0f;
        /* Infinite lights are spot lights too in llvmpipe (measured: piglit's
         * infinite-spot-light reads half the ambient red, its spot factor,
         * where the spec's attenuation would leave all of it). */
        o->spot = l->spot_cutoff != 180.0f;
        o->spot_exp = l->spot_exponent;
        o->cos_cutoff = cosf(l->spot_cutoff * (float)(FS_PI / 180.0));
        memcpy(o->spot_dir, l->spot_direction, sizeof o->spot_dir);
        normalize3(o->spot_dir);
        if (o->positional) {
            s->need_eye = true;
        } else {
            memcpy(o->vp_inf, l->position, sizeof o->vp_inf);
            normalize3(o->vp_inf);
            o->h_inf[0] = o->vp_inf[0];
            o->h_inf[1] = o->vp_inf[1];
            o->h_inf[2] = o->vp_inf[2] + 1.0f;
            normalize3(o->h_inf);
        }
    }
}

static float clamp01f(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* NaN becomes 0 */
}

/* One side of the lighting equation (GL 1.5 spec 2.14.1). */
static void light_side(const fs_vs_setup *s, const fs_material *m, const float eye[4],
                       const float n[3], float out[4], float *spec_out)
{
    float s_r = 0.0f, s_g = 0.0f, s_b = 0.0f; /* the specular sums, when apart */
    float r = m->emission[0] + m->ambient[0] * s->model_ambient[0];
    float g = m->emission[1] + m->ambient[1] * s->model_ambient[1];
    float b = m->emission[2] + m->ambient[2] * s->model_ambient[2];
    for (int i = 0; i < s->nlights; i++) {
        const fs_light_setup *l = &s->light[i];
        float vp[3], h[3], att = 1.0f;
        if (l->positional) {
            /* The vector to the light, from a homogeneous eye position. */
            float lx = l->pos[0], ly = l->pos[1], lz = l->pos[2];
            float ex = eye[0], ey = eye[1], ez = eye[2];
            if (eye[3] != 1.0f && eye[3] != 0.0f) {
                float iw = 1.0f / eye[3];
                ex *= iw; ey *= iw; ez *= iw;
            }
            if (l->pos[3] != 1.0f) {
                float iw = 1.0f / l->pos[3];
                lx *= iw; ly *= iw; lz *= iw;
            }
            vp[0] = lx - ex; vp[1] = ly - ey; vp[2] = lz - ez;
            float d2 = vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2];
            float d = sqrtf(d2);
            if (d > 0.0f) {
                float inv = 1.0f / d;
                vp[0] *= inv; vp[1] *= inv; vp[2] *= inv;
            }
            att = 1.0f / (l->att[0] + l->att[1] * d + l->att[2] * d2);
        } else {
            vp[0] = l->vp_inf[0]; vp[1] = l->vp_inf[1]; vp[2] = l->vp_inf[2];
        }
        if (l->spot) {
            /* The direction from the light to the vertex against the
             * spot direction (2.14.1); for an infinite light the light's
             * own direction. */
            float sd = -(vp[0] * l->spot_dir[0] + vp[1] * l->spot_dir[1] + vp[2] * l->spot_dir[2]);
            if (sd < l->cos_cutoff)
                continue; /* outside the cone: the whole term is zero */
            att *= l->spot_exp == 0.0f ? 1.0f : powf(sd, l->spot_exp);
        }
        float ar = l->amb[0] * m->ambient[0], ag = l->amb[1] * m->ambient[1], ab = l->amb[2] * m->ambient[2];
        float ndotvp = n[0] * vp[0] + n[1] * vp[1] + n[2] * vp[2];
        float dr = 0, dg = 0, db = 0, sr = 0, sg = 0, sb = 0;
        if (ndotvp > 0.0f) {
            dr = ndotvp * l->dif[0] * m->diffuse[0];
            dg = ndotvp * l->dif[1] * m->diffuse[1];
            db = ndotvp * l->dif[2] * m->diffuse[2];
            if (l->positional || s->local_viewer) {
                if (s->local_viewer) {
                    float v[3] = {-eye[0], -eye[1], -eye[2]};
                    normalize3(v);
                    h[0] = vp[0] + v[0]; h[1] = vp[1] + v[1]; h[2] = vp[2] + v[2];
                } else {
                    h[0] = vp[0]; h[1] = vp[1]; h[2] = vp[2] + 1.0f;
                }
                normalize3(h);
            } else {
                h[0] = l->h_inf[0]; h[1] = l->h_inf[1]; h[2] = l->h_inf[2];
            }
            float ndoth = n[0] * h[0] + n[1] * h[1] + n[2] * h[2];
            if (ndoth > 0.0f) {
                float spec = m->shininess == 0.0f ? 1.0f : powf(ndoth, m->shininess);
                sr = spec * l->spe[0] * m->specular[0];
                sg = spec * l->spe[1] * m->specular[1];
                sb = spec * l->spe[2] * m->specular[2];
            }
        }
        if (spec_out) {
            r += att * (ar + dr);
            g += att * (ag + dg);
            b += att * (ab + db);
            s_r += att * sr;
            s_g += att * sg;
            s_b += att * sb;
            continue;
        }
        r += att * (ar + dr + sr);
        g += att * (ag + dg + sg);
        b += att * (ab + db + sb);
    }
    if (spec_out) {
        /* GL_SEPARATE_SPECULAR_COLOR: the secondary colour, alpha 1. */
        spec_out[0] = clamp01f(s_r);
        spec_out[1] = clamp01f(s_g);
        spec_out[2] = clamp01f(s_b);
        spec_out[3] = 1.0f;
    }
    out[0] = clamp01f(r);
    out[1] = clamp01f(g);
    out[2] = clamp01f(b);
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
    light_side(s, mp[0], eye, n, out[0], apart ? spec[0] : NULL);
    if (s->two_side) {
        float nb[3] = {-n[0], -n[1], -n[2]};
        light_side(s, mp[1], eye, nb, out[1], apart ? spec[1] : NULL);
    }
}
