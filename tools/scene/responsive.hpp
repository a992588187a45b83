// Responsive grass in the sample scenes (docs/responsive.md): the wind and its sources, the
// interaction map, the blade mechanics and colliders that move along paths, evaluated at a
// frame's time and handed to grass (grass_set_wind, grass_set_colliders, ...).
#pragma once

#include <grass/grass.h>

#include "host_mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace grass_sample {

// A point that moves: keyframes (seconds, world metres), linear between them, held before
// the first and after the last. One keyframe: a point that stays.
struct Path {
    std::vector<double> times;
    std::vector<std::array<double, 3>> points;

    static Path fixed(const double p[3]);
    // From `from` at time `start` to `to` at `speed` m/s, then held there.
    static Path line(const double from[3], const double to[3], double speed, double start);
    void at(double t, double out[3]) const;
    bool empty() const { return times.empty(); }
};

// A collider of the scene: a sphere (centre) or a capsule (centre and end: its axis).
struct SceneCollider {
    grass_collider_shape shape = GRASS_COLLIDER_SPHERE;
    float radius = 0.0f;
    Path centre, end;
};

// A wind source whose position may move (a helicopter's downwash).
struct SceneWindSource {
    grass_wind_source source{}; // its position comes from `path`
    Path path;
};

struct Responsive {
    bool wind_given = false; // grass_set_wind is called (else grass's default: no wind)
    grass_wind_desc wind = grass_default_wind_desc();
    std::vector<SceneWindSource> sources;
    bool interaction_given = false;
    grass_interaction_desc interaction = grass_default_interaction_desc();
    bool mechanics_given = false; // the patch's, set with grass_set_blade_mechanics
    grass_blade_mechanics mechanics = grass_default_blade_mechanics();
    std::vector<SceneCollider> colliders;

    // Whether any of it is given (else the frame is still grass, as before issue 13).
    bool any() const { return wind_given || interaction_given || mechanics_given || !colliders.empty(); }
};

// The colliders at time t. Velocity: the motion over the last `step` seconds (> 0), so the
// interaction pass sweeps each collider over the path it took since the previous frame; a
// capsule takes the velocity of its lower end (along +y), the one that touches the grass.
std::vector<grass_collider> colliders_at(const Responsive& r, double t, double step);

// What the host draws of the colliders and wind sources at time t: a red ball for a sphere,
// a row of dark beads along a capsule's axis (a leg: a capsule's orientation changes, a
// bead's does not), a grey body of 0.8 m radius at a POINT source (a helicopter); grass-render
// moves them every frame (grass_host::Host::move_mesh) to moving_mesh_origins.
std::vector<grass_host::HostMesh> moving_meshes(const Responsive& r, double t);
// How many meshes moving_meshes makes, counted without making them (a capsule is up to 64
// beads); grass-render refuses more than kMaxMovingMeshes before it builds any.
size_t moving_mesh_count(const Responsive& r);
constexpr size_t kMaxMovingMeshes = 4096;
// The origins of moving_meshes' meshes at time t, in their order.
std::vector<std::array<double, 3>> moving_mesh_origins(const Responsive& r, double t);

// The wind sources at time t.
std::vector<grass_wind_source> wind_sources_at(const Responsive& r, double t);

// Hands what is given to grass for a frame at time t (a step of `step` seconds since the
// previous one): the mechanics and interaction map once (first = true), then the wind (when
// its sources move or first) and the colliders every frame. The first failing result.
grass_result apply_responsive(grass_context* ctx, grass_patch_id patch, const Responsive& r, double t, double step,
                              bool first);

// Command-line forms (grass-render --wind, --collider); false and *error naming the text.
// "DX,DZ,SPEED[,GUST]": the mean wind across y (m/s) and gust_strength.
bool parse_wind(const std::string& text, grass_wind_desc* wind, std::string* error);
// "sphere:X,Y,Z,R[,VX,VY,VZ]" or "capsule:AX,AY,AZ,BX,BY,BZ,R[,VX,VY,VZ]": where it is at
// `start` and the velocity it keeps (m/s) until `end`.
bool parse_collider(const std::string& text, double start, double end, SceneCollider* out, std::string* error);

} // namespace grass_sample
