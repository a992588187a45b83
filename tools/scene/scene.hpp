// A scene for the sample tools: one patch, one field, a camera and the sun. The built-in
// demo or a small JSON file (see docs/scene-format.md); its design maps made into a map stack.
#pragma once

#include <grass/grass.h>

#include "headless_host.hpp"
#include "host_mesh.hpp"
#include "responsive.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace grass_sample {

// The roles of a field's design maps (grass_map_stack), in the order Scene::maps holds them.
enum class MapRole { density, color, ambient, diffuse, height };
constexpr int kMapRoleCount = 5;

// The role's key in a scene file's "field.maps" ("density", "color", ...).
const char* map_role_name(MapRole role);
// The role's map in a map stack.
grass_map_id* map_slot(grass_map_stack* stack, MapRole role);

// The image's side in pixels: "image.width" and "image.height", grass-render's --size.
constexpr uint32_t kMaxImageSide = 8192;

struct Scene {
    grass_patch_desc patch = grass_default_patch_desc();
    grass_field_desc field = grass_default_field_desc();
    // Density map texels (R8), empty for uniform density.
    std::vector<uint8_t> density_texels;
    uint32_t density_width = 0, density_height = 0;
    // Design maps of the map stack, read from PNG files (empty pixels: none), by MapRole.
    struct MapImage {
        std::vector<uint8_t> pixels;
        uint32_t width = 0, height = 0;
        grass_map_format format = GRASS_MAP_FORMAT_R8_UNORM;
    };
    MapImage maps[kMapRoleCount];
    const MapImage& map(MapRole role) const { return maps[int(role)]; }
    float height_scale = 1.0f;
    // The field's wind map ("field.wind_map": an RGBA PNG, r and g the wind along the field's
    // x and z; empty pixels: none), its speed for an encoded 1 and its cell-to-map transform.
    MapImage wind_map;
    grass_wind_map_desc wind_map_desc = grass_default_wind_map_desc(); // map: set by create_scene_wind_map
    double eye[3] = {0.0, 1.7, -6.4};
    double target[3] = {0.0, 0.0, 1.0};
    float fov_degrees = 55.0f;
    float near_m = 0.05f; // the host projection's near plane
    float far_m = 500.0f; // the host projection's far plane
    // Tiers and lod tests; empty = grass_default_lod_setup (Lemme's football table).
    std::vector<grass_tier_desc> tiers;
    std::vector<grass_lod_test> lod_tests;
    float sun_direction[3] = {0.35f, 0.8f, 0.25f};
    float sun_color[3] = {1.0f, 0.95f, 0.85f};
    float ambient_color[3] = {0.30f, 0.36f, 0.45f};
    uint32_t width = 640, height = 360, samples = 4; // samples: 1 or 4
    // The host's ground under the grass (an engine's terrain stand-in).
    bool ground = true;
    float ground_color[3] = {0.040f, 0.042f, 0.016f};
    // The host's own meshes (a glTF scene's terrain, rocks and buildings), drawn before grass
    // into the depth it shares.
    std::vector<grass_host::HostMesh> meshes;
    // Wind, colliders on their paths, the interaction map and the blade mechanics
    // (docs/responsive.md); none given: still grass.
    Responsive responsive;
};

// The demo: a 12 m x 12 m lawn of 0.25 m cells centred on the origin, clustered blades,
// a winding path of thin grass in the density map, seen from 1.7 m.
Scene demo_scene();

// Reads a scene file over the demo's defaults, but for its lod setup and density path: a
// scene file starts from the library's default tiers and uniform density. False and *error
// on a bad file or key (named by its path, "field.tiers[1].kind"); *scene is then unchanged.
// The file is read by read_file_bytes (a regular file of at most kMaxSceneFileBytes) and
// refused when it nests deeper than kMaxJsonDepth, before it is parsed.
bool load_scene(const std::string& path, Scene* scene, std::string* error);

struct GltfInfo; // gltf_scene.hpp

// Reads a scene file of either kind by its extension: a glTF scene (.gltf, .glb: what
// load_gltf_scene finds besides the Scene goes into *gltf, which may be null) or a JSON
// scene file. The one call for any host that takes "any scene file".
bool load_scene_file(const std::string& path, Scene* scene, GltfInfo* gltf, std::string* error);

// Creates the scene's design maps on `ctx` into `stack` (their ids; its height scale the
// scene's). Stops at the first grass_create_map that fails and returns its result.
grass_result create_scene_maps(grass_context* ctx, const Scene& scene, grass_map_stack* stack);

// Creates the scene's wind map on `ctx` into *out (the scene's speed and transform; a null
// map without one). The host sets it on its fields (grass_set_field_wind_map, where
// set_scene_wind_map does it) and destroys the map after them.
grass_result create_scene_wind_map(grass_context* ctx, const Scene& scene, grass_wind_map_desc* out);
// Sets `wind` on `field` when it has a map (nothing otherwise).
grass_result set_scene_wind_map(grass_context* ctx, const grass_wind_map_desc& wind, grass_field_id field);

// The host target of the scene's image: size, samples and ground.
grass_host::TargetDesc target_desc(const Scene& scene);

// The scene's sun and ambient light into a view.
void apply_light(const Scene& scene, grass_view_desc* view);

} // namespace grass_sample
