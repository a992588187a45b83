// Drawing calls in the wrong order or on the wrong backend are refused, and the context
// still renders afterwards.
#include "render_fixture.hpp"

#include <cstring>

namespace grass_test {
namespace {

class RenderMisuseTest : public RenderTest {
protected:
    grass_result draw_outside_a_frame() {
        if (GetParam() == GRASS_BACKEND_GL) return grass_gl_render(ctx);
        grass_vk_record_desc r = grass_default_vk_record_desc();
        r.command_buffer = nullptr;
        return grass_vk_record(ctx, &r);
    }
    grass_result draw_with_the_other_backend() {
        if (GetParam() == GRASS_BACKEND_GL) {
            grass_vk_record_desc r = grass_default_vk_record_desc();
            return grass_vk_record(ctx, &r);
        }
        return grass_gl_render(ctx);
    }
};

TEST_P(RenderMisuseTest, RenderingBeforeAFrameHasBegunIsRefused) {
    make_field(field_desc(4));
    log.clear();
    EXPECT_EQ(draw_outside_a_frame(), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(log.find(std::to_string(int(GRASS_MSG_FRAME_NOT_BEGUN)) + ":"), std::string::npos) << log;
    // Still usable: a real frame renders grass.
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    const auto image = render(view(eye, target));
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    EXPECT_GT(grass_share(image, sky, 0, 0, image.width, image.height), 0.1);
}

TEST_P(RenderMisuseTest, DrawingWithTheOtherBackendsCallIsRefused) {
    EXPECT_EQ(draw_with_the_other_backend(), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(log.find(std::to_string(int(GRASS_MSG_WRONG_BACKEND)) + ":"), std::string::npos) << log;
}

TEST_P(RenderMisuseTest, ObjectsCanBeDestroyedAndRecreatedBetweenFrames) {
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    for (int round = 0; round < 3; ++round) {
        const grass_field_id f = make_field(field_desc(4));
        const auto image = render(view(eye, target));
        EXPECT_GT(grass_share(image, sky, 0, 0, image.width, image.height), 0.1) << "round " << round;
        ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        ASSERT_EQ(grass_destroy_patch(ctx, patch), GRASS_SUCCESS);
        grass_patch_desc p = grass_default_patch_desc();
        p.seed = 10u + static_cast<uint64_t>(round);
        ASSERT_EQ(grass_create_patch(ctx, &p, &patch), GRASS_SUCCESS);
    }
    // A frame with no field draws nothing and is fine.
    const auto empty = render(view(eye, target));
    EXPECT_EQ(grass_share(empty, sky, 0, 0, empty.width, empty.height), 0.0);
}

// A stereo frame (grass_stereo_view_desc) where the context draws mono: GL has no multiview
// path (GL_OVR_multiview: Mesa's llvmpipe has none); a Vulkan context made without a view mask
// draws into a mono pass. Refused before anything is planned; the context still renders.
TEST_P(RenderMisuseTest, AStereoFrameIsRefusedWhereTheContextDrawsMono) {
    make_field(field_desc(4));
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    grass_view_desc v = view(eye, target);
    grass_stereo_view_desc second = grass_default_stereo_view_desc();
    std::memcpy(second.view, v.view, sizeof(second.view));
    std::memcpy(second.projection, v.projection, sizeof(second.projection));
    second.camera_position[0] = eye[0] + 0.06;
    second.camera_position[1] = eye[1];
    second.camera_position[2] = eye[2];
    v.next = &second;
    log.clear();
    if (GetParam() == GRASS_BACKEND_GL) {
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_UNSUPPORTED);
        EXPECT_NE(log.find("GL_OVR_multiview"), std::string::npos) << log;
    } else {
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_STATE);
        EXPECT_NE(log.find("grass_vk_multiview_desc.view_mask 0"), std::string::npos) << log;
    }
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const auto image = render(view(eye, target));
    EXPECT_GT(grass_share(image, sky, 0, 0, image.width, image.height), 0.1);
}

INSTANTIATE_TEST_SUITE_P(Backends, RenderMisuseTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
