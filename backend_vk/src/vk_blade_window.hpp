// The blade window pass of responsive grass on Vulkan (docs/responsive.md "The blade window",
// api/src/plan/blade_window.hpp, api/shaders/blade_window.comp): once per frame, in
// grass_vk_prepare after the interaction pass, one dispatch per responsive geometry draw of
// view 0 that the core gave slots writes the pose of every blade of its instances; every
// view's window variant (kFeatureBladeWindow) then reads them in blade.vert.
//
// What it owns: the compute pipelines (one per kBladeWindowPassFeatures mask a draw has, the
// GRASS_INDEXED_BLOCKS module where the device wants it), their layout (set 0: the blade set
// layout, so the pass binds the same set as its draw; set 1: the pass's own, WindowPassBinding),
// the records (one device-local buffer, sized by the plan's pose_bytes, shared by every frame
// in flight with the barriers of grass_vk.h: pose, previous pose and Jahrmann's state per blade,
// kept when it grows) and the table and work items (streaming buffers per frame slot, sized by
// the plan's, written by the CPU each frame; all grown together). One window,
// not one per frame in flight: the poses are written and read on the GPU only, so a barrier
// orders a frame's pass after the earlier frames' draws, and the memory (up to
// kMaxBladeWindowPoseBytes) is taken once. Nothing exists until the first frame whose plan
// has a window: still grass costs nothing.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"
#include "vk_deferred.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_memory.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

// Bindings of blade_window.comp's set 1, the pass's own (set 0 is the blade layout, as its
// draw's). A binding the pass gains (a per-blade state, the colliders) is a row here, one in
// set_bindings() and one in write_dispatch_set() (vk_blade_window.cpp).
enum WindowPassBinding : uint32_t {
    kWindowPassBindingInstances = 0, // view 0's instances (TierInstance), a storage buffer
    kWindowPassBindingVertices = 1,  // the draw's patch's vertices (BladeVertex), a storage buffer
    kWindowPassBindingWork = 2,      // the plan's work items (slot, instance), a storage buffer
    kWindowPassBindingCount = 3
};
constexpr uint32_t kWindowPassSet = 1;
// Bindings of set 2: what the state's push-out reads, the interaction pass's buffers of its
// fine level (vk_interaction.hpp), one set per frame slot; without colliders the work items
// stand in (the shader reads none of them then).
enum WindowStateBinding : uint32_t {
    kWindowStateBindingColliders = 0,     // GpuCollider, a storage buffer
    kWindowStateBindingTileOffsets = 1,   // the fine level's tile offsets, a storage buffer
    kWindowStateBindingTileColliders = 2, // the fine level's tile colliders, a storage buffer
    kWindowStateBindingLevel = 3,         // the fine level's Interaction block, a uniform buffer
    kWindowStateBindingCount = 4
};
constexpr uint32_t kWindowStateSet = 2;
// Storage buffers the pass's compute stage sees in all: the blade set's curves and records,
// set 1's three and set 2's three. A device with fewer per stage runs no window.
constexpr uint32_t kWindowPassStorageBuffers = 8;
constexpr uint32_t kWindowGroupSize = 64; // local_size_x of blade_window.comp

// One dispatch of the pass: a draw's sets and dynamic offsets, its features (the pipeline's
// specialisation), and its size (blades x instances).
struct WindowDispatch {
    VkDescriptorSet blade_set; // set 0: the draw's (Frame, Field, maps, curves, poses)
    VkDescriptorSet pass_set;  // set 1: instances, the patch's vertices and the work items
    uint32_t block_offsets[2]; // Frame and Field
    uint32_t features;         // the draw's features within kBladeWindowPassFeatures
    uint32_t blades;           // the patch's blades
    uint32_t items;            // the dispatch's work items (instances the window holds)
};

class BladeWindowPass {
public:
    BladeWindowPass(const Functions& functions, VkDevice device, Memory& memory, DeferredDeletion& deferred,
                    uint32_t frames_in_flight, bool indexed_blocks, HostAllocator* host);
    ~BladeWindowPass();
    BladeWindowPass(const BladeWindowPass&) = delete;
    BladeWindowPass& operator=(const BladeWindowPass&) = delete;

    // Every pipeline goes through `cache` (VkBackend's: the host's or grass's own).
    void use_cache(VkPipelineCache cache) { cache_ = cache; }
    // The pipeline of the draw features `features` (masked to kBladeWindowPassFeatures), and
    // the layouts on first use (`blade_set`: set 0's). May throw std::bad_alloc before anything
    // is made. On failure *what names the object.
    bool ensure_pipeline(VkDescriptorSetLayout blade_set, uint32_t features, VkFailure* failure, const char** what);
    // For frame `frame` in slot `slot`, whose plan has a window: grows the poses to the plan's
    // pose_bytes (the old buffer retired: frames in flight read it) and the slot's table to the
    // plan's, and writes the table. On failure *what names the object; nothing the GPU uses changed.
    bool prepare(uint32_t slot, uint64_t frame, const BladeWindowPlan& plan, VkFailure* failure, const char** what);
    // A plan without a window: the buffers are retired (frames up to `frame` may use them).
    void release(uint64_t frame);
    // Points slot `slot`'s state set at the interaction pass's fine-level buffers (`inputs`,
    // kWindowStateBindingCount of them), or at stand-ins when `inputs` is null (no colliders).
    void write_state_set(uint32_t slot, const VkDescriptorBufferInfo* inputs) const;
    bool has_window() const { return poses_.buffer != VK_NULL_HANDLE; }
    VkBuffer table(uint32_t slot) const { return tables_[slot].buffer; }
    VkBuffer poses() const { return poses_.buffer; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; } // set 1 (after ensure_pipeline)
    // Points `set` (of set_layout()) at view 0's `instances`, the patch's `vertices` and slot
    // `slot`'s work items.
    void write_dispatch_set(VkDescriptorSet set, uint32_t slot, VkBuffer instances, VkBuffer vertices) const;
    // Records the barriers and dispatches of grass_vk.h (every dispatch's pipeline made), after
    // the copy of the records into a grown buffer where prepare() grew it.
    void record(VkCommandBuffer cmd, uint32_t slot, const WindowDispatch* dispatches, uint32_t count);
    // GPU bytes of the poses and the tables.
    uint64_t bytes() const;

private:
    struct Pipeline {
        uint32_t features;
        VkPipeline pipeline;
    };
    VkPipeline pipeline(uint32_t features) const;
    bool create_layouts(VkDescriptorSetLayout blade_set, VkFailure* failure, const char** what);
    bool create_state_sets(VkFailure* failure, const char** what);
    // Grows the slots' buffers in `buffers` (tables or work items) to hold `bytes`.
    bool grow_streaming(Buffer* buffers, VkDeviceSize bytes, uint64_t frame, const char* name, VkFailure* failure);

    const Functions& fn_;
    VkDevice device_;
    Memory& memory_;
    DeferredDeletion& deferred_;
    uint32_t frames_in_flight_;
    bool indexed_blocks_;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;   // set 1
    VkPipelineLayout layout_ = VK_NULL_HANDLE;            // sets 0 and 1
    Vector<Pipeline> pipelines_;                          // per features, made on first use
    Buffer poses_;                                        // device-local, every frame's
    Buffer tables_[kMaxFramesInFlight];                   // streaming, per frame slot, all of one size
    Buffer works_[kMaxFramesInFlight];                    // likewise: the work items
    VkDescriptorSetLayout state_layout_ = VK_NULL_HANDLE; // set 2
    VkDescriptorPool state_pool_ = VK_NULL_HANDLE;        // one state set per frame slot
    VkDescriptorSet state_sets_[kMaxFramesInFlight] = {};
    VkBuffer grown_from_ = VK_NULL_HANDLE; // the records before they grew (retired), to copy
    VkDeviceSize grown_bytes_ = 0;         // how many bytes to copy
};

} // namespace grass::vk
