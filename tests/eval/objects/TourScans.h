// TourScans: the laser scans of a simulated room tour (as rgnav-sim-tour drives it: start at the
// openest pose, TourPlanner route, TourDriver, runTour), each with its TRUE sensor pose, grouped
// by the ground-truth room the robot was in when it took them (the last room for scans taken on
// a door separator). The evaluation is about object detection, not SLAM, so no pose is
// estimated.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "core/sim/TourRun.h"

namespace rgnav {

struct TourScans {
  std::vector<std::vector<LaserScan>> byRoom;  // index = GT room; LaserScan::sensorPose is the true pose
  std::vector<bool> reachable;                 // row-major: cells the robot's centre can reach from the start
  TourRunResult run;
};

TourScans scanTour(const OccupancyGrid& grid, const GroundTruth& truth, std::uint64_t seed);

}  // namespace rgnav
