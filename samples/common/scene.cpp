#include "scene.hpp"

#include "gltf_scene.hpp"
#include "png_chunks.hpp"
#include "responsive_scene.hpp"

#include "scene_json.hpp"

#include <png.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace grass_sample {

Scene demo_scene() {
    Scene s;
    s.field.cells_x = 48;
    s.field.cells_z = 48;
    s.field.cell_size = 0.25;
    s.field.base_transform[12] = -6.0; // centre the 12 m field on the origin
    s.field.base_transform[14] = -6.0;
    // The lawn is small enough to be blades everywhere: one geometry tier out to 18 m
    // (Lemme's default setup would hand cells beyond 20 cells, 5 m, to the volume tier; the
    // football scene shows all three tiers).
    s.tiers = {grass_tier_desc{GRASS_TIER_GEOMETRY, 0}};
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.tier = 0;
    band.begin = 0.0f;
    band.end = 18.0f;
    s.lod_tests = {band};
    // A winding path where the grass thins out, to show the density thresholds.
    s.density_width = 96;
    s.density_height = 96;
    s.density_texels.resize(size_t(s.density_width) * s.density_height);
    for (uint32_t z = 0; z < s.density_height; ++z) {
        for (uint32_t x = 0; x < s.density_width; ++x) {
            const double u = (x + 0.5) / s.density_width, v = (z + 0.5) / s.density_height;
            const double centre = 0.5 + 0.18 * std::sin(v * 7.0);
            const double d = std::fabs(u - centre) / 0.05;
            const double density = 0.12 + 0.88 * std::min(1.0, d * d);
            s.density_texels[size_t(z) * s.density_width + x] = static_cast<uint8_t>(std::lround(density * 255.0));
        }
    }
    return s;
}

namespace {

using namespace scene_json;

// A PNG whose header claims more texels than a design map may have (grass_map_desc: at most
// 16384 a side) is refused before its pixels are allocated: a 60-byte file could otherwise
// ask for gigabytes (found by fuzz_png_map).
void check_png_size(png_image* png, const std::string& path) {
    constexpr png_uint_32 kMaxSide = 16384;
    if (png->width > kMaxSide || png->height > kMaxSide) {
        const std::string size = std::to_string(png->width) + " x " + std::to_string(png->height);
        png_image_free(png);
        throw std::runtime_error(path + " is " + size + " pixels; a design map is at most 16384 x 16384");
    }
}

// Begins reading the PNG at `path` from `bytes` (the whole file): its chunks checked first
// (png_chunks.hpp), then its header, then its size.
void begin_png(const std::string& path, std::vector<unsigned char>* bytes, png_image* png) {
    std::string error;
    if (!read_file_bytes(path, bytes, &error)) throw std::runtime_error(error);
    const std::string problem = png_chunk_problem(bytes->data(), bytes->size());
    if (!problem.empty()) throw std::runtime_error(path + " is refused: " + problem);
    png->version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(png, bytes->data(), bytes->size()))
        throw std::runtime_error("cannot read " + path + ": " + png->message);
    check_png_size(png, path);
}

void load_density_png(const std::string& path, Scene* s) {
    std::vector<unsigned char> bytes;
    png_image png{};
    begin_png(path, &bytes, &png);
    png.format = PNG_FORMAT_GRAY;
    s->density_texels.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, s->density_texels.data(), 0, nullptr)) {
        throw std::runtime_error("cannot decode " + path + ": " + png.message);
    }
    s->density_width = png.width;
    s->density_height = png.height;
}

// A design map from a PNG through libpng's simplified API: colour maps as 8-bit sRGB RGBA;
// data maps (density, light, height) as grey, 16-bit files kept at 16 bits (libpng treats
// 16-bit files as linear and 8-bit ones as sRGB: neither is converted here).
Scene::MapImage load_map_png(const std::string& path, bool color) {
    std::vector<unsigned char> bytes;
    png_image png{};
    begin_png(path, &bytes, &png);
    Scene::MapImage m;
    const bool sixteen = (png.format & PNG_FORMAT_FLAG_LINEAR) != 0 && !color;
    png.format = color ? PNG_FORMAT_RGBA : (sixteen ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY);
    m.format =
        color ? GRASS_MAP_FORMAT_RGBA8_UNORM : (sixteen ? GRASS_MAP_FORMAT_R16_UNORM : GRASS_MAP_FORMAT_R8_UNORM);
    m.pixels.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, m.pixels.data(), 0, nullptr)) {
        throw std::runtime_error("cannot decode " + path + ": " + png.message);
    }
    m.width = png.width;
    m.height = png.height;
    return m;
}

std::string beside(const std::string& scene_path, std::string file) {
    if (!file.empty() && file[0] != '/') {
        const auto slash = scene_path.find_last_of('/');
        if (slash != std::string::npos) file = scene_path.substr(0, slash + 1) + file;
    }
    return file;
}

void read_tiers(const json& list, Scene* s) {
    s->tiers.clear();
    for (const json& t : list) {
        check_keys(t, "a tier", {"kind", "slices"});
        grass_tier_desc tier{};
        const std::string kind = t.at("kind").get<std::string>();
        if (kind == "geometry")
            tier.kind = GRASS_TIER_GEOMETRY;
        else if (kind == "volume")
            tier.kind = GRASS_TIER_VOLUME;
        else if (kind == "image")
            tier.kind = GRASS_TIER_IMAGE;
        else
            throw std::runtime_error("a tier's \"kind\" must be geometry, volume or image, not \"" + kind + "\"");
        read(t, "slices", &tier.slices);
        s->tiers.push_back(tier);
    }
}

// {"kind": "band", "tier": 0, "begin": 0, "end": 20, "transition_in": 0, "transition_out": 15}
// {"kind": "macro", "tier": 1, "max_macro_cells": 40}      ("end": null means infinity)
void read_lod_tests(const json& list, Scene* s) {
    s->lod_tests.clear();
    for (const json& t : list) {
        check_keys(t, "a lod test",
                   {"kind", "tier", "begin", "end", "transition_in", "transition_out", "max_macro_cells", "edge_ratio",
                    "max_unplanarity", "unplanarity_ratio"});
        grass_lod_test test{};
        const std::string kind = t.at("kind").get<std::string>();
        if (kind == "band")
            test.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        else if (kind == "macro")
            test.kind = GRASS_LOD_TEST_MACRO_CELL;
        else if (kind == "unplanarity")
            test.kind = GRASS_LOD_TEST_UNPLANARITY;
        else if (kind == "hilltop")
            test.kind = GRASS_LOD_TEST_HILLTOP;
        else
            throw std::runtime_error("a lod test's \"kind\" must be band, macro, unplanarity or hilltop, not \"" +
                                     kind + "\"");
        read(t, "edge_ratio", &test.edge_ratio);
        read(t, "max_unplanarity", &test.max_unplanarity);
        read(t, "unplanarity_ratio", &test.unplanarity_ratio);
        read(t, "tier", &test.tier);
        read(t, "begin", &test.begin);
        test.end = std::numeric_limits<float>::infinity();
        if (t.contains("end") && !t["end"].is_null()) test.end = number_as<float>(t["end"], "\"end\"");
        read(t, "transition_in", &test.transition_in);
        read(t, "transition_out", &test.transition_out);
        read(t, "max_macro_cells", &test.max_macro_cells);
        s->lod_tests.push_back(test);
    }
}

} // namespace

bool load_scene(const std::string& path, Scene* s, std::string* error) {
    try {
        std::ifstream in(path);
        if (!in) throw std::runtime_error("cannot open " + path);
        const json j = json::parse(in, nullptr, true, true);
        // The demo's lod setup and its winding path of thin grass are made for its small
        // lawn: a scene file starts from the library's default tiers and uniform density
        // unless it gives its own. (Inherited, the path showed in every scene file without
        // "density_map": null, stretched over its field: holes in the far tiers over no
        // ground, a darker seam over a ground, that looked like artefacts of the tiers.)
        s->tiers.clear();
        s->lod_tests.clear();
        s->density_texels.clear();
        s->density_width = s->density_height = 0;
        check_keys(j, "the scene",
                   {"patch", "field", "camera", "light", "image", "ground", "wind", "interaction", "colliders"});
        if (j.contains("ground")) {
            const json& g = j["ground"];
            if (g.is_boolean()) {
                s->ground = g.get<bool>();
            } else {
                check_keys(g, "\"ground\"", {"color"});
                s->ground = true;
                read3(g, "color", s->ground_color);
            }
        }
        if (j.contains("patch")) {
            const json& p = j["patch"];
            check_keys(p, "\"patch\"",
                       {"blade_count", "subdivisions", "length", "width", "tilt", "bend", "root_color", "tip_color",
                        "blade_color_variation", "vertex_color_variation", "threshold_mode", "cluster_sigma",
                        "cluster_frequency", "ao_impact", "ao_height", "seed", "mechanics"});
            auto& d = s->patch;
            read(p, "blade_count", &d.blade_count);
            read(p, "subdivisions", &d.subdivisions);
            auto range = [&](const char* key, float* lo, float* hi) {
                if (!p.contains(key)) return;
                const auto v = numbers_as<float>(p.at(key), std::string("\"patch.") + key + "\"");
                if (v.size() != 2) throw std::runtime_error(std::string("\"patch.") + key + "\" must be [min, max]");
                *lo = v[0];
                *hi = v[1];
            };
            range("length", &d.length_min, &d.length_max);
            range("width", &d.width_min, &d.width_max);
            range("tilt", &d.tilt_min, &d.tilt_max);
            range("bend", &d.bend_min, &d.bend_max);
            read3(p, "root_color", d.root_color);
            read3(p, "tip_color", d.tip_color);
            read(p, "blade_color_variation", &d.blade_color_variation);
            read(p, "vertex_color_variation", &d.vertex_color_variation);
            if (p.contains("threshold_mode")) {
                const auto mode = p["threshold_mode"].get<std::string>();
                if (mode == "uniform")
                    d.threshold_mode = GRASS_THRESHOLD_UNIFORM;
                else if (mode == "clustered")
                    d.threshold_mode = GRASS_THRESHOLD_CLUSTERED;
                else
                    throw std::runtime_error("\"patch.threshold_mode\" must be \"uniform\" or \"clustered\", not \"" +
                                             mode + "\"");
            }
            read(p, "cluster_sigma", &d.cluster_sigma);
            read(p, "cluster_frequency", &d.cluster_frequency);
            read(p, "ao_impact", &d.ao_impact);
            read(p, "ao_height", &d.ao_height);
            read(p, "seed", &d.seed);
        }
        if (j.contains("field")) {
            const json& f = j["field"];
            check_keys(f, "\"field\"",
                       {"cells", "cell_size", "origin", "density", "density_map", "mirror_tiling", "mirror_seed",
                        "tiers", "lod_tests", "maps", "wind_map"});
            if (f.contains("wind_map")) {
                const json& w = f["wind_map"];
                check_keys(w, "\"field.wind_map\"", {"map", "speed", "cell_to_map"});
                if (!w.contains("map")) throw std::runtime_error("\"field.wind_map\" needs a \"map\" (an RGBA PNG)");
                s->wind_map = load_map_png(beside(path, w["map"].get<std::string>()), true);
                read(w, "speed", &s->wind_map_desc.speed);
                if (w.contains("cell_to_map")) {
                    const auto v = numbers_as<double>(w["cell_to_map"], "\"field.wind_map.cell_to_map\"");
                    if (v.size() != 6)
                        throw std::runtime_error("\"field.wind_map.cell_to_map\" must have 6 numbers, not " +
                                                 w["cell_to_map"].dump());
                    for (int k = 0; k < 6; ++k) s->wind_map_desc.cell_to_map[k] = v[k];
                }
            }
            if (f.contains("maps")) {
                const json& m = f["maps"];
                check_keys(m, "\"field.maps\"", {"density", "color", "ambient", "diffuse", "height", "height_scale"});
                for (int r = 0; r < kMapRoleCount; ++r) {
                    const MapRole role = MapRole(r);
                    const char* key = map_role_name(role);
                    if (!m.contains(key)) continue;
                    s->maps[r] = load_map_png(beside(path, m[key].get<std::string>()), role == MapRole::color);
                }
                read(m, "height_scale", &s->height_scale);
            }
            auto& d = s->field;
            if (f.contains("cells")) {
                const auto v = numbers_as<uint32_t>(f["cells"], "\"field.cells\"");
                if (v.size() != 2) throw std::runtime_error("\"field.cells\" must be [cells_x, cells_z]");
                d.cells_x = v[0];
                d.cells_z = v[1];
            }
            read(f, "cell_size", &d.cell_size);
            if (f.contains("origin")) {
                double o[3];
                read3(f, "origin", o);
                d.base_transform[12] = o[0];
                d.base_transform[13] = o[1];
                d.base_transform[14] = o[2];
            }
            read(f, "density", &d.density);
            if (f.contains("density_map")) {
                const auto& m = f["density_map"];
                if (m.is_null()) {
                    s->density_texels.clear();
                    s->density_width = s->density_height = 0;
                } else {
                    std::string file = m.get<std::string>();
                    if (!file.empty() && file[0] != '/') {
                        const auto slash = path.find_last_of('/');
                        if (slash != std::string::npos) file = path.substr(0, slash + 1) + file;
                    }
                    load_density_png(file, s);
                }
            }
            bool mirror = d.mirror_tiling != 0;
            read(f, "mirror_tiling", &mirror);
            d.mirror_tiling = mirror ? 1u : 0u;
            read(f, "mirror_seed", &d.mirror_seed);
            if (f.contains("tiers")) read_tiers(f["tiers"], s);
            if (f.contains("lod_tests")) read_lod_tests(f["lod_tests"], s);
        }
        if (j.contains("camera")) {
            const json& c = j["camera"];
            check_keys(c, "\"camera\"", {"position", "target", "fov", "far"});
            read(c, "far", &s->far_m);
            read3(c, "position", s->eye);
            read3(c, "target", s->target);
            read(c, "fov", &s->fov_degrees);
        }
        if (j.contains("light")) {
            const json& l = j["light"];
            check_keys(l, "\"light\"", {"sun_direction", "sun_color", "ambient_color"});
            read3(l, "sun_direction", s->sun_direction);
            read3(l, "sun_color", s->sun_color);
            read3(l, "ambient_color", s->ambient_color);
        }
        if (j.contains("image")) {
            const json& im = j["image"];
            check_keys(im, "\"image\"", {"width", "height", "samples"});
            read(im, "width", &s->width);
            read(im, "height", &s->height);
            read(im, "samples", &s->samples);
        }
        read_responsive(j, &s->responsive);
    } catch (const std::exception& e) {
        if (error) *error = path + ": " + e.what();
        return false;
    }
    return true;
}

bool load_scene_file(const std::string& path, Scene* scene, GltfInfo* gltf, std::string* error) {
    if (!is_gltf_path(path)) return load_scene(path, scene, error);
    GltfInfo ignored;
    return load_gltf_scene(path, scene, gltf ? gltf : &ignored, error);
}

const char* map_role_name(MapRole role) {
    static const char* const names[kMapRoleCount] = {"density", "color", "ambient", "diffuse", "height"};
    return names[int(role)];
}

grass_map_id* map_slot(grass_map_stack* stack, MapRole role) {
    switch (role) {
    case MapRole::density:
        return &stack->density;
    case MapRole::color:
        return &stack->color;
    case MapRole::ambient:
        return &stack->ambient;
    case MapRole::diffuse:
        return &stack->diffuse;
    case MapRole::height:
        return &stack->height;
    }
    return nullptr;
}

grass_result create_scene_maps(grass_context* ctx, const Scene& scene, grass_map_stack* stack) {
    for (int r = 0; r < kMapRoleCount; ++r) {
        const Scene::MapImage& m = scene.maps[r];
        if (m.pixels.empty()) continue;
        grass_map_desc md = grass_default_map_desc();
        md.pixels = m.pixels.data();
        md.width = m.width;
        md.height = m.height;
        md.format = m.format;
        const grass_result result = grass_create_map(ctx, &md, map_slot(stack, MapRole(r)));
        if (result != GRASS_SUCCESS) return result;
    }
    stack->height_scale = scene.height_scale;
    return GRASS_SUCCESS;
}

grass_result create_scene_wind_map(grass_context* ctx, const Scene& scene, grass_wind_map_desc* out) {
    *out = scene.wind_map_desc;
    out->map = grass_map_id{};
    const Scene::MapImage& m = scene.wind_map;
    if (m.pixels.empty()) return GRASS_SUCCESS;
    grass_map_desc md = grass_default_map_desc();
    md.pixels = m.pixels.data();
    md.width = m.width;
    md.height = m.height;
    md.format = m.format;
    return grass_create_map(ctx, &md, &out->map);
}

grass_result set_scene_wind_map(grass_context* ctx, const grass_wind_map_desc& wind, grass_field_id field) {
    if (grass_map_id_is_null(wind.map)) return GRASS_SUCCESS;
    return grass_set_field_wind_map(ctx, field, &wind);
}

grass_host::TargetDesc target_desc(const Scene& scene) {
    grass_host::TargetDesc t;
    t.width = scene.width;
    t.height = scene.height;
    t.samples = scene.samples;
    t.ground = scene.ground;
    t.meshes = scene.meshes;
    std::memcpy(t.ground_color, scene.ground_color, sizeof(t.ground_color));
    return t;
}

void apply_light(const Scene& scene, grass_view_desc* view) {
    std::memcpy(view->sun_direction, scene.sun_direction, sizeof(view->sun_direction));
    std::memcpy(view->sun_color, scene.sun_color, sizeof(view->sun_color));
    std::memcpy(view->ambient_color, scene.ambient_color, sizeof(view->ambient_color));
}

} // namespace grass_sample
