// Reading a frame plan in tests: instances per tier, cells they cover.
#pragma once

#include "context/context.hpp"

#include <cmath>
#include <vector>

struct PlannedInstance {
    grass_tier_kind kind;
    uint32_t tier;
    uint64_t x0, z0, count_x, count_z; // cells, recovered from map uv and size
    bool field_edge;                   // a volume tier standing in for the image tiers at the border
};

// Every planned instance's cell range.
inline std::vector<PlannedInstance> planned_instances(const grass_context* ctx, uint32_t, uint32_t) {
    std::vector<PlannedInstance> out;
    for (const auto& d : ctx->plan.draws) {
        for (uint32_t k = 0; k < d.instance_count; ++k) {
            const grass::TierInstance& inst = ctx->plan.instances[d.first_instance + k];
            PlannedInstance p;
            p.kind = d.kind;
            p.tier = d.tier;
            p.field_edge = inst.terrain[2] != 0.0f;
            p.x0 = inst.cell[0];
            p.z0 = inst.cell[1];
            p.count_x = inst.count[0];
            p.count_z = inst.count[1];
            out.push_back(p);
        }
    }
    return out;
}
