#include "plan/lod_setup.hpp"

#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace grass {

namespace {

grass_result validate_test(Log* log, const char* fn, uint32_t k, const grass_lod_test& t, const grass_tier_desc* tiers,
                           uint32_t tier_count) {
    const int64_t kind = raw_enum(t.kind);
    if (t.tier >= tier_count) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->lod_tests[%u].tier is %u; the field has %u tiers", fn, k, t.tier, tier_count);
    }
    const bool geometry = raw_enum(tiers[t.tier].kind) == GRASS_TIER_GEOMETRY;
    switch (kind) {
    case GRASS_LOD_TEST_DISTANCE_BAND: {
        const double b = t.begin, e = t.end, ti = t.transition_in, to = t.transition_out;
        if (!std::isfinite(b) || b < 0.0 || std::isnan(e) || !(e > b)) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u] is a distance band from %g to %g m; it needs 0 <= begin < end "
                             "(end may be infinite)",
                             fn, k, b, e);
        }
        if (!(t.edge_ratio >= 0.0f && t.edge_ratio <= 1.0f)) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u].edge_ratio is %g; it must be in [0, 1]", fn, k,
                             static_cast<double>(t.edge_ratio));
        }
        if (!std::isfinite(ti) || !std::isfinite(to) || ti < 0.0 || to < 0.0 || (std::isfinite(e) && ti + to > e - b)) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u] has transitions of %g m in and %g m out; they must be finite, "
                             ">= 0 and fit in the band (%g m)",
                             fn, k, ti, to, e - b);
        }
        return GRASS_SUCCESS;
    }
    case GRASS_LOD_TEST_MACRO_CELL:
        if (t.max_macro_cells < 1) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u].max_macro_cells is 0; it must be >= 1", fn, k);
        }
        if (geometry && t.max_macro_cells > 1) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u] asks for macro-cells of up to %u cells on tier %u, which is a "
                             "geometry tier; geometry draws single cells only",
                             fn, k, t.max_macro_cells, t.tier);
        }
        return GRASS_SUCCESS;
    case GRASS_LOD_TEST_UNPLANARITY:
        if (!(t.max_unplanarity >= 0.0f && std::isfinite(t.max_unplanarity))) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u].max_unplanarity is %g m; it must be finite and >= 0", fn, k,
                             static_cast<double>(t.max_unplanarity));
        }
        if (!(t.unplanarity_ratio >= 0.0f && t.unplanarity_ratio <= 1.0f)) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_tests[%u].unplanarity_ratio is %g; it must be in [0, 1]", fn, k,
                             static_cast<double>(t.unplanarity_ratio));
        }
        return GRASS_SUCCESS;
    case GRASS_LOD_TEST_HILLTOP:
        if (geometry) {
            return log->fail(
                GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                "%s: desc->lod_tests[%u] is a hilltop test on tier %u, a geometry tier; hilltop silhouettes "
                "are drawn by a volume (or image) tier",
                fn, k, t.tier);
        }
        return GRASS_SUCCESS;
    case GRASS_LOD_TEST_CALLBACK:
        if (!t.callback) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                             "%s: desc->lod_tests[%u].callback is NULL", fn, k);
        }
        return GRASS_SUCCESS;
    default:
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: desc->lod_tests[%u].kind is %lld; it must be a grass_lod_test_kind", fn, k,
                         static_cast<long long>(kind));
    }
}

} // namespace

grass_result make_lod_setup(Log* log, const char* fn, const grass_field_desc& d, LodSetup* out) {
    LodSetup s;
    if (d.tier_count == 0 && d.lod_test_count == 0 && !d.tiers && !d.lod_tests) {
        grass_default_lod_setup(d.cell_size, s.tiers, s.tests);
        s.tier_count = GRASS_DEFAULT_TIER_COUNT;
        s.test_count = GRASS_DEFAULT_LOD_TEST_COUNT;
        if (d.maps.height.index != 0) {
            // On a height map the volume and image tiers' macro-cells must follow the ground
            // (lemme 6.4.4): split them while their height range exceeds half a cell plus 2%
            // of their distance.
            for (uint32_t t = 0; t < s.tier_count; ++t) {
                if (s.tiers[t].kind == GRASS_TIER_GEOMETRY) continue;
                grass_lod_test u;
                std::memset(&u, 0, sizeof(u));
                u.kind = GRASS_LOD_TEST_UNPLANARITY;
                u.tier = t;
                u.max_unplanarity = static_cast<float>(0.5 * d.cell_size);
                u.unplanarity_ratio = 0.02f;
                s.tests[s.test_count++] = u;
            }
        }
    } else {
        if (d.tier_count < 1 || d.tier_count > GRASS_MAX_TIERS || !d.tiers) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->tier_count is %u with tiers %s; give 1..%d tiers, or neither tiers nor lod "
                             "tests for the defaults",
                             fn, d.tier_count, d.tiers ? "set" : "NULL", GRASS_MAX_TIERS);
        }
        if (d.lod_test_count < 1 || d.lod_test_count > GRASS_MAX_LOD_TESTS || !d.lod_tests) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->lod_test_count is %u with lod_tests %s; give 1..%d tests", fn, d.lod_test_count,
                             d.lod_tests ? "set" : "NULL", GRASS_MAX_LOD_TESTS);
        }
        s.tier_count = d.tier_count;
        s.test_count = d.lod_test_count;
        std::memcpy(s.tiers, d.tiers, sizeof(grass_tier_desc) * d.tier_count);
        std::memcpy(s.tests, d.lod_tests, sizeof(grass_lod_test) * d.lod_test_count);
    }
    for (uint32_t t = 0; t < s.tier_count; ++t) {
        const int64_t kind = raw_enum(s.tiers[t].kind);
        if (kind < GRASS_TIER_GEOMETRY || kind > GRASS_TIER_IMAGE) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: desc->tiers[%u].kind is %lld; it must be a grass_tier_kind", fn, t,
                             static_cast<long long>(kind));
        }
        const bool volume = kind == GRASS_TIER_VOLUME;
        if (volume ? (s.tiers[t].slices < 1 || s.tiers[t].slices > 64) : s.tiers[t].slices != 0) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->tiers[%u].slices is %u; volume tiers need 1..64 slices per axis, other tiers 0",
                             fn, t, s.tiers[t].slices);
        }
    }
    for (uint32_t k = 0; k < s.test_count; ++k) {
        GRASS_TRY(validate_test(log, fn, k, s.tests[k], s.tiers, s.tier_count));
        s.tests_of_tier[s.tests[k].tier] |= 1u << k;
        if (s.tests[k].kind == GRASS_LOD_TEST_HILLTOP) s.overlay_tiers |= 1u << s.tests[k].tier;
    }
    for (uint32_t t = 0; t < s.tier_count; ++t) {
        if (s.tests_of_tier[t] == 0) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->tiers[%u] has no lod test; every tier needs at least one", fn, t);
        }
    }
    *out = s;
    return GRASS_SUCCESS;
}

grass_lod_answer evaluate_builtin_test(const grass_lod_test& t, const grass_lod_node& n, double node_top,
                                       double camera_height) {
    if (t.kind == GRASS_LOD_TEST_DISTANCE_BAND) {
        if (n.distance_min > t.end || n.distance_max < t.begin) return GRASS_LOD_DISCARD;
        if (n.distance_min >= t.begin && n.distance_max <= t.end) return GRASS_LOD_DRAW;
        // Across an edge: whole once small for its distance (its far part is faded out).
        const double side = 2.0 * n.radius / 1.4142135623730951; // ~ the node's side, metres
        return side <= t.edge_ratio * n.distance_min ? GRASS_LOD_DRAW : GRASS_LOD_SPLIT;
    }
    if (t.kind == GRASS_LOD_TEST_UNPLANARITY) {
        const double unplanarity = n.height_max - n.height_min;
        return unplanarity <= t.max_unplanarity + double(t.unplanarity_ratio) * n.distance_min ? GRASS_LOD_DRAW
                                                                                               : GRASS_LOD_SPLIT;
    }
    if (t.kind == GRASS_LOD_TEST_HILLTOP) {
        return node_top <= camera_height ? GRASS_LOD_DISCARD : GRASS_LOD_DRAW;
    }
    // GRASS_LOD_TEST_MACRO_CELL
    return (n.cells_x <= t.max_macro_cells && n.cells_z <= t.max_macro_cells) ? GRASS_LOD_DRAW : GRASS_LOD_SPLIT;
}

} // namespace grass

extern "C" GRASS_API void grass_default_lod_setup(double cell_size, grass_tier_desc* out_tiers,
                                                  grass_lod_test* out_tests) {
    if (!out_tiers || !out_tests) return;
    // Lemme's distances are in cells (his cell is the unit patch): his player-height view
    // draws c_g = 106 geometry cells, which a 20-cell radius gives and a 20 m one at 0.25 m
    // cells (thousands of cells) does not. So metres = table value x cell size.
    const double scale = (std::isfinite(cell_size) && cell_size > 0.0) ? cell_size : 1.0;
    const grass_tier_desc tiers[GRASS_DEFAULT_TIER_COUNT] = {{GRASS_TIER_GEOMETRY, 0},
                                                             {GRASS_TIER_VOLUME, 8},
                                                             {GRASS_TIER_VOLUME, 2},
                                                             {GRASS_TIER_VOLUME, 1},
                                                             {GRASS_TIER_IMAGE, 0}};
    std::memcpy(out_tiers, tiers, sizeof(tiers));
    struct Band {
        double begin, end, in, out;
        uint32_t macro;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const Band bands[GRASS_DEFAULT_TIER_COUNT] = {{0, 20, 0, 15, 1},
                                                  {5, 80, 15, 30, 40},
                                                  {50, 160, 30, 60, 40},
                                                  {100, 300, 60, 100, 40},
                                                  {200, inf, 100, 0, 500}};
    uint32_t k = 0;
    for (uint32_t t = 0; t < GRASS_DEFAULT_TIER_COUNT; ++t) {
        grass_lod_test band;
        std::memset(&band, 0, sizeof(band));
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = t;
        band.begin = static_cast<float>(bands[t].begin * scale);
        band.end = static_cast<float>(bands[t].end * scale);
        band.transition_in = static_cast<float>(bands[t].in * scale);
        band.transition_out = static_cast<float>(bands[t].out * scale);
        band.edge_ratio = t == 0 ? 0.0f : 0.25f;
        out_tests[k++] = band;
        if (bands[t].macro > 1) { // the geometry tier draws single cells by itself
            grass_lod_test macro;
            std::memset(&macro, 0, sizeof(macro));
            macro.kind = GRASS_LOD_TEST_MACRO_CELL;
            macro.tier = t;
            macro.max_macro_cells = bands[t].macro;
            out_tests[k++] = macro;
        }
    }
}
