// The task evaluation of issue 29 ("rgctl eval tasks"): after the robot explored a map (RG
// exploration), its regions are named from the ground truth as a user would answer the naming
// dialog (thesis 6.1.3; in process: the kernel's nameRegion), and it carries out random
// "go to <room>" tasks, each planned to the region of that name (PlanGoal::inRegionNamed) and
// driven by the GoalDrive.
//   - nameRooms: each reachable ground-truth room (TruthCoverage.h) names the region that overlaps
//     it most (the final regions placed on the floor plan as the room evaluation places them,
//     RegionPixels.h, grown 0.3 m with holes up to 2 m²); one name per region: where two rooms
//     want the same region, the larger overlap wins and the other room gets no name (it cannot be
//     a task's goal). Names are "room<ID>".
//   - runRoomTasks: `count` tasks, each to a named room drawn uniformly (seeded) among those the
//     robot is not in (true pose); a task is reached when the drive reports reached and the TRUE
//     pose lies inside that room. A drive still going after max(minLimitS, limitFactor × predicted)
//     is cancelled (not reached). Time ratio: the simulated time from the task's start to the
//     drive's end over the plan's predicted time (PredictedTime.h), for reached tasks.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tests/eval/exploration/InProcessRobot.h"
#include "tests/eval/exploration/TruthCoverage.h"

namespace rgnav {

// Room ID -> name given to its region. Throws what the kernel throws.
std::map<int, std::string> nameRooms(InProcessRobot& robot, const OccupancyGrid& world, const GroundTruth& truth,
                                     const TruthCoverage& coverage);

struct TaskSetup {
  std::size_t count = 20;
  std::uint64_t seed = 29;
  double minLimitS = 60.0;
  double limitFactor = 5.0;
  bool trace = false;  // a line per task
};

struct TaskResult {
  int room = -1;
  bool reached = false;       // the drive reached, and the true pose is in the room
  bool driveReached = false;  // the drive reported reached
  double seconds = 0.0;       // simulated, from the task's start to the drive's end
  double predictedS = 0.0;    // 0: no plan
  std::string why;            // not reached: why
};

// Ends early when no named room is left but the one the robot is in.
std::vector<TaskResult> runRoomTasks(InProcessRobot& robot, const GroundTruth& truth,
                                     const std::map<int, std::string>& names, const TaskSetup& setup);

}  // namespace rgnav
