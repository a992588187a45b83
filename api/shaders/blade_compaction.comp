#version 450
// Culled blades compacted (jahrmann2017 6.1-6.2; docs/responsive.md "Culled blades
// compacted"): once per geometry draw of a view that runs the window variant, before the
// draw, one work group per instance of the draw. It decides what the window
// variant's vertex shader would: the blade's opacity in the draw's tier (density threshold
// against the local density at the root, the tier transitions by lod distance) and, where the
// field enables them, the per-blade culling tests (orientation, frustum, distance) on the pose
// the window pass wrote. A blade the view draws takes an item, in the blades' order; each
// instance of the draw gets indirect arguments (a multi-draw: one command per instance) with
// its items' count, and the draw runs one instance per item. Blocks: the view's
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
// The draw: x its first instance (into the view's instances), y its first item (its
// instance i's items start at y + i blades), z its first indirect arguments
// (DrawElementsIndirectCommand, five words each, one per instance).
layout(std140, GRASS_COMPACT_DRAW_BINDING) uniform CompactDraw {
    uvec4 compact_draw;
};
layout(std430, GRASS_COMPACT_COMMANDS_BINDING) writeonly buffer CompactCommands {
    uint command_words[];
};

// A threshold of exactly 1 must pass a density of exactly 1 (blade.vert's).
const float kThresholdEpsilon = 1.0 / 1048576.0;

// Whether the blade may have an opacity above 0 in the draw's tier: the vertex shader's
// tier_blade_opacity, evaluated here in another stage whose rounding may differ by an ulp,
// so a blade on a transition's edge is kept if a distance or density a hundred-thousandth
// away would keep it (the vertex shader then decides it, as it does uncompacted).
bool maybe_opaque(float d, float threshold, float density) {
    for (int k = 0; k < 5; ++k) {
        float dk = k == 0 ? d : d * (k % 2 == 0 ? 1.00001 : 0.99999);
        float nk = k == 0 ? density : density * (k < 3 ? 1.00001 : 0.99999);
        if (tier_blade_opacity(dk, threshold, nk) > 0.0) return true;
    }
    return false;
}

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
    if (!maybe_opaque(lod_distance(root_position), threshold, density + kThresholdEpsilon)) return false;
    if (!has_map(GRASS_BLADE_CULLING)) return true;
    mat3 to_world = mat3(field.patch_to_world) * mat3(vec3(s.x, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, s.y));
    vec3 side = to_world * vec3(-sin(curves[2u * blade + 1u].w), 0.0, cos(curves[2u * blade + 1u].w));
    BladePose pose = window_pose(cell, blade);
    return !blade_culled(blade, root_position, pose.v1, pose.v2, side, field.field_up.xyz,
                         threshold / max(density, 1e-30));
}

// One work group per instance of the draw, its blades in chunks of 64 in order: a chunk's
// survivors take the next items in blade order (a prefix count in shared memory), so the
// items are the uncompacted draw's blades in its order (the picture does not depend on
// which invocation finishes first). The instance's indirect arguments get the count and
// its first item.
shared uint s_drawn[64];
shared uint s_taken;

void main() {
    load_blocks();
    uint local_instance = gl_WorkGroupID.y;
    uint instance = compact_draw.x + local_instance;
    uint blades = uint(curves.length()) / 2u;
    uint lane = gl_LocalInvocationID.x;
    uint first_item = compact_draw.y + local_instance * blades;
    if (lane == 0u) s_taken = 0u;
    barrier();
    for (uint chunk = 0u; chunk < blades; chunk += 64u) {
        uint blade = chunk + lane;
        bool drawn = blade < blades && blade_drawn(instance, blade);
        s_drawn[lane] = drawn ? 1u : 0u;
        barrier();
        uint before = s_taken;
        for (uint k = 0u; k < lane; ++k) before += s_drawn[k];
        if (drawn) compact_items[first_item + before] = uvec2(instance, blade);
        barrier();
        if (lane == 63u) s_taken = before + s_drawn[63];
        barrier();
    }
    if (lane == 0u) {
        uint command = 5u * (compact_draw.z + local_instance);
        command_words[command + 1u] = s_taken;
        command_words[command + 4u] = first_item;
    }
}
