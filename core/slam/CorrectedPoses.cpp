// Look-up by ID (binary search) and the odometry interpolation between keyframes.
#include "core/slam/CorrectedPoses.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

Pose2D correctedPose(const SlamState& state, const ScanRecord& scan) {
  if (scan.keyframe != kNoKeyframe) return state.keyframes[scan.keyframe].pose;
  const Keyframe& before = state.keyframes[scan.previousKeyframe];
  const Pose2D fromBefore = compose(before.pose, between(before.odometry, scan.odometry));
  if (scan.previousKeyframe + 1 >= state.keyframes.size()) return fromBefore;
  const Keyframe& after = state.keyframes[scan.previousKeyframe + 1];
  const Pose2D fromAfter = compose(after.pose, between(after.odometry, scan.odometry));
  const double f = static_cast<double>(scan.id - before.scanId) / static_cast<double>(after.scanId - before.scanId);
  return {fromBefore.x + f * (fromAfter.x - fromBefore.x), fromBefore.y + f * (fromAfter.y - fromBefore.y),
          normalizeAngle(fromBefore.theta + f * normalizeAngle(fromAfter.theta - fromBefore.theta))};
}

std::vector<ScanRecord>::const_iterator lowerBound(const SlamState& state, DataId scanId) {
  return std::lower_bound(state.scans.begin(), state.scans.end(), scanId,
                          [](const ScanRecord& scan, DataId id) { return scan.id < id; });
}

}  // namespace

Pose2D correctedPose(const SlamState& state, DataId scanId) {
  const auto it = lowerBound(state, scanId);
  if (it == state.scans.end() || it->id != scanId)
    throw NotAvailableError("slam: no scan with ID " + std::to_string(scanId) + " was input");
  return correctedPose(state, *it);
}

Pose2D odomToMap(const SlamState& state, DataId scanId, const Pose2D& odometryPose) {
  if (state.scans.empty()) throw NotAvailableError("slam: no scan was input yet");
  auto it = lowerBound(state, scanId);
  if (it == state.scans.end() || (it != state.scans.begin() && it->id - scanId >= scanId - std::prev(it)->id)) --it;
  return compose(compose(correctedPose(state, *it), inverse(it->odometry)), odometryPose);
}

}  // namespace rgnav
