// grass-deferred's Vulkan half (grass-deferred --backend vk): the GL half's scene (scene.hpp)
// with the Vulkan deferred host of vk_deferred_host.hpp: the ground and grass (a
// GRASS_PASS_GBUFFER view, grass_vk_record) into the G-buffer, then the lighting pass with
// the GL half's lighting shader (shaders/lighting.frag), all on the GPU; the same G-buffer
// lit again without the lamps for the check that the lamps light it. With a velocity path, the
// velocity frames instead (velocity.hpp): the G-buffer's velocity attachment copied back.
#include "scene.hpp"
#include "velocity.hpp"
#include "vk_deferred_host.hpp"

#include <cstdio>

namespace deferred {

int run_vulkan(const std::string& out_path, const std::string& velocity_path) {
    grass_host::TargetDesc target;
    target.width = kWidth;
    target.height = kHeight;
    std::string error;
    std::unique_ptr<VkDeferredHost> host = VkDeferredHost::create(target, &error);
    if (!host) {
        std::fprintf(stderr, "no Vulkan device: %s\n", error.c_str());
        return 1;
    }
    const bool velocity = !velocity_path.empty();
    host->set_velocity(velocity);
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = nullptr;
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) {
        std::fprintf(stderr, "grass_vk_create_context failed\n");
        return 1;
    }
    grass_patch_id patch{};
    grass_field_id field{};
    grass_patch_desc pd = grass_default_patch_desc();
    grass_field_desc fd = grass_default_field_desc();
    bool ok = grass_create_patch(ctx, &pd, &patch) == GRASS_SUCCESS;
    fd.patch = patch;
    fd.cells_x = fd.cells_z = kCells;
    ok = ok && grass_create_field(ctx, &fd, &field) == GRASS_SUCCESS;

    // The lights: the sun, the ambient term and the lamps, camera-relative.
    LightingUniforms lights{};
    for (int c = 0; c < 3; ++c) {
        lights.sun_direction[c] = kSunDirection[c];
        lights.sun_color[c] = kSunColor[c];
        lights.ambient[c] = kAmbient[c];
        for (int i = 0; i < 3; ++i) {
            lights.light_position[i][c] = float(kLamps[i][c] - kEye[c]);
            lights.light_color[i][c] = kLampColors[i][c];
        }
    }
    for (int i = 0; i < 3; ++i) lights.light_position[i][3] = kLampRange;
    host->set_lights(lights);

    // grass into the G-buffer after the ground: albedo (RGBA16F), normal, material and, for
    // the velocity frames, velocity.
    grass_view_desc view = grass_host::make_view(*host, kEye, kAt, kFovy, kNear, kFar);
    grass_view_gbuffer_desc layout = gbuffer_layout(velocity);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    view.next = &pass;
    if (velocity) {
        // A frame without the wind's motion and one with it, each velocity attachment read back.
        view.time = kTime;
        const grass_wind_desc wind = gust_wind();
        ok = ok && grass_set_wind(ctx, &wind) == GRASS_SUCCESS;
        grass_view_motion_desc motion{};
        VelocityImage frames[2];
        for (int wind_moves = 0; wind_moves < 2 && ok; ++wind_moves) {
            motion = pan_motion(*host, wind_moves != 0);
            motion.next = &pass;
            view.next = &motion;
            frames[wind_moves].y_down = true;
            ok = host->render(ctx, view, nullptr, nullptr, &error) == GRASS_SUCCESS &&
                 host->read_velocity(&frames[wind_moves].rgba, &error);
        }
        grass_destroy_context(ctx);
        if (!ok || host->validation_messages() != 0) {
            std::fprintf(stderr, "the velocity frames failed: %s\n%s\n", error.c_str(), host->validation_log().c_str());
            return 1;
        }
        return check_and_write_velocity(view, frames[0], frames[1], velocity_path);
    }
    grass_host::Image lit, sun_only;
    ok = ok && host->render(ctx, view, nullptr, &lit, &error) == GRASS_SUCCESS;
    for (auto& color : lights.light_color) color[0] = color[1] = color[2] = 0.0f;
    host->set_lights(lights);
    ok = ok && host->relight(&sun_only, &error);
    grass_destroy_context(ctx);
    if (!ok || host->validation_messages() != 0) {
        std::fprintf(stderr, "the deferred frame failed: %s\n%s\n", error.c_str(), host->validation_log().c_str());
        return 1;
    }
    return holds_lit_grass(std::move(lit.rgba), sun_only.rgba, out_path) ? 0 : 1;
}

} // namespace deferred
