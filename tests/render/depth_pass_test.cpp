// Depth passes (grass_view_pass_desc, GRASS_PASS_DEPTH; docs/engine-frames.md "Shadows: grass in
// the host's shadow maps"): a field of geometry, volume and image tiers seen by an
// orthographic light view whose lod origin is the main camera, drawn as a colour pass and as
// a depth pass into the same target:
// - the depth pass writes grass depth where the colour pass draws grass (within a few percent
//   of the pixels, at edges) and the colour pass's depth there (within a small tolerance);
// - it writes no colour: the cleared colour target is byte for byte as the host cleared it;
// - its bias (glPolygonOffset) pushes the grass's depth away from the light;
// - bad pass descs are refused naming the argument and the value; a Vulkan context created
//   without a grass_vk_depth_pass_desc refuses a depth view and nothing is begun.
// Vulkan draws the depth pass into the host's depth-only render pass (no colour attachment:
// TargetDesc::vk_depth_pass, Host::depth_only) with the validation layers silent; GL into the
// colour and depth framebuffer with the colour masks off.
#include "render_fixture.hpp"

#include <cmath>
#include <cstring>
#include <string>

namespace grass_test {
namespace {

constexpr uint32_t kSize = 128;          // the light view's target, pixels
constexpr uint32_t kCells = 48;          // 12 m x 12 m
const double kEye[3] = {6.0, 1.5, -1.0}; // the main camera: the lod origin
constexpr double kHalf = 7.0;            // the light view's half extent, metres

class DepthPassTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        start(target(true));
    }

    // Vulkan: with a depth-only pass given to grass (grass_vk_depth_pass_desc) or without.
    static grass_host::TargetDesc target(bool vk_depth_pass) {
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.read_depth = true;
        t.vk_depth_pass = vk_depth_pass;
        return t;
    }

    // A depth view's frame: on Vulkan in the host's depth-only pass.
    grass_host::Image render_depth(const grass_view_desc& v) {
        host->depth_only = true;
        grass_host::Image image = render(v);
        host->depth_only = false;
        return image;
    }

    // Geometry near, a volume of 2 slices, the horizontal slice far (RenderTest::three_tier_field).
    void make_tiered_field() { make_field(three_tier_field(kCells)); }

    // An orthographic light view, slanted (the sun 50 degrees up), over the field's centre;
    // its lod origin is the main camera. `pass` is chained when given.
    grass_view_desc light_view(const grass_view_pass_desc* pass) {
        const bool vulkan = GetParam() == GRASS_BACKEND_VULKAN;
        const double at[3] = {6.0, 0.0, 6.0}, eye[3] = {6.0 + 10.0, 16.0, 6.0 - 8.0};
        grass_view_desc v = view(eye, at);
        const double near_m = 1.0, far_m = 40.0;
        std::memset(v.projection, 0, sizeof v.projection);
        v.projection[0] = float(1.0 / kHalf);
        v.projection[5] = float((vulkan ? -1.0 : 1.0) / kHalf);
        v.projection[10] = float(vulkan ? -1.0 / (far_m - near_m) : -2.0 / (far_m - near_m));
        v.projection[14] = float(vulkan ? -near_m / (far_m - near_m) : -(far_m + near_m) / (far_m - near_m));
        v.projection[15] = 1.0f;
        lod_origin_ = grass_default_lod_origin_desc();
        std::memcpy(lod_origin_.position, kEye, sizeof kEye);
        lod_origin_.next = pass;
        v.next = &lod_origin_;
        return v;
    }

    static grass_view_pass_desc depth_pass(float constant = 0.0f, float slope = 0.0f) {
        grass_view_pass_desc p = grass_default_view_pass_desc();
        p.pass = GRASS_PASS_DEPTH;
        p.depth_bias_constant = constant;
        p.depth_bias_slope = slope;
        return p;
    }

    // The host's frame with grass drawing nothing: its cleared target.
    grass_host::Image cleared(const grass_view_desc& v) {
        host->draw_grass = [](grass_context*, void*) { return GRASS_SUCCESS; };
        grass_host::Image image = render(v);
        host->draw_grass = nullptr;
        return image;
    }

    static bool has_depth(float d) { return d < 1.0f - 1e-6f; } // cleared to 1 (GRASS_DEPTH_LESS)

    grass_lod_origin_desc lod_origin_{};
};

TEST_P(DepthPassTest, TheDepthPassWritesTheColourPassDepthAndNoColour) {
    make_tiered_field();
    const grass_host::Image colour = render(light_view(nullptr));
    grass_frame_stats stats{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) EXPECT_GT(stats.instances[k], 0u) << "tier kind " << k;

    const grass_view_pass_desc pass = depth_pass();
    const grass_view_desc v = light_view(&pass);
    const grass_host::Image depth = render_depth(v);
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
        EXPECT_GT(stats.instances[k], 0u) << "the depth pass draws tier kind " << k;
    }
    const grass_host::Image clear = cleared(v);
    save(colour, "depth_pass_colour");
    ASSERT_EQ(colour.depth.size(), size_t(kSize) * kSize);
    ASSERT_EQ(depth.depth.size(), colour.depth.size());

    // No colour: the target is as the host cleared it, byte for byte.
    ASSERT_EQ(depth.rgba.size(), clear.rgba.size());
    EXPECT_EQ(std::memcmp(depth.rgba.data(), clear.rgba.data(), clear.rgba.size()), 0) << "the depth pass wrote colour";

    // Grass depth where the colour pass has grass, and the colour pass's depth.
    size_t colour_grass = 0, disagree = 0, compared = 0, far_off = 0;
    double worst = 0.0;
    for (size_t i = 0; i < colour.depth.size(); ++i) {
        const bool a = has_depth(colour.depth[i]), b = has_depth(depth.depth[i]);
        colour_grass += a;
        disagree += a != b;
        if (!a || !b) continue;
        ++compared;
        const double d = std::fabs(double(colour.depth[i]) - double(depth.depth[i]));
        worst = std::max(worst, d);
        far_off += d > 1e-5; // 0.4 mm of the light's 39 m
    }
    EXPECT_GT(colour_grass, colour.depth.size() / 3) << "too little grass to compare";
    EXPECT_LE(disagree, colour_grass / 50) << "pixels with grass in one pass only, of " << colour_grass;
    EXPECT_LE(far_off, compared / 100) << "pixels whose depth differs by more than 1e-5 (worst " << worst << ")";
}

TEST_P(DepthPassTest, TheBiasPushesTheDepthAwayFromTheLight) {
    make_tiered_field();
    const grass_view_pass_desc plain = depth_pass(), biased = depth_pass(4096.0f, 2.0f);
    const grass_host::Image a = render_depth(light_view(&plain));
    const grass_host::Image b = render_depth(light_view(&biased));
    size_t both = 0, deeper = 0;
    for (size_t i = 0; i < a.depth.size(); ++i) {
        if (!has_depth(a.depth[i]) || !has_depth(b.depth[i])) continue;
        ++both;
        deeper += b.depth[i] > a.depth[i];
    }
    EXPECT_GT(both, a.depth.size() / 3);
    EXPECT_GT(deeper, both * 95 / 100) << "of " << both << " pixels with grass in both";
}

TEST_P(DepthPassTest, BadPassDescsAreRefusedAndVulkanWithoutADepthTargetRefusesADepthView) {
    if (GetParam() == GRASS_BACKEND_VULKAN) start(target(false)); // no grass_vk_depth_pass_desc
    make_tiered_field();
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    EXPECT_EQ(pass.type, GRASS_STRUCT_TYPE_VIEW_PASS_DESC);
    EXPECT_EQ(pass.pass, GRASS_PASS_COLOR);
    const auto refused = [&](const grass_view_desc& v, grass_result expected, const std::string& message) {
        log.clear();
        EXPECT_EQ(grass_begin_frame(ctx, &v), expected);
        EXPECT_NE(log.find(message), std::string::npos) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
    };
    pass.pass = static_cast<grass_pass_kind>(7);
    refused(light_view(&pass), GRASS_ERROR_INVALID_ARGUMENT, "grass_view_pass_desc->pass is 7");
    pass = depth_pass(NAN, 0.0f);
    refused(light_view(&pass), GRASS_ERROR_INVALID_ARGUMENT, "grass_view_pass_desc->depth_bias_constant");
    pass = depth_pass(0.0f, 100.0f);
    refused(light_view(&pass), GRASS_ERROR_INVALID_ARGUMENT, "grass_view_pass_desc->depth_bias_slope");
    pass = depth_pass();
    grass_view_desc debug = light_view(&pass);
    debug.flags = GRASS_VIEW_FLAG_DEBUG_TIERS;
    refused(debug, GRASS_ERROR_INVALID_ARGUMENT, "view->flags is 0x2 with grass_view_pass_desc->pass GRASS_PASS_DEPTH");
    // Twice in one chain.
    grass_view_pass_desc second = grass_default_view_pass_desc();
    pass.next = &second;
    refused(light_view(&pass), GRASS_ERROR_WRONG_STRUCT_TYPE, "GRASS_STRUCT_TYPE_VIEW_PASS_DESC, each at most once");
    pass.next = nullptr;
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        refused(light_view(&pass), GRASS_ERROR_INVALID_STATE,
                "created without a grass_vk_depth_pass_desc (chained on grass_vk_desc.next)");
    }
    // A colour pass desc draws what a view without one draws.
    const grass_host::Image plain = render(light_view(nullptr));
    const grass_view_pass_desc colour = grass_default_view_pass_desc();
    const grass_host::Image chained = render(light_view(&colour));
    EXPECT_GT(expect_grass(plain, host->target(), 0.3, "the colour pass"), 0.3);
    EXPECT_EQ(plain.rgba, chained.rgba) << "a GRASS_PASS_COLOR desc changed the picture";
}

INSTANTIATE_TEST_SUITE_P(Backends, DepthPassTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
