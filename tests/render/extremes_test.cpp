// The extremes suite (issue 6, item 4): grass at the edges of its input ranges, in both
// backends, on a small linear float target (128 x 96, one sample) so that NaN and infinity
// reach the read-back unclamped. Every frame of every case asserts:
//  - every pixel finite, not negative and not blown up (<= kMaxLinear);
//  - no error, no crash, no validation message (RenderTest::TearDown);
//  - the plan's counts within their bounds (expect_sane_frame): instances no more than the
//    cells the view can reach times the tiers, cells no more than the field's times the tiers,
//    geometry cells no more than those in view, blades drawn <= submitted = cells x blades per
//    patch, nodes visited within the quadtree and a budget, plan time finite.
// The refusals of NaN, infinite and huge inputs at the API are the core's ExtremeInputs test
// (tests/core/extremes_test.cpp). Figures: docs/records/testing.md ("Extremes").
#include "render_fixture.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace grass_test {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr float kMaxLinear = 64.0f;      // the brightest lit grass is ~2 (sun + ambient)
constexpr uint64_t kNodeBudget = 200000; // quadtree nodes one frame may visit
constexpr double kPlanBudgetMs = 5000.0; // generous: sanitizer builds on 2 shared cores

// A camera: look-at, vertical fov, near and far planes.
struct Shot {
    double eye[3];
    double target[3];
    float fov = 50.0f;
    float near_m = 0.05f;
    float far_m = 200.0f;
};

struct Frame {
    grass_host::Image image;
    grass_frame_stats stats{};
    double ms = 0.0; // wall time of the frame (plan, draw, read-back)
};

// A field the test made, for the bounds of the plan's counts.
struct Placed {
    grass_field_id id;
    double ox, oz, cell; // corner (identity rotation) and cell size, metres
    uint32_t cx, cz;
    uint32_t tiers;   // tier count
    uint32_t largest; // cells a side of its largest instance
    uint64_t quadtree_nodes;
};

// A height map of smooth hills, 0..1 (R16).
std::vector<uint16_t> hills(uint32_t n) {
    std::vector<uint16_t> t(size_t(n) * n);
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            const double h = 0.5 + 0.25 * std::sin(2.0 * kPi * x / 16.0) * std::cos(2.0 * kPi * y / 11.0) +
                             0.2 * std::sin(2.0 * kPi * (x + 2.0 * y) / 37.0);
            t[size_t(y) * n + x] = uint16_t(std::lround(std::clamp(h, 0.0, 1.0) * 65535.0));
        }
    }
    return t;
}

class ExtremesTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = 128;
        t.height = 96;
        t.samples = 1;
        t.float_color = true;
        start(t);
        grass_patch_info info{};
        ASSERT_EQ(grass_get_patch_info(ctx, patch, &info), GRASS_SUCCESS);
        blades_per_patch_ = info.blade_count;
    }

    // The default lod setup (all five tiers) when the desc leaves its tiers empty.
    grass_field_id add(const grass_field_desc& d) {
        Placed p{};
        p.id = make_field(d);
        p.ox = d.base_transform[12];
        p.oz = d.base_transform[14];
        p.cell = d.cell_size;
        p.cx = d.cells_x;
        p.cz = d.cells_z;
        if (d.tier_count == 0) {
            p.tiers = GRASS_DEFAULT_TIER_COUNT;
            p.largest = 500; // the image tier's macro-cells
        } else {
            p.tiers = d.tier_count;
            p.largest = 1;
            bool macro = false, non_geometry = false;
            for (uint32_t t = 0; t < d.tier_count; ++t) non_geometry |= d.tiers[t].kind != GRASS_TIER_GEOMETRY;
            for (uint32_t k = 0; k < d.lod_test_count; ++k) {
                if (d.lod_tests[k].kind != GRASS_LOD_TEST_MACRO_CELL) continue;
                macro = true;
                p.largest = std::max(p.largest, d.lod_tests[k].max_macro_cells);
            }
            if (non_geometry && !macro) p.largest = std::max(d.cells_x, d.cells_z);
        }
        p.quadtree_nodes = 0;
        for (uint64_t sx = d.cells_x, sz = d.cells_z;; sx = (sx + 1) / 2, sz = (sz + 1) / 2) {
            p.quadtree_nodes += sx * sz;
            if (sx == 1 && sz == 1) break;
        }
        fields_.push_back(p);
        return p.id;
    }
    void remove(grass_field_id id) {
        EXPECT_EQ(grass_destroy_field(ctx, id), GRASS_SUCCESS) << log;
        fields_.erase(
            std::remove_if(fields_.begin(), fields_.end(), [&](const Placed& p) { return p.id.index == id.index; }),
            fields_.end());
    }
    void remove_all() {
        while (!fields_.empty()) remove(fields_.back().id);
    }

    grass_map_id hill_map(uint32_t n = 64) {
        const std::vector<uint16_t> texels = hills(n);
        grass_map_desc m = grass_default_map_desc();
        m.pixels = texels.data();
        m.width = m.height = n;
        m.format = GRASS_MAP_FORMAT_R16_UNORM;
        grass_map_id id{};
        EXPECT_EQ(grass_create_map(ctx, &m, &id), GRASS_SUCCESS) << log;
        return id;
    }

    grass_view_desc view_of(const Shot& s) const {
        return grass_host::make_view(*host, s.eye, s.target, s.fov, s.near_m, s.far_m);
    }

    // Renders the shot (after `edit` changes the view), saves the image and checks the frame.
    Frame shoot(const Shot& s, const std::string& tag, const std::function<void(grass_view_desc&)>& edit = {}) {
        grass_view_desc v = view_of(s);
        if (edit) edit(v);
        Frame f;
        const auto t0 = std::chrono::steady_clock::now();
        f.image = render(v);
        f.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        EXPECT_EQ(grass_get_frame_stats(ctx, &f.stats), GRASS_SUCCESS);
        save(f.image, tag);
        expect_sane_frame(f, s, tag);
        return f;
    }

    // Cells of field p in the axis-aligned box of the view frustum, widened by `margin` cells.
    double cells_in_view(const Placed& p, const Shot& s, double margin) const {
        double f[3], r[3], u[3];
        look_at_basis(s.eye, s.target, f, r, u);
        const double t = std::tan(s.fov * kPi / 360.0);
        const double aspect = double(host->target().width) / double(host->target().height);
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int k = 0; k < 8; ++k) {
            const double d = (k & 4) ? s.far_m : s.near_m;
            const double sx = (k & 1) ? 1.0 : -1.0, sy = (k & 2) ? 1.0 : -1.0;
            for (int a = 0; a < 2; ++a) {
                const int c = a == 0 ? 0 : 2;
                const double w = s.eye[c] + d * (f[c] + sx * t * aspect * r[c] + sy * t * u[c]);
                const double cell = (w - (a == 0 ? p.ox : p.oz)) / p.cell;
                lo[a] = std::min(lo[a], cell);
                hi[a] = std::max(hi[a], cell);
            }
        }
        const double x0 = std::max(0.0, std::floor(lo[0] - margin)),
                     x1 = std::min(double(p.cx), std::ceil(hi[0] + margin));
        const double z0 = std::max(0.0, std::floor(lo[1] - margin)),
                     z1 = std::min(double(p.cz), std::ceil(hi[1] + margin));
        return std::max(0.0, x1 - x0) * std::max(0.0, z1 - z0);
    }

    void expect_sane_frame(const Frame& f, const Shot& s, const std::string& tag) {
        SCOPED_TRACE(tag);
        const auto& px = f.image.rgba_f32;
        ASSERT_EQ(px.size(), size_t(host->target().width) * host->target().height * 4) << "a float read-back";
        uint64_t not_finite = 0, negative = 0, huge = 0;
        float largest = 0.0f;
        for (size_t k = 0; k < px.size(); ++k) {
            const float v = px[k];
            if (!std::isfinite(v)) {
                ++not_finite;
                continue;
            }
            negative += v < 0.0f;
            huge += v > kMaxLinear;
            if (k % 4 != 3) largest = std::max(largest, v); // rgb: alpha is 1 where the sky is
        }
        EXPECT_EQ(not_finite, 0u) << "NaN or infinite channels";
        EXPECT_EQ(negative, 0u) << "negative channels";
        EXPECT_EQ(huge, 0u) << "channels above " << kMaxLinear << " (largest " << largest << ")";

        const grass_frame_stats& st = f.stats;
        double field_cells = 0.0, tier_cells = 0.0, view_geometry = 0.0, view_instances = 0.0, nodes = 0.0;
        for (const Placed& p : fields_) {
            field_cells += double(p.cx) * p.cz;
            tier_cells += double(p.cx) * p.cz * p.tiers;
            view_geometry += cells_in_view(p, s, 3.0); // blade tips lean out of their cell
            view_instances += p.tiers * cells_in_view(p, s, p.largest + 3.0);
            nodes += double(p.quadtree_nodes);
        }
        uint64_t instances = 0, cells = 0;
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
            EXPECT_LE(st.instances[k], st.cells[k]) << "kind " << k << ": an instance covers at least one cell";
            EXPECT_LE(st.macro_cells[k], st.instances[k]) << "kind " << k;
            instances += st.instances[k];
            cells += st.cells[k];
        }
        EXPECT_LE(double(instances), view_instances) << "instances <= cells in view x tiers";
        EXPECT_LE(double(cells), tier_cells) << "cells covered <= field cells x tiers";
        EXPECT_EQ(st.cells_drawn, st.cells[GRASS_TIER_GEOMETRY]);
        EXPECT_LE(double(st.cells_drawn), std::min(view_geometry, field_cells)) << "geometry cells in view";
        EXPECT_EQ(st.blades_submitted, st.cells_drawn * blades_per_patch_);
        EXPECT_LE(st.blades_drawn, st.blades_submitted);
        EXPECT_LE(double(st.nodes_visited), nodes) << "no node visited twice";
        EXPECT_LE(st.nodes_visited, kNodeBudget);
        EXPECT_LE(st.nodes_empty, st.nodes_visited);
        // Culled by the sphere test when visited, or by the box test per tier that would draw it.
        EXPECT_LE(st.nodes_culled, st.nodes_visited * (1 + GRASS_MAX_TIERS));
        EXPECT_TRUE(std::isfinite(st.plan_ms) && st.plan_ms >= 0.0 && st.plan_ms < kPlanBudgetMs) << st.plan_ms;
        std::printf("[ measured ] %s %-22s %7.1f ms (plan %.2f ms), %6llu nodes, instances %llu/%llu/%llu, "
                    "blades %llu of %llu, brightest %.3f\n",
                    backend_name(GetParam()).c_str(), tag.c_str(), f.ms, st.plan_ms,
                    static_cast<unsigned long long>(st.nodes_visited), static_cast<unsigned long long>(st.instances[0]),
                    static_cast<unsigned long long>(st.instances[1]), static_cast<unsigned long long>(st.instances[2]),
                    static_cast<unsigned long long>(st.blades_drawn),
                    static_cast<unsigned long long>(st.blades_submitted), double(largest));
    }

    // Pixels whose colour is not exactly the clear colour (a float target stores it exactly).
    uint64_t drawn_pixels(const Frame& f) const {
        const float* clear = host->target().clear_color;
        uint64_t n = 0;
        for (size_t i = 0; i + 3 < f.image.rgba_f32.size(); i += 4) {
            n += f.image.rgba_f32[i] != clear[0] || f.image.rgba_f32[i + 1] != clear[1] ||
                 f.image.rgba_f32[i + 2] != clear[2];
        }
        return n;
    }
    // Mean linear luminance of the drawn pixels.
    double mean_drawn_luminance(const Frame& f) const {
        const float* clear = host->target().clear_color;
        double sum = 0.0;
        uint64_t n = 0;
        for (size_t i = 0; i + 3 < f.image.rgba_f32.size(); i += 4) {
            const float* p = &f.image.rgba_f32[i];
            if (p[0] == clear[0] && p[1] == clear[1] && p[2] == clear[2]) continue;
            sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            ++n;
        }
        return n ? sum / double(n) : 0.0;
    }
    double share(const Frame& f) const { return double(drawn_pixels(f)) / double(f.image.width * f.image.height); }

    // A 512 x 512 field of 0.25 m cells (128 m) with the default lod setup: every tier in view.
    grass_field_id lawn() {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 512;
        return add(d);
    }

    std::vector<Placed> fields_;
    uint64_t blades_per_patch_ = 0;
};

// The camera at 1 m, 1 km, 100 km and 10,000 km from the origin with the field there (plus
// an offset single precision cannot hold): 3 mm steps of the camera (0.21 px) draw exactly
// the frames they draw at the origin and move the grass by the expected sub-pixel amount,
// without jumps (RenderTest::step_camera; FarFromOriginTest does 1 mm steps at 1e7 m on a
// larger target). The motion is measured on an RGBA8 4x multisampled target, where coverage
// follows sub-pixel motion; the grass centroid still jitters by ~0.1-0.3 px per step there
// (blades thinner than a pixel), hence steps of 0.2 px and the loose per-step bound. Then
// every distance is rendered on the float target for the checks of every frame.
TEST_P(ExtremesTest, CameraFarFromTheOriginFollowsSubPixelMoves) {
    grass_host::TargetDesc msaa;
    msaa.width = 128;
    msaa.height = 96;
    msaa.samples = 4;
    start(msaa);
    const int steps = 8;
    const double step_m = 0.003, height = 1.5;
    const uint32_t cells = 4; // 1 m x 1 m from 1.5 m: as large on screen as 2 m from 3 m, a quarter of the blades
    const double distances[4] = {1.0, 1e3, 1e5, 1e7};
    const CameraSteps origin = step_camera(0.0, 0.0, steps, step_m, height, cells);
    for (const double distance : distances) {
        const CameraSteps far_out = step_camera(distance + 0.3719, -distance, steps, step_m, height, cells);
        double worst_origin = 0.0, worst_step = 0.0, least_change = 1e9, worst_residual = 0.0;
        for (int k = 0; k <= steps; ++k) {
            worst_origin = std::max(worst_origin, mean_difference(origin.frames[k], far_out.frames[k]));
            worst_residual = std::max(worst_residual, std::fabs(far_out.shift[k] - k * far_out.slope));
            if (k == 0) continue;
            worst_step = std::max(worst_step, std::fabs(far_out.shift[k] - far_out.shift[k - 1]));
            least_change = std::min(least_change, mean_difference(far_out.frames[k], far_out.frames[k - 1]));
        }
        std::printf("[ measured ] %s: %g m out: %.4f px per 3 mm (expected %.4f .. %.4f), largest step %.3f px, "
                    "largest residual %.3f px, %.4f levels from the origin's frames\n",
                    backend_name(GetParam()).c_str(), distance, far_out.px_per_step, far_out.expected_lo,
                    far_out.expected_hi, worst_step, worst_residual, worst_origin);
        EXPECT_LE(worst_origin, 0.05) << distance << " m: the origin's frames";
        EXPECT_GT(least_change, 0.0) << distance << " m: every step moves the grass";
        // A precision jump is metres out there (the float spacing at 1e7 m is 1 m: ~35 px).
        EXPECT_LT(worst_step, 0.75) << distance << " m: no jump";
        EXPECT_LT(worst_residual, 0.4) << distance << " m: the grass follows the camera";
        EXPECT_GE(far_out.px_per_step, far_out.expected_lo * 0.85) << distance << " m";
        EXPECT_LE(far_out.px_per_step, far_out.expected_hi * 1.15) << distance << " m";
    }

    grass_host::TargetDesc linear = host->target();
    linear.samples = 1;
    linear.float_color = true;
    start(linear);
    for (const double distance : distances) {
        const double ox = distance + 0.3719, oz = -distance;
        grass_field_desc fd = field_desc(8);
        fd.base_transform[12] = ox;
        fd.base_transform[14] = oz;
        const grass_field_id f = add(fd);
        const Shot s{{ox + 1.0 + step_m, 3.0, oz + 1.0}, {ox + 1.0 + step_m, 0.0, oz + 1.0001}};
        const Frame frame = shoot(s, "at_" + std::to_string(int(std::log10(distance))));
        EXPECT_EQ(frame.stats.cells_drawn, 64u);
        remove(f);
    }
}

// Cells of 1 mm and 1 km: the default lod setup scales with the cell, so the same scene in
// cells draws the same picture as at 0.25 m.
TEST_P(ExtremesTest, CellsOfAMillimetreAndAKilometreDrawTheSamePicture) {
    Frame reference;
    for (const double cell : {0.25, 1e-3, 1e3}) {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 512;
        d.cell_size = cell;
        const grass_field_id f = add(d);
        // 6 cells up at the near edge, looking 160 cells along: all five tiers.
        Shot s{{256.0 * cell, 6.0 * cell, 0.0}, {256.0 * cell, 0.0, 160.0 * cell}};
        s.near_m = float(0.2 * cell);
        s.far_m = float(800.0 * cell);
        const Frame frame = shoot(s, "cell_" + std::to_string(cell));
        remove(f);
        EXPECT_GT(frame.stats.instances[GRASS_TIER_GEOMETRY], 0u);
        EXPECT_GT(frame.stats.instances[GRASS_TIER_VOLUME], 0u);
        EXPECT_GT(frame.stats.instances[GRASS_TIER_IMAGE], 0u);
        if (cell == 0.25) {
            reference = frame;
            EXPECT_GT(share(frame), 0.4);
            continue;
        }
        const double diff = mean_difference(reference.image, frame.image);
        std::printf("[ measured ] %s: cell %g m: %.4f levels from the 0.25 m picture, instances %llu/%llu/%llu "
                    "(0.25 m: %llu/%llu/%llu)\n",
                    backend_name(GetParam()).c_str(), cell, diff,
                    static_cast<unsigned long long>(frame.stats.instances[0]),
                    static_cast<unsigned long long>(frame.stats.instances[1]),
                    static_cast<unsigned long long>(frame.stats.instances[2]),
                    static_cast<unsigned long long>(reference.stats.instances[0]),
                    static_cast<unsigned long long>(reference.stats.instances[1]),
                    static_cast<unsigned long long>(reference.stats.instances[2]));
        EXPECT_LE(diff, 1.0) << "cell " << cell;
    }
}

// A field of one cell, and one of 1e5 x 1e5 cells (25 km a side) seen to 30 km.
TEST_P(ExtremesTest, FieldsOfOneCellAndOfTenBillionCells) {
    {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 1;
        const grass_field_id f = add(d);
        const Frame frame = shoot(Shot{{0.125, 0.5, -0.35}, {0.125, 0.08, 0.125}}, "1x1");
        EXPECT_EQ(frame.stats.cells_drawn, 1u);
        EXPECT_GT(share(frame), 0.05);
        remove(f);
    }
    {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 100000;
        const grass_field_id f = add(d);
        Shot s{{12500.0, 1.7, 12500.0}, {12600.0, 0.0, 12700.0}};
        s.near_m = 0.5f;
        s.far_m = 30000.0f;
        const Frame frame = shoot(s, "1e5x1e5");
        EXPECT_GT(frame.stats.instances[GRASS_TIER_IMAGE], 0u);
        EXPECT_GT(share(frame), 0.4);
        // Looking at the horizon from a corner, along the field's edge.
        Shot edge{{0.0, 1.7, 0.0}, {0.0, 1.7, 1000.0}};
        edge.near_m = 0.5f;
        edge.far_m = 30000.0f;
        shoot(edge, "1e5x1e5_edge");
        remove(f);
    }
}

// Density exactly 0 draws nothing and visits one node; exactly 1 draws every blade.
TEST_P(ExtremesTest, DensityExactlyZeroAndExactlyOne) {
    const Shot s{{2.0, 1.5, -0.5}, {2.0, 0.0, 2.0}};
    grass_field_desc d = field_desc(16);
    d.density = 0.0f;
    grass_field_id f = add(d);
    Frame zero = shoot(s, "density0");
    EXPECT_EQ(drawn_pixels(zero), 0u);
    EXPECT_EQ(zero.stats.blades_drawn, 0u);
    EXPECT_EQ(zero.stats.nodes_visited, 1u);
    EXPECT_EQ(zero.stats.nodes_empty, 1u);
    remove(f);
    // The default lod setup too: no tier draws anything.
    grass_field_desc all = grass_default_field_desc();
    all.patch = patch;
    all.cells_x = all.cells_z = 512;
    all.density = 0.0f;
    f = add(all);
    zero = shoot(Shot{{64.0, 1.5, 0.0}, {64.0, 0.0, 40.0}}, "density0_all_tiers");
    EXPECT_EQ(drawn_pixels(zero), 0u);
    EXPECT_EQ(zero.stats.instances[0] + zero.stats.instances[1] + zero.stats.instances[2], 0u);
    remove(f);

    d.density = 1.0f;
    f = add(d);
    const Frame one = shoot(s, "density1");
    EXPECT_GT(one.stats.blades_drawn, 0u);
    EXPECT_EQ(one.stats.blades_drawn, one.stats.blades_submitted) << "a threshold of 1 passes a density of 1";
    EXPECT_GT(share(one), 0.5);
    remove(f);
}

// The camera straight down, grazing at 0.01 degrees, inside the grass and below the ground.
TEST_P(ExtremesTest, CameraStraightDownGrazingInsideTheGrassAndBelowTheGround) {
    lawn();
    const Frame down = shoot(Shot{{64.0, 3.0, 64.0}, {64.0, 0.0, 64.0}}, "straight_down");
    // Blades alone cover 0.85 of a lawn seen from straight above (VolumeGrazingTest); the
    // cells below lie in the blades / volume transition. Measured 0.854; a hole would show
    // as much less.
    EXPECT_GT(share(down), 0.8);
    // 0.01 degrees below level at 1.7 m: the view axis meets the ground 9.7 km out.
    const double drop = 1000.0 * std::tan(0.01 * kPi / 180.0);
    Shot grazing{{64.0, 1.7, 0.5}, {64.0, 1.7 - drop, 1000.5}};
    grazing.far_m = 1000.0f;
    const Frame graze = shoot(grazing, "grazing");
    EXPECT_GT(share(graze), 0.3);
    // And at 0.01 degrees from 2 cm up, inside the blade layer.
    Shot low{{64.0, 0.02, 0.5}, {64.0, 0.02 - drop, 1000.5}};
    low.far_m = 1000.0f;
    shoot(low, "grazing_2cm");
    const Frame inside = shoot(Shot{{64.0, 0.08, 64.0}, {64.0, 0.08, 100.0}}, "inside");
    EXPECT_GT(share(inside), 0.3);
    shoot(Shot{{64.0, -0.5, 64.0}, {64.0, 0.2, 70.0}}, "below_ground");
    shoot(Shot{{64.0, -1.0, 64.0}, {64.0, 0.0, 64.0}}, "below_looking_up");
}

// The sun at the zenith, on the horizon and below the ground.
TEST_P(ExtremesTest, SunAtTheZenithOnTheHorizonAndBelowTheGround) {
    lawn();
    const Shot s{{64.0, 1.5, 0.0}, {64.0, 0.0, 40.0}};
    auto sun = [](float x, float y, float z) {
        return [=](grass_view_desc& v) {
            v.sun_direction[0] = x;
            v.sun_direction[1] = y;
            v.sun_direction[2] = z;
        };
    };
    const Frame zenith = shoot(s, "sun_zenith", sun(0.0f, 1.0f, 0.0f));
    const Frame horizon = shoot(s, "sun_horizon", sun(1.0f, 0.0f, 0.0f));
    const Frame below = shoot(s, "sun_below", sun(0.3f, -1.0f, 0.2f));
    const Frame nadir = shoot(s, "sun_nadir", sun(0.0f, -1.0f, 0.0f));
    // No sun at all: ambient light only.
    const Frame dark =
        shoot(s, "sun_off", [](grass_view_desc& v) { v.sun_color[0] = v.sun_color[1] = v.sun_color[2] = 0.0f; });
    const double lz = mean_drawn_luminance(zenith), lh = mean_drawn_luminance(horizon),
                 lb = mean_drawn_luminance(below), ln = mean_drawn_luminance(nadir), l0 = mean_drawn_luminance(dark);
    std::printf("[ measured ] %s: mean luminance of the grass, sun at the zenith %.4f, horizon %.4f, below %.4f, "
                "nadir %.4f, no sun %.4f\n",
                backend_name(GetParam()).c_str(), lz, lh, lb, ln, l0);
    EXPECT_GT(lz, l0 * 1.2) << "the sun overhead lights the grass";
    EXPECT_GT(lh, l0) << "the sun on the horizon (half its disc up) lights the blades' sides";
    // Below the ground the terrain shadows the grass: the picture without a sun, exactly.
    EXPECT_EQ(below.image.rgba_f32, dark.image.rgba_f32) << "a sun below the ground lights nothing";
    EXPECT_EQ(nadir.image.rgba_f32, dark.image.rgba_f32) << "a sun below the ground lights nothing";
}

// The volume tier's ray march at its iteration bound: a level ray along the diagonal of one
// 64 x 64-cell macro-cell crosses every slice plane (8 x 128) and goes on 4 cells. With a
// density that passes no blade nothing stops it early.
TEST_P(ExtremesTest, VolumeRayMarchAtItsIterationBound) {
    const Shot s{{0.05, 0.1, 0.05}, {16.0, 0.1, 16.0}, 40.0f};
    for (const float density : {0.001f, 1.0f}) {
        grass_field_desc d = solo_tier_field(64, GRASS_TIER_VOLUME, 8, 64);
        d.density = density;
        const grass_field_id f = add(d);
        const Frame frame = shoot(s, density < 0.5f ? "volume_bound_empty" : "volume_bound_full");
        EXPECT_EQ(frame.stats.instances[GRASS_TIER_VOLUME], 1u) << "one macro-cell";
        if (density < 0.5f) {
            EXPECT_EQ(drawn_pixels(frame), 0u) << "a density of 0.001 passes no blade of 384";
        } else {
            // Rows clearly below the horizon: the lower 40%.
            uint8_t sky[3];
            expected_sky(host->target(), sky);
            const double below =
                grass_share(frame.image, sky, 0, frame.image.height * 6 / 10, frame.image.width, frame.image.height);
            std::printf("[ measured ] %s: diagonal grazing ray, grass below the horizon %.3f\n",
                        backend_name(GetParam()).c_str(), below);
            EXPECT_GT(below, 0.97);
        }
        remove(f);
    }
}

// A height map with a 10 km height scale: hills 4 m wide and kilometres high.
TEST_P(ExtremesTest, HeightMapWithATenKilometreScale) {
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = d.cells_z = 16;
    d.maps.height = hill_map(16);
    d.maps.height_scale = 1e4f;
    add(d);
    Shot above{{2.0, 1.2e4, 2.0}, {2.0, 0.0, 2.0}};
    above.near_m = 1.0f;
    above.far_m = 2e4f;
    shoot(above, "tall_above");
    Shot side{{2.0, 5e3, -3e3}, {2.0, 5e3, 2.0}};
    side.near_m = 1.0f;
    side.far_m = 2e4f;
    shoot(side, "tall_side");
    // In a valley, looking up a cliff.
    Shot valley{{0.5, 3000.0, 0.5}, {2.0, 6000.0, 2.0}};
    valley.far_m = 2e4f;
    const Frame f = shoot(valley, "tall_valley");
    EXPECT_GT(share(f), 0.05);
    // Under the terrain, looking up into it.
    Shot under{{2.0, -50.0, 2.0}, {2.5, 0.0, 3.0}};
    under.far_m = 2e4f;
    shoot(under, "tall_below");
}

// A hilly field 10,000 km out draws what it draws at the origin.
TEST_P(ExtremesTest, HillyFieldFarFromTheOrigin) {
    const grass_map_id map = hill_map(32);
    Frame at[2];
    for (int pass = 0; pass < 2; ++pass) {
        const double ox = pass == 0 ? 0.0 : 1e7 + 0.3719, oz = pass == 0 ? 0.0 : -1e7;
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 32;
        d.base_transform[12] = ox;
        d.base_transform[14] = oz;
        d.maps.height = map;
        d.maps.height_scale = 2.0f;
        const grass_field_id f = add(d);
        const Shot s{{ox + 4.0, 3.5, oz - 2.0}, {ox + 4.0, 1.0, oz + 4.0}};
        at[pass] = shoot(s, pass ? "hilly_far" : "hilly_origin");
        remove(f);
    }
    const double diff = mean_difference(at[0].image, at[1].image);
    std::printf("[ measured ] %s: hilly field 10,000 km out: %.4f levels from the origin's picture\n",
                backend_name(GetParam()).c_str(), diff);
    EXPECT_LE(diff, 0.05);
    EXPECT_GT(share(at[1]), 0.3);
    EXPECT_EQ(grass_destroy_map(ctx, map), GRASS_SUCCESS);
}

// Per-blade state (docs/responsive.md "Per-blade state", GL's blade window pass) at its
// extremes: the strongest wind and gravity the API takes, gusts at their most, a ball under
// the grass rolling at 1e3 m/s, and time steps of 10 s, 0 and 10 s again: every pixel stays
// finite (the steps are exact springs, the state is validated and reset if not finite).
TEST_P(ExtremesTest, BladeStateUnderTenSecondStepsAndTheStrongestForces) {
    const Shot s{{2.0, 1.5, -0.5}, {2.0, 0.0, 2.0}};
    grass_field_id f = add(field_desc(16));
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 1e3f;
    w.gust_strength = 4.0f;
    w.turbulence = 1.0f;
    w.gravity[0] = 1e3f;
    w.gravity[1] = -1e3f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    const double times[5] = {0.0, 10.0, 10.0, 20.0, 20.0 + 1.0 / 60.0};
    for (int k = 0; k < 5; ++k) {
        grass_collider c{};
        c.shape = GRASS_COLLIDER_SPHERE;
        c.radius = 0.4f;
        c.center[0] = 2.0 + (k % 2 == 0 ? 1.0 : -1.0);
        c.center[1] = 0.1;
        c.center[2] = 2.0;
        c.velocity[0] = k % 2 == 0 ? 1e3f : -1e3f;
        ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
        const Frame fr = shoot(s, "state_step" + std::to_string(k), [&](grass_view_desc& v) { v.time = times[k]; });
        EXPECT_GT(share(fr), 0.05) << k;
    }
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
    w = grass_default_wind_desc();
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    remove(f);
}

INSTANTIATE_TEST_SUITE_P(Backends, ExtremesTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
