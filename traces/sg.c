/* Scene generators: the counting emitter and the geometry helpers.  Built
 * twice: into scenegen, sending fsgl* calls to a fragsim context, and with
 * SG_DIRECT_GL into the culling program, sending plain gl* calls to the
 * current OSMesa context (sg.h); the scene table and the driver are in
 * sg_scenes.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sg.h"
#ifndef SG_DIRECT_GL
#include "../driver/capture.h"
#endif

#define SG_PI 3.14159265358979323846

/* ---- random numbers: splitmix64, so a seed fully determines a scene ---- */
void sg_rng_seed(sg_rng *r, uint64_t seed) { r->s = seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull; }

uint64_t sg_rng_u64(sg_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double sg_rng_unit(sg_rng *r) { return (double)(sg_rng_u64(r) >> 11) * (1.0 / 9007199254740992.0); }
double sg_rng_range(sg_rng *r, double lo, double hi) { return lo + (hi - lo) * sg_rng_unit(r); }
int sg_rng_int(sg_rng *r, int n) { return n <= 0 ? 0 : (int)(sg_rng_u64(r) % (uint64_t)n); }

/* ---- the emitter ---- */
void sg_init(sg *s, fs_context *c)
{
    memset(s, 0, sizeof *s);
    s->c = c;
    s->next_list = 1;
    s->min_frame_tris = UINT64_MAX;
}

void sg_free(sg *s)
{
    free(s->list_tris);
    for (int i = 0; i < 4; i++) free(s->scratch[i]);
    s->list_tris = NULL;
}

uint64_t sg_prim_tris(GLenum mode, uint64_t n)
{
    switch (mode) {
    case GL_TRIANGLES: return n / 3;
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
    case GL_POLYGON: return n >= 3 ? n - 2 : 0;
    case GL_QUADS: return n / 4 * 2;
    case GL_QUAD_STRIP: return n >= 4 ? (n / 2 - 1) * 2 : 0;
    default: return 0;
    }
}

static void add_tris(sg *s, uint64_t t)
{
    if (s->compiling) {
        s->compile_tris += t;
    } else {
        s->tris += t;
        s->frame_tris += t;
    }
}

void sg_begin(sg *s, GLenum mode)
{
    if (s->in_prim) s->misuse = 1;
    s->in_prim = 1;
    s->prim_mode = mode;
    s->prim_verts = 0;
    G(s, Begin, mode);
}

void sg_end(sg *s)
{
    if (!s->in_prim) s->misuse = 1;
    s->in_prim = 0;
    add_tris(s, sg_prim_tris(s->prim_mode, s->prim_verts));
    G0(s, End);
}

void sg_vtx(sg *s, float x, float y, float z)
{
    if (!s->in_prim) s->misuse = 1;
    s->prim_verts++;
    G(s, Vertex3f, x, y, z);
}

void sg_vtxv(sg *s, const float *v)
{
    if (!s->in_prim) s->misuse = 1;
    s->prim_verts++;
    G(s, Vertex3fv, v);
}

void sg_nrm(sg *s, float x, float y, float z) { G(s, Normal3f, x, y, z); }
void sg_col(sg *s, float r, float g, float b) { G(s, Color3f, r, g, b); }

void sg_draw_arrays(sg *s, GLenum mode, GLint first, GLsizei count)
{
    if (s->in_prim) s->misuse = 1;
    add_tris(s, sg_prim_tris(mode, (uint64_t)count));
    G(s, DrawArrays, mode, first, count);
}

void sg_draw_elements(sg *s, GLenum mode, GLsizei count, GLenum type, const void *idx)
{
    if (s->in_prim) s->misuse = 1;
    add_tris(s, sg_prim_tris(mode, (uint64_t)count));
    G(s, DrawElements, mode, count, type, idx);
}

GLuint sg_gen_lists(sg *s, GLsizei n)
{
    GLuint first;
    s->calls++;
    if (s->c) {
        first = SG_SEND(s, GenLists, n);
    } else {
        first = s->next_list;
        s->next_list += (GLuint)n;
    }
    if (first == 0) {
        s->misuse = 1;
        return 0;
    }
    uint64_t need = (uint64_t)first + (uint64_t)n;
    if (need > s->list_cap) {
        uint32_t cap = s->list_cap ? s->list_cap : 64;
        while (cap < need) cap *= 2;
        uint64_t *p = realloc(s->list_tris, cap * sizeof *p);
        if (!p) {
            s->oom = 1;
            return 0;
        }
        memset(p + s->list_cap, 0, (cap - s->list_cap) * sizeof *p);
        s->list_tris = p;
        s->list_cap = cap;
    }
    return first;
}

void sg_new_list(sg *s, GLuint list)
{
    if (s->compiling || list == 0 || list >= s->list_cap) s->misuse = 1;
    s->compiling = list;
    s->compile_tris = 0;
    G(s, NewList, list, GL_COMPILE);
}

void sg_end_list(sg *s)
{
    if (!s->compiling) s->misuse = 1;
    else s->list_tris[s->compiling] = s->compile_tris;
    s->compiling = 0;
    G0(s, EndList);
}

uint64_t sg_list_tris(const sg *s, GLuint list)
{
    return list < s->list_cap ? s->list_tris[list] : 0;
}

void sg_call_list(sg *s, GLuint list)
{
    if (list == 0 || list >= s->list_cap || list == s->compiling) s->misuse = 1;
    add_tris(s, sg_list_tris(s, list));
    G(s, CallList, list);
}

void sg_frame_begin(sg *s, float r, float g, float b)
{
    s->frame_tris = 0;
    G(s, ClearColor, r, g, b, 1.0f);
    G(s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void sg_frame_end(sg *s)
{
    G0(s, Flush);
#ifndef SG_DIRECT_GL
    if (s->c) fs_capture_frame_end(s->c);
#endif
    s->frames++;
    if (s->frame_tris > s->max_frame_tris) s->max_frame_tris = s->frame_tris;
    if (s->frame_tris < s->min_frame_tris) s->min_frame_tris = s->frame_tris;
    s->frame_tris = 0;
}

void *sg_buf(sg *s, int slot, size_t bytes)
{
    if (bytes > s->scratch_size[slot]) {
        void *p = realloc(s->scratch[slot], bytes);
        if (!p) {
            s->oom = 1;
            return NULL;
        }
        s->scratch[slot] = p;
        s->scratch_size[slot] = bytes;
    }
    return s->scratch[slot];
}

/* ---- camera ---- */
void sg_perspective(sg *s, double fovy_deg, double aspect, double znear, double zfar)
{
    double ymax = znear * tan(fovy_deg * SG_PI / 360.0);
    G(s, MatrixMode, GL_PROJECTION);
    G0(s, LoadIdentity);
    G(s, Frustum, -ymax * aspect, ymax * aspect, -ymax, ymax, znear, zfar);
    G(s, MatrixMode, GL_MODELVIEW);
}

void sg_lighting(sg *s, GLenum face)
{
    G(s, Enable, GL_LIGHTING);
    G(s, Enable, GL_COLOR_MATERIAL);
    G(s, ColorMaterial, face, GL_AMBIENT_AND_DIFFUSE);
}

static void norm3(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0f) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }
}

static void cross3(const float a[3], const float b[3], float r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

void sg_look_at(sg *s, const float eye[3], const float at[3], const float up[3])
{
    float f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]}, sd[3], u[3];
    norm3(f);
    cross3(f, up, sd);
    norm3(sd);
    cross3(sd, f, u);
    const float m[16] = {sd[0], u[0], -f[0], 0, sd[1], u[1], -f[1], 0,
                         sd[2], u[2], -f[2], 0, 0, 0, 0, 1};
    G(s, MultMatrixf, m);
    G(s, Translatef, -eye[0], -eye[1], -eye[2]);
}

void sg_light(sg *s, GLenum light, const float pos[4], const float diffuse[4],
              const float ambient[4], const float specular[4])
{
    G(s, Lightfv, light, GL_POSITION, pos);
    G(s, Lightfv, light, GL_DIFFUSE, diffuse);
    if (ambient) G(s, Lightfv, light, GL_AMBIENT, ambient);
    if (specular) G(s, Lightfv, light, GL_SPECULAR, specular);
    G(s, Enable, light);
}

/* ---- geometry ---- */
void sg_grid(sg *s, const float o[3], const float u[3], const float v[3], int nu, int nv)
{
    float n[3];
    cross3(u, v, n);
    norm3(n);
    sg_begin(s, GL_QUADS);
    sg_nrm(s, n[0], n[1], n[2]);
    for (int j = 0; j < nv; j++) {
        float b0 = (float)j / nv, b1 = (float)(j + 1) / nv;
        for (int i = 0; i < nu; i++) {
            float a0 = (float)i / nu, a1 = (float)(i + 1) / nu;
            const float ab[4][2] = {{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
            for (int k = 0; k < 4; k++)
                sg_vtx(s, o[0] + u[0] * ab[k][0] + v[0] * ab[k][1],
                       o[1] + u[1] * ab[k][0] + v[1] * ab[k][1],
                       o[2] + u[2] * ab[k][0] + v[2] * ab[k][1]);
        }
    }
    sg_end(s);
}

void sg_box(sg *s, float x0, float y0, float z0, float x1, float y1, float z1, int bottom)
{
    /* Sides as a GL_QUAD_STRIP would be fewer vertices, but Mesa (OSMesa,
     * the reference) mis-renders a display list in which a quad strip
     * follows a long run of other primitives, so plain quads it is.
     * Each face is listed counter-clockwise seen from outside. */
    const float f[6][4][3] = {
        {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, /* +z */
        {{x1, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}}, /* +x */
        {{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}, /* -z */
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, /* -x */
        {{x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}}, /* +y */
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, /* -y */
    };
    const float n[6][3] = {{0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    sg_begin(s, GL_QUADS);
    for (int k = 0; k < (bottom ? 6 : 5); k++) {
        sg_nrm(s, n[k][0], n[k][1], n[k][2]);
        for (int v = 0; v < 4; v++) sg_vtxv(s, f[k][v]);
    }
    sg_end(s);
}

void sg_cylinder(sg *s, float r, float h, int slices, int stacks, int caps)
{
    /* x = r cos t, z = r sin t with t increasing and (bottom, top) pairs
     * makes outward-facing counter-clockwise quads. */
    for (int j = 0; j < stacks; j++) {
        float y0 = h * j / stacks, y1 = h * (j + 1) / stacks;
        sg_begin(s, GL_QUAD_STRIP);
        for (int i = 0; i <= slices; i++) {
            double t = 2.0 * SG_PI * (i % slices) / slices;
            float cx = (float)cos(t), sz = (float)sin(t);
            sg_nrm(s, cx, 0, sz);
            sg_vtx(s, r * cx, y0, r * sz);
            sg_vtx(s, r * cx, y1, r * sz);
        }
        sg_end(s);
    }
    if (!caps) return;
    for (int top = 0; top < 2; top++) {
        float y = top ? h : 0.0f;
        sg_begin(s, GL_TRIANGLE_FAN);
        sg_nrm(s, 0, top ? 1.0f : -1.0f, 0);
        sg_vtx(s, 0, y, 0);
        for (int i = 0; i <= slices; i++) {
            int k = top ? (slices - i) % slices : i % slices;
            double t = 2.0 * SG_PI * k / slices;
            sg_vtx(s, r * (float)cos(t), y, r * (float)sin(t));
        }
        sg_end(s);
    }
}

void sg_sphere(sg *s, float r, int slices, int stacks)
{
    if (stacks < 2) stacks = 2;
    /* North pole fan, rim clockwise in t so that it faces up and out. */
    double p1 = SG_PI / stacks;
    sg_begin(s, GL_TRIANGLE_FAN);
    sg_nrm(s, 0, 1, 0);
    sg_vtx(s, 0, r, 0);
    for (int i = 0; i <= slices; i++) {
        double t = 2.0 * SG_PI * ((slices - i) % slices) / slices;
        float nx = (float)(sin(p1) * cos(t)), ny = (float)cos(p1), nz = (float)(sin(p1) * sin(t));
        sg_nrm(s, nx, ny, nz);
        sg_vtx(s, r * nx, r * ny, r * nz);
    }
    sg_end(s);
    for (int j = 1; j < stacks - 1; j++) {
        double pa = SG_PI * j / stacks, pb = SG_PI * (j + 1) / stacks;
        sg_begin(s, GL_TRIANGLE_STRIP);
        for (int i = 0; i <= slices; i++) {
            double t = 2.0 * SG_PI * (i % slices) / slices;
            /* (lower, upper) pairs, as for the cylinder. */
            float lx = (float)(sin(pb) * cos(t)), ly = (float)cos(pb), lz = (float)(sin(pb) * sin(t));
            float ux = (float)(sin(pa) * cos(t)), uy = (float)cos(pa), uz = (float)(sin(pa) * sin(t));
            sg_nrm(s, lx, ly, lz);
            sg_vtx(s, r * lx, r * ly, r * lz);
            sg_nrm(s, ux, uy, uz);
            sg_vtx(s, r * ux, r * uy, r * uz);
        }
        sg_end(s);
    }
    double pl = SG_PI * (stacks - 1) / stacks;
    sg_begin(s, GL_TRIANGLE_FAN);
    sg_nrm(s, 0, -1, 0);
    sg_vtx(s, 0, -r, 0);
    for (int i = 0; i <= slices; i++) {
        double t = 2.0 * SG_PI * (i % slices) / slices;
        float nx = (float)(sin(pl) * cos(t)), ny = (float)cos(pl), nz = (float)(sin(pl) * sin(t));
        sg_nrm(s, nx, ny, nz);
        sg_vtx(s, r * nx, r * ny, r * nz);
    }
    sg_end(s);
}

void sg_torus(sg *s, float R, float r, int nu, int nv)
{
    for (int j = 0; j < nv; j++) {
        sg_begin(s, GL_TRIANGLE_STRIP);
        for (int i = 0; i <= nu; i++) {
            double u = 2.0 * SG_PI * (i % nu) / nu;
            for (int k = 0; k < 2; k++) {
                double v = 2.0 * SG_PI * ((j + k) % nv) / nv;
                float nx = (float)(cos(v) * cos(u)), ny = (float)sin(v), nz = (float)(cos(v) * sin(u));
                sg_nrm(s, nx, ny, nz);
                sg_vtx(s, (float)((R + r * cos(v)) * cos(u)), r * ny, (float)((R + r * cos(v)) * sin(u)));
            }
        }
        sg_end(s);
    }
}

void sg_disc(sg *s, float cx, float cy, float cz, float radius, uint64_t n, int polygon)
{
    if (n == 0) return;
    sg_begin(s, polygon ? GL_POLYGON : GL_TRIANGLE_FAN);
    sg_nrm(s, 0, 1, 0);
    if (polygon) {
        /* n triangles need n + 2 corners; clockwise in t faces +y. */
        for (uint64_t k = 0; k < n + 2; k++) {
            double t = -2.0 * SG_PI * (double)k / (double)(n + 2);
            sg_vtx(s, cx + radius * (float)cos(t), cy, cz + radius * (float)sin(t));
        }
    } else {
        /* A closed fan needs 3 triangles; fewer make a partial disc so that
         * no triangle is degenerate. */
        double span = n >= 3 ? 2.0 * SG_PI : 2.0 * SG_PI * (double)n / 3.0;
        sg_vtx(s, cx, cy, cz);
        for (uint64_t k = 0; k <= n; k++) {
            double t = -span * (double)k / (double)n;
            if (n >= 3 && k == n) t = 0.0;
            sg_vtx(s, cx + radius * (float)cos(t), cy, cz + radius * (float)sin(t));
        }
    }
    sg_end(s);
}

/* ---- noise ---- */
static double lattice(uint64_t seed, int64_t x, int64_t y)
{
    uint64_t h = seed ^ ((uint64_t)x * 0x9E3779B97F4A7C15ull) ^ ((uint64_t)y * 0xC2B2AE3D27D4EB4Full);
    h = (h ^ (h >> 33)) * 0xFF51AFD7ED558CCDull;
    h = (h ^ (h >> 33)) * 0xC4CEB9FE1A85EC53ull;
    h ^= h >> 33;
    return (double)(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

static double value_noise(uint64_t seed, double x, double y)
{
    double fx = floor(x), fy = floor(y);
    int64_t ix = (int64_t)fx, iy = (int64_t)fy;
    double tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0 - 2.0 * tx);
    ty = ty * ty * (3.0 - 2.0 * ty);
    double a = lattice(seed, ix, iy), b = lattice(seed, ix + 1, iy);
    double c = lattice(seed, ix, iy + 1), d = lattice(seed, ix + 1, iy + 1);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

double sg_fractal(uint64_t seed, double x, double y, int octaves)
{
    double sum = 0.0, amp = 1.0, norm = 0.0;
    for (int o = 0; o < octaves; o++) {
        sum += amp * value_noise(seed + (uint64_t)o * 1013, x, y);
        norm += amp;
        amp *= 0.5;
        x *= 2.03;
        y *= 2.03;
    }
    return sum / norm;
}
