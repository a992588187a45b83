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
// With a motion desc, a VELOCITY attachment (RGBA32F) holds what the motion view's velocity
// attachment holds. A view without it draws with programs that declare no GrassGBuffer block,
// and after it makes none. Bad layouts and a framebuffer without the attachments are refused
// naming the field; a Vulkan context refuses the view.
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

class GBufferTest : public RenderTest {
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
        grass_view_desc d = v;
        d.viewport[0] = d.viewport[1] = 0;
        d.viewport[2] = d.viewport[3] = kSize;
        EXPECT_EQ(grass_begin_frame(ctx, &d), GRASS_SUCCESS) << log;
        EXPECT_EQ(grass_gl_render(ctx), GRASS_SUCCESS) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS) << log;
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

    // The four-attachment layout: albedo, normal (UNORM), material, NONE; default masks.
    static grass_view_gbuffer_desc four_attachments() {
        grass_view_gbuffer_desc g = grass_default_view_gbuffer_desc();
        g.attachment_count = 4;
        g.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
        g.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
        g.attachments[2].semantic = GRASS_GBUFFER_MATERIAL;
        g.attachments[3].semantic = GRASS_GBUFFER_NONE;
        return g;
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
    const grass_tier_kind kinds[3] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
    const char* const names[3] = {"geometry", "volume", "image"};
    // The direction towards the camera, roughly (the view's axis reversed).
    double to_camera[3] = {kEye[0] - kAt[0], kEye[1] - kAt[1], kEye[2] - kAt[2]};
    const double len =
        std::sqrt(to_camera[0] * to_camera[0] + to_camera[1] * to_camera[1] + to_camera[2] * to_camera[2]);
    for (double& c : to_camera) c /= len;
    // The host's state of draw buffers 0-3 and uniform binding 5, to come back.
    GLuint host_buffer = 0;
    gl.CreateBuffers(1, &host_buffer);
    gl.NamedBufferData(host_buffer, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBufferRange(GL_UNIFORM_BUFFER, 5, host_buffer, 256, 512);
    gl.Enablei(GL_BLEND, 2);
    gl.ColorMaski(3, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    for (int k = 0; k < 3; ++k) {
        const grass_field_id field =
            make_field(solo_tier_field(16, kinds[k], kinds[k] == GRASS_TIER_VOLUME ? 2u : 0u, 4));
        grass_view_pass_desc pass = grass_default_view_pass_desc();
        pass.pass = GRASS_PASS_GBUFFER;
        grass_view_gbuffer_desc layout = four_attachments();
        pass.next = &layout;
        grass_view_desc v = view(kEye, kAt);
        v.next = &pass;
        const Frame f = draw(v);
        size_t grass = 0, green = 0, unit = 0, facing = 0, material = 0, kept = 0, changed = 0;
        const size_t n = size_t(kSize) * kSize;
        for (size_t p = 0; p < n; ++p) {
            // Bytes that must keep their pattern: attachment 3 (NONE; the host's own mask there
            // leaves r and b writable, and grass still writes nothing), every masked-off channel,
            // every channel of a pixel without grass.
            for (int a = 0; a < kColour; ++a) {
                for (int c = 0; c < 4; ++c) {
                    const bool written = f.grass(p) && (a == 0 || a == 1 ? c < 3 : a == 2 ? c < 2 : false);
                    if (written) continue;
                    ++kept;
                    changed += f.colour[a][p * 4 + c] != pattern(a, p, c) ? 1u : 0u;
                }
            }
            if (!f.grass(p)) continue;
            ++grass;
            const uint8_t* albedo = &f.colour[0][p * 4];
            green += albedo[1] > albedo[0] && albedo[1] > albedo[2] ? 1u : 0u;
            double nrm[3], n2 = 0.0, dot = 0.0;
            for (int c = 0; c < 3; ++c) {
                nrm[c] = f.colour[1][p * 4 + c] / 255.0 * 2.0 - 1.0;
                n2 += nrm[c] * nrm[c];
                dot += nrm[c] * to_camera[c];
            }
            unit += std::fabs(std::sqrt(n2) - 1.0) < 0.03 ? 1u : 0u;
            facing += dot > 0.0 ? 1u : 0u;
            const uint8_t* m = &f.colour[2][p * 4];
            material += m[0] == 255 && m[1] == 64 ? 1u : 0u;
        }
        std::printf("%s: %zu of %zu pixels grass; green albedo %zu, unit normals %zu, facing %zu\n", names[k], grass, n,
                    green, unit, facing);
        EXPECT_GT(grass, n / 5) << names[k] << ": grass pixels";
        EXPECT_EQ(changed, 0u) << names[k] << ": of " << kept << " bytes grass must not write";
        EXPECT_GE(green * 100, grass * 95) << names[k] << ": green albedo, " << green << " of " << grass;
        EXPECT_GE(unit * 100, grass * 98) << names[k] << ": unit normals, " << unit << " of " << grass;
        EXPECT_GE(facing * 100, grass * 90) << names[k] << ": normals facing the camera, " << facing << " of " << grass;
        EXPECT_EQ(material, grass) << names[k] << ": roughness 1 and translucency 0.25";
        EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
    }
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

TEST_P(GBufferTest, VelocityIsTheMotionViewsVelocity) {
    make_target(true);
    make_field(three_tier_field(32));
    grass_view_desc v = view(kEye, kAt);
    grass_view_desc before = v;
    before.camera_position[0] -= 0.15;
    before.camera_position[2] -= 0.1;
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    std::memcpy(motion.previous_camera_position, before.camera_position, sizeof motion.previous_camera_position);
    std::memcpy(motion.previous_view, before.view, sizeof motion.previous_view);
    std::memcpy(motion.previous_projection, before.projection, sizeof motion.previous_projection);
    motion.previous_time = v.time;
    motion.velocity_attachment = 1;
    // The motion view: its lit colour to draw buffer 0, its velocity to draw buffer 1.
    grass_view_desc moving = v;
    moving.next = &motion;
    const Frame colour = draw(moving);
    // The G-buffer view: albedo to draw buffer 0, velocity to draw buffer 1.
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 2;
    layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[1].semantic = GRASS_GBUFFER_VELOCITY;
    layout.attachments[1].format = GRASS_GBUFFER_FORMAT_FLOAT;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    motion.next = &pass;
    const Frame g = draw(moving);
    const size_t n = size_t(kSize) * kSize;
    size_t both = 0, equal = 0, ba_changed = 0, moved = 0;
    for (size_t p = 0; p < n; ++p) {
        const float* a = &colour.velocity[p * 4];
        const float* b = &g.velocity[p * 4];
        ba_changed += b[2] != kVelocityClear[2] || b[3] != kVelocityClear[3] ? 1u : 0u;
        if (!colour.grass(p) || !g.grass(p) || colour.depth[p] != g.depth[p]) continue;
        ++both;
        moved += std::fabs(a[0]) + std::fabs(a[1]) > 1e-3f ? 1u : 0u;
        equal += std::fabs(a[0] - b[0]) <= 1e-5f && std::fabs(a[1] - b[1]) <= 1e-5f ? 1u : 0u;
    }
    EXPECT_GT(both, n / 5) << "grass pixels at the same depth in both views";
    EXPECT_GT(moved * 2, both) << "pixels that moved (the test would pass on zeros)";
    EXPECT_GE(equal * 100, both * 99) << equal << " of " << both << " pixels with the motion view's velocity";
    EXPECT_EQ(ba_changed, 0u) << "velocity pixels whose .ba grass wrote";
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
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    grass_view_gbuffer_desc layout = four_attachments();
    pass.next = &layout;
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
    // A Vulkan context refuses the view.
    bool vulkan = false;
    for (const grass_backend b : enabled_backends()) vulkan = vulkan || b == GRASS_BACKEND_VULKAN;
    if (!vulkan) return;
    release_target();
    grass_host::TargetDesc t;
    t.width = t.height = kSize;
    start(t, GRASS_BACKEND_VULKAN);
    make_field(field_desc(8));
    grass_view_gbuffer_desc layout = four_attachments();
    pass.next = &layout;
    grass_view_desc v = view(kEye, kAt);
    v.next = &pass;
    log.clear();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_UNSUPPORTED);
    EXPECT_NE(log.find("GRASS_PASS_GBUFFER, but the Vulkan backend does not draw G-buffer passes"), std::string::npos)
        << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
}

INSTANTIATE_TEST_SUITE_P(Gl, GBufferTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
