// Naming the explored regions and the "go to <room>" tasks; see RoomTasks.h.
#include "tests/eval/exploration/RoomTasks.h"

#include <algorithm>
#include <cstdio>
#include <random>
#include <tuple>

#include "tests/eval/exploration/PredictedTime.h"
#include "tests/eval/rooms/FinalMap.h"
#include "tests/eval/rooms/RegionPixels.h"
#include "tests/eval/rooms/RoomScoring.h"

namespace rgnav {
namespace {

// Regions placed as the room evaluation places them (tests/eval/rooms/main.cpp defaults).
constexpr double kGrowM = 0.3;
constexpr double kMaxHoleM2 = 2.0;

}  // namespace

std::map<int, std::string> nameRooms(InProcessRobot& robot, const OccupancyGrid& world, const GroundTruth& truth,
                                     const TruthCoverage& coverage) {
  const std::vector<SegmentPixels> regions =
      regionPixels(finalMapOf(robot.kernel()), robot.mapToWorld(), world, kGrowM, kMaxHoleM2);
  const RoomScore score = scoreRooms(truth, regions);
  // (overlap, room, region) of each reachable room's best region, largest overlap first.
  std::vector<std::tuple<std::size_t, int, std::uint64_t>> wishes;
  for (const RoomCoverage& room : coverage.rooms()) {
    if (!room.reachable()) continue;
    std::size_t best = 0;
    std::uint64_t region = 0;
    for (const SegmentMatch& segment : score.segments) {
      const std::size_t overlap = segment.roomOverlaps[std::size_t(room.room)];
      if (overlap > best) std::tie(best, region) = std::tie(overlap, segment.id);
    }
    if (best > 0) wishes.emplace_back(best, room.room, region);
  }
  std::sort(wishes.begin(), wishes.end(), [](const auto& a, const auto& b) { return a > b; });
  std::map<int, std::string> names;
  std::vector<std::uint64_t> named;
  for (const auto& [overlap, room, region] : wishes) {
    if (std::find(named.begin(), named.end(), region) != named.end()) continue;
    named.push_back(region);
    names[room] = "room" + std::to_string(room);
    robot.kernel().nameRegion(RegionId(region), names[room]);
  }
  robot.refreshMap();
  return names;
}

std::vector<TaskResult> runRoomTasks(InProcessRobot& robot, const GroundTruth& truth,
                                     const std::map<int, std::string>& names, const TaskSetup& setup) {
  std::mt19937_64 random(setup.seed);
  std::vector<TaskResult> results;
  for (std::size_t task = 0; task < setup.count; ++task) {
    const Pose2D here = robot.simulation().truePose();
    const int inRoom = truth.roomAt({here.x, here.y});
    std::vector<int> rooms;
    for (const auto& [room, name] : names)
      if (room != inRoom) rooms.push_back(room);
    if (rooms.empty()) break;
    TaskResult result;
    result.room = rooms[std::uniform_int_distribution<std::size_t>(0, rooms.size() - 1)(random)];
    const Pose2D start = robot.pose();
    const double started = robot.time();
    robot.driveTo(PlanGoal::inRegionNamed(names.at(result.room)));
    if (const std::optional<Plan>& plan = robot.drive().plan())
      result.predictedS = predictedSeconds(*plan, start, robot.setup().avoidance.candidates,
                                           referenceLimits(robot.setup().drive));
    const double limit = std::max(setup.minLimitS, setup.limitFactor * result.predictedS);
    while (robot.drive().state() == GoalDriveState::Driving && robot.time() - started < limit) robot.step();
    result.seconds = robot.time() - started;
    result.driveReached = robot.drive().state() == GoalDriveState::Reached;
    const Pose2D end = robot.simulation().truePose();
    result.reached = result.driveReached && truth.roomAt({end.x, end.y}) == result.room;
    if (robot.drive().state() == GoalDriveState::Driving) {
      robot.cancelDrive();
      result.why = "time limit";
    } else if (!result.driveReached) {
      result.why = robot.drive().reason();
    } else if (!result.reached) {
      result.why = "stopped in room " + std::to_string(truth.roomAt({end.x, end.y}));
    }
    if (setup.trace)
      std::printf("#   task %zu: %s from room %d: %s time_s=%.1f predicted_s=%.1f %s\n", task + 1,
                  names.at(result.room).c_str(), inRoom, result.reached ? "reached" : "NOT reached", result.seconds,
                  result.predictedS, result.why.c_str());
    results.push_back(result);
  }
  return results;
}

}  // namespace rgnav
