// Motion vectors (grass_view_motion_desc): the velocity a tier writes, in viewport units
// (NDC x 0.5, x right, y up), of its point's position in this frame minus its position in
// the previous one, both without jitter. Included only where GRASS_VELOCITY is defined (the
// GRASS_MOTION variants: GL defines it with GRASS_FEATURES), so every other variant declares
// neither the block nor the output and its preprocessed text is what it was. The grass's
// own motion comes from its pose at the previous time: wind_at() reads the previous gust
// phases while g_previous_time is set.
#if defined(VULKAN) && defined(GRASS_MULTIVIEW)
#error "a stereo (multiview) context does not write motion vectors (grass_vk_velocity_target_desc is mono only)"
#endif

// The GrassMotion block (api/src/foundation/frame_plan.hpp MotionUniforms): GL binding 3;
// Vulkan set 1, binding 0 (the view extras' blocks, which the layout of receiving and motion
// pipelines alone has, beside host_shadows.glsl's block at binding 1:
// backend_vk/src/vk_view_extras.hpp).
#ifdef VULKAN
layout(std140, set = 1, binding = 0) uniform GrassMotion {
#else
layout(std140, binding = 3) uniform GrassMotion {
#endif
    mat4 view_projection;          // camera-relative world -> clip, without jitter
    mat4 previous_view_projection; // camera-relative world -> the previous frame's clip, without jitter
    vec4 previous_wind_phase;      // the gust phases (Frame's wind_phase) at the previous time
    vec4 times;                    // x: this frame's time minus the previous time (s)
} grass_motion;

// Fragment shaders (they define GRASS_MOTION_FRAGMENT first): the velocity goes to output
// location 1; the backend routes it to the host's draw buffer
// (grass_view_motion_desc.velocity_attachment) and masks its .ba off. Vulkan: the backend
// rewrites the location to the velocity attachment's index in the module it makes the
// pipeline of (vk_view_extras.cpp); the velocity is Vulkan's clip y, down.
#ifdef GRASS_MOTION_FRAGMENT
layout(location = 1) out vec4 out_velocity;
void write_velocity(vec2 velocity) {
    out_velocity = vec4(velocity, 0.0, 0.0);
}
#endif

// The responsive grass's pose at the previous frame's time while set (wind.glsl).
bool g_previous_time = false;

// The clip positions of camera-relative `now` (this frame) and `before` (the same grass in
// the previous frame, in this frame's camera-relative coordinates).
vec4 clip_now(vec3 now) { return grass_motion.view_projection * vec4(now, 1.0); }
vec4 clip_before(vec3 before) { return grass_motion.previous_view_projection * vec4(before, 1.0); }

// The velocity of two clip positions, in viewport units.
vec2 clip_velocity(vec4 now, vec4 before) {
    return 0.5 * (now.xy / now.w - before.xy / before.w);
}
