// Descriptor sets of the backend, from pools it owns. Every set has the blade layout, so
// a pool's room is counted in sets: a set comes from the first pool with room, a new pool
// is added when all are full, and sets are freed one by one (FREE_DESCRIPTOR_SET).
#pragma once

#include "allocator.hpp"
#include "vk_functions.hpp"
#include "vk_result.hpp"

namespace grass::vk {

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

    // A set of `layout`, which must be the blade layout (two dynamic uniform buffers and
    // one combined image sampler): the pools are sized for it.
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

} // namespace grass::vk
