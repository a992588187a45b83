#include "vk_uploads.hpp"

namespace grass::vk {

VkImageMemoryBarrier image_barrier(VkImage image, uint32_t levels, uint32_t layers, VkImageLayout from,
                                   VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = src_access;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers};
    return b;
}

void UploadBatch::copy_buffer(VkBuffer src, VkDeviceSize src_offset, VkBuffer dst, VkDeviceSize size,
                              VkAccessFlags dst_access) {
    buffer_copies_.push_back(BufferCopy{src, dst, src_offset, size, dst_access});
    buffer_barriers_.reserve(buffer_copies_.size());
}

void UploadBatch::copy_image(VkBuffer src, VkDeviceSize src_offset, VkImage dst, uint32_t width, uint32_t height) {
    VkBufferImageCopy region{};
    region.bufferOffset = src_offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    copy_image_regions(src, dst, 1, 1, &region, 1);
}

void UploadBatch::update_image(VkBuffer src, VkImage dst, uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageOffset = {static_cast<int32_t>(x), static_cast<int32_t>(y), 0};
    region.imageExtent = {width, height, 1};
    const uint32_t first = static_cast<uint32_t>(regions_.size());
    regions_.push_back(region);
    image_copies_.push_back(ImageCopy{src, dst, 1, 1, first, 1, true});
    image_barriers_.reserve(image_copies_.size());
}

void UploadBatch::copy_image_regions(VkBuffer src, VkImage dst, uint32_t levels, uint32_t layers,
                                     const VkBufferImageCopy* regions, uint32_t region_count) {
    const uint32_t first = static_cast<uint32_t>(regions_.size());
    regions_.insert(regions_.end(), regions, regions + region_count);
    image_copies_.push_back(ImageCopy{src, dst, levels, layers, first, region_count, false});
    image_barriers_.reserve(image_copies_.size());
}

void UploadBatch::clear() {
    buffer_copies_.clear();
    image_copies_.clear();
    regions_.clear();
}

void UploadBatch::record(const Functions& fn, VkCommandBuffer cmd) {
    // The barrier vectors were reserved by the adds: no allocation below.
    // New images: their contents are discarded (UNDEFINED). Updated images: the copy waits
    // for the shader reads of earlier frames (a write-after-read hazard: an execution
    // dependency, no access to make available), and their texels are kept.
    image_barriers_.clear();
    VkPipelineStageFlags src_stages = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    for (const ImageCopy& c : image_copies_) {
        const VkImageLayout from = c.update ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
        if (c.update) src_stages = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
        image_barriers_.push_back(image_barrier(c.dst, c.levels, c.layers, from, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                                0, VK_ACCESS_TRANSFER_WRITE_BIT));
    }
    if (!image_barriers_.empty()) {
        fn.vkCmdPipelineBarrier(cmd, src_stages, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                                static_cast<uint32_t>(image_barriers_.size()), image_barriers_.data());
    }

    for (const BufferCopy& c : buffer_copies_) {
        const VkBufferCopy region{c.src_offset, 0, c.size};
        fn.vkCmdCopyBuffer(cmd, c.src, c.dst, 1, &region);
    }
    for (const ImageCopy& c : image_copies_) {
        fn.vkCmdCopyBufferToImage(cmd, c.src, c.dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, c.region_count,
                                  regions_.data() + c.first_region);
    }

    // Transfer writes -> vertex input (patch buffers), vertex shader reads (blade curves,
    // a storage buffer) and shader reads (design maps are sampled in both stages, slices
    // in the fragment shader).
    buffer_barriers_.clear();
    for (const BufferCopy& c : buffer_copies_) {
        VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.dstAccessMask = c.dst_access;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.buffer = c.dst;
        b.offset = 0;
        b.size = VK_WHOLE_SIZE;
        buffer_barriers_.push_back(b);
    }
    image_barriers_.clear();
    for (const ImageCopy& c : image_copies_) {
        image_barriers_.push_back(image_barrier(c.dst, c.levels, c.layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                                                VK_ACCESS_SHADER_READ_BIT));
    }
    if (!buffer_barriers_.empty() || !image_barriers_.empty()) {
        VkPipelineStageFlags dst_stages = 0;
        for (const BufferCopy& c : buffer_copies_) {
            if (c.dst_access & (VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT)) {
                dst_stages |= VK_PIPELINE_STAGE_VERTEX_INPUT_BIT;
            }
            if (c.dst_access & VK_ACCESS_SHADER_READ_BIT) dst_stages |= VK_PIPELINE_STAGE_VERTEX_SHADER_BIT;
        }
        if (!image_barriers_.empty()) {
            dst_stages |= VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
        }
        fn.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, dst_stages, 0, 0, nullptr,
                                static_cast<uint32_t>(buffer_barriers_.size()), buffer_barriers_.data(),
                                static_cast<uint32_t>(image_barriers_.size()), image_barriers_.data());
    }
    clear();
}

} // namespace grass::vk
