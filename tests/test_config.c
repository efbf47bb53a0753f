/*
 * The configuration tables (pipeline/config.def for the functional
 * pipeline, rtl_model/cycle_config.def for the cycle-level model) read as
 * one (driver/run_config.c): a key belongs to exactly one table, an INI
 * file and --set reach both, the listing gives the pipeline's keys first,
 * and the messages for unknown keys and bad values are the ones
 * docs/config.md and tests/cli_cycle.sh show.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "../driver/run_config.h"

/* No key is in both tables, and every key of a table is in its struct. */
TEST(tables_are_disjoint)
{
    fs_config_part gl = fs_config_part_of(NULL), cy = fs_cycle_config_part(NULL);
    CHECK_EQ_UINT(gl.nkeys, 10); /* with raster.threads */
    CHECK_EQ_UINT(cy.nkeys, 52); /* with sampling.max_error */
    for (size_t i = 0; i < gl.nkeys; i++) {
        CHECK(gl.keys[i].offset + sizeof(long) <= sizeof(fs_config));
        for (size_t k = 0; k < cy.nkeys; k++)
            CHECK(strcmp(gl.keys[i].section, cy.keys[k].section) != 0 || strcmp(gl.keys[i].key, cy.keys[k].key) != 0);
    }
    for (size_t k = 0; k < cy.nkeys; k++)
        CHECK(cy.keys[k].offset + sizeof(long) <= sizeof(fs_cycle_config));
}

/* One INI file sets keys of both tables; --set too; defaults elsewhere. */
TEST(one_file_sets_both_tables)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/fragsim_test_config_%d.ini", (int)getpid());
    FILE *f = fopen(path, "w");
    REQUIRE(f);
    fprintf(f, "[raster]\nsubpixel_bits = 4\nboards = 2\n[occlusion]\nengines = 3\nlatency = 9\n"
               "[memory]\nunified = false\n");
    fclose(f);
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    char err[512] = "";
    CHECK_EQ_INT(fs_run_config_load(&cfg, path, err, sizeof err), 0);
    remove(path);
    CHECK_EQ_INT(cfg.gl.raster_subpixel_bits, 4);
    CHECK_EQ_INT(cfg.cycle.raster_boards, 2);
    CHECK_EQ_INT(cfg.gl.occlusion_engines, 3);
    CHECK_EQ_INT(cfg.cycle.occlusion_latency, 9);
    CHECK_EQ_INT(cfg.cycle.memory_unified, 0);
    CHECK_EQ_INT(cfg.gl.framebuffer_depth_bits, 24);
    CHECK_EQ_INT(cfg.cycle.sampling_tiles, 64);
    CHECK_EQ_INT(fs_run_config_set(&cfg, "sampling.tiles=8", err, sizeof err), 0);
    CHECK_EQ_INT(fs_run_config_set(&cfg, "framebuffer.stencil_bits=0", err, sizeof err), 0);
    CHECK_EQ_INT(cfg.cycle.sampling_tiles, 8);
    CHECK_EQ_INT(cfg.gl.framebuffer_stencil_bits, 0);
    CHECK_EQ_INT(fs_run_config_check(&cfg, err, sizeof err), 0);
}

/* The messages, as before the split into two tables. */
TEST(errors_name_the_key)
{
    fs_run_config cfg;
    fs_run_config_defaults(&cfg);
    char err[512] = "";
    CHECK_EQ_INT(fs_run_config_set(&cfg, "raster.nonesuch=1", err, sizeof err), -1);
    CHECK_STR(err, "--set: unknown key raster.nonesuch (see `fragsim config --list`)");
    CHECK_EQ_INT(fs_run_config_set(&cfg, "texture.present=maybe", err, sizeof err), -1);
    CHECK_STR(err, "--set: texture.present: 'maybe' is not a boolean (true/false)");
    CHECK_EQ_INT(fs_run_config_set(&cfg, "occlusion.max_tiles=0", err, sizeof err), -1);
    CHECK_STR(err, "--set: occlusion.max_tiles: 0 is out of range [1, 4096] tiles");
    CHECK_EQ_INT(fs_run_config_set(&cfg, "frontend.latency=x", err, sizeof err), -1);
    CHECK_STR(err, "--set: frontend.latency: 'x' is not an integer");
    /* The pipeline's constraints are checked before the cycle model's. */
    cfg.gl.framebuffer_depth_bits = 20;
    cfg.cycle.fragment_interleave = 3;
    CHECK_EQ_INT(fs_run_config_check(&cfg, err, sizeof err), -1);
    CHECK_STR(err, "framebuffer.depth_bits: 20 is not supported (16 or 24)");
    cfg.gl.framebuffer_depth_bits = 16;
    CHECK_EQ_INT(fs_run_config_check(&cfg, err, sizeof err), -1);
    CHECK_STR(err, "fragment.interleave: 3 is not even");
    cfg.cycle.fragment_interleave = 2;
    cfg.cycle.texture_cache_ways = 3;
    CHECK_EQ_INT(fs_run_config_check(&cfg, err, sizeof err), -1);
    CHECK_STR(err, "texture.cache_ways: 3 is not a power of two");
}

/* `fragsim config --list`: the pipeline's keys, then the cycle model's. */
TEST(listing_order)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    REQUIRE(f);
    fs_run_config_list(f);
    fclose(f);
    REQUIRE(text);
    const char *first = strstr(text, "raster.subpixel_bits"), *last_gl = strstr(text, "occlusion.max_tiles");
    const char *first_cy = strstr(text, "frontend.cycles_per_vertex"), *last = strstr(text, "sampling.tile_size");
    CHECK(first == text);
    CHECK(first && last_gl && first_cy && last && last_gl < first_cy && first_cy < last);
    int lines = 0;
    for (const char *p = text; *p; p++)
        lines += *p == '\n';
    CHECK_EQ_INT(lines, 62);
    free(text);
}

TEST_LIST = {
    TEST_ENTRY(tables_are_disjoint),
    TEST_ENTRY(one_file_sets_both_tables),
    TEST_ENTRY(errors_name_the_key),
    TEST_ENTRY(listing_order),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
