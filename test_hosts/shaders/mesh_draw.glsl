// The host's meshes (host_mesh.hpp), drawn camera-relative and lit with Lambert + ambient.
// One block of 128 bytes: Vulkan's guaranteed push-constant size; a uniform block in GL.
// The ambient colour rides in the w components.
#ifdef VULKAN
layout(push_constant) uniform MeshDraw {
#else
layout(std140, binding = 0) uniform MeshDraw {
#endif
    mat4 view_projection;  // projection * view rotation (camera-relative)
    vec4 offset;           // xyz: the mesh's origin minus the camera (m); w: ambient red
    vec4 albedo;           // rgb: linear albedo; w: ambient green
    vec4 sun_direction;    // xyz: towards the sun, unit; w: ambient blue
    vec4 sun_color;        // rgb; w: 1 = encode the output to sRGB (UNORM targets)
} draw;
