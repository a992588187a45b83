// Mirrored aperiodic tiling (lemme2012 6.3, after boulanger2006 3.1): each cell draws the
// patch mirrored along x and/or z, chosen by high-frequency noise at the cell.
#pragma once

#include <cstdint>

namespace grass {

// Bit 0: mirror along x, bit 1: mirror along z. Eq. 6.4 with a white-noise lookup at the
// integer cell coordinates: s = 2 step(0.5, noise(cell)) - 1 per axis. Exact for any cell
// index (no float precision loss in huge fields). 32-bit integer arithmetic only: the
// shaders compute the same bits (mirror_bits in api/shaders/lighting.glsl).
uint32_t mirror_bits(uint32_t cell_x, uint32_t cell_z, uint32_t seed);

} // namespace grass
