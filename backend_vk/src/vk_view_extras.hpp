// The pipelines of views with extras: those that receive the host's shadow maps
// (grass_shadow_receive_desc, kFeatureShadowReceive), those that write motion vectors
// (grass_view_motion_desc, kFeatureMotion), those lit by the host's lights
// (grass_view_lights_desc, kFeatureHostLights), and those with several of them (the main view
// of a host with shadows, lights and temporal anti-aliasing has all three). Blades, volume and
// image, per colour feature mask, with the depth test and without, their modules the
// GRASS_HOST_SHADOWS, GRASS_VELOCITY and GRASS_HOST_LIGHTS variants (vk_spirv.hpp). One
// pipeline layout serves them all: the blade layout's set 0 and push constants plus
// - set 1, the view's blocks: binding 0 the GrassMotion block (a uniform buffer, vertex and
//   fragment; motion.glsl), binding 1 the GrassShadow block (a uniform buffer, fragment
//   stage; host_shadows.glsl), binding 2 the GrassLights block (a uniform buffer, fragment
//   stage; host_lights.glsl), binding 3 the GrassGBuffer block of a G-buffer view (a uniform
//   buffer, fragment stage; gbuffer.glsl; its pipelines: vk_gbuffer.hpp);
// - set 2, the host's map (binding 0: a combined image sampler with a depth-compare sampler),
//   bound by receiving views alone (a motion view has no map to write, and lavapipe, Mesa
//   22.3, crashed executing the draws of motion views whose set 1 held the map unwritten,
//   which Vulkan allows for a binding the pipeline does not use).
// Lavapipe (Mesa 22.3) also crashed on the first responsive motion draw (wind, blade.vert)
// while the GrassMotion block, the one binding of set 1 the vertex stage reads, came after
// the fragment-only GrassShadow block; with it at binding 0 it draws.
// A pipeline statically uses the bindings of its features alone; ViewExtrasSets writes
// them (and a stand-in for the other block). Motion pipelines draw in the host's pass of several
// colour attachments (grass_vk_velocity_target_desc, PipelineTarget::color_count): attachment
// 0 the lit colour, the velocity attachment .rg unblended, every other write mask 0; their
// fragment module's velocity output (location 1 as compiled) is moved to the velocity
// attachment's index before the module is made (relocate_output).
// Everything is made lazily: the layouts on the first view with any extra, the samplers on
// the first receiving view, each combination's table (any non-empty set of the three) on its
// first view: a context whose views use none holds nothing of it. BladePipeline owns one.
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
struct PipelineShape;

// The feature bits of a view's extras.
constexpr uint32_t kViewExtras = kFeatureShadowReceive | kFeatureMotion | kFeatureHostLights;
// Sets 1 and 2 of the extras' pipeline layout (host_shadows.glsl and motion.glsl under VULKAN).
constexpr uint32_t kExtrasSet = 1;
enum ExtrasBinding : uint32_t {
    kBindingMotionBlock = 0,
    kBindingShadowBlock = 1,
    kBindingLightsBlock = 2,
    kBindingGBufferBlock = 3, // a G-buffer view's GrassGBuffer block (gbuffer.glsl; vk_gbuffer.hpp)
    kExtrasBindingCount = 4
};
constexpr uint32_t kShadowMapSet = 2;
constexpr uint32_t kBindingShadowMap = 0;
static_assert(kShadowMapSet == kExtrasSet + 1, "a receiving view binds both at once (vk_record.cpp)");
constexpr uint32_t kExtrasPipelineKinds = 3;               // blades, volume, image: a debug view has no extras
constexpr uint32_t kExtrasColourMasks = kFeatureDepthPass; // the colour feature masks (kColourFeatureMasks)
constexpr uint32_t kExtrasCombinations = 7;                // the non-empty sets of receive, motion, lights

// Whether `id` is an OpVariable of the Output storage class in `code` (SPIR-V, `words` long).
bool is_output_variable(const uint32_t* code, size_t words, uint32_t id);

// `code` (SPIR-V of a fragment shader, `words` long) with the Location decoration of its
// Output variable at location `from` set to `to`. False when it has no such output.
bool relocate_output(uint32_t* code, size_t words, uint32_t from, uint32_t to);

class ViewExtrasPipelines {
public:
    ViewExtrasPipelines(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), host_(host), pipelines_{Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host)),
                                                                   Vector<VkPipeline>(StlAllocator<VkPipeline>(host))} {
    }
    ~ViewExtrasPipelines() { destroy(); }
    ViewExtrasPipelines(const ViewExtrasPipelines&) = delete;
    ViewExtrasPipelines& operator=(const ViewExtrasPipelines&) = delete;

    // Makes the pipeline of `variant` (with any of kFeatureShadowReceive, kFeatureMotion and
    // kFeatureHostLights;
    // blades, volume or image) from `shape` (its modules of those features) against `target`
    // (with motion: the velocity target), with the depth test or without it, unless it
    // exists; the layouts, the samplers (receiving) and the combination's table first, on
    // the first call that needs them (`blade_set`: set 0's layout; a table may throw
    // std::bad_alloc). On failure it does not exist and *what names what was being made.
    // `into` (a blade window variant's, kFeatureBladeWindow): the pipeline goes there, not
    // into the combination's table.
    bool create_variant(const PipelineTarget& target, VkDescriptorSetLayout blade_set, const ShaderVariant& variant,
                        const PipelineShape& shape, bool depth_test, VkFailure* failure, const char** what,
                        VkPipeline* into = nullptr);
    bool has_variant(const ShaderVariant& v, bool depth_test) const {
        const VkPipeline* p = slot(v.program, v.features, depth_test);
        return p != nullptr && *p != VK_NULL_HANDLE;
    }
    // The pipeline of `kind` for `features` (has_variant).
    VkPipeline pipeline(uint32_t kind, uint32_t features, bool depth_test) const {
        return *slot(kind, features, depth_test);
    }
    // VK_NULL_HANDLE until the first view with extras.
    VkPipelineLayout layout() const { return layout_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; }         // set 1
    VkDescriptorSetLayout map_set_layout() const { return map_set_layout_; } // set 2
    // The depth-compare sampler of the host's convention: lit where the point's depth is
    // <= the stored one (GRASS_SHADOW_COMPARE_LESS_EQUAL), or >= (`greater`). VK_NULL_HANDLE
    // until the first receiving view.
    VkSampler sampler(bool greater) const { return samplers_[greater ? 1 : 0]; }
    // Whether anything was made (a test's "costs nothing").
    bool empty() const { return layout_ == VK_NULL_HANDLE && samplers_[0] == VK_NULL_HANDLE; }
    void destroy();
    // The layouts, unless made (a G-buffer view's pipelines share them: vk_gbuffer.hpp).
    bool create_layouts(const PipelineTarget& target, VkDescriptorSetLayout blade_set, VkFailure* failure,
                        const char** what);

private:
    bool create_samplers(VkFailure* failure, const char** what);
    // The combination's table: [colour features][kind][0 = depth tested, 1 = depth off]
    // (the extras' bits above bit 11, less one: receive 0, motion 1, both 2, lights 3, ...).
    static uint32_t combination(uint32_t features) { return ((features & kViewExtras) >> 11) - 1; }
    static_assert(kFeatureShadowReceive == 1u << 11 && kFeatureMotion == 1u << 12 && kFeatureHostLights == 1u << 13,
                  "combination()");
    const VkPipeline* slot(uint32_t kind, uint32_t features, bool depth_test) const {
        const uint32_t colour = features & ~kViewExtras;
        if ((features & kViewExtras) == 0 || kind >= kExtrasPipelineKinds || colour >= kExtrasColourMasks)
            return nullptr;
        const Vector<VkPipeline>& table = pipelines_[combination(features)];
        if (table.empty()) return nullptr;
        return &table[(colour * kExtrasPipelineKinds + kind) * 2 + (depth_test ? 0 : 1)];
    }

    const Functions& fn_;
    VkDevice device_;
    HostAllocator* host_;
    VkSampler samplers_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE}; // LESS_OR_EQUAL, GREATER_OR_EQUAL
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;        // set 1
    VkDescriptorSetLayout map_set_layout_ = VK_NULL_HANDLE;    // set 2
    VkPipelineLayout layout_ = VK_NULL_HANDLE;                 // sets 0, 1 and 2
    Vector<VkPipeline> pipelines_[kExtrasCombinations];        // each empty until its first view
};

} // namespace grass::vk
