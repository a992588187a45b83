#include "vk_motion_blocks.hpp"

#include "vk_labels.hpp"
#include "vk_motion_pipelines.hpp"

#include <cstring>

namespace grass::vk {

bool MotionBlocks::write(uint32_t slot, uint64_t frame, const FramePlan& plan, VkDescriptorSetLayout set_layout,
                         VkFailure* failure, const char** what) {
    Slot& s = slots_[slot];
    if (s.written == frame && s.set != VK_NULL_HANDLE) return true; // this frame's plan is in it already
    if (pool_ == VK_NULL_HANDLE) {
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kMaxViewSlots};
        VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        info.maxSets = kMaxViewSlots;
        info.poolSizeCount = 1;
        info.pPoolSizes = &size;
        *what = "the motion descriptor pool";
        if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &info, fn_.callbacks(), &pool_), "vkCreateDescriptorPool",
                   failure)) {
            pool_ = VK_NULL_HANDLE;
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, *what);
    }
    if (s.block.buffer == VK_NULL_HANDLE) {
        *what = "the GrassMotion block of a motion view";
        if (!memory_.create_buffer(sizeof(MotionUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::streaming,
                                   &s.block, failure)) {
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, s.block.buffer, "grass motion block");
    }
    if (s.set == VK_NULL_HANDLE) {
        VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        info.descriptorPool = pool_;
        info.descriptorSetCount = 1;
        info.pSetLayouts = &set_layout;
        *what = "the motion descriptor set of a motion view";
        if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &info, &s.set), "vkAllocateDescriptorSets", failure)) {
            s.set = VK_NULL_HANDLE;
            return false;
        }
        const VkDescriptorBufferInfo block{s.block.buffer, 0, sizeof(MotionUniforms)};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = s.set;
        write.dstBinding = kBindingMotionBlock;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        write.pBufferInfo = &block;
        fn_.vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
    }
    *what = "the GrassMotion block of a motion view";
    std::memcpy(s.block.mapped, &plan.motion_uniforms, sizeof(MotionUniforms));
    if (!memory_.flush(s.block, 0, sizeof(MotionUniforms), failure)) return false;
    s.written = frame;
    return true;
}

void MotionBlocks::destroy() {
    for (Slot& s : slots_) {
        if (s.block.buffer) memory_.destroy_buffer(&s.block);
        s = Slot{};
    }
    if (pool_) fn_.vkDestroyDescriptorPool(device_, pool_, fn_.callbacks());
    pool_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
