// Corrected poses from another file of the run, matched by stamp; see StampedPoses.h.
#include "tests/eval/localization/StampedPoses.h"

#include <algorithm>
#include <cmath>

#include "core/logs/OpenLog.h"

namespace rgnav {

std::vector<StampedPose> readScanPoses(const std::string& path) {
  std::vector<StampedPose> poses;
  for (const LaserScan& scan : readLaserScans(path)) poses.push_back({scan.stamp, scan.sensorPose});
  std::stable_sort(poses.begin(), poses.end(), [](const StampedPose& a, const StampedPose& b) { return a.stamp < b.stamp; });
  return poses;
}

PoseMatch matchByStamp(std::span<const LaserScan> scans, std::span<const StampedPose> poses, double offsetS,
                       double toleranceS) {
  PoseMatch match;
  for (const LaserScan& scan : scans) {
    const double wanted = scan.stamp - offsetS;
    const auto after = std::lower_bound(poses.begin(), poses.end(), wanted,
                                        [](const StampedPose& p, double stamp) { return p.stamp < stamp; });
    std::optional<Pose2D> nearest;
    double nearestGap = toleranceS;
    for (auto it : {after, after == poses.begin() ? poses.end() : after - 1}) {
      if (it == poses.end()) continue;
      const double gap = std::abs(it->stamp - wanted);
      if (gap <= nearestGap) {
        nearestGap = gap;
        nearest = it->pose;
      }
    }
    match.matched += nearest.has_value();
    match.poses.push_back(nearest);
  }
  return match;
}

}  // namespace rgnav
