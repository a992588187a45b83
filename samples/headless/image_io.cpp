#include "image_io.hpp"

#include <png.h>

#include <cstdio>

namespace grass_host {

bool write_png(const std::string& path, const Image& image, std::string* error) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = PNG_FORMAT_RGBA;
    if (!png_image_write_to_file(&png, path.c_str(), 0, image.rgba.data(), 0, nullptr)) {
        if (error) *error = "cannot write " + path + ": " + png.message;
        return false;
    }
    return true;
}

} // namespace grass_host
