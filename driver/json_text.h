/*
 * Text from outside (a trace's function names, a file name) as a JSON
 * string: JSON text is UTF-8 (RFC 8259, 8.1) and jansson refuses any other
 * string, so bytes that do not form UTF-8 are written as '?' instead of
 * making the whole statistics file unwritable.
 */
#ifndef FS_JSON_TEXT_H
#define FS_JSON_TEXT_H
#include <jansson.h>
/* A new JSON string of s (NULL: JSON null); NULL only when out of memory. */
json_t *fs_json_text(const char *s);
#endif
