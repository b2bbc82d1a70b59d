// rgnav-eval-exploration: the exploration and task evaluations of issue 29, in process
// (InProcessRobot.h: simulator with odometry noise, mapping chain, RoutePlanner, Collision
// Avoidance and Low-Level Drive in lock-step; deterministic for a seed), on furnished IPA floor
// plans X_furnitures.png with their ground truth, from the first ground-truth room.
//   rgnav-eval-exploration <maps…>: each strategy (--strategies, default rg and frontier)
//     explores each map from the same start (ExplorationRun.h); a line per map and strategy
//       exploration <map> <strategy>: seen_95_m=… seen_99_m=… rooms_found=…/… collisions=… time_s=…
//     a picture per map and strategy in --out (ExplorationImage.h), and last
//       exploration: maps=… rooms_found_share=… path_ratio_vs_frontier=… collisions=…
//     rooms_found_share: RG exploration's rooms found over its reachable rooms, summed over the
//     maps; path_ratio_vs_frontier: the mean over maps of rg's seen_99_m / frontier's (over the
//     maps where both saw 99 %; "n/a" if none); collisions: all runs' together.
//   rgnav-eval-exploration --tasks <maps…>: RG exploration of each map, then the robot's regions
//     are named after the rooms and --task-count "go to <room>" tasks driven (RoomTasks.h); last
//       tasks: maps=… tasks=… reached=… mean_time_ratio=…
//     reached: the share of all tasks; mean_time_ratio: over the reached tasks.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/config/ShippedConfig.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/sim/LoadedWorld.h"
#include "tests/eval/exploration/ExplorationImage.h"
#include "tests/eval/exploration/ExplorationRun.h"
#include "tests/eval/exploration/RoomTasks.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  std::vector<std::string> strategies{"rg", "frontier"};
  std::string outDir = "out/exploration";
  std::string models = shippedConfigFile("gateways/gateway-hmms.txt");
  double usefulRangeM = 8.0;
  bool tasks = false;
  ExplorationSetup exploration;
  TaskSetup taskSetup;
};

struct Totals {
  std::size_t maps = 0, roomsFound = 0, roomsReachable = 0;
  std::uint64_t collisions = 0;
  double ratioSum = 0.0;
  std::size_t ratios = 0;
  std::size_t tasks = 0, reached = 0;
  double timeRatioSum = 0.0;
};

std::string shown(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void printDetails(const ExplorationResult& r, double wallS) {
  std::printf("#   done=%d path_m=%.1f seen_share=%.3f goals=%zu failed_drives=%zu wall_s=%.0f\n", r.done, r.pathM,
              r.seenShare, r.goals, r.failedDrives, wallS);
}

void runTasks(InProcessRobot& robot, const LoadedWorld& world, const TruthCoverage& coverage, const Options& options,
              Totals& totals) {
  const std::map<int, std::string> names = nameRooms(robot, world.grid, *world.truth, coverage);
  const std::vector<TaskResult> results = runRoomTasks(robot, *world.truth, names, options.taskSetup);
  std::size_t reached = 0;
  double ratios = 0.0;
  for (const TaskResult& t : results) {
    if (!t.reached || t.predictedS <= 0.0) continue;
    ++reached;
    ratios += t.seconds / t.predictedS;
  }
  std::printf("#   tasks: rooms_named=%zu tasks=%zu reached=%zu mean_time_ratio=%.3f collisions=%llu\n", names.size(),
              results.size(), reached, reached ? ratios / double(reached) : 0.0,
              static_cast<unsigned long long>(robot.simulation().robotCollisions()));
  totals.tasks += results.size();
  totals.reached += reached;
  totals.timeRatioSum += ratios;
}

void evaluate(const std::string& mapPath, const Options& options, const std::optional<HmmClassifier>& classifier,
              const RobotSetup& robotSetup, Totals& totals) {
  const LoadedWorld world = loadWorld(mapPath);
  if (!world.truth) throw FileError(mapPath + ": no ground truth beside it (" + ipaFilesOf(mapPath).truth + ")");
  const std::string name = ipaFilesOf(mapPath).name;
  const double radius = robotSetup.simulation.robot.footprint.circumradius();
  const Pose2D start = startInFirstRoom(world.grid, *world.truth, radius);
  std::map<std::string, std::optional<double>> seen99;
  for (const std::string& strategy : options.strategies) {
    const auto wallStart = std::chrono::steady_clock::now();
    InProcessRobot robot(world.grid, robotSetup, start, classifier);
    TruthCoverage coverage(world.grid, *world.truth, {start.x, start.y}, radius, options.usefulRangeM);
    ExplorationSetup setup = options.exploration;
    setup.strategy = strategy;
    const ExplorationResult result = runExploration(robot, coverage, setup);
    std::printf("%s\n", explorationLine(name, result).c_str());
    printDetails(result, std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count());
    writeExplorationImage(options.outDir + "/" + name + "_" + strategy + ".png", world.grid, *world.truth, coverage,
                          result.truePath, finalMapOf(robot.kernel()), robot.mapToWorld());
    std::fflush(stdout);
    seen99[strategy] = result.seen99M;
    totals.collisions += result.collisions;
    if (strategy == "rg") {
      totals.roomsFound += result.roomsFound;
      totals.roomsReachable += result.roomsReachable;
    }
    if (options.tasks) runTasks(robot, world, coverage, options, totals);
    std::fflush(stdout);
  }
  if (seen99["rg"] && seen99["frontier"] && *seen99["frontier"] > 0.0) {
    totals.ratioSum += *seen99["rg"] / *seen99["frontier"];
    ++totals.ratios;
  }
  ++totals.maps;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> maps;
  Options options;
  std::uint64_t seed = 0;
  po::options_description desc("rgnav-eval-exploration [options] <X_furnitures.png...>");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&maps)->required()->multitoken(), "furnished IPA floor plans (X_furnitures.png)")
      ("strategies", po::value(&options.strategies)->multitoken(), "exploration strategies (rg, frontier); default both")
      ("tasks", po::bool_switch(&options.tasks), "explore with rg, name the rooms, drive --task-count tasks per map")
      ("task-count", po::value(&options.taskSetup.count)->default_value(options.taskSetup.count), "tasks per map")
      ("task-seed", po::value(&options.taskSetup.seed)->default_value(options.taskSetup.seed), "seed of the tasks' rooms")
      ("time-limit-s", po::value(&options.exploration.timeLimitS)->default_value(options.exploration.timeLimitS, shown(options.exploration.timeLimitS)),
       "simulated seconds an exploration may take")
      ("useful-range", po::value(&options.usefulRangeM)->default_value(options.usefulRangeM, shown(options.usefulRangeM)),
       "m: the true laser's beams count as seen up to here")
      ("seed", po::value(&seed)->default_value(seed), "simulation seed; 0: config/sim/default.yaml's")
      ("models", po::value(&options.models)->default_value(options.models),
       "trained HMM file; used if it exists (else narrow passages only)")
      ("out", po::value(&options.outDir)->default_value(options.outDir), "folder for the pictures")
      ("trace", po::bool_switch(&options.exploration.trace), "print every goal, failed drive and task");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    RobotSetup robotSetup = shippedRobotSetup();
    if (seed != 0) robotSetup.simulation.seed = seed;
    if (options.tasks) options.strategies = {"rg"};
    options.taskSetup.trace = options.exploration.trace;
    std::optional<HmmClassifier> classifier;
    if (std::filesystem::exists(options.models)) classifier = loadHmmModels(options.models);
    std::filesystem::create_directories(options.outDir);
    std::printf("# in process, lock-step: simulator (odometry noise, no people) -> SLAM -> gateways (%s) -> RG\n"
                "# Mapping Kernel -> RoutePlanner -> Collision Avoidance -> Low-Level Drive; the explorer sees\n"
                "# the SLAM pose only. seen: reachable free cells the true laser passed within %.1f m\n",
                classifier ? "narrow passages + hallways" : "narrow passages only", options.usefulRangeM);
    Totals totals;
    for (const std::string& map : maps) evaluate(map, options, classifier, robotSetup, totals);
    if (options.tasks) {
      std::printf("tasks: maps=%zu tasks=%zu reached=%.3f mean_time_ratio=%.3f\n", totals.maps, totals.tasks,
                  totals.tasks ? double(totals.reached) / double(totals.tasks) : 0.0,
                  totals.reached ? totals.timeRatioSum / double(totals.reached) : 0.0);
      return 0;
    }
    std::printf("# path ratio over %zu of %zu maps (both strategies saw 99 %%)\n", totals.ratios, totals.maps);
    const std::string ratio = totals.ratios ? shown(std::round(totals.ratioSum / double(totals.ratios) * 1000) / 1000) : "n/a";
    std::printf("exploration: maps=%zu rooms_found_share=%.3f path_ratio_vs_frontier=%s collisions=%llu\n", totals.maps,
                totals.roomsReachable ? double(totals.roomsFound) / double(totals.roomsReachable) : 0.0, ratio.c_str(),
                static_cast<unsigned long long>(totals.collisions));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-exploration: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-exploration: " << e.what() << std::endl;
  }
  return 2;
}
