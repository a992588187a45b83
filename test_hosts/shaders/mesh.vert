#version 450
#include "mesh_draw.glsl"

layout(location = 0) in vec3 position; // relative to the mesh's origin
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_relative; // from the camera

void main() {
    vec3 p = position + draw.offset.xyz;
    v_normal = normal;
    v_relative = p;
    gl_Position = draw.view_projection * vec4(p, 1.0);
}
