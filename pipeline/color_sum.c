/*
 * The secondary colour and the colour sum (GL 1.5 spec 2.7, 3.9): the
 * current secondary colour glSecondaryColor3* sets, and the sum of a
 * fragment's primary and secondary colours.  llvmpipe (Mesa 22.3's
 * fixed-function fragment shader, ff_fragment_shader.cpp, read for the
 * method) adds the secondary r, g, b after texturing when GL_COLOR_SUM is
 * enabled or lighting uses GL_SEPARATE_SPECULAR_COLOR, unclamped: fog
 * then mixes with the unclamped sum and only the colour buffer's
 * conversion clamps (measured on OSMesa: (0.8 + 0.6) fogged with f = 0.5
 * writes 179, not 128; tests/test_color_sum.c).
 */
#include "vertex_internal.h"
#include "fragment_stages.h"

/* 2.7: three components; the fourth stays 1 (OSMesa answers
 * GL_CURRENT_SECONDARY_COLOR so); values are not clamped when set. */
static void secondary3(fs_context *c, float r, float g, float b)
{
    fs_vs_attrib_given(c, FS_ATTR_COLOR2);
    float *s = c->current.secondary_color;
    s[0] = r;
    s[1] = g;
    s[2] = b;
    s[3] = 1.0f;
}

/* Each type as glColor converts it (table 2.9), scalar and vector forms. */
#define SECONDARY3(sfx, T, CONV)                                                                \
    void fs_exec_SecondaryColor3##sfx(fs_context *c, T r, T g, T b) { secondary3(c, CONV(r), CONV(g), CONV(b)); } \
    void fs_exec_SecondaryColor3##sfx##v(fs_context *c, const T *v) { secondary3(c, CONV(v[0]), CONV(v[1]), CONV(v[2])); }
#define F2F(x) ((float)(x))
SECONDARY3(b, GLbyte, B2F)
SECONDARY3(d, GLdouble, F2F)
SECONDARY3(f, GLfloat, F2F)
SECONDARY3(i, GLint, I2F)
SECONDARY3(s, GLshort, S2F)
SECONDARY3(ub, GLubyte, UB2F)
SECONDARY3(ui, GLuint, UI2F)
SECONDARY3(us, GLushort, US2F)

void fs_color_sum_setup(fs_context *c, fs_vs_setup *s)
{
    s->separate_specular = c->lighting.enabled && c->lighting.color_control == GL_SEPARATE_SPECULAR_COLOR;
    s->color_sum = c->st.color_sum || s->separate_specular;
    if (s->color_sum != c->raster.interpolate_color2) {
        /* The fragment key has the sum (FS_FKEY_COLOR_SUM); GL_COLOR_SUM
         * is in no attribute group, so its change is marked here. */
        c->raster.interpolate_color2 = s->color_sum;
        c->dirty |= GL_ENABLE_BIT;
    }
}

void fs_color_sum_quad(fs_quad *q, unsigned mask)
{
    for (int i = 0; i < 4; i++)
        if (mask >> i & 1u)
            for (int k = 0; k < 3; k++)
                q->color[i][k] = q->color[i][k] + q->color2[i][k];
}
