// Seamless transitions (boulanger2006 3.4, lemme2012 5.4): over any distance, every blade's
// opacities over all tiers sum to one; without the smoothing window exactly one tier
// draws it; in Lemme's setup no blade is lost anywhere from the camera to infinity.
#include "plan/tier_transitions.hpp"

#include <grass/grass.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

std::vector<grass::TierBand> default_bands(double cell_size) {
    grass_tier_desc tiers[GRASS_DEFAULT_TIER_COUNT];
    grass_lod_test tests[GRASS_DEFAULT_LOD_TEST_COUNT];
    grass_default_lod_setup(cell_size, tiers, tests);
    std::vector<grass::TierBand> bands(GRASS_DEFAULT_TIER_COUNT);
    for (const auto& t : tests) {
        if (t.kind == GRASS_LOD_TEST_DISTANCE_BAND) bands[t.tier] = {t.begin, t.end, t.transition_in, t.transition_out};
    }
    return bands;
}

TEST(TierTransitions, EveryVisibleBladeIsDrawnByExactlyOneTierWithoutTheWindow) {
    const auto bands = default_bands(0.25);
    for (float d = 0.0f; d < 120.0f; d += 0.173f) {
        for (int k = 1; k <= 200; ++k) {
            const float threshold = k / 200.0f;
            for (float density : {1.0f, 0.6f}) {
                float sum = 0.0f;
                int drawers = 0;
                for (uint32_t t = 0; t < bands.size(); ++t) {
                    const float o =
                        grass::tier_blade_opacity(bands.data(), uint32_t(bands.size()), t, d, threshold, density, 0.0f);
                    ASSERT_TRUE(o == 0.0f || o == 1.0f);
                    sum += o;
                    drawers += o > 0.0f;
                }
                const bool visible = threshold <= density;
                ASSERT_EQ(drawers, visible ? 1 : 0)
                    << "d " << d << " threshold " << threshold << " density " << density;
                ASSERT_EQ(sum, visible ? 1.0f : 0.0f);
            }
        }
    }
}

TEST(TierTransitions, WithTheWindowTheOpacitiesOfABladeSumToOne) {
    const auto bands = default_bands(0.25);
    for (float d = 0.0f; d < 120.0f; d += 0.291f) {
        for (int k = 1; k <= 400; ++k) {
            const float threshold = k / 400.0f;
            float sum = 0.0f;
            for (uint32_t t = 0; t < bands.size(); ++t) {
                sum += grass::tier_blade_opacity(bands.data(), uint32_t(bands.size()), t, d, threshold, 1.0f, 0.05f);
            }
            ASSERT_NEAR(sum, 1.0f, 1e-5f) << "d " << d << " threshold " << threshold;
        }
    }
}

TEST(TierTransitions, BladesMoveFromTheFineToTheCoarseTierAcrossTheZoneInThresholdOrder) {
    const auto bands = default_bands(0.25); // geometry fades out and volume in over 1.25..5 m
    auto share = [&](uint32_t tier, float d) {
        int drawn = 0;
        for (int k = 1; k <= 1000; ++k) {
            drawn += grass::tier_blade_opacity(bands.data(), uint32_t(bands.size()), tier, d, k / 1000.0f, 1.0f, 0.0f) >
                     0.0f;
        }
        return drawn / 1000.0;
    };
    EXPECT_NEAR(share(0, 1.0f), 1.0, 1e-9);    // before the zone: all geometry
    EXPECT_NEAR(share(0, 3.125f), 0.5, 0.002); // middle of the zone: half and half
    EXPECT_NEAR(share(1, 3.125f), 0.5, 0.002);
    EXPECT_NEAR(share(1, 6.0f), 1.0, 1e-9); // after it: all volume
    // Threshold inversion: the coarse tier takes the low thresholds, so a blade that has
    // moved to the coarse tier stays there as the camera moves away.
    EXPECT_GT(grass::tier_blade_opacity(bands.data(), 5, 1, 3.125f, 0.1f, 1.0f, 0.0f), 0.0f);
    EXPECT_GT(grass::tier_blade_opacity(bands.data(), 5, 0, 3.125f, 0.9f, 1.0f, 0.0f), 0.0f);
    for (float d = 1.25f; d < 5.0f; d += 0.05f) {
        const float w_volume = float(share(1, d));
        EXPECT_GE(share(1, d + 0.05f), w_volume - 1e-9) << "the volume share only grows with distance";
    }
}

TEST(TierTransitions, ADensityOfZeroShowsNothingAndAThresholdAboveTheDensityNeither) {
    const auto bands = default_bands(0.25);
    for (uint32_t t = 0; t < bands.size(); ++t) {
        EXPECT_EQ(grass::tier_blade_opacity(bands.data(), 5, t, 3.0f, 0.001f, 0.0f, 0.05f), 0.0f);
        EXPECT_EQ(grass::tier_blade_opacity(bands.data(), 5, t, 3.0f, 0.7f, 0.6f, 0.0f), 0.0f);
    }
}

} // namespace
