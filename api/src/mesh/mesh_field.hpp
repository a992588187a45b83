// A mesh field (jahrmann2017 4): the blades scattered on a host's mesh (mesh_scatter), kept
// with what the frame planner culls them by (each patch's world box, grown by a blade's
// reach) and what a blade draw reads per blade (MeshBladeGpu: root, up, facing, threshold,
// UV and the local density), in the mesh's space; the renderer applies the transform.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/log.hpp"
#include "mesh/mesh_scatter.hpp"
#include "mesh/mesh_surface.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// One blade as a blade draw reads it: three vec4 of a std430 buffer, shared by both backends.
struct MeshBladeGpu {
    float root_threshold[4]; // xyz: root, mesh space; w: density threshold in (0, 1]
    float up_facing[4];      // xyz: unit up (the interpolated normal), mesh space; w: facing, radians about up
    float uv_density[4];     // xy: the mesh's UV at the root; z: the local density 0..1 (per-vertex source, else 1);
                             // w: the patch blade whose shape it takes (an integer below 2^24)
};
static_assert(sizeof(MeshBladeGpu) == 48, "MeshBladeGpu must match the shaders' std430 layout");

// A patch of blades as the planner culls it: its world box, every blade's reach included.
struct MeshPatchBounds {
    double centre[3]; // world
    double half[3];   // half extents along the world axes
};

struct MeshField {
    explicit MeshField(HostAllocator* host)
        : scatter(host), blade_density(StlAllocator<float>(host)), bounds(StlAllocator<MeshPatchBounds>(host)) {}
    MeshScatter scatter;
    Vector<float> blade_density;    // per blade, 0..1: the per-vertex density at its root (1 otherwise)
    Vector<MeshPatchBounds> bounds; // per patch of scatter.patches
    double transform[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // mesh to world, column-major
    double reach = 0.0;        // metres a blade may reach from its root (its height and lean)
    float patch_scale = 0.25f; // metres per patch unit
    grass_mesh_density_source density_source = GRASS_MESH_DENSITY_UNIFORM;
};

// Scatters `params` on `surface` into `out` (empty, made with the context's allocator):
// the blades, the per-vertex density at each root when `vertex_density` (one value a vertex,
// packed) is given, and each patch's world box grown by `reach` metres. Refusals as
// scatter_mesh_blades's; `out` is left as it was then.
grass_result build_mesh_field(Log* log, const char* fn, const MeshSurface& surface, const MeshScatterParams& params,
                              const float* vertex_density, double reach, MeshField* out);

// The blades as the GPU reads them, `out` holding one MeshBladeGpu per blade; each blade
// takes the shape of patch blade (its index modulo `patch_blade_count`).
void write_mesh_blades(const MeshField& field, uint32_t patch_blade_count, MeshBladeGpu* out);

} // namespace grass
