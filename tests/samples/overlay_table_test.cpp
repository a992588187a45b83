// The viewer overlay's tier table (samples/viewer/overlay_table.cpp): columns aligned and
// apart however large the numbers (it once showed cells 12902422 and 2.764 GPU ms as
// "12902422.764").
#include "overlay_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

grass_frame_stats stats_with(uint64_t instances, uint64_t cells) {
    grass_frame_stats stats{};
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
        stats.instances[k] = instances;
        stats.cells[k] = cells;
    }
    return stats;
}

// The fields of a line, split at runs of two or more spaces (leading ones dropped). No
// std::regex: GCC 12 warns inside it under the sanitizers (maybe-uninitialized).
std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    size_t at = line.find_first_not_of(' ');
    while (at != std::string::npos) {
        size_t gap = line.find("  ", at);
        out.push_back(line.substr(at, gap == std::string::npos ? std::string::npos : gap - at));
        at = gap == std::string::npos ? gap : line.find_first_not_of(' ', gap);
    }
    return out;
}

TEST(OverlayTable, LargeNumbersStayApartAndAligned) {
    grass_frame_stats stats = stats_with(1290, 12902422);
    stats.cells[1] = 7;
    const double ms[GRASS_TIER_KIND_COUNT] = {2.764, 1234.5, 0.001};
    const std::vector<std::string> lines = grass_viewer::tier_table_lines(stats, ms, true);
    ASSERT_EQ(lines.size(), 1u + GRASS_TIER_KIND_COUNT);
    EXPECT_EQ(lines[1].find("12902422.764"), std::string::npos) << lines[1];
    EXPECT_EQ(fields(lines[0]), (std::vector<std::string>{"tier", "instances", "cells", "GPU ms"}));
    EXPECT_EQ(fields(lines[1]), (std::vector<std::string>{"geometry", "1290", "12902422", "2.764"}));
    EXPECT_EQ(fields(lines[2]), (std::vector<std::string>{"volume", "1290", "7", "1234.500"}));
    // Right-aligned: every line is as long, and each number ends where its header ends.
    for (const std::string& line : lines) {
        EXPECT_EQ(line.size(), lines[0].size()) << line;
        const std::vector<std::string> f = fields(line);
        ASSERT_EQ(f.size(), 4u) << line;
        EXPECT_EQ(line.rfind(f[2]) + f[2].size(), lines[0].find("cells") + 5) << line;
        EXPECT_EQ(line.rfind(f[3]) + f[3].size(), line.size()) << line;
    }
}

TEST(OverlayTable, TheLargestCountsStayApart) {
    const grass_frame_stats stats = stats_with(UINT64_MAX, UINT64_MAX);
    const double ms[GRASS_TIER_KIND_COUNT] = {1e6, 1e6, 1e6};
    for (const std::string& line : grass_viewer::tier_table_lines(stats, ms, true)) {
        EXPECT_EQ(fields(line).size(), 4u) << line;
    }
}

TEST(OverlayTable, NoTimeWithoutTimersOrForAnUndrawnTier) {
    grass_frame_stats stats = stats_with(3, 30);
    stats.instances[2] = 0;
    const double ms[GRASS_TIER_KIND_COUNT] = {1.0, 2.0, 3.0};
    const std::vector<std::string> timed = grass_viewer::tier_table_lines(stats, ms, true);
    EXPECT_EQ(fields(timed[1]).back(), "1.000");
    EXPECT_EQ(fields(timed[3]).back(), "-");
    for (const std::string& line : grass_viewer::tier_table_lines(stats, ms, false)) {
        if (line.rfind("tier", 0) != 0) {
            EXPECT_EQ(fields(line).back(), "-") << line;
        }
    }
}

} // namespace
