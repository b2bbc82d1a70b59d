// rgnav-eval-routes: the routes evaluation of issue 26 ("rgctl eval routes"): does structuring a
// floor into regions and gateways make planning cheaper without making paths longer (thesis 2.1.3,
// 5.4)? For each furnished IPA floor plan (floorplans/SOURCES.md) the simulator's room tour is
// mapped in process (as "rgctl eval rooms --in-process": SLAM -> gateway detection -> RG Mapping
// Kernel, MappingRun.h); then --pairs random start/goal pairs (fixed seed), each pair's points in
// two different ground-truth rooms, both mapped (where the robot can stand in a region's planning
// grid and in the whole floor's grid) and joined in the floor plan itself for a robot of that
// radius, are planned twice on the same map:
//   - RG: RoutePlanner (RG-graph route, framed-quadtree paths in the regions it passes);
//   - floor: one FramedQuadtreePlanner over the whole floor's grid (FloorGrid.h), same robot
//     radius, resolution and wall costs.
// Each planner is timed over all pairs; the RG planner's region grids are built while sampling
// (regionsAt) and the floor tree once, before (its build time is printed). The RG planner runs
// twice: the first pass also plans the region paths between crossing points it caches; the second
// is timed.
// Prints a line per map and, last,
//   routes: maps=… pairs=… found=… length_ratio_mean=… speedup=…
// length_ratio = RG path length / floor path length, over pairs both found; speedup = floor time
// / RG time; rg_unsafe, floor_unsafe: paths that, placed on the floor plan, bring the robot within
// its radius less 0.1 m of an obstacle (BuildingClearance.h). The line before gives the figures per
// set of the IPA split.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>

#include "core/gateways/classify/HmmModelFile.h"
#include "core/lines/ScanPoints.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlanner.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/sim/LoadedWorld.h"
#include "tests/eval/rooms/MappingRun.h"
#include "core/rgmap/export/RgMapSnapshot.h"
#include "tests/eval/routes/BuildingClearance.h"
#include "tests/eval/routes/FloorGrid.h"
#include "tests/eval/routes/RoutePictures.h"
#include "tests/eval/split/IpaSplit.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::size_t pairs = 200;
  std::uint64_t seed = 1;
  std::string models = "config/gateways/gateway-hmms.txt";
  std::string split = "config/eval/ipa-split.yaml";
  bool list = false;
  std::string outDir;
  std::string config = "config/modules/pathplanning.yaml";
};

struct Totals {
  std::size_t maps = 0, pairs = 0, found = 0, floorFound = 0, compared = 0, rgUnsafe = 0, floorUnsafe = 0;
  double ratioSum = 0.0, rgSeconds = 0.0, floorSeconds = 0.0;

  void add(const Totals& o) {
    maps += o.maps;
    pairs += o.pairs;
    found += o.found;
    floorFound += o.floorFound;
    compared += o.compared;
    rgUnsafe += o.rgUnsafe;
    floorUnsafe += o.floorUnsafe;
    ratioSum += o.ratioSum;
    rgSeconds += o.rgSeconds;
    floorSeconds += o.floorSeconds;
  }
  double ratioMean() const { return compared == 0 ? 0.0 : ratioSum / double(compared); }
  double speedup() const { return rgSeconds > 0.0 ? floorSeconds / rgSeconds : 0.0; }
  double foundShare() const { return pairs == 0 ? 0.0 : double(found) / double(pairs); }
};

constexpr double kUnsafeToleranceM = 0.1;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct Pair {
  Eigen::Vector2d start, goal;  // map frame
};

// Random pairs in different rooms, both mapped (free on the RG planner's and the floor grid) and
// joined in the building itself (BuildingClearance): pairs no map of this building could join are
// none of the planners' failures. Fewer if the floor has too few such points.
std::vector<Pair> samplePairs(const LoadedWorld& world, const BuildingClearance& building, const Pose2D& mapToWorld,
                              const RoutePlanner& rg, const OccupancyGrid& floor, std::size_t count, std::uint64_t seed) {
  const GroundTruth& truth = *world.truth;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> col(0, world.grid.width() - 1), row(0, world.grid.height() - 1);
  const Pose2D worldToMap = inverse(mapToWorld);
  struct Drawn {
    Eigen::Vector2d at;
    int room = -1, piece = -1;
  };
  const auto draw = [&]() -> std::optional<Drawn> {
    for (int attempt = 0; attempt < 10000; ++attempt) {
      const CellIndex c{col(rng), row(rng)};
      const int room = truth.roomOf(c), piece = building.pieceAt(c);
      if (room < 0 || piece < 0) continue;
      const WorldPoint w = world.grid.center(c);
      const Eigen::Vector2d p = transformPoint(worldToMap, {w.x, w.y});
      const auto cell = floor.cellOf({p.x(), p.y()});
      if (!cell || floor.blocked(*cell) || rg.regionsAt(p).empty()) continue;
      return Drawn{p, room, piece};
    }
    return std::nullopt;
  };
  std::vector<Pair> out;
  for (std::size_t attempt = 0; out.size() < count && attempt < count * 50; ++attempt) {
    const auto a = draw(), b = draw();
    if (!a || !b) break;
    if (a->room != b->room && a->piece == b->piece) out.push_back({a->at, b->at});
  }
  return out;
}

// <stem>_routes.png: the six pairs with the largest length ratio; <stem>_quadtree.png: the
// quadtree of the region of the first pair's start.
void writePictures(const std::string& stem, const RgMapSnapshot& snapshot, const PlanningMap& map,
                   const RoutePlannerConfig& config, const std::vector<Pair>& pairs,
                   const std::vector<ComparedPaths>& paths, const std::vector<std::optional<double>>& rgLength,
                   const std::vector<std::optional<double>>& floorLength) {
  std::vector<std::pair<double, std::size_t>> ratios;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (rgLength[i] && floorLength[i] && *floorLength[i] > 0.0) ratios.emplace_back(*rgLength[i] / *floorLength[i], i);
  std::sort(ratios.rbegin(), ratios.rend());
  std::vector<ComparedPaths> worst;
  for (std::size_t k = 0; k < std::min<std::size_t>(6, ratios.size()); ++k) worst.push_back(paths[ratios[k].second]);
  writeRoutesPicture(stem + "_routes.png", snapshot, worst);
  RoutePlanner locate(config);
  locate.setMap(map);
  const std::vector<RegionId> regions = locate.regionsAt(pairs.front().start);
  for (const RegionView& region : map.regions)
    if (!regions.empty() && region.summary.id == regions.front())
      writeQuadtreePicture(stem + "_quadtree.png", region, config, pairs.front().start);
}

Totals evaluate(const std::string& mapPath, const Options& options, const std::optional<HmmClassifier>& classifier) {
  const LoadedWorld world = loadWorld(mapPath);
  if (!world.truth) throw FileError(mapPath + ": no ground-truth rooms beside it");
  const RoutePlannerConfig config = loadRoutePlannerConfig(options.config);
  MappingRunSetup setup;
  setup.pipeline = shippedPipelineConfig();
  PlanningMap map;
  OccupancyGrid floor;
  std::optional<RgMapSnapshot> snapshot;
  setup.atEnd = [&](const RgMappingKernel& kernel) {
    map = planningMapOf(kernel);
    if (!options.outDir.empty()) snapshot = snapshotOf(kernel);
    floor = floorGridOf(kernel.state(), config.gridResolutionM, config.robotRadiusM);
  };
  const MappingRun run = mapRoomTour(world.grid, *world.truth, setup, classifier);
  RoutePlanner rg(config);
  rg.setMap(map);
  const BuildingClearance building(world.grid, config.robotRadiusM);
  const std::vector<Pair> pairs = samplePairs(world, building, run.mapToWorld, rg, floor, options.pairs, options.seed);
  const auto floorBuildStart = Clock::now();
  const FramedQuadtreePlanner whole(floor, config.region);
  const double floorBuild = seconds(Clock::now() - floorBuildStart);
  const auto toCells = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p.x() - floor.origin().x) / floor.resolution(), (p.y() - floor.origin().y) / floor.resolution());
  };

  // The first RG pass builds the region grids; the second is timed.
  const auto rgStart = Clock::now();
  std::vector<std::optional<double>> rgLength(pairs.size());
  std::vector<ComparedPaths> paths(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) try {
      const Plan plan = rg.plan({pairs[i].start.x(), pairs[i].start.y(), 0.0}, PlanGoal::at(pairs[i].goal));
      rgLength[i] = plan.lengthM;
      paths[i].rg = plan.path;
    } catch (const NoPathError& e) {
      std::printf("#   RG no path (%.2f, %.2f) -> (%.2f, %.2f): %s\n", pairs[i].start.x(), pairs[i].start.y(),
                  pairs[i].goal.x(), pairs[i].goal.y(), e.what());
    }
  const double rgCold = seconds(Clock::now() - rgStart);
  const auto rgWarmStart = Clock::now();
  for (const Pair& p : pairs) try {
      rg.plan({p.start.x(), p.start.y(), 0.0}, PlanGoal::at(p.goal));
    } catch (const NoPathError&) {
    }
  const double rgWarm = seconds(Clock::now() - rgWarmStart);

  std::vector<std::optional<double>> floorLength(pairs.size());
  const auto floorStart = Clock::now();
  for (std::size_t i = 0; i < pairs.size(); ++i) try {
      const CellUnitPath path = whole.plan(toCells(pairs[i].start), toCells(pairs[i].goal));
      floorLength[i] = path.length * floor.resolution();
      for (const Eigen::Vector2d& c : path.points)
        paths[i].floor.push_back({floor.origin().x + c.x() * floor.resolution(), floor.origin().y + c.y() * floor.resolution()});
    } catch (const Error&) {
    }
  const double floorSeconds = seconds(Clock::now() - floorStart);
  if (snapshot && !pairs.empty()) writePictures(options.outDir + "/" + ipaMapName(mapPath), *snapshot, map, config,
                                                pairs, paths, rgLength, floorLength);

  Totals t;
  t.maps = 1;
  t.pairs = pairs.size();
  t.rgSeconds = rgWarm;
  t.floorSeconds = floorSeconds;
  // A path is unsafe where, placed in the floor plan, it brings the robot closer to an obstacle
  // than its radius less kUnsafeToleranceM (the map's own errors: SLAM, line fits).
  const auto inWorld = [&](const std::vector<Eigen::Vector2d>& path) {
    std::vector<Eigen::Vector2d> out;
    for (const Eigen::Vector2d& p : path) out.push_back(transformPoint(run.mapToWorld, p));
    return out;
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    t.found += rgLength[i].has_value();
    t.floorFound += floorLength[i].has_value();
    const bool rgUnsafe = rgLength[i] && !building.fits(inWorld(paths[i].rg), kUnsafeToleranceM);
    const bool floorUnsafe = floorLength[i] && !building.fits(inWorld(paths[i].floor), kUnsafeToleranceM);
    t.rgUnsafe += rgUnsafe;
    t.floorUnsafe += floorUnsafe;
    if (rgLength[i] && floorLength[i] && *floorLength[i] > 0.0) {
      ++t.compared;
      t.ratioSum += *rgLength[i] / *floorLength[i];
    }
    if (options.list)
      std::printf("#   pair %zu (%.2f, %.2f) -> (%.2f, %.2f): rg=%.2f m%s floor=%.2f m%s\n", i, pairs[i].start.x(),
                  pairs[i].start.y(), pairs[i].goal.x(), pairs[i].goal.y(), rgLength[i].value_or(-1.0),
                  rgUnsafe ? " unsafe" : "", floorLength[i].value_or(-1.0), floorUnsafe ? " unsafe" : "");
  }
  std::printf("%-28s regions=%zu gateways=%zu pairs=%zu found=%zu floor_found=%zu rg_unsafe=%zu floor_unsafe=%zu "
              "length_ratio_mean=%.3f rg_ms=%.3f floor_ms=%.3f speedup=%.1f rg_first_pass_s=%.2f floor_build_s=%.2f "
              "floor_cells=%dx%d\n",
              ipaMapName(mapPath).c_str(), map.regions.size(), map.gateways.size(), t.pairs, t.found, t.floorFound,
              t.rgUnsafe, t.floorUnsafe, t.ratioMean(), 1e3 * rgWarm / double(std::max<std::size_t>(t.pairs, 1)),
              1e3 * floorSeconds / double(std::max<std::size_t>(t.pairs, 1)), t.speedup(), rgCold, floorBuild,
              floor.width(), floor.height());
  std::fflush(stdout);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::vector<std::string> maps;
  po::options_description desc(
      "rgnav-eval-routes [options] <X_furnitures.png...>: RG routes against whole-floor planning on mapped floor plans");
  desc.add_options()
      ("map", po::value(&maps)->required(), "furnished IPA floor plans")
      ("pairs", po::value(&options.pairs)->default_value(options.pairs), "start/goal pairs per map")
      ("seed", po::value(&options.seed)->default_value(options.seed), "pair sampling seed")
      ("models", po::value(&options.models)->default_value(options.models), "gateway HMMs (used if the file exists)")
      ("split", po::value(&options.split)->default_value(options.split), "the IPA maps' tuning/check split")
      ("config", po::value(&options.config)->default_value(options.config),
       "route planner parameters (the PathPlanning module's; both planners use its grid, radius and wall costs)")
      ("list", po::bool_switch(&options.list), "print every pair with both path lengths")
      ("out", po::value(&options.outDir), "write pictures of the worst pairs and of a region's quadtree here");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    if (!options.outDir.empty()) std::filesystem::create_directories(options.outDir);
    std::optional<HmmClassifier> classifier;
    if (std::filesystem::exists(options.models)) classifier = loadHmmModels(options.models);
    const SplitTotals<Totals> bySet = evaluateMaps<Totals>(
        loadIpaSplit(options.split), maps, [&](const std::string& map) { return evaluate(map, options, classifier); });
    const Totals& t = bySet.all;
    const auto figures = [](const Totals& s) {
      return std::vector<Figure>{{"found_share", s.foundShare()}, {"length_ratio_mean", s.ratioMean()},
                                 {"speedup", s.speedup()}};
    };
    std::printf("%s\n", splitFiguresLine("routes_split", bySet, figures).c_str());
    std::printf("routes: maps=%zu pairs=%zu found=%zu found_share=%.3f floor_found=%zu rg_unsafe=%zu floor_unsafe=%zu "
                "length_ratio_mean=%.3f speedup=%.1f\n",
                t.maps, t.pairs, t.found, t.foundShare(), t.floorFound, t.rgUnsafe, t.floorUnsafe, t.ratioMean(), t.speedup());
    return t.found == t.pairs ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-routes: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-routes: " << e.what() << std::endl;
  }
  return 2;
}
