// libFuzzer target: the C API as a host might drive it, on a CPU-only context (the core with
// no GPU backend). The input decodes into a sequence of calls: patches, maps, map updates
// and fields made from hostile descs (NaN, infinities, negative, huge, stale, foreign and
// garbage ids), lod callbacks that answer garbage, frames with random views, and responsive
// grass (wind, colliders, the interaction map, blade mechanics: fuzz_responsive.hpp) with a
// clock that steps forwards and backwards by any amount. Whatever the
// input, every call returns a grass_result, an error leaves a message naming the call, and
// the context stays destroyable; AddressSanitizer and UBSan watch everything in between,
// and the context's own allocation counters must come back to zero.
//
// Built with GRASS_FUZZ_GPU_SEQUENCE it is fuzz_gpu_sequence: the same calls, fewer of them,
// on a grass context of a GL (llvmpipe) or Vulkan (lavapipe) device made once per process
// (fuzz_gpu_host.hpp), whose frames are also rendered into a small offscreen target; fields
// and patches are kept small enough for a software rasteriser, and the device's validation
// (Vulkan layers, GL debug output) must stay silent.
#include "fuzz_lod_callback.h"
#include "fuzz_responsive.hpp"
#ifdef GRASS_FUZZ_GPU_SEQUENCE
#    include "fuzz_gpu_host.hpp"
#else
namespace grass_host {
class Host;
}
#endif
#include "fuzz_values.hpp"

#include <grass/grass.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using grass_fuzz::hostile_double;
using grass_fuzz::hostile_float;
using grass_fuzz::hostile_u32;

#ifdef GRASS_FUZZ_GPU_SEQUENCE
constexpr size_t kMaxCalls = 12;
constexpr bool kGpu = true;
#else
constexpr size_t kMaxCalls = 64;
constexpr bool kGpu = false;
#endif

// On a software rasteriser a field of accepted size may take seconds a frame: fields of
// more than 16 cells a side and patches of more than 64 blades shrink (sizes grass must
// refuse stay as they are).
template <class T>
void shrink_for_gpu(T* value, T most, T accepted_up_to) {
    if (kGpu && *value > most && *value <= accepted_up_to) *value = most;
}

// An enum field holding any 32-bit value, as a C host can store it (C++ may not even load
// such a value: it is written and read as bytes here; grass reads enums the same way).
template <class Enum>
void set_raw(Enum* field, int64_t value) {
    static_assert(sizeof(Enum) == 4, "C enums are 32-bit here");
    const uint32_t bits = static_cast<uint32_t>(value);
    std::memcpy(field, &bits, sizeof(bits));
}

template <class Enum>
uint32_t enum_bits(const Enum& e) {
    uint32_t bits;
    std::memcpy(&bits, &e, sizeof(bits));
    return bits;
}

using grass_fuzz::Answers;
using grass_fuzz::garbage_answer;

struct Allocs {
    long live = 0;
};

// Every call returns one of grass's result codes.
void check_result(grass_result r) {
    if (r > 0 || r < GRASS_ERROR_IN_USE) {
        std::fprintf(stderr, "a call returned %d, which is no grass_result\n", static_cast<int>(r));
        std::abort();
    }
}

template <class Id>
Id pick_id(FuzzedDataProvider& in, const std::vector<Id>& own, const std::vector<Id>& foreign) {
    switch (in.ConsumeIntegralInRange<int>(0, 5)) {
    case 0:
        return Id{}; // the null id
    case 1:
        if (!foreign.empty()) return foreign[in.ConsumeIntegralInRange<size_t>(0, foreign.size() - 1)];
        return Id{};
    case 2: { // garbage
        Id id;
        id.index = in.ConsumeIntegral<uint32_t>();
        id.generation = in.ConsumeIntegral<uint16_t>();
        id.owner = in.ConsumeIntegral<uint16_t>();
        return id;
    }
    default: // one made here, maybe destroyed since (stale)
        if (!own.empty()) return own[in.ConsumeIntegralInRange<size_t>(0, own.size() - 1)];
        return Id{};
    }
}

void pick_format(FuzzedDataProvider& in, grass_map_format* format) {
    set_raw(format, in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(1, 6) : in.ConsumeIntegral<uint32_t>());
}

size_t texel_bytes(const grass_map_format& f) {
    switch (enum_bits(f)) {
    case 1:
        return 1;
    case 2:
        return 2;
    case 3:
    case 4:
        return 4;
    case 5:
        return 8;
    case 6:
        return 16;
    default:
        return 16;
    }
}

// A map desc whose pixels live in `storage`, big enough for what the desc claims (a host
// that lies about its buffer's size is out of any library's reach).
grass_map_desc make_map_desc(FuzzedDataProvider& in, std::vector<uint8_t>* storage) {
    grass_map_desc d = grass_default_map_desc();
    pick_format(in, &d.format);
    d.width = hostile_u32(in, 1, 24);
    d.height = hostile_u32(in, 1, 24);
    d.row_pitch = in.ConsumeBool() ? 0 : hostile_u32(in, 0, 128);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) set_raw(&d.type, in.ConsumeIntegral<int>());
    const uint64_t pitch = d.row_pitch ? d.row_pitch : uint64_t(d.width) * texel_bytes(d.format);
    const uint64_t bytes = pitch * d.height;
    if (d.width > 64 || d.height > 64 || bytes > (1u << 20)) {
        // Too big to back with memory here: sizes grass must refuse stay, sizes it would
        // accept shrink to one texel (a host that lies about its buffer is out of reach).
        storage->assign(64, 0);
        d.pixels = in.ConsumeBool() ? nullptr : storage->data();
        if (d.width <= 16384 && d.height <= 16384 && d.width && d.height) d.width = d.height = 1;
        return d;
    }
    storage->assign(bytes + 16, 0);
    const std::vector<uint8_t> fill = in.ConsumeBytes<uint8_t>(bytes);
    if (!fill.empty()) std::memcpy(storage->data(), fill.data(), fill.size());
    // Float maps: finite values or hostile ones.
    if ((enum_bits(d.format) == GRASS_MAP_FORMAT_R32_FLOAT || enum_bits(d.format) == GRASS_MAP_FORMAT_RGBA32_FLOAT) &&
        in.ConsumeBool()) {
        for (size_t k = 0; k + 4 <= bytes; k += 4) {
            const float v = hostile_float(in, 0.0, 1.0);
            std::memcpy(storage->data() + k, &v, 4);
        }
    }
    d.pixels = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? nullptr : storage->data();
    return d;
}

grass_patch_desc make_patch_desc(FuzzedDataProvider& in) {
    grass_patch_desc d = grass_default_patch_desc();
    d.blade_count = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(1, 64) : hostile_u32(in, 1, 400);
    shrink_for_gpu<uint32_t>(&d.blade_count, 64, 1u << 20);
    d.seed = in.ConsumeIntegral<uint64_t>();
    const int edits = in.ConsumeIntegralInRange<int>(0, 4);
    for (int e = 0; e < edits; ++e) {
        switch (in.ConsumeIntegralInRange<int>(0, 11)) {
        case 0:
            d.subdivisions = hostile_u32(in, 1, 8);
            break;
        case 1:
            d.length_min = hostile_float(in, 0.0, 2.0);
            break;
        case 2:
            d.length_max = hostile_float(in, 0.0, 2.0);
            break;
        case 3:
            d.width_max = hostile_float(in, 0.0, 0.2);
            break;
        case 4:
            d.tilt_max = hostile_float(in, 0.0, 1.5);
            break;
        case 5:
            d.bend_min = hostile_float(in, 0.0, 2.0);
            break;
        case 6:
            d.root_color[in.ConsumeIntegralInRange<int>(0, 2)] = hostile_float(in, 0.0, 1.0);
            break;
        case 7:
            set_raw(&d.threshold_mode, in.ConsumeIntegralInRange<int>(-1, 2));
            break;
        case 8:
            d.cluster_sigma = hostile_float(in, 0.0, 1.0);
            break;
        case 9:
            d.cluster_frequency = hostile_u32(in, 1, 64);
            break;
        case 10:
            d.ao_height = hostile_float(in, 0.0, 2.0);
            break;
        default:
            d.next = in.ConsumeBool() ? &d : nullptr; // a next chain that must be refused
            break;
        }
    }
    return d;
}

struct Session {
    grass_context* ctx = nullptr;
    grass_context* other = nullptr; // makes the foreign ids
    std::vector<grass_patch_id> patches, foreign_patches;
    std::vector<grass_map_id> maps, foreign_maps;
    std::vector<grass_field_id> fields, foreign_fields;
    std::vector<uint8_t> answer_bytes;
    Answers answers{nullptr, 0, 0};
    std::vector<uint8_t> pixels;
    bool in_frame = false;
    grass_host::Host* host = nullptr;            // fuzz_gpu_sequence: the device the context draws on
    double time = 0.0;                           // the last begun frame's grass_view_desc.time
    bool had_frame = false;                      // a frame has begun on ctx (this input or, GPU: before)
    std::vector<grass::InteractionTexel> map[2]; // the interaction map, kept on the CPU
    grass_context* target = nullptr;             // the context the last call went to
};

grass_result create_field(FuzzedDataProvider& in, Session& s) {
    grass_field_desc d = grass_default_field_desc();
    d.patch = pick_id(in, s.patches, s.foreign_patches);
    d.cells_x = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(1, 32) : hostile_u32(in, 1, 256);
    d.cells_z = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(1, 32) : hostile_u32(in, 1, 256);
    shrink_for_gpu<uint32_t>(&d.cells_x, 16, 1u << 24);
    shrink_for_gpu<uint32_t>(&d.cells_z, 16, 1u << 24);
    if (in.ConsumeBool()) d.cell_size = hostile_double(in, 1e-4, 10.0);
    if (in.ConsumeBool()) d.base_transform[in.ConsumeIntegralInRange<int>(0, 15)] = hostile_double(in, -100.0, 100.0);
    if (in.ConsumeBool()) d.density = hostile_float(in, 0.0, 1.0);
    if (in.ConsumeBool()) d.transition_window = hostile_float(in, 0.0, 0.25);
    d.mirror_seed = in.ConsumeIntegral<uint32_t>();
    std::vector<uint8_t> density_pixels;
    grass_map_desc density_map{};
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
        density_map = make_map_desc(in, &density_pixels);
        d.density_map = &density_map;
    }
    // Design maps: ids of this context, stale, foreign or garbage.
    if (in.ConsumeBool()) d.maps.density = pick_id(in, s.maps, s.foreign_maps);
    if (in.ConsumeBool()) d.maps.color = pick_id(in, s.maps, s.foreign_maps);
    if (in.ConsumeBool()) d.maps.height = pick_id(in, s.maps, s.foreign_maps);
    if (in.ConsumeBool()) d.maps.ambient = pick_id(in, s.maps, s.foreign_maps);
    if (in.ConsumeBool()) d.maps.height_scale = hostile_float(in, 0.0, 10.0);
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
        for (double& m : d.maps.cell_to_map) m = hostile_double(in, -2.0, 2.0);
    }
    // Tiers and lod tests: the default setup, or a hostile one.
    grass_tier_desc tiers[GRASS_MAX_TIERS + 1];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS + 1];
    if (in.ConsumeBool()) {
        d.tier_count = in.ConsumeIntegralInRange<uint32_t>(0, GRASS_MAX_TIERS + 1);
        d.lod_test_count = in.ConsumeIntegralInRange<uint32_t>(0, 6);
        for (uint32_t t = 0; t < d.tier_count; ++t) {
            set_raw(&tiers[t].kind, in.ConsumeIntegralInRange<int>(-1, 3));
            tiers[t].slices = hostile_u32(in, 0, 4);
        }
        for (uint32_t k = 0; k < d.lod_test_count; ++k) {
            grass_lod_test& t = tests[k];
            std::memset(&t, 0, sizeof(t));
            set_raw(&t.kind, in.ConsumeIntegralInRange<int>(0, 6));
            t.tier = in.ConsumeIntegralInRange<uint32_t>(0, GRASS_MAX_TIERS);
            t.begin = hostile_float(in, 0.0, 10.0);
            t.end = hostile_float(in, 0.0, 50.0);
            t.transition_in = hostile_float(in, 0.0, 2.0);
            t.transition_out = hostile_float(in, 0.0, 2.0);
            t.edge_ratio = hostile_float(in, 0.0, 1.0);
            t.max_macro_cells = hostile_u32(in, 1, 16);
            t.callback = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? nullptr : garbage_answer;
            t.user_data = &s.answers;
            t.max_unplanarity = hostile_float(in, 0.0, 1.0);
            t.unplanarity_ratio = hostile_float(in, 0.0, 1.0);
        }
        d.tiers = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? nullptr : tiers;
        d.lod_tests = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? nullptr : tests;
    }
    // More grass types through the next chain.
    grass_grass_type_desc types[3];
    const int type_count = in.ConsumeIntegralInRange<int>(0, 8) < 7 ? 0 : in.ConsumeIntegralInRange<int>(1, 3);
    for (int k = 0; k < type_count; ++k) {
        types[k] = grass_default_grass_type_desc();
        types[k].patch = pick_id(in, s.patches, s.foreign_patches);
        types[k].density = hostile_float(in, 0.0, 1.0);
        if (in.ConsumeBool()) types[k].density_map = pick_id(in, s.maps, s.foreign_maps);
        types[k].next = k + 1 < type_count ? &types[k + 1] : nullptr;
    }
    if (type_count) d.next = &types[0];
    grass_field_id f{};
    grass_context* target = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? s.other : s.ctx;
    s.target = target;
    const grass_result r = grass_create_field(target, &d, &f);
    check_result(r);
    if (r == GRASS_SUCCESS) (target == s.ctx ? s.fields : s.foreign_fields).push_back(f);
    return r;
}

grass_view_desc make_view(FuzzedDataProvider& in, double previous_time) {
    grass_view_desc v = grass_default_view_desc();
    // A plausible camera over the fields, then hostile edits.
    v.camera_position[0] = in.ConsumeFloatingPointInRange<double>(-10.0, 20.0);
    v.camera_position[1] = in.ConsumeFloatingPointInRange<double>(0.1, 30.0);
    v.camera_position[2] = in.ConsumeFloatingPointInRange<double>(-10.0, 20.0);
    const float ident[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    std::memcpy(v.view, ident, sizeof(ident));
    const float n = 0.1f, f = in.ConsumeFloatingPointInRange<float>(1.0f, 500.0f);
    const float proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -(f + n) / (f - n), -1, 0, 0, -2 * f * n / (f - n), 0};
    std::memcpy(v.projection, proj, sizeof(proj));
    v.viewport[2] = v.viewport[3] = 64;
    v.time = grass_fuzz::next_time(in, previous_time);
    const int edits = in.ConsumeIntegralInRange<int>(0, 3);
    for (int e = 0; e < edits; ++e) {
        switch (in.ConsumeIntegralInRange<int>(0, 6)) {
        case 0:
            v.camera_position[in.ConsumeIntegralInRange<int>(0, 2)] = hostile_double(in, -1e6, 1e6);
            break;
        case 1:
            v.view[in.ConsumeIntegralInRange<int>(0, 15)] = hostile_float(in, -1.0, 1.0);
            break;
        case 2:
            v.projection[in.ConsumeIntegralInRange<int>(0, 15)] = hostile_float(in, -2.0, 2.0);
            break;
        case 3:
            v.viewport[in.ConsumeIntegralInRange<int>(0, 3)] = in.ConsumeIntegral<int32_t>();
            break;
        case 4:
            v.sun_direction[in.ConsumeIntegralInRange<int>(0, 2)] = hostile_float(in, -1.0, 1.0);
            break;
        case 5:
            v.flags = in.ConsumeIntegral<uint32_t>();
            break;
        default:
            v.time = hostile_double(in, -1e9, 1e9);
            break;
        }
    }
    return v;
}

// After a begun frame at `time`: the step grass took is the one grass.h documents (the time
// since the previous frame; 0 at the first frame and when the time went backwards).
void check_time_step(Session& s, double time) {
    const double expected = !s.had_frame || time < s.time ? 0.0 : time - s.time;
    if (s.ctx->plan.stats.time_step != expected) {
        std::fprintf(stderr, "a frame at %.17g s after one at %.17g s stepped %.17g s, not %.17g s\n", time, s.time,
                     s.ctx->plan.stats.time_step, expected);
        std::abort();
    }
    s.time = time;
    s.had_frame = true;
}

void one_call(FuzzedDataProvider& in, Session& s) {
    grass_result r = GRASS_SUCCESS;
    s.target = s.ctx;
    const int which = in.ConsumeIntegralInRange<int>(0, 20);
    switch (which) {
    case 0: {
        const grass_patch_desc d = make_patch_desc(in);
        grass_patch_id p{};
        grass_context* target = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? s.other : s.ctx;
        s.target = target;
        r = grass_create_patch(target, &d, &p);
        if (r == GRASS_SUCCESS) (target == s.ctx ? s.patches : s.foreign_patches).push_back(p);
        break;
    }
    case 1:
        r = grass_destroy_patch(s.ctx, pick_id(in, s.patches, s.foreign_patches));
        break;
    case 2: {
        const grass_map_desc d = make_map_desc(in, &s.pixels);
        grass_map_id m{};
        grass_context* target = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? s.other : s.ctx;
        s.target = target;
        r = grass_create_map(target, &d, &m);
        if (r == GRASS_SUCCESS) (target == s.ctx ? s.maps : s.foreign_maps).push_back(m);
        break;
    }
    case 3: {
        const grass_map_id m = pick_id(in, s.maps, s.foreign_maps);
        const uint32_t x = hostile_u32(in, 0, 24), y = hostile_u32(in, 0, 24);
        const grass_map_desc d = make_map_desc(in, &s.pixels);
        r = grass_update_map(s.ctx, m, x, y, &d);
        break;
    }
    case 4:
        r = grass_destroy_map(s.ctx, pick_id(in, s.maps, s.foreign_maps));
        break;
    case 5:
        r = create_field(in, s);
        break;
    case 6:
        r = grass_destroy_field(s.ctx, pick_id(in, s.fields, s.foreign_fields));
        break;
    case 7:
    case 8: {
        const grass_view_desc v = make_view(in, s.time);
        s.answer_bytes = in.ConsumeBytes<uint8_t>(in.ConsumeIntegralInRange<size_t>(0, 16));
        s.answers = Answers{s.answer_bytes.data(), s.answer_bytes.size(), 0};
#ifdef GRASS_FUZZ_GPU_SEQUENCE
        if (s.host && !s.in_frame && in.ConsumeBool()) { // begin, draw, end and read back
            grass_host::Image image;
            std::string error;
            r = s.host->render(s.ctx, v, nullptr, &image, &error);
            if (r != GRASS_SUCCESS && grass_get_last_error(s.ctx)[0] == '\0') {
                std::fprintf(stderr, "the host's render failed: %s\n", error.c_str());
                std::abort();
            }
            if (r == GRASS_SUCCESS) {
                check_time_step(s, v.time);
                grass_fuzz::check_and_run_pass(s.ctx, nullptr);
            }
            break;
        }
#endif
        r = grass_begin_frame(s.ctx, &v);
        s.in_frame = s.in_frame || r == GRASS_SUCCESS;
        if (r == GRASS_SUCCESS) {
            check_time_step(s, v.time);
            grass_fuzz::check_and_run_pass(s.ctx, s.host ? nullptr : s.map);
        }
        grass_frame_stats stats{};
        check_result(grass_get_frame_stats(s.ctx, &stats));
        if (in.ConsumeBool() || r != GRASS_SUCCESS) {
            check_result(grass_end_frame(s.ctx));
            s.in_frame = false;
        }
        break;
    }
    case 9:
        r = grass_end_frame(s.ctx);
        s.in_frame = false;
        break;
    case 10: {
        grass_quality_desc q = grass_fuzz::fuzz_quality_preset(in.ConsumeIntegralInRange(-1, 5));
        if (in.ConsumeBool()) q.distance_scale = hostile_float(in, 0.1, 16.0);
        if (in.ConsumeBool()) q.slice_scale = hostile_float(in, 0.125, 8.0);
        if (in.ConsumeBool()) q.macro_cell_scale = hostile_float(in, 0.025, 4.0);
        if (in.ConsumeBool()) q.blade_fraction = hostile_float(in, 0.0, 1.0);
        if (in.ConsumeBool()) q.msaa_samples = hostile_u32(in, 1, 8);
        grass_patch_desc pd = make_patch_desc(in);
        grass_tier_desc tiers[GRASS_MAX_TIERS];
        grass_lod_test tests[GRASS_MAX_LOD_TESTS];
        uint32_t tier_count = 0, test_count = 0;
        r = grass_apply_quality(s.ctx, &q, hostile_double(in, 0.01, 10.0), &pd, tiers, &tier_count, tests, &test_count);
        break;
    }
    case 11: {
        const grass_patch_id p = pick_id(in, s.patches, s.foreign_patches);
        grass_patch_info info{};
        r = grass_get_patch_info(s.ctx, p, &info);
        check_result(r);
        std::vector<float> thresholds(in.ConsumeIntegralInRange<uint32_t>(0, 512));
        r = grass_get_patch_thresholds(s.ctx, p, thresholds.empty() ? nullptr : thresholds.data(),
                                       static_cast<uint32_t>(thresholds.size()));
        break;
    }
    case 12: {
        grass_memory_stats m{};
        r = grass_get_memory_stats(s.ctx, &m);
        double ms[GRASS_TIER_KIND_COUNT];
        grass_bool available = 1;
        check_result(grass_get_tier_gpu_ms(s.ctx, ms, &available));
        if (available && !s.host) std::abort(); // a CPU-only context has no GPU timings
        break;
    }
    case 14:
        r = grass_fuzz::set_wind(in, s.ctx);
        break;
    case 15:
        r = grass_fuzz::set_colliders(in, s.ctx);
        break;
    case 16:
        r = grass_fuzz::set_interaction(in, s.ctx);
        break;
    case 17:
        r = grass_fuzz::set_blade_mechanics(in, s.ctx, pick_id(in, s.patches, s.foreign_patches));
        break;
    case 18:
        r = grass_fuzz::set_blade_culling(in, s.ctx, pick_id(in, s.fields, s.foreign_fields));
        break;
    case 19: {
        const grass_field_id f = pick_id(in, s.fields, s.foreign_fields);
        r = grass_fuzz::set_field_wind_map(in, s.ctx, f, pick_id(in, s.maps, s.foreign_maps));
        break;
    }
    default: {
        grass_tier_desc tiers[GRASS_DEFAULT_TIER_COUNT];
        grass_lod_test tests[GRASS_DEFAULT_LOD_TEST_COUNT];
        grass_default_lod_setup(hostile_double(in, 0.01, 10.0), tiers, tests);
        break;
    }
    }
    check_result(r);
    // GRASS_FUZZ_TRACE=1: each call's number (one_call's cases) and result, to read a finding.
    static const bool trace = std::getenv("GRASS_FUZZ_TRACE") != nullptr;
    if (trace) std::fprintf(stderr, "call %d: %s %s\n", which, grass_result_string(r), grass_get_last_error(s.target));
    if (!grass_fuzz::fuzz_result_string(in.ConsumeIntegral<int32_t>())) std::abort();
    // An error always leaves a message.
    if (r != GRASS_SUCCESS && grass_get_last_error(s.target)[0] == '\0') {
        std::fprintf(stderr, "an error (%s) left no message\n", grass_result_string(r));
        std::abort();
    }
}

void* counted_alloc(void* user, size_t size, size_t alignment) {
    static_cast<Allocs*>(user)->live += 1;
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}
void counted_free(void* user, void* p) {
    static_cast<Allocs*>(user)->live -= 1;
    std::free(p);
}

#ifdef GRASS_FUZZ_GPU_SEQUENCE

// A grass context on a device, made once per process for each backend, sample count and
// depth convention (a Vulkan context takes seconds to make on lavapipe), shared by the
// inputs: each input's calls run on it, then what the input made is destroyed and what it
// set restored (wind, colliders, interaction map), so that the next input starts from the
// same context, and its host allocations stay within kKeptAllocations of what they were
// after it was made (the core's and the backend's tables keep the capacity they grew to: a
// few arrays; an allocation lost per input exceeds it within kKeptAllocations inputs).
constexpr long kKeptAllocations = 64;

struct GpuContext {
    grass_host::Host* host = nullptr;
    grass_context* ctx = nullptr;
    Allocs allocs;
    long baseline = 0; // live allocations of the fresh context
    double time = 0.0; // its last begun frame's time
    bool had_frame = false;
};

GpuContext& gpu_context(grass_backend backend, uint32_t samples, grass_depth_mode depth) {
    static GpuContext* made[2][2][2] = {};
    GpuContext*& g =
        made[backend == GRASS_BACKEND_GL ? 0 : 1][samples == 4 ? 1 : 0][depth == GRASS_DEPTH_GREATER ? 1 : 0];
    grass_host::Host* host = grass_fuzz::gpu_host(backend, samples); // its device current from here on
    if (!host) std::abort();
    if (!g) {
        g = new GpuContext; // never destroyed: see fuzz_gpu_host.hpp
        g->host = host;
        grass_context_desc cd = grass_default_context_desc();
        cd.allocator = {counted_alloc, counted_free, &g->allocs};
        cd.depth_mode = depth;
        if (g->host->create_context(cd, &g->ctx) != GRASS_SUCCESS) std::abort();
        g->baseline = g->allocs.live;
    }
    return *g;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    const grass_depth_mode depth = in.ConsumeBool() ? GRASS_DEPTH_GREATER : GRASS_DEPTH_LESS;
    const grass_backend backend = in.ConsumeBool() ? GRASS_BACKEND_VULKAN : GRASS_BACKEND_GL;
    GpuContext& g = gpu_context(backend, in.ConsumeBool() ? 4 : 1, depth);
    Session s;
    s.host = g.host;
    s.ctx = g.ctx;
    s.time = g.time;
    s.had_frame = g.had_frame;
    const grass_context_desc od = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &od, &s.other) != GRASS_SUCCESS) std::abort();
    for (size_t call = 0; call < kMaxCalls && in.remaining_bytes() > 0; ++call) one_call(in, s);
    // Whatever happened, the context takes a frame's end and gives back what the input made.
    grass_end_frame(s.ctx);
    g.time = s.time;
    g.had_frame = s.had_frame;
    for (const grass_field_id f : s.fields) grass_destroy_field(s.ctx, f);
    for (const grass_map_id m : s.maps) grass_destroy_map(s.ctx, m);
    for (const grass_patch_id p : s.patches) grass_destroy_patch(s.ctx, p);
    check_result(grass_set_wind(s.ctx, nullptr));
    check_result(grass_set_colliders(s.ctx, nullptr, 0));
    check_result(grass_set_interaction(s.ctx, nullptr));
    grass_destroy_context(s.other);
    if (s.host->validation_messages() != 0) {
        std::fprintf(stderr, "the device's validation spoke:\n%s\n", s.host->validation_log().c_str());
        std::abort();
    }
    if (g.allocs.live > g.baseline + kKeptAllocations) {
        std::fprintf(stderr, "%ld host allocations of a fresh context, %ld after an input's objects were destroyed\n",
                     g.baseline, g.allocs.live);
        std::abort();
    }
    return 0;
}

#else

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    Allocs allocs;
    grass_context_desc cd = grass_default_context_desc();
    cd.allocator = {counted_alloc, counted_free, &allocs};
    cd.depth_mode = in.ConsumeBool() ? GRASS_DEPTH_GREATER : GRASS_DEPTH_LESS;
    Session s;
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &s.ctx) != GRASS_SUCCESS) std::abort();
    const grass_context_desc od = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &od, &s.other) != GRASS_SUCCESS) std::abort();
    for (size_t call = 0; call < kMaxCalls && in.remaining_bytes() > 0; ++call) one_call(in, s);
    // Whatever happened, the context is still destroyable, with or without a frame open,
    // and gives back every allocation.
    grass_destroy_context(s.ctx);
    grass_destroy_context(s.other);
    if (allocs.live != 0) {
        std::fprintf(stderr, "%ld host allocations outlived their context\n", allocs.live);
        std::abort();
    }
    return 0;
}

#endif
