// A host wind-vector map (grass_set_field_wind_map, issue 13) as drawn, in every tier and
// both backends: with no other wind, the grass bends only where the map blows, a map blowing
// the other way bends it the other way, and removing the map draws the still grass again,
// bit for bit. The view looks along +z from above x = 1 m, so the map's calm/windy border
// projects onto the image's middle column and the field's +x is the image's left.
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace grass_test {
namespace {

struct TierCase {
    grass_tier_kind kind;
    uint32_t slices;
    const char* name;
};
const TierCase kTiers[3] = {
    {GRASS_TIER_GEOMETRY, 0, "geometry"}, {GRASS_TIER_VOLUME, 8, "volume"}, {GRASS_TIER_IMAGE, 0, "image"}};

constexpr float kSpeed = 6.0f; // m/s for an encoded 1: the speed of ResponsiveTiersTest's strong wind
constexpr uint32_t kMapWidth = 16, kMapHeight = 4;

// A wind map over the 8 x 8 cell field (2 m): calm over x < 1 m (texel value 0.5), and over
// x > 1 m blowing along the field's +x at kSpeed (r = 1) or -x (r = 0). Float texels: 0.5 is
// exactly calm.
std::vector<float> half_windy_texels(bool plus_x) {
    std::vector<float> t(size_t(kMapWidth) * kMapHeight * 4);
    for (uint32_t y = 0; y < kMapHeight; ++y) {
        for (uint32_t x = 0; x < kMapWidth; ++x) {
            float* p = &t[(size_t(y) * kMapWidth + x) * 4];
            const bool windy = x >= kMapWidth / 2;
            p[0] = windy ? (plus_x ? 1.0f : 0.0f) : 0.5f;
            p[1] = 0.5f;
            p[2] = 0.0f;
            p[3] = 1.0f;
        }
    }
    return t;
}

class WindMapTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
    }
    grass_field_id tier_field(const TierCase& tier) {
        return make_field(solo_tier_field(8, tier.kind, tier.slices, 4));
    }
    grass_map_id make_wind_map(bool plus_x) {
        const std::vector<float> texels = half_windy_texels(plus_x);
        grass_map_desc md = grass_default_map_desc();
        md.pixels = texels.data();
        md.width = kMapWidth;
        md.height = kMapHeight;
        md.format = GRASS_MAP_FORMAT_RGBA32_FLOAT;
        grass_map_id id{};
        EXPECT_EQ(grass_create_map(ctx, &md, &id), GRASS_SUCCESS) << log;
        return id;
    }
    void set_wind_map(grass_field_id f, grass_map_id map) {
        grass_wind_map_desc d = grass_default_wind_map_desc();
        d.map = map;
        d.speed = kSpeed;
        ASSERT_EQ(grass_set_field_wind_map(ctx, f, &d), GRASS_SUCCESS) << log;
    }
    grass_host::Image frame(const double eye[3], const double look[3], double time) {
        grass_view_desc v = view(eye, look);
        v.time = time;
        return render(v);
    }
};

// Mean |a - b| (8-bit levels, RGB) over the columns [x0, x1).
double columns_difference(const grass_host::Image& a, const grass_host::Image& b, uint32_t x0, uint32_t x1) {
    double sum = 0.0;
    size_t n = 0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = x0; x < x1; ++x) {
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]));
            n += 3;
        }
    }
    return n ? sum / double(n) : 0.0;
}

// Seen at an angle from above x = 1 m (the map's calm/windy border projects onto the image's
// middle column; the field's +x is the image's left), with the host's ground and 4 samples:
// against the still grass, the windy half changes and the calm half does not (but for the
// few centimetres of bilinear blend at the border, left out with a margin). Removing the map
// gives the still picture back, bit for bit: a field without a wind map costs nothing.
TEST_P(WindMapTest, GrassBendsOnlyWhereTheMapBlows) {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    t.samples = 4;
    t.ground = true;
    start(t);
    const double eye[3] = {1.0, 1.6, -0.2}, look[3] = {1.0, 0.0, 1.0};
    const uint32_t w = t.width, margin = w / 8;
    const grass_map_id map = make_wind_map(true);
    for (const TierCase& tier : kTiers) {
        const grass_field_id f = tier_field(tier);
        const grass_host::Image still = frame(eye, look, 1.0);
        expect_grass(still, host->target(), 0.3, tier.name);
        set_wind_map(f, map);
        const grass_host::Image windy = frame(eye, look, 1.0);
        const double moved = columns_difference(still, windy, 0, w / 2 - margin); // field x > 1 m
        const double calm = columns_difference(still, windy, w / 2 + margin, w);  // field x < 1 m
        std::printf("[ measured ] %s: the windy half changed by %.3f levels, the calm half by %.3f\n", tier.name, moved,
                    calm);
        save(still, std::string(tier.name) + ".still");
        save(windy, std::string(tier.name) + ".windy");
        EXPECT_GT(moved, 2.0) << tier.name << ": the map's wind must bend the grass where it blows";
        EXPECT_LT(calm, 0.25 * moved) << tier.name << ": the grass must stay still where the map is calm";
        ASSERT_EQ(grass_set_field_wind_map(ctx, f, nullptr), GRASS_SUCCESS) << log;
        const grass_host::Image removed = frame(eye, look, 1.0);
        EXPECT_EQ(still.rgba, removed.rgba) << tier.name << ": without its wind map the field must draw as before";
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log;
    }
    ASSERT_EQ(grass_destroy_map(ctx, map), GRASS_SUCCESS) << log;
}

// The luminance of `im` blurred by a (2r + 1)^2 box, edges clamped, row-major.
std::vector<double> blurred_luma(const grass_host::Image& im, int r) {
    const int w = int(im.width), h = int(im.height);
    std::vector<double> out(size_t(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double sum = 0.0;
            for (int dy = -r; dy <= r; ++dy) {
                for (int dx = -r; dx <= r; ++dx) {
                    const uint8_t* p =
                        im.pixel(uint32_t(std::clamp(x + dx, 0, w - 1)), uint32_t(std::clamp(y + dy, 0, h - 1)));
                    sum += 0.25 * p[0] + 0.5 * p[1] + 0.25 * p[2];
                }
            }
            out[size_t(y) * w + x] = sum / double((2 * r + 1) * (2 * r + 1));
        }
    }
    return out;
}

// The mean horizontal motion (pixels, + to the right) from `from` to `to` over the columns
// [x0, x1), by least squares on the brightness gradient (Lucas-Kanade with one unknown) of
// the images blurred so that blades are wider than they move: for a small motion s,
// to(x) = from(x - s), so to - from = -s d(from)/dx. Bending moves the blades' upper parts
// and not their roots: the estimate is the motion diluted by what does not move, and its
// sign is the direction.
double horizontal_motion(const grass_host::Image& from, const grass_host::Image& to, uint32_t x0, uint32_t x1) {
    const std::vector<double> a = blurred_luma(from, 3), b = blurred_luma(to, 3);
    const uint32_t w = from.width;
    double num = 0.0, den = 0.0;
    for (uint32_t y = 0; y < from.height; ++y) {
        for (uint32_t x = std::max(x0, 1u); x + 1 < x1 && x + 1 < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const double g = 0.5 * (a[i + 1] - a[i - 1]);
            num += (b[i] - a[i]) * g;
            den += g * g;
        }
    }
    return den > 0.0 ? -num / den : 0.0;
}

// The same view without ground, 1 sample: the windy half of the picture moves towards the
// field's +x (the image's left) under the map blowing +x, and towards -x under the reversed
// map; the calm half does not move.
TEST_P(WindMapTest, AReversedMapBendsTheOtherWay) {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    start(t);
    const double eye[3] = {1.0, 1.6, -0.2}, look[3] = {1.0, 0.0, 1.0};
    const uint32_t w = t.width, margin = w / 8;
    const grass_map_id plus = make_wind_map(true), minus = make_wind_map(false);
    for (const TierCase& tier : kTiers) {
        const grass_field_id f = tier_field(tier);
        const grass_host::Image still = frame(eye, look, 1.0);
        expect_grass(still, host->target(), 0.3, tier.name);
        set_wind_map(f, plus);
        const grass_host::Image east = frame(eye, look, 1.0);
        // Every frame at the same time (steps of 0): GL's per-blade state keeps the pose its
        // blades entered the window at (docs/responsive.md "Per-blade state"). A frame
        // without the map drops the window, so the -x map's blades enter at its pose.
        ASSERT_EQ(grass_set_field_wind_map(ctx, f, nullptr), GRASS_SUCCESS) << log;
        frame(eye, look, 1.0);
        set_wind_map(f, minus);
        const grass_host::Image west = frame(eye, look, 1.0);
        // East against west: the two bends, each the other's mirror, add up.
        const double s_windy = horizontal_motion(west, east, 0, w / 2 - margin);
        const double s_west = horizontal_motion(still, west, 0, w / 2 - margin);
        const double s_calm = horizontal_motion(west, east, w / 2 + margin, w);
        std::printf("[ measured ] %s: the windy half moves %.3f px from the -x map's picture to the +x map's, "
                    "%.3f px from the still one to the -x map's; the calm half %.3f px\n",
                    tier.name, s_windy, s_west, s_calm);
        save(east, std::string(tier.name) + ".east");
        save(west, std::string(tier.name) + ".west");
        EXPECT_LT(s_windy, -0.2) << tier.name
                                 << ": the +x map must lean the grass further towards +x (the image's "
                                    "left) than the -x map";
        EXPECT_GT(s_west, 0.1) << tier.name << ": the -x map must lean the grass towards -x (the image's right)";
        EXPECT_LT(std::fabs(s_calm), 0.02) << tier.name << ": the calm half must not move";
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log;
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, WindMapTest, ::testing::ValuesIn(enabled_backends()),
                         [](const ::testing::TestParamInfo<grass_backend>& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
