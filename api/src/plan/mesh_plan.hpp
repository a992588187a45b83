// The frame plan of a mesh field (jahrmann2017 6.1-6.2): each patch of blades culled by its
// world box against the view's frusta, and the distance test, which keeps the first blades of
// a patch (a prefix, spread over the whole patch by mesh_patches' order): every blade up to
// kMeshAllBladesDistance, then a share falling as the square of the distance (a blade's
// projected area falls so; the covered fraction of a pixel stays about the same), none beyond
// kMeshNoBladesDistance.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"
#include "mesh/mesh_field.hpp"
#include "plan/view_culling.hpp"

#include <cstdint>

namespace grass {

// Metres from the lod origin to a patch's nearest point up to which it draws every blade.
constexpr double kMeshAllBladesDistance = 15.0;
// Metres beyond which a mesh patch draws no blade: its share has fallen to (15/60)^2 = 1/16.
constexpr double kMeshNoBladesDistance = 60.0;

// The blades of a patch of `patch_blades` drawn at `distance` metres (its nearest point):
// all up to kMeshAllBladesDistance, then ceil(patch_blades * (kMeshAllBladesDistance /
// distance)^2), 0 beyond kMeshNoBladesDistance.
uint32_t mesh_prefix_blades(double distance, uint32_t patch_blades);

// Appends to `out` the patches of `mesh` (the field in `slot`) that meet `frusta` (positions
// relative to `origin`, the plan's origin) with the blades each draws, measured from
// `lod_origin` (world); returns the blades planned.
uint64_t plan_mesh_field(uint32_t slot, const MeshField& mesh, const double origin[3], const double lod_origin[3],
                         const Frusta& frusta, Vector<MeshPatchDraw>* out);

} // namespace grass
