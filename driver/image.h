/*
 * Images: comparison statistics (C, in the library) and PNG files through
 * OpenImageIO (driver/image_oiio.cpp, CLI and tools only).  Buffers are
 * RGBA8 with row 0 at the bottom, as GL and OSMesa store them.
 */
#ifndef FS_IMAGE_H
#define FS_IMAGE_H
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_image_diff {
    uint64_t pixels;          /* pixels compared */
    uint64_t pixels_differ;   /* pixels with any channel different */
    uint64_t pixels_within_1; /* of those, pixels whose largest channel difference is 1 */
    uint64_t pixels_beyond_1; /* pixels with a channel differing by more than 1 */
    int max_diff;             /* largest channel difference, 0..255 */
    double psnr;              /* over RGB, in dB; INFINITY when identical */
    uint64_t depth_differ;    /* pixels whose depth differs (when compared) */
    uint32_t depth_max_diff;
} fs_image_diff;

void fs_image_compare(const uint8_t *a, const uint8_t *b, int width, int height, fs_image_diff *out);
void fs_depth_compare(const uint32_t *a, const uint32_t *b, int width, int height, fs_image_diff *out);

/* Writes a PNG (top row first, as image files store it).  Returns 0, or -1
 * with a message in err. */
int fs_image_write_png(const char *path, const uint8_t *rgba_bottom_up, int width, int height,
                       char *err, size_t errlen);
/* The same with channels 3 (RGB: alpha dropped, as glretrace's snapshots) or
 * 4 (RGBA, unassociated alpha: the buffer's bytes as they are). */
int fs_image_write_png_channels(const char *path, const uint8_t *rgba_bottom_up, int width,
                                int height, int channels, char *err, size_t errlen);
/* Reads any image OpenImageIO reads into RGBA8, bottom row first; the caller
 * frees *rgba.  Returns 0, or -1 with a message in err. */
int fs_image_read(const char *path, uint8_t **rgba, int *width, int *height, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
