// G-buffer views on Vulkan (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc,
// grass_vk_gbuffer_target_desc; docs/engine-frames.md "Deferred renderers"), drawn by the
// Vulkan test host into a render pass of four RGBA8 UNORM colour attachments (the host's
// colour, then three more: TargetDesc::vk_gbuffer_formats) and depth, the layout {albedo,
// normal (UNORM), material, NONE}. Attachments 1-3 are cleared to a value of their own per
// channel, attachment 0 to the host's clear colour. Per tier (a field drawn by that tier
// alone, RenderTest::solo_tier_field), as GL's GBufferTest:
// - grass covers at least a fifth of the image, and there the albedo is grass-coloured (green
//   above red and blue), the normal unit length and facing the camera, the material roughness
//   1 and translucency 0.25;
// - the NONE attachment, every channel masked off (albedo and normal .a, material .ba) and
//   every pixel without grass keep their clear, byte for byte.
// The same at 4 samples (each attachment resolved), in a render pass and with dynamic
// rendering at 1 and 4 samples (the host's extra targets, extra_targets_vk.hpp), where grass
// drew told by the material attachment (by_material: no depth is read back there).
// With a motion desc, a VELOCITY attachment (RGBA32F, the context's velocity target too) holds
// what the motion view's velocity attachment holds. Plain views make nothing for G-buffers;
// each layout makes its own pipelines. A context without grass_vk_gbuffer_target_desc, or a
// layout of another attachment count, is refused naming both. The validation layers stay
// silent throughout (RenderTest::TearDown).
#include "gbuffer_checks.hpp"
#include "render_fixture.hpp"
#include "vk_intercept.hpp"

#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace grass_test {
namespace {

constexpr uint32_t kSize = 96;
constexpr int kColour = 4; // colour attachments
constexpr float kVelocityClear[4] = {9.0f, -9.0f, 7.0f, 5.0f};

const double kEye[3] = {2.0, 1.6, -0.6}, kAt[3] = {2.0, 0.0, 2.4};

class GBufferVkTest : public GBufferFixture {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        start(target(false));
    }
    // Four RGBA8 attachments ({colour, three more}), or with `velocity` two: the colour and an
    // RGBA32F velocity that is also the context's velocity target.
    static grass_host::TargetDesc target(bool velocity) {
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.unorm_color = true;
        t.read_depth = true;
        t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr(); // names grass's objects
        for (int c = 0; c < 4; ++c) t.clear_color[c] = c == 3 ? 1.0f : 0.1f;
        if (velocity) {
            t.vk_gbuffer_formats[0] = VK_FORMAT_R32G32B32A32_SFLOAT;
            t.vk_velocity_attachment = 1;
            std::memcpy(t.gbuffer_clear[0], kVelocityClear, sizeof kVelocityClear);
            return t;
        }
        for (int a = 0; a < 3; ++a) {
            t.vk_gbuffer_formats[a] = VK_FORMAT_R8G8B8A8_UNORM;
            for (int c = 0; c < 4; ++c) t.gbuffer_clear[a][c] = gbuffer_clear_byte(a + 1, c) / 255.0f;
        }
        return t;
    }
    grass_view_desc sized(grass_view_desc v) const {
        v.viewport[0] = v.viewport[1] = 0;
        v.viewport[2] = v.viewport[3] = kSize;
        return v;
    }
    // Draws a field of each tier alone into the G-buffer of `t` (target(false), perhaps at
    // other samples or with dynamic rendering) and checks its surface (expect_surface). Where
    // grass drew: its depth (`t.read_depth`), else by_material. Multisampled, the resolved
    // normals of blades are means (GBufferRead::mean_normals).
    void every_tier(const grass_host::TargetDesc& t, const char* how) {
        start(t);
        each_tier(kEye, kAt, [&](grass_tier_kind kind, const char* name, const grass_view_desc& whole) {
            const grass_host::Image f = render(sized(whole));
            ASSERT_EQ(f.gbuffer.size(), 3u);
            const size_t n = size_t(kSize) * kSize;
            GBufferRead g;
            g.pixels = n;
            size_t sky = n; // a pixel without grass: it keeps attachment 0's clear bytes
            g.byte = [&](int a, size_t p, int c) { return a == 0 ? f.rgba[p * 4 + c] : f.gbuffer[a - 1][p * 4 + c]; };
            g.before = [&](int a, size_t, int c) { return a == 0 ? f.rgba[sky * 4 + c] : gbuffer_clear_byte(a, c); };
            by_material(&g);
            if (t.read_depth) g.grass = g.touched = [&](size_t p) { return f.depth[p] < 1.0f; };
            for (size_t p = 0; p < n && sky == n; ++p) sky = g.touched(p) ? n : p;
            ASSERT_LT(sky, n) << how << ", " << name << ": a pixel without grass";
            g.mean_normals = t.samples > 1 && kind == GRASS_TIER_GEOMETRY;
            expect_surface(g, kEye, kAt, (std::string(how) + ", " + name).c_str());
            save(f, name); // the albedo, then the normal
            grass_host::Image normal = f;
            normal.rgba = f.gbuffer[0];
            save(normal, std::string(name) + ".normal");
        });
    }
};

TEST_P(GBufferVkTest, EveryTierWritesItsSurfaceAndNothingElse) { every_tier(target(false), "1 sample, render pass"); }

// As a host draws: 4 samples (each attachment resolved), a render pass or dynamic rendering.
TEST_P(GBufferVkTest, EveryTierAt4SamplesInARenderPass) {
    grass_host::TargetDesc t = target(false);
    t.samples = 4;
    t.read_depth = false;
    every_tier(t, "4 samples, render pass");
}

TEST_P(GBufferVkTest, EveryTierWithDynamicRendering) {
    grass_host::TargetDesc t = target(false);
    t.vk_dynamic_rendering = true;
    t.read_depth = false;
    every_tier(t, "1 sample, dynamic rendering");
}

TEST_P(GBufferVkTest, EveryTierAt4SamplesWithDynamicRendering) {
    grass_host::TargetDesc t = target(false);
    t.samples = 4;
    t.vk_dynamic_rendering = true;
    t.read_depth = false;
    every_tier(t, "4 samples, dynamic rendering");
}

TEST_P(GBufferVkTest, VelocityIsTheMotionViewsVelocity) {
    start(target(true));
    make_field(three_tier_field(32));
    const grass_view_desc v = sized(view(kEye, kAt));
    grass_view_motion_desc motion = panned_motion(v);
    grass_view_desc moving = v;
    moving.next = &motion;
    const grass_host::Image colour = render(moving);
    grass_view_gbuffer_desc layout = albedo_velocity();
    grass_view_pass_desc pass = gbuffer_pass(&layout);
    motion.next = &pass;
    const grass_host::Image g = render(moving);
    expect_same_velocity(colour.velocity, colour.depth, g.velocity, g.depth, kVelocityClear);
}

// Plain views make nothing for G-buffers, even in a context with a G-buffer target; the first
// G-buffer view makes the blade, volume and image pipelines of its layout and its block, a
// second layout three more, and a plain view after them none. Depth is the plain view's.
TEST_P(GBufferVkTest, AViewWithoutItMakesNothingForIt) {
    vk_intercept::clear_debug_records();
    start(target(false)); // a context made since
    make_field(three_tier_field(32));
    const auto named = [](const char* what) {
        size_t n = 0;
        for (const auto& name : vk_intercept::names()) n += name.second.find(what) != std::string::npos;
        return n;
    };
    const grass_view_desc plain = sized(view(kEye, kAt));
    render(plain);
    const grass_host::Image a = render(plain);
    const vk_intercept::Live plain_live = vk_intercept::live();
    EXPECT_EQ(named("G-buffer"), 0u) << "objects for G-buffers before any G-buffer view";
    EXPECT_EQ(named("view extras"), 0u) << "the view extras' objects before any G-buffer view";
    grass_view_gbuffer_desc layout = four_attachments();
    grass_view_pass_desc pass = gbuffer_pass(&layout);
    grass_view_desc deferred = plain;
    deferred.next = &pass;
    const grass_host::Image b = render(deferred);
    const vk_intercept::Live first = vk_intercept::live();
    EXPECT_EQ(first.pipelines_made - plain_live.pipelines_made, 3) << "the blade, volume and image G-buffer pipelines";
    EXPECT_EQ(named("G-buffer pipelines"), 3u);
    EXPECT_EQ(named("G-buffer block"), 1u) << "the GrassGBuffer block of the view slot";
    EXPECT_EQ(a.depth, b.depth) << "the G-buffer view's depth differs from the plain view's";
    render(deferred);
    EXPECT_EQ(vk_intercept::live().pipelines_made, first.pipelines_made) << "a second frame of the same layout";
    layout.attachments[1].write_mask = 0x1; // another layout: normal .r alone
    render(deferred);
    EXPECT_EQ(vk_intercept::live().pipelines_made - first.pipelines_made, 3) << "another layout's pipelines";
    const int64_t made = vk_intercept::live().pipelines_made;
    const grass_host::Image c = render(plain);
    EXPECT_EQ(vk_intercept::live().pipelines_made, made) << "a plain view after G-buffer views made pipelines";
    EXPECT_EQ(c.rgba, a.rgba);
}

TEST_P(GBufferVkTest, AContextWithoutTheTargetOrAnotherCountIsRefused) {
    make_field(field_desc(8));
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    grass_view_gbuffer_desc layout = four_attachments();
    layout.attachment_count = 3;
    pass.next = &layout;
    grass_view_desc v = sized(view(kEye, kAt));
    v.next = &pass;
    log.clear();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(log.find("grass_view_gbuffer_desc->attachment_count is 3, but the context's "
                       "grass_vk_gbuffer_target_desc.color_attachment_count is 4"),
              std::string::npos)
        << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
    EXPECT_EQ(grass_default_vk_gbuffer_target_desc().type, GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC);
    EXPECT_EQ(grass_default_vk_gbuffer_target_desc().color_attachment_count, 4u);

    grass_host::TargetDesc plain;
    plain.width = plain.height = kSize;
    start(plain);
    make_field(field_desc(8));
    layout = four_attachments();
    log.clear();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(log.find("GRASS_PASS_GBUFFER, but the context was made without a grass_vk_gbuffer_target_desc"),
              std::string::npos)
        << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
}

INSTANTIATE_TEST_SUITE_P(Vk, GBufferVkTest, ::testing::Values(GRASS_BACKEND_VULKAN),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
