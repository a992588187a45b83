// GPU resources of the backend: buffers, 2D images and 2D array images, each on the memory
// type that suits its use, suballocated from that type's blocks (vk_memory_blocks.hpp).
// Counts the bytes they hold.
#pragma once

#include "vk_functions.hpp"
#include "vk_memory_blocks.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

// How the CPU and the GPU use a resource; it picks the memory type.
enum class MemoryUse {
    device_local, // written by transfers only, read by the GPU every frame
    staging,      // written once by the CPU, read once by a transfer
    streaming     // written by the CPU every frame, read by the GPU: persistently mapped
};

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    Allocation memory;
    VkDeviceSize size = 0;      // bytes asked for
    VkDeviceSize allocated = 0; // bytes of device memory it takes (its memory requirements)
    void* mapped = nullptr;     // staging and streaming buffers: mapped for their lifetime
    bool coherent = true;       // false: writes must be flushed (Memory::flush)
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    Allocation memory;
    VkDeviceSize allocated = 0;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t layers = 1;
    uint32_t levels = 1;
};

class Memory {
public:
    Memory(const Functions& functions, VkDevice device, const VkPhysicalDeviceMemoryProperties& properties,
           const VkPhysicalDeviceLimits& limits, HostAllocator* host)
        : fn_(functions), device_(device), properties_(properties), atom_(limits.nonCoherentAtomSize),
          blocks_(functions, device, properties, limits.bufferImageGranularity, limits.nonCoherentAtomSize, host) {}
    Memory(const Memory&) = delete;
    Memory& operator=(const Memory&) = delete;

    // On failure *out stays empty and *failure names the call.
    bool create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, Buffer* out, VkFailure* failure);
    void destroy_buffer(Buffer* buffer);

    // A device-local, optimally tiled, single-mip 2D image with a colour view.
    bool create_image(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage, Image* out,
                      VkFailure* failure);
    // A device-local, optimally tiled 2D array image of `layers` layers and `levels` mip
    // levels, with a 2D array colour view of all of them.
    bool create_array_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkFormat format,
                            VkImageUsageFlags usage, Image* out, VkFailure* failure);
    void destroy_image(Image* image);

    // Makes CPU writes to [offset, offset + size) of a mapped buffer visible to the device
    // (nothing to do on coherent memory).
    bool flush(const Buffer& buffer, VkDeviceSize offset, VkDeviceSize size, VkFailure* failure);

    uint64_t bytes() const { return blocks_.bytes_in_use(); }
    const MemoryBlocks& blocks() const { return blocks_; }

private:
    bool make_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkImageViewType view_type,
                    VkFormat format, VkImageUsageFlags usage, Image* out, VkFailure* failure);
    // Allocates `request` on the best memory type for `use`, falling back to the next
    // suitable type when a heap is full.
    bool allocate(const AllocationRequest& request, MemoryUse use, Allocation* out, VkMemoryPropertyFlags* out_flags,
                  VkFailure* failure);

    const Functions& fn_;
    VkDevice device_;
    VkPhysicalDeviceMemoryProperties properties_;
    VkDeviceSize atom_;
    MemoryBlocks blocks_;
};

} // namespace grass::vk
