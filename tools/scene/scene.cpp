#include "scene.hpp"

#include "file_bytes.hpp"
#include "gltf_scene.hpp"
#include "json_depth.hpp"
#include "png_chunks.hpp"
#include "png_palette.hpp"
#include "responsive_scene.hpp"

#include "scene_json.hpp"

#include <png.h>

#include <cmath>
#include <cstring>
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

// Begins reading the PNG at `path` from `bytes` (the whole file, read_file_bytes): its chunks
// checked first (png_chunks.hpp), then its header, its size and its palette's indices.
void begin_png(const std::string& path, std::vector<unsigned char>* bytes, png_image* png) {
    std::string error;
    if (!read_file_bytes(path, kMaxFileBytes, bytes, &error)) throw std::runtime_error(error);
    const std::string name = cut_path(path);
    const std::string problem = png_chunk_problem(bytes->data(), bytes->size());
    if (!problem.empty()) throw std::runtime_error(name + " is refused: " + problem);
    png->version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(png, bytes->data(), bytes->size()))
        throw std::runtime_error("cannot read " + name + ": " + png->message);
    check_png_size(png, name);
    const std::string palette = png_palette_problem(bytes->data(), bytes->size());
    if (!palette.empty()) {
        png_image_free(png);
        throw std::runtime_error(name + " is refused: " + palette);
    }
}

void load_density_png(const std::string& path, Scene* s) {
    std::vector<unsigned char> bytes;
    png_image png{};
    begin_png(path, &bytes, &png);
    png.format = PNG_FORMAT_GRAY;
    s->density_texels.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, s->density_texels.data(), 0, nullptr)) {
        throw std::runtime_error("cannot decode " + cut_path(path) + ": " + png.message);
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
        throw std::runtime_error("cannot decode " + cut_path(path) + ": " + png.message);
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

// A list under `path` that must not be empty, of at most `max` entries.
const json& list_at(const json& v, const std::string& path, const char* of, size_t max) {
    array_at(v, path, of);
    if (v.empty()) {
        throw std::runtime_error(quoted(path) + " is empty: give at least one, or leave the key out for the "
                                                "library's defaults");
    }
    if (v.size() > max) {
        throw std::runtime_error(quoted(path) + " has " + std::to_string(v.size()) + " entries; at most " +
                                 std::to_string(max));
    }
    return v;
}

void read_tiers(const json& list, Scene* s) {
    list_at(list, "field.tiers", "tiers", GRASS_MAX_TIERS);
    s->tiers.clear();
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = "field.tiers[" + std::to_string(i) + "]";
        const json& t = list[i];
        check_keys(t, where, {"kind", "slices"});
        grass_tier_desc tier{};
        if (!t.contains("kind")) throw std::runtime_error(quoted(where) + " needs a \"kind\"");
        const std::string kind = text_of(t, where, "kind");
        if (kind == "geometry")
            tier.kind = GRASS_TIER_GEOMETRY;
        else if (kind == "volume")
            tier.kind = GRASS_TIER_VOLUME;
        else if (kind == "image")
            tier.kind = GRASS_TIER_IMAGE;
        else
            throw std::runtime_error(quoted(where + ".kind") + " must be geometry, volume or image, not \"" +
                                     cut(kind) + "\"");
        read(t, where, "slices", &tier.slices);
        s->tiers.push_back(tier);
    }
}

// {"kind": "band", "tier": 0, "begin": 0, "end": 20, "transition_in": 0, "transition_out": 15}
// {"kind": "macro", "tier": 1, "max_macro_cells": 40}      ("end": null means infinity)
void read_lod_tests(const json& list, Scene* s) {
    list_at(list, "field.lod_tests", "lod tests", GRASS_MAX_LOD_TESTS);
    s->lod_tests.clear();
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = "field.lod_tests[" + std::to_string(i) + "]";
        const json& t = list[i];
        check_keys(t, where,
                   {"kind", "tier", "begin", "end", "transition_in", "transition_out", "max_macro_cells", "edge_ratio",
                    "max_unplanarity", "unplanarity_ratio"});
        grass_lod_test test{};
        if (!t.contains("kind")) throw std::runtime_error(quoted(where) + " needs a \"kind\"");
        const std::string kind = text_of(t, where, "kind");
        if (kind == "band")
            test.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        else if (kind == "macro")
            test.kind = GRASS_LOD_TEST_MACRO_CELL;
        else if (kind == "unplanarity")
            test.kind = GRASS_LOD_TEST_UNPLANARITY;
        else if (kind == "hilltop")
            test.kind = GRASS_LOD_TEST_HILLTOP;
        else
            throw std::runtime_error(quoted(where + ".kind") + " must be band, macro, unplanarity or hilltop, not \"" +
                                     cut(kind) + "\"");
        read(t, where, "edge_ratio", &test.edge_ratio);
        read(t, where, "max_unplanarity", &test.max_unplanarity);
        read(t, where, "unplanarity_ratio", &test.unplanarity_ratio);
        read(t, where, "tier", &test.tier);
        read(t, where, "begin", &test.begin);
        test.end = std::numeric_limits<float>::infinity();
        if (t.contains("end") && !t["end"].is_null()) test.end = number_as<float>(t["end"], quoted(where + ".end"));
        read(t, where, "transition_in", &test.transition_in);
        read(t, where, "transition_out", &test.transition_out);
        read(t, where, "max_macro_cells", &test.max_macro_cells);
        s->lod_tests.push_back(test);
    }
}

// A file a scene names (a map), beside the scene unless absolute; `where` is its key's path.
std::string named_file(const std::string& scene_path, const json& j, const std::string& where, const char* key) {
    const std::string file = text_of(j, where, key);
    if (file.empty()) throw std::runtime_error(quoted(join(where, key)) + " is an empty file name");
    return beside(scene_path, file);
}

// The whole scene file, checked (regular, at most kMaxSceneFileBytes, nested at most
// kMaxJsonDepth deep) before it is parsed.
json parse_scene_file(const std::string& path) {
    std::vector<unsigned char> bytes;
    std::string error;
    if (!read_file_bytes(path, kMaxSceneFileBytes, &bytes, &error)) throw std::runtime_error(error);
    const char* text = reinterpret_cast<const char*>(bytes.data());
    const std::string deep = json_depth_problem(text, bytes.size(), kMaxJsonDepth, true);
    if (!deep.empty()) throw std::runtime_error("the scene " + deep);
    try {
        return json::parse(text, text + bytes.size(), nullptr, true, true);
    } catch (const json::exception& e) {
        throw std::runtime_error(cut(e.what(), 200)); // a parse error quotes the token it stopped in
    }
}

void read_camera(const json& c, Scene* s) {
    check_keys(c, "camera", {"position", "target", "fov", "far"});
    read(c, "camera", "far", &s->far_m);
    read3(c, "camera", "position", s->eye);
    read3(c, "camera", "target", s->target);
    read(c, "camera", "fov", &s->fov_degrees);
    if (c.contains("fov") && !(s->fov_degrees > 0.0f && s->fov_degrees < 180.0f)) {
        throw std::runtime_error("\"camera.fov\" is " + shown(c["fov"]) +
                                 "; it must lie between 0 and 180 degrees (exclusive)");
    }
    if (c.contains("far") && !(s->far_m > s->near_m)) {
        throw std::runtime_error("\"camera.far\" is " + shown(c["far"]) + "; it must lie beyond the near plane (" +
                                 std::to_string(s->near_m) + " m)");
    }
}

void read_image(const json& im, Scene* s) {
    check_keys(im, "image", {"width", "height", "samples"});
    for (const char* key : {"width", "height"}) {
        uint32_t v = 0;
        read(im, "image", key, &v);
        if (!im.contains(key)) continue;
        if (v < 1 || v > kMaxImageSide) {
            throw std::runtime_error("\"image." + std::string(key) + "\" is " + shown(im[key]) + "; it must be 1.." +
                                     std::to_string(kMaxImageSide) + " (as --size)");
        }
        (std::string(key) == "width" ? s->width : s->height) = v;
    }
    read(im, "image", "samples", &s->samples);
    if (im.contains("samples") && s->samples != 1 && s->samples != 4)
        throw std::runtime_error("\"image.samples\" is " + shown(im["samples"]) + "; it must be 1 or 4 (as --samples)");
}

} // namespace

bool load_scene(const std::string& path, Scene* out, std::string* error) {
    try {
        const json j = parse_scene_file(path);
        Scene scene = *out; // all or nothing: *out stays as it was when a key is refused
        Scene* s = &scene;
        // The demo's lod setup and its winding path of thin grass are made for its small
        // lawn: a scene file starts from the library's default tiers and uniform density
        // unless it gives its own. (Inherited, the path showed in every scene file without
        // "density_map": null, stretched over its field: holes in the far tiers over no
        // ground, a darker seam over a ground, that looked like artefacts of the tiers.)
        s->tiers.clear();
        s->lod_tests.clear();
        s->density_texels.clear();
        s->density_width = s->density_height = 0;
        check_keys(j, "", {"patch", "field", "camera", "light", "image", "ground", "wind", "interaction", "colliders"});
        if (j.contains("ground")) {
            const json& g = j["ground"];
            if (g.is_boolean()) {
                s->ground = g.get<bool>();
            } else {
                check_keys(g, "ground", {"color"});
                s->ground = true;
                read3(g, "ground", "color", s->ground_color);
            }
        }
        if (j.contains("patch")) {
            const json& p = j["patch"];
            check_keys(p, "patch",
                       {"blade_count", "subdivisions", "length", "width", "tilt", "bend", "root_color", "tip_color",
                        "blade_color_variation", "vertex_color_variation", "threshold_mode", "cluster_sigma",
                        "cluster_frequency", "ao_impact", "ao_height", "seed", "mechanics"});
            auto& d = s->patch;
            read(p, "patch", "blade_count", &d.blade_count);
            read(p, "patch", "subdivisions", &d.subdivisions);
            auto range = [&](const char* key, float* lo, float* hi) {
                if (!p.contains(key)) return;
                const auto v = numbers_as<float>(p.at(key), quoted(join("patch", key)));
                if (v.size() != 2) throw std::runtime_error(quoted(join("patch", key)) + " must be [min, max]");
                *lo = v[0];
                *hi = v[1];
            };
            range("length", &d.length_min, &d.length_max);
            range("width", &d.width_min, &d.width_max);
            range("tilt", &d.tilt_min, &d.tilt_max);
            range("bend", &d.bend_min, &d.bend_max);
            read3(p, "patch", "root_color", d.root_color);
            read3(p, "patch", "tip_color", d.tip_color);
            read(p, "patch", "blade_color_variation", &d.blade_color_variation);
            read(p, "patch", "vertex_color_variation", &d.vertex_color_variation);
            if (p.contains("threshold_mode")) {
                const auto mode = text_of(p, "patch", "threshold_mode");
                if (mode == "uniform")
                    d.threshold_mode = GRASS_THRESHOLD_UNIFORM;
                else if (mode == "clustered")
                    d.threshold_mode = GRASS_THRESHOLD_CLUSTERED;
                else
                    throw std::runtime_error("\"patch.threshold_mode\" must be \"uniform\" or \"clustered\", not \"" +
                                             cut(mode) + "\"");
            }
            read(p, "patch", "cluster_sigma", &d.cluster_sigma);
            read(p, "patch", "cluster_frequency", &d.cluster_frequency);
            read(p, "patch", "ao_impact", &d.ao_impact);
            read(p, "patch", "ao_height", &d.ao_height);
            read(p, "patch", "seed", &d.seed);
        }
        if (j.contains("field")) {
            const json& f = j["field"];
            check_keys(f, "field",
                       {"cells", "cell_size", "origin", "density", "density_map", "mirror_tiling", "mirror_seed",
                        "tiers", "lod_tests", "maps", "wind_map"});
            if (f.contains("wind_map")) {
                const json& w = f["wind_map"];
                check_keys(w, "field.wind_map", {"map", "speed", "cell_to_map"});
                if (!w.contains("map")) throw std::runtime_error("\"field.wind_map\" needs a \"map\" (an RGBA PNG)");
                s->wind_map = load_map_png(named_file(path, w, "field.wind_map", "map"), true);
                read(w, "field.wind_map", "speed", &s->wind_map_desc.speed);
                if (w.contains("cell_to_map")) {
                    const auto v = numbers_as<double>(w["cell_to_map"], "\"field.wind_map.cell_to_map\"");
                    if (v.size() != 6)
                        throw std::runtime_error("\"field.wind_map.cell_to_map\" must have 6 numbers, not " +
                                                 shown(w["cell_to_map"]));
                    for (int k = 0; k < 6; ++k) s->wind_map_desc.cell_to_map[k] = v[k];
                }
            }
            if (f.contains("maps")) {
                const json& m = f["maps"];
                check_keys(m, "field.maps", {"density", "color", "ambient", "diffuse", "height", "height_scale"});
                for (int r = 0; r < kMapRoleCount; ++r) {
                    const MapRole role = MapRole(r);
                    const char* key = map_role_name(role);
                    if (!m.contains(key)) continue;
                    s->maps[r] = load_map_png(named_file(path, m, "field.maps", key), role == MapRole::color);
                }
                read(m, "field.maps", "height_scale", &s->height_scale);
            }
            auto& d = s->field;
            if (f.contains("cells")) {
                const auto v = numbers_as<uint32_t>(f["cells"], "\"field.cells\"");
                if (v.size() != 2) throw std::runtime_error("\"field.cells\" must be [cells_x, cells_z]");
                d.cells_x = v[0];
                d.cells_z = v[1];
            }
            read(f, "field", "cell_size", &d.cell_size);
            if (f.contains("origin")) {
                double o[3];
                read3(f, "field", "origin", o);
                d.base_transform[12] = o[0];
                d.base_transform[13] = o[1];
                d.base_transform[14] = o[2];
            }
            read(f, "field", "density", &d.density);
            if (f.contains("density_map")) {
                if (f["density_map"].is_null()) {
                    s->density_texels.clear();
                    s->density_width = s->density_height = 0;
                } else {
                    load_density_png(named_file(path, f, "field", "density_map"), s);
                }
            }
            bool mirror = d.mirror_tiling != 0;
            read(f, "field", "mirror_tiling", &mirror);
            d.mirror_tiling = mirror ? 1u : 0u;
            read(f, "field", "mirror_seed", &d.mirror_seed);
            if (f.contains("tiers")) read_tiers(f["tiers"], s);
            if (f.contains("lod_tests")) read_lod_tests(f["lod_tests"], s);
        }
        if (j.contains("camera")) read_camera(j["camera"], s);
        if (j.contains("light")) {
            const json& l = j["light"];
            check_keys(l, "light", {"sun_direction", "sun_color", "ambient_color"});
            read3(l, "light", "sun_direction", s->sun_direction);
            read3(l, "light", "sun_color", s->sun_color);
            read3(l, "light", "ambient_color", s->ambient_color);
        }
        if (j.contains("image")) read_image(j["image"], s);
        read_responsive(j, &s->responsive);
        *out = std::move(scene);
    } catch (const std::exception& e) {
        if (error) *error = cut_path(path) + ": " + e.what();
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
