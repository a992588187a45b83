// The grass of a sample scene on one context: its patch, maps and field, made with the
// scene's own lod setup or with one of grass's quality presets (grass_apply_quality).
// Switching the preset makes the patch and field again; the maps stay.
#pragma once

#include <grass/grass.h>

#include "scene.hpp"

#include <string>

namespace grass_viewer {

// The scene's own setup, or a grass_quality_level.
constexpr int kSceneSetup = -1;

// "scene", "reference", "high", "default", "low" or "fastest".
const char* quality_name(int quality);

class ViewerScene {
public:
    ViewerScene() = default;
    ~ViewerScene();
    ViewerScene(const ViewerScene&) = delete;
    ViewerScene& operator=(const ViewerScene&) = delete;

    // Makes the scene's grass on `ctx` at `quality` (kSceneSetup or a grass_quality_level).
    // On failure returns the failing call's result and *error names it; nothing is left on
    // the context.
    grass_result create(grass_context* ctx, const grass_sample::Scene& scene, int quality, std::string* error);
    // Makes the patch and field again at another quality; on failure the earlier ones stay.
    grass_result set_quality(int quality, std::string* error);
    // Destroys what create() made (before the context is destroyed).
    void destroy();

    int quality() const { return quality_; }
    const grass_patch_info& patch_info() const { return patch_info_; }
    grass_patch_id patch() const { return patch_; }

private:
    grass_result make_field(int quality, grass_patch_id* patch, grass_field_id* field, std::string* error);

    grass_context* ctx_ = nullptr;
    grass_sample::Scene scene_;
    grass_map_stack maps_{};
    grass_wind_map_desc wind_map_{}; // the scene's wind map (a null map: none), set on each field made
    grass_patch_id patch_{};
    grass_field_id field_{};
    grass_patch_info patch_info_{};
    int quality_ = kSceneSetup;
};

} // namespace grass_viewer
