// A Vulkan host's extra colour targets: the colour attachments its pass has besides the lit
// colour. A velocity target (TargetDesc::vk_velocity_attachment), for motion vectors
// (grass_view_motion_desc): an RGBA32F velocity image at colour attachment
// `vk_velocity_attachment` (1 or 2) and, with 2, an RGBA8 image at colour attachment 1 that
// grass must leave as cleared; single-sampled render passes only. The host chains
// grass_vk_velocity_target_desc from chain() and reads both images back after the pass
// (Image::velocity, Image::other). A G-buffer target (TargetDesc::vk_gbuffer_formats): up to
// three attachments of the given formats, chained as a grass_vk_gbuffer_target_desc (and a
// velocity target where vk_velocity_attachment names one of them), read back into
// Image::gbuffer; single- or multisampled (each then with its single-sample resolve image,
// read back), in a render pass (grass_bootstrap::VkPassDesc's more_colors) or with dynamic
// rendering (begin_rendering, end_rendering).
#pragma once

#include "headless_host.hpp"
#include "vk_bootstrap.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace grass_host {

class VkExtraTargets {
public:
    static constexpr VkFormat kVelocityFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr VkFormat kOtherFormat = VK_FORMAT_R8G8B8A8_UNORM;

    // The device features a host with `target` enables besides `chain` (a VkDeviceCreateInfo
    // pNext chain): independentBlend for a velocity target (grass's motion pipelines write
    // its attachments with different masks). Returns the chain to pass.
    const void* enable_features(const TargetDesc& target, const void* chain);

    // The images and their read-back buffer for `target` (its vk_velocity_attachment 1 or 2,
    // or its vk_gbuffer_formats; neither: nothing, true), and the render pass's further colour
    // attachments in *pass.
    bool create(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const TargetDesc& target,
                grass_bootstrap::VkPassDesc* pass, std::string* error);
    void destroy(VkDevice device);

    // The colour attachments after the lit colour.
    uint32_t count() const { return count_; }
    // The framebuffer's views after the host's own (`at`: colour, depth and, multisampled, its
    // resolve): the attachments, then (multisampled) their resolve images. Returns how many.
    uint32_t views(VkImageView* at) const;
    // The render pass's clear values, `clears` indexed by attachment: the host's colour and
    // depth at 0 and 1 stay as they are, the extras' from after the host's own. Returns the count.
    uint32_t clear_values(VkClearValue* clears) const;
    // Dynamic rendering: records the extras' transitions into COLOR_ATTACHMENT_OPTIMAL and
    // fills out[0..count) (cleared, stored or resolved); after vkCmdEndRendering,
    // end_rendering moves the images read back into TRANSFER_SRC_OPTIMAL.
    void begin_rendering(VkCommandBuffer cmd, VkRenderingAttachmentInfo* out) const;
    void end_rendering(VkCommandBuffer cmd) const;
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
    bool msaa_ = false;    // target.samples > 1: images_ multisampled, resolves_ read back
    uint32_t count_ = 0;
    VkFormat formats_[3] = {};
    grass_bootstrap::VkImageParts images_[3];   // velocity target: [count_ - 1] the velocity
    grass_bootstrap::VkImageParts resolves_[3]; // msaa_ only
    // The image read back of attachment i.
    VkImage read_image(uint32_t i) const { return msaa_ ? resolves_[i].image : images_[i].image; }
    // Dynamic rendering's transitions: `into_pass` every image from UNDEFINED into
    // COLOR_ATTACHMENT_OPTIMAL, else the images read back from there into TRANSFER_SRC_OPTIMAL.
    void barrier(VkCommandBuffer cmd, bool into_pass) const;
    grass_bootstrap::VkBufferParts readback_; // host-visible, coherent: velocity, then the other image
};

} // namespace grass_host
