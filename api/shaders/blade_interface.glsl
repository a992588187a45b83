// The data every grass shader sees: the uniform blocks of api/src/frame_plan.hpp (std140)
// and the design maps. Shared by the GL and Vulkan backends (Vulkan: descriptor set 0).

layout(std140, binding = 0) uniform Frame {
    mat4 view_projection;  // camera-relative world -> clip (the host's projection)
    vec4 sun_direction;    // xyz: unit vector towards the sun
    vec4 sun_color;        // rgb
    vec4 ambient_color;    // rgb
    vec4 params;           // x: time in seconds, y: view flags, z: +1 depth 0 near, -1 reversed depth,
                           // w: 1 when the target is multisampled (set by the backend)
} frame;

layout(std140, binding = 1) uniform Field {
    mat4 patch_to_world;   // patch units -> world metres; rotation x cell size, no translation
    vec4 map_params;       // xy: map uv per cell, z: density (or map multiplier), w: 1 = density map bound
    vec4 blade_params;     // x: ao impact (B_impact), y: ao height (B_height, patch units), z: tier kind,
                           // w: height of the baked slices (patch units)
    uvec4 tiling;          // x: mirror seed, y: 1 = mirrored tiling on, z: slices per axis of this tier
    vec4 bands[8];         // the field's tiers: begin, end, transition in, transition out (metres)
    uvec4 tiers;           // x: this draw's tier, y: the field's tier count
    vec4 transition;       // x: crossover window (threshold units; 0 = exact)
} field;

layout(binding = 2) uniform sampler2D density_map;
// The tier's baked slices (api/src/baked_slices.hpp): vertical slices of a volume tier, or
// the horizontal slice (one layer) of the image tier.
layout(binding = 3) uniform sampler2DArray slice_color;     // sRGB albedo + coverage
layout(binding = 4) uniform sampler2DArray slice_normal;    // xyz: normal * 0.5 + 0.5, w: height / slice height
layout(binding = 5) uniform sampler2DArray slice_threshold; // r: density threshold (0 = no blade)

// The local density at a point of the field given in cells (bilinear density map).
float local_density(vec2 cell_point) {
    float density = field.map_params.z;
    if (field.map_params.w > 0.5) density *= textureLod(density_map, cell_point * field.map_params.xy, 0.0).r;
    return density;
}

// Alpha below which a fragment is dropped: with multisampling alpha-to-coverage turns alpha
// into coverage; without it a fragment is all or nothing.
float alpha_cut() {
    return frame.params.w > 0.5 ? 0.02 : 0.5;
}

// The window depth of a camera-relative world position, for gl_FragDepth (GL's default
// depth range; Vulkan's clip z is already 0..1).
float window_depth(vec3 position) {
    vec4 clip = frame.view_projection * vec4(position, 1.0);
#ifdef VULKAN
    return clip.z / clip.w;
#else
    return 0.5 * (clip.z / clip.w) + 0.5;
#endif
}
