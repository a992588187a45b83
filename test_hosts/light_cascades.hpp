// The host's cascaded sun shadows, the part both backends share (TargetDesc::host_shadows):
// the cascades' orthographic light views fitted around slices of the main camera's frustum,
// grass's depth views and receive desc for them, and the uniform block the host's own
// shaders (shaders/cascade_shadows.glsl) read the map through.
#pragma once

#include "headless_host.hpp"

namespace grass_host {

// std140 block `HostShadowBlock` (shaders/cascade_shadows.glsl).
struct HostShadowUniforms {
    float relative_to_shadow[GRASS_MAX_SHADOW_CASCADES][16]; // camera-relative position -> (u, v, depth)
    float cascade_end[4];                                    // metres along the view axis
    float forward[4];                                        // xyz: the camera's view axis (unit); w: bias
    float params[4];                                         // x: cascades, y: 1 / map size, z: filter radius (texels)
};
static_assert(sizeof(HostShadowUniforms) == 4 * 64 + 48, "std140 HostShadowBlock");

// One frame's cascades, fitted to the main view.
struct LightCascades {
    uint32_t count = 0;
    grass_view_desc light_view[GRASS_MAX_SHADOW_CASCADES]{}; // the sun's orthographic views (next: none)
    float world_to_shadow[GRASS_MAX_SHADOW_CASCADES][16]{};  // world -> (u, v, depth), column-major
    HostShadowUniforms uniforms{};                           // the host's shaders' view of the same
};

// Fits `shadows.cascades` light views around the slices [splits[i-1], splits[i]] (the first
// from the view's near plane) of `main`'s frustum, each a square of map_size texels snapped to
// whole texels, its near plane `caster_reach` beyond the slice's bounding sphere towards the
// sun. vulkan: clip z 0..1 and y down (else GL's -1..1, y up). Viewports: the whole layer.
LightCascades fit_light_cascades(const grass_view_desc& main, const HostShadows& shadows, bool vulkan);

// Grass's views of one shadowed frame: the main view receiving the map (when `receive`) and
// each cascade's depth view at the main camera's lod. Keeps the chains it builds.
struct ShadowFrameViews {
    grass_view_desc main{};
    grass_view_desc cascade[GRASS_MAX_SHADOW_CASCADES]{};
    grass_shadow_receive_desc receive{};
    grass_view_pass_desc pass[GRASS_MAX_SHADOW_CASCADES]{};
    grass_lod_origin_desc lod_origin[GRASS_MAX_SHADOW_CASCADES]{};
    ShadowFrameViews() = default;
    ShadowFrameViews(const ShadowFrameViews&) = delete; // the chains point into it
    ShadowFrameViews& operator=(const ShadowFrameViews&) = delete;
};
void make_shadow_frame_views(const grass_view_desc& main, const LightCascades& cascades, const HostShadows& shadows,
                             uint64_t shadow_map, uint32_t vk_image_layout, bool receive, ShadowFrameViews* out);

// Begins grass's frame of `views`: grass_begin_frame(main) (view 0), then, when
// `grass_casts`, grass_plan_view of each cascade (cascade i is view 1 + i).
grass_result plan_shadow_frame(grass_context* context, const ShadowFrameViews& views, uint32_t cascades,
                               bool grass_casts);

// Checks TargetDesc::host_shadows: false and *error naming the field and its value.
bool check_host_shadows(const TargetDesc& target, std::string* error);

} // namespace grass_host
