#include "vk_pipeline.hpp"

#include "vk_debug_view.hpp"
#include "vk_labels.hpp"
#include "vk_slice_pipelines.hpp"

#include "context/backend.hpp"
#include "foundation/frame_plan.hpp"
#include "patch/patch_data.hpp"
#include "vk_spirv.hpp"

#include <cstddef>

namespace grass::vk {

namespace {

// Vertex input: binding 0 = patch vertices (grass::BladeVertex), binding 1 = the tier
// instances (grass::TierInstance, per instance); locations as in blade.vert.
constexpr VkVertexInputBindingDescription kBindings[] = {
    {0, sizeof(BladeVertex), VK_VERTEX_INPUT_RATE_VERTEX},
    {1, sizeof(TierInstance), VK_VERTEX_INPUT_RATE_INSTANCE},
};
constexpr VkVertexInputAttributeDescription kAttributes[] = {
    {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(BladeVertex, position)},
    {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(BladeVertex, normal)},
    {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(BladeVertex, root_shape)},
    {3, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(BladeVertex, color)},
    {4, 0, VK_FORMAT_R32_SFLOAT, offsetof(BladeVertex, threshold)},
    {5, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(TierInstance, origin)},
    {6, 1, VK_FORMAT_R32G32B32A32_UINT, offsetof(TierInstance, cell)},
    {7, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(TierInstance, terrain)},
};
static_assert(offsetof(BladeVertex, normal) == 12 && offsetof(BladeVertex, root_shape) == 24 &&
                  offsetof(BladeVertex, color) == 40 && offsetof(BladeVertex, threshold) == 44,
              "vertex layout of blade.vert");
static_assert(offsetof(TierInstance, cell) == 16 && offsetof(TierInstance, terrain) == 32 && sizeof(TierInstance) == 48,
              "instance layout of blade.vert");

} // namespace

PipelineShape blade_shape(SpirvVariant variant) {
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 2;
    vertex_input.pVertexBindingDescriptions = kBindings;
    vertex_input.vertexAttributeDescriptionCount = sizeof(kAttributes) / sizeof(kAttributes[0]);
    vertex_input.pVertexAttributeDescriptions = kAttributes;
    // With multisampling, the blade edge alpha becomes coverage (blade.frag).
    const Spirv vert = spirv(Shader::blade_vert, variant);
    const Spirv frag = spirv(Shader::blade_frag, variant);
    return PipelineShape{vert.code, vert.size, frag.code, frag.size, vertex_input, true, "the blade pipelines"};
}

namespace {

// The locations of the vertex shader's inputs (bit l: location l), read from its SPIR-V:
// the Input variables of its entry point with a Location decoration. A pipeline supplies
// exactly those attributes of its vertex input: the validation layers warn of attributes a
// shader does not consume, and a shader that reads the instance's terrain (location 7)
// only where it needs it stays free to. ~0u when the code cannot be read.
uint32_t vertex_input_locations(const uint32_t* code, size_t bytes) {
    constexpr uint32_t kOpEntryPoint = 15, kOpDecorate = 71, kOpVariable = 59;
    constexpr uint32_t kDecorationLocation = 30, kStorageInput = 1, kExecutionVertex = 0;
    const size_t words = bytes / sizeof(uint32_t);
    if (words < 5 || code[0] != 0x07230203u) return ~0u;
    // Three passes over the instructions (a few thousand words): entry point interface,
    // locations, input variables.
    const auto each = [&](auto&& visit) {
        for (size_t at = 5; at < words;) {
            const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
            if (count == 0 || at + count > words) return false;
            visit(op, code + at, count);
            at += count;
        }
        return true;
    };
    const auto location_of = [&](uint32_t id, uint32_t* location) {
        bool found = false;
        each([&](uint32_t op, const uint32_t* in, uint32_t count) {
            if (op == kOpDecorate && count >= 4 && in[1] == id && in[2] == kDecorationLocation) {
                *location = in[3];
                found = true;
            }
        });
        return found;
    };
    const auto is_input = [&](uint32_t id) {
        bool input = false;
        each([&](uint32_t op, const uint32_t* in, uint32_t count) {
            if (op == kOpVariable && count >= 4 && in[2] == id && in[3] == kStorageInput) input = true;
        });
        return input;
    };
    uint32_t mask = 0;
    bool entry = false;
    const bool ok = each([&](uint32_t op, const uint32_t* in, uint32_t count) {
        if (op != kOpEntryPoint || count < 4 || in[1] != kExecutionVertex || entry) return;
        entry = true;
        // The name: a nul-terminated string padded to words, after the model and the id.
        uint32_t at = 3;
        while (at < count) {
            const uint32_t w = in[at++];
            if ((w >> 24) == 0 || ((w >> 16) & 0xff) == 0 || ((w >> 8) & 0xff) == 0 || (w & 0xff) == 0) break;
        }
        for (; at < count; ++at) {
            uint32_t location = 0;
            if (is_input(in[at]) && location_of(in[at], &location) && location < 32) mask |= 1u << location;
        }
    });
    return ok && entry ? mask : ~0u;
}

bool format_has_stencil(VkFormat format) {
    return format == VK_FORMAT_D16_UNORM_S8_UINT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
           format == VK_FORMAT_D32_SFLOAT_S8_UINT || format == VK_FORMAT_S8_UINT;
}

} // namespace

bool BladePipeline::create(const PipelineTarget& target, VkFailure* failure, const char** what) {
    target_ = target;
    if (!create_layouts(failure, what) || !create_variants(0, failure, what)) {
        destroy();
        return false;
    }
    return true;
}

bool BladePipeline::create_variant(const ShaderVariant& variant, bool depth_test, VkFailure* failure,
                                   const char** what) {
    if (has_variant(variant, depth_test)) return true;
    const bool depth_pass = (variant.features & kFeatureDepthPass) != 0;
    const uint32_t extras = variant.features & kViewExtras;
    // The blade window's variant (kFeatureBladeWindow): responsive blades only; its pipelines
    // live in a list of their own (window_slot), the colour features index the others' tables.
    const bool window = (variant.features & kFeatureBladeWindow) != 0;
    if (window &&
        (variant.program != kShaderBlades || (variant.features & (kFeatureWind | kFeatureInteraction)) == 0)) {
        *what = "a blade window pipeline (only responsive blades read the window)";
        return false;
    }
    const uint32_t tabled = variant.features & ~kFeatureBladeWindow;
    if (variant.features & kFeatureGBuffer) return create_gbuffer_variant(variant, depth_test, failure, what);
    if (extras) {
        // The core refuses a receiving, motion or lit stereo view and a motion view without
        // the host's velocity target, and gives a depth pass and a debug view none of them.
        const bool motion = (extras & kFeatureMotion) != 0;
        if (depth_pass || target_.view_mask != 0 || variant.program >= kExtrasPipelineKinds ||
            (motion && velocity_target_.velocity_attachment == 0)) {
            *what = "a pipeline that receives the host's shadows, writes motion vectors or is lit by the host's "
                    "lights (a depth pass, stereo, a debug view, or motion without a grass_vk_velocity_target_desc)";
            return false;
        }
    } else if (depth_pass) {
        // The core refuses a depth view without the host's depth target, and a depth view
        // with debug views or without the depth test (check_pass).
        if (!depth_target_.depth_only || !depth_test || variant.program >= kDepthPipelineKinds ||
            (tabled & ~kFeatureDepthPass) >= kColourFeatureMasks) {
            *what = "a depth-only pipeline (no grass_vk_depth_pass_desc)";
            return false;
        }
        if (depth_pipelines_.empty() && !window)
            depth_pipelines_.assign(kColourFeatureMasks * kDepthPipelineKinds, VK_NULL_HANDLE);
    } else if (tabled >= kColourFeatureMasks) {
        return false;
    }
    // Responsive variants run the shaders compiled with GRASS_RESPONSIVE; still grass its own.
    // A multiview target (stereo) runs the GRASS_MULTIVIEW modules for every pipeline.
    SpirvVariant modules;
    modules.responsive = (variant.features & kBladeCurveFeatures) != 0;
    modules.indexed_blocks = target_.indexed_blocks;
    modules.multiview = target_.view_mask != 0;
    modules.depth_target = depth_pass; // no colour output: the depth-only target has no attachment for it
    modules.host_shadows = (extras & kFeatureShadowReceive) != 0; // the map and its block in set 1
    modules.velocity = (extras & kFeatureMotion) != 0;            // the GrassMotion block in set 1
    modules.host_lights = (extras & kFeatureHostLights) != 0;     // the GrassLights block in set 1
    modules.blade_window = window;                                // the poses read (bindings 14, 15)
    VkPipeline* into = window ? window_slot(variant.program, variant.features, depth_test) : nullptr;
    const PipelineShape shape = variant.program == kShaderBlades   ? blade_shape(modules)
                                : variant.program == kShaderVolume ? SlicePipelines::volume_shape(modules)
                                : variant.program == kShaderImage  ? SlicePipelines::image_shape(modules)
                                                                   : DebugViewPipeline::shape(modules);
    if (extras) {
        const PipelineTarget& target = modules.velocity ? velocity_target_ : target_;
        return extras_.create_variant(target, set_layout_, variant, shape, depth_test, failure, what, into);
    }
    if (depth_pass) {
        const uint32_t colour = variant.features & ~kFeatureDepthPass;
        return create_pipeline(fn_, device_, depth_target_, layout_, shape, variant.features, true,
                               into ? into : &depth_pipelines_[colour * kDepthPipelineKinds + variant.program], failure,
                               what);
    }
    return create_pipeline(fn_, device_, target_, layout_, shape, variant.features, depth_test,
                           into ? into : &pipelines_[variant.features][variant.program][depth_test ? 0 : 1], failure,
                           what);
}

VkPipeline* BladePipeline::window_slot(uint32_t program, uint32_t features, bool depth_test) {
    for (WindowPipeline& w : window_pipelines_) {
        if (w.program == program && w.features == features && w.depth_test == depth_test) return &w.pipeline;
    }
    window_pipelines_.push_back(WindowPipeline{program, features, depth_test, VK_NULL_HANDLE});
    return &window_pipelines_.back().pipeline;
}

bool BladePipeline::create_gbuffer_variant(const ShaderVariant& variant, bool depth_test, VkFailure* failure,
                                           const char** what) {
    // The core refuses a G-buffer view without the host's G-buffer target and gives it no
    // shadows, lights nor depth pass; a debug view draws boxes.
    const uint32_t others = kFeatureDepthPass | kFeatureShadowReceive | kFeatureHostLights;
    if (gbuffer_target_.color_count == 0 || target_.view_mask != 0 || variant.program >= kExtrasPipelineKinds ||
        (variant.features & others) != 0) {
        *what = "a G-buffer view's pipeline (a depth pass, stereo, a debug view, shadows, lights, or no "
                "grass_vk_gbuffer_target_desc)";
        return false;
    }
    SpirvVariant modules;
    modules.responsive = (variant.features & kBladeCurveFeatures) != 0;
    modules.indexed_blocks = target_.indexed_blocks;
    modules.velocity = (variant.features & kFeatureMotion) != 0; // the GrassMotion block in set 1
    modules.gbuffer = true;                                      // the GrassGBuffer block in set 1
    modules.blade_window = (variant.features & kFeatureBladeWindow) != 0;
    const PipelineShape shape = variant.program == kShaderBlades   ? blade_shape(modules)
                                : variant.program == kShaderVolume ? SlicePipelines::volume_shape(modules)
                                                                   : SlicePipelines::image_shape(modules);
    if (!extras_.create_layouts(gbuffer_target_, set_layout_, failure, what)) return false;
    return gbuffer_.create_variant(gbuffer_target_, extras_.layout(), routes_, variant, shape, depth_test, failure,
                                   what);
}

bool BladePipeline::create_variants(uint32_t features, VkFailure* failure, const char** what) {
    const ShaderVariant variants[] = {{kShaderBlades, features},
                                      {kShaderVolume, features},
                                      {kShaderImage, features},
                                      {kShaderDebugBoxes, features & kDebugBoxFeatures}};
    for (const ShaderVariant& v : variants) {
        if (!create_variant(v, true, failure, what)) return false;
    }
    return true;
}

void BladePipeline::destroy_variants(uint32_t features) {
    for (auto& modes : pipelines_[features]) {
        for (VkPipeline& p : modes) {
            if (p) fn_.vkDestroyPipeline(device_, p, fn_.callbacks());
            p = VK_NULL_HANDLE;
        }
    }
}

void BladePipeline::destroy() {
    for (uint32_t f = 0; f < kColourFeatureMasks; ++f) destroy_variants(f);
    for (VkPipeline& p : depth_pipelines_) {
        if (p) fn_.vkDestroyPipeline(device_, p, fn_.callbacks());
    }
    depth_pipelines_.clear();
    for (WindowPipeline& w : window_pipelines_) {
        if (w.pipeline) fn_.vkDestroyPipeline(device_, w.pipeline, fn_.callbacks());
    }
    window_pipelines_.clear();
    gbuffer_.destroy();
    extras_.destroy();
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
    if (sampler_) fn_.vkDestroySampler(device_, sampler_, fn_.callbacks());
    if (slice_linear_) fn_.vkDestroySampler(device_, slice_linear_, fn_.callbacks());
    if (slice_nearest_) fn_.vkDestroySampler(device_, slice_nearest_, fn_.callbacks());
    slice_linear_ = slice_nearest_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
    sampler_ = VK_NULL_HANDLE;
}

VkSamplerCreateInfo linear_clamped_sampler_info() {
    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = VK_FILTER_LINEAR;
    sampler.minFilter = VK_FILTER_LINEAR;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.minLod = 0.0f;
    sampler.maxLod = 0.0f;
    return sampler;
}

bool BladePipeline::create_layouts(VkFailure* failure, const char** what) {
    // Design maps: bilinear, clamped to the edge, one mip.
    VkSamplerCreateInfo sampler = linear_clamped_sampler_info();
    *what = "the design map sampler";
    if (!vk_ok(fn_.vkCreateSampler(device_, &sampler, fn_.callbacks(), &sampler_), "vkCreateSampler", failure))
        return false;
    name_object(fn_, device_, VK_OBJECT_TYPE_SAMPLER, sampler_, *what);

    // Baked slices: colour and normal trilinear over the whole mip chain; thresholds are
    // never blended (a blend of two blades' thresholds is no blade's), nearest texel and mip.
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    sampler.maxLod = VK_LOD_CLAMP_NONE;
    *what = "the slice sampler";
    if (!vk_ok(fn_.vkCreateSampler(device_, &sampler, fn_.callbacks(), &slice_linear_), "vkCreateSampler", failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_SAMPLER, slice_linear_, *what);
    sampler.magFilter = VK_FILTER_NEAREST;
    sampler.minFilter = VK_FILTER_NEAREST;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    *what = "the slice threshold sampler";
    if (!vk_ok(fn_.vkCreateSampler(device_, &sampler, fn_.callbacks(), &slice_nearest_), "vkCreateSampler", failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_SAMPLER, slice_nearest_, *what);

    const VkShaderStageFlags stages = kBladeSetStages;
    const VkDescriptorSetLayoutBinding bindings[kBindingCount] = {
        {kBindingFrame, kBlockDescriptorType, 1, stages, nullptr},
        {kBindingField, kBlockDescriptorType, 1, stages, nullptr},
        {kBindingDensityMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &sampler_},
        {kBindingSliceColor, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_linear_},
        {kBindingSliceNormal, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_linear_},
        {kBindingSliceThreshold, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_nearest_},
        {kBindingColorMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &sampler_},
        {kBindingAmbientMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &sampler_},
        {kBindingDiffuseMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &sampler_},
        {kBindingHeightMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &sampler_},
        // texelFetch ignores the sampler; a nearest one keeps RGBA32F (no linear filtering
        // guaranteed) valid.
        {kBindingInteractionMap0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_nearest_},
        {kBindingInteractionMap1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_nearest_},
        {kBindingBladeCurves, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {kBindingWindMap, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, &slice_nearest_},
        // The pass never reads the table: the compute stage sees four storage buffers with
        // its own set's (Vulkan's least maxPerStageDescriptorStorageBuffers).
        {kBindingWindowTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {kBindingWindowPoses, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
    };
    const VkPushConstantRange block_index{kBlockIndexStages, 0, kBlockIndexBytes};
    return create_set_and_pipeline_layout(
        fn_, device_, bindings, kBindingCount, target_.indexed_blocks ? &block_index : nullptr,
        "the blade descriptor set layout", "the blade pipeline layout", &set_layout_, &layout_, failure, what);
}

bool create_set_and_pipeline_layout(const Functions& fn, VkDevice device, const VkDescriptorSetLayoutBinding* bindings,
                                    uint32_t binding_count, const VkPushConstantRange* push_range, const char* set_name,
                                    const char* layout_name, VkDescriptorSetLayout* set_layout,
                                    VkPipelineLayout* layout, VkFailure* failure, const char** what) {
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = binding_count;
    set_info.pBindings = bindings;
    *what = set_name;
    if (!vk_ok(fn.vkCreateDescriptorSetLayout(device, &set_info, fn.callbacks(), set_layout),
               "vkCreateDescriptorSetLayout", failure)) {
        return false;
    }
    name_object(fn, device, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, *set_layout, set_name);
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = set_layout;
    layout_info.pushConstantRangeCount = push_range ? 1 : 0;
    layout_info.pPushConstantRanges = push_range;
    *what = layout_name;
    if (!vk_ok(fn.vkCreatePipelineLayout(device, &layout_info, fn.callbacks(), layout), "vkCreatePipelineLayout",
               failure)) {
        return false;
    }
    name_object(fn, device, VK_OBJECT_TYPE_PIPELINE_LAYOUT, *layout, layout_name);
    return true;
}

bool create_pipeline(const Functions& fn, VkDevice device, const PipelineTarget& target, VkPipelineLayout layout,
                     const PipelineShape& shape, uint32_t features, bool depth_test, VkPipeline* out_pipeline,
                     VkFailure* failure, const char** what) {
    *out_pipeline = VK_NULL_HANDLE;
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    const uint32_t* code[2] = {shape.vertex_code, shape.fragment_code};
    const size_t code_size[2] = {shape.vertex_code_size, shape.fragment_code_size};
    *what = "a shader module";
    bool ok = true;
    for (int i = 0; i < 2 && ok; ++i) {
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = code_size[i];
        info.pCode = code[i];
        ok =
            vk_ok(fn.vkCreateShaderModule(device, &info, fn.callbacks(), &modules[i]), "vkCreateShaderModule", failure);
        if (ok) name_object(fn, device, VK_OBJECT_TYPE_SHADER_MODULE, modules[i], "grass shader module");
    }

    // The shape's vertex attributes that the vertex shader reads.
    const uint32_t inputs = vertex_input_locations(shape.vertex_code, shape.vertex_code_size);
    VkVertexInputAttributeDescription attributes[16];
    VkPipelineVertexInputStateCreateInfo vertex_input = shape.vertex_input;
    vertex_input.vertexAttributeDescriptionCount = 0;
    vertex_input.pVertexAttributeDescriptions = attributes;
    for (uint32_t i = 0; i < shape.vertex_input.vertexAttributeDescriptionCount && i < 16; ++i) {
        const VkVertexInputAttributeDescription& a = shape.vertex_input.pVertexAttributeDescriptions[i];
        if (a.location < 32 && ((inputs >> a.location) & 1u))
            attributes[vertex_input.vertexAttributeDescriptionCount++] = a;
    }

    // GRASS_FEATURES (blade_interface.glsl): the map feature mask, constant id 0, both stages.
    const VkSpecializationMapEntry feature_entry{0, 0, sizeof(uint32_t)};
    VkSpecializationInfo specialization{};
    specialization.mapEntryCount = 1;
    specialization.pMapEntries = &feature_entry;
    specialization.dataSize = sizeof(uint32_t);
    specialization.pData = &features;

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = modules[0];
    stages[0].pName = "main";
    stages[0].pSpecializationInfo = &specialization;
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = modules[1];
    stages[1].pName = "main";
    stages[1].pSpecializationInfo = &specialization;

    VkPipelineInputAssemblyStateCreateInfo input_assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    input_assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    // Blades are two-sided (the fragment shader lights the side that faces the camera);
    // debug boxes are seen from above or below.
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    raster.depthBiasEnable = target.depth_only ? VK_TRUE : VK_FALSE; // a depth pass's bias: vkCmdSetDepthBias

    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = target.samples;
    multisample.alphaToCoverageEnable =
        shape.alpha_to_coverage && target.samples != VK_SAMPLE_COUNT_1_BIT && !target.depth_only ? VK_TRUE : VK_FALSE;

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = depth_test ? VK_TRUE : VK_FALSE;
    depth.depthWriteEnable = depth_test ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = target.depth_greater ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
    depth.maxDepthBounds = 1.0f;

    // The lit colour at attachment 0, opaque; a velocity target's .rg (unblended), any other
    // colour attachment of its pass untouched (write mask 0).
    const uint32_t color_count = target.depth_only ? 0 : target.color_count < 8 ? target.color_count : 8;
    VkPipelineColorBlendAttachmentState attachments[8] = {};
    attachments[0].colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (target.velocity_attachment != 0 && target.velocity_attachment < color_count)
        attachments[target.velocity_attachment].colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT;
    for (uint32_t i = 0; target.explicit_masks && i < color_count; ++i) // a G-buffer view's layout
        attachments[i].colorWriteMask = target.write_masks[i];
    VkFormat formats[8] = {target.color_format};
    for (uint32_t i = 1; i < color_count; ++i) formats[i] = target.other_formats[i - 1];
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = color_count; // a depth-only target has no colour attachment
    blend.pAttachments = color_count ? attachments : nullptr;

    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                             VK_DYNAMIC_STATE_DEPTH_BIAS};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = target.depth_only ? 3 : 2;
    dynamic.pDynamicStates = dynamic_states;

    // Dynamic rendering (Vulkan 1.3 or VK_KHR_dynamic_rendering): the formats stand in
    // for the render pass.
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.viewMask = target.view_mask; // stereo: both eyes in one pass (0: mono)
    rendering.colorAttachmentCount = color_count;
    rendering.pColorAttachmentFormats = color_count ? formats : nullptr;
    rendering.depthAttachmentFormat = target.depth_format;
    if (format_has_stencil(target.depth_format)) rendering.stencilAttachmentFormat = target.depth_format;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = target.render_pass ? nullptr : &rendering;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &input_assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    info.renderPass = target.render_pass;
    info.subpass = target.subpass;
    if (ok) {
        *what = shape.name;
        ok = vk_ok(fn.vkCreateGraphicsPipelines(device, target.cache, 1, &info, fn.callbacks(), out_pipeline),
                   "vkCreateGraphicsPipelines", failure);
        if (ok) name_object(fn, device, VK_OBJECT_TYPE_PIPELINE, *out_pipeline, shape.name);
        if (!ok) {
            if (*out_pipeline) fn.vkDestroyPipeline(device, *out_pipeline, fn.callbacks());
            *out_pipeline = VK_NULL_HANDLE;
        }
    }
    for (VkShaderModule m : modules) {
        if (m) fn.vkDestroyShaderModule(device, m, fn.callbacks());
    }
    return ok;
}

VkPipelineVertexInputStateCreateInfo instance_only_vertex_input() {
    static constexpr VkVertexInputBindingDescription binding = {0, sizeof(TierInstance), VK_VERTEX_INPUT_RATE_INSTANCE};
    static constexpr VkVertexInputAttributeDescription attributes[] = {
        {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(TierInstance, origin)},
        {6, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(TierInstance, cell)},
        {7, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(TierInstance, terrain)},
    };
    VkPipelineVertexInputStateCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    info.vertexBindingDescriptionCount = 1;
    info.pVertexBindingDescriptions = &binding;
    info.vertexAttributeDescriptionCount = sizeof(attributes) / sizeof(attributes[0]);
    info.pVertexAttributeDescriptions = attributes;
    return info;
}

} // namespace grass::vk
