// The host's lights (grass_view_lights_desc): directional, point and spot lights besides the
// sun, Kajiya-Kay anisotropic specular (bakay2003 3.3.2) and the ambient light as spherical
// harmonics. Included only where GRASS_HOST_LIGHTS is defined (the GRASS_HOST_LIGHTS
// feature's variants: GL defines it with GRASS_FEATURES), so every other variant declares
// nothing of it and its preprocessed text is what it was. The tiers include it after
// blade_interface.glsl and before lighting.glsl, whose ambient terms read host_ambient();
// they add host_lights_blade() or host_lights_lobes() to their lit colour.
#if defined(VULKAN) && defined(GRASS_MULTIVIEW)
#error "a stereo (multiview) view is not lit by the host's lights (the core refuses such a view)"
#endif

#define GRASS_HOST_LIGHTS_BLOCK 1 // lighting.glsl's ambient terms read host_ambient()

// lighting.glsl's, defined after this file.
vec3 world_to_patch_direction(vec3 d);
float soft_clamp(float mu, float sigma);
float texel_lobes(vec3 n, vec3 folded, vec3 to_camera, vec3 bend_dir, float turn, out vec3 lobe[4], out float w[4]);

struct GrassLight {
    vec4 position_kind; // xyz: camera-relative position (m), or the unit direction towards a directional light; w: kind
    vec4 axis;          // xyz: a spot's unit axis (the way it shines); w unused
    vec4 color_range;   // rgb: colour x intensity; w: range (m)
    vec4 cone;          // x: cos(inner angle), y: cos(outer angle) of a spot
};
struct GrassLightsData {
    vec4 counts;         // x: lights, y: specular strength, z: specular exponent, w: 1 = ambient harmonics
    vec4 ambient_sh[9];  // rgb per coefficient (grass.h's order)
    GrassLight light[8];
};
// The GrassLights block (api/src/foundation/frame_plan.hpp LightUniforms): GL binding 4;
// Vulkan set 1 (the view extras' blocks, backend_vk/src/vk_view_extras.hpp), binding 2. The
// block holds its struct as the one element of an array read at the Frame block's index
// (blade_interface.glsl says why: lavapipe would compile the shader again on every draw for
// the light count read at a constant offset).
#ifdef VULKAN
layout(std140, set = 1, binding = 2) uniform GrassLights { GrassLightsData lights_at[1]; };
#else
layout(std140, binding = 4) uniform GrassLights { GrassLightsData lights_at[1]; };
#endif
#ifdef GRASS_INDEXED_BLOCKS
#define grass_lights lights_at[grass_push.block_index]
#else
#define grass_lights lights_at[0]
#endif

// The ambient light at the world normal `n` (unit): the harmonics where the host gave them,
// else the view's ambient colour.
vec3 host_ambient(vec3 n) {
    if (grass_lights.counts.w < 0.5) return frame.ambient_color.rgb;
    vec3 a = grass_lights.ambient_sh[0].rgb * 0.282095;
    a += grass_lights.ambient_sh[1].rgb * (0.488603 * n.y) + grass_lights.ambient_sh[2].rgb * (0.488603 * n.z) +
         grass_lights.ambient_sh[3].rgb * (0.488603 * n.x);
    a += grass_lights.ambient_sh[4].rgb * (1.092548 * n.x * n.y) + grass_lights.ambient_sh[5].rgb * (1.092548 * n.y * n.z) +
         grass_lights.ambient_sh[6].rgb * (0.315392 * (3.0 * n.z * n.z - 1.0)) +
         grass_lights.ambient_sh[7].rgb * (1.092548 * n.x * n.z) +
         grass_lights.ambient_sh[8].rgb * (0.546274 * (n.x * n.x - n.y * n.y));
    return max(a, vec3(0.0));
}

// Kajiya-Kay's specular of a strand with unit tangent `t` (any frame, as `l` and `v`): the
// half vector's share in the strand's plane of normals, to the exponent. 0 without specular.
float host_specular(vec3 t, vec3 l, vec3 v) {
    if (grass_lights.counts.y <= 0.0) return 0.0;
    vec3 h = normalize(l + v);
    float th = dot(t, h);
    return grass_lights.counts.y * pow(sqrt(max(1.0 - th * th, 0.0)), grass_lights.counts.z);
}

// The tangent of a strand whose width runs level (the blades': patch_generator.cpp) and whose
// unit normal is `n`: the surface's direction across the level one, up the strand. `up` unit.
vec3 strand_tangent(vec3 n, vec3 up) {
    vec3 side = cross(up, n);
    return length(side) > 1e-4 ? normalize(cross(normalize(side), n)) : up;
}

// The specular of the blades a slice texel's normal lobe stands for (patch space): their
// normals spread about the lobe by `sigma` (lighting.glsl's texel_lobes), and so do their
// tangents' elevations, to which a high exponent is sensitive (the mean's tangent alone lost
// the highlight of the blades bent furthest): the three-point Gauss-Hermite mean over the
// spread, normals tilted up and down by sqrt(3) sigma.
float lobe_specular(vec3 lobe, float sigma, vec3 l, vec3 v) {
    const vec3 up = vec3(0.0, 1.0, 0.0);
    float s = 1.7320508 * sigma;
    float spec = 4.0 * host_specular(strand_tangent(lobe, up), l, v);
    spec += host_specular(strand_tangent(normalize(lobe + s * up), up), l, v);
    spec += host_specular(strand_tangent(normalize(lobe - s * up), up), l, v);
    return spec / 6.0;
}

// Light i at camera-relative point `p`: the unit direction towards it (world) and its
// irradiance (KHR_lights_punctual: 1/d^2, windowed by the range; a spot's smooth cone).
vec3 host_light_at(int i, vec3 p, out vec3 l) {
    GrassLight g = grass_lights.light[i];
    int kind = int(g.position_kind.w + 0.5);
    if (kind == 0) {
        l = g.position_kind.xyz;
        return g.color_range.rgb;
    }
    vec3 d = g.position_kind.xyz - p;
    float d2 = max(dot(d, d), 1e-8);
    l = d * inversesqrt(d2);
    float x = d2 / (g.color_range.w * g.color_range.w);
    float window = clamp(1.0 - x * x, 0.0, 1.0);
    float falloff = window * window / max(d2, 1e-4);
    if (kind == 2) falloff *= smoothstep(g.cone.y, g.cone.x, dot(-l, g.axis.xyz));
    return g.color_range.rgb * falloff;
}

// Banks' self-shadowing of a strand on a surface: none of a light below the field's ground
// plane reaches it (faded over +-1 degree as sun_above_ground()). `l` world, unit.
float above_ground(vec3 l) {
    return smoothstep(-0.0175, 0.0175, dot(l, normalize(mat3(field.patch_to_world)[1])));
}

// The blades (blade.frag): the host's lights on a two-sided blade of unit world normal `n`
// (its side facing the camera; `to_camera` towards the viewer, any length) at camera-relative
// `p`, and the sun's specular (`sun_share`:
// the share of the sun that reaches the point, light.y of the tier).
vec3 host_lights_blade(vec3 albedo, vec3 n, vec3 to_camera, vec3 p, float sun_share) {
    vec3 t = strand_tangent(n, normalize(mat3(field.patch_to_world)[1]));
    to_camera = normalize(to_camera); // towards_viewer() is not unit
    vec3 sun = frame.sun_direction.xyz;
    vec3 sum = frame.sun_color.rgb * (sun_share * above_ground(sun) * host_specular(t, sun, to_camera));
    int count = int(grass_lights.counts.x + 0.5);
    for (int i = 0; i < count; ++i) {
        vec3 l;
        vec3 e = host_light_at(i, p, l) * above_ground(l);
        sum += e * (albedo * max(dot(n, l), 0.0) + host_specular(t, l, to_camera));
    }
    return sum;
}

// The volume and image tiers (volume.frag, image.frag): the host's lights on a slice texel of
// mean normal `n` (patch space, lighting.glsl's lobes; `to_camera` patch space) at
// camera-relative `p`, bent by `turn` towards `bend_dir`, and the sun's specular. Each normal
// lobe stands for blades of about that normal: lit as lighting.glsl lights them, with the
// specular of their tangents (lobe_specular).
vec3 host_lights_lobes(vec3 albedo, vec3 n, vec3 folded, vec3 to_camera, vec3 p, vec3 bend_dir, float turn,
                       float sun_share) {
    vec3 lobe[4];
    float w[4];
    float sigma = texel_lobes(n, folded, to_camera, bend_dir, turn, lobe, w);
    float weight = w[0] + w[1] + w[2] + w[3];
    vec3 sun = frame.sun_direction.xyz;
    vec3 sun_patch = world_to_patch_direction(sun);
    float sun_specular = 0.0;
    for (int k = 0; k < 4; ++k) sun_specular += w[k] * lobe_specular(lobe[k], sigma, sun_patch, to_camera);
    vec3 sum = frame.sun_color.rgb * (sun_share * above_ground(sun) * sun_specular / weight);
    int count = int(grass_lights.counts.x + 0.5);
    for (int i = 0; i < count; ++i) {
        vec3 l;
        vec3 e = host_light_at(i, p, l) * above_ground(l);
        vec3 lp = world_to_patch_direction(l);
        float lit = 0.0, specular = 0.0;
        for (int k = 0; k < 4; ++k) {
            lit += w[k] * soft_clamp(dot(lobe[k], lp), sigma);
            specular += w[k] * lobe_specular(lobe[k], sigma, lp, to_camera);
        }
        sum += e * (albedo * lit + specular) / weight;
    }
    return sum;
}
