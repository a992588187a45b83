#version 450
// grass-deferred's ground in its G-buffer, both halves (GL compiles this text at run time,
// Vulkan as SPIR-V built by glslc): a quad at y = 0 from -40 to 56 m in x and z, six vertices
// and no buffer, in world space (metres within 60 of the origin: floats hold them to a
// micrometre), with its position in the previous frame's clip space for its velocity.
#ifdef VULKAN
layout(push_constant) uniform Ground {
    mat4 u_world_to_clip;          // velocity.hpp's ground_matrices
    mat4 u_world_to_previous_clip; // the previous frame's camera (this frame's: no motion)
};
#define VERTEX_ID gl_VertexIndex
#else
layout(location = 0) uniform mat4 u_world_to_clip;
layout(location = 1) uniform mat4 u_world_to_previous_clip;
#define VERTEX_ID gl_VertexID
#endif
layout(location = 0) out vec4 v_clip;
layout(location = 1) out vec4 v_previous_clip;
void main() {
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    vec2 corner = corners[VERTEX_ID];
    vec4 world = vec4(mix(-40.0, 56.0, corner.x), 0.0, mix(-40.0, 56.0, corner.y), 1.0);
    v_clip = u_world_to_clip * world;
    v_previous_clip = u_world_to_previous_clip * world;
    gl_Position = v_clip;
}
