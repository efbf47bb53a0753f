// The one file that talks to OpenImageIO (C++), behind the C interface in
// image.h.  Linked only into the CLI and tools: OpenImageIO pulls in about
// 260 shared libraries (shared/reference-notes.md).
#include <OpenImageIO/imageio.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>
#include "image.h"

using namespace OIIO;

extern "C" int fs_image_write_png_channels(const char *path, const uint8_t *rgba, int width,
                                           int height, int channels, char *err, size_t errlen)
{
    if (channels != 3 && channels != 4) {
        std::snprintf(err, errlen, "%s: %d channels (3 or 4)", path, channels);
        return -1;
    }
    std::unique_ptr<ImageOutput> out = ImageOutput::create(path);
    if (!out) {
        std::snprintf(err, errlen, "%s: cannot create: %s", path, OIIO::geterror().c_str());
        return -1;
    }
    ImageSpec spec(width, height, channels, TypeDesc::UINT8);
    // The colour buffer's RGB is not premultiplied by its alpha.  Without
    // this attribute OpenImageIO takes RGBA as associated alpha and divides
    // RGB by alpha on writing a PNG (whose alpha is unassociated), so every
    // pixel with alpha < 255 was stored wrong.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // Rows stored unfiltered (libpng's PNG_FILTER_NONE, 0x08): the same pixels,
    // quicker to write, and quick to decode for the conformance runner's own
    // PNG reader (tests/conformance/pngio.py), which has no libpng.
    spec.attribute("png:filter", 0x08);
    if (!out->open(path, spec)) {
        std::snprintf(err, errlen, "%s: %s", path, out->geterror().c_str());
        return -1;
    }
    // GL's row 0 is the bottom; files store the top row first.
    const stride_t row = (stride_t)width * 4;
    const uint8_t *last_row = rgba + (size_t)(height - 1) * (size_t)row;
    // With 3 channels the 4-byte pixels' alpha is skipped (xstride 4).
    bool ok = out->write_image(TypeDesc::UINT8, last_row, 4, -row);
    ok = out->close() && ok;
    if (!ok) {
        std::snprintf(err, errlen, "%s: write failed: %s", path, out->geterror().c_str());
        return -1;
    }
    return 0;
}

extern "C" int fs_image_write_png(const char *path, const uint8_t *rgba, int width, int height,
                                  char *err, size_t errlen)
{
    return fs_image_write_png_channels(path, rgba, width, height, 4, err, errlen);
}

extern "C" int fs_image_read(const char *path, uint8_t **rgba, int *width, int *height, char *err,
                             size_t errlen)
{
    // Read RGB as stored, not multiplied by alpha (see fs_image_write_png).
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<ImageInput> in = ImageInput::open(path, &config);
    if (!in) {
        std::snprintf(err, errlen, "%s: cannot read: %s", path, OIIO::geterror().c_str());
        return -1;
    }
    const ImageSpec &spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0 || (long long)w * h > (1LL << 28)) {
        std::snprintf(err, errlen, "%s: unsupported image size %dx%d", path, w, h);
        return -1;
    }
    std::vector<uint8_t> pix((size_t)w * h * nc);
    if (!in->read_image(0, 0, 0, nc, TypeDesc::UINT8, pix.data())) {
        std::snprintf(err, errlen, "%s: %s", path, in->geterror().c_str());
        return -1;
    }
    uint8_t *outp = (uint8_t *)std::malloc((size_t)w * h * 4);
    if (!outp) {
        std::snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    for (int y = 0; y < h; y++) {
        const uint8_t *src = pix.data() + (size_t)(h - 1 - y) * w * nc;
        uint8_t *dst = outp + (size_t)y * w * 4;
        for (int x = 0; x < w; x++) {
            for (int ch = 0; ch < 4; ch++) {
                uint8_t v;
                if (nc >= 3)
                    v = ch < nc ? src[x * nc + ch] : 255;
                else if (ch < 3)
                    v = src[x * nc]; // grey images: replicate
                else
                    v = nc == 2 ? src[x * nc + 1] : 255;
                dst[x * 4 + ch] = v;
            }
        }
    }
    *rgba = outp;
    *width = w;
    *height = h;
    return 0;
}
