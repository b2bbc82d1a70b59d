// connectedComponents: labels the 8-connected sets of cells of a mask (cv::connectedComponentsWithStats),
// dropping small ones. Used for ground-truth rooms (8-connected free components,
// floorplans/SOURCES.md), door separator blobs (4- and 8-connectivity give the same blobs on all
// ten benchmark maps) and furniture blobs.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace rgnav {

struct Components {
  std::vector<int> labels;  // per cell, row-major: component 0..count-1, or -1 (not in the mask, or dropped)
  std::vector<int> sizes;   // cells per component
  int count() const { return static_cast<int>(sizes.size()); }
};

// `mask` is an 8-bit single-channel Mat, non-zero = in the set (throws InvalidArgumentError
// otherwise). Components with fewer than `minSize` cells are dropped; the others are numbered in
// the order of their first cell in row-major order.
Components connectedComponents(const cv::Mat& mask, int minSize);

}  // namespace rgnav
