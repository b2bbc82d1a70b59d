// ScanMapper: the SLAM core of the ScanMapper module (thesis 5.2, issue 5). The thesis used
// Gutmann & Konolige's Local Registration / Global Correlation; this is a graph-based
// counterpart: each scan passing the distance/angle filter becomes a keyframe, registered against
// the recent keyframes (correlative search + point-to-line refinement fused with the odometry
// prediction); older keyframes are grouped into rigid submaps that revisits are correlated
// against; loop constraints trigger an incremental pose graph optimisation (Ceres). Every input
// scan ID gets a corrected pose, and the odometry -> map transform at any scan ID (thesis 3.3.5).
// For consumers that follow the map as it was made, every scan also keeps its pose as mapped
// (right after it was input) and every optimisation its keyframe poses (the latest
// graph.keptRevisions of them), so that they can replay the same sequence of poses whenever
// they read.
// All state that matters lives in a SlamState, which the caller can serialise and restore.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"
#include "core/slam/LoopCloser.h"
#include "core/slam/ReferenceMap.h"
#include "core/slam/SlamConfig.h"
#include "core/slam/SlamState.h"

namespace rgnav {

struct ScanOutcome {
  bool keyframe = false;        // taken into the map
  bool registered = false;      // a keyframe registered by its points (not odometry alone)
  std::size_t loopsAdded = 0;   // loop constraints found for it
  bool optimized = false;       // the pose graph was optimised after it
};

class ScanMapper {
 public:
  // Resumes from `state` (empty: a new map); with the configuration the state was made with, it
  // continues exactly as the mapper that made the state would have. Throws ConfigError for an
  // invalid configuration, InvalidArgumentError for a state whose parts do not fit together.
  explicit ScanMapper(const SlamConfig& config = {}, SlamState state = {});

  // Processes the next scan. Its ID must exceed lastInputId() (InvalidArgumentError otherwise;
  // the state is unchanged then).
  ScanOutcome addScan(const LaserScan& scan);

  // Optimises now if loop constraints are pending (e.g. at the end of a log).
  void optimize();

  // Corrected pose of an input scan (NotAvailableError for an unknown ID).
  Pose2D correctedPose(DataId scanId) const;
  // Its pose right after it was input (ScanRecord::mapped; NotAvailableError for an unknown ID).
  Pose2D mappedPose(DataId scanId) const;
  // Its pose right after a kept revision (CorrectedPoses.h revisedPose).
  Pose2D revisedPose(DataId scanId, std::uint64_t revision) const;
  // Drops the kept revisions numbered up to `number` (every follower has applied them).
  void forgetRevisionsUpTo(std::uint64_t number);
  // Map pose of an odometry pose taken near scan `scanId` (nearest held ID; thesis 3.3.5).
  Pose2D odomToMap(DataId scanId, const Pose2D& odometryPose) const;
  // 0 before the first scan.
  DataId lastInputId() const { return state_.lastInputId(); }

  const SlamState& state() const { return state_; }
  const SlamConfig& config() const { return config_; }

 private:
  struct LocalRegistration {
    Pose2D pose;                   // map frame
    Eigen::Matrix3d information;   // of that pose, map frame
    bool registered = false;       // false: the odometry prediction alone
  };
  // Registers a new keyframe's points against the recent keyframes, fused with odometry.
  LocalRegistration registerLocally(const std::vector<Eigen::Vector2f>& points, const Pose2D& odometry);
  void addKeyframe(const LaserScan& scan, ScanOutcome& outcome);
  void addSubmapIfComplete();
  // Adds loop constraints for the newest keyframe; returns how many and whether one moves it far.
  std::size_t closeLoops(bool& largeCorrection);
  // Optimises the pose graph and keeps the result as a revision made while scan `atScan` was input.
  void runOptimization(DataId atScan);

  SlamConfig config_;
  SlamState state_;
  std::vector<std::vector<Eigen::Vector2f>> normals_;  // per keyframe, derived from its points
  ReferenceMap localReference_;
  LoopCloser loopCloser_;
};

}  // namespace rgnav
