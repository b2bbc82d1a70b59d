// connectedComponents: labels the 8-connected sets of cells of a mask, dropping small ones.
// Used for ground-truth rooms (8-connected free components, floorplans/SOURCES.md) and door
// separator blobs (4- and 8-connectivity give the same blobs on all ten benchmark maps).
#pragma once

#include <cstdint>
#include <vector>

namespace rgnav {

struct Components {
  std::vector<int> labels;  // per cell: component 0..count-1, or -1 (not in the mask, or dropped)
  std::vector<int> sizes;   // cells per component
  int count() const { return static_cast<int>(sizes.size()); }
};

// `mask` is row-major, width x height, non-zero = in the set. Components with fewer than
// `minSize` cells are dropped; the others are numbered in the order of their first cell.
Components connectedComponents(const std::vector<std::uint8_t>& mask, int width, int height, int minSize);

}  // namespace rgnav
