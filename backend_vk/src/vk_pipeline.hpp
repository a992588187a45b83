// The blade pipeline: descriptor set layout (Frame and Field uniform blocks as dynamic
// uniform buffers, the density map with an immutable linear clamp sampler, the baked
// slices of the volume and image tiers with immutable trilinear / nearest samplers),
// pipeline layout, and two graphics pipelines, with and without the depth test; and the state
// every pipeline of the backend shares (create_pipeline_pair).
#pragma once

#include "vk_functions.hpp"
#include "vk_result.hpp"

#include <cstddef>
#include <cstdint>

namespace grass::vk {

// Binding numbers of blade_interface.glsl, descriptor set 0.
enum BladeBinding : uint32_t {
    kBindingFrame = 0,
    kBindingField = 1,
    kBindingDensityMap = 2,
    kBindingSliceColor = 3,
    kBindingSliceNormal = 4,
    kBindingSliceThreshold = 5,
    kBindingCount = 6
};

struct PipelineTarget {
    VkRenderPass render_pass = VK_NULL_HANDLE; // VK_NULL_HANDLE: dynamic rendering with the formats
    uint32_t subpass = 0;
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool depth_greater = false;                // reversed-Z host: GREATER_OR_EQUAL
};

// What differs between the graphics pipelines of the backend; the rest (viewport and
// scissor dynamic, no culling, opaque colour, the target's samples and formats) is shared.
struct PipelineShape {
    const uint32_t* vertex_code;
    size_t vertex_code_size; // bytes
    const uint32_t* fragment_code;
    size_t fragment_code_size;
    const VkPipelineVertexInputStateCreateInfo* vertex_input;
    bool alpha_to_coverage; // only with multisampling
    const char* name;       // for *what: "the blade pipelines"
};

// Index 0 of out_pipelines depth-tests and writes depth (the target's compare op), index 1
// does neither. On failure both are VK_NULL_HANDLE.
// The vertex input of the shaders that read instances only (locations 5 and 6 on binding
// 0: debug_tiers, volume and image): its arrays live as long as the program.
VkPipelineVertexInputStateCreateInfo instance_only_vertex_input();

bool create_pipeline_pair(const Functions& fn, VkDevice device, const PipelineTarget& target, VkPipelineLayout layout,
                          const PipelineShape& shape, VkPipeline out_pipelines[2], VkFailure* failure,
                          const char** what);

class BladePipeline {
public:
    BladePipeline(const Functions& functions, VkDevice device) : fn_(functions), device_(device) {}
    ~BladePipeline() { destroy(); }
    BladePipeline(const BladePipeline&) = delete;
    BladePipeline& operator=(const BladePipeline&) = delete;

    // *what names the object being made when it fails.
    bool create(const PipelineTarget& target, VkFailure* failure, const char** what);
    void destroy();

    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipeline pipeline(bool depth_test) const { return depth_test ? depth_tested_ : depth_off_; }

private:
    bool create_layouts(VkFailure* failure, const char** what);
    bool create_pipelines(const PipelineTarget& target, VkFailure* failure, const char** what);

    const Functions& fn_;
    VkDevice device_;
    VkSampler sampler_ = VK_NULL_HANDLE;         // density maps: bilinear, one mip
    VkSampler slice_linear_ = VK_NULL_HANDLE;    // slice colour and normal: trilinear
    VkSampler slice_nearest_ = VK_NULL_HANDLE;   // slice thresholds: never blended
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline depth_tested_ = VK_NULL_HANDLE;
    VkPipeline depth_off_ = VK_NULL_HANDLE;
};

} // namespace grass::vk
