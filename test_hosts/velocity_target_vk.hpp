// A Vulkan host's velocity target (TargetDesc::vk_velocity_attachment), for motion vectors
// (grass_view_motion_desc): the colour attachments its pass has besides the lit colour, an
// RGBA32F velocity image at colour attachment `vk_velocity_attachment` (1 or 2) and, with 2,
// an RGBA8 image at colour attachment 1 that grass must leave as cleared (a G-buffer
// target). Single-sampled render passes only (the pass: grass_bootstrap::VkPassDesc's
// more_colors). The host chains grass_vk_velocity_target_desc from chain() and reads both
// images back after the pass (Image::velocity, Image::other). A G-buffer target
// (TargetDesc::vk_gbuffer_formats) is the same pass with up to three attachments of the
// given formats, chained as a grass_vk_gbuffer_target_desc (and a velocity target where
// vk_velocity_attachment names one of them), read back into Image::gbuffer.
#pragma once

#include "headless_host.hpp"
#include "vk_bootstrap.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace grass_host {

class VkVelocityTarget {
public:
    static constexpr VkFormat kVelocityFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr VkFormat kOtherFormat = VK_FORMAT_R8G8B8A8_UNORM;

    // The device features a host with `target` enables besides `chain` (a VkDeviceCreateInfo
    // pNext chain): independentBlend for a velocity target (grass's motion pipelines write
    // its attachments with different masks). Returns the chain to pass.
    const void* enable_features(const TargetDesc& target, const void* chain);

    // The images and their read-back buffer for `target` (its vk_velocity_attachment 1 or 2;
    // 0: nothing, true), and the render pass's further colour attachments in *pass.
    bool create(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const TargetDesc& target,
                grass_bootstrap::VkPassDesc* pass, std::string* error);
    void destroy(VkDevice device);

    // The colour attachments after the lit colour, in order: formats, views, clear values.
    uint32_t count() const { return count_; }
    const VkFormat* formats() const { return formats_; }
    const VkImageView* views() const { return views_; }
    void clear_values(VkClearValue* out) const;
    // grass_vk_desc.next `next` with what grass is told of the pass (a
    // grass_vk_velocity_target_desc) in front, or `next` without a velocity target.
    const void* chain(const void* next);
    // After the pass (the images in TRANSFER_SRC_OPTIMAL): copies them into the read-back buffer.
    void copy(VkCommandBuffer cmd) const;
    // After the submission has finished: the images' texels, top row first.
    void read(VkDevice device, Image* out) const;

private:
    TargetDesc target_;
    VkPhysicalDeviceFeatures2 features_{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    grass_vk_velocity_target_desc desc_ = grass_default_vk_velocity_target_desc();
    grass_vk_gbuffer_target_desc gbuffer_desc_ = grass_default_vk_gbuffer_target_desc();
    bool gbuffer_ = false; // TargetDesc::vk_gbuffer_formats
    uint32_t count_ = 0;
    VkFormat formats_[3] = {};
    VkImageView views_[3] = {};
    grass_bootstrap::VkImageParts images_[3]; // velocity target: [count_ - 1] the velocity
    grass_bootstrap::VkBufferParts readback_; // host-visible, coherent: velocity, then the other image
};

} // namespace grass_host
