// Statistics of measured samples (frame times, pixel differences).
#pragma once

#include <vector>

namespace grass_sample {

// The median; the mean of the two middle values for an even count; NaN for none.
double median(std::vector<double> v);
// The upper of the two middle values for an even count (what grass-measure tier-cost reports).
double median_high(std::vector<double> v);
// The smallest value: the fastest of a set of frame times.
double fastest(const std::vector<double>& v);
double mean(const std::vector<float>& v);
// The q-quantile (0..1), nearest rank; 0 for none.
double percentile(std::vector<float> v, double q);

} // namespace grass_sample
