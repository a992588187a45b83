// The plan of a stereo frame (grass_stereo_view_desc) and the lod origin
// (grass_lod_origin_desc), without a GPU:
// - a stereo frame culls against the union of the eyes' frusta: eyes looking apart plan
//   more cells than either eye alone;
// - its lod distances are measured from the eyes' midpoint, as a mono frame's from a
//   grass_lod_origin_desc (the root node's distances, as a lod callback sees them);
// - a bad extension chain or a bad extension is refused, naming it, and no frame begins;
// - the Frame block tells the shaders the lod origin (relative to the plan's origin) and an
//   orthographic view's axis (zero for perspective views and stereo frames).
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"

#include <cmath>
#include <cstring>

namespace {

class StereoPlanTest : public CoreTest {
protected:
    // A 16 m x 16 m field of blades (cells of 1/4 m) drawn within 30 m, asking `test`.
    void make_field(const grass_lod_test& test) {
        patch = make_patch();
        tier = grass_tier_desc{GRASS_TIER_GEOMETRY, 0};
        lod = test;
        grass_field_desc d = one_tier_field(patch, 64, &tier, &lod);
        grass_field_id field{};
        ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
    }
    grass_frame_stats frame(const grass_view_desc& view) {
        grass_frame_stats stats{};
        EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        return stats;
    }
    static grass_stereo_view_desc second_eye(const grass_view_desc& eye) {
        grass_stereo_view_desc s = grass_default_stereo_view_desc();
        std::memcpy(s.camera_position, eye.camera_position, sizeof(s.camera_position));
        std::memcpy(s.view, eye.view, sizeof(s.view));
        std::memcpy(s.projection, eye.projection, sizeof(s.projection));
        return s;
    }
    grass_patch_id patch{};
    grass_tier_desc tier{};
    grass_lod_test lod{};
};

grass_lod_test band(float end) {
    grass_lod_test t{};
    t.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    t.end = end;
    return t;
}

TEST_F(StereoPlanTest, AStereoFramePlansWhatEitherEyeSees) {
    make_field(band(30.0f));
    // Eyes in the middle of the field, looking apart along -x and +x with a narrow view.
    const double left_eye[3] = {7.9, 1.5, 8.0}, right_eye[3] = {8.1, 1.5, 8.0};
    const double left_look[3] = {0.0, 0.0, 8.0}, right_look[3] = {16.0, 0.0, 8.0};
    const grass_view_desc left = test_view(left_eye, left_look, 30.0f), right = test_view(right_eye, right_look, 30.0f);
    grass_view_desc stereo = left;
    const grass_stereo_view_desc second = second_eye(right);
    stereo.next = &second;
    const uint64_t both = frame(stereo).cells_drawn, l = frame(left).cells_drawn, r = frame(right).cells_drawn;
    EXPECT_GT(l, 100u);
    EXPECT_GT(r, 100u);
    // The frusta barely overlap: the stereo plan holds both eyes' cells.
    EXPECT_GE(both + 16, l + r) << "left " << l << ", right " << r;
    EXPECT_LE(both, l + r);
}

// The root node's distances, as the lod callback sees them (its first call of a frame).
struct RootDistances {
    bool seen = false;
    double min = 0.0, max = 0.0;
};

grass_lod_answer record_root(void* user, const grass_lod_node* node) {
    auto* root = static_cast<RootDistances*>(user);
    if (!root->seen) {
        root->seen = true;
        root->min = node->distance_min;
        root->max = node->distance_max;
    }
    return node->level == 0 ? GRASS_LOD_DRAW : GRASS_LOD_SPLIT;
}

TEST_F(StereoPlanTest, TheLodOfAStereoFrameIsMeasuredFromTheEyesMidpoint) {
    RootDistances root;
    grass_lod_test test{};
    test.kind = GRASS_LOD_TEST_CALLBACK;
    test.callback = &record_root;
    test.user_data = &root;
    make_field(test);
    const double left_eye[3] = {-3.0, 2.0, -1.0}, right_eye[3] = {-1.0, 2.0, -1.0}, middle[3] = {-2.0, 2.0, -1.0};
    const double look[3] = {8.0, 0.0, 8.0};
    const grass_view_desc left = test_view(left_eye, look), right = test_view(right_eye, look);
    const auto root_of = [&](const grass_view_desc& view) {
        root = RootDistances{};
        frame(view);
        EXPECT_TRUE(root.seen);
        return root;
    };
    grass_view_desc stereo = left;
    const grass_stereo_view_desc second = second_eye(right);
    stereo.next = &second;
    const RootDistances from_stereo = root_of(stereo);
    const RootDistances from_middle = root_of(test_view(middle, look));
    const RootDistances from_left = root_of(left);
    EXPECT_DOUBLE_EQ(from_stereo.min, from_middle.min);
    EXPECT_DOUBLE_EQ(from_stereo.max, from_middle.max);
    EXPECT_GT(std::fabs(from_left.min - from_middle.min), 0.1);
    // A mono frame with a lod origin measures from it.
    grass_lod_origin_desc origin = grass_default_lod_origin_desc();
    std::memcpy(origin.position, middle, sizeof(origin.position));
    grass_view_desc moved = left;
    moved.next = &origin;
    const RootDistances from_origin = root_of(moved);
    EXPECT_DOUBLE_EQ(from_origin.min, from_middle.min);
    EXPECT_DOUBLE_EQ(from_origin.max, from_middle.max);
}

TEST_F(StereoPlanTest, ABadExtensionIsRefusedByName) {
    make_field(band(30.0f));
    const double eye[3] = {8.0, 1.5, -1.0}, look[3] = {8.0, 0.0, 8.0};
    grass_view_desc view = test_view(eye, look);
    grass_stereo_view_desc second = second_eye(view);
    grass_lod_origin_desc origin = grass_default_lod_origin_desc();

    // A struct that is not a view extension.
    grass_wind_desc wind = grass_default_wind_desc();
    view.next = &wind;
    EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(last_message().find("view->next chain element 0"), std::string::npos) << last_message();
    // Each extension once.
    view.next = &origin;
    origin.next = &second;
    second.next = &origin;
    EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(last_message().find("view->next chain element 2"), std::string::npos) << last_message();
    second.next = nullptr;
    // Bad values, named.
    origin.position[1] = 2e12;
    EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass_lod_origin_desc->position[1] is 2e+12"), std::string::npos) << last_message();
    origin.position[1] = 0.0;
    for (float& v : second.view) v = 0.0f;
    EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass_stereo_view_desc->view has a singular rotation"), std::string::npos)
        << last_message();
    // No frame began: ending one is refused, and a good frame begins.
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE);
    std::memcpy(second.view, view.view, sizeof(second.view));
    EXPECT_GT(frame(view).cells_drawn, 0u);
}

// What the shaders measure the tiers' distances from, and which way an orthographic view's
// parallel rays run (frame_plan.hpp FrameUniforms target.yzw, lod_origin).
TEST_F(StereoPlanTest, TheFrameBlockCarriesTheLodOriginAndAnOrthographicViewsAxis) {
    make_field(band(30.0f));
    const double eye[3] = {8.0, 30.0, -2.0}, look[3] = {8.0, 0.0, 8.0};
    const double d[3] = {0.0, -30.0, 10.0}, len = std::sqrt(1000.0);
    const auto frame_block = [&](const grass_view_desc& view) {
        EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
        const grass::FrameUniforms f = ctx->plan.frame;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        return f;
    };
    // Perspective: no axis, the lod origin at the camera.
    grass::FrameUniforms f = frame_block(test_view(eye, look));
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(f.target[1 + c], 0.0f);
        EXPECT_EQ(f.lod_origin[c], 0.0f);
    }
    // Orthographic (a box 10 m high starting 5 m behind the eye): the unit direction it looks along.
    grass_view_desc ortho = test_ortho_view(eye, look, 10.0f, 1.0f, -5.0f, 60.0f);
    f = frame_block(ortho);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.target[1 + c], d[c] / len, 1e-6) << c;
    // A lod origin: relative to the camera.
    grass_lod_origin_desc origin = grass_default_lod_origin_desc();
    std::memcpy(origin.position, look, sizeof(origin.position));
    ortho.next = &origin;
    f = frame_block(ortho);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(f.target[1 + c], d[c] / len, 1e-6) << c;
        EXPECT_EQ(f.lod_origin[c], float(look[c] - eye[c])) << c;
    }
    // A stereo frame is drawn as perspective (a headset's eyes are), even with orthographic eyes, and
    // its plan's origin is its lod origin.
    const double right_eye[3] = {8.2, 30.0, -2.0};
    grass_view_desc stereo = ortho;
    const grass_stereo_view_desc second = second_eye(test_ortho_view(right_eye, look, 10.0f, 1.0f, -5.0f, 60.0f));
    stereo.next = &second;
    f = frame_block(stereo);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(f.target[1 + c], 0.0f);
        EXPECT_EQ(f.lod_origin[c], 0.0f);
    }
}

// Where the rays of a view under any projection matrix start (frame_plan.hpp FrameUniforms
// projection_centre, target.yzw): the camera for an ordinary perspective; the spot of a
// perspective placed off camera_position by the projection's translation; at infinity along
// the light for a light-space perspective warp of an orthographic box.
TEST_F(StereoPlanTest, TheFrameBlockCarriesTheCentreOfProjection) {
    make_field(band(30.0f));
    const double eye[3] = {8.0, 30.0, -2.0}, look[3] = {8.0, 0.0, 8.0};
    const auto frame_block = [&](const grass_view_desc& view) {
        EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
        const grass::FrameUniforms f = ctx->plan.frame;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        return f;
    };
    grass_view_desc plain = test_view(eye, look);
    grass::FrameUniforms f = frame_block(plain);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(f.projection_centre[c], 0.0f) << c;
    // The same frustum, camera_position 3 m to the side and 2 m lower: the projection moves
    // it back (P T(R o), o the offset), its rays start at the eye, (-3, 2, 0) from the camera.
    const double offset[3] = {3.0, -2.0, 0.0};
    grass_view_desc moved = plain;
    double shift[3] = {0, 0, 0};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) shift[r] += plain.view[4 * c + r] * offset[c];
    }
    for (int r = 0; r < 4; ++r) {
        moved.projection[12 + r] = float(plain.projection[r] * shift[0] + plain.projection[4 + r] * shift[1] +
                                         plain.projection[8 + r] * shift[2] + plain.projection[12 + r]);
    }
    for (int c = 0; c < 3; ++c) moved.camera_position[c] += offset[c];
    f = frame_block(moved);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(f.projection_centre[c], -offset[c], 1e-4) << c;
        EXPECT_EQ(f.target[1 + c], 0.0f) << c;
    }
    // An orthographic box warped in its image's y (w' = 0.5 y + w): parallel rays, the axis.
    grass_view_desc warped = test_ortho_view(eye, look, 10.0f, 1.0f, -5.0f, 60.0f);
    for (int col = 0; col < 4; ++col) warped.projection[4 * col + 3] += 0.5f * warped.projection[4 * col + 1];
    f = frame_block(warped);
    const double d[3] = {0.0, -30.0, 10.0}, len = std::sqrt(1000.0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(f.target[1 + c], d[c] / len, 1e-6) << c;
        EXPECT_EQ(f.projection_centre[c], 0.0f) << c;
    }
}

} // namespace
