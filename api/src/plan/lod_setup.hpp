// Tiers and lod tests of a field (lemme2012 6.1.2, 6.2): validation, the default setup,
// and evaluating one built-in test for a node.
#pragma once

#include "foundation/log.hpp"
#include "plan/lod_setup_types.hpp"

#include <grass/grass.h>

namespace grass {

// Validates the tiers and tests of a field desc (or takes the defaults when both are
// empty) and fills `out`. Logs and returns an error naming the bad test or tier.
grass_result make_lod_setup(Log* log, const char* fn, const grass_field_desc& desc, LodSetup* out);

// Answer of a built-in test (not CALLBACK) for a node whose box top lies `node_top` metres
// above the field's plane, the camera `camera_height` metres above it.
grass_lod_answer evaluate_builtin_test(const grass_lod_test& test, const grass_lod_node& node, double node_top,
                                       double camera_height);

} // namespace grass
