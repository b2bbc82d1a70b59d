// The Collision Avoidance module's map frame from its pose source (see MapFrameSource.h).
#include "servers/collisionavoidance/MapFrameSource.h"

#include <algorithm>

namespace rgnav {

MapFrameSource::MapFrameSource(PoseSource source, ClientSettings settings, const MapFrameObjects& objects,
                               ModuleHealth& health)
    : source_(source), health_(health) {
  settings.retryBudget = kRetryBudget;
  switch (source) {
    case PoseSource::Odometry: frame_ = Pose2D{}; break;
    case PoseSource::GroundTruth: truth_.emplace(settings, objects.truth); break;
    case PoseSource::ScanMapper: scanMapper_.emplace(settings, objects.scanMapper); break;
    case PoseSource::Localization:
      localization_.emplace(settings, objects.localization);
      laser_.emplace(settings, objects.laser);
      break;
  }
}

void MapFrameSource::refresh(std::span<const LaserScan> scans) {
  if (source_ == PoseSource::Odometry) return;
  try {
    frame_ = ask(scans);
  } catch (const Error& e) {  // NotAvailable, not localized, the module away or failing
    health_.setError("pose_source", e.what());
    return;
  }
  health_.clearError("pose_source");
  health_.add("frame_refreshes");
}

Pose2D MapFrameSource::ask(std::span<const LaserScan> scans) {
  const LaserScan& newest = scans.back();
  switch (source_) {
    case PoseSource::GroundTruth: return mapFromOdometry(truth_->truePose(newest.id), newest.odometry);
    case PoseSource::ScanMapper: return scanMapper_->odomToMap(newest.id, Pose2D{});
    case PoseSource::Localization: return fromLocalization(scans);
    case PoseSource::Odometry: break;
  }
  return Pose2D{};
}

Pose2D MapFrameSource::fromLocalization(std::span<const LaserScan> scans) {
  const ScanEstimate latest = localization_->latestEstimate();
  const auto read = std::find_if(scans.begin(), scans.end(), [&](const LaserScan& s) { return s.id == latest.scanId; });
  const Pose2D odometry = read != scans.end() ? read->odometry : laser_->scan(latest.scanId).odometry;
  return mapFromOdometry(latest.estimate.mapPose, odometry);
}

}  // namespace rgnav
