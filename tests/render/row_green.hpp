// Each row's mean green level over the middle half of the columns: the rows of grass seen
// from above, away from the field's sides (MoireTest, TierBoundaryTest).
#pragma once

#include "headless_host.hpp"

#include <cstdint>
#include <vector>

namespace grass_test {

inline std::vector<double> middle_row_green(const grass_host::Image& image) {
    std::vector<double> mean(image.height, 0.0);
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = image.width / 4; x < 3 * image.width / 4; ++x) mean[y] += image.pixel(x, y)[1];
        mean[y] /= image.width / 2;
    }
    return mean;
}

} // namespace grass_test
