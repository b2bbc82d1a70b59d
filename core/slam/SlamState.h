// SlamState: everything the scan mapper must keep across a restart (DESIGN.md "State
// survives"): every input scan's ID and odometry, the keyframes with their points and estimated
// poses, the pose graph constraints, the frozen submaps used for loop closing, the counters
// that steer loop search and optimisation, and what a consumer needs to follow the map in the
// order it was made: each scan's pose as mapped and the keyframe poses of the latest revisions.
// Caches (grids, normals) are not part of it: they are rebuilt from it, so a restored mapper
// continues exactly as an uninterrupted one.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"

namespace rgnav {

using KeyframeIndex = std::uint32_t;
inline constexpr KeyframeIndex kNoKeyframe = UINT32_MAX;

// One input scan: what is needed to give it a corrected pose later.
struct ScanRecord {
  DataId id = 0;
  Timestamp stamp = 0.0;
  Pose2D odometry;
  KeyframeIndex keyframe = kNoKeyframe;  // its keyframe, or kNoKeyframe if filtered out
  KeyframeIndex previousKeyframe = kNoKeyframe;  // the latest keyframe at or before this scan
  Pose2D mapped;  // its corrected pose right after it was input (before any later scan)

  friend bool operator==(const ScanRecord&, const ScanRecord&) = default;
};

// A scan taken into the map: its points in the sensor frame and its estimated pose.
struct Keyframe {
  DataId scanId = 0;
  Pose2D odometry;
  Pose2D pose;                          // map frame, updated by optimisation
  std::vector<Eigen::Vector2f> points;  // sensor frame, metres

  friend bool operator==(const Keyframe&, const Keyframe&) = default;
};

// A measured relative pose `to` in the frame of `from`, with its information matrix
// (x, y, theta order).
struct Constraint {
  enum class Kind : std::uint8_t { Sequential = 0, Loop = 1 };
  Kind kind = Kind::Sequential;
  KeyframeIndex from = 0;
  KeyframeIndex to = 0;
  Pose2D measurement;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();

  friend bool operator==(const Constraint&, const Constraint&) = default;
};

// Consecutive keyframes [first, first + memberPoses.size()) rasterised together for loop
// closing, rigid: their poses relative to the anchor keyframe frozen when the submap was made.
struct SubmapRecord {
  KeyframeIndex first = 0;
  KeyframeIndex anchor = 0;
  std::vector<Pose2D> memberPoses;  // relative to the anchor

  friend bool operator==(const SubmapRecord&, const SubmapRecord&) = default;
};

// One pose graph optimisation: the keyframe poses it gave (every keyframe of its time). It ran
// while scan `atScan` was input, so it revises the scans before that one; one run after the
// input (ScanMapper::optimize) has atScan = the last input ID + 1.
struct PoseRevision {
  std::uint64_t number = 0;  // SlamCounters::optimizations right after it
  DataId atScan = 0;
  std::vector<Pose2D> keyframePoses;

  friend bool operator==(const PoseRevision&, const PoseRevision&) = default;
};

struct SlamCounters {
  std::uint64_t failedRegistrations = 0;  // keyframes placed by odometry alone
  std::uint64_t loopClosures = 0;         // loop constraints added
  std::uint64_t optimizations = 0;        // pose graph optimisations run

  friend bool operator==(const SlamCounters&, const SlamCounters&) = default;
};

struct SlamState {
  std::vector<ScanRecord> scans;        // increasing IDs
  std::vector<Keyframe> keyframes;
  std::vector<Constraint> constraints;
  std::vector<SubmapRecord> submaps;
  double distanceSinceLoop = 0.0;       // m of estimated path since the last loop closure
  std::uint64_t pendingLoops = 0;       // loop constraints not yet optimised
  std::uint64_t keyframesAtLastOptimization = 0;  // keyframe count when the graph was last optimised
  SlamCounters counters;
  std::vector<PoseRevision> revisions;  // the latest SlamConfig::graph.keptRevisions, oldest first

  // 0 if no scan was input yet.
  DataId lastInputId() const { return scans.empty() ? 0 : scans.back().id; }

  friend bool operator==(const SlamState&, const SlamState&) = default;
};

}  // namespace rgnav
