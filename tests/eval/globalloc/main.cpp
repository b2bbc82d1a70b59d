// rgnav-eval-globalloc: the global localization evaluation of issue 28 ("rgctl eval globalloc"):
// can the robot find where it is in an RG map without being told (GlobalLocalizer.h)? Each
// furnished IPA floor plan (floorplans/SOURCES.md) is mapped in process by the simulator's room
// tour (as "rgctl eval rooms --in-process", MappingRun.h). Then --trials trials per map: the
// robot is put at a random reachable free pose (seeded), the localizer is not told, and the robot
// wanders to random goals (RandomGoalDriver.h) for --trial-seconds of simulated time, the
// localizer taking every scan with its odometry. The truth is the simulator's pose put into the
// map where the map holds that place (LocalTruth.h: fitted to the mapped scans nearby, so that the
// SLAM map's own distortion, slam_error_m, is not counted against the localizer).
//   success:           at the end the localizer says it is localized and its estimate has been
//                      within 0.3 m and 10 degrees of the truth since some scan on;
//   wrong_convergence: at the end the localizer says it is localized but its estimate is not
//                      within that tolerance;
//   wrong_claims:      trials in which, at any scan, it said it was localized more than 1 m or
//                      30 degrees away from the truth;
//   travel_to_converge_m: true travel from the start to that scan, over successful trials;
//   first_top1:        trials whose first recognition ranked a pose within 0.5 m and 15 degrees
//                      of the truth first (how well recognition alone does); first_any: among its
//                      seeded candidates at all.
// Prints a line per map, then the figures per set of the IPA split, then
//   globalloc: maps=… trials=… success=… wrong_convergence=… travel_to_converge_m_median=…
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>

#include "core/gateways/classify/HmmModelFile.h"
#include "core/lines/ScanPoints.h"
#include "core/nav/localization/GlobalLocalizer.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/Simulation.h"
#include "core/sim/StartPose.h"
#include "tests/eval/globalloc/MappedFloor.h"
#include "tests/eval/globalloc/RandomGoalDriver.h"
#include "tests/eval/split/IpaSplit.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  std::size_t trials = 30;
  std::uint64_t seed = 1;
  double trialSeconds = 120.0;
  std::string models = "config/gateways/gateway-hmms.txt";
  std::string split = "config/eval/ipa-split.yaml";
  bool list = false;
  bool truePoses = false;
};

constexpr double kToleranceM = 0.3, kToleranceRad = 10.0 * M_PI / 180.0;
constexpr double kClaimM = 1.0, kClaimRad = 30.0 * M_PI / 180.0;

struct Totals {
  std::size_t maps = 0, trials = 0, success = 0, wrong = 0, wrongClaims = 0, firstTop1 = 0, firstAny = 0;
  std::vector<double> travel;  // to convergence, successful trials
  // The filter's fit per beam at scans where its estimate was within the tolerance / over 1 m off
  // (what the kidnap threshold must separate).
  std::vector<double> fitRight, fitWrong;

  void add(const Totals& o) {
    maps += o.maps;
    trials += o.trials;
    success += o.success;
    wrong += o.wrong;
    wrongClaims += o.wrongClaims;
    firstTop1 += o.firstTop1;
    firstAny += o.firstAny;
    travel.insert(travel.end(), o.travel.begin(), o.travel.end());
    fitRight.insert(fitRight.end(), o.fitRight.begin(), o.fitRight.end());
    fitWrong.insert(fitWrong.end(), o.fitWrong.begin(), o.fitWrong.end());
  }
  double share(std::size_t n) const { return trials == 0 ? 0.0 : double(n) / double(trials); }
  double travelMedian() const { return quantile(travel, 0.5); }
  static double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    const auto at = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), at, v.end());
    return *at;
  }
};

struct Trial {
  bool success = false, wrong = false, wrongClaim = false, firstTop1 = false, firstAny = false;
  double travelToConverge = 0.0, travel = 0.0;
  std::size_t recognitions = 0, kidnaps = 0, corrections = 0, localizedScans = 0, goodScans = 0;
  double finalErrorM = 0.0;
  std::vector<double> fitRight, fitWrong;
};

Trial runTrial(const LoadedWorld& world, const GridPlanner& planner, const std::vector<bool>& reachable,
               const LocalTruth& truthInMap, const LocalizationMap& map, const std::vector<RegionView>& regions,
               const std::vector<GatewayView>& gateways, const Options& options, std::uint64_t seed) {
  RandomGoalDriver driver(planner, reachable, seed);
  const WorldPoint at = driver.randomPoint();
  std::mt19937_64 rng(seed);
  const Pose2D start{at.x, at.y, std::uniform_real_distribution<double>(-M_PI, M_PI)(rng)};
  SimulationConfig simulation;
  simulation.seed = seed;
  Simulation sim(world.grid, simulation, start);
  GlobalLocalizer localizer(GlobalLocalizerConfig{}, MclConfig{}, map, regions, gateways, seed);
  Trial t;
  bool inStreak = false, firstSeen = false;
  while (sim.time() < options.trialSeconds) {
    sim.command(driver.command(sim.truePose(), sim.time()));
    const Pose2D before = sim.truePose();
    SimulationStep step = sim.step();
    t.travel += std::hypot(step.truePose.x - before.x, step.truePose.y - before.y);
    if (!step.scan) continue;
    step.scan->sensorPose = step.scan->odometry;
    localizer.update(*step.scan);
    const Pose2D truth = truthInMap.toMap(step.truePose);
    if (!firstSeen && !localizer.candidates().empty()) {
      firstSeen = true;
      const auto& c = localizer.candidates();
      t.firstTop1 = poseWithin(c.front().mapPose, truth, 0.5, 15.0 * M_PI / 180.0);
      t.firstAny = std::any_of(c.begin(), c.end(), [&](const PoseCandidate& p) {
        return poseWithin(p.mapPose, truth, 0.5, 15.0 * M_PI / 180.0);
      });
    }
    if (const std::optional<PoseEstimate> f = localizer.estimate()) {
      if (poseWithin(f->mapPose, truth, kToleranceM, kToleranceRad)) t.fitRight.push_back(f->fitPerBeam);
      if (!poseWithin(f->mapPose, truth, kClaimM, kClaimRad)) t.fitWrong.push_back(f->fitPerBeam);
    }
    const std::optional<PoseEstimate> e = localizer.localized() ? localizer.estimate() : std::nullopt;
    const bool good = e && poseWithin(e->mapPose, truth, kToleranceM, kToleranceRad);
    if (e && !poseWithin(e->mapPose, truth, kClaimM, kClaimRad)) t.wrongClaim = true;
    t.localizedScans += e.has_value();
    t.goodScans += good;
    if (good && !inStreak) t.travelToConverge = t.travel;
    inStreak = good;
    t.success = good;
    t.wrong = e && !good;
    t.finalErrorM = e ? std::hypot(e->mapPose.x - truth.x, e->mapPose.y - truth.y) : -1.0;
  }
  t.recognitions = localizer.recognitions();
  t.kidnaps = localizer.kidnapsDetected();
  t.corrections = localizer.corrections();
  return t;
}

Totals evaluate(const std::string& mapPath, const Options& options, const std::optional<HmmClassifier>& classifier) {
  const MappedFloor floor = mapFloor(mapPath, classifier, options.truePoses);
  const LoadedWorld& world = floor.world;
  const std::vector<RegionView>& regions = floor.regions;
  const std::vector<GatewayView>& gateways = floor.gateways;
  const MclConfig mcl;
  const LocalizationMap map = LocalizationMap::fromViews(regions, gateways, mcl.beam);
  const LocalTruth truthInMap(floor.scans, floor.mapToWorld);
  const GridPlanner planner(world.grid);
  const Pose2D tourStart = openestPose(world.grid);
  const std::vector<bool> reachable = planner.reachableFrom({tourStart.x, tourStart.y});
  Totals totals;
  totals.maps = 1;
  for (std::size_t i = 0; i < options.trials; ++i) {
    const Trial t = runTrial(world, planner, reachable, truthInMap, map, regions, gateways, options,
                             options.seed * 1000003 + i);
    ++totals.trials;
    totals.success += t.success;
    totals.wrong += t.wrong;
    totals.wrongClaims += t.wrongClaim;
    totals.firstTop1 += t.firstTop1;
    totals.firstAny += t.firstAny;
    if (t.success) totals.travel.push_back(t.travelToConverge);
    totals.fitRight.insert(totals.fitRight.end(), t.fitRight.begin(), t.fitRight.end());
    totals.fitWrong.insert(totals.fitWrong.end(), t.fitWrong.begin(), t.fitWrong.end());
    if (options.list)
      std::printf("#   trial %zu: %s travel=%.1f m converged_after=%.1f m recognitions=%zu kidnaps_detected=%zu corrections=%zu "
                  "localized_scans=%zu within_scans=%zu final_error_m=%.2f%s first_top1=%d\n",
                  i, t.success ? "success" : t.wrong ? "WRONG" : "not localized", t.travel, t.travelToConverge,
                  t.recognitions, t.kidnaps, t.corrections, t.localizedScans, t.goodScans, t.finalErrorM,
                  t.wrongClaim ? " wrong_claim" : "", int(t.firstTop1));
  }
  std::printf("%-28s regions=%zu gateways=%zu slam_error_m=%.2f/%.2f trials=%zu success=%.3f wrong_convergence=%.3f wrong_claims=%zu "
              "first_top1=%.3f first_any=%.3f travel_to_converge_m_median=%.2f fit_right_p1/p5/p50=%.2f/%.2f/%.2f "
              "fit_wrong_p50/p95/p99=%.2f/%.2f/%.2f\n",
              ipaMapName(mapPath).c_str(), regions.size(), gateways.size(), floor.slamErrorMeanM, floor.slamErrorMaxM, totals.trials, totals.share(totals.success),
              totals.share(totals.wrong), totals.wrongClaims, totals.share(totals.firstTop1),
              totals.share(totals.firstAny), totals.travelMedian(), Totals::quantile(totals.fitRight, 0.01),
              Totals::quantile(totals.fitRight, 0.05), Totals::quantile(totals.fitRight, 0.5),
              Totals::quantile(totals.fitWrong, 0.5), Totals::quantile(totals.fitWrong, 0.95),
              Totals::quantile(totals.fitWrong, 0.99));
  std::fflush(stdout);
  return totals;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::vector<std::string> maps;
  po::options_description desc(
      "rgnav-eval-globalloc [options] <X_furnitures.png...>: global localization by region recognition on mapped floor plans");
  desc.add_options()
      ("map", po::value(&maps)->required(), "furnished IPA floor plans")
      ("trials", po::value(&options.trials)->default_value(options.trials), "trials per map")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed of the start poses, goals and simulation")
      ("trial-seconds", po::value(&options.trialSeconds)->default_value(options.trialSeconds), "simulated seconds per trial")
      ("models", po::value(&options.models)->default_value(options.models), "gateway HMMs (used if the file exists)")
      ("split", po::value(&options.split)->default_value(options.split), "the IPA maps' tuning/check split")
      ("list", po::bool_switch(&options.list), "print every trial")
      ("true-poses", po::bool_switch(&options.truePoses),
       "map with the true poses instead of SLAM (the trials then measure the localizer without the map's distortion)");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    std::optional<HmmClassifier> classifier;
    if (std::filesystem::exists(options.models)) classifier = loadHmmModels(options.models);
    const SplitTotals<Totals> bySet = evaluateMaps<Totals>(
        loadIpaSplit(options.split), maps, [&](const std::string& map) { return evaluate(map, options, classifier); });
    const auto figures = [](const Totals& s) {
      return std::vector<Figure>{{"success", s.share(s.success)},
                                 {"wrong_convergence", s.share(s.wrong)},
                                 {"travel_to_converge_m_median", s.travelMedian()}};
    };
    std::printf("%s\n", splitFiguresLine("globalloc_split", bySet, figures).c_str());
    const Totals& t = bySet.all;
    std::printf("globalloc: maps=%zu trials=%zu success=%.3f wrong_convergence=%.3f travel_to_converge_m_median=%.2f "
                "wrong_claims=%zu first_top1=%.3f first_any=%.3f\n",
                t.maps, t.trials, t.share(t.success), t.share(t.wrong), t.travelMedian(), t.wrongClaims,
                t.share(t.firstTop1), t.share(t.firstAny));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-globalloc: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-globalloc: " << e.what() << std::endl;
  }
  return 2;
}
