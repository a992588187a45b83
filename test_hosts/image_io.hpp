// PNG output for the headless hosts, through libpng.
#pragma once

#include "headless_host.hpp"

#include <string>

namespace grass_host {

// Writes an RGBA8 image (top row first) as PNG. False and *error on failure.
bool write_png(const std::string& path, const Image& image, std::string* error);

} // namespace grass_host
