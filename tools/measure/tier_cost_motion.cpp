// grass-measure tier-cost --motion: the plain table's rows drawn without and with motion
// vectors (grass_view_motion_desc), without wind and in wind, into the host's framebuffer
// with a velocity target: GL an RG16F renderbuffer added at draw buffer 1, Vulkan the host's
// RGBA32F colour attachment 1 of its pass (the Rig makes the host with it). Also the GL
// targets that --motion and --gbuffer add (add_colour_targets).
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace grass_measure {
namespace tier_cost {

bool add_colour_targets(grass_host::Host& host, uint32_t width, uint32_t height, const uint32_t* formats,
                        uint32_t count, uint32_t* out) {
    const auto get = reinterpret_cast<PFNGLGETINTEGERVPROC>(host.gl_proc_address("glGetIntegerv"));
    const auto create = reinterpret_cast<PFNGLCREATERENDERBUFFERSPROC>(host.gl_proc_address("glCreateRenderbuffers"));
    const auto storage = reinterpret_cast<PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEPROC>(
        host.gl_proc_address("glNamedRenderbufferStorageMultisample"));
    const auto attach =
        reinterpret_cast<PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC>(host.gl_proc_address("glNamedFramebufferRenderbuffer"));
    const auto buffers =
        reinterpret_cast<PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC>(host.gl_proc_address("glNamedFramebufferDrawBuffers"));
    GLint framebuffer = 0, samples = 0;
    get(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    get(GL_SAMPLES, &samples);
    if (framebuffer == 0 || count > 7) return false;
    GLenum list[8] = {GL_COLOR_ATTACHMENT0};
    create(GLsizei(count), out);
    for (uint32_t i = 0; i < count; ++i) {
        storage(out[i], samples, GLenum(formats[i]), GLsizei(width), GLsizei(height));
        attach(GLuint(framebuffer), GL_COLOR_ATTACHMENT1 + i, GL_RENDERBUFFER, out[i]);
        list[i + 1] = GL_COLOR_ATTACHMENT1 + i;
    }
    buffers(GLuint(framebuffer), GLsizei(count + 1), list);
    return true;
}

void delete_colour_targets(grass_host::Host& host, uint32_t count, const uint32_t* targets) {
    const auto destroy = reinterpret_cast<PFNGLDELETERENDERBUFFERSPROC>(host.gl_proc_address("glDeleteRenderbuffers"));
    destroy(GLsizei(count), targets);
}

int run_motion(Rig& rig, const std::vector<Setup>& rows) {
    const Options& o = rig.options();
    grass_context* ctx = rig.ctx();
    const bool gl = o.backend == GRASS_BACKEND_GL;
    rig.frame_times(1); // the host binds its framebuffer and leaves it bound
    const uint32_t rg16f = GL_RG16F;
    GLuint velocity = 0;
    if (gl && !add_colour_targets(rig.host(), o.width, o.height, &rg16f, 1, &velocity)) {
        std::fprintf(stderr, "grass-tier-cost --motion: the host left no framebuffer bound\n");
        return 1;
    }
    // The previous frame: the camera 5 cm to the side, a frame (1/60 s) earlier.
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    const grass_view_desc& view = rig.view();
    for (int c = 0; c < 3; ++c) motion.previous_camera_position[c] = view.camera_position[c] + (c == 0 ? 0.05 : 0.0);
    std::memcpy(motion.previous_view, view.view, sizeof motion.previous_view);
    std::memcpy(motion.previous_projection, view.projection, sizeof motion.previous_projection);
    motion.previous_time = view.time - 1.0 / 60.0;
    grass_wind_desc calm = grass_default_wind_desc(), wind = grass_default_wind_desc();
    wind.speed = 4.0f;
    std::printf("grass-tier-cost --motion: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU "
                "%.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | plain per basic cell (us) | motion | wind | wind, motion | CPU: plain (us) | CPU: motion / "
                "plain | CPU: wind (us) | CPU: wind, motion / wind |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        double us[4], cpu_us[4];
        rig.per_cell_variants( // plain, motion, wind, wind with motion
            4,
            [&](int variant) {
                grass_sample::check(grass_set_wind(ctx, variant < 2 ? &calm : &wind), "grass_set_wind", ctx);
                rig.set_motion(variant % 2 == 1 ? &motion : nullptr);
            },
            us, cpu_us);
        rig.set_motion(nullptr);
        grass_sample::check(grass_set_wind(ctx, &calm), "grass_set_wind", ctx);
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s.name, us[0], us[1], us[2],
                    us[3], cpu_us[0], cpu_us[1] / cpu_us[0], cpu_us[2], cpu_us[3] / cpu_us[2]);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    if (gl) delete_colour_targets(rig.host(), 1, &velocity);
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
