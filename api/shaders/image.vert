#version 450
// Image tier (lemme2012 5.3): one horizontal quad per cell or macro-cell, slightly above the
// ground; the fragment shader repeats and mirrors the horizontal slice per cell.
#include "blade_interface.glsl"

layout(location = 5) in vec4 i_origin; // xyz: corner relative to the camera (m)
layout(location = 6) in uvec4 i_cell;  // xy: first cell, zw: size in cells
layout(location = 7) in vec4 i_terrain; // x, y: lowest, highest terrain under the instance (patch units)

layout(location = 0) out vec3 v_position; // camera-relative world position
layout(location = 1) out vec2 v_local;    // position in the instance, cells
layout(location = 2) flat out uvec2 v_first_cell;

void main() {
    load_blocks();
#ifdef VULKAN
    int v = gl_VertexIndex;
#else
    int v = gl_VertexID;
#endif
    const int corner[6] = int[6](0, 1, 2, 2, 1, 3);
    // Vertices 0-5: the quad. On a height map, 6-29: a skirt hanging from each edge (the
    // backends draw them only then). Neighbouring instances of different sizes meet with
    // their edges interpolated differently (a T-junction); the skirts close those cracks,
    // which are at most the instance's terrain height range deep. Below the ground they
    // are hidden by the host's terrain.
    int q = v % 6, side = v / 6 - 1;
    vec2 c = vec2(float(corner[q] & 1), float(corner[q] >> 1));
    float drop = 0.0;
    if (side >= 0) { // edge side (0: z = 0, 1: x = 1, 2: z = 1, 3: x = 0); c.y picks top or bottom
        float along = c.x;
        c = side == 0 ? vec2(along, 0.0) : side == 1 ? vec2(1.0, along) : side == 2 ? vec2(1.0 - along, 1.0)
                                                                          : vec2(0.0, 1.0 - along);
        drop = float(corner[q] >> 1) * (i_terrain.y - i_terrain.x);
    }
    vec2 local = c * vec2(i_cell.zw);
    // Above the ground (lemme 5.3): at half the blade height, where the grass surface is
    // seen from afar; lower, the host's ground wins the depth test at a distance. On a
    // height map each corner is raised by the terrain under it (lemme 6.4.4): inside, the
    // quad's two triangles interpolate the corners, flattening the terrain within an
    // instance (the UNPLANARITY lod test keeps hilly instances small).
    float ground = terrain_height(vec2(i_cell.xy) + local);
    vec3 p = vec3(local.x, 0.5 * field.blade_params.w + ground - drop, local.y);
    v_position = mat3(field.patch_to_world) * p + GRASS_INSTANCE_ORIGIN(i_origin.xyz);
    v_local = local;
    v_first_cell = i_cell.xy;
    gl_Position = GRASS_VIEW_PROJECTION * vec4(v_position, 1.0);
}
