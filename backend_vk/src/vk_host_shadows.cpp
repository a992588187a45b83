#include "vk_host_shadows.hpp"

#include "vk_labels.hpp"

#include <cstring>

namespace grass::vk {

bool HostShadowSets::write(uint32_t slot, uint64_t frame, const FramePlan& plan, const ReceivePipelines& pipelines,
                           VkFailure* failure, const char** what) {
    Slot& s = slots_[slot];
    if (s.written == frame && s.set != VK_NULL_HANDLE) return true; // this frame's plan is in it already
    if (pool_ == VK_NULL_HANDLE) {
        const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kMaxViewSlots},
                                               {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxViewSlots}};
        VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        info.maxSets = kMaxViewSlots;
        info.poolSizeCount = 2;
        info.pPoolSizes = sizes;
        *what = "the host shadow descriptor pool";
        if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &info, fn_.callbacks(), &pool_), "vkCreateDescriptorPool",
                   failure)) {
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, *what);
    }
    if (s.block.buffer == VK_NULL_HANDLE) {
        *what = "the GrassShadow block of a receiving view";
        if (!memory_.create_buffer(sizeof(ShadowUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::streaming,
                                   &s.block, failure)) {
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, s.block.buffer, "grass host shadow block");
    }
    if (s.set == VK_NULL_HANDLE) {
        const VkDescriptorSetLayout layout = pipelines.set_layout();
        VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        info.descriptorPool = pool_;
        info.descriptorSetCount = 1;
        info.pSetLayouts = &layout;
        *what = "the host shadow descriptor set of a receiving view";
        if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &info, &s.set), "vkAllocateDescriptorSets", failure)) {
            s.set = VK_NULL_HANDLE;
            return false;
        }
    }
    *what = "the GrassShadow block of a receiving view";
    std::memcpy(s.block.mapped, &plan.shadow, sizeof(ShadowUniforms));
    if (!memory_.flush(s.block, 0, sizeof(ShadowUniforms), failure)) return false;

    // The host's view of its map, in the layout it said the map is in during the pass.
    const VkDescriptorBufferInfo block{s.block.buffer, 0, sizeof(ShadowUniforms)};
    VkDescriptorImageInfo map{};
    map.sampler = pipelines.sampler(plan.shadow.params[0] < 0.0f);  // params.x -1: GREATER_EQUAL
    map.imageView = reinterpret_cast<VkImageView>(plan.shadow_map); // non-dispatchable handles are 64-bit
    map.imageLayout = static_cast<VkImageLayout>(plan.shadow_layout);
    VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                      {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    writes[0].dstSet = s.set;
    writes[0].dstBinding = kBindingShadowBlock;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[0].pBufferInfo = &block;
    writes[1].dstSet = s.set;
    writes[1].dstBinding = kBindingShadowMap;
    writes[1].descriptorCount = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[1].pImageInfo = &map;
    fn_.vkUpdateDescriptorSets(device_, 2, writes, 0, nullptr);
    s.written = frame;
    return true;
}

void HostShadowSets::destroy() {
    for (Slot& s : slots_) {
        if (s.block.buffer) memory_.destroy_buffer(&s.block);
        s = Slot{};
    }
    if (pool_) fn_.vkDestroyDescriptorPool(device_, pool_, fn_.callbacks());
    pool_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
