#version 450
// Blade tier: two-sided Lambert + ambient with blade ambient occlusion; the blade's edges
// give alpha for alpha-to-coverage when the host's target is multisampled.
#include "blade_interface.glsl"
#ifdef GRASS_HOST_LIGHTS // the host's lights' variants only
#include "host_lights.glsl"
#endif
#include "lighting.glsl"
#ifdef GRASS_HOST_SHADOWS
#include "host_shadows.glsl"
#endif
#ifdef GRASS_VELOCITY
#define GRASS_MOTION_FRAGMENT
#include "motion.glsl"
#endif

// The blade's varyings, packed four to a slot (blade.vert says why).
layout(location = 0) in vec4 v_position_density;
layout(location = 1) in vec4 v_normal_opacity;
layout(location = 2) in vec4 v_albedo_code;
layout(location = 3) centroid in vec4 v_shape_light;
#ifdef GRASS_VELOCITY
layout(location = 4) in vec4 v_clip_now;
layout(location = 5) in vec4 v_clip_before;
#endif

#ifdef GRASS_DEPTH_TARGET
vec4 out_color; // Vulkan's depth-only target (a depth pass): no colour attachment, no output
#else
layout(location = 0) out vec4 out_color;
#endif
#ifdef GRASS_GBUFFER // G-buffer views' variants only
#include "gbuffer.glsl"
#endif

void main() {
    load_blocks();
    if (depth_pass()) return; // the geometry's depth alone: no colour, no alpha to coverage
    vec3 n = normalize(v_normal_opacity.xyz);
    vec3 to_camera = towards_viewer(v_position_density.xyz);
    if (dot(n, to_camera) < 0.0) n = -n; // two-sided: light the side that faces the camera

    float ao =
        blade_ambient_occlusion(v_position_density.w, v_shape_light.y, field.blade_params.x, field.blade_params.y);
    // The light maps at the root, read only by a variant that has them (else zw go
    // unread and the products with 1 fold away).
    vec2 light = has_map(GRASS_MAP_AMBIENT | GRASS_MAP_DIFFUSE) ? v_shape_light.zw : vec2(1.0);
#ifdef GRASS_HOST_SHADOWS
    light.y *= host_sun_visibility(v_position_density.xyz); // the host's shadow at the fragment
#endif
#ifdef GRASS_GBUFFER // the surface instead of its light; the whole blade, as the depth pass
    write_gbuffer(v_albedo_code.rgb, n, ao * light.x);
#ifdef GRASS_VELOCITY
    write_velocity(clip_velocity(v_clip_now, v_clip_before));
#endif
    return;
#endif
    vec3 color = grass_lighting(v_albedo_code.rgb, n, ao, light);
#ifdef GRASS_HOST_LIGHTS
    color += host_lights_blade(v_albedo_code.rgb, n, to_camera, v_position_density.xyz, light.y);
#endif

    // Distance to the nearest blade edge in pixels -> coverage. Without multisampling the
    // alpha is ignored (no blending); with alpha-to-coverage it antialiases the edges.
    // Blades narrower than a pixel already lose coverage to the rasteriser: their centre
    // stays opaque (the scale is at least 2), or far grass would wash out to the sky.
    float edge = 0.5 - abs(v_shape_light.x - 0.5);
    float alpha = clamp(edge * max(1.0 / max(fwidth(v_shape_light.x), 1e-6), 2.0) + 0.5, 0.0, 1.0);
    out_color = debug_thresholds() ? threshold_color(uint(v_albedo_code.a + 0.5))
                                   : output_color(vec4(debug_tint(color), alpha * v_normal_opacity.w));
#ifdef GRASS_VELOCITY
    write_velocity(clip_velocity(v_clip_now, v_clip_before));
#endif
}
