// Jahrmann's dynamic tessellation (jahrmann2017 6.3) without a tessellation stage: coarser
// levels of a blade are index subsets of its quad strip. Level k keeps every 2^k-th row of
// the blade's vertices (a row is the 2 vertices across the blade at one t) and always the tip
// row, so a coarser level is a coarser polyline of the same curve and needs no vertex data.
// The patch's index buffer holds the levels one after another, every blade of level 0 (the
// full strip), then every blade of level 1, and so on down to one quad a blade.
#pragma once

#include "patch/patch_data.hpp"

#include <cstdint>

namespace grass {

// Quads along a blade of `subdivisions` at level `level` (the full strip at level 0).
uint32_t blade_level_segments(uint32_t subdivisions, uint32_t level);

// Levels of a blade of `subdivisions` quads: 1 + ceil(log2(subdivisions)) (1 for one quad).
uint32_t blade_level_count(uint32_t subdivisions);

// Appends the coarser levels' indices to patch->indices (which holds level 0) and fills
// patch->levels, with each level's error: the farthest any blade's full vertex lies from the
// level's outline (its centre line bent less, its pointed width straightened). The content
// hash is not changed: the coarser levels follow from level 0.
void add_blade_levels(uint32_t subdivisions, PatchData* patch);

} // namespace grass
