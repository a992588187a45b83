// The other ways a host can hand over its target draw the same picture: Vulkan dynamic
// rendering instead of a render pass, and OSMesa instead of EGL for GL.
#include "render_fixture.hpp"

#include <cstdlib>

namespace grass_test {
namespace {

grass_host::Image render_with(grass_backend backend, const grass_host::TargetDesc& target) {
    const double eye[3] = {1.0, 0.7, -0.4}, look[3] = {1.0, 0.0, 1.0};
    return render_default_scene(backend, target, 8, eye, look);
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
        expect_grass(with_pass, t, 0.25, "the render pass's image"); // two images of the sky alone would agree
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
    expect_grass(egl, t, 0.25, "EGL's image"); // two images of the sky alone would agree
    EXPECT_LE(mean_difference(egl, osmesa), 0.05);
}
#endif

} // namespace
} // namespace grass_test
