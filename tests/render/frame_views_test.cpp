// Frames and views (grass.h "Frames and views"; docs/integration.md): a host frame of a main
// camera and three orthographic shadow-cascade views, each drawn into its own quadrant of one
// target (a shadow atlas's layout), in both backends:
// - every view of the multi-view frame, planned all before any is drawn, is pixel for pixel
//   that view drawn alone by grass_begin_frame (so planning a view changed no other view's
//   plan or per-frame data), over the geometry, volume and image tiers and with wind;
// - the frames report completed frames as a host with two frames in flight does (the newest
//   finished frame lags two behind), on Vulkan under the synchronization validation;
// - misuse is refused naming the argument and the value, and leaves the earlier state: frame
//   indices that do not grow, a completed frame that is not older, a view that was not
//   planned, a view planned outside a frame, and (Vulkan) a frame for which every frame slot
//   is still held by an unfinished frame.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace grass_test {
namespace {

constexpr uint32_t kQuadrant = 96;       // each view's viewport, in pixels
constexpr uint32_t kCells = 48;          // 12 m x 12 m
const double kEye[3] = {6.0, 1.5, -1.0}; // the main camera
const double kLook[3] = {6.0, 0.0, 6.0};
constexpr double kCascadeHalf[3] = {2.0, 4.0, 6.0}; // half extents of the cascades, metres
constexpr double kCascadeHeight = 20.0;             // metres above the ground

class FrameViewsTest : public RenderTest {
protected:
    void SetUp() override {
        // Vulkan: the synchronization validation too (read when the host makes its instance).
        setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 1);
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = 2 * kQuadrant;
        t.height = 2 * kQuadrant;
        start(t);
    }
    void TearDown() override {
        RenderTest::TearDown();
        unsetenv("VK_LAYER_ENABLES");
    }

    // Geometry near, a volume of 2 slices, the horizontal slice far (RenderTest::three_tier_field).
    grass_field_id make_tiered_field() { return make_field(three_tier_field(kCells)); }

    // The viewport of quadrant q (0: top left, 1: top right, 2: bottom left, 3: bottom right)
    // in the backend's convention (GL: lower-left origin).
    void quadrant_viewport(int q, int32_t out[4]) const {
        const int32_t x = (q % 2) * int32_t(kQuadrant), top = (q / 2) * int32_t(kQuadrant);
        const bool gl = GetParam() == GRASS_BACKEND_GL;
        out[0] = x;
        out[1] = gl ? int32_t(2 * kQuadrant) - top - int32_t(kQuadrant) : top;
        out[2] = out[3] = int32_t(kQuadrant);
    }

    // The main camera (quadrant 0) and the cascades (1-3): straight down over the field's
    // centre, orthographic, their lod origin the main camera's position (so their blades and
    // tiers are the main view's).
    std::vector<grass_view_desc> views(double time) {
        std::vector<grass_view_desc> out;
        grass_view_desc main = view(kEye, kLook);
        // The projection of a square viewport (view() takes the whole target's aspect: square too).
        main.time = time;
        quadrant_viewport(0, main.viewport);
        out.push_back(main);
        const bool vulkan = GetParam() == GRASS_BACKEND_VULKAN;
        const double near_m = 1.0, far_m = 40.0;
        for (int c = 0; c < 3; ++c) {
            const double eye[3] = {6.0, kCascadeHeight, 6.0}, at[3] = {6.0, 0.0, 6.0};
            grass_view_desc v = view(eye, at);
            std::memset(v.projection, 0, sizeof v.projection);
            v.projection[0] = float(1.0 / kCascadeHalf[c]);
            v.projection[5] = float((vulkan ? -1.0 : 1.0) / kCascadeHalf[c]);
            v.projection[10] = float(vulkan ? -1.0 / (far_m - near_m) : -2.0 / (far_m - near_m));
            v.projection[14] = float(vulkan ? -near_m / (far_m - near_m) : -(far_m + near_m) / (far_m - near_m));
            v.projection[15] = 1.0f;
            v.time = time;
            quadrant_viewport(c + 1, v.viewport);
            lod_origin_[c] = grass_default_lod_origin_desc();
            std::memcpy(lod_origin_[c].position, kEye, sizeof kEye);
            v.next = &lod_origin_[c];
            out.push_back(v);
        }
        return out;
    }

    // One host frame of every view in `vs`, planned all before any is drawn, each drawn once.
    grass_host::Image render_frame(const grass_frame_desc& frame, const std::vector<grass_view_desc>& vs) {
        std::vector<uint32_t> indices(vs.size(), ~0u);
        host->begin_grass_frame = [&](grass_context* c) {
            grass_result r = grass_begin_host_frame(c, &frame);
            for (size_t i = 0; r == GRASS_SUCCESS && i < vs.size(); ++i) r = grass_plan_view(c, &vs[i], &indices[i]);
            return r;
        };
        host->draw_grass = [&](grass_context* c, void* cmd) {
            grass_result r = GRASS_SUCCESS;
            for (size_t i = vs.size(); r == GRASS_SUCCESS && i-- > 0;) { // the last planned first
                if (GetParam() == GRASS_BACKEND_GL) {
                    r = grass_gl_render_view(c, indices[i]);
                } else {
                    grass_vk_record_desc record = grass_default_vk_record_desc();
                    record.command_buffer = cmd;
                    r = grass_vk_record_view(c, indices[i], &record);
                }
            }
            return r;
        };
        const grass_host::Image image = render(vs[0]);
        host->begin_grass_frame = nullptr;
        host->draw_grass = nullptr;
        for (size_t i = 0; i < vs.size(); ++i) EXPECT_EQ(indices[i], i) << "grass_plan_view numbers views from 0";
        return image;
    }

    // Pixels of quadrant q that differ between a and b.
    static size_t differing(const grass_host::Image& a, const grass_host::Image& b, int q) {
        size_t n = 0;
        const uint32_t x0 = (q % 2) * kQuadrant, y0 = (q / 2) * kQuadrant;
        for (uint32_t y = y0; y < y0 + kQuadrant; ++y) {
            for (uint32_t x = x0; x < x0 + kQuadrant; ++x) n += std::memcmp(a.pixel(x, y), b.pixel(x, y), 3) != 0;
        }
        return n;
    }

    grass_lod_origin_desc lod_origin_[3] = {};
};

TEST_P(FrameViewsTest, EachViewOfAFrameIsThatViewDrawnAlone) {
    make_tiered_field();
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << log;
    uint8_t sky[3];
    expected_sky(host->target(), sky);

    // Four host frames, two in flight: frame n is begun knowing frame n - 2 finished.
    grass_host::Image multi;
    double time = 1.0;
    for (uint64_t n = 1; n <= 4; ++n, time += 0.25) {
        grass_frame_desc frame = grass_default_frame_desc();
        frame.frame_index = n;
        frame.completed_frame_index = n > 2 ? n - 2 : 0;
        frame.time = time;
        multi = render_frame(frame, views(time));
        ASSERT_FALSE(HasFailure()) << log;
    }
    save(multi, "frame_views_multi");
    time -= 0.25; // the last frame's

    // Each view alone, at the last frame's time (grass_begin_frame: the view's time is the frame's).
    const std::vector<grass_view_desc> vs = views(time);
    grass_frame_stats stats{};
    for (int q = 0; q < 4; ++q) {
        const grass_host::Image alone = render(vs[q]);
        ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        save(alone, "frame_views_alone_" + std::to_string(q));
        const uint32_t x0 = (q % 2) * kQuadrant, y0 = (q / 2) * kQuadrant;
        const double share = grass_share(alone, sky, x0, y0, x0 + kQuadrant, y0 + kQuadrant);
        EXPECT_GT(share, 0.3) << "view " << q << " draws too little grass to compare";
        // Alone, a view is view 0: its geometry draws run the window variant, which GL compacts
        // (docs/responsive.md "Culled blades compacted"), where in the multi-view frame a later
        // view's cells beyond view 0's window run the per-vertex variant: up to rounding, one
        // edge pixel of a 64 x 64 quadrant (seen: 1).
        EXPECT_LE(differing(multi, alone, q), 2u) << "view " << q << " of the multi-view frame differs from it alone";
        // Every tier kind is drawn by the main view.
        if (q == 0) {
            for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) EXPECT_GT(stats.instances[k], 0u) << "tier kind " << k;
        }
    }
}

TEST_P(FrameViewsTest, MisuseIsRefusedAndLeavesTheFrameAsItWas) {
    make_tiered_field();
    const std::vector<grass_view_desc> vs = views(0.0);
    uint32_t index = 99;
    // A view outside a frame.
    EXPECT_EQ(grass_plan_view(ctx, &vs[0], &index), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(log.find("grass_plan_view: no frame has begun"), std::string::npos) << log;
    EXPECT_EQ(index, 99u);

    grass_frame_desc frame = grass_default_frame_desc();
    frame.frame_index = 5;
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_plan_view(ctx, &vs[0], &index), GRASS_SUCCESS) << log;
    EXPECT_EQ(index, 0u);
    // A bad view is refused; the frame keeps its one view.
    grass_view_desc bad = vs[1];
    bad.viewport[2] = 0;
    index = 99;
    EXPECT_EQ(grass_plan_view(ctx, &bad, &index), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(index, 99u);
    // Drawing a view that was not planned.
    log.clear();
    if (GetParam() == GRASS_BACKEND_GL) {
        EXPECT_EQ(grass_gl_render_view(ctx, 1), GRASS_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(log.find("grass_gl_render_view: view is 1, but the begun frame has 1 planned view(s)"),
                  std::string::npos)
            << log;
    } else {
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = reinterpret_cast<void*>(uintptr_t(1)); // refused before it is used
        EXPECT_EQ(grass_vk_record_view(ctx, 1, &record), GRASS_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(log.find("grass_vk_record_view: view is 1, but the begun frame has 1 planned view(s)"),
                  std::string::npos)
            << log;
    }
    // A second frame inside the first.
    frame.frame_index = 6;
    EXPECT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_ERROR_INVALID_STATE);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    // Frame indices grow; the completed one is older and does not go back.
    log.clear();
    frame.frame_index = 5;
    EXPECT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(log.find("frame->frame_index is 5; it must be at least 1 and greater than the previous frame's 5"),
              std::string::npos)
        << log;
    frame.frame_index = 6;
    frame.completed_frame_index = 6;
    EXPECT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(log.find("frame->completed_frame_index is 6; it must be less than frame_index 6"), std::string::npos)
        << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused frame is not begun";

    // Frames 5 and 6, begun with none finished, hold both frame slots of a Vulkan context made
    // with frames_in_flight 2: frame 7 is refused until the host reports frame 5 finished.
    frame.frame_index = 6;
    frame.completed_frame_index = 0;
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    log.clear();
    frame.frame_index = 7;
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        EXPECT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_ERROR_INVALID_STATE);
        EXPECT_NE(log.find("grass_begin_host_frame: frame 7 needs a frame slot, but all 2"), std::string::npos) << log;
        EXPECT_NE(log.find(std::to_string(int(GRASS_MSG_FRAMES_IN_FLIGHT)) + ":"), std::string::npos) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused frame is not begun";
        frame.completed_frame_index = 5;
    }
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << log;
    uint32_t index2 = 99;
    ASSERT_EQ(grass_plan_view(ctx, &vs[0], &index2), GRASS_SUCCESS) << log;
    EXPECT_EQ(index2, 0u);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

INSTANTIATE_TEST_SUITE_P(Backends, FrameViewsTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
