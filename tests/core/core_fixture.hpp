// A context with no GPU backend plus a log recorder, for the core tests.
#pragma once

#include <grass/grass.h>

#include <gtest/gtest.h>

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

    grass_context* ctx = nullptr;
    std::vector<LogRecord> log;
};
