// Design maps (lemme2012 6.4): host images validated and converted once to 16-bit unorm
// (colour maps: linear RGB + alpha), with a min/max pyramid for the single-channel ones.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/log.hpp"
#include "maps/map_pyramid.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct DesignMap {
    explicit DesignMap(HostAllocator* host) : texels(StlAllocator<uint16_t>(host)), pyramid(host) {}
    Vector<uint16_t> texels; // width x height x channels, row-major, tightly packed
    uint32_t width = 0, height = 0;
    uint32_t channels = 1; // 1 or 4
    grass_map_format format = GRASS_MAP_FORMAT_R8_UNORM;
    MapPyramid pyramid; // single-channel maps only
    uint32_t field_users = 0;
    bool field_private = false; // made from grass_field_desc.density_map: owned by its field, no public id
};

// The channels of a format (1 or 4), or 0 if `format` is not a grass_map_format.
uint32_t map_format_channels(int64_t format);

// Validates `desc` (size, pitch, format, finite values in [0, 1]) and converts its pixels
// to 16-bit unorm in `out` (sRGB colour to linear). `max_width`/`max_height` bound the size
// (16384 for a new map, the space left for a region). On error logs, returns the code and
// leaves `out` untouched.
grass_result convert_map(Log* log, const char* function, const char* name, const grass_map_desc* desc,
                         uint32_t max_width, uint32_t max_height, Vector<uint16_t>* out);

// Bilinear sample of channel 0 with edge clamping at map uv (u along x, v along z), as the
// GPU does; `channels` is the texel stride.
float sample_map(const uint16_t* texels, uint32_t width, uint32_t height, uint32_t channels, double u, double v);

} // namespace grass
