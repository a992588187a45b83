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

// Centre of the grass, weighted by how far each pixel is from the sky colour, in pixels.
double grass_centroid_x(const grass_host::Image& image, const uint8_t sky[3]) {
    double sum_w = 0.0, sum_x = 0.0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = image.pixel(x, y);
            const double w = std::abs(p[0] - sky[0]) + std::abs(p[1] - sky[1]) + std::abs(p[2] - sky[2]);
            sum_w += w;
            sum_x += w * (x + 0.5);
        }
    }
    return sum_x / sum_w;
}

TEST_P(FarFromOriginTest, MillimetreMovesFarOutShiftTheGrassSmoothlyBySubPixelAmounts) {
    grass_host::TargetDesc t;
    t.width = t.height = 256;
    t.samples = 4; // coverage follows sub-pixel motion
    start(t);
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const int steps = 16;
    std::vector<double> shift[2];
    std::vector<grass_host::Image> frames[2];
    for (int pass = 0; pass < 2; ++pass) { // 0: at the origin, 1: 10,000 km out
        const double ox = pass == 0 ? 0.0 : kFar, oz = pass == 0 ? 0.0 : -kFar;
        const grass_field_id f = field_at(ox, oz);
        for (int k = 0; k <= steps; ++k) {
            frames[pass].push_back(render(top_down(ox, oz, 0.001 * k)));
            shift[pass].push_back(grass_centroid_x(frames[pass].back(), sky) - grass_centroid_x(frames[pass][0], sky));
        }
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    }
    // Out there every 1 mm step draws what it draws at the origin, where double precision
    // leaves no doubt: the same sub-pixel motion, no jumps.
    for (int k = 0; k <= steps; ++k) {
        EXPECT_LE(mean_difference(frames[0][k], frames[1][k]), 0.05) << "step " << k << " mm";
    }
    // Each millimetre changes the picture, by less than half a pixel of motion.
    for (int k = 1; k <= steps; ++k) {
        EXPECT_GT(mean_difference(frames[1][k], frames[1][k - 1]), 0.0) << "step " << k << " mm moves the grass";
        EXPECT_LT(std::fabs(shift[1][k] - shift[1][k - 1]), 0.5) << "step " << k << " mm: no jump";
    }
    // The amount: a ground point moves dx * f_px / depth; blades stand up to ~0.21 m, so the
    // depth is between kHeight - 0.21 and kHeight. Least-squares slope through zero.
    const double f_px = 128.0 / std::tan(kFov * 3.141592653589793 / 360.0);
    const double lo = f_px / kHeight * 0.001, hi = f_px / (kHeight - 0.25) * 0.001; // px per mm
    double sxy = 0.0, sxx = 0.0;
    for (int k = 0; k <= steps; ++k) {
        sxy += k * shift[1][k];
        sxx += double(k) * k;
    }
    const double slope = std::fabs(sxy / sxx);
    std::printf("[ measured ] %s: grass moves %.4f px per mm 10,000 km out (expected %.4f .. %.4f)\n",
                backend_name(GetParam()).c_str(), slope, lo, hi);
    EXPECT_GE(slope, lo * 0.85);
    EXPECT_LE(slope, hi * 1.15);
}

INSTANTIATE_TEST_SUITE_P(Backends, FarFromOriginTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
