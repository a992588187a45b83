#include "patch/blade_levels.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

uint32_t blade_level_segments(uint32_t subdivisions, uint32_t level) {
    const uint32_t step = level < 31 ? (1u << level) : 0x80000000u;
    return (subdivisions + step - 1) / step;
}

uint32_t blade_level_count(uint32_t subdivisions) {
    uint32_t levels = 1;
    while (blade_level_segments(subdivisions, levels - 1) > 1) ++levels;
    return levels;
}

namespace {

// The farthest a vertex of blade `b`'s full strip lies from the outline of level `k` (each
// edge of a coarse quad runs straight between its rows; a full row between them is compared
// with the point at its t on that edge), patch units.
float level_error(const PatchData& pd, uint32_t subdivisions, uint32_t b, uint32_t k) {
    const uint32_t step = 1u << k;
    const BladeVertex* v = pd.vertices.data() + size_t(b) * pd.vertices_per_blade;
    double worst = 0.0;
    for (uint32_t r = 0; r <= subdivisions; ++r) {
        const uint32_t lo = (r / step) * step, hi = std::min(lo + step, subdivisions);
        if (r == lo || hi == lo) continue;
        const double f = double(r - lo) / double(hi - lo);
        for (uint32_t e = 0; e < 2; ++e) {
            double d2 = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double a = v[2 * lo + e].position[c], z = v[2 * hi + e].position[c];
                const double d = v[2 * r + e].position[c] - (a + (z - a) * f);
                d2 += d * d;
            }
            worst = std::max(worst, std::sqrt(d2));
        }
    }
    return static_cast<float>(worst);
}

} // namespace

void add_blade_levels(uint32_t subdivisions, PatchData* patch) {
    PatchData& pd = *patch;
    const uint32_t levels = std::min(blade_level_count(subdivisions), kMaxBladeLevels);
    pd.level_count = levels;
    size_t total = 0;
    for (uint32_t k = 0; k < levels; ++k) {
        pd.levels[k].first_index = static_cast<uint32_t>(total);
        pd.levels[k].indices_per_blade = blade_level_segments(subdivisions, k) * 6;
        pd.levels[k].error = 0.0f;
        total += size_t(pd.blade_count) * pd.levels[k].indices_per_blade;
    }
    pd.indices.resize(total);
    for (uint32_t k = 1; k < levels; ++k) {
        const uint32_t step = 1u << k, segments = blade_level_segments(subdivisions, k);
        uint32_t* idx = pd.indices.data() + pd.levels[k].first_index;
        float error = pd.levels[k - 1].error; // a coarser level never counts as nearer the full blade
        for (uint32_t b = 0; b < pd.blade_count; ++b) {
            const uint32_t base = b * pd.vertices_per_blade;
            for (uint32_t s = 0; s < segments; ++s) {
                const uint32_t lo = base + 2 * (s * step), hi = base + 2 * std::min((s + 1) * step, subdivisions);
                *idx++ = lo;
                *idx++ = lo + 1;
                *idx++ = hi;
                *idx++ = hi;
                *idx++ = lo + 1;
                *idx++ = hi + 1;
            }
            error = std::max(error, level_error(pd, subdivisions, b, k));
        }
        pd.levels[k].error = error;
    }
}

} // namespace grass
