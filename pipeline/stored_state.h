/*
 * State fragsim stores for glGet and glPushAttrib (pipeline/state.def) but
 * does not model yet: what uses it (stippled lines, the accumulation
 * buffer, colour index mode, glDrawPixels' zoom, multisampling) is absent
 * or counted as unsupported where it would change the image; fog and the
 * colour sum are modelled.  Each part has the file
 * of its commands.
 */
#ifndef FS_STORED_STATE_H
#define FS_STORED_STATE_H
#include <stdbool.h>
#include <GL/gl.h>

/* GL 1.5 spec 3.10, table 6.10 (pipeline/fog.c, which applies it; the
 * one part of this header that is modelled). */
typedef struct fs_fog_state {
    bool enabled;               /* GL_FOG: false */
    GLenum mode;                /* GL_EXP */
    float density, start, end;  /* 1, 0, 1 */
    float index;                /* 0 */
    float color[4];             /* (0, 0, 0, 0), clamped to [0, 1] */
    GLenum coord_src;           /* GL_FRAGMENT_DEPTH */
    /* Derived by the validation step (fs_fog_validate), in no state row:
     * the four constants llvmpipe's fragment shader takes, -1/(e - s),
     * e/(e - s), density/ln 2 and density/sqrt(ln 2). */
    float params[4];
} fs_fog_state;

typedef struct fs_stored_state {
    fs_fog_state fog;
    /* 3.4.2, table 6.13 (pipeline/polygon_state.c), read by the line
     * stipple (pipeline/rasterize_line.c). */
    GLuint line_stipple_pattern; /* 0xffff */
    GLint line_stipple_repeat;   /* 1, clamped to [1, 256] */
    /* 3.6.4, table 6.23 (pipeline/pixel_state.c): glDrawPixels and
     * glCopyPixels, which zoom, are not commands of fragsim yet. */
    float zoom[2];               /* 1, 1 */
    /* 4.2.2-4.2.3, table 6.21 (pipeline/clear.c, pipeline/write_masks.c):
     * the window has no accumulation buffer and no colour index mode
     * (GL_ACCUM_*_BITS and GL_INDEX_BITS 0), so the values only answer
     * glGet. */
    float accum_clear[4];        /* (0, 0, 0, 0), clamped to [-1, 1] */
    GLint index_clear;           /* 0; an integer, as on OSMesa (pipeline/clear.c) */
    GLint index_mask;            /* all ones */
    /* 3.2.1 and 4.1.3, table 6.13 (pipeline/multisample.c): with
     * GL_SAMPLE_BUFFERS 0 these have no effect on rendering. */
    bool multisample;            /* GL_MULTISAMPLE: true */
    bool sample_alpha_to_coverage, sample_alpha_to_one, sample_coverage;
    float sample_coverage_value; /* 1, clamped to [0, 1] */
    bool sample_coverage_invert; /* false */
    /* 3.9, table 6.10: GL_COLOR_SUM (pipeline/color_sum.c). */
    bool color_sum;
    /* 2.7, table 6.5 (pipeline/texture_select.c): the units glActiveTexture
     * and glClientActiveTexture select (read as indices through
     * fs_active_unit and fs_client_active_unit, vertex_stage.h). */
    GLenum active_texture, client_active_texture; /* GL_TEXTURE0 */
    /* 2.6.2, table 6.5: polygon edges are drawn only in GL_LINE/GL_POINT
     * polygon mode, which is counted as unsupported. */
    bool edge_flag;              /* true */
    /* 2.7, table 6.5 (pipeline/immediate.c): the current colour index,
     * kept as the float glIndex gives; the window is RGBA, so it only
     * answers glGet. */
    float current_index;         /* 1 */
} fs_stored_state;

#endif
