// detectAlongTour: drives the simulated room tour of rgnav-sim-tour (openest start pose,
// TourPlanner route, TourDriver, runTour) through a world and runs the narrow-passage detector
// and the passage tracker on every `everyScans`-th scan at the scan's TRUE sensor pose (the
// tracker gets the true robot pose). The evaluation scores detection, not SLAM.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/gateways/passages/NarrowPassageDetector.h"
#include "core/gateways/passages/PassageTracker.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

struct TourDetectionSetup {
  NarrowPassageConfig detector;
  PassageTrackerConfig tracker;
  std::size_t everyScans = 1;
  std::uint64_t seed = 1;
};

struct TourPassages {
  std::vector<TrackedGateway> gateways;  // confirmed at the end of the tour
  std::size_t traversals = 0;     // traversal events the tracker reported
  std::size_t scansDetected = 0;  // scans the detector ran on
  std::size_t hypotheses = 0;     // single-scan hypotheses
  std::vector<int> unreachableRooms;  // of the tour plan
  std::vector<Eigen::Vector2d> path;  // true robot positions at the scans the detector ran on
};

TourPassages detectAlongTour(const OccupancyGrid& grid, const GroundTruth& truth, const TourDetectionSetup& setup);

}  // namespace rgnav
