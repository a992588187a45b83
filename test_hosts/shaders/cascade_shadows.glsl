// The host's cascaded sun shadows (TargetDesc::host_shadows), read by the host's ground and
// meshes when built with HOST_SHADOWS: the share of the sun that reaches a camera-relative
// point, from a 2D-array depth map with a 3x3 grid of hardware 2x2 PCF taps. The block is
// light_cascades.hpp's HostShadowUniforms. Vulkan: descriptor set 1 (the ground's block is set 0).
#ifdef VULKAN
layout(std140, set = 1, binding = 0) uniform HostShadowBlock {
#else
layout(std140, binding = 3) uniform HostShadowBlock {
#endif
    mat4 relative_to_shadow[4]; // camera-relative position -> (u, v, depth)
    vec4 cascade_end;           // metres along the view axis
    vec4 forward;               // xyz: the camera's view axis; w: depth bias
    vec4 params;                // x: cascades, y: 1 / map size, z: filter radius (texels)
} host_shadow;
#ifdef VULKAN
layout(set = 1, binding = 1) uniform sampler2DArrayShadow host_shadow_map;
#else
layout(binding = 1) uniform sampler2DArrayShadow host_shadow_map;
#endif

float cascade_sun_visibility(vec3 relative) {
    float along = dot(relative, host_shadow.forward.xyz);
    int count = int(host_shadow.params.x);
    int cascade = count;
    for (int i = count - 1; i >= 0; --i) {
        if (along < host_shadow.cascade_end[i]) cascade = i;
    }
    if (cascade >= count) return 1.0;
    vec4 s = host_shadow.relative_to_shadow[cascade] * vec4(relative, 1.0);
    vec3 p = s.xyz / s.w;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
    float depth = p.z - host_shadow.forward.w;
    vec2 step_uv = vec2(host_shadow.params.y * host_shadow.params.z);
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            lit += texture(host_shadow_map, vec4(p.xy + vec2(x, y) * step_uv, float(cascade), depth));
        }
    }
    return lit / 9.0;
}
