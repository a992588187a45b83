// A Vulkan host's cascaded shadow map, as a host hands it to grass_shadow_receive_desc: a
// D32_SFLOAT 2D array image (one layer per cascade) filled from the CPU by a buffer-to-image
// copy of its depth aspect, then moved to the read-only layout the host names (made visible to
// fragment-shader reads), with a 2D array view of its depth aspect. Used by the Vulkan test
// host (Host::make_vk_shadow_map).
#pragma once

#include "vk_bootstrap.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace grass_host {

// What the map is made with: the host's device, its memory types, its queue and a command
// buffer and an unsignalled fence of its own that nothing else uses meanwhile.
struct VkShadowMapDevice {
    VkDevice device = VK_NULL_HANDLE;
    const VkPhysicalDeviceMemoryProperties* memory = nullptr;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
};

class VkShadowMap {
public:
    VkShadowMap() = default;
    ~VkShadowMap() { destroy(); }
    VkShadowMap(const VkShadowMap&) = delete;
    VkShadowMap& operator=(const VkShadowMap&) = delete;

    // `layers` layers of `size` x `size` depths, depths[(layer * size + row) * size + column]
    // in 0..1, left in `layout` when the copy has finished (the call waits for it). Replaces
    // the map made before. The view (a VkImageView as a 64-bit handle), or 0 with *error set.
    uint64_t make(const VkShadowMapDevice& device, uint32_t size, uint32_t layers, const float* depths,
                  VkImageLayout layout, std::string* error);
    // The device must be idle for the map (the host waits for its frames).
    void destroy();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    grass_bootstrap::VkImageParts image_; // its view is of layer 0 when there is one layer
    VkImageView array_view_ = VK_NULL_HANDLE;
};

} // namespace grass_host
