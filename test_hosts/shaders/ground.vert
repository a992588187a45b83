#version 450
// The host's ground: a horizontal square around the camera at the ground's height,
// drawn camera-relative like grass. Not part of grass: a stand-in for an engine's terrain.
layout(std140, binding = 0) uniform Ground {
    mat4 view_projection;  // projection * view rotation (camera-relative)
    vec4 plane;            // x: ground height relative to the camera (m), y: half size (m)
    vec4 color;            // rgb: albedo
    vec4 sun_direction;    // xyz: towards the sun
    vec4 sun_color;
    vec4 ambient_color;
} ground;

void main() {
    // Two triangles from the vertex index: corners (-1,-1) (1,-1) (-1,1) (1,1).
#ifdef VULKAN
    int v = gl_VertexIndex;
#else
    int v = gl_VertexID;
#endif
    const int corner[6] = int[6](0, 1, 2, 2, 1, 3);
    int c = corner[v];
    vec2 xz = vec2(float(c & 1) * 2.0 - 1.0, float(c >> 1) * 2.0 - 1.0) * ground.plane.y;
    gl_Position = ground.view_projection * vec4(xz.x, ground.plane.x, xz.y, 1.0);
}
