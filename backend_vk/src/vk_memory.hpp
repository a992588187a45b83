// GPU memory of the backend: buffers, 2D images and 2D array images, each with its own vkAllocateMemory
// (grass holds a handful of resources per patch and field, far below any allocation
// limit), on the memory type that suits its use. Counts the bytes it holds.
#pragma once

#include "vk_functions.hpp"
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
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;      // bytes asked for
    VkDeviceSize allocated = 0; // bytes of device memory held
    void* mapped = nullptr;     // staging and streaming buffers: mapped for their lifetime
    bool coherent = true;       // false: writes must be flushed (Memory::flush)
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize allocated = 0;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t layers = 1;
    uint32_t levels = 1;
};

class Memory {
public:
    Memory(const Functions& functions, VkDevice device, const VkPhysicalDeviceMemoryProperties& properties,
           VkDeviceSize non_coherent_atom_size)
        : fn_(functions), device_(device), properties_(properties), atom_(non_coherent_atom_size) {}
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

    uint64_t bytes() const { return bytes_; }

private:
    bool make_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkImageViewType view_type,
                    VkFormat format, VkImageUsageFlags usage, Image* out, VkFailure* failure);
    // Allocates `requirements` on the best memory type for `use`, falling back to the
    // next suitable type when a heap is full.
    bool allocate(const VkMemoryRequirements& requirements, MemoryUse use, VkDeviceMemory* out,
                  VkMemoryPropertyFlags* out_flags, VkFailure* failure);

    const Functions& fn_;
    VkDevice device_;
    VkPhysicalDeviceMemoryProperties properties_;
    VkDeviceSize atom_;
    uint64_t bytes_ = 0;
};

} // namespace grass::vk
