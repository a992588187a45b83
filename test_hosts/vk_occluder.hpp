// The Vulkan host's occluder (headless_host.hpp's Occluder): recorded inside its pass.
#pragma once

#include "headless_host.hpp"

#include <vulkan/vulkan.h>

namespace grass_host {

// Clears the occluder's rectangle of the pass's colour (attachment 0) and depth to its
// colour and the window depth of view-space z = -distance (target: its size, unorm_color).
void record_occluder(VkCommandBuffer cmd, const TargetDesc& target, const grass_view_desc& view,
                     const Occluder& occluder);

} // namespace grass_host
