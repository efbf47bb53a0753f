/*
 * Occlusion Unit timing (Huettner 1999, 3.3): E Occlusion Engines test a
 * fragment against their tiles, one tile test per engine per cycle (tiles
 * assigned round robin, so T tiles take ceil(T/E) cycles per fragment,
 * 3.3.1); the engines work in lockstep on one fragment.  OccU Control
 * serialises the engines' hit-list writes on one memory bus (3.3.2): an
 * entry (x, y) of 8 bytes takes ceil(8 / bus_bytes) bus cycles, and handing
 * the bus from one engine to another costs the arbitration time.
 *
 * The tests and hits themselves come from the functional unit through
 * fs_occu_hooks (units/occlusion_unit.h), called in its processing order:
 * per fragment, engines in index order.
 */
#include "cycle_internal.h"
#include "../units/occlusion_unit.h"

static void engine_fragment(void *user, int engine, int x, int y, unsigned tests, unsigned hits)
{
    (void)hits;
    fs_cycle *cy = user;
    /* A new fragment starts when the engine index does not increase or the
     * position changes. */
    if (engine <= cy->occ_last_engine || x != cy->occ_last_x || y != cy->occ_last_y) {
        cy->occ_cycles += cy->occ_cur;
        cy->occ_cur = 0;
    }
    if (tests > cy->occ_cur)
        cy->occ_cur = tests;
    cy->occ_last_engine = engine;
    cy->occ_last_x = x;
    cy->occ_last_y = y;
    cy->occ_pending = true;
}

static void control_write(void *user, int engine, int tile, int x, int y, uint32_t slot, bool stored)
{
    (void)tile, (void)x, (void)y, (void)slot;
    fs_cycle *cy = user;
    if (!stored)
        return; /* a full list: the overflow flag is set, nothing goes on the bus */
    cy->occ_writes++;
    if (engine != cy->occ_last_writer)
        cy->occ_arb++;
    cy->occ_last_writer = engine;
    cy->occ_pending = true;
}

void fs_cyc_occlusion_hook(fs_cycle *cy, fs_context *c)
{
    if (cy->occu_hooked || !cy->cfg.occlusion_present || !fs_occlusion_unit(c))
        return;
    fs_occu_hooks h = {cy, engine_fragment, control_write};
    if (fs_occlusion_set_hooks(c, &h) == 0)
        cy->occu_hooked = true;
    cy->occ_last_engine = -1;
    cy->occ_last_writer = -1;
}

void fs_cyc_occlusion_quad_end(fs_cycle *cy, uint64_t *service, bool *writes)
{
    uint64_t tests = cy->occ_cycles + cy->occ_cur;
    uint64_t bus = (8u + (uint64_t)cy->cfg.occlusion_bus_bytes - 1) / (uint64_t)cy->cfg.occlusion_bus_bytes;
    uint64_t wr = cy->occ_writes * bus + cy->occ_arb * (uint64_t)cy->cfg.occlusion_arbitration_cycles;
    cy->acc.occlusion_test_cycles += tests;
    cy->acc.occlusion_write_cycles += wr;
    /* Engines and OccU Control overlap: the slower one sets the pace. */
    *service = tests > wr ? tests : wr;
    *writes = cy->occ_writes != 0;
    cy->occ_last_tests = tests;
    cy->occ_last_writes = wr;
    cy->occ_cycles = cy->occ_cur = cy->occ_writes = cy->occ_arb = 0;
    cy->occ_last_engine = -1;
    cy->occ_pending = false;
}
