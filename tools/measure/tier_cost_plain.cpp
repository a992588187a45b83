// grass-measure tier-cost without --maps or --features: 1024 cells drawn by each tier alone,
// then by the volume (8 slices) and image tiers in macro-cells of up to 2, 4, 8 and 16 cells a
// side; the median frame, and per basic cell the frame minus the empty one, in wall and in CPU
// time. --single: the first, third and fifth rows only (kSingleTiers); --tier: one tier's rows.
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <cstdio>
#include <cstring>
#include <iterator>
#include <vector>

namespace grass_measure {
namespace tier_cost {

int run_plain(Rig& rig) {
    const Setup setups[] = {
        {"geometry", GRASS_TIER_GEOMETRY, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
        {"volume, 2 slices", GRASS_TIER_VOLUME, 2, 1},
        {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1},
        {"image", GRASS_TIER_IMAGE, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 2},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 4},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 8},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 16},
        {"image", GRASS_TIER_IMAGE, 0, 2},
        {"image", GRASS_TIER_IMAGE, 0, 4},
        {"image", GRASS_TIER_IMAGE, 0, 8},
        {"image", GRASS_TIER_IMAGE, 0, 16},
    };
    const Options& o = rig.options();
    const std::vector<Setup> rows = o.single ? std::vector<Setup>(std::begin(kSingleTiers), std::end(kSingleTiers))
                                             : std::vector<Setup>(std::begin(setups), std::end(setups));
    grass_context* ctx = rig.ctx();
    std::printf("grass-tier-cost: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU %.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | macro-cells up to | instances | frame (ms) | per basic cell (us) | CPU per basic cell (us) "
                "|\n|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        std::vector<double> cpu;
        const double ms = grass_sample::median_high(rig.frame_times(o.frames, nullptr, &cpu));
        const grass_frame_stats stats = rig.frame_stats();
        std::printf("| %s | %u | %llu | %.1f | %.1f | %.1f |\n", s.name, s.macro,
                    static_cast<unsigned long long>(stats.instances[s.kind]), ms,
                    1000.0 * (ms - rig.empty_ms()) / 1024.0,
                    1000.0 * (grass_sample::median_high(cpu) - rig.empty_cpu_ms()) / 1024.0);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
