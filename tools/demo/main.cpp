// rgnav-demo: the navigating demo (`rgctl demo`, issue "Exploration, tasks and the navigating
// demo"; thesis chapter 1's tasks, 6.1.3's naming by the user, chapter 7's exploration) on the
// running set config/sets/demo.yaml: the robot, placed on the office floor knowing nothing, is told
// to explore (HighLevelPlanning::explore); the scripted user (DemoScript.h, DemoUser.h) answers
// the first naming questions as they come; once the floor is explored the user names the most
// confident object of the map the robot finds a way to (the kernel's nameObject: an object to go
// to must exist in the map, and which objects the laser makes out is only known after exploring;
// the PathPlanning module is asked whether a free pose in front of it can be reached from where
// the robot stands, as a user would not name what the robot cannot go to), then the script's tasks
// run one after the other (goTo a named room, the named object, the start). Progress lines on
// stdout; at the end the kernel exports the map (<name>.rgmap.json/.svg/.png) into its export
// root, the driven path (DrivenPath.h) goes beside it into --out, and the last line is
//   demo: explored_share=… regions=… gateways=… neutralized=… tasks=N/M collisions=… path_m=… time_s=…
// explored_share: ExploredShare.h; collisions: the simulator's health counter robot_collisions;
// path_m: the length of the driven path; time_s: wall time of this program (the set is up before).
// The demo reads the simulator's ground truth once, for the scoring only: where the world frame
// lies in the map frame (the first scan's true pose against its corrected pose). No module of the
// robot reads it.
// Exit code 0 if the exploration ended done, every task was reached and nothing collided; 1 if
// not; 2 for bad arguments or a set that does not answer.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <thread>

#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "clientlibs/pathplanning/PathPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/nav/planning/PlanningMapJson.h"
#include "core/sim/LoadedWorld.h"
#include "tools/common/CommandLine.h"
#include "tools/common/QuotedText.h"
#include "tools/common/ToolClient.h"
#include "tools/demo/DemoScript.h"
#include "tools/demo/DemoUser.h"
#include "tools/demo/DrivenPath.h"
#include "tools/demo/ExploredShare.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  std::string world, answers, tasks, out, name = "demo";
  int exploreLimitS = 3600, taskLimitS = 600, startLimitS = 60;
};

// The robot's first corrected pose (map frame) and where the world frame lies in the map's.
struct DemoStart {
  PoseUpdate first;
  Pose2D trueFirst;  // world frame

  Pose2D mapToWorld() const { return compose(trueFirst, inverse(first.corrected)); }
};

DemoStart waitForStart(ScanMapperClient& scanMapper, GroundTruthClient& truth, std::chrono::seconds limit) {
  const auto giveUp = std::chrono::steady_clock::now() + limit;
  while (scanMapper.latestCorrectedId() == 0) {
    if (std::chrono::steady_clock::now() > giveUp)
      throw NotAvailableError("the ScanMapper corrected no scan within " + std::to_string(limit.count()) + " s");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const std::vector<PoseUpdate> first = scanMapper.poses(1, scanMapper.latestCorrectedId());
  if (first.empty()) throw NotAvailableError("the ScanMapper holds no corrected pose");
  return {first.front(), truth.truePose(first.front().id)};
}

// Names an object of the map `name`: the most confident one (a user clicks first what the robot
// saw all round) that the PathPlanning module finds a way to from where the robot stands (a free
// pose in front of it); a candidate without a way loses the name again. False if no object has one.
bool nameAnObject(RgMappingKernelClient& kernel, PathPlanningClient& planner, const Pose2D& here,
                  const std::string& name) {
  std::vector<std::pair<RegionId, RectangleObjectView>> objects;
  for (const RegionSummaryView& summary : kernel.regions())
    for (const RectangleObjectView& o : kernel.region(summary.id).objects) objects.emplace_back(summary.id, o);
  std::stable_sort(objects.begin(), objects.end(),
                   [](const auto& a, const auto& b) { return a.second.confidence > b.second.confidence; });
  for (const auto& [region, o] : objects) {
    const Eigen::Vector2d at{o.pose.x, o.pose.y};
    kernel.nameObject(region, at, name);
    try {
      planner.plan(here, PlanGoal::atObject(name));
    } catch (const Error& e) {  // no way to it (NoPath), or no free pose in front of it
      kernel.nameObject(region, at, "");
      continue;
    }
    std::printf("demo: the user names the object of region %llu at (%.2f, %.2f) (%.1f x %.1f m, %.0f %% seen) %s\n",
                static_cast<unsigned long long>(region.value()), o.pose.x, o.pose.y, o.lengthM, o.widthM,
                100.0 * o.confidence, quotedText(name).c_str());
    return true;
  }
  return false;
}

PlanGoal goalOf(const DemoTask& task, const DemoStart& start) {
  switch (task.kind) {
    case DemoTask::Kind::Region: return PlanGoal::inRegionNamed(task.name);
    case DemoTask::Kind::Object: return PlanGoal::atObject(task.name);
    case DemoTask::Kind::Start: return PlanGoal::at({start.first.corrected.x, start.first.corrected.y});
    case DemoTask::Kind::Point: break;
  }
  return PlanGoal::at(task.point);
}

// The line of `files` (exportMap's answer, one file per line) that ends in `suffix`.
std::string exportedFile(const std::string& files, const std::string& suffix) {
  std::istringstream lines(files);
  for (std::string line; std::getline(lines, line);)
    if (line.size() >= suffix.size() && line.compare(line.size() - suffix.size(), suffix.size(), suffix) == 0) return line;
  throw NotAvailableError("the kernel's export wrote no " + suffix + " file");
}

int run(const Options& options) {
  const auto begin = std::chrono::steady_clock::now();
  const DemoScript script = loadDemoScript(options.answers, options.tasks);
  const LoadedWorld world = loadWorld(options.world);
  const ClientSettings settings = ClientSettings::fromEnvironment();
  HighLevelPlanningClient hlp(settings);
  RgMappingKernelClient kernel(settings);
  ScanMapperClient scanMapper(settings);
  GroundTruthClient truth(settings);
  DemoUser user(hlp, kernel, script.regionNames, begin);

  const DemoStart start = waitForStart(scanMapper, truth, std::chrono::seconds(options.startLimitS));
  std::printf("demo: the robot starts at (%.2f, %.2f) of its map, knowing nothing; it explores the floor\n",
              start.first.corrected.x, start.first.corrected.y);
  const Task explored = user.follow(hlp.explore().id, std::chrono::seconds(options.exploreLimitS));
  user.answerWaiting();
  bool ok = explored.state == TaskState::Done;

  PathPlanningClient planner(settings);
  const Pose2D here = scanMapper.correctedPose(scanMapper.latestCorrectedId());
  if (!nameAnObject(kernel, planner, here, script.objectName))
    std::printf("demo: the map holds no object the robot finds a way to, to name %s\n",
                quotedText(script.objectName).c_str());
  std::size_t reached = 0;
  for (const DemoTask& task : script.tasks) {
    std::printf("demo: the user asks the robot to go to %s\n", task.describe().c_str());
    const Task done = user.follow(hlp.goTo(goalOf(task, start)).id, std::chrono::seconds(options.taskLimitS));
    reached += done.state == TaskState::Reached;
  }
  ok = ok && reached == script.tasks.size();

  const std::string files = kernel.exportMap("", options.name, false);
  std::cout << files;
  const std::string mapFile = exportedFile(files, ".rgmap.json");
  const PlanningMap map = loadPlanningMap(mapFile);
  const DrivenPath path = fetchDrivenPath(scanMapper, start.first.id);
  const std::string pathBase = options.out + "/" + options.name + ".path";
  writeDrivenPathJson(pathBase + ".json", path);
  writeDrivenPathPictures(pathBase, map, path);
  std::printf("%s.json\n%s.svg\n%s.png\n", pathBase.c_str(), pathBase.c_str(), pathBase.c_str());

  const double share =
      exploredShare(world.grid, {start.trueFirst.x, start.trueFirst.y}, map.regions, start.mapToWorld());
  const ModuleStatusInfo simulator = truth.status();
  const std::uint64_t collisions =
      simulator.counters.count("robot_collisions") ? simulator.counters.at("robot_collisions") : 0;
  const MapSummaryView summary = kernel.summary();
  ok = ok && collisions == 0;
  std::printf("demo: explored_share=%.3f regions=%zu gateways=%zu neutralized=%zu tasks=%zu/%zu collisions=%llu "
              "path_m=%.1f time_s=%.0f\n",
              share, summary.regions, summary.gateways, summary.neutralised, reached, script.tasks.size(),
              static_cast<unsigned long long>(collisions), path.lengthM(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-demo: the navigating demo on the running set config/sets/demo.yaml");
  desc.add_options()
      ("help", "this text")
      ("world", po::value(&options.world)->required(), "the simulator's world file (explored_share)")
      ("answers", po::value(&options.answers)->required(), "the user's names (config/demo/answers.yaml)")
      ("tasks", po::value(&options.tasks)->required(), "the tasks after exploring (config/demo/tasks.yaml)")
      ("out", po::value(&options.out)->required(), "directory of the driven path's files (the kernel's export root)")
      ("name", po::value(&options.name)->default_value(options.name), "name of the exported files")
      ("explore-limit-s", po::value(&options.exploreLimitS)->default_value(options.exploreLimitS),
       "the exploration is cancelled after this")
      ("task-limit-s", po::value(&options.taskLimitS)->default_value(options.taskLimitS), "each task is cancelled after this");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    return run(options);
  } catch (const po::error& e) {
    std::cerr << "rgnav-demo: " << e.what() << "\n" << desc << std::endl;
  } catch (const ModuleUnavailableError& e) {
    reportUnreachable("rgnav-demo", e, true);
  } catch (const std::exception& e) {
    std::cerr << "rgnav-demo: " << e.what() << std::endl;
  }
  return 2;
}
