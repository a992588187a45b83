// grass-measure bench's scenes: the scene files it measures, each on a part of its field with
// its cameras (the bench's four and five that games use), the lod setup of a preset for a
// scene, and a scene prepared for a run.
#pragma once

#include "bench.hpp"
#include "scene.hpp"

#include <grass/grass.h>

#include <string>
#include <vector>

namespace grass_measure {
namespace bench {

struct Camera {
    const char* name;
    double eye[3];
    double target[3];
};

// Every scene has these cameras, named alike in this order (bench_scenes.cpp has their
// eyes and targets): the first four (high, player, ant, grazing) are measured by default,
// the game cameras after them (third, elevated, strategy, topdown, flight) on request
// (--camera).
constexpr int kCameraCount = 9;
constexpr int kDefaultCameraCount = 4;

// A scene file on a part of its field (the maps are mapped so that the part keeps its place
// in them). The reduced variants (football, park, hills) also have fewer and wider blades per
// patch, so that their reference (blades everywhere) renders in seconds on llvmpipe; the
// real ones (football-real, ...) keep the scene file's patch (blade_count 0), and their
// references take minutes: by default they are measured from the player camera only. Heights of cameras over a height map are above
// the terrain under the eye (the target moves up by the same amount, so the view direction
// is the flat one).
struct BenchScene {
    const char* name;
    const char* file;
    uint32_t first_x, first_z; // the part of the scene's field, in its cells
    uint32_t cells_x, cells_z;
    uint32_t blade_count;       // 0: the scene file's
    float width_min, width_max; // patch units; 0: the scene file's
    const Camera* cameras;      // kCameraCount: high, player, ant, grazing, then the game cameras
    // The scene file's patch: by default the player camera only, the reference timed on one frame.
    bool real;
};

extern const BenchScene kScenes[];
extern const int kSceneCount;

// grass_apply_quality's tiers, plus, on a height map, what hills.json adds to Lemme's table:
// an UNPLANARITY test on every tier but the blades, and a hilltop overlay volume tier
// (2 slices times the preset's slice scale, macro-cells up to 8) where the image tier starts.
bool lod_setup(grass_context* ctx, const grass_quality_desc& q, const grass_sample::Scene& s, grass_patch_desc* patch,
               std::vector<grass_tier_desc>* tiers, std::vector<grass_lod_test>* tests, std::string* error);

// A scene of kScenes reduced for the bench, and its cameras' eyes and targets (over its
// terrain on a height map).
struct PreparedScene {
    const BenchScene* bench = nullptr;
    grass_sample::Scene scene;
    double cams[kCameraCount][2][3] = {};
    std::vector<int> cameras; // the cameras to measure
    std::string identity;     // what defines its images but the camera (reference_key)
};

// A scene of kScenes prepared for the bench's options (its part, blades and cameras).
bool prepare_scene(const Options& opt, const BenchScene& bs, PreparedScene* ps, std::string* error);

} // namespace bench
} // namespace grass_measure
