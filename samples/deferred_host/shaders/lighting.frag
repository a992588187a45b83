#version 450
// grass-deferred's lighting pass, written once for both halves (GL compiles this text at run
// time, Vulkan as SPIR-V built by glslc): every pixel of the G-buffer lit by the sun, the
// ambient light and three point lights (glTF's falloff, as grass_light's), the sky where
// nothing wrote depth. The target stores sRGB (GL_SRGB8_ALPHA8 / VK_FORMAT_R8G8B8A8_SRGB).
// Window y runs up in GL and down in Vulkan, as clip y does under each half's projection, so
// gl_FragCoord maps to clip x and y alike; clip z is depth * 2 - 1 in GL, depth in Vulkan.
layout(binding = 0) uniform sampler2D g_albedo;
layout(binding = 1) uniform sampler2D g_normal;
layout(binding = 2) uniform sampler2D g_material;
layout(binding = 3) uniform sampler2D g_depth;
#ifdef VULKAN
layout(std140, binding = 4) uniform Lighting { // vk_deferred_host.hpp's LightingUniforms
    mat4 u_view_projection; // camera-relative world -> clip
    vec2 u_size;
    vec3 u_sun_direction; // towards the sun
    vec3 u_sun_color;
    vec3 u_ambient;
    vec4 u_light_position[3]; // camera-relative xyz, w: range
    vec4 u_light_color[3];    // rgb x intensity
};
#define CLIP_Z(depth) (depth)
#else
layout(location = 0) uniform mat4 u_view_projection; // camera-relative world -> clip
layout(location = 1) uniform vec2 u_size;
layout(location = 2) uniform vec3 u_sun_direction;   // towards the sun
layout(location = 3) uniform vec3 u_sun_color;
layout(location = 4) uniform vec3 u_ambient;
layout(location = 5) uniform vec4 u_light_position[3]; // camera-relative xyz, w: range
layout(location = 8) uniform vec4 u_light_color[3];    // rgb x intensity
#define CLIP_Z(depth) ((depth) * 2.0 - 1.0)
#endif
layout(location = 0) out vec4 out_color;
// What a blade lets through to its front of the light on its back (the material's g).
vec3 diffuse(vec3 albedo, vec3 n, vec3 l, float translucency) {
    float d = dot(n, l);
    return albedo * (max(d, 0.0) + translucency * max(-d, 0.0));
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(g_depth, p, 0).r;
    if (depth >= 1.0) { out_color = vec4(0.30, 0.42, 0.62, 1.0); return; } // the sky: scene.hpp's kSky
    vec3 albedo = texelFetch(g_albedo, p, 0).rgb;
    vec3 n = normalize(texelFetch(g_normal, p, 0).xyz * 2.0 - 1.0);
    vec3 m = texelFetch(g_material, p, 0).rgb;
    vec4 clip = vec4(gl_FragCoord.xy / u_size * 2.0 - 1.0, CLIP_Z(depth), 1.0);
    vec4 rel = inverse(u_view_projection) * clip;
    vec3 position = rel.xyz / rel.w; // camera-relative
    vec3 color = albedo * u_ambient * m.b + u_sun_color * diffuse(albedo, n, u_sun_direction, m.g);
    for (int i = 0; i < 3; ++i) {
        vec3 to_light = u_light_position[i].xyz - position;
        float d = length(to_light);
        float fade = clamp(1.0 - pow(d / u_light_position[i].w, 4.0), 0.0, 1.0);
        color += u_light_color[i].rgb * diffuse(albedo, n, to_light / d, m.g) * fade * fade / max(d * d, 1e-4);
    }
    out_color = vec4(color, 1.0);
}
