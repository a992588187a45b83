// API misuse: each mistake is answered by its error code and message id, and the context
// stays usable afterwards.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include <cmath>
#include <limits>

namespace {

class MisuseTest : public CoreTest {
protected:
    // After every refusal the context must still create a field and plan a frame.
    void expect_context_still_usable() {
        grass_field_desc d = grass_default_field_desc();
        d.patch = make_patch();
        d.cells_x = d.cells_z = 4;
        grass_field_id f{};
        ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        const double eye[3] = {0.5, 3.0, 0.5}, target[3] = {0.5, 0.0, 0.5};
        const grass_view_desc v = test_view(eye, target);
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        grass_frame_stats s{};
        ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
        EXPECT_EQ(s.cells_drawn, 16u);
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    }
    grass_field_desc valid_field() {
        grass_field_desc d = grass_default_field_desc();
        d.patch = make_patch();
        d.cells_x = d.cells_z = 8;
        return d;
    }
};

// A getter given NULL for its output says which argument, like every other refusal.
TEST_F(MisuseTest, GettersGivenNullOutputsLogTheArgument) {
    double ms[GRASS_TIER_KIND_COUNT];
    grass_bool available = 0;
    const struct {
        const char* argument;
        grass_result result;
    } cases[] = {
        {"out_stats", grass_get_frame_stats(ctx, nullptr)},
        {"out_stats", grass_get_memory_stats(ctx, nullptr)},
        {"out_ms", grass_get_tier_gpu_ms(ctx, nullptr, &available)},
        {"out_available", grass_get_tier_gpu_ms(ctx, ms, nullptr)},
    };
    ASSERT_EQ(log.size(), 4u) << "one message per refusal";
    for (size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(cases[k].result, GRASS_ERROR_INVALID_ARGUMENT);
        EXPECT_EQ(log[k].id, GRASS_MSG_NULL_ARGUMENT);
        EXPECT_NE(log[k].message.find(cases[k].argument), std::string::npos) << log[k].message;
    }
    expect_context_still_usable();
}

TEST_F(MisuseTest, NanInTheBaseTransformIsRefused) {
    grass_field_desc d = valid_field();
    d.base_transform[13] = std::numeric_limits<double>::quiet_NaN();
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE);
    EXPECT_NE(last_message().find("desc->base_transform[13]"), std::string::npos) << last_message();
    EXPECT_EQ(f.index, 0u) << "the out id is untouched";
    expect_context_still_usable();
}

TEST_F(MisuseTest, AScaledOrShearedBaseTransformIsRefused) {
    grass_field_desc d = valid_field();
    d.base_transform[0] = 2.0;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_TRANSFORM);
    expect_context_still_usable();
}

TEST_F(MisuseTest, ZeroCellsAreRefused) {
    grass_field_desc d = valid_field();
    d.cells_z = 0;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_ZERO_CELLS);
    expect_context_still_usable();
}

TEST_F(MisuseTest, AStaleIdIsRefused) {
    grass_field_desc d = valid_field();
    grass_field_id f{};
    ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS);
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(last_id(), GRASS_MSG_STALE_HANDLE);
    // The slot is reused by a new field: the old id must still be refused.
    grass_field_id g{};
    ASSERT_EQ(grass_create_field(ctx, &d, &g), GRASS_SUCCESS);
    EXPECT_EQ(g.index, f.index);
    EXPECT_NE(g.generation, f.generation);
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(grass_destroy_field(ctx, g), GRASS_SUCCESS);
    // A destroyed patch id in a field desc.
    grass_patch_id p = make_patch();
    ASSERT_EQ(grass_destroy_patch(ctx, p), GRASS_SUCCESS);
    d.patch = p;
    EXPECT_EQ(grass_create_field(ctx, &d, &g), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(last_id(), GRASS_MSG_STALE_HANDLE);
    expect_context_still_usable();
}

TEST_F(MisuseTest, TheNullIdAndAnotherContextsIdAreRefused) {
    grass_field_desc d = valid_field();
    d.patch = grass_patch_id{};
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(last_id(), GRASS_MSG_NULL_HANDLE);

    grass_context* other = nullptr;
    grass_context_desc cd = grass_default_context_desc();
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &other), GRASS_SUCCESS);
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id foreign{};
    ASSERT_EQ(grass_create_patch(other, &pd, &foreign), GRASS_SUCCESS);
    d.patch = foreign;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(last_id(), GRASS_MSG_FOREIGN_HANDLE);
    grass_destroy_context(other);
    expect_context_still_usable();
}

TEST_F(MisuseTest, ADescWithTheWrongTypeTagIsRefused) {
    grass_field_desc d = valid_field();
    d.type = GRASS_STRUCT_TYPE_PATCH_DESC;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_EQ(last_id(), GRASS_MSG_WRONG_STRUCT_TYPE);
    grass_patch_desc p = grass_default_patch_desc();
    p.type = GRASS_STRUCT_TYPE_VIEW_DESC;
    grass_patch_id pid{};
    EXPECT_EQ(grass_create_patch(ctx, &p, &pid), GRASS_ERROR_WRONG_STRUCT_TYPE);
    grass_view_desc v = grass_default_view_desc();
    v.type = GRASS_STRUCT_TYPE_FIELD_DESC;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_WRONG_STRUCT_TYPE);
    expect_context_still_usable();
}

TEST_F(MisuseTest, EndingAFrameThatWasNotBegunOrBeginningTwiceIsRefused) {
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_FRAME_NOT_BEGUN);
    const double eye[3] = {0, 2, 0}, target[3] = {0, 0, 1};
    const grass_view_desc v = test_view(eye, target);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS);
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_FRAME_ALREADY_BEGUN);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    expect_context_still_usable();
}

TEST_F(MisuseTest, BadViewsAreRefused) {
    const double eye[3] = {0, 2, 0}, target[3] = {0, 0, 1};
    grass_view_desc v = test_view(eye, target);
    v.camera_position[0] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE);
    v = test_view(eye, target);
    v.sun_direction[0] = v.sun_direction[1] = v.sun_direction[2] = 0.0f;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_ZERO_VECTOR);
    v = test_view(eye, target);
    v.viewport[2] = 0;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    v = test_view(eye, target);
    v.projection[5] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE);
    expect_context_still_usable();
}

TEST_F(MisuseTest, BadPatchDescsAreRefusedWithTheArgumentNamed) {
    grass_patch_desc d = grass_default_patch_desc();
    d.length_min = 0.9f;
    d.length_max = 0.5f;
    grass_patch_id p{};
    EXPECT_EQ(grass_create_patch(ctx, &d, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_RANGE_INVERTED);
    EXPECT_NE(last_message().find("desc->length_min"), std::string::npos) << last_message();
    d = grass_default_patch_desc();
    d.blade_count = 0;
    EXPECT_EQ(grass_create_patch(ctx, &d, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_OUT_OF_RANGE);
    d = grass_default_patch_desc();
    d.cluster_sigma = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(grass_create_patch(ctx, &d, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE);
    expect_context_still_usable();
}

TEST_F(MisuseTest, BadDensityMapsAreRefused) {
    grass_field_desc d = valid_field();
    const float texels[4] = {0.0f, 0.5f, std::numeric_limits<float>::quiet_NaN(), 1.0f};
    grass_map_desc m = grass_default_map_desc();
    m.pixels = texels;
    m.width = m.height = 2;
    m.format = GRASS_MAP_FORMAT_R32_FLOAT;
    d.density_map = &m;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_MAP);
    m.width = 0;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    m.width = 2;
    m.row_pitch = 4; // less than 2 floats
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    m.row_pitch = 0;
    m.format = static_cast<grass_map_format>(42);
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    expect_context_still_usable();
}

TEST_F(MisuseTest, APatchUsedByAFieldCannotBeDestroyed) {
    grass_field_desc d = valid_field();
    grass_field_id f{};
    ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_patch(ctx, d.patch), GRASS_ERROR_IN_USE);
    EXPECT_EQ(last_id(), GRASS_MSG_PATCH_IN_USE);
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_patch(ctx, d.patch), GRASS_SUCCESS);
    expect_context_still_usable();
}

TEST(ContextCreation, AHeaderOfAnotherMajorVersionIsRefused) {
    grass_context_desc d = grass_default_context_desc();
    grass_context* ctx = nullptr;
    grass_message_id seen = GRASS_MSG_NONE;
    d.log_fn = [](void* user, grass_log_level, grass_message_id id, const char*) {
        *static_cast<grass_message_id*>(user) = id;
    };
    d.log_user_data = &seen;
    const uint32_t next_major = (static_cast<uint32_t>(GRASS_VERSION_MAJOR) + 1u) << 22;
    EXPECT_EQ(grass_create_context(next_major, &d, &ctx), GRASS_ERROR_VERSION_MISMATCH);
    EXPECT_EQ(ctx, nullptr);
    EXPECT_EQ(seen, GRASS_MSG_VERSION_MISMATCH);
    d.type = GRASS_STRUCT_TYPE_FIELD_DESC;
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_EQ(grass_get_library_version(), GRASS_HEADER_VERSION);
}

TEST(ResultStrings, EveryCodeHasItsName) {
    EXPECT_STREQ(grass_result_string(GRASS_SUCCESS), "GRASS_SUCCESS");
    EXPECT_STREQ(grass_result_string(GRASS_ERROR_INVALID_HANDLE), "GRASS_ERROR_INVALID_HANDLE");
    EXPECT_STREQ(grass_result_string(GRASS_ERROR_IN_USE), "GRASS_ERROR_IN_USE");
    EXPECT_STREQ(grass_result_string(static_cast<grass_result>(-1000)), "GRASS_ERROR_UNKNOWN");
}

} // namespace
