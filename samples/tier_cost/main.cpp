// grass-tier-cost: the frame cost of each tier per basic cell (the analogues of lemme2012
// Tables 7.1 and 7.2), measured in one run: 1024 cells (32 x 32 of 0.25 m) drawn by each
// tier alone, then by the volume (8 slices) and image tiers in macro-cells of 1, 2, 4, 8 and
// 16 cells a side. Wall time of a rendered and read-back frame, median of 5, minus the
// same frame with no grass; per basic cell. Prints a Markdown table.
// --maps: instead, the cost of each design map (docs/feature-cost.md). For each tier alone
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
// --frames N: frames measured per row (after one that uploads); default 5 (median).
// Usage: grass-tier-cost [--backend gl|vk] [--size WxH] [--maps | --features] [--frames N] [--rounds N]
#include <grass/grass.h>

#include "headless_host.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Setup {
    const char* name;
    grass_tier_kind kind;
    uint32_t slices;
    uint32_t macro; // largest macro-cell side; 1 = single cells
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

constexpr uint32_t kMapSize = 128; // texels a side, over the 32 x 32 cells of the field

// The maps of one row of the --maps table: a bit per map role, as GRASS_FEATURES.
enum MapBits : uint32_t { kDensity = 1, kColor = 2, kAmbient = 4, kDiffuse = 8, kHeight = 16, kAll = 31 };

struct MapRow {
    const char* name;
    uint32_t maps;
};

// Creates the maps of `bits` into `stack` (ids appended to `made`); false on failure.
bool make_maps(grass_context* ctx, uint32_t bits, double cell_size, grass_map_stack* stack,
               std::vector<grass_map_id>* made) {
    const uint32_t n = kMapSize;
    auto create = [&](const void* pixels, grass_map_format format, grass_map_id* id) {
        grass_map_desc md = grass_default_map_desc();
        md.pixels = pixels;
        md.width = md.height = n;
        md.format = format;
        if (grass_create_map(ctx, &md, id) != GRASS_SUCCESS) {
            std::fprintf(stderr, "grass-tier-cost: %s\n", grass_get_last_error(ctx));
            return false;
        }
        made->push_back(*id);
        return true;
    };
    std::vector<uint8_t> r8(n * n);
    if (bits & kDensity) { // density 1 everywhere: every blade passes, the map is still sampled
        std::fill(r8.begin(), r8.end(), uint8_t(255));
        if (!create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->density)) return false;
    }
    if (bits & kColor) { // a straw-to-green wash along x, stripes along z, alpha 0.3
        std::vector<uint8_t> rgba(n * n * 4);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                uint8_t* t = &rgba[4 * (y * n + x)];
                t[0] = uint8_t(120 + 100 * x / n);
                t[1] = uint8_t((y / 16) % 2 ? 170 : 140);
                t[2] = uint8_t(60);
                t[3] = uint8_t(77); // 0.3
            }
        if (!create(rgba.data(), GRASS_MAP_FORMAT_RGBA8_UNORM, &stack->color)) return false;
    }
    if (bits & kAmbient) { // ambient occlusion: darker towards one corner, 0.5 .. 1
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) r8[y * n + x] = uint8_t(255 - 64 * (x + y) / n);
        if (!create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->ambient)) return false;
    }
    if (bits & kDiffuse) { // a soft shadow band across the middle of the field, 0.3 .. 1
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const double d = std::fabs(double(x) - 0.5 * n) / (0.25 * n);
                r8[y * n + x] = uint8_t(255 * (0.3 + 0.7 * std::min(1.0, d)));
            }
        if (!create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->diffuse)) return false;
    }
    if (bits & kHeight) { // a gentle ramp along x: 0 .. 1 cell over the 32 cells
        std::vector<uint16_t> r16(n * n);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) r16[y * n + x] = uint16_t(65535u * x / (n - 1));
        if (!create(r16.data(), GRASS_MAP_FORMAT_R16_UNORM, &stack->height)) return false;
        stack->height_scale = float(cell_size);
    }
    return true;
}

// The rows of the --features table: the optional feature each row switches on.
enum Feature : uint32_t { kNone, kMirror, kTransition, kWindow, kSecondType, kAllMaps };

struct FeatureRow {
    const char* name;
    Feature feature;
};

// Appends the lod tests of tier `tier` (single cells, as `s`) drawn between begin and end
// metres with the given transition widths; returns the count appended.
uint32_t band_tests(const Setup& s, uint32_t tier, float begin, float end, float in, float out, grass_lod_test* tests) {
    tests[0] = {};
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].tier = tier;
    tests[0].begin = begin;
    tests[0].end = end;
    tests[0].transition_in = in;
    tests[0].transition_out = out;
    if (s.kind == GRASS_TIER_GEOMETRY) return 1; // the geometry tier draws single cells by itself
    tests[1] = {};
    tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[1].tier = tier;
    tests[1].max_macro_cells = s.macro;
    return 2;
}

// Destroys the context and returns the exit status: 1 if the host's validation layers
// spoke during the run (their log on stderr), else 0.
int finish(grass_host::Host& host, grass_context* ctx) {
    const uint32_t messages = host.validation_messages();
    grass_destroy_context(ctx);
    if (messages) {
        std::fprintf(stderr, "grass-tier-cost: %u validation messages\n%s\n", messages, host.validation_log().c_str());
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    grass_backend backend = GRASS_BACKEND_GL;
    grass_host::TargetDesc target;
    target.width = 320;
    target.height = 240;
    bool maps_mode = false;
    bool features_mode = false;
    int frames = 5;
    int rounds = 3; // --maps and --features only
    for (int k = 1; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--backend") && k + 1 < argc) {
            backend = std::strcmp(argv[++k], "vk") == 0 ? GRASS_BACKEND_VULKAN : GRASS_BACKEND_GL;
        } else if (!std::strcmp(argv[k], "--size") && k + 1 < argc) {
            std::sscanf(argv[++k], "%ux%u", &target.width, &target.height);
        } else if (!std::strcmp(argv[k], "--maps")) {
            maps_mode = true;
        } else if (!std::strcmp(argv[k], "--features")) {
            features_mode = true;
        } else if (!std::strcmp(argv[k], "--frames") && k + 1 < argc) {
            frames = std::max(1, std::atoi(argv[++k]));
        } else if (!std::strcmp(argv[k], "--rounds") && k + 1 < argc) {
            rounds = std::max(1, std::atoi(argv[++k]));
        } else {
            std::fprintf(stderr, "usage: grass-tier-cost [--backend gl|vk] [--size WxH] [--maps | --features] "
                                 "[--frames N] [--rounds N]\n");
            return 2;
        }
    }
    if (maps_mode && features_mode) {
        std::fprintf(stderr, "grass-tier-cost: --maps and --features are separate runs; give one\n");
        return 2;
    }
    std::string error;
    auto host = grass_host::Host::create(backend, target, &error);
    if (!host) {
        std::fprintf(stderr, "grass-tier-cost: %s\n", error.c_str());
        return 1;
    }
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) return 1;
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    grass_create_patch(ctx, &pd, &patch);

    // The whole 8 m x 8 m field in view, seen at 30 degrees from 9 m away.
    const double eye[3] = {4.0, 4.5, -4.0}, look[3] = {4.0, 0.0, 4.0};
    const grass_view_desc view = grass_host::make_view(*host, eye, look, 55.0f, 0.05f, 200.0f);
    // The times of `count` frames after one that uploads (and compiles); with `plan_ms`,
    // also appends each measured frame's plan time (grass_frame_stats.plan_ms).
    auto frame_times = [&](int count, std::vector<double>* plan_ms = nullptr) {
        std::vector<double> times;
        grass_host::Image image;
        for (int r = 0; r < count + 1; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            host->render(ctx, view, nullptr, &image, &error);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (r > 0) times.push_back(ms); // the first frame uploads
            if (r > 0 && plan_ms) {
                grass_frame_stats stats{};
                grass_get_frame_stats(ctx, &stats);
                plan_ms->push_back(stats.plan_ms);
            }
        }
        return times;
    };
    auto frame_ms = [&]() { return median(frame_times(frames)); };
    const double empty = frame_ms();
    if (maps_mode) {
        const Setup tiers[] = {{"geometry", GRASS_TIER_GEOMETRY, 0, 1},
                               {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
                               {"image", GRASS_TIER_IMAGE, 0, 1}};
        const MapRow rows[] = {{"plain (no maps)", 0},  {"density", kDensity}, {"colour", kColor},
                               {"ambient", kAmbient}, {"diffuse", kDiffuse}, {"height", kHeight},
                               {"all five", kAll}, {"plain again", 0}};
        constexpr size_t kRows = sizeof rows / sizeof rows[0];
        grass_memory_stats base{};
        grass_get_memory_stats(ctx, &base);
        std::printf("grass-tier-cost --maps: %s (%s), %ux%u, 1024 cells of 0.25 m, maps %ux%u texels; "
                    "%d rounds of %d frames per row, rows interleaved; frame with no grass %.2f ms; "
                    "GPU memory with no field %.2f MiB\n\n",
                    backend == GRASS_BACKEND_GL ? "gl" : "vk", host->device_name().c_str(), target.width, target.height,
                    kMapSize, kMapSize, rounds, frames, empty, base.gpu_bytes / 1048576.0);
        std::printf("| tier | maps | instances | frame - empty, median (ms) | ratio to plain | fastest frame - empty (ms) | "
                    "ratio to plain | GPU memory (MiB) | vs plain (KiB) |\n|---|---|---|---|---|---|---|---|---|\n");
        std::fflush(stdout);
        for (const Setup& s : tiers) {
            // Each round draws every row once (after the empty frame again), so that a load
            // that comes and goes on the machine falls on every row alike.
            std::vector<double> times[kRows], empties;
            uint64_t instances[kRows] = {}, gpu_bytes[kRows] = {};
            for (int round = 0; round < rounds; ++round) {
                for (double t : frame_times(frames)) empties.push_back(t);
                for (size_t r = 0; r < kRows; ++r) {
                    grass_tier_desc tier{s.kind, s.slices};
                    grass_lod_test tests[2] = {};
                    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
                    tests[0].end = INFINITY;
                    tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
                    tests[1].max_macro_cells = s.macro;
                    grass_field_desc fd = grass_default_field_desc();
                    fd.patch = patch;
                    fd.cells_x = fd.cells_z = 32;
                    fd.tiers = &tier;
                    fd.tier_count = 1;
                    fd.lod_tests = tests;
                    fd.lod_test_count = s.kind == GRASS_TIER_GEOMETRY ? 1 : 2;
                    std::vector<grass_map_id> made;
                    if (!make_maps(ctx, rows[r].maps, fd.cell_size, &fd.maps, &made)) return 1;
                    grass_field_id field{};
                    if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) {
                        std::fprintf(stderr, "grass-tier-cost: %s\n", grass_get_last_error(ctx));
                        return 1;
                    }
                    for (double t : frame_times(frames)) times[r].push_back(t);
                    grass_frame_stats stats{};
                    grass_get_frame_stats(ctx, &stats);
                    grass_memory_stats mem{};
                    grass_get_memory_stats(ctx, &mem);
                    instances[r] = stats.instances[s.kind];
                    gpu_bytes[r] = mem.gpu_bytes;
                    grass_destroy_field(ctx, field);
                    for (grass_map_id m : made) grass_destroy_map(ctx, m);
                }
            }
            const double empty_median = median(empties);
            const double empty_min = *std::min_element(empties.begin(), empties.end());
            const double plain_median = median(times[0]) - empty_median;
            const double plain_min = *std::min_element(times[0].begin(), times[0].end()) - empty_min;
            for (size_t r = 0; r < kRows; ++r) {
                const double med = median(times[r]) - empty_median;
                const double fastest = *std::min_element(times[r].begin(), times[r].end()) - empty_min;
                std::printf("| %s | %s | %llu | %.1f | %.2f | %.1f | %.2f | %.2f | %+.0f |\n", s.name, rows[r].name,
                            static_cast<unsigned long long>(instances[r]), med, med / plain_median, fastest,
                            fastest / plain_min, gpu_bytes[r] / 1048576.0,
                            (double(gpu_bytes[r]) - double(gpu_bytes[0])) / 1024.0);
            }
            std::fflush(stdout);
        }
        return finish(*host, ctx);
    }
    if (features_mode) {
        const Setup tiers[] = {{"geometry", GRASS_TIER_GEOMETRY, 0, 1},
                               {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
                               {"image", GRASS_TIER_IMAGE, 0, 1}};
        // The tier each one shares its transition zone with: the next cheaper kind, and
        // whether that one is the finer of the two (tier 0, the nearer band).
        const Setup partners[] = {{"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
                                  {"image", GRASS_TIER_IMAGE, 0, 1},
                                  {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1}};
        const bool partner_finer[] = {false, false, true};
        const FeatureRow rows[] = {{"plain (all off)", kNone},
                                   {"mirror tiling", kMirror},
                                   {"transition zone", kTransition},
                                   {"transition zone + window 0.05", kWindow},
                                   {"second grass type", kSecondType},
                                   {"all five maps", kAllMaps},
                                   {"plain again", kNone}};
        constexpr size_t kRows = sizeof rows / sizeof rows[0];
        // The field's distances from the camera: its ground rectangle (32 x 32 cells of
        // 0.25 m at y = 0) from its nearest point to its farthest corner. The transition
        // zone spans them with 2 m to spare each side (blade tops and bounding boxes).
        const double side = 32 * 0.25;
        const double nx = std::clamp(eye[0], 0.0, side) - eye[0], nz = std::clamp(eye[2], 0.0, side) - eye[2];
        const double near_m = std::sqrt(nx * nx + eye[1] * eye[1] + nz * nz);
        const double fx = std::max(std::fabs(eye[0]), std::fabs(side - eye[0]));
        const double fz = std::max(std::fabs(eye[2]), std::fabs(side - eye[2]));
        const double far_m = std::sqrt(fx * fx + eye[1] * eye[1] + fz * fz);
        const float zone_begin = float(std::max(0.0, std::floor(near_m) - 2.0));
        const float zone_end = float(std::ceil(far_m) + 2.0);
        // One row's field, with a patch of its own (baked slices are kept per patch and slice
        // count, so each row's GPU memory holds the slices its tiers need, and no more) and
        // its maps; destroy_row destroys all three.
        struct RowField {
            grass_patch_id patch{};
            grass_field_id field{};
            std::vector<grass_map_id> maps;
        };
        auto destroy_row = [&](const RowField& row) {
            if (row.field.index) grass_destroy_field(ctx, row.field);
            for (grass_map_id m : row.maps) grass_destroy_map(ctx, m);
            if (row.patch.index) grass_destroy_patch(ctx, row.patch);
        };
        // Makes the field of feature `feature` on tier setup `i`; false (with the error
        // printed and nothing left) on failure.
        auto make_row = [&](size_t i, Feature feature, RowField* row) {
            const Setup& s = tiers[i];
            const Setup& p = partners[i];
            const bool transition = feature == kTransition || feature == kWindow;
            grass_tier_desc tier_descs[2] = {{s.kind, s.slices}, {p.kind, p.slices}};
            grass_lod_test tests[4] = {};
            uint32_t test_count = 0;
            if (!transition) { // the single tier at all distances
                test_count = band_tests(s, 0, 0.0f, INFINITY, 0.0f, 0.0f, tests);
            } else {
                // Two tiers, the finer one (tier 0) from 0 to the zone's end fading out over
                // the zone, the coarser from the zone's begin to infinity fading in over it:
                // their weights sum to 1 and both draw every cell.
                if (partner_finer[i]) std::swap(tier_descs[0], tier_descs[1]);
                const Setup& finer = partner_finer[i] ? p : s;
                const Setup& coarser = partner_finer[i] ? s : p;
                const float width = zone_end - zone_begin;
                test_count = band_tests(finer, 0, 0.0f, zone_end, 0.0f, width, tests);
                test_count += band_tests(coarser, 1, zone_begin, INFINITY, width, 0.0f, tests + test_count);
            }
            if (grass_create_patch(ctx, &pd, &row->patch) != GRASS_SUCCESS) {
                std::fprintf(stderr, "grass-tier-cost: %s\n", grass_get_last_error(ctx));
                return false;
            }
            grass_field_desc fd = grass_default_field_desc();
            fd.patch = row->patch;
            fd.cells_x = fd.cells_z = 32;
            fd.tiers = tier_descs;
            fd.tier_count = transition ? 2 : 1;
            fd.lod_tests = tests;
            fd.lod_test_count = test_count;
            fd.mirror_tiling = feature == kMirror ? 1 : 0;
            fd.transition_window = feature == kWindow ? 0.05f : 0.0f;
            // The second grass type: the same patch, tier and lod tests, density 1.
            grass_grass_type_desc second = grass_default_grass_type_desc();
            second.patch = row->patch;
            second.density = 1.0f;
            second.tiers = tier_descs;
            second.tier_count = 1;
            second.lod_tests = tests;
            second.lod_test_count = test_count;
            if (feature == kSecondType) fd.next = &second;
            if (!make_maps(ctx, feature == kAllMaps ? uint32_t(kAll) : 0u, fd.cell_size, &fd.maps, &row->maps)) {
                destroy_row(*row); // make_maps printed the error
                return false;
            }
            if (grass_create_field(ctx, &fd, &row->field) != GRASS_SUCCESS) {
                std::fprintf(stderr, "grass-tier-cost: %s\n", grass_get_last_error(ctx));
                destroy_row(*row);
                return false;
            }
            return true;
        };
        // The instance and uniform buffers keep the largest size a frame needed: frames of the
        // largest row (2048 instances in 2 draws) before the table size them for every row,
        // so that the memory columns differ by what each row's field holds. Vulkan keeps a
        // copy per frame in flight (2 in the headless host) and frees what the GPU may still
        // read (a destroyed patch, a grown buffer, an upload's staging buffer) 2 frames
        // later: hence 3 frames of each, and the memory of a row read no sooner than 2 frames
        // after the one that uploads.
        constexpr int kSettleFrames = 2;
        {
            RowField warm;
            if (!make_row(2, kSecondType, &warm)) return 1;
            frame_times(kSettleFrames);
            destroy_row(warm);
            frame_times(kSettleFrames);
        }
        grass_memory_stats base{};
        grass_get_memory_stats(ctx, &base);
        std::printf("grass-tier-cost --features: %s (%s), %ux%u, 1024 cells of 0.25 m, %.1f .. %.1f m from the "
                    "camera, transition zones %.0f .. %.0f m; %d rounds of %d frames per row, rows interleaved; "
                    "frame with no grass %.2f ms; GPU memory with no field %.2f MiB\n\n",
                    backend == GRASS_BACKEND_GL ? "gl" : "vk", host->device_name().c_str(), target.width, target.height,
                    near_m, far_m, double(zone_begin), double(zone_end), rounds, frames, empty,
                    base.gpu_bytes / 1048576.0);
        std::printf("| tier | feature | instances | frame - empty, median (ms) | ratio to plain | fastest frame - empty (ms) | "
                    "ratio to plain | plan, median (ms) | GPU memory (MiB) | vs plain (KiB) |\n"
                    "|---|---|---|---|---|---|---|---|---|---|\n");
        std::fflush(stdout);
        for (size_t i = 0; i < sizeof tiers / sizeof tiers[0]; ++i) {
            const Setup& s = tiers[i];
            const Setup& p = partners[i];
            // Each round draws every row once (after the empty frame again), so that a load
            // that comes and goes on the machine falls on every row alike.
            std::vector<double> times[kRows], plans[kRows], empties;
            uint64_t instances[kRows] = {}, partner_instances[kRows] = {}, gpu_bytes[kRows] = {};
            for (int round = 0; round < rounds; ++round) {
                for (double t : frame_times(frames)) empties.push_back(t);
                for (size_t r = 0; r < kRows; ++r) {
                    RowField row;
                    if (!make_row(i, rows[r].feature, &row)) return 1;
                    for (double t : frame_times(frames, &plans[r])) times[r].push_back(t);
                    // frame_times(n) draws n + 1 frames.
                    if (frames < kSettleFrames) frame_times(kSettleFrames - frames - 1);
                    grass_frame_stats stats{};
                    grass_get_frame_stats(ctx, &stats);
                    grass_memory_stats mem{};
                    grass_get_memory_stats(ctx, &mem);
                    instances[r] = stats.instances[s.kind];
                    partner_instances[r] = stats.instances[p.kind]; // p.kind differs from s.kind
                    gpu_bytes[r] = mem.gpu_bytes;
                    destroy_row(row);
                }
            }
            const double empty_median = median(empties);
            const double empty_min = *std::min_element(empties.begin(), empties.end());
            const double plain_median = median(times[0]) - empty_median;
            const double plain_min = *std::min_element(times[0].begin(), times[0].end()) - empty_min;
            for (size_t r = 0; r < kRows; ++r) {
                const double med = median(times[r]) - empty_median;
                const double fastest = *std::min_element(times[r].begin(), times[r].end()) - empty_min;
                // The instances of the measured tier, plus its partner's in the transition rows.
                char count[64];
                if (partner_instances[r]) {
                    std::snprintf(count, sizeof count, "%llu + %llu %s", static_cast<unsigned long long>(instances[r]),
                                  static_cast<unsigned long long>(partner_instances[r]), p.name);
                } else {
                    std::snprintf(count, sizeof count, "%llu", static_cast<unsigned long long>(instances[r]));
                }
                std::printf("| %s | %s | %s | %.1f | %.2f | %.1f | %.2f | %.3f | %.2f | %+.0f |\n", s.name, rows[r].name,
                            count, med, med / plain_median, fastest, fastest / plain_min, median(plans[r]),
                            gpu_bytes[r] / 1048576.0, (double(gpu_bytes[r]) - double(gpu_bytes[0])) / 1024.0);
            }
            std::fflush(stdout);
        }
        return finish(*host, ctx);
    }

    const Setup setups[] = {
        {"geometry", GRASS_TIER_GEOMETRY, 0, 1}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
        {"volume, 2 slices", GRASS_TIER_VOLUME, 2, 1}, {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1},
        {"image", GRASS_TIER_IMAGE, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 2}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 4},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 8}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 16},
        {"image", GRASS_TIER_IMAGE, 0, 2}, {"image", GRASS_TIER_IMAGE, 0, 4},
        {"image", GRASS_TIER_IMAGE, 0, 8}, {"image", GRASS_TIER_IMAGE, 0, 16},
    };
    std::printf("grass-tier-cost: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms\n\n",
                backend == GRASS_BACKEND_GL ? "gl" : "vk", host->device_name().c_str(), target.width, target.height, empty);
    std::printf("| tier | macro-cells up to | instances | frame (ms) | per basic cell (us) |\n|---|---|---|---|---|\n");
    for (const Setup& s : setups) {
        grass_tier_desc tier{s.kind, s.slices};
        grass_lod_test tests[2] = {};
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].end = INFINITY;
        tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
        tests[1].max_macro_cells = s.macro;
        grass_field_desc fd = grass_default_field_desc();
        fd.patch = patch;
        fd.cells_x = fd.cells_z = 32;
        fd.tiers = &tier;
        fd.tier_count = 1;
        fd.lod_tests = tests;
        fd.lod_test_count = s.kind == GRASS_TIER_GEOMETRY ? 1 : 2;
        grass_field_id field{};
        if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) {
            std::fprintf(stderr, "grass-tier-cost: %s\n", grass_get_last_error(ctx));
            return 1;
        }
        const double ms = frame_ms();
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        std::printf("| %s | %u | %llu | %.1f | %.1f |\n", s.name, s.macro,
                    static_cast<unsigned long long>(stats.instances[s.kind]), ms, 1000.0 * (ms - empty) / 1024.0);
        grass_destroy_field(ctx, field);
    }
    return finish(*host, ctx);
}
