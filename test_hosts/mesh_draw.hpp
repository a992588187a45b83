// What the mesh drawers (mesh_drawer_gl.hpp, mesh_drawer_vk.hpp) hand their shaders for one
// host mesh: the block of shaders/mesh_draw.glsl.
#pragma once

#include "host_mesh.hpp"

#include <grass/grass.h>

#include <cstddef>

namespace grass_host {

// std140 block / push constants `MeshDraw` (128 bytes: Vulkan's guaranteed push-constant size).
struct MeshDraw {
    float view_projection[16]; // projection * view rotation: camera-relative
    float offset[4];           // xyz: mesh origin - camera (m, taken in double); w: ambient red
    float albedo[4];           // rgb; w: ambient green
    float sun_direction[4];    // xyz: unit, towards the sun; w: ambient blue
    float sun_color[4];        // rgb; w: 1 = encode to sRGB in the shader (UNORM targets)
};
static_assert(sizeof(MeshDraw) == 128, "MeshDraw must fit Vulkan's 128 guaranteed push-constant bytes");

// The meshes a host draws (TargetDesc::meshes), as Host::move_mesh moves them between
// frames: a host object that moves (a ball that rolls). Both mesh drawers are such.
class MovableMeshes {
public:
    virtual ~MovableMeshes() = default;
    // Moves mesh `index` (of the drawer's list) to a new world origin; an index past the list
    // is ignored.
    virtual void set_origin(size_t index, const double origin[3]) = 0;
};

// projection * the view's rotation (its translation unused: everything is camera-relative).
void camera_relative_view_projection(const grass_view_desc& view, float out[16]);

// The block for `mesh` seen by `view` (its sun and ambient light).
MeshDraw make_mesh_draw(const grass_view_desc& view, const HostMesh& mesh, bool encode_srgb);

} // namespace grass_host
