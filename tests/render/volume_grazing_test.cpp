// The volume tier's ray march (lemme2012 5.2) has a fixed bound from the slice count and the
// macro-cell size: a grazing view into a large macro-cell finishes and leaves no holes.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>

namespace grass_test {
namespace {

class VolumeGrazingTest : public RenderTest {
protected:
    // The field's share of grass in the rows below the horizon, drawn by `kind` alone with
    // macro-cells of up to 64 cells: the whole 64 x 64 field is one instance.
    double share_below_horizon(grass_tier_kind kind, const double eye[3], const double target[3]) {
        // The whole 16 m x 16 m field is one instance.
        const grass_field_desc d = solo_tier_field(64, kind, kind == GRASS_TIER_VOLUME ? 8u : 0u, 64);
        const grass_field_id f = make_field(d);
        const auto image = render(view(eye, target, 40.0f));
        save(image, std::to_string(int(kind)));
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        if (kind == GRASS_TIER_VOLUME) {
            EXPECT_EQ(stats.instances[GRASS_TIER_VOLUME], 1u) << "one 64-cell macro-cell";
        }
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        // Rows clearly below the horizon (the camera looks level): the lower 40%.
        return grass_share(image, sky, 0, image.height * 6 / 10, image.width, image.height);
    }
};

TEST_P(VolumeGrazingTest, AGrazingViewIntoALargeMacroCellFinishesWithoutHoles) {
    // 12 cm up, inside the blade layer, looking almost level along the field.
    const double eye[3] = {8.0, 0.12, 0.5}, target[3] = {8.0, 0.11, 20.0};
    const double blades = share_below_horizon(GRASS_TIER_GEOMETRY, eye, target);
    const double volume = share_below_horizon(GRASS_TIER_VOLUME, eye, target);
    std::printf("[ measured ] %s: grass below the horizon, blades %.3f, one volume macro-cell %.3f\n",
                backend_name(GetParam()).c_str(), blades, volume);
    EXPECT_GT(blades, 0.97);
    EXPECT_GT(volume, 0.97) << "no holes";
    // And level with the ground (0.01 degrees): the ray runs along the slices for 16 m.
    const double level_target[3] = {8.0, 0.12 - 20.0 * 0.000175, 20.0};
    const double level = share_below_horizon(GRASS_TIER_VOLUME, eye, level_target);
    std::printf("[ measured ] %s: at 0.01 degrees below level, volume %.3f\n", backend_name(GetParam()).c_str(), level);
    EXPECT_GT(level, 0.97);
}

// Seen from straight above the vertical slices are edge-on; the horizontal slice near the
// ground (the last layer of a volume tier's set, after boulanger 3.3) fills in.
TEST_P(VolumeGrazingTest, FromStraightAboveTheVolumeCoversLikeTheBlades) {
    const double eye[3] = {8.0, 3.0, 8.0}, target[3] = {8.0, 0.0, 8.0001};
    auto top_share = [&](grass_tier_kind kind) {
        const grass_field_desc d = solo_tier_field(64, kind, kind == GRASS_TIER_VOLUME ? 8u : 0u, 1);
        const grass_field_id f = make_field(d);
        const auto image = render(view(eye, target, 30.0f));
        save(image, "above_" + std::to_string(int(kind)));
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        return grass_share(image, sky, 0, 0, image.width, image.height);
    };
    const double blades = top_share(GRASS_TIER_GEOMETRY), volume = top_share(GRASS_TIER_VOLUME);
    std::printf("[ measured ] %s: from above, blades cover %.3f, the volume %.3f\n", backend_name(GetParam()).c_str(),
                blades, volume);
    EXPECT_GT(volume, 0.85 * blades);
}

INSTANTIATE_TEST_SUITE_P(Backends, VolumeGrazingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
