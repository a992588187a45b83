#version 450
// Blade tier (lemme2012 5.1): instanced patch geometry, one instance per planned cell; the
// compacted window variant (GRASS_BLADE_COMPACT): one instance per blade the view draws.
#if defined(GRASS_BLADE_COMPACT) && !defined(VULKAN)
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "blade_interface.glsl"
#include "lighting.glsl"
#include "tier_transitions.glsl"
#ifdef GRASS_VELOCITY // motion vectors' variants only
#include "motion.glsl"
#endif
#ifdef GRASS_RESPONSIVE // responsive grass variants only (blade_interface.glsl)
#include "wind.glsl"
#include "interaction.glsl"
#include "blade_dynamics.glsl"
#include "blade_culling.glsl"
#ifdef GRASS_BLADE_WINDOW // the blade window's variant (kFeatureBladeWindow): poses read, not computed
#include "blade_window.glsl"
#ifdef GRASS_BLADE_COMPACT // the compacted window variant: one instance per drawn blade
#include "blade_compaction.glsl"
#endif
#endif
#endif

#ifdef GRASS_BLADE_COMPACT
// The vertex's inputs, read from storage (load_compacted_vertex) for the instance's item:
// the blade's vertex of the same index in the blade's index pattern, and its cell.
vec3 a_position;
vec3 a_normal;
vec4 a_root_shape;
vec4 a_color;
float a_threshold;
vec4 i_origin;
uvec4 i_cell;
uint g_vertex; // the vertex's index in the patch

void load_compacted_vertex() {
#ifdef VULKAN
    uvec2 item = compact_items[uint(gl_InstanceIndex)];
    uint in_blade = uint(gl_VertexIndex);
#else
    uvec2 item = compact_items[uint(gl_BaseInstanceARB + gl_InstanceID)];
    uint in_blade = uint(gl_VertexID);
#endif
    g_vertex = item.y * compact_vertices_per_blade() + in_blade;
    uint w = g_vertex * kCompactVertexWords;
    a_position = vec3(compact_vertex_words[w], compact_vertex_words[w + 1u], compact_vertex_words[w + 2u]);
    a_normal = vec3(compact_vertex_words[w + 3u], compact_vertex_words[w + 4u], compact_vertex_words[w + 5u]);
    a_root_shape = vec4(compact_vertex_words[w + 6u], compact_vertex_words[w + 7u], compact_vertex_words[w + 8u],
                        compact_vertex_words[w + 9u]);
    uint rgba = floatBitsToUint(compact_vertex_words[w + 10u]);
    a_color = vec4((uvec4(rgba) >> uvec4(0u, 8u, 16u, 24u)) & 0xffu) / 255.0;
    a_threshold = compact_vertex_words[w + 11u];
    i_origin = compact_instance_words[3u * item.x];
    i_cell = floatBitsToUint(compact_instance_words[3u * item.x + 1u]);
}
#else
layout(location = 0) in vec3 a_position;     // patch units
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_root_shape;   // root x, root z, u across, v along
layout(location = 3) in vec4 a_color;        // unorm8 modulation, linear
layout(location = 4) in float a_threshold;   // density threshold in (0, 1]
layout(location = 5) in vec4 i_origin;        // xyz: cell corner relative to the camera (m)
layout(location = 6) in uvec4 i_cell;         // xy: the cell, zw: size in cells (1, 1 here)
#endif

// The varyings, packed four to a slot. lavapipe (Mesa's Vulkan on llvmpipe; seen in 22.3)
// neither packs varyings nor drops those the fragment shader does not read, and it copies, sets
// up and interpolates every slot of every vertex and triangle; GL's linker packs them. Per-blade
// values ride in interpolated slots: the same value at the three vertices interpolates to itself
// up to rounding, which the light (a factor) does not see and the threshold's debug code (an
// integer, rounded where it is read) survives.
layout(location = 0) out vec4 v_position_density; // xyz: camera-relative world position, w: local density
layout(location = 1) out vec4 v_normal_opacity;   // xyz: normal, w: the blade's opacity in this tier
layout(location = 2) out vec4 v_albedo_code;      // rgb: albedo, a: threshold_index() of the blade's threshold
// Centroid: with multisampling, a thin blade often misses the pixel centre; u must be
// taken inside the covered samples or the edge alpha would discard them.
layout(location = 3) centroid out vec4 v_shape_light; // x: u across the blade, y: height in patch units,
                                                      // zw: light_maps() at the root
#ifdef GRASS_VELOCITY
layout(location = 4) out vec4 v_clip_now;    // motion vectors: the clip position without jitter
layout(location = 5) out vec4 v_clip_before; // ... and the previous frame's
#endif

// A threshold of exactly 1 must pass a density of exactly 1 after bilinear filtering;
// the smallest threshold (1 / 65536) must still fail a density of 0.
const float kThresholdEpsilon = 1.0 / 1048576.0;

void main() {
    load_blocks();
#ifdef GRASS_BLADE_COMPACT
    load_compacted_vertex();
#endif
    // Mirrored aperiodic tiling (eq. 6.7): mirror about the cell centre; roots stay inside.
    vec2 s = mirror_signs(i_cell.xy);
    vec3 p = a_position;
    p.xz = (p.xz - 0.5) * s + 0.5;
    vec2 root = (a_root_shape.xy - 0.5) * s + 0.5;
    vec3 n = a_normal;
    n.xz *= s;

    // Density thresholds (lemme 3.3) and tier transitions (boulanger 3.4, lemme 5.4): the
    // blade's opacity in this tier, from its threshold, the local density and its distance,
    // all taken at the root so that the whole blade agrees. So are the design maps: the
    // blade has one colour and one light, and every vertex moves up by the terrain height
    // under the root (lemme eq. 6.13), so a bent blade is not sheared by the terrain.
    vec2 cell_point = vec2(i_cell.xy) + root;
    float density = local_density(cell_point);
    float ground = terrain_height(cell_point);
    vec3 root_position = mat3(field.patch_to_world) * vec3(root.x, ground, root.y) + GRASS_INSTANCE_ORIGIN(i_origin.xyz);
    float opacity = tier_blade_opacity(lod_distance(root_position), a_threshold, density + kThresholdEpsilon);

    vec3 position = mat3(field.patch_to_world) * vec3(p.x, p.y + ground, p.z) + GRASS_INSTANCE_ORIGIN(i_origin.xyz);
    vec3 normal = mat3(field.patch_to_world) * n;
    vec3 albedo = modulate_color(a_color.rgb, cell_point);
#ifdef GRASS_VELOCITY
    vec3 previous = position; // where the vertex was at the previous frame's time (motion vectors)
#endif
#ifdef GRASS_RESPONSIVE
    if (has_map(GRASS_WIND | GRASS_INTERACTION | GRASS_BLADE_CULLING)) {
#if defined(GRASS_BLADE_COMPACT)
        uint vertex = g_vertex;
#elif defined(VULKAN)
        uint vertex = uint(gl_VertexIndex);
#else
        uint vertex = uint(gl_VertexID);
#endif
        uint per_blade = max(uint(field.trample.w + 0.5), 4u); // vertices per blade (set by the backend)
        uint blade = vertex / per_blade;
        mat3 to_world = mat3(field.patch_to_world) * mat3(vec3(s.x, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, s.y));
        vec3 i1 = to_world * curves[2u * blade].xyz; // the rest pose, world metres from the root
        vec3 i2 = to_world * curves[2u * blade + 1u].xyz;
        vec3 side = to_world * vec3(-sin(curves[2u * blade + 1u].w), 0.0, cos(curves[2u * blade + 1u].w));
        vec3 v1 = i1, v2 = i2;
        if (has_map(GRASS_WIND | GRASS_INTERACTION)) {
            // Responsive grass (blade_dynamics.glsl): the blade's curve moves from its rest pose
            // I to the deformed one; each vertex keeps its offset across the blade (its width).
            // The window variant (a draw whose cells the blade window all holds) reads the pose
            // the pass wrote; the others compute it here by the same step (cell_blade_pose).
            int segments = int(per_blade / 2u) - 1;
#ifdef GRASS_BLADE_WINDOW
            BladePose pose = window_pose(i_cell.xy, blade);
#else
            BladePose pose = cell_blade_pose(blade, i_cell.xy, GRASS_INSTANCE_ORIGIN(i_origin.xyz), a_root_shape.xy, segments);
#endif
            v1 = pose.v1;
            v2 = pose.v2;
            float t = a_root_shape.w;
            vec3 rest = root_position + bezier(i1, i2, t);
            vec3 offset = position - rest; // across the blade
            position = bezier(pose.v1, pose.v2, t) + root_position + offset;
#ifdef GRASS_VELOCITY
#ifdef GRASS_BLADE_WINDOW
            // The last frame's pose, which the pass keeps; none where the host's previous time
            // is this frame's (grass_view_motion_desc: nothing moves).
            BladePose before = grass_motion.times.x != 0.0 ? window_previous_pose(i_cell.xy, blade) : pose;
#else
            g_previous_time = true; // the pose at the previous frame's time (motion.glsl)
            BladePose before = cell_blade_pose(blade, i_cell.xy, GRASS_INSTANCE_ORIGIN(i_origin.xyz), a_root_shape.xy, segments);
            g_previous_time = false;
#endif
            previous = bezier(before.v1, before.v2, t) + root_position + offset;
#endif
            // The normal turns with the tangent: cross(side, tangent) of the deformed curve,
            // applied as the change from the rest curve's, so a still blade keeps its normal.
            vec3 rest_n = cross(side, bezier_tangent(i1, i2, t));
            vec3 new_n = cross(side, bezier_tangent(pose.v1, pose.v2, t));
            float scale = length(normal);
            vec3 turn = new_n / max(length(new_n), 1e-12) - rest_n / max(length(rest_n), 1e-12);
            normal += scale * (dot(rest_n, normal) < 0.0 ? -turn : turn);
            albedo *= pose.shade;
        }
        // Per-blade culling (blade_culling.glsl), on the blade as drawn.
        if (has_map(GRASS_BLADE_CULLING) &&
            blade_culled(blade, root_position, v1, v2, side, field.field_up.xyz, a_threshold / max(density, 1e-30))) {
            opacity = 0.0;
        }
    }
#endif
    v_position_density = vec4(position, density);
    v_normal_opacity = vec4(normal, opacity);
    v_albedo_code = vec4(albedo, float(threshold_index(a_threshold)));
    v_shape_light = vec4(a_root_shape.z, p.y, light_maps(cell_point));
    gl_Position = GRASS_VIEW_PROJECTION * vec4(position, 1.0);
#ifdef GRASS_VELOCITY
    v_clip_now = clip_now(position);
    v_clip_before = clip_before(previous);
#endif
    // Without multisampling a blade is all or nothing (tier_blade_opacity: drawn by the tier
    // where its opacity is at least one half, exactly one tier). With it, alpha-to-coverage
    // fades it.
    if (opacity <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: the blade is culled
    }
}
