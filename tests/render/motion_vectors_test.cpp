// Motion vectors (grass_view_motion_desc; docs/engine-frames.md "Motion vectors"), drawn into
// a framebuffer the test makes: draw buffers {colour, a G-buffer-like target filled with a
// pattern, velocity (RGBA32F)}, so the velocity goes to draw buffer 2. Vulkan: the host's
// pass of colour attachments {colour, an RGBA8 target, velocity (RGBA32F)}
// (TargetDesc::vk_velocity_attachment 2, grass_vk_velocity_target_desc); rows top first and
// the velocity's y down there, which the checks below take as they come (each backend's
// own NDC), the window depth 0..1.
// - A camera pan (static grass, both projections jittered): on every tier's pixels the
//   velocity is the reprojection of the pixel's world point (from the depth buffer) by the
//   two frames' unjittered matrices, within 1e-3 viewport units (0.13 px) at 97% of them.
// - A gust (still orthographic camera, soft blades): per tier, a finite difference of the
//   frames at the two times: frame t1's grass compared with frame t0 where its velocity says
//   it was differs less than unmoved and than moved the other way (the colour of the volume
//   and image tiers, the coverage of sparse blades); with previous_time = time it is zero.
// - The other draw buffer stays byte-identical, the velocity's .ba and its pixels without
//   grass keep their clear, and the host's draw buffers, masks, blend and binding 3 come back.
// - A view without the struct draws with programs that declare no GrassMotion block and the
//   same picture; bad descs are refused naming the field; a Vulkan context without
//   grass_vk_velocity_target_desc, or with another velocity attachment, refuses the view.
#include "gl_program_spy.hpp"
#include "gl_test_functions.hpp"
#include "matrix4.hpp"
#include "render_fixture.hpp"
#include "vk_intercept.hpp"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace grass_test {
namespace {

constexpr int kSize = 128;

using grass_host::invert4; // matrix4.hpp

// projection x the view's rotation (camera-relative world -> clip), in double.
void camera_relative_vp(const float view[16], const float projection[16], double out[16]) {
    double r[16] = {0}, p[16];
    for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < 3; ++k) r[4 * c + k] = view[4 * c + k];
    }
    r[15] = 1.0;
    for (int k = 0; k < 16; ++k) p[k] = projection[k];
    grass_host::multiply4(p, r, out);
}

// Jitters a projection by `j` in NDC: clip.xy += j clip.w.
void jitter(float projection[16], const float j[2]) {
    for (int c = 0; c < 4; ++c) {
        projection[4 * c + 0] += j[0] * projection[4 * c + 3];
        projection[4 * c + 1] += j[1] * projection[4 * c + 3];
    }
}

// What a frame left in the test's framebuffer; rows bottom first (GL's).
struct Frame {
    std::vector<uint8_t> color, extra;
    std::vector<float> velocity, depth;
    bool grass(int x, int y) const { return depth[size_t(y) * kSize + x] < 1.0f; }
    const float* v(int x, int y) const { return &velocity[(size_t(y) * kSize + x) * 4]; }
};

const float kExtraClear[4] = {0.2f, 0.4f, 0.6f, 0.8f};
const float kVelocityClear[4] = {9.0f, -9.0f, 7.0f, 5.0f};

class MotionVectorsTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        if (GetParam() == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_program_spy_filter;
        if (GetParam() == GRASS_BACKEND_VULKAN) {
            t.vk_velocity_attachment = 2;
            t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr(); // counts grass's objects
            t.read_depth = true;
            for (int c = 0; c < 4; ++c) {
                t.clear_color[c] = c == 3 ? 1.0f : 0.0f;
                t.velocity_clear[c] = kVelocityClear[c];
                t.other_clear[c] = kExtraClear[c];
            }
        }
        start(t);
        if (GetParam() != GRASS_BACKEND_GL) return;
        load_gl_test_functions(*host, &gl);
        const GLenum formats[4] = {GL_RGBA8, GL_RGBA32F, GL_RGBA8, GL_DEPTH_COMPONENT32F};
        gl.CreateTextures(GL_TEXTURE_2D, 4, textures_);
        for (int i = 0; i < 4; ++i) gl.TextureStorage2D(textures_[i], 1, formats[i], kSize, kSize);
        gl.CreateFramebuffers(1, &fbo_);
        for (int i = 0; i < 3; ++i) gl.NamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0 + i, textures_[i], 0);
        gl.NamedFramebufferTexture(fbo_, GL_DEPTH_ATTACHMENT, textures_[3], 0);
        // Draw buffer 1: the pattern (attachment 2); draw buffer 2: the velocity (attachment 1).
        const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT1};
        gl.NamedFramebufferDrawBuffers(fbo_, 3, buffers);
    }
    void TearDown() override {
        if (fbo_ != 0) {
            gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
            gl.DeleteFramebuffers(1, &fbo_);
            gl.DeleteTextures(4, textures_);
        }
        RenderTest::TearDown();
    }

    // A motion desc of the previous camera `v` (its matrices, position, time), velocity at
    // draw buffer 2.
    static grass_view_motion_desc motion_of(const grass_view_desc& v, const float previous_jitter[2]) {
        grass_view_motion_desc m = grass_default_view_motion_desc();
        std::memcpy(m.previous_camera_position, v.camera_position, sizeof m.previous_camera_position);
        std::memcpy(m.previous_view, v.view, sizeof m.previous_view);
        std::memcpy(m.previous_projection, v.projection, sizeof m.previous_projection);
        m.previous_jitter[0] = previous_jitter[0];
        m.previous_jitter[1] = previous_jitter[1];
        m.previous_time = v.time;
        m.velocity_attachment = 2;
        return m;
    }

    // Draws `v` into the test's framebuffer, cleared first, and reads it back.
    Frame draw(const grass_view_desc& v) {
        Frame f;
        if (GetParam() == GRASS_BACKEND_VULKAN) {
            grass_host::Image image;
            grass_view_desc d = v;
            d.viewport[0] = d.viewport[1] = 0;
            d.viewport[2] = d.viewport[3] = kSize;
            EXPECT_EQ(host->render(ctx, d, nullptr, &image, nullptr), GRASS_SUCCESS) << log;
            f.color = image.rgba;
            f.extra = image.other;
            f.velocity = image.velocity;
            f.depth = image.depth;
            return f;
        }
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f}, far = 1.0f;
        gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 0, black);
        gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 1, kExtraClear);
        gl.ClearNamedFramebufferfv(fbo_, GL_COLOR, 2, kVelocityClear);
        gl.ClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &far);
        draw_whole_view(ctx, v, kSize, log);
        const size_t n = size_t(kSize) * kSize;
        f.color.resize(n * 4);
        f.extra.resize(n * 4);
        f.velocity.resize(n * 4);
        f.depth.resize(n);
        gl.GetTextureImage(textures_[0], 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4), f.color.data());
        gl.GetTextureImage(textures_[1], 0, GL_RGBA, GL_FLOAT, GLsizei(n * 16), f.velocity.data());
        gl.GetTextureImage(textures_[2], 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4), f.extra.data());
        gl.GetTextureImage(textures_[3], 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(n * 4), f.depth.data());
        return f;
    }

    // An orthographic camera over (0.5, 0, 0.5), 0.4 m half extent: from above, or
    // (`oblique`) 45 degrees down looking +z; depth 1..10 m.
    grass_view_desc top_down(double time, bool oblique = false) {
        const double eye[3] = {0.5, 5.0, oblique ? -4.5 : 0.5}, at[3] = {0.5, 0.0, 0.5};
        grass_view_desc v = view(eye, at);
        std::memset(v.projection, 0, sizeof v.projection);
        v.projection[0] = v.projection[5] = float(1.0 / 0.4);
        const bool vk = GetParam() == GRASS_BACKEND_VULKAN; // clip z 0..1
        v.projection[10] = float(vk ? -1.0 / 9.0 : -2.0 / 9.0);
        v.projection[14] = float(vk ? -1.0 / 9.0 : -11.0 / 9.0);
        v.projection[15] = 1.0f;
        v.time = time;
        return v;
    }

    // Tier case k of the gust and trail tests: sparse blades seen from above (k 0; their
    // coverage moves over the dark ground), the volume of 2 slices a cell (k 1, seen from 45
    // degrees: from above the rays meet the grass near its roots, which hardly move), the
    // image tier (k 2, from above).
    grass_field_desc tier_case_field(int k) {
        const grass_tier_kind kinds[3] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
        grass_field_desc d = k == 0 ? field_desc(4) : solo_tier_field(4, kinds[k], k == 1 ? 2u : 0u, 4);
        if (k == 0) d.density = 0.15f;
        return d;
    }
    // Two frames of the top-down camera (`oblique`: 45 degrees down): *a at time ta, drawn with
    // previous_time = ta (nothing moves), and *b at tb, whose previous frame is a.
    void draw_pair(double ta, double tb, bool oblique, Frame* a, Frame* b) {
        const float none[2] = {0.0f, 0.0f};
        const grass_view_desc first = top_down(ta, oblique);
        grass_view_motion_desc still = motion_of(first, none);
        grass_view_desc v0 = first;
        v0.next = &still;
        *a = draw(v0);
        grass_view_desc v1 = top_down(tb, oblique);
        grass_view_motion_desc motion = motion_of(first, none);
        v1.next = &motion;
        *b = draw(v1);
    }

    // What frame b's velocity explains of how it differs from frame a (the finite difference
    // of two frames): each of b's grass pixels against frame a where its velocity says that
    // grass was (bilinear), against a at the same pixel, and at the opposite displacement. It
    // compares the colour (a carpet of the volume or image tier) or, `coverage`, whether grass
    // covers the pixel (sparse blades over the dark ground).
    struct Displacement {
        double err_v = 0.0, err_0 = 0.0, err_neg = 0.0;
        double moved = 0.0; // the mean displacement, px
        size_t n = 0;       // b's grass pixels
    };
    // `relit`: a's colours are first scaled per channel to b's mean over b's grass pixels (a
    // trail's grass brightens as it stands up: press_shade).
    static Displacement displacement(const Frame& a, const Frame& b, bool coverage, bool relit = false) {
        Displacement m;
        double gain[3] = {1.0, 1.0, 1.0};
        if (relit) {
            double sum_a[3] = {}, sum_b[3] = {};
            for (size_t i = 0; i < size_t(kSize) * kSize; ++i) {
                if (b.depth[i] >= 1.0f) continue;
                for (int c = 0; c < 3; ++c) {
                    sum_a[c] += a.color[4 * i + c];
                    sum_b[c] += b.color[4 * i + c];
                }
            }
            for (int c = 0; c < 3; ++c) gain[c] = sum_a[c] > 0.0 ? sum_b[c] / sum_a[c] : 1.0;
        }
        const auto sample = [&a, coverage, &gain](double fx, double fy, int c) {
            const double x = std::min(std::max(fx - 0.5, 0.0), kSize - 1.001);
            const double y = std::min(std::max(fy - 0.5, 0.0), kSize - 1.001);
            const int x0 = int(x), y0 = int(y);
            const double tx = x - x0, ty = y - y0;
            const auto at = [&a, &gain, c, coverage](int px, int py) {
                return coverage ? (a.grass(px, py) ? 255.0 : 0.0)
                                : gain[c] * double(a.color[(size_t(py) * kSize + px) * 4 + c]);
            };
            return (1 - ty) * ((1 - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) +
                   ty * ((1 - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
        };
        for (int y = 8; y < kSize - 8; ++y) {
            for (int x = 8; x < kSize - 8; ++x) {
                if (!b.grass(x, y)) continue;
                const double dx = b.v(x, y)[0] * kSize, dy = b.v(x, y)[1] * kSize;
                for (int c = 0; c < (coverage ? 1 : 3); ++c) {
                    const double now = coverage ? 255.0 : b.color[(size_t(y) * kSize + x) * 4 + c];
                    m.err_v += std::fabs(now - sample(x + 0.5 - dx, y + 0.5 - dy, c));
                    m.err_0 += std::fabs(now - sample(x + 0.5, y + 0.5, c));
                    m.err_neg += std::fabs(now - sample(x + 0.5 + dx, y + 0.5 + dy, c));
                }
                m.moved += std::sqrt(dx * dx + dy * dy);
                ++m.n;
            }
        }
        if (m.n > 0) m.moved /= double(m.n);
        return m;
    }
    // The velocity explains most of what changed: frame b against frame a moved by it differs
    // less than `bound` times b against a unmoved, and against a moved the other way.
    static void expect_explained(const Displacement& m, double bound, const char* name) {
        ASSERT_GT(m.n, 1000u) << name << ": grass pixels";
        std::printf("%s: mean displacement %.2f px; error moved by the velocity / unmoved %.2f, / moved the other "
                    "way %.2f\n",
                    name, m.moved, m.err_v / std::max(m.err_0, 1e-9), m.err_v / std::max(m.err_neg, 1e-9));
        EXPECT_GT(m.moved, 0.5) << name << ": the mean displacement (px)";
        EXPECT_LT(m.err_v, bound * m.err_0) << name << ": frame b against frame a moved by the velocity, and unmoved"
                                            << " (mean displacement " << m.moved << " px)";
        EXPECT_LT(m.err_v, bound * m.err_neg) << name << ": ... and moved the other way";
    }
    // A frame drawn with previous_time = time: none of its grass pixels moves.
    static void expect_still(const Frame& a, const char* name) {
        double still_v = 0.0;
        for (int y = 8; y < kSize - 8; ++y) {
            for (int x = 8; x < kSize - 8; ++x) {
                if (a.grass(x, y)) {
                    still_v = std::max(still_v, double(std::fabs(a.v(x, y)[0]) + std::fabs(a.v(x, y)[1])));
                }
            }
        }
        EXPECT_LT(still_v * kSize, 0.01) << name << ": previous_time = time moves nothing (px)";
    }

    GlTestFunctions gl{};
    GLuint fbo_ = 0;
    GLuint textures_[4] = {};
};

TEST_P(MotionVectorsTest, ACameraPanGivesEachGrassPixelsReprojection) {
    const bool vk = GetParam() == GRASS_BACKEND_VULKAN; // window depth is NDC z
    make_field(three_tier_field(48));
    const double before_eye[3] = {5.7, 0.75, 0.3}, before_at[3] = {6.2, 0.0, 8.0};
    const double eye[3] = {6.0, 0.8, 0.5}, at[3] = {6.9, 0.0, 8.0};
    const float before_jitter[2] = {-0.006f, 0.004f}, now_jitter[2] = {0.005f, -0.007f};
    grass_view_desc before = view(before_eye, before_at);
    grass_view_desc now = view(eye, at);
    // The unjittered camera-relative matrices the expectation uses.
    double vp_now[16], vp_before[16], inv_now[16];
    camera_relative_vp(now.view, now.projection, vp_now);
    camera_relative_vp(before.view, before.projection, vp_before);
    invert4(vp_now, inv_now);
    jitter(before.projection, before_jitter);
    jitter(now.projection, now_jitter);
    grass_view_motion_desc motion = motion_of(before, before_jitter);
    motion.jitter[0] = now_jitter[0];
    motion.jitter[1] = now_jitter[1];
    now.next = &motion;
    const Frame f = draw(now);

    // Per tier, by distance from the camera (three_tier_field's bands, no transition).
    size_t count[3] = {}, within[3] = {};
    double worst[3] = {};
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!f.grass(x, y)) continue;
            const double ndc[4] = {
                (x + 0.5) / kSize * 2.0 - 1.0 - now_jitter[0], (y + 0.5) / kSize * 2.0 - 1.0 - now_jitter[1],
                vk ? f.depth[size_t(y) * kSize + x] : 2.0 * f.depth[size_t(y) * kSize + x] - 1.0, 1.0};
            double rel[4] = {};
            for (int r = 0; r < 4; ++r) {
                for (int k = 0; k < 4; ++k) rel[r] += inv_now[4 * k + r] * ndc[k];
            }
            double world[3], d2 = 0.0;
            for (int c = 0; c < 3; ++c) {
                world[c] = eye[c] + rel[c] / rel[3];
                d2 += (rel[c] / rel[3]) * (rel[c] / rel[3]);
            }
            const double dist = std::sqrt(d2);
            const int tier = dist < 1.9 ? 0 : dist > 3.2 && dist < 4.8 ? 1 : dist > 7.5 ? 2 : -1;
            if (tier < 0) continue;
            const double p[4] = {world[0] - before_eye[0], world[1] - before_eye[1], world[2] - before_eye[2], 1.0};
            double clip[4] = {};
            for (int r = 0; r < 4; ++r) {
                for (int k = 0; k < 4; ++k) clip[r] += vp_before[4 * k + r] * p[k];
            }
            const double expected[2] = {0.5 * (ndc[0] - clip[0] / clip[3]), 0.5 * (ndc[1] - clip[1] / clip[3])};
            const float* v = f.v(x, y);
            const double error = std::max(std::fabs(v[0] - expected[0]), std::fabs(v[1] - expected[1]));
            ++count[tier];
            within[tier] += error <= 1e-3;
            worst[tier] = std::max(worst[tier], error);
        }
    }
    const char* const names[3] = {"geometry", "volume", "image"};
    for (int t = 0; t < 3; ++t) {
        EXPECT_GT(count[t], 100u) << names[t] << " pixels";
        EXPECT_GE(within[t] * 100, count[t] * 97)
            << names[t] << ": " << within[t] << " of " << count[t] << " within 1e-3, worst " << worst[t];
    }
    // The camera moved: the velocities are not all alike nor zero (the test is not vacuous).
    double lo = 1e9, hi = -1e9;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!f.grass(x, y)) continue;
            lo = std::min(lo, double(f.v(x, y)[0]));
            hi = std::max(hi, double(f.v(x, y)[0]));
        }
    }
    EXPECT_GT(hi - lo, 0.02) << "the velocity's x across the grass";
}

TEST_P(MotionVectorsTest, AGustMovesTheGrassAsTwoFramesDo) {
    grass_wind_desc wind = grass_default_wind_desc();
    wind.direction[0] = 1.0f;
    wind.direction[2] = 0.4f;
    wind.speed = 2.0f;
    wind.gust_strength = 4.0f;
    wind.gust_length = 10.0f;
    wind.turbulence = 0.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << log;
    grass_blade_mechanics soft = grass_default_blade_mechanics();
    soft.stiffness = 10.0f; // blades that the gusts bend far
    ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &soft), GRASS_SUCCESS) << log;
    const double t0 = 22.0, t1 = 23.0; // the gust passing changes the bend
    const char* const names[3] = {"geometry", "volume", "image"};
    for (int k = 0; k < 3; ++k) {
        const grass_field_id field = make_field(tier_case_field(k));
        Frame a, b;
        draw_pair(t0, t1, k == 1, &a, &b);
        expect_still(a, names[k]);
        // Blades bend and turn as they move, and the volume's velocity is its depth point's
        // (the tips in front of it move more): they are held to less than the image tier.
        expect_explained(displacement(a, b, k == 0), k == 2 ? 0.5 : 0.85, names[k]);
        EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
    }
}

// A trail standing up again (the interaction map's recovery, docs/responsive.md): a large
// ball pressed the grass and was taken away; two frames 0.2 s apart while the grass rises
// (recovery 0.5 s). Per tier, as the gust: the velocity explains frame b against frame a.
// Without the trail's age at the previous time, the pressed grass has no velocity.
TEST_P(MotionVectorsTest, ATrailStandingUpMovesTheGrassAsTwoFramesDo) {
    grass_blade_mechanics m = grass_default_blade_mechanics();
    m.recovery_time = 0.5f;
    ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << log;
    grass_collider ball{};
    ball.shape = GRASS_COLLIDER_SPHERE;
    ball.radius = 1.0f; // its underside 2 cm above the ground at the view's centre, 10 cm at its edge
    ball.center[0] = 0.5;
    ball.center[1] = 1.02;
    ball.center[2] = 0.5;
    const double t0 = 30.0, t1 = 30.3, t2 = 30.5;
    const char* const names[3] = {"geometry", "volume", "image"};
    for (int k = 0; k < 3; ++k) {
        const grass_field_id field = make_field(tier_case_field(k));
        const grass_interaction_desc fresh = grass_default_interaction_desc(); // no trail of the last tier's
        ASSERT_EQ(grass_set_interaction(ctx, &fresh), GRASS_SUCCESS) << log;
        ASSERT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS) << log;
        draw(top_down(t0, k == 1));
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
        Frame a, b;
        draw_pair(t1, t2, k == 1, &a, &b);
        expect_still(a, names[k]);
        // Rising blades also stand taller in the picture, and the trail brightens unevenly as
        // it stands up (its shade follows each texel's press; one gain takes out its mean):
        // the velocity explains less of the change than the gust's (measured 0.84 and 0.73
        // for the blades and the volume, 0.57-0.65 for the image tier), and nothing without
        // the trail's age at the previous time (1.0: no grass pixel moves).
        expect_explained(displacement(a, b, k == 0, true), k == 2 ? 0.8 : 0.92, names[k]);
        EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
    }
}

// Vulkan: the targets alone (the pass's attachment 1, write mask 0; the velocity's .ba).
TEST_P(MotionVectorsTest, OtherTargetsAndTheHostsStateStay) {
    const bool gl_host = GetParam() == GRASS_BACKEND_GL;
    make_field(three_tier_field(48));
    const double eye[3] = {6.0, 0.8, 0.5}, at[3] = {6.9, 0.0, 8.0};
    const float none[2] = {0.0f, 0.0f};
    grass_view_desc v = view(eye, at);
    grass_view_desc before = v;
    before.camera_position[0] -= 0.2;
    grass_view_motion_desc motion = motion_of(before, none);
    v.next = &motion;
    // The host's own state of draw buffer 2's output slot (1 for grass), binding 3, blend.
    GLuint host_buffer = 0;
    if (gl_host) {
        gl.CreateBuffers(1, &host_buffer);
        gl.NamedBufferData(host_buffer, 1024, nullptr, GL_STATIC_DRAW);
        gl.BindBufferRange(GL_UNIFORM_BUFFER, 3, host_buffer, 256, 512);
        gl.Enablei(GL_BLEND, 1);
        gl.ColorMaski(1, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        gl.ColorMaski(2, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl.Disablei(GL_BLEND, 2);
    }
    // Blending off for the clears (they respect masks, not blending); the masks as above.
    const Frame f = draw(v);
    size_t grass = 0, moved = 0, extra_changed = 0, ba_changed = 0, sky_changed = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const size_t i = size_t(y) * kSize + x;
            const uint8_t* e = &f.extra[i * 4];
            // Draw buffer 1's pattern, under the host's mask (r and b cleared, g and a kept at 0);
            // Vulkan: all four as cleared.
            extra_changed += e[0] != 51 || e[2] != 153 || (!gl_host && (e[1] != 102 || e[3] != 204));
            const float* vel = f.v(x, y);
            ba_changed += vel[2] != kVelocityClear[2] || vel[3] != kVelocityClear[3];
            if (f.grass(x, y)) {
                ++grass;
                moved += vel[0] != kVelocityClear[0] && std::fabs(vel[0]) < 1.0f;
            } else {
                sky_changed += vel[0] != kVelocityClear[0] || vel[1] != kVelocityClear[1];
            }
        }
    }
    EXPECT_GT(grass, 1000u);
    EXPECT_EQ(moved, grass) << "grass pixels with a velocity written";
    EXPECT_EQ(extra_changed, 0u) << "pixels of the other draw buffer grass wrote";
    EXPECT_EQ(ba_changed, 0u) << "velocity pixels whose .ba grass wrote";
    EXPECT_EQ(sky_changed, 0u) << "velocity pixels without grass that grass wrote";
    if (!gl_host) return;
    GLint buffers[3] = {}, binding = 0;
    for (int i = 0; i < 3; ++i) gl.GetIntegerv(GL_DRAW_BUFFER0 + i, &buffers[i]);
    EXPECT_EQ(buffers[0], GL_COLOR_ATTACHMENT0);
    EXPECT_EQ(buffers[1], GL_COLOR_ATTACHMENT2);
    EXPECT_EQ(buffers[2], GL_COLOR_ATTACHMENT1);
    gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 3, &binding);
    EXPECT_EQ(GLuint(binding), host_buffer) << "uniform binding 3";
    GLboolean mask[4] = {};
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, 1, mask);
    EXPECT_TRUE(mask[0] == GL_TRUE && mask[1] == GL_FALSE && mask[2] == GL_TRUE && mask[3] == GL_FALSE)
        << "draw buffer 1's colour mask";
    EXPECT_TRUE(gl.IsEnabledi(GL_BLEND, 1)) << "draw buffer 1's blend";
    gl.Disablei(GL_BLEND, 1);
    gl.ColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DeleteBuffers(1, &host_buffer);
}

TEST_P(MotionVectorsTest, AViewWithoutItKeepsItsProgramsAndPicture) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "GL programs";
    make_field(three_tier_field(48));
    const double eye[3] = {6.0, 0.8, 0.5}, at[3] = {6.9, 0.0, 8.0};
    const float none[2] = {0.0f, 0.0f};
    const grass_view_desc plain = view(eye, at);
    gl_program_spy().used.clear();
    gl_program_spy().created = 0;
    const Frame a = draw(plain);
    const std::set<GLuint> plain_programs = gl_program_spy().used;
    ASSERT_GE(plain_programs.size(), 3u) << "a program per tier kind";
    for (const GLuint program : plain_programs) {
        EXPECT_EQ(gl.GetUniformBlockIndex(program, "GrassMotion"), GL_INVALID_INDEX)
            << "program " << program << " of a view without motion vectors declares the GrassMotion block";
    }
    const int64_t plain_created = gl_program_spy().created;
    grass_view_desc before = plain;
    before.camera_position[2] -= 0.3;
    grass_view_motion_desc motion = motion_of(before, none);
    grass_view_desc moving = plain;
    moving.next = &motion;
    gl_program_spy().used.clear();
    const Frame b = draw(moving);
    EXPECT_GE(gl_program_spy().created - plain_created, 3) << "a motion view compiles its own variants";
    for (const GLuint program : gl_program_spy().used) {
        EXPECT_EQ(plain_programs.count(program), 0u) << "the motion view drew with a plain view's program";
        EXPECT_NE(gl.GetUniformBlockIndex(program, "GrassMotion"), GL_INVALID_INDEX);
    }
    EXPECT_EQ(a.color, b.color) << "the motion view's colour differs";
    EXPECT_EQ(a.depth, b.depth) << "the motion view's depth differs";
    const int64_t created = gl_program_spy().created;
    gl_program_spy().used.clear();
    const Frame c = draw(plain);
    EXPECT_EQ(gl_program_spy().created, created) << "a plain view after a motion view made programs";
    EXPECT_EQ(gl_program_spy().used, plain_programs);
    EXPECT_EQ(c.color, a.color);
}

// Vulkan: plain views make nothing for motion vectors, even in a context with a velocity
// target (no pipeline, no object grass names "motion"); the first motion view makes its
// pipelines (blades, volume, image), layouts, the GrassMotion block's buffer and its pool;
// the motion view's colour and depth are the plain view's.
TEST_P(MotionVectorsTest, AVulkanViewWithoutItMakesNothingForIt) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan objects";
    vk_intercept::clear_debug_records(); // what earlier tests of the process made
    const grass_host::TargetDesc target = host->target();
    start(target); // a context made since
    make_field(three_tier_field(48));
    const double eye[3] = {6.0, 0.8, 0.5}, at[3] = {6.9, 0.0, 8.0};
    const float none[2] = {0.0f, 0.0f};
    const grass_view_desc plain = view(eye, at);
    // The objects grass made and named since the context began whose name says `what` and `kind`.
    const auto named = [](const char* what, const char* kind) {
        size_t n = 0;
        for (const auto& name : vk_intercept::names())
            n += name.second.find(what) != std::string::npos && name.second.find(kind) != std::string::npos;
        return n;
    };
    const auto motion_objects = [&](const char* kind) { return named("motion", kind); };
    draw(plain); // the plain pipelines and per-frame buffers of both frame slots
    const Frame a = draw(plain);
    const vk_intercept::Live plain_live = vk_intercept::live();
    draw(plain);
    const vk_intercept::Live again = vk_intercept::live();
    EXPECT_EQ(again.pipelines_made, plain_live.pipelines_made) << "plain frames made pipelines";
    EXPECT_EQ(motion_objects(""), 0u) << "objects for motion vectors before any motion view";
    EXPECT_EQ(named("view extras", ""), 0u) << "the view extras' objects before any motion view";
    grass_view_desc before = plain;
    before.camera_position[2] -= 0.3;
    grass_view_motion_desc motion = motion_of(before, none);
    grass_view_desc moving = plain;
    moving.next = &motion;
    const Frame b = draw(moving);
    const vk_intercept::Live motion_live = vk_intercept::live();
    EXPECT_GE(motion_live.pipelines_made - again.pipelines_made, 3) << "the motion pipelines";
    EXPECT_EQ(motion_objects("pipelines"), 3u) << "the blade, volume and image tier motion pipelines";
    EXPECT_EQ(motion_objects("block"), 1u) << "the GrassMotion block of the view slot";
    EXPECT_EQ(named("view extras", "pool"), 1u) << "the view extras' descriptor pool";
    EXPECT_EQ(named("view extras", "layout"), 3u) << "the view extras' two set layouts and pipeline layout";
    EXPECT_EQ(named("shadow", ""), 0u) << "a motion view made objects for receiving shadows";
    EXPECT_EQ(a.color, b.color) << "the motion view's colour differs";
    EXPECT_EQ(a.depth, b.depth) << "the motion view's depth differs";
    const Frame c = draw(plain);
    EXPECT_EQ(vk_intercept::live().pipelines_made, motion_live.pipelines_made) << "a plain view after a motion view";
    EXPECT_EQ(c.color, a.color);
}

TEST_P(MotionVectorsTest, BadDescsAreRefused) {
    make_field(field_desc(8));
    const double eye[3] = {1.0, 1.0, -1.0}, at[3] = {1.0, 0.0, 1.0};
    const float none[2] = {0.0f, 0.0f};
    const grass_view_desc plain = view(eye, at);
    const grass_view_motion_desc d = motion_of(plain, none);
    EXPECT_EQ(grass_default_view_motion_desc().type, GRASS_STRUCT_TYPE_VIEW_MOTION_DESC);
    EXPECT_EQ(grass_default_view_motion_desc().velocity_attachment, 1u);
    const auto refused = [&](const grass_view_motion_desc& m, grass_result expected, const std::string& message) {
        log.clear();
        grass_view_desc v = plain;
        v.next = &m;
        EXPECT_EQ(grass_begin_frame(ctx, &v), expected) << message;
        EXPECT_NE(log.find(message), std::string::npos) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
    };
    grass_view_motion_desc bad = d;
    bad.previous_camera_position[1] = NAN;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_camera_position");
    bad = d;
    bad.previous_camera_position[2] = 2e12;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_camera_position[2] is 2e+12");
    bad = d;
    bad.previous_view[5] = INFINITY;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_view");
    bad = d;
    std::memset(bad.previous_view, 0, sizeof bad.previous_view);
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_view has a singular rotation");
    bad = d;
    std::memset(bad.previous_projection, 0, sizeof bad.previous_projection);
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_projection is all zero");
    bad = d;
    bad.jitter[1] = 3.0f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->jitter[1]");
    bad = d;
    bad.previous_jitter[0] = -2.5f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_jitter[0]");
    bad = d;
    bad.previous_time = NAN;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->previous_time");
    bad = d;
    bad.velocity_attachment = 0;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->velocity_attachment is 0");
    bad.velocity_attachment = 8;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_view_motion_desc->velocity_attachment is 8");
    grass_view_motion_desc second = d;
    bad = d;
    bad.next = &second;
    refused(bad, GRASS_ERROR_WRONG_STRUCT_TYPE, "GRASS_STRUCT_TYPE_VIEW_MOTION_DESC");
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        // The context's velocity target is colour attachment 2: another is refused, and a
        // context made without grass_vk_velocity_target_desc refuses every motion view.
        bad = d;
        bad.velocity_attachment = 1;
        refused(bad, GRASS_ERROR_INVALID_ARGUMENT,
                "grass_view_motion_desc->velocity_attachment is 1, but the context's "
                "grass_vk_velocity_target_desc.velocity_attachment is 2");
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        start(t);
        make_field(field_desc(8));
        refused(d, GRASS_ERROR_INVALID_STATE, "the context was made without a grass_vk_velocity_target_desc");
        return;
    }
    // GL: a framebuffer without a draw buffer at velocity_attachment draws nothing.
    for (const uint32_t attachment : {3u, 0u}) {
        grass_view_motion_desc m = d;
        m.velocity_attachment = attachment == 0 ? 1u : attachment;
        grass_view_desc v = plain;
        v.next = &m;
        gl.BindFramebuffer(GL_FRAMEBUFFER, attachment == 0 ? 0u : fbo_); // 0: the default framebuffer
        log.clear();
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
        EXPECT_EQ(grass_gl_render(ctx), GRASS_ERROR_INVALID_STATE);
        EXPECT_NE(log.find("grass_view_motion_desc->velocity_attachment is " + std::to_string(m.velocity_attachment)),
                  std::string::npos)
            << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, MotionVectorsTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
