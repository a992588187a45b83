#include "plan/blade_window.hpp"

#include "plan/field.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

constexpr uint32_t kEntryWords = 4;

// The table of `field_slot` in `window`, or nullptr.
const BladeWindowField* find_field(const BladeWindowPlan& window, uint32_t field_slot) {
    for (const BladeWindowField& f : window.fields) {
        if (f.field_slot == field_slot) return &f;
    }
    return nullptr;
}

void set_table(FieldUniforms* u, const BladeWindowField& f) {
    u->transition[1] = static_cast<float>(f.side);
    u->transition[2] = static_cast<float>(f.first_entry);
}

bool responsive_geometry(const TierDraw& draw) {
    return draw.kind == GRASS_TIER_GEOMETRY && (draw.features & (kFeatureWind | kFeatureInteraction)) != 0;
}

// Whether `window` holds the poses of every instance of `draw`: each cell's entry is that
// cell's (a field's draws share its patch, so the entry's blades are the draw's).
bool holds_every_cell(const BladeWindowPlan& window, const FramePlan& plan, const TierDraw& draw) {
    const BladeWindowField* f = find_field(window, draw.field_slot);
    if (!f || f->side == 0 || draw.instance_count == 0) return false;
    for (uint32_t i = 0; i < draw.instance_count; ++i) {
        const TierInstance& instance = plan.instances[draw.first_instance + i];
        const uint32_t* entry =
            window.table.data() +
            (size_t(f->first_entry) + size_t(instance.cell[1] % f->side) * f->side + instance.cell[0] % f->side) *
                kEntryWords;
        if (entry[0] != instance.cell[0] || entry[1] != instance.cell[1]) return false;
    }
    return true;
}

// Gives the window variant (kFeatureBladeWindow) to the responsive geometry draws of `plan`
// whose cells `window` all holds; the others keep the per-vertex variant.
void mark_held_draws(const BladeWindowPlan& window, FramePlan* plan) {
    for (TierDraw& draw : plan->draws) {
        draw.features &= ~kFeatureBladeWindow;
        if (responsive_geometry(draw) && holds_every_cell(window, *plan, draw)) {
            draw.features |= kFeatureBladeWindow;
        }
        draw.uniforms.tiling[3] = draw.features;
    }
}

} // namespace

uint32_t blade_window_side(double reach, double cell_size, uint32_t cells_x, uint32_t cells_z) {
    const uint32_t field_side = std::max(std::max(cells_x, cells_z), 1u);
    const uint32_t cap = std::min(field_side, kMaxBladeWindowSide);
    if (!(cell_size > 0.0) || !(reach >= 0.0) || !std::isfinite(reach / cell_size)) return cap;
    const double side = 2.0 * std::ceil(reach / cell_size) + 2.0;
    return side >= double(cap) ? cap : std::max(static_cast<uint32_t>(side), 1u);
}

void plan_blade_window(FramePlan* plan_out, bool enabled, const HandlePool<Patch>& patches) {
    FramePlan& plan = *plan_out;
    BladeWindowPlan& window = plan.blade_window;
    window.clear();
    if (!enabled || (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0) return; // debug boxes pose no blade
    uint64_t slots = 0;
    for (uint32_t d = 0; d < plan.draws.size(); ++d) {
        TierDraw& draw = plan.draws[d];
        if (!responsive_geometry(draw) || draw.instance_count == 0) continue;
        if (draw.instance_count > kMaxBladeWindowInstances) continue; // computed in the vertex shader
        const Patch* patch = patches.get(draw.patch_slot);
        const uint32_t blades = patch ? static_cast<uint32_t>(patch->data.blade_curves.size() / 8) : 0;
        if (blades == 0) continue;
        const uint64_t bytes = uint64_t(draw.instance_count) * blades * kBladeWindowPoseBytes;
        if (window.pose_bytes + bytes > kMaxBladeWindowPoseBytes) continue; // computed in the vertex shader
        const BladeWindowField* table = find_field(window, draw.field_slot);
        if (!table) { // the field's first responsive geometry draw: its table covers its geometry tiers' reach
            const FieldUniforms& u = draw.uniforms;
            double reach = 0.0;
            for (const TierDraw& other : plan.draws) {
                if (other.field_slot != draw.field_slot || other.kind != GRASS_TIER_GEOMETRY) continue;
                const uint32_t t = std::min<uint32_t>(other.tier, GRASS_MAX_TIERS - 1);
                reach = std::max(reach, double(u.bands[t][1]) + double(u.bands[t][3]));
            }
            BladeWindowField f;
            f.field_slot = draw.field_slot;
            f.side = blade_window_side(reach, double(u.field_up[3]), static_cast<uint32_t>(u.map_params[2]),
                                       static_cast<uint32_t>(u.map_params[3]));
            f.first_entry = static_cast<uint32_t>(window.table.size() / kEntryWords);
            window.table.resize(window.table.size() + size_t(f.side) * f.side * kEntryWords, kNoWindowEntry);
            window.fields.push_back(f);
            table = &window.fields.back();
        }
        // Each instance takes a slot; the table points at it unless another cell of the
        // frame holds its entry (a reach wider than the table), which the vertex shader
        // then poses itself.
        const uint32_t first_slot = static_cast<uint32_t>(slots);
        for (uint32_t i = 0; i < draw.instance_count; ++i) {
            const TierInstance& instance = plan.instances[draw.first_instance + i];
            const uint32_t side = table->side;
            uint32_t* entry = window.table.data() + (size_t(table->first_entry) +
                                                     size_t(instance.cell[1] % side) * side + instance.cell[0] % side) *
                                                        kEntryWords;
            if (entry[0] != kNoWindowEntry) continue;
            entry[0] = instance.cell[0];
            entry[1] = instance.cell[1];
            entry[2] = first_slot + i;
            entry[3] = blades;
        }
        slots += draw.instance_count;
        window.pose_bytes += bytes;
        draw.uniforms.tiers[3] = first_slot;
        draw.uniforms.transition[3] = static_cast<float>(draw.first_instance);
        window.dispatches.push_back(BladeWindowDispatch{d, first_slot});
    }
    for (TierDraw& draw : plan.draws) {
        if ((draw.features & (kFeatureWind | kFeatureInteraction)) == 0 || draw.kind != GRASS_TIER_GEOMETRY) continue;
        if (const BladeWindowField* f = find_field(window, draw.field_slot)) set_table(&draw.uniforms, *f);
    }
    mark_held_draws(plan.blade_window, &plan);
}

void apply_blade_window(const FramePlan& first, FramePlan* plan) {
    if (first.blade_window.dispatches.empty()) return;
    for (TierDraw& draw : plan->draws) {
        if (!responsive_geometry(draw)) continue;
        if (const BladeWindowField* f = find_field(first.blade_window, draw.field_slot)) set_table(&draw.uniforms, *f);
    }
    mark_held_draws(first.blade_window, plan);
}

} // namespace grass
