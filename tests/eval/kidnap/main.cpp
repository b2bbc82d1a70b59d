// rgnav-eval-kidnap: the kidnapping evaluation of issue 28 ("rgctl eval kidnap"): does the
// localizer notice when the robot is carried somewhere else, and find it there
// (GlobalLocalizer.h)? The office world (config/worlds/office.yaml) is mapped in process by the
// room tour (MappedFloor.h). Then one run: the robot starts at a random reachable pose, the
// localizer is told it (setPose), and the robot wanders to random goals (RandomGoalDriver.h).
// --jumps times, after --segment-seconds of simulated time each, the robot is put at another
// random reachable pose at least --min-jump-m away; its odometry goes on as if nothing happened
// (a carried robot's wheels do not turn), so only the scans tell.
//   detected:  jumps after which the localizer reported a kidnapping (kidnapsDetected grew)
//              before the next jump;
//   recovered: jumps after which, at the end of the segment, it was localized within 0.3 m and
//              10 degrees of the truth (in the map: LocalTruth.h) and had been since some scan on;
//   recover_travel_m: true travel from the jump to that scan, over recovered jumps.
// The first segment (before any jump) is not counted; its state is printed.
// Last line: kidnap: jumps=… detected=… recovered=… recover_travel_m_median=…
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>

#include "core/gateways/classify/HmmModelFile.h"
#include "core/nav/localization/GlobalLocalizer.h"
#include "core/sim/Simulation.h"
#include "core/sim/StartPose.h"
#include "tests/eval/globalloc/LocalTruth.h"
#include "tests/eval/globalloc/MappedFloor.h"
#include "tests/eval/globalloc/RandomGoalDriver.h"
#include "tests/support/Statistics.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  std::string world = "config/worlds/office.yaml";
  std::size_t jumps = 10;
  double segmentSeconds = 90.0;
  double minJumpM = 5.0;
  std::uint64_t seed = 1;
  std::string models = "config/gateways/gateway-hmms.txt";
  bool truePoses = false;
};

constexpr double kToleranceM = 0.3, kToleranceRad = 10.0 * M_PI / 180.0;

struct Segment {
  bool detected = false, recovered = false;
  double travelToRecover = 0.0;
  double finalErrorM = -1.0;
};

int run(const Options& options) {
  std::optional<HmmClassifier> classifier;
  if (std::filesystem::exists(options.models)) classifier = loadHmmModels(options.models);
  const MappedFloor floor = mapFloor(options.world, classifier, options.truePoses);
  const MclConfig mcl;
  const LocalizationMap map = LocalizationMap::fromViews(floor.regions, floor.gateways, mcl.beam);
  const GridPlanner planner(floor.world.grid);
  const Pose2D tourStart = openestPose(floor.world.grid);
  const std::vector<bool> reachable = planner.reachableFrom({tourStart.x, tourStart.y});
  RandomGoalDriver driver(planner, reachable, options.seed);
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  const auto randomPose = [&](const Pose2D* awayFrom) {
    for (;;) {
      const WorldPoint p = driver.randomPoint();
      if (!awayFrom || std::hypot(p.x - awayFrom->x, p.y - awayFrom->y) >= options.minJumpM) return Pose2D{p.x, p.y, heading(rng)};
    }
  };
  const LocalTruth truthInMap(floor.scans, floor.mapToWorld);
  GlobalLocalizer localizer(GlobalLocalizerConfig{}, mcl, map, floor.regions, floor.gateways, options.seed);
  Pose2D start = randomPose(nullptr);
  localizer.setPose(truthInMap.toMap(start), Eigen::Vector3d(0.1, 0.1, 0.05));
  std::printf("kidnap world %s: regions=%zu gateways=%zu slam_error_m=%.2f/%.2f\n", options.world.c_str(),
              floor.regions.size(), floor.gateways.size(), floor.slamErrorMeanM, floor.slamErrorMaxM);

  Pose2D reportedOdometry = start;  // the odometry the localizer sees, continuous over the jumps
  std::vector<Segment> segments;
  SimulationConfig config;
  for (std::size_t k = 0; k <= options.jumps; ++k) {
    config.seed = options.seed * 1000003 + k;
    Simulation sim(floor.world.grid, config, start);
    // The new simulation's odometry starts at `start`; the localizer's goes on from where it was.
    const Pose2D odometryShift = compose(reportedOdometry, inverse(sim.odometryPose()));
    const std::size_t kidnapsBefore = localizer.kidnapsDetected();
    Segment s;
    bool inStreak = false;
    double travel = 0.0;
    while (sim.time() < options.segmentSeconds) {
      sim.command(driver.command(sim.truePose(), sim.time()));
      const Pose2D before = sim.truePose();
      SimulationStep step = sim.step();
      travel += std::hypot(step.truePose.x - before.x, step.truePose.y - before.y);
      if (!step.scan) continue;
      step.scan->odometry = compose(odometryShift, step.scan->odometry);
      step.scan->sensorPose = step.scan->odometry;
      reportedOdometry = step.scan->odometry;
      localizer.update(*step.scan);
      const Pose2D truth = truthInMap.toMap(step.truePose);
      const std::optional<PoseEstimate> e = localizer.localized() ? localizer.estimate() : std::nullopt;
      const bool good = e && poseWithin(e->mapPose, truth, kToleranceM, kToleranceRad);
      if (good && !inStreak) s.travelToRecover = travel;
      inStreak = good;
      s.recovered = good;
      s.finalErrorM = e ? std::hypot(e->mapPose.x - truth.x, e->mapPose.y - truth.y) : -1.0;
    }
    s.detected = localizer.kidnapsDetected() > kidnapsBefore;
    std::printf("#   segment %zu%s: %s%s travel=%.1f m recovered_after=%.1f m final_error_m=%.2f\n", k,
                k == 0 ? " (start told)" : "", s.detected ? "detected " : "not detected ",
                s.recovered ? "recovered" : "NOT recovered", travel, s.travelToRecover, s.finalErrorM);
    std::fflush(stdout);
    if (k > 0) segments.push_back(s);
    start = randomPose(&sim.truePose());
  }
  std::size_t detected = 0, recovered = 0;
  std::vector<double> travel;
  for (const Segment& s : segments) {
    detected += s.detected;
    recovered += s.recovered;
    if (s.recovered) travel.push_back(s.travelToRecover);
  }
  std::printf("kidnap: jumps=%zu detected=%zu recovered=%zu recover_travel_m_median=%.2f\n", segments.size(), detected,
              recovered, testing::median(travel));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-eval-kidnap [options]: kidnapping detection and recovery in the office world");
  desc.add_options()
      ("world", po::value(&options.world)->default_value(options.world), "simulator world with ground-truth rooms")
      ("jumps", po::value(&options.jumps)->default_value(options.jumps), "times the robot is carried away")
      ("segment-seconds", po::value(&options.segmentSeconds)->default_value(options.segmentSeconds),
       "simulated seconds before each jump and after the last")
      ("min-jump-m", po::value(&options.minJumpM)->default_value(options.minJumpM), "least distance of a jump")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed of the poses, goals and simulation")
      ("models", po::value(&options.models)->default_value(options.models), "gateway HMMs (used if the file exists)")
      ("true-poses", po::bool_switch(&options.truePoses), "map with the true poses instead of SLAM");
  try {
    if (!parseCommandLine(argc, argv, desc, {})) return 0;
    return run(options);
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-kidnap: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-kidnap: " << e.what() << std::endl;
  }
  return 2;
}
