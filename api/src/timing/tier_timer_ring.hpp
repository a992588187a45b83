// The bookkeeping of grass_get_tier_gpu_ms that every backend shares: a ring of timestamp
// sets, one per frame in flight, which frame writes which set, which set is read next, and
// the milliseconds of each tier kind of the latest finished frame. A backend only issues
// and reads its queries: stamp s of a set's pass p is query first + s, where
// first = set * kStampsPerSet + p * kStampsPerPass is what next_pass() returns.
#pragma once

#include <grass/grass.h>

#include <cstdint>

namespace grass {

class TierTimerRing {
public:
    static constexpr uint32_t kUntimed = 0xffffffffu;
    static constexpr uint32_t kMaxSets = 8; // Vulkan's most frames in flight
    // Timed passes (renders or records) per frame; a frame with more is not reported.
    static constexpr uint32_t kPassesPerFrame = 4;
    // Per pass: before the blades, after the blades, after the volumes, after the images.
    static constexpr uint32_t kStampsPerPass = 4;
    static constexpr uint32_t kStampsPerSet = kPassesPerFrame * kStampsPerPass;

    // What open_frame() does when the oldest set's results are still unread: GL leaves the
    // frame untimed rather than wait; Vulkan drops them (the host has waited for the frame
    // that wrote them, so results still unavailable then will never come).
    enum class WhenBusy { skip_frame, drop_results };

    // `sets` (1..kMaxSets) sets of kStampsPerSet queries.
    TierTimerRing(uint32_t sets, WhenBusy when_busy);
    // The device's clock: `valid_bits` of each timestamp count (wrapping), at `ns_per_tick`
    // nanoseconds a tick (default: 64 bits of nanoseconds).
    void set_clock(uint32_t valid_bits, double ns_per_tick);

    // The set the frame beginning now writes (after collect()), or kUntimed. A backend
    // calls it once a frame, where it can issue queries.
    uint32_t open_frame();
    // The first query of the next pass of the open frame, or kUntimed: no open frame, or
    // kPassesPerFrame passes already (the frame is then not reported).
    uint32_t next_pass();
    // The open frame writes no more stamps: its set is read once its stamps are available.
    void close_frame();

    // Reads the closed sets, oldest first, without waiting: read(first, count, stamps)
    // fills stamps[0..count) from queries first.. and returns true, or returns false when
    // they are not all available yet (reading stops there: later sets finish later).
    template <class Read>
    void collect(Read&& read) {
        uint32_t first = 0, count = 0;
        while (next_unread(&first, &count)) {
            uint64_t stamps[kStampsPerSet] = {};
            if (!read(first, count, stamps)) return;
            accept(stamps);
        }
    }

    // The milliseconds of each tier kind in the latest finished, fully timed frame; false
    // (zeros) before there is one.
    bool latest(double out_ms[GRASS_TIER_KIND_COUNT]) const;

private:
    struct Set {
        uint32_t passes = 0;  // passes of its frame that wrote stamps
        bool pending = false; // opened; results not read yet
        bool closed = false;  // its frame writes no more stamps
        bool complete = true; // every pass of its frame was timed
    };
    bool next_unread(uint32_t* first, uint32_t* count) const;
    void accept(const uint64_t* stamps);

    Set sets_[kMaxSets];
    uint32_t set_count_;
    WhenBusy when_busy_;
    uint64_t mask_ = ~uint64_t(0);
    double ns_per_tick_ = 1.0;
    uint32_t next_ = 0;        // the oldest set: the next frame's
    uint32_t open_ = kUntimed; // the set of the open frame
    bool valid_ = false;
    double ms_[GRASS_TIER_KIND_COUNT] = {};
};

} // namespace grass
