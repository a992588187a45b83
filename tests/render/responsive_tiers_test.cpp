// Responsive grass (issue 13) in every tier drawn alone: still grass is exactly what it was
// without responsive grass, wind moves the grass and a time step of 0 freezes it, and a
// collider's trail stays visible.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace grass_test {
namespace {

// Both backends draw responsive grass.
std::vector<grass_backend> responsive_backends() { return enabled_backends(); }

struct TierCase {
    grass_tier_kind kind;
    uint32_t slices;
    const char* name;
};
const TierCase kTiers[3] = {
    {GRASS_TIER_GEOMETRY, 0, "geometry"}, {GRASS_TIER_VOLUME, 8, "volume"}, {GRASS_TIER_IMAGE, 0, "image"}};

// An 8 x 8 cell field (2 m) seen from above at an angle, one tier at every distance.
const double kEye[3] = {1.0, 1.6, -0.2};
const double kLook[3] = {1.0, 0.0, 1.0};

class ResponsiveTiersTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = t.height = 80;
        start(t);
    }
    grass_field_id tier_field(const TierCase& tier, grass_patch_id p) {
        grass_field_desc d = solo_tier_field(8, tier.kind, tier.slices, 4);
        d.patch = p;
        return make_field(d);
    }
    grass_host::Image frame(double time) {
        grass_view_desc v = view(kEye, kLook);
        v.time = time;
        return render(v);
    }
};

grass_wind_desc strong_wind() {
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 6.0f;
    return w;
}

// Mean RGB (8-bit levels) over the pixels within `radius_px` of (x, y).
double region_mean(const grass_host::Image& image, double x, double y, double radius_px) {
    double sum = 0.0;
    size_t n = 0;
    for (uint32_t py = 0; py < image.height; ++py) {
        for (uint32_t px = 0; px < image.width; ++px) {
            if (std::hypot(px + 0.5 - x, py + 0.5 - y) > radius_px) continue;
            const uint8_t* p = image.pixel(px, py);
            sum += (p[0] + p[1] + p[2]) / 3.0;
            ++n;
        }
    }
    return n ? sum / double(n) : 0.0;
}

// Setting no wind and no colliders keeps the frame bit for bit what it was before any
// responsive grass was asked for (the shaders of still grass, nothing bound).
TEST_P(ResponsiveTiersTest, StillGrassIsUnchanged) {
    for (const TierCase& tier : kTiers) {
        const grass_field_id f = tier_field(tier, patch);
        const grass_host::Image before = frame(1.0);
        expect_grass(before, host->target(), 0.3, tier.name);
        const grass_wind_desc calm = grass_default_wind_desc(); // speed 0, standard gravity
        ASSERT_EQ(grass_set_wind(ctx, &calm), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        const grass_host::Image after = frame(2.0);
        EXPECT_EQ(before.rgba, after.rgba) << tier.name << ": still grass changed";
        // The wind variant with a blade that does not respond: the same picture but for
        // rounding (the blade is rebuilt from its curve).
        grass_blade_mechanics m = grass_default_blade_mechanics();
        m.wind_response = 0.0f;
        ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << log;
        const grass_wind_desc w = strong_wind();
        ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
        const grass_host::Image unmoved = frame(3.0);
        save(before, std::string(tier.name) + ".before");
        save(unmoved, std::string(tier.name) + ".unmoved");
        if (tier.kind == GRASS_TIER_GEOMETRY) {
            EXPECT_LT(mean_difference(before, unmoved), 0.5) << tier.name;
        }
        ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS) << log;
        const grass_blade_mechanics defaults = grass_default_blade_mechanics();
        ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &defaults), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log;
    }
}

// Wind moves the grass in every tier (two times differ), and a frame at the same time as
// the one before (dt = 0) is that frame again.
TEST_P(ResponsiveTiersTest, WindMovesEveryTierAndDtZeroFreezes) {
    const grass_wind_desc w = strong_wind();
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    for (const TierCase& tier : kTiers) {
        const grass_field_id f = tier_field(tier, patch);
        const grass_host::Image a = frame(1.0);
        const grass_host::Image b = frame(1.6);
        const grass_host::Image b_again = frame(1.6);
        save(a, std::string(tier.name) + ".t1");
        save(b, std::string(tier.name) + ".t2");
        expect_grass(a, host->target(), 0.3, tier.name);
        EXPECT_GT(mean_difference(a, b), 1.0) << tier.name << ": the wind must move the grass";
        EXPECT_EQ(b.rgba, b_again.rgba) << tier.name << ": dt = 0 must freeze the grass";
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log;
    }
}

// A sphere pressed the grass flat and left: the trail (flattened, darker grass) shows in each
// tier. Its region's mean colour moves by far more than the mean of the same region moves
// between two patches of different seeds.
TEST_P(ResponsiveTiersTest, TrailVisibleInEveryTier) {
    grass_blade_mechanics m = grass_default_blade_mechanics();
    m.trample_depth = 1.0f;
    m.recovery_time = 1000.0f;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.seed += 1;
    grass_patch_id other{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &other), GRASS_SUCCESS) << log;
    for (grass_patch_id p : {patch, other}) ASSERT_EQ(grass_set_blade_mechanics(ctx, p, &m), GRASS_SUCCESS) << log;
    const double centre[3] = {1.0, 0.0, 1.0};
    double cx = 0.0, cy = 0.0;
    ASSERT_TRUE(project_point(kEye, kLook, 50.0f, host->target().width, host->target().height, centre, &cx, &cy));
    const double radius_px = 6.0;
    const grass_collider c = [] {
        grass_collider s{};
        s.shape = GRASS_COLLIDER_SPHERE;
        s.radius = 0.4f;
        s.center[0] = 1.0;
        s.center[1] = 0.41;
        s.center[2] = 1.0;
        return s;
    }();
    double time = 0.0;
    for (const TierCase& tier : kTiers) {
        const grass_field_id seed_b = tier_field(tier, other);
        const grass_host::Image other_seed = frame(time += 1.0);
        ASSERT_EQ(grass_destroy_field(ctx, seed_b), GRASS_SUCCESS);
        const grass_field_id f = tier_field(tier, patch);
        const grass_host::Image still = frame(time += 1.0);
        ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
        frame(time += 0.01);
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        const grass_host::Image trail = frame(time += 0.01);
        save(still, std::string(tier.name) + ".still");
        save(trail, std::string(tier.name) + ".trail");
        expect_grass(still, host->target(), 0.3, tier.name);
        const double noise =
            std::fabs(region_mean(still, cx, cy, radius_px) - region_mean(other_seed, cx, cy, radius_px));
        const double change = std::fabs(region_mean(trail, cx, cy, radius_px) - region_mean(still, cx, cy, radius_px));
        EXPECT_GT(change, std::max(3.0 * noise, 3.0))
            << tier.name << ": trail changes its region by " << change << " levels, seeds by " << noise;
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        // Clear the trail for the next tier.
        grass_interaction_desc d = grass_default_interaction_desc();
        ASSERT_EQ(grass_set_interaction(ctx, &d), GRASS_SUCCESS) << log;
    }
}

// Each inner cell's mean colour around its projected centre, seen from `eye`.
std::vector<double> cell_means(const grass_host::Image& image, const double eye[3], const double look[3]) {
    std::vector<double> means;
    for (int j = 1; j < 7; ++j) {
        for (int i = 1; i < 7; ++i) {
            const double centre[3] = {(i + 0.5) * 0.25, 0.0, (j + 0.5) * 0.25};
            double x = 0.0, y = 0.0;
            if (!project_point(eye, look, 50.0f, image.width, image.height, centre, &x, &y)) continue;
            means.push_back(region_mean(image, x, y, 2.5));
        }
    }
    return means;
}

// The standard deviation over the cells of how much each one's colour moved from a to b.
double cell_change_spread(const std::vector<double>& a, const std::vector<double>& b) {
    double mean = 0.0, var = 0.0;
    for (size_t k = 0; k < a.size(); ++k) mean += (b[k] - a[k]) / double(a.size());
    for (size_t k = 0; k < a.size(); ++k) var += (b[k] - a[k] - mean) * (b[k] - a[k] - mean) / double(a.size());
    return std::sqrt(var);
}

// A wind that is the same everywhere (no gusts, no turbulence) bends every cell's slices alike,
// so it changes every cell's colour about alike, whatever its mirroring. Turning the slices'
// folded mean normal with the bend, instead of each lobe, lit mirrored cells differently: a
// cell-sized checkerboard under wind: the cells' changes spread by 4.1 levels in the volume
// tier (1.5 with the lobes turned; the image tier 1.7 against 1.0).
TEST_P(ResponsiveTiersTest, UniformWindLightsMirroredCellsAlike) {
    grass_wind_desc w = strong_wind();
    w.direction[0] = 1.0f;
    w.direction[2] = 1.0f;
    w.gust_strength = 0.0f;
    w.turbulence = 0.0f;
    const double eye[3] = {1.0, 0.6, -0.6};
    for (const TierCase& tier : kTiers) {
        if (tier.kind == GRASS_TIER_GEOMETRY) continue; // blades are not mirrored sample by sample
        const grass_field_id f = tier_field(tier, patch);
        ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS) << log;
        grass_view_desc v = view(eye, kLook);
        v.time = 1.0;
        const grass_host::Image still = render(v);
        ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
        v.time = 2.0;
        const grass_host::Image windy = render(v);
        save(windy, std::string(tier.name) + ".uniform-wind");
        expect_grass(windy, host->target(), 0.3, tier.name);
        EXPECT_GT(mean_difference(still, windy), 1.0) << tier.name << ": the wind must bend the grass";
        const double spread = cell_change_spread(cell_means(still, eye, kLook), cell_means(windy, eye, kLook));
        std::printf("[ cells    ] %s: spread of the cells' change under a uniform wind %.2f levels\n", tier.name,
                    spread);
        EXPECT_LT(spread, 3.0) << tier.name;
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    }
}

// A ball rolling 1.6 m in 1 s leaves the same trail whether the frames come at 30 fps, 10 fps
// or as one step of 1 s, seen 10 s later (the pass sweeps each collider over the step, and a texel keeps the
// deepest contact of a passage), drawn by the blades. A rule that let each frame's contact
// replace the stored one left a trail of shallower dents at 30 fps.
TEST_P(ResponsiveTiersTest, ARollingBallsTrailIsTheSameAtAnyFrameRate) {
    grass_blade_mechanics m = grass_default_blade_mechanics();
    m.recovery_time = 1000.0f;
    ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << log;
    const grass_field_id f = tier_field(kTiers[0], patch);
    const float speed = 1.6f;
    auto ball_at = [&](double t) {
        grass_collider c{};
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = 0.3f;
        c.center[0] = 0.2 + speed * t;
        c.center[1] = 0.22;
        c.center[2] = 1.0;
        c.velocity[0] = speed;
        return c;
    };
    const int steps[3] = {30, 10, 1};
    grass_host::Image last[3];
    grass_host::Image still;
    for (int r = 0; r < 3; ++r) {
        const double t0 = 10.0 + 10.0 * r;
        const grass_interaction_desc fresh = grass_default_interaction_desc();
        ASSERT_EQ(grass_set_interaction(ctx, &fresh), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        still = frame(t0); // no wind, no map: no blade window, so GL's per-blade state starts afresh
        // GL's blades enter the window (their state at rest) before the ball comes, at a
        // collider far off the field: every run steps its state from the same start.
        grass_collider away{};
        away.shape = GRASS_COLLIDER_SPHERE;
        away.radius = 0.1f;
        away.center[0] = away.center[2] = 40.0;
        ASSERT_EQ(grass_set_colliders(ctx, &away, 1), GRASS_SUCCESS) << log;
        frame(t0);
        for (int k = 1; k <= steps[r]; ++k) {
            const double t = double(k) / steps[r];
            const grass_collider c = ball_at(t);
            ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
            frame(t0 + t);
        }
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        // The ball gone, 10 s later: GL's per-blade state has settled at the stateless pose
        // (eta held near 1 by the 1000 s recovery, so recovery is at its floor and the tip's
        // spring overdamped: e^-13 of the push is left), and the trail is 1% shallower in
        // every run alike. With the state still moving (no time passed) the runs differ by
        // how the ball pushed the blades at each frame rate (2.1 levels at 30 fps).
        last[r] = frame(t0 + 11.0);
        save(last[r], "trail-" + std::to_string(steps[r]) + "steps");
    }
    expect_grass(still, host->target(), 0.3, "still");
    const double trail = mean_difference(still, last[2]);
    EXPECT_GT(trail, 2.0) << "the ball must leave a trail";
    for (int r = 0; r < 2; ++r) {
        const double d = mean_difference(last[r], last[2]);
        std::printf("[ fps      ] %d steps against one: %.3f levels per pixel (the trail itself: %.2f)\n", steps[r], d,
                    trail);
        EXPECT_LT(d, 0.05 * trail) << steps[r] << " steps";
    }
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
}

// The interaction map moves with the camera: a trail left here is cleared when the camera goes
// 10 km away, and nothing of it reappears when the camera comes back; the map's memory stays
// what it was.
TEST_P(ResponsiveTiersTest, AfterA10KmMoveNoStaleTrailReappears) {
    grass_blade_mechanics m = grass_default_blade_mechanics();
    m.recovery_time = 1000.0f;
    ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << log;
    const grass_field_id f = tier_field(kTiers[0], patch);
    grass_collider c{};
    c.shape = GRASS_COLLIDER_SPHERE;
    c.radius = 0.4f;
    c.center[0] = 1.0;
    c.center[1] = 0.3;
    c.center[2] = 1.0;
    const grass_host::Image still = frame(1.0);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
    frame(1.1);
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
    const grass_host::Image trail = frame(1.2);
    grass_memory_stats before{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &before), GRASS_SUCCESS);
    EXPECT_GT(mean_difference(still, trail), 2.0) << "the ball must leave a trail";
    const double away[3] = {kEye[0] + 10000.0, kEye[1], kEye[2]};
    const double away_look[3] = {kLook[0] + 10000.0, kLook[1], kLook[2]};
    grass_view_desc v = view(away, away_look);
    v.time = 1.3;
    render(v);
    const grass_host::Image back = frame(1.4);
    save(back, "after-10km");
    grass_memory_stats after{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &after), GRASS_SUCCESS);
    EXPECT_LT(mean_difference(still, back), 0.05) << "a stale trail reappeared";
    EXPECT_EQ(after.dynamics_gpu_bytes, before.dynamics_gpu_bytes);
    EXPECT_GT(after.dynamics_gpu_bytes, 0u);
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
}

// The share of pixels that are green grass: green the largest channel and not dark. A NaN
// position drops a blade (sky shows), a NaN colour writes black or garbage: both lower it.
double green_share(const grass_host::Image& image) {
    size_t green = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = image.pixel(x, y);
            green += p[1] > 20 && p[1] > p[0] && p[1] > p[2];
        }
    }
    return double(green) / double(size_t(image.width) * image.height);
}

// The extremes of the issue, drawn in every tier: a 10 s time step, a 1e3 m/s wind, a collider
// of radius 0 and one of 1e6 m over the field, colliders 1e7 m away. Each frame draws, every
// tier keeps its green grass (green_share), and the far colliders change nothing.
TEST_P(ResponsiveTiersTest, TheExtremesDrawFiniteGrassInEveryTier) {
    for (const TierCase& tier : kTiers) {
        const grass_field_id f = tier_field(tier, patch);
        double time = 1.0;
        ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        const grass_host::Image still = frame(time);
        grass_collider far[2] = {};
        for (int k = 0; k < 2; ++k) {
            far[k].shape = k == 0 ? GRASS_COLLIDER_SPHERE : GRASS_COLLIDER_CAPSULE;
            far[k].radius = 5.0f;
            far[k].center[0] = 1e7;
            far[k].center[2] = -1e7 * k;
            far[k].end[0] = 1e7 + 3.0;
            far[k].end[2] = -1e7 * k;
            far[k].velocity[0] = 1e5f;
        }
        ASSERT_EQ(grass_set_colliders(ctx, far, 2), GRASS_SUCCESS) << log;
        // Still grass's frame, up to rounding: a geometry tier with colliders runs the window
        // variant, which GL compacts (docs/responsive.md "Culled blades compacted"): another
        // program and one draw per instance, whose rasterisation moved one edge pixel by one
        // level here (mean 5.2e-5). A blade the colliders moved would change many pixels.
        const double kRounding = 1e-4;
        EXPECT_LE(mean_difference(still, frame(time += 10.0)), kRounding) << tier.name << ": colliders 1e7 m away";
        grass_collider zero{};
        zero.shape = GRASS_COLLIDER_SPHERE;
        zero.center[0] = 1.0;
        zero.center[2] = 1.0;
        ASSERT_EQ(grass_set_colliders(ctx, &zero, 1), GRASS_SUCCESS) << log;
        EXPECT_LE(mean_difference(still, frame(time += 10.0)), kRounding) << tier.name << ": a collider of radius 0";
        grass_wind_desc w = grass_default_wind_desc();
        w.speed = 1e3f;
        w.gust_strength = 4.0f;
        w.turbulence = 1.0f;
        ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
        const grass_host::Image gale = frame(time += 10.0);
        save(gale, std::string(tier.name) + ".gale");
        const double still_green = green_share(still);
        EXPECT_GT(still_green, 0.5) << tier.name;
        EXPECT_GT(green_share(gale), 0.8 * still_green) << tier.name << " in a 1e3 m/s wind";
        grass_collider huge{};
        huge.shape = GRASS_COLLIDER_SPHERE;
        huge.radius = 1e6f;
        huge.center[0] = 1.0;
        huge.center[1] = 1e6 - 0.02; // its underside 2 cm above the ground: everything pressed
        huge.center[2] = 1.0;
        ASSERT_EQ(grass_set_colliders(ctx, &huge, 1), GRASS_SUCCESS) << log;
        const grass_host::Image pressed = frame(time += 10.0);
        save(pressed, std::string(tier.name) + ".huge-collider");
        EXPECT_GT(green_share(pressed), 0.8 * still_green) << tier.name << " under a collider of 1e6 m";
        EXPECT_GT(mean_difference(gale, pressed), 1.0) << tier.name << ": the huge collider must press the grass";
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS) << log;
        const grass_interaction_desc fresh = grass_default_interaction_desc();
        ASSERT_EQ(grass_set_interaction(ctx, &fresh), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, ResponsiveTiersTest, ::testing::ValuesIn(responsive_backends()),
                         [](const ::testing::TestParamInfo<grass_backend>& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
