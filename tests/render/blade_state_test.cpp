// The per-blade state of responsive grass (api/shaders/blade_state.glsl, docs/responsive.md
// "Per-blade state") on the GPU: a test-only compute program (shaders/blade_state_test.comp,
// embedded with grass's include machinery) steps a buffer of synthetic blades in the headless
// GL host's context and reads their states and poses back. A ball pushes a tip sideways, a
// gust makes it lag and overshoot, eta builds under a resting collider and recovers, 30 fps,
// 60 fps and 1 s steps agree, 10 s steps and extreme inputs stay finite and validated, and
// the shader's constants are the core's (api/src/dynamics/blade_state.hpp).
#include "gl_loader.hpp"
#include "headless_host.hpp"

#include "dynamics/blade_state.hpp"

#include <GL/glcorearb.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace grass_blade_state_shaders {
extern const char* const blade_state_test_comp;
} // namespace grass_blade_state_shaders

namespace grass_test {
namespace {

// blade_state_test.comp's TestBlade, BladeCollider and Params header (std430).
struct TestBlade {
    float i1[4];      // xyz: rest v1 relative to the root (m), w: stiffness (m/s^2)
    float i2[4];      // xyz: rest v2, w: segments
    float up[4];      // xyz: unit up, w: recovery time (s)
    float front[4];   // xyz: unit front, w: wind response
    float wind[4];    // xyz: wind at the root (m/s), w: mass
    float gravity[4]; // xyz: gravity minus standard gravity (m/s^2)
};
struct Collider {
    float a[4];        // xyz: centre or one axis end relative to the root (m), w: radius
    float b[4];        // xyz: the capsule's other end, w: 0 sphere, 1 capsule
    float velocity[4]; // xyz: m/s
};
struct Params {
    float dt;
    int32_t mode;
    int32_t collider_count;
    int32_t blade_count;
};
struct Pose {
    float v1[4];       // the state's drawn v1, w: rest length
    float v2[4];       // the state's drawn v2, w: eta
    float still_v1[4]; // the stateless pose (blade_equilibrium)
    float still_v2[4];
};

// A grass blade 0.5 m long leaning along +z, up +y, the default mechanics.
TestBlade blade() {
    return TestBlade{{0.0f, 0.25f, 0.03f, 40.0f}, {0.0f, 0.47f, 0.12f, 6.0f}, {0.0f, 1.0f, 0.0f, 4.0f},
                     {0.0f, 0.0f, 1.0f, 2.0f},    {0.0f, 0.0f, 0.0f, 1.0f},   {0.0f, 0.0f, 0.0f, 0.0f}};
}

Collider sphere(float x, float y, float z, float r) {
    return Collider{{x, y, z, r}, {x, y, z, 0.0f}, {0.0f, 0.0f, 0.0f, 0.0f}};
}

float dist(const float* a, const float* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The length of the quadratic Bezier 0, v1, v2 drawn with `segments` segments.
float drawn_length(const float* v1, const float* v2, int segments) {
    float len = 0.0f, prev[3] = {0.0f, 0.0f, 0.0f};
    for (int k = 1; k <= segments; ++k) {
        const float t = float(k) / float(segments);
        float p[3];
        for (int c = 0; c < 3; ++c) p[c] = 2.0f * (1.0f - t) * t * v1[c] + t * t * v2[c];
        len += dist(p, prev);
        std::copy(p, p + 3, prev);
    }
    return len;
}

class BladeStateTest : public ::testing::Test {
protected:
    void SetUp() override {
        grass_host::TargetDesc target;
        target.width = target.height = 16;
        std::string error;
        host_ = grass_host::Host::create(GRASS_BACKEND_GL, target, &error);
        ASSERT_TRUE(host_) << error;
        const auto loader = [](void* host, const char* name) {
            return static_cast<grass_host::Host*>(host)->gl_proc_address(name);
        };
        ASSERT_TRUE(gl_.load(loader, host_.get(), &error)) << error;
        program_ = grass_bootstrap::compile_compute_program(gl_, grass_blade_state_shaders::blade_state_test_comp,
                                                            "blade_state_test.comp", &error);
        ASSERT_NE(program_, 0u) << error;
        gl_.CreateBuffers(4, buffers_);
    }

    void TearDown() override {
        if (program_ != 0) {
            gl_.DeleteBuffers(4, buffers_);
            gl_.DeleteProgram(program_);
        }
        if (host_) {
            EXPECT_EQ(host_->validation_messages(), 0u) << host_->validation_log();
        }
    }

    // Sets the blades (their states are set at rest by the next at_rest()).
    void set_blades(const std::vector<TestBlade>& blades) {
        blades_ = blades;
        gl_.NamedBufferData(buffers_[0], GLsizeiptr(blades.size() * sizeof(TestBlade)), blades.data(), GL_DYNAMIC_DRAW);
        gl_.NamedBufferData(buffers_[1], GLsizeiptr(blades.size() * grass::kBladeStateBytes), nullptr, GL_DYNAMIC_COPY);
        gl_.NamedBufferData(buffers_[2], GLsizeiptr(blades.size() * sizeof(Pose)), nullptr, GL_DYNAMIC_READ);
    }
    // Changes the blades' inputs (the wind), keeping their states.
    void update_blades(const std::vector<TestBlade>& blades) {
        blades_ = blades;
        gl_.NamedBufferData(buffers_[0], GLsizeiptr(blades.size() * sizeof(TestBlade)), blades.data(), GL_DYNAMIC_DRAW);
    }
    void set_colliders(const std::vector<Collider>& colliders) { colliders_ = colliders; }

    void dispatch(int mode, float dt) {
        std::vector<unsigned char> params(sizeof(Params) + colliders_.size() * sizeof(Collider) + sizeof(Collider));
        const Params p{dt, mode, int32_t(colliders_.size()), int32_t(blades_.size())};
        std::copy_n(reinterpret_cast<const unsigned char*>(&p), sizeof p, params.data());
        std::copy_n(reinterpret_cast<const unsigned char*>(colliders_.data()), colliders_.size() * sizeof(Collider),
                    params.data() + sizeof p);
        gl_.NamedBufferData(buffers_[3], GLsizeiptr(params.size()), params.data(), GL_DYNAMIC_DRAW);
        for (GLuint k = 0; k < 4; ++k) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4 + k, buffers_[k]);
        gl_.UseProgram(program_);
        gl_.DispatchCompute(GLuint((blades_.size() + 63) / 64), 1, 1);
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        gl_.UseProgram(0);
    }
    void at_rest() { dispatch(0, 0.0f); }
    void step(float dt) { dispatch(1, dt); }

    std::vector<Pose> poses() {
        std::vector<Pose> out(blades_.size());
        gl_.GetNamedBufferSubData(buffers_[2], 0, GLsizeiptr(out.size() * sizeof(Pose)), out.data());
        return out;
    }
    std::vector<grass::GpuBladeState> states() {
        std::vector<grass::GpuBladeState> out(blades_.size());
        gl_.GetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(out.size() * sizeof(grass::GpuBladeState)), out.data());
        return out;
    }

    std::unique_ptr<grass_host::Host> host_;
    grass_bootstrap::GlFunctions gl_;
    GLuint program_ = 0;
    GLuint buffers_[4] = {}; // blades, states, poses, params
    std::vector<TestBlade> blades_;
    std::vector<Collider> colliders_;
};

// The shader's constants are the core's (the core sizes and describes what the shader does).
TEST_F(BladeStateTest, TheShaderMirrorsTheCoresConstants) {
    set_blades({blade()});
    dispatch(2, 0.0f);
    const Pose p = poses()[0];
    EXPECT_EQ(p.v1[0], grass::kBladeStateSubstep);
    EXPECT_EQ(p.v1[1], float(grass::kBladeStateMaxSubsteps));
    EXPECT_EQ(p.v1[2], grass::kBladeStateDamping);
    EXPECT_EQ(p.v1[3], grass::kBladeStateEtaBuild);
    EXPECT_EQ(p.v2[0], grass::kBladeStateMinRecovery);
    EXPECT_EQ(p.v2[1], grass::kBladeStateMaxDeflection);
}

// A blade entering the window starts where the stateless pose has it, and under constant
// forces it stays there.
TEST_F(BladeStateTest, AtRestTheStateIsTheStatelessPose) {
    TestBlade windy = blade();
    windy.wind[0] = 6.0f;
    TestBlade heavy = blade();
    heavy.gravity[1] = -30.0f;
    set_blades({blade(), windy, heavy});
    at_rest();
    for (int frame = 0; frame < 30; ++frame) step(1.0f / 60.0f);
    const std::vector<Pose> p = poses();
    for (size_t i = 0; i < p.size(); ++i) {
        const float len = p[i].v1[3];
        EXPECT_LT(dist(p[i].v2, p[i].still_v2), 1e-5f * len) << "blade " << i;
        EXPECT_LT(dist(p[i].v1, p[i].still_v1), 1e-5f * len) << "blade " << i;
    }
    EXPECT_GT(dist(p[1].v2, p[0].v2), 0.05f) << "the wind bends the blade (not a vacuous pass)";
    EXPECT_GT(dist(p[2].v2, p[0].v2), 0.05f) << "gravity bends the blade";
}

// Jahrmann's eq. 14-15: a ball beside a blade pushes its tip out of the ball, sideways.
TEST_F(BladeStateTest, ABallBesideABladePushesItsTipSidewaysAwayFromIt) {
    set_blades({blade(), blade()});
    const float r = 0.1f;
    // To the -x side of the tip (0, 0.47, 0.12), 0.06 m away: inside the ball.
    set_colliders({sphere(-0.06f, 0.45f, 0.12f, r)});
    at_rest();
    std::vector<float> x;
    for (int frame = 0; frame < 60; ++frame) {
        step(1.0f / 60.0f);
        x.push_back(poses()[0].v2[0]);
    }
    const Pose p = poses()[0];
    const float centre[3] = {-0.06f, 0.45f, 0.12f};
    EXPECT_GT(x[0], 0.02f) << "pushed sideways at once (along +x, away from the ball)";
    EXPECT_GT(p.v2[0], 0.03f) << "the tip stays pushed aside";
    EXPECT_GT(dist(p.v2, centre), r - 0.01f) << "the tip is out of the ball";
    EXPECT_GT(p.v2[1], 0.3f) << "pushed aside, not flattened";
    // The same blade without the ball stays upright.
    set_colliders({});
    at_rest();
    step(1.0f / 60.0f);
    EXPECT_NEAR(poses()[0].v2[0], 0.0f, 1e-6f) << "no ball, no push";
}

// A gust (wind on, then off): the tip lags behind the stateless pose, overshoots it, and
// settles; when the wind stops it overshoots the rest pose and settles.
TEST_F(BladeStateTest, AGustMakesTheTipLagAndOvershootThenSettle) {
    set_blades({blade()});
    at_rest();
    const float rest_x = poses()[0].v2[0];
    TestBlade gust = blade();
    gust.wind[0] = 5.0f;
    update_blades({gust});
    std::vector<float> on, off;
    float equilibrium = 0.0f;
    for (int frame = 0; frame < 120; ++frame) {
        step(1.0f / 60.0f);
        const Pose p = poses()[0];
        on.push_back(p.v2[0] - rest_x);
        equilibrium = p.still_v2[0] - rest_x;
    }
    update_blades({blade()});
    for (int frame = 0; frame < 120; ++frame) {
        step(1.0f / 60.0f);
        off.push_back(poses()[0].v2[0] - rest_x);
    }
    ASSERT_GT(equilibrium, 0.05f) << "the gust bends the stateless blade (not a vacuous pass)";
    EXPECT_LT(on[0], 0.5f * equilibrium) << "the tip lags behind the gust";
    const float peak = *std::max_element(on.begin(), on.end());
    EXPECT_GT(peak, 1.1f * equilibrium) << "and overshoots it";
    EXPECT_LT(peak, 1.6f * equilibrium) << "damped";
    EXPECT_NEAR(on.back(), equilibrium, 0.01f * equilibrium) << "and settles there";
    EXPECT_GT(off[0], 0.5f * equilibrium) << "the tip lags behind the wind's end";
    const float swing = *std::min_element(off.begin(), off.end());
    EXPECT_LT(swing, -0.1f * equilibrium) << "and overshoots the rest pose";
    EXPECT_NEAR(off.back(), 0.0f, 0.01f * equilibrium) << "and settles there";
    std::printf("gust: equilibrium %.4f m, first frame %.4f, peak %.4f, after the gust %.4f, swing %.4f\n",
                double(equilibrium), double(on[0]), double(peak), double(off[0]), double(swing));
}

// Eq. 2-3, 16: eta builds while a ball rests on the blade, weakening its recovery; after the
// ball leaves, eta falls to 0 and the blade stands up within the recovery time. A twin whose
// eta decays at once (recovery time 0.01 s) stands up sooner.
TEST_F(BladeStateTest, EtaBuildsUnderARestingColliderAndTheBladeRecoversWithinTheRecoveryTime) {
    TestBlade crippled = blade();
    const float recovery_time = crippled.up[3];
    TestBlade twin = blade();
    twin.up[3] = 0.01f;
    set_blades({crippled, twin});
    at_rest();
    const Pose rest = poses()[0];
    set_colliders({sphere(0.0f, 0.5f, 0.0f, 0.25f)}); // rests on the blade, presses it along its lean
    std::vector<float> eta;
    for (int frame = 0; frame < 120; ++frame) {
        step(1.0f / 60.0f);
        eta.push_back(poses()[0].v2[3]);
    }
    const Pose pressed = poses()[0];
    EXPECT_LT(pressed.v2[1], rest.v2[1] - 0.03f) << "the ball presses the blade down";
    EXPECT_GT(eta[0], 0.0f) << "eta builds from the first step";
    EXPECT_LT(eta[0], 0.5f) << "gradually";
    EXPECT_GE(eta.back(), 0.99f) << "to its full strength under a resting ball";
    EXPECT_TRUE(std::is_sorted(eta.begin(), eta.end())) << "never falling while the ball rests";
    EXPECT_LT(poses()[1].v2[3], 0.01f) << "the twin's eta decays at once";

    set_colliders({});
    const int frames = int(std::lround(recovery_time * 60.0f));
    float crippled_at_half_second = 0.0f, twin_at_half_second = 0.0f;
    for (int frame = 1; frame <= frames; ++frame) {
        step(1.0f / 60.0f);
        if (frame == 30) {
            crippled_at_half_second = poses()[0].v2[1];
            twin_at_half_second = poses()[1].v2[1];
        }
    }
    const std::vector<Pose> p = poses();
    EXPECT_LT(crippled_at_half_second, twin_at_half_second - 0.02f) << "eta weakens the recovery (eq. 3)";
    EXPECT_LT(p[0].v2[3], 1e-4f) << "eta has decayed over the recovery time (eq. 2)";
    EXPECT_LT(dist(p[0].v2, rest.v2), 0.01f * rest.v1[3]) << "the blade stands up within the recovery time";
    std::printf("eta after 1 frame %.3f, 1 s %.3f, 2 s %.3f; tip height at rest %.3f m, pressed %.3f m, 0.5 s "
                "after: %.3f m (twin %.3f m)\n",
                double(eta[0]), double(eta[59]), double(eta.back()), double(rest.v2[1]), double(pressed.v2[1]),
                double(crippled_at_half_second), double(twin_at_half_second));
}

// 30 fps, 60 fps and 1 s steps over the same 5 s (wind starting at t = 0; a blade with a ball
// resting beside it besides) agree at each second within a stated tolerance.
TEST_F(BladeStateTest, ThirtySixtyFpsAndOneSecondStepsAgree) {
    TestBlade windy = blade();
    windy.wind[0] = 5.0f;
    TestBlade against = windy;
    against.wind[0] = -5.0f; // the wind pushes this one into the ball
    const std::vector<TestBlade> blades = {windy, against};
    const std::vector<Collider> ball = {sphere(-0.12f, 0.4f, 0.1f, 0.1f)};
    const int steps_per_second[3] = {60, 30, 1};
    std::vector<Pose> at[3][5];
    for (int run = 0; run < 3; ++run) {
        set_blades({blade(), blade()});
        set_colliders({});
        at_rest();
        update_blades(blades);
        set_colliders(ball);
        for (int second = 0; second < 5; ++second) {
            for (int k = 0; k < steps_per_second[run]; ++k) step(1.0f / float(steps_per_second[run]));
            at[run][second] = poses();
        }
    }
    // Tolerances (of the blade's length): the free blade's spring is exact at any step, so
    // only float rounding differs. The pressed blade is pushed out of the ball every substep:
    // 1/60 s at 30 and 60 fps (the same substeps: they agree exactly), 1/16 s in 1 s steps,
    // which take the transient (the wind presses the blade in, eta builds and weakens it)
    // differently: 0.058 of the length at most, measured at the third second, 4e-5 at the fifth.
    const float len = at[0][0][0].v1[3];
    float worst[2][2] = {}; // blade, run (30 fps, 1 s) against 60 fps
    for (int second = 0; second < 5; ++second) {
        for (int run = 1; run < 3; ++run) {
            for (int b = 0; b < 2; ++b) {
                const float d = dist(at[run][second][b].v2, at[0][second][b].v2) / len;
                worst[b][run - 1] = std::max(worst[b][run - 1], d);
            }
        }
    }
    EXPECT_LT(worst[0][0], 1e-5f) << "free blade, 30 fps";
    EXPECT_LT(worst[0][1], 1e-5f) << "free blade, 1 s steps";
    EXPECT_LT(worst[1][0], 1e-5f) << "pressed blade, 30 fps";
    EXPECT_LT(worst[1][1], 0.08f) << "pressed blade, 1 s steps";
    const float settled = dist(at[2][4][1].v2, at[0][4][1].v2) / len;
    EXPECT_LT(settled, 1e-3f) << "pressed blade, 1 s steps, after 5 s";
    const float pressed_by = dist(at[0][4][1].v2, at[0][4][1].still_v2) / len;
    EXPECT_GT(pressed_by, 0.1f) << "the ball holds the pressed blade off its stateless pose (not a vacuous pass)";
    std::printf("largest difference to 60 fps (x blade length): free blade 30 fps %.2g, 1 s %.2g; pressed blade "
                "30 fps %.2g, 1 s %.2g (held %.2f off its stateless pose)\n",
                double(worst[0][0]), double(worst[0][1]), double(worst[1][0]), double(worst[1][1]), double(pressed_by));
    std::printf("pressed blade, 1 s steps, after 5 s: %.2g\n", double(settled));
}

// dt = 10 s (the API's longest step) and extreme inputs: every state and pose finite, the
// tip above the root's plane, the length kept, eta in 0..1.
TEST_F(BladeStateTest, TenSecondStepsAndExtremeInputsStayFiniteAndValidated) {
    std::vector<TestBlade> blades(8, blade());
    blades[1].wind[0] = 2e4f; // the API's strongest wind, the weakest blade
    blades[1].front[3] = 100.0f;
    blades[1].i1[3] = 0.01f;
    blades[2].wind[2] = -1e30f;                                 // far beyond it: the deflection's bound
    blades[3].i1[0] = blades[3].i1[1] = blades[3].i1[2] = 0.0f; // zero length
    blades[3].i2[0] = blades[3].i2[1] = blades[3].i2[2] = 0.0f;
    for (int c = 0; c < 3; ++c) { // a tiny, stiff blade
        blades[4].i1[c] *= 1e-4f;
        blades[4].i2[c] *= 1e-4f;
    }
    blades[4].i1[3] = 1e5f;
    blades[5].gravity[1] = -1e4f; // heavy gravity into the ground
    blades[5].wind[3] = 100.0f;
    blades[6].gravity[1] = 1e4f; // and out of it
    blades[6].wind[3] = 100.0f;
    blades[7].up[3] = 1e5f; // eta that never decays
    set_blades(blades);
    // A huge ball over everything, a ball centred on the tips, a fast capsule.
    set_colliders({sphere(0.0f, 1e4f, 0.0f, 1e4f + 0.2f), sphere(0.0f, 0.47f, 0.12f, 0.05f),
                   Collider{{-1.0f, 0.2f, 0.0f, 0.1f}, {1.0f, 0.2f, 0.0f, 1.0f}, {0.0f, 0.0f, 1e3f, 0.0f}}});
    at_rest();
    const float dts[] = {10.0f, 10.0f, 1e-6f, 10.0f, 1.0f / 60.0f, 10.0f};
    for (float dt : dts) {
        step(dt);
        const std::vector<Pose> p = poses();
        const std::vector<grass::GpuBladeState> s = states();
        for (size_t i = 0; i < p.size(); ++i) {
            const float* values[] = {p[i].v1, p[i].v2, p[i].still_v1, p[i].still_v2, s[i].v2_eta, s[i].velocity};
            for (const float* v : values) {
                for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(v[c])) << "blade " << i << ", dt " << dt;
            }
            const float len = p[i].v1[3];
            EXPECT_GE(p[i].v2[3], 0.0f) << "eta, blade " << i;
            EXPECT_LE(p[i].v2[3], 1.0f) << "eta, blade " << i;
            if (len <= 0.0f) continue;
            EXPECT_GE(p[i].v2[1], -1e-5f * len) << "above the root's plane, blade " << i << ", dt " << dt;
            EXPECT_NEAR(drawn_length(p[i].v1, p[i].v2, 6), len, 0.01f * len) << "length, blade " << i << ", dt " << dt;
        }
    }
}

// The cost of one blade-step on this device (printed; recorded in docs/responsive.md): a
// step of 1/60 s of 16,384 blades, without colliders and with four.
TEST_F(BladeStateTest, CostPerBladeStep) {
    std::vector<TestBlade> blades(16384, blade());
    for (size_t i = 0; i < blades.size(); ++i) blades[i].wind[0] = float(i % 7);
    set_blades(blades);
    at_rest();
    double ns[2] = {};
    for (int with = 0; with < 2; ++with) {
        set_colliders(with == 0 ? std::vector<Collider>{}
                                : std::vector<Collider>{sphere(-0.06f, 0.45f, 0.12f, 0.1f), sphere(1, 0, 0, 0.2f),
                                                        sphere(0, 0, 1, 0.2f), sphere(-1, 0, 0, 0.2f)});
        step(1.0f / 60.0f);
        gl_.Finish();
        const int repeats = 10;
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < repeats; ++k) step(1.0f / 60.0f);
        gl_.Finish();
        const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
        ns[with] = took.count() / (repeats * double(blades.size()));
    }
    const std::vector<Pose> p = poses();
    EXPECT_TRUE(std::isfinite(p.back().v2[0]));
    EXPECT_GT(p[0].v2[0], 0.03f) << "the collider was stepped (not a vacuous timing)";
    std::printf("%s: %.0f ns a blade-step without colliders, %.0f ns with four (16,384 blades, 1/60 s)\n",
                host_->device_name().c_str(), ns[0], ns[1]);
}

} // namespace
} // namespace grass_test
