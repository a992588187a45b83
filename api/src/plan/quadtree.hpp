// The implicit quadtree over a field's cells (lemme2012 6.1.1). Built bottom-up: level 0
// nodes are cells, a level-k node groups 2x2 nodes of level k-1, so nodes stay square
// (2^k cells a side) except where the field ends. Nothing is stored per node or per cell:
// a node's cells come from (level, x, z) and its vertical extent from a per-level table, so
// a field of 1e10 cells costs as much memory as one of 100.
#pragma once

#include <cstdint>

namespace grass {

struct NodeCells {
    uint64_t x0, z0;           // first cell
    uint64_t count_x, count_z; // cells spanned (>= 1)
};

class QuadtreeShape {
public:
    QuadtreeShape() = default;
    QuadtreeShape(uint32_t cells_x, uint32_t cells_z);

    uint32_t levels() const { return levels_; } // level levels()-1 is the root
    uint32_t root_level() const { return levels_ - 1; }
    uint64_t nodes_x(uint32_t level) const { return (uint64_t(cells_x_) + (uint64_t(1) << level) - 1) >> level; }
    uint64_t nodes_z(uint32_t level) const { return (uint64_t(cells_z_) + (uint64_t(1) << level) - 1) >> level; }
    NodeCells cells_of(uint32_t level, uint64_t x, uint64_t z) const;

private:
    uint32_t cells_x_ = 1, cells_z_ = 1;
    uint32_t levels_ = 1;
};

// The vertical extent of each level's nodes, in cells above the field plane: the lowest
// and highest point any blade of any node of that level reaches. A flat field has the same
// extent at every level; height and density maps (the design-map issue) will give each
// level its own from min/max pyramids.
struct LevelExtent {
    float min_y = 0.0f;
    float max_y = 0.0f;
};

} // namespace grass
