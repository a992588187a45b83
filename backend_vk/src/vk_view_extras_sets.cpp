#include "vk_view_extras_sets.hpp"

#include "vk_labels.hpp"

#include <cstring>

namespace grass::vk {

namespace {
// A write of one descriptor of `set`: a uniform buffer's `block`, or the host's `map`.
VkWriteDescriptorSet write_of(VkDescriptorSet set, uint32_t binding, const VkDescriptorBufferInfo* block,
                              const VkDescriptorImageInfo* map) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = block ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pBufferInfo = block;
    w.pImageInfo = map;
    return w;
}
} // namespace

bool ViewExtrasSets::create_block(Buffer* block, VkDeviceSize bytes, const char* name, VkFailure* failure,
                                  const char** what) {
    if (block->buffer != VK_NULL_HANDLE) return true;
    *what = name;
    if (!memory_.create_buffer(bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::streaming, block, failure))
        return false;
    name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, block->buffer, name);
    return true;
}

bool ViewExtrasSets::allocate(VkDescriptorSetLayout layout, VkDescriptorSet* set, const char* name, VkFailure* failure,
                              const char** what) {
    if (*set != VK_NULL_HANDLE) return true;
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool_;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    *what = name;
    if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &info, set), "vkAllocateDescriptorSets", failure)) {
        *set = VK_NULL_HANDLE;
        return false;
    }
    return true;
}

bool ViewExtrasSets::write(uint32_t slot, uint64_t frame, const FramePlan& plan, const ViewExtrasPipelines& pipelines,
                           VkFailure* failure, const char** what) {
    Slot& s = slots_[slot];
    if (s.written == frame && s.set != VK_NULL_HANDLE) return true; // this frame's plan is in it already
    if (pool_ == VK_NULL_HANDLE) {
        const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kExtrasBindingCount * kMaxViewSlots},
                                               {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxViewSlots}};
        VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        info.maxSets = 2 * kMaxViewSlots;
        info.poolSizeCount = 2;
        info.pPoolSizes = sizes;
        *what = "the view extras descriptor pool";
        if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &info, fn_.callbacks(), &pool_), "vkCreateDescriptorPool",
                   failure)) {
            pool_ = VK_NULL_HANDLE;
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, *what);
    }
    // Each binding's block: whether the view uses it, its bytes and its name.
    const bool used[kExtrasBindingCount] = {plan.motion, plan.shadow_receive, plan.host_lights, plan.gbuffer};
    const void* const data[kExtrasBindingCount] = {&plan.motion_uniforms, &plan.shadow, &plan.lights,
                                                   &plan.gbuffer_uniforms};
    const VkDeviceSize bytes[kExtrasBindingCount] = {sizeof(MotionUniforms), sizeof(ShadowUniforms),
                                                     sizeof(LightUniforms), sizeof(GBufferUniforms)};
    const char* const names[kExtrasBindingCount] = {"grass motion block", "grass host shadow block",
                                                    "grass host lights block", "grass G-buffer block"};
    const char* const writing[kExtrasBindingCount] = {
        "the GrassMotion block of a motion view", "the GrassShadow block of a receiving view",
        "the GrassLights block of a lit view", "the GrassGBuffer block of a G-buffer view"};
    for (uint32_t b = 0; b < kExtrasBindingCount; ++b) {
        if (used[b] && !create_block(&s.blocks[b], bytes[b], names[b], failure, what)) return false;
    }
    if (!allocate(pipelines.set_layout(), &s.set, "the view extras descriptor set of a view", failure, what))
        return false;
    if (plan.shadow_receive && !allocate(pipelines.map_set_layout(), &s.map_set,
                                         "the shadow map descriptor set of a receiving view", failure, what)) {
        return false;
    }

    // Every binding of set 1, always, so that no set grass binds holds a descriptor left
    // unwritten (lavapipe, Mesa 22.3, crashed on a set whose unused map binding was: see
    // vk_view_extras.hpp). A block the view's pipelines do not use points at one it uses
    // (that block's range; never read).
    uint32_t stand_in = 0;
    while (stand_in < kExtrasBindingCount && !used[stand_in]) ++stand_in;
    if (stand_in == kExtrasBindingCount) {
        *what = "the view extras descriptor set of a view without extras";
        return false;
    }
    VkDescriptorBufferInfo infos[kExtrasBindingCount];
    VkWriteDescriptorSet writes[kExtrasBindingCount + 1];
    for (uint32_t b = 0; b < kExtrasBindingCount; ++b) {
        if (used[b]) {
            *what = writing[b];
            std::memcpy(s.blocks[b].mapped, data[b], bytes[b]);
            if (!memory_.flush(s.blocks[b], 0, bytes[b], failure)) return false;
        }
        const uint32_t from = used[b] ? b : stand_in;
        infos[b] = VkDescriptorBufferInfo{s.blocks[from].buffer, 0, bytes[from]};
        writes[b] = write_of(s.set, b, &infos[b], nullptr);
    }
    uint32_t count = kExtrasBindingCount;
    // The host's view of its map, in the layout it said the map is in during the pass.
    VkDescriptorImageInfo map{};
    if (plan.shadow_receive) {
        map.sampler = pipelines.sampler(plan.shadow.params[0] < 0.0f);  // params.x -1: GREATER_EQUAL
        map.imageView = reinterpret_cast<VkImageView>(plan.shadow_map); // non-dispatchable handles are 64-bit
        map.imageLayout = static_cast<VkImageLayout>(plan.shadow_layout);
        writes[count++] = write_of(s.map_set, kBindingShadowMap, nullptr, &map);
    }
    fn_.vkUpdateDescriptorSets(device_, count, writes, 0, nullptr);
    s.written = frame;
    return true;
}

void ViewExtrasSets::destroy() {
    for (Slot& s : slots_) {
        for (Buffer& block : s.blocks) {
            if (block.buffer) memory_.destroy_buffer(&block);
        }
        s = Slot{};
    }
    if (pool_) fn_.vkDestroyDescriptorPool(device_, pool_, fn_.callbacks());
    pool_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
