// Descriptor sets of the backend, from pools it owns. Every set has the blade layout, so
// a pool's room is counted in sets. DescriptorAllocator: long-lived sets (one per field and
// frame in flight); a set comes from the first pool with room, a new pool is added when all
// are full, and sets are freed one by one (FREE_DESCRIPTOR_SET). FrameDescriptors: sets
// written for one frame only (the volume and image draws, which pair a field's design maps
// with a patch's slices), from per-frame pools reset when their frame slot comes round.
#pragma once

#include "foundation/allocator.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_result.hpp"

namespace grass::vk {

// What one set of the blade layout holds: the Frame and Field blocks (dynamic uniform
// buffers), eleven combined image samplers (the five design maps; slice colour, normal,
// threshold; the interaction map's two levels; the wind map) and three storage buffers
// (blade curves; the blade window's table and poses). The blade window pass's own set
// (vk_blade_window.hpp: two storage buffers) fits in the same room and comes from the same
// per-frame pools.
constexpr uint32_t kUniformBuffersPerSet = 2;
constexpr uint32_t kImageSamplersPerSet = 11;
constexpr uint32_t kStorageBuffersPerSet = 3;

// A set and the pool it came from (needed to free it).
struct DescriptorSet {
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
};

class DescriptorAllocator {
public:
    DescriptorAllocator(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), pools_(StlAllocator<Pool>(host)) {}
    ~DescriptorAllocator();
    DescriptorAllocator(const DescriptorAllocator&) = delete;
    DescriptorAllocator& operator=(const DescriptorAllocator&) = delete;

    // A set of `layout`, which must be the blade layout (kUniformBuffersPerSet dynamic
    // uniform buffers, kImageSamplersPerSet combined image samplers, kStorageBuffersPerSet
    // storage buffers): pools are sized for it.
    bool allocate(VkDescriptorSetLayout layout, DescriptorSet* out, VkFailure* failure);
    // The set must not be in use by a pending command buffer. Empty sets are ignored.
    void free(DescriptorSet* set);

private:
    struct Pool {
        VkDescriptorPool pool;
        uint32_t live_sets;
    };
    bool add_pool(VkFailure* failure);

    const Functions& fn_;
    VkDevice device_;
    Vector<Pool> pools_;
};

class FrameDescriptors {
public:
    FrameDescriptors(const Functions& functions, VkDevice device, HostAllocator* host);
    ~FrameDescriptors();
    FrameDescriptors(const FrameDescriptors&) = delete;
    FrameDescriptors& operator=(const FrameDescriptors&) = delete;

    // View slot `slot` (vk_desc_check.hpp) begins: its earlier frame has finished, so every
    // set allocated for it can go (the pools are reset, not destroyed).
    void reset(uint32_t slot);
    // A set of the blade layout `layout` (or of a layout needing no more of any type, as the
    // blade window pass's set 1) that lives until slot `slot` is reset. May throw
    // std::bad_alloc (before any Vulkan object is made); a slot gets its pools on first use.
    bool allocate(uint32_t slot, VkDescriptorSetLayout layout, VkDescriptorSet* out, VkFailure* failure);

private:
    struct Slot {
        explicit Slot(HostAllocator* host) : pools(StlAllocator<VkDescriptorPool>(host)) {}
        Vector<VkDescriptorPool> pools;
        uint32_t current = 0; // the pool sets come from
        uint32_t used = 0;    // sets taken from pools[current]
    };
    const Functions& fn_;
    VkDevice device_;
    HostAllocator* host_;
    Vector<Slot> slots_; // grown to the highest slot used
};

} // namespace grass::vk
