#include "viewer_scene.hpp"

#include <vector>

namespace grass_viewer {

const char* quality_name(int quality) {
    static const char* const names[GRASS_QUALITY_LEVEL_COUNT] = {"reference", "high", "default", "low", "fastest"};
    return quality >= 0 && quality < GRASS_QUALITY_LEVEL_COUNT ? names[quality] : "scene";
}

ViewerScene::~ViewerScene() { destroy(); }

namespace {
std::string failed(grass_context* ctx, const char* call, grass_result r) {
    return std::string(call) + " failed: " + grass_result_string(r) + " (" + grass_get_last_error(ctx) + ")";
}
} // namespace

grass_result ViewerScene::create(grass_context* ctx, const grass_sample::Scene& scene, int quality,
                                 std::string* error) {
    destroy();
    ctx_ = ctx;
    scene_ = scene;
    maps_ = grass_map_stack{};
    grass_result r = grass_sample::create_scene_maps(ctx, scene_, &maps_);
    if (r == GRASS_SUCCESS) r = grass_sample::create_scene_wind_map(ctx, scene_, &wind_map_);
    if (r != GRASS_SUCCESS) {
        *error = failed(ctx, "grass_create_map", r);
    } else {
        r = make_field(quality, &patch_, &field_, error);
    }
    if (r != GRASS_SUCCESS) {
        destroy();
        return r;
    }
    quality_ = quality;
    return r;
}

grass_result ViewerScene::set_quality(int quality, std::string* error) {
    grass_patch_id patch{};
    grass_field_id field{};
    const grass_result r = make_field(quality, &patch, &field, error);
    if (r != GRASS_SUCCESS) return r;
    grass_destroy_field(ctx_, field_);
    grass_destroy_patch(ctx_, patch_);
    patch_ = patch;
    field_ = field;
    quality_ = quality;
    return r;
}

grass_result ViewerScene::make_field(int quality, grass_patch_id* patch, grass_field_id* field, std::string* error) {
    grass_patch_desc pd = scene_.patch;
    grass_field_desc fd = scene_.field;
    std::vector<grass_tier_desc> tiers = scene_.tiers;
    std::vector<grass_lod_test> tests = scene_.lod_tests;
    grass_result r = GRASS_SUCCESS;
    if (quality != kSceneSetup) {
        const grass_quality_desc q = grass_quality_preset(static_cast<grass_quality_level>(quality));
        tiers.resize(GRASS_MAX_TIERS);
        tests.resize(GRASS_MAX_LOD_TESTS);
        uint32_t tier_count = 0, test_count = 0;
        r = grass_apply_quality(ctx_, &q, fd.cell_size, &pd, tiers.data(), &tier_count, tests.data(), &test_count);
        if (r != GRASS_SUCCESS) {
            *error = failed(ctx_, "grass_apply_quality", r);
            return r;
        }
        tiers.resize(tier_count);
        tests.resize(test_count);
    }
    r = grass_create_patch(ctx_, &pd, patch);
    if (r != GRASS_SUCCESS) {
        *error = failed(ctx_, "grass_create_patch", r);
        return r;
    }
    fd.patch = *patch;
    fd.tiers = tiers.empty() ? nullptr : tiers.data();
    fd.tier_count = static_cast<uint32_t>(tiers.size());
    fd.lod_tests = tests.empty() ? nullptr : tests.data();
    fd.lod_test_count = static_cast<uint32_t>(tests.size());
    grass_map_desc density = grass_default_map_desc();
    if (!scene_.density_texels.empty()) {
        density.pixels = scene_.density_texels.data();
        density.width = scene_.density_width;
        density.height = scene_.density_height;
        density.format = GRASS_MAP_FORMAT_R8_UNORM;
        fd.density_map = &density;
    }
    fd.maps = maps_;
    r = grass_create_field(ctx_, &fd, field);
    if (r != GRASS_SUCCESS) {
        *error = failed(ctx_, "grass_create_field", r);
        grass_destroy_patch(ctx_, *patch);
        return r;
    }
    r = grass_sample::set_scene_wind_map(ctx_, wind_map_, *field);
    if (r != GRASS_SUCCESS) {
        *error = failed(ctx_, "grass_set_field_wind_map", r);
        grass_destroy_field(ctx_, *field);
        grass_destroy_patch(ctx_, *patch);
        return r;
    }
    grass_get_patch_info(ctx_, *patch, &patch_info_);
    return r;
}

void ViewerScene::destroy() {
    if (!ctx_) return;
    if (!grass_field_id_is_null(field_)) grass_destroy_field(ctx_, field_);
    if (!grass_patch_id_is_null(patch_)) grass_destroy_patch(ctx_, patch_);
    for (int r = 0; r < grass_sample::kMapRoleCount; ++r) {
        grass_map_id* id = grass_sample::map_slot(&maps_, grass_sample::MapRole(r));
        if (!grass_map_id_is_null(*id)) grass_destroy_map(ctx_, *id);
    }
    if (!grass_map_id_is_null(wind_map_.map)) grass_destroy_map(ctx_, wind_map_.map);
    wind_map_ = grass_wind_map_desc{};
    field_ = {};
    patch_ = {};
    maps_ = {};
    ctx_ = nullptr;
}

} // namespace grass_viewer
