// The blade window (docs/responsive.md "The blade window"): responsive grass's poses once per
// frame. The cells view 0 draws in a geometry tier get a slot each; the backend's pass
// (blade_window.comp) writes the pose of every blade of every slot (v1, v2, shade: the
// per-blade step cell_blade_pose of blade_dynamics.glsl), after the interaction pass. Every
// view of the frame reads them through a table per field of side x side entries,
// toroidally addressed by cell, which covers the band the field's geometry tiers draw in;
// a draw with a cell without a slot (outside view 0's frustum, a far shadow cascade) keeps
// the per-vertex variant, which computes every pose in the vertex shader as before; a draw
// whose cells all have one gets the window variant (kFeatureBladeWindow), which only reads. View-independent: a blade's shadow and the blade agree.
// Planned only for frames with wind or colliders; still grass plans nothing here.
#pragma once

#include "foundation/frame_plan.hpp"
#include "foundation/handle_pool.hpp"

#include <cstdint>

namespace grass {

struct Patch;

// The largest side of a field's table (cells): a geometry band wider than ~128 cells from
// the lod origin (or an unbounded one) keeps slots only for the cells that fall in distinct
// entries; the others compute their poses in the vertex shader.
constexpr uint32_t kMaxBladeWindowSide = 256;
// The most bytes the window's records of one frame take (kBladeWindowRecordBytes per blade
// and slot): the instances past it get no slot (their poses are computed in the vertex shader).
constexpr uint64_t kMaxBladeWindowPoseBytes = 256ull << 20;
// The most instances of one draw the pass takes (one work group row each: GL's and Vulkan's
// least maximum dispatch size); a draw with more computes its poses in the vertex shader.
constexpr uint32_t kMaxBladeWindowInstances = 65535;

// The side of a field's table for geometry tiers drawing out to `reach` metres from the lod
// origin (band end plus its transition), in cells of `cell_size` metres, on a field of
// cells_x x cells_z cells: 2 ceil(reach / cell) + 2, at most the field's larger side and
// kMaxBladeWindowSide, at least 1.
uint32_t blade_window_side(double reach, double cell_size, uint32_t cells_x, uint32_t cells_z);

// View 0: plans the window from plan->draws (their features, uniforms and instances) and
// writes each responsive draw's table (FieldUniforms::transition y, z) and, for the pass,
// its first work item (tiers[3]), and gives the draws whose cells it all holds the window
// variant (kFeatureBladeWindow). A cell that `previous` (the last frame's window,
// keep_blade_window) held keeps its slot, and its blades their state; a cell new to the
// window takes a free slot, marked entered (kWindowSlotEntered) in its work item: the pass
// starts its blades at the equilibrium pose. `used`: scratch. `enabled` false (a backend
// without the pass) plans none.
void plan_blade_window(FramePlan* plan, bool enabled, const HandlePool<Patch>& patches, const BladeWindowPlan& previous,
                       Vector<uint32_t>* used);

// Once view 0's frame has begun: its window becomes the one the next frame's slots follow.
void keep_blade_window(const BladeWindowPlan& frame, BladeWindowPlan* kept);

// A later view of the frame: its responsive draws read view 0's tables; those whose cells
// view 0's window all holds get the window variant.
void apply_blade_window(const FramePlan& first, FramePlan* plan);

} // namespace grass
