// grass-measure tier-cost --lights: the plain table's rows drawn without and with the host's
// lights (grass_view_lights_desc): one point light, eight (point and spot lights), and eight
// with Kajiya-Kay specular and ambient harmonics (GL or Vulkan, --backend).
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <cstdio>
#include <cstring>
#include <vector>

namespace grass_measure {
namespace tier_cost {

int run_lights(Rig& rig, const std::vector<Setup>& rows) {
    const Options& o = rig.options();
    grass_context* ctx = rig.ctx();
    // Eight lights over the rig's 8 m x 8 m field, 2 m up: points and (odd ones) spots aimed down.
    grass_light lights[GRASS_MAX_VIEW_LIGHTS];
    for (int i = 0; i < GRASS_MAX_VIEW_LIGHTS; ++i) {
        lights[i] = grass_default_light();
        lights[i].position[0] = 1.0 + 2.0 * (i % 4);
        lights[i].position[1] = 2.0;
        lights[i].position[2] = 2.0 + 4.0 * (i / 4);
        lights[i].intensity = 4.0f;
        if (i % 2 == 1) {
            lights[i].kind = GRASS_LIGHT_SPOT;
            lights[i].outer_cone_angle = 0.6f;
            lights[i].inner_cone_angle = 0.4f;
        }
    }
    grass_view_lights_desc one = grass_default_view_lights_desc();
    one.light_count = 1;
    one.lights = lights;
    grass_view_lights_desc eight = one;
    eight.light_count = GRASS_MAX_VIEW_LIGHTS;
    grass_view_lights_desc full = eight;
    full.specular_strength = 0.3f;
    full.ambient_sh_enabled = 1;
    for (int c = 0; c < 3; ++c) {
        full.ambient_sh[0][c] = 0.3f / 0.282095f;
        full.ambient_sh[1][c] = 0.2f;
    }
    const grass_view_lights_desc* variants[4] = {nullptr, &one, &eight, &full};
    std::printf("grass-tier-cost --lights: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU "
                "%.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | plain per basic cell (us) | 1 light | 8 lights | 8, specular, harmonics | CPU: plain (us) | "
                "CPU: 1 / plain | CPU: 8 / plain | CPU: 8, specular, harmonics / plain |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        double us[4], cpu_us[4];
        rig.per_cell_variants(
            4, [&](int variant) { rig.set_lights(variants[variant]); }, us, cpu_us);
        rig.set_lights(nullptr);
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s.name, us[0], us[1], us[2],
                    us[3], cpu_us[0], cpu_us[1] / cpu_us[0], cpu_us[2] / cpu_us[0], cpu_us[3] / cpu_us[0]);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
