// The host's sun shadows (grass_shadow_receive_desc): the share of the sun that reaches a
// point, 0..1, read from the host's cascaded shadow map. Included only where
// GRASS_HOST_SHADOWS is defined (the GRASS_SHADOW_RECEIVE variants: GL defines it with
// GRASS_FEATURES, Vulkan compiles SPIR-V modules with it, vk_spirv.hpp), so every other variant declares neither the map nor its block and its
// preprocessed text is what it was. The tiers multiply their sun term by it (light.y).

// The GrassShadow block (api/src/foundation/frame_plan.hpp ShadowUniforms): GL binding 2;
// Vulkan set 1 (the view extras' blocks, which the layout of receiving and motion pipelines
// alone has, backend_vk/src/vk_view_extras.hpp), binding 1; the map in set 2, binding 0, which
// only a receiving view binds. The block holds its struct as
// the one element of an array read at the Frame block's index (blade_interface.glsl says why).
#if defined(VULKAN) && defined(GRASS_MULTIVIEW)
#error "a stereo (multiview) view does not receive the host's shadow maps (the core refuses such a view)"
#endif
struct GrassShadowData {
    mat4 world_to_shadow[4]; // per cascade: camera-relative world -> (u, v, stored depth)
    vec4 cascade_end;        // metres along the camera's view axis
    vec4 axis;               // xyz: the camera's view axis (world, unit), w: cascade count
    vec4 params;             // x: +1 lit where depth <= stored, -1 >=; y: depth bias; z: filter radius (texels)
};
// The host's map (a 2D array, one layer per cascade) through grass's sampler: linear with
// depth compare, so each tap is the hardware's 2x2 percentage-closer filter. GL: texture unit 14.
#ifdef VULKAN
layout(std140, set = 1, binding = 1) uniform GrassShadow { GrassShadowData shadow_at[1]; };
layout(set = 2, binding = 0) uniform sampler2DArrayShadow host_shadow_map;
#else
layout(std140, binding = 2) uniform GrassShadow { GrassShadowData shadow_at[1]; };
uniform sampler2DArrayShadow host_shadow_map;
#endif
// Read at the pushed index, the block is copied once per invocation with the others
// (load_blocks(), blade_interface.glsl), not at every point the volume's ray composites.
#ifdef GRASS_INDEXED_BLOCKS
GrassShadowData g_shadow;
#undef load_blocks
#define load_blocks()                                                                                  \
    g_frame = frame_at[grass_push.block_index], g_field = field_at[grass_push.block_index],           \
    g_shadow = shadow_at[grass_push.block_index]
#define grass_shadow g_shadow
#else
#define grass_shadow shadow_at[0]
#endif

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
