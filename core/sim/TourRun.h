// runTour: drives a Simulation through a whole planned room tour with a TourDriver, hands every
// step (odometry reading, scan) to a sink (a log writer, a server buffer), and reports which
// rooms the robot reached and entered.
#pragma once

#include <functional>
#include <set>
#include <vector>

#include "core/sim/GroundTruth.h"
#include "core/sim/Simulation.h"
#include "core/sim/TourDriver.h"

namespace rgnav {

struct TourRunResult {
  std::set<int> roomsVisited;    // rooms whose visiting point was reached
  std::set<int> roomsEntered;    // rooms the robot's centre was in at some step
  std::vector<int> roomsMissed;  // planned visits given up (stuck) or not reached in time
  std::uint64_t collisions = 0;
  std::uint64_t scans = 0;
  double distance = 0.0;         // m driven (true)
  double seconds = 0.0;          // simulated
  bool finished = false;         // every planned visit was reached
};

// Called for every step, in order.
using StepSink = std::function<void(const SimulationStep&)>;

// Ends when the driver has finished or the simulated time exceeds maxSeconds.
TourRunResult runTour(Simulation& simulation, TourDriver& driver, const GroundTruth& truth, const StepSink& sink,
                      double maxSeconds);

// The standard room tour of a world with ground truth, as every tool and evaluation drives it:
// from the free cell farthest from walls, planned and followed with the default settings.
struct RoomTour {
  Pose2D start;
  Tour plan;
  TourRunResult run;
};
inline constexpr double kRoomTourMaxSeconds = 4 * 3600.0;
RoomTour driveRoomTour(const OccupancyGrid& grid, const GroundTruth& truth, const SimulationConfig& config,
                       const StepSink& sink, double maxSeconds = kRoomTourMaxSeconds);

}  // namespace rgnav
