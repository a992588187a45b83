// Plan building (quadtree traversal, lod tests, culling, instances) for Lemme's football
// field (380 x 532 cells of 0.25 m) and for a field of 1e10 cells (100,000 x 100,000), from
// four cameras each. No GPU: a context without backend. Run:
//   build/tests/grass_plan_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <grass/grass.h>

#include <benchmark/benchmark.h>

#include "../core/view_helpers.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Camera {
    const char* name;
    double eye[3]; // relative to the field's centre line: x from its middle, z from its near end
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
    grass_view_desc v = test_view(eye, target, 55.0f, 16.0f / 9.0f, 0.05f, far_m);
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
            benchmark::RegisterBenchmark(
                ("plan/1e10/" + std::string(cam.name) + far).c_str(),
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
