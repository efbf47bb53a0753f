/*
 * GL_FRAGSIM_mp_grid (docs/extensions/mp_grid.txt): MP-Grid texture objects
 * (Huettner 1999, 4.1), their images, bounding boxes and adaptation, and
 * the sampler's texel path through the CTR (4.1.4).  Every command checks
 * its arguments first; a call that sets a GL error changes nothing (GL 1.5
 * spec 2.5).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "mpgrid.h"
#include "mpgrid_gl.h"
#include "texture_priv.h"
#include "../glext/GL_FRAGSIM_mp_grid.h"
#include "../pipeline/context.h"

/* The GL's limit on n and m (GL_MAX_MPGRID_PYRAMIDS): 1024 x 1024 pyramids
 * of 13 levels keep the pointer table near 0.5 GB in the model. */
#define MAX_PYRAMIDS 1024

struct fs_mpgrid_tex {
    fs_mpgrid grid;
    fs_mpgrid_ctr ctr;
    fs_mpgrid_box *boxes;       /* per pyramid, j*n + i */
    int *want;                  /* per pyramid: finest level wanted */
    GLint internal_format;
    GLenum base_format;
    int keep_side;
    int merge_block;            /* GL_MPGRID_MERGE_BLOCK as set (4) */
    int64_t images_missing;     /* level images not yet supplied */
    fs_stats *stats;            /* the context's per-frame counters */
    /* GL_MPGRID_AUTO_ADAPT: the context whose camera drives adaptation,
     * and the camera (projection, modelview, viewport size) last adapted to. */
    fs_context *ctx;
    bool auto_adapt, adapted_once;
    float last_p[16], last_mv[16];
    GLint last_vp[2];
};

static void tex_free(struct fs_mpgrid_tex *g)
{
    if (!g)
        return;
    fs_mpgrid_free(&g->grid);
    free(g->boxes);
    free(g->want);
    free(g);
}

void fs_mpgrid_gl_release(fs_tex_object *t)
{
    tex_free(t->mpgrid);
    t->mpgrid = NULL;
}

/* A fresh grid with the given merging (images none, boxes unknown). */
static struct fs_mpgrid_tex *tex_new(const fs_mpgrid_layout *L, int merge_side, int merge_block)
{
    struct fs_mpgrid_tex *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    size_t np = (size_t)L->n * (size_t)L->m;
    g->boxes = calloc(np, sizeof *g->boxes);
    g->want = calloc(np, sizeof *g->want);
    if (!g->boxes || !g->want || fs_mpgrid_init(&g->grid, L, 4, merge_side, merge_block) < 0) {
        tex_free(g);
        return NULL;
    }
    for (size_t p = 0; p < np; p++)
        g->boxes[p].unbounded = true;
    g->images_missing = (int64_t)np * L->levels;
    g->merge_block = 4;
    fs_mpgrid_ctr_reset(&g->ctr);
    return g;
}

static fs_tex_object *bound_grid(fs_context *c, GLenum target, bool need_grid)
{
    if (target != GL_TEXTURE_2D) {
        fs_error(c, GL_INVALID_ENUM);
        return NULL;
    }
    fs_tex_object *t = fs_tex_bound_2d(c);
    if (need_grid && !t->mpgrid) {
        fs_error(c, GL_INVALID_OPERATION);
        return NULL;
    }
    return t;
}

static bool is_pow2(GLsizei v) { return v > 0 && (v & (v - 1)) == 0; }

void fs_exec_MPGridTexture(fs_context *c, GLenum target, GLsizei n, GLsizei m, GLsizei tileWidth,
                           GLsizei tileHeight, GLint internalformat)
{
    fs_tex_object *t = bound_grid(c, target, false);
    if (!t)
        return;
    if (n < 1 || m < 1 || n > MAX_PYRAMIDS || m > MAX_PYRAMIDS || !is_pow2(tileWidth) || !is_pow2(tileHeight) ||
        tileWidth > FS_TEX_MAX_SIZE || tileHeight > FS_TEX_MAX_SIZE ||
        !fs_tex_base_format(internalformat)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (t == &c->texture->default_obj[FS_TEX_2D]) {
        /* Texture object 0 stays a conventional texture. */
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    fs_mpgrid_layout L;
    if (fs_mpgrid_make_layout(n, m, tileWidth, tileHeight, &L) < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    struct fs_mpgrid_tex *g = tex_new(&L, 0, 1);
    if (!g) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    GLenum base = fs_tex_base_format(internalformat);
    g->internal_format = internalformat;
    g->base_format = base;
    g->stats = &c->stats;
    g->ctx = c;
    fs_mpgrid_gl_release(t);
    t->mpgrid = g;
    /* The level descriptors describe the whole grid (n*tile >> level), with
     * no texels of their own: the sampler reads through the CTR. */
    for (int l = 0; l < FS_TEX_MAX_LEVELS; l++) {
        fs_tex_image *img = &t->level[l];
        fs_tex_image_free(img);
        memset(img, 0, sizeof *img);
        if (l < L.levels) {
            img->width = L.n * fs_mpgrid_level_w(&L, l);
            img->height = L.m * fs_mpgrid_level_h(&L, l);
            img->depth = 1;
            img->internal_format = internalformat;
            img->base_format = base;
        }
    }
    t->complete = -1;
}

void fs_exec_MPGridImage(fs_context *c, GLenum target, GLint i, GLint j, GLint level, GLsizei width, GLsizei height,
                         GLenum format, GLenum type, const GLvoid *pixels)
{
    fs_tex_object *t = bound_grid(c, target, false);
    if (!t)
        return;
    GLenum e = fs_tex_unpack_rgba8(c, NULL, 0, 0, GL_RGBA, format, type, NULL);
    if (e == GL_INVALID_ENUM) {
        fs_error(c, e);
        return;
    }
    if (!t->mpgrid) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    struct fs_mpgrid_tex *g = t->mpgrid;
    const fs_mpgrid_layout *L = &g->grid.L;
    if (i < 0 || j < 0 || i >= L->n || j >= L->m || level < 0 || level >= L->levels ||
        width != fs_mpgrid_level_w(L, level) || height != fs_mpgrid_level_h(L, level) || !pixels) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (e != GL_NO_ERROR) {
        fs_error(c, e);
        return;
    }
    uint8_t *rgba = malloc((size_t)width * (size_t)height * 4);
    if (!rgba) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    fs_tex_unpack_rgba8(c, rgba, width, height, g->base_format, format, type, pixels);
    bool first = fs_mpgrid_entry_at(&g->grid, level, i, j) && !g->grid.src[((size_t)level * L->m + j) * L->n + i];
    uint64_t loaded = g->grid.levels_loaded;
    int rc = fs_mpgrid_set_image(&g->grid, i, j, level, rgba);
    /* A newly supplied level becomes resident if the pyramid wants it. */
    if (rc == 0)
        rc = fs_mpgrid_set_finest(&g->grid, i, j, g->want[j * L->n + i]);
    free(rgba);
    if (rc < 0) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    g->stats->mpgrid_levels_loaded += g->grid.levels_loaded - loaded;
    g->stats->mpgrid_bytes_resident = g->grid.bytes_resident;
    if (first)
        g->images_missing--;
    t->complete = -1;
}

void fs_exec_MPGridParameteri(fs_context *c, GLenum target, GLenum pname, GLint param)
{
    fs_tex_object *t = bound_grid(c, target, false);
    if (!t)
        return;
    if (pname != GL_MPGRID_KEEP_SIDE && pname != GL_MPGRID_MERGE_SIDE && pname != GL_MPGRID_MERGE_BLOCK &&
        pname != GL_MPGRID_AUTO_ADAPT) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (!t->mpgrid) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    struct fs_mpgrid_tex *g = t->mpgrid;
    const fs_mpgrid_layout *L = &g->grid.L;
    if (pname == GL_MPGRID_AUTO_ADAPT) {
        if (param != GL_TRUE && param != GL_FALSE) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        g->auto_adapt = param == GL_TRUE;
        g->adapted_once = false;
        return;
    }
    if (pname == GL_MPGRID_KEEP_SIDE) {
        if (param < 0 || param > FS_TEX_MAX_SIZE) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
        g->keep_side = param;
        return;
    }
    /* The merging is part of the layout of the store: it can change only
     * before the first image. */
    int side = pname == GL_MPGRID_MERGE_SIDE ? param : g->grid.merge_side;
    int block = pname == GL_MPGRID_MERGE_BLOCK ? param : g->merge_block;
    if (param < 0 || param > FS_TEX_MAX_SIZE || (pname == GL_MPGRID_MERGE_BLOCK && param < 1)) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    if (g->images_missing != (int64_t)L->n * L->m * L->levels) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    /* A block larger than the grid is the whole grid. */
    int inner = block > (L->n > L->m ? L->n : L->m) ? (L->n > L->m ? L->n : L->m) : block;
    struct fs_mpgrid_tex *ng = tex_new(L, side, side > 0 ? inner : 1);
    if (!ng) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return;
    }
    ng->internal_format = g->internal_format;
    ng->base_format = g->base_format;
    ng->keep_side = g->keep_side;
    ng->stats = g->stats;
    ng->merge_block = block;
    ng->ctx = g->ctx;
    ng->auto_adapt = g->auto_adapt;
    memcpy(ng->boxes, g->boxes, (size_t)L->n * L->m * sizeof *ng->boxes);
    memcpy(ng->want, g->want, (size_t)L->n * L->m * sizeof *ng->want);
    tex_free(g);
    t->mpgrid = ng;
}

void fs_exec_MPGridBoundingBox(fs_context *c, GLenum target, GLint i, GLint j, const GLfloat *box,
                               GLboolean occluded)
{
    fs_tex_object *t = bound_grid(c, target, true);
    if (!t)
        return;
    struct fs_mpgrid_tex *g = t->mpgrid;
    if (i < 0 || j < 0 || i >= g->grid.L.n || j >= g->grid.L.m || !box) {
        fs_error(c, GL_INVALID_VALUE);
        return;
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(box[k]) || !isfinite(box[k + 3]) || box[k] > box[k + 3]) {
            fs_error(c, GL_INVALID_VALUE);
            return;
        }
    fs_mpgrid_box *b = &g->boxes[j * g->grid.L.n + i];
    for (int k = 0; k < 3; k++) {
        b->lo[k] = box[k];
        b->hi[k] = box[k + 3];
    }
    b->occluded = occluded != GL_FALSE;
    b->unbounded = false;
}

/* Adapts to the current PROJECTION * MODELVIEW and viewport size. */
static void adapt_now(fs_context *c, struct fs_mpgrid_tex *g)
{
    /* The camera: current projection * modelview (GL 1.5 spec 2.11) and
     * the viewport's size (2.11.1). */
    const fs_matrix *P = &c->xf.projection[c->xf.projection_top], *M = &c->xf.modelview[c->xf.modelview_top];
    fs_mpgrid_camera cam;
    for (int col = 0; col < 4; col++)
        for (int r = 0; r < 4; r++) {
            double a = 0;
            for (int k = 0; k < 4; k++)
                a += (double)P->m[k * 4 + r] * (double)M->m[col * 4 + k];
            cam.m[col * 4 + r] = a;
        }
    cam.vp_w = c->xf.viewport[2] > 0 ? c->xf.viewport[2] : 1;
    cam.vp_h = c->xf.viewport[3] > 0 ? c->xf.viewport[3] : 1;
    /* A camera with Inf or NaN entries projects nothing meaningfully: the
     * grid stays as it is (docs/extensions/mp_grid.txt, Issue 4). */
    for (int k = 0; k < 16; k++)
        if (!isfinite(cam.m[k]))
            return;
    memcpy(g->last_p, P->m, sizeof g->last_p);
    memcpy(g->last_mv, M->m, sizeof g->last_mv);
    g->last_vp[0] = c->xf.viewport[2];
    g->last_vp[1] = c->xf.viewport[3];
    g->adapted_once = true;
    uint64_t loaded = g->grid.levels_loaded, freed = g->grid.levels_freed;
    fs_mpgrid_frame fr;
    /* Boxes and camera are finite here: only memory can fail. */
    int rc = fs_mpgrid_adapt(&g->grid, &cam, g->boxes, g->keep_side, &fr);
    for (int p = 0; p < g->grid.L.n * g->grid.L.m; p++)
        g->want[p] = g->grid.finest[p];
    g->stats->mpgrid_levels_loaded += g->grid.levels_loaded - loaded;
    g->stats->mpgrid_levels_freed += g->grid.levels_freed - freed;
    g->stats->mpgrid_bytes_resident = g->grid.bytes_resident;
    if (rc < 0)
        fs_error(c, GL_OUT_OF_MEMORY);
}

void fs_exec_MPGridAdapt(fs_context *c, GLenum target)
{
    fs_tex_object *t = bound_grid(c, target, true);
    if (!t)
        return;
    adapt_now(c, t->mpgrid);
}

void fs_exec_GetMPGridiv(fs_context *c, GLenum target, GLenum pname, GLint *params)
{
    if (target != GL_TEXTURE_2D) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    if (pname == GL_MAX_MPGRID_PYRAMIDS) {
        *params = MAX_PYRAMIDS;
        return;
    }
    if ((pname < GL_MPGRID_PYRAMIDS_S || pname > GL_MPGRID_MERGE_BLOCK) && pname != GL_MPGRID_AUTO_ADAPT) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    const struct fs_mpgrid_tex *g = fs_tex_bound_2d(c)->mpgrid;
    if (!g) {
        fs_error(c, GL_INVALID_OPERATION);
        return;
    }
    uint64_t v = 0;
    switch (pname) {
    case GL_MPGRID_PYRAMIDS_S: v = (uint64_t)g->grid.L.n; break;
    case GL_MPGRID_PYRAMIDS_T: v = (uint64_t)g->grid.L.m; break;
    case GL_MPGRID_TILE_WIDTH: v = (uint64_t)g->grid.L.tile_w; break;
    case GL_MPGRID_TILE_HEIGHT: v = (uint64_t)g->grid.L.tile_h; break;
    case GL_MPGRID_LEVELS: v = (uint64_t)g->grid.L.levels; break;
    case GL_MPGRID_BYTES_RESIDENT: v = g->grid.bytes_resident; break;
    case GL_MPGRID_LEVELS_LOADED: v = g->grid.levels_loaded; break;
    case GL_MPGRID_LEVELS_FREED: v = g->grid.levels_freed; break;
    case GL_MPGRID_SUBSTITUTIONS: v = g->ctr.substitutions; break;
    case GL_MPGRID_CTR_RELOADS: v = g->ctr.reloads; break;
    case GL_MPGRID_POINTER_THRASHING: v = g->ctr.thrashing; break;
    case GL_MPGRID_IMAGES_MISSING: v = (uint64_t)g->images_missing; break;
    case GL_MPGRID_KEEP_SIDE: v = (uint64_t)g->keep_side; break;
    case GL_MPGRID_MERGE_SIDE: v = (uint64_t)g->grid.merge_side; break;
    case GL_MPGRID_MERGE_BLOCK: v = (uint64_t)g->merge_block; break;
    case GL_MPGRID_AUTO_ADAPT: v = g->auto_adapt ? GL_TRUE : GL_FALSE; break;
    default: break;
    }
    /* Integer queries of larger values saturate (GL 1.5 spec 6.1.2). */
    *params = v > INT32_MAX ? INT32_MAX : (GLint)v;
}

/* ---- the texture unit's side ---- */

bool fs_mpgrid_gl_complete(fs_tex_object *t)
{
    struct fs_mpgrid_tex *g = t->mpgrid;
    const fs_mpgrid_layout *L = &g->grid.L;
    bool ok = g->images_missing == 0;
    /* A conventional image given to an MP-Grid object (glTexImage2D)
     * makes it incomplete: the object has no such images. */
    for (int l = 0; l < FS_TEX_MAX_LEVELS; l++)
        ok = ok && !t->level[l].texels;
    /* The sampler's REPEAT wraps power-of-two sizes only. */
    if (t->wrap_s == GL_REPEAT && !is_pow2(L->n))
        ok = false;
    if (t->wrap_t == GL_REPEAT && !is_pow2(L->m))
        ok = false;
    /* The six GL filters only: other min filters (extensions) read the
     * level images directly, which an MP-Grid object does not have. */
    switch (t->min_filter) {
    case GL_NEAREST: case GL_LINEAR: case GL_NEAREST_MIPMAP_NEAREST: case GL_LINEAR_MIPMAP_NEAREST:
    case GL_NEAREST_MIPMAP_LINEAR: case GL_LINEAR_MIPMAP_LINEAR:
        break;
    default:
        ok = false;
    }
    bool mip = t->min_filter != GL_NEAREST && t->min_filter != GL_LINEAR;
    t->last_level = ok && mip ? L->levels - 1 : 0;
    t->complete = ok ? 1 : 0;
    /* GL_MPGRID_AUTO_ADAPT: the sampler asks for completeness before it
     * textures a quad; adapt there when the camera changed since the last
     * adaptation (a few compares per quad otherwise). */
    if (ok && g->auto_adapt && g->ctx) {
        const fs_context *c = g->ctx;
        const fs_matrix *P = &c->xf.projection[c->xf.projection_top];
        const fs_matrix *M = &c->xf.modelview[c->xf.modelview_top];
        if (!g->adapted_once || memcmp(P->m, g->last_p, sizeof g->last_p) != 0 ||
            memcmp(M->m, g->last_mv, sizeof g->last_mv) != 0 || c->xf.viewport[2] != g->last_vp[0] ||
            c->xf.viewport[3] != g->last_vp[1])
            adapt_now(g->ctx, g);
    }
    return ok;
}

const uint8_t *fs_mpgrid_gl_texel(struct fs_mpgrid_tex *g, fs_mpgrid_work *w, int level, int x, int y,
                                  uint8_t tmp[4])
{
    uint64_t r0 = g->ctr.reloads, th0 = g->ctr.thrashing, s0 = g->ctr.substitutions;
    fs_mpgrid_fetch(&g->grid, &g->ctr, level, x, y, tmp);
    w->reloads += g->ctr.reloads - r0;
    w->thrashing += g->ctr.thrashing - th0;
    w->substitutions += g->ctr.substitutions - s0;
    return tmp;
}

void fs_mpgrid_gl_work_done(struct fs_mpgrid_tex *g, const fs_mpgrid_work *w)
{
    g->stats->mpgrid_ctr_reloads += w->reloads;
    g->stats->mpgrid_pointer_thrashing += w->thrashing;
    g->stats->mpgrid_substitutions += w->substitutions;
}
