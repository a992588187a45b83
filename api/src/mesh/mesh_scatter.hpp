// Blades scattered on a host's mesh (jahrmann2017 4): as many as the surface's area and the
// density ask, single blades uniformly at random by area, or tufts whose centres keep a
// minimum distance (Poisson-disk sampling) with their blades around them; each blade with its
// root, up, UV, facing and density threshold, grouped into patches for culling (mesh_patches).
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/log.hpp"
#include "mesh/mesh_patches.hpp"
#include "mesh/mesh_surface.hpp"
#include "patch/density_threshold.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

enum class MeshSeeding : uint32_t {
    kSingleBlades = 0, // uniformly at random by area: even cover, natural clumping
    kTufts = 1,        // Poisson-disk tuft centres, blades at random within a radius of each
};

struct MeshScatterParams {
    MeshSeeding seeding = MeshSeeding::kSingleBlades;
    double density = 100.0;         // blades per square metre of surface (world units), (0, 1e5]
    uint32_t patch_blades = 1024;   // blades per patch, [64, 16384]
    double tuft_min_distance = 0.2; // tufts: metres between tuft centres (a chord), (0, 1e4]
    double tuft_radius = 0.05;      // tufts: metres from its centre to a blade, in its triangle's plane, [0, 1e4]
    uint32_t blades_per_tuft = 8;   // tufts: [1, 4096]
    ThresholdParams thresholds;     // uniform; or clustered, over the mesh's UVs (needs UVs)
    uint64_t seed = 1;              // same seed, mesh and params: same bytes
};

// The most blades one mesh scatters.
constexpr uint64_t kMaxMeshBlades = uint64_t{1} << 26;

struct MeshScatter {
    explicit MeshScatter(HostAllocator* host)
        : blades(StlAllocator<MeshBlade>(host)), patches(StlAllocator<MeshPatch>(host)),
          tuft_centres(StlAllocator<float>(host)) {}
    Vector<MeshBlade> blades;   // patch after patch, each in its prefix order
    Vector<MeshPatch> patches;  // blades.size() / patch_blades of them
    Vector<float> tuft_centres; // tufts: 3 floats per tuft, mesh space; MeshBlade::tuft indexes them
    uint32_t patch_blades = 0;
};

// The tangent frame about a unit normal n (Duff et al. 2017, "Building an orthonormal basis,
// revisited"): a blade's facing angle runs from `tangent` towards `bitangent`.
void orthonormal_basis(const double n[3], double tangent[3], double bitangent[3]);

// Scatters blades on `surface`. The count is round(area * density / patch_blades) patches of
// patch_blades blades (at least one patch). Refused, naming the argument and the value and
// leaving `out` as it was: parameters out of range, more than kMaxMeshBlades blades, the
// clustered thresholds on a mesh without UVs, and tufts whose minimum distance lets fewer
// tufts fit on the surface than the count needs.
grass_result scatter_mesh_blades(Log* log, const char* fn, const MeshSurface& surface, const MeshScatterParams& params,
                                 MeshScatter* out);

} // namespace grass
