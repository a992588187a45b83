#include "host_scene_options.hpp"

#include "mesh_shapes.hpp"

#include <cmath>
#include <cstdlib>

namespace grass_sample {

namespace {

// Comma-separated finite numbers: between min_count and max_count of them.
bool parse_numbers(const std::string& text, size_t min_count, size_t max_count, std::vector<double>* out,
                   std::string* error) {
    out->clear();
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(v)) {
            *error = "'" + text + "' is not a list of numbers ('" + item + "')";
            return false;
        }
        out->push_back(v);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (out->size() < min_count || out->size() > max_count) {
        *error = "'" + text + "' has " + std::to_string(out->size()) + " numbers; expected " +
                 std::to_string(min_count) + (max_count > min_count ? " to " + std::to_string(max_count) : "");
        return false;
    }
    return true;
}

enum class Kind { box, tree, splits };

CLI::Validator numbers(Kind kind, size_t min_count, size_t max_count, const char* name) {
    return CLI::Validator(
        [=](std::string& text) {
            std::vector<double> v;
            std::string error;
            if (!parse_numbers(text, min_count, max_count, &v, &error)) return error;
            if (kind == Kind::box && !(v[0] < v[3] && v[1] < v[4] && v[2] < v[5]))
                return "'" + text + "': each low corner coordinate must be below the high one";
            if (kind == Kind::tree && !(v[2] > 0.0 && v[3] > 0.0))
                return "'" + text + "': the trunk and crown must be taller than 0";
            if (kind == Kind::splits) {
                for (size_t i = 0; i < v.size(); ++i) {
                    if (!(v[i] > (i ? v[i - 1] : 0.0)))
                        return "'" + text + "': split distances must be > 0 and ascending";
                }
            }
            return std::string();
        },
        name);
}

} // namespace

void add_host_scene_options(CLI::App& app, HostSceneOptions* o) {
    app.add_option("--box", o->boxes, "a box the host draws (repeatable): X0,Y0,Z0,X1,Y1,Z1, metres")
        ->check(numbers(Kind::box, 6, 6, "X0,Y0,Z0,X1,Y1,Z1"));
    app.add_option("--tree", o->trees, "a tree the host draws (repeatable): X,Z,TRUNK,CROWN, metres")
        ->check(numbers(Kind::tree, 4, 4, "X,Z,TRUNK,CROWN"));
    app.add_option("--host-shadows", o->shadows,
                   "the host's cascaded sun shadows: where each cascade ends, metres along the view axis "
                   "(1 to 4 ascending distances); the meshes and grass cast, the ground, meshes and grass receive")
        ->check(numbers(Kind::splits, 1, GRASS_MAX_SHADOW_CASCADES, "SPLIT[,SPLIT...]"));
}

void add_host_meshes(const HostSceneOptions& o, std::vector<grass_host::HostMesh>* meshes) {
    std::vector<double> v;
    std::string error;
    const float wall[3] = {0.55f, 0.5f, 0.45f};
    for (const std::string& text : o.boxes) {
        if (parse_numbers(text, 6, 6, &v, &error)) meshes->push_back(grass_host::box_mesh("box", &v[0], &v[3], wall));
    }
    for (const std::string& text : o.trees) {
        if (parse_numbers(text, 4, 4, &v, &error)) grass_host::add_tree(meshes, v[0], v[1], v[2], v[3]);
    }
}

void apply_host_shadows(const HostSceneOptions& o, grass_host::TargetDesc* target) {
    std::vector<double> v;
    std::string error;
    if (o.shadows.empty() || !parse_numbers(o.shadows, 1, GRASS_MAX_SHADOW_CASCADES, &v, &error)) return;
    target->host_shadows.cascades = uint32_t(v.size());
    target->host_shadows.map_size = 1024;
    for (size_t i = 0; i < v.size(); ++i) target->host_shadows.splits[i] = float(v[i]);
}

} // namespace grass_sample
