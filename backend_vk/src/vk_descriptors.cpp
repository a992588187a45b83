#include "vk_descriptors.hpp"

namespace grass::vk {

namespace {
constexpr uint32_t kSetsPerPool = 64;
} // namespace

DescriptorAllocator::~DescriptorAllocator() {
    // Destroying a pool frees every set still allocated from it.
    for (const Pool& p : pools_) fn_.vkDestroyDescriptorPool(device_, p.pool, nullptr);
}

bool DescriptorAllocator::add_pool(VkFailure* failure) {
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 2 * kSetsPerPool},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSetsPerPool},
    };
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    info.maxSets = kSetsPerPool;
    info.poolSizeCount = 2;
    info.pPoolSizes = sizes;
    pools_.reserve(pools_.size() + 1); // push_back below cannot throw with a live pool in hand
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &info, nullptr, &pool), "vkCreateDescriptorPool", failure)) {
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

} // namespace grass::vk
