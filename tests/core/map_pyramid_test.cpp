// The min/max pyramid bounds every value bilinear sampling can return over a rectangle, and
// stays exact after a region update.
#include "maps/design_map.hpp"
#include "maps/map_pyramid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

struct Checker {
    std::vector<uint16_t> texels;
    uint32_t w, h;
    // Brute force: sample densely over the rectangle.
    void sampled_range(double u0, double v0, double u1, double v1, float* lo, float* hi) const {
        *lo = 1.0f, *hi = 0.0f;
        for (int j = 0; j <= 40; ++j) {
            for (int i = 0; i <= 40; ++i) {
                const float s =
                    grass::sample_map(texels.data(), w, h, 1, u0 + (u1 - u0) * i / 40.0, v0 + (v1 - v0) * j / 40.0);
                *lo = std::min(*lo, s), *hi = std::max(*hi, s);
            }
        }
    }
};

TEST(MapPyramid, BoundsEveryBilinearSampleOverRandomRectangles) {
    grass::HostAllocator host(grass_allocator{});
    std::mt19937 rng(7);
    for (uint32_t w : {1u, 5u, 64u, 77u}) {
        for (uint32_t h : {1u, 3u, 64u, 50u}) {
            Checker c{std::vector<uint16_t>(size_t(w) * h), w, h};
            for (uint16_t& t : c.texels) t = static_cast<uint16_t>(rng() & 0xffff);
            grass::MapPyramid p(&host);
            p.build(c.texels.data(), w, h);
            std::uniform_real_distribution<double> uv(-0.2, 1.2);
            for (int k = 0; k < 60; ++k) {
                double u0 = uv(rng), u1 = uv(rng), v0 = uv(rng), v1 = uv(rng);
                if (u0 > u1) std::swap(u0, u1);
                if (v0 > v1) std::swap(v0, v1);
                const grass::MapRange r = p.range(u0, v0, u1, v1);
                float lo, hi;
                c.sampled_range(u0, v0, u1, v1, &lo, &hi);
                EXPECT_LE(r.min, lo + 1e-6f) << w << "x" << h;
                EXPECT_GE(r.max, hi - 1e-6f) << w << "x" << h;
            }
            // The whole map: exactly its extremes.
            const auto [mn, mx] = std::minmax_element(c.texels.begin(), c.texels.end());
            const grass::MapRange all = p.range(0.0, 0.0, 1.0, 1.0);
            EXPECT_FLOAT_EQ(all.min, *mn / 65535.0f);
            EXPECT_FLOAT_EQ(all.max, *mx / 65535.0f);
        }
    }
}

TEST(MapPyramid, ASmallRectangleIsBoundedByItsNeighbourhoodNotTheWholeMap) {
    grass::HostAllocator host(grass_allocator{});
    std::vector<uint16_t> t(64 * 64, 0);
    t[10 * 64 + 50] = 65535; // one bright texel far from the query
    grass::MapPyramid p(&host);
    p.build(t.data(), 64, 64);
    const grass::MapRange r = p.range(2.0 / 64, 2.0 / 64, 6.0 / 64, 6.0 / 64);
    EXPECT_EQ(r.max, 0.0f);
    EXPECT_EQ(p.range(0.0, 0.0, 1.0, 1.0).max, 1.0f);
}

TEST(MapPyramid, UpdateOfARegionMatchesARebuild) {
    grass::HostAllocator host(grass_allocator{});
    std::mt19937 rng(3);
    const uint32_t w = 93, h = 41;
    std::vector<uint16_t> t(size_t(w) * h);
    for (uint16_t& x : t) x = static_cast<uint16_t>(rng() & 0xffff);
    grass::MapPyramid updated(&host);
    updated.build(t.data(), w, h);
    for (uint32_t y = 7; y < 19; ++y) {
        for (uint32_t x = 30; x < 71; ++x) t[size_t(y) * w + x] = 0;
    }
    updated.update(t.data(), 30, 7, 41, 12);
    grass::MapPyramid rebuilt(&host);
    rebuilt.build(t.data(), w, h);
    std::uniform_real_distribution<double> uv(0.0, 1.0);
    for (int k = 0; k < 300; ++k) {
        double u0 = uv(rng), u1 = uv(rng), v0 = uv(rng), v1 = uv(rng);
        if (u0 > u1) std::swap(u0, u1);
        if (v0 > v1) std::swap(v0, v1);
        const grass::MapRange a = updated.range(u0, v0, u1, v1), b = rebuilt.range(u0, v0, u1, v1);
        EXPECT_EQ(a.min, b.min);
        EXPECT_EQ(a.max, b.max);
    }
    // Bilinear footprint texels 32..47 x 8..15: inside the mown rectangle.
    EXPECT_EQ(updated.range(33.0 / w, 9.0 / h, 47.0 / w, 15.0 / h).max, 0.0f);
}

} // namespace
