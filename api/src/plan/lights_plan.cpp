// The host's lights (grass_view_lights_desc): the GrassLights block of a view lit by them.
#include "plan/lights_plan.hpp"

#include "foundation/shader_interface.hpp"

#include <cmath>

namespace grass {
namespace {

void unit(const float v[3], float out[4]) {
    const double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
    for (int c = 0; c < 3; ++c) out[c] = len > 0.0 ? static_cast<float>(v[c] / len) : 0.0f;
}

} // namespace

void plan_lights(const ViewExtensions& ext, const double camera[3], FramePlan* plan) {
    plan->host_lights = ext.lights != nullptr && !plan->depth_pass && !plan->gbuffer;
    plan->lights = LightUniforms{};
    if (!plan->host_lights) return;
    const grass_view_lights_desc& d = *ext.lights;
    LightUniforms& u = plan->lights;
    u.counts[0] = static_cast<float>(d.light_count);
    u.counts[1] = d.specular_strength;
    u.counts[2] = d.specular_exponent;
    u.counts[3] = d.ambient_sh_enabled ? 1.0f : 0.0f;
    if (d.ambient_sh_enabled) {
        for (int k = 0; k < 9; ++k) {
            for (int c = 0; c < 3; ++c) u.ambient_sh[k][c] = d.ambient_sh[k][c];
        }
    }
    for (uint32_t i = 0; i < d.light_count && i < GRASS_MAX_VIEW_LIGHTS; ++i) {
        const grass_light& l = d.lights[i];
        LightUniforms::Light& g = u.light[i];
        if (l.kind == GRASS_LIGHT_DIRECTIONAL) {
            unit(l.direction, g.position_kind);
        } else {
            for (int c = 0; c < 3; ++c) g.position_kind[c] = static_cast<float>(l.position[c] - camera[c]);
        }
        g.position_kind[3] = static_cast<float>(l.kind);
        if (l.kind == GRASS_LIGHT_SPOT) unit(l.direction, g.axis);
        for (int c = 0; c < 3; ++c) g.color_range[c] = l.color[c] * l.intensity;
        g.color_range[3] = l.kind == GRASS_LIGHT_DIRECTIONAL ? 0.0f : l.range;
        g.cone[0] = std::cos(l.inner_cone_angle);
        g.cone[1] = std::cos(l.outer_cone_angle);
    }
    for (TierDraw& draw : plan->draws) {
        draw.features |= kFeatureHostLights;
        draw.uniforms.tiling[3] = draw.features;
    }
}

} // namespace grass
