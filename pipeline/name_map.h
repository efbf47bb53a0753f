/*
 * A map from GL object names to objects, for every kind of object with
 * names (GL 1.5 spec 2.9 buffer objects, 5.4 display lists).  Open
 * addressing on the name with linear probing; deleted slots are marked so
 * probing continues past them, and the table is rebuilt without them when
 * it grows.  The map holds pointers only: the caller owns the objects.
 */
#ifndef FS_NAME_MAP_H
#define FS_NAME_MAP_H
#include <stdbool.h>
#include <stddef.h>
#include <GL/gl.h>

typedef struct fs_name_slot {
    GLuint name;
    void *obj; /* NULL: free, or deleted when `gone` */
    bool gone;
} fs_name_slot;

typedef struct fs_name_map {
    fs_name_slot *slot;
    size_t cap;  /* a power of two, or 0 before the first insert */
    size_t held; /* objects in the map */
    size_t used; /* slots taken: held + deleted */
} fs_name_map;

/* The object of a name, or NULL. */
void *fs_name_map_get(const fs_name_map *m, GLuint name);
/* Adds an object under a name the map does not hold.  Returns 0, or -1
 * when out of memory (the map is unchanged). */
int fs_name_map_put(fs_name_map *m, GLuint name, void *obj);
/* Removes a name; returns its object, or NULL when the map did not hold it. */
void *fs_name_map_remove(fs_name_map *m, GLuint name);
/* Visits the objects: start with *pos = 0; returns the next object (and
 * its name in *name when not NULL), or NULL after the last.  The map may
 * be changed by fs_name_map_take during a visit. */
void *fs_name_map_next(const fs_name_map *m, size_t *pos, GLuint *name);
/* Removes the object that the last fs_name_map_next(m, pos, ...) returned. */
void fs_name_map_take(fs_name_map *m, size_t pos);
/* Frees the table (not the objects) and leaves an empty map. */
void fs_name_map_clear(fs_name_map *m);
#endif
