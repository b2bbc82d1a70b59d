// The per-scan pipeline: filter, local registration, submaps, loop search, incremental
// optimisation.
#include "core/slam/ScanMapper.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"
#include "core/slam/CorrectedPoses.h"
#include "core/slam/KeyframeFilter.h"
#include "core/slam/OdometryModel.h"
#include "core/slam/PoseGraph.h"
#include "core/slam/ScanPoints.h"
#include "core/slam/ScanRegistration.h"
#include "core/slam/SlamStateCodec.h"

namespace rgnav {

namespace {

// An information matrix of a pose error in the map frame, re-expressed in a frame rotated by theta.
Eigen::Matrix3d rotateInformation(const Eigen::Matrix3d& information, double theta) {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  rotation.topLeftCorner<2, 2>() << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return rotation.transpose() * information * rotation;
}

const SlamConfig& validated(const SlamConfig& config) {
  validate(config);
  return config;
}

}  // namespace

ScanMapper::ScanMapper(const SlamConfig& config, SlamState state)
    : config_(validated(config)),
      state_(std::move(state)),
      localReference_(config.local.grid, pyramidLevelsFor(config.local.searchTranslation, config.local.grid.resolution)),
      loopCloser_(config.loop, config.icp) {
  validate(state_);
  normals_.reserve(state_.keyframes.size());
  for (const Keyframe& keyframe : state_.keyframes) normals_.push_back(estimateNormals(keyframe.points, config_.points));
}

ScanOutcome ScanMapper::addScan(const LaserScan& scan) {
  if (scan.id <= lastInputId())
    throw InvalidArgumentError("slam: scan ID " + std::to_string(scan.id) + " does not follow the last input ID " +
                               std::to_string(lastInputId()));
  ScanOutcome outcome;
  const bool keyframe =
      state_.keyframes.empty() || isKeyframe(state_.keyframes.back().odometry, scan.odometry, config_.filter);
  if (keyframe) addKeyframe(scan, outcome);
  const auto latest = static_cast<KeyframeIndex>(state_.keyframes.size() - 1);
  state_.scans.push_back({scan.id, scan.stamp, scan.odometry, keyframe ? latest : kNoKeyframe, latest, {}});
  state_.scans.back().mapped = rgnav::correctedPose(state_, scan.id);
  return outcome;
}

void ScanMapper::addKeyframe(const LaserScan& scan, ScanOutcome& outcome) {
  outcome.keyframe = true;
  std::vector<Eigen::Vector2f> points = scanToPoints(scan, config_.points);
  Pose2D pose = scan.odometry;  // the first keyframe fixes the map frame to the odometry frame
  if (!state_.keyframes.empty()) {
    const LocalRegistration local = registerLocally(points, scan.odometry);
    const Keyframe& previous = state_.keyframes.back();
    pose = local.pose;
    outcome.registered = local.registered;
    if (!local.registered) ++state_.counters.failedRegistrations;
    state_.distanceSinceLoop += std::hypot(pose.x - previous.pose.x, pose.y - previous.pose.y);
    Constraint sequential;
    sequential.kind = Constraint::Kind::Sequential;
    sequential.from = static_cast<KeyframeIndex>(state_.keyframes.size() - 1);
    sequential.to = static_cast<KeyframeIndex>(state_.keyframes.size());
    sequential.measurement = between(previous.pose, pose);
    sequential.information = rotateInformation(local.information, previous.pose.theta);
    state_.constraints.push_back(sequential);
  }
  normals_.push_back(estimateNormals(points, config_.points));
  state_.keyframes.push_back({scan.id, scan.odometry, pose, std::move(points)});
  addSubmapIfComplete();
  bool largeCorrection = false;
  outcome.loopsAdded = closeLoops(largeCorrection);
  const bool due =
      state_.keyframes.size() - state_.keyframesAtLastOptimization >= config_.graph.keyframesBetweenOptimizations;
  if (state_.pendingLoops > 0 && (largeCorrection || due)) {
    runOptimization(scan.id);
    outcome.optimized = true;
  }
}

ScanMapper::LocalRegistration ScanMapper::registerLocally(const std::vector<Eigen::Vector2f>& points,
                                                          const Pose2D& odometry) {
  const Keyframe& previous = state_.keyframes.back();
  const Pose2D motion = between(previous.odometry, odometry);
  const PosePrior prior{compose(previous.pose, motion), odometryInformation(motion, config_.local.odometry)};
  LocalRegistration result{prior.pose, prior.information, false};
  if (points.size() < config_.points.minPoints) return result;

  localReference_.clear();
  const std::size_t count = std::min(config_.local.windowKeyframes, state_.keyframes.size());
  for (std::size_t k = state_.keyframes.size() - count; k < state_.keyframes.size(); ++k)
    localReference_.add(state_.keyframes[k].points, normals_[k], state_.keyframes[k].pose);
  localReference_.build();
  const RegistrationCriteria criteria{{config_.local.searchTranslation, config_.local.searchRotation},
                                     config_.local.minScore,
                                     config_.local.minInlierFraction};
  const auto registration = registerScan(localReference_, points, prior.pose, criteria, config_.icp, &prior);
  if (!registration) return result;
  return {registration->pose, registration->information, true};
}

void ScanMapper::addSubmapIfComplete() {
  const std::size_t first =
      state_.submaps.empty() ? 0 : state_.submaps.back().first + state_.submaps.back().memberPoses.size();
  if (state_.keyframes.size() - first < config_.loop.submapKeyframes) return;
  SubmapRecord submap;
  submap.first = static_cast<KeyframeIndex>(first);
  submap.anchor = static_cast<KeyframeIndex>(first + config_.loop.submapKeyframes / 2);
  const Pose2D& anchor = state_.keyframes[submap.anchor].pose;
  for (std::size_t k = first; k < state_.keyframes.size(); ++k)
    submap.memberPoses.push_back(between(anchor, state_.keyframes[k].pose));
  state_.submaps.push_back(std::move(submap));
}

std::size_t ScanMapper::closeLoops(bool& largeCorrection) {
  const auto current = static_cast<KeyframeIndex>(state_.keyframes.size() - 1);
  const std::vector<Constraint> loops = loopCloser_.search(state_, current, normals_);
  const Pose2D& pose = state_.keyframes[current].pose;
  for (const Constraint& loop : loops) {
    const Pose2D implied = compose(state_.keyframes[loop.from].pose, loop.measurement);
    largeCorrection |= std::hypot(implied.x - pose.x, implied.y - pose.y) > config_.graph.immediateCorrection;
    state_.constraints.push_back(loop);
  }
  if (!loops.empty()) state_.distanceSinceLoop = 0.0;
  state_.pendingLoops += loops.size();
  state_.counters.loopClosures += loops.size();
  return loops.size();
}

void ScanMapper::optimize() {
  if (state_.pendingLoops > 0) runOptimization(lastInputId() + 1);
}

void ScanMapper::runOptimization(DataId atScan) {
  std::vector<Pose2D> poses;
  poses.reserve(state_.keyframes.size());
  for (const Keyframe& keyframe : state_.keyframes) poses.push_back(keyframe.pose);
  optimizePoseGraph(poses, state_.constraints, config_.graph);  // leaves the poses as they were if it fails
  for (std::size_t k = 0; k < poses.size(); ++k) state_.keyframes[k].pose = poses[k];
  state_.pendingLoops = 0;
  state_.keyframesAtLastOptimization = state_.keyframes.size();
  ++state_.counters.optimizations;
  state_.revisions.push_back({state_.counters.optimizations, atScan, std::move(poses)});
  if (state_.revisions.size() > config_.graph.keptRevisions)
    state_.revisions.erase(state_.revisions.begin(),
                           state_.revisions.end() - static_cast<std::ptrdiff_t>(config_.graph.keptRevisions));
}

Pose2D ScanMapper::correctedPose(DataId scanId) const { return rgnav::correctedPose(state_, scanId); }

Pose2D ScanMapper::mappedPose(DataId scanId) const { return rgnav::mappedPose(state_, scanId); }

Pose2D ScanMapper::revisedPose(DataId scanId, std::uint64_t revision) const {
  return rgnav::revisedPose(state_, scanId, revision);
}

void ScanMapper::forgetRevisionsUpTo(std::uint64_t number) {
  std::erase_if(state_.revisions, [number](const PoseRevision& r) { return r.number <= number; });
}

Pose2D ScanMapper::odomToMap(DataId scanId, const Pose2D& odometryPose) const {
  return rgnav::odomToMap(state_, scanId, odometryPose);
}

}  // namespace rgnav
