// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc; docs/engine-frames.md
// "Deferred renderers"): what such a view adds to its plan.
#pragma once

#include "foundation/frame_plan.hpp"
#include "foundation/shader_variants.hpp"
#include "plan/frame_planner.hpp"

#include <grass/grass.h>

namespace grass {

// The write mask an attachment gets: its own, or by default its semantic's (rgb for albedo
// and normal, rg for material and velocity).
uint32_t gbuffer_write_mask(const grass_gbuffer_attachment& a);

// Where the outputs of a G-buffer view of layout `d` (validated) go: the attachment of each
// output's semantic and its write mask (a view's plan, and grass_prepare_pipelines).
GBufferLayout gbuffer_layout(const grass_view_gbuffer_desc& d);

// A view whose pass is GRASS_PASS_GBUFFER (validated: it has a layout): every draw gets
// kFeatureGBuffer, and the plan where each output location goes (the host's attachment of
// its semantic), its colour mask and the normal's encoding (the NORMAL attachment's format).
// Any other view: plan.gbuffer false and no routes.
void plan_gbuffer(const ViewExtensions& ext, FramePlan* plan);

} // namespace grass
