// Level h from level h-1: a horizontal then a vertical maximum of cells 2^(h-1) apart.
#include "core/slam/LikelihoodPyramid.h"

#include <algorithm>

#include "core/common/Errors.h"

namespace rgnav {

void LikelihoodPyramid::build(const PointGrid& grid, int levels) {
  if (levels < 1) throw InvalidArgumentError("slam: a likelihood pyramid needs at least one level");
  padding_ = (1 << (levels - 1)) - 1;
  width_ = grid.width() + 2 * padding_;
  height_ = grid.height() + 2 * padding_;
  const std::size_t w = static_cast<std::size_t>(width_);
  const std::size_t cells = w * static_cast<std::size_t>(height_);
  levels_.resize(static_cast<std::size_t>(levels));
  std::vector<std::uint8_t>& base = levels_[0];
  base.assign(cells, 0);
  const auto fine = grid.likelihoods();
  for (int y = 0; y < grid.height(); ++y)
    std::copy_n(fine.begin() + static_cast<std::ptrdiff_t>(y) * grid.width(), grid.width(),
                base.begin() + static_cast<std::ptrdiff_t>((y + padding_) * width_ + padding_));
  scratch_.resize(cells);
  for (int h = 1; h < levels; ++h) {
    const std::size_t half = std::size_t{1} << (h - 1);
    const std::uint8_t* in = levels_[static_cast<std::size_t>(h - 1)].data();
    std::uint8_t* tmp = scratch_.data();
    for (std::size_t row = 0; row < cells; row += w) {
      for (std::size_t x = 0; x + half < w; ++x) tmp[row + x] = std::max(in[row + x], in[row + x + half]);
      for (std::size_t x = w - half; x < w; ++x) tmp[row + x] = in[row + x];
    }
    std::vector<std::uint8_t>& outLevel = levels_[static_cast<std::size_t>(h)];
    outLevel.resize(cells);
    std::uint8_t* out = outLevel.data();
    const std::size_t shift = half * w;
    for (std::size_t k = 0; k + shift < cells; ++k) out[k] = std::max(tmp[k], tmp[k + shift]);
    std::copy(tmp + (cells - shift), tmp + cells, out + (cells - shift));
  }
}

}  // namespace rgnav
