// What every backend relies on the core for, checked once here rather than in each
// backend: the frame plan agrees with the fields, patches, maps and baked slice sets the
// core uploaded, a field's feature mask with its maps, a baked slice set with its layout
// contract (baked_slices.hpp). A broken invariant is a bug in grass, not the host's doing:
// GRASS_ERROR_INVALID_STATE with GRASS_MSG_INTERNAL_ERROR, whatever the backend.
// What only a backend can know (a GPU call failed, a Vulkan upload not recorded yet) stays
// in the backend.
#pragma once

#include "bake/baked_slices.hpp"
#include "context/backend.hpp"

#include <grass/grass.h>

#include <cstdint>

struct grass_context;

namespace grass {

// `set`, about to be uploaded for the patch in `patch_slot`: a live patch, 2N + 1 layers
// (1 for N = 0), a mip chain no longer than the full one, and arrays of the sizes its
// dimensions give.
grass_result check_slice_set(grass_context* ctx, const char* fn, uint32_t patch_slot, const SliceSet& set);

// `maps`, about to be uploaded for the field in `field_slot`: bit r of the feature mask set
// exactly where role r has a map, each such map live with the channels of its role.
grass_result check_field_maps(grass_context* ctx, const char* fn, uint32_t field_slot, const FieldMaps& maps);

// A view's plan, just built: each draw of a known tier kind, of a live field and its
// patch, within the plan's instances, with the field's feature mask, and (volume and image
// draws, on a backend that draws) of a slice set the core uploaded for the patch; the
// responsive feature bits only past the map roles (kFeatureInteraction only while the map is
// bound); and the interaction plan (check_interaction_plan).
grass_result check_plan(grass_context* ctx, const char* fn, const FramePlan& plan);

// Each level's tile lists: tiles^2 + 1 ascending offsets covering every entry, each entry a
// collider of the plan, tiles x tile size = the resolution.
grass_result check_interaction_plan(grass_context* ctx, const char* fn, const InteractionPlan& plan);

} // namespace grass
