// Shared depth: the host's objects hide grass behind them and grass hides what is behind
// it. The check is built so that it fails when grass ignores the host's depth buffer.
#include "render_fixture.hpp"

namespace grass_test {
namespace {

class DepthTest : public RenderTest {};

TEST_P(DepthTest, ABoxDrawnByTheHostInFrontOfTheGrassHidesIt) {
    make_field(field_desc(16)); // 4 m x 4 m
    const double eye[3] = {2.0, 0.9, -0.5}, target[3] = {2.0, 0.0, 2.0};
    grass_view_desc v = view(eye, target);
    grass_host::Occluder box;
    box.x0 = 48;
    box.y0 = 48;
    box.x1 = 80;
    box.y1 = 80;
    box.distance = 0.4f; // closer than any grass: the nearest cell is 0.5 m ahead and below
    const auto image = render(v, &box);
    save(image, "depth");
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const uint8_t* centre = image.pixel(64, 64);
    // The box colour (0.8, 0.1, 0.1) linear is about (231, 89, 89) in sRGB.
    EXPECT_NEAR(centre[0], 231, 3);
    EXPECT_NEAR(centre[1], 89, 3);
    EXPECT_NEAR(centre[2], 89, 3);
    EXPECT_TRUE(is_grass(image.pixel(64, 110), sky)) << "off the box, below the horizon: grass";
    const uint8_t* corner = image.pixel(2, 2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(corner[c], sky[c], 2) << "the top corner shows the host's clear colour";

    // Without the depth test the same box shows grass at its centre: the check above can fail.
    v.flags = GRASS_VIEW_FLAG_NO_DEPTH_TEST;
    const auto no_depth = render(v, &box);
    save(no_depth, "no_depth_test");
    const uint8_t* c2 = no_depth.pixel(64, 64);
    EXPECT_GT(std::abs(int(c2[0]) - 231) + std::abs(int(c2[1]) - 89), 40) << "grass drawn over the box";
}

TEST_P(DepthTest, GrassHidesAHostBoxBehindIt) {
    make_field(field_desc(16));
    const double eye[3] = {2.0, 0.3, -0.5}, target[3] = {2.0, 0.2, 2.0};
    grass_host::Occluder wall;
    wall.x0 = 0;
    wall.y0 = 0;
    wall.x1 = 128;
    wall.y1 = 128;
    wall.distance = 30.0f; // far behind the 4 m field
    const auto image = render(view(eye, target), &wall);
    save(image, "wall");
    // Low rows look into the grass: it is in front of the wall, so grass colours win.
    const uint8_t* low = image.pixel(64, 120);
    EXPECT_FALSE(std::abs(int(low[0]) - 231) <= 3 && std::abs(int(low[1]) - 89) <= 3) << "grass in front of the wall";
    const uint8_t* high = image.pixel(64, 4);
    EXPECT_NEAR(high[0], 231, 3) << "the wall above the grass";
}

INSTANTIATE_TEST_SUITE_P(Backends, DepthTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
