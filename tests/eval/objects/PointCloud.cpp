// Thinned tour point cloud; see PointCloud.h.
#include "tests/eval/objects/PointCloud.h"

#include <cmath>

#include "core/lines/ScanPoints.h"

namespace rgnav {

PointCloud::PointCloud(double cellSizeM, double thinningM) : push_(0.5 * cellSizeM), thinning_(thinningM) {}

void PointCloud::add(const LaserScan& scan) {
  const Eigen::Vector2d sensor(scan.sensorPose.x, scan.sensorPose.y);
  for (const ScanPoint& p : scanPoints(scan, scan.sensorPose)) {
    const auto ix = static_cast<std::int64_t>(std::floor(p.position.x() / thinning_));
    const auto iy = static_cast<std::int64_t>(std::floor(p.position.y() / thinning_));
    if (!occupied_.insert((std::uint64_t(ix) << 32) ^ (std::uint64_t(iy) & 0xffffffffULL)).second) continue;
    points_.push_back({p.position, p.position + push_ * (p.position - sensor).normalized()});
  }
}

}  // namespace rgnav
