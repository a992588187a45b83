// The blade window's plan (api/src/plan/blade_window.hpp): the table's side from the
// geometry tiers' reach, a slot per instance of view 0's responsive geometry draws, the
// table's entries, what later views read, which draws get the window's variant, and nothing
// at all for still grass.
#include "plan/blade_window.hpp"
#include "plan/field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace {

using grass::BladeWindowField;
using grass::FramePlan;
using grass::TierDraw;
using grass::TierInstance;

struct Fixture {
    grass::HostAllocator host{grass_allocator{}};
    grass::HandlePool<grass::Patch> patches{&host};
    FramePlan plan{&host};
    grass::BladeWindowPlan previous{&host}; // the last frame's window (keep_blade_window)
    grass::Vector<uint32_t> used{grass::StlAllocator<uint32_t>(&host)};
    uint32_t patch_slot = 0;

    explicit Fixture(uint32_t blades) {
        grass::Patch* patch = host.create<grass::Patch>(&host);
        patch->data.blade_curves.assign(size_t(blades) * 8, 0.0f);
        patch_slot = patches.insert(patch);
    }

    // A draw of field `field` with `cells` (x, z) instances; geometry tier 0 (band to
    // `end` m, transition out `out` m), 0.25 m cells, a 380 x 532 field.
    TierDraw& add_draw(uint32_t field, grass_tier_kind kind, uint32_t features,
                       const std::vector<std::pair<uint32_t, uint32_t>>& cells, float end = 5.0f, float out = 3.75f) {
        TierDraw draw{};
        draw.kind = kind;
        draw.tier = kind == GRASS_TIER_GEOMETRY ? 0 : 1;
        draw.field_slot = field;
        draw.patch_slot = patch_slot;
        draw.first_instance = static_cast<uint32_t>(plan.instances.size());
        draw.instance_count = static_cast<uint32_t>(cells.size());
        draw.features = features;
        draw.uniforms.field_up[3] = 0.25f;
        draw.uniforms.map_params[2] = 380.0f;
        draw.uniforms.map_params[3] = 532.0f;
        draw.uniforms.tiers[1] = 2;
        draw.uniforms.bands[0][1] = end;
        draw.uniforms.bands[0][3] = out;
        draw.uniforms.bands[1][1] = std::numeric_limits<float>::infinity();
        for (const auto& c : cells) {
            TierInstance instance{};
            instance.cell[0] = c.first;
            instance.cell[1] = c.second;
            instance.count[0] = instance.count[1] = 1;
            plan.instances.push_back(instance);
        }
        plan.draws.push_back(draw);
        return plan.draws.back();
    }
};

const uint32_t* entry(const FramePlan& plan, const BladeWindowField& f, uint32_t x, uint32_t z) {
    return plan.blade_window.table.data() + (size_t(f.first_entry) + size_t(z % f.side) * f.side + x % f.side) * 4;
}

TEST(BladeWindowTest, SideCoversTheReachPlusACellEachWay) {
    EXPECT_EQ(grass::blade_window_side(8.75, 0.25, 380, 532), 72u); // 2 x 35 + 2
    EXPECT_EQ(grass::blade_window_side(8.8, 0.25, 380, 532), 74u);  // 35.2 cells: 36
    EXPECT_EQ(grass::blade_window_side(0.0, 0.25, 380, 532), 2u);
    EXPECT_EQ(grass::blade_window_side(8.75, 0.25, 40, 30), 40u); // the field's larger side
    EXPECT_EQ(grass::blade_window_side(std::numeric_limits<double>::infinity(), 0.25, 380, 532),
              grass::kMaxBladeWindowSide);
    EXPECT_EQ(grass::blade_window_side(1e9, 0.25, 1000000, 1000000), grass::kMaxBladeWindowSide);
    EXPECT_EQ(grass::blade_window_side(8.75, 0.25, 1, 1), 1u);
}

TEST(BladeWindowTest, SlotsForViewZerosResponsiveGeometryInstances) {
    Fixture f(100);
    const uint32_t wind = grass::kFeatureWind;
    f.add_draw(3, GRASS_TIER_GEOMETRY, wind, {{10, 20}, {11, 20}, {10, 21}});
    f.add_draw(3, GRASS_TIER_VOLUME, wind, {{40, 40}});
    f.add_draw(5, GRASS_TIER_GEOMETRY, wind | grass::kFeatureInteraction, {{0, 0}, {82, 0}});
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    const grass::BladeWindowPlan& w = f.plan.blade_window;
    ASSERT_EQ(w.dispatches.size(), 2u);
    EXPECT_EQ(w.dispatches[0].draw, 0u);
    EXPECT_EQ(w.dispatches[0].first_item, 0u);
    EXPECT_EQ(w.dispatches[0].items, 3u);
    EXPECT_EQ(w.dispatches[1].draw, 2u);
    EXPECT_EQ(w.dispatches[1].first_item, 3u);
    EXPECT_EQ(w.stride, 100u);
    EXPECT_EQ(w.slots, 5u);
    EXPECT_EQ(w.pose_bytes, 5u * 100u * 96u);
    ASSERT_EQ(w.fields.size(), 2u);
    EXPECT_EQ(w.fields[0].side, 72u);
    EXPECT_EQ(w.fields[1].first_entry, 72u * 72u);
    EXPECT_EQ(w.table.size(), 2u * 72u * 72u * 4u);
    const uint32_t* e = entry(f.plan, w.fields[0], 11, 20);
    EXPECT_EQ(e[0], 11u);
    EXPECT_EQ(e[1], 20u);
    EXPECT_EQ(e[2], 1u);
    EXPECT_EQ(e[3], 100u);
    // Cell 82 lands where cell 10 of the same row would (82 mod 72): its own field's table.
    EXPECT_EQ(entry(f.plan, w.fields[1], 82, 0)[2], 4u);
    EXPECT_EQ(entry(f.plan, w.fields[0], 12, 20)[0], grass::kNoWindowEntry);
    // A first frame: every cell enters (its work item's slot has the flag, the table's not).
    ASSERT_EQ(w.work.size(), 10u);
    EXPECT_EQ(w.work[2], 1u | grass::kWindowSlotEntered); // cell (11, 20): slot 1, instance 1
    EXPECT_EQ(w.work[3], 1u);
    // The draws' uniforms: the table for the shaders, the first work item and the stride for the pass.
    EXPECT_EQ(f.plan.draws[0].uniforms.transition[1], 72.0f);
    EXPECT_EQ(f.plan.draws[0].uniforms.transition[2], 0.0f);
    EXPECT_EQ(f.plan.draws[2].uniforms.tiers[3], 3u);
    EXPECT_EQ(f.plan.draws[2].uniforms.transition[3], 100.0f);
    EXPECT_EQ(f.plan.draws[2].uniforms.transition[2], float(72 * 72));
    EXPECT_EQ(f.plan.draws[1].uniforms.transition[1], 0.0f); // volume: poses as before
}

TEST(BladeWindowTest, ACellWhoseEntryIsTakenComputesItsOwnPose) {
    Fixture f(10);
    f.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{1, 1}, {73, 1}}); // 73 mod 72 = 1
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    const BladeWindowField& t = f.plan.blade_window.fields[0];
    EXPECT_EQ(entry(f.plan, t, 1, 1)[0], 1u);                  // the first keeps it; 73 finds cell 1 there
    EXPECT_EQ(f.plan.blade_window.pose_bytes, 1u * 10u * 96u); // one slot: 73 has none
    EXPECT_EQ(f.plan.blade_window.work.size(), 2u);
}

// The state stays with its cell: a cell the last frame's window held keeps its slot (not
// entered), a new cell takes the lowest free slot (entered), a cell that left frees its
// slot; a patch of another blade count (a new stride) starts every cell afresh.
TEST(BladeWindowTest, ACellKeepsItsSlotWhileItStaysInTheWindow) {
    Fixture f(10);
    f.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{1, 1}, {2, 1}, {3, 1}});
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    grass::keep_blade_window(f.plan.blade_window, &f.previous);
    ASSERT_EQ(f.previous.slots, 3u);

    // The camera moved: cell 1 left, cell 4 came; the draw lists them in another order.
    f.plan.draws.clear();
    f.plan.instances.clear();
    f.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{4, 1}, {3, 1}, {2, 1}});
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    const grass::BladeWindowPlan& w = f.plan.blade_window;
    const BladeWindowField& t = w.fields[0];
    EXPECT_EQ(entry(f.plan, t, 2, 1)[2], 1u);
    EXPECT_EQ(entry(f.plan, t, 3, 1)[2], 2u);
    EXPECT_EQ(entry(f.plan, t, 4, 1)[2], 0u); // cell 1's slot, free again
    ASSERT_EQ(w.work.size(), 6u);
    EXPECT_EQ(w.work[0], 0u | grass::kWindowSlotEntered);
    EXPECT_EQ(w.work[2], 2u);
    EXPECT_EQ(w.work[4], 1u);
    EXPECT_EQ(w.slots, 3u);

    // Another patch, of 20 blades: a new stride, every cell enters.
    grass::keep_blade_window(w, &f.previous);
    Fixture g(20);
    g.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{4, 1}, {3, 1}});
    grass::plan_blade_window(&g.plan, true, g.patches, f.previous, &g.used);
    ASSERT_EQ(g.plan.blade_window.work.size(), 4u);
    EXPECT_EQ(g.plan.blade_window.work[0], 1u | grass::kWindowSlotEntered);
    EXPECT_EQ(g.plan.blade_window.work[2], 0u | grass::kWindowSlotEntered);
    EXPECT_EQ(g.plan.blade_window.stride, 20u);

    // A frame without a window (still grass) keeps nothing: the next window starts afresh.
    Fixture still(10);
    still.add_draw(0, GRASS_TIER_GEOMETRY, 0u, {{4, 1}});
    grass::plan_blade_window(&still.plan, true, still.patches, f.previous, &still.used);
    grass::keep_blade_window(still.plan.blade_window, &f.previous);
    EXPECT_EQ(f.previous.slots, 0u);
    EXPECT_TRUE(f.previous.table.empty());
}

TEST(BladeWindowTest, LaterViewsReadViewZerosTables) {
    Fixture f(10);
    f.add_draw(2, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{5, 5}});
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    FramePlan later(&f.host);
    TierDraw draw{};
    draw.kind = GRASS_TIER_GEOMETRY;
    draw.field_slot = 2;
    draw.features = grass::kFeatureWind;
    later.draws.push_back(draw);
    draw.field_slot = 7; // a field view 0 does not draw with blades: no window
    later.draws.push_back(draw);
    grass::apply_blade_window(f.plan, &later);
    EXPECT_EQ(later.draws[0].uniforms.transition[1], 72.0f);
    EXPECT_EQ(later.draws[1].uniforms.transition[1], 0.0f);
    EXPECT_TRUE(later.blade_window.dispatches.empty()); // one pass a frame: view 0's
}

// The core chooses the variant per draw: the window's (kFeatureBladeWindow, no per-vertex
// pose code) for a responsive geometry draw whose cells the window all holds, the
// per-vertex one for a draw with any cell it does not hold, in view 0 and in later views.
TEST(BladeWindowTest, TheWindowVariantOnlyForDrawsWhoseCellsItAllHolds) {
    constexpr uint32_t kWindow = grass::kFeatureBladeWindow;
    Fixture f(10);
    f.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{1, 1}, {2, 1}});
    f.add_draw(1, GRASS_TIER_GEOMETRY, grass::kFeatureInteraction, {{1, 1}, {73, 1}}); // 73 mod 72 = 1: taken
    f.add_draw(0, GRASS_TIER_VOLUME, grass::kFeatureWind, {{9, 9}});
    f.add_draw(2, GRASS_TIER_GEOMETRY, 0u, {{5, 5}}); // still grass
    grass::plan_blade_window(&f.plan, true, f.patches, f.previous, &f.used);
    const uint32_t expected[4] = {grass::kFeatureWind | kWindow, grass::kFeatureInteraction, grass::kFeatureWind, 0u};
    for (uint32_t d = 0; d < 4; ++d) {
        EXPECT_EQ(f.plan.draws[d].features, expected[d]) << d;
        EXPECT_EQ(f.plan.draws[d].uniforms.tiling[3], float(expected[d])) << d; // the uniforms agree
    }

    // A later view: a draw of held cells only, one with a cell view 0 did not draw, one of a
    // field without a window; a bit left from an earlier plan is taken back.
    FramePlan later(&f.host);
    auto add_later = [&](uint32_t field, const std::vector<std::pair<uint32_t, uint32_t>>& cells) {
        TierDraw draw{};
        draw.kind = GRASS_TIER_GEOMETRY;
        draw.field_slot = field;
        draw.features = grass::kFeatureWind | kWindow;
        draw.first_instance = static_cast<uint32_t>(later.instances.size());
        draw.instance_count = static_cast<uint32_t>(cells.size());
        for (const auto& c : cells) {
            TierInstance instance{};
            instance.cell[0] = c.first;
            instance.cell[1] = c.second;
            later.instances.push_back(instance);
        }
        later.draws.push_back(draw);
    };
    add_later(0, {{2, 1}, {1, 1}});
    add_later(0, {{1, 1}, {3, 1}});
    add_later(7, {{1, 1}});
    grass::apply_blade_window(f.plan, &later);
    EXPECT_EQ(later.draws[0].features, grass::kFeatureWind | kWindow);
    EXPECT_EQ(later.draws[1].features, grass::kFeatureWind);
    EXPECT_EQ(later.draws[2].features, grass::kFeatureWind);

    // A backend without the pass: every draw keeps the per-vertex variant.
    Fixture off(10);
    off.add_draw(0, GRASS_TIER_GEOMETRY, grass::kFeatureWind, {{1, 1}});
    grass::plan_blade_window(&off.plan, false, off.patches, off.previous, &off.used);
    EXPECT_EQ(off.plan.draws[0].features, grass::kFeatureWind);
}

// Still grass (no wind, no colliders), a switched-off window and the debug boxes plan none.
TEST(BladeWindowTest, StillGrassPlansNothing) {
    for (int c = 0; c < 3; ++c) {
        Fixture f(10);
        f.add_draw(0, GRASS_TIER_GEOMETRY, c == 0 ? 0u : grass::kFeatureWind, {{5, 5}});
        if (c == 2) f.plan.flags = GRASS_VIEW_FLAG_DEBUG_CELLS;
        grass::plan_blade_window(&f.plan, c != 1, f.patches, f.previous, &f.used);
        EXPECT_TRUE(f.plan.blade_window.dispatches.empty()) << c;
        EXPECT_TRUE(f.plan.blade_window.table.empty()) << c;
        EXPECT_EQ(f.plan.blade_window.pose_bytes, 0u) << c;
        EXPECT_EQ(f.plan.draws[0].uniforms.transition[1], 0.0f) << c;
        EXPECT_EQ(f.plan.draws[0].uniforms.tiers[3], 0u) << c;
    }
}

} // namespace
