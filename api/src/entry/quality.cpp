// Quality presets and the knobs behind them: the speed/accuracy trade of docs/quality.md.
// A preset is a grass_quality_desc; applying one shapes a patch desc and Lemme's default lod
// setup (lod_setup.cpp) by a few scales, so every level is the same method, nearer or further.
#include "context/context.hpp"
#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace grass {
namespace {

grass_quality_desc make(grass_bool everywhere, float distance, float transition, float slices, float macro,
                        uint32_t subdivisions, float fraction, uint32_t msaa) {
    grass_quality_desc q;
    std::memset(&q, 0, sizeof(q));
    q.type = GRASS_STRUCT_TYPE_QUALITY_DESC;
    q.blades_everywhere = everywhere;
    q.distance_scale = distance;
    q.transition_scale = transition;
    q.slice_scale = slices;
    q.macro_cell_scale = macro;
    q.blade_subdivisions = subdivisions;
    q.blade_fraction = fraction;
    q.msaa_samples = msaa;
    return q;
}

grass_result validate_quality(grass_context* ctx, const char* fn, const grass_quality_desc* q) {
    GRASS_TRY(GRASS_CHECK_DESC(ctx, fn, q, GRASS_STRUCT_TYPE_QUALITY_DESC));
    GRASS_TRY(check_range(ctx, fn, "quality->distance_scale", q->distance_scale, 0.1, 16.0));
    GRASS_TRY(check_range(ctx, fn, "quality->transition_scale", q->transition_scale, 0.0, double(1.2f)));
    GRASS_TRY(check_range(ctx, fn, "quality->slice_scale", q->slice_scale, 0.125, 8.0));
    GRASS_TRY(check_range(ctx, fn, "quality->macro_cell_scale", q->macro_cell_scale, 0.025, 4.0));
    GRASS_TRY(check_range(ctx, fn, "quality->blade_subdivisions", q->blade_subdivisions, 1, 32));
    if (!(q->blade_fraction > 0.0f && q->blade_fraction <= 1.0f)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: quality->blade_fraction is %g; it must be in (0, 1]", fn,
                         static_cast<double>(q->blade_fraction));
    }
    const uint32_t s = q->msaa_samples;
    if (s != 1 && s != 2 && s != 4 && s != 8) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: quality->msaa_samples is %u; it must be 1, 2, 4 or 8", fn, s);
    }
    return GRASS_SUCCESS;
}

uint32_t scaled_count(uint32_t value, double scale, uint32_t lo, uint32_t hi) {
    const double v = std::round(value * scale);
    return static_cast<uint32_t>(std::min<double>(std::max<double>(v, lo), hi));
}

grass_result apply_quality(grass_context* ctx, const grass_quality_desc* q, double cell_size, grass_patch_desc* patch,
                           grass_tier_desc* tiers, uint32_t* tier_count, grass_lod_test* tests, uint32_t* test_count) {
    const char* fn = "grass_apply_quality";
    GRASS_TRY(validate_quality(ctx, fn, q));
    GRASS_TRY(check_range(ctx, fn, "cell_size", cell_size, 1e-4, 1e4));
    GRASS_TRY(check_not_null(ctx, fn, "inout_patch", patch));
    GRASS_TRY(check_not_null(ctx, fn, "out_tiers", tiers));
    GRASS_TRY(check_not_null(ctx, fn, "out_tier_count", tier_count));
    GRASS_TRY(check_not_null(ctx, fn, "out_tests", tests));
    GRASS_TRY(check_not_null(ctx, fn, "out_test_count", test_count));

    patch->blade_count =
        std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(patch->blade_count * double(q->blade_fraction))));
    patch->subdivisions = q->blade_subdivisions;
    if (q->blades_everywhere) {
        std::memset(&tiers[0], 0, sizeof(tiers[0]));
        tiers[0].kind = GRASS_TIER_GEOMETRY;
        std::memset(&tests[0], 0, sizeof(tests[0]));
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].end = std::numeric_limits<float>::infinity();
        *tier_count = 1;
        *test_count = 1;
        return GRASS_SUCCESS;
    }
    grass_default_lod_setup(cell_size, tiers, tests);
    for (uint32_t t = 0; t < GRASS_DEFAULT_TIER_COUNT; ++t) {
        if (tiers[t].kind == GRASS_TIER_VOLUME) tiers[t].slices = scaled_count(tiers[t].slices, q->slice_scale, 1, 64);
    }
    for (uint32_t k = 0; k < GRASS_DEFAULT_LOD_TEST_COUNT; ++k) {
        grass_lod_test& t = tests[k];
        if (t.kind == GRASS_LOD_TEST_DISTANCE_BAND) {
            t.begin *= q->distance_scale;
            t.end *= q->distance_scale; // infinity stays infinite
            t.transition_in *= q->distance_scale * q->transition_scale;
            t.transition_out *= q->distance_scale * q->transition_scale;
        } else if (t.kind == GRASS_LOD_TEST_MACRO_CELL) {
            t.max_macro_cells = scaled_count(t.max_macro_cells, q->macro_cell_scale, 1, 1u << 30);
        }
    }
    *tier_count = GRASS_DEFAULT_TIER_COUNT;
    *test_count = GRASS_DEFAULT_LOD_TEST_COUNT;
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

extern "C" {

GRASS_API grass_quality_desc grass_quality_preset(grass_quality_level level) {
    using grass::make;
    switch (grass::raw_enum(level)) { // a C host may pass any int
    case GRASS_QUALITY_REFERENCE:
        return make(1, 1.0f, 1.0f, 1.0f, 1.0f, 8, 1.0f, 4);
    case GRASS_QUALITY_HIGH:
        return make(0, 2.0f, 1.0f, 2.0f, 0.5f, 6, 1.0f, 4);
    case GRASS_QUALITY_DEFAULT:
        return make(0, 1.0f, 1.0f, 1.0f, 1.0f, 4, 1.0f, 4);
    case GRASS_QUALITY_LOW:
        return make(0, 0.6f, 1.0f, 1.0f, 2.0f, 3, 0.75f, 1);
    case GRASS_QUALITY_FASTEST:
        return make(0, 0.35f, 0.6f, 0.5f, 4.0f, 2, 0.5f, 1);
    }
    // Not a level: a desc with no type tag, which grass_apply_quality refuses.
    grass_quality_desc none;
    std::memset(&none, 0, sizeof(none));
    return none;
}

GRASS_API grass_result grass_apply_quality(grass_context* context, const grass_quality_desc* quality, double cell_size,
                                           grass_patch_desc* inout_patch, grass_tier_desc* out_tiers,
                                           uint32_t* out_tier_count, grass_lod_test* out_tests,
                                           uint32_t* out_test_count) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(context, "grass_apply_quality", [&] {
        return grass::apply_quality(context, quality, cell_size, inout_patch, out_tiers, out_tier_count, out_tests,
                                    out_test_count);
    });
}

} // extern "C"
