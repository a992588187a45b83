// grass-measure dynamics: the cost of responsive grass (issue 13 item 6; the record is
// docs/records/responsive.md). Measured as tier-cost --features measures the features
// (tier_cost.hpp): the 32 x 32 cells of 0.25 m seen whole, each tier drawn alone (geometry,
// volume 8 slices, image; single cells), rows drawn in --rounds rounds, each drawing every row
// once with --frames frames after one that uploads; per row the median and the fastest frame
// minus the empty frame's (measured in each round too). Time advances 1/60 s a frame, so the
// wind blows and the colliders sweep.
// The rows of each tier: still grass (no wind, no colliders: the frame as before responsive
// grass); a moderate wind (5 m/s, default gusts and turbulence); the interaction map kept
// after a frame with one collider, with none now (the pass still ages and scrolls the map);
// crowds of 1, 100, 183 (jahrmann2017's scene) and 10,000 spheres of 0.3 m moving at
// (1, 0, 0.5) m/s, on a jittered grid over the field, their centres 0.2 m up; the still grass
// again (the map released by grass_set_interaction(NULL)). The same rows with no field at
// all ("no grass") give the interaction pass alone: its frame minus the empty one is the
// pass's cost (the frame's plan, the dispatch and the compute work) with nothing drawn.
// The tool times wall clock over rendered and read-back frames (the host waits for the GPU):
// the backends' timer queries cover the tiers' draws only, and on llvmpipe they leave out the
// deferred fragment work (docs/records/quality-bench.md), so they are not used here.
// After the tables, per crowd: the pass alone against each tier's still draw, as the fraction
// of a frame that draws both (jahrmann2017 7: 0.547 ms of 8.13 ms, 7%).
// The run checks what "optional" promises, and exits 1 if any fails: a still row has no pass
// (interaction_texels 0) and no responsive GPU memory (dynamics_gpu_bytes 0: "still again" too,
// once the map is released and the responsive rows' patches are gone), and a crowd row has a
// pass, every collider in the map's window and the map's memory. (gpu_bytes is not compared:
// the frame's uniform and instance buffers keep the largest size a frame needed.)
// --quick: the image tier and no grass, crowds of 1 and 100 only (a smoke run of seconds).
// --blades: the geometry tier alone, still, wind and crowds of 1, 100 and 1000.
// Usage: grass-measure dynamics [--backend gl|vk] [--size WxH] [--frames N] [--rounds N] [--quick] [--blades]
#include "tier_cost.hpp"

#include "cli.hpp"
#include "measure.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace grass_measure {
namespace dynamics {

namespace {

using tier_cost::Cost;
using tier_cost::Rig;
using tier_cost::Setup;

constexpr double kFrameStep = 1.0 / 60.0; // s between frames
constexpr int kSettleFrames = 2;          // Vulkan frees what the GPU may still read 2 frames late
constexpr int kNoCollider = -1;           // a row without colliders or map
constexpr int kMapKept = 0;               // a row with the map of an earlier collider, none now
constexpr float kWindSpeed = 5.0f;        // m/s: a moderate breeze

struct Row {
    const char* name;
    bool wind;
    int colliders; // kNoCollider, kMapKept or the crowd's size
};

const Row kRows[] = {{"still", false, kNoCollider},         {"wind 5 m/s", true, kNoCollider},
                     {"map, 0 colliders", false, kMapKept}, {"1 collider", false, 1},
                     {"100 colliders", false, 100},         {"183 colliders", false, 183},
                     {"10000 colliders", false, 10000},     {"still again", false, kNoCollider}};
const Row kQuickRows[] = {{"still", false, kNoCollider},
                          {"wind 5 m/s", true, kNoCollider},
                          {"1 collider", false, 1},
                          {"100 colliders", false, 100},
                          {"still again", false, kNoCollider}};
// --blades: the geometry tier's rows of issue 35's cost goals (the blade window's measure).
const Row kBladeRows[] = {{"still", false, kNoCollider},   {"wind 5 m/s", true, kNoCollider},
                          {"1 collider", false, 1},        {"100 colliders", false, 100},
                          {"1000 colliders", false, 1000}, {"still again", false, kNoCollider}};

struct Options {
    tier_cost::Options rig;
    bool quick = false;
    bool blades = false;
};

// A crowd of n spheres of 0.3 m on a jittered grid over the field, moving.
std::vector<grass_collider> crowd(int n) {
    std::vector<grass_collider> out(size_t(n > 0 ? n : 0));
    const double side_m = tier_cost::kCells * 0.25;
    const int side = int(std::ceil(std::sqrt(double(n))));
    const double step = side_m / side;
    uint32_t seed = 12345u;
    const auto jitter = [&]() { // a small LCG: the same crowd in every run
        seed = seed * 1664525u + 1013904223u;
        return (double(seed >> 8) / double(1u << 24) - 0.5) * 0.5 * step;
    };
    for (int i = 0; i < n; ++i) {
        grass_collider& c = out[size_t(i)];
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = 0.3f;
        c.center[0] = (i % side + 0.5) * step + jitter();
        c.center[1] = 0.2;
        c.center[2] = (i / side + 0.5) * step + jitter();
        c.velocity[0] = 1.0f;
        c.velocity[2] = 0.5f;
    }
    return out;
}

// One row's state: its field (none for "no grass") with a patch of its own (a patch keeps its
// blade curves once a responsive frame has drawn it), wind and colliders; all undone when it
// goes (the map released with them).
class RowState {
public:
    RowState(Rig& rig, const Setup* tier, const Row& row) : ctx_(rig.ctx()) {
        if (tier) {
            const grass_patch_desc pd = grass_default_patch_desc();
            grass_sample::check(grass_create_patch(ctx_, &pd, &patch_), "grass_create_patch", ctx_);
            const tier_cost::TierField tf(*tier, patch_);
            grass_sample::check(grass_create_field(ctx_, &tf.desc, &field_), "grass_create_field", ctx_);
        }
        if (row.wind) {
            grass_wind_desc wd = grass_default_wind_desc();
            wd.speed = kWindSpeed;
            grass_sample::check(grass_set_wind(ctx_, &wd), "grass_set_wind", ctx_);
        }
        const std::vector<grass_collider> colliders = crowd(row.colliders == kMapKept ? 1 : row.colliders);
        if (!colliders.empty()) {
            grass_sample::check(grass_set_colliders(ctx_, colliders.data(), uint32_t(colliders.size())),
                                "grass_set_colliders", ctx_);
        }
        if (row.colliders == kMapKept) { // one frame makes the map; then no collider
            rig.frame_times(0);
            grass_sample::check(grass_set_colliders(ctx_, nullptr, 0), "grass_set_colliders", ctx_);
        }
    }
    ~RowState() {
        if (field_.index) grass_destroy_field(ctx_, field_);
        if (patch_.index) grass_destroy_patch(ctx_, patch_);
        grass_set_colliders(ctx_, nullptr, 0);
        grass_set_wind(ctx_, nullptr);
        grass_set_interaction(ctx_, nullptr); // releases the map
    }
    RowState(const RowState&) = delete;
    RowState& operator=(const RowState&) = delete;

private:
    grass_context* ctx_;
    grass_patch_id patch_{};
    grass_field_id field_{};
};

// The measures of one tier's rows over every round (stats and memory: the last round's).
struct TierRows {
    std::vector<std::vector<double>> times, plans;
    std::vector<double> empties;
    std::vector<grass_frame_stats> stats;
    std::vector<grass_memory_stats> memory;
    explicit TierRows(size_t rows) : times(rows), plans(rows), stats(rows), memory(rows) {}
};

void measure_row(Rig& rig, const Setup* tier, const Row& row, size_t r, TierRows* out) {
    const int frames = rig.options().frames;
    const RowState state(rig, tier, row);
    for (double t : rig.frame_times(frames, &out->plans[r])) out->times[r].push_back(t);
    if (frames < kSettleFrames) rig.frame_times(kSettleFrames - frames - 1); // frame_times(n) draws n + 1
    out->stats[r] = rig.frame_stats();
    out->memory[r] = rig.memory_stats();
}

// What "optional" promises, checked on the last round's stats; each failure appended.
void check_rows(const char* tier, const std::vector<Row>& rows, const TierRows& t, std::vector<std::string>* fails) {
    const auto fail = [&](size_t r, const std::string& what) {
        fails->push_back(std::string(tier) + ", " + rows[r].name + ": " + what);
    };
    for (size_t r = 0; r < rows.size(); ++r) {
        const grass_frame_stats& s = t.stats[r];
        const grass_memory_stats& m = t.memory[r];
        if (!rows[r].wind && rows[r].colliders == kNoCollider) {
            if (s.interaction_texels)
                fail(r, "an interaction pass of " + std::to_string(s.interaction_texels) + " texels");
            if (m.dynamics_gpu_bytes) fail(r, "dynamics_gpu_bytes " + std::to_string(m.dynamics_gpu_bytes));
        }
        if (rows[r].colliders >= kMapKept) {
            if (!s.interaction_texels) fail(r, "no interaction pass");
            if (!m.dynamics_gpu_bytes) fail(r, "dynamics_gpu_bytes 0");
        }
        if (rows[r].colliders > 0 && s.colliders_in_map != uint64_t(rows[r].colliders))
            fail(r, std::to_string(s.colliders_in_map) + " colliders in the map's window");
    }
}

void print_rows(const char* tier, bool drawn, const std::vector<Row>& rows, const TierRows& t) {
    const Cost still = tier_cost::cost(t.times[0], t.empties);
    for (size_t r = 0; r < rows.size(); ++r) {
        const Cost c = tier_cost::cost(t.times[r], t.empties);
        char ratio[32] = "-";
        if (drawn) std::snprintf(ratio, sizeof ratio, "%.2f", c.median / still.median);
        std::printf("| %s | %s | %llu | %llu | %.1f | %+.1f | %s | %.1f | %.3f | %.0f | %.2f |\n", tier, rows[r].name,
                    static_cast<unsigned long long>(t.stats[r].colliders_in_map),
                    static_cast<unsigned long long>(t.stats[r].interaction_texels), c.median, c.median - still.median,
                    ratio, c.fastest, grass_sample::median_high(t.plans[r]), t.memory[r].dynamics_gpu_bytes / 1024.0,
                    t.memory[r].gpu_bytes / 1048576.0);
    }
    std::fflush(stdout);
}

// The pass alone against each tier's still draw (both from this run): the last of
// `measured` is the "no grass" tier.
void print_pass_alone(const std::vector<Row>& rows, const std::vector<const Setup*>& tiers,
                      const std::vector<TierRows>& measured) {
    std::printf("\n| colliders | pass alone (ms) |");
    for (const Setup* tier : tiers)
        if (tier) std::printf(" %s: still draw (ms) | pass / (pass + draw) |", tier->name);
    std::printf("\n|---|---|");
    for (const Setup* tier : tiers)
        if (tier) std::printf("---|---|");
    std::printf("\n");
    const TierRows& alone = measured.back();
    const Cost alone_still = tier_cost::cost(alone.times[0], alone.empties);
    for (size_t r = 0; r < rows.size(); ++r) {
        if (rows[r].colliders < kMapKept) continue;
        const double pass = tier_cost::cost(alone.times[r], alone.empties).median - alone_still.median;
        std::printf("| %s | %.2f |", rows[r].name, pass);
        for (size_t i = 0; i + 1 < measured.size(); ++i) {
            const double draw = tier_cost::cost(measured[i].times[0], measured[i].empties).median;
            std::printf(" %.1f | %.1f%% |", draw, 100.0 * pass / (pass + draw));
        }
        std::printf("\n");
    }
}

int run(const Options& o) {
    Rig rig(o.rig);
    rig.set_time_step(kFrameStep);
    const std::vector<Row> rows = o.quick    ? std::vector<Row>(std::begin(kQuickRows), std::end(kQuickRows))
                                  : o.blades ? std::vector<Row>(std::begin(kBladeRows), std::end(kBladeRows))
                                             : std::vector<Row>(std::begin(kRows), std::end(kRows));
    std::vector<const Setup*> tiers; // nullptr: no grass, the pass alone
    if (o.blades) {
        tiers = {&tier_cost::kSingleTiers[0]};
    } else if (o.quick) {
        tiers = {&tier_cost::kSingleTiers[2], nullptr};
    } else {
        tiers = {&tier_cost::kSingleTiers[0], &tier_cost::kSingleTiers[1], &tier_cost::kSingleTiers[2], nullptr};
    }
    std::printf("grass-measure dynamics: %s (%s), %ux%u, 1024 cells of 0.25 m, %d rounds of %d frames per row, rows "
                "interleaved, %.4f s a frame; frame with no grass %.2f ms\n\n",
                grass_sample::backend_name(o.rig.backend), rig.host().device_name().c_str(), o.rig.width, o.rig.height,
                o.rig.rounds, o.rig.frames, kFrameStep, rig.empty_ms());
    std::printf(
        "| tier | row | colliders in the map | pass texels | frame - empty, median (ms) | vs still (ms) | ratio "
        "to still | fastest - empty (ms) | plan, median (ms) | dynamics GPU memory (KiB) | GPU memory (MiB) "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
    std::vector<TierRows> measured;
    std::vector<std::string> fails;
    for (const Setup* tier : tiers) {
        TierRows t(rows.size());
        for (int round = 0; round < o.rig.rounds; ++round) {
            for (double e : rig.frame_times(o.rig.frames)) t.empties.push_back(e);
            for (size_t r = 0; r < rows.size(); ++r) measure_row(rig, tier, rows[r], r, &t);
        }
        const char* name = tier ? tier->name : "no grass";
        print_rows(name, tier != nullptr, rows, t);
        check_rows(name, rows, t, &fails);
        measured.push_back(std::move(t));
    }
    if (!o.blades) print_pass_alone(rows, tiers, measured); // --blades has no "no grass" rows
    std::fflush(stdout);
    const int status = rig.finish();
    for (const std::string& f : fails) std::fprintf(stderr, "grass-measure dynamics: %s\n", f.c_str());
    return fails.empty() ? status : 1;
}

} // namespace

} // namespace dynamics

Subcommand add_dynamics(CLI::App& measure) {
    auto o = std::make_shared<dynamics::Options>();
    o->rig.frames = 3;
    o->rig.rounds = 2;
    CLI::App* app = measure.add_subcommand(
        "dynamics", "The cost of responsive grass: each tier still, under wind and with crowds of 0 to 10,000 "
                    "colliders, and the interaction pass alone; its GPU memory. Prints Markdown tables; exits 1 if "
                    "still grass has a pass or responsive memory.");
    grass_sample::add_backend_option(*app, &o->rig.backend);
    grass_sample::add_size_option(*app, &o->rig.width, &o->rig.height, 16, 4096, "image size in pixels");
    app->add_option("--frames", o->rig.frames, "frames measured per row (after one that uploads; median)")
        ->capture_default_str()
        ->check(grass_sample::at_least(1));
    app->add_option("--rounds", o->rig.rounds, "rounds, each drawing every row once")
        ->capture_default_str()
        ->check(grass_sample::at_least(1));
    app->add_flag("--quick", o->quick, "the image tier and no grass, crowds of 1 and 100 only (a smoke run)");
    app->add_flag("--blades", o->blades,
                  "the geometry tier alone: still, wind, crowds of 1, 100 and 1000 (the blade window's cost)");
    return {app, [o]() { return dynamics::run(*o); }};
}

} // namespace grass_measure
