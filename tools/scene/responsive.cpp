#include "responsive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace grass_sample {

Path Path::fixed(const double p[3]) {
    Path path;
    path.times = {0.0};
    path.points = {{p[0], p[1], p[2]}};
    return path;
}

Path Path::line(const double from[3], const double to[3], double speed, double start) {
    const double d = std::sqrt((to[0] - from[0]) * (to[0] - from[0]) + (to[1] - from[1]) * (to[1] - from[1]) +
                               (to[2] - from[2]) * (to[2] - from[2]));
    Path path = fixed(from);
    path.times[0] = start;
    if (d > 0.0 && speed > 0.0) {
        path.times.push_back(start + d / speed);
        path.points.push_back({to[0], to[1], to[2]});
    }
    return path;
}

void Path::at(double t, double out[3]) const {
    if (times.empty()) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    // The first keyframe after t; before the first and after the last the point is held.
    const size_t next = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    if (next == 0 || next == times.size()) {
        const auto& p = points[next == 0 ? 0 : times.size() - 1];
        out[0] = p[0], out[1] = p[1], out[2] = p[2];
        return;
    }
    const double s = (t - times[next - 1]) / (times[next] - times[next - 1]);
    for (int k = 0; k < 3; ++k) out[k] = points[next - 1][k] + (points[next][k] - points[next - 1][k]) * s;
}

namespace {

void velocity_of(const Path& path, double t, double step, float out[3]) {
    double now[3], before[3];
    path.at(t, now);
    path.at(t - step, before);
    for (int k = 0; k < 3; ++k) out[k] = static_cast<float>((now[k] - before[k]) / step);
}

} // namespace

std::vector<grass_collider> colliders_at(const Responsive& r, double t, double step) {
    std::vector<grass_collider> out;
    for (const SceneCollider& c : r.colliders) {
        grass_collider g{};
        g.shape = c.shape;
        g.radius = c.radius;
        c.centre.at(t, g.center);
        const Path* lower = &c.centre;
        if (c.shape == GRASS_COLLIDER_CAPSULE) {
            c.end.at(t, g.end);
            if (g.end[1] < g.center[1]) lower = &c.end;
        }
        velocity_of(*lower, t, step, g.velocity);
        out.push_back(g);
    }
    return out;
}

namespace {

constexpr int kMaxBeads = 64;

// Beads along a capsule of axis length `length`: closer than half the radius, so they read as
// a tube.
int bead_count(double length, float radius) {
    const double spacing = 0.5 * std::max(double(radius), 1e-3);
    return std::clamp(int(std::ceil(length / spacing)) + 1, 2, kMaxBeads);
}

double distance(const double a[3], const double b[3]) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

grass_host::HostMesh sphere_mesh(float radius, const float albedo[3]) {
    constexpr int kRings = 12, kSegments = 20;
    constexpr double kPi = 3.14159265358979323846;
    grass_host::HostMesh m;
    m.name = "collider";
    std::copy(albedo, albedo + 3, m.color);
    for (int i = 0; i <= kRings; ++i) {
        const double polar = kPi * i / kRings;
        for (int j = 0; j <= kSegments; ++j) {
            const double azimuth = 2.0 * kPi * j / kSegments;
            const float n[3] = {float(std::sin(polar) * std::cos(azimuth)), float(std::cos(polar)),
                                float(std::sin(polar) * std::sin(azimuth))};
            for (int k = 0; k < 3; ++k) m.vertices.push_back(n[k] * radius);
            for (int k = 0; k < 3; ++k) m.vertices.push_back(n[k]);
        }
    }
    for (uint32_t i = 0; i < kRings; ++i) {
        for (uint32_t j = 0; j < kSegments; ++j) {
            const uint32_t a = i * (kSegments + 1) + j, b = a + kSegments + 1;
            m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    return m;
}

// Each collider's meshes: its count of beads (1 for a sphere), fixed at `t0`.
std::vector<int> beads_of(const Responsive& r, double t0) {
    std::vector<int> beads;
    for (const grass_collider& c : colliders_at(r, t0, 1.0))
        beads.push_back(c.shape == GRASS_COLLIDER_SPHERE ? 1 : bead_count(distance(c.center, c.end), c.radius));
    return beads;
}

} // namespace

constexpr float kBodyRadius = 0.8f; // a POINT source's body

std::vector<grass_host::HostMesh> moving_meshes(const Responsive& r, double t) {
    const float ball[3] = {0.55f, 0.06f, 0.04f}, leg[3] = {0.04f, 0.05f, 0.12f}, body[3] = {0.12f, 0.12f, 0.11f};
    std::vector<grass_host::HostMesh> out;
    const std::vector<int> beads = beads_of(r, 0.0);
    for (size_t i = 0; i < r.colliders.size(); ++i) {
        const bool sphere = r.colliders[i].shape == GRASS_COLLIDER_SPHERE;
        for (int k = 0; k < beads[i]; ++k) out.push_back(sphere_mesh(r.colliders[i].radius, sphere ? ball : leg));
    }
    for (const SceneWindSource& s : r.sources)
        if (s.source.kind == GRASS_WIND_SOURCE_POINT) out.push_back(sphere_mesh(kBodyRadius, body));
    const std::vector<std::array<double, 3>> origins = moving_mesh_origins(r, t);
    for (size_t i = 0; i < out.size(); ++i) std::copy(origins[i].begin(), origins[i].end(), out[i].origin);
    return out;
}

size_t moving_mesh_count(const Responsive& r) {
    size_t count = 0;
    for (int beads : beads_of(r, 0.0)) count += size_t(beads);
    for (const SceneWindSource& s : r.sources) count += s.source.kind == GRASS_WIND_SOURCE_POINT ? 1 : 0;
    return count;
}

std::vector<std::array<double, 3>> moving_mesh_origins(const Responsive& r, double t) {
    // A capsule's bead count is fixed (its length at time 0), so the meshes stay the same.
    const std::vector<int> beads = beads_of(r, 0.0);
    std::vector<std::array<double, 3>> out;
    const std::vector<grass_collider> colliders = colliders_at(r, t, 1.0);
    for (size_t i = 0; i < colliders.size(); ++i) {
        const grass_collider& c = colliders[i];
        for (int k = 0; k < beads[i]; ++k) {
            const double s = beads[i] > 1 ? double(k) / (beads[i] - 1) : 0.0; // a sphere: its centre
            out.push_back({c.center[0] + (c.end[0] - c.center[0]) * s, c.center[1] + (c.end[1] - c.center[1]) * s,
                           c.center[2] + (c.end[2] - c.center[2]) * s});
        }
    }
    for (const grass_wind_source& s : wind_sources_at(r, t))
        if (s.kind == GRASS_WIND_SOURCE_POINT) out.push_back({s.position[0], s.position[1], s.position[2]});
    return out;
}

std::vector<grass_wind_source> wind_sources_at(const Responsive& r, double t) {
    std::vector<grass_wind_source> out;
    for (const SceneWindSource& s : r.sources) {
        grass_wind_source w = s.source;
        s.path.at(t, w.position);
        out.push_back(w);
    }
    return out;
}

grass_result apply_responsive(grass_context* ctx, grass_patch_id patch, const Responsive& r, double t, double step,
                              bool first) {
    grass_result result = GRASS_SUCCESS;
    if (first && r.mechanics_given) result = grass_set_blade_mechanics(ctx, patch, &r.mechanics);
    if (result == GRASS_SUCCESS && first && r.interaction_given) result = grass_set_interaction(ctx, &r.interaction);
    const bool moving_sources = std::any_of(r.sources.begin(), r.sources.end(),
                                            [](const SceneWindSource& s) { return s.path.times.size() > 1; });
    if (result == GRASS_SUCCESS && r.wind_given && (first || moving_sources)) {
        const std::vector<grass_wind_source> sources = wind_sources_at(r, t);
        grass_wind_desc wind = r.wind;
        wind.sources = sources.empty() ? nullptr : sources.data();
        wind.source_count = static_cast<uint32_t>(sources.size());
        result = grass_set_wind(ctx, &wind);
    }
    if (result == GRASS_SUCCESS && !r.colliders.empty()) {
        const std::vector<grass_collider> colliders = colliders_at(r, t, step);
        result = grass_set_colliders(ctx, colliders.data(), static_cast<uint32_t>(colliders.size()));
    }
    return result;
}

namespace {

// Comma-separated finite numbers; false unless there are between min and max of them.
bool numbers(const std::string& text, size_t min, size_t max, std::vector<double>* out) {
    std::stringstream ss(text);
    std::string part;
    out->clear();
    while (std::getline(ss, part, ',')) {
        char* end = nullptr;
        const double v = std::strtod(part.c_str(), &end);
        if (part.empty() || end == part.c_str() || *end != '\0' || !std::isfinite(v)) return false;
        out->push_back(v);
    }
    return !text.empty() && text.back() != ',' && out->size() >= min && out->size() <= max;
}

} // namespace

bool parse_wind(const std::string& text, grass_wind_desc* wind, std::string* error) {
    std::vector<double> v;
    if (!numbers(text, 3, 4, &v)) {
        *error = "\"" + text + "\" is not DX,DZ,SPEED[,GUST]";
        return false;
    }
    if (v[0] == 0.0 && v[1] == 0.0) {
        *error = "\"" + text + "\": the direction DX,DZ is zero";
        return false;
    }
    wind->direction[0] = static_cast<float>(v[0]);
    wind->direction[1] = 0.0f;
    wind->direction[2] = static_cast<float>(v[1]);
    wind->speed = static_cast<float>(v[2]);
    if (v.size() == 4) wind->gust_strength = static_cast<float>(v[3]);
    return true;
}

bool parse_collider(const std::string& text, double start, double end, SceneCollider* out, std::string* error) {
    const auto colon = text.find(':');
    const std::string shape = text.substr(0, colon == std::string::npos ? 0 : colon);
    const bool capsule = shape == "capsule";
    std::vector<double> v;
    const size_t n = capsule ? 7 : 4; // the points and the radius
    if ((shape != "sphere" && !capsule) || !numbers(text.substr(colon + 1), n, n + 3, &v) ||
        (v.size() != n && v.size() != n + 3)) {
        *error = "\"" + text + "\" is not sphere:X,Y,Z,R[,VX,VY,VZ] or capsule:AX,AY,AZ,BX,BY,BZ,R[,VX,VY,VZ]";
        return false;
    }
    SceneCollider c;
    c.shape = capsule ? GRASS_COLLIDER_CAPSULE : GRASS_COLLIDER_SPHERE;
    c.radius = static_cast<float>(v[n - 1]);
    const double zero[3] = {0.0, 0.0, 0.0};
    const double* velocity = v.size() > n ? &v[n] : zero;
    auto moving = [&](const double* p) {
        const double to[3] = {p[0] + velocity[0] * (end - start), p[1] + velocity[1] * (end - start),
                              p[2] + velocity[2] * (end - start)};
        Path path = Path::fixed(p);
        path.times[0] = start;
        if (end > start) {
            path.times.push_back(end);
            path.points.push_back({to[0], to[1], to[2]});
        }
        return path;
    };
    c.centre = moving(&v[0]);
    if (capsule) c.end = moving(&v[3]);
    *out = c;
    return true;
}

} // namespace grass_sample
