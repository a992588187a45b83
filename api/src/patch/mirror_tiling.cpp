#include "patch/mirror_tiling.hpp"

namespace grass {

uint32_t mirror_bits(uint32_t cell_x, uint32_t cell_z, uint32_t seed) {
    // The cell and seed mixed by odd constants, then the "lowbias32" finaliser (Wellons).
    uint32_t h = cell_x * 0x8da6b343u ^ cell_z * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    // Two noise channels ("red" and "green" of the noise map), each stepped at 0.5.
    return (h >> 30) & 3u;
}

} // namespace grass
