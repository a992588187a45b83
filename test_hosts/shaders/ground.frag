#version 450
layout(std140, binding = 0) uniform Ground {
    mat4 view_projection;
    vec4 plane;
    vec4 color;
    vec4 sun_direction;
    vec4 sun_color;
    vec4 ambient_color;
} ground;

layout(location = 0) out vec4 out_color;

#ifdef HOST_SHADOWS
#include "cascade_shadows.glsl"
layout(location = 0) in vec3 v_relative;
#endif

void main() {
    float n_dot_l = max(ground.sun_direction.y, 0.0); // the ground's normal is +y
#ifdef HOST_SHADOWS
    n_dot_l *= cascade_sun_visibility(v_relative);
#endif
    out_color = vec4(ground.color.rgb * (ground.ambient_color.rgb + ground.sun_color.rgb * n_dot_l), 1.0);
}
