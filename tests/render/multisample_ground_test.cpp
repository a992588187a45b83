// The volume over the host's ground, seen from above (issue 32, item 4). From 20 m up the
// football field with 4 samples was 17.8 levels darker on Vulkan than on GL, in rows of
// stripes. The volume's depth lies at its horizontal slice or on the field's plane, where the
// host drew its ground, and the ground won the samples whose depth lay nearer than the
// pixel's centre: it showed through the grass. volume.frag now keeps the depth it writes in
// front of the plane's nearest sample (in_front_of_plane). What made the backends differ was
// the test hosts' ground, one 4 km square whose clipped triangles both drivers interpolated
// with errors as large as the grass's height over it (now a grid: test_hosts/shaders/ground.vert).
// Measured per backend: the mean green of bands of rows with 4 samples against 1 sample, with
// the standard and the reversed depth convention. Where nothing shows through the grass they
// agree within 2 levels; before the fix they differed by 3.3-3.5 levels from 20 m and 23-25
// from 60 m up, on both backends.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>

namespace grass_test {
namespace {

constexpr uint32_t kCells = 400; // 100 m x 100 m
constexpr uint32_t kWidth = 160, kHeight = 90, kBands = 9;

struct Camera {
    const char* name;
    double eye[3], at[3];
};
// Elevated (20 m up, 30 degrees down) and strategic (60 m up, 55 degrees down).
const Camera kCameras[] = {{"elevated", {50.0, 20.0, 10.0}, {50.0, 0.0, 44.6}},
                           {"strategic", {50.0, 60.0, 10.0}, {50.0, 0.0, 52.0}}};

class MultisampleGroundTest : public RenderTest {
protected:
    // The mean green level of each of kBands bands of rows, over the middle half of the image.
    std::vector<double> bands(const Camera& camera, uint32_t samples, bool reversed_z) {
        grass_host::TargetDesc t;
        t.width = kWidth;
        t.height = kHeight;
        t.samples = samples;
        t.ground = true;
        t.reversed_z = reversed_z;
        start(t);
        make_field(solo_tier_field(kCells, GRASS_TIER_VOLUME, 2, 16));
        const grass_host::Image image = render(view(camera.eye, camera.at, 30.0f));
        save(image, std::string(camera.name) + (reversed_z ? "_reversed_" : "_") + std::to_string(samples));
        std::vector<double> mean(kBands, 0.0);
        const uint32_t rows = kHeight / kBands;
        for (uint32_t y = 0; y < kBands * rows; ++y) {
            for (uint32_t x = kWidth / 4; x < 3 * kWidth / 4; ++x) mean[y / rows] += image.pixel(x, y)[1];
        }
        for (double& m : mean) m /= double(rows) * (kWidth / 2);
        return mean;
    }
};

TEST_P(MultisampleGroundTest, FromAboveTheGroundShowsThroughTheVolumeNoMoreWithFourSamples) {
    for (const Camera& camera : kCameras) {
        for (const bool reversed : {false, true}) {
            const std::vector<double> one = bands(camera, 1, reversed), four = bands(camera, 4, reversed);
            double worst = 0.0;
            for (uint32_t b = 0; b < kBands; ++b) {
                // Not vacuous: grass, not the host's dark ground (green level about 53), fills the band.
                EXPECT_GT(one[b], 80.0) << camera.name << " band " << b;
                worst = std::max(worst, std::abs(four[b] - one[b]));
            }
            std::printf("[ measured ] %s %s%s: worst band, 4 samples against 1: %.1f green levels\n",
                        backend_name(GetParam()).c_str(), camera.name, reversed ? " (reversed depth)" : "", worst);
            // Measured with the fix: 0.5-1.4 on GL, 0.4-1.5 on Vulkan.
            EXPECT_LE(worst, 2.0) << camera.name << (reversed ? ", reversed depth" : "");
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, MultisampleGroundTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
