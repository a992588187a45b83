// Baked slices (lemme2012 4.2, boulanger2006 3.3-3.4): determinism, layout, coverage across
// mips, colour bleeding, tiling, thresholds, and the disk cache.
#include "core_fixture.hpp"

#include "bake/bake_cache.hpp"
#include "bake/baked_slices.hpp"
#include "bake/slice_baker.hpp"
#include "bake/slice_mips.hpp"
#include "bake/slice_set_hash.hpp"
#include "context/context.hpp"
#include "patch/random.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace {

using grass::CacheMiss;
using grass::SliceSet;

class SliceBakingTest : public CoreTest {
protected:
    const grass::PatchData& default_patch() {
        if (!patch_.index) patch_ = make_patch();
        return ctx->patches.get(patch_.index - 1)->data;
    }
    grass::HostAllocator* host() { return &ctx->host; }

    // Bakes and prints the time taken.
    void bake(uint32_t n, SliceSet* out, uint32_t w = 0, uint32_t h = 0) {
        const grass::PatchData& p = default_patch();
        const auto start = std::chrono::steady_clock::now();
        grass::bake_slices(p, n, w, h, host(), out);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::printf("[ baking   ] N = %u, %u x %u, %u layers, %u mips: %.1f ms\n", n, out->width, out->height,
                    out->layers, out->mip_levels, ms);
    }

    std::set<uint16_t> patch_thresholds() {
        std::set<uint16_t> s;
        for (float t : default_patch().thresholds) {
            s.insert(static_cast<uint16_t>(std::min(65535L, std::max(1L, std::lround(double(t) * 65535.0)))));
        }
        return s;
    }

    grass_patch_id patch_{};
};

uint8_t alpha_at(const SliceSet& s, uint32_t layer, uint32_t level, uint32_t x, uint32_t y) {
    return s.color[(s.offset(layer, level) + uint64_t(y) * s.level_width(level) + x) * 4 + 3];
}

// eq. 4.11 on the stored bytes: a > 0.5.
double stored_coverage(const SliceSet& s, uint32_t layer, uint32_t level) {
    const uint64_t n = uint64_t(s.level_width(level)) * s.level_height(level);
    uint64_t above = 0;
    for (uint64_t i = 0; i < n; ++i) above += s.color[(s.offset(layer, level) + i) * 4 + 3] > 127;
    return double(above) / double(n);
}

std::vector<uint8_t> read_file(const std::string& path) {
    std::vector<uint8_t> bytes;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return bytes;
    uint8_t chunk[65536];
    size_t n;
    while ((n = std::fread(chunk, 1, sizeof(chunk), f)) > 0) bytes.insert(bytes.end(), chunk, chunk + n);
    std::fclose(f);
    return bytes;
}

void write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    if (!bytes.empty()) {
        ASSERT_EQ(std::fwrite(bytes.data(), 1, bytes.size(), f), bytes.size());
    }
    std::fclose(f);
}

bool same_bytes(const SliceSet& a, const SliceSet& b) {
    return a.slices_per_axis == b.slices_per_axis && a.layers == b.layers && a.width == b.width &&
           a.height == b.height && a.mip_levels == b.mip_levels && a.height_patch_units == b.height_patch_units &&
           a.content_hash == b.content_hash && a.color == b.color && a.normal == b.normal && a.threshold == b.threshold;
}

// Pins the baked slices of the default patch. If this fails, the baked bytes changed (the
// generator, the rasteriser, the mip filters or the encoding): update the values only for
// an intended change, say so, and bump kBakeFormatVersion so that disk caches rebake.
TEST_F(SliceBakingTest, BakingIsDeterministicAndPinned) {
    SliceSet a(host()), b(host()), h1(host()), h2(host());
    bake(8, &a);
    bake(8, &b);
    EXPECT_TRUE(same_bytes(a, b));
    EXPECT_EQ(a.content_hash, grass::slice_content_hash(a));
    bake(0, &h1);
    bake(0, &h2);
    EXPECT_TRUE(same_bytes(h1, h2));
    std::printf("[ hashes   ] N = 8: 0x%016llx, horizontal: 0x%016llx\n", (unsigned long long)a.content_hash,
                (unsigned long long)h1.content_hash);
    EXPECT_EQ(a.content_hash, 0xd08d42cc514f4546ull) << std::hex << "actual 0x" << a.content_hash;
    EXPECT_EQ(h1.content_hash, 0x02e7a0737eb9ea0eull) << std::hex << "actual 0x" << h1.content_hash;
}

TEST_F(SliceBakingTest, LayoutFollowsTheContract) {
    SliceSet v(host()), h(host()), small(host());
    bake(8, &v);
    EXPECT_EQ(v.slices_per_axis, 8u);
    EXPECT_EQ(v.layers, 17u); // 2N vertical + the horizontal slice
    EXPECT_EQ(v.width, 256u);
    EXPECT_EQ(v.height, 64u);
    EXPECT_EQ(v.mip_levels, 9u); // 256 x 64 down to 1 x 1
    EXPECT_EQ(v.height_patch_units, default_patch().bounds_max[1]);
    uint64_t layer_texels = 0;
    for (uint32_t k = 0; k < v.mip_levels; ++k) {
        EXPECT_EQ(v.offset(0, k), layer_texels);
        layer_texels += uint64_t(std::max(1u, 256u >> k)) * std::max(1u, 64u >> k);
    }
    EXPECT_EQ(layer_texels, 21847u); // 16384+4096+1024+256+64+16+4+2+1
    EXPECT_EQ(v.offset(3, 2), 3 * layer_texels + 256 * 64 + 128 * 32);
    EXPECT_EQ(v.color.size(), 17 * layer_texels * 4);
    EXPECT_EQ(v.normal.size(), 17 * layer_texels * 4);
    EXPECT_EQ(v.threshold.size(), 17 * layer_texels * 4); // threshold + coverage curve
    EXPECT_EQ(v.level_width(8), 1u);
    EXPECT_EQ(v.level_height(7), 1u);

    bake(0, &h);
    EXPECT_EQ(h.layers, 3u); // from above; the grazing view's, normals along x and along z
    EXPECT_EQ(h.width, 128u);
    EXPECT_EQ(h.height, 128u);
    EXPECT_EQ(h.mip_levels, 8u);
    EXPECT_EQ(h.threshold.size(), h.offset(3, 0) * 4);
    EXPECT_EQ(h.offset(1, 0), 21845u);
    // The three layers share their coverage and thresholds; layer 0 holds the colour seen
    // from above, layers 1 and 2 the grazing view's (the same in both) and its normals per
    // heading.
    const size_t layer = size_t(h.offset(1, 0)) * 4;
    for (uint32_t k = 1; k < 3; ++k) {
        EXPECT_TRUE(std::equal(h.threshold.begin(), h.threshold.begin() + layer, h.threshold.begin() + k * layer)) << k;
        EXPECT_FALSE(std::equal(h.color.begin(), h.color.begin() + layer, h.color.begin() + k * layer)) << k;
        EXPECT_FALSE(std::equal(h.normal.begin(), h.normal.begin() + layer, h.normal.begin() + k * layer)) << k;
        for (size_t i = 3; i < layer; i += 4) ASSERT_EQ(h.color[i], h.color[k * layer + i]) << "alpha, layer " << k;
    }
    EXPECT_TRUE(std::equal(h.color.begin() + layer, h.color.begin() + 2 * layer, h.color.begin() + 2 * layer));
    EXPECT_FALSE(std::equal(h.normal.begin() + layer, h.normal.begin() + 2 * layer, h.normal.begin() + 2 * layer));

    bake(1, &small, 32, 16);
    EXPECT_EQ(small.layers, 3u);
    EXPECT_EQ(small.mip_levels, 6u);
    EXPECT_EQ(small.threshold.size(), 4u * 3u * (512 + 128 + 32 + 8 + 2 + 1));
}

// lemme eq. 4.11, 4.13-4.15 against eq. 4.7-4.8: the coverage at a_r = 0.5 of every level
// down to 8 texels on the short side (256 x 64 .. 32 x 8), relative to level 0's, per layer.
// N = 8 slabs are dense near the ground, where a box filter keeps "a > 0.5"; the thinner
// N = 16 slabs are sparse, and there the box filter loses the blades. For comparison the
// test also prints lemme's eq. 4.12 as written (max, then the same rescale).
TEST_F(SliceBakingTest, CoverageSurvivesTheMipChainWhereTheBoxFilterLosesIt) {
    const uint32_t levels = 4;
    for (uint32_t n : {8u, 16u}) {
        SliceSet v(host());
        bake(n, &v);
        double worst_ours = 0, worst_box = 0, worst_max = 0;
        double ours_sum[levels] = {}, box_sum[levels] = {}, max_sum[levels] = {};
        const uint32_t vertical = 2 * n; // the horizontal slice keeps its mean opacity (below)
        for (uint32_t layer = 0; layer < vertical; ++layer) {
            const double base = stored_coverage(v, layer, 0);
            ASSERT_GT(base, 0.05) << "layer " << layer;
            grass::Vector<grass::SliceImage> box{grass::StlAllocator<grass::SliceImage>(host())};
            box.emplace_back(host());
            grass::rasterize_slice_layer(default_patch(), n, layer, 0, 0, host(), &box[0]);
            for (float& a : box[0].alpha) a = std::round(a * 255.0f) / 255.0f; // as stored
            grass::Vector<grass::SliceImage> max = box;
            grass::build_box_mips(&box, levels, host());
            grass::build_coverage_mips(&max, levels, host(), grass::MipAlphaBase::kMax);
            ASSERT_EQ(grass::alpha_coverage(box[0].alpha.data(), box[0].texels(), 0.5f), base);
            for (uint32_t k = 0; k < levels; ++k) {
                const double ours = stored_coverage(v, layer, k) / base;
                const double boxed = grass::alpha_coverage(box[k].alpha.data(), box[k].texels(), 0.5f) / base;
                const double maxed = grass::alpha_coverage(max[k].alpha.data(), max[k].texels(), 0.5f) / base;
                ours_sum[k] += ours;
                box_sum[k] += boxed;
                max_sum[k] += maxed;
                worst_ours = std::max(worst_ours, std::fabs(ours - 1.0));
                worst_box = std::max(worst_box, 1.0 - boxed);
                worst_max = std::max(worst_max, std::fabs(maxed - 1.0));
            }
        }
        std::printf("[ coverage ] N = %2u, coverage / level 0's, mean over layers:\n", n);
        for (uint32_t k = 0; k < levels; ++k) {
            std::printf("[ coverage ]   %3u x %2u: coverage-preserving %.3f, box %.3f, eq. 4.12 max %.3f\n",
                        v.level_width(k), v.level_height(k), ours_sum[k] / vertical, box_sum[k] / vertical,
                        max_sum[k] / vertical);
        }
        std::printf("[ coverage ]   worst layer: coverage-preserving %.2f%% off, box loses %.1f%%, eq. 4.12 max "
                    "%.1f%% off\n",
                    100 * worst_ours, 100 * worst_box, 100 * worst_max);
        // Relative to level 0's coverage.
        EXPECT_LE(worst_ours, 0.05) << "N = " << n;
        if (n == 16) {
            EXPECT_GE(worst_box, 0.45) << "the box filter loses the sparse blades";
            EXPECT_LT(box_sum[levels - 1] / vertical, 0.8);
        }
    }
}

// The horizontal slice is met once by a ray and drawn as an opacity (the share of a pixel's
// samples, sample_coverage.glsl), so its mips keep the mean alpha of level 0: seen from above
// through a coarse level, the coverage-preserving rescale (which keeps the share of texels
// above a_r instead) drew it over 0.57-0.66 of the view where the blades cover 0.82
// (docs/records/tier-sweep.md). The test prints what that rescale makes of the mean.
double mean_alpha(const uint8_t* rgba, uint64_t texels) {
    double sum = 0.0;
    for (uint64_t i = 0; i < texels; ++i) sum += rgba[i * 4 + 3] / 255.0;
    return sum / double(texels);
}

TEST_F(SliceBakingTest, TheHorizontalSliceKeepsItsMeanOpacityThroughTheMips) {
    for (uint32_t n : {8u, 0u}) {
        SliceSet v(host());
        bake(n, &v);
        const uint32_t layer = n ? 2 * n : 0;
        grass::Vector<grass::SliceImage> rescaled{grass::StlAllocator<grass::SliceImage>(host())};
        rescaled.emplace_back(host());
        grass::rasterize_slice_layer(default_patch(), n, layer, 0, 0, host(), &rescaled[0]);
        grass::build_coverage_mips(&rescaled, v.mip_levels, host(), grass::MipAlphaBase::kMean);
        const double base = mean_alpha(&v.color[v.offset(layer, 0) * 4], uint64_t(v.width) * v.height);
        ASSERT_GT(base, 0.3) << "N = " << n;
        double worst = 0.0, worst_rescaled = 0.0;
        for (uint32_t k = 0; k + 1 < v.mip_levels; ++k) {
            const uint64_t texels = uint64_t(v.level_width(k)) * v.level_height(k);
            const double ours = mean_alpha(&v.color[v.offset(layer, k) * 4], texels) / base;
            double sum = 0.0;
            for (float a : rescaled[k].alpha) sum += a;
            const double other = sum / double(texels) / base;
            std::printf("[ opacity  ] N = %u, %3u x %3u: mean alpha / level 0's %.3f (rescaled to the coverage at "
                        "a_r: %.3f)\n",
                        n, v.level_width(k), v.level_height(k), ours, other);
            worst = std::max(worst, std::fabs(ours - 1.0));
            worst_rescaled = std::max(worst_rescaled, std::fabs(other - 1.0));
        }
        EXPECT_LE(worst, 0.01) << "N = " << n << ": the horizontal slice's mean opacity through the mips";
        EXPECT_GE(worst_rescaled, 0.1) << "N = " << n << ": the rescale this test guards against moved it so little";
    }
}

// eq. 4.16: transparent texels take the colour of the nearby blades, not black.
TEST_F(SliceBakingTest, ColourBleedsIntoTransparentTexels) {
    SliceSet v(host());
    bake(8, &v);
    double dist_sum = 0, black_sum = 0;
    uint64_t samples = 0, black = 0;
    for (uint32_t layer = 0; layer < v.layers; ++layer) {
        const uint64_t base = v.offset(layer, 0);
        for (uint32_t y = 1; y + 1 < v.height; ++y) {
            for (uint32_t x = 1; x + 1 < v.width; ++x) {
                const uint8_t* c = &v.color[(base + uint64_t(y) * v.width + x) * 4];
                if (c[3] != 0) continue;
                black += c[0] == 0 && c[1] == 0 && c[2] == 0;
                // Mean colour of the opaque 8-neighbours.
                double mean[3] = {0, 0, 0};
                int opaque = 0;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const uint8_t* n = &v.color[(base + uint64_t(y + dy) * v.width + (x + dx)) * 4];
                        if (n[3] < 255) continue;
                        for (int ch = 0; ch < 3; ++ch) mean[ch] += n[ch];
                        ++opaque;
                    }
                }
                if (!opaque) continue;
                double d = 0, db = 0;
                for (int ch = 0; ch < 3; ++ch) {
                    mean[ch] /= opaque;
                    d += (c[ch] - mean[ch]) * (c[ch] - mean[ch]);
                    db += mean[ch] * mean[ch];
                }
                dist_sum += std::sqrt(d);
                black_sum += std::sqrt(db);
                ++samples;
            }
        }
    }
    ASSERT_GT(samples, 1000u);
    std::printf("[ bleeding ] %llu transparent texels next to opaque ones: mean sRGB distance %.1f to their "
                "neighbours, %.1f from black; %llu black transparent texels\n",
                (unsigned long long)samples, dist_sum / samples, black_sum / samples, (unsigned long long)black);
    EXPECT_EQ(black, 0u);
    EXPECT_LT(dist_sum / samples, 0.25 * black_sum / samples);
}

// boulanger2006 3.3: with the 8 neighbours drawn, blades crossing the border carry on, so the
// border columns are as covered as the others.
TEST_F(SliceBakingTest, SlicesTileAcrossTheBorder) {
    SliceSet v(host()), h(host());
    bake(8, &v);
    double first = 0, last = 0, all = 0;
    for (uint32_t layer = 0; layer < v.layers; ++layer) {
        for (uint32_t y = 0; y < v.height; ++y) {
            for (uint32_t x = 0; x < v.width; ++x) {
                const double a = alpha_at(v, layer, 0, x, y) / 255.0;
                all += a;
                if (x == 0) first += a;
                if (x == v.width - 1) last += a;
            }
        }
    }
    const double mean_column = all / v.width;
    std::printf("[ tiling   ] vertical: column 0 %.1f, column %u %.1f, mean column %.1f (alpha sums)\n", first,
                v.width - 1, last, mean_column);
    EXPECT_GT(first, 0.6 * mean_column);
    EXPECT_GT(last, 0.6 * mean_column);
    EXPECT_LT(std::fabs(first - last), 0.35 * std::max(first, last));

    bake(0, &h);
    double edges[4] = {0, 0, 0, 0}, total = 0;
    for (uint32_t y = 0; y < h.height; ++y) {
        for (uint32_t x = 0; x < h.width; ++x) {
            const double a = alpha_at(h, 0, 0, x, y) / 255.0;
            total += a;
            if (x == 0) edges[0] += a;
            if (x == h.width - 1) edges[1] += a;
            if (y == 0) edges[2] += a;
            if (y == h.height - 1) edges[3] += a;
        }
    }
    std::printf("[ tiling   ] horizontal: edges %.1f %.1f %.1f %.1f, mean line %.1f\n", edges[0], edges[1], edges[2],
                edges[3], total / h.width);
    for (double e : edges) EXPECT_GT(e, 0.6 * total / h.width);
}

// boulanger2006 3.4: each covered texel carries the threshold of a blade of the patch.
TEST_F(SliceBakingTest, TexelsCarryTheThresholdOfTheirBlade) {
    SliceSet v(host());
    bake(8, &v);
    const std::set<uint16_t> thresholds = patch_thresholds();
    std::set<uint16_t> seen;
    for (uint32_t layer = 0; layer < v.layers; ++layer) {
        for (uint32_t k = 0; k < v.mip_levels; ++k) {
            const uint64_t base = v.offset(layer, k);
            const uint64_t n = uint64_t(v.level_width(k)) * v.level_height(k);
            for (uint64_t i = 0; i < n; ++i) {
                const uint16_t t = v.threshold[(base + i) * 4];
                const uint8_t a = v.color[(base + i) * 4 + 3];
                if (t) {
                    ASSERT_TRUE(thresholds.count(t)) << "layer " << layer << " level " << k << " texel " << i;
                    seen.insert(t);
                }
                ASSERT_EQ(t == 0, a == 0) << "layer " << layer << " level " << k << " texel " << i;
            }
        }
    }
    std::printf("[ thresh   ] %zu of %zu blade thresholds appear in the vertical slices\n", seen.size(),
                thresholds.size());
    EXPECT_GT(seen.size(), thresholds.size() * 3 / 4);
}

TEST_F(SliceBakingTest, HorizontalSliceCoversThePatch) {
    SliceSet h(host());
    bake(0, &h);
    const std::set<uint16_t> thresholds = patch_thresholds();
    std::set<uint16_t> seen;
    double alpha = 0, height = 0;
    const uint64_t n = uint64_t(h.width) * h.height;
    for (uint64_t i = 0; i < n; ++i) {
        const uint16_t t = h.threshold[i * 4];
        const uint8_t a = h.color[i * 4 + 3];
        alpha += a / 255.0;
        ASSERT_EQ(t == 0, a == 0);
        if (t) {
            ASSERT_TRUE(thresholds.count(t));
            seen.insert(t);
            height += h.normal[i * 4 + 3] / 255.0;
            EXPECT_GT(h.normal[i * 4 + 1], 128) << "normals face up";
        }
    }
    const double coverage = alpha / n;
    std::printf("[ horizon  ] mean alpha %.3f, coverage at 0.5 %.3f, %zu of %zu thresholds, mean height %.2f\n",
                coverage, stored_coverage(h, 0, 0), seen.size(), thresholds.size(), height / n);
    EXPECT_GT(coverage, 0.3);
    EXPECT_LE(coverage, 1.0);
    EXPECT_GT(seen.size(), thresholds.size() / 2);
}

TEST_F(SliceBakingTest, BakeKeyFollowsTheDescAndParameters) {
    const grass_patch_desc d = grass_default_patch_desc();
    const uint64_t k = grass::bake_key(d, 8, 0, 0);
    EXPECT_EQ(k, grass::bake_key(d, 8, 256, 64)) << "0 sizes are the defaults";
    EXPECT_NE(k, grass::bake_key(d, 4, 0, 0));
    EXPECT_NE(k, grass::bake_key(d, 8, 128, 64));
    EXPECT_NE(k, grass::bake_key(d, 0, 0, 0));
    grass_patch_desc other = d;
    other.seed = 2;
    EXPECT_NE(k, grass::bake_key(other, 8, 0, 0));
    other = d;
    other.tip_color[1] = 0.46f;
    EXPECT_NE(k, grass::bake_key(other, 8, 0, 0));
    other = d;
    other.next = &d; // not part of the key
    EXPECT_EQ(k, grass::bake_key(other, 8, 0, 0));
}

TEST_F(SliceBakingTest, CacheRoundTripsAndRejectsDamagedFiles) {
    SliceSet v(host());
    bake(2, &v, 64, 32);
    const std::string dir = ::testing::TempDir();
    const uint64_t key = grass::bake_key(grass_default_patch_desc(), 2, 64, 32);
    ASSERT_TRUE(grass::store_baked(dir.c_str(), key, v));
    char name[64];
    std::snprintf(name, sizeof(name), "grass-slices-%016llx.bin", (unsigned long long)key);
    const std::string path = dir + (dir.empty() || dir.back() == '/' ? "" : "/") + name;
    const std::vector<uint8_t> good = read_file(path);
    ASSERT_EQ(good.size(), 72 + v.threshold.size() / 4 * 16);

    SliceSet loaded(host());
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(grass::load_baked(dir.c_str(), key, host(), &loaded), CacheMiss::none);
    std::printf("[ cache    ] load of %zu bytes: %.2f ms\n", good.size(),
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    EXPECT_TRUE(same_bytes(v, loaded));

    // Each damage is rejected with its own reason (the warning a context logs names it).
    auto expect_rejected = [&](const std::vector<uint8_t>& bytes, const char* what, CacheMiss why) {
        write_file(path, bytes);
        SliceSet s(host());
        EXPECT_EQ(grass::load_baked(dir.c_str(), key, host(), &s), why) << what;
        EXPECT_TRUE(s.color.empty() && s.normal.empty() && s.threshold.empty()) << what;
    };
    std::vector<uint8_t> bad = good;
    bad[72 + good.size() / 2] ^= 0x10;
    expect_rejected(bad, "a corrupted data byte", CacheMiss::content_hash);
    bad = good;
    bad[good.size() - 1] ^= 0x01;
    expect_rejected(bad, "a corrupted threshold byte", CacheMiss::content_hash);
    for (size_t cut : {size_t(0), size_t(10), size_t(63), size_t(64), size_t(72), good.size() / 2, good.size() - 1}) {
        expect_rejected(std::vector<uint8_t>(good.begin(), good.begin() + long(cut)), "a truncated file",
                        CacheMiss::truncated);
    }
    bad = good;
    bad.push_back(0);
    expect_rejected(bad, "trailing bytes", CacheMiss::truncated);
    for (size_t field : {size_t(0), size_t(8), size_t(16), size_t(24), size_t(28), size_t(32), size_t(36), size_t(40),
                         size_t(44), size_t(48), size_t(56), size_t(64)}) {
        bad = good;
        bad[field + 1] ^= 0x40; // magic, version, key, sizes, height, texel count, hashes
        expect_rejected(bad, "a corrupted header field", CacheMiss::corrupt); // the header hash no longer matches
    }
    // Huge sizes in an otherwise consistent header (header hash recomputed) must not be
    // trusted: the file is too short for them, and that is checked before allocating.
    bad = good;
    auto put = [&](size_t at, uint64_t value, int bytes) {
        for (int k = 0; k < bytes; ++k) bad[at + k] = uint8_t(value >> (8 * k));
    };
    put(32, 16384, 4);
    put(36, 16384, 4);
    put(40, 15, 4);
    put(48, uint64_t(v.layers) * grass::slice_layer_texels(16384, 16384, 15), 8);
    put(64, grass::fnv1a64(bad.data(), 64, grass::kFnvOffset), 8);
    expect_rejected(bad, "huge sizes", CacheMiss::truncated);
    // Another format version (an older grass), its header hash consistent.
    bad = good;
    put(8, grass::kBakeFormatVersion - 1, 4);
    put(64, grass::fnv1a64(bad.data(), 64, grass::kFnvOffset), 8);
    expect_rejected(bad, "another format version", CacheMiss::other_version);

    // The right file under the wrong key: the key in the header does not match.
    write_file(path, good);
    char other[64];
    std::snprintf(other, sizeof(other), "grass-slices-%016llx.bin", (unsigned long long)(key + 1));
    const std::string other_path = dir + (dir.empty() || dir.back() == '/' ? "" : "/") + other;
    write_file(other_path, good);
    SliceSet s(host());
    EXPECT_EQ(grass::load_baked(dir.c_str(), key + 1, host(), &s), CacheMiss::other_patch) << "a wrong key";
    EXPECT_EQ(grass::load_baked(dir.c_str(), key + 2, host(), &s), CacheMiss::missing) << "no file";
    EXPECT_EQ(grass::load_baked((dir + "/no-such-directory").c_str(), key, host(), &s), CacheMiss::missing);
    EXPECT_FALSE(grass::store_baked((dir + "/no-such-directory").c_str(), key, v));
    EXPECT_EQ(grass::load_baked(dir.c_str(), key, host(), &s), CacheMiss::none) << "the good file still loads";
    EXPECT_TRUE(same_bytes(v, s));
    std::remove(path.c_str());
    std::remove(other_path.c_str());
}

} // namespace

namespace {

// The coverage curve (baked_slices.hpp): in every covered texel the shares of its coverage
// whose blades' thresholds are at most 1/4, 1/2, 3/4 never decrease; over the vertical
// slices of a patch with uniform thresholds they average about 1/4, 1/2 and 3/4 of the
// coverage (each blade's threshold is equally likely anywhere in (0, 1]).
TEST_F(SliceBakingTest, TheCoverageCurveGrowsWithTheDensity) {
    SliceSet v(host());
    bake(8, &v);
    double weighted[3] = {0, 0, 0}, alpha = 0;
    const uint64_t n = uint64_t(v.width) * v.height; // level 0 of each layer
    for (uint32_t layer = 0; layer + 1 < v.layers; ++layer) {
        const uint64_t base = v.offset(layer, 0);
        for (uint64_t i = 0; i < n; ++i) {
            const uint16_t* t = &v.threshold[(base + i) * 4];
            const double a = v.color[(base + i) * 4 + 3] / 255.0;
            if (t[0] == 0) continue;
            ASSERT_LE(t[1], t[2]);
            ASSERT_LE(t[2], t[3]);
            for (int c = 0; c < 3; ++c) weighted[c] += a * t[1 + c] / 65535.0;
            alpha += a;
        }
    }
    std::printf("[ curve    ] coverage with thresholds <= 1/4, 1/2, 3/4: %.3f %.3f %.3f of the texels' coverage\n",
                weighted[0] / alpha, weighted[1] / alpha, weighted[2] / alpha);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(weighted[c] / alpha, 0.25 * (c + 1), 0.1) << "point " << c;
}

} // namespace
