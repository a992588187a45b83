#include "vk_view_extras.hpp"

#include "vk_labels.hpp"
#include "vk_pipeline.hpp"

namespace grass::vk {

namespace {
// The velocity output's location as motion.glsl compiles it.
constexpr uint32_t kCompiledVelocityLocation = 1;
// The pipelines' names, [combination (ViewExtrasPipelines::combination)][kind].
const char* const kNames[kExtrasCombinations][kExtrasPipelineKinds] = {
    {"the blade receiving pipelines", "the volume tier receiving pipelines", "the image tier receiving pipelines"},
    {"the blade motion pipelines", "the volume tier motion pipelines", "the image tier motion pipelines"},
    {"the blade receiving motion pipelines", "the volume tier receiving motion pipelines",
     "the image tier receiving motion pipelines"},
    {"the blade lit pipelines", "the volume tier lit pipelines", "the image tier lit pipelines"},
    {"the blade lit receiving pipelines", "the volume tier lit receiving pipelines",
     "the image tier lit receiving pipelines"},
    {"the blade lit motion pipelines", "the volume tier lit motion pipelines", "the image tier lit motion pipelines"},
    {"the blade lit receiving motion pipelines", "the volume tier lit receiving motion pipelines",
     "the image tier lit receiving motion pipelines"},
};
} // namespace

bool is_output_variable(const uint32_t* code, size_t words, uint32_t id) {
    constexpr uint32_t kOpVariable = 59, kStorageOutput = 3;
    for (size_t at = 5; at < words;) {
        const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
        if (count == 0 || at + count > words) return false;
        if (op == kOpVariable && count >= 4 && code[at + 2] == id) return code[at + 3] == kStorageOutput;
        at += count;
    }
    return false;
}

bool relocate_output(uint32_t* code, size_t words, uint32_t from, uint32_t to) {
    constexpr uint32_t kOpDecorate = 71, kDecorationLocation = 30;
    if (words < 5 || code[0] != 0x07230203u) return false;
    for (size_t at = 5; at < words;) {
        const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
        if (count == 0 || at + count > words) return false;
        if (op == kOpDecorate && count >= 4 && code[at + 2] == kDecorationLocation && code[at + 3] == from &&
            is_output_variable(code, words, code[at + 1])) {
            code[at + 3] = to;
            return true;
        }
        at += count;
    }
    return false;
}

bool ViewExtrasPipelines::create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set,
                                         const ShaderVariant& variant, const PipelineShape& shape, bool depth_test,
                                         VkFailure* failure, const char** what, VkPipeline* into) {
    if (into == nullptr && has_variant(variant, depth_test)) return true;
    const bool receive = (variant.features & kFeatureShadowReceive) != 0;
    const bool motion = (variant.features & kFeatureMotion) != 0;
    if ((variant.features & kViewExtras) == 0 || variant.program >= kExtrasPipelineKinds ||
        (variant.features & ~(kViewExtras | kFeatureBladeWindow)) >= kExtrasColourMasks ||
        (motion && target.velocity_attachment == 0) || shape.vertex_code == nullptr || shape.fragment_code == nullptr) {
        *what = "a pipeline that receives the host's shadows, writes motion vectors or is lit by the host's lights "
                "(no such variant, or no grass_vk_velocity_target_desc)";
        return false;
    }
    if (!create_layouts(target, blade_set, failure, what)) {
        destroy();
        return false;
    }
    if (receive && samplers_[0] == VK_NULL_HANDLE && !create_samplers(failure, what)) return false;
    VkPipeline* p = into;
    if (p == nullptr) {
        Vector<VkPipeline>& table = pipelines_[combination(variant.features)];
        if (table.empty()) table.assign(kExtrasColourMasks * kExtrasPipelineKinds * 2, VK_NULL_HANDLE);
        const uint32_t colour = variant.features & ~kViewExtras;
        p = &table[(colour * kExtrasPipelineKinds + variant.program) * 2 + (depth_test ? 0 : 1)];
    }
    PipelineShape named = shape;
    named.name = kNames[combination(variant.features)][variant.program];
    if (!motion)
        return create_pipeline(fn_, device_, target, layout_, named, variant.features, depth_test, p, failure, what);

    // The velocity output moved from where motion.glsl compiles it to the host's velocity attachment.
    Vector<uint32_t> code(shape.fragment_code, shape.fragment_code + shape.fragment_code_size / sizeof(uint32_t),
                          StlAllocator<uint32_t>(host_));
    if (!relocate_output(code.data(), code.size(), kCompiledVelocityLocation, target.velocity_attachment)) {
        *what = "a motion vectors' fragment module (no velocity output)";
        return false;
    }
    named.fragment_code = code.data();
    return create_pipeline(fn_, device_, target, layout_, named, variant.features, depth_test, p, failure, what);
}

bool ViewExtrasPipelines::create_samplers(VkFailure* failure, const char** what) {
    // The host's map: linear (each tap the hardware's 2x2 percentage-closer filter), one
    // level, clamped; the comparison the host's depth convention's.
    VkSamplerCreateInfo info = linear_clamped_sampler_info();
    info.compareEnable = VK_TRUE;
    const VkCompareOp ops[2] = {VK_COMPARE_OP_LESS_OR_EQUAL, VK_COMPARE_OP_GREATER_OR_EQUAL};
    const char* const names[2] = {"grass host shadow sampler (less or equal)",
                                  "grass host shadow sampler (greater or equal)"};
    for (int i = 0; i < 2; ++i) {
        info.compareOp = ops[i];
        *what = names[i];
        if (!vk_ok(fn_.vkCreateSampler(device_, &info, fn_.callbacks(), &samplers_[i]), "vkCreateSampler", failure)) {
            samplers_[i] = VK_NULL_HANDLE;
            for (VkSampler& s : samplers_) {
                if (s) fn_.vkDestroySampler(device_, s, fn_.callbacks());
                s = VK_NULL_HANDLE;
            }
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_SAMPLER, samplers_[i], names[i]);
    }
    return true;
}

bool ViewExtrasPipelines::create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set,
                                         VkFailure* failure, const char** what) {
    if (layout_ != VK_NULL_HANDLE) return true;
    const VkDescriptorSetLayoutBinding bindings[kExtrasBindingCount] = {
        {kBindingMotionBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {kBindingShadowBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {kBindingLightsBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {kBindingGBufferBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    };
    const VkDescriptorSetLayoutBinding map{kBindingShadowMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                           VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = kExtrasBindingCount;
    set_info.pBindings = bindings;
    *what = "the view extras descriptor set layout";
    if (!vk_ok(fn_.vkCreateDescriptorSetLayout(device_, &set_info, fn_.callbacks(), &set_layout_),
               "vkCreateDescriptorSetLayout", failure)) {
        set_layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, set_layout_, *what);
    set_info.bindingCount = 1;
    set_info.pBindings = &map;
    *what = "the view extras host map set layout";
    if (!vk_ok(fn_.vkCreateDescriptorSetLayout(device_, &set_info, fn_.callbacks(), &map_set_layout_),
               "vkCreateDescriptorSetLayout", failure)) {
        map_set_layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, map_set_layout_, *what);

    // Set 0 and the push constants as the blade layout's, so that set 0 bound through either
    // layout stays bound for the other (pipeline layout compatibility).
    const VkDescriptorSetLayout sets[3] = {blade_set, set_layout_, map_set_layout_};
    const VkPushConstantRange block_index{kBlockIndexStages, 0, kBlockIndexBytes};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 3;
    layout_info.pSetLayouts = sets;
    layout_info.pushConstantRangeCount = target.indexed_blocks ? 1 : 0;
    layout_info.pPushConstantRanges = target.indexed_blocks ? &block_index : nullptr;
    *what = "the view extras pipeline layout";
    if (!vk_ok(fn_.vkCreatePipelineLayout(device_, &layout_info, fn_.callbacks(), &layout_), "vkCreatePipelineLayout",
               failure)) {
        layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, *what);
    return true;
}

void ViewExtrasPipelines::destroy() {
    for (Vector<VkPipeline>& table : pipelines_) {
        for (VkPipeline& p : table) {
            if (p) fn_.vkDestroyPipeline(device_, p, fn_.callbacks());
        }
        table.clear();
    }
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
    if (map_set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, map_set_layout_, fn_.callbacks());
    for (VkSampler& s : samplers_) {
        if (s) fn_.vkDestroySampler(device_, s, fn_.callbacks());
        s = VK_NULL_HANDLE;
    }
    layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
    map_set_layout_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
