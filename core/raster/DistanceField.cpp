// squaredDistanceToBlocked on cv::distanceTransform. OpenCV returns the distance as a float (its
// square root, correctly rounded); squaring it and rounding to the nearest integer gives back the
// exact integer square for every distance below 2048 cells (relative error 2^-23 < 0.5 / d^2),
// far beyond any floor we map (the IPA plans are under 1500 pixels a side).
#include "core/raster/DistanceField.h"

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/raster/GridMat.h"

namespace rgnav {

std::vector<float> squaredDistanceToBlocked(const OccupancyGrid& grid) {
  if (grid.cells().empty()) return {};
  const cv::Mat free = cellMat(grid) == static_cast<int>(Cell::Free);
  if (cv::countNonZero(free) == static_cast<int>(free.total()))
    return std::vector<float>(grid.cells().size(), kNoBlockedCell);
  cv::Mat distance;
  cv::distanceTransform(free, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  std::vector<float> out(grid.cells().size());
  const auto* d = distance.ptr<float>();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(std::round(double(d[i]) * double(d[i])));
  return out;
}

}  // namespace rgnav
