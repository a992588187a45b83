// A mesh of the host's own scene (terrain, rocks, buildings): what an engine draws around
// grass. Plain data, filled by a scene loader (tools/scene/gltf_scene.hpp) and drawn by the
// hosts' mesh drawers (mesh_drawer_gl.hpp, mesh_drawer_vk.hpp), simply lit, into the depth
// buffer grass shares.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grass_host {

struct HostMesh {
    std::string name;
    // World position (metres) the vertices are relative to: drawn camera-relative, so the
    // offset from the camera is taken in double and the vertices stay small floats.
    double origin[3] = {0.0, 0.0, 0.0};
    // Interleaved per vertex: position x, y, z (metres, relative to origin), normal x, y, z.
    std::vector<float> vertices;
    std::vector<uint32_t> indices;       // triangle list, each below vertices.size() / 6
    float color[3] = {0.5f, 0.5f, 0.5f}; // linear albedo: Lambert + ambient
    static constexpr uint32_t kFloatsPerVertex = 6;
    uint32_t vertex_count() const { return static_cast<uint32_t>(vertices.size() / kFloatsPerVertex); }
};

} // namespace grass_host
