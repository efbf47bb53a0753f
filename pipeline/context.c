/* Context lifetime, GL errors (GL 1.5 spec 2.5) and bookkeeping shared by all stages. */
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include "context.h"
#include "raster_threads.h"
#include "../units/occlusion_unit.h"
#include "../units/texture_unit.h"
#include "buffer_object.h"

fs_context *fs_context_create(const fs_config *cfg, int width, int height)
{
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return NULL;
    fs_context *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    if (cfg)
        c->cfg = *cfg;
    else
        fs_config_defaults(&c->cfg);
    c->error = GL_NO_ERROR;
    c->pack_alignment = c->unpack_alignment = 4;
    fs_raster_state_init(&c->raster, (int)c->cfg.raster_subpixel_bits);
    fs_fragment_state_init(&c->frag);
    fs_vertex_stage_init(c);
    fs_render_mode_init(c);
    fs_state_init(c); /* the initial values of GL 1.5 spec tables 6.5-6.32 */
    for (int k = 0; k < 4; k++) /* 16 bits a component, or no buffer (pipeline/accum.h) */
        c->accum.bits[k] = c->cfg.framebuffer_accum_bits > 0 ? 16 : 0;
    fs_texgen_init(c); /* table 6.17's planes and modes (no glGet name: not in the table) */
    if (fs_texture_init(c) != 0) {
        fs_context_destroy(c);
        return NULL;
    }
    if (fs_context_resize(c, width, height) != 0) {
        fs_context_destroy(c);
        return NULL;
    }
    /* GL 1.5 spec 4.1.2 and 2.11.1: the scissor box and the viewport start
     * as the window's rectangle. */
    c->frag.scissor[0] = c->frag.scissor[1] = 0;
    c->frag.scissor[2] = width;
    c->frag.scissor[3] = height;
    fs_context_set_double_buffered(c, false); /* OSMesa's contexts are single-buffered */
    return c;
}

int fs_context_resize(fs_context *c, int width, int height)
{
    return fs_framebuffer_init(&c->fb, width, height, (int)c->cfg.framebuffer_depth_bits,
                               (int)c->cfg.framebuffer_stencil_bits);
}

void fs_context_destroy(fs_context *c)
{
    if (!c)
        return;
    if (c->driver_free)
        c->driver_free(c);
    fs_par_free(c);
    fs_state_free(c);
    fs_accum_free(c);
    fs_occlusion_free(c);
    fs_texture_free(c);
    fs_eval_free(c);
    fs_buffer_objects_free(c);
    fs_vertex_stage_free(c);
    fs_framebuffer_free(&c->fb);
    free(c->scratch);
    for (size_t i = 0; i < sizeof c->array_copy / sizeof c->array_copy[0]; i++)
        for (int k = 0; k < 2; k++)
            free(c->array_copy[i].buf[k]);
    free(c);
}

bool fs_gen_names_ok(fs_context *c, GLsizei n, size_t held)
{
    if (n < 0) {
        fs_error(c, GL_INVALID_VALUE);
        return false;
    }
    if (held > FS_MAX_NAMES || (size_t)n > FS_MAX_NAMES - held) {
        fs_error(c, GL_OUT_OF_MEMORY);
        return false;
    }
    return true;
}

void fs_error(fs_context *c, GLenum err)
{
    c->stats.gl_errors++;
    if (c->error == GL_NO_ERROR)
        c->error = err;
    if (c->error_hook)
        c->error_hook(c->error_user, err);
}

void fs_unsupported(fs_context *c, const char *what)
{
    c->stats.unsupported_calls++;
    for (int i = 0; i < c->unsupported_feature_count; i++) {
        if (strcmp(c->unsupported_feature[i].name, what) == 0) {
            c->unsupported_feature[i].count++;
            return;
        }
    }
    /* The last slot collects everything once the table is full. */
    int n = c->unsupported_feature_count;
    int cap = (int)(sizeof c->unsupported_feature / sizeof c->unsupported_feature[0]);
    if (n == cap) {
        c->unsupported_feature[cap - 1].count++;
        snprintf(c->unsupported_feature[cap - 1].name, sizeof c->unsupported_feature[0].name, "(other)");
        return;
    }
    snprintf(c->unsupported_feature[n].name, sizeof c->unsupported_feature[n].name, "%s", what);
    c->unsupported_feature[n].count = 1;
    c->unsupported_feature_count++;
}

void *fs_scratch(fs_context *c, size_t bytes)
{
    if (bytes > c->scratch_size) {
        void *p = realloc(c->scratch, bytes);
        if (!p)
            return NULL;
        c->scratch = p;
        c->scratch_size = bytes;
    }
    memset(c->scratch, 0, bytes);
    return c->scratch;
}
