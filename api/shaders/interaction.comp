#version 450
// The interaction pass (docs/responsive.md): one dispatch per level of the interaction map,
// one invocation per texel. It clears the texels that left the window since the last frame,
// ages the others by the time step, and records this frame's collider contacts (jahrmann2017
// 5.3: spheres; capsules too), swept over the time step so that a fast collider leaves a
// continuous trail. Texel: (dir_u, dir_v, U, age), see interaction.glsl.
layout(local_size_x = 8, local_size_y = 8) in;

// api/src/foundation/frame_plan.hpp InteractionLevelUniforms.
layout(std140, binding = 0) uniform Interaction {
    ivec4 window; // xy: the window's first texel mod N, zw: W - W_prev (clamped to +-N)
    vec4 origin;  // xy: texel W's lower corner relative to the camera (m), z: texel size (m), w: time step (s)
    uvec4 counts; // x: N, y: tile size (texels), z: tiles per side, w: 1 = clear everything
    vec4 least;   // x: the least footprint radius of the level (m): a narrower collider's is widened to it
} level;

// api/src/foundation/frame_plan.hpp GpuCollider: u, v, h in the map's frame (m; h above the anchor).
struct Collider {
    vec4 a;        // xyz: centre (sphere) or one axis end (capsule), w: radius
    vec4 b;        // xyz: the capsule's other end, w: shape (0 sphere, 1 capsule)
    vec4 velocity; // xyz: m/s, w: 1 = the collider continues its passage, 0 = new (its first frame)
};
layout(std430, binding = 1) readonly buffer Colliders {
    Collider colliders[];
};
layout(std430, binding = 2) readonly buffer TileOffsets {
    uint tile_offsets[]; // tiles^2 + 1 entries into tile_colliders, tile = y * tiles + x
};
layout(std430, binding = 3) readonly buffer TileColliders {
    uint tile_colliders[];
};
#ifdef VULKAN
layout(binding = 4, rgba32f) uniform image2D map;
#else
layout(binding = 0, rgba32f) uniform image2D map; // GL: image unit 0 (grass_gl.h)
#endif

const vec4 kCleared = vec4(0.0, 0.0, 1e30, 1e30);

// A contact of this frame: the lowest underside wins, ties the youngest.
struct Contact {
    float u; // underside height (m above the anchor)
    float age;
    vec2 dir;
    bool hit;
    bool continues; // the collider already touched the texel at the start of the sweep
};

void keep(inout Contact best, float u, float age, vec2 dir, bool continues) {
    if (!best.hit || u < best.u || (u == best.u && age < best.age)) {
        best.hit = true;
        best.u = u;
        best.age = age;
        best.dir = dir;
        best.continues = continues;
    }
}

// The direction away from point q (u, v) at horizontal distance d, or along the velocity
// under its centre, or `fallback`.
vec2 away_from(vec2 column, vec2 q, float d, float r, vec2 velocity, vec2 fallback) {
    if (d >= 1e-6 * r && d > 0.0) return (column - q) / d;
    float speed = length(velocity);
    return speed > 0.0 ? velocity / speed : fallback;
}

// The horizontal distance from the axis of a collider of radius r at which a texel centre d
// from it is pressed. The coarse level widens a footprint narrower than half a texel's
// diagonal to that radius R (d r / R), so every point of it lies within R of a texel centre
// and a collider narrower than a texel cannot slip between the centres; a wider one is
// pressed exactly. Strictly increasing in d: the deepest contact of a passage is at one
// point of it, at any frame rate.
float reached(float d, float r) {
    return level.least.x > r ? d * (r / level.least.x) : d;
}

void sphere_contact(inout Contact best, Collider c, vec2 column, float dt, vec2 fallback) {
    float r = c.a.w;
    vec3 c1 = c.a.xyz;
    vec3 c0 = c1 - c.velocity.xyz * dt;
    vec2 sweep = c1.xy - c0.xy;
    float len2 = dot(sweep, sweep);
    float s = len2 > 0.0 ? clamp(dot(column - c0.xy, sweep) / len2, 0.0, 1.0) : 1.0;
    vec3 cs = mix(c0, c1, s);
    float d = length(column - cs.xy);
    float e = reached(d, r);
    if (e >= r) return;
    bool continues = c.velocity.w > 0.5 && reached(length(column - c0.xy), r) < r; // w: not new (bin_colliders)
    keep(best, cs.z - sqrt(r * r - e * e), (1.0 - s) * dt, away_from(column, cs.xy, d, r, c.velocity.xy, fallback),
         continues);
}

void capsule_contact(inout Contact best, Collider c, vec2 column, float dt, float texel, vec2 fallback) {
    float r = c.a.w;
    vec3 v = c.velocity.xyz;
    int steps = int(clamp(ceil(length(v) * dt / max(r, texel)), 1.0, 8.0));
    vec3 axis = c.b.xyz - c.a.xyz;
    float axis2 = dot(axis.xy, axis.xy);
    bool continues = false;
    for (int k = 0; k <= steps; ++k) {
        float s = float(k) / float(steps);
        vec3 a = c.a.xyz - v * (dt * (1.0 - s));
        // The closest point of the axis to the column across up (a vertical capsule: its
        // lower end, whose underside is the lowest).
        float t = axis2 > 0.0 ? clamp(dot(column - a.xy, axis.xy) / axis2, 0.0, 1.0) : (axis.z < 0.0 ? 1.0 : 0.0);
        vec3 q = a + axis * t;
        float d = length(column - q.xy);
        float e = reached(d, r);
        if (e >= r) continue;
        continues = continues || (k == 0 && c.velocity.w > 0.5);
        keep(best, q.z - sqrt(r * r - e * e), (1.0 - s) * dt, away_from(column, q.xy, d, r, v.xy, fallback),
             continues);
    }
}

void main() {
    int n = int(level.counts.x);
    ivec2 i = ivec2(gl_GlobalInvocationID.xy);
    if (i.x >= n || i.y >= n) return;
    ivec2 j = (i - level.window.xy + n) % n; // window-relative: world texel W + j (operands >= 0)
    ivec2 moved = j + level.window.zw;
    bool stale = level.counts.w == 1u || any(lessThan(moved, ivec2(0))) || any(greaterThanEqual(moved, ivec2(n)));
    vec4 texel = stale ? kCleared : imageLoad(map, i);
    float dt = level.origin.w;
    if (texel.w < 1e29) texel.w += dt;

    uint tile_size = max(level.counts.y, 1u);
    uvec2 tile = uvec2(j) / tile_size;
    uint tiles = level.counts.z;
    if (tile.x < tiles && tile.y < tiles) {
        uint index = tile.y * tiles + tile.x;
        float texel_size = level.origin.z;
        vec2 column = level.origin.xy + (vec2(j) + 0.5) * texel_size;
        Contact best;
        best.hit = false;
        best.u = 0.0;
        best.age = 0.0;
        best.dir = vec2(0.0);
        best.continues = false;
        for (uint k = tile_offsets[index]; k < tile_offsets[index + 1u]; ++k) {
            Collider c = colliders[tile_colliders[k]];
            if (c.b.w < 0.5) {
                sphere_contact(best, c, column, dt, texel.xy);
            } else {
                capsule_contact(best, c, column, dt, texel_size, texel.xy);
            }
        }
        // A collider that was already on the texel when this frame's sweep began, and at the
        // last frame (velocity.w, decided by the core), continues the same passage: the texel keeps the deepest contact of the passage (ties: the
        // youngest), so a trail is the same at any frame rate (tests/core/interaction_pass_test).
        // A new passage replaces what an earlier one left.
        bool keep_stored = best.continues && texel.w < 1e29 && (texel.z < best.u || (texel.z == best.u && texel.w < best.age));
        if (best.hit && !keep_stored) texel = vec4(best.dir, best.u, best.age);
    }
    imageStore(map, i, texel);
}
