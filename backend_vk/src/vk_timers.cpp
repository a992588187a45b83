// GPU timings per tier kind (grass_get_tier_gpu_ms): a timestamp query pool with one range
// per set of the core's ring (timing/tier_timer_ring.hpp), one set per frame in flight.
// prepare_frame resets the frame's range outside the render pass, record writes a
// timestamp before the blades and after each kind's draws (bottom of pipe: when everything
// before has finished), and the results of a frame are read once available, with
// VK_QUERY_RESULT_WITH_AVAILABILITY_BIT and never VK_QUERY_RESULT_WAIT_BIT. A frame's set
// is closed when the next frame begins (a host submits each frame before it begins the
// next; until then its queries still hold the results of the frame that used the range
// before, the reset being recorded, not executed), and read at the latest when it comes
// round again (the host has waited for it).
#include "vk_backend.hpp"

#include "context/context.hpp"
#include "vk_labels.hpp"

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
    info.queryCount = desc_.frames_in_flight * TierTimerRing::kStampsPerSet;
    if (fn_.vkCreateQueryPool(device_.device, &info, fn_.callbacks(), &timer_pool_) != VK_SUCCESS) {
        timer_pool_ = VK_NULL_HANDLE; // timings unavailable; drawing does not need them
        return;
    }
    name_object(fn_, device_.device, VK_OBJECT_TYPE_QUERY_POOL, timer_pool_, "grass tier timer queries");
    timer_ring_.set_clock(valid_bits, period);
}

uint32_t VkBackend::timer_stamps() {
    // Untimed unless prepare_frame was called this frame: the range is not reset otherwise.
    if (timer_set_ == TierTimerRing::kUntimed || !timer_reset_) return TierTimerRing::kUntimed;
    return timer_ring_.next_pass();
}

void VkBackend::write_stamp(VkCommandBuffer cmd, uint32_t first, uint32_t stamp) {
    if (first == TierTimerRing::kUntimed) return;
    fn_.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timer_pool_, first + stamp);
}

void VkBackend::collect_timers() {
    if (timer_pool_ == VK_NULL_HANDLE) return;
    timer_ring_.collect([&](uint32_t first, uint32_t count, uint64_t* stamps) {
        if (count == 0) return true;                            // no record of its frame was timed
        uint64_t results[TierTimerRing::kStampsPerSet][2] = {}; // value, availability
        const VkResult r = fn_.vkGetQueryPoolResults(device_.device, timer_pool_, first, count, sizeof(results),
                                                     results, sizeof(results[0]),
                                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
        if (r != VK_SUCCESS && r != VK_NOT_READY) return false; // device lost and the like: keep the last figures
        for (uint32_t q = 0; q < count; ++q) {
            if (results[q][1] == 0) return false;
            stamps[q] = results[q][0];
        }
        return true;
    });
}

bool VkBackend::tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) {
    collect_timers();
    return timer_ring_.latest(out_ms);
}

} // namespace grass::vk
