/*
 * The texels the texture unit read for one quad: its record for the cycle
 * model (rtl_model/texture_stage.c), which times the texture cache and
 * memory from it instead of addressing texels itself.  Per pixel, the
 * (level, x, y) of every texel fetched from a level's image, in the order
 * the sampler read them, after its wrapping and clamping (GL 1.5 spec
 * 3.8.7; units/texture_sample.c).  A GL_CLAMP border texel comes from the
 * border colour, not from the image, and is not listed.
 */
#ifndef FS_TEXTURE_READS_H
#define FS_TEXTURE_READS_H

/* At most a pixel: LINEAR on two levels (GL_LINEAR_MIPMAP_LINEAR), 8
 * texels a level for a 3D texture. */
#define FS_TEX_READS_MAX 16

typedef struct fs_tex_reads {
    unsigned n[4];
    struct fs_tex_read {
        int level, x, y;
    } texel[4][FS_TEX_READS_MAX];
} fs_tex_reads;
#endif
