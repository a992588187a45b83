// The staging layout the Vulkan backend's uploads share: what upload_slices writes into a
// slice set's staging buffer (vk_resources.cpp) and prepare_frame copies from it
// (vk_record.cpp), and the image usages of the uploaded images.
#pragma once

#include "vk_memory.hpp"

#include <cstdint>

namespace grass::vk {

constexpr VkImageUsageFlags kMapUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kSliceUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// Texel sizes of the slice images (colour and normal RGBA8, threshold and coverage curve RGBA16).
constexpr uint32_t kSliceColorBytes = 4, kSliceNormalBytes = 4, kSliceThresholdBytes = 8;

// The staging layout of one slice image: its levels of each layer, layer after layer, each
// starting on a multiple of 4 bytes (vkCmdCopyBufferToImage's bufferOffset rule). Returns
// the offset after the image's last texel; calls visit(layer, level, offset, w, h) per region.
template <typename Visit>
VkDeviceSize slice_staging_layout(const Image& image, uint32_t texel_bytes, VkDeviceSize offset, Visit&& visit) {
    for (uint32_t layer = 0; layer < image.layers; ++layer) {
        for (uint32_t level = 0; level < image.levels; ++level) {
            const uint32_t w = image.width >> level ? image.width >> level : 1;
            const uint32_t h = image.height >> level ? image.height >> level : 1;
            offset = (offset + 3) & ~VkDeviceSize(3);
            visit(layer, level, offset, w, h);
            offset += VkDeviceSize(w) * h * texel_bytes;
        }
    }
    return offset;
}

} // namespace grass::vk
