#include "timing/tier_timer_ring.hpp"

namespace grass {

TierTimerRing::TierTimerRing(uint32_t sets, WhenBusy when_busy)
    : set_count_(sets < 1          ? 1
                 : sets > kMaxSets ? kMaxSets
                                   : sets),
      when_busy_(when_busy) {}

void TierTimerRing::set_clock(uint32_t valid_bits, double ns_per_tick) {
    mask_ = valid_bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << valid_bits) - 1;
    ns_per_tick_ = ns_per_tick;
}

uint32_t TierTimerRing::open_frame() {
    close_frame();
    Set& set = sets_[next_];
    if (set.pending && when_busy_ == WhenBusy::skip_frame) return kUntimed; // never wait for the GPU
    set = Set{};
    set.pending = true;
    open_ = next_;
    next_ = (next_ + 1) % set_count_;
    return open_;
}

uint32_t TierTimerRing::next_pass() {
    if (open_ == kUntimed) return kUntimed;
    Set& set = sets_[open_];
    if (set.passes == kPassesPerFrame) {
        set.complete = false;
        return kUntimed;
    }
    return open_ * kStampsPerSet + kStampsPerPass * set.passes++;
}

void TierTimerRing::close_frame() {
    if (open_ != kUntimed) sets_[open_].closed = true;
    open_ = kUntimed;
}

bool TierTimerRing::next_unread(uint32_t* first, uint32_t* count) const {
    for (uint32_t i = 0; i < set_count_; ++i) {
        const uint32_t s = (next_ + i) % set_count_;
        if (!sets_[s].pending) continue;
        if (!sets_[s].closed) return false; // its frame is still drawing
        *first = s * kStampsPerSet;
        *count = kStampsPerPass * sets_[s].passes;
        return true;
    }
    return false;
}

void TierTimerRing::accept(const uint64_t* stamps) {
    uint32_t first = 0, count = 0;
    next_unread(&first, &count);
    Set& set = sets_[first / kStampsPerSet];
    // Stamps 0-1 of a pass bracket the blades, 1-2 the volumes, 2-3 the images.
    static const grass_tier_kind kinds[kStampsPerPass - 1] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
    double ms[GRASS_TIER_KIND_COUNT] = {};
    for (uint32_t p = 0; p < set.passes; ++p) {
        for (uint32_t k = 0; k + 1 < kStampsPerPass; ++k) {
            const uint64_t ticks = (stamps[kStampsPerPass * p + k + 1] - stamps[kStampsPerPass * p + k]) & mask_;
            ms[kinds[k]] += static_cast<double>(ticks) * ns_per_tick_ * 1e-6;
        }
    }
    set.pending = false;
    if (set.complete && set.passes > 0) {
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) ms_[k] = ms[k];
        valid_ = true;
    }
}

bool TierTimerRing::latest(double out_ms[GRASS_TIER_KIND_COUNT]) const {
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = valid_ ? ms_[k] : 0.0;
    return valid_;
}

} // namespace grass
