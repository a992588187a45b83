#version 450
#include "mesh_draw.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_relative;
layout(location = 0) out vec4 out_color;
#ifdef HOST_SHADOWS
#include "cascade_shadows.glsl"
#endif

void main() {
    vec3 n = dot(v_normal, v_normal) > 1e-20 ? normalize(v_normal) : vec3(0.0, 1.0, 0.0);
    if (dot(n, v_relative) > 0.0) n = -n; // two-sided: the side that faces the camera
    vec3 ambient = vec3(draw.offset.w, draw.albedo.w, draw.sun_direction.w);
    float n_dot_l = max(dot(n, draw.sun_direction.xyz), 0.0);
#ifdef HOST_SHADOWS
    n_dot_l *= cascade_sun_visibility(v_relative);
#endif
    vec3 c = draw.albedo.rgb * (ambient + draw.sun_color.rgb * n_dot_l);
    if (draw.sun_color.w > 0.5) { // the target stores what is written: encode
        c = clamp(c, 0.0, 1.0);
        c = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
    }
    out_color = vec4(c, 1.0);
}
