#version 450
// The blade window pass (docs/responsive.md "The blade window", "Per-blade state"): once per
// frame, after the interaction pass, one dispatch per geometry draw of view 0 with
// responsive grass, one invocation per (work item, blade): the blade's state stepped by the
// frame's time step (blade_state.glsl: wind and gravity, recovery weakened by eta, the
// push-out of the colliders binned to the blade's tile of the interaction map's fine level),
// then its pose (cell_blade_pose, blade_dynamics.glsl: the state's pose, the map's press, the
// terrain) into the slot's record, the last frame's pose kept beside it (motion vectors). A
// slot the core marked entered starts at the equilibrium pose: the stateless one.
// Blocks: view 0's Frame, the draw's Field (field.tiers.w: the draw's first work item,
// field.transition.w: the blades a slot holds) and the fine level's Interaction block.
layout(local_size_x = 64) in;
#define GRASS_BLADE_WINDOW_PASS 1
#define GRASS_BLADE_STATE 1
#include "blade_interface.glsl"
#include "lighting.glsl"
#include "wind.glsl"
#include "interaction.glsl"
#include "blade_dynamics.glsl"
#include "blade_window.glsl"
#include "blade_state.glsl"

// The pass's bindings beyond the draws' (listed here only; GL: gl_blade_window.cpp, Vulkan:
// the pass's own sets 1 and 2, backend_vk/src/vk_blade_window.hpp WindowPassBinding and
// WindowStateBinding).
#ifdef VULKAN
#define GRASS_WINDOW_INSTANCES_BINDING set = 1, binding = 0
#define GRASS_WINDOW_ROOTS_BINDING set = 1, binding = 1
#define GRASS_WINDOW_WORK_BINDING set = 1, binding = 2
#define GRASS_WINDOW_COLLIDERS_BINDING set = 2, binding = 0 // set 2: WindowStateBinding
#define GRASS_WINDOW_TILE_OFFSETS_BINDING set = 2, binding = 1
#define GRASS_WINDOW_TILE_COLLIDERS_BINDING set = 2, binding = 2
#define GRASS_WINDOW_LEVEL_BINDING set = 2, binding = 3
#else // GL: shader storage bindings 1, 3-7, uniform binding 2
#define GRASS_WINDOW_INSTANCES_BINDING binding = 1
#define GRASS_WINDOW_ROOTS_BINDING binding = 3
#define GRASS_WINDOW_WORK_BINDING binding = 4
#define GRASS_WINDOW_COLLIDERS_BINDING binding = 5
#define GRASS_WINDOW_TILE_OFFSETS_BINDING binding = 6
#define GRASS_WINDOW_TILE_COLLIDERS_BINDING binding = 7
#define GRASS_WINDOW_LEVEL_BINDING binding = 2
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
// The work items (BladeWindowPlan::work): slot (| 1 << 31: entered this frame), instance.
layout(std430, GRASS_WINDOW_WORK_BINDING) readonly buffer WindowWork {
    uint work_words[];
};
// The interaction pass's colliders (GpuCollider, the map's frame) and the fine level's tile
// lists (interaction.comp); read only with GRASS_INTERACTION.
struct WindowCollider {
    vec4 a;        // u, v, h of the centre or one axis end; w: radius
    vec4 b;        // u, v, h of the other end; w: shape (0 sphere, 1 capsule)
    vec4 velocity; // u, v, h (m/s)
};
layout(std430, GRASS_WINDOW_COLLIDERS_BINDING) readonly buffer WindowColliders {
    WindowCollider window_colliders[];
};
layout(std430, GRASS_WINDOW_TILE_OFFSETS_BINDING) readonly buffer WindowTileOffsets {
    uint window_tile_offsets[];
};
layout(std430, GRASS_WINDOW_TILE_COLLIDERS_BINDING) readonly buffer WindowTileColliders {
    uint window_tile_colliders[];
};
layout(std140, GRASS_WINDOW_LEVEL_BINDING) uniform WindowLevel {
    ivec4 window; // interaction.comp's Interaction block of the fine level
    vec4 origin;  // xy: the window's lower corner relative to the camera (m), z: texel size (m)
    uvec4 counts; // x: N, y: tile size (texels), z: tiles per side
    vec4 least;
} window_level;

const uint kVertexWords = 12u;
const uint kRootWord = 6u;

uint g_record;            // the first vec4 of the blade's record
bool g_entered;           // its slot's cell entered the window this frame
uint g_first_collider;    // the blade's tile's colliders: window_tile_colliders[first, first + count)
int g_collider_count;
vec3 g_root;              // the blade's root relative to the camera (m)

int blade_state_collider_count() { return g_collider_count; }

// A point of the map's frame (u, v along its axes from the camera, h above its anchor)
// relative to the blade's root, world metres.
vec3 map_point(vec3 m) {
    return m.x * frame.map_axis_u.xyz + m.y * frame.map_axis_v.xyz + (m.z - frame.map_axis_v.w) * frame.map_up.xyz -
           g_root;
}

BladeCollider blade_state_collider(int k) {
    WindowCollider c = window_colliders[window_tile_colliders[g_first_collider + uint(k)]];
    BladeCollider b;
    b.a = vec4(map_point(c.a.xyz), c.a.w);
    b.b = vec4(map_point(c.b.xyz), c.b.w);
    b.velocity = vec4(c.velocity.x * frame.map_axis_u.xyz + c.velocity.y * frame.map_axis_v.xyz +
                          c.velocity.z * frame.map_up.xyz,
                      0.0);
    return b;
}

// The colliders binned to the fine level's tile under `root` (none outside its window).
void find_colliders(vec3 root) {
    g_root = root;
    g_first_collider = 0u;
    g_collider_count = 0;
    if (!has_map(GRASS_INTERACTION) || frame.map_up.w < 0.5) return;
    vec2 uv = vec2(dot(root, frame.map_axis_u.xyz), dot(root, frame.map_axis_v.xyz));
    vec2 j = floor((uv - window_level.origin.xy) / window_level.origin.z);
    float n = float(window_level.counts.x);
    if (any(lessThan(j, vec2(0.0))) || any(greaterThanEqual(j, vec2(n)))) return;
    uvec2 tile = uvec2(j) / max(window_level.counts.y, 1u);
    uint tiles = window_level.counts.z;
    if (tile.x >= tiles || tile.y >= tiles) return;
    uint index = tile.y * tiles + tile.x;
    g_first_collider = window_tile_offsets[index];
    g_collider_count = int(window_tile_offsets[index + 1u] - g_first_collider);
}

BladePose blade_window_step(uint blade, uvec2 cell, vec3 i1, vec3 i2, vec3 up, float len, int segments, vec3 root,
                            vec3 forces) {
    BladeRest rest;
    rest.i1 = i1;
    rest.i2 = i2;
    rest.up = up;
    rest.len = len;
    rest.segments = segments;
    float stiffness = blade_mechanics(blade, cell).stiffness;
    BladeState s = blade_state_at_rest(rest, stiffness, forces);
    if (!g_entered) {
        BladeState kept = blade_state_unpack(window_poses[g_record + kWindowState],
                                             window_poses[g_record + kWindowState + 1u]);
        find_colliders(root);
        float recovery_time = field.trample.y * blade_variation(blade, cell, 4u);
        blade_state_step(kept, rest, stiffness, forces, recovery_time, frame.wind_shape.w);
        // A state that is not finite (non-finite forces) starts again at the equilibrium.
        vec4 sum = vec4(kept.v2, kept.eta) + vec4(kept.velocity, 0.0);
        if (!any(isnan(sum)) && !any(isinf(sum))) s = kept;
    }
    vec4 a, b;
    blade_state_pack(s, a, b);
    window_poses[g_record + kWindowState] = a;
    window_poses[g_record + kWindowState + 1u] = b;
    return blade_state_pose(s, rest);
}

void main() {
    load_blocks();
    uint blade = gl_GlobalInvocationID.x;
    uint blades = uint(curves.length()) / 2u;
    if (blade >= blades) return;
    uint item = uint(field.tiers.w) + gl_GlobalInvocationID.y;
    uint slot = work_words[2u * item];
    uint instance = work_words[2u * item + 1u];
    g_entered = (slot & 0x80000000u) != 0u;
    g_record = window_pose_index(slot & 0x7fffffffu, uint(field.transition.w + 0.5), blade);
    BladePose previous = window_record_pose(g_record);
    vec3 origin = instance_words[3u * instance].xyz;
    uvec2 cell = floatBitsToUint(instance_words[3u * instance + 1u].xy);
    uint per_blade = max(uint(field.trample.w + 0.5), 4u);
    uint root = blade * per_blade * kVertexWords + kRootWord;
    BladePose pose = cell_blade_pose(blade, cell, origin, vec2(vertex_words[root], vertex_words[root + 1u]),
                                     int(per_blade / 2u) - 1);
    if (g_entered) previous = pose;
    window_poses[g_record] = vec4(pose.v1, pose.shade);
    window_poses[g_record + 1u] = vec4(pose.v2, 0.0);
    window_poses[g_record + kWindowPrevious] = vec4(previous.v1, previous.shade);
    window_poses[g_record + kWindowPrevious + 1u] = vec4(previous.v2, 0.0);
}
