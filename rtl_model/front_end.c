/*
 * Command/vertex front end: a cost per vertex (transform, lighting,
 * clipping of the geometry engines), charged per triangle in the share of
 * the draw's vertices that triangle consumes, so setup sees triangles at
 * the rate the front end produces them.
 */
#include "cycle_internal.h"

uint64_t fs_cyc_front_end_cycles(const fs_cycle_config *cfg, size_t vertices)
{
    return (uint64_t)cfg->frontend_cycles_per_vertex * (uint64_t)vertices;
}

/* Triangles a draw assembles (GL 1.5 spec 2.6.1), for the per-triangle share. */
static size_t triangles_of(GLenum mode, size_t n)
{
    switch (mode) {
    case GL_TRIANGLES: return n / 3;
    case GL_TRIANGLE_STRIP: case GL_TRIANGLE_FAN: case GL_POLYGON: return n >= 3 ? n - 2 : 0;
    case GL_QUADS: return n / 4 * 2;
    case GL_QUAD_STRIP: return n >= 4 ? (n - 2) / 2 * 2 : 0;
    default: return 0;
    }
}

uint64_t fs_cyc_front_end_per_triangle(const fs_cycle_config *cfg, GLenum mode, size_t n)
{
    size_t t = triangles_of(mode, n);
    if (!t)
        return 0;
    return fs_cyc_front_end_cycles(cfg, n) * 256u / t;
}
