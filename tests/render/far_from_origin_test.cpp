// Precision far from the origin (DESIGN: world positions stay double until they are made
// camera-relative). In both backends:
//  - a field 10,000 km out renders, from the same relative camera, the image of the same
//    field at the origin, within the GL-vs-Vulkan tolerance (per pixel, 1 sample);
//  - out there, moving the camera by 1 mm steps moves the grass on screen by the expected
//    sub-pixel amount, smoothly, exactly as it does at the origin.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace grass_test {
namespace {

class FarFromOriginTest : public RenderTest {
protected:
    // An 8 x 8 field (2 m x 2 m) with its corner at `origin`, seen from above its centre.
    grass_field_id field_at(double ox, double oz) {
        grass_field_desc d = field_desc(8);
        d.base_transform[12] = ox;
        d.base_transform[14] = oz;
        return make_field(d);
    }
    grass_view_desc top_down(double ox, double oz, double dx) {
        const double eye[3] = {ox + 1.0 + dx, kHeight, oz + 1.0};
        const double target[3] = {ox + 1.0 + dx, 0.0, oz + 1.0001};
        return view(eye, target, kFov);
    }
    static constexpr double kHeight = 3.0;
    static constexpr float kFov = 50.0f;
};

// 10,000 km out, at an offset that single precision cannot hold (its spacing there is 1 m).
const double kFar = 1e7 + 0.3719;

TEST_P(FarFromOriginTest, AFieldTenThousandKilometresOutRendersLikeOneAtTheOrigin) {
    const grass_field_id near_field = field_at(0.0, 0.0);
    // A fractional camera offset (0.3 m): single-precision placement would round the field
    // and the camera differently out there.
    const auto at_origin = render(top_down(0.0, 0.0, 0.3));
    ASSERT_EQ(grass_destroy_field(ctx, near_field), GRASS_SUCCESS);
    field_at(kFar, -kFar);
    const auto far_out = render(top_down(kFar, -kFar, 0.3));
    save(at_origin, "origin");
    save(far_out, "far");
    ASSERT_EQ(at_origin.rgba.size(), far_out.rgba.size());
    const double diff = mean_difference(at_origin, far_out);
    std::printf("[ measured ] %s: mean |origin - 10,000 km| = %.4f levels\n", backend_name(GetParam()).c_str(), diff);
    EXPECT_LE(diff, 0.05) << "the GL-vs-Vulkan per-pixel tolerance (docs/testing.md)";
}

TEST_P(FarFromOriginTest, MillimetreMovesFarOutShiftTheGrassSmoothlyBySubPixelAmounts) {
    grass_host::TargetDesc t;
    t.width = t.height = 256;
    t.samples = 4; // coverage follows sub-pixel motion
    start(t);
    const int steps = 16;
    // 0: at the origin, 1: 10,000 km out (RenderTest::step_camera; ExtremesTest runs it at
    // 1 m, 1 km, 100 km and 10,000 km on a float target).
    const CameraSteps origin = step_camera(0.0, 0.0, steps, 0.001, kHeight);
    const CameraSteps far_out = step_camera(kFar, -kFar, steps, 0.001, kHeight);
    // Out there every 1 mm step draws what it draws at the origin, where double precision
    // leaves no doubt: the same sub-pixel motion, no jumps.
    for (int k = 0; k <= steps; ++k) {
        EXPECT_LE(mean_difference(origin.frames[k], far_out.frames[k]), 0.05) << "step " << k << " mm";
    }
    // Each millimetre changes the picture, by less than half a pixel of motion.
    for (int k = 1; k <= steps; ++k) {
        EXPECT_GT(mean_difference(far_out.frames[k], far_out.frames[k - 1]), 0.0)
            << "step " << k << " mm moves the grass";
        EXPECT_LT(std::fabs(far_out.shift[k] - far_out.shift[k - 1]), 0.5) << "step " << k << " mm: no jump";
    }
    // The amount: a ground point moves dx * f_px / depth (least-squares slope through zero).
    std::printf("[ measured ] %s: grass moves %.4f px per mm 10,000 km out (expected %.4f .. %.4f)\n",
                backend_name(GetParam()).c_str(), far_out.px_per_step, far_out.expected_lo, far_out.expected_hi);
    EXPECT_GE(far_out.px_per_step, far_out.expected_lo * 0.85);
    EXPECT_LE(far_out.px_per_step, far_out.expected_hi * 1.15);
}

INSTANTIATE_TEST_SUITE_P(Backends, FarFromOriginTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
