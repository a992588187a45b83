// Mirrored aperiodic tiling seen on screen: an 8 x 8 field renders differently with and
// without mirroring, with the same amount of grass.
#include "render_fixture.hpp"

namespace grass_test {
namespace {

class MirrorTest : public RenderTest {};

TEST_P(MirrorTest, AnEightByEightFieldRendersDifferentlyWithoutMirroring) {
    grass_field_desc d = field_desc(8);
    const double eye[3] = {1.0, 3.2, 1.0}, target[3] = {1.0, 0.0, 1.0001};
    uint8_t sky[3];
    expected_sky(host->target(), sky);

    d.mirror_tiling = 0;
    const grass_field_id plain = make_field(d);
    const auto periodic = render(view(eye, target, 40.0f));
    ASSERT_EQ(grass_destroy_field(ctx, plain), GRASS_SUCCESS);
    d.mirror_tiling = 1;
    make_field(d);
    const auto mirrored = render(view(eye, target, 40.0f));
    save(periodic, "periodic");
    save(mirrored, "mirrored");

    uint64_t differing = 0;
    for (uint32_t y = 0; y < periodic.height; ++y) {
        for (uint32_t x = 0; x < periodic.width; ++x) {
            const uint8_t* a = periodic.pixel(x, y);
            const uint8_t* b = mirrored.pixel(x, y);
            differing += std::abs(int(a[0]) - int(b[0])) + std::abs(int(a[1]) - int(b[1])) > 24;
        }
    }
    const double share = double(differing) / (periodic.width * periodic.height);
    EXPECT_GT(share, 0.25) << "mirroring moves blades across most of the frame";
    const double ga = grass_share(periodic, sky, 0, 0, 128, 128), gb = grass_share(mirrored, sky, 0, 0, 128, 128);
    EXPECT_NEAR(ga, gb, 0.05) << "the same amount of grass";
}

INSTANTIATE_TEST_SUITE_P(Backends, MirrorTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
