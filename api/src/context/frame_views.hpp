// The views of the host's frame (grass.h, "Frames and views"): each planned view keeps its
// own plan until the frame ends, so that planning one never changes another's. View 0's plan
// is the context's `plan` (grass_begin_frame's one view); the others are made on first use
// and kept, so a frame allocates nothing once the host's view count is reached.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

class FrameViews {
public:
    FrameViews(HostAllocator* host, FramePlan* first) : host_(host) { plans_[0] = first; }
    ~FrameViews() {
        for (uint32_t i = 1; i < GRASS_MAX_VIEWS_PER_FRAME; ++i) host_->destroy(plans_[i]);
    }
    FrameViews(const FrameViews&) = delete;
    FrameViews& operator=(const FrameViews&) = delete;

    // Views planned in the begun frame.
    uint32_t count() const { return count_; }
    const FramePlan& plan(uint32_t view) const { return *plans_[view]; }
    // The plan the next view is planned into (view count(); made on first use, may throw
    // std::bad_alloc); count() grows only with commit(), once it planned well.
    FramePlan& next() {
        FramePlan*& p = plans_[count_];
        if (!p) p = host_->create<FramePlan>(host_);
        return *p;
    }
    void commit() { ++count_; }
    void begin() { count_ = 0; }

private:
    HostAllocator* host_;
    FramePlan* plans_[GRASS_MAX_VIEWS_PER_FRAME] = {};
    uint32_t count_ = 0;
};

// The host's frame: its index, the newest finished one, its time (grass_frame_desc).
struct HostFrame {
    uint64_t index = 0;     // the begun or last frame's (0: none yet)
    uint64_t completed = 0; // the newest finished frame the host reported
    double time = 0.0;
};

} // namespace grass
