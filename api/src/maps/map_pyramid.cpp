#include "maps/map_pyramid.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

void MapPyramid::build(const uint16_t* texels, uint32_t width, uint32_t height) {
    base_ = texels;
    width_ = width;
    height_ = height;
    levels_.clear();
    uint32_t w = width, h = height;
    while (w > 1 || h > 1) {
        w = (w + 1) / 2;
        h = (h + 1) / 2;
        Level level(host_);
        level.width = w;
        level.height = h;
        level.lo.resize(static_cast<size_t>(w) * h);
        level.hi.resize(static_cast<size_t>(w) * h);
        levels_.push_back(std::move(level));
        fill(static_cast<uint32_t>(levels_.size()), 0, 0, w - 1, h - 1);
    }
}

void MapPyramid::update(const uint16_t* texels, uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    base_ = texels;
    if (w == 0 || h == 0) return;
    uint32_t x0 = x, y0 = y, x1 = x + w - 1, y1 = y + h - 1;
    for (uint32_t k = 1; k <= levels_.size(); ++k) {
        x0 >>= 1, y0 >>= 1, x1 >>= 1, y1 >>= 1;
        fill(k, x0, y0, x1, y1);
    }
}

void MapPyramid::fill(uint32_t k, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
    Level& dst = levels_[k - 1];
    const uint32_t sw = k == 1 ? width_ : levels_[k - 2].width;
    const uint32_t sh = k == 1 ? height_ : levels_[k - 2].height;
    for (uint32_t y = y0; y <= y1; ++y) {
        for (uint32_t x = x0; x <= x1; ++x) {
            uint16_t lo = 0xffff, hi = 0;
            for (uint32_t dy = 0; dy < 2; ++dy) {
                for (uint32_t dx = 0; dx < 2; ++dx) {
                    const uint32_t sx = 2 * x + dx, sy = 2 * y + dy;
                    if (sx >= sw || sy >= sh) continue;
                    const size_t i = static_cast<size_t>(sy) * sw + sx;
                    lo = std::min(lo, k == 1 ? base_[i] : levels_[k - 2].lo[i]);
                    hi = std::max(hi, k == 1 ? base_[i] : levels_[k - 2].hi[i]);
                }
            }
            const size_t o = static_cast<size_t>(y) * dst.width + x;
            dst.lo[o] = lo;
            dst.hi[o] = hi;
        }
    }
}

MapRange MapPyramid::range(double u0, double v0, double u1, double v1) const {
    // Bilinear sampling at u reads texels floor(u w - 0.5) and the one after, clamped.
    auto texel_span = [](double a, double b, uint32_t n, uint32_t* first, uint32_t* last) {
        const double lo = std::floor(std::min(a, b) * n - 0.5), hi = std::floor(std::max(a, b) * n - 0.5) + 1.0;
        const double top = static_cast<double>(n - 1);
        *first = static_cast<uint32_t>(std::min(std::max(lo, 0.0), top));
        *last = static_cast<uint32_t>(std::min(std::max(hi, 0.0), top));
    };
    uint32_t x0, x1, y0, y1;
    texel_span(u0, u1, width_, &x0, &x1);
    texel_span(v0, v1, height_, &y0, &y1);
    uint32_t k = 0;
    while ((x1 >> k) - (x0 >> k) > 3 || (y1 >> k) - (y0 >> k) > 3) ++k; // at most 4 x 4 entries
    x0 >>= k, x1 >>= k, y0 >>= k, y1 >>= k;
    uint16_t lo = 0xffff, hi = 0;
    for (uint32_t y = y0; y <= y1; ++y) {
        for (uint32_t x = x0; x <= x1; ++x) {
            if (k == 0) {
                const uint16_t t = base_[static_cast<size_t>(y) * width_ + x];
                lo = std::min(lo, t);
                hi = std::max(hi, t);
            } else {
                const Level& l = levels_[k - 1];
                const size_t i = static_cast<size_t>(y) * l.width + x;
                lo = std::min(lo, l.lo[i]);
                hi = std::max(hi, l.hi[i]);
            }
        }
    }
    return MapRange{lo / 65535.0f, hi / 65535.0f};
}

} // namespace grass
