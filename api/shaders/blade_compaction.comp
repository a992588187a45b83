#version 450
// Culled blades compacted (jahrmann2017 6.1-6.2; docs/responsive.md "Culled blades
// compacted"): once per geometry draw of a view that runs the window variant, before the
// draw, one invocation per (instance, blade) of the draw. It decides what the window
// variant's vertex shader would: the blade's opacity in the draw's tier (density threshold
// against the local density at the root, the tier transitions by lod distance) and, where the
// field enables them, the per-blade culling tests (orientation, frustum, distance) on the pose
// the window pass wrote. A blade the view draws takes an item (atomic counter: the draw's
// indirect instance count); the draw then runs one instance per item. Blocks: the view's
// Frame and the draw's Field, so every view (shadow cascades, G-buffer and motion views)
// compacts its own draws with its own tests.
layout(local_size_x = 64) in;
#define GRASS_BLADE_COMPACTION_PASS 1
#include "blade_interface.glsl"
#include "lighting.glsl"
#include "tier_transitions.glsl"
#include "wind.glsl"
#include "interaction.glsl"
#include "blade_dynamics.glsl"
#include "blade_culling.glsl"
#include "blade_window.glsl"
#include "blade_compaction.glsl"

#ifdef VULKAN
#define GRASS_COMPACT_DRAW_BINDING set = 1, binding = 0
#define GRASS_COMPACT_COMMANDS_BINDING set = 1, binding = 1
#else // GL: uniform binding 2, shader storage binding 6
#define GRASS_COMPACT_DRAW_BINDING binding = 2
#define GRASS_COMPACT_COMMANDS_BINDING binding = 6
#endif
// The draw: x its first instance (into the view's instances), y its first item, z its
// indirect arguments (DrawElementsIndirectCommand, five words each).
layout(std140, GRASS_COMPACT_DRAW_BINDING) uniform CompactDraw {
    uvec4 compact_draw;
};
layout(std430, GRASS_COMPACT_COMMANDS_BINDING) buffer CompactCommands {
    uint command_words[];
};

// A threshold of exactly 1 must pass a density of exactly 1 (blade.vert's).
const float kThresholdEpsilon = 1.0 / 1048576.0;

// Whether the view draws blade `blade` of instance `instance`: blade.vert's tests, on the
// same inputs (its root mirrored as the vertex shader mirrors it, the window's pose).
bool blade_drawn(uint instance, uint blade) {
    uint first = blade * compact_vertices_per_blade() * kCompactVertexWords;
    vec2 root_shape = vec2(compact_vertex_words[first + 6u], compact_vertex_words[first + 7u]);
    float threshold = compact_vertex_words[first + 11u];
    vec3 origin = compact_instance_words[3u * instance].xyz;
    uvec2 cell = floatBitsToUint(compact_instance_words[3u * instance + 1u].xy);
    vec2 s = mirror_signs(cell);
    vec2 root = (root_shape - 0.5) * s + 0.5;
    vec2 cell_point = vec2(cell) + root;
    float density = local_density(cell_point);
    float ground = terrain_height(cell_point);
    vec3 root_position = mat3(field.patch_to_world) * vec3(root.x, ground, root.y) + GRASS_INSTANCE_ORIGIN(origin);
    if (tier_blade_opacity(lod_distance(root_position), threshold, density + kThresholdEpsilon) <= 0.0) return false;
    if (!has_map(GRASS_BLADE_CULLING)) return true;
    mat3 to_world = mat3(field.patch_to_world) * mat3(vec3(s.x, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, s.y));
    vec3 side = to_world * vec3(-sin(curves[2u * blade + 1u].w), 0.0, cos(curves[2u * blade + 1u].w));
    BladePose pose = window_pose(cell, blade);
    return !blade_culled(blade, root_position, pose.v1, pose.v2, side, field.field_up.xyz,
                         threshold / max(density, 1e-30));
}

void main() {
    load_blocks();
    uint blade = gl_GlobalInvocationID.x;
    if (blade >= uint(curves.length()) / 2u) return;
    uint instance = compact_draw.x + gl_GlobalInvocationID.y;
    if (!blade_drawn(instance, blade)) return;
    uint item = atomicAdd(command_words[5u * compact_draw.z + 1u], 1u);
    compact_items[compact_draw.y + item] = uvec2(instance, blade);
}
