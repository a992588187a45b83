// Trails to the horizon (issue 35, item 4): at the player camera (1.7 m eye height) a ball's
// trail running away from the camera reads 100 m and 120 m away, where the image tier draws
// the grass: the interaction map's coarse level (1 m texels, 256 m across) covers the image
// tier's band, and it widens a footprint narrower than half a texel's diagonal to that radius
// (no ball slips between its texel centres).
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace grass_test {
namespace {

// The player's eye, looking along +z at the ground 100 m away through a narrow field of view
// (a zoomed look; 12 degrees over 90 rows: a 1 m trail 100 m away is 5 pixels wide).
const double kEye[3] = {0.0, 1.7, 0.0};
const double kLook[3] = {0.0, 0.0, 100.0};
constexpr float kFov = 12.0f;

class FarTrailTest : public RenderTest {
protected:
    void SetUp() override {
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 90;
        start(t);
    }
    // The image tier alone over 20 m x 100 m from 40 m to 140 m ahead (the band where a
    // player's grass is the image tier's).
    grass_field_id far_field(grass_patch_id p) {
        grass_field_desc d = solo_tier_field(80, GRASS_TIER_IMAGE, 0, 64);
        d.patch = p;
        d.cells_z = 400;
        d.base_transform[12] = -10.0;
        d.base_transform[14] = 40.0;
        return make_field(d);
    }
    grass_host::Image frame(double time) {
        grass_view_desc v = grass_host::make_view(*host, kEye, kLook, kFov, 0.5f, 400.0f);
        v.time = time;
        return render(v);
    }
};

// Mean RGB (8-bit levels) over the pixels within `radius_px` of (x, y), and the share of
// them that is grass.
double region_mean(const grass_host::Image& image, double x, double y, double radius_px) {
    double sum = 0.0;
    size_t n = 0;
    for (uint32_t py = 0; py < image.height; ++py) {
        for (uint32_t px = 0; px < image.width; ++px) {
            if (std::hypot(px + 0.5 - x, (py + 0.5 - y) * 2.0) > radius_px) continue; // flat: 2 rows per radius
            const uint8_t* p = image.pixel(px, py);
            sum += (p[0] + p[1] + p[2]) / 3.0;
            ++n;
        }
    }
    return n ? sum / double(n) : 0.0;
}

// A 1 m ball rolled along +z in one step of 1 s, from 50 m to 125 m ahead, leaves a trail
// that changes the grass 100 m and 120 m away by at least twice what a different field seed
// changes there (the seed spread) and by at least 2 levels; rolled from 112 m to 126 m alone,
// it changes the grass 120 m away likewise. With the old coarse level (0.5 m texels, cut at
// 64 m) neither changed anything there.
TEST_P(FarTrailTest, ABallsTrailReads100And120MetresAway) {
    grass_patch_desc pd = grass_default_patch_desc();
    pd.seed += 1;
    grass_patch_id other{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &other), GRASS_SUCCESS) << log;
    const grass_field_id seed_b = far_field(other);
    const grass_host::Image other_seed = frame(1.0);
    ASSERT_EQ(grass_destroy_field(ctx, seed_b), GRASS_SUCCESS) << log;
    const grass_field_id f = far_field(patch);
    const grass_host::Image still = frame(1.0);
    save(other_seed, "other-seed");
    save(still, "still");

    double time = 1.0;
    // The ball rests at `from` m ahead, then rolls to `to` in one step of 1 s (swept: a
    // continuous trail) and is taken away: the frame after.
    const auto roll = [&](double from, double to) {
        EXPECT_EQ(grass_set_interaction(ctx, nullptr), GRASS_SUCCESS) << log; // no earlier trail
        grass_collider ball{};
        ball.shape = GRASS_COLLIDER_SPHERE;
        ball.radius = 0.5f;
        ball.center[1] = 0.5;
        ball.center[2] = from;
        EXPECT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS) << log;
        frame(time += 1.0);
        ball.center[2] = to;
        ball.velocity[2] = float(to - from);
        EXPECT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS) << log;
        frame(time += 1.0);
        EXPECT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        return frame(time += 0.01);
    };
    const auto expect_trail_at = [&](const grass_host::Image& trail, double z, const char* what) {
        const double at[3] = {0.0, 0.0, z};
        double x = 0.0, y = 0.0;
        ASSERT_TRUE(project_point(kEye, kLook, kFov, host->target().width, host->target().height, at, &x, &y));
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        EXPECT_GE(grass_share(still, sky, uint32_t(x) - 4, uint32_t(y), uint32_t(x) + 4, uint32_t(y) + 1), 0.99)
            << "the point's row must be grass";
        const double radius_px = 2.5;
        const double seeds = std::fabs(region_mean(still, x, y, radius_px) - region_mean(other_seed, x, y, radius_px));
        const double change = std::fabs(region_mean(trail, x, y, radius_px) - region_mean(still, x, y, radius_px));
        std::printf("[ far trail] %s, %s, %.0f m (pixel %.1f, %.1f): the trail changes the grass by %.2f levels, a "
                    "different seed by %.2f\n",
                    backend_name(GetParam()).c_str(), what, z, x, y, change, seeds);
        EXPECT_GT(change, std::max(2.0 * seeds, 2.0)) << what << ", " << z << " m: the trail changes its region by "
                                                      << change << " levels, the seeds by " << seeds;
    };
    const grass_host::Image long_trail = roll(50.0, 125.0);
    save(long_trail, "trail-50-125");
    expect_trail_at(long_trail, 100.0, "50-125 m");
    expect_trail_at(long_trail, 120.0, "50-125 m");
    const grass_host::Image far_trail = roll(112.0, 126.0);
    save(far_trail, "trail-112-126");
    expect_trail_at(far_trail, 120.0, "112-126 m");
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log;
}

INSTANTIATE_TEST_SUITE_P(Backends, FarTrailTest, ::testing::ValuesIn(enabled_backends()),
                         [](const ::testing::TestParamInfo<grass_backend>& i) { return backend_name(i.param); });

} // namespace
} // namespace grass_test
