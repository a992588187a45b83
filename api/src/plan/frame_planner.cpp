#include "plan/frame_planner.hpp"

#include "dynamics/dynamics_plan.hpp"
#include "foundation/validate.hpp"
#include "maps/design_map.hpp"
#include "plan/blade_tessellation.hpp"
#include "plan/blade_window.hpp"
#include "plan/gbuffer_plan.hpp"
#include "plan/lights_plan.hpp"
#include "plan/lod_setup.hpp"
#include "plan/mesh_plan.hpp"
#include "plan/motion_plan.hpp"
#include "plan/tier_transitions.hpp"
#include "plan/view_culling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace grass {

namespace {

// c = a * b for column-major 4x4 matrices.
void mul4(const double a[16], const double b[16], double c[16]) {
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += a[4 * k + row] * b[4 * col + k];
            c[4 * col + row] = s;
        }
    }
}

// Blades passing a density d: thresholds are (k+1)/N (density_threshold.cpp), so floor(d N).
uint64_t blades_passing(double density, uint32_t blade_count) {
    const double n = std::floor(density * blade_count + 1e-6);
    return static_cast<uint64_t>(std::min<double>(std::max(n, 0.0), blade_count));
}

// A field seen from the camera: its frame in camera-relative world space. The camera is
// the plan's origin (the eyes' midpoint in a stereo frame); the lod origin is where the lod
// distances are measured from (the camera unless grass_lod_origin_desc moves it).
struct FieldFrame {
    double cam_local[3];  // the lod origin in field space, cells
    double origin_rel[3]; // field origin relative to the camera, metres
    double axis[3][3];    // one cell along field x, y, z, in world metres
    double cell_size;
};

FieldFrame field_frame(const Field& field, const double camera[3], const double lod_origin[3]) {
    FieldFrame f;
    const double* R = field.rotation;
    const double cs = field.desc.cell_size;
    const double rel[3] = {lod_origin[0] - field.translation[0], lod_origin[1] - field.translation[1],
                           lod_origin[2] - field.translation[2]};
    for (int c = 0; c < 3; ++c) {
        f.cam_local[c] = (R[3 * c] * rel[0] + R[3 * c + 1] * rel[1] + R[3 * c + 2] * rel[2]) / cs;
        f.origin_rel[c] = field.translation[c] - camera[c];
        for (int a = 0; a < 3; ++a) f.axis[a][c] = R[3 * a + c] * cs;
    }
    f.cell_size = cs;
    return f;
}

// A point in field space (cells) relative to the camera (metres).
void to_camera(const FieldFrame& f, double x, double y, double z, double out[3]) {
    for (int c = 0; c < 3; ++c) out[c] = f.origin_rel[c] + f.axis[0][c] * x + f.axis[1][c] * y + f.axis[2][c] * z;
}

struct NodeBox {
    double lo[3], hi[3];                       // field space, cells
    double terrain_lo = 0.0, terrain_hi = 0.0; // terrain height range under the node, cells
};

// The vertices of a geometry draw: the patch's full blades (none for a patch without blades).
uint32_t patch_indices(const PatchData& pd) { return pd.vertices.empty() ? 0u : pd.full_index_count(); }

class FieldPlanner {
public:
    FieldPlanner(const FramePlanning& in, uint32_t slot, const Field& field, const Patch& patch, const double camera[3],
                 const double lod_origin[3], const Frusta& culling, const DynamicsFrame& dynamics, uint32_t view_flags,
                 bool depth_pass, const ScreenScale& screen)
        : in_(in), slot_(slot), field_(field), patch_(patch), culling_(culling),
          frame_(field_frame(field, camera, lod_origin)), screen_(screen) {
        for (int c = 0; c < 3; ++c) camera_[c] = camera[c];
        for (int c = 0; c < 3; ++c) lod_rel_[c] = lod_origin[c] - camera[c];
        // Responsive grass: the shader variant of every draw of the field (still grass: the
        // maps' bits only).
        for (int c = 0; c < 3; ++c) field_up_[c] = frame_.axis[1][c] / frame_.cell_size;
        reads_map_ = dynamics.field_reads_map(field_up_);
        features_ = field.maps.features | (dynamics.wind ? kFeatureWind : 0u) | (reads_map_ ? kFeatureInteraction : 0u);
        if (field.wind_map.active()) features_ |= kFeatureWind | kFeatureWindMap;
        if (view_flags & kDebugViewFlags) features_ |= kFeatureDebugView;
        if (depth_pass) features_ |= kFeatureDepthPass; // the depth pass's own variant of every tier
        debug_cells_ = (view_flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0;
        const uint32_t density_slot = field.maps.map_slot[kMapDensity], height_slot = field.maps.map_slot[kMapHeight];
        density_map_ = density_slot != kNoMap ? in.maps.get(density_slot) : nullptr;
        height_map_ = height_slot != kNoMap ? in.maps.get(height_slot) : nullptr;
        // Field edges: each image tier's stand-in at the border, the nearest volume tier before
        // it (neither an overlay tier).
        const LodSetup& lod = field_.lod;
        uint32_t volume = kNoEdgeTier;
        for (uint32_t t = 0; t < lod.tier_count; ++t) {
            edge_tier_[t] = kNoEdgeTier;
            if ((lod.overlay_tiers >> t) & 1u) continue;
            if (lod.tiers[t].kind == GRASS_TIER_VOLUME) volume = t;
            if (lod.tiers[t].kind == GRASS_TIER_IMAGE) edge_tier_[t] = volume;
        }
    }

    grass_result run() {
        PlanScratch& scratch = in_.scratch;
        const LodSetup& lod = field_.lod;
        for (uint32_t t = 0; t < lod.tier_count; ++t) scratch.per_tier[t].clear();
        scratch.stack.clear();
        const uint32_t all_tests = lod.test_count == 32 ? 0xffffffffu : (1u << lod.test_count) - 1u;
        scratch.stack.push_back(PlanNode{field_.tree.root_level(), all_tests, 0, 0});
        while (!scratch.stack.empty()) {
            const PlanNode node = scratch.stack.back();
            scratch.stack.pop_back();
            GRASS_TRY(visit(node));
        }
        emit_draws();
        return GRASS_SUCCESS;
    }

private:
    // The range of `map` over the node's cells, through the field's cell-to-map transform.
    MapRange map_range(const DesignMap& map, const NodeCells& cells) const {
        const double* m = field_.cell_to_map;
        double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
        for (int k = 0; k < 4; ++k) {
            const double x = double(cells.x0) + ((k & 1) ? double(cells.count_x) : 0.0);
            const double z = double(cells.z0) + ((k & 2) ? double(cells.count_z) : 0.0);
            const double u = m[0] * x + m[2] * z + m[4], v = m[1] * x + m[3] * z + m[5];
            u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
        }
        return map.pyramid.range(u0, v0, u1, v1);
    }

    NodeBox box_of(const NodeCells& cells, uint32_t level) const {
        NodeBox b;
        const double oh = field_.overhang;
        if (height_map_) { // terrain unplanarity (lemme 6.4.4): the node's box spans its terrain
            const MapRange r = map_range(*height_map_, cells);
            const double to_cells = field_.height_scale / frame_.cell_size;
            b.terrain_lo = r.min * to_cells;
            b.terrain_hi = r.max * to_cells;
        }
        b.lo[0] = double(cells.x0) - oh;
        b.hi[0] = double(cells.x0 + cells.count_x) + oh;
        b.lo[1] = b.terrain_lo + field_.extents[level].min_y;
        b.hi[1] = b.terrain_hi + field_.extents[level].max_y;
        b.lo[2] = double(cells.z0) - oh;
        b.hi[2] = double(cells.z0 + cells.count_z) + oh;
        return b;
    }

    // The local density at a point of the field (cells), as the shaders find it.
    float density_at(double x, double z) const {
        float density = field_.desc.density;
        if (density_map_) {
            const double* m = field_.cell_to_map;
            density *= sample_map(density_map_->texels.data(), density_map_->width, density_map_->height, 1,
                                  m[0] * x + m[2] * z + m[4], m[1] * x + m[3] * z + m[5]);
        }
        return density;
    }

    grass_result visit(const PlanNode& node) {
        FramePlan& plan = in_.plan;
        plan.stats.nodes_visited += 1;
        const NodeCells cells = field_.tree.cells_of(node.level, node.x, node.z);
        // No grass anywhere in the node: discard it without visiting its subtree.
        const double max_density =
            double(field_.desc.density) * (density_map_ ? double(map_range(*density_map_, cells).max) : 1.0);
        if (!(max_density > 0.0)) {
            plan.stats.nodes_empty += 1;
            return GRASS_SUCCESS;
        }
        const NodeBox box = box_of(cells, node.level);

        // Bounding sphere of the node's own box (not merged from its children's).
        double center_local[3], half2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            center_local[c] = 0.5 * (box.lo[c] + box.hi[c]);
            const double h = 0.5 * (box.hi[c] - box.lo[c]);
            half2 += h * h;
        }
        grass_lod_node info;
        to_camera(frame_, center_local[0], center_local[1], center_local[2], info.center);
        info.radius = std::sqrt(half2) * frame_.cell_size;
        if (!culling_.sphere_may_be_visible(info.center, info.radius)) {
            plan.stats.nodes_culled += 1;
            return GRASS_SUCCESS;
        }
        // Nearest and farthest points of the box; the transform is rigid, so distances in
        // field space times the cell size are world distances.
        double near2 = 0.0, far2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double p = frame_.cam_local[c];
            const double n = std::min(std::max(p, box.lo[c]), box.hi[c]) - p;
            const double f = std::max(std::fabs(p - box.lo[c]), std::fabs(p - box.hi[c]));
            near2 += n * n;
            far2 += f * f;
        }
        info.distance_min = std::sqrt(near2) * frame_.cell_size;
        info.distance_max = std::sqrt(far2) * frame_.cell_size;
        for (int c = 0; c < 3; ++c) info.center[c] += camera_[c]; // the host sees world space
        info.level = node.level;
        info.cell_x = static_cast<uint32_t>(cells.x0);
        info.cell_z = static_cast<uint32_t>(cells.z0);
        info.cells_x = static_cast<uint32_t>(cells.count_x);
        info.cells_z = static_cast<uint32_t>(cells.count_z);
        info.height_min = box.terrain_lo * frame_.cell_size;
        info.height_max = box.terrain_hi * frame_.cell_size;
        const double node_top = box.hi[1] * frame_.cell_size, camera_height = frame_.cam_local[1] * frame_.cell_size;

        // Every still-active test answers; a tier draws when all its tests say draw.
        const LodSetup& lod = field_.lod;
        uint32_t discard = 0, split = 0; // per tier bits
        for (uint32_t active = node.active_tests; active != 0; active &= active - 1) {
            const uint32_t k = static_cast<uint32_t>(__builtin_ctz(active));
            const grass_lod_test& test = lod.tests[k];
            info.tier = test.tier;
            int64_t answer;
            if (test.kind == GRASS_LOD_TEST_CALLBACK) {
                {
                    CallbackScope scope(in_.lod_callbacks_running); // calls on the context are refused meanwhile
                    answer = static_cast<int64_t>(test.callback(test.user_data, &info));
                }
                if (answer < GRASS_LOD_DISCARD || answer > GRASS_LOD_DRAW) {
                    return in_.log.fail(
                        GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                        "grass_begin_frame: lod test %u of field %u (a callback) answered %lld for node "
                        "(level %u, cell %u, %u); it must answer a grass_lod_answer",
                        k, slot_ + 1, static_cast<long long>(answer), node.level, info.cell_x, info.cell_z);
                }
            } else {
                answer = evaluate_builtin_test(test, info, node_top, camera_height);
            }
            plan.stats.lod_test_calls += 1;
            if (answer == GRASS_LOD_DISCARD) discard |= 1u << test.tier;
            if (answer == GRASS_LOD_SPLIT) split |= 1u << test.tier;
        }

        const bool leaf = node.level == 0;
        uint32_t children_tests = node.active_tests;
        for (uint32_t t = 0; t < lod.tier_count; ++t) {
            if ((lod.tests_of_tier[t] & node.active_tests) == 0) continue; // decided above
            if (discard & (1u << t)) {
                children_tests &= ~lod.tests_of_tier[t];
                continue;
            }
            bool draw = leaf || (split & (1u << t)) == 0;
            if (lod.tiers[t].kind == GRASS_TIER_GEOMETRY && !leaf) draw = false; // cells only
            if (!draw) continue;
            children_tests &= ~lod.tests_of_tier[t];
            if (edge_tier_[t] != kNoEdgeTier) {
                add_with_field_edges(t, cells, box, node.level);
            } else {
                add_instance(t, cells, box);
            }
        }
        if (!leaf && children_tests != 0) push_children(node, children_tests);
        return GRASS_SUCCESS;
    }

    void push_children(const PlanNode& node, uint32_t tests) {
        const uint32_t level = node.level - 1;
        const uint64_t nx = field_.tree.nodes_x(level), nz = field_.tree.nodes_z(level);
        for (uint64_t dz = 0; dz < 2; ++dz) {
            for (uint64_t dx = 0; dx < 2; ++dx) {
                const uint64_t x = node.x * 2 + dx, z = node.z * 2 + dz;
                if (x < nx && z < nz) in_.scratch.stack.push_back(PlanNode{level, tests, x, z});
            }
        }
    }

    // Field edges (issue 12): the image tier is a flat slice at half the grass's height, so a
    // field drawn by it ended in a flat line at its border, where the grass's height shows
    // against what lies behind (blades everywhere show it). The cells along the field's border
    // are drawn by the image tier's stand-in, the nearest volume tier before it, whose carriers
    // have the grass's height: as field-edge instances, which draw the share of the tiers
    // after the stand-in (tier_transitions.glsl), so that in the transition zone the stand-in's
    // own instances and the edge instances together draw each border cell whole. The rest of
    // the node stays the image tier's.
    void add_with_field_edges(uint32_t tier, const NodeCells& cells, const NodeBox& box, uint32_t level) {
        const uint64_t nx = field_.desc.cells_x, nz = field_.desc.cells_z;
        uint64_t x0 = cells.x0, x1 = cells.x0 + cells.count_x, z0 = cells.z0, z1 = cells.z0 + cells.count_z;
        if (x0 > 0 && z0 > 0 && x1 < nx && z1 < nz) {
            add_instance(tier, cells, box);
            return;
        }
        const uint32_t stand_in = edge_tier_[tier];
        const uint64_t depth = edge_depth(box, level);
        if (z0 == 0) { // the rows along x first, whole; then the columns between them
            const uint64_t d = std::min(depth, z1 - z0);
            add_edge_strip(stand_in, NodeCells{x0, 0, x1 - x0, d}, level);
            z0 = d;
        }
        if (z1 == nz && z1 > z0) {
            const uint64_t d = std::min(depth, z1 - z0);
            add_edge_strip(stand_in, NodeCells{x0, z1 - d, x1 - x0, d}, level);
            z1 -= d;
        }
        if (x0 == 0 && z1 > z0) {
            const uint64_t d = std::min(depth, x1 - x0);
            add_edge_strip(stand_in, NodeCells{0, z0, d, z1 - z0}, level);
            x0 = d;
        }
        if (x1 == nx && x1 > x0 && z1 > z0) {
            const uint64_t d = std::min(depth, x1 - x0);
            add_edge_strip(stand_in, NodeCells{x1 - d, z0, d, z1 - z0}, level);
            x1 -= d;
        }
        if (x1 > x0 && z1 > z0) {
            const NodeCells inner{x0, z0, x1 - x0, z1 - z0};
            add_instance(tier, inner, box_of(inner, level));
        }
    }

    // How deep into the field a view ray that passes the grass's top at the border goes before
    // it reaches the ground, in cells: the grass's height times the node's distance over the
    // camera's height above the grass. Seen low, the border's silhouette is the tips of many
    // rows; seen from above, of one. At least 1, at most kEdgeDepth.
    uint64_t edge_depth(const NodeBox& box, uint32_t level) const {
        const double* c = frame_.cam_local;
        const double dx = std::max({box.lo[0] - c[0], 0.0, c[0] - box.hi[0]});
        const double dz = std::max({box.lo[2] - c[2], 0.0, c[2] - box.hi[2]});
        const double above = c[1] - box.hi[1], grass = double(field_.extents[level].max_y);
        const double depth = above > 0.0 ? grass * std::sqrt(dx * dx + dz * dz) / above : double(kEdgeDepth);
        return static_cast<uint64_t>(std::min(std::max(std::ceil(depth), 1.0), double(kEdgeDepth)));
    }

    // A strip along the border as field-edge instances of `tier`, at most kEdgeStrip cells long.
    void add_edge_strip(uint32_t tier, const NodeCells& strip, uint32_t level) {
        const bool along_x = strip.count_x >= strip.count_z;
        const uint64_t length = along_x ? strip.count_x : strip.count_z;
        for (uint64_t k = 0; k < length; k += kEdgeStrip) {
            const uint64_t n = std::min<uint64_t>(kEdgeStrip, length - k);
            const NodeCells part = along_x ? NodeCells{strip.x0 + k, strip.z0, n, strip.count_z}
                                           : NodeCells{strip.x0, strip.z0 + k, strip.count_x, n};
            add_instance(tier, part, box_of(part, level), true);
        }
    }

    // The exact test before drawing: the node's box against the clip planes.
    void add_instance(uint32_t tier, const NodeCells& cells, const NodeBox& box, bool field_edge = false) {
        double corners[8][3];
        for (int k = 0; k < 8; ++k) {
            to_camera(frame_, (k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1],
                      (k & 4) ? box.hi[2] : box.lo[2], corners[k]);
        }
        if (!culling_.box_may_be_visible(corners)) {
            in_.plan.stats.nodes_culled += 1;
            return;
        }
        PlanCandidate c;
        double origin[3], centre[3];
        to_camera(frame_, double(cells.x0), 0.0, double(cells.z0), origin);
        to_camera(frame_, double(cells.x0) + 0.5 * double(cells.count_x), 0.0,
                  double(cells.z0) + 0.5 * double(cells.count_z), centre);
        for (int a = 0; a < 3; ++a) centre[a] -= lod_rel_[a]; // sorted by the distance to the lod origin
        c.distance2 = centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2];
        for (int a = 0; a < 3; ++a) c.instance.origin[a] = static_cast<float>(origin[a]);
        c.instance.reserved = 0.0f;
        c.instance.cell[0] = static_cast<uint32_t>(cells.x0);
        c.instance.cell[1] = static_cast<uint32_t>(cells.z0);
        c.instance.count[0] = static_cast<uint32_t>(cells.count_x);
        c.instance.count[1] = static_cast<uint32_t>(cells.count_z);
        c.instance.terrain[0] = static_cast<float>(box.terrain_lo);
        c.instance.terrain[1] = static_cast<float>(box.terrain_hi);
        c.instance.terrain[2] = field_edge ? 1.0f : 0.0f;
        c.instance.terrain[3] = 0.0f;
        c.density =
            density_at(double(cells.x0) + 0.5 * double(cells.count_x), double(cells.z0) + 0.5 * double(cells.count_z));
        c.level = 0;
        if (field_.lod.tiers[tier].kind == GRASS_TIER_GEOMETRY && field_.tessellation.enabled) {
            // Measured at the instance's nearest point: its centre less half its diagonal.
            const double half_diagonal =
                0.5 * frame_.cell_size * std::hypot(double(cells.count_x), double(cells.count_z));
            c.level = blade_level(field_.tessellation, patch_.data, frame_.cell_size, screen_,
                                  std::max(std::sqrt(c.distance2) - half_diagonal, 0.0));
        }
        in_.scratch.per_tier[tier].push_back(c);
    }

    void emit_draws() {
        const LodSetup& lod = field_.lod;
        bool drew = false;
        for (uint32_t t = 0; t < lod.tier_count; ++t) {
            auto& candidates = in_.scratch.per_tier[t];
            if (candidates.empty()) continue;
            const grass_tier_kind kind = lod.tiers[t].kind;
            if (kind == GRASS_TIER_GEOMETRY) { // front to back: early depth rejects the rest
                // Each tessellation level in a run of its own (one draw), the finer first;
                // the levels follow the distance, so the draws stay front to back.
                std::sort(candidates.begin(), candidates.end(), [](const PlanCandidate& a, const PlanCandidate& b) {
                    return a.level != b.level ? a.level < b.level : a.distance2 < b.distance2;
                });
            }
            for (size_t begin = 0, end = 0; begin < candidates.size(); begin = end) {
                for (end = begin + 1; end < candidates.size() && candidates[end].level == candidates[begin].level;)
                    ++end;
                emit_draw(t, kind, begin, end);
            }
            drew = true;
        }
        if (drew) in_.plan.stats.fields_drawn += 1;
    }

    // The draw of candidates [begin, end) of tier t: all of it but for a geometry tier with
    // dynamic tessellation, whose candidates of one level it is.
    void emit_draw(uint32_t t, grass_tier_kind kind, size_t begin, size_t end) {
        FramePlan& plan = in_.plan;
        const LodSetup& lod = field_.lod;
        const PatchData& pd = patch_.data;
        const auto& candidates = in_.scratch.per_tier[t];
        const uint32_t level = candidates[begin].level;
        TierDraw draw;
        draw.kind = kind;
        draw.tier = t;
        draw.slices = lod.tiers[t].slices;
        draw.field_slot = slot_;
        draw.patch_slot = field_.patch_slot;
        draw.first_instance = static_cast<uint32_t>(plan.instances.size());
        draw.instance_count = static_cast<uint32_t>(end - begin);
        draw.features = features_;
        if (kind == GRASS_TIER_GEOMETRY && field_.culling.enabled) draw.features |= kFeatureBladeCulling;
        fill_uniforms(kind, t, &draw.uniforms);
        draw.uniforms.tiling[3] = draw.features;
        // Responsive variants find a vertex's blade from the patch's vertices per blade.
        if ((draw.features & kBladeCurveFeatures) != 0) {
            draw.uniforms.trample[3] = static_cast<float>(pd.vertices_per_blade);
        }
        draw.vertex_count = debug_cells_                  ? kDebugBoxVertices
                            : kind == GRASS_TIER_GEOMETRY ? patch_indices(pd)
                                                          : slice_tier_vertices(kind, draw.features);
        if (kind == GRASS_TIER_GEOMETRY && level > 0 && !debug_cells_) {
            draw.blade_level = level;
            draw.first_index = pd.levels[level].first_index;
            draw.vertex_count = pd.blade_count * pd.levels[level].indices_per_blade;
        }
        plan.draws.push_back(draw);
        const uint64_t triangles_per_blade = pd.levels[level].indices_per_blade / 3;
        TierBand bands[GRASS_MAX_TIERS];
        for (uint32_t b = 0; b < lod.tier_count; ++b) {
            bands[b] = {field_.bands[b][0], field_.bands[b][1], field_.bands[b][2], field_.bands[b][3]};
        }
        for (size_t k = begin; k < end; ++k) {
            const PlanCandidate& c = candidates[k];
            plan.instances.push_back(c.instance);
            const uint64_t cells = uint64_t(c.instance.count[0]) * c.instance.count[1];
            plan.stats.instances[kind] += 1;
            plan.stats.cells[kind] += cells;
            plan.stats.macro_cells[kind] += cells > 1 ? 1 : 0;
            if (kind == GRASS_TIER_GEOMETRY) {
                // The blades this tier draws at the cell's centre: those whose r =
                // threshold / density falls in its interval (tier_transitions.hpp).
                const float d = static_cast<float>(std::sqrt(c.distance2));
                float total = 0.0f, lo = 0.0f, self = 0.0f;
                for (uint32_t b = 0; b < lod.tier_count; ++b) {
                    const float w = band_weight(bands[b], d);
                    total += w;
                    if (b > t) lo += w;
                    if (b == t) self = w;
                }
                const double share_lo = total > 0.0f ? lo / total : 0.0,
                             share_hi = total > 0.0f ? (lo + self) / total : 0.0;
                const uint64_t passing = blades_passing(c.density * share_hi, pd.blade_count) -
                                         blades_passing(c.density * share_lo, pd.blade_count);
                plan.stats.cells_drawn += 1;
                plan.stats.blades_submitted += pd.blade_count;
                plan.stats.blades_drawn += passing;
                plan.stats.triangles += passing * triangles_per_blade;
            }
        }
    }

    void fill_uniforms(grass_tier_kind kind, uint32_t tier, FieldUniforms* u) const {
        const grass_field_desc& d = field_.desc;
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                u->patch_to_world[4 * c + r] =
                    (c < 3 && r < 3) ? static_cast<float>(frame_.axis[c][r]) : (c == 3 && r == 3 ? 1.0f : 0.0f);
            }
        }
        const double* m = field_.cell_to_map;
        u->map_u[0] = static_cast<float>(m[0]);
        u->map_u[1] = static_cast<float>(m[2]);
        u->map_u[2] = static_cast<float>(m[4]);
        u->map_v[0] = static_cast<float>(m[1]);
        u->map_v[1] = static_cast<float>(m[3]);
        u->map_v[2] = static_cast<float>(m[5]);
        u->map_u[3] = u->map_v[3] = 0.0f;
        u->map_params[0] = d.density;
        u->map_params[1] = static_cast<float>(field_.height_scale / frame_.cell_size);
        u->map_params[2] = static_cast<float>(d.cells_x);
        u->map_params[3] = static_cast<float>(d.cells_z);
        u->blade_params[0] = patch_.data.ao_impact;
        u->blade_params[1] = patch_.data.ao_height;
        u->blade_params[2] = static_cast<float>(kind);
        u->blade_params[3] = std::max(0.0f, patch_.data.bounds_max[1]); // the slices' height
        u->tiling[0] = d.mirror_seed;
        u->tiling[1] = d.mirror_tiling ? 1u : 0u;
        u->tiling[2] = field_.lod.tiers[tier].slices;
        u->tiling[3] = features_;
        for (uint32_t t = 0; t < GRASS_MAX_TIERS; ++t) {
            for (int k = 0; k < 4; ++k) u->bands[t][k] = t < field_.lod.tier_count ? field_.bands[t][k] : 0.0f;
        }
        u->tiers[0] = tier;
        u->tiers[1] = field_.lod.tier_count;
        u->tiers[2] = (field_.lod.overlay_tiers >> tier) & 1u;
        // The geometry tiers' bits (tier_transitions.glsl, texel_transition); on a blade draw the
        // blade window's pass puts its first work item there instead (blade_window.hpp). An
        // orthographic view marks every tier: its texel tiers keep the thinned shares of each
        // (docs/three-tiers.md "Transitions"), since their parts of the samples, measured at
        // points that differ along its axis, left 1% of an oblique view's pixels uncovered
        // (OrthographicTest.EveryTierCoversTheFieldWithTheBladesColours).
        u->tiers[3] = 0u;
        for (uint32_t t = 0; t < field_.lod.tier_count; ++t) {
            const bool geometry = field_.lod.tiers[t].kind == GRASS_TIER_GEOMETRY;
            if (geometry || culling_.culling[0]->orthographic()) u->tiers[3] |= 1u << t;
        }
        u->transition[0] = d.transition_window;
        u->transition[1] = u->transition[2] = u->transition[3] = 0.0f;
        const grass_blade_mechanics& mech = patch_.mechanics;
        u->mechanics[0] = mech.stiffness;
        u->mechanics[1] = mech.mass;
        u->mechanics[2] = mech.wind_response;
        u->mechanics[3] = mech.variation;
        u->trample[0] = mech.trample_depth;
        u->trample[1] = mech.recovery_time;
        u->trample[2] = reads_map_ ? 1.0f : 0.0f;
        u->trample[3] = 0.0f;
        for (int c = 0; c < 3; ++c) u->field_up[c] = static_cast<float>(field_up_[c]);
        u->field_up[3] = static_cast<float>(frame_.cell_size);
        pack_wind_map(field_.wind_map, u);
        const BladeCulling& c = field_.culling;
        u->culling[0] = c.orientation_limit;
        u->culling[1] = c.frustum_tolerance;
        u->culling[2] = c.distance_max;
        u->culling[3] = c.distance_levels;
        const SliceSet* slices = kind == GRASS_TIER_GEOMETRY ? nullptr
                                 : kind == GRASS_TIER_VOLUME ? patch_.slices(field_.lod.tiers[tier].slices)
                                                             : patch_.slices(0);
        for (uint32_t k = 0; k < 16; ++k)
            u->alpha_test_scale[k / 4][k % 4] = slices ? slices->alpha_test_scale[k] : 1.0f;
    }

    const FramePlanning& in_;
    uint32_t slot_;
    const Field& field_;
    const Patch& patch_;
    const Frusta& culling_;
    FieldFrame frame_;
    ScreenScale screen_; // the view's pixels per metre, for the blades' tessellation
    double camera_[3];
    double lod_rel_[3]; // the lod origin relative to the camera (metres)
    const DesignMap* density_map_ = nullptr;
    const DesignMap* height_map_ = nullptr;
    double field_up_[3] = {0, 1, 0}; // the field's up, world, unit
    bool reads_map_ = false;         // the field reads the interaction map
    uint32_t features_ = 0;          // TierDraw::features of every draw of the field
    bool debug_cells_ = false;       // every draw is drawn as debug boxes (GRASS_VIEW_FLAG_DEBUG_CELLS)
    static constexpr uint32_t kNoEdgeTier = ~0u;
    static constexpr uint64_t kEdgeStrip = 16; // cells along the border in a field-edge instance, at most
    static constexpr uint64_t kEdgeDepth = 16; // cells into the field of the field-edge instances, at most
    uint32_t edge_tier_[GRASS_MAX_TIERS];      // per tier: its stand-in at the field's border, or kNoEdgeTier
};

} // namespace

// Camera-relative view-projection: the host's projection times its rotation only (the
// translation is the camera position).
void eye_view_projection(const float view[16], const float projection[16], double out[16]) {
    double rotation[16] = {0};
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) rotation[4 * c + r] = view[4 * c + r];
    }
    rotation[15] = 1.0;
    double p[16];
    for (int k = 0; k < 16; ++k) p[k] = projection[k];
    mul4(p, rotation, out);
}

// A colour view with a grass_shadow_receive_desc (a depth pass ignores it): every draw
// gets kFeatureShadowReceive, and the plan the map and its block. The matrices are made
// camera-relative in double (the shaders' positions are), the view axis is the camera's.
static void plan_shadow_receive(const grass_view_desc& view, const ViewExtensions& ext, const double camera[3],
                                FramePlan* plan) {
    plan->shadow_receive = ext.shadow != nullptr && !plan->depth_pass && !plan->gbuffer;
    plan->shadow = ShadowUniforms{};
    plan->shadow_map = plan->shadow_receive ? ext.shadow->shadow_map : 0u;
    plan->shadow_layout = plan->shadow_receive ? ext.shadow->vk_image_layout : 0u;
    if (!plan->shadow_receive) return;
    const grass_shadow_receive_desc& d = *ext.shadow;
    ShadowUniforms& u = plan->shadow;
    for (uint32_t i = 0; i < d.cascade_count && i < GRASS_MAX_SHADOW_CASCADES; ++i) {
        const float* m = d.world_to_shadow[i];
        for (int k = 0; k < 12; ++k) u.world_to_shadow[i][k] = m[k];
        for (int r = 0; r < 4; ++r) { // column 3 of M * T(camera)
            const double t = m[12 + r] + m[r] * camera[0] + m[4 + r] * camera[1] + m[8 + r] * camera[2];
            u.world_to_shadow[i][12 + r] = static_cast<float>(t);
        }
        u.cascade_end[i] = d.cascade_end[i];
    }
    // The view matrix's third row is the eye's +z in world space; the camera looks along -z.
    double axis[3] = {-view.view[2], -view.view[6], -view.view[10]};
    const double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (int c = 0; c < 3; ++c) u.axis[c] = static_cast<float>(axis[c] / len);
    u.axis[3] = static_cast<float>(d.cascade_count);
    u.params[0] = d.compare == GRASS_SHADOW_COMPARE_GREATER_EQUAL ? -1.0f : 1.0f;
    u.params[1] = d.depth_bias;
    u.params[2] = d.filter_radius;
    for (TierDraw& draw : plan->draws) {
        draw.features |= kFeatureShadowReceive;
        draw.uniforms.tiling[3] = draw.features;
    }
}

grass_result build_frame_plan(const FramePlanning& in, const grass_view_desc& view, const ViewExtensions& ext) {
    const auto start = std::chrono::steady_clock::now();
    FramePlan& plan = in.plan;
    plan.clear();

    // The plan's origin (what every position is relative to) and the lod origin. Mono: the
    // camera, and the lod origin where grass_lod_origin_desc puts it. Stereo: both at the lod
    // origin, by default the eyes' midpoint, so both eyes draw one plan and neither is
    // favoured; the shaders subtract each eye's position (plan.eyes).
    const grass_stereo_view_desc* stereo = ext.stereo;
    double lod_origin[3], camera[3];
    for (int c = 0; c < 3; ++c) {
        lod_origin[c] = ext.lod_origin ? ext.lod_origin->position[c]
                        : stereo       ? 0.5 * (view.camera_position[c] + stereo->camera_position[c])
                                       : view.camera_position[c];
        camera[c] = stereo ? lod_origin[c] : view.camera_position[c];
    }
    double view_projection[16], second_view_projection[16];
    eye_view_projection(view.view, view.projection, view_projection);
    for (int k = 0; k < 16; ++k) plan.frame.view_projection[k] = static_cast<float>(view_projection[k]);
    plan.stereo = stereo != nullptr;
    Frusta frusta{};
    frusta.count = 1;
    if (stereo) {
        eye_view_projection(stereo->view, stereo->projection, second_view_projection);
        frusta.count = 2;
        const double* eyes[2] = {view.camera_position, stereo->camera_position};
        const double* vps[2] = {view_projection, second_view_projection};
        for (int e = 0; e < 2; ++e) {
            for (int k = 0; k < 16; ++k) plan.eyes.eye_view_projection[e][k] = static_cast<float>(vps[e][k]);
            for (int c = 0; c < 3; ++c) {
                frusta.eye[e][c] = eyes[e][c] - camera[c];
                plan.eyes.eye_position[e][c] = static_cast<float>(frusta.eye[e][c]);
            }
            plan.eyes.eye_position[e][3] = 0.0f;
        }
    }

    const double sun[3] = {view.sun_direction[0], view.sun_direction[1], view.sun_direction[2]};
    const double len = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    for (int c = 0; c < 3; ++c) {
        plan.frame.sun_direction[c] = static_cast<float>(sun[c] / len);
        plan.frame.sun_color[c] = view.sun_color[c];
        plan.frame.ambient_color[c] = view.ambient_color[c];
    }
    plan.frame.sun_direction[3] = plan.frame.sun_color[3] = plan.frame.ambient_color[3] = 0.0f;
    plan.frame.params[0] = static_cast<float>(std::fmod(in.time, 86400.0));
    plan.frame.params[1] = static_cast<float>(view.flags);
    plan.frame.params[2] = in.depth_mode == GRASS_DEPTH_GREATER ? -1.0f : 1.0f;
    // The target's samples and clip convention, as the backend reports them.
    // (A depth view's: the depth-only target's samples, where the backend has one of its own.)
    const bool depth_view = ext.pass && ext.pass->pass == GRASS_PASS_DEPTH;
    RenderTarget target = in.target;
    if (depth_view && target.depth_pass_samples != 0) target.samples = target.depth_pass_samples;
    write_render_target(&plan.frame, target);
    // The lod origin relative to the plan's origin (zero but for a mono view with
    // grass_lod_origin_desc): the shaders measure the tiers' distances from it.
    for (int c = 0; c < 3; ++c) plan.frame.lod_origin[c] = static_cast<float>(lod_origin[c] - camera[c]);
    plan.frame.lod_origin[3] = 0.0f;
    for (int k = 0; k < 4; ++k) plan.viewport[k] = view.viewport[k];
    plan.flags = view.flags;
    plan.depth_pass = depth_view;
    plan.depth_bias[0] = plan.depth_pass ? ext.pass->depth_bias_constant : 0.0f;
    plan.depth_bias[1] = plan.depth_pass ? ext.pass->depth_bias_slope : 0.0f;
    // Responsive grass is planned around the plan's origin (the wind's phases, the
    // interaction map's window): the eyes of a stereo frame share it.
    grass_view_desc origin_view = view;
    for (int c = 0; c < 3; ++c) origin_view.camera_position[c] = plan.origin[c] = camera[c];
    origin_view.time = in.time;
    const DynamicsFrame dynamics = in.first_view ? plan_view_dynamics(in.dynamics, *in.first_view, &plan, origin_view)
                                                 : plan_dynamics(&in.dynamics, &plan, &in.log, origin_view);

    const ViewCulling culling(view_projection, in.depth_mode);
    frusta.culling[0] = &culling;
    // An orthographic view's axis (a shadow cascade's, a top-down map's, a warp of one with
    // parallel rays): its rays are parallel to it, and it is the direction towards the viewer
    // in the lighting. Zero: perspective (a stereo frame's eyes are). A perspective view's rays
    // start at its centre of projection: the camera (zero), or where an off-centre or warped
    // projection puts it (zero in stereo: each eye's own).
    for (int c = 0; c < 3; ++c) {
        plan.frame.target[1 + c] = culling.orthographic() && !stereo ? static_cast<float>(culling.axis()[c]) : 0.0f;
        plan.frame.projection_centre[c] =
            culling.orthographic() || stereo ? 0.0f : static_cast<float>(culling.apex()[c]);
    }
    plan.frame.projection_centre[3] = 0.0f;
    const ViewCulling second_culling(stereo ? second_view_projection : view_projection, in.depth_mode);
    frusta.culling[1] = &second_culling;
    const ScreenScale screen = screen_scale(view.projection, view.viewport[3], culling.orthographic());
    for (uint32_t slot = 0; slot < in.fields.capacity(); ++slot) {
        const Field* field = in.fields.get(slot);
        if (!field) continue;
        if (field->mesh) { // a mesh field: its patches (mesh_plan.hpp)
            plan.stats.blades_submitted +=
                plan_mesh_field(slot, *field->mesh, camera, lod_origin, frusta, &plan.mesh_draws);
            continue;
        }
        FieldPlanner planner(in, slot, *field, *in.patches.get(field->patch_slot), camera, lod_origin, frusta, dynamics,
                             view.flags, plan.depth_pass, screen);
        const grass_result r = planner.run();
        if (r != GRASS_SUCCESS) {
            plan.clear();
            return r;
        }
    }
    if (in.first_view) {
        apply_blade_window(*in.first_view, &plan);
    } else {
        plan_blade_window(&plan, in.blade_window, in.patches, in.dynamics.window, &in.dynamics.window_used);
    }
    plan.compact_blade_window = in.blade_window && in.compact_blade_window;
    plan_gbuffer(ext, &plan); // before the others: a G-buffer view receives no shadows nor lights
    plan_shadow_receive(view, ext, camera, &plan);
    plan_motion(view, ext, camera, in.time, dynamics.wind ? &in.dynamics.wind : nullptr, dynamics.map_up, &plan);
    plan_lights(ext, camera, &plan);
    plan.stats.draws = plan.draws.size();
    plan.stats.plan_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return GRASS_SUCCESS;
}

} // namespace grass
