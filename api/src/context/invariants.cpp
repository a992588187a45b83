#include "context/invariants.hpp"

#include "context/context.hpp"
#include "foundation/names.hpp"
#include "foundation/raw_enum.hpp"

namespace grass {

grass_result check_slice_set(grass_context* ctx, const char* fn, uint32_t patch_slot, const SliceSet& set) {
    const uint32_t n = set.slices_per_axis;
    if (!ctx->patches.get(patch_slot)) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                         "%s: baked slices (N = %u) for patch slot %u, which holds no patch (internal error)", fn, n,
                         patch_slot);
    }
    uint32_t full_chain = 1;
    for (uint32_t larger = set.width > set.height ? set.width : set.height; larger > 1; larger >>= 1) ++full_chain;
    const bool shape_ok = set.width > 0 && set.height > 0 && set.layers == slice_layer_count(n) &&
                          set.mip_levels >= 1 && set.mip_levels <= full_chain;
    const uint64_t values = shape_ok ? set.offset(set.layers, 0) * 4 : 0; // RGBA: every level of every layer
    if (!shape_ok || set.color.size() != values || set.normal.size() != values || set.threshold.size() != values) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                         "%s: the baked slice set (N = %u) of patch slot %u is malformed: %u layers of %ux%u texels, "
                         "%u mip levels, %zu/%zu/%zu colour/normal/threshold values (internal error)",
                         fn, n, patch_slot, set.layers, set.width, set.height, set.mip_levels, set.color.size(),
                         set.normal.size(), set.threshold.size());
    }
    return GRASS_SUCCESS;
}

grass_result check_field_maps(grass_context* ctx, const char* fn, uint32_t field_slot, const FieldMaps& maps) {
    for (uint32_t role = 0; role < kMapRoleCount; ++role) {
        const uint32_t slot = maps.map_slot[role];
        const bool sampled = ((maps.features >> role) & 1u) != 0;
        const DesignMap* map = slot != kNoMap ? ctx->maps.get(slot) : nullptr;
        const uint32_t channels = role == kMapColor ? 4u : 1u;
        if (sampled != (slot != kNoMap) || (slot != kNoMap && (!map || map->channels != channels))) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: field slot %u samples map role %u from map slot %u (feature mask 0x%x), which holds "
                             "no map with %u channel(s) (internal error)",
                             fn, field_slot, role, slot, maps.features, channels);
        }
    }
    if ((maps.features >> kMapRoleCount) != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                         "%s: field slot %u has the feature mask 0x%x, beyond the %u map roles (internal error)", fn,
                         field_slot, maps.features, kMapRoleCount);
    }
    return GRASS_SUCCESS;
}

grass_result check_plan(grass_context* ctx, const char* fn, const FramePlan& plan) {
    const bool drawing = ctx->backend->kind() != GRASS_BACKEND_NONE; // only a drawing backend gets baked slices
    for (const TierDraw& draw : plan.draws) {
        const Field* field = ctx->fields.get(draw.field_slot);
        const Patch* patch = ctx->patches.get(draw.patch_slot);
        const int64_t kind = raw_enum(draw.kind); // a broken plan may hold any value
        const bool known_kind = kind == GRASS_TIER_GEOMETRY || kind == GRASS_TIER_VOLUME || kind == GRASS_TIER_IMAGE;
        const bool instances_ok = uint64_t(draw.first_instance) + draw.instance_count <= plan.instances.size();
        if (!known_kind || !field || !patch || field->patch_slot != draw.patch_slot || !instances_ok) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: the frame plan has a %s draw of patch slot %u, field slot %u, instances %u+%u of "
                             "%zu, which the context does not hold (internal error)",
                             fn, known_kind ? tier_kind_name(draw.kind) : "unknown", draw.patch_slot, draw.field_slot,
                             draw.first_instance, draw.instance_count, plan.instances.size());
        }
        // The maps' bits are the field's; past them only the responsive bits, the interaction
        // one only while the map is bound, the culling one on geometry draws only, the debug
        // view's exactly when the frame draws one, the blade window's on responsive geometry
        // draws of a backend that runs the window, the depth pass's exactly on a depth view, the shadow
        // receiver's exactly on a receiving view, the G-buffer's exactly on a G-buffer view.
        const uint32_t map_bits = (1u << kMapRoleCount) - 1u;
        const uint32_t dynamics_bits = draw.features & ~map_bits;
        const bool debug_ok = ((draw.features & kFeatureDebugView) != 0) == ((plan.flags & kDebugViewFlags) != 0) &&
                              ((draw.features & kFeatureDepthPass) != 0) == plan.depth_pass &&
                              ((draw.features & kFeatureShadowReceive) != 0) == plan.shadow_receive &&
                              ((draw.features & kFeatureMotion) != 0) == plan.motion &&
                              ((draw.features & kFeatureHostLights) != 0) == plan.host_lights &&
                              ((draw.features & kFeatureGBuffer) != 0) == plan.gbuffer;
        const bool dynamics_ok =
            (dynamics_bits &
             ~(kBladeCurveFeatures | kFeatureWindMap | kFeatureDebugView | kFeatureDepthPass | kFeatureShadowReceive |
               kFeatureMotion | kFeatureHostLights | kFeatureGBuffer | kFeatureBladeWindow)) == 0 &&
            ((dynamics_bits & kFeatureBladeWindow) == 0 ||
             (draw.kind == GRASS_TIER_GEOMETRY && (dynamics_bits & (kFeatureWind | kFeatureInteraction)) != 0 &&
              ctx->backend->runs_blade_window())) &&
            ((dynamics_bits & kFeatureInteraction) == 0 || plan.interaction.levels > 0) &&
            ((dynamics_bits & kFeatureWindMap) != 0) == field->wind_map.active() &&
            ((dynamics_bits & kFeatureWindMap) == 0 || (dynamics_bits & kFeatureWind) != 0) &&
            ((dynamics_bits & kFeatureBladeCulling) == 0 || draw.kind == GRASS_TIER_GEOMETRY);
        if ((draw.features & map_bits) != field->maps.features || !dynamics_ok || !debug_ok ||
            draw.features != draw.uniforms.tiling[3]) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: a draw of field slot %u has the feature mask 0x%x (0x%x in its uniforms), the field "
                             "0x%x, the interaction map %u level(s) (internal error)",
                             fn, draw.field_slot, draw.features, draw.uniforms.tiling[3], field->maps.features,
                             plan.interaction.levels);
        }
        // A geometry draw's index range lies in its patch's indices (the blades' levels); the
        // others have none.
        const bool indices_ok = draw.kind == GRASS_TIER_GEOMETRY
                                    ? (draw.vertex_count == 0 || (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0 ||
                                       uint64_t(draw.first_index) + draw.vertex_count <= patch->data.indices.size())
                                    : draw.first_index == 0 && draw.blade_level == 0;
        if (!indices_ok) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: a %s draw of patch slot %u has the indices %u+%u of %zu (internal error)", fn,
                             tier_kind_name(draw.kind), draw.patch_slot, draw.first_index, draw.vertex_count,
                             patch->data.indices.size());
        }
        if (drawing && draw.kind != GRASS_TIER_GEOMETRY && !patch->slices(draw_slice_set(draw))) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: tier %u (%s) of field slot %u draws patch slot %u with %u slices per axis, but no "
                             "such slice set was uploaded for that patch (internal error: the core uploads every "
                             "set a field's tiers need at field creation)",
                             fn, draw.tier, tier_kind_name(draw.kind), draw.field_slot, draw.patch_slot,
                             draw_slice_set(draw));
        }
    }
    return plan.interaction.pass ? check_interaction_plan(ctx, fn, plan.interaction) : GRASS_SUCCESS;
}

grass_result check_interaction_plan(grass_context* ctx, const char* fn, const InteractionPlan& ip) {
    for (uint32_t l = 0; l < ip.levels; ++l) {
        const uint32_t tiles = ip.level[l].counts[2];
        const Vector<uint32_t>& offsets = ip.tile_offsets[l];
        bool ok = ip.levels <= 2 && tiles * ip.level[l].counts[1] == ip.resolution &&
                  offsets.size() == size_t(tiles) * tiles + 1 && offsets.front() == 0 &&
                  offsets.back() == ip.tile_colliders[l].size();
        for (size_t t = 1; ok && t < offsets.size(); ++t) ok = offsets[t - 1] <= offsets[t];
        for (uint32_t i : ip.tile_colliders[l]) ok = ok && i < ip.colliders.size();
        if (!ok) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: level %u of the interaction plan has malformed tile lists (%u tiles per side, %zu "
                             "offsets, %zu entries, %zu colliders; internal error)",
                             fn, l, tiles, offsets.size(), ip.tile_colliders[l].size(), ip.colliders.size());
        }
    }
    return GRASS_SUCCESS;
}

} // namespace grass
