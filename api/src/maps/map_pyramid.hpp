// Min/max pyramids of a single-channel design map (lemme2012 6.4.4: terrain unplanarity
// and minimal height per node; the same for density, so that empty nodes are discarded).
// Level k holds, per block of 2^k x 2^k texels, the lowest and highest texel. A query over
// any rectangle of the map reads at most 4 x 4 entries of one level: O(1) per quadtree
// node, whatever the field's size.
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

struct MapRange {
    float min = 0.0f; // 0..1
    float max = 0.0f;
};

class MapPyramid {
public:
    explicit MapPyramid(HostAllocator* host) : host_(host), levels_(StlAllocator<Level>(host)) {}

    // Builds every level from `texels` (width x height, 16-bit unorm, one channel).
    void build(const uint16_t* texels, uint32_t width, uint32_t height);
    // Recomputes the entries over texels [x, x + w) x [y, y + h) after they changed.
    void update(const uint16_t* texels, uint32_t x, uint32_t y, uint32_t w, uint32_t h);

    // The range of every value that bilinear sampling with edge clamping (as the GPU does)
    // can return anywhere in the uv rectangle [u0, u1] x [v0, v1].
    MapRange range(double u0, double v0, double u1, double v1) const;

private:
    struct Level {
        explicit Level(HostAllocator* host) : lo(StlAllocator<uint16_t>(host)), hi(StlAllocator<uint16_t>(host)) {}
        uint32_t width = 0, height = 0;
        Vector<uint16_t> lo, hi;
    };
    void fill(uint32_t level, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1); // entries [x0, x1] x [y0, y1]

    HostAllocator* host_;
    const uint16_t* base_ = nullptr; // level 0 is the map's own texels
    uint32_t width_ = 0, height_ = 0;
    Vector<Level> levels_; // levels_[k - 1] is level k
};

} // namespace grass
