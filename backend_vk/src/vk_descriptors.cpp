#include "vk_descriptors.hpp"

#include "vk_labels.hpp"

namespace grass::vk {

namespace {
constexpr uint32_t kSetsPerPool = 64;
constexpr uint32_t kFrameSetsPerPool = 32;

VkResult create_pool(const Functions& fn, VkDevice device, uint32_t sets, VkDescriptorPoolCreateFlags flags,
                     VkDescriptorPool* out) {
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, kUniformBuffersPerSet * sets}, // the Frame and Field blocks
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kImageSamplersPerSet * sets},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStorageBuffersPerSet * sets},
    };
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = flags;
    info.maxSets = sets;
    info.poolSizeCount = sizeof(sizes) / sizeof(sizes[0]);
    info.pPoolSizes = sizes;
    const VkResult r = fn.vkCreateDescriptorPool(device, &info, fn.callbacks(), out);
    if (r == VK_SUCCESS) {
        name_object(fn, device, VK_OBJECT_TYPE_DESCRIPTOR_POOL, *out,
                    flags ? "grass descriptor pool (fields)" : "grass descriptor pool (frame draws)");
    }
    return r;
}
} // namespace

DescriptorAllocator::~DescriptorAllocator() {
    // Destroying a pool frees every set still allocated from it.
    for (const Pool& p : pools_) fn_.vkDestroyDescriptorPool(device_, p.pool, fn_.callbacks());
}

bool DescriptorAllocator::add_pool(VkFailure* failure) {
    pools_.reserve(pools_.size() + 1); // push_back below cannot throw with a live pool in hand
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (!vk_ok(create_pool(fn_, device_, kSetsPerPool, VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT, &pool),
               "vkCreateDescriptorPool", failure)) {
        return false;
    }
    pools_.push_back(Pool{pool, 0});
    return true;
}

bool DescriptorAllocator::allocate(VkDescriptorSetLayout layout, DescriptorSet* out, VkFailure* failure) {
    Pool* pool = nullptr;
    for (Pool& p : pools_) {
        if (p.live_sets < kSetsPerPool) {
            pool = &p;
            break;
        }
    }
    if (!pool) {
        if (!add_pool(failure)) return false;
        pool = &pools_.back();
    }
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool->pool;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &info, &set), "vkAllocateDescriptorSets", failure)) return false;
    pool->live_sets += 1;
    *out = {set, pool->pool};
    return true;
}

void DescriptorAllocator::free(DescriptorSet* set) {
    if (!set->set) return;
    fn_.vkFreeDescriptorSets(device_, set->pool, 1, &set->set);
    for (Pool& p : pools_) {
        if (p.pool == set->pool) {
            p.live_sets -= 1;
            break;
        }
    }
    *set = DescriptorSet{};
}

// ---- FrameDescriptors -----------------------------------------------------------------------

FrameDescriptors::FrameDescriptors(const Functions& functions, VkDevice device, HostAllocator* host)
    : fn_(functions), device_(device), host_(host), slots_(StlAllocator<Slot>(host)) {}

FrameDescriptors::~FrameDescriptors() {
    for (const Slot& s : slots_) {
        for (VkDescriptorPool p : s.pools) fn_.vkDestroyDescriptorPool(device_, p, fn_.callbacks());
    }
}

void FrameDescriptors::reset(uint32_t slot) {
    if (slot >= slots_.size()) return; // never handed out a set
    Slot& s = slots_[slot];
    // Only the pools that handed out sets since the last reset need it.
    for (uint32_t i = 0; i < s.pools.size() && (i < s.current || (i == s.current && s.used > 0)); ++i) {
        fn_.vkResetDescriptorPool(device_, s.pools[i], 0);
    }
    s.current = 0;
    s.used = 0;
}

bool FrameDescriptors::allocate(uint32_t slot, VkDescriptorSetLayout layout, VkDescriptorSet* out, VkFailure* failure) {
    while (slots_.size() <= slot) slots_.emplace_back(host_); // may throw: nothing made yet
    Slot& s = slots_[slot];
    if (s.current < s.pools.size() && s.used == kFrameSetsPerPool) {
        s.current += 1;
        s.used = 0;
    }
    if (s.current == s.pools.size()) {
        s.pools.reserve(s.pools.size() + 1); // may throw: nothing made yet
        VkDescriptorPool pool = VK_NULL_HANDLE;
        if (!vk_ok(create_pool(fn_, device_, kFrameSetsPerPool, 0, &pool), "vkCreateDescriptorPool", failure)) {
            return false;
        }
        s.pools.push_back(pool);
        s.used = 0;
    }
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = s.pools[s.current];
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &info, out), "vkAllocateDescriptorSets", failure)) return false;
    s.used += 1;
    return true;
}

} // namespace grass::vk
