#version 450
// grass-deferred's ground in its G-buffer, both halves (GL compiles this text at run time,
// Vulkan as SPIR-V built by glslc): a quad at y = 0 from -40 to 56 m in x and z
// (scene.hpp's kGroundMin, kGroundMax), camera-relative, six vertices and no buffer.
#ifdef VULKAN
layout(push_constant) uniform Ground {
    mat4 u_view_projection; // camera-relative world -> clip
    vec3 u_camera;
};
#define VERTEX_ID gl_VertexIndex
#else
layout(location = 0) uniform mat4 u_view_projection; // camera-relative world -> clip
layout(location = 1) uniform vec3 u_camera;
#define VERTEX_ID gl_VertexID
#endif
void main() {
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    vec2 corner = corners[VERTEX_ID];
    vec3 world = vec3(mix(-40.0, 56.0, corner.x), 0.0, mix(-40.0, 56.0, corner.y));
    gl_Position = u_view_projection * vec4(world - u_camera, 1.0);
}
