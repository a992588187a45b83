// The host's sun shadows (grass_shadow_receive_desc): the share of the sun that reaches a
// point, 0..1, read from the host's cascaded shadow map. Included only where
// GRASS_HOST_SHADOWS is defined (the GRASS_SHADOW_RECEIVE variants: GL defines it with
// GRASS_FEATURES), so every other variant declares neither the map nor its block and its
// preprocessed text is what it was. The tiers multiply their sun term by it (light.y).
#ifdef VULKAN
#error "the Vulkan backend does not receive the host's shadow maps yet (the core refuses such a view)"
#endif

// The GrassShadow block (api/src/foundation/frame_plan.hpp ShadowUniforms), GL binding 2.
layout(std140, binding = 2) uniform GrassShadow {
    mat4 world_to_shadow[4]; // per cascade: camera-relative world -> (u, v, stored depth)
    vec4 cascade_end;        // metres along the camera's view axis
    vec4 axis;               // xyz: the camera's view axis (world, unit), w: cascade count
    vec4 params;             // x: +1 lit where depth <= stored, -1 >=; y: depth bias; z: filter radius (texels)
} grass_shadow;
// The host's map (a 2D array, one layer per cascade) through grass's sampler: linear with
// depth compare, so each tap is the hardware's 2x2 percentage-closer filter. Texture unit 14.
uniform sampler2DArrayShadow host_shadow_map;

// `p` relative to the camera (world axes, metres), as the tiers' positions are.
float host_sun_visibility(vec3 p) {
    float along = dot(p, grass_shadow.axis.xyz);
    int count = int(grass_shadow.axis.w + 0.5);
    int c = 0;
    while (c < count && along >= grass_shadow.cascade_end[c]) ++c;
    if (c >= count) return 1.0; // beyond the last cascade
    vec4 s = grass_shadow.world_to_shadow[c] * vec4(p, 1.0);
    vec3 uvz = s.xyz / s.w;
    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) return 1.0; // off the map
    float ref = uvz.z - grass_shadow.params.x * grass_shadow.params.y; // moved towards the light
    float radius = grass_shadow.params.z;
    if (radius <= 0.0) return texture(host_shadow_map, vec4(uvz.xy, float(c), ref));
    // A 3x3 grid of filtered taps `radius` texels apart.
    vec2 texel_step = radius / vec2(textureSize(host_shadow_map, 0).xy);
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) lit += texture(host_shadow_map, vec4(uvz.xy + vec2(x, y) * texel_step, float(c), ref));
    }
    return lit / 9.0;
}
