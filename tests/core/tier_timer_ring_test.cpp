// The timer ring the backends share (timing/tier_timer_ring.hpp), driven by a fake clock:
// which set a frame writes, when a set is read, what a frame reports.
#include "timing/tier_timer_ring.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using grass::TierTimerRing;

// Query values: stamps[q] of the query space (sets x kStampsPerSet); available[q] or not.
struct FakeQueries {
    std::vector<uint64_t> stamps = std::vector<uint64_t>(TierTimerRing::kMaxSets * TierTimerRing::kStampsPerSet, 0);
    std::vector<bool> available = std::vector<bool>(stamps.size(), true);
    // One pass from `first`: blades, volumes and images take these many ticks.
    void write_pass(uint32_t first, uint64_t blades, uint64_t volumes, uint64_t images, uint64_t start = 1000) {
        stamps[first] = start;
        stamps[first + 1] = start + blades;
        stamps[first + 2] = start + blades + volumes;
        stamps[first + 3] = start + blades + volumes + images;
    }
    void collect(TierTimerRing& ring) {
        ring.collect([&](uint32_t first, uint32_t count, uint64_t* out) {
            for (uint32_t q = 0; q < count; ++q) {
                if (!available[first + q]) return false;
                out[q] = stamps[first + q];
            }
            return true;
        });
    }
};

TEST(TierTimerRing, AClosedFrameReportsEachKindsTimeSummedOverItsPasses) {
    TierTimerRing ring(2, TierTimerRing::WhenBusy::skip_frame);
    ring.set_clock(64, 1e6); // a tick is a millisecond
    FakeQueries q;
    double ms[GRASS_TIER_KIND_COUNT] = {9, 9, 9};
    EXPECT_FALSE(ring.latest(ms)) << "no frame yet";
    EXPECT_EQ(ms[0], 0.0);
    EXPECT_EQ(ring.open_frame(), 0u);
    q.write_pass(ring.next_pass(), 1, 2, 3);
    q.write_pass(ring.next_pass(), 10, 20, 30);
    q.collect(ring);
    EXPECT_FALSE(ring.latest(ms)) << "an open frame is not read";
    ring.close_frame();
    q.collect(ring);
    ASSERT_TRUE(ring.latest(ms));
    EXPECT_DOUBLE_EQ(ms[GRASS_TIER_GEOMETRY], 11.0);
    EXPECT_DOUBLE_EQ(ms[GRASS_TIER_VOLUME], 22.0);
    EXPECT_DOUBLE_EQ(ms[GRASS_TIER_IMAGE], 33.0);
}

TEST(TierTimerRing, UnavailableResultsAreNotWaitedForAndAFullRingSkipsFrames) {
    TierTimerRing ring(2, TierTimerRing::WhenBusy::skip_frame);
    FakeQueries q;
    for (uint32_t frame = 0; frame < 2; ++frame) {
        EXPECT_EQ(ring.open_frame(), frame);
        const uint32_t first = ring.next_pass();
        q.write_pass(first, 5, 5, 5);
        q.available[first + 3] = false;
        ring.close_frame();
    }
    q.collect(ring);
    double ms[GRASS_TIER_KIND_COUNT];
    EXPECT_FALSE(ring.latest(ms));
    EXPECT_EQ(ring.open_frame(), TierTimerRing::kUntimed) << "both sets unread: this frame goes untimed";
    EXPECT_EQ(ring.next_pass(), TierTimerRing::kUntimed);
    q.available[3] = true; // set 0 finished
    q.collect(ring);
    EXPECT_TRUE(ring.latest(ms));
    EXPECT_EQ(ring.open_frame(), 0u) << "set 0 is free again";
}

TEST(TierTimerRing, VulkanDropsASetThatNeverRanWhenItComesRoundAgain) {
    TierTimerRing ring(2, TierTimerRing::WhenBusy::drop_results);
    FakeQueries q;
    EXPECT_EQ(ring.open_frame(), 0u);
    q.write_pass(ring.next_pass(), 1, 1, 1);
    q.available[0] = false; // never submitted
    EXPECT_EQ(ring.open_frame(), 1u);
    q.write_pass(ring.next_pass(), 2, 2, 2);
    q.collect(ring);
    EXPECT_EQ(ring.open_frame(), 0u) << "dropped, not skipped";
    q.available[0] = true;
    q.write_pass(ring.next_pass(), 4, 4, 4);
    ring.close_frame();
    q.collect(ring);
    double ms[GRASS_TIER_KIND_COUNT];
    ASSERT_TRUE(ring.latest(ms));
    EXPECT_DOUBLE_EQ(ms[GRASS_TIER_GEOMETRY], 4e-6) << "the newest frame, at a nanosecond a tick";
}

TEST(TierTimerRing, AFrameWithTooManyPassesIsNotReportedAndStampsWrap) {
    TierTimerRing ring(1, TierTimerRing::WhenBusy::skip_frame);
    ring.set_clock(8, 1e6); // 8-bit counter
    FakeQueries q;
    ring.open_frame();
    for (uint32_t p = 0; p < TierTimerRing::kPassesPerFrame; ++p) q.write_pass(ring.next_pass(), 1, 1, 1);
    EXPECT_EQ(ring.next_pass(), TierTimerRing::kUntimed);
    ring.close_frame();
    q.collect(ring);
    double ms[GRASS_TIER_KIND_COUNT];
    EXPECT_FALSE(ring.latest(ms)) << "a render went untimed: the frame's figures would be short";
    ring.open_frame();
    const uint32_t first = ring.next_pass();
    q.write_pass(first, 3, 3, 3, 254);
    for (uint32_t k = 0; k < TierTimerRing::kStampsPerPass; ++k) q.stamps[first + k] &= 255; // blades: 254 to 1
    ring.close_frame();
    q.collect(ring);
    ASSERT_TRUE(ring.latest(ms));
    EXPECT_DOUBLE_EQ(ms[GRASS_TIER_GEOMETRY], 3.0);
}

} // namespace
