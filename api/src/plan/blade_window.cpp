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

namespace {

// The blades of `draw`'s patch when view 0's window may hold its instances, else 0.
uint32_t window_blades(const TierDraw& draw, const HandlePool<Patch>& patches) {
    if (!responsive_geometry(draw) || draw.instance_count == 0) return 0;
    if (draw.instance_count > kMaxBladeWindowInstances) return 0; // computed in the vertex shader
    const Patch* patch = patches.get(draw.patch_slot);
    return patch ? static_cast<uint32_t>(patch->data.blade_curves.size() / 8) : 0;
}

// The slot `previous` gave the cell of `entry` (field `field_slot`), or kNoWindowEntry.
uint32_t previous_slot(const BladeWindowPlan& previous, uint32_t field_slot, const uint32_t* entry) {
    const BladeWindowField* f = find_field(previous, field_slot);
    if (!f || f->side == 0) return kNoWindowEntry;
    const uint32_t* was =
        previous.table.data() +
        (size_t(f->first_entry) + size_t(entry[1] % f->side) * f->side + entry[0] % f->side) * kEntryWords;
    return was[0] == entry[0] && was[1] == entry[1] ? was[2] : kNoWindowEntry;
}

// Gives each entry of the table its slot: the one its cell held at the last frame (same
// stride), else the lowest free one, marked entered in the work items.
void assign_slots(BladeWindowPlan* window_out, const BladeWindowPlan& previous, Vector<uint32_t>* used_out) {
    BladeWindowPlan& window = *window_out;
    Vector<uint32_t>& used = *used_out;
    const bool keep = previous.stride == window.stride;
    used.assign(keep ? previous.slots : 0, 0u);
    uint32_t held = 0;
    for (uint32_t f = 0; f < window.fields.size(); ++f) {
        const BladeWindowField& field = window.fields[f];
        for (uint32_t e = 0; e < field.side * field.side; ++e) {
            uint32_t* entry = window.table.data() + size_t(field.first_entry + e) * kEntryWords;
            if (entry[0] == kNoWindowEntry) continue;
            ++held;
            const uint32_t slot = keep ? previous_slot(previous, field.field_slot, entry) : kNoWindowEntry;
            entry[2] = slot < used.size() && used[slot] == 0 ? slot : kNoWindowEntry;
            if (entry[2] != kNoWindowEntry) used[entry[2]] = 1;
        }
    }
    // Kept slots may leave holes: past the byte cap, every cell starts afresh from slot 0.
    if (uint64_t(std::max<size_t>(used.size(), held)) * window.stride * kBladeWindowRecordBytes >
        kMaxBladeWindowPoseBytes) {
        used.clear();
        for (size_t w = 0; w < window.table.size(); w += kEntryWords) {
            if (window.table[w] != kNoWindowEntry) window.table[w + 2] = kNoWindowEntry;
        }
    }
    uint32_t next_free = 0;
    uint32_t slots = 0;
    for (size_t w = 0; w < window.table.size(); w += kEntryWords) {
        uint32_t* entry = window.table.data() + w;
        if (entry[0] == kNoWindowEntry) continue;
        if (entry[2] == kNoWindowEntry) {
            while (next_free < used.size() && used[next_free] != 0) ++next_free;
            entry[2] = next_free++ | kWindowSlotEntered; // the flag is cleared once the work items have it
        }
        slots = std::max(slots, (entry[2] & ~kWindowSlotEntered) + 1);
    }
    window.slots = slots;
    window.pose_bytes = uint64_t(slots) * window.stride * kBladeWindowRecordBytes;
}

} // namespace

void plan_blade_window(FramePlan* plan_out, bool enabled, const HandlePool<Patch>& patches,
                       const BladeWindowPlan& previous, Vector<uint32_t>* used) {
    FramePlan& plan = *plan_out;
    BladeWindowPlan& window = plan.blade_window;
    window.clear();
    if (!enabled || (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0) return; // debug boxes pose no blade
    for (const TierDraw& draw : plan.draws) window.stride = std::max(window.stride, window_blades(draw, patches));
    if (window.stride == 0) return;
    uint64_t held = 0; // instances with an entry of their own
    for (uint32_t d = 0; d < plan.draws.size(); ++d) {
        TierDraw& draw = plan.draws[d];
        if (window_blades(draw, patches) == 0) continue;
        const uint64_t bytes = uint64_t(draw.instance_count) * window.stride * kBladeWindowRecordBytes;
        if ((held * window.stride * kBladeWindowRecordBytes) + bytes > kMaxBladeWindowPoseBytes) continue;
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
        // Each instance whose cell finds its entry free takes it (a work item of this draw:
        // the entry's index for now, its slot below); a cell whose entry another cell of the
        // frame holds (a reach wider than the table, or the same cell in another tier's draw)
        // is posed by the draw that holds it, or by the vertex shader.
        BladeWindowDispatch dispatch{d, static_cast<uint32_t>(window.work.size() / 2), 0};
        for (uint32_t i = 0; i < draw.instance_count; ++i) {
            const TierInstance& instance = plan.instances[draw.first_instance + i];
            const uint32_t side = table->side;
            const size_t at =
                size_t(table->first_entry) + size_t(instance.cell[1] % side) * side + instance.cell[0] % side;
            uint32_t* entry = window.table.data() + at * kEntryWords;
            if (entry[0] != kNoWindowEntry) continue;
            entry[0] = instance.cell[0];
            entry[1] = instance.cell[1];
            entry[3] = window.stride;
            window.work.push_back(static_cast<uint32_t>(at));
            window.work.push_back(draw.first_instance + i);
            ++dispatch.items;
            ++held;
        }
        draw.uniforms.tiers[3] = dispatch.first_item;
        draw.uniforms.transition[3] = static_cast<float>(window.stride);
        if (dispatch.items > 0) window.dispatches.push_back(dispatch);
    }
    if (window.dispatches.empty()) {
        window.clear();
    } else {
        assign_slots(&window, previous, used);
        for (size_t w = 0; w < window.work.size(); w += 2) {
            uint32_t* entry = window.table.data() + size_t(window.work[w]) * kEntryWords;
            window.work[w] = entry[2];
            entry[2] &= ~kWindowSlotEntered;
        }
    }
    for (TierDraw& draw : plan.draws) {
        if ((draw.features & (kFeatureWind | kFeatureInteraction)) == 0 || draw.kind != GRASS_TIER_GEOMETRY) continue;
        if (const BladeWindowField* f = find_field(window, draw.field_slot)) set_table(&draw.uniforms, *f);
    }
    mark_held_draws(plan.blade_window, &plan);
}

void keep_blade_window(const BladeWindowPlan& frame, BladeWindowPlan* kept_out) {
    BladeWindowPlan& kept = *kept_out;
    kept.clear();
    kept.table.assign(frame.table.begin(), frame.table.end());
    kept.fields.assign(frame.fields.begin(), frame.fields.end());
    kept.stride = frame.stride;
    kept.slots = frame.slots;
    kept.pose_bytes = frame.pose_bytes;
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
