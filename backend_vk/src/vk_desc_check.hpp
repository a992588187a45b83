// Argument checks of grass_vk_create_context: what can be said about a grass_vk_desc
// without calling Vulkan. What the device supports is checked by load_device().
#pragma once

#include <grass/grass_vk.h>

struct grass_context;

namespace grass::vk {

// The most frames in flight a context keeps per-frame buffers for (grass_vk_desc).
constexpr uint32_t kMaxFramesInFlight = 8;
// A view slot: the per-frame buffers and descriptor sets of one view (grass.h, "Frames and
// views") of one frame slot. View 0's slots are 0 .. frames_in_flight - 1.
constexpr uint32_t kMaxViewSlots = kMaxFramesInFlight * GRASS_MAX_VIEWS_PER_FRAME;
inline uint32_t view_slot(uint32_t frame_slot, uint32_t view) { return view * kMaxFramesInFlight + frame_slot; }

// The extensions chained to grass_vk_desc.next, copied (their next NULL), or their defaults
// where the chain has none.
struct VkDescExtensions {
    grass_vk_host_objects_desc host_objects = grass_default_vk_host_objects_desc();
    grass_vk_multiview_desc multiview = grass_default_vk_multiview_desc();
    bool has_depth_pass = false; // a grass_vk_depth_pass_desc is chained: the context draws depth views
    grass_vk_depth_pass_desc depth_pass = grass_default_vk_depth_pass_desc();
    bool has_velocity = false; // a grass_vk_velocity_target_desc is chained: the context draws motion views
    grass_vk_velocity_target_desc velocity = grass_default_vk_velocity_target_desc();
    bool has_gbuffer = false; // a grass_vk_gbuffer_target_desc is chained: the context draws G-buffer views
    grass_vk_gbuffer_target_desc gbuffer = grass_default_vk_gbuffer_target_desc();
};

// Logs the first problem through `context` (named after `function`) and returns its code.
// Walks vk_desc->next: on success *extensions holds what it chains.
grass_result check_vk_desc(grass_context* context, const char* function, const grass_vk_desc* vk_desc,
                           VkDescExtensions* extensions);

} // namespace grass::vk
