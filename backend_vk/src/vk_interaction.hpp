// The interaction pass of responsive grass on Vulkan (api/shaders/interaction.comp, the
// design in docs/responsive.md): the interaction map, one RGBA32F image of N x N texels
// per level, always in GENERAL layout (the pass writes it as a storage image, the draws
// read it with texelFetch); the compute pipeline and its own set layout; and per frame in
// flight one buffer holding what the pass reads (each level's Interaction block, the
// colliders, each level's tile offsets and tile colliders) with a descriptor set per level.
// Nothing exists until the first frame whose plan has a pass: still grass costs nothing.
// begin_frame calls prepare() (makes what the plan needs, writes the slot's buffer and
// sets), prepare_frame calls record() (barriers and dispatches, outside the render pass).
#pragma once

#include "foundation/frame_plan.hpp"
#include "vk_deferred.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_memory.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

// Bindings of interaction.comp's descriptor set 0.
enum InteractionBinding : uint32_t {
    kInteractionBindingLevel = 0,         // uniform Interaction (InteractionLevelUniforms)
    kInteractionBindingColliders = 1,     // readonly buffer of GpuCollider
    kInteractionBindingTileOffsets = 2,   // readonly buffer of uint: tiles^2 + 1 offsets
    kInteractionBindingTileColliders = 3, // readonly buffer of uint: collider indices
    kInteractionBindingMap = 4,           // image2D, rgba32f: the level being updated
    kInteractionBindingCount = 5
};

// The map's texel format and the pass's work group (interaction.comp's local size).
constexpr VkFormat kInteractionMapFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr uint32_t kInteractionGroupSize = 8;

class InteractionPass {
public:
    InteractionPass(const Functions& functions, VkDevice device, Memory& memory, DeferredDeletion& deferred,
                    uint32_t frames_in_flight, const VkPhysicalDeviceLimits& limits);
    ~InteractionPass();
    InteractionPass(const InteractionPass&) = delete;
    InteractionPass& operator=(const InteractionPass&) = delete;

    // For frame `frame` in slot `slot`, whose plan has a pass (plan.levels > 0): makes the
    // pipeline (once), the map's images (plan.map_is_new, or none yet; the old ones are
    // retired), grows the slot's buffer, fills it and writes the slot's sets. On failure
    // *what names the object and nothing the GPU uses has changed.
    bool prepare(uint32_t slot, uint64_t frame, const InteractionPlan& plan, VkFailure* failure, const char** what);
    // Every pipeline goes through `cache` (VkBackend's: the host's or grass's own).
    void use_cache(VkPipelineCache cache) { cache_ = cache; }
    // Makes the pipeline unless it exists (grass_prepare_pipelines; prepare() otherwise).
    bool ensure_pipeline(VkFailure* failure, const char** what) {
        return pipeline_ != VK_NULL_HANDLE || create_pipeline(failure, what);
    }
    // The core dropped the map (a plan without a pass): its images and the per-frame
    // buffers are retired (frames up to `frame` may use them); the pipeline stays.
    void release(uint64_t frame);
    bool has_map() const { return levels_ > 0; }
    // Records the pass of the frame prepare() last saw in `slot` (grass_vk_prepare,
    // outside a render pass): see grass_vk.h for the barriers.
    void record(VkCommandBuffer cmd, uint32_t slot, const InteractionPlan& plan);

    // The map's level `level` (a level the map lacks: level 0), VK_NULL_HANDLE before the
    // first pass. Read in VK_IMAGE_LAYOUT_GENERAL.
    VkImageView level_view(uint32_t level) const;
    // Whether the map's contents are defined (its first pass recorded: a cleared map).
    bool map_ready() const { return levels_ > 0 && defined_; }
    // The blade window's state inputs (vk_blade_window.hpp WindowStateBinding) from slot
    // `slot`'s buffer as prepare() laid it out: the colliders and the fine level's tile
    // offsets, tile colliders and Interaction block. False before the slot has a buffer.
    bool state_inputs(uint32_t slot, VkDescriptorBufferInfo out[4]) const;
    // GPU bytes of the map's images.
    uint64_t map_bytes() const;

private:
    struct Slot {
        Buffer data;                                          // uniforms, colliders, tiles (streaming)
        VkDescriptorSet sets[2] = {};                         // per level
        VkDeviceSize offsets[kInteractionBindingMap][2] = {}; // per buffer binding, per level
        VkDeviceSize ranges[kInteractionBindingMap][2] = {};
    };
    bool create_pipeline(VkFailure* failure, const char** what);
    bool create_map(const InteractionPlan& plan, uint64_t frame, VkFailure* failure, const char** what);
    // Lays out the slot's buffer for `plan` (offsets, ranges) and returns its size.
    VkDeviceSize layout(Slot& s, const InteractionPlan& plan) const;

    const Functions& fn_;
    VkDevice device_;
    Memory& memory_;
    DeferredDeletion& deferred_;
    uint32_t frames_in_flight_;
    VkDeviceSize uniform_alignment_;
    VkDeviceSize storage_alignment_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE; // 2 sets per frame in flight, never freed one by one
    Image maps_[2];
    uint32_t levels_ = 0;        // levels of the map's images
    uint32_t resolution_ = 0;    // N
    bool defined_ = false;       // a pass has been recorded since the images were made
    bool clear_pending_ = false; // made, not yet cleared: record() clears before the pass
    Slot slots_[kMaxFramesInFlight];
};

} // namespace grass::vk
