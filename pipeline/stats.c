#include "stats.h"
#include <stddef.h>
#include <jansson.h>

const fs_stat_info fs_stat_table[] = {
#define FS_STAT(name, unit, meaning) {#name, unit, meaning, offsetof(fs_stats, name)},
#include "stats.def"
#undef FS_STAT
};
const int fs_stat_count = (int)(sizeof fs_stat_table / sizeof fs_stat_table[0]);

void fs_stats_add(fs_stats *into, const fs_stats *from)
{
    for (int i = 0; i < fs_stat_count; i++)
        *(uint64_t *)((char *)into + fs_stat_table[i].offset) += fs_stat_get(from, i);
}

json_t *fs_stats_json(const fs_stats *s)
{
    json_t *o = json_object();
    for (int i = 0; o && i < fs_stat_count; i++)
        if (json_object_set_new(o, fs_stat_table[i].name, json_integer((json_int_t)fs_stat_get(s, i))) != 0) {
            json_decref(o);
            o = NULL;
        }
    return o;
}

void fs_stats_list(FILE *f)
{
    for (int i = 0; i < fs_stat_count; i++)
        fprintf(f, "%-24s %-10s %s\n", fs_stat_table[i].name, fs_stat_table[i].unit,
                fs_stat_table[i].meaning);
}
