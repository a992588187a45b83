// Density thresholds against the field density and the density map, in both backends.
#include "render_fixture.hpp"

#include <cmath>
#include <vector>

namespace grass_test {
namespace {

class DensityTest : public RenderTest {};

const double kTopEye[3] = {1.0, 4.0, 1.0};
const double kTopTarget[3] = {1.0, 0.0, 1.0001};

TEST_P(DensityTest, ZeroDensityLeavesNoGrassPixel) {
    grass_field_desc d = field_desc(8);
    d.density = 0.0f;
    make_field(d);
    const auto image = render(view(kTopEye, kTopTarget));
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    EXPECT_EQ(grass_share(image, sky, 0, 0, image.width, image.height), 0.0);
    save(image, backend_name(GetParam()));
}

TEST_P(DensityTest, AZeroDensityMapLeavesNoGrassPixel) {
    grass_field_desc d = field_desc(8);
    const std::vector<uint8_t> zeros(16 * 16, 0);
    grass_map_desc m = grass_default_map_desc();
    m.pixels = zeros.data();
    m.width = m.height = 16;
    m.format = GRASS_MAP_FORMAT_R8_UNORM;
    d.density_map = &m;
    make_field(d);
    const auto image = render(view(kTopEye, kTopTarget));
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    EXPECT_EQ(grass_share(image, sky, 0, 0, image.width, image.height), 0.0);
}

// Seen at a slant, full-density grass hides the ground it stands on: every pixel whose ray
// meets the field (away from its edges) is grass, and no pixel whose ray passes far above
// the field is.
TEST_P(DensityTest, FullDensityCoversTheShareOfTheFrameWhereTheFieldIs) {
    make_field(field_desc(16)); // 4 m x 4 m
    const double eye[3] = {2.0, 1.0, -1.0}, target[3] = {2.0, 0.0, 1.5};
    const float fov = 50.0f;
    const auto image = render(view(eye, target, fov));
    save(image, backend_name(GetParam()));
    uint8_t sky[3];
    expected_sky(host->target(), sky);

    // Cast each pixel's ray on the CPU.
    double f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    const double r[3] = {-f[2], 0.0, f[0]}; // cross(f, up), |r| = 1 since f.x = 0 here
    const double rl = std::sqrt(r[0] * r[0] + r[2] * r[2]);
    const double rn[3] = {r[0] / rl, 0.0, r[2] / rl};
    const double u[3] = {rn[1] * f[2] - rn[2] * f[1], rn[2] * f[0] - rn[0] * f[2], rn[0] * f[1] - rn[1] * f[0]};
    const double t = std::tan(fov * 3.141592653589793 / 360.0);
    uint64_t inside = 0, inside_grass = 0, outside = 0, outside_grass = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const double sx = (2.0 * (x + 0.5) / image.width - 1.0) * t;
            const double sy = (1.0 - 2.0 * (y + 0.5) / image.height) * t;
            double dir[3];
            for (int c = 0; c < 3; ++c) dir[c] = f[c] + sx * rn[c] + sy * u[c];
            const bool grass = is_grass(image.pixel(x, y), sky);
            // Ray against the ground plane, and against a plane 0.4 m above it (taller than
            // any blade: default blades are at most 0.85 x 0.25 m).
            if (dir[1] < 0.0) {
                const double s = -eye[1] / dir[1];
                const double gx = eye[0] + s * dir[0], gz = eye[2] + s * dir[2];
                if (gx > 0.3 && gx < 3.7 && gz > 0.3 && gz < 3.7) {
                    ++inside;
                    inside_grass += grass;
                    continue;
                }
            }
            // Outside: the ray passes the plane 0.4 m up beyond the field's far or side edges
            // (or never comes down), so it cannot meet a blade.
            const double lift = 0.4;
            bool misses = dir[1] >= 0.0;
            if (!misses) {
                const double s = (lift - eye[1]) / dir[1];
                const double gx = eye[0] + s * dir[0], gz = eye[2] + s * dir[2];
                misses = gz > 4.0 + lift || gx < -lift || gx > 4.0 + lift;
            }
            if (misses) {
                ++outside;
                outside_grass += grass;
            }
        }
    }
    ASSERT_GT(inside, image.width * image.height / 4) << "the field fills a good part of the frame";
    ASSERT_GT(outside, image.width * image.height / 10) << "and some sky is seen past it";
    EXPECT_GE(double(inside_grass) / inside, 0.98) << "grass hides the ground inside the field";
    EXPECT_EQ(outside_grass, 0u) << "no grass where the field is not";
}

TEST_P(DensityTest, HalfDensityThinsTheGrassSeenFromAbove) {
    grass_field_desc d = field_desc(8);
    const grass_field_id full = make_field(d);
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const auto image_full = render(view(kTopEye, kTopTarget, 20.0f));
    const double share_full = grass_share(image_full, sky, 16, 16, 112, 112);
    ASSERT_EQ(grass_destroy_field(ctx, full), GRASS_SUCCESS);
    d.density = 0.5f;
    make_field(d);
    const auto image_half = render(view(kTopEye, kTopTarget, 20.0f));
    const double share_half = grass_share(image_half, sky, 16, 16, 112, 112);
    save(image_full, "full");
    save(image_half, "half");
    EXPECT_GT(share_full, 0.5);
    EXPECT_GT(share_half, 0.15);
    EXPECT_LT(share_half, share_full * 0.85);
}

TEST_P(DensityTest, TheZeroHalfOfADensityMapIsEmptyAndTheFullHalfIsNot) {
    grass_field_desc d = field_desc(8);
    std::vector<uint16_t> texels(32 * 32);
    for (uint32_t z = 0; z < 32; ++z) {
        for (uint32_t x = 0; x < 32; ++x) texels[z * 32 + x] = x < 16 ? 0 : 65535; // x < 1 m: no grass
    }
    grass_map_desc m = grass_default_map_desc();
    m.pixels = texels.data();
    m.width = m.height = 32;
    m.format = GRASS_MAP_FORMAT_R16_UNORM;
    d.density_map = &m;
    make_field(d);
    // Top-down, image x follows world x; 20 degrees from 4 m sees about 1.4 m across.
    const auto image = render(view(kTopEye, kTopTarget, 20.0f));
    save(image, backend_name(GetParam()));
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    // World x < 0.85 m (left of the boundary by more than a blade's lean) must be empty.
    // The view spans x in [1 - 0.705, 1 + 0.705] over 128 pixels.
    const double metres_per_pixel = 2.0 * 4.0 * std::tan(10.0 * 3.141592653589793 / 180.0) / 128.0;
    const auto px = [&](double world_x) { return static_cast<uint32_t>((world_x - 1.0) / metres_per_pixel + 64.0); };
    EXPECT_EQ(grass_share(image, sky, 0, 0, px(0.85), 128), 0.0);
    EXPECT_GT(grass_share(image, sky, px(1.15), 0, 128, 128), 0.5);
}

INSTANTIATE_TEST_SUITE_P(Backends, DensityTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
