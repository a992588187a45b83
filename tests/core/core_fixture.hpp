// A context with no GPU backend plus a log recorder, for the core tests.
#pragma once

#include <grass/grass.h>

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

// A square field of `cells` cells of `patch` drawn by one tier chosen by one lod test
// (both must outlive the desc's use).
inline grass_field_desc one_tier_field(grass_patch_id patch, uint32_t cells, const grass_tier_desc* tier,
                                       const grass_lod_test* test) {
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = d.cells_z = cells;
    d.tiers = tier;
    d.tier_count = 1;
    d.lod_tests = test;
    d.lod_test_count = 1;
    return d;
}

struct LogRecord {
    grass_log_level level;
    grass_message_id id;
    std::string message;
};

class CoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        grass_context_desc d = grass_default_context_desc();
        d.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char* message) {
            // Errors and warnings carry a stable message id (grass.h), whatever the path.
            if (level != GRASS_LOG_INFO) {
                EXPECT_NE(id, GRASS_MSG_NONE) << message;
            }
            static_cast<std::vector<LogRecord>*>(user)->push_back({level, id, message});
        };
        d.log_user_data = &log;
        ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_SUCCESS);
    }
    void TearDown() override { grass_destroy_context(ctx); }

    grass_message_id last_id() const { return log.empty() ? GRASS_MSG_NONE : log.back().id; }
    std::string last_message() const { return log.empty() ? std::string() : log.back().message; }

    grass_patch_id make_patch(grass_patch_desc d = grass_default_patch_desc()) {
        grass_patch_id p{};
        EXPECT_EQ(grass_create_patch(ctx, &d, &p), GRASS_SUCCESS) << last_message();
        return p;
    }

    // A field of 48 x 48 cells of a new default patch drawn by three tiers: blades to 3 m,
    // the volume (2 slices a cell) to 7 m, the image tier beyond.
    grass_field_id make_three_tier_field() {
        const grass_patch_id patch = make_patch();
        const grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 2}, {GRASS_TIER_IMAGE, 0}};
        grass_lod_test bands[3] = {};
        const float ends[3] = {3.0f, 7.0f, INFINITY};
        for (uint32_t t = 0; t < 3; ++t) {
            bands[t].kind = GRASS_LOD_TEST_DISTANCE_BAND;
            bands[t].tier = t;
            bands[t].begin = t == 0 ? 0.0f : ends[t - 1];
            bands[t].end = ends[t];
        }
        grass_field_desc d = one_tier_field(patch, 48, &tiers[0], &bands[0]);
        d.tier_count = 3;
        d.lod_test_count = 3;
        grass_field_id field{};
        EXPECT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
        return field;
    }

    // Begins a host frame and plans `views` in order (views 0, 1, ...).
    void plan_frame(std::initializer_list<const grass_view_desc*> views) {
        grass_frame_desc frame = grass_default_frame_desc();
        ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
        for (const grass_view_desc* v : views) {
            uint32_t index = 0;
            ASSERT_EQ(grass_plan_view(ctx, v, &index), GRASS_SUCCESS) << last_message();
        }
    }

    grass_context* ctx = nullptr;
    std::vector<LogRecord> log;
};
