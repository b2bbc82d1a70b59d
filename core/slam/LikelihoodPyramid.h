// LikelihoodPyramid: the precomputed low-resolution tables of the multi-resolution correlative
// search (Olson 2009; the "precomputation grids" of Hess et al. 2016): level h holds, for every
// cell c, the maximum likelihood of the fine cells [c, c + 2^h) in both axes, so the score of a
// coarse candidate bounds the score of every fine candidate it covers. Level 0 is the grid itself.
// All levels share one padded layout so that building a level is two branch-free max passes.
#pragma once

#include <cstdint>
#include <vector>

#include "core/slam/PointGrid.h"

namespace rgnav {

class LikelihoodPyramid {
 public:
  // Replaces the content with `levels` levels (at least 1) of `grid`. Throws InvalidArgumentError
  // for fewer than one level.
  void build(const PointGrid& grid, int levels);

  int levels() const { return static_cast<int>(levels_.size()); }
  // The maximum over the fine cells [cx, cx + 2^level) x [cy, cy + 2^level); 0 far outside.
  std::uint8_t value(int level, int cx, int cy) const {
    const int x = cx + padding_, y = cy + padding_;
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0;
    return levels_[static_cast<std::size_t>(level)][static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                                                    static_cast<std::size_t>(x)];
  }

 private:
  int padding_ = 0;  // cell c is stored at c + padding_ in both axes
  int width_ = 0;
  int height_ = 0;
  std::vector<std::vector<std::uint8_t>> levels_;
  std::vector<std::uint8_t> scratch_;
};

}  // namespace rgnav
