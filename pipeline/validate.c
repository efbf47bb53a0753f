/*
 * The validation step (issue 18 item 2): derived state built once when the
 * state it derives from changed, as Mesa validates from dirty flags and
 * softpipe rebuilds its quad stages (docs/architecture.md).  Every command
 * that changes state marks its glPushAttrib group in fs_context.dirty
 * (pipeline/state.h); a quad finding any bit set validates first
 * (fs_fragment_quad), so nothing derived is ever used stale.
 *
 * The fragment half: the fragment key (validate.h) packs the state that
 * decides the per-fragment path (GL 1.5 spec 4.1, 4.2.1, 4.2.2), and the
 * first entry of the table of variants (fragment_ops.c) that serves the key
 * becomes c->frag.quad_fn.
 */
#include "context.h"
#include "validate.h"
#include "fragment_stages.h"

_Static_assert(FS_FKEY_NO_COLOR == 1u && FS_FKEY_DEPTH_WRITE == 1u << 6, "the flags are bits 0-6");

uint32_t fs_fragment_key(const fs_context *c)
{
    const fs_fragment_state *f = &c->frag;
    uint32_t k = 0;
    /* The flags of bits 0-6, in validate.h's order. */
    const bool flag[] = {c->draw_buffer == GL_NONE, f->suppress_writes, f->scissor_enabled, f->alpha_enabled,
                         f->stencil_enabled, f->depth_enabled, f->depth_write};
    for (int i = 0; i < 7; i++)
        k |= (uint32_t)flag[i] << i;
    k |= f->blend_enabled ? FS_FKEY_BLEND : 0u;
    k |= f->logic_op_enabled ? FS_FKEY_LOGIC : 0u;
    k |= c->st.fog.enabled ? FS_FKEY_FOG : 0u;
    k |= c->raster.interpolate_color2 ? FS_FKEY_COLOR_SUM : 0u;
    /* The setters accept only GL_NEVER..GL_ALWAYS and GL_CLEAR..GL_SET;
     * the masks keep any other value out of the neighbouring fields. */
    k |= FS_FKEY_DEPTH_FUNC(f->depth_func) & FS_FKEY_DEPTH_FUNC_MASK;
    k |= (uint32_t)(f->logic_op - GL_CLEAR) << FS_FKEY_LOGIC_OP_SHIFT & FS_FKEY_LOGIC_OP_MASK;
    k |= fs_fkey_blend_factor(f->blend_src) << FS_FKEY_BLEND_SRC_SHIFT;
    k |= fs_fkey_blend_factor(f->blend_dst) << FS_FKEY_BLEND_DST_SHIFT;
    if (f->blend_src_alpha != f->blend_src || f->blend_dst_alpha != f->blend_dst || f->blend_equation != GL_FUNC_ADD)
        k |= FS_FKEY_BLEND_EXT;
    for (int i = 0; i < 4; i++)
        if (f->color_mask[i])
            k |= 1u << (FS_FKEY_COLOR_MASK_SHIFT + i);
    return k;
}

static void validate_fragment(fs_context *c)
{
    int n;
    const fs_fragment_variant *v = fs_fragment_variants(&n);
    uint32_t key = fs_fragment_key(c);
    int i = 0;
    while (i < n - 1 && (key & v[i].mask) != v[i].value)
        i++; /* the last entry, the general path, serves every key */
    c->frag.key = key;
    c->frag.quad_fn = v[i].fn;
}

void fs_validate(fs_context *c)
{
    uint32_t dirty = c->dirty;
    c->dirty = 0;
    if (dirty & GL_FOG_BIT)
        fs_fog_validate(c);
    if (dirty & FS_FRAGMENT_KEY_GROUPS)
        validate_fragment(c);
}
