#version 450
// Debug view: the tier colour, lit like the ground so the field's shape reads.
#include "blade_interface.glsl"

layout(location = 0) flat in vec3 v_color;
layout(location = 0) out vec4 out_color;

void main() {
    load_blocks();
    float n_dot_l = max(frame.sun_direction.y, 0.0); // flat boxes face +y
    out_color = output_color(vec4(v_color * (frame.ambient_color.rgb + frame.sun_color.rgb * n_dot_l), 1.0));
}
