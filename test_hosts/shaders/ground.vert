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

// A grid of kTiles x kTiles squares (host_gl.cpp and host_vk.cpp draw 6 vertices each), not
// one square: a 4 km triangle clipped at the near plane is interpolated with a depth error of
// some 1e-6 (standard depth at 20-60 m), as large as what separates grass a few centimetres
// above the ground from it; an engine's terrain has smaller triangles.
const int kTiles = 32;

#ifdef HOST_SHADOWS
layout(location = 0) out vec3 v_relative; // from the camera
#endif

void main() {
    // Two triangles per square from the vertex index: corners (0,0) (1,0) (0,1) (1,1).
#ifdef VULKAN
    int v = gl_VertexIndex;
#else
    int v = gl_VertexID;
#endif
    const int corner[6] = int[6](0, 1, 2, 2, 1, 3);
    int c = corner[v % 6], tile = v / 6;
    vec2 cell = vec2(float(tile % kTiles + (c & 1)), float(tile / kTiles + (c >> 1)));
    vec2 xz = (cell / float(kTiles) * 2.0 - 1.0) * ground.plane.y;
    gl_Position = ground.view_projection * vec4(xz.x, ground.plane.x, xz.y, 1.0);
#ifdef HOST_SHADOWS
    v_relative = vec3(xz.x, ground.plane.x, xz.y);
#endif
}
