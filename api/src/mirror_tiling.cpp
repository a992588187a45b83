#include "mirror_tiling.hpp"

#include "random.hpp"

namespace grass {

uint32_t mirror_bits(uint64_t cell_x, uint64_t cell_z, uint32_t seed) {
    const uint64_t h = hash_cell(cell_x, cell_z, 0x6d6972726f72ull ^ seed); // "mirror"
    // Two independent noise channels ("red" and "green" of the noise map), step at 0.5.
    const uint32_t sx = (h >> 63) & 1u;
    const uint32_t sz = (h >> 31) & 1u;
    return sx | (sz << 1);
}

} // namespace grass
