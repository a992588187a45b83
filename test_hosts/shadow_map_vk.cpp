#include "shadow_map_vk.hpp"

#include <cstring>

namespace grass_host {

using grass_bootstrap::vk_error;

uint64_t VkShadowMap::make(const VkShadowMapDevice& d, uint32_t size, uint32_t layers, const float* depths,
                           VkImageLayout layout, std::string* error) {
    destroy();
    device_ = d.device;
    grass_bootstrap::VkImageDesc desc;
    desc.extent = {size, size};
    desc.format = VK_FORMAT_D32_SFLOAT;
    // A host renders its map (the attachment usage, which the depth read-only layouts need too);
    // this one is filled by a copy.
    desc.usage =
        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    desc.layers = layers;
    if (!grass_bootstrap::create_image(d.device, *d.memory, desc, &image_, error)) return 0;
    // sampler2DArrayShadow samples a 2D array view, even of one layer.
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    view.format = VK_FORMAT_D32_SFLOAT;
    view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
    VkResult r = vkCreateImageView(d.device, &view, nullptr, &array_view_);
    if (r != VK_SUCCESS) {
        *error = vk_error("vkCreateImageView", r);
        return 0;
    }

    const VkDeviceSize bytes = VkDeviceSize(size) * size * layers * sizeof(float);
    grass_bootstrap::VkBufferParts staging;
    if (!grass_bootstrap::create_buffer(d.device, *d.memory, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                        &staging, error)) {
        return 0;
    }
    std::memcpy(staging.mapped, depths, bytes);

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    r = vkResetCommandBuffer(d.cmd, 0);
    if (r == VK_SUCCESS) r = vkBeginCommandBuffer(d.cmd, &begin);
    if (r == VK_SUCCESS) {
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image_.image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        vkCmdPipelineBarrier(d.cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &barrier);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, layers};
        copy.imageExtent = {size, size, 1};
        vkCmdCopyBufferToImage(d.cmd, staging.buffer, image_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        // What a host owes grass: the map written, in the layout it names, visible to the
        // fragment shaders of the pass grass records in.
        barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        barrier.newLayout = layout;
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        vkCmdPipelineBarrier(d.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &barrier);
        r = vkEndCommandBuffer(d.cmd);
    }
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &d.cmd;
    if (r == VK_SUCCESS) r = vkQueueSubmit(d.queue, 1, &submit, d.fence);
    if (r == VK_SUCCESS) r = vkWaitForFences(d.device, 1, &d.fence, VK_TRUE, UINT64_MAX);
    if (r == VK_SUCCESS) r = vkResetFences(d.device, 1, &d.fence);
    grass_bootstrap::destroy_buffer(d.device, &staging);
    if (r != VK_SUCCESS) {
        *error = vk_error("the shadow map's upload", r);
        return 0;
    }
    return reinterpret_cast<uint64_t>(array_view_); // 64-bit handles
}

void VkShadowMap::destroy() {
    if (!device_) return;
    if (array_view_) vkDestroyImageView(device_, array_view_, nullptr);
    array_view_ = VK_NULL_HANDLE;
    grass_bootstrap::destroy_image(device_, &image_);
    device_ = VK_NULL_HANDLE;
}

} // namespace grass_host
