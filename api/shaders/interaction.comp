#version 450
// The interaction pass (docs/responsive.md): one dispatch per level of the interaction map,
// one invocation per texel. Provisional (h13-vk) until the shared one lands (h13-gl); same
// bindings. Texel: (dir_u, dir_v, U, age); cleared = (0, 0, 1e30, 1e30).
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform image2D map_level;
layout(std140, binding = 1) uniform Interaction {
    ivec4 window; // xy: the window's first texel mod N, zw: W - W_prev (clamped to +-N)
    vec4 origin;  // xy: texel W's lower corner relative to the camera (m), z: texel size (m), w: dt (s)
    uvec4 counts; // x: N, y: tile size (texels), z: tiles per side, w: 1 = clear everything
} level;
struct Collider {
    vec4 a;        // u, v, h of the centre / one end; w: radius
    vec4 b;        // u, v, h of the other end; w: shape (0 sphere, 1 capsule)
    vec4 velocity; // u, v, h (m/s)
};
layout(std430, binding = 2) readonly buffer Colliders { Collider colliders[]; };
layout(std430, binding = 3) readonly buffer TileOffsets { uint tile_offsets[]; };
layout(std430, binding = 4) readonly buffer TileColliders { uint tile_colliders[]; };

const vec4 kCleared = vec4(0.0, 0.0, 1e30, 1e30);

void main() {
    const int n = int(level.counts.x);
    const ivec2 i = ivec2(gl_GlobalInvocationID.xy);
    if (i.x >= n || i.y >= n) return;
    const ivec2 j = (i - level.window.xy + 2 * n) % n;
    const ivec2 shifted = j + level.window.zw;
    vec4 texel = imageLoad(map_level, i);
    if (level.counts.w == 1u || any(lessThan(shifted, ivec2(0))) || any(greaterThanEqual(shifted, ivec2(n)))) {
        texel = kCleared;
    }
    const float dt = level.origin.w;
    if (texel.w < 1e29) texel.w += dt;

    const vec2 column = level.origin.xy + (vec2(j) + 0.5) * level.origin.z;
    const uvec2 tile = uvec2(j) / level.counts.y;
    const uint t = tile.y * level.counts.z + tile.x;
    float best_u = 1e30, best_age = 1e30;
    vec2 best_dir = vec2(0.0);
    for (uint k = tile_offsets[t]; k < tile_offsets[t + 1u]; ++k) {
        const Collider c = colliders[tile_colliders[k]];
        const float r = c.a.w;
        if (r <= 0.0) continue;
        const vec3 v = c.velocity.xyz;
        if (c.b.w < 0.5) {
            const vec3 c1 = c.a.xyz, c0 = c1 - v * dt;
            const vec2 d01 = c1.xy - c0.xy;
            const float len2 = dot(d01, d01);
            const float s = len2 > 0.0 ? clamp(dot(column - c0.xy, d01) / len2, 0.0, 1.0) : 1.0;
            const vec3 cs = mix(c0, c1, s);
            const float d = distance(column, cs.xy);
            if (d >= r) continue;
            const float u = cs.z - sqrt(r * r - d * d);
            const float age = (1.0 - s) * dt;
            if (u < best_u || (u == best_u && age < best_age)) {
                best_u = u;
                best_age = age;
                best_dir = d >= 1e-6 * r ? (column - cs.xy) / d : (dot(v.xy, v.xy) > 0.0 ? normalize(v.xy) : texel.xy);
            }
        } else {
            const int steps = int(clamp(ceil(length(v) * dt / max(r, level.origin.z)), 1.0, 8.0));
            for (int q = 0; q <= steps; ++q) {
                const float s = float(q) / float(steps);
                const vec3 shift = v * dt * (s - 1.0);
                const vec3 a = c.a.xyz + shift, b = c.b.xyz + shift;
                const vec2 ab = b.xy - a.xy;
                const float len2 = dot(ab, ab);
                const float tt = len2 > 0.0 ? clamp(dot(column - a.xy, ab) / len2, 0.0, 1.0) : 0.0;
                const vec3 p = mix(a, b, tt);
                const float d = distance(column, p.xy);
                if (d >= r) continue;
                const float u = p.z - sqrt(r * r - d * d);
                const float age = (1.0 - s) * dt;
                if (u < best_u || (u == best_u && age < best_age)) {
                    best_u = u;
                    best_age = age;
                    best_dir = d >= 1e-6 * r ? (column - p.xy) / d : (dot(v.xy, v.xy) > 0.0 ? normalize(v.xy) : texel.xy);
                }
            }
        }
    }
    if (best_u < 1e29) texel = vec4(best_dir, best_u, best_age);
    imageStore(map_level, i, texel);
}
