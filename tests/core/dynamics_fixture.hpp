// A context with one small field seen from above, for the responsive grass tests: frames at
// given times and camera positions, and the interaction map kept on the CPU by the reference
// pass (dynamics/interaction_pass.hpp), as a backend keeps it on the GPU.
#pragma once

#include "core_fixture.hpp"
#include "test_backend.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "dynamics/interaction_pass.hpp"

#include <cmath>
#include <vector>

// A backend that draws nothing and records what responsive grass asks of it: the blade
// curves it was given, and the map it would hold (levels x N^2 x 16 bytes while planned).
class RecordingBackend final : public HollowBackend {
public:
    grass_backend kind() const override { return GRASS_BACKEND_NONE; }
    grass_result upload_blade_curves(uint32_t, const grass::PatchData& patch) override {
        curve_uploads += 1;
        curve_bytes += patch.blade_curves.size() * sizeof(float);
        return GRASS_SUCCESS;
    }
    grass_result begin_view(const char*, uint32_t view, const grass::FramePlan& plan) override {
        if (view > 0) return GRASS_SUCCESS; // the frame's map is view 0's
        const grass::InteractionPlan& ip = plan.interaction;
        map_bytes = uint64_t(ip.levels) * ip.resolution * ip.resolution * 16;
        return GRASS_SUCCESS;
    }
    uint64_t gpu_bytes() const override { return dynamics_gpu_bytes(); }
    uint64_t dynamics_gpu_bytes() const override { return curve_bytes + map_bytes; }
    uint32_t curve_uploads = 0;
    uint64_t curve_bytes = 0, map_bytes = 0;
};

class DynamicsTest : public CoreTest {
protected:
    void SetUp() override {
        // The fixture's log, on a context whose backend is the recording backend.
        CoreTest::SetUp();
        remake_with<RecordingBackend>(&ctx);
        backend = static_cast<RecordingBackend*>(ctx->backend);
        patch = make_patch();
        tier = grass_tier_desc{GRASS_TIER_GEOMETRY, 0};
        band = grass_lod_test{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = 0;
        band.begin = 0.0f;
        band.end = 1e4f;
        grass_field_desc d = one_tier_field(patch, 16, &tier, &band);
        ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
    }

    // A view from `eye` (world) looking down at the point 4 m below and 1 m along +z.
    static grass_view_desc view_at(const double eye[3], double time) {
        const double target[3] = {eye[0], eye[1] - 4.0, eye[2] + 1.0};
        grass_view_desc v = test_view(eye, target, 60.0f, 1.0f, 0.05f, 1e4f);
        v.time = time;
        return v;
    }

    // Begins and ends a frame; then runs the interaction pass on the CPU map (when planned).
    grass_result frame(double time, const double eye[3] = nullptr) {
        const double origin[3] = {2.0, 3.0, 2.0};
        const grass_view_desc v = view_at(eye ? eye : origin, time);
        const grass_result r = grass_begin_frame(ctx, &v);
        if (r != GRASS_SUCCESS) return r;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        if (auto_pass) run_pass();
        return r;
    }

    void run_pass() {
        const grass::InteractionPlan& ip = ctx->plan.interaction;
        if (ip.levels == 0) return;
        const size_t texels = size_t(ip.resolution) * ip.resolution;
        for (uint32_t l = 0; l < ip.levels; ++l) {
            if (ip.map_is_new || map[l].size() != texels) map[l].assign(texels, grass::cleared_texel());
            grass::run_interaction_pass(ip, l, map[l].data());
        }
    }

    const grass::FramePlan& plan() const { return ctx->plan; }

    static grass_collider sphere(double x, double y, double z, float radius, float vx = 0, float vy = 0, float vz = 0) {
        grass_collider c{};
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = radius;
        c.center[0] = x, c.center[1] = y, c.center[2] = z;
        c.velocity[0] = vx, c.velocity[1] = vy, c.velocity[2] = vz;
        return c;
    }

    RecordingBackend* backend = nullptr;
    grass_patch_id patch{};
    grass_field_id field{};
    grass_tier_desc tier{};
    grass_lod_test band{};
    std::vector<grass::InteractionTexel> map[2];
    bool auto_pass = true; // frame() runs the pass on `map`
};
