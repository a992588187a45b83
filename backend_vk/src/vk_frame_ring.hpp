// Per-frame data, one copy per view slot (a view of a frame in flight, vk_desc_check.hpp): a
// persistently mapped instance buffer
// (the plan's tier instances) and a uniform buffer (the Frame block, then one Field
// block per draw, each at a multiple of minUniformBufferOffsetAlignment). A copy is
// rewritten when its slot comes round again, after the host has waited for its frame.
// Buffers grow as needed; the old ones go to the deferred deletion queue.
#pragma once

#include "foundation/frame_plan.hpp"
#include "vk_deferred.hpp"
#include "vk_desc_check.hpp"
#include "vk_memory.hpp"

#include <cstdint>

namespace grass::vk {

class FrameRing {
public:
    // uniform_alignment: the device's offset alignment of uniform buffers (the Frame and
    // Field blocks). stereo: a multiview context's Frame block, StereoUniforms after FrameUniforms.
    FrameRing(Memory& memory, DeferredDeletion& deferred, uint32_t frames_in_flight, VkDeviceSize uniform_alignment,
              bool stereo);
    ~FrameRing();
    FrameRing(const FrameRing&) = delete;
    FrameRing& operator=(const FrameRing&) = delete;

    // Makes view 0's slots' buffers (slots 0 .. frames_in_flight - 1) with a small starting
    // capacity (descriptor sets always need a uniform buffer to point at).
    bool create(VkFailure* failure, const char** what);
    // Makes slot `slot`'s buffers (another view's: view_slot()), unless it has them.
    bool create_slot(uint32_t slot, VkFailure* failure, const char** what);

    // Writes `plan` into slot `slot` as it is (its blocks are complete), growing its
    // buffers first if needed.
    // *uniforms_replaced: the slot's uniform buffer is new, so descriptor sets that point
    // at it must be rewritten. May throw std::bad_alloc.
    bool write(uint32_t slot, const FramePlan& plan, uint64_t frame, bool* uniforms_replaced, VkFailure* failure,
               const char** what);

    VkBuffer instance_buffer(uint32_t slot) const { return slots_[slot].instances.buffer; }
    VkBuffer uniform_buffer(uint32_t slot) const { return slots_[slot].uniforms.buffer; }
    // Dynamic offsets of the Frame block and of draw i's Field block.
    uint32_t frame_offset() const { return 0; }
    // The Frame block's bytes: FrameUniforms, and StereoUniforms in a stereo context.
    VkDeviceSize frame_block_bytes() const { return frame_bytes_; }
    uint32_t field_offset(uint32_t draw) const { return static_cast<uint32_t>(frame_stride_ + field_stride_ * draw); }

private:
    struct Slot {
        Buffer instances;
        Buffer uniforms;
        uint32_t instance_capacity = 0;
        uint32_t draw_capacity = 0;
    };
    bool replace_buffer(Buffer* buffer, VkDeviceSize size, VkBufferUsageFlags usage, uint64_t frame,
                        VkFailure* failure);
    bool grow_instances(Slot& s, uint32_t needed, uint64_t frame, VkFailure* failure);
    bool grow_uniforms(Slot& s, uint32_t needed, uint64_t frame, VkFailure* failure);

    Memory& memory_;
    DeferredDeletion& deferred_;
    uint32_t frames_in_flight_;
    VkDeviceSize frame_bytes_;
    VkDeviceSize frame_stride_;
    VkDeviceSize field_stride_;
    Slot slots_[kMaxViewSlots];
};

} // namespace grass::vk
