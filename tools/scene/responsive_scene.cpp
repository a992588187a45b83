#include "responsive_scene.hpp"

#include "scene_json.hpp"

#include <string>
#include <utility>

namespace grass_sample {

namespace {

using namespace scene_json;

const json& object(const json& j, const std::string& name) { return object_at(j, name); }

template <class T>
void read_named(const json& j, const char* key, const std::string& where, T* out) {
    read(j, where, key, out);
}

template <class T>
void read_named3(const json& j, const char* key, const std::string& where, T out[3]) {
    read3(j, where, key, out);
}

// A point [x, y, z], keyframes {"keyframes": [[t, x, y, z], ...]} (times ascending) or a line
// {"from": [x, y, z], "to": [x, y, z], "speed": m/s, "start": s}.
Path read_path(const json& v, const std::string& name) {
    if (v.is_array()) {
        const auto p = numbers_as<double>(v, quoted(name));
        if (p.size() != 3) throw std::runtime_error(quoted(name) + " must be [x, y, z] or a path, not " + shown(v));
        return Path::fixed(p.data());
    }
    if (!v.is_object()) throw std::runtime_error(quoted(name) + " must be [x, y, z] or a path, not " + shown(v));
    check_keys(v, name, {"keyframes", "from", "to", "speed", "start"});
    if (v.contains("keyframes")) {
        if (v.contains("from") || v.contains("to") || v.contains("speed") || v.contains("start"))
            throw std::runtime_error(quoted(name) + " has \"keyframes\" and a line's keys: give one path");
        const std::string kname = name + ".keyframes";
        const json& list = v["keyframes"];
        if (!list.is_array() || list.empty())
            throw std::runtime_error(quoted(kname) + " must be a list of [t, x, y, z], not " + shown(list));
        Path path;
        for (const json& k : list) {
            const auto f = numbers_as<double>(k, quoted(kname));
            if (f.size() != 4) throw std::runtime_error(quoted(kname) + " has " + shown(k) + "; each is [t, x, y, z]");
            if (!path.times.empty() && !(f[0] > path.times.back()))
                throw std::runtime_error(quoted(kname) + " times must ascend: " + shown(k) + " after time " +
                                         std::to_string(path.times.back()));
            path.times.push_back(f[0]);
            path.points.push_back({f[1], f[2], f[3]});
        }
        return path;
    }
    for (const char* key : {"from", "to", "speed"}) {
        if (!v.contains(key))
            throw std::runtime_error(quoted(name) + " needs \"keyframes\" or \"from\", \"to\" and \"speed\"; \"" + key +
                                     "\" is missing");
    }
    double from[3], to[3], speed = 0.0, start = 0.0;
    read_named3(v, "from", name, from);
    read_named3(v, "to", name, to);
    read_named(v, "speed", name, &speed);
    read_named(v, "start", name, &start);
    if (!(speed > 0.0))
        throw std::runtime_error(quoted(name + ".speed") + " is " + shown(v["speed"]) + "; it must be > 0");
    return Path::line(from, to, speed, start);
}

void read_wind(const json& w, Responsive* r) {
    check_keys(w, "wind", {"direction", "speed", "gust_strength", "gust_length", "turbulence", "gravity", "sources"});
    r->wind_given = true;
    grass_wind_desc& d = r->wind;
    read_named3(w, "direction", "wind", d.direction);
    read_named(w, "speed", "wind", &d.speed);
    read_named(w, "gust_strength", "wind", &d.gust_strength);
    read_named(w, "gust_length", "wind", &d.gust_length);
    read_named(w, "turbulence", "wind", &d.turbulence);
    read_named3(w, "gravity", "wind", d.gravity);
    if (!w.contains("sources")) return;
    const json& list = w["sources"];
    if (!list.is_array()) throw std::runtime_error("\"wind.sources\" must be a list, not " + shown(list));
    if (list.size() > GRASS_MAX_WIND_SOURCES) {
        throw std::runtime_error("\"wind.sources\" has " + std::to_string(list.size()) +
                                 " sources; grass takes at most " + std::to_string(GRASS_MAX_WIND_SOURCES) +
                                 " (GRASS_MAX_WIND_SOURCES)");
    }
    r->sources.clear();
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string name = "wind.sources[" + std::to_string(i) + "]";
        const json& s = object(list[i], name);
        check_keys(s, name,
                   {"kind", "position", "direction", "cone_angle", "speed", "radius", "start_time", "duration",
                    "front_speed"});
        SceneWindSource src;
        grass_wind_source& g = src.source;
        g.radius = 1.0f;
        const std::string kind = text_of(s, name, "kind", "point");
        if (kind == "point")
            g.kind = GRASS_WIND_SOURCE_POINT;
        else if (kind == "cone")
            g.kind = GRASS_WIND_SOURCE_CONE;
        else if (kind == "blast")
            g.kind = GRASS_WIND_SOURCE_BLAST;
        else
            throw std::runtime_error(quoted(name + ".kind") + " must be point, cone or blast, not \"" + cut(kind) +
                                     "\"");
        if (!s.contains("position")) throw std::runtime_error(quoted(name) + " needs a \"position\"");
        src.path = read_path(s["position"], name + ".position");
        read_named3(s, "direction", name, g.direction);
        read_named(s, "cone_angle", name, &g.cone_angle);
        read_named(s, "speed", name, &g.speed);
        read_named(s, "radius", name, &g.radius);
        read_named(s, "start_time", name, &g.start_time);
        read_named(s, "duration", name, &g.duration);
        read_named(s, "front_speed", name, &g.front_speed);
        r->sources.push_back(src);
    }
}

void read_interaction(const json& m, Responsive* r) {
    check_keys(m, "interaction", {"up", "resolution", "levels", "texel_size"});
    r->interaction_given = true;
    grass_interaction_desc& d = r->interaction;
    read_named3(m, "up", "interaction", d.up);
    read_named(m, "resolution", "interaction", &d.resolution);
    read_named(m, "levels", "interaction", &d.level_count);
    if (m.contains("texel_size")) {
        const auto v = numbers_as<float>(m["texel_size"], "\"interaction.texel_size\"");
        if (v.empty() || v.size() > 2)
            throw std::runtime_error("\"interaction.texel_size\" must be [level 0] or [level 0, level 1], not " +
                                     shown(m["texel_size"]));
        for (size_t k = 0; k < v.size(); ++k) d.texel_size[k] = v[k];
    }
}

void read_colliders(const json& list, Responsive* r) {
    if (!list.is_array()) throw std::runtime_error("\"colliders\" must be a list, not " + shown(list));
    // Counted before any is read: 70,000 colliders took 37 s and 4.5 GB of the tool's meshes
    // before grass_set_colliders refused them (issue 37).
    if (list.size() > GRASS_MAX_COLLIDERS) {
        throw std::runtime_error("\"colliders\" has " + std::to_string(list.size()) +
                                 " colliders; grass takes at most " + std::to_string(GRASS_MAX_COLLIDERS) +
                                 " (GRASS_MAX_COLLIDERS)");
    }
    r->colliders.clear();
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string name = "colliders[" + std::to_string(i) + "]";
        const json& c = object(list[i], name);
        check_keys(c, name, {"shape", "radius", "centre", "end"});
        SceneCollider col;
        const std::string shape = text_of(c, name, "shape", "sphere");
        if (shape == "capsule")
            col.shape = GRASS_COLLIDER_CAPSULE;
        else if (shape != "sphere")
            throw std::runtime_error(quoted(name + ".shape") + " must be sphere or capsule, not \"" + cut(shape) +
                                     "\"");
        read_named(c, "radius", name, &col.radius);
        if (!c.contains("centre")) throw std::runtime_error(quoted(name) + " needs a \"centre\"");
        col.centre = read_path(c["centre"], name + ".centre");
        if (col.shape == GRASS_COLLIDER_CAPSULE) {
            if (!c.contains("end")) throw std::runtime_error(quoted(name) + " is a capsule: it needs an \"end\"");
            col.end = read_path(c["end"], name + ".end");
        } else if (c.contains("end")) {
            throw std::runtime_error(quoted(name) + " is a sphere: \"end\" is a capsule's key");
        }
        r->colliders.push_back(col);
    }
}

void read_mechanics(const json& m, Responsive* r) {
    check_keys(m, "patch.mechanics",
               {"stiffness", "mass", "wind_response", "trample_depth", "recovery_time", "variation"});
    r->mechanics_given = true;
    grass_blade_mechanics& d = r->mechanics;
    const std::pair<const char*, float*> fields[] = {
        {"stiffness", &d.stiffness},         {"mass", &d.mass},
        {"wind_response", &d.wind_response}, {"trample_depth", &d.trample_depth},
        {"recovery_time", &d.recovery_time}, {"variation", &d.variation}};
    for (const auto& [key, value] : fields) read_named(m, key, "patch.mechanics", value);
}

} // namespace

void read_responsive(const json& scene, Responsive* out) {
    Responsive r = *out; // all or nothing: *out stays as it was when a key is refused
    if (scene.contains("wind")) read_wind(object(scene["wind"], "wind"), &r);
    if (scene.contains("interaction")) read_interaction(object(scene["interaction"], "interaction"), &r);
    if (scene.contains("colliders")) read_colliders(scene["colliders"], &r);
    if (scene.contains("patch") && scene["patch"].contains("mechanics"))
        read_mechanics(object(scene["patch"]["mechanics"], "patch.mechanics"), &r);
    *out = r;
}

} // namespace grass_sample
