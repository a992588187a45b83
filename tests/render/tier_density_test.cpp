// Thin grass in every tier: at a low density the volume and image tiers cover about as much
// as the blades they replace. A slice texel holds several blades; drawn whole whenever the
// threshold stored for it passed, texels left a lawn at density 0.1 covered more than twice
// as much as the blades; the coverage curve baked with the slices (baked_slices.hpp) draws
// the share of each texel's blades that the density keeps. The test prints what it measures.
// Measured (GL; coverage of the field's footprint in linear RGB, 4x MSAA, 5 m up looking
// 9 m ahead; Vulkan within 0.01):
//   density 0.1: blades 0.316, volume 8 0.323, volume 2 0.270, volume 1 0.262, image 0.254
//   density 0.3: blades 0.605, volume 8 0.628, volume 2 0.575, volume 1 0.564, image 0.582
// Before the horizontal slice's mips kept its mean opacity (slice_mips.hpp), volume 2 and 1
// read 0.287 and 0.316 at 0.1: each tier's coverage is measured against its own colour at
// density 1, and there the slices let the sky through (volume 1 covered less of the field
// than the blades), which made every lower density read as more covered.
// With the coverage curve interpolated linearly from (0, 0) instead of geometrically
// (tier_transitions.glsl), density 0.1 gave volume 8 0.263, volume 2 0.231, volume 1 0.235:
// a texel of a thick slab holds many blades and is mostly covered at low density already.
// Before the volume weighted its two slice families (volume.frag) it met every blade twice
// and covered about 1 - (1 - c)^2 (0.77 where the blades covered 0.51, in sRGB distances).
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace grass_test {
namespace {

class TierDensityTest : public RenderTest {
protected:
    grass_host::Image render_with(grass_tier_kind kind, uint32_t slices, float density) {
        grass_field_desc d = solo_tier_field(48, kind, slices, 1); // 12 m x 12 m
        d.density = density;
        const grass_field_id f = make_field(d);
        const double eye[3] = {6.0, 5.0, -3.0}, target[3] = {6.0, 0.0, 6.0};
        const auto image = render(view(eye, target, 50.0f));
        save(image, std::to_string(int(kind)) + "_" + std::to_string(slices) + "_" + std::to_string(density));
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        return image;
    }
};

// The largest difference of each representation's coverage to the blades'.
constexpr double kLimit[5] = {0.0, 0.06, 0.06, 0.07, 0.07};

TEST_P(TierDensityTest, ThinGrassCoversAboutAsMuchInEveryTier) {
    grass_host::TargetDesc t;
    t.width = 160;
    t.height = 96;
    t.samples = 4; // translucent texels become coverage, as on a host's multisampled target
    start(t);
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    // The blades, the volume tier with Lemme's slice counts (8, 2, 1 per axis: the thicker
    // the slab, the more blades a texel holds) and the image tier.
    constexpr int kCount = 5;
    const grass_tier_kind kinds[kCount] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_VOLUME, GRASS_TIER_VOLUME,
                                           GRASS_TIER_IMAGE};
    const uint32_t slices[kCount] = {0, 8, 2, 1, 0};
    const char* names[kCount] = {"geometry", "volume 8", "volume 2", "volume 1", "image"};
    // The field's footprint (the pixels the full-density blades cover) and each tier's own
    // colour of full grass there (its mean over the footprint at density 1).
    const grass_host::Image full = render_with(GRASS_TIER_GEOMETRY, 0, 1.0f);
    std::vector<bool> footprint(size_t(full.width) * full.height);
    uint64_t area = 0;
    for (uint32_t y = 0; y < full.height; ++y) {
        for (uint32_t x = 0; x < full.width; ++x) {
            const bool g = is_grass(full.pixel(x, y), sky, 40);
            footprint[size_t(y) * full.width + x] = g;
            area += g;
        }
    }
    ASSERT_GT(area, uint64_t(full.width) * full.height / 3);
    // Distances in linear RGB: the resolve mixes a pixel's samples there, so a pixel's
    // covered share is linear in them (in sRGB bytes a quarter-covered pixel reads as ~0.15).
    auto linear = [](double byte) {
        const double c = byte / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    auto distance = [&](const uint8_t* p, const double q[3]) {
        return std::fabs(linear(p[0]) - q[0]) + std::fabs(linear(p[1]) - q[1]) + std::fabs(linear(p[2]) - q[2]);
    };
    const double sky_d[3] = {linear(sky[0]), linear(sky[1]), linear(sky[2])};
    double grass_colour[kCount][3] = {};
    for (int k = 0; k < kCount; ++k) {
        const grass_host::Image im = k == 0 ? full : render_with(kinds[k], slices[k], 1.0f);
        for (uint32_t y = 0; y < im.height; ++y) {
            for (uint32_t x = 0; x < im.width; ++x) {
                if (!footprint[size_t(y) * im.width + x]) continue;
                for (int c = 0; c < 3; ++c) grass_colour[k][c] += linear(im.pixel(x, y)[c]) / double(area);
            }
        }
    }
    // A resolved pixel is the sky and the grass mixed by the covered share of its samples.
    auto coverage = [&](const grass_host::Image& im, int k) {
        const double full_distance = std::fabs(grass_colour[k][0] - sky_d[0]) +
                                     std::fabs(grass_colour[k][1] - sky_d[1]) +
                                     std::fabs(grass_colour[k][2] - sky_d[2]);
        double sum = 0.0;
        for (uint32_t y = 0; y < im.height; ++y) {
            for (uint32_t x = 0; x < im.width; ++x) {
                if (footprint[size_t(y) * im.width + x])
                    sum += std::min(1.0, distance(im.pixel(x, y), sky_d) / full_distance);
            }
        }
        return sum / double(area);
    };
    for (const float density : {0.1f, 0.3f}) {
        double c[kCount];
        std::printf("[ measured ] %s density %.1f, coverage:", backend_name(GetParam()).c_str(), density);
        for (int k = 0; k < kCount; ++k) {
            c[k] = coverage(render_with(kinds[k], slices[k], density), k);
            std::printf(" %s %.3f%s", names[k], c[k], k + 1 < kCount ? "," : "\n");
        }
        for (int k = 1; k < kCount; ++k) EXPECT_NEAR(c[k], c[0], kLimit[k]) << names[k] << ", density " << density;
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, TierDensityTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
