#include "vk_memory_blocks.hpp"
#include "vk_labels.hpp"

#include <algorithm>

namespace grass::vk {

namespace {

uint64_t align_up(uint64_t value, uint64_t alignment) { return (value + alignment - 1) / alignment * alignment; }

} // namespace

MemoryBlocks::MemoryBlocks(const Functions& functions, VkDevice device,
                           const VkPhysicalDeviceMemoryProperties& properties, VkDeviceSize buffer_image_granularity,
                           VkDeviceSize non_coherent_atom_size, HostAllocator* host)
    : fn_(functions), device_(device), properties_(properties),
      granularity_(std::max<VkDeviceSize>(buffer_image_granularity, 1)),
      atom_(std::max<VkDeviceSize>(non_coherent_atom_size, 1)), host_(host), blocks_(StlAllocator<Block>(host)) {}

MemoryBlocks::~MemoryBlocks() {
    while (!blocks_.empty()) release_block(blocks_.size() - 1);
}

VkDeviceSize MemoryBlocks::full_block_size(uint32_t type) const {
    const VkDeviceSize heap = properties_.memoryHeaps[properties_.memoryTypes[type].heapIndex].size;
    VkDeviceSize full = kBlockBytes;
    while (full > kSmallestFullBlock && full > heap / 8) full /= 2; // small heaps: an eighth
    return full;
}

VkDeviceSize MemoryBlocks::next_block_size(uint32_t type, VkDeviceSize fits) const {
    const VkDeviceSize full = full_block_size(type);
    const uint32_t made = blocks_made_[type];
    VkDeviceSize size = made == 0 ? full / 4 : made == 1 ? full / 2 : full;
    while (size < fits && size < full) size *= 2;
    return size;
}

VkResult MemoryBlocks::allocate_memory(uint32_t type, VkDeviceSize size, const AllocationRequest* dedicated_for,
                                       VkDeviceMemory* out) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = size;
    info.memoryTypeIndex = type;
    VkMemoryDedicatedAllocateInfo dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO};
    if (dedicated_for && dedicated_for->dedicated) {
        dedicated.buffer = dedicated_for->buffer;
        dedicated.image = dedicated_for->image;
        info.pNext = &dedicated;
    }
    const VkResult r = fn_.vkAllocateMemory(device_, &info, fn_.callbacks(), out);
    if (r == VK_SUCCESS) {
        name_object(fn_, device_, VK_OBJECT_TYPE_DEVICE_MEMORY, *out,
                    dedicated_for && dedicated_for->dedicated ? "grass dedicated memory" : "grass memory block");
        heap_allocated_[properties_.memoryTypes[type].heapIndex] += size;
        device_allocations_ += 1;
    }
    return r;
}

void MemoryBlocks::free_memory(VkDeviceMemory memory, uint32_t type, VkDeviceSize size) {
    fn_.vkFreeMemory(device_, memory, fn_.callbacks()); // unmaps it too
    heap_allocated_[properties_.memoryTypes[type].heapIndex] -= size;
    device_allocations_ -= 1;
}

VkResult MemoryBlocks::map(Block* block) {
    if (block->mapped) return VK_SUCCESS;
    return fn_.vkMapMemory(device_, block->memory, 0, VK_WHOLE_SIZE, 0, &block->mapped);
}

void MemoryBlocks::release_block(size_t index) {
    const Block& b = blocks_[index];
    free_memory(b.memory, b.type, b.space.size());
    blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(index));
}

VkResult MemoryBlocks::allocate(uint32_t type, const AllocationRequest& request, Allocation* out, const char** call) {
    const VkMemoryRequirements& req = request.requirements;
    const VkMemoryPropertyFlags flags = properties_.memoryTypes[type].propertyFlags;
    const bool non_coherent =
        (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) && !(flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    // Flushed ranges are whole atoms: a non-coherent resource owns the atoms it touches.
    const VkDeviceSize alignment =
        non_coherent ? std::max(req.alignment, atom_) : std::max<VkDeviceSize>(req.alignment, 1);
    const VkDeviceSize size = non_coherent ? align_up(req.size, atom_) : req.size;
    const uint32_t heap = properties_.memoryTypes[type].heapIndex;
    Allocation a;
    a.size = req.size;
    a.type = type;

    if (request.dedicated || size > full_block_size(type) / 2) {
        *call = "vkAllocateMemory";
        VkResult r = allocate_memory(type, size, &request, &a.memory);
        if (r != VK_SUCCESS) return r;
        if (request.mapped) {
            r = fn_.vkMapMemory(device_, a.memory, 0, VK_WHOLE_SIZE, 0, &a.mapped);
            if (r != VK_SUCCESS) {
                *call = "vkMapMemory";
                free_memory(a.memory, type, size);
                return r;
            }
        }
        a.dedicated = true;
        heap_in_use_[heap] += req.size;
        in_use_ += req.size;
        *out = a;
        return VK_SUCCESS;
    }

    // An existing block of the type with room (mapping it where needed).
    for (Block& b : blocks_) {
        if (b.type != type) continue;
        uint64_t offset = 0;
        if (!b.space.allocate(size, alignment, request.tiling, &offset)) continue;
        if (request.mapped) {
            const VkResult r = map(&b);
            if (r != VK_SUCCESS) {
                b.space.free(offset);
                *call = "vkMapMemory";
                return r;
            }
            a.mapped = static_cast<char*>(b.mapped) + offset;
        }
        a.memory = b.memory;
        a.offset = offset;
        heap_in_use_[heap] += req.size;
        in_use_ += req.size;
        *out = a;
        return VK_SUCCESS;
    }

    // A new block. Its bookkeeping is made first, so a std::bad_alloc leaves no allocation.
    const VkDeviceSize block_size = next_block_size(type, size);
    blocks_.reserve(blocks_.size() + 1);
    BlockSpace space(block_size, granularity_, host_);
    uint64_t offset = 0;
    space.allocate(size, alignment, request.tiling, &offset); // fits: at offset 0, size <= block_size
    Block block{VK_NULL_HANDLE, type, nullptr, std::move(space)};
    *call = "vkAllocateMemory";
    VkResult r = allocate_memory(type, block_size, nullptr, &block.memory);
    if (r != VK_SUCCESS) return r;
    if (request.mapped) {
        r = map(&block);
        if (r != VK_SUCCESS) {
            *call = "vkMapMemory";
            free_memory(block.memory, type, block_size);
            return r;
        }
        a.mapped = static_cast<char*>(block.mapped) + offset;
    }
    blocks_made_[type] += 1;
    blocks_.push_back(std::move(block)); // reserved: does not throw
    a.memory = blocks_.back().memory;
    a.offset = offset;
    heap_in_use_[heap] += req.size;
    in_use_ += req.size;
    *out = a;
    return VK_SUCCESS;
}

void MemoryBlocks::free(Allocation* a) {
    if (a->memory == VK_NULL_HANDLE) return;
    const uint32_t heap = properties_.memoryTypes[a->type].heapIndex;
    heap_in_use_[heap] -= a->size;
    in_use_ -= a->size;
    if (a->dedicated) {
        const VkMemoryPropertyFlags flags = properties_.memoryTypes[a->type].propertyFlags;
        const bool non_coherent =
            (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) && !(flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        free_memory(a->memory, a->type, non_coherent ? align_up(a->size, atom_) : a->size);
        *a = Allocation{};
        return;
    }
    for (size_t i = 0; i < blocks_.size(); ++i) {
        Block& b = blocks_[i];
        if (b.memory != a->memory) continue;
        b.space.free(a->offset);
        if (b.space.empty()) {
            // Keep one empty block of the type as a spare; release any other.
            for (size_t j = 0; j < blocks_.size(); ++j) {
                if (j != i && blocks_[j].type == b.type && blocks_[j].space.empty()) {
                    release_block(i);
                    break;
                }
            }
        }
        break;
    }
    *a = Allocation{};
}

void MemoryBlocks::heap_bytes(uint64_t allocated[VK_MAX_MEMORY_HEAPS], uint64_t in_use[VK_MAX_MEMORY_HEAPS]) const {
    for (uint32_t h = 0; h < VK_MAX_MEMORY_HEAPS; ++h) {
        allocated[h] = heap_allocated_[h];
        in_use[h] = heap_in_use_[h];
    }
}

} // namespace grass::vk
