// BuildingClearance: the floor plan's truth for a round robot (see the header).
#include "tests/eval/routes/BuildingClearance.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/raster/DistanceField.h"

namespace rgnav {

BuildingClearance::BuildingClearance(const OccupancyGrid& plan, double radiusM) : plan_(plan), radiusM_(radiusM) {
  const std::vector<float> squared = squaredDistanceToBlocked(plan);
  distance_.create(plan.height(), plan.width(), CV_32F);
  for (int r = 0; r < plan.height(); ++r)
    for (int c = 0; c < plan.width(); ++c)
      distance_.at<float>(r, c) = std::sqrt(squared[static_cast<std::size_t>(r) * plan.width() + c]);
  const cv::Mat room = distance_ > radiusM / plan.resolution();
  cv::connectedComponents(room, pieces_, 8, CV_32S);
  pieces_.setTo(-1, ~room);
}

bool BuildingClearance::fits(const std::vector<Eigen::Vector2d>& path, double toleranceM) const {
  const double needed = (radiusM_ - toleranceM) / plan_.resolution();
  for (std::size_t i = 0; i + 1 < path.size() || (i == 0 && path.size() == 1); ++i) {
    const Eigen::Vector2d a = path[i], b = i + 1 < path.size() ? path[i + 1] : path[i];
    const int samples = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.025)));
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2d p = a + (b - a) * (double(k) / samples);
      const auto cell = plan_.cellOf({p.x(), p.y()});
      if (!cell || distance_.at<float>(cell->row, cell->col) < needed) return false;
    }
  }
  return true;
}

}  // namespace rgnav
