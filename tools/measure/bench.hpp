// grass-measure bench: the speed/accuracy trade of the quality presets (docs/quality.md).
//
// For each scene (the football field, the park, the hills; reduced for the bench, see
// kScenes) x camera (high, player height, ant, grazing; on request the game cameras third
// person, elevated, strategy, top-down and flight) x backend, it renders every preset of
// grass_quality_preset(): the REFERENCE first (blades everywhere), then the others, each on a
// target with the preset's MSAA sample count. Per frame it measures the wall time of a
// rendered and read-back frame (median of --frames frames after one warm-up), the plan time
// (grass_frame_stats.plan_ms, median), the GPU time per tier where the driver has timer
// queries (grass_get_tier_gpu_ms), and the image error against the truth of the same scene and
// camera (accuracy.hpp): the reference supersampled (--supersample times larger per axis,
// box-downsampled in linear light) with the scene's seeds, its error divided by that of the
// truth rendered with other patch and mirror seeds, at full size, x2 and x4; per row band the
// mean-colour and coverage differences; SSIM and PSNR too. The truths and the reference's timed
// frames are cached on disk (reference_cache.hpp, --references). The real scenes
// (football-real, park-real, hills-real) keep the scene files' patches; by default they are
// measured from the player camera only.
// It writes each frame and an amplified difference image into --out, and a CSV, a Markdown
// table (also printed) and an SVG plot of cost ratio against 1 - SSIM into --docs (or --out).
//
// --sweep renders, instead of the presets, DEFAULT with one knob of grass_quality_desc changed at a
// time (a few values each around DEFAULT's, the others at DEFAULT's; see sweep_variants), after
// the REFERENCE and DEFAULT presets themselves, for football / player unless --scene/--camera
// say otherwise. Each row is measured as the presets' are (against the reference's image of the
// same frame) and set against DEFAULT's row: cost / DEFAULT and the change of 1 - SSIM. It
// writes sweep.csv and a Markdown table sweep.md (also printed) into --docs (or --out), leaving
// bench.* alone.
#pragma once

#include <grass/grass.h>

#include "accuracy.hpp"
#include "headless_host.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace grass_measure {
namespace bench {

extern const char* const kLevelNames[GRASS_QUALITY_LEVEL_COUNT];

struct Options {
    std::vector<grass_backend> backends = {GRASS_BACKEND_GL, GRASS_BACKEND_VULKAN};
    std::vector<int> scenes;  // indices into kScenes; empty = all
    std::vector<int> cameras; // indices into a scene's cameras; empty = the default ones
    std::vector<int> presets; // quality levels; empty = all (ignored by --sweep)
    std::string scene_dir = GRASS_SCENE_DIR;
    std::string out = "grass-bench-out";
    std::string docs;       // CSV, Markdown and SVG here; empty: into --out
    std::string cache;      // slice cache; empty: <out>/cache
    std::string references; // reference image cache; empty: default_reference_dir()
    uint32_t width = 320, height = 180;
    uint32_t supersample = 2; // the truth: rendered supersample times larger per axis, box-downsampled
    uint64_t seed_step = 1;   // the other sample of the truth: patch and mirror seeds + seed_step
    int frames = 3;
    bool sweep = false;             // --sweep: one knob at a time from DEFAULT instead of the presets
    std::vector<std::string> knobs; // --sweep --knob: the knobs to sweep; empty = all
    bool full_tessellation = false; // --full-tessellation: no preset tessellates its blades dynamically
};

struct Row {
    std::string scene, camera, backend, preset;
    std::string knob, value; // --sweep: the knob changed from DEFAULT and its value ("preset", level name)
    int level = 0;
    uint32_t msaa = 1, blades = 0, subdivisions = 0;
    double field_ms = 0, frame_ms = 0, frame_min_ms = 0, ratio = 1, plan_ms = 0;
    bool gpu_available = false;
    double gpu_ms[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
    double ssim = 1, psnr = std::numeric_limits<double>::infinity(); // against the truth (seeds A)
    double ssim_other = 1;                                           // against the truth of the other seeds (B)
    grass_bench::ImageError error;                                   // against the truth (seeds A)
    grass_bench::ImageError seed;                                    // the truth with seeds B against A
    grass_bench::ImageError norm;                                    // error / seed
    bool cached = false;                                  // the reference's frame came from the reference cache
    double backend_diff_mean = -1, backend_diff_max = -1; // vk reference rows: against GL's, sRGB levels
    grass_host::Image native_reference;                   // reference rows, until the run compares the backends
    uint64_t triangles = 0, instances[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
    // The share of grass pixels (grass_bench::is_grass) in the frame and in truth A: how much
    // of the view the camera's grass fills (the game cameras from high up see the part small).
    double grass_share = 0, truth_grass_share = 0;
    double gpu_total() const { return gpu_ms[0] + gpu_ms[1] + gpu_ms[2]; }
};

inline std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof(b), f, v);
    return b;
}
inline std::string psnr_text(double p) { return std::isinf(p) ? "inf" : fmt("%.2f", p); }
inline std::string gpu_text(const Row& r, int tier) {
    if (!r.gpu_available) return "n/a";
    return fmt("%.2f", tier < 0 ? r.gpu_total() : r.gpu_ms[tier]);
}

// The reports (bench_report.cpp): the presets' CSV, Markdown table and SVG plot of cost
// against error, and --sweep's CSV and Markdown table. total_s: the run's duration.
std::string csv(const std::vector<Row>& rows, const Options& o);
std::string markdown(const std::vector<Row>& rows, const Options& o, double total_s);
std::string svg(const std::vector<Row>& rows);
std::string sweep_csv(const std::vector<Row>& rows, const Options& o);
std::string sweep_markdown(const std::vector<Row>& rows, const Options& o, double total_s);

} // namespace bench
} // namespace grass_measure
