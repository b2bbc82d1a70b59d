// Placing scans into the reference frame and rasterising them.
#include "core/slam/ReferenceMap.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

int pyramidLevelsFor(double maxTranslation, double resolution) {
  const int cells = static_cast<int>(std::ceil(maxTranslation / resolution));
  int levels = 1;
  while ((1 << (levels - 1)) <= cells) ++levels;
  return levels;
}

ReferenceMap::ReferenceMap(const GridConfig& grid, int pyramidLevels) : pyramidLevels_(pyramidLevels), grid_(grid) {
  if (pyramidLevels < 1) throw InvalidArgumentError("slam: a reference map needs at least one pyramid level");
}

void ReferenceMap::clear() {
  points_.clear();
  normals_.clear();
}

void ReferenceMap::add(std::span<const Eigen::Vector2f> points, std::span<const Eigen::Vector2f> normals,
                       const Pose2D& pose) {
  if (points.size() != normals.size()) throw InvalidArgumentError("slam: points and normals differ in number");
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2f& p = points[i];
    const Eigen::Vector2f& n = normals[i];
    points_.emplace_back(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
    normals_.emplace_back(c * n.x() - s * n.y(), s * n.x() + c * n.y());
  }
}

void ReferenceMap::build() {
  grid_.build(points_);
  pyramid_.build(grid_, pyramidLevels_);
}

}  // namespace rgnav
