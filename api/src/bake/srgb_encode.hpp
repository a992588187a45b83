// Linear -> sRGB 8-bit encoding that gives the same bytes on every platform: the code is
// found by comparing against the linear values of the midpoints between codes, and those
// come from +, -, *, / only (no pow from the C library, whose last bit varies).
#pragma once

#include <cstdint>

namespace grass {

// sRGB code (0..255) of a linear value; clamps to [0, 1]; NaN gives 0.
uint8_t linear_to_srgb8(float linear);

// Linear value in [0, 1] to unorm8 (round to nearest); clamps; NaN gives 0.
uint8_t float_to_unorm8(float value);

} // namespace grass
