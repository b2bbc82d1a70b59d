// localizeAlong: one run of the region Monte Carlo localization (core/nav/localization RegionMcl)
// along a log for the localization evaluation (issue 28): the filter starts at the first scan's
// corrected pose (particles drawn with a small sigma), takes every scan with its raw odometry,
// and after each scan its estimate is compared with the scan's corrected pose. For a scan on
// which the filter did not update (the robot moved less than MclConfig::updateMinTravelM), the
// last estimate is carried forward by the odometry moved since. The same code runs the region
// map and the global-map baseline (LocalizationMap::wholeFloor): only the map differs.
// The fields of all regions are built before the run (as a module holding the map would have
// them) and timed apart; updates_per_s counts the filter's own compute time (this thread's CPU
// time inside RegionMcl::update), so other processes on the machine do not change it much.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "core/nav/localization/RegionMcl.h"
#include "tests/eval/localization/LocalizationErrors.h"

namespace rgnav {

struct LocalizationSetup {
  MclConfig config;
  std::uint64_t seed = 1;
  Eigen::Vector3d initialSigma{0.05, 0.05, 0.03};  // x, y (m), theta (rad) around the first true pose
};

struct LocalizedScan {
  DataId scanId = 0;
  bool updated = false;
  Pose2D truth;
  Pose2D estimate;      // the heaviest cluster's mean, map frame
  Pose2D bestParticle;  // map frame
  RegionId region;          // the estimate's region (PoseEstimate::region)
  RegionId particleRegion;  // the region holding the most particle weight
  std::size_t particles = 0;
  double clusterWeight = 0.0;
  double fitPerBeam = 0.0;
  PoseError error, bestParticleError;
};

struct LocalizationRun {
  std::vector<LocalizedScan> scans;
  std::size_t updates = 0;
  double filterSeconds = 0.0;      // thread CPU time spent in RegionMcl::update
  double fieldSeconds = 0.0;       // thread CPU time building the fields before the run
  double particlesMean = 0.0;      // over the updates
  std::size_t fieldBytes = 0;
  std::size_t traversals = 0;      // gateway traversals the filter confirmed
};

// `scans`: in log order, each with its raw odometry (LaserScan::odometry) and its corrected pose
// as sensorPose; at least one. `startRegion`: the region of the map the first scan was mapped
// into (RegionMcl::setPose prefers the region whose freespace holds the pose, and takes this one
// where none does: a region's freespace need not cover the cell the robot stood in). Throws
// what RegionMcl throws.
LocalizationRun localizeAlong(const LocalizationMap& map, std::span<const LaserScan> scans, RegionId startRegion,
                              const LocalizationSetup& setup);

}  // namespace rgnav
