// Order statistics for benchmark and fault-test figures: the median and nearest-rank percentiles
// of a sample (0 for an empty sample).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace rgnav::testing {

// The value at rank round(p * (n - 1)) of the sorted sample, p in [0, 1].
inline double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(p * double(values.size() - 1) + 0.5))];
}

// The upper median: the value at rank n / 2 of the sorted sample.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace rgnav::testing
