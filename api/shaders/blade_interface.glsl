// The data every grass shader sees: the uniform blocks of api/src/frame_plan.hpp (std140)
// and the design maps. Shared by the GL and Vulkan backends (Vulkan: descriptor set 0).

layout(std140, binding = 0) uniform Frame {
    mat4 view_projection;  // camera-relative world -> clip (the host's projection)
    vec4 sun_direction;    // xyz: unit vector towards the sun
    vec4 sun_color;        // rgb
    vec4 ambient_color;    // rgb
    vec4 params;           // x: time in seconds, y: view flags, z: +1 depth 0 near, -1 reversed depth
} frame;

layout(std140, binding = 1) uniform Field {
    mat4 patch_to_world;   // patch units -> world metres; rotation x cell size, no translation
    vec4 map_params;       // xy: map uv per cell, z: density (or map multiplier), w: 1 = density map bound
    vec4 blade_params;     // x: ao impact (B_impact), y: ao height (B_height, patch units), z: tier kind
    uvec4 tiling;          // x: mirror seed, y: 1 = mirrored tiling on
} field;

layout(binding = 2) uniform sampler2D density_map;
