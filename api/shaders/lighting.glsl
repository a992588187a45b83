// The lighting of every tier (lemme2012 6.4.3): Lambert plus ambient, with the ambient
// occlusion of neighbouring blades (eq. 6.9-6.11). One function, so a cell's colour does
// not change when it changes tier.

// AO_blade = 1 - B_impact * density * smoothstep(B_height, 0, P_y)   (eq. 6.11)
// GLSL leaves smoothstep undefined for edge0 >= edge1, so the falling edge is written as
// 1 - smoothstep(0, B_height, P_y).
float blade_ambient_occlusion(float density, float height_over_ground, float impact, float ao_height) {
    return 1.0 - impact * density * (1.0 - smoothstep(0.0, ao_height, height_over_ground));
}

// The share of the sun above the field's ground plane: 1 above it, 0 below it (the ground
// shadows the grass, as it does the host's terrain), faded over +-1 degree about the horizon
// so that a setting sun does not pop. Without it a sun below the ground lit the grass from
// underneath about as brightly as one overhead (ExtremesTest.SunAtTheZenith...).
float sun_above_ground() {
    vec3 up = normalize(mat3(field.patch_to_world)[1]);
    return smoothstep(-0.0175, 0.0175, dot(frame.sun_direction.xyz, up));
}

// light = I_ambient * AO * albedo + I_diffuse * albedo * max(0, N.L)   (eq. 6.9)
// `n` is the normal of the side that faces the camera (two-sided material). `light` is
// light_maps() at the point (blade_interface.glsl): x scales the ambient term (the ambient
// map holds the scene's AO, eq. 6.10, AO_blade is `ambient_occlusion`), y the sun term (the
// diffuse map's shadows). Without light maps it is (1, 1) and the products fold away.
// With the host's lights (GRASS_HOST_LIGHTS) the ambient colour may vary with the normal
// (host_lights.glsl, included before this file by the fragment shaders that light grass).
#ifdef GRASS_HOST_LIGHTS_BLOCK
#define GRASS_AMBIENT(n) host_ambient(n)
#else
#define GRASS_AMBIENT(n) frame.ambient_color.rgb
#endif
vec3 grass_lighting(vec3 albedo, vec3 n, float ambient_occlusion, vec2 light) {
    float n_dot_l = max(dot(n, frame.sun_direction.xyz), 0.0) * sun_above_ground();
    return albedo * (GRASS_AMBIENT(n) * (ambient_occlusion * light.x) + frame.sun_color.rgb * (n_dot_l * light.y));
}

// The debug view's tint of a tier (GRASS_VIEW_FLAG_DEBUG_TIERS = 2 in frame.params.y):
// red geometry, yellow volume, blue image, mixed half into the lit colour.
// Both debug views' code exists only in the GRASS_DEBUG_VIEW variants (api/src/foundation/shader_interface.hpp).
vec3 debug_tint(vec3 color) {
    if (!has_map(GRASS_DEBUG_VIEW) || (uint(frame.params.y + 0.5) & 2u) == 0u) return color;
    float kind = field.blade_params.z;
    vec3 tint = kind < 0.5 ? vec3(0.85, 0.06, 0.04) : kind < 1.5 ? vec3(0.90, 0.75, 0.04) : vec3(0.04, 0.18, 0.90);
    return mix(color, tint * (0.4 + 0.6 * dot(color, vec3(0.33)) / 0.2), 0.6);
}

// GRASS_VIEW_FLAG_DEBUG_THRESHOLDS (8 in frame.params.y): the blade's threshold in 16 bits
// (red high byte, green low byte) and the tier kind in blue, as linear values that an sRGB
// target encodes back to exactly those bytes; with GRASS_VIEW_FLAG_ENCODE_SRGB (a target
// that stores what it is given) as the bytes themselves.
bool debug_thresholds() {
    return has_map(GRASS_DEBUG_VIEW) && (uint(frame.params.y + 0.5) & 8u) != 0u;
}
float srgb_byte_to_linear(float byte) {
    float c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}
uint threshold_index(float threshold) {
    return uint(clamp(threshold, 0.0, 1.0) * 65535.0 + 0.5);
}
vec4 threshold_color(uint code) {
    float kind = field.blade_params.z;
    float blue = kind < 0.5 ? 0.0 : kind < 1.5 ? 128.0 : 255.0;
    if (encode_srgb()) return vec4(float(code >> 8) / 255.0, float(code & 255u) / 255.0, blue / 255.0, 1.0);
    return vec4(srgb_byte_to_linear(float(code >> 8)), srgb_byte_to_linear(float(code & 255u)),
                srgb_byte_to_linear(blue), 1.0);
}
vec4 threshold_code(float threshold) {
    return threshold_color(threshold_index(threshold));
}

// The light of the blades behind one slice texel. The texel keeps the mean normal of the
// sides facing the slice's viewer, its component along the slice's view axis signed and the
// two across it as magnitudes (api/src/slice_rasterizer.cpp): those lean one way for some
// blades and the other way for the rest, and an averaged normal would cancel them (a high
// sun would light a vertical slice's blades too little, a sun from the side not at all).
// The four sign lobes of `n` across the `folded` axes (1 where folded, 0 on the view axis)
// stand for those blades. Each lobe is lit on its side that faces the camera (two-sided
// blades) and weighted by its area projected towards the camera, |n.v|, as blades are in
// the picture. Everything in patch space: `n` the texel's mean normal (not unit), `to_camera` and `sun` unit directions
// (patch_to_world is a rotation and a uniform scale). `light` as for grass_lighting.
// E[max(x, 0)] for x normal with mean mu and deviation sigma, mu Phi(mu/sigma) +
// sigma phi(mu/sigma), approximated by (mu + sqrt(mu^2 + (2/pi) sigma^2)) / 2: exact at
// mu = 0 and in both tails, within 0.071 sigma between, and one square root instead of two
// exponentials. The mean light of normals that spread about their mean: where some blades
// turn to the sun and some away, the clamp of the mean normal alone would be too dark.
float soft_clamp(float mu, float sigma) {
    return 0.5 * (mu + sqrt(mu * mu + 0.63662 * sigma * sigma));
}

// A normal turned as a bent column's tangent turns (responsive grass, shell_bend.glsl): by
// angle `turn` from up towards `d` (unit, across up; patch space). No turn: n as it is.
vec3 turned_towards(vec3 n, vec3 d, float turn) {
    if (turn < 1e-4) return n;
    vec3 k = vec3(d.z, 0.0, -d.x); // up x d: the axis that turns up towards d
    float c = cos(turn), s = sin(turn);
    return n * c + cross(k, n) * s + k * dot(k, n) * (1.0 - c);
}

#ifdef GRASS_HOST_LIGHTS_BLOCK
// The four sign lobes of a slice texel's mean normal `n` (patch space, not unit) across its
// `folded` axes, each turned with the column by `turn` towards `bend_dir` and facing the
// camera, with their weights |n.v| towards `to_camera`: grass_lighting_lobes_bent's, for the
// host's lights (host_lights.glsl), which light several directions with one set. Returns the
// spread sigma of the blades' normals about the mean. (grass_lighting_lobes_bent keeps its
// own loop: on llvmpipe the arrays made every plain volume frame 1.45 times slower.)
float texel_lobes(vec3 n, vec3 folded, vec3 to_camera, vec3 bend_dir, float turn, out vec3 lobe[4], out float w[4]) {
    float r = length(n);
    n = r > 1e-4 ? n / r : vec3(0.0, 1.0, 0.0);
    vec3 a = folded.x > 0.5 ? vec3(-1.0, 1.0, 1.0) : vec3(1.0, -1.0, 1.0);
    vec3 b = folded.z > 0.5 ? vec3(1.0, 1.0, -1.0) : vec3(1.0, -1.0, 1.0);
    for (int k = 0; k < 4; ++k) {
        lobe[k] = turned_towards(n * ((k & 1) != 0 ? a : vec3(1.0)) * ((k & 2) != 0 ? b : vec3(1.0)), bend_dir, turn);
        float v = dot(lobe[k], to_camera);
        if (v < 0.0) lobe[k] = -lobe[k]; // each lobe is lit on its side that faces the camera (two-sided blades)
        w[k] = abs(v) + 1e-3;
    }
    return sqrt(max(1.0 - r * r, 0.0) * 0.5);
}

// The ambient light at the lobes' normals, weighted as their light is (the host's harmonics).
vec3 lobes_ambient(vec3 n, vec3 folded, vec3 to_camera, vec3 bend_dir, float turn) {
    if (grass_lights.counts.w < 0.5) return frame.ambient_color.rgb;
    vec3 lobe[4];
    float w[4];
    texel_lobes(n, folded, to_camera, bend_dir, turn, lobe, w);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        sum += w[k] * host_ambient(normalize(mat3(field.patch_to_world) * lobe[k]));
        weight += w[k];
    }
    return sum / weight;
}
#define GRASS_LOBES_AMBIENT(n, folded, to_camera, bend_dir, turn) lobes_ambient(n, folded, to_camera, bend_dir, turn)
#else
#define GRASS_LOBES_AMBIENT(n, folded, to_camera, bend_dir, turn) frame.ambient_color.rgb
#endif

// grass_lighting_lobes of slices whose grass is bent (bakay's shells lit by their bent
// tangents): each lobe, a blade's normal, turns with the column by `turn` towards `bend_dir`.
// The lobes turn, not the mean normal before them: the lobes fold signs that a cell's
// mirroring flips, and turning the folded mean made mirrored cells light differently (a
// cell-sized checkerboard under wind).
vec3 grass_lighting_lobes_bent(vec3 albedo, vec3 n, vec3 folded, vec3 to_camera, vec3 sun, float ambient_occlusion,
                               vec2 light, vec3 bend_dir, float turn) {
    vec3 ambient = GRASS_LOBES_AMBIENT(n, folded, to_camera, bend_dir, turn);
    // The texel's mean normal: its length r < 1 says how much the blades' normals spread,
    // 1 - r^2 their variance (Toksvig), about half of it along any one direction.
    float r = length(n);
    n = r > 1e-4 ? n / r : vec3(0.0, 1.0, 0.0);
    float sigma = sqrt(max(1.0 - r * r, 0.0) * 0.5);
    // The two folded axes as sign masks: a flips the first, b the second.
    vec3 a = folded.x > 0.5 ? vec3(-1.0, 1.0, 1.0) : vec3(1.0, -1.0, 1.0);
    vec3 b = folded.z > 0.5 ? vec3(1.0, 1.0, -1.0) : vec3(1.0, -1.0, 1.0);
    float lit = 0.0, weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec3 lobe = turned_towards(n * ((k & 1) != 0 ? a : vec3(1.0)) * ((k & 2) != 0 ? b : vec3(1.0)), bend_dir, turn);
        float v = dot(lobe, to_camera);
        float w = abs(v) + 1e-3;
        lit += w * soft_clamp((v < 0.0 ? -1.0 : 1.0) * dot(lobe, sun), sigma);
        weight += w;
    }
    float n_dot_l = lit / weight * sun_above_ground();
    return albedo * (ambient * (ambient_occlusion * light.x) + frame.sun_color.rgb * (n_dot_l * light.y));
}

vec3 grass_lighting_lobes(vec3 albedo, vec3 n, vec3 folded, vec3 to_camera, vec3 sun, float ambient_occlusion,
                          vec2 light) {
    return grass_lighting_lobes_bent(albedo, n, folded, to_camera, sun, ambient_occlusion, light, vec3(0.0), 0.0);
}

// A world direction in patch space (the inverse of patch_to_world's rotation).
vec3 world_to_patch_direction(vec3 d) {
    return normalize(transpose(mat3(field.patch_to_world)) * d);
}

// The mirror bits of a cell (lemme eq. 6.4): white noise at the integer cell, bit 0 mirrors
// x, bit 1 mirrors z. The same function as grass::mirror_bits (api/src/mirror_tiling.cpp).
uint mirror_bits(uvec2 cell, uint seed) {
    uint h = cell.x * 0x8da6b343u ^ cell.y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return (h >> 30) & 3u;
}

// The mirror signs of a cell of this field (all +1 when mirrored tiling is off).
vec2 mirror_signs(uvec2 cell) {
    uint b = field.tiling.y != 0u ? mirror_bits(cell, field.tiling.x) : 0u;
    return vec2((b & 1u) != 0u ? -1.0 : 1.0, (b & 2u) != 0u ? -1.0 : 1.0);
}
