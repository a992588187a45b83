// The GrassMotion block as a motion view binds it (grass_view_motion_desc, set 1 of
// MotionPipelines' layout): per view slot (view_slot(), a view of a frame in flight) a small
// persistently mapped uniform buffer holding the view's MotionUniforms and a descriptor set
// pointing at it. Made on a slot's first motion view, from a pool of their own made on the
// first of all; written when the view is recorded (the slot's previous frame has finished,
// so neither its buffer nor its set is in use), once a frame. A context whose views never
// write motion vectors holds none of it.
#pragma once

#include "foundation/frame_plan.hpp"
#include "vk_desc_check.hpp"
#include "vk_functions.hpp"
#include "vk_memory.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

class MotionBlocks {
public:
    MotionBlocks(const Functions& functions, VkDevice device, Memory& memory)
        : fn_(functions), device_(device), memory_(memory) {}
    ~MotionBlocks() { destroy(); }
    MotionBlocks(const MotionBlocks&) = delete;
    MotionBlocks& operator=(const MotionBlocks&) = delete;

    // View slot `slot` of frame `frame` records the motion view `plan`: its block and its set
    // (of `set_layout`, made) now hold the plan's (a second record of the view in the same
    // frame writes nothing). On failure *what names what was being made.
    bool write(uint32_t slot, uint64_t frame, const FramePlan& plan, VkDescriptorSetLayout set_layout,
               VkFailure* failure, const char** what);
    VkDescriptorSet set(uint32_t slot) const { return slots_[slot].set; }
    // Whether anything was made (a test's "costs nothing").
    bool empty() const { return pool_ == VK_NULL_HANDLE; }
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
