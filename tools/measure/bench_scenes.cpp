// grass-measure bench's scenes (bench_scenes.hpp): the scene list, the terrain under the
// cameras, the lod setup of a preset and the preparation of a scene for a run.
#include "bench_scenes.hpp"

#include "file_bytes.hpp"
#include "reference_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace grass_measure {
namespace bench {

// ---- The bench's scenes ---------------------------------------------------------------

// Football: scripts/football-cameras.sh's cameras. The field's centre strip, 20 m wide and
// 60 m deep from the near goal line (80 x 240 of its 380 x 532 cells), so every preset's
// tiers up to the image tier (200 cells = 50 m out for DEFAULT) are in view.
// Park: the whole 40 m x 40 m park (its maps are the scene), fewer blades.
// Hills: 80 m x 100 m of the 200 m x 200 m hills (160 x 200 cells of 0.5 m) around the
// valley camera of docs/design-maps.md, with the host's ground drawn (see main).
// The real variants: the same parts and cameras with the scene files' patches (football 3100
// blades of 0.02..0.03 patch units, park and hills 1200 of the default width).
namespace {

// The game cameras (issue 32) after the four: third person 4 m up looking 15 degrees down
// from the near edge of the part; elevated (20 m, 30 degrees down), strategy (60 m, 55) and
// top-down (100 m, 85) aimed at the part's centre; a flight pass 150 m up looking 20 degrees
// down, placed so that the part's centre lies 40 degrees down, near the bottom of the view
// (the fields are small from 150 m: a few percent of the view). Each target is where the view's
// centre meets the flat ground: eye height / tan(angle) ahead of the eye.
const Camera kFootballCameras[kCameraCount] = {{"high", {47.5, 60, -40}, {47.5, 0, 80}},
                                               {"player", {47.5, 1.7, 6}, {47.5, 0, 60}},
                                               {"ant", {47.3, 0.05, 6}, {47.3, 0.04, 20}},
                                               {"grazing", {47.3, 3, -2}, {47.3, 2.9, 400}},
                                               {"third", {47.5, 4, 2}, {47.5, 0, 16.928}},
                                               {"elevated", {47.5, 20, -4.641}, {47.5, 0, 30}},
                                               {"strategy", {47.5, 60, -12.012}, {47.5, 0, 30}},
                                               {"topdown", {47.5, 100, 21.251}, {47.5, 0, 30}},
                                               {"flight", {47.5, 150, -148.763}, {47.5, 0, 263.359}}};
const Camera kParkCameras[kCameraCount] = {{"high", {20, 30, -15}, {20, 0, 22}},
                                           {"player", {20, 1.7, 2}, {20, 0, 30}},
                                           {"ant", {30, 0.05, 5}, {30, 0.04, 19}},
                                           {"grazing", {20, 3, -2}, {20, 2.9, 400}},
                                           {"third", {20, 4, 2}, {20, 0, 16.928}},
                                           {"elevated", {20, 20, -14.641}, {20, 0, 20}},
                                           {"strategy", {20, 60, -22.012}, {20, 0, 20}},
                                           {"topdown", {20, 100, 11.251}, {20, 0, 20}},
                                           {"flight", {20, 150, -158.763}, {20, 0, 253.359}}};
const Camera kHillsCameras[kCameraCount] = {{"high", {100, 40, -30}, {100, 0, 60}},
                                            {"player", {100, 1.7, 5}, {100, 4, 60}},
                                            {"ant", {100, 0.05, 5}, {100, 0.04, 19}},
                                            {"grazing", {100, 3, -2}, {100, 2.9, 400}},
                                            {"third", {100, 4, 2}, {100, 0, 16.928}},
                                            {"elevated", {100, 20, 15.359}, {100, 0, 50}},
                                            {"strategy", {100, 60, 7.988}, {100, 0, 50}},
                                            {"topdown", {100, 100, 41.251}, {100, 0, 50}},
                                            {"flight", {100, 150, -128.763}, {100, 0, 283.359}}};
} // namespace

const BenchScene kScenes[] = {
    {"football", "football.json", 150, 0, 80, 240, 32, 0.05f, 0.08f, kFootballCameras, false},
    {"park", "park.json", 0, 0, 160, 160, 24, 0.05f, 0.08f, kParkCameras, false},
    {"hills", "hills.json", 120, 0, 160, 200, 24, 0.0f, 0.0f, kHillsCameras, false},
    {"football-real", "football.json", 150, 0, 80, 240, 0, 0.0f, 0.0f, kFootballCameras, true},
    {"park-real", "park.json", 0, 0, 160, 160, 0, 0.0f, 0.0f, kParkCameras, true},
    {"hills-real", "hills.json", 120, 0, 160, 200, 0, 0.0f, 0.0f, kHillsCameras, true},
};
const int kSceneCount = int(sizeof(kScenes) / sizeof(kScenes[0]));

namespace {

// ---- Terrain heights for cameras over a height map ---------------------------------------

// The height map's value under world (x, z), bilinear between texel centres like the GPU.
double terrain_height(const grass_sample::Scene& s, uint32_t full_cells_x, uint32_t full_cells_z, double x, double z) {
    const auto& m = s.map(grass_sample::MapRole::height);
    if (m.pixels.empty()) return 0.0;
    const double cs = s.field.cell_size;
    // The scene's full field starts at its own origin (base_transform before the bench moves it).
    const double u = (x - s.field.base_transform[12]) / (cs * full_cells_x),
                 v = (z - s.field.base_transform[14]) / (cs * full_cells_z);
    auto texel = [&](int64_t tx, int64_t tz) {
        tx = std::clamp<int64_t>(tx, 0, m.width - 1);
        tz = std::clamp<int64_t>(tz, 0, m.height - 1);
        const size_t i = size_t(tz) * m.width + size_t(tx);
        if (m.format == GRASS_MAP_FORMAT_R16_UNORM) {
            uint16_t t;
            std::memcpy(&t, &m.pixels[2 * i], 2);
            return t / 65535.0;
        }
        return m.pixels[i] / 255.0;
    };
    const double fx = u * m.width - 0.5, fz = v * m.height - 0.5;
    const int64_t x0 = int64_t(std::floor(fx)), z0 = int64_t(std::floor(fz));
    const double ax = fx - double(x0), az = fz - double(z0);
    const double h = (1 - az) * ((1 - ax) * texel(x0, z0) + ax * texel(x0 + 1, z0)) +
                     az * ((1 - ax) * texel(x0, z0 + 1) + ax * texel(x0 + 1, z0 + 1));
    return s.field.base_transform[13] + h * s.height_scale;
}

} // namespace

// ---- The lod setup of a preset for a scene --------------------------------------------

// grass_apply_quality's tiers, plus, on a height map, what hills.json adds to Lemme's table:
// an UNPLANARITY test on every tier but the blades, and a hilltop overlay volume tier
// (2 slices times the preset's slice scale, macro-cells up to 8) where the image tier starts.
bool lod_setup(grass_context* ctx, const grass_quality_desc& q, const grass_sample::Scene& s, grass_patch_desc* patch,
               std::vector<grass_tier_desc>* tiers, std::vector<grass_lod_test>* tests, std::string* error) {
    tiers->assign(GRASS_MAX_TIERS, grass_tier_desc{});
    tests->assign(GRASS_MAX_LOD_TESTS, grass_lod_test{});
    uint32_t tc = 0, lc = 0;
    const grass_result r =
        grass_apply_quality(ctx, &q, s.field.cell_size, patch, tiers->data(), &tc, tests->data(), &lc);
    if (r != GRASS_SUCCESS) {
        *error = std::string("grass_apply_quality failed: ") + grass_result_string(r) + " (" +
                 grass_get_last_error(ctx) + ")";
        return false;
    }
    tiers->resize(tc);
    tests->resize(lc);
    if (s.map(grass_sample::MapRole::height).pixels.empty() || q.blades_everywhere) return true;
    float image_begin = std::numeric_limits<float>::infinity();
    for (uint32_t t = 0; t < tc; ++t) {
        if ((*tiers)[t].kind == GRASS_TIER_GEOMETRY) continue;
        grass_lod_test u{};
        u.kind = GRASS_LOD_TEST_UNPLANARITY;
        u.tier = t;
        u.max_unplanarity = 0.25f;
        u.unplanarity_ratio = 0.02f;
        tests->push_back(u);
        if ((*tiers)[t].kind == GRASS_TIER_IMAGE) {
            for (const auto& b : *tests)
                if (b.kind == GRASS_LOD_TEST_DISTANCE_BAND && b.tier == t) image_begin = std::min(image_begin, b.begin);
        }
    }
    if (std::isfinite(image_begin) && tiers->size() < GRASS_MAX_TIERS) {
        const uint32_t t = uint32_t(tiers->size());
        grass_tier_desc overlay{};
        overlay.kind = GRASS_TIER_VOLUME;
        overlay.slices = std::max<uint32_t>(1, uint32_t(std::lround(2.0 * q.slice_scale)));
        tiers->push_back(overlay);
        grass_lod_test band{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = t;
        band.begin = image_begin;
        band.end = std::numeric_limits<float>::infinity();
        grass_lod_test hill{};
        hill.kind = GRASS_LOD_TEST_HILLTOP;
        hill.tier = t;
        grass_lod_test macro{};
        macro.kind = GRASS_LOD_TEST_MACRO_CELL;
        macro.tier = t;
        macro.max_macro_cells = 8;
        tests->insert(tests->end(), {band, hill, macro});
    }
    return true;
}

namespace {

// FNV-1a 64 of a file's bytes, as hex; "none" for an empty path, "missing" for one that
// read_file_bytes refuses (missing, not a regular file, over kMaxFileBytes).
std::string file_hash(const std::string& path) {
    if (path.empty()) return "none";
    std::vector<unsigned char> bytes;
    std::string error;
    if (!grass_sample::read_file_bytes(path, grass_sample::kMaxFileBytes, &bytes, &error)) return "missing";
    return reference_hash(std::string(bytes.begin(), bytes.end()));
}

} // namespace

bool prepare_scene(const Options& opt, const BenchScene& bs, PreparedScene* ps, std::string* error) {
    ps->bench = &bs;
    grass_sample::Scene& scene = ps->scene;
    if (!grass_sample::load_scene(opt.scene_dir + "/" + bs.file, &scene, error)) return false;
    // The bench's variant: a part of the field, its maps mapped onto that part.
    const uint32_t full_x = scene.field.cells_x, full_z = scene.field.cells_z;
    if (bs.first_x + bs.cells_x > full_x || bs.first_z + bs.cells_z > full_z) {
        *error = std::string(bs.name) + ": the bench's part lies outside the field";
        return false;
    }
    const double cs = scene.field.cell_size;
    for (int c = 0; c < kCameraCount; ++c) {
        const Camera& cam = bs.cameras[c];
        const double lift = terrain_height(scene, full_x, full_z, cam.eye[0], cam.eye[2]);
        for (int k = 0; k < 3; ++k) {
            ps->cams[c][0][k] = cam.eye[k] + (k == 1 ? lift : 0.0);
            ps->cams[c][1][k] = cam.target[k] + (k == 1 ? lift : 0.0);
        }
    }
    scene.field.cells_x = bs.cells_x;
    scene.field.cells_z = bs.cells_z;
    scene.field.base_transform[12] += bs.first_x * cs;
    scene.field.base_transform[14] += bs.first_z * cs;
    double* m = scene.field.maps.cell_to_map;
    m[0] = 1.0 / full_x, m[1] = 0.0, m[2] = 0.0, m[3] = 1.0 / full_z;
    m[4] = double(bs.first_x) / full_x, m[5] = double(bs.first_z) / full_z;
    if (bs.blade_count > 0) scene.patch.blade_count = bs.blade_count;
    if (bs.width_max > 0.0f) scene.patch.width_min = bs.width_min, scene.patch.width_max = bs.width_max;
    // The hills scene draws no ground (the host's ground is flat); with the bench's
    // sparse blades the sky showed through the grass, so the flat ground at y = 0, under
    // the hills, shows as soil behind it instead.
    scene.ground = true;
    if (!scene.density_texels.empty()) {
        *error = std::string(bs.name) + ": the bench reads density through the map stack only";
        return false;
    }
    ps->cameras = opt.cameras;
    if (ps->cameras.empty()) {
        if (bs.real) ps->cameras = {1}; // the player
        for (int c = 0; c < kDefaultCameraCount && !bs.real; ++c) ps->cameras.push_back(c);
    }
    // The scene file's bytes, its maps' texels and the bench's changes define its images.
    std::ostringstream id;
    id << "scene " << bs.name << " file " << file_hash(opt.scene_dir + "/" + bs.file) << " maps";
    for (const auto& map : scene.maps) id << ' ' << reference_hash(std::string(map.pixels.begin(), map.pixels.end()));
    id << " part " << bs.first_x << ',' << bs.first_z << ',' << bs.cells_x << ',' << bs.cells_z << " blades "
       << scene.patch.blade_count << " width " << scene.patch.width_min << ',' << scene.patch.width_max << " seed "
       << scene.patch.seed << " mirror " << scene.field.mirror_seed << " ground " << scene.ground;
    ps->identity = id.str();
    return true;
}

} // namespace bench
} // namespace grass_measure
