// The pipelines of views that write motion vectors (grass_view_motion_desc, kFeatureMotion):
// blades, volume and image, per colour feature mask, with the depth test and without, from
// the GRASS_VELOCITY modules (blade.vert, blade.frag, volume.frag, image.frag; motion.glsl).
// They draw in the host's pass of several colour attachments (grass_vk_velocity_target_desc,
// PipelineTarget::color_count): attachment 0 the lit colour as the other pipelines write it,
// the velocity attachment .rg unblended, every other attachment write mask 0. The fragment
// module's velocity output (location 1 as compiled) is moved to the velocity attachment's
// index before the module is made (relocate_output). Their pipeline layout is the blade
// layout's set 0 and push constants plus set 1: the GrassMotion block (a uniform buffer,
// vertex and fragment stages). Everything here is made on the first motion view: a context
// whose views never write motion vectors holds none of it. BladePipeline owns one.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"
#include "vk_functions.hpp"
#include "vk_result.hpp"

#include <cstddef>
#include <cstdint>

namespace grass::vk {

struct PipelineTarget; // vk_pipeline.hpp, which includes this header
struct SpirvVariant;

// Set 1 of a motion pipeline layout (motion.glsl under VULKAN), binding 0: the GrassMotion block.
constexpr uint32_t kMotionSet = 1;
constexpr uint32_t kBindingMotionBlock = 0;
constexpr uint32_t kMotionPipelineKinds = 3;               // blades, volume, image: a debug view writes none
constexpr uint32_t kMotionColourMasks = kFeatureDepthPass; // the colour feature masks (kColourFeatureMasks)

// `code` (SPIR-V of a fragment shader, `words` long) with the Location decoration of its
// Output variable at location `from` set to `to`. False when it has no such output.
bool relocate_output(uint32_t* code, size_t words, uint32_t from, uint32_t to);

class MotionPipelines {
public:
    MotionPipelines(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), host_(host), pipelines_(StlAllocator<VkPipeline>(host)) {}
    ~MotionPipelines() { destroy(); }
    MotionPipelines(const MotionPipelines&) = delete;
    MotionPipelines& operator=(const MotionPipelines&) = delete;

    // Makes the pipeline of `variant` (with kFeatureMotion; blades, volume or image) from the
    // GRASS_VELOCITY modules of `modules` against `target` (its color_count attachments), with
    // the depth test or without it, unless it exists; the layouts and the table first, on the
    // first call (`blade_set`: set 0's layout; the table may throw std::bad_alloc). On failure
    // it does not exist and *what names what was being made.
    bool create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set, const ShaderVariant& variant,
                        const SpirvVariant& modules, bool depth_test, VkFailure* failure, const char** what);
    bool has_variant(const ShaderVariant& v, bool depth_test) const {
        const VkPipeline* p = slot(v.program, v.features, depth_test);
        return p != nullptr && *p != VK_NULL_HANDLE;
    }
    // The pipeline of `kind` for `features` (has_variant).
    VkPipeline pipeline(uint32_t kind, uint32_t features, bool depth_test) const {
        return *slot(kind, features, depth_test);
    }
    // VK_NULL_HANDLE until the first motion view.
    VkPipelineLayout layout() const { return layout_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    void destroy();

private:
    bool create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set, VkFailure* failure,
                        const char** what);
    // [colour features][kind][0 = depth tested, 1 = depth off], or nullptr outside the table.
    const VkPipeline* slot(uint32_t kind, uint32_t features, bool depth_test) const {
        const uint32_t colour = features & ~kFeatureMotion;
        if (pipelines_.empty() || kind >= kMotionPipelineKinds || colour >= kMotionColourMasks) return nullptr;
        return &pipelines_[(colour * kMotionPipelineKinds + kind) * 2 + (depth_test ? 0 : 1)];
    }

    const Functions& fn_;
    VkDevice device_;
    HostAllocator* host_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE; // set 1
    VkPipelineLayout layout_ = VK_NULL_HANDLE;          // sets 0 and 1
    Vector<VkPipeline> pipelines_;                      // empty until the first motion view
};

} // namespace grass::vk
