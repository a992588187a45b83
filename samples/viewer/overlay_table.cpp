#include "overlay_table.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace grass_viewer {

std::vector<std::string> tier_table_lines(const grass_frame_stats& stats, const double gpu_ms[GRASS_TIER_KIND_COUNT],
                                          bool gpu_available) {
    constexpr int kColumns = 4;
    static const char* const kKinds[GRASS_TIER_KIND_COUNT] = {"geometry", "volume", "image"};
    std::vector<std::array<std::string, kColumns>> rows;
    rows.push_back({"tier", "instances", "cells", "GPU ms"});
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
        char ms[32] = "-";
        if (gpu_available && stats.instances[k] != 0) std::snprintf(ms, sizeof(ms), "%.3f", gpu_ms[k]);
        rows.push_back({kKinds[k], std::to_string(stats.instances[k]), std::to_string(stats.cells[k]), ms});
    }
    size_t width[kColumns] = {};
    for (const auto& row : rows) {
        for (int c = 0; c < kColumns; ++c) width[c] = std::max(width[c], row[c].size());
    }
    std::vector<std::string> lines;
    for (const auto& row : rows) {
        std::string line = row[0] + std::string(width[0] - row[0].size(), ' '); // the name: left-aligned
        for (int c = 1; c < kColumns; ++c) line += "  " + std::string(width[c] - row[c].size(), ' ') + row[c];
        lines.push_back(line);
    }
    return lines;
}

} // namespace grass_viewer
