// grass-measure tier-cost: the frame cost of each tier per basic cell (the analogues of lemme2012
// Tables 7.1 and 7.2), measured in one run: 1024 cells (32 x 32 of 0.25 m) drawn by each
// tier alone, then by the volume (8 slices) and image tiers in macro-cells of 1, 2, 4, 8 and
// 16 cells a side. Wall time of a rendered and read-back frame, median of 5, minus the
// same frame with no grass; per basic cell. Prints a Markdown table.
// --maps: instead, the cost of each design map (docs/records/feature-cost.md). For each tier alone
// (geometry, volume 8 slices, image; single cells), the plain field (no maps), then the same
// field with each map alone (density all 1, colour with alpha 0.3, ambient, diffuse, height:
// a ramp along x, height scale 1 cell), then all five, then the plain field again (the
// run's noise). The rows are drawn in --rounds rounds (default 3), each drawing every row
// once with --frames frames after one that uploads, so that a load that comes and goes on
// the machine falls on all rows alike; per row, the median and the fastest of the pooled
// frames minus those of the empty frame (measured in each round too), their ratios to the
// plain field, and the GPU memory the context holds (grass_get_memory_stats) with that
// field and its maps alive. Maps are 128 x 128 texels (4 per cell), made for each field and
// destroyed with it.
// --features: instead, the cost of the other optional features, measured as --maps measures
// the maps (rounds, rows interleaved, the same columns plus the CPU time of the frame plan).
// For each tier alone (as --maps): the plain field with every optional feature off (no
// mirror tiling, transition window 0, no maps, one grass type), then with mirror tiling;
// then a transition zone: the field gets a second tier, the next cheaper one (geometry with
// volume 8 slices, volume 8 slices with image, image with volume 1 slice, the finer of the
// two nearer), and the two distance bands overlap in a zone 2 m wider each side than the
// field's distances from the camera, so both tiers draw every cell, each its share of the
// blades (boulanger2006 3.4); then the same with the default transition window (0.05; the
// tool's target is single-sampled, so the crossover stays exact and only the shaders'
// work shows); then a second grass type (same patch, tier and lod tests, density 1, chained
// from grass_field_desc.next); then all five maps (as --maps); then the plain field again.
// Each row's field has a patch of its own, made and destroyed with it, so that its GPU memory
// holds the baked slices its tiers need (the transition rows: the second tier's too) and no
// more; frames of the largest row before the table size the context's instance buffers
// (which keep their largest size) for every row, and each row's memory is read at least 2
// frames after its upload (Vulkan frees what the GPU may still read 2 frames late).
// The plain table also gives each row's CPU time per basic cell: the process's CPU time over
// the frame (every thread, the software rasteriser's included) minus the empty frame's. On a
// machine that others load, wall time grows with their load and CPU time far less, so the
// CPU column is the one to compare between backends there.
// --single: only the three tiers alone in single cells (geometry, volume 8 slices, image).
// --depth-pass: each row of the plain table also as a depth pass of the same view
// (grass_view_pass_desc, GRASS_PASS_DEPTH; docs/records/depth-pass.md), the rows' frames
// alternating colour and depth; per basic cell each, and the ratio depth / colour.
// --receive: each row of the plain table also receiving a shadow map (grass_shadow_receive_desc;
// GL or Vulkan; docs/records/shadow-receiving.md) that shades half the field, with filter_radius 0
// and 1.5, rounds alternating; per basic cell each, and the ratios to the plain frame.
// --lights: each row of the plain table also lit by the host's lights (grass_view_lights_desc;
// GL; docs/records/host-lights.md): 1 light, 8, and 8 with specular and harmonics.
// --motion: each row of the plain table also writing motion vectors (grass_view_motion_desc;
// docs/records/motion-vectors.md) into a velocity target (GL: an RG16F target the tool adds to
// the host's framebuffer; Vulkan: the host's RGBA32F colour attachment 1), without wind and in wind (the pose computed twice); per basic cell each, and
// the ratios to the plain frame of the same wind.
// --gbuffer: each row of the plain table also as a G-buffer view (GRASS_PASS_GBUFFER; GL;
// docs/records/gbuffer.md) into the host's colour and two RGBA8 targets the tool adds.
// --frames N: frames measured per row (after one that uploads); default 5 (median).
// Usage: grass-measure tier-cost [--backend gl|vk] [--size WxH] [--maps | --features | --single] [--frames N]
//        [--rounds N] [--depth-pass | --receive | --motion | --lights | --gbuffer]
#pragma once

#include <grass/grass.h>

#include "headless_host.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grass_measure {
namespace tier_cost {

struct Options {
    grass_backend backend = GRASS_BACKEND_GL;
    uint32_t width = 320, height = 240;
    bool maps = false, features = false;
    bool single = false;     // only the tiers alone in single cells (kSingleTiers)
    bool depth_pass = false; // --depth-pass: each plain row also as a depth pass
    bool receive = false;    // --receive: each plain row also receiving a shadow map (GL)
    bool motion = false;     // --motion: each plain row also writing motion vectors
    bool lights = false;     // --lights: each plain row also lit by the host's lights (GL)
    bool gbuffer = false;    // --gbuffer: each plain row also as a G-buffer view (GL)
    int frames = 5;
    int rounds = 3;          // --maps and --features only
    std::string patch_scene; // --patch-of: the patch of this scene file instead of the default patch
    std::string tier;        // --tier: only the rows of this tier (geometry, volume or image); empty: all
};

// One tier drawn alone: its kind, slices and largest macro-cell side (1 = single cells).
struct Setup {
    const char* name;
    grass_tier_kind kind;
    uint32_t slices;
    uint32_t macro;
};

// The tiers of the --maps and --features tables, single cells each.
extern const Setup kSingleTiers[3];

constexpr uint32_t kCells = 32;    // the field's cells a side (of the default 0.25 m)
constexpr uint32_t kMapSize = 128; // texels a side of --maps' maps, over the field

// The maps of one row of the --maps table: a bit per map role, as GRASS_FEATURES.
enum MapBits : uint32_t { kDensity = 1, kColor = 2, kAmbient = 4, kDiffuse = 8, kHeight = 16, kAll = 31 };

// The run's host, grass context (with one default patch) and camera: the whole 8 m x 8 m
// field in view, seen at 30 degrees from 9 m away. Every grass call is checked (a failure
// throws grass_sample::Failure).
class Rig {
public:
    explicit Rig(const Options& options);
    ~Rig();
    Rig(const Rig&) = delete;
    Rig& operator=(const Rig&) = delete;

    const Options& options() const { return options_; }
    grass_host::Host& host() { return *host_; }
    grass_context* ctx() { return ctx_; }
    grass_patch_id patch() const { return patch_; }
    const double* eye() const { return eye_; }
    // The median frame with no grass, measured when the rig was made: wall and CPU time.
    double empty_ms() const { return empty_ms_; }
    double empty_cpu_ms() const { return empty_cpu_ms_; }

    // The wall times of `count` frames after one that uploads (and compiles); with plan_ms,
    // also each measured frame's plan time (grass_frame_stats.plan_ms); with cpu_ms, the
    // CPU time the process spent on each (every thread: the software rasteriser's too).
    // Per basic cell, for `variants` variants of the drawn row (set_variant(v) before each
    // one's frames): 3 rounds of --frames frames each, the variants in turn (a load that comes
    // and goes falls on all), pooled per variant; the median frame minus the empty one, in
    // wall (us[v]) and in CPU time (cpu_us[v]).
    void per_cell_variants(int variants, const std::function<void(int)>& set_variant, double* us, double* cpu_us);
    std::vector<double> frame_times(int count, std::vector<double>* plan_ms = nullptr,
                                    std::vector<double>* cpu_ms = nullptr);
    // Advances grass_view_desc.time by `seconds` before each frame from now on (0, the
    // default: every frame at time 0, so the responsive grass steps 0).
    void set_time_step(double seconds) { time_step_ = seconds; }
    // Chains `pass` on the view (nullptr: none, a colour pass) for the frames from now on;
    // Vulkan draws a depth pass in the host's depth-only pass (Host::depth_only).
    void set_pass(const grass_view_pass_desc* pass) {
        view_.next = pass;
        host_->depth_only = pass != nullptr && pass->pass == GRASS_PASS_DEPTH;
    }
    // Chains `shadow` on the view (nullptr: none) for the frames from now on.
    void set_shadow(const grass_shadow_receive_desc* shadow) {
        view_.next = shadow;
        host_->depth_only = false;
    }
    // Chains `motion` on the view (nullptr: none) for the frames from now on.
    void set_motion(const grass_view_motion_desc* motion) {
        view_.next = motion;
        host_->depth_only = false;
    }
    // Chains `lights` on the view (nullptr: none) for the frames from now on.
    void set_lights(const grass_view_lights_desc* lights) {
        view_.next = lights;
        host_->depth_only = false;
    }
    const grass_view_desc& view() const { return view_; }
    grass_frame_stats frame_stats();
    grass_memory_stats memory_stats();

    // Destroys the context; the exit status: 1 if the host's validation layers spoke during
    // the run (their log on stderr), else 0.
    int finish();

private:
    const Options options_;
    std::unique_ptr<grass_host::Host> host_;
    grass_context* ctx_ = nullptr;
    grass_patch_id patch_{};
    const double eye_[3] = {4.0, 4.5, -4.0}, look_[3] = {4.0, 0.0, 4.0};
    grass_view_desc view_{};
    double empty_ms_ = 0.0, empty_cpu_ms_ = 0.0;
    double time_step_ = 0.0;
};

// A field of the 32 x 32 cells with one tier drawn alone at every distance.
struct TierField {
    grass_tier_desc tier{};
    grass_lod_test tests[2] = {};
    grass_field_desc desc{};
    TierField(const Setup& s, grass_patch_id patch);
    TierField(const TierField&) = delete; // desc points into the object
};

// Appends the lod tests of tier `tier` (single cells, as `s`) drawn between begin and end
// metres with the given transition widths; returns the count appended.
uint32_t band_tests(const Setup& s, uint32_t tier, float begin, float end, float in, float out, grass_lod_test* tests);

// Creates the maps of `bits` into `stack` (ids appended to `made`).
void make_maps(grass_context* ctx, uint32_t bits, double cell_size, grass_map_stack* stack,
               std::vector<grass_map_id>* made);

// A row's frame times minus the empty frame's: median and fastest.
struct Cost {
    double median, fastest;
};
Cost cost(const std::vector<double>& times, const std::vector<double>& empties);

int run_plain(Rig& rig); // tier_cost_plain.cpp
// --motion: the plain rows without and with motion vectors, still and in wind (tier_cost_motion.cpp).
int run_motion(Rig& rig, const std::vector<Setup>& rows);
// --lights: the plain rows without and with the host's lights (tier_cost_lights.cpp).
int run_lights(Rig& rig, const std::vector<Setup>& rows);
// GL: adds `count` renderbuffers (`formats`: GLenums) of the host's size and samples to the
// framebuffer the host left bound, as its draw buffers 1..count (tier_cost_motion.cpp);
// false when none is bound. delete_colour_targets deletes them.
bool add_colour_targets(grass_host::Host& host, uint32_t width, uint32_t height, const uint32_t* formats,
                        uint32_t count, uint32_t* out);
void delete_colour_targets(grass_host::Host& host, uint32_t count, const uint32_t* targets);
// --gbuffer: the plain rows as a colour view and as a G-buffer view (tier_cost_gbuffer.cpp).
int run_gbuffer(Rig& rig, const std::vector<Setup>& rows);
int run_maps(Rig& rig);     // tier_cost_maps.cpp
int run_features(Rig& rig); // tier_cost_features.cpp

} // namespace tier_cost
} // namespace grass_measure
