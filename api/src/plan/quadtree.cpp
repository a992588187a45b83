#include "plan/quadtree.hpp"

#include <algorithm>

namespace grass {

QuadtreeShape::QuadtreeShape(uint32_t cells_x, uint32_t cells_z) : cells_x_(cells_x), cells_z_(cells_z) {
    // depth = ceil(log2(max(columns, rows))) + 1   (lemme eq. 6.1)
    const uint64_t dim = std::max(cells_x, cells_z);
    levels_ = 1;
    while ((uint64_t(1) << (levels_ - 1)) < dim) ++levels_;
}

NodeCells QuadtreeShape::cells_of(uint32_t level, uint64_t x, uint64_t z) const {
    NodeCells c;
    const uint64_t side = uint64_t(1) << level;
    c.x0 = x << level;
    c.z0 = z << level;
    c.count_x = std::min<uint64_t>(side, cells_x_ - c.x0);
    c.count_z = std::min<uint64_t>(side, cells_z_ - c.z0);
    return c;
}

} // namespace grass
