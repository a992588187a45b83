// GPU timings per tier kind (grass_get_tier_gpu_ms): a timestamp query pool with one range
// per frame slot. prepare_frame resets the frame's range outside the render pass, record
// writes a timestamp before the blades and after each kind's draws (bottom of pipe: when
// everything before has finished), and the results of a frame are read once available,
// with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT and never VK_QUERY_RESULT_WAIT_BIT. A slot is
// read at the latest when its frame slot comes round again (the host has waited for it).
#include "vk_backend.hpp"

#include "context/context.hpp"

namespace grass::vk {

void VkBackend::create_timers() {
    uint32_t family_count = 0;
    fn_.vkGetPhysicalDeviceQueueFamilyProperties(device_.physical_device, &family_count, nullptr);
    if (desc_.queue_family >= family_count) return;
    Vector<VkQueueFamilyProperties> families(family_count, VkQueueFamilyProperties{},
                                             StlAllocator<VkQueueFamilyProperties>(&ctx_->host));
    fn_.vkGetPhysicalDeviceQueueFamilyProperties(device_.physical_device, &family_count, families.data());
    const uint32_t valid_bits = families[desc_.queue_family].timestampValidBits;
    const float period = device_.properties.limits.timestampPeriod;
    if (valid_bits == 0 || !(period > 0.0f)) return; // no timestamps on the host's queue
    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = desc_.frames_in_flight * kTimerQueriesPerSlot;
    if (fn_.vkCreateQueryPool(device_.device, &info, nullptr, &timer_pool_) != VK_SUCCESS) {
        timer_pool_ = VK_NULL_HANDLE; // timings unavailable; drawing does not need them
        return;
    }
    timestamp_period_ns_ = period;
    timestamp_mask_ = valid_bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << valid_bits) - 1;
}

uint32_t VkBackend::timer_stamps() {
    if (timer_pool_ == VK_NULL_HANDLE) return UINT32_MAX;
    TimerSlot& t = timer_slots_[slot_];
    if (!t.reset) return UINT32_MAX; // prepare_frame was not called this frame: the range is not reset
    if (t.records == kTimedRecords) {
        t.complete = false;
        return UINT32_MAX;
    }
    t.pending = true;
    t.frame = frame_;
    return slot_ * kTimerQueriesPerSlot + kStampsPerRecord * t.records++;
}

void VkBackend::write_stamp(VkCommandBuffer cmd, uint32_t first, uint32_t stamp) {
    if (first == UINT32_MAX) return;
    fn_.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timer_pool_, first + stamp);
}

void VkBackend::collect_timers() {
    if (timer_pool_ == VK_NULL_HANDLE) return;
    uint64_t after = 0; // slots in frame order
    for (;;) {
        TimerSlot* oldest = nullptr;
        uint32_t oldest_slot = 0;
        for (uint32_t s = 0; s < desc_.frames_in_flight; ++s) {
            TimerSlot& t = timer_slots_[s];
            if (t.pending && t.frame > after && (!oldest || t.frame < oldest->frame)) {
                oldest = &t;
                oldest_slot = s;
            }
        }
        if (!oldest) return;
        // Only frames before the last begun one: the current frame may still add stamps, and
        // until the host submits it, its queries still hold the results of the frame that
        // used the slot before (the reset is recorded, not executed). A host submits each
        // frame before it begins the next.
        if (oldest->frame >= frame_) return;
        after = oldest->frame;
        const uint32_t count = kStampsPerRecord * oldest->records;
        uint64_t results[kTimerQueriesPerSlot][2] = {}; // value, availability
        const VkResult r = fn_.vkGetQueryPoolResults(device_.device, timer_pool_, oldest_slot * kTimerQueriesPerSlot,
                                                     count, sizeof(results), results, sizeof(results[0]),
                                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
        if (r != VK_SUCCESS && r != VK_NOT_READY) return; // device lost and the like: keep the last figures
        bool available = true;
        for (uint32_t q = 0; q < count; ++q) available = available && results[q][1] != 0;
        if (!available) return; // later frames finish later
        double ms[GRASS_TIER_KIND_COUNT] = {};
        static const grass_tier_kind kinds[kStampsPerRecord - 1] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME,
                                                                    GRASS_TIER_IMAGE};
        for (uint32_t rec = 0; rec < oldest->records; ++rec) {
            for (uint32_t k = 0; k + 1 < kStampsPerRecord; ++k) {
                const uint64_t a = results[kStampsPerRecord * rec + k][0];
                const uint64_t b = results[kStampsPerRecord * rec + k + 1][0];
                ms[kinds[k]] += static_cast<double>((b - a) & timestamp_mask_) * timestamp_period_ns_ * 1e-6;
            }
        }
        oldest->pending = false;
        if (oldest->complete) {
            for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) timings_ms_[k] = ms[k];
            timings_valid_ = true;
        }
    }
}

bool VkBackend::tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) {
    collect_timers();
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = timings_valid_ ? timings_ms_[k] : 0.0;
    return timings_valid_;
}

} // namespace grass::vk
