// Blade response (jahrmann2017 5): each blade is a quadratic Bezier curve v0, v1, v2 (its
// rest pose I_v1, I_v2 from the BladeCurves buffer). Without state per blade, the tip v2 is
// the *equilibrium* of the recovery force (eq. 3) against wind (eq. 7-8) and gravity (eq.
// 4-6), then the state is validated (eq. 9, 11, 13) and capped by the interaction map's
// press. Included by blade.vert and blade_window.comp after lighting.glsl (mirror_signs),
// wind.glsl and interaction.glsl; used only by variants with GRASS_WIND or GRASS_INTERACTION.
// The per-blade state (blade_state.glsl) uses its forces, equilibrium and validation.

#ifdef VULKAN
#define GRASS_BLADE_CURVES_BINDING 12
#else
#define GRASS_BLADE_CURVES_BINDING 0 // GL: shader storage buffer binding 0 (grass_gl.h)
#endif
// Per blade, two vec4 (api/src/patch/patch_data.hpp): v1 - v0 and the arc length; v2 - v0
// and the facing angle. Patch units.
layout(std430, binding = GRASS_BLADE_CURVES_BINDING) readonly buffer BladeCurves {
    vec4 curves[];
};

// A point of the curve v0 = 0, v1, v2 at parameter t.
vec3 bezier(vec3 v1, vec3 v2, float t) { return 2.0 * (1.0 - t) * t * v1 + t * t * v2; }
vec3 bezier_tangent(vec3 v1, vec3 v2, float t) { return 2.0 * (1.0 - t) * v1 + 2.0 * t * (v2 - v1); }

// The length of the curve as drawn: the polyline through its `segments` + 1 vertices.
float drawn_length(vec3 v1, vec3 v2, int segments) {
    float len = 0.0;
    vec3 prev = vec3(0.0);
    for (int k = 1; k <= segments; ++k) {
        vec3 p = bezier(v1, v2, float(k) / float(segments));
        len += length(p - prev);
        prev = p;
    }
    return len;
}

// A factor in [1 - variation, 1 + variation] for parameter k of one blade of one cell.
float blade_variation(uint blade, uvec2 cell, uint k) {
    uint h = blade * 0x9E3779B9u ^ cell.x * 0x85EBCA6Bu ^ cell.y * 0xC2B2AE35u ^ k * 0x27D4EB2Fu;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return 1.0 + field.mechanics.w * (float(h) * (2.0 / 4294967295.0) - 1.0);
}

// Jahrmann's eq. 11, relative: v1 descends as v2 leaves its idle position. His v1 stands on
// the up axis; the generator's rest v1 leans with the blade, so it is scaled towards the
// root by q(v2) / q(I_v2) (at most 1): the rest pose stays as it is, and a blade laid flat
// has v1 near its root (a curve as long as its chord, whichever way it was laid).
float v1_height_factor(vec3 v2, vec3 up, float h) {
    float l_proj = length(v2 - up * dot(v2, up)); // eq. 10
    return max(1.0 - l_proj / h, 0.05 * max(l_proj / h, 1.0));
}

// The highest point of the curve 0, v1, v2 along up (v1 is a control point: it may stand
// above the curve): h1^2 / (2 h1 - h2) where the curve turns down before its tip, else h2.
float curve_top(vec3 v1, vec3 v2, vec3 up) {
    float h1 = dot(v1, up), h2 = dot(v2, up);
    return h1 > h2 ? h1 * h1 / (2.0 * h1 - h2) : h2;
}

// One blade's response (grass_blade_mechanics, field.mechanics) with its variation.
struct BladeMechanics {
    float stiffness; // recovery (m/s^2 for a tip moved its whole length), at least 1e-3
    float mass;      // x the gravity difference
    float response;  // wind response (m/s^2 per m/s)
};

BladeMechanics blade_mechanics(uint blade, uvec2 cell) {
    BladeMechanics m;
    m.stiffness = max(field.mechanics.x * blade_variation(blade, cell, 0u), 1e-3);
    m.mass = field.mechanics.y * blade_variation(blade, cell, 1u);
    m.response = field.mechanics.z * blade_variation(blade, cell, 2u);
    return m;
}

// The acceleration (world m/s^2) wind and gravity give the tip of a blade of rest tip i2,
// length `len` and unit `front` (across up): wind (eq. 7-8) aligned with the rest blade,
// and the gravity difference `gravity` to the standard gravity the rest pose has (eq. 4-6),
// plus a quarter of its magnitude along the front. The stateless pose balances it against
// recovery, the per-blade state (blade_state.glsl) is driven by it: the forces are computed
// here only.
vec3 blade_forces(BladeMechanics m, vec3 wind, vec3 gravity, vec3 i2, vec3 up, vec3 front, float len) {
    float wind_speed = length(wind);
    float f_d = wind_speed > 0.0 ? 1.0 - abs(dot(wind / wind_speed, normalize(i2))) : 0.0;
    float f_r = clamp(dot(i2, up) / len, 0.0, 1.0);
    vec3 w = m.response * wind * f_d * f_r;
    vec3 g_e = m.mass * gravity;
    vec3 g = g_e + 0.25 * length(g_e) * front;
    return w + g;
}

struct BladePose {
    vec3 v1, v2;  // deformed control points relative to the root (world metres)
    float shade;  // press darkening (press_shade)
};

// Validation (eq. 9, 11, 13) of tip v2 for a blade of rest points i1, i2 and length `len`
// (drawn length, m), then a cap of its height at `cap` (m along up).
void validate_blade(inout BladePose pose, vec3 i1, vec3 i2, vec3 up, float len, float cap, int segments) {
    vec3 v2 = pose.v2;
    v2 -= up * min(dot(up, v2), 0.0); // eq. 9: the tip stays above the root's plane
    vec3 v1 = i1 * min(v1_height_factor(v2, up, len) / v1_height_factor(i2, up, len), 1.0); // eq. 11 (relative)
    // eq. 13: scale both segments to the rest length: an exact scale about the root (up or
    // down: gravity may pull the tip towards the root), so one pass with the drawn length
    // is enough; the curve's top is kept at the cap first (v1's height at most cap +
    // sqrt(cap (cap - h2)), where h1^2 / (2 h1 - h2) = cap), which changes the length a
    // little: hence a second pass.
    for (int pass = 0; pass < 3; ++pass) {
        float h1_max = cap + sqrt(max(cap * (cap - dot(v2, up)), 0.0));
        v1 -= up * max(dot(v1, up) - h1_max, 0.0);
        float r = len / max(drawn_length(v1, v2, segments), 1e-6 * len);
        v1 *= r;
        v2 *= r;
        if (abs(r - 1.0) < 1e-4) break;
    }
    pose.v1 = v1;
    pose.v2 = v2;
}

// The equilibrium of recovery (I_v2 - v2) s against the forces (blade_forces), validated:
// an acceleration a moves the tip a / s of the blade's length `len`.
BladePose blade_equilibrium(vec3 i1, vec3 i2, vec3 up, float len, float stiffness, vec3 forces, int segments) {
    BladePose pose;
    pose.v1 = i1;
    pose.v2 = i2 + len * forces / stiffness;
    pose.shade = 1.0;
    validate_blade(pose, i1, i2, up, len, len, segments);
    return pose;
}

#ifdef GRASS_BLADE_STATE
// The blade window pass (blade_window.comp) steps the blade's state: its drawn pose replaces
// the equilibrium, before the interaction map's press and the terrain apply as they do to it.
BladePose blade_window_step(uint blade, uvec2 cell, vec3 i1, vec3 i2, vec3 up, float len, int segments, vec3 root,
                            vec3 forces);
#endif

// The deformed pose of blade `blade` of cell `cell`: rest points in world metres relative to
// the root (`to_world`: patch -> world with the cell's mirroring), root at camera-relative
// `root`, drawn with `segments` segments; on a height map the root stands at `ground`
// (patch units) at field point `cell_point` (cells).
BladePose blade_pose(uint blade, uvec2 cell, mat3 to_world, vec3 root, int segments, vec2 cell_point, float ground) {
    vec4 c1 = curves[2u * blade];
    vec4 c2 = curves[2u * blade + 1u];
    vec3 up = normalize(field.field_up.xyz);
    vec3 i1 = to_world * c1.xyz;
    vec3 i2 = to_world * c2.xyz;
    float len = drawn_length(i1, i2, segments); // the rest pose's, so eq. 13 keeps it exactly
    BladePose pose;
    pose.v1 = i1;
    pose.v2 = i2;
    pose.shade = 1.0;
    if (len <= 0.0) return pose;
    vec3 front = to_world * vec3(cos(c2.w), 0.0, sin(c2.w));
    front = normalize(front - up * dot(front, up) + 1e-12 * up);

    vec3 forces = vec3(0.0);
    float stiffness = 1.0;
    if (has_map(GRASS_WIND)) {
        BladeMechanics m = blade_mechanics(blade, cell);
        forces = blade_forces(m, wind_at(root, up, cell_point), frame.gravity.xyz, i2, up, front, len);
        stiffness = m.stiffness;
    }
    pose = blade_equilibrium(i1, i2, up, len, stiffness, forces, segments);
#ifdef GRASS_BLADE_STATE
    pose = blade_window_step(blade, cell, i1, i2, up, len, segments, root, forces);
#endif

    if (has_map(GRASS_INTERACTION)) {
        float depth = field.trample.x * blade_variation(blade, cell, 3u);
        float recovery = field.trample.y * blade_variation(blade, cell, 4u);
        // The press at the root, the blade's midpoint and its tip (eq. 14 tests the tip and
        // the midpoint), each on the ground under it; the lowest cap wins.
        float cap = len;
        vec3 dir = vec3(0.0);
        vec3 mid = 0.5 * pose.v1 + 0.25 * pose.v2;
        vec3 at[3] = vec3[3](vec3(0.0), mid - up * dot(mid, up), pose.v2 - up * dot(pose.v2, up));
        for (int k = 0; k < 3; ++k) {
            float c;
            vec3 d;
            if (interaction_press(root + at[k], len, depth, recovery, c, d) && c < cap) {
                cap = c;
                dir = d;
            }
        }
        if (curve_top(pose.v1, pose.v2, up) > cap) {
            // Lay the blade along the press until its top is at the cap: the tip at height
            // `aim` and reach sqrt(len^2 - aim^2), validated; eq. 13 then shortens the
            // chord a little (the curve is longer than it), so the aim is raised until the
            // validated tip is at the cap (the trail's depth is then exactly len - cap).
            dir -= up * dot(dir, up);
            if (dot(dir, dir) < 1e-12) dir = pose.v2 - up * dot(pose.v2, up);
            if (dot(dir, dir) < 1e-12) dir = front;
            dir = normalize(dir);
            float aim = cap;
            for (int pass = 0; pass < 3; ++pass) {
                pose.v2 = dir * sqrt(max(len * len - aim * aim, 0.0)) + up * aim;
                validate_blade(pose, i1, i2, up, len, cap, segments);
                float tip = dot(pose.v2, up);
                if (tip <= 0.0 || abs(tip - cap) < 1e-3 * len) break;
                aim = min(aim * cap / tip, len);
            }
        }
        pose.shade = press_shade(cap / len);
    }

    if (has_map(GRASS_MAP_HEIGHT)) {
        // Eq. 9 keeps the tip above the root's plane; on a height map the terrain under the
        // tip may be higher (uphill): the tip is lifted onto it, then validated again.
        mat3 to_patch = transpose(mat3(field.patch_to_world)) / (field.field_up.w * field.field_up.w);
        for (int pass = 0; pass < 2; ++pass) {
            vec3 tip = to_patch * pose.v2;
            float floor_height = (terrain_height(cell_point + tip.xz) - ground) * field.field_up.w;
            float height = dot(pose.v2, up);
            if (height >= floor_height) break;
            pose.v2 += up * (floor_height - height);
            validate_blade(pose, i1, i2, up, len, len, segments);
        }
    }
    return pose;
}

// The per-blade step (docs/responsive.md "The blade window"): the pose of blade `blade` of
// cell `cell`, whose (0, 0) corner lies at `origin` (m, relative to the view's eye), from
// the blade's root `root_patch` (patch units, before the cell's mirroring), drawn with
// `segments` segments. blade_window.comp runs it once per blade and frame; blade.vert runs
// it where the window holds no pose for the blade.
BladePose cell_blade_pose(uint blade, uvec2 cell, vec3 origin, vec2 root_patch, int segments) {
    vec2 s = mirror_signs(cell);
    vec2 root = (root_patch - 0.5) * s + 0.5;
    vec2 cell_point = vec2(cell) + root;
    float ground = terrain_height(cell_point);
    vec3 root_position = mat3(field.patch_to_world) * vec3(root.x, ground, root.y) + origin;
    mat3 to_world = mat3(field.patch_to_world) * mat3(vec3(s.x, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, s.y));
    return blade_pose(blade, cell, to_world, root_position, segments, cell_point, ground);
}
