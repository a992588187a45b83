// The device memory of a context: every vkAllocateMemory and vkFreeMemory grass makes. Resources
// are suballocated from a few large blocks per memory type, so the number of allocations stays
// small whatever the number of patches, fields and maps (drivers limit it:
// maxMemoryAllocationCount is 4096 on some):
// - a full block is kBlockBytes (32 MiB), or an eighth of its heap where that is smaller; the
//   first block of a type is a quarter of that and the second half of it (each grown to fit
//   the resource that needs it), so a small scene takes little memory;
// - a resource larger than half a full block, or one the driver requires or prefers to have
//   on its own (VkMemoryDedicatedRequirements), gets a dedicated allocation;
// - host-visible blocks are mapped once, whole, when a mapped resource first needs them, and
//   stay mapped until freed;
// - a block whose last resource is freed is released, except one spare per memory type.
// Alignment and bufferImageGranularity are kept inside a block (vk_block_space.hpp). Every
// call passes the host's VkAllocationCallbacks (Functions::callbacks). One context is
// externally synchronized, so there is one MemoryBlocks per context and no lock.
#pragma once

#include "vk_block_space.hpp"
#include "vk_functions.hpp"

#include <cstdint>

namespace grass::vk {

// Where a resource's memory lives.
struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE; // the block's (or the dedicated allocation's)
    VkDeviceSize offset = 0;                // inside `memory`
    VkDeviceSize size = 0;                  // bytes asked for (VkMemoryRequirements::size)
    void* mapped = nullptr;                 // where `offset` is mapped; asked for mapped only
    uint32_t type = 0;                      // memory type index
    bool dedicated = false;
};

// What allocate() needs to know of the resource beyond its requirements.
struct AllocationRequest {
    VkMemoryRequirements requirements{};
    Tiling tiling = Tiling::linear; // buffers linear; optimally tiled images optimal
    bool mapped = false;            // the resource is read or written by the CPU
    // The driver requires or prefers a dedicated allocation (VkMemoryDedicatedRequirements)
    // for this buffer or image.
    bool dedicated = false;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkImage image = VK_NULL_HANDLE;
};

class MemoryBlocks {
public:
    static constexpr VkDeviceSize kBlockBytes = VkDeviceSize{32} << 20;
    static constexpr VkDeviceSize kSmallestFullBlock = VkDeviceSize{1} << 20;

    MemoryBlocks(const Functions& functions, VkDevice device, const VkPhysicalDeviceMemoryProperties& properties,
                 VkDeviceSize buffer_image_granularity, VkDeviceSize non_coherent_atom_size, HostAllocator* host);
    ~MemoryBlocks(); // frees every block; the resources in them must be destroyed already
    MemoryBlocks(const MemoryBlocks&) = delete;
    MemoryBlocks& operator=(const MemoryBlocks&) = delete;

    // Memory of type `type` for `request`: from a block with room, else from a new block (or a
    // dedicated allocation). On failure returns the VkResult of the failed vkAllocateMemory or
    // vkMapMemory (with `*call` naming it); the blocks are as they were, but for a new block
    // that could not be mapped (released again). May throw std::bad_alloc, changing nothing.
    VkResult allocate(uint32_t type, const AllocationRequest& request, Allocation* out, const char** call);
    void free(Allocation* allocation);

    // Per heap: device memory allocated (blocks and dedicated allocations) and bytes of it
    // that resources use.
    void heap_bytes(uint64_t allocated[VK_MAX_MEMORY_HEAPS], uint64_t in_use[VK_MAX_MEMORY_HEAPS]) const;
    uint32_t device_allocations() const { return device_allocations_; } // live vkAllocateMemory
    uint64_t bytes_in_use() const { return in_use_; }

    // A full block of `type`: kBlockBytes, or an eighth of the heap where that is smaller (but
    // kSmallestFullBlock at least). Resources over half of it get dedicated allocations.
    VkDeviceSize full_block_size(uint32_t type) const;
    // The next block of `type`: a quarter of a full block for the first, a half for the second,
    // then full; doubled (up to full) until `fits` bytes fit.
    VkDeviceSize next_block_size(uint32_t type, VkDeviceSize fits) const;

private:
    struct Block {
        VkDeviceMemory memory;
        uint32_t type;
        void* mapped; // the whole block, once a mapped resource asked for it
        BlockSpace space;
    };
    VkResult allocate_memory(uint32_t type, VkDeviceSize size, const AllocationRequest* dedicated_for,
                             VkDeviceMemory* out);
    void free_memory(VkDeviceMemory memory, uint32_t type, VkDeviceSize size);
    // Maps the block if it is not yet.
    VkResult map(Block* block);
    void release_block(size_t index);

    const Functions& fn_;
    VkDevice device_;
    VkPhysicalDeviceMemoryProperties properties_;
    VkDeviceSize granularity_;
    VkDeviceSize atom_;
    HostAllocator* host_;
    Vector<Block> blocks_;
    uint32_t blocks_made_[VK_MAX_MEMORY_TYPES] = {}; // blocks made per type, ever (their sizes grow)
    uint64_t heap_allocated_[VK_MAX_MEMORY_HEAPS] = {};
    uint64_t heap_in_use_[VK_MAX_MEMORY_HEAPS] = {};
    uint64_t in_use_ = 0;
    uint32_t device_allocations_ = 0;
};

} // namespace grass::vk
