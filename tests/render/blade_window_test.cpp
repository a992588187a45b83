// The blade window (docs/responsive.md "The blade window"): responsive grass posed once per
// frame by a compute pass draws what the per-vertex poses drew, a view whose cells the
// window does not hold poses its blades itself, and the window takes memory only while
// responsive grass is drawn. Both backends run the pass (GL in grass_gl_render, Vulkan in
// grass_vk_prepare).
#include "render_fixture.hpp"

namespace grass_test {
namespace {

grass_collider ball(double x, double z, double t) {
    grass_collider c{};
    c.shape = GRASS_COLLIDER_SPHERE;
    c.radius = 0.3f;
    c.velocity[0] = 0.8f;
    c.center[0] = x + 0.8 * t;
    c.center[1] = 0.25;
    c.center[2] = z;
    return c;
}

// A host frame of two views: view 0 `first` (planned, never drawn: it makes the window) and
// view 1 `second`.
grass_result plan_two_views(grass_context* c, const grass_frame_desc& frame, const grass_view_desc& first,
                            const grass_view_desc& second) {
    uint32_t index = 0;
    grass_result r = grass_begin_host_frame(c, &frame);
    if (r == GRASS_SUCCESS) r = grass_plan_view(c, &first, &index);
    if (r == GRASS_SUCCESS) r = grass_plan_view(c, &second, &index);
    return r;
}

// Draws view 1 of the frame on `backend`'s host (`cmd`: Vulkan's command buffer).
grass_result draw_view_one(grass_backend backend, grass_context* c, void* cmd) {
    if (backend == GRASS_BACKEND_GL) return grass_gl_render_view(c, 1);
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = cmd;
    return grass_vk_record_view(c, 1, &record);
}

class BladeWindowRenderTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND; // field_desc's geometry tier, out to 60 m
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 120;
        start(t);
    }
};

// Three frames of wind and a ball over a 4 m x 4 m field, all at the same time (time steps
// of 0: the state stays where it entered, the stateless pose), drawn by view 1 of each frame. View 0 (planned, never drawn) stands at the same eye (the interaction map follows
// it, so both runs' maps are the same): looking where view 1 looks, the window holds every
// cell view 1 draws and its draw runs the window's variant (poses read, none computed);
// looking away, it holds none of them and view 1's draw runs the per-vertex variant. The same
// picture within rounding (the pass and the vertex shader run the same step, compiled into
// different stages), and not still grass.
TEST_P(BladeWindowRenderTest, PosesOnceAFrameDrawWhatPerVertexPosesDrew) {
    const double eye[3] = {2.0, 1.4, -0.8}, look[3] = {2.0, 0.0, 2.0}, away[3] = {2.0, 2.8, -3.6};
    const grass_view_desc whole = view(eye, look, 50.0f);
    const grass_view_desc behind = view(eye, away, 50.0f);
    uint64_t dynamics_bytes[2] = {0, 0};
    const grass_host::TargetDesc target = host->target(); // a copy: start() makes a new host
    auto run = [&](int which, const grass_view_desc* first, bool responsive) {
        start(target);
        make_field(field_desc(16));
        int frame = 0;
        host->begin_grass_frame = [&](grass_context* c) {
            grass_frame_desc fd = grass_default_frame_desc();
            fd.frame_index = uint64_t(frame) + 1;
            fd.completed_frame_index = uint64_t(frame);
            // Every frame at the same time: the first steps 0 (a context's first frame), the
            // others too, so the blades' state stays the equilibrium they entered the window
            // at (docs/responsive.md "Per-blade state"), which the per-vertex variant draws.
            fd.time = 1.0;
            if (responsive) {
                grass_wind_desc wind = grass_default_wind_desc();
                wind.speed = 6.0f;
                EXPECT_EQ(grass_set_wind(c, &wind), GRASS_SUCCESS);
                const grass_collider b = ball(1.5, 1.6, fd.time);
                EXPECT_EQ(grass_set_colliders(c, &b, 1), GRASS_SUCCESS);
            }
            return plan_two_views(c, fd, *first, whole);
        };
        host->draw_grass = [&](grass_context* c, void* cmd) { return draw_view_one(GetParam(), c, cmd); };
        grass_host::Image image;
        for (frame = 0; frame < 3; ++frame) image = render(whole);
        grass_memory_stats stats{};
        EXPECT_EQ(grass_get_memory_stats(ctx, &stats), GRASS_SUCCESS);
        if (which < 2) dynamics_bytes[which] = stats.dynamics_gpu_bytes;
        host->begin_grass_frame = nullptr;
        host->draw_grass = nullptr;
        return image;
    };
    const grass_host::Image window = run(0, &whole, true);
    const grass_host::Image per_vertex = run(1, &behind, true);
    const grass_host::Image still = run(2, &whole, false);
    save(window, "window");
    save(per_vertex, "per_vertex");
    expect_grass(window, target, 0.3, "the window's frame");
    expect_grass(per_vertex, target, 0.3, "the per-vertex frame");
    const double moved = mean_difference(window, still);
    const double apart = mean_difference(window, per_vertex);
    const double share = share_apart(window, per_vertex, 32);
    std::printf("window vs per-vertex: %.4f levels, %.5f of pixels over 32; vs still grass %.2f levels; dynamics "
                "memory %llu B with view 1's cells in the window, %llu B with few\n",
                apart, share, moved, static_cast<unsigned long long>(dynamics_bytes[0]),
                static_cast<unsigned long long>(dynamics_bytes[1]));
    EXPECT_GT(moved, 2.0) << "wind and the ball must move the grass for the comparison to mean something";
    EXPECT_LT(apart, 0.01);
    EXPECT_LT(share, 0.0005);
    // The window's table and poses: more slots when view 0 looks where view 1 does.
    const grass_patch_desc pd = grass_default_patch_desc();
    EXPECT_GE(dynamics_bytes[0], dynamics_bytes[1] + uint64_t(pd.blade_count) * 32u);
}

// View 0 looks at a corner of the field: the window holds only the cells it draws. View 1
// sees the whole field; its other cells pose their blades in the vertex shader. The same
// picture as when view 0 is view 1 (every cell in the window), and not still grass. Wind
// alone: the interaction map follows view 0's camera, so with a collider the two frames'
// maps would differ by their texels' placement (0.03 levels, on Vulkan too).
TEST_P(BladeWindowRenderTest, AViewBeyondTheWindowPosesItsOwnBlades) {
    grass_field_desc fd = field_desc(8); // 2 m x 2 m, 0.25 m cells: each cell its own entry
    make_field(fd);
    const double corner_eye[3] = {0.15, 0.35, 0.05}, corner_look[3] = {0.2, 0.0, 0.3};
    const double eye[3] = {1.0, 1.6, -0.4}, look[3] = {1.0, 0.0, 1.1};
    const grass_view_desc corner = view(corner_eye, corner_look, 20.0f);
    const grass_view_desc whole = view(eye, look);
    uint64_t next_frame = 100;
    const grass_view_desc* first = &corner;
    host->begin_grass_frame = [&](grass_context* c) {
        grass_frame_desc frame = grass_default_frame_desc();
        frame.frame_index = next_frame;
        frame.completed_frame_index = next_frame - 1;
        frame.time = 1.0; // every frame at the same time: the same poses
        next_frame += 1;
        return plan_two_views(c, frame, *first, whole);
    };
    host->draw_grass = [&](grass_context* c, void* cmd) { return draw_view_one(GetParam(), c, cmd); };
    const grass_host::Image still = render(whole);
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 8.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << log;
    grass_memory_stats stats{};
    const grass_host::Image beyond = render(whole);
    ASSERT_EQ(grass_get_memory_stats(ctx, &stats), GRASS_SUCCESS);
    const uint64_t corner_bytes = stats.dynamics_gpu_bytes;
    first = &whole;
    const grass_host::Image inside = render(whole);
    ASSERT_EQ(grass_get_memory_stats(ctx, &stats), GRASS_SUCCESS);
    const uint64_t whole_bytes = stats.dynamics_gpu_bytes;
    // Still grass again: no window, and the window's buffers are gone.
    ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS) << log;
    const grass_host::Image still_again = render(whole);
    ASSERT_EQ(grass_get_memory_stats(ctx, &stats), GRASS_SUCCESS);
    const uint64_t still_bytes = stats.dynamics_gpu_bytes;
    EXPECT_EQ(mean_difference(still_again, still), 0.0);
    host->begin_grass_frame = nullptr;
    host->draw_grass = nullptr;
    save(beyond, "beyond_window");
    save(inside, "inside_window");
    expect_grass(beyond, host->target(), 0.3, "view 1 beyond the window");
    const double moved = mean_difference(beyond, still);
    const double apart = mean_difference(beyond, inside);
    const double share = share_apart(beyond, inside, 32);
    std::printf("beyond vs inside the window: %.4f levels, %.5f of pixels over 32; vs still grass %.2f levels; "
                "dynamics memory %llu B (corner window), %llu B (whole), %llu B (still again)\n",
                apart, share, moved, static_cast<unsigned long long>(corner_bytes),
                static_cast<unsigned long long>(whole_bytes), static_cast<unsigned long long>(still_bytes));
    EXPECT_GT(moved, 2.0) << "view 1 must draw responsive grass";
    EXPECT_LT(apart, 0.01);
    EXPECT_LT(share, 0.0005);
    EXPECT_GT(whole_bytes, corner_bytes) << "the corner's window must hold fewer cells than view 1 draws";
    EXPECT_LT(still_bytes, corner_bytes) << "still grass keeps no window (the blade curves stay)";
}

INSTANTIATE_TEST_SUITE_P(Backends, BladeWindowRenderTest, ::testing::ValuesIn(enabled_backends()),
                         [](const ::testing::TestParamInfo<grass_backend>& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
