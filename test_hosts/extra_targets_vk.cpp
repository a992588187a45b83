#include "extra_targets_vk.hpp"

#include <cstring>
#include <initializer_list>

namespace grass_host {

namespace {
// The bytes of a texel of `format` (the formats the tests use: 8-bit RGBA, 32-bit float RGBA).
uint32_t texel_bytes(VkFormat format) { return format == VK_FORMAT_R32G32B32A32_SFLOAT ? 16u : 4u; }
} // namespace

const void* VkExtraTargets::enable_features(const TargetDesc& target, const void* chain) {
    if (target.vk_velocity_attachment == 0 && target.vk_gbuffer_formats[0] == 0) return chain;
    features_.features.independentBlend = VK_TRUE;
    features_.pNext = const_cast<void*>(chain);
    return &features_;
}

bool VkExtraTargets::create(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const TargetDesc& target,
                            grass_bootstrap::VkPassDesc* pass, std::string* error) {
    target_ = target;
    gbuffer_ = target.vk_gbuffer_formats[0] != 0;
    msaa_ = target.samples > 1;
    if (target.vk_velocity_attachment == 0 && !gbuffer_) return true;
    const uint32_t most = gbuffer_ ? 3 : 2;
    if ((!gbuffer_ && target.vk_velocity_attachment < 1) || target.vk_velocity_attachment > most ||
        (!gbuffer_ && (msaa_ || target.vk_dynamic_rendering)) || target.ground || !target.meshes.empty()) {
        *error = "vk_velocity_attachment needs 1 or 2 and a single-sampled target drawn with a render pass (a "
                 "G-buffer target: any), without ground or meshes";
        return false;
    }
    count_ = target.vk_velocity_attachment;
    formats_[0] = count_ == 2 ? kOtherFormat : kVelocityFormat;
    formats_[1] = kVelocityFormat;
    if (gbuffer_) {
        count_ = 0;
        while (count_ < 3 && target.vk_gbuffer_formats[count_] != 0) {
            formats_[count_] = static_cast<VkFormat>(target.vk_gbuffer_formats[count_]);
            count_ += 1;
        }
    }
    for (uint32_t i = 0; i < count_; ++i) {
        grass_bootstrap::VkImageDesc desc;
        desc.extent = {target.width, target.height};
        desc.format = formats_[i];
        desc.samples = static_cast<VkSampleCountFlagBits>(target.samples);
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (msaa_ ? 0 : VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
        if (!grass_bootstrap::create_image(device, memory, desc, &images_[i], error)) return false;
        desc.samples = VK_SAMPLE_COUNT_1_BIT;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        if (msaa_ && !grass_bootstrap::create_image(device, memory, desc, &resolves_[i], error)) return false;
    }
    pass->more_colors = formats_;
    pass->more_color_count = count_;
    const VkDeviceSize size = VkDeviceSize(target.width) * target.height * 16 * 3;
    return grass_bootstrap::create_buffer(device, memory, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                          &readback_, error);
}

void VkExtraTargets::destroy(VkDevice device) {
    for (grass_bootstrap::VkImageParts& image : images_) grass_bootstrap::destroy_image(device, &image);
    for (grass_bootstrap::VkImageParts& image : resolves_) grass_bootstrap::destroy_image(device, &image);
    grass_bootstrap::destroy_buffer(device, &readback_);
    count_ = 0;
}

uint32_t VkExtraTargets::views(VkImageView* at) const {
    for (uint32_t i = 0; i < count_; ++i) {
        at[i] = images_[i].view;
        if (msaa_) at[count_ + i] = resolves_[i].view;
    }
    return msaa_ ? 2 * count_ : count_;
}

uint32_t VkExtraTargets::clear_values(VkClearValue* clears) const {
    const uint32_t first = msaa_ ? 3 : 2; // after colour, depth and (multisampled) the resolve image
    for (uint32_t i = 0; i < count_; ++i) {
        const float* c = gbuffer_          ? target_.gbuffer_clear[i]
                         : i + 1 == count_ ? target_.velocity_clear
                                           : target_.other_clear;
        std::memcpy(clears[first + i].color.float32, c, 4 * sizeof(float));
    }
    return first + count_;
}

void VkExtraTargets::barrier(VkCommandBuffer cmd, bool into_pass) const {
    VkImageMemoryBarrier barriers[6] = {};
    uint32_t n = 0;
    for (uint32_t i = 0; i < count_; ++i) {
        for (const VkImage image : {images_[i].image, resolves_[i].image}) {
            if (image == VK_NULL_HANDLE || (!into_pass && image != read_image(i))) continue;
            VkImageMemoryBarrier& b = barriers[n++];
            b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
            b.srcAccessMask = into_pass ? 0 : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
            b.dstAccessMask = into_pass ? VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT
                                        : VK_ACCESS_TRANSFER_READ_BIT;
            b.oldLayout = into_pass ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            b.newLayout = into_pass ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.image = image;
            b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        }
    }
    // Into the pass: after the last frame's read-back copy; out of it: before this frame's.
    const VkPipelineStageFlags src =
        into_pass ? VK_PIPELINE_STAGE_TRANSFER_BIT : VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkPipelineStageFlags dst =
        into_pass ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 0, nullptr, 0, nullptr, n, barriers);
}

void VkExtraTargets::begin_rendering(VkCommandBuffer cmd, VkRenderingAttachmentInfo* out) const {
    if (count_ == 0) return;
    barrier(cmd, true);
    VkClearValue clears[6] = {};
    const uint32_t first = clear_values(clears) - count_;
    for (uint32_t i = 0; i < count_; ++i) {
        VkRenderingAttachmentInfo& a = out[i];
        a = VkRenderingAttachmentInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = images_[i].view;
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = msaa_ ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue = clears[first + i];
        if (!msaa_) continue;
        a.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        a.resolveImageView = resolves_[i].view;
        a.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
}

void VkExtraTargets::end_rendering(VkCommandBuffer cmd) const {
    if (count_ != 0) barrier(cmd, false);
}

const void* VkExtraTargets::chain(const void* next) {
    if (count_ == 0) return next;
    if (gbuffer_) {
        gbuffer_desc_.color_attachment_count = 1 + count_;
        for (uint32_t i = 0; i < count_; ++i) gbuffer_desc_.color_formats[1 + i] = formats_[i];
        gbuffer_desc_.next = next;
        if (target_.vk_velocity_attachment == 0) return &gbuffer_desc_;
        desc_.color_attachment_count = 1 + count_;
        desc_.velocity_attachment = target_.vk_velocity_attachment;
        for (uint32_t i = 0; i < count_; ++i) desc_.color_formats[i] = formats_[i];
        desc_.next = &gbuffer_desc_;
        return &desc_;
    }
    desc_.color_attachment_count = 1 + count_;
    desc_.velocity_attachment = count_;
    for (uint32_t i = 0; i < count_; ++i) desc_.color_formats[i] = formats_[i];
    desc_.next = next;
    return &desc_;
}

void VkExtraTargets::copy(VkCommandBuffer cmd) const {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target_.width, target_.height, 1};
    for (uint32_t i = 0; gbuffer_ && i < count_; ++i) { // each at a stride of 16 bytes a texel
        region.bufferOffset = VkDeviceSize(target_.width) * target_.height * 16 * i;
        vkCmdCopyImageToBuffer(cmd, read_image(i), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    }
    if (gbuffer_) {
        const VkBufferMemoryBarrier b = grass_bootstrap::host_read_barrier(readback_.buffer);
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                             nullptr);
        return;
    }
    vkCmdCopyImageToBuffer(cmd, images_[count_ - 1].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1,
                           &region);
    if (count_ == 2) {
        region.bufferOffset = VkDeviceSize(target_.width) * target_.height * 16;
        vkCmdCopyImageToBuffer(cmd, images_[0].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1,
                               &region);
    }
    const VkBufferMemoryBarrier b = grass_bootstrap::host_read_barrier(readback_.buffer);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                         nullptr);
}

void VkExtraTargets::read(VkDevice, Image* out) const {
    const size_t n = size_t(target_.width) * target_.height;
    if (gbuffer_) {
        const auto* bytes = static_cast<const uint8_t*>(readback_.mapped);
        out->gbuffer.assign(count_, {});
        for (uint32_t i = 0; i < count_; ++i) {
            const uint8_t* at = bytes + n * 16 * i;
            out->gbuffer[i].assign(at, at + n * texel_bytes(formats_[i]));
        }
        out->velocity.clear();
        if (target_.vk_velocity_attachment != 0) {
            out->velocity.resize(n * 4);
            std::memcpy(out->velocity.data(), bytes + n * 16 * (target_.vk_velocity_attachment - 1), n * 16);
        }
        return;
    }
    out->velocity.resize(n * 4);
    std::memcpy(out->velocity.data(), readback_.mapped, n * 16);
    out->other.clear();
    if (count_ == 2) {
        out->other.resize(n * 4);
        std::memcpy(out->other.data(), static_cast<const uint8_t*>(readback_.mapped) + n * 16, n * 4);
    }
}

} // namespace grass_host
