// Design maps (lemme2012 6.4): host images validated and converted once to 16-bit unorm.
#pragma once

#include "context.hpp"

namespace grass {

// Validates `desc` (size, pitch, format, finite values in [0, 1]) and converts its pixels
// to 16-bit unorm in `out`. On error logs, returns the code and leaves `out` untouched.
grass_result convert_map(grass_context* ctx, const char* function, const char* name, const grass_map_desc* desc,
                         Vector<uint16_t>* out);

// Bilinear sample with edge clamping at map uv (u along x, v along z), as the GPU does.
float sample_map(const uint16_t* texels, uint32_t width, uint32_t height, double u, double v);

} // namespace grass
