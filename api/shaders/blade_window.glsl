// The blade window (docs/responsive.md "The blade window", api/src/plan/blade_window.hpp):
// the poses of the blades of the cells that view 0 draws in a geometry tier, computed once
// per frame by blade_window.comp, read by blade.vert's window variant (GRASS_BLADE_WINDOW:
// a draw whose cells the window all holds). Compiled only there and in the pass.
//
// The table: per field, side x side entries (field.transition.y: the side, 0 where the field
// has no window; field.transition.z: its first entry), toroidally addressed by cell
// (entry = (z mod side) side + x mod side); an entry is (cell x, cell z, slot, blades of the
// patch), or all ones where no cell holds it. The records (api/src/foundation/frame_plan.hpp
// kBladeWindowRecordBytes): per slot, `stride` blades (the entry's w), per blade six vec4:
// the pose (v1, shade) and (v2, 0), v1 and v2 relative to the root in world metres; the
// previous frame's pose, likewise (motion vectors); the blade's state (blade_state.glsl
// blade_state_pack: (v2, eta), (velocity, 0)), which only the pass reads.

#ifdef VULKAN
#define GRASS_WINDOW_TABLE_BINDING 14
#define GRASS_WINDOW_POSES_BINDING 15
#else
#define GRASS_WINDOW_TABLE_BINDING 1 // GL: shader storage bindings 1 and 2 (grass_gl.h)
#define GRASS_WINDOW_POSES_BINDING 2
#endif
#ifdef GRASS_BLADE_WINDOW_PASS
#define GRASS_WINDOW_POSES_ACCESS
#else
#define GRASS_WINDOW_POSES_ACCESS readonly
#endif

layout(std430, binding = GRASS_WINDOW_POSES_BINDING) GRASS_WINDOW_POSES_ACCESS buffer BladeWindowPoses {
    vec4 window_poses[];
};

const uint kWindowRecordVectors = 6u; // per blade: pose, previous pose, state (two vec4 each)
const uint kWindowPrevious = 2u;      // the previous pose's first vec4 in a record
const uint kWindowState = 4u;         // the state's first vec4 in a record

// The index of the first vec4 of the record of blade `blade` at slot `slot`, `stride` blades a slot.
uint window_pose_index(uint slot, uint stride, uint blade) { return kWindowRecordVectors * (slot * stride + blade); }

BladePose window_record_pose(uint at) {
    vec4 a = window_poses[at];
    vec4 b = window_poses[at + 1u];
    BladePose pose;
    pose.v1 = a.xyz;
    pose.shade = a.w;
    pose.v2 = b.xyz;
    return pose;
}

#ifndef GRASS_BLADE_WINDOW_PASS
layout(std430, binding = GRASS_WINDOW_TABLE_BINDING) readonly buffer BladeWindowTable {
    uvec4 window_table[];
};

// The first vec4 of the record of blade `blade` of cell `cell` in the window. Only the
// window variant (GRASS_BLADE_WINDOW) reads it, on a draw whose cells the window all holds
// (the core's choice, plan/blade_window.hpp): the cell's entry is its own.
uint window_record(uvec2 cell, uint blade) {
    uint side = uint(field.transition.y + 0.5);
    uvec4 entry = window_table[uint(field.transition.z + 0.5) + (cell.y % side) * side + cell.x % side];
    return window_pose_index(entry.z, entry.w, blade);
}

// The pose of blade `blade` of cell `cell` this frame, and at the previous frame.
BladePose window_pose(uvec2 cell, uint blade) { return window_record_pose(window_record(cell, blade)); }
BladePose window_previous_pose(uvec2 cell, uint blade) {
    return window_record_pose(window_record(cell, blade) + kWindowPrevious);
}
#endif
