#include "image_io.hpp"

#include <png.h>

#include <cstdio>
#include <vector>

namespace grass_host {

bool write_png(const std::string& path, const Image& image, std::string* error) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    // The picture is opaque: the host composites grass without blending, so the target's
    // alpha channel holds whatever the last fragment wrote (alpha-to-coverage leaves partial
    // values). Written as RGBA, viewers would show those pixels blended with their
    // background; the file keeps RGB only.
    png.format = PNG_FORMAT_RGB;
    std::vector<uint8_t> rgb(size_t(image.width) * image.height * 3);
    for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i) {
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
    }
    if (!png_image_write_to_file(&png, path.c_str(), 0, rgb.data(), 0, nullptr)) {
        if (error) *error = "cannot write " + path + ": " + png.message;
        return false;
    }
    return true;
}

} // namespace grass_host
