// Incremental convex hull of the measurements inside a region; see MeasurementHull.h.
#include "core/rgmap/describe/MeasurementHull.h"

#include "core/lines/ScanPoints.h"

namespace rgnav {

void MeasurementHull::addBeams(const RegionBeams& beams) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(beams.beams.size() + vertices_.size());
  for (const RegionBeam& b : beams.beams)
    if (b.hit) points.push_back(b.end);
  if (!points.empty()) extend(std::move(points));
}

void MeasurementHull::mergeFrom(const MeasurementHull& other, const Pose2D& otherInThis) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(other.vertices_.size() + vertices_.size());
  for (const Eigen::Vector2d& v : other.vertices_) points.push_back(transformPoint(otherInThis, v));
  if (!points.empty()) extend(std::move(points));
}

void MeasurementHull::extend(std::vector<Eigen::Vector2d> points) {
  points.insert(points.end(), vertices_.begin(), vertices_.end());
  vertices_ = convexHull(std::move(points));
}

}  // namespace rgnav
