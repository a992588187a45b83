// A glTF 2.0 scene (.gltf or .glb, read by tinygltf) made into the tools' Scene:
// the terrain mesh becomes the field (its extent, a height map and a density map rasterised
// from the mesh), every mesh becomes a host mesh drawn around grass, the first perspective
// camera the scene's camera, and nodes marked as colliders a list of collider shapes.
// The convention (node names, `extras`, units, axes) is in docs/gltf.md.
//
// Hostile files are refused with an error naming the file, the object and the value, never
// a crash: every index, count, byte range and number is checked before use.
#pragma once

#include "scene.hpp"

#include <string>
#include <vector>

namespace grass_sample {

// A collider shape from a node marked `"extras": {"grass": {"role": "collider", ...}}`, in
// world space. Grass has no colliders yet: the sample tools list them.
struct GltfCollider {
    enum class Shape { sphere, capsule };
    Shape shape = Shape::sphere;
    std::string node;              // the node's name, or "node N"
    double a[3] = {0.0, 0.0, 0.0}; // sphere: its centre; capsule: one end of its segment (m)
    double b[3] = {0.0, 0.0, 0.0}; // capsule: the other end (a sphere: its centre again)
    double radius = 0.0;           // metres
};

// What the loader found besides the Scene.
struct GltfInfo {
    std::vector<GltfCollider> colliders;
    std::string camera;                     // the camera node's name; empty: the file has none
    std::string terrain;                    // the terrain nodes' names, comma-separated
    uint32_t map_width = 0, map_height = 0; // the height and density maps' texels
    uint64_t terrain_triangles = 0;
    uint64_t mesh_triangles = 0;    // of every host mesh, terrain included
    std::vector<std::string> notes; // what the file has and the loader leaves out
};

// True for a path ending in .gltf or .glb (any case).
bool is_gltf_path(const std::string& path);

// Reads a glTF scene over *scene (keeping its patch, light and image settings): field,
// maps, camera and host meshes; the host's flat ground is turned off (the terrain mesh is
// the ground). False and *error ("FILE: what is wrong") on a bad file; *scene is then
// unchanged.
bool load_gltf_scene(const std::string& path, Scene* scene, GltfInfo* info, std::string* error);

} // namespace grass_sample
