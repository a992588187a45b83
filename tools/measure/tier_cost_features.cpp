// grass-measure tier-cost --features: the cost of the optional features other than the maps
// (docs/records/feature-cost.md), measured as --maps measures the maps: for each tier alone, the
// plain field with every optional feature off, then mirror tiling, a transition zone shared
// with the next cheaper tier, the same with the default transition window, a second grass
// type, all five maps, and the plain field again.
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace grass_measure {
namespace tier_cost {

namespace {

// The rows of the --features table: the optional feature each row switches on.
enum Feature : uint32_t { kNone, kMirror, kTransition, kWindow, kSecondType, kAllMaps };

struct FeatureRow {
    const char* name;
    Feature feature;
};

const FeatureRow kRows[] = {{"plain (all off)", kNone},
                            {"mirror tiling", kMirror},
                            {"transition zone", kTransition},
                            {"transition zone + window 0.05", kWindow},
                            {"second grass type", kSecondType},
                            {"all five maps", kAllMaps},
                            {"plain again", kNone}};
constexpr size_t kRowCount = sizeof kRows / sizeof kRows[0];

// The tier each of kSingleTiers shares its transition zone with: the next cheaper kind, and
// whether that one is the finer of the two (tier 0, the nearer band).
const Setup kPartners[] = {{"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
                           {"image", GRASS_TIER_IMAGE, 0, 1},
                           {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1}};
const bool kPartnerFiner[] = {false, false, true};

// The instance and uniform buffers keep the largest size a frame needed: frames of the
// largest row (2048 instances in 2 draws) before the table size them for every row, so that
// the memory columns differ by what each row's field holds. Vulkan keeps a copy per frame in
// flight (2 in the headless host) and frees what the GPU may still read (a destroyed patch, a
// grown buffer, an upload's staging buffer) 2 frames later: hence 3 frames of each, and the
// memory of a row read no sooner than 2 frames after the one that uploads.
constexpr int kSettleFrames = 2;

// The field's distances from the camera: its ground rectangle (32 x 32 cells of 0.25 m at
// y = 0) from its nearest point to its farthest corner. The transition zone spans them with
// 2 m to spare each side (blade tops and bounding boxes).
struct Zone {
    double near_m, far_m;
    float begin, end;
};

Zone transition_zone(const double eye[3]) {
    const double side = kCells * 0.25;
    const double nx = std::clamp(eye[0], 0.0, side) - eye[0], nz = std::clamp(eye[2], 0.0, side) - eye[2];
    Zone z{};
    z.near_m = std::sqrt(nx * nx + eye[1] * eye[1] + nz * nz);
    const double fx = std::max(std::fabs(eye[0]), std::fabs(side - eye[0]));
    const double fz = std::max(std::fabs(eye[2]), std::fabs(side - eye[2]));
    z.far_m = std::sqrt(fx * fx + eye[1] * eye[1] + fz * fz);
    z.begin = float(std::max(0.0, std::floor(z.near_m) - 2.0));
    z.end = float(std::ceil(z.far_m) + 2.0);
    return z;
}

// One row's field, with a patch of its own (baked slices are kept per patch and slice count,
// so each row's GPU memory holds the slices its tiers need, and no more) and its maps;
// destroyed with them.
class RowField {
public:
    // The field of `feature` on tier setup `i` of kSingleTiers.
    RowField(grass_context* ctx, size_t i, Feature feature, const Zone& zone);
    ~RowField() { release(); }
    RowField(const RowField&) = delete;
    RowField& operator=(const RowField&) = delete;

private:
    void release();
    grass_context* ctx_;
    grass_patch_id patch_{};
    grass_field_id field_{};
    std::vector<grass_map_id> maps_;
};

RowField::RowField(grass_context* ctx, size_t i, Feature feature, const Zone& zone) : ctx_(ctx) {
    const Setup& s = kSingleTiers[i];
    const Setup& p = kPartners[i];
    const bool transition = feature == kTransition || feature == kWindow;
    grass_tier_desc tier_descs[2] = {{s.kind, s.slices}, {p.kind, p.slices}};
    grass_lod_test tests[4] = {};
    uint32_t test_count = 0;
    if (!transition) { // the single tier at all distances
        test_count = band_tests(s, 0, 0.0f, INFINITY, 0.0f, 0.0f, tests);
    } else {
        // Two tiers, the finer one (tier 0) from 0 to the zone's end fading out over the
        // zone, the coarser from the zone's begin to infinity fading in over it: their
        // weights sum to 1 and both draw every cell.
        if (kPartnerFiner[i]) std::swap(tier_descs[0], tier_descs[1]);
        const Setup& finer = kPartnerFiner[i] ? p : s;
        const Setup& coarser = kPartnerFiner[i] ? s : p;
        const float width = zone.end - zone.begin;
        test_count = band_tests(finer, 0, 0.0f, zone.end, 0.0f, width, tests);
        test_count += band_tests(coarser, 1, zone.begin, INFINITY, width, 0.0f, tests + test_count);
    }
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_sample::check(grass_create_patch(ctx, &pd, &patch_), "grass_create_patch", ctx);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch_;
    fd.cells_x = fd.cells_z = kCells;
    fd.tiers = tier_descs;
    fd.tier_count = transition ? 2 : 1;
    fd.lod_tests = tests;
    fd.lod_test_count = test_count;
    fd.mirror_tiling = feature == kMirror ? 1 : 0;
    fd.transition_window = feature == kWindow ? 0.05f : 0.0f;
    // The second grass type: the same patch, tier and lod tests, density 1.
    grass_grass_type_desc second = grass_default_grass_type_desc();
    second.patch = patch_;
    second.density = 1.0f;
    second.tiers = tier_descs;
    second.tier_count = 1;
    second.lod_tests = tests;
    second.lod_test_count = test_count;
    if (feature == kSecondType) fd.next = &second;
    try {
        make_maps(ctx, feature == kAllMaps ? uint32_t(kAll) : 0u, fd.cell_size, &fd.maps, &maps_);
        grass_sample::check(grass_create_field(ctx, &fd, &field_), "grass_create_field", ctx);
    } catch (...) {
        release(); // what was made before the failure
        throw;
    }
}

void RowField::release() {
    if (field_.index) grass_destroy_field(ctx_, field_);
    field_ = {};
    for (grass_map_id m : maps_) grass_destroy_map(ctx_, m);
    maps_.clear();
    if (patch_.index) grass_destroy_patch(ctx_, patch_);
    patch_ = {};
}

// The measures of one tier's rows over every round.
struct TierRows {
    std::vector<double> times[kRowCount], plans[kRowCount], empties;
    uint64_t instances[kRowCount] = {}, partner_instances[kRowCount] = {}, gpu_bytes[kRowCount] = {};
};

// Draws row r of tier setup i once: its field made, frames measured, then destroyed.
void measure_row(Rig& rig, size_t i, size_t r, const Zone& zone, TierRows* out) {
    const int frames = rig.options().frames;
    const RowField row(rig.ctx(), i, kRows[r].feature, zone);
    for (double t : rig.frame_times(frames, &out->plans[r])) out->times[r].push_back(t);
    // frame_times(n) draws n + 1 frames.
    if (frames < kSettleFrames) rig.frame_times(kSettleFrames - frames - 1);
    const grass_frame_stats stats = rig.frame_stats();
    out->instances[r] = stats.instances[kSingleTiers[i].kind];
    out->partner_instances[r] = stats.instances[kPartners[i].kind]; // the partner's kind differs
    out->gpu_bytes[r] = rig.memory_stats().gpu_bytes;
}

void print_rows(size_t i, const TierRows& t) {
    const Setup& s = kSingleTiers[i];
    const Cost plain = cost(t.times[0], t.empties);
    for (size_t r = 0; r < kRowCount; ++r) {
        const Cost c = cost(t.times[r], t.empties);
        // The instances of the measured tier, plus its partner's in the transition rows.
        char count[64];
        if (t.partner_instances[r]) {
            std::snprintf(count, sizeof count, "%llu + %llu %s", static_cast<unsigned long long>(t.instances[r]),
                          static_cast<unsigned long long>(t.partner_instances[r]), kPartners[i].name);
        } else {
            std::snprintf(count, sizeof count, "%llu", static_cast<unsigned long long>(t.instances[r]));
        }
        std::printf("| %s | %s | %s | %.1f | %.2f | %.1f | %.2f | %.3f | %.2f | %+.0f |\n", s.name, kRows[r].name,
                    count, c.median, c.median / plain.median, c.fastest, c.fastest / plain.fastest,
                    grass_sample::median_high(t.plans[r]), t.gpu_bytes[r] / 1048576.0,
                    (double(t.gpu_bytes[r]) - double(t.gpu_bytes[0])) / 1024.0);
    }
    std::fflush(stdout);
}

} // namespace

int run_features(Rig& rig) {
    const Options& o = rig.options();
    const Zone zone = transition_zone(rig.eye());
    {
        const RowField warm(rig.ctx(), 2, kSecondType, zone);
        rig.frame_times(kSettleFrames);
    }
    rig.frame_times(kSettleFrames);
    const grass_memory_stats base = rig.memory_stats();
    std::printf("grass-tier-cost --features: %s (%s), %ux%u, 1024 cells of 0.25 m, %.1f .. %.1f m from the "
                "camera, transition zones %.0f .. %.0f m; %d rounds of %d frames per row, rows interleaved; "
                "frame with no grass %.2f ms; GPU memory with no field %.2f MiB\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height, zone.near_m,
                zone.far_m, double(zone.begin), double(zone.end), o.rounds, o.frames, rig.empty_ms(),
                base.gpu_bytes / 1048576.0);
    std::printf(
        "| tier | feature | instances | frame - empty, median (ms) | ratio to plain | fastest frame - empty (ms) | "
        "ratio to plain | plan, median (ms) | GPU memory (MiB) | vs plain (KiB) |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
    for (size_t i = 0; i < sizeof kSingleTiers / sizeof kSingleTiers[0]; ++i) {
        // Each round draws every row once (after the empty frame again), so that a load that
        // comes and goes on the machine falls on every row alike.
        TierRows t;
        for (int round = 0; round < o.rounds; ++round) {
            for (double e : rig.frame_times(o.frames)) t.empties.push_back(e);
            for (size_t r = 0; r < kRowCount; ++r) measure_row(rig, i, r, zone, &t);
        }
        print_rows(i, t);
    }
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
