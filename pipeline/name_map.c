/*
 * Names to objects (pipeline/name_map.h).  One table serves buffer objects
 * and display lists, which had written the same probing twice.
 */
#include <stdlib.h>
#include "name_map.h"

/* Fibonacci hashing: consecutive names (as glGen* hands them out) spread
 * over the table instead of filling one run of slots. */
static size_t home(GLuint name, size_t cap)
{
    return (size_t)(name * 2654435761u) & (cap - 1);
}

static fs_name_slot *find(const fs_name_map *m, GLuint name)
{
    if (!m->cap)
        return NULL;
    for (size_t i = home(name, m->cap), k = 0; k < m->cap; k++, i = (i + 1) & (m->cap - 1)) {
        fs_name_slot *s = &m->slot[i];
        if (!s->obj && !s->gone)
            return NULL;
        if (s->obj && s->name == name)
            return s;
    }
    return NULL;
}

void *fs_name_map_get(const fs_name_map *m, GLuint name)
{
    fs_name_slot *s = find(m, name);
    return s ? s->obj : NULL;
}

/* Rebuilds the table at a size that keeps it at most half full after one
 * more insert, dropping the deleted slots. */
static int grow(fs_name_map *m)
{
    size_t cap = m->cap ? m->cap : 64;
    while ((m->held + 1) * 2 > cap)
        cap *= 2;
    fs_name_slot *s = calloc(cap, sizeof *s);
    if (!s)
        return -1;
    for (size_t i = 0; i < m->cap; i++) {
        if (!m->slot[i].obj)
            continue;
        size_t j = home(m->slot[i].name, cap);
        while (s[j].obj)
            j = (j + 1) & (cap - 1);
        s[j] = m->slot[i];
    }
    free(m->slot);
    m->slot = s;
    m->cap = cap;
    m->used = m->held;
    return 0;
}

int fs_name_map_put(fs_name_map *m, GLuint name, void *obj)
{
    if ((m->used + 1) * 2 > m->cap && grow(m) != 0)
        return -1;
    size_t i = home(name, m->cap);
    while (m->slot[i].obj)
        i = (i + 1) & (m->cap - 1);
    if (!m->slot[i].gone)
        m->used++;
    m->slot[i] = (fs_name_slot){name, obj, false};
    m->held++;
    return 0;
}

void fs_name_map_take(fs_name_map *m, size_t pos)
{
    fs_name_slot *s = &m->slot[pos - 1];
    s->obj = NULL;
    s->gone = true;
    m->held--;
}

void *fs_name_map_remove(fs_name_map *m, GLuint name)
{
    fs_name_slot *s = find(m, name);
    if (!s)
        return NULL;
    void *obj = s->obj;
    fs_name_map_take(m, (size_t)(s - m->slot) + 1);
    return obj;
}

void *fs_name_map_next(const fs_name_map *m, size_t *pos, GLuint *name)
{
    while (*pos < m->cap) {
        const fs_name_slot *s = &m->slot[(*pos)++];
        if (s->obj) {
            if (name)
                *name = s->name;
            return s->obj;
        }
    }
    return NULL;
}

void fs_name_map_clear(fs_name_map *m)
{
    free(m->slot);
    *m = (fs_name_map){0};
}
