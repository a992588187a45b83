#include "vk_frame_ring.hpp"

#include <cstring>

namespace grass::vk {

namespace {
constexpr uint32_t kInitialInstances = 256;
constexpr uint32_t kInitialDraws = 16;

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

// Doubles until `needed` fits, so that a growing scene reallocates a few times only.
uint32_t grown_capacity(uint32_t current, uint32_t needed) {
    uint64_t capacity = current ? current : needed;
    while (capacity < needed) capacity *= 2;
    return capacity > 0xffffffffu ? needed : static_cast<uint32_t>(capacity);
}
} // namespace

FrameRing::FrameRing(Memory& memory, DeferredDeletion& deferred, uint32_t frames_in_flight,
                     VkDeviceSize uniform_alignment, bool stereo)
    : memory_(memory), deferred_(deferred), frames_in_flight_(frames_in_flight),
      frame_bytes_(sizeof(FrameUniforms) + (stereo ? sizeof(StereoUniforms) : 0)),
      frame_stride_(align_up(frame_bytes_, uniform_alignment ? uniform_alignment : 1)),
      field_stride_(align_up(sizeof(FieldUniforms), uniform_alignment ? uniform_alignment : 1)) {}

FrameRing::~FrameRing() {
    for (Slot& s : slots_) {
        deferred_.destroy_now(&s.instances);
        deferred_.destroy_now(&s.uniforms);
    }
}

bool FrameRing::create(VkFailure* failure, const char** what) {
    for (uint32_t i = 0; i < frames_in_flight_; ++i) {
        if (!create_slot(i, failure, what)) return false;
    }
    return true;
}

bool FrameRing::create_slot(uint32_t slot, VkFailure* failure, const char** what) {
    Slot& s = slots_[slot];
    *what = "a per-frame instance buffer";
    if (s.instance_capacity == 0 && !grow_instances(s, kInitialInstances, 0, failure)) return false;
    *what = "a per-frame uniform buffer";
    return s.draw_capacity > 0 || grow_uniforms(s, kInitialDraws, 0, failure);
}

bool FrameRing::replace_buffer(Buffer* buffer, VkDeviceSize size, VkBufferUsageFlags usage, uint64_t frame,
                               VkFailure* failure) {
    // The old buffer may still be read by frames in flight: it waits in the deferred
    // deletion queue (in the place its creation reserved, so that retiring cannot throw).
    Buffer fresh;
    if (!deferred_.create_buffer(size, usage, MemoryUse::streaming, &fresh, failure)) return false;
    deferred_.retire(buffer, frame);
    *buffer = fresh;
    return true;
}

bool FrameRing::grow_instances(Slot& s, uint32_t needed, uint64_t frame, VkFailure* failure) {
    const uint32_t capacity = grown_capacity(s.instance_capacity, needed);
    // A storage buffer too: the blade window pass reads view 0's instances (vk_blade_window.hpp).
    if (!replace_buffer(&s.instances, VkDeviceSize(capacity) * sizeof(TierInstance),
                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frame, failure)) {
        return false;
    }
    s.instance_capacity = capacity;
    return true;
}

bool FrameRing::grow_uniforms(Slot& s, uint32_t needed, uint64_t frame, VkFailure* failure) {
    const uint32_t capacity = grown_capacity(s.draw_capacity, needed);
    if (!replace_buffer(&s.uniforms, frame_stride_ + field_stride_ * capacity, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                        frame, failure)) {
        return false;
    }
    s.draw_capacity = capacity;
    return true;
}

bool FrameRing::write(uint32_t slot, const FramePlan& plan, uint64_t frame, bool* uniforms_replaced, VkFailure* failure,
                      const char** what) {
    Slot& s = slots_[slot];
    *uniforms_replaced = false;
    const uint32_t instances = static_cast<uint32_t>(plan.instances.size());
    const uint32_t draws = static_cast<uint32_t>(plan.draws.size());
    if (instances > s.instance_capacity) {
        *what = "a per-frame instance buffer";
        if (!grow_instances(s, instances, frame, failure)) return false;
    }
    if (draws > s.draw_capacity) {
        *what = "a per-frame uniform buffer";
        if (!grow_uniforms(s, draws, frame, failure)) return false;
        *uniforms_replaced = true;
    }

    if (instances > 0) std::memcpy(s.instances.mapped, plan.instances.data(), instances * sizeof(TierInstance));
    auto* uniforms = static_cast<unsigned char*>(s.uniforms.mapped);
    std::memcpy(uniforms + frame_offset(), &plan.frame, sizeof(FrameUniforms));
    if (frame_bytes_ > sizeof(FrameUniforms)) { // stereo: the eyes after the Frame block's mono part
        std::memcpy(uniforms + frame_offset() + sizeof(FrameUniforms), &plan.eyes, sizeof(StereoUniforms));
    }
    for (uint32_t i = 0; i < draws; ++i) {
        std::memcpy(uniforms + field_offset(i), &plan.draws[i].uniforms, sizeof(FieldUniforms));
    }

    *what = "the per-frame buffers";
    return memory_.flush(s.instances, 0, VkDeviceSize(instances) * sizeof(TierInstance), failure) &&
           memory_.flush(s.uniforms, 0, field_offset(draws), failure);
}

} // namespace grass::vk
