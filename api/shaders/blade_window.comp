#version 450
// The blade window pass (docs/responsive.md "The blade window"): once per frame, after the
// interaction pass, one dispatch per geometry draw of view 0 with responsive grass, one
// invocation per (instance, blade): the blade's pose (cell_blade_pose, blade_dynamics.glsl,
// the step blade.vert runs where the window has none) into the window's poses at the
// instance's slot. Blocks: view 0's Frame and the draw's Field (field.tiers.w: the draw's
// first slot; field.transition.w: its first instance).
layout(local_size_x = 64) in;
#define GRASS_BLADE_WINDOW_PASS 1
#include "blade_interface.glsl"
#include "lighting.glsl"
#include "wind.glsl"
#include "interaction.glsl"
#include "blade_dynamics.glsl"
#include "blade_window.glsl"

#ifdef VULKAN // the pass's own set 1 (backend_vk/src/vk_blade_window.hpp WindowPassBinding)
#define GRASS_WINDOW_INSTANCES_BINDING set = 1, binding = 0
#define GRASS_WINDOW_ROOTS_BINDING set = 1, binding = 1
#else
#define GRASS_WINDOW_INSTANCES_BINDING binding = 1 // GL: shader storage bindings 1 and 3 (gl_blade_window.cpp)
#define GRASS_WINDOW_ROOTS_BINDING binding = 3
#endif
// View 0's instances (api/src/foundation/frame_plan.hpp TierInstance: three vec4 each).
layout(std430, GRASS_WINDOW_INSTANCES_BINDING) readonly buffer WindowInstances {
    vec4 instance_words[];
};
// The patch's vertices (api/src/patch/patch_data.hpp BladeVertex: 12 words each, the root's
// x and z at word 6 and 7; a blade's vertices follow each other).
layout(std430, GRASS_WINDOW_ROOTS_BINDING) readonly buffer WindowPatchVertices {
    float vertex_words[];
};
const uint kVertexWords = 12u;
const uint kRootWord = 6u;

void main() {
    load_blocks();
    uint blade = gl_GlobalInvocationID.x;
    uint blades = uint(curves.length()) / 2u;
    if (blade >= blades) return;
    uint instance = uint(field.transition.w + 0.5) + gl_GlobalInvocationID.y;
    vec3 origin = instance_words[3u * instance].xyz;
    uvec2 cell = floatBitsToUint(instance_words[3u * instance + 1u].xy);
    uint per_blade = max(uint(field.trample.w + 0.5), 4u);
    uint root = blade * per_blade * kVertexWords + kRootWord;
    BladePose pose = cell_blade_pose(blade, cell, origin, vec2(vertex_words[root], vertex_words[root + 1u]),
                                     int(per_blade / 2u) - 1);
    uint at = window_pose_index(field.tiers.w + gl_GlobalInvocationID.y, blades, blade);
    window_poses[at] = vec4(pose.v1, pose.shade);
    window_poses[at + 1u] = vec4(pose.v2, 0.0);
}
