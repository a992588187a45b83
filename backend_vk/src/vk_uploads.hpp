// One batch of uploads recorded by grass_vk_prepare: staging-buffer copies into
// device-local vertex/index buffers, design map images and slice array images, with the
// barriers around them (image layouts UNDEFINED -> TRANSFER_DST -> SHADER_READ_ONLY, every
// level and layer; transfer writes made visible to vertex input and shader reads); and
// updates of a rectangle of a design map that earlier frames sample (SHADER_READ_ONLY ->
// TRANSFER_DST after those frames' shader reads, then back). Recorded outside any render
// pass. At most one copy per image in a batch.
#pragma once

#include "foundation/allocator.hpp"
#include "vk_functions.hpp"

namespace grass::vk {

// A barrier on every level and layer of a colour image (no queue family transfer).
VkImageMemoryBarrier image_barrier(VkImage image, uint32_t levels, uint32_t layers, VkImageLayout from,
                                   VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access);

class UploadBatch {
public:
    explicit UploadBatch(HostAllocator* host)
        : buffer_copies_(StlAllocator<BufferCopy>(host)), image_copies_(StlAllocator<ImageCopy>(host)),
          regions_(StlAllocator<VkBufferImageCopy>(host)), buffer_barriers_(StlAllocator<VkBufferMemoryBarrier>(host)),
          image_barriers_(StlAllocator<VkImageMemoryBarrier>(host)) {}

    // The adds may throw std::bad_alloc; nothing is recorded until record().
    // `dst_access`: how the draws read `dst` (VERTEX_ATTRIBUTE_READ, INDEX_READ, or
    // SHADER_READ for a storage buffer the vertex shader reads).
    void copy_buffer(VkBuffer src, VkDeviceSize src_offset, VkBuffer dst, VkDeviceSize size, VkAccessFlags dst_access);
    // A whole single-mip colour image, tightly packed in `src` from `src_offset`.
    void copy_image(VkBuffer src, VkDeviceSize src_offset, VkImage dst, uint32_t width, uint32_t height);
    // A rectangle of a single-mip colour image in SHADER_READ_ONLY_OPTIMAL layout that
    // earlier commands may sample (its other texels are kept), tightly packed in `src`.
    void update_image(VkBuffer src, VkImage dst, uint32_t x, uint32_t y, uint32_t width, uint32_t height);
    // A colour image of `levels` mips and `layers` layers, filled by `region_count` regions
    // (which together must cover every level of every layer).
    void copy_image_regions(VkBuffer src, VkImage dst, uint32_t levels, uint32_t layers,
                            const VkBufferImageCopy* regions, uint32_t region_count);

    bool empty() const { return buffer_copies_.empty() && image_copies_.empty(); }
    // Records the batch into `cmd` and empties it (capacity is kept for the next frame).
    void record(const Functions& fn, VkCommandBuffer cmd);
    void clear();

private:
    struct BufferCopy {
        VkBuffer src, dst;
        VkDeviceSize src_offset, size;
        VkAccessFlags dst_access;
    };
    struct ImageCopy {
        VkBuffer src;
        VkImage dst;
        uint32_t levels, layers;
        uint32_t first_region, region_count; // in regions_
        bool update;                         // the image holds texels that are kept (update_image)
    };
    Vector<BufferCopy> buffer_copies_;
    Vector<ImageCopy> image_copies_;
    Vector<VkBufferImageCopy> regions_;
    Vector<VkBufferMemoryBarrier> buffer_barriers_;
    Vector<VkImageMemoryBarrier> image_barriers_;
};

} // namespace grass::vk
