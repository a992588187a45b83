// Per-blade state in rendered frames (docs/responsive.md "Per-blade state"): the blade window
// pass steps each held blade's state (jahrmann2017 5: recovery weakened by eta, wind,
// gravity, push-out of colliders) by the frame's time step. GL: the window's records (pose,
// previous pose, state per blade, api/src/foundation/frame_plan.hpp kBladeWindowRecordBytes)
// are read back through the host's GL, from the buffer grass labels "grass blade window
// poses" (debug labels on). Vulkan runs no window pass yet.
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace grass_test {
namespace {

// One blade's record in the window (blade_window.glsl).
struct Record {
    float pose_v1[4]; // xyz: v1, w: shade
    float pose_v2[4]; // xyz: v2
    float prev_v1[4]; // the previous frame's pose
    float prev_v2[4];
    float state_v2[4]; // xyz: the free tip (relative to the root), w: eta
    float velocity[4]; // xyz: the tip's velocity
};
static_assert(sizeof(Record) == 96, "the window's record (kBladeWindowRecordBytes)");

class BladeStateRenderTest : public RenderTest {
protected:
    void SetUp() override {
        labels.labels = GRASS_DEBUG_LABELS_ON; // the read-back finds the window's buffer by its label
        context_next = &labels;
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = 64;
        t.height = 48;
        start(t);
        make_scene();
    }

    // The patch's mechanics and the field (again after start() made a new context).
    void make_scene() {
        grass_blade_mechanics m = grass_default_blade_mechanics();
        m.variation = 0.0f;     // every blade alike
        m.recovery_time = 1.0f; // eta falls by 1 a second
        ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << log;
        make_field(field_desc(8)); // 2 m x 2 m from the origin, 0.25 m cells
    }

    // A frame at `time` seen from above the field's centre.
    grass_host::Image frame(double time) {
        const double eye[3] = {1.0, 2.2, -0.6}, look[3] = {1.0, 0.0, 1.0};
        grass_view_desc v = view(eye, look, 60.0f);
        v.time = time;
        return render(v);
    }

    // The window's records, read back from its buffer.
    std::vector<Record> records() const {
        const auto is_buffer = reinterpret_cast<PFNGLISBUFFERPROC>(host->gl_proc_address("glIsBuffer"));
        const auto get_label = reinterpret_cast<PFNGLGETOBJECTLABELPROC>(host->gl_proc_address("glGetObjectLabel"));
        const auto get_size = reinterpret_cast<PFNGLGETNAMEDBUFFERPARAMETERI64VPROC>(
            host->gl_proc_address("glGetNamedBufferParameteri64v"));
        const auto get_data =
            reinterpret_cast<PFNGLGETNAMEDBUFFERSUBDATAPROC>(host->gl_proc_address("glGetNamedBufferSubData"));
        EXPECT_TRUE(is_buffer && get_label && get_size && get_data);
        std::vector<Record> out;
        if (!is_buffer || !get_label || !get_size || !get_data) return out;
        for (GLuint name = 1; name < 4096; ++name) {
            if (!is_buffer(name)) continue;
            char text[64] = {};
            GLsizei length = 0;
            get_label(GL_BUFFER, name, sizeof text, &length, text);
            if (std::strcmp(text, "grass blade window poses") != 0) continue;
            GLint64 bytes = 0;
            get_size(name, GL_BUFFER_SIZE, &bytes);
            out.resize(size_t(bytes) / sizeof(Record));
            get_data(name, 0, static_cast<GLsizeiptr>(out.size() * sizeof(Record)), out.data());
            return out;
        }
        ADD_FAILURE() << "no buffer labelled \"grass blade window poses\"";
        return out;
    }

    // A collider far off the field: the interaction map (and so the window) exists, nothing
    // is touched.
    void far_collider() {
        grass_collider c{};
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = 0.1f;
        c.center[0] = 30.0;
        c.center[2] = 30.0;
        ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
    }

    // A ball of radius `r` at (x, y, z), rolling at `vx`, `vz` m/s.
    void ball(double x, double y, double z, float r, float vx, float vz) {
        grass_collider c{};
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = r;
        c.center[0] = x;
        c.center[1] = y;
        c.center[2] = z;
        c.velocity[0] = vx;
        c.velocity[2] = vz;
        ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
    }

    void steady_wind(float speed) {
        grass_wind_desc w = grass_default_wind_desc();
        w.direction[0] = 1.0f;
        w.direction[1] = 0.0f;
        w.direction[2] = 0.0f;
        w.speed = speed;
        w.gust_strength = 0.0f;
        w.turbulence = 0.0f;
        ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    }

    grass_debug_labels_desc labels = grass_default_debug_labels_desc();
};

// Mean of the state's tip along x minus `rest`'s, over every record.
double mean_tip_x(const std::vector<Record>& now, const std::vector<Record>& rest) {
    double sum = 0.0;
    const size_t n = std::min(now.size(), rest.size());
    for (size_t k = 0; k < n; ++k) sum += double(now[k].state_v2[0]) - double(rest[k].state_v2[0]);
    return n > 0 ? sum / double(n) : 0.0;
}

// A step gust: still air, then a steady 8 m/s wind along +x from one frame to the next
// (60 fps). The tips lag (the first frame has moved them a fraction of the way to where
// the stateless pose puts them), overshoot (the damped spring, 25% for damping 0.4 before
// the validation shortens it), and settle there.
TEST_P(BladeStateRenderTest, AStepGustMakesTipsLagThenOvershoot) {
    far_collider();
    frame(0.0); // the cells enter the window at rest
    const std::vector<Record> rest = records();
    ASSERT_FALSE(rest.empty());
    steady_wind(8.0f);
    std::vector<double> along;
    for (int k = 1; k <= 150; ++k) {
        frame(k / 60.0);
        along.push_back(mean_tip_x(records(), rest));
    }
    const double settled = along.back();
    const double peak = *std::max_element(along.begin(), along.end());
    std::printf("step gust: mean tip +x after 1 frame %.4f m, peak %.4f m, after 2.5 s %.4f m (1 frame before %.4f)\n",
                along[0], peak, settled, along[along.size() - 2]);
    EXPECT_GT(settled, 0.02) << "the wind must bend the blades for the test to mean anything";
    EXPECT_LT(along[0], 0.25 * settled) << "a blade lags behind the gust";
    EXPECT_GT(peak, 1.08 * settled) << "and overshoots";
    EXPECT_LT(std::fabs(along.back() - along[along.size() - 2]), 0.01 * settled) << "then settles";
}

// A ball rolls along the field's left edge (its centre 0.35 m outside it, along +z): the
// blades it reaches are pushed out of it (eq. 15-16), their tips away from its centre, so to
// +x; the stateless pose has no such push (the free tips stand where they entered).
TEST_P(BladeStateRenderTest, ARollingBallPushesBladesAwayFromItsCentre) {
    far_collider();
    frame(0.0);
    const std::vector<Record> rest = records();
    ASSERT_FALSE(rest.empty());
    grass_host::Image image;
    for (int k = 1; k <= 45; ++k) {
        const double t = k / 30.0;
        ball(-0.35, 0.25, -0.5 + 1.0 * t, 0.45f, 0.0f, 1.0f);
        image = frame(t);
    }
    save(image, "rolling_ball");
    expect_grass(image, host->target(), 0.1, "the rolling ball's frame"); // the field in view
    const std::vector<Record> now = records();
    ASSERT_EQ(now.size(), rest.size());
    size_t pushed = 0, outward = 0;
    double sum_x = 0.0, largest = 0.0;
    for (size_t k = 0; k < now.size(); ++k) {
        const double dx = double(now[k].state_v2[0]) - rest[k].state_v2[0];
        const double dy = double(now[k].state_v2[1]) - rest[k].state_v2[1];
        const double dz = double(now[k].state_v2[2]) - rest[k].state_v2[2];
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (d < 0.01) continue;
        ++pushed;
        outward += dx > 0.0;
        sum_x += dx;
        largest = std::max(largest, d);
    }
    std::printf("rolling ball: %zu of %zu blades pushed over 1 cm, %zu of them to +x, mean %.4f m along x, largest "
                "%.4f m\n",
                pushed, now.size(), outward, pushed ? sum_x / double(pushed) : 0.0, largest);
    EXPECT_GT(pushed, 100u) << "the ball must reach blades for the test to mean anything";
    EXPECT_GT(double(outward), 0.9 * double(pushed)) << "pushed away from the ball's centre";
    EXPECT_GT(sum_x / double(std::max<size_t>(pushed, 1)), 0.02);
}

// A ball rests on the field's middle: eta (the collision strength, eq. 2-3, 16) builds up in
// the blades it holds; once it is gone, eta falls back to 0 within the recovery time (1 s).
TEST_P(BladeStateRenderTest, EtaBuildsUnderARestingBallAndRecovers) {
    far_collider();
    frame(0.0);
    auto eta = [&](size_t* over_half) {
        double most = 0.0;
        *over_half = 0;
        for (const Record& r : records()) {
            most = std::max(most, double(r.state_v2[3]));
            *over_half += r.state_v2[3] > 0.5f;
        }
        return most;
    };
    size_t held = 0, left = 0;
    for (int k = 1; k <= 30; ++k) {
        ball(1.0, 0.2, 1.0, 0.3f, 0.0f, 0.0f);
        frame(k / 30.0);
    }
    const double built = eta(&held);
    far_collider();
    for (int k = 31; k <= 75; ++k) frame(k / 30.0);
    const double after = eta(&left);
    std::printf("eta: after 1 s under the ball at most %.3f (%zu blades over 0.5), 1.5 s after it left %.3f\n", built,
                held, after);
    EXPECT_GT(built, 0.9);
    EXPECT_GT(held, 20u);
    EXPECT_EQ(after, 0.0);
    EXPECT_EQ(left, 0u);
}

// The same second of wind pressing blades into a resting ball, stepped at 60 fps, at 30 fps
// and in one step of 1 s: 30 and 60 fps take the same 1/60 s substeps and agree to rounding;
// the 1 s step (16 substeps of 1/16 s) within 0.08 of the blade's length (blade_state.hpp),
// here against the blade's rest chord (shorter than its length).
TEST_P(BladeStateRenderTest, ThirtySixtyFpsAndOneSecondStepsAgree) {
    const grass_host::TargetDesc target = host->target();
    std::vector<Record> runs[3];
    std::vector<Record> rest;
    const int frames[3] = {60, 30, 1};
    for (int r = 0; r < 3; ++r) {
        if (r > 0) {
            start(target);
            make_scene();
        }
        far_collider();
        frame(0.0);
        if (r == 0) rest = records();
        steady_wind(6.0f);
        for (int k = 1; k <= frames[r]; ++k) {
            const double t = double(k) / frames[r];
            ball(1.2, 0.24, 1.0, 0.1f, 0.0f, 0.0f); // over the tips: the wind presses them into it
            frame(t);
        }
        runs[r] = records();
        ASSERT_EQ(runs[r].size(), rest.size());
    }
    // The state (the free tip the pass steps), against each blade's rest chord; the drawn
    // poses are printed too: the interaction map's press lays a pressed blade along its
    // texel's direction, from the lowest of three samples taken on the pose, so a blade the
    // state holds at the edge of a press may be laid another way.
    double apart30 = 0.0, apart1 = 0.0, moved = 0.0, drawn1 = 0.0;
    for (size_t k = 0; k < rest.size(); ++k) {
        const double chord = std::sqrt(double(rest[k].pose_v2[0]) * rest[k].pose_v2[0] +
                                       double(rest[k].pose_v2[1]) * rest[k].pose_v2[1] +
                                       double(rest[k].pose_v2[2]) * rest[k].pose_v2[2]);
        for (int c = 0; c < 3; ++c) {
            const double d60 = runs[0][k].state_v2[c];
            apart30 = std::max(apart30, std::fabs(runs[1][k].state_v2[c] - d60) / chord);
            apart1 = std::max(apart1, std::fabs(runs[2][k].state_v2[c] - d60) / chord);
            moved = std::max(moved, std::fabs(double(runs[0][k].pose_v2[c]) - rest[k].pose_v2[c]) / chord);
            drawn1 = std::max(drawn1, std::fabs(double(runs[2][k].pose_v2[c]) - runs[0][k].pose_v2[c]) / chord);
        }
    }
    std::printf("after 1 s: drawn tips moved up to %.3f chords; states: 30 fps vs 60 fps %.2e, 1 s step vs 60 fps "
                "%.4f chords (drawn poses %.4f)\n",
                moved, apart30, apart1, drawn1);
    EXPECT_GT(moved, 0.2) << "wind and the ball must move the tips for the comparison to mean something";
    EXPECT_LT(apart30, 1e-3);
    EXPECT_LT(apart1, 0.08);
}

INSTANTIATE_TEST_SUITE_P(Backends, BladeStateRenderTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
