// grass-measure first-frame: the hitch of the first windy frame, with and without
// grass_prepare_pipelines (issue 34 item 1; the record is docs/records/prepare-pipelines.md).
// Each run makes a fresh host, context, patch (default) and field (64 x 64 cells, the default
// three tiers) seen from 2 m, renders one still frame (uploads, still grass's variants), then:
//   without: turns on wind (5 m/s) and times the next frame, then a second windy frame;
//   with:    times grass_prepare_pipelines(default features, or --features), then the same
//            two frames.
// --features takes a grass_pipeline_desc.features mask (0x3E0: the views of an engine's
// frame); with GRASS_PIPELINE_FEATURE_GBUFFER it chains the layout {albedo, velocity}. The
// target then holds every view (--view-targets: Vulkan's depth-only, velocity and G-buffer
// targets, an RGBA32F attachment 1), so that no view mode is skipped.
// A frame's time is its wall clock and the process's CPU time (CLOCK_PROCESS_CPUTIME_ID, every
// thread: llvmpipe and lavapipe compile and draw on the CPU) around Host::render (begin, record,
// submit, wait, read back). The second windy frame is the steady state: the first minus it is
// the hitch. Medians over --runs runs; runs alternate without / with.
// Usage: grass-measure first-frame [--backend gl|vk] [--runs N] [--features MASK] [--view-targets]
#include "cli.hpp"
#include "headless_host.hpp"
#include "measure.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace grass_measure {
namespace first_frame {

namespace {

struct Options {
    grass_backend backend = GRASS_BACKEND_VULKAN;
    int runs = 5;
    std::string features; // empty: the default desc's
    bool view_targets = false;
};

// The features to prepare: --features parsed as C does (0x for hex), or the default.
uint32_t features_of(const Options& o) {
    if (o.features.empty()) return grass_default_pipeline_desc().features;
    size_t used = 0;
    const unsigned long v = std::stoul(o.features, &used, 0);
    if (used != o.features.size()) throw grass_sample::Failure("--features " + o.features + ": not a number");
    return static_cast<uint32_t>(v);
}

struct Clock {
    double wall_ms = 0.0, cpu_ms = 0.0;
};

Clock now() {
    timespec wall{}, cpu{};
    clock_gettime(CLOCK_MONOTONIC, &wall);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
    return {wall.tv_sec * 1e3 + wall.tv_nsec * 1e-6, cpu.tv_sec * 1e3 + cpu.tv_nsec * 1e-6};
}

Clock since(const Clock& start) {
    const Clock end = now();
    return {end.wall_ms - start.wall_ms, end.cpu_ms - start.cpu_ms};
}

struct Run {
    Clock prepare, first, second; // prepare: zero without preparation
    uint64_t blob_bytes = 0;      // grass_get_pipeline_cache_data after the frames
};

Run run_once(const Options& o, bool prepared) {
    grass_host::TargetDesc target;
    target.width = target.height = 256;
    if (o.view_targets) {
        target.read_depth = target.vk_depth_pass = true;
        target.vk_gbuffer_formats[0] = 109; // VK_FORMAT_R32G32B32A32_SFLOAT: velocity and G-buffer target
        target.vk_velocity_attachment = 1;
    }
    std::string error;
    std::unique_ptr<grass_host::Host> host = grass_host::Host::create(o.backend, target, &error);
    if (!host) throw grass_sample::Failure(error);
    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = &grass_sample::log_to_stderr;
    grass_context* ctx = nullptr;
    grass_sample::check(host->create_context(cd, &ctx), "grass_*_create_context");
    struct Guard {
        grass_context* ctx;
        ~Guard() { grass_destroy_context(ctx); }
    } guard{ctx};
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    grass_sample::check(grass_create_patch(ctx, &pd, &patch), "grass_create_patch", ctx);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    grass_field_id field{};
    grass_sample::check(grass_create_field(ctx, &fd, &field), "grass_create_field", ctx);

    const double eye[3] = {8.0, 2.0, -1.0}, look[3] = {8.0, 0.0, 10.0};
    grass_view_desc view = grass_host::make_view(*host, eye, look, 50.0f, 0.05f, 200.0f);
    grass_host::Image image;
    const auto frame = [&](double time) {
        view.time = time;
        const Clock start = now();
        const grass_result r = host->render(ctx, view, nullptr, &image, &error);
        if (r != GRASS_SUCCESS) throw grass_sample::Failure("Host::render: " + error + " " + grass_get_last_error(ctx));
        return since(start);
    };
    frame(0.0); // uploads and still grass
    Run run;
    if (prepared) {
        grass_pipeline_desc pipelines = grass_default_pipeline_desc();
        pipelines.features = features_of(o);
        grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
        layout.attachment_count = 2;
        layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
        layout.attachments[1].semantic = GRASS_GBUFFER_VELOCITY;
        layout.attachments[1].format = GRASS_GBUFFER_FORMAT_FLOAT;
        if (pipelines.features & GRASS_PIPELINE_FEATURE_GBUFFER) pipelines.next = &layout;
        const Clock start = now();
        grass_sample::check(grass_prepare_pipelines(ctx, &pipelines), "grass_prepare_pipelines", ctx);
        run.prepare = since(start);
    }
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 5.0f;
    grass_sample::check(grass_set_wind(ctx, &wind), "grass_set_wind", ctx);
    run.first = frame(1.0 / 60.0);
    run.second = frame(2.0 / 60.0);
    grass_sample::check(grass_get_pipeline_cache_data(ctx, nullptr, &run.blob_bytes), "grass_get_pipeline_cache_data",
                        ctx);
    return run;
}

double median_of(const std::vector<Run>& runs, double (*pick)(const Run&)) {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(pick(r));
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

int run(const Options& o) {
    std::vector<Run> without, with;
    for (int i = 0; i < o.runs; ++i) {
        without.push_back(run_once(o, false));
        with.push_back(run_once(o, true));
    }
    std::printf("grass-measure first-frame: %s, %d runs, features 0x%x%s, medians (ms)\n\n",
                grass_sample::backend_name(o.backend), o.runs, features_of(o), o.view_targets ? ", view targets" : "");
    std::printf("| | prepare wall | prepare CPU | 1st windy wall | 1st windy CPU | 2nd windy wall | 2nd windy CPU |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    const struct {
        const char* name;
        const std::vector<Run>* runs;
    } rows[] = {{"without preparation", &without}, {"with preparation", &with}};
    for (const auto& row : rows) {
        std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", row.name,
                    median_of(*row.runs, [](const Run& r) { return r.prepare.wall_ms; }),
                    median_of(*row.runs, [](const Run& r) { return r.prepare.cpu_ms; }),
                    median_of(*row.runs, [](const Run& r) { return r.first.wall_ms; }),
                    median_of(*row.runs, [](const Run& r) { return r.first.cpu_ms; }),
                    median_of(*row.runs, [](const Run& r) { return r.second.wall_ms; }),
                    median_of(*row.runs, [](const Run& r) { return r.second.cpu_ms; }));
    }
    const double a = median_of(without, [](const Run& r) { return r.first.wall_ms; });
    const double b = median_of(with, [](const Run& r) { return r.first.wall_ms; });
    std::printf("\nfirst windy frame, wall clock: %.1f ms without, %.1f ms with preparation (%.1fx)\n", a, b,
                b > 0.0 ? a / b : 0.0);
    std::printf("pipeline cache blob after the frames: %llu bytes without, %llu bytes with preparation\n",
                static_cast<unsigned long long>(without.back().blob_bytes),
                static_cast<unsigned long long>(with.back().blob_bytes));
    return 0;
}

} // namespace

} // namespace first_frame

Subcommand add_first_frame(CLI::App& measure) {
    auto o = std::make_shared<first_frame::Options>();
    CLI::App* app = measure.add_subcommand(
        "first-frame", "The first windy frame's time with and without grass_prepare_pipelines, and the call's own "
                       "time (docs/records/prepare-pipelines.md). Prints a Markdown table.");
    grass_sample::add_backend_option(*app, &o->backend);
    app->add_option("--runs", o->runs, "runs per case (fresh host and context each; median)")
        ->capture_default_str()
        ->check(grass_sample::at_least(1));
    app->add_option("--features", o->features,
                    "grass_pipeline_desc.features to prepare (0x for hex; default: the default desc's)");
    app->add_flag("--view-targets", o->view_targets,
                  "Vulkan: a depth-only, velocity and G-buffer target besides, so that every view mode is prepared");
    return {app, [o]() { return first_frame::run(*o); }};
}

} // namespace grass_measure
