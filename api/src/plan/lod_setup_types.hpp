// The tiers and lod tests a field keeps (validated copies of its desc's).
#pragma once

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct LodSetup {
    grass_tier_desc tiers[GRASS_MAX_TIERS];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS];
    uint32_t tier_count = 0;
    uint32_t test_count = 0;
    uint32_t tests_of_tier[GRASS_MAX_TIERS] = {}; // bit mask of the tests that feed each tier
    uint32_t overlay_tiers = 0; // bit per tier with a HILLTOP test: drawn on top, no share of the transitions
};

} // namespace grass
