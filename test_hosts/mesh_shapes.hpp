// Simple host meshes (host_mesh.hpp) for the tests and figures that need the host's own
// scene around grass: a building as a box, a tree as a trunk and a crown.
#pragma once

#include "host_mesh.hpp"

namespace grass_host {

// An axis-aligned box from `low` to `high` (world metres), its origin at `low`: 24 vertices
// with face normals, 12 triangles.
HostMesh box_mesh(const char* name, const double low[3], const double high[3], const float color[3]);

// A tree standing at (x, 0, z): a trunk box `trunk_height` tall and a crown box `crown`
// metres wide and tall on it.
void add_tree(std::vector<HostMesh>* meshes, double x, double z, double trunk_height, double crown);

} // namespace grass_host
