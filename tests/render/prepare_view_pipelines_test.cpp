// Pipelines before the first frame for the views of an engine's frame (grass.h "Pipelines
// before the first frame", GRASS_PIPELINE_FEATURE_DEPTH_PASS ... _GBUFFER), on both
// backends, counted through the loaders the hosts hand grass (Vulkan: vkCreateGraphicsPipelines
// in grass's dispatch table, vk_intercept.hpp; GL: glCreateProgram, gl_program_spy.hpp). A
// field of blades, drawn into a target that holds every view: GL a framebuffer of its own
// (draw buffer 0 RGBA8, 1 RGBA32F for velocity, depth), Vulkan the host's pass with an RGBA32F
// attachment 1 that is its velocity and G-buffer target, and a depth-only target.
// - After grass_prepare_pipelines(GRASS_PIPELINE_FEATURE_ALL_VIEWS with the G-buffer layout),
//   which makes one variant per view mode (9), a depth view, a receiving view, a motion view,
//   a lit view, a G-buffer view with velocity and a view receiving, moving and lit at once
//   create no pipeline or program; each draws grass.
// - Without it, the first frame of each view creates its own (the behaviour before).
// - Vulkan: a context without depth, velocity or G-buffer targets skips what it cannot draw
//   (the receiving and lit modes alone are made) and succeeds.
// The validation layers stay silent (RenderTest::TearDown).
#include "gl_program_spy.hpp"
#include "gl_test_functions.hpp"
#include "render_fixture.hpp"
#include "vk_intercept.hpp"

#include <vulkan/vulkan.h>

#include <cstring>
#include <string>
#include <vector>

namespace grass_test {
namespace {

constexpr uint32_t kSize = 64;
constexpr int kMapTexels = 4;
const double kEye[3] = {2.0, 1.2, -0.4}, kAt[3] = {2.0, 0.0, 2.0};

class PrepareViewPipelines : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        if (GetParam() == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_program_spy_filter;
        if (GetParam() == GRASS_BACKEND_VULKAN) {
            t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr();
            t.read_depth = true;
            t.vk_depth_pass = true;
            t.vk_gbuffer_formats[0] = VK_FORMAT_R32G32B32A32_SFLOAT;
            t.vk_velocity_attachment = 1;
        }
        start(t);
        make_field(field_desc(16));
        const std::vector<float> depths(size_t(kMapTexels) * kMapTexels, 0.5f);
        if (GetParam() == GRASS_BACKEND_VULKAN) {
            std::string error;
            shadow_map_ = host->make_vk_shadow_map(kMapTexels, 1, depths.data(), 5, &error); // SHADER_READ_ONLY
            ASSERT_NE(shadow_map_, 0u) << error;
            return;
        }
        load_gl_test_functions(*host, &gl);
        const auto storage_3d =
            reinterpret_cast<PFNGLTEXTURESTORAGE3DPROC>(host->gl_proc_address("glTextureStorage3D"));
        const auto sub_image_3d =
            reinterpret_cast<PFNGLTEXTURESUBIMAGE3DPROC>(host->gl_proc_address("glTextureSubImage3D"));
        ASSERT_TRUE(storage_3d && sub_image_3d);
        const GLenum formats[3] = {GL_RGBA8, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
        gl.CreateTextures(GL_TEXTURE_2D, 3, textures_);
        for (int i = 0; i < 3; ++i) gl.TextureStorage2D(textures_[i], 1, formats[i], kSize, kSize);
        gl.CreateFramebuffers(1, &fbo_);
        for (int i = 0; i < 2; ++i) gl.NamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0 + i, textures_[i], 0);
        gl.NamedFramebufferTexture(fbo_, GL_DEPTH_ATTACHMENT, textures_[2], 0);
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        gl.NamedFramebufferDrawBuffers(fbo_, 2, buffers);
        GLuint map = 0;
        gl.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, &map);
        storage_3d(map, 1, GL_DEPTH_COMPONENT32F, kMapTexels, kMapTexels, 1);
        sub_image_3d(map, 0, 0, 0, 0, kMapTexels, kMapTexels, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
        shadow_map_ = map;
    }
    void TearDown() override {
        if (fbo_ != 0) {
            gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
            gl.DeleteFramebuffers(1, &fbo_);
            gl.DeleteTextures(3, textures_);
            const GLuint map = GLuint(shadow_map_);
            gl.DeleteTextures(1, &map);
        }
        RenderTest::TearDown();
    }

    // Pipelines (Vulkan) or programs (GL) grass has created so far.
    int64_t made() const {
        return GetParam() == GRASS_BACKEND_VULKAN ? vk_intercept::live().pipelines_made : gl_program_spy().created;
    }

    // Draws `v` (Vulkan: a depth view in the depth-only pass); the instances drawn.
    uint64_t draw(grass_view_desc v, bool depth_view) {
        v.viewport[0] = v.viewport[1] = 0;
        v.viewport[2] = v.viewport[3] = kSize;
        if (GetParam() == GRASS_BACKEND_VULKAN) {
            grass_host::Image image;
            std::string error;
            host->depth_only = depth_view;
            EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error << log;
            host->depth_only = false;
        } else {
            gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
            const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f}, far = 1.0f;
            gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 0, clear);
            gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 1, clear);
            gl.ClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &far);
            EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
            EXPECT_EQ(grass_gl_render(ctx), GRASS_SUCCESS) << log;
            EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS) << log;
        }
        grass_frame_stats stats{};
        EXPECT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        uint64_t instances = 0;
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) instances += stats.instances[k];
        return instances;
    }

    // The G-buffer layout of the views: albedo at attachment 0, velocity (float) at 1.
    static grass_view_gbuffer_desc layout() {
        grass_view_gbuffer_desc g = grass_default_view_gbuffer_desc();
        g.attachment_count = 2;
        g.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
        g.attachments[1].semantic = GRASS_GBUFFER_VELOCITY;
        g.attachments[1].format = GRASS_GBUFFER_FORMAT_FLOAT;
        return g;
    }

    struct ViewFrame {
        const char* name;
        int64_t made; // pipelines or programs its frame created
        uint64_t instances;
    };
    // One frame of each view of an engine's frame, in turn, after a plain one.
    std::vector<ViewFrame> frames_of_every_view() {
        const grass_view_desc plain = view(kEye, kAt);
        draw(plain, false);
        grass_view_pass_desc depth = grass_default_view_pass_desc();
        depth.pass = GRASS_PASS_DEPTH;
        grass_shadow_receive_desc shadow = grass_default_shadow_receive_desc();
        shadow.shadow_map = shadow_map_;
        shadow.vk_image_layout = 5; // VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
        grass_view_motion_desc motion = grass_default_view_motion_desc();
        std::memcpy(motion.previous_view, plain.view, sizeof motion.previous_view);
        std::memcpy(motion.previous_projection, plain.projection, sizeof motion.previous_projection);
        std::memcpy(motion.previous_camera_position, plain.camera_position, sizeof motion.previous_camera_position);
        motion.velocity_attachment = 1;
        grass_view_lights_desc lights = grass_default_view_lights_desc();
        const grass_view_gbuffer_desc g = layout();
        grass_view_pass_desc gbuffer = grass_default_view_pass_desc();
        gbuffer.pass = GRASS_PASS_GBUFFER;
        gbuffer.next = &g;
        grass_view_motion_desc gbuffer_motion = motion;
        gbuffer_motion.next = &gbuffer;
        grass_view_motion_desc all_three = motion;
        grass_shadow_receive_desc all_shadow = shadow;
        grass_view_lights_desc all_lights = lights;
        all_three.next = &all_shadow;
        all_shadow.next = &all_lights;
        const struct {
            const void* next;
            const char* name;
        } views[] = {{&depth, "a depth view"},
                     {&shadow, "a receiving view"},
                     {&motion, "a motion view"},
                     {&lights, "a lit view"},
                     {&gbuffer_motion, "a G-buffer view"},
                     {&all_three, "a view receiving, moving and lit"}};
        std::vector<ViewFrame> frames;
        for (const auto& each : views) {
            grass_view_desc v = plain;
            v.next = each.next;
            const int64_t before = made();
            const uint64_t instances = draw(v, each.next == &depth);
            frames.push_back({each.name, made() - before, instances});
        }
        return frames;
    }

    GlTestFunctions gl{};
    GLuint fbo_ = 0;
    GLuint textures_[3] = {};
    uint64_t shadow_map_ = 0; // GL: a depth texture array's name; Vulkan: the host's VkImageView
};

TEST_P(PrepareViewPipelines, AfterPreparationNoViewCreatesAPipeline) {
    grass_pipeline_desc d = grass_default_pipeline_desc();
    d.features = GRASS_PIPELINE_FEATURE_ALL_VIEWS;
    const grass_view_gbuffer_desc g = layout();
    d.next = &g;
    const int64_t before = made();
    ASSERT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_SUCCESS) << log;
    EXPECT_EQ(made() - before, 9)
        << "one variant of the blades per view mode: depth, 7 combinations of receiving, motion and lights, G-buffer";
    for (const ViewFrame& f : frames_of_every_view()) {
        EXPECT_GT(f.instances, 0u) << f.name << " drew no grass";
        EXPECT_EQ(f.made, 0) << f.name << " created a pipeline or program after preparation";
    }
}

TEST_P(PrepareViewPipelines, WithoutPreparationEachViewCreatesItsOwn) {
    for (const ViewFrame& f : frames_of_every_view()) {
        EXPECT_GT(f.instances, 0u) << f.name << " drew no grass";
        EXPECT_GT(f.made, 0) << f.name << " created nothing: the hook does not see its frame";
    }
}

// A Vulkan context without a depth-only, velocity or G-buffer target draws no depth, motion
// or G-buffer view: preparing them skips them and makes the receiving and lit modes alone.
TEST_P(PrepareViewPipelines, AVulkanContextWithoutTheTargetsSkipsTheirViews) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan's targets";
    grass_host::TargetDesc t;
    t.width = t.height = kSize;
    t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr();
    start(t);
    make_field(field_desc(16));
    grass_pipeline_desc d = grass_default_pipeline_desc();
    d.features = GRASS_PIPELINE_FEATURE_ALL_VIEWS;
    grass_view_gbuffer_desc g = layout();
    d.next = &g;
    const int64_t before = made();
    ASSERT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_SUCCESS) << log;
    EXPECT_EQ(made() - before, 3) << "receiving, lit, and both";
}

INSTANTIATE_TEST_SUITE_P(Backends, PrepareViewPipelines, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
