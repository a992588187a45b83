#include "vk_motion_pipelines.hpp"

#include "vk_labels.hpp"
#include "vk_pipeline.hpp"
#include "vk_slice_pipelines.hpp"
#include "vk_spirv.hpp"

namespace grass_vk_spirv {
#define GRASS_MOTION_MODULE(name) \
    extern const uint32_t name[]; \
    extern const uint32_t name##_size; /* bytes */
GRASS_MOTION_MODULE(blade_vert_grass_velocity)
GRASS_MOTION_MODULE(blade_vert_grass_velocity_grass_responsive)
GRASS_MOTION_MODULE(blade_vert_grass_velocity_grass_indexed_blocks)
GRASS_MOTION_MODULE(blade_vert_grass_velocity_grass_responsive_grass_indexed_blocks)
GRASS_MOTION_MODULE(blade_frag_grass_velocity)
GRASS_MOTION_MODULE(blade_frag_grass_velocity_grass_indexed_blocks)
GRASS_MOTION_MODULE(volume_frag_grass_velocity)
GRASS_MOTION_MODULE(volume_frag_grass_velocity_grass_responsive)
GRASS_MOTION_MODULE(volume_frag_grass_velocity_grass_indexed_blocks)
GRASS_MOTION_MODULE(volume_frag_grass_velocity_grass_responsive_grass_indexed_blocks)
GRASS_MOTION_MODULE(image_frag_grass_velocity)
GRASS_MOTION_MODULE(image_frag_grass_velocity_grass_responsive)
GRASS_MOTION_MODULE(image_frag_grass_velocity_grass_indexed_blocks)
GRASS_MOTION_MODULE(image_frag_grass_velocity_grass_responsive_grass_indexed_blocks)
#undef GRASS_MOTION_MODULE
} // namespace grass_vk_spirv

namespace grass::vk {

namespace {
using namespace grass_vk_spirv;
#define GRASS_MOTION_SPIRV(name) \
    { name, name##_size }
// The GRASS_VELOCITY modules, [program: blades' vertex, blades, volume, image fragment]
// [responsive][indexed blocks] (blade.frag has no responsive variant).
const Spirv kMotionModules[4][2][2] = {
    {{GRASS_MOTION_SPIRV(blade_vert_grass_velocity),
      GRASS_MOTION_SPIRV(blade_vert_grass_velocity_grass_indexed_blocks)},
     {GRASS_MOTION_SPIRV(blade_vert_grass_velocity_grass_responsive),
      GRASS_MOTION_SPIRV(blade_vert_grass_velocity_grass_responsive_grass_indexed_blocks)}},
    {{GRASS_MOTION_SPIRV(blade_frag_grass_velocity),
      GRASS_MOTION_SPIRV(blade_frag_grass_velocity_grass_indexed_blocks)},
     {GRASS_MOTION_SPIRV(blade_frag_grass_velocity),
      GRASS_MOTION_SPIRV(blade_frag_grass_velocity_grass_indexed_blocks)}},
    {{GRASS_MOTION_SPIRV(volume_frag_grass_velocity),
      GRASS_MOTION_SPIRV(volume_frag_grass_velocity_grass_indexed_blocks)},
     {GRASS_MOTION_SPIRV(volume_frag_grass_velocity_grass_responsive),
      GRASS_MOTION_SPIRV(volume_frag_grass_velocity_grass_responsive_grass_indexed_blocks)}},
    {{GRASS_MOTION_SPIRV(image_frag_grass_velocity),
      GRASS_MOTION_SPIRV(image_frag_grass_velocity_grass_indexed_blocks)},
     {GRASS_MOTION_SPIRV(image_frag_grass_velocity_grass_responsive),
      GRASS_MOTION_SPIRV(image_frag_grass_velocity_grass_responsive_grass_indexed_blocks)}},
};
#undef GRASS_MOTION_SPIRV

Spirv motion_module(uint32_t program, const SpirvVariant& v) {
    return kMotionModules[program][v.responsive ? 1 : 0][v.indexed_blocks ? 1 : 0];
}

// The velocity output's location as motion.glsl compiles it.
constexpr uint32_t kCompiledVelocityLocation = 1;
} // namespace

bool relocate_output(uint32_t* code, size_t words, uint32_t from, uint32_t to) {
    constexpr uint32_t kOpDecorate = 71, kOpVariable = 59, kDecorationLocation = 30, kStorageOutput = 3;
    if (words < 5 || code[0] != 0x07230203u) return false;
    const auto is_output = [&](uint32_t id) {
        for (size_t at = 5; at < words;) {
            const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
            if (count == 0 || at + count > words) return false;
            if (op == kOpVariable && count >= 4 && code[at + 2] == id) return code[at + 3] == kStorageOutput;
            at += count;
        }
        return false;
    };
    for (size_t at = 5; at < words;) {
        const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
        if (count == 0 || at + count > words) return false;
        if (op == kOpDecorate && count >= 4 && code[at + 2] == kDecorationLocation && code[at + 3] == from &&
            is_output(code[at + 1])) {
            code[at + 3] = to;
            return true;
        }
        at += count;
    }
    return false;
}

bool MotionPipelines::create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set,
                                     const ShaderVariant& variant, const SpirvVariant& modules, bool depth_test,
                                     VkFailure* failure, const char** what) {
    if (has_variant(variant, depth_test)) return true;
    if (variant.program >= kMotionPipelineKinds || (variant.features & ~kFeatureMotion) >= kMotionColourMasks ||
        target.velocity_attachment == 0) {
        *what = "a pipeline that writes motion vectors (no such variant, or no grass_vk_velocity_target_desc)";
        return false;
    }
    if (layout_ == VK_NULL_HANDLE && !create_layouts(target, blade_set, failure, what)) {
        destroy();
        return false;
    }
    if (pipelines_.empty()) pipelines_.assign(kMotionColourMasks * kMotionPipelineKinds * 2, VK_NULL_HANDLE);

    // The shape of the plain pipelines, with the GRASS_VELOCITY modules: the blades' both,
    // the volume's and the image tier's fragment (their vertex shaders have no motion).
    PipelineShape shape = variant.program == kShaderBlades   ? blade_shape(modules)
                          : variant.program == kShaderVolume ? SlicePipelines::volume_shape(modules)
                                                             : SlicePipelines::image_shape(modules);
    if (variant.program == kShaderBlades) {
        const Spirv vert = motion_module(0, modules);
        shape.vertex_code = vert.code;
        shape.vertex_code_size = vert.size;
    }
    const Spirv frag = motion_module(variant.program + 1, modules);
    Vector<uint32_t> code(frag.code, frag.code + frag.size / sizeof(uint32_t), StlAllocator<uint32_t>(host_));
    if (!relocate_output(code.data(), code.size(), kCompiledVelocityLocation, target.velocity_attachment)) {
        *what = "a motion vectors' fragment module (no velocity output)";
        return false;
    }
    shape.fragment_code = code.data();
    shape.fragment_code_size = frag.size;
    shape.name = variant.program == kShaderBlades   ? "the blade motion pipelines"
                 : variant.program == kShaderVolume ? "the volume tier motion pipelines"
                                                    : "the image tier motion pipelines";
    const uint32_t colour = variant.features & ~kFeatureMotion;
    VkPipeline* p = &pipelines_[(colour * kMotionPipelineKinds + variant.program) * 2 + (depth_test ? 0 : 1)];
    return create_pipeline(fn_, device_, target, layout_, shape, variant.features, depth_test, p, failure, what);
}

bool MotionPipelines::create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set, VkFailure* failure,
                                     const char** what) {
    const VkDescriptorSetLayoutBinding binding{kBindingMotionBlock, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    *what = "the motion descriptor set layout";
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
    *what = "the motion pipeline layout";
    if (!vk_ok(fn_.vkCreatePipelineLayout(device_, &layout_info, fn_.callbacks(), &layout_), "vkCreatePipelineLayout",
               failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, *what);
    return true;
}

void MotionPipelines::destroy() {
    for (VkPipeline& p : pipelines_) {
        if (p) fn_.vkDestroyPipeline(device_, p, fn_.callbacks());
    }
    pipelines_.clear();
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
    layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
