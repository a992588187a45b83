// Reading a frame plan in tests: instances per tier, cells they cover.
#pragma once

#include "context.hpp"

#include <cmath>
#include <vector>

struct PlannedInstance {
    grass_tier_kind kind;
    uint32_t tier;
    uint64_t x0, z0, count_x, count_z; // cells, recovered from map uv and size
};

// Recovers every planned instance's cell range (map uv x cells gives the first cell).
inline std::vector<PlannedInstance> planned_instances(const grass_context* ctx, uint32_t cells_x, uint32_t cells_z) {
    std::vector<PlannedInstance> out;
    for (const auto& d : ctx->plan.draws) {
        for (uint32_t k = 0; k < d.instance_count; ++k) {
            const grass::TierInstance& inst = ctx->plan.instances[d.first_instance + k];
            PlannedInstance p;
            p.kind = d.kind;
            p.tier = d.tier;
            p.x0 = static_cast<uint64_t>(std::llround(double(inst.map_uv[0]) * cells_x));
            p.z0 = static_cast<uint64_t>(std::llround(double(inst.map_uv[1]) * cells_z));
            p.count_x = static_cast<uint64_t>(inst.cells[0]);
            p.count_z = static_cast<uint64_t>(inst.cells[1]);
            out.push_back(p);
        }
    }
    return out;
}
