#version 450
// Debug view: each planned instance as a flat box on the ground, the size of its cell or
// macro-cell, inset so that neighbours stay apart. No per-vertex input: the six corners come
// from the vertex index; the instance layout is the one every tier uses.
#include "blade_interface.glsl"

layout(location = 5) in vec4 i_origin; // xyz: corner relative to the camera (m)
layout(location = 6) in uvec4 i_cell;  // xy: first cell, zw: size in cells

layout(location = 0) flat out vec3 v_color;

// Red geometry, yellow volume, blue image (boulanger2006 figure 12, lemme2012 figure 7.1).
vec3 tier_color(float kind) {
    if (kind < 0.5) return vec3(0.85, 0.06, 0.04);
    if (kind < 1.5) return vec3(0.90, 0.75, 0.04);
    return vec3(0.04, 0.18, 0.90);
}

void main() {
    load_blocks();
#ifdef VULKAN
    int v = gl_VertexIndex;
#else
    int v = gl_VertexID;
#endif
    const int corner[6] = int[6](0, 1, 2, 2, 1, 3);
    vec2 c = vec2(float(corner[v] & 1), float(corner[v] >> 1));
    // Inset by 6% of a cell plus 0.6% of the box (at most a quarter of it) on every side,
    // so that macro-cells show their borders from far away.
    vec2 size = vec2(i_cell.zw);
    vec2 inset = min(vec2(0.06) + 0.006 * size, size * 0.25);
    vec2 xz = inset + c * (size - 2.0 * inset);
    // Just above the ground, finer tiers on top: in a transition zone two tiers share a cell.
    float kind = field.blade_params.z;
    // On a height map the corners follow the terrain like the image tier's quads.
    float ground = terrain_height(vec2(i_cell.xy) + xz);
    vec3 p = vec3(xz.x, 0.02 + 0.03 * (2.0 - kind) + ground, xz.y); // cells
    vec3 position = mat3(field.patch_to_world) * p + GRASS_INSTANCE_ORIGIN(i_origin.xyz);
    v_color = tier_color(kind);
    gl_Position = GRASS_VIEW_PROJECTION * vec4(position, 1.0);
    // Far away the few centimetres above the ground are below the depth buffer's
    // resolution: pull the boxes slightly towards the camera in clip space, finer tiers
    // more (params.z: +1 when depth 0 is near, -1 for reversed depth).
    gl_Position.z -= frame.params.z * 2e-6 * (3.0 - kind) * gl_Position.w;
}
