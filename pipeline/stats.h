/* Statistics registry: see stats.def. */
#ifndef FS_STATS_H
#define FS_STATS_H
#include <stdint.h>
#include <stdio.h>

typedef struct fs_stats {
#define FS_STAT(name, unit, meaning) uint64_t name;
#include "stats.def"
#undef FS_STAT
} fs_stats;

typedef struct fs_stat_info {
    const char *name, *unit, *meaning;
    size_t offset;
} fs_stat_info;

extern const fs_stat_info fs_stat_table[];
extern const int fs_stat_count;

static inline uint64_t fs_stat_get(const fs_stats *s, int i)
{
    return *(const uint64_t *)((const char *)s + fs_stat_table[i].offset);
}
void fs_stats_add(fs_stats *into, const fs_stats *from);
/* The counters as a new JSON object (jansson), in the table's order;
 * NULL when out of memory. */
struct json_t;
struct json_t *fs_stats_json(const fs_stats *s);
void fs_stats_list(FILE *f);
#endif
