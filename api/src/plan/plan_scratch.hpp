// Working memory of the frame planner, kept by the context so that planning a frame
// allocates nothing once the vectors have grown.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct PlanNode {
    uint32_t level;
    uint32_t active_tests; // bit k: test k still decides for this subtree (lemme figure 6.3)
    uint64_t x, z;
};

struct PlanCandidate {
    double distance2; // squared distance from the camera to the cell centre, metres^2
    float density;    // density at the cell centre, for the blade stats
    uint32_t level;   // geometry: the blades' tessellation level (blade_tessellation.hpp), else 0
    TierInstance instance;
};

struct PlanScratch {
    using Candidates = Vector<PlanCandidate>;
    static_assert(GRASS_MAX_TIERS == 8, "one initialiser per tier below");
    explicit PlanScratch(HostAllocator* host)
        : stack(StlAllocator<PlanNode>(host)), per_tier{Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host)),
                                                        Candidates(StlAllocator<PlanCandidate>(host))} {}
    Vector<PlanNode> stack;
    Candidates per_tier[GRASS_MAX_TIERS];
};

} // namespace grass
