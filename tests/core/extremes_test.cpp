// The extremes suite, core half (issue 6, item 4): NaN, infinite and huge inputs are refused
// at the API with GRASS_ERROR_INVALID_ARGUMENT and a message that names the argument, and the
// context keeps working. Only what tests/core/api_misuse_test.cpp and design_map_test.cpp do
// not already check (an infinite camera, zero sun, NaN projection, zero cells, NaN
// base_transform[13], NaN height_scale are there). The rendering half is
// tests/render/extremes_test.cpp.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr float kInff = std::numeric_limits<float>::infinity();

class ExtremeInputs : public CoreTest {
protected:
    grass_field_desc valid_field() {
        grass_field_desc d = grass_default_field_desc();
        if (patch_.index == 0) patch_ = make_patch();
        d.patch = patch_;
        d.cells_x = d.cells_z = 8;
        return d;
    }
    grass_view_desc valid_view() const {
        const double eye[3] = {1.0, 2.0, -1.0}, target[3] = {1.0, 0.0, 1.0};
        return test_view(eye, target);
    }

    // The field desc `edit` makes is refused naming `argument`; nothing is created.
    void expect_field_refused(const std::function<void(grass_field_desc&)>& edit, const std::string& argument,
                              grass_message_id id) {
        grass_field_desc d = valid_field();
        edit(d);
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT) << argument;
        EXPECT_EQ(last_id(), id) << last_message();
        EXPECT_NE(last_message().find(argument), std::string::npos) << last_message();
        EXPECT_EQ(f.index, 0u);
    }
    void expect_view_refused(const std::function<void(grass_view_desc&)>& edit, const std::string& argument,
                             grass_message_id id) {
        grass_view_desc v = valid_view();
        edit(v);
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT) << argument;
        EXPECT_EQ(last_id(), id) << last_message();
        EXPECT_NE(last_message().find(argument), std::string::npos) << last_message();
    }
    // After the refusals the context still makes a field and plans a frame over it.
    void expect_still_usable() {
        const grass_field_desc d = valid_field();
        grass_field_id f{};
        ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        const grass_view_desc v = valid_view();
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        grass_frame_stats s{};
        ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
        EXPECT_GT(s.cells_drawn, 0u);
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    }

    grass_patch_id patch_{};
};

TEST_F(ExtremeInputs, NanInfiniteAndHugeViewsAreRefused) {
    expect_view_refused([](grass_view_desc& v) { v.camera_position[1] = kNaN; }, "view->camera_position[1]",
                        GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.camera_position[2] = -kInf; }, "view->camera_position[2]",
                        GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.camera_position[0] = 1e300; }, "view->camera_position[0]",
                        GRASS_MSG_OUT_OF_RANGE);
    expect_view_refused([](grass_view_desc& v) { v.camera_position[0] = 1.0000001e12; }, "view->camera_position[0]",
                        GRASS_MSG_OUT_OF_RANGE);
    expect_view_refused([](grass_view_desc& v) { v.view[6] = kNaNf; }, "view->view[6]", GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.view[0] = kInff; }, "view->view[0]", GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.projection[0] = kNaNf; }, "view->projection[0]",
                        GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.projection[14] = -kInff; }, "view->projection[14]",
                        GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.sun_direction[1] = kNaNf; }, "view->sun_direction[1]",
                        GRASS_MSG_NOT_FINITE);
    expect_view_refused([](grass_view_desc& v) { v.sun_direction[0] = kInff; }, "view->sun_direction[0]",
                        GRASS_MSG_NOT_FINITE);
    // A direction too short to normalise is refused like zero, with its value in the message.
    expect_view_refused(
        [](grass_view_desc& v) {
            v.sun_direction[0] = 1e-30f;
            v.sun_direction[1] = v.sun_direction[2] = 0.0f;
        },
        "view->sun_direction", GRASS_MSG_ZERO_VECTOR);
    // Within the bound the camera is fine, even 10^11 m out.
    grass_view_desc v = valid_view();
    v.camera_position[0] = 1e11;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    // A huge but finite sun direction is normalised, not overflowed.
    v = valid_view();
    v.sun_direction[0] = 3e38f;
    v.sun_direction[1] = 3e38f;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    expect_still_usable();
}

TEST_F(ExtremeInputs, NanTinyAndHugeCellSizesAreRefused) {
    expect_field_refused([](grass_field_desc& d) { d.cell_size = 0.0; }, "desc->cell_size", GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.cell_size = 1e-9; }, "desc->cell_size", GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.cell_size = 1e9; }, "desc->cell_size", GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.cell_size = -0.25; }, "desc->cell_size", GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.cell_size = kNaN; }, "desc->cell_size", GRASS_MSG_NOT_FINITE);
    expect_field_refused([](grass_field_desc& d) { d.cell_size = kInf; }, "desc->cell_size", GRASS_MSG_NOT_FINITE);
    expect_still_usable();
}

TEST_F(ExtremeInputs, ZeroAndTooManyCellsAreRefused) {
    expect_field_refused([](grass_field_desc& d) { d.cells_x = 0; }, "desc->cells_x", GRASS_MSG_ZERO_CELLS);
    expect_field_refused([](grass_field_desc& d) { d.cells_x = (1u << 30) + 1; }, "desc->cells_x",
                         GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.cells_z = 0xffffffffu; }, "desc->cells_z", GRASS_MSG_OUT_OF_RANGE);
    // 2^30 each way is the documented limit, and is accepted (the quadtree is implicit).
    grass_field_desc d = valid_field();
    d.cells_x = d.cells_z = 1u << 30;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    expect_still_usable();
}

TEST_F(ExtremeInputs, NanAndFarTranslationsOfTheBaseTransformAreRefused) {
    expect_field_refused([](grass_field_desc& d) { d.base_transform[0] = kNaN; }, "desc->base_transform[0]",
                         GRASS_MSG_NOT_FINITE);
    expect_field_refused([](grass_field_desc& d) { d.base_transform[12] = kInf; }, "desc->base_transform[12]",
                         GRASS_MSG_NOT_FINITE);
    // Beyond 1e12 m (where a double's spacing reaches 0.1 mm; the camera has the same bound).
    expect_field_refused([](grass_field_desc& d) { d.base_transform[12] = 1e300; }, "desc->base_transform[12]",
                         GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.base_transform[13] = -2e12; }, "desc->base_transform[13]",
                         GRASS_MSG_OUT_OF_RANGE);
    expect_field_refused([](grass_field_desc& d) { d.base_transform[14] = 1.0000001e12; }, "desc->base_transform[14]",
                         GRASS_MSG_OUT_OF_RANGE);
    // A huge rotation entry is not a rotation.
    expect_field_refused([](grass_field_desc& d) { d.base_transform[5] = 1e300; }, "desc->base_transform",
                         GRASS_MSG_BAD_TRANSFORM);
    grass_field_desc d = valid_field();
    d.base_transform[12] = 1e12;
    d.base_transform[14] = -1e12;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << "the bound itself is accepted: " << last_message();
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    expect_still_usable();
}

TEST_F(ExtremeInputs, InfiniteAndHugeHeightScalesAreRefused) {
    grass_map_desc m = grass_default_map_desc();
    const uint8_t texels[4] = {0, 64, 128, 255};
    m.pixels = texels;
    m.width = m.height = 2;
    grass_map_id height{};
    ASSERT_EQ(grass_create_map(ctx, &m, &height), GRASS_SUCCESS) << last_message();
    for (const float scale : {kInff, -kInff, kNaNf}) {
        expect_field_refused(
            [&](grass_field_desc& d) {
                d.maps.height = height;
                d.maps.height_scale = scale;
            },
            "desc->maps.height_scale", GRASS_MSG_NOT_FINITE);
    }
    for (const float scale : {1e30f, 3e38f, 1.0001e5f, -1.0f}) {
        expect_field_refused(
            [&](grass_field_desc& d) {
                d.maps.height = height;
                d.maps.height_scale = scale;
            },
            "desc->maps.height_scale", GRASS_MSG_OUT_OF_RANGE);
    }
    // 1e5 m, the documented limit, is accepted.
    grass_field_desc d = valid_field();
    d.maps.height = height;
    d.maps.height_scale = 1e5f;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    expect_still_usable();
}

} // namespace
