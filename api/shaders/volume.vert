#version 450
// Volume tier (lemme2012 5.2): a cuboid carrier per cell or macro-cell, as tall as the
// baked slices plus the terrain's height range under it (lemme 6.4.4). Every face is drawn;
// the fragment shader keeps the back faces, where the view ray leaves the cuboid, so a
// camera inside the volume still sees it.
#include "blade_interface.glsl"

layout(location = 5) in vec4 i_origin; // xyz: corner relative to the camera (m)
layout(location = 6) in uvec4 i_cell;  // xy: first cell, zw: size in cells
layout(location = 7) in vec4 i_terrain; // x: lowest, y: highest terrain height under it (patch units);
                                        // z: 1 for a field-edge instance (tier_interval)

layout(location = 0) out vec3 v_local;              // position in the cuboid, cells
layout(location = 1) flat out vec3 v_camera_local;  // the camera in the same frame (perspective rays start there)
layout(location = 2) flat out vec3 v_face_normal;   // outward normal of this face
layout(location = 3) flat out uvec4 v_cell;
layout(location = 4) flat out vec2 v_terrain;       // i_terrain.xy (0, 0 without a height map)
layout(location = 5) flat out float v_field_edge;   // i_terrain.z

void main() {
    load_blocks();
#ifdef VULKAN
    int v = gl_VertexIndex;
#else
    int v = gl_VertexID;
#endif
    // 6 faces x 2 triangles; corner bits: x = 1, y = 2, z = 4.
    const int corners[36] = int[36](0, 4, 6, 0, 6, 2,   1, 3, 7, 1, 7, 5,   // -x, +x
                                    0, 1, 5, 0, 5, 4,   2, 6, 7, 2, 7, 3,   // -y, +y
                                    0, 2, 3, 0, 3, 1,   4, 5, 7, 4, 7, 6);  // -z, +z
    const vec3 normals[6] = vec3[6](vec3(-1, 0, 0), vec3(1, 0, 0), vec3(0, -1, 0), vec3(0, 1, 0), vec3(0, 0, -1),
                                    vec3(0, 0, 1));
    int k = corners[v];
    vec3 size = vec3(float(i_cell.z), field.blade_params.w, float(i_cell.w));
    vec3 local = vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1)) * size;
    // On a height map the cuboid is extruded (lemme eq. 6.14): from the lowest terrain under
    // the instance to the slices' height above the highest.
    vec2 terrain = has_map(GRASS_MAP_HEIGHT) ? i_terrain.xy : vec2(0.0);
    if (has_map(GRASS_MAP_HEIGHT)) local.y = terrain.x + float((k >> 1) & 1) * (terrain.y - terrain.x + size.y);
    mat3 to_world = mat3(field.patch_to_world);
    vec3 position = to_world * local + GRASS_INSTANCE_ORIGIN(i_origin.xyz);
    v_local = local;
    v_camera_local = inverse(to_world) * (-GRASS_INSTANCE_ORIGIN(i_origin.xyz));
    v_face_normal = normals[v / 6];
    v_cell = i_cell;
    v_terrain = terrain;
    v_field_edge = i_terrain.z;
    gl_Position = GRASS_VIEW_PROJECTION * vec4(position, 1.0);
}
