// Wind (jahrmann2017 5.1, bakay2003 3.3): the wind velocity as a function of position and
// time, evaluated where blades and slices are drawn (no state). Included after
// blade_interface.glsl by the draw shaders; read only by variants with GRASS_WIND.
//
// The mean wind W = frame.wind.xyz (speed S, direction dir) carries three gust waves of
// wavelengths lambda_k = gust_length * (1, 0.618034, 0.381966), travelling along dir at
// S * (1, 1.13, 0.87). Their phases at the camera are frame.wind_phase.xyz (cycles, computed
// by the core in double: api/src/plan); at a camera-relative point p the phase of wave k is
// wind_phase[k] + dot(p, dir) / lambda_k. The waves' periods are incommensurate, so the gust
// train never repeats visibly (bakay: a period that hides itself). Each wave's profile has a
// strong attack and a slow fall (bakay 3.3, after Neyret); the speed is S (1 + gust_strength
// G) with G in [0, 1] the mean of the three profiles, plus turbulence: small waves of speed
// and of direction across the wind, at most turbulence x S. Local sources add their own
// wind (frame.wind_sources), and so does the field's wind map (wind_of_map).

// The gust phases at the camera: the frame's, or the previous frame's while a motion
// variant poses the grass at the previous time (motion.glsl).
#ifdef GRASS_VELOCITY
#define GRASS_WIND_PHASE (g_previous_time ? grass_motion.previous_wind_phase : frame.wind_phase)
#else
#define GRASS_WIND_PHASE frame.wind_phase
#endif

const float kWindTwoPi = 6.283185307179586;
const vec3 kGustWavelength = vec3(1.0, 0.618034, 0.381966); // x gust_length
const float kGustAttack = 0.15; // share of a gust's cycle spent rising

// One gust's profile at phase f (cycles): 0 at the cycle's ends, 1 at its peak. Phases fall
// with time (they travel along +dir), so the cycle's progress in time is 1 - fract(f): a
// quick rise over kGustAttack of the cycle, then a slow quadratic fall.
float gust_profile(float f) {
    float x = 1.0 - fract(f);
    if (x < kGustAttack) return smoothstep(0.0, kGustAttack, x);
    float fall = 1.0 - (x - kGustAttack) / (1.0 - kGustAttack);
    return fall * fall;
}

// The velocity (world m/s) of the wind sources at camera-relative p.
vec3 wind_of_sources(vec3 p) {
    vec3 w = vec3(0.0);
    int count = min(int(frame.wind_shape.z + 0.5), 16);
    for (int i = 0; i < count; ++i) {
        vec4 s0 = frame.wind_sources[4 * i + 0]; // xyz: position, w: kind
        vec4 s1 = frame.wind_sources[4 * i + 1]; // xyz: direction (CONE), w: cos(cone angle)
        vec4 s2 = frame.wind_sources[4 * i + 2]; // x: speed, y: radius, z: since start, w: duration
        vec4 s3 = frame.wind_sources[4 * i + 3]; // x: front speed
        vec3 r = p - s0.xyz;
        float d = length(r);
        float radius = max(s2.y, 1e-3);
        float speed = s2.x / (1.0 + (d / radius) * (d / radius));
        vec3 away = d > 1e-6 * radius ? r / d : vec3(0.0);
        int kind = int(s0.w + 0.5);
        if (kind == 0) { // POINT: outwards, strongest under it
            w += speed * away;
        } else if (kind == 1) { // CONE: along its axis inside the cone, a smooth edge
            float edge = max(0.05 * (1.0 - s1.w), 0.005);
            w += speed * smoothstep(s1.w - edge, s1.w + edge, dot(away, s1.xyz)) * s1.xyz;
        } else if (s2.z >= 0.0 && s2.z <= s2.w) { // BLAST: outwards in a ring around its front
            float front = s3.x * s2.z;
            float ring = 1.0 - smoothstep(0.0, radius, abs(d - front));
            w += speed * ring * (1.0 - s2.z / max(s2.w, 1e-6)) * away;
        }
    }
    return w;
}

// The field's wind map (grass_set_field_wind_map; bound only for variants with
// GRASS_WIND_MAP): an RGBA design map whose r and g are the wind along the field's x and z,
// v = (2 t - 1) x speed. The core stores colour maps with linear rgb, so each texel's r and
// g are encoded back to the host's values before the bilinear weights apply: the wind is
// interpolated as the host painted it, edges clamped.
#ifdef GRASS_RESPONSIVE
layout(binding = 13) uniform sampler2D wind_map;
#endif

vec2 wind_map_value(ivec2 texel, ivec2 size) {
    vec2 c = texelFetch(wind_map, clamp(texel, ivec2(0), size - 1), 0).rg;
    return mix(12.92 * c, 1.055 * pow(c, vec2(1.0 / 2.4)) - 0.055, step(vec2(0.0031308), c));
}

// The wind of the field's map (world m/s) at a point of the field given in cells.
vec3 wind_of_map(vec2 cell_point) {
    if (!has_map(GRASS_WIND_MAP)) return vec3(0.0);
    vec3 q = vec3(cell_point, 1.0);
    vec2 uv = vec2(dot(field.wind_map_u.xyz, q), dot(field.wind_map_v.xyz, q));
    ivec2 size = textureSize(wind_map, 0);
    vec2 t = uv * vec2(size) - 0.5;
    vec2 f = fract(t);
    ivec2 i = ivec2(floor(t));
    vec2 e = mix(mix(wind_map_value(i, size), wind_map_value(i + ivec2(1, 0), size), f.x),
                 mix(wind_map_value(i + ivec2(0, 1), size), wind_map_value(i + ivec2(1, 1), size), f.x), f.y);
    vec2 v = (2.0 * e - 1.0) * field.wind_map_u.w; // m/s along the field's x and z
    return mat3(field.patch_to_world) * vec3(v.x, 0.0, v.y) / max(field.field_up.w, 1e-30);
}

// The wind velocity (world m/s) at camera-relative p, which lies over `cell_point` of the
// field (cells), across `up` (the field's up: the component along it moves nothing).
vec3 wind_at(vec3 p, vec3 up, vec2 cell_point) {
#ifdef GRASS_MULTIVIEW
    p += GRASS_EYE; // eye-relative -> relative to the plan's origin, the wind's
#endif
    vec3 w = vec3(0.0);
    vec3 mean = frame.wind.xyz;
    float speed = length(mean);
    if (speed > 0.0) {
        vec3 dir = mean / speed;
        vec3 inv_lambda = frame.wind_shape.x / kGustWavelength;
        vec3 phase = GRASS_WIND_PHASE.xyz + dot(p, dir) * inv_lambda;
        float gust = (gust_profile(phase.x) + gust_profile(phase.y) + gust_profile(phase.z)) / 3.0;
        // Turbulence: integer multiples of the phases (continuous across their wrap at 1),
        // along the wind and across it (wind_phase.w: the cross-wind coordinate at the
        // camera, in cycles of half a gust length).
        vec3 cross_dir = cross(up, dir);
        float cross_len = length(cross_dir);
        cross_dir = cross_len > 1e-6 ? cross_dir / cross_len : vec3(0.0);
        float across = GRASS_WIND_PHASE.w + dot(p, cross_dir) * 2.0 * frame.wind_shape.x;
        float t_speed = 0.5 * sin(kWindTwoPi * (3.0 * phase.y + 2.0 * across)) +
                        0.5 * sin(kWindTwoPi * (5.0 * phase.z - 3.0 * across));
        float t_dir = sin(kWindTwoPi * (2.0 * phase.x - 5.0 * across));
        float turbulence = frame.wind_shape.y * speed;
        w = dir * (speed * (1.0 + frame.wind.w * gust) + turbulence * 0.5 * t_speed) +
            cross_dir * (turbulence * 0.5 * t_dir);
    }
    w += wind_of_sources(p);
    w += wind_of_map(cell_point);
    return w - up * dot(w, up);
}
