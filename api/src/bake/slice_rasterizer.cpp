// Edge functions are evaluated in double at the sample centres of a regular 4 x 4 grid per
// texel, each from the triangle's vertices (no incremental stepping), so the result does not
// depend on the traversal order. Coordinates are in sample units: sample (i, j) sits at
// (i + 0.5, j + 0.5).
#include "bake/slice_rasterizer.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

SliceRasterizer::SliceRasterizer(uint32_t width, uint32_t height, const float toward_viewer[3], HostAllocator* host)
    : width_(width), height_(height), samples_w_(width * kSamplesPerAxis), samples_h_(height * kSamplesPerAxis),
      depth_(StlAllocator<float>(host)), threshold_(StlAllocator<uint16_t>(host)),
      min_threshold_(StlAllocator<uint16_t>(host)), attributes_(StlAllocator<float>(host)) {
    for (int c = 0; c < 3; ++c) toward_viewer_[c] = toward_viewer[c];
    const size_t n = static_cast<size_t>(samples_w_) * samples_h_;
    depth_.resize(n);
    threshold_.resize(n);
    min_threshold_.resize(n);
    attributes_.resize(n * kAttributes);
    clear();
}

void SliceRasterizer::clear() {
    std::fill(depth_.begin(), depth_.end(), 0.0f);
    std::fill(threshold_.begin(), threshold_.end(), uint16_t(0));
    std::fill(min_threshold_.begin(), min_threshold_.end(), uint16_t(0xffff));
}

namespace {

// Twice the signed area of (a, b, p); positive when p is left of a -> b (t up).
inline double edge(double ax, double ay, double bx, double by, double px, double py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

} // namespace

void SliceRasterizer::draw_triangle(const RasterVertex& a, const RasterVertex& b0, const RasterVertex& c0,
                                    uint16_t threshold) {
    if (threshold == 0) threshold = 1; // 0 marks uncovered samples
    const double sx = samples_w_, sy = samples_h_;
    const RasterVertex* b = &b0;
    const RasterVertex* c = &c0;
    double ax = a.s * sx, ay = a.t * sy;
    double bx = b->s * sx, by = b->t * sy;
    double cx = c->s * sx, cy = c->t * sy;
    double area = edge(ax, ay, bx, by, cx, cy);
    if (!(area != 0.0) || !std::isfinite(area)) return; // degenerate (edge-on) or NaN
    if (area < 0.0) {
        std::swap(b, c);
        std::swap(bx, cx);
        std::swap(by, cy);
        area = -area;
    }
    // Samples whose centre k + 0.5 lies in [min, max].
    const double min_x = std::min(ax, std::min(bx, cx)), max_x = std::max(ax, std::max(bx, cx));
    const double min_y = std::min(ay, std::min(by, cy)), max_y = std::max(ay, std::max(by, cy));
    if (max_x < 0.5 || max_y < 0.5 || min_x > sx - 0.5 || min_y > sy - 0.5) return;
    const long x0 = std::max(0L, static_cast<long>(std::ceil(min_x - 0.5)));
    const long x1 = std::min(static_cast<long>(samples_w_) - 1, static_cast<long>(std::floor(max_x - 0.5)));
    const long y0 = std::max(0L, static_cast<long>(std::ceil(min_y - 0.5)));
    const long y1 = std::min(static_cast<long>(samples_h_) - 1, static_cast<long>(std::floor(max_y - 0.5)));
    const double inv_area = 1.0 / area;
    const RasterVertex* v[3] = {&a, b, c};
    for (long y = y0; y <= y1; ++y) {
        const double py = static_cast<double>(y) + 0.5;
        for (long x = x0; x <= x1; ++x) {
            const double px = static_cast<double>(x) + 0.5;
            const double w0 = edge(bx, by, cx, cy, px, py);
            const double w1 = edge(cx, cy, ax, ay, px, py);
            const double w2 = edge(ax, ay, bx, by, px, py);
            if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
            const double l0 = w0 * inv_area, l1 = w1 * inv_area, l2 = w2 * inv_area;
            const float depth = static_cast<float>(l0 * v[0]->depth + l1 * v[1]->depth + l2 * v[2]->depth);
            const size_t k = static_cast<size_t>(y) * samples_w_ + static_cast<size_t>(x);
            // At a density d the sample is covered when any blade over it has a threshold
            // <= d, whether or not it is the nearest: the coverage curve counts those.
            min_threshold_[k] = std::min(min_threshold_[k], threshold);
            if (threshold_[k] != 0 && !(depth < depth_[k])) continue; // ties: the first drawn stays
            depth_[k] = depth;
            threshold_[k] = threshold;
            float* out = &attributes_[k * kAttributes];
            for (int ch = 0; ch < 3; ++ch) {
                out[ch] = static_cast<float>(l0 * v[0]->albedo[ch] + l1 * v[1]->albedo[ch] + l2 * v[2]->albedo[ch]);
            }
            float n[3];
            for (int ch = 0; ch < 3; ++ch) {
                n[ch] = static_cast<float>(l0 * v[0]->normal[ch] + l1 * v[1]->normal[ch] + l2 * v[2]->normal[ch]);
            }
            const float facing = n[0] * toward_viewer_[0] + n[1] * toward_viewer_[1] + n[2] * toward_viewer_[2];
            const float sign = facing < 0.0f ? -1.0f : 1.0f;
            // The side facing the slice's viewer keeps its sign along the view axis. The two
            // components across it lean one way for some blades and the other way for the
            // others, and would cancel in the texel averages and the mips (a vertical slice
            // would lose the blades' tilt to a high sun, and both would lose the light from
            // the side); the slice keeps their magnitudes and the shaders light the four
            // sign lobes (lighting.glsl, grass_lighting_lobes).
            for (int ch = 0; ch < 3; ++ch) {
                out[3 + ch] = toward_viewer_[ch] != 0.0f ? sign * n[ch] : std::fabs(n[ch]);
            }
            out[6] = static_cast<float>(l0 * v[0]->height + l1 * v[1]->height + l2 * v[2]->height);
        }
    }
}

void SliceRasterizer::resolve(SliceImage* out) const {
    out->resize(width_, height_);
    constexpr uint32_t S = kSamplesPerAxis;
    for (uint32_t ty = 0; ty < height_; ++ty) {
        for (uint32_t tx = 0; tx < width_; ++tx) {
            const size_t texel = static_cast<size_t>(ty) * width_ + tx;
            uint32_t covered = 0;
            double sum[kAttributes] = {0, 0, 0, 0, 0, 0, 0};
            uint16_t ids[kSamplesPerTexel];
            uint32_t counts[kSamplesPerTexel];
            uint32_t distinct = 0;
            for (uint32_t sy = 0; sy < S; ++sy) {
                for (uint32_t sx = 0; sx < S; ++sx) {
                    const size_t k = static_cast<size_t>(ty * S + sy) * samples_w_ + (tx * S + sx);
                    const uint16_t id = threshold_[k];
                    if (id == 0) continue;
                    ++covered;
                    const float* attr = &attributes_[k * kAttributes];
                    for (uint32_t ch = 0; ch < kAttributes; ++ch) sum[ch] += attr[ch];
                    uint32_t d = 0;
                    while (d < distinct && ids[d] != id) ++d;
                    if (d == distinct) {
                        ids[distinct] = id;
                        counts[distinct++] = 0;
                    }
                    ++counts[d];
                }
            }
            float* color = &out->color[texel * 3];
            float* normal = &out->normal[texel * 4];
            if (covered == 0) {
                for (int ch = 0; ch < 3; ++ch) normal[ch] = toward_viewer_[ch];
                continue;
            }
            out->alpha[texel] = static_cast<float>(covered) / static_cast<float>(kSamplesPerTexel);
            for (uint32_t q = 0; q < 3; ++q) {
                const uint32_t limit = (65535u * (q + 1) + 2u) / 4u; // round(65535 (q + 1) / 4)
                uint32_t below = 0;
                for (uint32_t sy = 0; sy < S; ++sy) {
                    for (uint32_t sx = 0; sx < S; ++sx) {
                        const size_t k = static_cast<size_t>(ty * S + sy) * samples_w_ + (tx * S + sx);
                        below += threshold_[k] != 0 && min_threshold_[k] <= limit ? 1u : 0u;
                    }
                }
                out->coverage[texel * 3 + q] = static_cast<float>(below) / static_cast<float>(covered);
            }
            const double inv = 1.0 / covered;
            for (int ch = 0; ch < 3; ++ch) color[ch] = static_cast<float>(sum[ch] * inv);
            // The mean of the unit normals, not renormalised: its length says how much they
            // spread (1 when they agree), which the shaders turn into a softer light
            // (lighting.glsl; Toksvig's mip-mapped normals). The mips average it on.
            for (int ch = 0; ch < 3; ++ch) normal[ch] = static_cast<float>(sum[3 + ch] * inv);
            normal[3] = static_cast<float>(sum[6] * inv);
            uint32_t best = 0;
            for (uint32_t d = 1; d < distinct; ++d) {
                if (counts[d] > counts[best] || (counts[d] == counts[best] && ids[d] < ids[best])) best = d;
            }
            out->threshold[texel] = ids[best];
        }
    }
}

} // namespace grass
