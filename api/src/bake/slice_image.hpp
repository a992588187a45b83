// One layer of a baked slice in linear floating point, before it is encoded into a
// SliceSet: what the slice rasteriser resolves to and what the mip filters work on.
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

struct SliceImage {
    explicit SliceImage(HostAllocator* host)
        : alpha(StlAllocator<float>(host)), color(StlAllocator<float>(host)), normal(StlAllocator<float>(host)),
          threshold(StlAllocator<uint16_t>(host)), coverage(StlAllocator<float>(host)) {}

    void resize(uint32_t w, uint32_t h) {
        width = w;
        height = h;
        const size_t n = static_cast<size_t>(w) * h;
        alpha.assign(n, 0.0f);
        color.assign(n * 3, 0.0f);
        normal.assign(n * 4, 0.0f);
        threshold.assign(n, 0);
        coverage.assign(n * 3, 1.0f);
    }
    size_t texels() const { return static_cast<size_t>(width) * height; }

    uint32_t width = 0;
    uint32_t height = 0;
    Vector<float> alpha;        // coverage in [0, 1]
    Vector<float> color;        // rgb, linear; not premultiplied
    Vector<float> normal;       // xyz unit, patch space, facing the viewer; w = height / H
    Vector<uint16_t> threshold; // unorm16 density threshold of the covering blade, 0 = none
    // The coverage curve: the part of the texel's coverage whose blades have thresholds at
    // most 1/4, 1/2 and 3/4 (relative to alpha; at 1 it is all of it). A tier draws the part
    // of a texel its density and transition interval select, not the whole texel.
    Vector<float> coverage;
};

} // namespace grass
