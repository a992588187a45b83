// The host's cascaded sun shadows end to end (TargetDesc::host_shadows; docs/engine-frames.md
// "Shadows: grass in the host's shadow maps" and "Receiving the host's shadows"): each frame
// the host fits three orthographic cascades of the sun around the main camera's frustum,
// draws its box "building" and grass's depth views (one grass frame: the main view, then a
// depth view per cascade at the main camera's lod) into a 2D-array depth map, and draws the
// main view with its ground and the building sampling the map and grass receiving it:
// - grass in the building's shadow is darker than the same grass with the host's shadows
//   off by a clear margin, and lit grass is unchanged within a level (the receive bias keeps
//   grass from shading itself as a slab; without it the lit grass darkens);
// - grass casts onto the host's bare ground in front of the field (the side away from the
//   sun): that strip is darker than ground far from it, and is not when grass casts nothing;
// - GL and Vulkan agree; validation (Vulkan: synchronization too) stays silent.
// Pixel sets come from world points whose rays to the sun do or do not cross the building
// (eroded by a margin), each set checked non-empty and covered by grass.
#include "render_fixture.hpp"

#include "mesh_shapes.hpp"

#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

namespace grass_test {
namespace {

constexpr uint32_t kWidth = 192, kHeight = 144;
constexpr uint32_t kCells = 48; // 12 m x 12 m from the origin
const double kEye[3] = {6.0, 5.0, -7.0}, kLook[3] = {6.0, 0.0, 5.0};
const float kSun[3] = {0.5f, 0.55f, 0.65f}; // towards the sun: shadows fall to -x, -z
const double kBuildingLow[3] = {7.0, 0.0, 6.0}, kBuildingHigh[3] = {9.0, 3.0, 8.0};

// Whether the ray from p towards the sun crosses the building (a slab test).
bool in_building_shadow(const double p[3]) {
    double s[3];
    const double len = std::sqrt(double(kSun[0]) * kSun[0] + double(kSun[1]) * kSun[1] + double(kSun[2]) * kSun[2]);
    for (int c = 0; c < 3; ++c) s[c] = kSun[c] / len;
    double t0 = 0.0, t1 = 1e9;
    for (int c = 0; c < 3; ++c) {
        const double a = (kBuildingLow[c] - p[c]) / s[c], b = (kBuildingHigh[c] - p[c]) / s[c];
        t0 = std::fmax(t0, std::fmin(a, b));
        t1 = std::fmin(t1, std::fmax(a, b));
    }
    return t0 <= t1;
}

// Shadowed (want true) or lit (want false) for the point and every point within `margin`
// of it, at the ground and at blade height.
bool surely(const double x, const double z, bool want, double margin) {
    for (double dx = -margin; dx <= margin + 1e-9; dx += margin) {
        for (double dz = -margin; dz <= margin + 1e-9; dz += margin) {
            for (double y : {0.0, 0.5}) {
                const double p[3] = {x + dx, y, z + dz};
                if (in_building_shadow(p) != want) return false;
            }
        }
    }
    return true;
}

using Pixels = std::vector<std::pair<uint32_t, uint32_t>>;

// The pixels where the ground points of [x0, x1] x [z0, z1] (a 5 cm grid) that pass `keep` appear.
template <class Keep>
Pixels pixels_of(double x0, double x1, double z0, double z1, Keep keep) {
    std::set<std::pair<uint32_t, uint32_t>> seen;
    for (double x = x0; x <= x1; x += 0.05) {
        for (double z = z0; z <= z1; z += 0.05) {
            if (!keep(x, z)) continue;
            const double p[3] = {x, 0.0, z};
            double px = 0.0, py = 0.0;
            if (!project_point(kEye, kLook, 50.0f, kWidth, kHeight, p, &px, &py)) continue;
            if (px < 0.0 || py < 0.0 || px >= kWidth || py >= kHeight) continue;
            seen.insert({uint32_t(px), uint32_t(py)});
        }
    }
    return Pixels(seen.begin(), seen.end());
}

double mean_level(const grass_host::Image& image, const Pixels& pixels) {
    double sum = 0.0;
    for (const auto& [x, y] : pixels) {
        const uint8_t* p = image.pixel(x, y);
        sum += (double(p[0]) + p[1] + p[2]) / 3.0;
    }
    return pixels.empty() ? 0.0 : sum / double(pixels.size());
}

class CascadedShadowsTest : public RenderTest {
protected:
    void SetUp() override {
        setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 1);
        RenderTest::SetUp();
    }
    void TearDown() override {
        RenderTest::TearDown();
        unsetenv("VK_LAYER_ENABLES");
    }

    static grass_host::TargetDesc target(float receive_bias) {
        grass_host::TargetDesc t;
        t.width = kWidth;
        t.height = kHeight;
        t.ground = true;
        t.ground_color[0] = 0.25f, t.ground_color[1] = 0.2f, t.ground_color[2] = 0.12f;
        const float wall[3] = {0.6f, 0.55f, 0.5f};
        t.meshes.push_back(grass_host::box_mesh("building", kBuildingLow, kBuildingHigh, wall));
        t.host_shadows.cascades = 3;
        t.host_shadows.map_size = 512;
        t.host_shadows.splits[0] = 6.0f, t.host_shadows.splits[1] = 12.0f, t.host_shadows.splits[2] = 30.0f;
        t.host_shadows.grass_receive_bias = receive_bias;
        return t;
    }

    // The scene on `backend` with the given shadow parts (all off: no shadows).
    // sun_off: the sun's colour zero (the picture of grass wholly in shade).
    grass_host::Image scene(grass_backend backend, float receive_bias, grass_host::Host::ShadowParts parts,
                            bool sun_off = false) {
        start(target(receive_bias), backend);
        if (HasFailure()) return {};
        host->shadow_parts = parts;
        // Blades of 0.4-0.6 m (the default's are 0.11-0.21 m): a shadow on the ground wide
        // enough to measure.
        grass_patch_desc tall = grass_default_patch_desc();
        tall.length_min = 1.6f;
        tall.length_max = 2.4f;
        grass_patch_id tall_patch{};
        EXPECT_EQ(grass_create_patch(ctx, &tall, &tall_patch), GRASS_SUCCESS) << log;
        grass_field_desc d = field_desc(kCells);
        d.patch = tall_patch;
        make_field(d);
        grass_view_desc v = view(kEye, kLook);
        for (int c = 0; c < 3; ++c) v.sun_direction[c] = kSun[c];
        // A dim sky: the sun's share of grass's light, what a shadow takes away, is larger.
        v.ambient_color[0] = 0.10f, v.ambient_color[1] = 0.12f, v.ambient_color[2] = 0.15f;
        if (sun_off) v.sun_color[0] = v.sun_color[1] = v.sun_color[2] = 0.0f;
        const grass_host::Image image = render(v);
        EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
        return image;
    }

    static grass_host::Host::ShadowParts off() {
        grass_host::Host::ShadowParts p;
        p.grass_casts = p.grass_receives = p.host_casts = p.host_receives = false;
        return p;
    }
};

TEST_P(CascadedShadowsTest, BuildingShadesGrassAndGrassShadesTheGround) {
    const float bias = grass_host::HostShadows{}.grass_receive_bias;
    const grass_host::Image on = scene(GetParam(), bias, grass_host::Host::ShadowParts{});
    save(on, "on");
    const grass_host::Image none = scene(GetParam(), bias, off());
    save(none, "off");
    const grass_host::Image shade = scene(GetParam(), bias, off(), true);
    ASSERT_FALSE(HasFailure()) << log;
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    expect_grass(on, host->target(), 0.3, "the shadowed scene");

    // Grass in the building's shadow and grass well lit, in front of the building.
    const Pixels shaded = pixels_of(0.5, 11.5, 0.5, 5.8, [](double x, double z) { return surely(x, z, true, 0.5); });
    const Pixels lit = pixels_of(0.5, 11.5, 0.5, 5.8, [](double x, double z) { return surely(x, z, false, 1.0); });
    ASSERT_GT(shaded.size(), 100u) << "the building's shadow covers too few pixels to measure";
    ASSERT_GT(lit.size(), 300u);
    size_t grass_px = 0;
    for (const auto& [x, y] : shaded) grass_px += is_grass(none.pixel(x, y), sky) ? 1 : 0;
    EXPECT_EQ(grass_px, shaded.size()) << "the shadow's pixels are not all grass";
    const double shaded_on = mean_level(on, shaded), shaded_off = mean_level(none, shaded);
    const double lit_on = mean_level(on, lit), lit_off = mean_level(none, lit);
    const double shaded_sun_off = mean_level(shade, shaded);
    std::printf("grass in the building's shadow %.2f (shadows off %.2f, sun off %.2f); lit grass %.2f (off %.2f)\n",
                shaded_on, shaded_off, shaded_sun_off, lit_on, lit_off);
    EXPECT_LT(shaded_on, shaded_off - 0.6 * (shaded_off - shaded_sun_off))
        << "grass in the building's shadow is not darker by most of the sun's share";
    EXPECT_NEAR(lit_on, lit_off, 1.0) << "lit grass changed: grass shades itself";

    // The bare ground in front of the field (z < 0: the side away from the sun) in grass's
    // shadow, against ground far from the field.
    const auto any = [](double, double) { return true; };
    const Pixels strip = pixels_of(1.0, 11.0, -0.3, -0.1, any);
    const Pixels far_ground = pixels_of(1.0, 11.0, -2.0, -1.5, any);
    ASSERT_GT(strip.size(), 50u);
    ASSERT_GT(far_ground.size(), 50u);
    const double strip_on = mean_level(on, strip), far_on = mean_level(on, far_ground);
    const double strip_off = mean_level(none, strip), far_off = mean_level(none, far_ground);
    std::printf("ground in grass's shadow %.2f, far from it %.2f (shadows off %.2f, %.2f)\n", strip_on, far_on,
                strip_off, far_off);
    EXPECT_NEAR(strip_off, far_off, 2.0) << "without shadows the ground is not even";
    EXPECT_LT(strip_on, far_on - 8.0) << "grass casts no shadow onto the ground";
}

TEST_P(CascadedShadowsTest, WithoutTheReceiveBiasGrassShadesItselfAsASlab) {
    const grass_host::Image zero = scene(GetParam(), 0.0f, grass_host::Host::ShadowParts{});
    const grass_host::Image none = scene(GetParam(), 0.0f, off());
    const grass_host::Image shade = scene(GetParam(), 0.0f, off(), true);
    ASSERT_FALSE(HasFailure()) << log;
    const Pixels lit = pixels_of(0.5, 11.5, 0.5, 5.8, [](double x, double z) { return surely(x, z, false, 1.0); });
    const double lit_zero = mean_level(zero, lit), lit_off = mean_level(none, lit);
    const double lit_sun_off = mean_level(shade, lit);
    std::printf("lit grass with receive bias 0: %.2f (shadows off %.2f, sun off %.2f)\n", lit_zero, lit_off,
                lit_sun_off);
    EXPECT_LT(lit_zero, lit_off - 0.25 * (lit_off - lit_sun_off))
        << "grass casting into the map does not reach the grass that receives it";
}

INSTANTIATE_TEST_SUITE_P(Backends, CascadedShadowsTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

#if defined(GRASS_HOST_HAS_GL) && defined(GRASS_HOST_HAS_VULKAN)
// GL and Vulkan draw the shadowed scene alike (their cascades are fitted in their own clip
// conventions, and grass's depth views and receiving run in each backend's shaders).
class CascadedShadowsAgreementTest : public CascadedShadowsTest {};

TEST_P(CascadedShadowsAgreementTest, GlAndVulkanAgree) {
    const float bias = grass_host::HostShadows{}.grass_receive_bias;
    const grass_host::Image gl = scene(GRASS_BACKEND_GL, bias, grass_host::Host::ShadowParts{});
    const grass_host::Image vk = scene(GRASS_BACKEND_VULKAN, bias, grass_host::Host::ShadowParts{});
    ASSERT_FALSE(HasFailure()) << log;
    save(gl, "gl");
    save(vk, "vk");
    expect_grass(vk, host->target(), 0.3, "the Vulkan picture");
    const Pixels shaded = pixels_of(0.5, 11.5, 0.5, 5.8, [](double x, double z) { return surely(x, z, true, 0.5); });
    const Pixels strip = pixels_of(1.0, 11.0, -0.3, -0.1, [](double, double) { return true; });
    const double whole = mean_difference(gl, vk);
    std::printf("GL against Vulkan: mean difference %.2f levels; shaded grass %.2f / %.2f, ground strip %.2f / %.2f\n",
                whole, mean_level(gl, shaded), mean_level(vk, shaded), mean_level(gl, strip), mean_level(vk, strip));
    EXPECT_LT(whole, 0.2) << "the pictures differ (a broken part in one backend moves the mean by about 0.5)";
    EXPECT_NEAR(mean_level(gl, shaded), mean_level(vk, shaded), 2.0) << "the building's shadow on grass differs";
    EXPECT_NEAR(mean_level(gl, strip), mean_level(vk, strip), 3.0) << "grass's shadow on the ground differs";
}

INSTANTIATE_TEST_SUITE_P(Backends, CascadedShadowsAgreementTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });
#endif

} // namespace
} // namespace grass_test
