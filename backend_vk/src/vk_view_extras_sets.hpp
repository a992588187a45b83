// A view's extras as its draws bind them (sets 1 and 2 of ViewExtrasPipelines' layout): per
// view slot (view_slot(), a view of a frame in flight) a descriptor set of the view's blocks
// (set 1) and the small persistently mapped uniform buffers behind it: the GrassShadow block
// (ShadowUniforms) of a view that receives the host's shadow maps, the GrassMotion block
// (MotionUniforms) of a view that writes motion vectors, the GrassLights block
// (LightUniforms) of a view lit by the host's lights and the GrassGBuffer block
// (GBufferUniforms) of a G-buffer view; and for a receiving view a set of the
// host's image view with the compare sampler of the host's convention (set 2). Every binding
// of set 1 is written (a block a view does not use points at one it uses, so no bound set
// holds an unwritten descriptor); set 2 only by a receiving view, which alone binds it.
// Each block and the map's set are made on their slot's first view with that feature, set 1
// on the slot's first view with any, the pool on the first of all; written when the view
// is recorded (the slot's previous frame has finished, so neither its buffers nor its sets
// are in use), once a frame. A context whose views use none holds none of it.
#pragma once

#include "foundation/frame_plan.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_memory.hpp"
#include "vk_result.hpp"
#include "vk_view_extras.hpp"

#include <cstdint>

namespace grass::vk {

class ViewExtrasSets {
public:
    ViewExtrasSets(const Functions& functions, VkDevice device, Memory& memory)
        : fn_(functions), device_(device), memory_(memory) {}
    ~ViewExtrasSets() { destroy(); }
    ViewExtrasSets(const ViewExtrasSets&) = delete;
    ViewExtrasSets& operator=(const ViewExtrasSets&) = delete;

    // View slot `slot` of frame `frame` records `plan`, a view that receives shadows, writes
    // motion vectors, is lit by the host's lights or several of these: its blocks and its set (pipelines.set_layout(): made) now hold
    // the plan's (a second record of the view in the same frame writes nothing). On failure
    // *what names what was being made.
    bool write(uint32_t slot, uint64_t frame, const FramePlan& plan, const ViewExtrasPipelines& pipelines,
               VkFailure* failure, const char** what);
    VkDescriptorSet set(uint32_t slot) const { return slots_[slot].set; }         // set 1
    VkDescriptorSet map_set(uint32_t slot) const { return slots_[slot].map_set; } // set 2: receiving
    // Whether anything was made (a test's "costs nothing").
    bool empty() const { return pool_ == VK_NULL_HANDLE; }
    void destroy();

private:
    struct Slot {
        Buffer blocks[kExtrasBindingCount];   // [ExtrasBinding]: GrassMotion, GrassShadow, GrassLights, GrassGBuffer
        VkDescriptorSet set = VK_NULL_HANDLE; // set 1: the blocks
        VkDescriptorSet map_set = VK_NULL_HANDLE; // set 2: the host's map
        uint64_t written = 0;                     // the frame whose plan the blocks and the set hold (0: none)
    };
    bool allocate(VkDescriptorSetLayout layout, VkDescriptorSet* set, const char* name, VkFailure* failure,
                  const char** what);
    bool create_block(Buffer* block, VkDeviceSize bytes, const char* name, VkFailure* failure, const char** what);
    const Functions& fn_;
    VkDevice device_;
    Memory& memory_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE; // room for both sets per view slot
    Slot slots_[kMaxViewSlots];
};

} // namespace grass::vk
