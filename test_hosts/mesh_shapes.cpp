#include "mesh_shapes.hpp"

namespace grass_host {

HostMesh box_mesh(const char* name, const double low[3], const double high[3], const float color[3]) {
    HostMesh m;
    m.name = name;
    for (int c = 0; c < 3; ++c) {
        m.origin[c] = low[c];
        m.color[c] = color[c];
    }
    const float size[3] = {float(high[0] - low[0]), float(high[1] - low[1]), float(high[2] - low[2])};
    // Each face: its axis, its side (0 low, 1 high); four corners in the other two axes.
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const uint32_t first = m.vertex_count();
            for (int k = 0; k < 4; ++k) {
                float p[3] = {0.0f, 0.0f, 0.0f}, n[3] = {0.0f, 0.0f, 0.0f};
                p[axis] = side ? size[axis] : 0.0f;
                p[a] = (k & 1) ? size[a] : 0.0f;
                p[b] = (k & 2) ? size[b] : 0.0f;
                n[axis] = side ? 1.0f : -1.0f;
                m.vertices.insert(m.vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2]});
            }
            for (uint32_t i : {0u, 1u, 2u, 2u, 1u, 3u}) m.indices.push_back(first + i);
        }
    }
    return m;
}

void add_tree(std::vector<HostMesh>* meshes, double x, double z, double trunk_height, double crown) {
    const float bark[3] = {0.12f, 0.07f, 0.03f}, leaves[3] = {0.05f, 0.16f, 0.04f};
    const double trunk_low[3] = {x - 0.15, 0.0, z - 0.15}, trunk_high[3] = {x + 0.15, trunk_height, z + 0.15};
    meshes->push_back(box_mesh("trunk", trunk_low, trunk_high, bark));
    const double h = 0.5 * crown;
    const double crown_low[3] = {x - h, trunk_height, z - h}, crown_high[3] = {x + h, trunk_height + crown, z + h};
    meshes->push_back(box_mesh("crown", crown_low, crown_high, leaves));
}

} // namespace grass_host
