// The interaction map (docs/responsive.md): collider trails around the camera, written by
// interaction.comp, read here by the draw shaders with GRASS_INTERACTION. One or two
// square RGBA32F levels of N x N texels across the map's up, toroidally addressed; a texel
// is (dir_u, dir_v, U, age): the direction pressed grass lies towards (map axes), the
// collider's underside at its deepest contact (m above the map's height anchor) and the
// seconds since that contact. A cleared texel is (0, 0, 1e30, 1e30).

// GL: texture units 10 and 11 (grass_gl.h); Vulkan: set 0, bindings 10 and 11.
layout(binding = 10) uniform sampler2D interaction_level0;
layout(binding = 11) uniform sampler2D interaction_level1;

// The map's texel at camera-relative point p: level 0 where p is inside its window, else
// level 1 where inside it, else false (no press known there).
bool interaction_texel(vec3 p, out vec4 texel) {
#ifdef GRASS_MULTIVIEW
    p += GRASS_EYE; // eye-relative -> relative to the plan's origin, the map's
#endif
    p += frame.map_offset.xyz; // relative to the camera the map's window follows (view 0's)
    texel = vec4(0.0, 0.0, 1e30, 1e30);
    int levels = int(frame.map_up.w + 0.5);
    vec2 uv = vec2(dot(p, frame.map_axis_u.xyz), dot(p, frame.map_axis_v.xyz));
    for (int l = 0; l < 2; ++l) {
        if (l >= levels) break;
        vec4 level = frame.map_levels[l]; // xy: camera's coordinate (texels, mod N), z: texels per metre, w: N
        vec2 offset = uv * level.z;
        if (any(greaterThanEqual(abs(offset), vec2(0.5 * level.w - 1.0)))) continue;
        ivec2 at = ivec2(mod(floor(level.xy + offset), level.w));
        texel = l == 0 ? texelFetch(interaction_level0, at, 0) : texelFetch(interaction_level1, at, 0);
        return true;
    }
    return false;
}

// The press at camera-relative ground point p on grass of rest length `len` (m): the height
// `cap` (m above the ground at p, along the map's up) that the grass there may reach, and
// the world direction `dir` it lies towards (zero when unknown). The collider's underside U
// pressed it to P0 = max(U - g, 0) (1 - depth); it stands up again as
// P(age) = len - (len - P0) exp(-age / recovery): the trail's depth len - P decays as
// exp(-age / recovery). False where nothing presses (no contact, or the contact was above
// the grass).
bool interaction_press(vec3 p, float len, float depth, float recovery, out float cap, out vec3 dir) {
    cap = len;
    dir = vec3(0.0);
    vec4 texel;
    if (!interaction_texel(p, texel) || texel.w >= 1e29) return false;
    // m above the anchor (map_axis_v.w: the map camera's height above it)
    float ground = dot(p + frame.map_offset.xyz, frame.map_up.xyz) + frame.map_axis_v.w;
    float p0 = max(texel.z - ground, 0.0) * (1.0 - clamp(depth, 0.0, 1.0));
    if (p0 >= len) return false;
    float age = texel.w;
#ifdef GRASS_VELOCITY
    // The pose at the previous time (motion.glsl): the trail was that much younger. A press
    // younger than that is taken as it is now: the map keeps no earlier contact (a collider
    // resting on the grass renews its contact every frame), so the frame a collider first
    // presses grass gives that press no velocity; a trail standing up again gives its own.
    if (g_previous_time) age = max(age - grass_motion.times.x, 0.0);
#endif
    cap = len - (len - p0) * exp(-age / max(recovery, 1e-6));
    dir = texel.x * frame.map_axis_u.xyz + texel.y * frame.map_axis_v.xyz;
    return true;
}

// Pressed grass darkens (the shade of the trail), from its height cap over its rest
// length: 1 standing, 0.65 flat.
float press_shade(float cap_over_len) {
    return 1.0 - 0.35 * (1.0 - clamp(cap_over_len, 0.0, 1.0));
}
