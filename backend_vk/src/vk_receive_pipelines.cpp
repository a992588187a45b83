#include "vk_receive_pipelines.hpp"

#include "vk_labels.hpp"
#include "vk_pipeline.hpp"

namespace grass::vk {

bool ReceivePipelines::create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set,
                                      const ShaderVariant& variant, const PipelineShape& shape, bool depth_test,
                                      VkFailure* failure, const char** what) {
    if (has_variant(variant, depth_test)) return true;
    if (variant.program >= kReceivePipelineKinds ||
        (variant.features & ~kFeatureShadowReceive) >= kReceiveColourMasks) {
        *what = "a pipeline that receives the host's shadows (no such variant)";
        return false;
    }
    if (layout_ == VK_NULL_HANDLE && !create_layouts(target, blade_set, failure, what)) {
        destroy();
        return false;
    }
    if (pipelines_.empty()) pipelines_.assign(kReceiveColourMasks * kReceivePipelineKinds * 2, VK_NULL_HANDLE);
    const uint32_t colour = variant.features & ~kFeatureShadowReceive;
    VkPipeline* p = &pipelines_[(colour * kReceivePipelineKinds + variant.program) * 2 + (depth_test ? 0 : 1)];
    return create_pipeline(fn_, device_, target, layout_, shape, variant.features, depth_test, p, failure, what);
}

bool ReceivePipelines::create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set, VkFailure* failure,
                                      const char** what) {
    // The host's map: linear (each tap the hardware's 2x2 percentage-closer filter), one
    // level, clamped; the comparison the host's depth convention's.
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.compareEnable = VK_TRUE;
    info.minLod = 0.0f;
    info.maxLod = 0.0f;
    const VkCompareOp ops[2] = {VK_COMPARE_OP_LESS_OR_EQUAL, VK_COMPARE_OP_GREATER_OR_EQUAL};
    const char* const names[2] = {"grass host shadow sampler (less or equal)",
                                  "grass host shadow sampler (greater or equal)"};
    for (int i = 0; i < 2; ++i) {
        info.compareOp = ops[i];
        *what = names[i];
        if (!vk_ok(fn_.vkCreateSampler(device_, &info, fn_.callbacks(), &samplers_[i]), "vkCreateSampler", failure))
            return false;
        name_object(fn_, device_, VK_OBJECT_TYPE_SAMPLER, samplers_[i], names[i]);
    }

    const VkDescriptorSetLayoutBinding bindings[kShadowBindingCount] = {
        {kBindingShadowBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {kBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    };
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = kShadowBindingCount;
    set_info.pBindings = bindings;
    *what = "the host shadow descriptor set layout";
    if (!vk_ok(fn_.vkCreateDescriptorSetLayout(device_, &set_info, fn_.callbacks(), &set_layout_),
               "vkCreateDescriptorSetLayout", failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, set_layout_, *what);

    // Set 0 and the push constants as the blade layout's, so that set 0 bound through either
    // layout stays bound for the other (pipeline layout compatibility).
    const VkDescriptorSetLayout sets[2] = {blade_set, set_layout_};
    const VkPushConstantRange block_index{kBlockIndexStages, 0, kBlockIndexBytes};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 2;
    layout_info.pSetLayouts = sets;
    layout_info.pushConstantRangeCount = target.indexed_blocks ? 1 : 0;
    layout_info.pPushConstantRanges = target.indexed_blocks ? &block_index : nullptr;
    *what = "the host shadow pipeline layout";
    if (!vk_ok(fn_.vkCreatePipelineLayout(device_, &layout_info, fn_.callbacks(), &layout_), "vkCreatePipelineLayout",
               failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, *what);
    return true;
}

void ReceivePipelines::destroy() {
    for (VkPipeline& p : pipelines_) {
        if (p) fn_.vkDestroyPipeline(device_, p, fn_.callbacks());
    }
    pipelines_.clear();
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
    for (VkSampler& s : samplers_) {
        if (s) fn_.vkDestroySampler(device_, s, fn_.callbacks());
        s = VK_NULL_HANDLE;
    }
    layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
