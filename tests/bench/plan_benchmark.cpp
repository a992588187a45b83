// Plan building (quadtree traversal, lod tests, culling, instances) for Lemme's football
// field (380 x 532 cells of 0.25 m) and for a field of 1e10 cells (100,000 x 100,000), from
// four cameras each. No GPU: a context without backend. Run:
//   build/tests/grass_plan_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <grass/grass.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Camera {
    const char* name;
    double eye[3];    // relative to the field's centre line: x from its middle, z from its near end
    double target[3];
};

// High overview, player height, an ant's eye, grazing towards the horizon.
const Camera kCameras[4] = {
    {"high", {0.0, 60.0, -40.0}, {0.0, 0.0, 80.0}},
    {"player", {0.0, 1.7, 6.0}, {0.0, 0.0, 60.0}},
    {"ant", {-0.2, 0.05, 6.0}, {-0.2, 0.04, 20.0}},
    {"grazing", {-0.2, 3.0, -2.0}, {-0.2, 2.9, 400.0}},
};

grass_view_desc make_view(const double eye[3], const double target[3], float far_m) {
    grass_view_desc v = grass_default_view_desc();
    for (int c = 0; c < 3; ++c) v.camera_position[c] = eye[c];
    double f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    double r[3] = {-f[2], 0.0, f[0]};
    const double rl = std::sqrt(r[0] * r[0] + r[2] * r[2]);
    r[0] /= rl;
    r[2] /= rl;
    const double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    for (int k = 0; k < 16; ++k) v.view[k] = 0.0f;
    for (int c = 0; c < 3; ++c) {
        v.view[4 * c + 0] = static_cast<float>(r[c]);
        v.view[4 * c + 1] = static_cast<float>(u[c]);
        v.view[4 * c + 2] = static_cast<float>(-f[c]);
    }
    v.view[15] = 1.0f;
    const float aspect = 16.0f / 9.0f, near_m = 0.05f;
    const float t = 1.0f / std::tan(55.0f * 3.14159265f / 360.0f);
    for (float& p : v.projection) p = 0.0f;
    v.projection[0] = t / aspect;
    v.projection[5] = t;
    v.projection[10] = (far_m + near_m) / (near_m - far_m);
    v.projection[11] = -1.0f;
    v.projection[14] = 2.0f * far_m * near_m / (near_m - far_m);
    v.viewport[2] = 1280;
    v.viewport[3] = 720;
    return v;
}

void plan_field(benchmark::State& state, uint32_t cells_x, uint32_t cells_z, const Camera& cam, float far_m) {
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) std::abort();
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    grass_create_patch(ctx, &pd, &patch);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = cells_x;
    fd.cells_z = cells_z;
    fd.cell_size = 0.25;
    // The camera stands at the middle of the field's x, at its z = 0 end, looking in.
    const double mid_x = 0.5 * cells_x * fd.cell_size;
    const double start_z = 0.0;
    grass_field_id field{};
    if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) std::abort();
    const double eye[3] = {mid_x + cam.eye[0], cam.eye[1], start_z + cam.eye[2]};
    const double target[3] = {mid_x + cam.target[0], cam.target[1], start_z + cam.target[2]};
    const grass_view_desc view = make_view(eye, target, far_m);
    grass_frame_stats stats{};
    for (auto _ : state) {
        grass_begin_frame(ctx, &view);
        grass_end_frame(ctx);
        benchmark::DoNotOptimize(stats);
    }
    grass_get_frame_stats(ctx, &stats);
    state.counters["nodes"] = static_cast<double>(stats.nodes_visited);
    state.counters["lod_calls"] = static_cast<double>(stats.lod_test_calls);
    state.counters["geometry"] = static_cast<double>(stats.instances[GRASS_TIER_GEOMETRY]);
    state.counters["volume"] = static_cast<double>(stats.instances[GRASS_TIER_VOLUME]);
    state.counters["image"] = static_cast<double>(stats.instances[GRASS_TIER_IMAGE]);
    grass_destroy_context(ctx);
}

// Far planes: 500 m (a stadium: the football field is 133 m long) and 2 km (open land:
// the huge field then shows ~40x the football field's grass area).
void register_all() {
    for (const float far_m : {500.0f, 2000.0f}) {
        const std::string far = "/far" + std::to_string(static_cast<int>(far_m));
        for (const Camera& cam : kCameras) {
            benchmark::RegisterBenchmark(("plan/football/" + std::string(cam.name) + far).c_str(),
                                         [&cam, far_m](benchmark::State& s) { plan_field(s, 380, 532, cam, far_m); })
                ->Unit(benchmark::kMicrosecond);
            benchmark::RegisterBenchmark(("plan/1e10/" + std::string(cam.name) + far).c_str(),
                                         [&cam, far_m](benchmark::State& s) { plan_field(s, 100000, 100000, cam, far_m); })
                ->Unit(benchmark::kMicrosecond);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
