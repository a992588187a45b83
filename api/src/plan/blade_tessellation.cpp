#include "plan/blade_tessellation.hpp"

#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

grass_blade_tessellation_desc default_blade_tessellation_desc() {
    grass_blade_tessellation_desc d{};
    d.type = GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC;
    d.next = nullptr;
    d.enabled = 0;
    d.error_pixels = 0.5f;
    return d;
}

grass_blade_tessellation_desc quality_blade_tessellation(grass_quality_level level) {
    grass_blade_tessellation_desc d = default_blade_tessellation_desc();
    const int64_t l = static_cast<int64_t>(level);
    if (l < GRASS_QUALITY_HIGH || l > GRASS_QUALITY_FASTEST) return d; // REFERENCE (the truth), unknown: full
    d.enabled = 1;
    d.error_pixels = 0.25f * static_cast<float>(l); // HIGH 0.25, DEFAULT 0.5, LOW 0.75, FASTEST 1
    return d;
}

grass_result resolve_blade_tessellation(Log* log, const char* fn, const grass_blade_tessellation_desc& d,
                                        BladeTessellation* out) {
    GRASS_TRY(check_bool(log, fn, "tessellation->enabled", d.enabled));
    GRASS_TRY(check_float_range(log, fn, "tessellation->error_pixels", d.error_pixels, 0.01, 16.0));
    out->enabled = d.enabled != 0;
    out->error_pixels = d.error_pixels;
    return GRASS_SUCCESS;
}

double ScreenScale::pixels_per_metre(double distance) const {
    if (orthographic) return scale;
    return scale / std::max(distance, 1e-6);
}

ScreenScale screen_scale(const float projection[16], int32_t viewport_height, bool orthographic) {
    ScreenScale s;
    s.scale = 0.5 * std::fabs(double(viewport_height)) * std::fabs(double(projection[5]));
    s.orthographic = orthographic;
    return s;
}

uint32_t blade_level(const BladeTessellation& t, const PatchData& patch, double metres_per_unit,
                     const ScreenScale& screen, double distance) {
    if (!t.enabled || patch.level_count < 2) return 0;
    const double pixels_per_unit = metres_per_unit * screen.pixels_per_metre(distance);
    uint32_t level = 0;
    for (uint32_t k = 1; k < patch.level_count; ++k) {
        if (!(double(patch.levels[k].error) * pixels_per_unit <= double(t.error_pixels))) break;
        level = k;
    }
    return level;
}

} // namespace grass
