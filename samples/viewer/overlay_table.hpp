// The overlay's tier table as text: one line per tier kind under a header, each column as
// wide as its widest entry, numbers right-aligned, two spaces between columns, so that no two
// numbers run together in the overlay's monospaced font, however large (samples/viewer).
#pragma once

#include <grass/grass.h>

#include <string>
#include <vector>

namespace grass_viewer {

// "tier  instances  cells  GPU ms" and a line per tier kind (geometry, volume, image). A
// tier's GPU ms is "-" when the timers are not available or the tier drew nothing (an
// undrawn tier has no time of its own).
std::vector<std::string> tier_table_lines(const grass_frame_stats& stats, const double gpu_ms[GRASS_TIER_KIND_COUNT],
                                          bool gpu_available);

} // namespace grass_viewer
