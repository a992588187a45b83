// Blades on a mesh grouped into patches for culling (jahrmann2017 6.1-6.2): nearby blades,
// an equal count in every patch, each patch's bounding box, and within a patch an order whose
// every prefix is spread over the whole patch, so that the distance test, which draws the
// first k blades of a patch, thins it evenly instead of baring a corner (jahrmann 6.2).
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

// One blade scattered on a mesh. Mesh space: the renderer applies the mesh's transform.
struct MeshBlade {
    float root[3];     // on the surface (single blades) or in its triangle's plane (a tuft's blades)
    float up[3];       // unit: the surface's normal interpolated at the root (a tuft's: at its centre)
    float uv[2];       // the mesh's UV there (a tuft's: at its centre), for the design maps; (0, 0) without UVs
    float facing;      // radians about `up`, from the tangent of orthonormal_basis (mesh_scatter.hpp)
    float threshold;   // density threshold in (0, 1]: drawn where the density is at least this
    uint32_t triangle; // the host's triangle (first index / 3) the blade grows from
    uint32_t tuft;     // its tuft, or UINT32_MAX for a single blade
};

struct MeshPatch {
    uint32_t first_blade = 0;        // blades [first_blade, first_blade + blades per patch)
    float bounds_min[3] = {0, 0, 0}; // the roots' box, mesh space (the blades' height not included)
    float bounds_max[3] = {0, 0, 0};
};

// Sorts `blades` (a multiple of `patch_blades`) along a k-d tree of their roots, split at
// medians and at whole patches, so that each patch of `patch_blades` blades is a compact
// subtree; orders each patch for its prefixes (its blades along the tree taken in bit-
// reversed order: any prefix takes about one blade from each small subtree) and writes each
// patch's box.
void group_into_patches(Vector<MeshBlade>& blades, uint32_t patch_blades, Vector<MeshPatch>& patches);

} // namespace grass
