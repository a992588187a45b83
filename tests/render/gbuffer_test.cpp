// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc; docs/integration.md "Deferred
// renderers") on GL, drawn into a framebuffer the test makes: four RGBA8 attachments, the
// host's draw buffers 0-3 = {albedo, normal (UNORM), material, NONE}, each prefilled with a
// pattern of bytes that differs per pixel and channel, and a depth attachment. Per tier (a
// field drawn by that tier alone, RenderTest::solo_tier_field):
// - grass covers at least a fifth of the image, and there the albedo is grass-coloured (green
//   above red and blue), the normal unit length and facing the camera (as each tier's
//   lighting turns it), the material roughness 1 and translucency 0.25;
// - the NONE attachment, every channel masked off (albedo and normal .a, material .ba) and
//   every pixel without grass keep their pattern, byte for byte;
// - the host's draw buffers, colour masks, blend enables and uniform binding 5 come back.
// The same at 4 samples, as a host makes the framebuffer (multisampled textures, cleared),
// after each attachment's resolve (EveryTierAt4Samples).
// With a motion desc, a VELOCITY attachment (RGBA32F) holds what the motion view's velocity
// attachment holds. A view without it draws with programs that declare no GrassGBuffer block,
// and after it makes none. Bad layouts and a framebuffer without the attachments are refused
// naming the field. Vulkan: GBufferVkTest, and VulkanWritesWhatGlWrites below.
#include "gbuffer_checks.hpp"
#include "gl_program_spy.hpp"
#include "gl_test_functions.hpp"
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace grass_test {
namespace {

constexpr int kSize = 96;
constexpr int kColour = 4; // colour attachments

// The prefilled byte of attachment `a` at pixel `p`, channel `c`.
uint8_t pattern(int a, size_t p, int c) {
    return static_cast<uint8_t>((p * 7u + size_t(c) * 61u + size_t(a) * 101u + (p >> 5) * 13u) & 255u);
}

// What a view left in the test's framebuffer; rows bottom first (GL's).
struct Frame {
    std::vector<uint8_t> colour[kColour];
    std::vector<float> velocity; // the velocity test's attachment 1 (RGBA32F)
    std::vector<float> depth;
    bool grass(size_t p) const { return depth[p] < 1.0f; }
};

class GBufferTest : public GBufferFixture {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.gl_proc_filter = &gl_program_spy_filter;
        start(t);
        load_gl_test_functions(*host, &gl);
    }
    void TearDown() override {
        release_target();
        RenderTest::TearDown();
    }

    // Attachments 0-3 (RGBA8; attachment 1 RGBA32F with `float_velocity`) and depth, draw
    // buffers 0-3 = attachments 0-3.
    void make_target(bool float_velocity) {
        release_target();
        float_velocity_ = float_velocity;
        gl.CreateTextures(GL_TEXTURE_2D, kColour + 1, textures_);
        for (int i = 0; i < kColour; ++i) {
            gl.TextureStorage2D(textures_[i], 1, i == 1 && float_velocity ? GL_RGBA32F : GL_RGBA8, kSize, kSize);
        }
        gl.TextureStorage2D(textures_[kColour], 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        gl.CreateFramebuffers(1, &fbo_);
        GLenum buffers[kColour];
        for (int i = 0; i < kColour; ++i) {
            gl.NamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0 + i, textures_[i], 0);
            buffers[i] = GL_COLOR_ATTACHMENT0 + i;
        }
        gl.NamedFramebufferTexture(fbo_, GL_DEPTH_ATTACHMENT, textures_[kColour], 0);
        gl.NamedFramebufferDrawBuffers(fbo_, kColour, buffers);
    }
    void release_target() {
        if (fbo_ == 0) return;
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl.DeleteFramebuffers(1, &fbo_);
        gl.DeleteTextures(kColour + 1, textures_);
        fbo_ = 0;
    }

    // Prefills the attachments (pattern(); the float one with its clear), draws `v` and reads
    // the target back.
    Frame draw(const grass_view_desc& v) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
        const size_t n = size_t(kSize) * kSize;
        std::vector<uint8_t> bytes(n * 4);
        for (int a = 0; a < kColour; ++a) {
            if (a == 1 && float_velocity_) {
                gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 1, kVelocityClear);
                continue;
            }
            for (size_t p = 0; p < n; ++p) {
                for (int c = 0; c < 4; ++c) bytes[p * 4 + c] = pattern(a, p, c);
            }
            gl.TextureSubImage2D(textures_[a], 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        }
        const float far = 1.0f;
        gl.ClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &far);
        draw_whole_view(ctx, v, kSize, log);
        Frame f;
        for (int a = 0; a < kColour; ++a) {
            if (a == 1 && float_velocity_) continue;
            f.colour[a].resize(n * 4);
            gl.GetTextureImage(textures_[a], 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4), f.colour[a].data());
        }
        if (float_velocity_) {
            f.velocity.resize(n * 4);
            gl.GetTextureImage(textures_[1], 0, GL_RGBA, GL_FLOAT, GLsizei(n * 16), f.velocity.data());
        }
        f.depth.resize(n);
        gl.GetTextureImage(textures_[kColour], 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(n * 4), f.depth.data());
        return f;
    }

    // As a host draws at 4 samples: attachments 0-3 (RGBA8) and depth multisampled textures,
    // draw buffers 0-3, each cleared to gbuffer_clear_byte (a multisampled texture takes no
    // upload); draws `v`, then resolves each attachment (glBlitNamedFramebuffer) into a
    // single-sample RGBA8 texture and reads that back (Frame::colour; no depth).
    Frame draw_4_samples(const grass_view_desc& v) {
        GLuint ms[kColour + 1] = {}, resolved[kColour] = {}, fbos[2] = {};
        gl.CreateTextures(GL_TEXTURE_2D_MULTISAMPLE, kColour + 1, ms);
        gl.CreateTextures(GL_TEXTURE_2D, kColour, resolved);
        gl.CreateFramebuffers(2, fbos);
        GLenum buffers[kColour];
        for (int i = 0; i < kColour; ++i) {
            gl.TextureStorage2DMultisample(ms[i], 4, GL_RGBA8, kSize, kSize, GL_TRUE);
            gl.NamedFramebufferTexture(fbos[0], GL_COLOR_ATTACHMENT0 + i, ms[i], 0);
            gl.TextureStorage2D(resolved[i], 1, GL_RGBA8, kSize, kSize);
            gl.NamedFramebufferTexture(fbos[1], GL_COLOR_ATTACHMENT0 + i, resolved[i], 0);
            buffers[i] = GL_COLOR_ATTACHMENT0 + i;
        }
        gl.TextureStorage2DMultisample(ms[kColour], 4, GL_DEPTH_COMPONENT32F, kSize, kSize, GL_TRUE);
        gl.NamedFramebufferTexture(fbos[0], GL_DEPTH_ATTACHMENT, ms[kColour], 0);
        gl.NamedFramebufferDrawBuffers(fbos[0], kColour, buffers);
        for (int a = 0; a < kColour; ++a) {
            float clear[4];
            for (int c = 0; c < 4; ++c) clear[c] = gbuffer_clear_byte(a, c) / 255.0f;
            gl.ClearNamedFramebufferfv(fbos[0], GL_COLOR, a, clear);
        }
        const float far = 1.0f;
        gl.ClearNamedFramebufferfv(fbos[0], GL_DEPTH, 0, &far);
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbos[0]);
        draw_whole_view(ctx, v, kSize, log);
        Frame f;
        const size_t n = size_t(kSize) * kSize;
        for (int a = 0; a < kColour; ++a) {
            gl.NamedFramebufferReadBuffer(fbos[0], buffers[a]);
            gl.NamedFramebufferDrawBuffers(fbos[1], 1, &buffers[a]);
            gl.BlitNamedFramebuffer(fbos[0], fbos[1], 0, 0, kSize, kSize, 0, 0, kSize, kSize, GL_COLOR_BUFFER_BIT,
                                    GL_NEAREST);
            f.colour[a].resize(n * 4);
            gl.GetTextureImage(resolved[a], 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4), f.colour[a].data());
        }
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl.DeleteFramebuffers(2, fbos);
        gl.DeleteTextures(kColour + 1, ms);
        gl.DeleteTextures(kColour, resolved);
        return f;
    }

    static constexpr float kVelocityClear[4] = {9.0f, -9.0f, 7.0f, 5.0f};
    GlTestFunctions gl{};
    GLuint fbo_ = 0;
    GLuint textures_[kColour + 1] = {};
    bool float_velocity_ = false;
};

constexpr float GBufferTest::kVelocityClear[4];

const double kEye[3] = {2.0, 1.6, -0.6}, kAt[3] = {2.0, 0.0, 2.4};

TEST_P(GBufferTest, EveryTierWritesItsSurfaceAndNothingElse) {
    make_target(false);
    // The host's state of draw buffers 0-3 and uniform binding 5, to come back.
    GLuint host_buffer = 0;
    gl.CreateBuffers(1, &host_buffer);
    gl.NamedBufferData(host_buffer, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBufferRange(GL_UNIFORM_BUFFER, 5, host_buffer, 256, 512);
    gl.Enablei(GL_BLEND, 2);
    gl.ColorMaski(3, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    each_tier(kEye, kAt, [&](grass_tier_kind, const char* name, const grass_view_desc& v) {
        const Frame f = draw(v);
        // Attachment 3 keeps its pattern though the host's own mask there leaves r and b writable.
        GBufferRead g;
        g.pixels = size_t(kSize) * kSize;
        g.byte = [&](int a, size_t p, int c) { return f.colour[a][p * 4 + c]; };
        g.before = pattern;
        g.grass = [&](size_t p) { return f.grass(p); };
        expect_surface(g, kEye, kAt, name);
    });
    GLint buffers[kColour] = {}, binding = 0;
    for (int i = 0; i < kColour; ++i) {
        gl.GetIntegerv(GL_DRAW_BUFFER0 + i, &buffers[i]);
        EXPECT_EQ(buffers[i], GL_COLOR_ATTACHMENT0 + i) << "draw buffer " << i;
    }
    gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 5, &binding);
    EXPECT_EQ(GLuint(binding), host_buffer) << "uniform binding 5";
    GLboolean mask[4] = {};
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, 3, mask);
    EXPECT_TRUE(mask[0] == GL_TRUE && mask[1] == GL_FALSE && mask[2] == GL_TRUE && mask[3] == GL_FALSE)
        << "draw buffer 3's colour mask";
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, 1, mask);
    EXPECT_TRUE(mask[0] == GL_TRUE && mask[1] == GL_TRUE && mask[2] == GL_TRUE && mask[3] == GL_TRUE)
        << "draw buffer 1's colour mask";
    EXPECT_TRUE(gl.IsEnabledi(GL_BLEND, 2)) << "draw buffer 2's blend";
    EXPECT_FALSE(gl.IsEnabledi(GL_BLEND, 1)) << "draw buffer 1's blend";
    gl.Disablei(GL_BLEND, 2);
    gl.ColorMaski(3, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DeleteBuffers(1, &host_buffer);
}

// As a host draws at 4 samples (draw_4_samples): per tier the same checks after the resolve,
// where grass drew found by_material; the blades' resolved normals are means of several
// blades' (GBufferRead::mean_normals).
TEST_P(GBufferTest, EveryTierAt4Samples) {
    each_tier(kEye, kAt, [&](grass_tier_kind kind, const char* name, const grass_view_desc& v) {
        const Frame f = draw_4_samples(v);
        GBufferRead g;
        g.pixels = size_t(kSize) * kSize;
        g.byte = [&](int a, size_t p, int c) { return f.colour[a][p * 4 + c]; };
        g.before = [](int a, size_t, int c) { return gbuffer_clear_byte(a, c); };
        by_material(&g);
        g.mean_normals = kind == GRASS_TIER_GEOMETRY;
        expect_surface(g, kEye, kAt, (std::string("4 samples, ") + name).c_str());
    });
}

TEST_P(GBufferTest, VelocityIsTheMotionViewsVelocity) {
    make_target(true);
    make_field(three_tier_field(32));
    grass_view_desc v = view(kEye, kAt);
    grass_view_motion_desc motion = panned_motion(v);
    // The motion view: its lit colour to draw buffer 0, its velocity to draw buffer 1.
    grass_view_desc moving = v;
    moving.next = &motion;
    const Frame colour = draw(moving);
    // The G-buffer view: albedo to draw buffer 0, velocity to draw buffer 1.
    grass_view_gbuffer_desc layout = albedo_velocity();
    grass_view_pass_desc pass = gbuffer_pass(&layout);
    motion.next = &pass;
    const Frame g = draw(moving);
    expect_same_velocity(colour.velocity, colour.depth, g.velocity, g.depth, kVelocityClear);
    // Without the motion desc the VELOCITY attachment is refused, naming it.
    log.clear();
    grass_view_desc still = v;
    still.next = &pass;
    EXPECT_EQ(grass_begin_frame(ctx, &still), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(log.find("grass_view_gbuffer_desc->attachments[1].semantic is GRASS_GBUFFER_VELOCITY, but view->next "
                       "chains no grass_view_motion_desc"),
              std::string::npos)
        << log;
}

TEST_P(GBufferTest, AViewWithoutItKeepsItsPrograms) {
    make_target(false);
    make_field(three_tier_field(32));
    const grass_view_desc plain = view(kEye, kAt);
    gl_program_spy().used.clear();
    gl_program_spy().created = 0;
    const Frame a = draw(plain);
    const std::set<GLuint> plain_programs = gl_program_spy().used;
    ASSERT_GE(plain_programs.size(), 3u) << "a program per tier kind";
    for (const GLuint program : plain_programs) {
        EXPECT_EQ(gl.GetUniformBlockIndex(program, "GrassGBuffer"), GL_INVALID_INDEX)
            << "program " << program << " of a colour view declares the GrassGBuffer block";
    }
    const int64_t plain_created = gl_program_spy().created;
    grass_view_gbuffer_desc layout = four_attachments();
    grass_view_pass_desc pass = gbuffer_pass(&layout);
    grass_view_desc deferred = plain;
    deferred.next = &pass;
    gl_program_spy().used.clear();
    const Frame b = draw(deferred);
    EXPECT_GE(gl_program_spy().created - plain_created, 3) << "a G-buffer view compiles its own variants";
    for (const GLuint program : gl_program_spy().used) {
        EXPECT_EQ(plain_programs.count(program), 0u) << "the G-buffer view drew with a colour view's program";
        EXPECT_NE(gl.GetUniformBlockIndex(program, "GrassGBuffer"), GL_INVALID_INDEX);
    }
    EXPECT_EQ(a.depth, b.depth) << "the G-buffer view's depth differs from the colour view's";
    const int64_t created = gl_program_spy().created;
    gl_program_spy().used.clear();
    const Frame c = draw(plain);
    EXPECT_EQ(gl_program_spy().created, created) << "a colour view after a G-buffer view made programs";
    EXPECT_EQ(gl_program_spy().used, plain_programs);
    EXPECT_EQ(c.colour[0], a.colour[0]);
}

TEST_P(GBufferTest, BadLayoutsAndTargetsAreRefused) {
    make_target(false);
    make_field(field_desc(8));
    const grass_view_desc plain = view(kEye, kAt);
    EXPECT_EQ(grass_default_view_gbuffer_desc().type, GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC);
    EXPECT_EQ(grass_default_view_gbuffer_desc().attachment_count, 1u);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    // A framebuffer without a draw buffer at an attachment grass writes draws nothing.
    grass_view_gbuffer_desc wide = four_attachments();
    wide.attachment_count = 6;
    wide.attachments[5].semantic = GRASS_GBUFFER_MATERIAL;
    wide.attachments[2].semantic = GRASS_GBUFFER_NONE;
    for (const bool default_framebuffer : {false, true}) {
        pass.next = &wide;
        grass_view_desc v = plain;
        v.next = &pass;
        gl.BindFramebuffer(GL_FRAMEBUFFER, default_framebuffer ? 0u : fbo_);
        log.clear();
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
        EXPECT_EQ(grass_gl_render(ctx), GRASS_ERROR_INVALID_STATE);
        EXPECT_NE(log.find(std::string("grass_view_gbuffer_desc->attachments[") + (default_framebuffer ? "0" : "5") +
                           "] is written, but the bound draw framebuffer"),
                  std::string::npos)
            << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
}

// The Vulkan backend writes the G-buffer GL writes: the four-attachment layout of the first
// test over a three-tier field, drawn by GL into the test's framebuffer and by Vulkan into the
// Vulkan host's pass of four RGBA8 UNORM attachments (GBufferVkTest's). Grass covers the same
// share of pixels (within 1%), and per written attachment and channel the mean over grass
// pixels agrees within half a level of 255 (seen: within 0.03).
TEST_P(GBufferTest, VulkanWritesWhatGlWrites) {
    bool vulkan = false;
    for (const grass_backend b : enabled_backends()) vulkan = vulkan || b == GRASS_BACKEND_VULKAN;
    if (!vulkan) GTEST_SKIP() << "a build without Vulkan";
    make_target(false);
    make_field(three_tier_field(32));
    grass_view_gbuffer_desc layout = four_attachments();
    grass_view_pass_desc pass = gbuffer_pass(&layout);
    grass_view_desc v = view(kEye, kAt);
    v.next = &pass;
    const Frame gl_frame = draw(v);
    release_target();
    grass_host::TargetDesc t;
    t.width = t.height = kSize;
    t.unorm_color = true;
    t.read_depth = true;
    for (uint32_t& f : t.vk_gbuffer_formats) f = 37; // VK_FORMAT_R8G8B8A8_UNORM
    start(t, GRASS_BACKEND_VULKAN);
    make_field(three_tier_field(32));
    grass_view_desc vk_view = view(kEye, kAt);
    vk_view.next = &pass;
    vk_view.viewport[0] = vk_view.viewport[1] = 0;
    vk_view.viewport[2] = vk_view.viewport[3] = kSize;
    const grass_host::Image vk = render(vk_view);
    ASSERT_EQ(vk.gbuffer.size(), 3u);
    const size_t n = size_t(kSize) * kSize;
    // [backend][attachment 0-2][channel 0-2]: sums over grass pixels.
    double sums[2][3][3] = {};
    size_t grass[2] = {};
    for (size_t p = 0; p < n; ++p) {
        for (int b = 0; b < 2; ++b) {
            if ((b == 0 ? gl_frame.depth[p] : vk.depth[p]) >= 1.0f) continue;
            ++grass[b];
            for (int a = 0; a < 3; ++a) {
                const uint8_t* texel = b == 0   ? &gl_frame.colour[a][p * 4]
                                       : a == 0 ? &vk.rgba[p * 4]
                                                : &vk.gbuffer[a - 1][p * 4];
                for (int c = 0; c < 3; ++c) sums[b][a][c] += texel[c];
            }
        }
    }
    const char* const names[3] = {"albedo", "normal", "material"};
    EXPECT_GT(grass[0], n / 5) << "GL's grass pixels";
    EXPECT_NEAR(double(grass[1]), double(grass[0]), 0.01 * n) << "Vulkan's grass pixels against GL's";
    for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < (a == 2 ? 2 : 3); ++c) {
            const double gl_mean = sums[0][a][c] / double(grass[0]), vk_mean = sums[1][a][c] / double(grass[1]);
            std::printf("%s.%c: GL %.2f, Vulkan %.2f\n", names[a], "rgb"[c], gl_mean, vk_mean);
            EXPECT_NEAR(vk_mean, gl_mean, 0.5) << names[a] << " channel " << c;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Gl, GBufferTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
