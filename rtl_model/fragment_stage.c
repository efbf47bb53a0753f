/*
 * Per-fragment operations of an image engine (GL 1.5 spec 4.1) and their
 * framebuffer traffic: the time per fragment reaching the tests, a depth
 * (with stencil, one 32-bit word) read per fragment tested, a depth write
 * per fragment passing with depth writes on, a colour read when blending or
 * a logic op needs the destination, and a colour write per fragment
 * written.  The outcome (which fragments passed, which were written) comes
 * from the functional pipeline's counters.
 */
#include "cycle_internal.h"
#include "../pipeline/context.h"

void fs_cyc_fragment_work(const fs_context *c, const fs_cycle *cy, unsigned reaching, unsigned passed,
                          unsigned written, uint64_t *service, uint64_t *bytes, bool *reads)
{
    const fs_fragment_state *f = &c->frag;
    uint64_t b = 0;
    bool rd = false;
    if (f->depth_enabled || f->stencil_enabled) {
        b += 4u * reaching;
        rd = reaching != 0;
        if (f->depth_enabled && f->depth_write && !f->suppress_writes)
            b += 4u * passed;
    }
    if (written) {
        b += 4u * written;
        if (f->blend_enabled || f->logic_op_enabled) {
            b += 4u * written;
            rd = true;
        }
    }
    *service = (uint64_t)cy->cfg.fragment_cycles_per_fragment * reaching;
    *bytes = b;
    *reads = rd;
}
