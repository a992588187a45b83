// grass-measure tier-cost --maps: the cost of each design map (docs/records/feature-cost.md). For each
// tier alone, the plain field, each map alone, all five, the plain field again; rows drawn in
// rounds, interleaved; per row the frame cost and the GPU memory of the field and its maps.
#include "tier_cost.hpp"

#include "cli.hpp"
#include "tool.hpp"

#include <cstdio>
#include <vector>

namespace grass_measure {
namespace tier_cost {

namespace {

struct MapRow {
    const char* name;
    uint32_t maps;
};

const MapRow kRows[] = {{"plain (no maps)", 0}, {"density", kDensity}, {"colour", kColor}, {"ambient", kAmbient},
                        {"diffuse", kDiffuse},  {"height", kHeight},   {"all five", kAll}, {"plain again", 0}};
constexpr size_t kRowCount = sizeof kRows / sizeof kRows[0];

// The measures of one tier's rows over every round.
struct TierRows {
    std::vector<double> times[kRowCount], empties;
    uint64_t instances[kRowCount] = {}, gpu_bytes[kRowCount] = {};
};

// Draws row r once: its field and maps made, frames measured, then destroyed.
void measure_row(Rig& rig, const Setup& s, size_t r, TierRows* out) {
    grass_context* ctx = rig.ctx();
    TierField tf(s, rig.patch());
    std::vector<grass_map_id> made;
    make_maps(ctx, kRows[r].maps, tf.desc.cell_size, &tf.desc.maps, &made);
    grass_field_id field{};
    grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
    for (double t : rig.frame_times(rig.options().frames)) out->times[r].push_back(t);
    out->instances[r] = rig.frame_stats().instances[s.kind];
    out->gpu_bytes[r] = rig.memory_stats().gpu_bytes;
    grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    for (grass_map_id m : made) grass_sample::check(grass_destroy_map(ctx, m), "grass_destroy_map", ctx);
}

void print_rows(const Setup& s, const TierRows& t) {
    const Cost plain = cost(t.times[0], t.empties);
    for (size_t r = 0; r < kRowCount; ++r) {
        const Cost c = cost(t.times[r], t.empties);
        std::printf("| %s | %s | %llu | %.1f | %.2f | %.1f | %.2f | %.2f | %+.0f |\n", s.name, kRows[r].name,
                    static_cast<unsigned long long>(t.instances[r]), c.median, c.median / plain.median, c.fastest,
                    c.fastest / plain.fastest, t.gpu_bytes[r] / 1048576.0,
                    (double(t.gpu_bytes[r]) - double(t.gpu_bytes[0])) / 1024.0);
    }
    std::fflush(stdout);
}

} // namespace

int run_maps(Rig& rig) {
    const Options& o = rig.options();
    const grass_memory_stats base = rig.memory_stats();
    std::printf("grass-tier-cost --maps: %s (%s), %ux%u, 1024 cells of 0.25 m, maps %ux%u texels; "
                "%d rounds of %d frames per row, rows interleaved; frame with no grass %.2f ms; "
                "GPU memory with no field %.2f MiB\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height, kMapSize,
                kMapSize, o.rounds, o.frames, rig.empty_ms(), base.gpu_bytes / 1048576.0);
    std::printf(
        "| tier | maps | instances | frame - empty, median (ms) | ratio to plain | fastest frame - empty (ms) | "
        "ratio to plain | GPU memory (MiB) | vs plain (KiB) |\n|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
    for (const Setup& s : kSingleTiers) {
        // Each round draws every row once (after the empty frame again), so that a load
        // that comes and goes on the machine falls on every row alike.
        TierRows t;
        for (int round = 0; round < o.rounds; ++round) {
            for (double e : rig.frame_times(o.frames)) t.empties.push_back(e);
            for (size_t r = 0; r < kRowCount; ++r) measure_row(rig, s, r, &t);
        }
        print_rows(s, t);
    }
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
