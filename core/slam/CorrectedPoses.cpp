// Look-up by ID (binary search) and the odometry interpolation between keyframes, with the
// keyframes' current poses or those of a kept revision.
#include "core/slam/CorrectedPoses.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// The pose of `scan` with keyframe k at poseOf(k), for the keyframes 0 .. keyframeCount - 1.
template <class PoseOf>
Pose2D blendedPose(const SlamState& state, const ScanRecord& scan, PoseOf poseOf, std::size_t keyframeCount) {
  if (scan.keyframe != kNoKeyframe) return poseOf(scan.keyframe);
  const Keyframe& before = state.keyframes[scan.previousKeyframe];
  const Pose2D fromBefore = compose(poseOf(scan.previousKeyframe), between(before.odometry, scan.odometry));
  if (scan.previousKeyframe + 1 >= keyframeCount) return fromBefore;
  const Keyframe& after = state.keyframes[scan.previousKeyframe + 1];
  const Pose2D fromAfter = compose(poseOf(scan.previousKeyframe + 1), between(after.odometry, scan.odometry));
  const double f = static_cast<double>(scan.id - before.scanId) / static_cast<double>(after.scanId - before.scanId);
  return {fromBefore.x + f * (fromAfter.x - fromBefore.x), fromBefore.y + f * (fromAfter.y - fromBefore.y),
          normalizeAngle(fromBefore.theta + f * normalizeAngle(fromAfter.theta - fromBefore.theta))};
}

Pose2D correctedPose(const SlamState& state, const ScanRecord& scan) {
  return blendedPose(
      state, scan, [&state](KeyframeIndex k) { return state.keyframes[k].pose; }, state.keyframes.size());
}

const ScanRecord& inputScan(const SlamState& state, DataId scanId) {
  const auto it = firstScanFrom(state, scanId);
  if (it == state.scans.end() || it->id != scanId)
    throw NotAvailableError("slam: no scan with ID " + std::to_string(scanId) + " was input");
  return *it;
}

}  // namespace

std::vector<ScanRecord>::const_iterator firstScanFrom(const SlamState& state, DataId scanId) {
  return std::lower_bound(state.scans.begin(), state.scans.end(), scanId,
                          [](const ScanRecord& scan, DataId id) { return scan.id < id; });
}

const PoseRevision& keptRevision(const SlamState& state, std::uint64_t revision) {
  const auto kept = std::lower_bound(state.revisions.begin(), state.revisions.end(), revision,
                                     [](const PoseRevision& r, std::uint64_t number) { return r.number < number; });
  if (kept == state.revisions.end() || kept->number != revision)
    throw NotAvailableError("slam: revision " + std::to_string(revision) + " is not kept");
  return *kept;
}

Pose2D correctedPose(const SlamState& state, DataId scanId) { return correctedPose(state, inputScan(state, scanId)); }

Pose2D mappedPose(const SlamState& state, DataId scanId) { return inputScan(state, scanId).mapped; }

Pose2D revisedPose(const SlamState& state, DataId scanId, std::uint64_t revision) {
  const PoseRevision& kept = keptRevision(state, revision);
  const ScanRecord& scan = inputScan(state, scanId);
  if (scanId >= kept.atScan)
    throw InvalidArgumentError("slam: scan " + std::to_string(scanId) + " was input after revision " +
                               std::to_string(revision));
  const std::vector<Pose2D>& poses = kept.keyframePoses;
  return blendedPose(state, scan, [&poses](KeyframeIndex k) { return poses[k]; }, poses.size());
}

Pose2D odomToMap(const SlamState& state, DataId scanId, const Pose2D& odometryPose) {
  if (state.scans.empty()) throw NotAvailableError("slam: no scan was input yet");
  auto it = firstScanFrom(state, scanId);
  if (it == state.scans.end() || (it != state.scans.begin() && it->id - scanId >= scanId - std::prev(it)->id)) --it;
  return compose(compose(correctedPose(state, *it), inverse(it->odometry)), odometryPose);
}

}  // namespace rgnav
