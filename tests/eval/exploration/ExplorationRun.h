// runExploration: one exploration of the evaluation of issue 29 ("rgctl eval exploration"): an
// InProcessRobot (simulator with odometry noise, no people; mapping chain; planner; Collision
// Avoidance and Low-Level Drive in lock-step) explores under an Explorer with the strategy asked
// for ("rg": region by region, thesis chapter 7; "frontier": nearest frontier, Yamauchi 1997).
// On every scan the Explorer gets the planning map, the SLAM pose, the kernel's current region
// and how the drive to its goal stands (Driving, Reached, Failed); its PathLength is the
// RoutePlanner's plan length to the point (nullopt: NoPathError). A DriveTo starts a GoalDrive
// to the goal point. The run ends when the Explorer is done or at the simulated time limit.
// The truth is used only by the figures (TruthCoverage.h): seen_95_m / seen_99_m are the true
// distance driven when 95 / 99 % of the reachable free area had been seen.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/nav/exploration/ExplorationConfig.h"
#include "tests/eval/exploration/InProcessRobot.h"
#include "tests/eval/exploration/TruthCoverage.h"

namespace rgnav {

struct ExplorationSetup {
  std::string strategy = "rg";
  ExplorationConfig exploration;
  double timeLimitS = 3600.0;  // simulated
  bool trace = false;          // print every goal and every failed drive
};

struct ExplorationResult {
  std::string strategy;
  bool done = false;             // the Explorer said so (else: the time limit)
  double seconds = 0.0;          // simulated
  double pathM = 0.0;            // true distance driven
  std::optional<double> seen95M, seen99M;
  double seenShare = 0.0;        // at the end
  std::size_t roomsReachable = 0, roomsFound = 0;  // ground-truth rooms (TruthCoverage.h)
  std::size_t goals = 0;         // goals the Explorer gave
  std::size_t failedDrives = 0;  // drives that ended Failed
  std::uint64_t collisions = 0;  // the simulator's count
  std::vector<Eigen::Vector2d> truePath;  // true positions at the scans
};

// `exploration <map> <strategy>: seen_95_m=… seen_99_m=… rooms_found=…/… collisions=… time_s=…`
// ("n/a": never seen so much).
std::string explorationLine(const std::string& mapName, const ExplorationResult& result);

// The start in the first ground-truth room (lowest ID) on the floor: the traversable cells
// connected to the floor plan's most open place (openestPose), which leaves out rooms the robot
// does not fit in and scraps of free space outside the building (Freiburg79_scan's rooms 0 and 1);
// the room's cell there farthest from any wall, heading 0. InvalidArgumentError if there is none.
Pose2D startInFirstRoom(const OccupancyGrid& world, const GroundTruth& truth, double robotRadiusM);

// Drives `robot` (just made, standing at its start) until done or the time limit; every true
// scan goes into `coverage`. Throws ConfigError for an unknown strategy.
ExplorationResult runExploration(InProcessRobot& robot, TruthCoverage& coverage, const ExplorationSetup& setup);

}  // namespace rgnav
