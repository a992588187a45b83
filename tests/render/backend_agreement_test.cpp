// The GL and Vulkan backends draw the same picture of the same scene.
//
// Metric: mean absolute difference over all pixels and channels (8-bit sRGB levels), and
// the share of pixels whose largest channel difference exceeds 32 levels (a blade present
// in one image and not the other). Thresholds were set from measurements: see the note in
// docs/testing.md (measured values are printed by the test).
#include "render_fixture.hpp"

#include "image_io.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace grass_test {
namespace {

struct Rendered {
    grass_host::Image image;
    std::string validation;
};

Rendered render_scene(grass_backend backend, uint32_t samples) {
    Rendered out;
    grass_host::TargetDesc t;
    t.width = 160;
    t.height = 120;
    t.samples = samples;
    std::string error;
    auto host = grass_host::Host::create(backend, t, &error);
    EXPECT_TRUE(host) << error;
    if (!host) return out;
    grass_context* ctx = nullptr;
    grass_context_desc cd = grass_default_context_desc();
    EXPECT_EQ(host->create_context(cd, &ctx), GRASS_SUCCESS);
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    EXPECT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 16;
    grass_field_id field{};
    EXPECT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS);
    const double eye[3] = {2.0, 0.8, -0.6}, target[3] = {2.0, 0.0, 2.0};
    const grass_view_desc v = grass_host::make_view(*host, eye, target, 50.0f, 0.05f, 100.0f);
    EXPECT_EQ(host->render(ctx, v, nullptr, &out.image, &error), GRASS_SUCCESS) << error;
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    return out;
}

void compare(uint32_t samples, double max_mean_difference, double max_blade_share) {
    const Rendered gl = render_scene(GRASS_BACKEND_GL, samples);
    const Rendered vk = render_scene(GRASS_BACKEND_VULKAN, samples);
    ASSERT_EQ(gl.image.rgba.size(), vk.image.rgba.size());
    ASSERT_FALSE(gl.image.rgba.empty());
    double sum = 0.0;
    uint64_t blade_pixels = 0;
    const size_t pixels = gl.image.rgba.size() / 4;
    for (size_t k = 0; k < pixels; ++k) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(gl.image.rgba[4 * k + c]) - int(vk.image.rgba[4 * k + c]));
            sum += d;
            worst = std::max(worst, d);
        }
        blade_pixels += worst > 32;
    }
    const double mean = sum / (3.0 * pixels);
    const double share = double(blade_pixels) / pixels;
    std::printf("[ measured ] samples %u: mean |gl - vk| = %.4f levels, pixels > 32 levels apart = %.4f%%\n", samples,
                mean, 100.0 * share);
    if (const char* dir = std::getenv("GRASS_TEST_IMAGE_DIR")) {
        grass_host::write_png(std::string(dir) + "/agreement_gl_" + std::to_string(samples) + ".png", gl.image, nullptr);
        grass_host::write_png(std::string(dir) + "/agreement_vk_" + std::to_string(samples) + ".png", vk.image, nullptr);
    }
    EXPECT_LE(mean, max_mean_difference);
    EXPECT_LE(share, max_blade_share);
}

TEST(BackendAgreement, GlAndVulkanImagesOfTheSameSceneAgree) { compare(1, 0.5, 0.005); }

TEST(BackendAgreement, GlAndVulkanImagesAgreeWithFourTimesMultisampling) { compare(4, 0.5, 0.005); }

} // namespace
} // namespace grass_test
