// grass_get_tier_gpu_ms: GPU timestamps around each tier kind's draws (GL_TIMESTAMP
// queries, a Vulkan timestamp pool), read back without waiting. llvmpipe and lavapipe have
// timer queries; a driver without them must take the unavailable path. The test prints
// what it measures.
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grass_test {
namespace {

class TierTimingTest : public RenderTest {
protected:
    // A 32 m square field drawn by all three tiers: blades to `blades_end` metres, an 8-slice
    // volume for 8 m after them, then the image tier. Renders `frames` frames from player
    // height and returns the median of the timings read after each (nothing if none was
    // available); *available_frames counts the reads that had timings.
    std::vector<double> timed_frames(float blades_end, int frames, int* available_frames) {
        const grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 8}, {GRASS_TIER_IMAGE, 0}};
        grass_lod_test tests[5] = {};
        const float begins[3] = {0.0f, blades_end - 1.0f, blades_end + 6.0f};
        const float ends[3] = {blades_end, blades_end + 8.0f, INFINITY};
        for (uint32_t t = 0; t < 3; ++t) {
            tests[t].kind = GRASS_LOD_TEST_DISTANCE_BAND;
            tests[t].tier = t;
            tests[t].begin = begins[t];
            tests[t].end = ends[t];
            tests[t].transition_in = t > 0 ? 1.0f : 0.0f;
            tests[t].transition_out = t < 2 ? 1.0f : 0.0f;
        }
        for (uint32_t t = 1; t < 3; ++t) {
            tests[2 + t].kind = GRASS_LOD_TEST_MACRO_CELL;
            tests[2 + t].tier = t;
            tests[2 + t].max_macro_cells = 8;
        }
        grass_field_desc d = field_desc(128); // 0.25 m cells
        d.tiers = tiers;
        d.tier_count = 3;
        d.lod_tests = tests;
        d.lod_test_count = 5;
        const grass_field_id f = make_field(d);
        const double eye[3] = {16.0, 1.7, -0.5}, target[3] = {16.0, 0.0, 12.0};
        const grass_view_desc v = view(eye, target, 60.0f);
        std::vector<double> reads[GRASS_TIER_KIND_COUNT];
        *available_frames = 0;
        grass_frame_stats stats{};
        for (int i = 0; i < frames; ++i) {
            render(v);
            double ms[GRASS_TIER_KIND_COUNT] = {-1.0, -1.0, -1.0};
            grass_bool available = 7;
            EXPECT_EQ(grass_get_tier_gpu_ms(ctx, ms, &available), GRASS_SUCCESS) << log;
            EXPECT_TRUE(available == 0 || available == 1);
            if (available) {
                *available_frames += 1;
                for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
                    EXPECT_GE(ms[k], 0.0);
                    EXPECT_TRUE(std::isfinite(ms[k]));
                    reads[k].push_back(ms[k]);
                }
            } else {
                for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) EXPECT_EQ(ms[k], 0.0);
            }
        }
        EXPECT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
            EXPECT_GT(stats.instances[k], 0u) << "tier kind " << k << " draws nothing; the scene must show all three";
        }
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        std::vector<double> median;
        if (reads[0].empty()) return median;
        for (auto& r : reads) {
            std::sort(r.begin(), r.end());
            median.push_back(r[r.size() / 2]);
        }
        std::printf("[ measured ] %s blades to %.0f m: %llu geometry cells; GPU ms geometry %.3f, volume %.3f, image "
                    "%.3f (median of %d frames)\n",
                    backend_name(GetParam()).c_str(), blades_end, static_cast<unsigned long long>(stats.cells[0]),
                    median[0], median[1], median[2], *available_frames);
        return median;
    }
};

TEST_P(TierTimingTest, EachTierKindIsTimedAndBladesCostMoreWhenThereAreMore) {
    grass_host::TargetDesc t;
    t.width = 128;
    t.height = 72;
    t.samples = 4;
    start(t);
    int available_few = 0, available_many = 0;
    const std::vector<double> few = timed_frames(3.0f, 5, &available_few);
    const std::vector<double> many = timed_frames(8.0f, 5, &available_many);
    if (available_few == 0 && available_many == 0) {
        // The unavailable path (a driver without timer queries): zeros, said so.
        std::printf("[ measured ] %s: no timer queries on \"%s\"\n", backend_name(GetParam()).c_str(),
                    host->device_name().c_str());
        GTEST_SKIP() << "the driver has no timer queries";
    }
    // llvmpipe and lavapipe have them: timings arrive within the frames in flight (GL reads
    // up to 4 frames back, Vulkan 2) and then every frame.
    EXPECT_GE(available_few, 3);
    EXPECT_GE(available_many, 3);
    ASSERT_EQ(few.size(), 3u);
    ASSERT_EQ(many.size(), 3u);
    // Each kind's time may be 0 on llvmpipe: it stamps per rasteriser thread as the thread
    // reaches the query in its last tile, which need not hold that kind's pixels. The frame
    // as a whole took time.
    EXPECT_GT(few[0] + few[1] + few[2], 0.0);
    // About 6 times the cells in blades.
    EXPECT_GT(many[0], 1.5 * few[0]) << "geometry ms with blades to 4 m: " << few[0] << ", to 14 m: " << many[0];
}

INSTANTIATE_TEST_SUITE_P(Backends, TierTimingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

// A context without a GPU has no timings; bad arguments are refused.
TEST(TierTiming, AContextWithoutAGpuHasNoTimings) {
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_SUCCESS);
    double ms[GRASS_TIER_KIND_COUNT] = {1.0, 2.0, 3.0};
    grass_bool available = 1;
    EXPECT_EQ(grass_get_tier_gpu_ms(ctx, ms, &available), GRASS_SUCCESS);
    EXPECT_EQ(available, 0u);
    for (double m : ms) EXPECT_EQ(m, 0.0);
    EXPECT_EQ(grass_get_tier_gpu_ms(nullptr, ms, &available), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(grass_get_tier_gpu_ms(ctx, nullptr, &available), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(grass_get_tier_gpu_ms(ctx, ms, nullptr), GRASS_ERROR_INVALID_ARGUMENT);
    grass_destroy_context(ctx);
}

} // namespace
} // namespace grass_test
