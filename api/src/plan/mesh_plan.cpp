#include "plan/mesh_plan.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

uint32_t mesh_prefix_blades(double distance, uint32_t patch_blades) {
    if (!(distance <= kMeshNoBladesDistance)) return 0;
    if (distance <= kMeshAllBladesDistance) return patch_blades;
    const double share = (kMeshAllBladesDistance / distance) * (kMeshAllBladesDistance / distance);
    return std::min(patch_blades, static_cast<uint32_t>(std::ceil(patch_blades * share)));
}

uint64_t plan_mesh_field(uint32_t slot, const MeshField& mesh, const double origin[3], const double lod_origin[3],
                         const Frusta& frusta, Vector<MeshPatchDraw>* out) {
    uint64_t planned = 0;
    const uint32_t per_patch = mesh.scatter.patch_blades;
    for (size_t p = 0; p < mesh.bounds.size(); ++p) {
        const MeshPatchBounds& b = mesh.bounds[p];
        // The distance test first (cheap): from the lod origin to the box's nearest point.
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double gap = std::max(0.0, std::fabs(lod_origin[c] - b.centre[c]) - b.half[c]);
            d2 += gap * gap;
        }
        const uint32_t count = mesh_prefix_blades(std::sqrt(d2), per_patch);
        if (count == 0) continue;
        double corners[8][3];
        for (int k = 0; k < 8; ++k) {
            for (int c = 0; c < 3; ++c) {
                const double sign = ((k >> c) & 1) ? 1.0 : -1.0;
                corners[k][c] = b.centre[c] + sign * b.half[c] - origin[c];
            }
        }
        if (!frusta.box_may_be_visible(corners)) continue;
        out->push_back(MeshPatchDraw{slot, mesh.scatter.patches[p].first_blade, count});
        planned += count;
    }
    return planned;
}

} // namespace grass
