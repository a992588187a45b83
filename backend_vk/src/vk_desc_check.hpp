// Argument checks of grass_vk_create_context: what can be said about a grass_vk_desc
// without calling Vulkan. What the device supports is checked by load_device().
#pragma once

#include <grass/grass_vk.h>

struct grass_context;

namespace grass::vk {

// The most frames in flight a context keeps per-frame buffers for (grass_vk_desc).
constexpr uint32_t kMaxFramesInFlight = 8;

// Logs the first problem through `context` (named after `function`) and returns its code.
// Walks vk_desc->next: on success *host_objects is the chained grass_vk_host_objects_desc,
// copied, or its defaults where there is none (its next then NULL).
grass_result check_vk_desc(grass_context* context, const char* function, const grass_vk_desc* vk_desc,
                           grass_vk_host_objects_desc* host_objects);

} // namespace grass::vk
