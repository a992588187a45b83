// The pipelines of views that receive the host's shadow maps (grass_shadow_receive_desc,
// kFeatureShadowReceive): blades, volume and image, per colour feature mask, with the depth
// test and without, their fragment shaders the GRASS_HOST_SHADOWS modules (vk_spirv.hpp).
// Their pipeline layout is the blade layout's set 0 and push constants plus set 1: the
// GrassShadow block (a uniform buffer) and the host's map (a combined image sampler) of
// host_shadows.glsl. Everything here (the two depth-compare samplers, the set layout, the
// pipeline layout and the table) is made on the first receiving view: a context whose views
// never receive holds none of it. BladePipeline owns one and hands it the receiving variants.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"
#include "vk_functions.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

struct PipelineTarget; // vk_pipeline.hpp, which includes this header
struct PipelineShape;

// Set 1 of a receiving pipeline layout (host_shadows.glsl under VULKAN).
constexpr uint32_t kShadowSet = 1;
enum ShadowBinding : uint32_t { kBindingShadowBlock = 0, kBindingShadowMap = 1, kShadowBindingCount = 2 };
constexpr uint32_t kReceivePipelineKinds = 3;               // blades, volume, image: a debug view receives nothing
constexpr uint32_t kReceiveColourMasks = kFeatureDepthPass; // the colour feature masks (kColourFeatureMasks)

class ReceivePipelines {
public:
    ReceivePipelines(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), pipelines_(StlAllocator<VkPipeline>(host)) {}
    ~ReceivePipelines() { destroy(); }
    ReceivePipelines(const ReceivePipelines&) = delete;
    ReceivePipelines& operator=(const ReceivePipelines&) = delete;

    // Makes the pipeline of `variant` (with kFeatureShadowReceive; blades, volume or image)
    // from `shape` (its GRASS_HOST_SHADOWS modules) against `target`, with the depth test or
    // without it, unless it exists; the samplers, the layouts and the table first, on the
    // first call (`blade_set`: set 0's layout; the table may throw std::bad_alloc). On
    // failure it does not exist and *what names what was being made.
    bool create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set, const ShaderVariant& variant,
                        const PipelineShape& shape, bool depth_test, VkFailure* failure, const char** what);
    bool has_variant(const ShaderVariant& v, bool depth_test) const {
        const VkPipeline* p = slot(v.program, v.features, depth_test);
        return p != nullptr && *p != VK_NULL_HANDLE;
    }
    // The pipeline of `kind` for `features` (has_variant).
    VkPipeline pipeline(uint32_t kind, uint32_t features, bool depth_test) const {
        return *slot(kind, features, depth_test);
    }
    // VK_NULL_HANDLE until the first receiving view.
    VkPipelineLayout layout() const { return layout_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    // The depth-compare sampler of the host's convention: lit where the point's depth is
    // <= the stored one (GRASS_SHADOW_COMPARE_LESS_EQUAL), or >= (`greater`).
    VkSampler sampler(bool greater) const { return samplers_[greater ? 1 : 0]; }
    void destroy();

private:
    bool create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set, VkFailure* failure,
                        const char** what);
    // [colour features][kind][0 = depth tested, 1 = depth off], or nullptr outside the table.
    const VkPipeline* slot(uint32_t kind, uint32_t features, bool depth_test) const {
        const uint32_t colour = features & ~kFeatureShadowReceive;
        if (pipelines_.empty() || kind >= kReceivePipelineKinds || colour >= kReceiveColourMasks) return nullptr;
        return &pipelines_[(colour * kReceivePipelineKinds + kind) * 2 + (depth_test ? 0 : 1)];
    }

    const Functions& fn_;
    VkDevice device_;
    VkSampler samplers_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE}; // LESS_OR_EQUAL, GREATER_OR_EQUAL
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;        // set 1
    VkPipelineLayout layout_ = VK_NULL_HANDLE;                 // sets 0 and 1
    Vector<VkPipeline> pipelines_;                             // empty until the first receiving view
};

} // namespace grass::vk
