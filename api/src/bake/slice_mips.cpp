#include "bake/slice_mips.hpp"

#include "bake/baked_slices.hpp"
#include "bake/srgb_encode.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace grass {

namespace {

uint32_t level_size(uint32_t size, uint32_t level) { return size >> level ? size >> level : 1; }

// Footprint of texel `x` of a level of `size` texels in its parent of `parent` texels:
// [first, last). 2 texels for halving sizes, 1 where the parent is 1 wide.
void footprint(uint32_t x, uint32_t size, uint32_t parent, uint32_t* first, uint32_t* last) {
    *first = static_cast<uint32_t>(static_cast<uint64_t>(x) * parent / size);
    *last = static_cast<uint32_t>((static_cast<uint64_t>(x + 1) * parent + size - 1) / size);
}

float quantise_unorm8(float a) { return static_cast<float>(float_to_unorm8(a)) / 255.0f; }

uint64_t count_above(const Vector<float>& alpha, float reference) {
    uint64_t n = 0;
    for (float a : alpha) n += a > reference;
    return n;
}

// eq. 4.13-4.14: the scale that makes `target` texels of `raw` pass the alpha test at a_r,
// or the closest count the values allow (equal values pass or fail together; ties of the
// distance go to the larger count: opaque texels stay visible).
double coverage_scale(const Vector<float>& raw, uint64_t target, Vector<float>* sorted) {
    sorted->assign(raw.begin(), raw.end());
    std::sort(sorted->begin(), sorted->end(), std::greater<float>());
    const uint64_t n = sorted->size();
    const Vector<float>& s = *sorted;
    if (n == 0 || !(s[0] > 0.0f)) return 1.0;
    target = std::min(target, n);
    auto achievable = [&](uint64_t m) {
        if (m == 0) return true;
        if (m == n) return s[n - 1] > 0.0f;
        return s[m - 1] > s[m];
    };
    uint64_t m = target;
    for (uint64_t d = 0; d <= n; ++d) {
        if (target + d <= n && achievable(target + d)) {
            m = target + d;
            break;
        }
        if (d <= target && achievable(target - d)) {
            m = target - d;
            break;
        }
    }
    // a'_r of eq. 4.13: halfway between the last value that passes and the first that fails.
    double reference;
    if (m == 0)
        reference = 2.0 * s[0];
    else if (m == n)
        reference = 0.5 * s[n - 1];
    else
        reference = 0.5 * (static_cast<double>(s[m - 1]) + static_cast<double>(s[m]));
    return static_cast<double>(kCoverageReference) / reference; // eq. 4.14
}

template <class Filter>
void append_levels(Vector<SliceImage>* levels, uint32_t level_count, HostAllocator* host, Filter filter) {
    while (levels->size() < level_count) {
        const uint32_t k = static_cast<uint32_t>(levels->size());
        levels->emplace_back(host);
        const SliceImage& parent = (*levels)[k - 1];
        SliceImage& level = (*levels)[k];
        level.resize(level_size((*levels)[0].width, k), level_size((*levels)[0].height, k));
        for (uint32_t y = 0; y < level.height; ++y) {
            uint32_t y0, y1;
            footprint(y, level.height, parent.height, &y0, &y1);
            for (uint32_t x = 0; x < level.width; ++x) {
                uint32_t x0, x1;
                footprint(x, level.width, parent.width, &x0, &x1);
                filter(parent, x0, x1, y0, y1, &level, static_cast<size_t>(y) * level.width + x);
            }
        }
    }
}

} // namespace

uint32_t full_mip_count(uint32_t width, uint32_t height) {
    uint32_t size = std::max(width, height), count = 1;
    while (size > 1) {
        size >>= 1;
        ++count;
    }
    return count;
}

double alpha_coverage(const float* alpha, size_t count, float reference) {
    if (count == 0) return 0.0;
    uint64_t n = 0;
    for (size_t i = 0; i < count; ++i) n += alpha[i] > reference;
    return static_cast<double>(n) / static_cast<double>(count);
}

void build_coverage_mips(Vector<SliceImage>* levels, uint32_t level_count, HostAllocator* host, MipAlphaBase base) {
    SliceImage& level0 = (*levels)[0];
    for (float& a : level0.alpha) a = quantise_unorm8(a);
    const uint64_t base_count = count_above(level0.alpha, kCoverageReference);
    const uint64_t base_texels = level0.texels();

    auto filter = [base](const SliceImage& p, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1, SliceImage* out,
                         size_t texel) {
        double sum_a = 0, color[3] = {0, 0, 0}, normal[4] = {0, 0, 0, 0}, plain[3] = {0, 0, 0};
        double curve[3] = {0, 0, 0}, plain_curve[3] = {0, 0, 0};
        float max_a = 0;
        uint16_t threshold = 0;
        bool first = true;
        for (uint32_t y = y0; y < y1; ++y) {
            for (uint32_t x = x0; x < x1; ++x) {
                const size_t i = static_cast<size_t>(y) * p.width + x;
                const float a = p.alpha[i];
                sum_a += a;
                for (int c = 0; c < 3; ++c) color[c] += a * static_cast<double>(p.color[i * 3 + c]);
                for (int c = 0; c < 4; ++c) normal[c] += a * static_cast<double>(p.normal[i * 4 + c]);
                for (int c = 0; c < 3; ++c) plain[c] += p.normal[i * 4 + c];
                for (int c = 0; c < 3; ++c) curve[c] += a * static_cast<double>(p.coverage[i * 3 + c]);
                for (int c = 0; c < 3; ++c) plain_curve[c] += p.coverage[i * 3 + c];
                const uint16_t t = p.threshold[i];
                if (first || a > max_a || (a == max_a && t < threshold)) {
                    max_a = a;
                    threshold = t;
                    first = false;
                }
            }
        }
        const double s_a = sum_a > 0.0 ? sum_a : 1.0; // eq. 4.9
        float* oc = &out->color[texel * 3];
        float* on = &out->normal[texel * 4];
        for (int c = 0; c < 3; ++c) oc[c] = static_cast<float>(color[c] / s_a); // eq. 4.10
        // Mean normals stay unnormalised, so their length keeps the spread (slice_rasterizer.cpp).
        const double footprint_texels = static_cast<double>(x1 - x0) * (y1 - y0);
        for (int c = 0; c < 3; ++c)
            on[c] = static_cast<float>(sum_a > 0.0 ? normal[c] / sum_a : plain[c] / footprint_texels);
        on[3] = static_cast<float>(normal[3] / s_a);
        // The coverage curve is a share of the coverage: alpha-weighted like the colour.
        for (int c = 0; c < 3; ++c) {
            out->coverage[texel * 3 + c] =
                static_cast<float>(sum_a > 0.0 ? curve[c] / sum_a : plain_curve[c] / footprint_texels);
        }
        // The value the coverage scale applies to: eq. 4.12 (max) or the footprint's mean.
        out->alpha[texel] = base == MipAlphaBase::kMax ? max_a : static_cast<float>(sum_a / ((x1 - x0) * (y1 - y0)));
        out->threshold[texel] = threshold;
    };

    Vector<float> sorted{StlAllocator<float>(host)};
    while (levels->size() < level_count) {
        const size_t k = levels->size();
        append_levels(levels, static_cast<uint32_t>(k + 1), host, filter);
        SliceImage& level = (*levels)[k];
        const uint64_t texels = level.texels();
        // round(base coverage * texels), in integers.
        const uint64_t target = (2 * base_count * texels + base_texels) / (2 * base_texels);
        const double scale = base == MipAlphaBase::kMeanOpacity ? 1.0 : coverage_scale(level.alpha, target, &sorted);
        for (size_t i = 0; i < texels; ++i) {
            float& a = level.alpha[i];
            a = quantise_unorm8(static_cast<float>(std::min(1.0, scale * static_cast<double>(a)))); // eq. 4.15
            if (a == 0.0f) level.threshold[i] = 0; // a trace that rounds to nothing: no blade
        }
    }
}

void set_alpha_test_scales(SliceSet* set, HostAllocator* host) {
    for (float& s : set->alpha_test_scale) s = 1.0f;
    if (set->layers == 0 || set->color.empty()) return;
    const uint32_t layer = set->slices_per_axis ? 2 * set->slices_per_axis : 0;
    Vector<float> alpha{StlAllocator<float>(host)}, sorted{StlAllocator<float>(host)};
    const auto read = [&](uint32_t level) {
        const uint64_t texels = uint64_t(set->level_width(level)) * set->level_height(level);
        const uint8_t* rgba = &set->color[set->offset(layer, level) * 4];
        alpha.resize(texels);
        for (uint64_t i = 0; i < texels; ++i) alpha[i] = static_cast<float>(rgba[i * 4 + 3]) / 255.0f;
        return texels;
    };
    const uint64_t base_texels = read(0);
    const uint64_t base_count = count_above(alpha, kCoverageReference);
    const uint32_t levels = std::min(set->mip_levels, SliceSet::kAlphaTestLevels);
    for (uint32_t k = 1; k < levels; ++k) {
        const uint64_t texels = read(k);
        const uint64_t target = (2 * base_count * texels + base_texels) / (2 * base_texels);
        set->alpha_test_scale[k] = static_cast<float>(coverage_scale(alpha, target, &sorted));
    }
}

void build_box_mips(Vector<SliceImage>* levels, uint32_t level_count, HostAllocator* host) {
    auto filter = [](const SliceImage& p, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1, SliceImage* out,
                     size_t texel) {
        double sum[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (uint32_t y = y0; y < y1; ++y) {
            for (uint32_t x = x0; x < x1; ++x) {
                const size_t i = static_cast<size_t>(y) * p.width + x;
                sum[0] += p.alpha[i];
                for (int c = 0; c < 3; ++c) sum[1 + c] += p.color[i * 3 + c];
                for (int c = 0; c < 4; ++c) sum[4 + c] += p.normal[i * 4 + c];
            }
        }
        const double inv = 1.0 / (static_cast<double>(x1 - x0) * (y1 - y0));
        out->alpha[texel] = static_cast<float>(sum[0] * inv);                                         // eq. 4.8
        for (int c = 0; c < 3; ++c) out->color[texel * 3 + c] = static_cast<float>(sum[1 + c] * inv); // eq. 4.7
        for (int c = 0; c < 4; ++c) out->normal[texel * 4 + c] = static_cast<float>(sum[4 + c] * inv);
        out->threshold[texel] = p.threshold[static_cast<size_t>(y0) * p.width + x0];
        for (int c = 0; c < 3; ++c)
            out->coverage[texel * 3 + c] = p.coverage[(static_cast<size_t>(y0) * p.width + x0) * 3 + c];
    };
    append_levels(levels, level_count, host, filter);
}

void bleed_colours(Vector<SliceImage>* levels) {
    for (size_t k = levels->size(); k-- > 1;) {
        const SliceImage& next = (*levels)[k];
        SliceImage& level = (*levels)[k - 1];
        for (uint32_t y = 0; y < level.height; ++y) {
            // Nearest texel of level k at the centre of texel y: floor((y + 0.5) * h' / h).
            const uint32_t ny = static_cast<uint32_t>((2ull * y + 1) * next.height / (2ull * level.height));
            for (uint32_t x = 0; x < level.width; ++x) {
                const uint32_t nx = static_cast<uint32_t>((2ull * x + 1) * next.width / (2ull * level.width));
                const size_t i = static_cast<size_t>(y) * level.width + x;
                const size_t j = static_cast<size_t>(ny) * next.width + nx;
                // Only empty texels take the coarser level's values. A partly covered texel
                // keeps its own: the tiers blend it with its alpha, so its colour is that of
                // the blades it covers; eq. 4.16's A C + (1 - A) C' (made for an alpha test,
                // which shows a passing texel opaque) mixed in the coarser footprint's mean,
                // whose denser rows lower down are darker, once per level: the volume came out
                // darker the more slices (thinner, sparser slabs) and the coarser the mip.
                if (level.alpha[i] > 0.0f) continue;
                for (int c = 0; c < 3; ++c) level.color[i * 3 + c] = next.color[j * 3 + c];
                for (int c = 0; c < 4; ++c) level.normal[i * 4 + c] = next.normal[j * 4 + c];
            }
        }
    }
}

} // namespace grass
