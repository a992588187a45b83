// The other ways a host can hand over its target draw the same picture: Vulkan dynamic
// rendering instead of a render pass, and OSMesa instead of EGL for GL.
#include "render_fixture.hpp"

#include <cstdlib>

namespace grass_test {
namespace {

grass_host::Image render_with(grass_backend backend, const grass_host::TargetDesc& target) {
    grass_host::Image image;
    std::string error;
    auto host = grass_host::Host::create(backend, target, &error);
    EXPECT_TRUE(host) << error;
    if (!host) return image;
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    EXPECT_EQ(host->create_context(cd, &ctx), GRASS_SUCCESS);
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    EXPECT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 8;
    grass_field_id field{};
    EXPECT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS);
    const double eye[3] = {1.0, 0.7, -0.4}, look[3] = {1.0, 0.0, 1.0};
    const grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f, 0.05f, 100.0f);
    EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error;
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    return image;
}

double mean_difference(const grass_host::Image& a, const grass_host::Image& b) {
    if (a.rgba.size() != b.rgba.size() || a.rgba.empty()) return 1e9;
    double sum = 0.0;
    for (size_t k = 0; k < a.rgba.size(); ++k) {
        if (k % 4 != 3) sum += std::abs(int(a.rgba[k]) - int(b.rgba[k]));
    }
    return sum / (a.rgba.size() / 4 * 3);
}

#ifdef GRASS_HOST_HAS_VULKAN
TEST(HostPaths, VulkanDynamicRenderingDrawsWhatTheRenderPassDraws) {
    for (uint32_t samples : {1u, 4u}) {
        grass_host::TargetDesc t;
        t.width = 96;
        t.height = 96;
        t.samples = samples;
        const auto with_pass = render_with(GRASS_BACKEND_VULKAN, t);
        t.vk_dynamic_rendering = true;
        const auto dynamic = render_with(GRASS_BACKEND_VULKAN, t);
        EXPECT_EQ(mean_difference(with_pass, dynamic), 0.0) << samples << " samples";
    }
}
#endif

#ifdef GRASS_HOST_HAS_GL
TEST(HostPaths, TheOsMesaFallbackDrawsWhatEglDraws) {
    grass_host::TargetDesc t;
    t.width = 96;
    t.height = 96;
    ::setenv("GRASS_HOST_GL", "egl", 1);
    const auto egl = render_with(GRASS_BACKEND_GL, t);
    ::setenv("GRASS_HOST_GL", "osmesa", 1);
    const auto osmesa = render_with(GRASS_BACKEND_GL, t);
    ::unsetenv("GRASS_HOST_GL");
    EXPECT_LE(mean_difference(egl, osmesa), 0.05);
}
#endif

} // namespace
} // namespace grass_test
