// The host's shadow map as a receiving view binds it (grass_shadow_receive_desc, set 1 of
// ReceivePipelines' layout): per view slot (view_slot(), a view of a frame in flight) a small
// persistently mapped uniform buffer holding the view's GrassShadow block (ShadowUniforms) and
// a descriptor set pointing at it and at the host's image view with the compare sampler of the
// host's convention. Made on a slot's first receiving view, from a pool of their own made on
// the first of all; written when the view is recorded (the slot's previous frame has
// finished, so neither its buffer nor its set is in use), once a frame.
#pragma once

#include "foundation/frame_plan.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_memory.hpp"
#include "vk_receive_pipelines.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

class HostShadowSets {
public:
    HostShadowSets(const Functions& functions, VkDevice device, Memory& memory)
        : fn_(functions), device_(device), memory_(memory) {}
    ~HostShadowSets() { destroy(); }
    HostShadowSets(const HostShadowSets&) = delete;
    HostShadowSets& operator=(const HostShadowSets&) = delete;

    // View slot `slot` of frame `frame` records the receiving view `plan`: its block and its
    // set (pipelines.set_layout(): made) now hold the plan's (a second record of the view in
    // the same frame writes nothing). On failure *what names what was being made.
    bool write(uint32_t slot, uint64_t frame, const FramePlan& plan, const ReceivePipelines& pipelines,
               VkFailure* failure, const char** what);
    VkDescriptorSet set(uint32_t slot) const { return slots_[slot].set; }
    void destroy();

private:
    struct Slot {
        Buffer block;
        VkDescriptorSet set = VK_NULL_HANDLE;
        uint64_t written = 0; // the frame whose plan the block and the set hold (0: none)
    };
    const Functions& fn_;
    VkDevice device_;
    Memory& memory_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE; // room for a set per view slot
    Slot slots_[kMaxViewSlots];
};

} // namespace grass::vk
